# C12 task c1: convergence of the secant iteration for v4(e) = v0/2.
# Call: gnuplot -e "dir='results'; term='png'; out='results/c1_secant.png'" study/c1_secant.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/c1_iterations.tsv'
# what the run did, from its tables: the precision and the starts from c1.e's
# how, the stopping tolerance from c1.iterations' how, the target as v4 at
# the root less its residual (the last row of c1_iterations.tsv)
answers = dir.'/c1_answers.tsv'
stats answers using (strcol('key') eq 'c1.e' ? (how_e = strcol('how'), 0) : NaN) nooutput
stats answers using (strcol('key') eq 'c1.iterations' ? (how_k = strcol('how'), 0) : NaN) nooutput
stats answers using (strcol('key') eq 'c1.v4' ? column('value') : NaN) nooutput
v4_root = STATS_max
after(s, tag) = s[strstrt(s, tag) + strlen(tag):]
upto(s, tag) = s[1:strstrt(s, tag) - 1]
precision = 'real('.upto(after(how_e, ' in real('), ')').')'
e0 = real(upto(after(how_e, ' from e = '), ','))
e1 = real(upto(after(after(how_e, ' from e = '), ', '), ';'))
f_tol = real(upto(after(how_k, '<= '), ':'))
r = 'residual=v4-target[V]'
stats f using (r_last = column(r), 0) nooutput
target = v4_root - r_last
# a power of ten as such
decade(x) = floor(log10(x) + 0.5)
power(x) = abs(x/10.0**decade(x) - 1) < 1e-9 ? sprintf('10^{%d}', decade(x)) : sprintf('%g', x)
set title sprintf("C12 task c1: secant iteration in %s for v_4(e) = %g v_0", precision, target)
set xlabel "iteration k"
set ylabel sprintf("|v_4(e_k) - %g v_0| [v_0]", target)
set logscale y
set format y "10^{%L}"
set yrange [1e-36:1]
set xtics 1
set grid
set key top right box opaque
plot f using (column('k')):(abs(column(r)) > 0 ? abs(column(r)) : 1e-36) with linespoints pt 7 ps 1.3 lw 2 lc rgb '#1f77b4' title sprintf('|residual| from e_0 = %g, e_1 = %g', e0, e1), \
     f_tol with lines dt 2 lc rgb '#d62728' title 'tolerance '.power(f_tol), \
     2**-113 with lines dt 3 lc rgb '#7f7f7f' title 'real(16) unit roundoff 2^{-113}'
