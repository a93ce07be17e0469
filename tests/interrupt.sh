#!/bin/bash
# interrupt.sh [BIN] -- a program interrupted while it writes leaves
# nothing half-done.
#
# triple_sine writes its figure data while it computes (a temporary
# named triple_sine_b0.dat.tmp.PID).  It is started, and once that
# temporary exists it gets SIGINT, SIGTERM or SIGHUP: it must die of the
# signal, leaving neither the final file nor a temporary.  Then it is
# killed with SIGKILL, which no program can catch: the temporary stays,
# and the next run writing the same file must remove it.  The last line
# is "interrupt: N passed, M failed".
set -u
set -m # background jobs in their own process groups, SIGINT not ignored
bin=$(cd "${1:-build/bin}" && pwd) || exit 2
prog=$bin/paper2_toolbox/triple_sine
# The program is started with the signals this test sends at their default
# (a shell started in the background or under nohup passes them on ignored,
# and a program leaves an ignored signal ignored).
work=$(mktemp -d "${TMPDIR:-/tmp}/hj-interrupt.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
shopt -s nullglob
d=$work/out
long=(--quick --b 0 --N 200 --out-dir "$d") # seconds: the temporary is open throughout
short=(--quick --b 0 --N 20 --out-dir "$d")

check() {
    if [ -z "$2" ]; then pass=$((pass + 1)); else fail=$((fail + 1)) && echo "FAIL $1: $2"; fi
}

# start: run the long case in the background ($pid) and wait until its
# temporary exists ($tmp); fails after 120 s.
start() {
    rm -rf "$d" && mkdir -p "$d"
    env --default-signal=INT,TERM,HUP "$prog" "${long[@]}" >/dev/null 2>"$work/err" </dev/null &
    pid=$!
    local k t
    for ((k = 0; k < 1200; k++)); do
        t=("$d"/triple_sine_b0.dat.tmp.*)
        if [ ${#t[@]} -gt 0 ]; then tmp=${t[0]} && return 0; fi
        kill -0 $pid 2>/dev/null || break
        sleep 0.1
    done
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null
    return 1
}

for sig in INT TERM HUP; do
    if ! start; then
        check "SIG$sig" "no temporary appeared: $(head -c 300 "$work/err")"
        continue
    fi
    kill -$sig $pid
    wait $pid 2>/dev/null
    rc=$?
    left=("$d"/*.tmp.* "$d"/triple_sine_b0.da[t])
    why=""
    [ $rc -eq $((128 + $(kill -l $sig))) ] || why="exit status $rc, not death by SIG$sig"
    [ ${#left[@]} -eq 0 ] || why="$why${why:+; }left ${left[*]##*/}"
    check "SIG$sig" "$why"
done

if start; then
    kill -KILL $pid
    wait $pid 2>/dev/null
    why=""
    [ -f "$tmp" ] || why="SIGKILL left no temporary to test with"
    "$prog" "${short[@]}" >/dev/null 2>"$work/err" </dev/null || why="$why${why:+; }the next run failed: $(head -c 300 "$work/err")"
    [ -e "$tmp" ] && why="$why${why:+; }the next run left the stale ${tmp##*/}"
    [ -f "$d/triple_sine_b0.dat" ] || why="$why${why:+; }the next run wrote no triple_sine_b0.dat"
    check "SIGKILL, then a new run" "$why"
else
    check "SIGKILL" "no temporary appeared: $(head -c 300 "$work/err")"
fi

echo "interrupt: $pass passed, $fail failed"
[ $fail -eq 0 ]
