#!/bin/bash
# bench-mpi.sh PROG DIR -- the MPI kernel's cost here and a scaling model.
#
# Measured (DIR/mpi_weak.tsv): the 6-D double integrators, first order
# (upwind differences, forward Euler), 5^4 x 9 x (9 P) nodes on P = 1, 2, 4
# processes split along axis 5 (weak scaling: 9 x 5^4 x 9 nodes per
# process), one OpenMP thread per process.  Per-step wall time (the
# slowest process), the communication fraction (halo exchange plus
# reductions, including the wait for the slowest process, over the wall
# time, averaged over processes), halo bytes sent per process per step,
# and the weak-scaling efficiency step_ms(1) / step_ms(P).  This machine
# has 2 cores: P = 4 is oversubscribed, and other jobs may load it, so the
# figures at P = 4 (and at P = 2 under load) measure time sharing as much
# as communication; they are labelled.
#
# Model (DIR/mpi_model.tsv): a 100^6 problem on 64 and 1,024 nodes (one
# process per node), splitting 1, 2 or 3 axes, for each stencil: first
# order (halo 1 layer wide, forward Euler: 1 exchange per step), ENO2
# (2 layers, RK2: 2 exchanges), ENO3 or WENO5 (3 layers, RK3: 3
# exchanges) -- the halo each ghost fill exchanges is as wide as the
# scheme reads (hj_ls_scheme_ghost), while every array keeps HJ_LS_GHOST
# (3) ghost layers and every block at least 3 nodes per split axis.  Per
# process and step: halo bytes = stages x sum over split axes of 2 faces
# x width x the face's ghosted extent x 8 B; time = messages x latency +
# bytes / bandwidth + reductions x 2 log2(P) x latency, against the
# compute time stages x nodes x (the measured first order cost per node
# and step at P = 1; higher orders cost more per node, so their
# communication fractions are upper bounds).  Assumptions (stated in the
# table): bandwidth 12.5 GB/s per node (100 Gb/s), latency 2 us per
# message, 5 reductions per step (CFL bound, the two Lax-Friedrichs
# ranges, blow-up test, convergence test) and one exact sum (norms,
# measures: one reduction of 70 integers, not per step), no overlap of
# communication and computation.  The measured cost is that of hj_reach's
# generic control-affine Hamiltonian on a small grid whose ghost layers
# outweigh its interior; comm_frac_at_10ns repeats the fraction for an
# assumed 10 ns per node and stage (a vectorised first order kernel).
set -eu
prog=$1 dir=$2
mkdir -p "$dir"
run="mpirun --oversubscribe --allow-run-as-root --mca btl self,vader,tcp --mca btl_tcp_if_include lo"
tmp=$dir/.mpi_weak.tsv.tmp.$$
trap 'rm -f "$tmp" "$dir/.mpi_model.tsv.tmp.$$"' EXIT
ncores=$(nproc)
{
    printf 'ranks\tnodes\tsteps\tstep_ms\tcomm_frac\thalo_frac\thalo_bytes_per_rank_step\tweak_efficiency\tnote\n'
    base=""
    for p in 1 2 4; do
        line=$(OMP_NUM_THREADS=1 $run -np $p "$prog" --case di6 --first-order --N 5 --Nsplit 9 --N5 $((9 * p)) \
               --tmax 0.1 --split 5)
        IFS=$'\t' read -r _ ranks _ nodes steps _ step_ms comm halo bytes _ <<< "$line"
        [ -z "$base" ] && base=$step_ms
        note="measured, load average $(cut -d' ' -f1 /proc/loadavg) on $ncores cores"
        [ "$p" -gt "$ncores" ] && note="oversubscribed: $p processes on $ncores cores, load average $(cut -d' ' -f1 /proc/loadavg)"
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.3f\t%s\n' "$ranks" "$nodes" "$steps" "$step_ms" "$comm" "$halo" "$bytes" \
               "$(echo "$base / $step_ms" | bc -l)" "$note"
    done
} > "$tmp"
mv "$tmp" "$dir/mpi_weak.tsv"
column -t -s $'\t' "$dir/mpi_weak.tsv"

# Cost per node and step at P = 1 (ns), for the model's compute time.
ns=$(awk -F'\t' 'NR == 2 { printf "%.1f", $4 * 1e6 / $2 }' "$dir/mpi_weak.tsv")
awk -v ns="$ns" -v bw=12.5e9 -v lat=2e-6 -v nred=5 'BEGIN {
    OFS = "\t"
    G = 3 # HJ_LS_GHOST: the allocated ghost layers and the thinnest block
    print "nodes", "split_axes", "process_grid", "block", "scheme", "halo_width", "stages", "feasible",
          "halo_MB_per_rank_step", "messages_per_step", "array_GB_per_rank", "ghost_overhead", "compute_s_per_step",
          "comm_s_per_step", "comm_frac", "comm_frac_at_10ns", "assumptions"
    split64[1] = "64"; split64[2] = "8x8"; split64[3] = "4x4x4"
    split1k[1] = "1024"; split1k[2] = "32x32"; split1k[3] = "16x8x8"
    name[1] = "first order"; name[2] = "ENO2"; name[3] = "ENO3/WENO5"
    for (q = 0; q < 2; q++) {
        P = q ? 1024 : 64
        for (k = 1; k <= 3; k++) {
            pg = q ? split1k[k] : split64[k]
            np = split(pg, pp, "x")
            # Six axes of 100 nodes; the last k are split (largest blocks).
            feas = "yes"; blk = ""
            for (d = 1; d <= 6; d++) n[d] = 100
            for (j = 1; j <= np; j++) {
                d = 7 - j
                n[d] = int((100 + pp[j] - 1) / pp[j])
                if (int(100 / pp[j]) < G) feas = "no"
            }
            inner = 1; ext = 1
            for (d = 1; d <= 6; d++) { inner *= n[d]; ext *= n[d] + 2 * G; blk = blk (d > 1 ? "x" : "") n[d] }
            for (w = 1; w <= 3; w++) {
                st = w # stages per step: Euler, RK2, RK3
                bytes = 0; msgs = 0
                for (j = 1; j <= np; j++) {
                    d = 7 - j
                    bytes += st * 2 * w * (ext / (n[d] + 2 * G)) * 8
                    msgs += st * 2
                }
                comp = st * inner * ns * 1e-9
                comm = msgs * lat + bytes / bw + nred * 2 * log(P) / log(2) * lat
                print P, k, pg, blk, name[w], w, st, feas, sprintf("%.1f", bytes / 1e6), msgs,
                      sprintf("%.1f", ext * 8 / 1e9), sprintf("%.3f", ext / inner), sprintf("%.3g", comp),
                      sprintf("%.3g", comm), sprintf("%.4f", comm / (comm + comp)),
                      sprintf("%.4f", comm / (comm + st * inner * 1e-8)),
                      sprintf("bw 12.5 GB/s, latency 2 us, %d reductions/step, %s ns/node-stage measured here (first order)", nred, ns)
            }
        }
    }
}' > "$dir/.mpi_model.tsv.tmp.$$"
mv "$dir/.mpi_model.tsv.tmp.$$" "$dir/mpi_model.tsv"
echo
cut -f1-16 "$dir/mpi_model.tsv" | column -t -s $'\t'
