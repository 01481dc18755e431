# C12 task c2: half-width of the 95 % interval of the mean and the error of the
# mean against the sample size N, log-log, with an N^{-1/2} reference.
# Call:
#   gnuplot -e "dir='results'; term='png'; out='results/c2_convergence.png'" \
#       study/c2_convergence.gp
if (!exists("dir")) dir = 'results'
if (!exists("term")) term = 'png'
if (!exists("out")) out = dir.'/c2_convergence.'.term
if (term eq 'png') {
    set terminal pngcairo size 900,600 enhanced font ',11'
} else {
    set terminal svg size 900,600 enhanced font ',11'
}
set output out
set datafile separator '\t'
set datafile missing '-'
data = dir.'/c2_convergence.tsv'
# the stream and its precision, from the answers: nmax runs from one seed;
# precision=auto runs each in real(8) under its rounding certificate and again
# in real(16) where it fails (escalated_nmax of the whole stream)
answers = dir.'/c2_answers.tsv'
precision = ''
stats answers using ((strcol(1) eq 'c2.precision') ? (precision = strcol(2), 0) : 1/0) nooutput
stats answers using ((strcol(1) eq 'c2.nmax') ? $2 : 1/0) nooutput
nmax = int(STATS_max)
stats answers using ((strcol(1) eq 'c2.seed') ? $2 : 1/0) nooutput
seed = int(STATS_max)
stats answers using ((strcol(1) eq 'c2.escalated_nmax') ? $2 : 1/0) nooutput
escalated = int(STATS_max)
stream = sprintf('N: prefixes of one stream of %d runs (seed %d)', nmax, seed)
runs = (precision eq 'auto') ? \
    sprintf("%s\n%d in real(8) under its rounding certificate, %d again in real(16)", \
            stream, nmax - escalated, escalated) : (precision eq 'qp') ? \
    stream.', all in real(16)' : stream.', precision not recorded'
set title "C12 task c2: convergence of the Monte Carlo mean of v_4\n".runs
set xlabel 'sample size N [1]'
set ylabel 'half-width, error of the mean [v_0]'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set key left bottom box opaque
set grid
# The reference line passes through the first row's half-width, so a slope of
# -1/2 shows as parallel lines.
stats data using 1 skip 1 every ::0::0 nooutput
n0 = STATS_min
stats data using 4 skip 1 every ::0::0 nooutput
h0 = STATS_min
plot data using 1:4 skip 1 with linespoints pt 7 lw 2 lc rgb '#1f77b4' \
         title 'half-width of the 95 % interval of the mean', \
     '' using 1:(abs($8)) skip 1 with linespoints pt 5 lw 1.5 lc rgb '#d62728' \
         title '|mean - exact mean|', \
     h0*sqrt(n0/x) with lines dt 2 lw 1.5 lc rgb '#000000' title 'N^{-1/2} reference'
