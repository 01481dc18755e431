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
es = "0.99 0.9 0.5"
colours = "#1f77b4 #ff7f0e #2ca02c"
is(e) = (abs(column('e') - e) < 1e-9 && column('collisions_per_sphere') > 0) ? column('collisions_per_sphere') : NaN
plot for [i=1:3] f using (is(real(word(es, i)))):(column('T_over_T0')) with points pt 7 ps 0.7 \
        lc rgb word(colours, i) title sprintf("e = %s, the engine", word(es, i)), \
     for [i=1:3] f using (is(real(word(es, i)))):(column('exp_law')) with lines lw 1.5 \
        lc rgb word(colours, i) title sprintf("exp(-(1 - e^2) c), e = %s", word(es, i))
