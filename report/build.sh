#!/usr/bin/env bash
# build.sh RESULTS OUTDIR HJCHECK [quick] -- assemble OUTDIR/report.html.
#
# The report is generated, never edited: report/intro.md, the comparison
# rules (hjcheck --rules), the check summary, then for each paper its
# overview.md and, for every row of its report.tsv (source, tables,
# figures), the program's own literate comment, the published-vs-computed
# table of each table it makes (from results/<paper>/<table>.check.tsv),
# the fitted orders (<table>.fit.tsv), its figures and its notes (a
# NAME.md entry: the template <paper>/notes/NAME.md with every number
# filled from the results by report/note.awk; programs write data only).
# Markdown goes through cmark (CommonMark); tables are emitted as HTML
# blocks.
set -euo pipefail
res=$1 out=$2 hjcheck=$3 quick=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

# The first /* ... */ comment of a C file, headings pushed two levels down.
literate() {
    if [ ! -f "$1" ]; then
        printf '\n**Missing source: `%s`**\n\n' "$1"
        return
    fi
    awk 'BEGIN { on = 0 }
         !on && /^\/\*/ { on = 1; sub(/^\/\*+ ?/, ""); if ($0 == "") next }
         on && /\*\// { sub(/ *\*\/.*$/, ""); if ($0 != "") print; exit }
         on { sub(/^ \* ?/, ""); if ($0 ~ /^#/) $0 = "##" $0; print }' "$1"
    printf '\n*Source: `%s`*\n\n' "$(realpath -m --relative-to=. "$1")"
}

# A figure as an <img> with its data inline, so report.html is one file.
embed_figure() {
    local path=$1 alt=$2 mime
    case $path in
    *.png) mime=image/png ;;
    *.svg) mime=image/svg+xml ;;
    *) printf '\n*figure of unknown type: %s*\n\n' "$alt"; return ;;
    esac
    printf '\n<p><img alt="%s" src="data:%s;base64,' "$alt" "$mime"
    base64 -w 0 "$path"
    printf '"></p>\n\n'
}

html_escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }

