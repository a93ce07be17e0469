# Figure 22: four convergence panels from fig22.dat (one block per scheme:
# N, maximum, average, rms, jumps).  Called with
#   gnuplot -e "dat='.../fig22.dat'; out='.../tmp.svg'" fig22.gp
# Reference slopes 1, 2, 3, 5 start at N = 160 and end at N = 320, as the
# toolbox's addSlopes call does (anchored at 100 x the panel's smallest error).
set terminal svg size 1000,800 dynamic font "sans,10"
set output out
set logscale xy
set format y "10^{%L}"
set xlabel "grid size N"
set ylabel "error"
set grid
set key bottom left font ",8" opaque
set xrange [15:1700]
set xtics ("20" 20, "40" 40, "80" 80, "160" 160, "320" 320, "640" 640, "1280" 1280)
names = "upwindFirstFirst upwindFirstENO2 upwindFirstENO3a upwindFirstENO3b upwindFirstWENO5a upwindFirstWENO5b upwindFirstWENO3"
titles = "(a)_Maximum_error. (b)_Average_error. (c)_Average_error_at_derivative_discontinuities. (d)_Root_mean_square_error."
cols = "2 3 5 4"
set multiplot layout 2,2
do for [p=1:4] {
    c = int(word(cols, p))
    stats dat using c nooutput
    y0 = 100 * STATS_min
    set title system("echo '".word(titles, p)."' | tr _ ' '")
    unset label
    do for [s in "1 2 3 5"] {
        set label s at 330, y0 * 2.0**(-real(s)) font ",8"
    }
    plot for [k=0:6] dat index k using 1:c with linespoints title word(names, k+1), \
         for [s in "1 2 3 5"] [160:320] y0 * (x / 160.0)**(-real(s)) with lines lc "black" lw 1.5 notitle
}
unset multiplot
