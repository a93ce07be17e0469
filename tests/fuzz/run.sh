#!/bin/bash
# run.sh SECONDS TARGET... -- run each libFuzzer target (build/fuzz/fuzz_T)
# for SECONDS, from the seeds in tests/fuzz/corpus/T; new inputs collect
# in build/fuzz/corpus/T (never in the repository).  A crash, leak,
# sanitizer report, timeout or oversized allocation leaves the input in
# build/fuzz/artifacts/ and fails.  Prints the executions per target.
set -u
secs=$1
shift
mkdir -p build/fuzz/artifacts
fail=0
for t in "$@"; do
    mkdir -p "build/fuzz/corpus/$t"
    log=build/fuzz/$t.log
    build/fuzz/fuzz_$t -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=256 -max_len=8192 \
        -print_final_stats=1 -artifact_prefix="build/fuzz/artifacts/$t-" \
        "build/fuzz/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1
    rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    if [ $rc -ne 0 ]; then
        fail=$((fail + 1))
        echo "fuzz $t: FAILED (exit $rc) after ${runs:-?} executions; see $log:"
        grep -m 5 -E 'ERROR|SUMMARY|runtime error|Test unit written' "$log"
    else
        echo "fuzz $t: ${runs:-?} executions in ${secs} s, no failure"
    fi
done
echo "fuzz: $(($# - fail)) passed, $fail failed"
[ $fail -eq 0 ]
