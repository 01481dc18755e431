# Stability map of the methods compared (ARGESIM C12).
#
#   gnuplot -e "dir='results'; out='results/methods_stability'" study/stability_map.gp
#
# reads  dir/methods_stability.tsv (written by c12-methods)
# writes out.png and out.svg: one row per method and setting, one mark per
#        value of e, coloured by the outcome against the real128 reference.
#
# The x axis is the distance to the collapse threshold e_c = 3 - 2 sqrt(2) on
# a log scale, in two panels: e > e_c on the left (e - e_c from 0.83, e = 1,
# down to 1e-7) and e < e_c on the right (e_c - e from 1e-7 up to e_c, e = 0),
# so that e decreases from left to right throughout. A log scale, because
# everything of interest happens in decades of the distance: the count grows
# like (e - e_c)^(-1/2) and each precision fails at its own decade. On a
# linear e axis all of that would fall into one column of pixels at e_c.

if (!exists("dir")) dir = "results"
if (!exists("out")) out = dir."/methods_stability"
file = dir."/methods_stability.tsv"

set datafile separator "\t"
set datafile columnheaders

# columns of methods_stability.tsv, by their header names
c_row = "row"; c_label = "label"; c_dist = "e_minus_ec[1]"; c_code = "category_code"

stats file using (column(c_row)) nooutput
n_rows = int(STATS_max)

# outcome categories (sphere_row_outcome): colour per code
color(c) = (c == 0 ? 0x1a9850 : c == 1 ? 0xfdae61 : c == 2 ? 0x7b3294 : \
    c == 3 ? 0xd73027 : 0x404040)
e_c = 3 - 2*sqrt(2)
e_definition = 0.2

set yrange [0.4:n_rows + 0.6]
set ytics scale 0 font ",10" noenhanced
set logscale x
set format x "10^{%L}"
set grid xtics lc rgb "#dddddd"
unset key

do for [fmt in "pngcairo svg"] {
    if (fmt eq "pngcairo") {
        set terminal pngcairo size 1600,800 font "Sans,11" enhanced
        set output out.".png"
    } else {
        set terminal svg size 1600,800 font "Sans,11" enhanced background "white"
        set output out.".svg"
    }
    set multiplot title "ARGESIM C12 methods: outcome of each method against the real128 " . \
        "reference, from e = 1 through e_c = 3 - 2{/Symbol \326}2 to e = 0 " . \
        "(p = 4, d = a = v_0 = 1)" font ",14"

    # left: e > e_c, e decreasing to the right
    set lmargin at screen 0.15
    set rmargin at screen 0.75
    set tmargin at screen 0.90
    set bmargin at screen 0.22
    set xrange [1:1e-7]
    set xlabel "e - e_c   (e > e_c, e decreasing)"
    set ytics ()
    set arrow 1 from e_definition - e_c, graph 0 to e_definition - e_c, graph 1 nohead \
        lc rgb "#555555" dt 2
    set label 1 "e = 0.2" at e_definition - e_c, graph 1.02 center font ",9"
    plot file every ::0::(n_rows - 1) using (NaN):(column(c_row)):ytic(strcol(c_label)), \
         file using (column(c_dist) > 0 ? column(c_dist) : NaN):(column(c_row)):\
           (color(column(c_code))) with points pt 5 ps 0.55 lc rgb variable
    unset arrow 1
    unset label 1

    # right: e < e_c, e decreasing to the right
    set lmargin at screen 0.78
    set rmargin at screen 0.97
    set xrange [1e-7:0.2]
    set xtics 1e-7, 100
    set xlabel "e_c - e   (e < e_c)"
    set format y ""
    plot file using (column(c_dist) < 0 ? -column(c_dist) : NaN):(column(c_row)):\
           (color(column(c_code))) with points pt 5 ps 0.55 lc rgb variable

    # legend along the bottom
    unset xlabel
    unset border
    unset tics
    unset logscale x
    set lmargin at screen 0.15
    set rmargin at screen 0.97
    set tmargin at screen 0.09
    set bmargin at screen 0.02
    set xrange [0:1]
    set yrange [0:1]
    set key center center horizontal box font ",11" samplen 1
    plot NaN with points pt 5 ps 1.5 lc rgb color(0) title "right count and state", \
         NaN with points pt 5 ps 1.5 lc rgb color(1) title "wrong count or sequence", \
         NaN with points pt 5 ps 1.5 lc rgb color(2) title "wrong final state", \
         NaN with points pt 5 ps 1.5 lc rgb color(3) title "negative gap", \
         NaN with points pt 5 ps 1.5 lc rgb color(4) title "no end (budget or solver)"
    unset multiplot

    # restore the panel settings for the next format
    unset key
    set border
    set tics
    set ytics scale 0 font ",10" noenhanced
    set format y "% h"
    set logscale x
    set xtics autofreq
    set yrange [0.4:n_rows + 0.6]
}
