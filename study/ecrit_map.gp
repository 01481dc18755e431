# C12 study e_crit(p): the outcome map near the edge. Each row p is drawn along
# its scan, x = (e - e_f)/(1 - e_f) with e_f its lowest separated point, one
# colour per outcome of the engine's labelled answer (runs of equal outcomes
# from ecrit_map.tsv).
# Call: gnuplot -e "dir='results'; term='png'; out='results/ecrit_map.png'" study/ecrit_map.gp
if (term eq 'png') { set terminal pngcairo size 1200,720 font ',11' } else { set terminal svg size 1200,720 dynamic font ',11' }
set output out
set datafile separator tab
set datafile missing '-'
m = dir.'/ecrit_map.tsv'
f = dir.'/ecrit.tsv'
# per p, read once, every column by its name in the header: the spacing h of
# the scan from ecrit.tsv, (window_to - window_from)/(points - 1) (each run is
# drawn from half a spacing before its first point to half after its last),
# and e_f, the first point of the first separated run of the real16 scan in
# ecrit_map.tsv (every digit of the grid, where ecrit.tsv rounds e_finite_min
# to its width); both kept in arrays indexed by p itself, so that a row
# missing from the sweep cannot shift the others
stats f using (column("p")) nooutput
p_top = int(STATS_max)
array EF[p_top]
array H[p_top]
do for [i = 1:p_top] { EF[i] = NaN; H[i] = NaN }
stats f using (H[int(column("p"))] = column("points") > 1 ? \
    (column("window_to[1]") - column("window_from[1]"))/(column("points") - 1) : NaN, 0) nooutput
stats m using ((strcol("scan") eq "real16" && strcol("outcome") eq "separated" && \
    EF[int(column("p"))] != EF[int(column("p"))]) ? (EF[int(column("p"))] = column("e_first[1]"), 0) : 0) \
    nooutput
ef(p) = (p >= 1 && p <= p_top) ? EF[int(p)] : NaN
h(p) = (p >= 1 && p <= p_top) ? H[int(p)] : NaN
x(e, p) = (e - ef(p))/(1 - ef(p))
from(p) = x(column("e_first[1]") - h(p)/2, p)
to(p) = x(column("e_last[1]") + h(p)/2, p)
colour(o) = o eq 'separated' ? 0x1f77b4 : o eq 'certified' ? 0xd62728 : o eq 'unproven' ? 0xff7f0e : 0x7f7f7f
# what the map shows (rows, points, tolerances, budget), from ecrit_answers.tsv,
# a line for each part of it
shows = system("awk -F'\t' '$1 == \"ecrit.rows\" { gsub(/; /, \"\\n\", $6); gsub(/ in real/, \"\\nin real\", $6); gsub(/, max_collisions/, \"\\nmax_collisions\", $6); print $6 }' ".dir."/ecrit_answers.tsv")
set label 1 "C12 study e_{crit}(p): outcome of each scan point near the edge" at screen 0.36, screen 0.97 center
set label 2 shows at screen 0.36, screen 0.935 center font ',9' noenhanced
set tmargin 8
set xlabel "(e - e_f) / (1 - e_f) [1],  e_f = lowest separated point of the row"
set ylabel "number of spheres p"
# p on a log axis: the short rows, each scanned in full up to p = 20, keep
# room of their own beside the long ones
stats m using (column("p")) nooutput
set logscale y
set yrange [STATS_min - 0.5:STATS_max + 0.5]
set ytics (3, 4, 5, 6, 7, 8, 10, 12, 15, 20, 25, 30, 40, 50, 64, 80, 100, 128)
set grid
set key outside right top box opaque
plot m using (strcol("scan") eq "real16" ? from(column("p")) : NaN):(column("p")):(to(column("p")) - from(column("p"))):(0):(colour(strcol("outcome"))) \
        with vectors nohead lw 3 lc rgb variable notitle, \
     NaN with lines lw 4 lc rgb '#1f77b4' title 'separated', \
     NaN with lines lw 4 lc rgb '#d62728' title 'collapse, certified', \
     NaN with lines lw 4 lc rgb '#ff7f0e' title 'merged at tol, collapse unproven', \
     NaN with lines lw 4 lc rgb '#7f7f7f' title 'undecided'
