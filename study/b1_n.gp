# C12 task b1: number of collisions n(e) over the scan of e.
# Call: gnuplot -e "dir='results'; term='png'; out='results/b1_n.png'" study/b1_n.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/b1_scan.tsv'
stats dir.'/b1_answers.tsv' using (strcol('key') eq 'b1.e_crit' ? column('value') : NaN) nooutput
ecrit = STATS_max
set title sprintf("C12 task b1: number of collisions n(e); inelastic collapse below e_{crit} = %.12f", ecrit)
set xlabel "restitution coefficient e"
set ylabel "collisions n"
set logscale y
set xrange [0:1]
set grid
set key top right box opaque
set arrow from ecrit, graph 0 to ecrit, graph 1 nohead dt 2 lc rgb '#d62728'
set label "e_{crit}" at ecrit, graph 0.95 offset 1,0 tc rgb '#d62728'
plot f using ((strcol('status') eq 'normal') ? column('e') : NaN):(column('collisions')) with steps lw 2 lc rgb '#1f77b4' title 'n(e), run ends (finite)', \
     f using ((strcol('status') eq 'quasi_plastic') ? column('e') : NaN):(column('collisions')) with points pt 7 ps 0.4 lc rgb '#ff7f0e' title 'quasi-plastic: collisions until the collapse limit (depends on tol)'
