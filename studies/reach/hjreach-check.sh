#!/bin/bash
# hjreach-check.sh [BIN] -- hjreach's outputs as a user's tools read them.
#
# 1. reach.vtk of a run whose set does not cover the grid: every value
#    after a LOOKUP_TABLE line is a finite number (VTK's text reader stops
#    at "inf"), the unreached nodes' time-to-reach -1.
# 2. An output name other than value.dat that cannot be written (a
#    directory named ttr.dat, reach.vtk): refused before the run, one line
#    on stderr, a non-zero status, and no value.dat written.
# The last line is "hjreach-check: N passed, M failed".
set -u
bin=$(cd "${1:-build/bin}" && pwd) || exit 2
h=$bin/studies/reach/hjreach
work=$(mktemp -d "${TMPDIR:-/tmp}/hjreach-check.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "hjreach-check: FAIL: $*"; }

mkdir "$work/vtk"
if OMP_NUM_THREADS=1 "$h" --quiet --N 15,15,12 --horizon 0.3 --out-dir "$work/vtk" >/dev/null 2>&1; then
    grep -q 'inf' "$work/vtk/ttr.dat" || bad "the run reached every node: no case"
    awk '/^LOOKUP_TABLE/ {data = 1; next} /^[A-Z]/ {data = 0} data && NF {
             for (i = 1; i <= NF; i++) if ($i !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/) { print "not a finite number: " $i; exit 1 } }' \
        "$work/vtk/reach.vtk" && ok || bad "reach.vtk holds a value VTK cannot read"
    grep -qx -- '-1' "$work/vtk/reach.vtk" && ok || bad "reach.vtk: no -1 for the unreached nodes"
else
    bad "the VTK run failed"
fi

for name in ttr.dat reach.vtk; do
    d=$work/in-the-way-$name
    mkdir -p "$d/$name"
    OMP_NUM_THREADS=1 "$h" --quiet --N 15,15,12 --horizon 0.3 --out-dir "$d" >"$work/out" 2>"$work/err"
    rc=$?
    if [ $rc -eq 0 ]; then bad "$name a directory: exit 0"
    elif [ "$(wc -l <"$work/err")" -ne 1 ]; then bad "$name a directory: $(wc -l <"$work/err") lines on stderr"
    elif [ -e "$d/value.dat" ]; then bad "$name a directory: value.dat written before the failure"
    else ok; fi
done

echo "hjreach-check: $pass passed, $fail failed"
[ $fail -eq 0 ]
