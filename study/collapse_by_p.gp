# Collapse in general rows: how good the answer of seeded random rows is, by
# row length p: the share of rows exact, certified, ended at tolerance,
# bounded and unresolved (every collapse rule, the survey's budget).
# Call: gnuplot -e "dir='results'; term='png'; out='results/collapse_by_p.png'" study/collapse_by_p.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/collapse_by_p.tsv'
# the sample, from the run: its size as the rows of every length summed, its
# seed, lengths and budget as collapse_answers.tsv's how of collapse.exact
# says them ("random rows (seed S, p = A..B) whose ... within N collisions")
stats f using (column("scenes")) nooutput
rows = int(STATS_sum)
stats dir.'/collapse_answers.tsv' using (strcol('key') eq 'collapse.exact' ? (how = strcol('how'), 0) : NaN) \
    nooutput
drawn = how[strstrt(how, '(') + 1:strstrt(how, ')') - 1]
budget = how[strstrt(how, ' within ') + 8:strstrt(how, ' collisions') - 1]
set title sprintf("Collapse in general rows: how good the answer is, by row length\n%d random rows (%s), every collapse rule within %s collisions", \
    rows, drawn, budget) noenhanced
set xlabel "number of spheres p"
set ylabel "share of rows"
set yrange [0:1]
set xrange [1.5:*]
set xtics 1
set grid y
set key outside right top box opaque
set style fill solid 0.85 border -1
w = 0.8
s(c) = column(c)/column("scenes")
plot f using (column("p")):(s("exact")+s("certified")+s("tolerance")+s("bounded")+s("unresolved")):(w) \
        with boxes lc rgb '#d62728' title 'unresolved', \
     f using (column("p")):(s("exact")+s("certified")+s("tolerance")+s("bounded")):(w) \
        with boxes lc rgb '#ff7f0e' title 'bounded', \
     f using (column("p")):(s("exact")+s("certified")+s("tolerance")):(w) \
        with boxes lc rgb '#bcbd22' title 'tolerance', \
     f using (column("p")):(s("exact")+s("certified")):(w) \
        with boxes lc rgb '#1f77b4' title 'certified', \
     f using (column("p")):(s("exact")):(w) with boxes lc rgb '#2ca02c' title 'exact'
