# The freely cooling ring of hard rods: T/T0 against t/t0 for each
# restitution (the engine's run, to its horizon or its budget), Haff's law
# T0/(1 + t/t0)^2, the sticky gas's t^(-2/3) for its slope, and the same gas
# with collisions below a cutoff speed elastic (the field's workaround).
# Call: gnuplot -e "dir='results'; term='png'; out='results/gas_haff.png'" study/gas_haff.gp
if (term eq 'png') { set terminal pngcairo size 1000,650 font ',11' } else { set terminal svg size 1000,650 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/gas_haff.tsv'
a = dir.'/gas_answers.tsv'
stats a using (strcol('key') eq 'gas.n' ? column('value') : NaN) nooutput
n = STATS_max
stats a using (strcol('key') eq 'gas.density' ? column('value') : NaN) nooutput
density = STATS_max
set title sprintf("The cooling ring of %d hard rods, n d = %g: T/T0 against Haff's law (engine, real(16))", n, density)
set xlabel "t / t0  (t0: Haff's time)"
set ylabel "temperature T / T0"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xrange [0.01:30]
set grid
set key bottom left box opaque
haff(x) = 1/(1 + x)**2
# the restitutions run, from the table (column e, in the order of its rows)
es = system("awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == \"e\") c = i; next } !($c in seen) { seen[$c] = 1; printf \"%s \", $c }' ".f)
palette = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b"
colour(i) = word(palette, (i - 1) % words(palette) + 1)
is(e) = (abs(column('e') - e) < 1e-9 && column('t_over_t0') > 0) ? column('t_over_t0') : NaN
cut(s) = (s eq '-') ? NaN : real(s)
plot haff(x) with lines lw 2 dt 1 lc rgb '#000000' title "Haff's law T0/(1 + t/t0)^2", \
     0.3*x**(-2.0/3) with lines dt 3 lc rgb '#7f7f7f' title "t^{-2/3} (the sticky gas's slope)", \
     for [i=1:words(es)] f using (is(real(word(es, i)))):(column('T_over_T0')) with linespoints \
        pt 7 ps 0.6 lw 1.5 lc rgb colour(i) title sprintf("e = %s, the engine", word(es, i)), \
     for [i=1:words(es)] f using (is(real(word(es, i)))):(cut(strcol('cutoff_T_over_T0'))) with lines \
        dt 2 lw 1 lc rgb colour(i) \
        title sprintf("e = %s, collisions below the cutoff elastic", word(es, i))