# check_table CHECK NAME LABEL FILE...: published beside computed, from a
# .check.tsv, under the source line of each FILE of reference values that
# exists (published/<table>.tsv, reference/{paper,exact,regression,peer}/<table>.tsv).
check_table() {
    local f=$1 name=$2 label=${3:-published} src what
    shift $(($# < 3 ? $# : 3))
    if [ ! -f "$f" ]; then
        printf '\n**%s: not computed** (no %s)\n\n' "$name" "$f"
        return
    fi
    for src in "$@"; do
        [ -f "$src" ] || continue
        case $src in
        */reference/paper/*) what='values from the paper' ;;
        */reference/exact/*) what='exact values' ;;
        */reference/regression/*) what="regression values (our run at commit $(sed -n 's/^# commit: *//p' "$src" | head -1))" ;;
        */reference/peer/*) what="values of the peer's own run" ;;
        *) what="$label values" ;;
        esac
        sed -n 's/^# source: *//p' "$src" | head -1 | html_escape | sed 's/^/\n<p class="tsrc"><i>Source of the '"$what"':<\/i> /; s/$/<\/p>/'
    done
    # Each distinct reason is written once, under the table, numbered; the
    # cells it covers point to it.
    awk -F'\t' -v name="$name" -v label="$label" '
        function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }
        /^#/ || $1 == "table" { next }
        { n++; split($8, v, " "); cnt[v[1]]++
          cls = v[1]; if ($8 ~ /round-off/) cls = "match";
          ref = ""
          if ($10 != "" && $10 != "-") {
              if (!($10 in rid)) { nr++; rid[$10] = nr; rtext[nr] = $10; rcells[nr] = "" }
              k = rid[$10]; rcells[k] = rcells[k] (rcells[k] == "" ? "" : "; ") esc($2) " " esc($3)
              ref = sprintf("<a href=\"#%s-r%d\">[%d]</a>", anchor, k, k)
          }
          row[n] = sprintf("<tr class=\"%s\"><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>",
                           cls, esc($2), esc($3), esc($5), esc($11 == "" ? "paper" : $11), esc($6), esc($7), esc($8), esc($9), ref) }
        END {
          printf "\n<p class=\"tsum\"><b>%s</b>: %d match, %d close, %d differ", name, cnt["match"], cnt["close"], cnt["differs"]
          if (cnt["missing"]) printf ", %d missing", cnt["missing"]
          if (cnt["ambiguous"]) printf ", %d ambiguous", cnt["ambiguous"]
          printf "</p>\n<table class=\"check\">\n<tr><th>row</th><th>quantity</th><th>%s</th><th>origin</th><th>computed</th><th>difference</th><th>verdict</th><th>accepted</th><th>reason</th></tr>\n", label
          for (i = 1; i <= n; i++) print row[i]
          print "</table>"
          if (nr) {
              print "<ol class=\"reasons\">"
              for (k = 1; k <= nr; k++)
                  printf "<li id=\"%s-r%d\">%s <span class=\"cells\">(cells: %s)</span></li>\n", anchor, k, esc(rtext[k]), rcells[k]
              print "</ol>"
          }
          print ""
        }' anchor="$(printf '%s' "$name" | tr -c 'A-Za-z0-9' '-')" "$f"
}

# A row whose fit failed (p = nan: hj_fit_order returned an error, e.g. the
# robust fit did not converge) says so; its pairwise orders are in the
# table above it.
fit_table() {
    local f=$1
    [ -f "$f" ] || return 0
    awk -F'\t' '
        /^#/ || $1 == "case" { next }
        $3 == "nan" { nofit++ }
        { rows = rows sprintf("<tr><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>\n",
                              $1, $2, ($3 == "nan" ? "no fit" : sprintf("%.2f", $3)),
                              ($4 == "nan" || $4 == "" ? "-" : sprintf("%.2f", $4)),
                              ($6 == "nan" ? "-" : sprintf("%.2f", $6)), $7) }
        END { if (rows != "") printf "\n<table class=\"fit\">\n<tr><th>case</th><th>error</th><th>fitted order p</th><th>std. error</th><th>least-squares p</th><th>points</th></tr>\n%s</table>\n\n", rows
              if (nofit) printf "<p class=\"tsum\"><i>no fit</i>: the order fit of common/hj_fit.h returned no order for this row (as when the points scatter about a line by more than the Huber scale, so that its robust fit does not converge); the least-squares column gives the plain fit of the same points where one exists, the figure shows p = nan, and the pairwise orders are in the table above.</p>\n\n" }' "$f"
}

# The cost of a program's runs in make reproduce (hjtime's files
# time/<program>[.<table>].tsv): one line under the example.
run_times() {
    local dir=$1 prog=$2 f line=""
    for f in "$dir/$prog.tsv" "$dir/$prog".*.tsv; do
        [ -f "$f" ] || continue
        line+=$(awk -F'\t' 'NR == 2 { printf "%s%s: %s s wall, %s s CPU, peak %s MB", sep, $1, $2, $3, $4 }' sep="${line:+; }" "$f")
    done
    [ -z "$line" ] || printf '\n*Run time on this machine (`make reproduce`): %s.*\n\n' "$line"
}

# All of a paper's runs, as a table at the end of its section.
run_time_table() {
    local dir=$1 name=$2
    compgen -G "$dir/*.tsv" > /dev/null || return 0
    printf '\n### Run times of %s\n\n' "$name"
    printf 'Each program run of `make reproduce` on this machine (2 cores), measured by `hjtime` (common/tools/hjtime.c): elapsed time, CPU time (user + system, all threads) and peak resident memory.  Shown, never compared.\n\n'
    printf '<table>\n<tr><th>run</th><th>wall (s)</th><th>CPU (s)</th><th>peak memory (MB)</th></tr>\n'
    awk -F'\t' 'FNR == 2 { printf "<tr><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>\n", $1, $2, $3, $4; w += $2; c += $3 }
                END { printf "<tr><td><b>sum</b></td><td><b>%.1f</b></td><td><b>%.1f</b></td><td></td></tr>\n</table>\n\n", w, c }' "$dir"/*.tsv
}

md=$tmp/report.md
{
    cat report/intro.md
    printf '\n## How a cell is judged\n\n'
    "$hjcheck" --rules
    printf '\nThe match limits of errors, counts, ratios and values are relative, |computed/published - 1| (those of orders are absolute, of bounds and exact counts as stated), and their close limits are factors taken both ways, computed/published between 1/F and F: a value is *close within 10 %%* (F = 1.1) from -9.1 %% to +10 %%, an error *close within a factor 2* from 0.5 to 2 times.\n'
    printf '\n## Summary of `make check`\n\n```\n'
    cat "$res/check-summary.txt"
    printf '```\n\n'
    for entry in paper1:paper1_fastsweeping eik:paper1_fastsweeping/eik paper2:paper2_toolbox paper3:paper3_ultrabee reach:studies/reach mpi:mpi; do
        name=${entry%%:*} dir=${entry#*:}
        [ -f "$dir/report.tsv" ] || continue
        if [ -f "$dir/overview.md" ]; then cat "$dir/overview.md"; printf '\n'; fi
        tail -n +2 "$dir/report.tsv" | while IFS=$'\t' read -r src tables figs; do
            [ -n "$src" ] || continue
            literate "$dir/$src"
            for t in $tables; do
                [ "$t" = - ] && continue
                # Paper 2 and eik publish almost no numbers and the
                # reachability study is not a paper: their cells are checked
                # against exact values and accepted runs (see the source lines).
                label=published; case $name in paper2 | eik | reach) label=reference ;; esac
                check_table "$res/$name/$t.check.tsv" "$name $t" "$label" "$dir/published/$t.tsv" \
                    "$dir"/reference/{paper,exact,regression,peer}/"$t".tsv
                fit_table "$res/$name/$t.fit.tsv"
            done
            for f in $figs; do
                case $f in
                -) ;;
                *.md) # a note: its template, filled from the results (report/note.awk)
                      if [ ! -f "$dir/notes/$f" ]; then printf '\n**missing note template: %s/notes/%s**\n\n' "$dir" "$f"
                      elif awk -v dir="$res/$name" -f report/note.awk "$dir/notes/$f" > "$tmp/note.md"; then
                          cat "$tmp/note.md"; printf '\n'
                      elif [[ $src == bench_* || $name == mpi ]]; then printf '\n*Not in this report: the data of `%s` come from `make bench` (benchmarks stay out of `make reproduce` and the tests); run `make bench`, then `make report-now`, to see them here.*\n\n' "$f"
                      elif [ -n "$quick" ]; then printf '\n*Not run in the quick path: the data of `%s` comes with the published sizes (`make %s`).*\n\n' "$f" "$name"
                      else cat "$tmp/note.md"; printf '\n'; fi ;; # with its **missing: ...** marks
                *) if [ -f "$res/$name/$f" ]; then
                       embed_figure "$res/$name/$f" "$f"
                   else
                       printf '\n*missing figure: %s*\n\n' "$f"
                   fi ;;
                esac
            done
            run_times "$res/$name/time" "${src%.c}"
        done
        run_time_table "$res/$name/time" "$name"
    done
} > "$md"

