# C12 study e_crit(p): critical restitution of the struck row of p equal spheres.
# Call: gnuplot -e "dir='results'; term='png'; out='results/ecrit.png'" study/ecrit.gp
if (term eq 'png') { set terminal pngcairo size 1200,560 font ',11' } else { set terminal svg size 1200,560 dynamic font ',11' }
set output out
set datafile separator tab
set datafile missing '-'
f = dir.'/ecrit.tsv'
a = dir.'/ecrit_answers.tsv'
beta = real(system("awk -F'\t' '$1==\"ecrit.power_beta\"{print $2}' ".a))
c = real(system("awk -F'\t' '$1==\"ecrit.power_c\"{print $2}' ".a))
k = real(system("awk -F'\t' '$1==\"ecrit.mcnamara_young_k\"{print $2}' ".a))
set multiplot layout 1,2 title "C12 study e_{crit}(p): struck resting row of p equal spheres (a = d = v_0 = 1)"
set xlabel "number of spheres p"
set ylabel "critical restitution e_{crit}"
set logscale x
set grid
set key bottom right box opaque
set title "e_{crit} against p"
set yrange [0:1]
plot f using (column("p")):(column("e_crit[1]")) with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'simulation edge / rate map', \
     f using (column("p")):(column("e_crit_rate_map[1]")) with points pt 6 ps 1.6 lc rgb '#2ca02c' title 'rate map of the collapse cycle', \
     f using (column("p")):(column("e_crit_power_fit[1]")) with lines lw 2 lc rgb '#d62728' title sprintf('1 - %.3g p^{-%.3f}', c, beta), \
     f using (column("p")):(column("e_crit_mcnamara_young[1]")) with lines dt 2 lw 2 lc rgb '#7f7f7f' title sprintf('McNamara-Young: p = %.3f (-ln(1-e))/(1-e)', k)
set title "1 - e_{crit} against p (log-log)"
set ylabel "1 - e_{crit}"
set autoscale y
set logscale xy
set key top right box opaque
plot f using (column("p")):(1 - column("e_crit[1]")) with points pt 7 ps 0.8 lc rgb '#1f77b4' title '1 - e_{crit}', \
     f using (column("p")):(1 - column("e_crit_power_fit[1]")) with lines lw 2 lc rgb '#d62728' title 'power-law fit', \
     f using (column("p")):(1 - column("e_crit_mcnamara_young[1]")) with lines dt 2 lw 2 lc rgb '#7f7f7f' title 'McNamara-Young'
unset multiplot
