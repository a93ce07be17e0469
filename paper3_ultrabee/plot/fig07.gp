# fig07.gp -- Figure 7 of Bokanowski, Cristiani & Zidani (2010): Example 3,
# the half plane x2 <= 0 deformed by f = -s(t) max(1 - |x|, 0) (-2 pi x2,
# 2 pi x1) (s = +1 before T / 2 = 3, -1 after), CFL 0.9, N = 100 on
# [-1, 1]^2: the fronts at t = 3 (three turns) and t = 6 (back to the
# initial data).  Top row UB-HJB (0 contour of V), bottom row the level
# set RK2-ENO2 method (0 contour), each with the exact front (0 contour of
# g = sin(th) x1 + cos(th) x2 on a 201^2 grid, th = 2 pi max(1 - |x|, 0)
# min(t, T - t)).  Also drawn by fig08.gp (N = 50).
# Data: fig07_deformation.dat (index 0, 1: x y V_ub V_ls at t = 3, 6;
# index 2, 3: x y g at t = 3, 6), written by examples2d.
# Variables (gnuplot -e): dir, out; fig08.gp sets dat, N and fignum first.
if (!exists("dat")) dat = 'fig07_deformation.dat'
if (!exists("N")) N = 100
if (!exists("fignum")) fignum = 7
set terminal pngcairo size 1000,1060 font "Helvetica,11"
set output out
f = dir.'/'.dat
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set cntrparam linear
do for [k=0:1] {
    eval sprintf('set table $ub%d', k)
    splot f index k using 1:2:3 with lines
    unset table
    eval sprintf('set table $ls%d', k)
    splot f index k using 1:2:4 with lines
    unset table
    eval sprintf('set table $ex%d', k)
    splot f index k + 2 using 1:2:3 with lines
    unset table
}
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
set key outside bottom center horizontal
set xlabel "x_1"; set ylabel "x_2"
set multiplot layout 2,2 title sprintf("Figure %d (Example 3): deformation of the half plane x_2 <= 0, N = %d, CFL 0.9 for UB-HJB (0.5 for the level set, see the overview), T = 6", fignum, N)
do for [m=0:1] {
    do for [k=0:1] {
        set title sprintf("%s, t = %d%s", m ? "level set RK2-ENO2" : "UB-HJB", 3 * (k + 1), k ? " (return to initial data)" : " (three turns)")
        if (m) { eval sprintf('plot $ex%d using 1:2 with lines lw 1.2 lc rgb "black" title "exact front", $ls%d using 1:2 with lines lw 2 lc rgb "#d62728" title "level set front (phi = 0)"', k, k) }
        else { eval sprintf('plot $ex%d using 1:2 with lines lw 1.2 lc rgb "black" title "exact front", $ub%d using 1:2 with lines lw 2 lc rgb "#1f5fa8" title "UB-HJB front (V = 0)"', k, k) }
    }
}
unset multiplot
