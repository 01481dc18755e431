# The collapse region: the answer of each struck row of the grid (equal
# spheres, d = a = v0 = 1, default settings) over its length p and restitution
# e, each cell labelled with its bound v_bound (the collisions below it).
# Call: gnuplot -e "dir='results'; term='png'; out='results/collapse_grid.png'" study/collapse_grid.gp
if (term eq 'png') { set terminal pngcairo size 1100,850 font ',11' } else { set terminal svg size 1100,850 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/collapse_grid.tsv'
set title "The collapse region of a struck row: answer by row length p and restitution e (default settings)"
# noenhanced: the column's name v_bound as written, not v with a subscript b
set xlabel "number of spheres p  (each cell: v_bound in v0 above, collisions below)" noenhanced
set ylabel "restitution coefficient e"
set logscale x
set format x "10^{%L}"
set xrange [25:200000]
set yrange [0.1:1.02]
set grid
set key outside right top box opaque title "answer"
colour(a) = a eq "exact" ? 0x2ca02c : a eq "certified" ? 0x1f77b4 : a eq "tolerance" ? 0xbcbd22 : \
    a eq "bounded" ? 0xff7f0e : 0xd62728
is(a, b) = (strcol("answer") eq b) ? column("e") : NaN
plot for [a in "exact certified tolerance bounded unresolved"] f \
        using (column("p")):(is(a, a)) with points pt 5 ps 3 lc rgb colour(a) title a, \
     f using (column("p")):(column("e")+0.014):(strcol("v_bound[V]")) with labels font ",7" notitle, \
     f using (column("p")):(column("e")-0.014):(strcol("collisions")) with labels font ',7' \
        tc rgb '#555555' notitle
