# contour.gp -- contour lines of the computed solution, one panel per case.
# Variables (gnuplot -e): table = path of the table without ".tsv",
#   out = output SVG, title = figure title.
# Reads <table>.fit.gp for case_names and <table>.<case>.grid.tsv
# (x y phi exact error, gnuplot grid format).
load table.'.fit.gp'
n = words(case_names)
if (out[strlen(out)-2:] eq "png") { set terminal pngcairo size (n > 1 ? 1000 : 560),500 font "Helvetica,11" } else { set terminal svg size (n > 1 ? 1000 : 560),500 dynamic font "Helvetica,12" }
set output out
set datafile separator "\t"
set view map
set size ratio -1
unset surface
set contour base
set cntrparam levels auto 14
unset key
set xlabel "x"
set ylabel "y"
set multiplot layout 1, n title title
do for [k = 1:n] {
    c = word(case_names, k)
    set title (c eq "sol") ? "" : sprintf("case (%s)", c)
    splot table.'.'.c.'.grid.tsv' using 1:2:3 with lines lw 1.2
}
unset multiplot
