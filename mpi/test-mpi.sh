#!/bin/bash
# test-mpi.sh PROG DIR [UNIT] -- the MPI runs against the single-process
# library.  UNIT (hj_mpi's cmocka tests: halo fill against the undivided
# grid for halo widths 1-3, exact sums against the library's norms and
# measures, MPI-IO files) runs first on 1, 2, 3, 4 processes.
#
# For air3D (NX = 26, t = 2.8: about 185 steps) and the 6-D double
# integrators (5^4 x 9^2 nodes, tau = 0.1: 3 steps), run the undivided library
# (--serial, two OpenMP threads) and then 1, 2, 3, 4 processes (one
# thread each; oversubscribed on a 2-core machine): every result file must
# equal the reference byte for byte, and so must the printed norms and set
# size and measure (exact sums).  air3D is also split along psi alone (periodic
# across processes) and along y alone; the 6-D case along the default two
# outermost axes; air3D at accuracy high under the toolbox's CFL rule and
# WENO5 epsilon on 3 and 4 processes; first order (halo 1 layer wide) and
# WENO5 (3 layers) runs.  Bad decompositions must fail with one message.
set -u
prog=$1 dir=$2 unit=${3:+$(realpath "$3")}
mkdir -p "$dir"
run="mpirun --oversubscribe --allow-run-as-root --mca btl self,vader,tcp --mca btl_tcp_if_include lo"
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }

if [ -n "$unit" ]; then
    for np in 1 2 3 4; do
        if (cd "$dir" && OMP_NUM_THREADS=1 $run -np $np "$unit") > "$dir/unit-np$np.log" 2>&1; then
            ok "hj_mpi unit tests on $np process(es): $(grep -c '\[       OK \]' "$dir/unit-np$np.log") passed"
        else
            bad "hj_mpi unit tests on $np process(es) (see $dir/unit-np$np.log)"
        fi
    done
fi
# The columns that must not depend on the decomposition: nodes, steps,
# max, avg, rms, negative, measure (exact sums: the single-process run
# computes them with the library functions, the others over MPI).
numbers() { cut -f4,5,11-15 "$1"; }

check_case() { # name args... ; then the runs as "np split"
    local name=$1; shift
    local args=$1; shift
    local ext=$1; shift
    local ref=$dir/$name-serial.$ext
    if ! OMP_NUM_THREADS=2 $run -np 1 $prog $args --serial --out "$ref" > "$dir/$name-serial.tsv"; then
        bad "$name: the single-process run failed"; return
    fi
    for spec in "$@"; do
        local np=${spec%% *} split=${spec#* } tag
        tag=$name-np$np${split:+-s${split//,/}}
        local opt=""
        [ -n "$split" ] && opt="--split $split"
        if ! OMP_NUM_THREADS=1 $run -np "$np" $prog $args $opt --out "$dir/$tag.$ext" > "$dir/$tag.tsv"; then
            bad "$tag: the run failed"; continue
        fi
        if cmp -s "$ref" "$dir/$tag.$ext" && [ "$(numbers "$dir/$name-serial.tsv")" = "$(numbers "$dir/$tag.tsv")" ]; then
            ok "$tag: $(cut -f3 "$dir/$tag.tsv") bitwise equal to the single-process library ($(cut -f5 "$dir/$tag.tsv") steps)"
        else
            bad "$tag: differs from the single-process library"
        fi
    done
}

check_case air3d "--case air3d --N 26" vtk "1 " "2 " "3 " "4 " "2 2" "3 2" "4 2" "2 1"
# The toolbox's CFL rule (per-dimension maxima) and grid-wide WENO5
# epsilon: two more global reductions.
check_case air3d-toolbox "--case air3d --N 26 --tmax 0.5 --accuracy high --toolbox-rules" vtk "3 " "4 2"
check_case di6 "--case di6 --N 5 --tmax 0.1" raw "1 " "2 " "3 " "4 "
# The halo is as wide as the stencil: 1 layer for first order (di6
# --first-order, air3D low), 2 for ENO2 (di6 and air3D above), 3 for ENO3
# (air3D high above) and WENO5 (air3D veryHigh).
check_case di6-first "--case di6 --N 5 --tmax 0.1 --first-order" raw "2 " "4 "
check_case air3d-first "--case air3d --N 26 --tmax 0.5 --accuracy low" vtk "3 " "4 2"
check_case air3d-weno5 "--case air3d --N 26 --tmax 0.3 --accuracy veryHigh" vtk "2 " "4 2"

# Refused decompositions: axis 0 holds the rows; blocks thinner than the
# ghost width (9 nodes over 4 processes along one axis).
for args in "--case air3d --split 0" "--case di6 --N 5 --tmax 0.1 --split 5"; do
    np=2; [ "${args##*split }" = 5 ] && np=4
    if $run -np $np $prog $args > /dev/null 2> "$dir/refused.err"; then
        bad "refused: '$args' on $np processes ran"
    elif [ "$(grep -c . "$dir/refused.err")" -ge 1 ] && grep -q "mpi_reach" "$dir/refused.err"; then
        ok "refused: '$args' on $np processes: $(grep -m1 mpi_reach "$dir/refused.err")"
    else
        bad "refused: '$args' on $np processes failed without a message"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
