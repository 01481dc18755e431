# C12 task a1: gaps y_i(t) of the definition's scene at e = 0.2.
# Call: gnuplot -e "dir='results'; term='png'; out='results/a1_paths.png'" study/a1_paths.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
set key top right box opaque
set title "C12 task a1: distances y_1, y_2, y_3 between the spheres, e = 0.2, d = 1, a = 1, v_0 = 1"
set xlabel "time t [a/v_0]"
set ylabel "gap y_i [a]"
set xrange [0:15]
set yrange [-0.05:*]
set grid
f = dir.'/a1_paths.tsv'
# the paths are piecewise linear: joining the breakpoints draws them exactly
plot f using (column('t[L/V]')):(column('y1[L]')) with lines lw 2 lc rgb '#1f77b4' title 'y_1 (spheres 1-2)', \
     f using (column('t[L/V]')):(column('y2[L]')) with lines lw 2 lc rgb '#ff7f0e' title 'y_2 (spheres 2-3)', \
     f using (column('t[L/V]')):(column('y3[L]')) with lines lw 2 lc rgb '#2ca02c' title 'y_3 (spheres 3-4)', \
     f using ((strcol('event') eq 'collision' && column('first') == 1) ? column('t[L/V]') : NaN):(0) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'collision 1-2', \
     f using ((strcol('event') eq 'collision' && column('first') == 2) ? column('t[L/V]') : NaN):(0) with points pt 5 ps 1.2 lc rgb '#ff7f0e' title 'collision 2-3', \
     f using ((strcol('event') eq 'collision' && column('first') == 3) ? column('t[L/V]') : NaN):(0) with points pt 9 ps 1.4 lc rgb '#2ca02c' title 'collision 3-4'
