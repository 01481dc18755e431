# C12 task b1: growth of n as e approaches the critical restitution from above.
# Call: gnuplot -e "dir='results'; term='png'; out='results/b1_critical.png'" study/b1_critical.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/b1_critical.tsv'
a = dir.'/b1_answers.tsv'
# the fit of the answers: the values of keys b1.exponent and b1.prefactor
stats a using (strcol('key') eq 'b1.exponent' ? column('value') : NaN) nooutput
k = STATS_max
stats a using (strcol('key') eq 'b1.prefactor' ? column('value') : NaN) nooutput
c = STATS_max
set title sprintf("C12 task b1: n against the distance to e_{crit}; fitted n = %.3f (e - e_{crit})^{%.4f}", c, k)
set xlabel "e - e_{crit}"
set ylabel "collisions n"
set logscale xy
set format x "10^{%L}"
set grid
set key top right box opaque
plot f using (column('delta=e-e_crit')):(column('collisions')) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'n, event-driven real(16), tol = 1e-4000', \
     c*x**k with lines lw 2 lc rgb '#d62728' title 'least-squares fit (n >= 200)', \
     2.33*x**(-0.5) with lines dt 2 lc rgb '#7f7f7f' title 'slope -1/2'
