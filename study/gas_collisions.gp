# The freely cooling ring of hard rods: T/T0 against the collisions per rod
# c, for each restitution, against exp(-(1 - e^2) c), Haff's law per
# collision.
# Call: gnuplot -e "dir='results'; term='png'; out='results/gas_collisions.png'" study/gas_collisions.gp
if (term eq 'png') { set terminal pngcairo size 1000,650 font ',11' } else { set terminal svg size 1000,650 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/gas_haff.tsv'
a = dir.'/gas_answers.tsv'
stats a using (strcol('key') eq 'gas.n' ? column('value') : NaN) nooutput
n = STATS_max
set title sprintf("The cooling ring of %d hard rods: T/T0 per collisions per rod (engine, real(16))", n)
set xlabel "collisions per rod c"
set ylabel "temperature T / T0"
set logscale xy
set format y "10^{%L}"
set yrange [1e-3:2]
set grid
set key bottom left box opaque
# the restitutions run, from the table (column e, in the order of its rows)
es = system("awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == \"e\") c = i; next } !($c in seen) { seen[$c] = 1; printf \"%s \", $c }' ".f)
palette = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b"
colour(i) = word(palette, (i - 1) % words(palette) + 1)
is(e) = (abs(column('e') - e) < 1e-9 && column('collisions_per_sphere') > 0) ? column('collisions_per_sphere') : NaN
plot for [i=1:words(es)] f using (is(real(word(es, i)))):(column('T_over_T0')) with points pt 7 ps 0.7 \
        lc rgb colour(i) title sprintf("e = %s, the engine", word(es, i)), \
     for [i=1:words(es)] f using (is(real(word(es, i)))):(column('exp_law')) with lines lw 1.5 \
        lc rgb colour(i) title sprintf("exp(-(1 - e^2) c), e = %s", word(es, i))
