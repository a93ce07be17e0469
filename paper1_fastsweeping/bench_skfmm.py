#!/usr/bin/python3
"""bench_skfmm.py OUT.tsv N2 N3 -- the peer of bench_eik: scikit-fmm
(Debian's python3-scikit-fmm) on the same problems, on [-1, 1]^d with N
intervals per side (N2: comma-separated sizes in 2-D, N3 in 3-D, "" for
none), a point source at the origin:

  distance  speed 1: T = r (skfmm.distance);
  linear    speed v = 2 + g.x, g = (0.5, 1) in 2-D, (0.5, 0.5, 0.5) in
            3-D: T = arccosh(1 + |g|^2 r^2 / (2 v(0) v(x))) / |g|
            (skfmm.travel_time).

A point source in scikit-fmm is the zero contour of phi: phi = r - r0, a
circle of radius r0 = 1.5 h (the nodes within it negative), whose nodes
near the contour start from the exact distance; T = t + r0 / v(0).
Errors are against the exact T over every node.  CPU time (process_time)
of the skfmm call only, the least of 3 runs below a million nodes, else
one; one process, one thread.

Columns: problem, solver, dim, order, N, cpu_s, err_max, err_mean.
"""
import math
import os
import sys
import time

import numpy as np
import skfmm


def run(problem, dim, n, order):
    h = 2.0 / n
    axes = [np.linspace(-1, 1, n + 1)] * dim
    grids = np.meshgrid(*axes, indexing="ij")
    r = np.sqrt(sum(g * g for g in grids))
    r0 = 1.5 * h
    phi = r - r0
    if problem == "linear":
        gv = (0.5, 1.0) if dim == 2 else (0.5, 0.5, 0.5)
        gn = math.sqrt(sum(c * c for c in gv))
        v = 2.0 + sum(c * x for c, x in zip(gv, grids))
        exact = np.arccosh(1 + gn * gn * r * r / (2 * 2.0 * v)) / gn
        v0 = 2.0
    else:
        v, exact, v0 = None, r, 1.0
    best = None
    repeat = 3 if (n + 1) ** dim < 1e6 else 1
    for _ in range(repeat):
        t0 = time.process_time()
        if v is None:
            d = skfmm.distance(phi, dx=h, order=order)
        else:
            d = skfmm.travel_time(phi, v, dx=h, order=order)
        cpu = time.process_time() - t0
        best = cpu if best is None or cpu < best else best
    e = np.abs(np.asarray(d) + r0 / v0 - exact)
    return best, float(e.max()), float(e.mean())


def main():
    if len(sys.argv) != 4:
        sys.stderr.write("usage: bench_skfmm.py OUT.tsv N2 N3\n")
        return 2
    out, n2, n3 = sys.argv[1:]
    rows = []
    for problem in ("distance", "linear"):
        for dim, sizes in ((2, n2), (3, n3)):
            for n in [int(s) for s in sizes.split(",") if s]:
                for order in (1, 2):
                    cpu, emax, emean = run(problem, dim, n, order)
                    sys.stderr.write("bench_skfmm: %s %d-D N = %d order %d: %.3g s CPU, mean error %.3g\n"
                                     % (problem, dim, n, order, cpu, emean))
                    rows.append("%s\tscikit-fmm\t%d\t%d\t%d\t%.6g\t%.6g\t%.6g"
                                % (problem, dim, order, n, cpu, emax, emean))
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write("# scikit-fmm %s, a point source at the origin of [-1, 1]^d, circle r0 = 1.5 h\n" % skfmm.__version__)
        f.write("problem\tsolver\tdim\torder\tN\tcpu_s\terr_max\terr_mean\n")
        f.write("\n".join(rows) + "\n")
    os.replace(tmp, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
