# convergence.gp -- errors against N, log-log, with the fitted order.
# Variables (gnuplot -e): table = path of the table without ".tsv",
#   out = output SVG, title = figure title.
# Reads <table>.tsv (columns case N h L1 L1_order Linf ...) and
# <table>.fit.gp (hN = h*N, case_keys/case_names, fit_<case>_<L1|Linf>_{p,se,C},
# written by the program from its Ceres fit: nothing is fitted here).
load table.'.fit.gp'
if (out[strlen(out)-2:] eq "png") { set terminal pngcairo size 900,520 font "Helvetica,12" } else { set terminal svg size 760,480 dynamic enhanced font "Helvetica,13" }
set output out
set datafile separator "\t"
set logscale xy
set format y "10^{%T}"
set xlabel "N (intervals per direction)"
set ylabel "error"
set key outside right top
set grid
set title title
data = table.'.tsv'
fitlabel(c, q) = (value(sprintf("fit_%s_%s_se", c, q)) >= 0) ? \
    sprintf("fit p = %.2f ± %.2f", value(sprintf("fit_%s_%s_p", c, q)), value(sprintf("fit_%s_%s_se", c, q))) : \
    sprintf("fit p = %.2f", value(sprintf("fit_%s_%s_p", c, q)))
fitline(x, c, q) = value(sprintf("fit_%s_%s_C", c, q)) * (hN / x) ** value(sprintf("fit_%s_%s_p", c, q))
sel(k, col) = (strcol(1) eq word(case_keys, k)) ? column(col) : NaN
casename(k) = (word(case_keys, k) eq "-") ? "" : sprintf(" (%s)", word(case_keys, k))
stats data using 2 nooutput
nmin = STATS_min
nmax = STATS_max
set xrange [nmin / 1.3 : nmax * 1.3]
stats data using 4 nooutput
e3 = STATS_min
plot for [k = 1:words(case_keys)] data using 2:(sel(k, 4)) with points pt 7 ps 1.2 lc k \
         title sprintf("L1%s: %s", casename(k), fitlabel(word(case_names, k), "L1")), \
     for [k = 1:words(case_keys)] fitline(x, word(case_names, k), "L1") with lines lc k dt 1 notitle, \
     for [k = 1:words(case_keys)] data using 2:(sel(k, 6)) with points pt 5 ps 1.0 lc k + 2 \
         title sprintf("L∞%s: %s", casename(k), fitlabel(word(case_names, k), "Linf")), \
     for [k = 1:words(case_keys)] fitline(x, word(case_names, k), "Linf") with lines lc k + 2 dt 2 notitle, \
     e3 * (nmax / x) ** 3 with lines lc rgb "#888888" dt 3 title "slope 3 (reference)"
