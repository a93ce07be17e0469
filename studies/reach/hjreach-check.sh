#!/bin/bash
# hjreach-check.sh [BIN] -- hjreach's outputs as a user's tools read them.
#
# 1. reach.vtk of a run whose set does not cover the grid: every value
#    after a LOOKUP_TABLE line is a finite number (VTK's text reader stops
#    at "inf"), the unreached nodes' time-to-reach -1.
# 2. An output name other than value.dat that cannot be written (a
#    directory named ttr.dat, reach.vtk): refused before the run, one line
#    on stderr, a non-zero status, and no value.dat written.
# 3. --boundary: a Dubins car (disc target of radius 0.3, so phi >= -0.3
#    in exact arithmetic; a box obstacle) over a horizon of 6 on 41^2 x 40:
#    with the default (away) the value at a face the dynamics leave sinks
#    below -0.45, with --boundary toward no value is below -0.3.
# 4. Boxes outside the range hjreach takes (coordinates beyond +-1e100, a
#    spacing below 1e-100), empty boxes and other command lines whose
#    messages name a dimension: refused before the run (exit 2, one line
#    on stderr naming the option and the dimension counted from 1, as
#    --N lists them, no file written).  A box of +-1e300 ran and failed
#    with a non-finite Hamiltonian (exit 1); an empty box or period was
#    reported with the library's dimension, counted from 0.
# 5. A horizon on a small time scale (1e-30) takes its step: the summary
#    says 1 step and tau = 1e-30 (it took none and said tau = 0).
# 6. A periodic dimension (an angle of dubins or air3d) whose period is
#    not 2 pi or a multiple of it within a relative 1e-5: refused (exit 2);
#    6.2832 and 4 pi run.  Before, [0, pi) ran and gave a wrong set.
# 7. A 4-D grid whose arrays fit one by one but whose solve does not (one
#    array about 0.6 of the machine's memory): refused at once, exit 2.
#    Before, every node was visited (the target and obstacle checks, the
#    CFL estimate) before the solver refused it: 183 s at 200^4, exit 1.
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

minphi() { awk '!/^#/ && NF >= 4 { if (m == "" || $4 < m) m = $4 } END { print m }' "$1"; }
for b in away toward; do
    mkdir -p "$work/bc-$b"
    OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive "$h" --quiet --system dubins --N 41,41,40 --min -2,-2,0 \
        --max 2,2,6.283185307179586 --horizon 6 --target-radius 0.3 --obstacle 0.5,-0.5:0.8,0.5 --speed 0.8 \
        --u-max 1.5 --boundary $b --out-dir "$work/bc-$b" >/dev/null 2>"$work/err" || bad "--boundary $b: $(cat "$work/err")"
done
m_away=$(minphi "$work/bc-away/value.dat") m_toward=$(minphi "$work/bc-toward/value.dat")
awk -v a="$m_away" 'BEGIN { exit !(a < -0.45) }' && ok || bad "--boundary away: min phi $m_away, not below -0.45"
awk -v t="$m_toward" 'BEGIN { exit !(t >= -0.3 - 1e-9) }' && ok || bad "--boundary toward: min phi $m_toward below -0.3"

mkdir -p "$work/tiny"
OMP_NUM_THREADS=1 "$h" --quiet --N 15,15,12 --horizon 1e-30 --out-dir "$work/tiny" >"$work/out" 2>"$work/err"
grep -q '1 step, tau = 1e-30,' "$work/out" && ok || bad "--horizon 1e-30: $(cat "$work/out" "$work/err")"

# refused 'TEXT1|TEXT2|..' ARGS...: exit 2, one line on stderr holding every
# TEXT, nothing written into the (empty) --out-dir.
nref=0
refused() {
    local want=$1 d=$work/refused-$nref t
    shift
    nref=$((nref + 1))
    mkdir -p "$d"
    OMP_NUM_THREADS=1 timeout 120 "$h" --quiet "$@" --out-dir "$d" >/dev/null 2>"$work/err"
    local rc=$? why=""
    if [ $rc -ne 2 ]; then why="exit $rc, expected 2"
    elif [ "$(wc -l <"$work/err")" -ne 1 ]; then why="$(wc -l <"$work/err") lines on stderr"
    elif [ -n "$(ls -A "$d")" ]; then why="wrote $(ls -A "$d" | tr '\n' ' ')"
    else
        IFS='|' read -ra t <<<"$want"
        for w in "${t[@]}"; do grep -qF -- "$w" "$work/err" || why="no '$w' in the message"; done
    fi
    [ -z "$why" ] && ok || bad "$* : $why: $(head -c 300 "$work/err")"
}
refused '--min|dimension 1|1e+100' --min -1e300,-1e300,0 --max 1e300,1e300,6
refused '--min|dimension 1' --system double_integrator --min -1e200,-1e200 --max 1e200,1e200
refused '--min|dimension 2' --system air3d --min -6,-1e101,0 --max 20,10,6
refused '--max|dimension 2' --system planar_di --max 1.6,1e150,1.2,1.2
refused '--max|--min|dimension 1' --min 2,-2,0 --max 1,2,6
refused '--max|--min|dimension 3|period' --min -2,-2,1 --max 2,2,1
refused '--N|spacing|dimension 3|1e-100' --min -2,-2,0 --max 2,2,1e-300
refused '--N|spacing|dimension 1' --system double_integrator --min 0,-2 --max 1e-300,2
refused 'limited by dimension 2|coarsen dimension 2' --system double_integrator --N 11,4001 --u-max 1e6
refused 'spacing 0.1 in dimension 1, 0.2 in dimension 2' --N 41,21,40 --target-centre 0.05,0.05 --target-radius 0.01

# A periodic dimension (the catalogue's angles) on a period other than 2 pi
# or a multiple: refused (a Dubins car on [0, pi) ran, measure 8.49 where
# [-pi, pi) gives 16.27); 6.2832 and 4 pi pass.
refused 'dimension 3|period|2 pi' --system dubins --N 41,41,40 --min -2,-2,0 --max 2,2,3.14159
refused 'dimension 3|period|2 pi' --system air3d --max 20,10,6.28
for hi in 6.2832 12.566370614359172; do
    mkdir -p "$work/period-$hi"
    OMP_NUM_THREADS=1 "$h" --quiet --system dubins --N 15,15,12 --max 2,2,$hi --horizon 0.1 \
        --out-dir "$work/period-$hi" >/dev/null 2>"$work/err" && ok || bad "period $hi refused: $(cat "$work/err")"
done
# A grid whose arrays fit one by one but whose solve does not: refused at
# once (exit 2, within refused's timeout), not after the checks that visit
# every node (minutes at 200^4).  One array on the grid about 0.6 of the
# machine's memory, so the caller's value and time-to-reach alone exceed it.
mem_kb=$(awk '/^MemTotal:/ {print $2}' /proc/meminfo 2>/dev/null)
if [ -n "$mem_kb" ]; then
    n4=$(awk -v m="$mem_kb" 'BEGIN { printf "%d", exp(log(0.6 * m * 1024 / 8) / 4) - 6 }')
    refused 'GB|coarsen --N' --system planar_di --N $n4,$n4,$n4,$n4 --horizon 1
fi

echo "hjreach-check: $pass passed, $fail failed"
[ $fail -eq 0 ]
