# Collapse in general rows: share of seeded random rows that end with an answer
# (normal or quasi-plastic within the collision cap), by row length p.
# Call: gnuplot -e "dir='results'; term='png'; out='results/collapse_by_p.png'" study/collapse_by_p.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/collapse_by_p.tsv'
set title "Collapse in general rows: random rows that end with an answer, closed-form collapse limits"
set xlabel "number of spheres p"
set ylabel "share of rows answered"
set yrange [0:1.05]
set xtics 1
set grid
set key bottom left box opaque
plot f using (column("p")):(column("answered_share")) with linespoints pt 7 ps 1.3 lw 2 \
     lc rgb '#1f77b4' title 'answered within the collision cap'
