#!/bin/bash
# cli-matrix.sh [BIN] -- bad command lines for every program, generated
# from each program's own option table.
#
# Every executable under BIN (default build/bin, tools included) that
# answers --list-options (hj_cli_list: name, type, min, max, choices,
# maxn) gets, for each option: a missing value, values
# below and above its range, nan, inf, an empty string, garbage (12abc)
# and the option given twice, as far as each applies to the option's
# type; per program an unknown option, a stray argument, values with
# control bytes (newline, escape; once per option type) and --help with
# stdout on /dev/full (exit status 1 there, not 2); and the
# conflicting pairs of the list below (there with the --out-dir made, so
# that the pair itself must be refused).  Each run happens in an empty directory (with
# --out-dir inside it where the program has one) and must end with exit
# status 2, exactly one line on stderr, and no file created.  Programs
# that do not answer --list-options (hand-written parsers) are listed as
# not covered.  The last line is "cli-matrix: N passed, M failed".
set -u
bin=${1:-build/bin}
jobs=${JOBS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/hj-cli-matrix.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT

# Conflicting options: program pattern, then the command line.  With the
# pattern '*' a case runs for every program that lists all its options;
# a named program runs it whether or not it answers --list-options.
conflicts=(
    '*|--quick --sizes 8'
    '*|--eps 1e-6 --eps-h2 1'
    'eikonal|--speed s.txt --slowness f.txt --source 0,0'
    'eikonal|--speed-const 1 --slowness-const 1 --source 0,0'
    'eikonal|--speed s.txt --speed-const 1 --source 0,0'
    'eikonal|--speed-const 1'
    'eikonal|--speed-const 1 --source 2,0.5'
    'eikonal|--speed-const 1 --source 0.5,0.5 --source 0.5,0.5,1'
    'eikonal|--speed-const 1 --source 0.5'
    'eikonal|--speed-const 1 --domain 0,1,0,1,0,1 --N 8 --source 0.5,0.5'
    'eikonal|--speed-const 1 --domain 0,1,0,1,0,1 --N 8 --source 0,0,0 --format matrix'
    'eikonal|--speed-const 1 --domain 1,0,0,1 --source 0,0'
    'eikonal|--speed-const 1 --raw 4,4 --source 0,0'
    'eikonal|--speed s.txt --raw 4 --source 0,0'
    'eikonal|--speed s.txt --N 10 --source 0,0'
    'eikonal|--speed-const 1 --source 0,0 --format vtk --out -'
    'eikonal|--speed-const 1 --raw-type float64 --source 0,0'
    'eikonal|--speed-const 1 --pgm-range 0,2 --source 0,0'
    'hjreach|--horizon 1e12'
    'hjreach|--min -2,-2,0 --max 2,2,1e-300'
    'hjreach|--min -1e300,-1e300,0 --max 1e300,1e300,6'
    'hjreach|--system double_integrator --N 11,11 --discount 1e4 --horizon 1 --max-steps 100'
    'hjreach|--system dubins --target-centre 10,0'
    'hjreach|--system double_integrator --target-centre 0.05 --target-radius 0.01'
    'hjreach|--obstacle -3,-3:3,3'
    'hjreach|--obstacle -1,-1:1,1'
    'hjreach|--system air3d --N 11 --target-radius 100'
    'hjreach|--quiet --progress'
)

shopt -s nullglob dotglob

# run PROGRAM CLASS ARGS...: one case, in the empty directory $pw/run (the
# current directory); appends "class<TAB>ok|FAIL<TAB>text" to $res.
run() {
    local prog=$1 class=$2
    shift 2
    timeout 30 "$prog" "$@" >"${stdout_to:-$pw/out}" 2>"$pw/err" </dev/null
    local rc=$?
    # an output directory made for the case (conflicts) must stay empty
    [ -n "${made_out:-}" ] && rmdir "$pw/run/out" 2>/dev/null
    local why="" all="" left=("$pw"/run/*) want=${want_status:-2}
    IFS= read -r -d '' all <"$pw/err"
    if [ $rc -eq 124 ]; then why="still running after 30 s (input accepted?)"
    elif [ $rc -ne "$want" ]; then why="exit status $rc, expected $want"
    elif [[ $all != *$'\n' || ${all%$'\n'} == *$'\n'* || ${all%$'\n'} == "" ]]; then
        why="stderr is not exactly one line: $(head -c 300 "$pw/err" | od -c | head -5 | tr '\n' ' ')"
    elif [ ${#left[@]} -ne 0 ]; then
        why="created ${left[*]#$pw/run/}"
        rm -rf "$pw/run" && mkdir "$pw/run" && cd "$pw/run" || exit 1
    fi
    local shown
    printf -v shown '%q ' "$@"
    if [ -z "$why" ]; then printf '%s\tok\t%s\n' "$class" "$shown" >>"$res"
    else printf '%s\tFAIL\t%s %s: %s\n' "$class" "${prog##*/}" "$shown" "$why" >>"$res"; fi
}

# Below and above [min, max] for the parser's type, or "" when there is no
# representable value beyond the bound.
beyond() {
    awk -v t="$1" -v lo="$2" -v hi="$3" 'BEGIN {
        if (t == "double") {
            b = lo > 0 ? lo / 2 : lo == 0 ? -1e-9 : lo * 2
            a = hi > 0 ? hi * 2 : hi == 0 ? 1e-9 : hi / 2
            printf "%s %s\n", (b - b == 0 ? sprintf("%.17g", b) : "-"), (a - a == 0 ? sprintf("%.17g", a) : "-")
        } else printf "%.0f %.0f\n", lo - 1, hi + 1 }'
}

