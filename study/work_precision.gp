# Work-precision chart of the methods compared (ARGESIM C12).
#
#   gnuplot -e "dir='results'; out='results/timing/methods_work_precision'" study/work_precision.gp
#
# reads  dir/methods_work_precision.tsv (written by c12-methods: the errors) beside
#        dir/timing/methods_work_precision.tsv (the same rows' CPU times, this
#        machine's), joined row by row
# writes out.png and out.svg: one panel per scene, CPU time per run against
#        the largest error (velocities in v0, collision times in a/v0), log-log,
#        one line per method through its settings. Filled symbols: the run has
#        the reference's collision sequence; open symbols: it has not. Runs
#        that did not end are left out; an error of exactly 0 (the engine in
#        real128 against the real128 reference) is drawn at 1e-34.

if (!exists("dir")) dir = "results"
if (!exists("out")) out = dir."/timing/methods_work_precision"
file = "< paste '".dir."/methods_work_precision.tsv' '".dir."/timing/methods_work_precision.tsv'"

set datafile separator "\t"
set datafile missing "nan"
set datafile columnheaders

# columns of methods_work_precision.tsv, by their header names
c_scene = "scene"; c_e = "e[1]"; c_dist = "e_minus_ec[1]"; c_label = "label"
c_method = "method"; c_kind = "kind"; c_cpu = "cpu_per_run[s]"; c_error = "error[1]"
c_category = "category"

stats file using (column(c_scene)) nooutput
n_scenes = int(STATS_max)

floor_error = 1e-34
err(x) = (x > floor_error ? x : floor_error)
ended(i) = (column(c_scene) == i && strcol(c_category) ne "no_end")
# symbol: filled when the sequence is right or wrong only in the final state
symbol(filled, open) = (strcol(c_category) eq "right" || \
    strcol(c_category) eq "wrong_state" ? filled : open)

is_engine = 'strcol(c_method) eq "engine" && strstrt(strcol(c_label), "_tol") == 0'
is_engine_tol = 'strcol(c_method) eq "engine" && strstrt(strcol(c_label), "_tol") > 0'
is_absolute = 'strcol(c_method) eq "absolute"'
is_rk8pd = 'strcol(c_method) eq "ode_rk8pd"'
is_rkf45 = 'strcol(c_method) eq "ode_rkf45"'
is_stepping = 'strcol(c_method) eq "stepping"'

set style line 1 lc rgb "#1b9e77" lw 2 pt 7 ps 1.1
set style line 2 lc rgb "#66a61e" lw 2 pt 9 ps 1.3
set style line 3 lc rgb "#d95f02" lw 2 pt 5 ps 1.0
set style line 4 lc rgb "#7570b3" lw 2 pt 13 ps 1.2
set style line 5 lc rgb "#e7298a" lw 2 pt 11 ps 1.2
set style line 6 lc rgb "#a6761d" lw 2 pt 15 ps 1.2

# each kind's label on its own side of its point: the kinds' points crowd
# together where every kind ends at the same (wrong) count near e_c
# (sp right, dp below, xdp left, qp above)
kind_label = 'font ",9" tc rgb "#1b9e77"'

set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xrange [1e-35:1e2]
set yrange [1e-7:1]
set xtics 1e-35, 1e5
set grid xtics ytics lc rgb "#dddddd"
set xlabel "largest error: final velocities / v_0, collision times / (a/v_0)"
set ylabel "CPU time per run [s]"
unset key

do for [fmt in "pngcairo svg"] {
    if (fmt eq "pngcairo") {
        set terminal pngcairo size 1800,1100 font "Sans,11" enhanced
        set output out.".png"
    } else {
        set terminal svg size 1800,1100 font "Sans,11" enhanced background "white"
        set output out.".svg"
    }
    set multiplot layout 2,3 title "ARGESIM C12 methods: work-precision of four methods " . \
        "against the real128 reference (p = 4, d = a = v_0 = 1)" font ",15"
    do for [i=1:n_scenes] {
        stats file using (column(c_scene) == i ? column(c_e) : NaN) nooutput
        e_i = STATS_min
        stats file using (column(c_scene) == i ? column(c_dist) : NaN) nooutput
        set title sprintf("e = %.6g   (e - e_c = %.2g)", e_i, STATS_min)
        plot \
          file using (ended(i) && @is_engine ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(7, 6)) with linespoints ls 1 pt variable, \
          file using (ended(i) && @is_engine && strcol(c_kind) eq "sp" ? err(column(c_error)) \
            : NaN):(column(c_cpu)):(strcol(c_kind)) with labels offset 1.6,0 @kind_label, \
          file using (ended(i) && @is_engine && strcol(c_kind) eq "dp" ? err(column(c_error)) \
            : NaN):(column(c_cpu)):(strcol(c_kind)) with labels offset 0,-1.1 @kind_label, \
          file using (ended(i) && @is_engine && strcol(c_kind) eq "xdp" ? err(column(c_error)) \
            : NaN):(column(c_cpu)):(strcol(c_kind)) with labels offset -2.2,0 @kind_label, \
          file using (ended(i) && @is_engine && strcol(c_kind) eq "qp" ? err(column(c_error)) \
            : NaN):(column(c_cpu)):(strcol(c_kind)) with labels offset 0,1.1 @kind_label, \
          file using (ended(i) && @is_engine_tol ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(9, 8)) with points ls 2 pt variable, \
          file using (ended(i) && @is_absolute ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(5, 4)) with linespoints ls 3 pt variable, \
          file using (ended(i) && @is_rk8pd ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(13, 12)) with linespoints ls 4 pt variable, \
          file using (ended(i) && @is_rkf45 ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(11, 10)) with linespoints ls 5 pt variable, \
          file using (ended(i) && @is_stepping ? err(column(c_error)) : NaN):(column(c_cpu)):\
            (symbol(15, 14)) with linespoints ls 6 pt variable
    }
    # the last panel holds the legend
    unset title
    unset border
    unset tics
    unset xlabel
    unset ylabel
    unset grid
    set key center center box reverse Left spacing 1.6 font ",12" width -6
    unset logscale
    set xrange [0:1]
    set yrange [0:1]
    plot \
      NaN with linespoints ls 1 title "engine, relative variables (sp, dp, xdp, qp; tol = epsilon)", \
      NaN with points ls 2 title "engine dp, tol = sqrt(tiny)", \
      NaN with linespoints ls 3 title "absolute variables (dp, qp)", \
      NaN with linespoints ls 4 title "GSL rk8pd + events (tol 1e-3 ... 1e-13)", \
      NaN with linespoints ls 5 title "GSL rkf45 + events (tol 1e-4 ... 1e-12)", \
      NaN with linespoints ls 6 title "time stepping (h 1e-1 ... 1e-5)", \
      NaN with points pt 6 lc rgb "black" title "open symbol: wrong collision count or sequence"
    unset multiplot
    # restore the panel settings for the next format
    set border
    set tics
    set xtics 1e-35, 1e5
    set logscale xy
    set xrange [1e-35:1e2]
    set yrange [1e-7:1]
    set grid xtics ytics lc rgb "#dddddd"
    set xlabel "largest error: final velocities / v_0, collision times / (a/v_0)"
    set ylabel "CPU time per run [s]"
    unset key
}
