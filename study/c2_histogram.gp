# C12 task c2: histogram of v4 as a density, with the exact density and the
# normal density of the same mean and deviation.
# Call:
#   gnuplot -e "dir='results'; term='png'; out='results/c2_histogram.png'" \
#       study/c2_histogram.gp
if (!exists("dir")) dir = 'results'
if (!exists("term")) term = 'png'
if (!exists("out")) out = dir.'/c2_histogram.'.term
if (term eq 'png') {
    set terminal pngcairo size 900,600 enhanced font ',11'
} else {
    set terminal svg size 900,600 enhanced font ',11'
}
set output out
set datafile separator '\t'
set datafile missing '-'
data = dir.'/c2_histogram.tsv'
stats data using 2 skip 1 nooutput
n = int(STATS_sum)
# the law of e, from the check column of its sample moments
answers = dir.'/c2_answers.tsv'
stats answers using ((strcol(1) eq 'c2.e_mean') ? $4 : 1/0) nooutput
m = STATS_max
stats answers using ((strcol(1) eq 'c2.e_sd') ? $4 : 1/0) nooutput
s = STATS_max
heading = sprintf('C12 task c2: histogram of v_4, e normal (m = %g, s = %g)', m, s)
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
set title heading."\n".runs
set xlabel 'final velocity v_4 [v_0]'
set ylabel 'probability density [1/v_0]'
set key right top box opaque
set grid
set style fill solid 0.35 border lc rgb '#1f77b4'
set yrange [0:*]
plot data using 1:3 skip 1 with boxes lc rgb '#1f77b4' title 'Monte Carlo histogram', \
     '' using 1:5 skip 1 with lines lw 1.5 lc rgb '#d62728' \
         title 'normal density, same mean and sd', \
     '' using 1:4 skip 1 with lines lw 2 dt 2 lc rgb '#000000' \
         title 'exact density of v_0((1+e)/2)^3'
