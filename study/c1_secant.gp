# C12 task c1: convergence of the secant iteration for v4(e) = v0/2.
# Call: gnuplot -e "dir='results'; term='png'; out='results/c1_secant.png'" study/c1_secant.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/c1_iterations.tsv'
set title "C12 task c1: secant iteration in real(16) for v_4(e) = v_0/2"
set xlabel "iteration k"
set ylabel "|v_4(e_k) - v_0/2| [v_0]"
set logscale y
set format y "10^{%L}"
set yrange [1e-36:1]
set xtics 1
set grid
set key top right box opaque
r = 'residual=v4-target[V]'
plot f using (column('k')):(abs(column(r)) > 0 ? abs(column(r)) : 1e-36) with linespoints pt 7 ps 1.3 lw 2 lc rgb '#1f77b4' title '|residual| from e_0 = 0.5, e_1 = 0.6', \
     1e-30 with lines dt 2 lc rgb '#d62728' title 'tolerance 10^{-30}', \
     2**-113 with lines dt 3 lc rgb '#7f7f7f' title 'real(16) unit roundoff 2^{-113}'
