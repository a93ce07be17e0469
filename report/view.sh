#!/usr/bin/env bash
# view.sh REPORT.html -- render the report in headless Chromium and check it.
#
# The page counts its images that did not decode and its tables without a
# body cell (a script at its end writes them on <body> once loaded); this
# reads them from the rendered DOM, fails if either is non-zero, and writes
# a screenshot of the top of the page beside the report (REPORT.png).
set -euo pipefail
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: view.sh REPORT.html" >&2; exit 2; }
page=$(realpath "$1")
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
flags=(--headless=new --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --user-data-dir="$profile" --virtual-time-budget=10000)
dom=$(chromium "${flags[@]}" --dump-dom "file://$page" 2>/dev/null)
attr() { printf '%s' "$dom" | grep -o "<body[^>]*>" | head -1 | sed -n "s/.* $1=\"\([0-9]*\)\".*/\1/p"; }
images=$(attr data-images) broken=$(attr data-broken-images) tables=$(attr data-tables) empty=$(attr data-empty-tables)
if [ -z "$images" ] || [ -z "$tables" ]; then
    echo "report-view: the page did not finish loading in Chromium (no counts on <body>)" >&2
    exit 1
fi
chromium "${flags[@]}" --window-size=1200,3000 --screenshot="${page%.html}.png" "file://$page" >/dev/null 2>&1 || true
echo "report-view: $images figures ($broken broken), $tables tables ($empty empty); screenshot ${page%.html}.png"
[ "$broken" -eq 0 ] && [ "$empty" -eq 0 ]
