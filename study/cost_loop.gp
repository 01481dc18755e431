# The price of the engine's bookkeeping: ns per collision against the row
# length p, sphere-row's engine in real(16), in real(8) (its own epsilon as
# tol) and precision=auto, against the study's tight event loop (the same
# variables, rule and stop, a heap and nothing else) with its clock in one
# real and in two as the engine's; elastic rows as lines, the inelastic rows
# that end normally, the collapse-heavy row (e = 0.2, 10^6 collisions) and
# the collapse region late (p = 100, e = 0.9, run to its answer) as points.
# From cost_vs_loop.tsv (c12-cost), whose first 12 rows are the elastic
# rows, each p in the order qp, dp, auto (so `every 3` picks a line).
# Call: gnuplot -e "dir='results'; term='png'; out='results/cost_loop.png'" study/cost_loop.gp
if (term eq 'png') { set terminal pngcairo size 1150,650 font ',11' } else { set terminal svg size 1150,650 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/cost_vs_loop.tsv'
# how many paired rounds each median took, from the table's rounds column
stats f using (column("rounds")) nooutput
rounds = (STATS_min == STATS_max) ? sprintf('%d', STATS_min) : sprintf('%d to %d', STATS_min, STATS_max)
set title sprintf("Engine against the tight loop (one core, medians of %s paired rounds)", rounds)
set xlabel "number of spheres p"
set ylabel "wall time per collision [ns]"
set logscale xy
set format x "10^{%L}"
set grid
set key outside right box opaque
set xrange [70:2e6]
pick(row, prec, col) = (strcol("row") eq row && strcol("precision") eq prec) ? column(col) : 1/0
plot f every 3::0::11 using (column("p")):(pick("elastic", "qp", "engine_ns_per_collision")) with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'elastic: engine, real(16)', \
     f every 3::0::11 using (column("p")):(pick("elastic", "qp", "loop_ns_per_collision")) with linespoints pt 6 lw 1 dt 2 lc rgb '#1f77b4' title 'elastic: loop, real(16), one-real clock', \
     f every 3::0::11 using (column("p")):(pick("elastic", "qp", "loop2_ns_per_collision")) with linespoints pt 4 lw 1 dt 3 lc rgb '#1f77b4' title 'elastic: loop, real(16), two-real clock', \
     f every 3::2::11 using (column("p")):(pick("elastic", "auto", "engine_ns_per_collision")) with linespoints pt 9 lw 2 lc rgb '#9467bd' title 'elastic: engine, precision=auto', \
     f every 3::1::11 using (column("p")):(pick("elastic", "dp", "engine_ns_per_collision")) with linespoints pt 7 lw 2 lc rgb '#d62728' title 'elastic: engine, real(8)', \
     f every 3::1::11 using (column("p")):(pick("elastic", "dp", "loop_ns_per_collision")) with linespoints pt 6 lw 1 dt 2 lc rgb '#d62728' title 'elastic: loop, real(8), one-real clock', \
     f every 3::1::11 using (column("p")):(pick("elastic", "dp", "loop2_ns_per_collision")) with linespoints pt 4 lw 1 dt 3 lc rgb '#d62728' title 'elastic: loop, real(8), two-real clock', \
     f using (column("p")):(pick("inelastic", "qp", "engine_ns_per_collision")) with points pt 5 ps 1.5 lc rgb '#1f77b4' title 'inelastic (ends normally): engine, real(16)', \
     f using (column("p")):(pick("inelastic", "qp", "loop_ns_per_collision")) with points pt 4 ps 1.5 lc rgb '#1f77b4' title 'inelastic: loop, real(16)', \
     f using (column("p")):(pick("inelastic", "dp", "engine_ns_per_collision")) with points pt 5 ps 1.5 lc rgb '#d62728' title 'inelastic: engine, real(8)', \
     f using (column("p")):(pick("inelastic", "dp", "loop_ns_per_collision")) with points pt 4 ps 1.5 lc rgb '#d62728' title 'inelastic: loop, real(8)', \
     f using (column("p")):(pick("collapse", "qp", "engine_ns_per_collision")) with points pt 13 ps 2 lc rgb '#1f77b4' title 'e = 0.2, 10^6 collisions: engine, real(16)', \
     f using (column("p")):(pick("collapse", "dp", "engine_ns_per_collision")) with points pt 13 ps 2 lc rgb '#d62728' title 'e = 0.2: engine, real(8)', \
     f using (column("p")):(pick("collapse", "qp", "loop_ns_per_collision")) with points pt 12 ps 2 lc rgb '#1f77b4' title 'e = 0.2: loop, real(16)', \
     f using (column("p")):(pick("collapse_late", "qp", "engine_ns_per_collision")) with points pt 11 ps 2 lc rgb '#1f77b4' title 'e = 0.9 to its answer: engine, real(16)', \
     f using (column("p")):(pick("collapse_late", "dp", "engine_ns_per_collision")) with points pt 11 ps 2 lc rgb '#d62728' title 'e = 0.9: engine, real(8)', \
     f using (column("p")):(pick("collapse_late", "qp", "loop_ns_per_collision")) with points pt 10 ps 2 lc rgb '#1f77b4' title 'e = 0.9: loop, real(16)', \
     f using (column("p")):(pick("collapse_late", "dp", "loop_ns_per_collision")) with points pt 10 ps 2 lc rgb '#d62728' title 'e = 0.9: loop, real(8)'
