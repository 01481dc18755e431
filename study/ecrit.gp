# C12 study e_crit(p): 1 - e_c of the struck row of p equal spheres against p,
# on log axes, with three fits and their residuals. e_c of a row is the lowest
# point of its scan that separated; the bar reaches up to the highest point
# that collapsed where that lies above it (the mixed band).
# Call: gnuplot -e "dir='results'; term='png'; out='results/ecrit.png'" study/ecrit.gp
if (term eq 'png') { set terminal pngcairo size 1200,760 font ',11' } else { set terminal svg size 1200,760 dynamic font ',11' }
set output out
set datafile separator tab
set datafile missing '-'
f = dir.'/ecrit.tsv'
a = dir.'/ecrit_answers.tsv'
answer(key) = real(system("awk -F'\t' '$1==\"".key."\"{print $2}' ".a))
beta = answer("ecrit.power_beta")
c = answer("ecrit.power_c")
cp = answer("ecrit.c_over_p")
k = answer("ecrit.mcnamara_young_k")
# the bar's top: the highest collapse if it lies above the lowest separation
top(col_c, col_f) = (strcol(col_c) ne "-" && column(col_c) > column(col_f)) ? column(col_c) : column(col_f)
# what the scans were (rows, points, precision, tolerances, budget): the how of
# ecrit.rows in ecrit_answers.tsv, under the title (noenhanced: max_collisions)
scans = system("awk -F'\t' '$1 == \"ecrit.rows\" { print $NF }' ".a)
set multiplot layout 2,1 title "C12 study e_{crit}(p): struck resting row of p equal spheres (a = d = v_0 = 1)"
set lmargin 12
set logscale xy
set grid
set xrange [2.5:*]
set xtics (3, 5, 10, 20, 50, 100)
set autoscale xfixmax
set ylabel "1 - e_c [1]"
set key top right box opaque
set format x ""
set size 1,0.555
set origin 0,0.38
set label 1 scans at screen 0.5, screen 0.948 center font ',9' noenhanced
plot f using (column("p")):(1 - column("e_finite_min[1]")):(1 - top("e_collapse_max[1]", "e_finite_min[1]")):(1 - column("e_finite_min[1]")) \
        with yerrorbars pt 7 ps 0.6 lc rgb '#1f77b4' title '1 - e_c (lowest separated point; bar: mixed band)', \
     f using (column("p")):(1 - column("e_collapse_max[1]")) with points pt 6 ps 0.8 lc rgb '#9467bd' title 'highest point certified to collapse', \
     f using (column("p")):(column("fit_power[1]")) with lines lw 2 lc rgb '#d62728' title sprintf('%.3g p^{-%.3f}', c, beta), \
     f using (column("p")):(column("fit_c_over_p[1]")) with lines dt 3 lw 2 lc rgb '#2ca02c' title sprintf('%.3g / p', cp), \
     f using (column("p")):(column("fit_mcnamara_young[1]")) with lines dt 2 lw 2 lc rgb '#7f7f7f' title sprintf('McNamara-Young: p = %.3g (-ln(1-e))/(1-e)', k)
unset label 1
set size 1,0.38
set origin 0,0.0
unset logscale y
set format x "%g"
set xlabel "number of spheres p"
set ylabel "(1 - e_c) / fit [1]"
# the titles left-aligned after their samples, the box wide enough for them
set key top left box opaque reverse Left width 2
plot f using (column("p")):((1 - column("e_finite_min[1]"))/column("fit_power[1]")) with linespoints pt 7 ps 0.5 lc rgb '#d62728' title 'power law', \
     f using (column("p")):((1 - column("e_finite_min[1]"))/column("fit_c_over_p[1]")) with linespoints pt 6 ps 0.5 lc rgb '#2ca02c' title 'C/p', \
     f using (column("p")):((1 - column("e_finite_min[1]"))/column("fit_mcnamara_young[1]")) with linespoints pt 4 ps 0.5 lc rgb '#7f7f7f' title 'McNamara-Young', \
     1 with lines lc rgb 'black' notitle
unset multiplot
