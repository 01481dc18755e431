# C12 task b1: growth of n as e approaches the critical restitution from above.
# Call: gnuplot -e "dir='results'; term='png'; out='results/b1_critical.png'" study/b1_critical.gp
if (term eq 'png') { set terminal pngcairo size 1000,600 font ',11' } else { set terminal svg size 1000,600 dynamic font ',11' }
set output out
set datafile separator tab
set datafile columnheaders
f = dir.'/b1_critical.tsv'
a = dir.'/b1_answers.tsv'
# the fit of the answers: the values of keys b1.exponent and b1.prefactor
stats a using (strcol('key') eq 'b1.exponent' ? column('value') : NaN) nooutput
k = STATS_max
stats a using (strcol('key') eq 'b1.prefactor' ? column('value') : NaN) nooutput
c = STATS_max
# the runs' tolerance, b1.tol_fine, as written (10^-4000 is no double)
stats a using (strcol('key') eq 'b1.tol_fine' ? (tol_text = strcol('value'), 0) : NaN) nooutput
tol_mantissa = real(tol_text[1:strstrt(tol_text, 'E') - 1])
tol_decade = int(tol_text[strstrt(tol_text, 'E') + 1:])
tol = (tol_mantissa == 1 ? '' : sprintf('%g ', tol_mantissa)).sprintf('10^{%d}', tol_decade)
# the fitted points: n >= 200 (min_fit_collisions of c12-b1, where the
# asymptote holds); the fit is drawn over their range only
n_fit_min = 200
stats f using (column('collisions') >= n_fit_min ? column('delta=e-e_crit') : NaN) nooutput
fit_lo = STATS_min
fit_hi = STATS_max
set title sprintf("C12 task b1: n against the distance to e_{crit}; fitted n = %.3f (e - e_{crit})^{%.4f}", c, k)
set xlabel "e - e_{crit} [1]"
set ylabel "collisions n [1]"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set samples 400
set key top right box opaque
fitted(x) = (x >= fit_lo && x <= fit_hi) ? c*x**k : NaN
plot f using (column('delta=e-e_crit')):(column('collisions')) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'n, event-driven real(16), tol = '.tol, \
     fitted(x) with lines lw 2 lc rgb '#d62728' \
         title sprintf('least-squares fit over 10^{%d} <= e - e_{crit} <= 10^{%d} (n >= %d)', \
                       floor(log10(fit_lo) + 0.5), floor(log10(fit_hi) + 0.5), n_fit_min), \
     0.5*c*x**(-0.5) with lines lw 1.5 dt 2 lc rgb '#7f7f7f' \
         title 'slope -1/2 (theory), drawn at half the fit''s height'
