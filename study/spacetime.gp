# The space-time diagram of one run of C12: the world lines x_i(t) of the
# spheres (position across, time upwards), the collisions on them and the
# collapse limits, from the tables of c12-spacetime.
# Call: gnuplot -e "dir='results'; name='spacetime_p30_e06'; out='results/spacetime_p30_e06'" \
#           study/spacetime.gp
# writes out.png and out.svg (name: the tables' base name, as c12-spacetime's key name).
lines = dir.'/'.name.'_lines.tsv'
marks = dir.'/'.name.'_collisions.tsv'
limits = dir.'/'.name.'_collapses.tsv'
info = dir.'/'.name.'_info.tsv'

set encoding utf8
set datafile separator tab
# the run in words and numbers (key-value rows of the info table)
caption = ''
every_k = 1
p = 0
d = 0
drawn = 0
n_marks = 0
n_limits = 0
stats info using (strcol(1) eq 'caption' ? (caption = strcol(2), 0) : 0, \
                  strcol(1) eq 'every' ? (every_k = column(2), 0) : 0, \
                  strcol(1) eq 'p' ? (p = column(2), 0) : 0, \
                  strcol(1) eq 'd' ? (d = column(2), 0) : 0, \
                  strcol(1) eq 'spheres_drawn' ? (drawn = column(2), 0) : 0, \
                  strcol(1) eq 'collisions_drawn' ? (n_marks = column(2), 0) : 0, \
                  strcol(1) eq 'collapses_drawn' ? (n_limits = column(2), 0) : 0) nooutput
set datafile columnheaders

title = 'C12 space-time diagram: '.caption
ordinal(k) = (int(k) % 100 >= 11 && int(k) % 100 <= 13) ? 'th' : \
    (int(k) % 10 == 1 ? 'st' : (int(k) % 10 == 2 ? 'nd' : (int(k) % 10 == 3 ? 'rd' : 'th')))
if (every_k > 1) {
    title = title.sprintf("\nworld lines of every %d%s sphere (%d of %d) and their collisions", \
                          every_k, ordinal(every_k), drawn, p)
}
set title title noenhanced
set xlabel 'position x_i of the sphere centres [L]'
set ylabel 'time t [L/V]'
# speeds span decades (a row shares one impulse among ever more spheres):
# colour by log10 of the speed over three decades below the fastest, rest and
# anything slower at the bottom
stats lines using (abs(column("v[V]"))) name 'speed' nooutput
v_top = (speed_max > 0) ? speed_max : 1
top = ceil(log10(v_top) - 1e-9)
decades = 3
shade(v) = (abs(v) > 10**(top - decades)) ? log10(abs(v)) : top - decades
set cbrange [top - decades:top]
set cbtics ('0' top - decades)
do for [k = top - decades + 1:top] { set cbtics add (sprintf('%g', 10**k) k) }
set cblabel sprintf('speed |v| [V] (log scale; below %g, and rest, at the bottom)', \
                    10**(top - decades))
set key outside below center horizontal box samplen 2 spacing 1.1 width 1
set grid front lc rgb '#dddddd' lw 0.5
set grid noxtics noytics
set border front
set palette defined (0 '#1f3b73', 0.45 '#2a9d8f', 0.75 '#e9c46a', 1 '#d1495b')
set offsets graph 0.02, graph 0.02, graph 0.02, 0
set autoscale xfix
set yrange [0:*]
# a dense run: smaller collision marks
mark_size = (n_marks > 2000) ? 0.15 : (n_marks > 200 ? 0.25 : 0.45)
line_width = (drawn > 100) ? 0.5 : (drawn > 20 ? 0.8 : 1.5)

# each row of the lines table is one piece of constant velocity, exact: a
# world line is the polygon of its pieces. A few spheres: their edges x_i ± d/2
# too, which meet at each point of contact
draw = 'plot '
if (drawn <= 12 && d > 0) {
    draw = draw.'lines using (column("x0[L]") - d/2):(column("t0[L/V]")):' \
        .'(column("x1[L]") - column("x0[L]")):(column("t1[L/V]") - column("t0[L/V]")) ' \
        .'with vectors nohead lw 0.8 lc rgb "#b0b0b0" notitle, ' \
        .'lines using (column("x0[L]") + d/2):(column("t0[L/V]")):' \
        .'(column("x1[L]") - column("x0[L]")):(column("t1[L/V]") - column("t0[L/V]")) ' \
        .'with vectors nohead lw 0.8 lc rgb "#b0b0b0" notitle, '
}
# the world lines carry no title of their own: a line coloured by the palette
# would show a sample in whatever colour the palette gives it (the red of its
# top end); the key's sample below is drawn in the palette's middle colour
draw = draw.'lines using (column("x0[L]")):(column("t0[L/V]")):' \
    .'(column("x1[L]") - column("x0[L]")):(column("t1[L/V]") - column("t0[L/V]")):' \
    .'(shade(column("v[V]"))) with vectors nohead lw line_width lc palette notitle, ' \
    .'NaN with lines lw 2 lc rgb "#2a9d8f" ' \
    .'title "world line x_i(t) of a sphere (colour: its speed)", ' \
    .'marks using (column("x[L]")):(column("t[L/V]")) with points pt 7 ps mark_size ' \
    .'lc rgb "black" title "collision (point of contact)"'
# collapse bars in a colour the palette does not use, nearly opaque, as wide
# as their number leaves room for: 3 px up to 30 limits, 2 px up to 100, then
# 1 px (a long row's limits come a few pixels apart), never thinner
bar_width = (n_limits > 100) ? 1 : (n_limits > 30 ? 2 : 3)
bar_colour = '#207b2cbf'
if (n_limits > 0) {
    draw = draw.', limits using (column("x_left[L]")):(column("t[L/V]")):' \
        .'(column("x_right[L]") - column("x_left[L]")):(0) with vectors nohead lw bar_width ' \
        .'lc rgb bar_colour title "collapse limit: the group, edge to edge"'
}
if (drawn <= 12 && d > 0) {
    draw = draw.', NaN with lines lw 0.8 lc rgb "#b0b0b0" title "edges of a sphere, x_i ± d/2"'
}
if (n_limits > 0 && n_limits <= 12) {
    draw = draw.', limits using (column("x_left[L]")):(column("t[L/V]")):' \
        .'(sprintf("%d-%d ", column("first"), column("last"))) with labels right ' \
        .'offset -0.5,0 tc rgb "#7b2cbf" notitle'
}

set terminal pngcairo size 1200,800 font ',11'
set output out.'.png'
eval(draw)
set terminal svg size 1200,800 dynamic font ',11'
set output out.'.svg'
eval(draw)
unset output
