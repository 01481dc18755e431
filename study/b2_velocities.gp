# C12 task b2: final velocities of the four spheres against e.
# Call: gnuplot -e "dir='results'; term='png'; out='results/b2_velocities.png'" study/b2_velocities.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/b2_velocities.tsv'
stats dir.'/b1_answers.tsv' using (strcol('key') eq 'b1.e_crit' ? column('value') : NaN) nooutput
ecrit = STATS_max
# the grid and the precision that answered each point, from b2_answers.tsv
# (precision = auto: real(8) under its rounding certificate, else real(16))
answers = dir.'/b2_answers.tsv'
stats answers using (strcol('key') eq 'b2.grid_points' ? column('value') : NaN) nooutput
points = int(STATS_max)
stats answers using (strcol('key') eq 'b2.points_in_real64' ? column('value') : NaN) nooutput
in_real64 = int(STATS_max)
set title sprintf("C12 task b2: final velocities against the restitution coefficient (v_0 = 1)\n%d points of e: %d in real(8) under its rounding certificate, %d in real(16)", \
    points, in_real64, points - in_real64)
set xlabel "restitution coefficient e"
set ylabel "final velocity [v_0]"
set xrange [0:1]
set yrange [0:1]
set grid
set key top left box opaque
set arrow from ecrit, graph 0 to ecrit, graph 1 nohead dt 2 lc rgb '#d62728'
set label "e_{crit}: quasi-plastic below" at ecrit, graph 0.6 offset 1,0 tc rgb '#d62728'
plot f using (column('e')):(column('v1[V]')) with lines lw 2 lc rgb '#1f77b4' title 'v_1', \
     f using (column('e')):(column('v2[V]')) with lines lw 2 lc rgb '#ff7f0e' title 'v_2', \
     f using (column('e')):(column('v3[V]')) with lines lw 2 lc rgb '#2ca02c' title 'v_3', \
     f using (column('e')):(column('v4[V]')) with lines lw 2 lc rgb '#9467bd' title 'v_4', \
     f using (column('e')):((strcol('v4_single_hit[V]') eq '-') ? NaN : column('v4_single_hit[V]')) every 20 with points pt 6 ps 1.2 lc rgb '#000000' title 'closed form v_4 = ((1+e)/2)^3 (sphere 4 hit once)'
