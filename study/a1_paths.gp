# C12 task a1: gaps y_i(t) of the definition's scene at e = 0.2.
# Call: gnuplot -e "dir='results'; term='png'; out='results/a1_paths.png'" study/a1_paths.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
set key top right box opaque
f = dir.'/a1_paths.tsv'
# the scene and the precision from the run: e, d and v0 from a1_answers.tsv
# (a1.e's value and its how), the precision from a1.collisions' how, a as
# the gaps at t = 0
answers = dir.'/a1_answers.tsv'
stats answers using (strcol('key') eq 'a1.e' ? (e = column('value'), how_e = strcol('how'), 0) : NaN) \
    nooutput
stats answers using (strcol('key') eq 'a1.collisions' ? (how_n = strcol('how'), 0) : NaN) nooutput
after(s, tag) = s[strstrt(s, tag) + strlen(tag):]
upto(s, tag) = s[1:strstrt(s, tag) - 1]
d = real(upto(after(how_e, 'd = '), ','))
v0 = real(upto(after(how_e, 'v0 = '), ')'))
precision = 'real('.upto(after(how_n, ' in real('), ')').')'
stats f using (column('y1[L]')) every ::0::0 nooutput
a = STATS_min
set title sprintf("C12 task a1: distances y_1, y_2, y_3 between the spheres, e = %g, d = %g, a = %g, v_0 = %g (event-driven in %s)", \
    e, d, a, v0, precision)
set xlabel "time t [a/v_0]"
set ylabel "gap y_i [a]"
set xrange [0:15]
set yrange [-0.05:*]
set grid
# the paths are piecewise linear: joining the breakpoints draws them exactly
plot f using (column('t[L/V]')):(column('y1[L]')) with lines lw 2 lc rgb '#1f77b4' title 'y_1 (spheres 1-2)', \
     f using (column('t[L/V]')):(column('y2[L]')) with lines lw 2 lc rgb '#ff7f0e' title 'y_2 (spheres 2-3)', \
     f using (column('t[L/V]')):(column('y3[L]')) with lines lw 2 lc rgb '#2ca02c' title 'y_3 (spheres 3-4)', \
     f using ((strcol('event') eq 'collision' && column('first') == 1) ? column('t[L/V]') : NaN):(0) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'collision 1-2', \
     f using ((strcol('event') eq 'collision' && column('first') == 2) ? column('t[L/V]') : NaN):(0) with points pt 5 ps 1.2 lc rgb '#ff7f0e' title 'collision 2-3', \
     f using ((strcol('event') eq 'collision' && column('first') == 3) ? column('t[L/V]') : NaN):(0) with points pt 9 ps 1.4 lc rgb '#2ca02c' title 'collision 3-4'
