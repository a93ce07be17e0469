# fig06.gp -- Figure 6 of the toolbox: laxFriedrichsDemo, rotation of a
# square as a general Hamiltonian.  (a) laxFriedrichsDemo('linear', 'cube',
# 'low'): zero level set at the nine output times; (b) the final zero level
# sets of the four accuracies over the initial square (global dissipation;
# local and local-local give the same bits here).  Variables: dir, out.
set terminal pngcairo size 1100,1500 font "Helvetica,10"
set output out
fa = dir.'/lax_friedrichs_low.dat'
fb = dir.'/lax_friedrichs_final.dat'
set view map
unset surface
set contour base
set cntrparam levels discrete 0
do for [k=0:8] {
    eval sprintf('set table $a%d', k)
    splot fa index k using 1:2:3 with lines
    unset table
}
do for [c=3:7] {
    eval sprintf('set table $b%d', c)
    splot fb using 1:2:c with lines
    unset table
}
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
unset key
set xlabel "x"; set ylabel "y"
set multiplot title "Figure 6: laxFriedrichsDemo, rigid rotation of a square (Lax-Friedrichs, global dissipation)"
do for [k=0:8] {
    set origin (k % 3) / 3.0, 0.74 - (k / 3) * 0.2
    set size 1/3.0, 0.2
    set title sprintf("(a) 'low', t = %g", k/8.0)
    eval sprintf('plot $a%d using 1:2 with lines lw 2 lc rgb "#1f5fa8"', k)
}
set origin 0.15, 0.0
set size 0.7, 0.34
set key outside right
set title "(b) t = 1 (one turn) for each accuracy, over the initial square"
plot $b3 using 1:2 with lines lw 3 lc rgb "black" title "initial", \
     $b4 using 1:2 with lines lw 2 lc rgb "#c0392b" title "low", \
     $b5 using 1:2 with lines lw 2 lc rgb "#e67e22" title "medium", \
     $b6 using 1:2 with lines lw 2 lc rgb "#27ae60" title "high", \
     $b7 using 1:2 with lines lw 2 dt 2 lc rgb "#1f5fa8" title "veryHigh"
unset multiplot