# Pipe tables (GitHub style: a header row, a |---| row, body rows) become
# HTML tables: CommonMark has no tables, and generated .md files and the
# overviews use them.
awk 'function cells(line, out,   n, i) {
         sub(/^[ \t]*\|/, "", line); sub(/\|[ \t]*$/, "", line)
         n = split(line, out, "|")
         for (i = 1; i <= n; i++) { gsub(/^[ \t]+|[ \t]+$/, "", out[i]) }
         return n }
     function esc(t) { gsub(/&/, "\\&amp;", t); gsub(/</, "\\&lt;", t); gsub(/>/, "\\&gt;", t); gsub(/`/, "", t); return t }
     /^```/ { code = !code }
     holding && /^[ \t]*\|[ \t:|-]+\|?[ \t]*$/ && /---/ {
         n = cells(held, h); printf "\n<table>\n<tr>"
         for (i = 1; i <= n; i++) printf "<th>%s</th>", esc(h[i]); print "</tr>"
         holding = 0; intable = 1; next }
     holding { print held; holding = 0 }
     !code && !intable && /^[ \t]*\|/ { held = $0; holding = 1; next }
     intable && /^[ \t]*\|/ { n = cells($0, c); printf "<tr>"
         for (i = 1; i <= n; i++) printf "<td>%s</td>", esc(c[i]); print "</tr>"; next }
     intable { print "</table>\n"; intable = 0 }
     { print }
     END { if (holding) print held; if (intable) print "</table>" }' "$md" > "$tmp/tables.md"
mv "$tmp/tables.md" "$md"

# Anchors and a table of contents for the level-2 and level-3 headings
# (outside code blocks); cmark itself adds no ids.
awk 'BEGIN { n = 0 }
     /^```/ { code = !code; print; next }
     !code && /^###? / { lvl = ($0 ~ /^### /) ? 3 : 2; t = $0; sub(/^###? /, "", t); n++
                        gsub(/&/, "\\&amp;", t); gsub(/</, "\\&lt;", t); gsub(/`/, "", t)
                        printf "\n<h%d id=\"s%d\">%s</h%d>\n\n", lvl, n, t, lvl
                        toc = toc sprintf("%s<li><a href=\"#s%d\">%s</a></li>\n", (lvl == 3 ? "<li style=\"list-style:none\"><ul>" : ""), n, t) (lvl == 3 ? "</ul></li>\n" : "")
                        next }
     { print }
     END { printf "%s", toc > TOCFILE }' TOCFILE="$tmp/toc.html" "$md" > "$tmp/anchored.md"
