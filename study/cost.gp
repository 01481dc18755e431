# The cost of a collision against the row length: ns per collision of the
# engine in real(16), scanning every gap or taking the next impact from the
# calendar (a heap), for elastic rows and inelastic rows (e = 0.5).
# Call: gnuplot -e "dir='results'; term='png'; out='results/cost.png'" study/cost.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/cost.tsv'
set title "Cost of a collision against the row length (real(16), one core)"
set xlabel "number of spheres p"
set ylabel "wall time per collision [ns]"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key top left box opaque
pick(row, search) = (strcol("row") eq row && strcol("search") eq search) ? column("ns_per_collision") : 1/0
plot f using (column("p")):(pick("elastic", "scan")) with linespoints pt 7 lw 2 lc rgb '#d62728' title 'elastic, scan of every gap', \
     f using (column("p")):(pick("elastic", "calendar")) with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'elastic, calendar', \
     f using (column("p")):(pick("inelastic", "scan")) with linespoints pt 5 lw 2 dt 2 lc rgb '#ff7f0e' title 'inelastic (e = 0.5), scan', \
     f using (column("p")):(pick("inelastic", "calendar")) with linespoints pt 5 lw 2 dt 2 lc rgb '#2ca02c' title 'inelastic (e = 0.5), calendar'
