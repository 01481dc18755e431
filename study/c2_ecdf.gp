# C12 task c2: empirical distribution function of v4 with the normal law of
# the same mean and deviation and the exact law overlaid; below, both laws'
# distance from the exact one, where the Monte Carlo noise and the skew that
# the normal law misses can be told apart.
# Call:
#   gnuplot -e "dir='results'; term='png'; out='results/c2_ecdf.png'" \
#       study/c2_ecdf.gp
if (!exists("dir")) dir = 'results'
if (!exists("term")) term = 'png'
if (!exists("out")) out = dir.'/c2_ecdf.'.term
if (term eq 'png') {
    set terminal pngcairo size 900,800 enhanced font ',11'
} else {
    set terminal svg size 900,800 enhanced font ',11'
}
set output out
set datafile separator '\t'
set datafile missing '-'
data = dir.'/c2_ecdf.tsv'
# the last rank is the sample size
stats data using 1 skip 1 nooutput
n = int(STATS_max)

# the law of e, from the check column of its sample moments
answers = dir.'/c2_answers.tsv'
stats answers using ((strcol(1) eq 'c2.e_mean') ? $4 : 1/0) nooutput
m = STATS_max
stats answers using ((strcol(1) eq 'c2.e_sd') ? $4 : 1/0) nooutput
s = STATS_max
heading = sprintf('C12 task c2: distribution function of v_4, e normal (m = %g, s = %g)', m, s)
# the precision of the runs, from the answers: precision=auto runs each in
# real(8) under its rounding certificate and again in real(16) where it fails;
# qp all in real(16); a table without the row is said to be so, not guessed
precision = ''
stats answers using ((strcol(1) eq 'c2.precision') ? (precision = strcol(2), 0) : 1/0) nooutput
stats answers using ((strcol(1) eq 'c2.escalated') ? $2 : 1/0) nooutput
escalated = int(STATS_max)
runs = (precision eq 'auto') ? \
    sprintf('%d runs: %d in real(8) under its rounding certificate, %d again in real(16)', \
            n, n - escalated, escalated) : (precision eq 'qp') ? \
    sprintf('%d runs in real(16)', n) : sprintf('%d runs, precision not recorded', n)
set multiplot title heading."\n".runs
set lmargin 12
set rmargin 3
set grid
set xrange [*:*] writeback

set tmargin at screen 0.92
set bmargin at screen 0.40
set ylabel 'P(v_4 {/Symbol \243} v) [1]'
set format x ''
set key left top box opaque
set yrange [0:1]
plot data using 2:3 skip 1 with steps lw 3 lc rgb '#1f77b4' title 'empirical (Monte Carlo)', \
     '' using 2:4 skip 1 with lines lw 1.5 lc rgb '#d62728' title 'normal law, same mean and sd', \
     '' using 2:5 skip 1 with lines lw 1.5 dt 2 lc rgb '#000000' \
         title 'exact law {/Symbol F}((2(v/v_0)^{1/3} - 1 - m)/s)'

set tmargin at screen 0.37
set bmargin at screen 0.08
set xrange restore
set format x '%g'
set xlabel 'final velocity v_4 [v_0]'
set ylabel 'difference from the exact law [1]'
set key right top box opaque
set yrange [*:*]
plot data using 2:($3 - $5) skip 1 with steps lw 2 lc rgb '#1f77b4' title 'empirical - exact', \
     '' using 2:($4 - $5) skip 1 with lines lw 1.5 lc rgb '#d62728' title 'normal - exact', \
     0 with lines lw 1 lc rgb '#000000' notitle
unset multiplot
