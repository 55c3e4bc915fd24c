# fricon response figure: gnuplot table1_patch_response.gp draws table1_patch_response.png from table1_patch_summary.csv (from any folder)
gp_dir = ''
do for [i_ = strlen(ARG0):1:-1] { if (gp_dir eq '' && ARG0[i_:i_] eq '/') { gp_dir = ARG0[1:i_] } }
summary = gp_dir.'table1_patch_summary.csv'
response_png = gp_dir.'table1_patch_response.png'
title = 'fricon: Table 1 reading: central patch of width 0.1 l, b/l 0.0055 (response)'
x_col = 3
x_label = 'EPS_BAR'
x_log = 1
n_keys = 12
array key_col[12]
array key_title[12]
key_col[1] = 8
key_title[1] = 'max settlement'
key_col[2] = 10
key_title[2] = 'min settlement'
key_col[3] = 12
key_title[3] = 'differential settlement (max - min)'
key_col[4] = 13
key_title[4] = 'mean settlement over the base'
key_col[5] = 18
key_title[5] = 'max |dw/dx - tilt| between stations'
key_col[6] = 27
key_title[6] = 'max pressure (element mean at a station)'
key_col[7] = 30
key_title[7] = 'pressure at d from the left end'
key_col[8] = 31
key_title[8] = 'pressure at d from the right end'
key_col[9] = 32
key_title[9] = 'pressure at the centre x = 0'
key_col[10] = 33
key_title[10] = 'max sagging M (bottom in tension)'
key_col[11] = 35
key_title[11] = 'max hogging M (top in tension)'
key_col[12] = 37
key_title[12] = 'max |Q| (signed)'
n_groups = 1
array group_title[1]
group_title[1] = ''
# fricon response figure: each key result of a sweep against the first swept parameter, one
# curve per value of the other swept parameters (their combinations), read from the sweep's
# summary CSV (its two lines before the rows: a '#' line and the header). fricon writes
# output/STEM_response.gp with these settings, then this template:
#   summary, response_png, title   the summary CSV and the figure (relative to gp_dir)
#   x_col, x_label, x_log          the first swept parameter's column and name; 1: log axis
#   n_keys, key_col[k], key_title[k]   the key results plotted: columns, panel titles
#   n_groups, group_title[g]       the curves: the combinations of the other swept values
# The summary lists the cases in case order, the last SWEEP varying fastest, so curve g is
# every n_groups-th row from row g (every n_groups::g-1); gnuplot 5.4 has no row filter that
# keeps a curve unbroken. A failed case has empty fields: no point there. A variable
# png_override (gnuplot -e) replaces response_png (fricon renders to a temporary name).
png = exists("png_override") ? png_override : response_png
n_cols = (n_keys < 4) ? n_keys : 4
n_rows = int((n_keys + n_cols - 1)/n_cols)
key_rows = (n_groups > 1) ? int((n_groups + 5)/6) : 0
set terminal pngcairo size 1600, 300*n_rows + 120 + 30*key_rows font 'Sans,10' noenhanced
set output png
set datafile separator comma
bottom = (60.0 + 30*key_rows)/(300*n_rows + 120 + 30*key_rows)
set multiplot layout n_rows, n_cols title title font 'Sans,14' \
    margins 0.05, 0.98, bottom, 1.0 - 70.0/(300*n_rows + 120 + 30*key_rows) spacing 0.06, 0.1
set grid
set format y '%g'
set xlabel x_label offset 0, 0.5
if (x_log) { set logscale x; set format x '%g' }
set autoscale xfix
set offsets graph 0.04, graph 0.04, graph 0.08, graph 0.08

# 12 distinguishable colours and point types; one per curve
array palette[12] = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', \
                     '#e377c2', '#17becf', '#000000', '#bcbd22', '#7f7f7f', '#0b3d91']
colour(g) = palette[(g - 1)%12 + 1]
marker(g) = (g - 1)%12 + 4

do for [k=1:n_keys] {
    set title key_title[k]
    if (k == 1 && n_groups > 1) {
        set key at screen 0.5, 0.01 center bottom horizontal maxrows key_rows width 2 \
            samplen 3 spacing 1.2 font ',10' box opaque
    } else {
        unset key
    }
    plot for [g=1:n_groups] summary skip 2 every n_groups::(g - 1) \
        u (column(x_col)):(column(key_col[k])) smooth unique \
        w lp lw 2 pt marker(g) ps 1.1 lc rgb colour(g) t group_title[g]
}
unset multiplot