cmark --unsafe "$tmp/anchored.md" > "$tmp/body.html"
{
    cat <<'HEAD'
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>Hamilton-Jacobi numerics: reproduction report</title>
<style>
body { font-family: Georgia, serif; max-width: 60em; margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #222; }
h1, h2, h3, h4 { font-family: Helvetica, Arial, sans-serif; }
h2 { border-bottom: 1px solid #ccc; margin-top: 2em; }
pre, code { font-size: 0.9em; }
pre { background: #f6f6f6; padding: 0.6em; overflow-x: auto; }
table { border-collapse: collapse; margin: 0.8em 0; font-family: Helvetica, Arial, sans-serif; font-size: 0.85em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { background: #eee; }
tr.match td:nth-child(7) { background: #dff0d8; }
tr.close td:nth-child(7) { background: #fcf8e3; }
tr.differs td:nth-child(7) { background: #f2dede; }
tr.missing td:nth-child(7) { background: #f2dede; font-weight: bold; }
tr.ambiguous td:nth-child(7) { background: #e8e8f8; }
img { max-width: 100%; }
ol.reasons { font-size: 0.85em; margin-top: 0.2em; }
ol.reasons .cells { color: #666; }
</style></head><body>
HEAD
    # title (the first h1), then the contents, then the rest
    sed -n '0,/<\/h1>/p' "$tmp/body.html"
    printf '<nav><h2>Contents</h2>\n<ul>\n'
    cat "$tmp/toc.html"
    printf '</ul></nav>\n'
    sed '0,/<\/h1>/d' "$tmp/body.html"
    # Counts that `make report-view` reads back from the rendered page.
    cat <<'TAIL'
<script>
window.addEventListener('load', function () {
  var imgs = document.images, broken = 0, empty = 0, tables = document.querySelectorAll('table');
  for (var i = 0; i < imgs.length; i++) if (!imgs[i].complete || imgs[i].naturalWidth === 0) broken++;
  for (var j = 0; j < tables.length; j++) if (tables[j].querySelectorAll('td').length === 0) empty++;
  document.body.setAttribute('data-images', imgs.length);
  document.body.setAttribute('data-broken-images', broken);
  document.body.setAttribute('data-tables', tables.length);
  document.body.setAttribute('data-empty-tables', empty);
});
</script>
TAIL
    printf '</body></html>\n'
} > "$out/report.html.tmp"
mv "$out/report.html.tmp" "$out/report.html"
echo "report: $out/report.html"