# matrix PROGRAM: every case of one program into $res (a file per program).
matrix() {
    local prog=$1 name=${1##*/}
    pw=$work/$name.d res=$work/$name.res
    mkdir -p "$pw/run" && cd "$pw/run" && : >"$res" || exit 1
    timeout 30 "$prog" --list-options >"$pw/list" 2>/dev/null </dev/null
    local rc=$? covered=1
    rm -rf "$pw/run" && mkdir "$pw/run" && cd "$pw/run" || exit 1
    if [ $rc -ne 0 ] || [ "$(head -n 1 "$pw/list")" != $'name\ttype\tmin\tmax\tchoices\tmaxn' ]; then
        covered=0
        printf 'not-covered\t-\t%s\n' "$name" >>"$res"
    fi
    local out=() opts=" "
    if [ $covered = 1 ]; then
        grep -q $'^--out-dir\tstring\t' "$pw/list" && out=(--out-dir "$pw/run/out")
        run "$prog" unknown "${out[@]}" --no-such-option 1
        run "$prog" unknown "${out[@]}" stray
        run "$prog" control $'--no\nsuch\e[0m'
        # --help into a full disk: a write error, not a silent 0
        [ -w /dev/full ] && stdout_to=/dev/full want_status=1 run "$prog" help-full --help
        local o t lo hi ch maxn v below above k args ctl=" "
        while IFS=$'\t' read -r o t lo hi ch maxn; do
            opts+="$o "
            local rest=("${out[@]}")
            [ "$o" = --out-dir ] && rest=()
            case $t in
            flag)
                run "$prog" garbage "${rest[@]}" "$o" 12abc
                run "$prog" repeated "${rest[@]}" "$o" "$o" ;;
            string)
                run "$prog" missing "${rest[@]}" "$o"
                run "$prog" empty "${rest[@]}" "$o" ""
                v=x
                [ "$o" = --out-dir ] && v=$pw/run/out
                run "$prog" repeated "${rest[@]}" "$o" "$v" "$o" "$v" ;;
            string-list)
                run "$prog" missing "${rest[@]}" "$o"
                run "$prog" empty "${rest[@]}" "$o" ""
                args=()
                for ((k = 0; k <= maxn; k++)); do args+=("$o" x); done
                run "$prog" list-shape "${rest[@]}" "${args[@]}" ;;
            long | double | long-list | choice)
                run "$prog" missing "${rest[@]}" "$o"
                for v in nan inf ""; do
                    run "$prog" "${v:-empty}" "${rest[@]}" "$o" "$v"
                done
                run "$prog" garbage "${rest[@]}" "$o" 12abc
                # control bytes: once per type (the message path is the type's)
                [[ $ctl == *" $t "* ]] || run "$prog" control "${rest[@]}" "$o" $'1\n2\e[0m'
                ctl+="$t "
                if [ "$t" = choice ]; then
                    v=${ch%%,*}
                else
                    read -r below above < <(beyond "${t%-list}" "$lo" "$hi")
                    [ "$below" != - ] && run "$prog" below-min "${rest[@]}" "$o" "$below"
                    [ "$above" != - ] && run "$prog" above-max "${rest[@]}" "$o" "$above"
                    v=$lo
                    [ "$t" = double ] && v=$(awk -v x="$lo" 'BEGIN { printf "%.17g", x }')
                fi
                if [ "$t" = long-list ]; then
                    run "$prog" list-shape "${rest[@]}" "$o" "$lo,,$lo"
                    run "$prog" list-shape "${rest[@]}" "$o" "$(yes "$lo" | head -n $((maxn + 1)) | paste -sd,)"
                fi
                run "$prog" repeated "${rest[@]}" "$o" "$v" "$o" "$v" ;;
            *)
                run "$prog" missing "${rest[@]}" "$o" ;;
            esac
        done < <(tail -n +2 "$pw/list")
    fi
    local c pat args all w
    for c in "${conflicts[@]}"; do
        pat=${c%%|*} args=${c#*|}
        [[ $name == $pat ]] || continue
        if [ "$pat" = '*' ]; then
            [ $covered = 1 ] || continue
            all=1
            for w in $args; do [[ $w == --* && $opts != *" $w "* ]] && all=0; done
            [ $all = 1 ] || continue
        fi
        # the output directory exists: a refused combination, not a
        # missing directory, must end the run
        [ ${#out[@]} -gt 0 ] && mkdir -p "$pw/run/out"
        # shellcheck disable=SC2086
        made_out=${out[*]:+1} run "$prog" conflict "${out[@]}" $args
    done
}

progs=()
for p in "$bin"/*/* "$bin"/*/*/*; do
    [ -f "$p" ] && [ -x "$p" ] && progs+=("$(cd "$(dirname "$p")" && pwd)/${p##*/}")
done
[ ${#progs[@]} -gt 0 ] || { echo "cli-matrix: no programs under $bin" >&2; exit 2; }

running=0
for p in "${progs[@]}"; do
    matrix "$p" &
    running=$((running + 1))
    if [ $running -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait

cat "$work"/*.res >"$work/all"
awk -F'\t' '
    $1 == "not-covered" { nc = nc " " $3; next }
    { n[$1]++; if ($2 == "FAIL") { f[$1]++; print "FAIL " $3; bad++ } else good++ }
    END {
        for (c in n) printf "  %-12s %4d case%s, %d failed\n", c, n[c], n[c] == 1 ? "" : "s", f[c] | "sort"
        close("sort")
        if (nc != "") print "not covered (no --list-options):" nc
        printf "cli-matrix: %d passed, %d failed\n", good, bad
        exit bad > 0
    }' "$work/all"
