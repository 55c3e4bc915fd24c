# fricon sweep figure: gnuplot fig09_p2_18_sweep.gp draws fig09_p2_18_sweep.png (from any folder)
gp_dir = ''
do for [i_ = strlen(ARG0):1:-1] { if (gp_dir eq '' && ARG0[i_:i_] eq '/') { gp_dir = ARG0[1:i_] } }
model = 'BEAM'
csv = 0
# columns of the data file (station column table)
c_x = 1
c_w = 3
c_gap = 7
c_p = 6
c_s = 5
c_state = 9
c_slip = 8
c_m = 11
c_mt = 0
c_q = 12
c_n = 10
c_nt = 0
# axis labels and legend names
lab_x = 't = x/l'
lab_w = 'settlement W'
lab_p = 'contact pressure Sigma_z'
lab_s = 'shear traction Sigma_x'
lab_slip = 'slip u_b - u_f'
lab_m = 'bending moment M/(Fl)'
lab_q = 'shear force Q/F'
lab_n = 'axial force N/F'
lab_mr = 'bending moment M/(Fl)'
lab_mt = ''
key_w = 'W'
key_p = 'Sigma_z'
key_s = 'Sigma_x'
key_slip = 'slip'
key_m = 'M/(Fl)'
key_mt = ''
key_q = 'Q/F'
key_n = 'N/F'
key_nt = ''
p_unit = ''
line_width = 0.00000000000000E+000
lab_line = ''
# clip rule: p_clip = max(clip_factor p_mean, clip_inner x the largest pressure
# at least edge_d from a free edge); p_mean = V / contact area, edge_d = h
p_mean = 1.64289788933257E+000
clip_factor = 1.50000000000000E+000
clip_inner = 1.25000000000000E+000
edge_d = 1.00000000000000E-001
friction = 6.00000000000000E-001
# loads: P point, M moment, R ring, D patch [load_x1, load_x2] (plotted unit)
n_loads = 1
array load_kind[1] = ['P']
array load_x1[1] = [0.00000000000000E+000]
array load_x2[1] = [0.00000000000000E+000]
files = ''
labels = ''
p_means = ''
files = files.' '.gp_dir.'fig09_p2_18_001.dat'
labels = labels." 'RHO=0.00025'"
p_means = p_means.' 1.64289788933257E+000'
files = files.' '.gp_dir.'fig09_p2_18_002.dat'
labels = labels." 'RHO=0.0025'"
p_means = p_means.' 1.06273062730627E+000'
sweep_png = gp_dir.'fig09_p2_18_sweep.png'
title = 'fricon: Fig. 9 (P2, 93 unknowns): N_e 18, U P1, W psi P2 (sweep)'
# fricon sweep figure: the cases of a SWEEP deck overlaid, six panels, one colour per case.
# fricon writes output/STEM_sweep.gp with the settings of the first solved case (columns c_*,
# labels lab_*, key_*, p_unit, clip_factor, edge_d and the load arrays, as described in
# fricon_panels.gp), sweep_png, title and model, then this template; it defines
#   files   = "a.csv b.csv ..."         (whitespace-separated data files)
#   labels  = "'RHO=0.001 F=0' ..."     (one quoted phrase per file: the legend)
#   p_means = "v1 v2 ..."               (mean contact pressure of each case; optional)
# (scripts/paper.sh instead calls  call 'scripts/gnuplot/fricon_sweep.gp' PNG TITLE MODEL)
# Without the case settings (e.g. scripts/paper.sh) the files are nondimensional .dat files
# in the column layout of README (t U W Psi Sigma_x Sigma_z gap slip state, then resultants);
# c_s and c_p, if defined, choose the shear-traction and pressure columns.
# A variable png_override (gnuplot -e) replaces PNG (fricon renders to a temporary name).
# Pressure clip (the rule of fricon_panels.gp over all cases): max(clip_factor * the largest
# mean pressure of the cases, clip_inner * the largest station pressure at least edge_d from a
# free edge); clipped stations are marked with a triangle on the clip line.
# fricon writes sweep_png, title and model into the sweep script; paper.sh passes them as
# the arguments of a call
if (!exists("sweep_png")) { sweep_png = ARG1; title = ARG2; model = ARG3 }
png = exists("png_override") ? png_override : sweep_png
is_beam = (model eq 'BEAM')
if (!exists("c_x")) {
    csv = 0
    c_x = 1; c_w = 3; c_state = 9; c_slip = 8
    # the tractions may be chosen by the caller (scripts/paper.sh: the finite-element columns)
    if (!exists("c_s")) { c_s = 5 }
    if (!exists("c_p")) { c_p = 6 }
    if (is_beam) { c_m = 11; c_mt = 0; c_q = 12 } else { c_m = 12; c_mt = 13; c_q = 14 }
    lab_x = is_beam ? 't = x/l' : 't = r/a'
    lab_w = 'settlement W'; lab_p = 'contact pressure Sigma_z'; lab_s = 'shear traction Sigma_x'
    lab_slip = 'slip'
    lab_mr = is_beam ? 'bending moment M/(Fl)' : 'radial moment M_r/F'
    lab_mt = 'hoop moment M_theta/F'
    lab_q = is_beam ? 'shear force Q/F' : 'radial shear force Q_r*a/F'
    key_mt = 'M_theta/F'
    p_unit = ''
    clip_factor = 1.5
    clip_inner = 1.25
    edge_d = 0
    n_loads = 0
}
if (!exists("p_means")) { p_means = '' }
set terminal pngcairo size 1600,1150 font 'Sans,11' noenhanced
set output png
if (csv) { set datafile separator comma; skip_rows = 1 } else { set datafile separator whitespace; skip_rows = 0 }
n = words(files)

# 12 distinguishable colours; dash types change after every 12 cases
array palette[12] = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', \
                     '#e377c2', '#17becf', '#000000', '#bcbd22', '#7f7f7f', '#0b3d91']
colour(i) = palette[(i - 1)%12 + 1]
dash(i) = (i - 1)/12%5 + 1

# ---- clip level over all cases -----------------------------------------------------------
p_clip = 0
p_top = 0
do for [i=1:n] {
    f = word(files, i)
    stats f skip skip_rows u c_x nooutput
    x_lo = STATS_min; x_hi = STATS_max
    stats f skip skip_rows u ((column(c_x) > x_hi - edge_d || (is_beam && column(c_x) < x_lo + edge_d)) ? 0 : column(c_p)) nooutput
    if (clip_inner*STATS_max > p_clip) { p_clip = clip_inner*STATS_max }
    stats f skip skip_rows u c_p nooutput
    if (STATS_max > p_top) { p_top = STATS_max }
    if (words(p_means) >= i) { if (clip_factor*real(word(p_means, i)) > p_clip) { p_clip = clip_factor*real(word(p_means, i)) } }
}
p_cut = (p_top > p_clip*1.0001)
clip_p(v) = (v > p_clip) ? p_clip : v

# ---- loads ---------------------------------------------------------------------------------
c_load = '#e07000'
do for [k=1:n_loads] {
    if (load_kind[k] eq 'D') {
        set object 100+k rect from first load_x1[k], graph 0.955 to first load_x2[k], graph 1 \
            front fc rgb c_load fs solid 0.55 noborder
    } else {
        set arrow 100+2*k from first load_x1[k], graph 0 to first load_x1[k], graph 1 nohead back dt 2 lw 1.2 lc rgb c_load
    }
}

# ---- layout: six panels, one legend below them all -------------------------------------------
key_rows = int((n + 3)/4)
bottom = 0.05 + 0.032*key_rows
set multiplot layout 3,2 title title font 'Sans,14' margins 0.07,0.97,bottom,0.91 spacing 0.08,0.09
set grid
set format y '%g'
set xlabel lab_x offset 0,0.5
set autoscale xfix
set offsets 0, 0, graph 0.08, graph 0.05
zero_line = "0 w l lw 1 lc rgb '#606060' notitle"

set title 'Settlement (down positive)'
set ylabel lab_w
set yrange [*:*] reverse
set key at screen 0.5, 0.012 center bottom horizontal maxrows key_rows width 2 samplen 3 spacing 1.25 font ',10' box opaque
plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_w w l lw 2 lc rgb colour(i) dt dash(i) t word(labels, i)
set yrange [*:*] noreverse
unset key

set title p_cut ? sprintf('Contact pressure (clipped at %.4g %s; red triangles: clipped)', p_clip, p_unit) : 'Contact pressure'
set ylabel lab_p
plot for [i=1:n] word(files, i) skip skip_rows u c_x:(clip_p(column(c_p))) w l lw 2 lc rgb colour(i) dt dash(i) notitle, \
     for [i=1:n] word(files, i) skip skip_rows u c_x:((column(c_p) > p_clip*1.0001) ? p_clip : 1/0) w p pt 9 ps 1.5 lc rgb '#c00000' notitle, \
     @zero_line

set title 'Shear traction on the soil'
set ylabel lab_s
# every case frictionless (sigma_x = 0): a fixed axis, not gnuplot's "empty y range" warning
s_any = 0
do for [i=1:n] {
    stats word(files, i) skip skip_rows u (abs(column(c_s))) nooutput
    s_any = (STATS_max > s_any) ? STATS_max : s_any
}
if (s_any == 0) { set yrange [-1:1] }
plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_s w l lw 2 lc rgb colour(i) dt dash(i) notitle, @zero_line
set yrange [*:*]

set title 'Bending moment '.(c_mt > 0 ? 'M_r' : 'M').' (> 0 hogging)'
set ylabel lab_mr
plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_m w l lw 2 lc rgb colour(i) dt dash(i) notitle, @zero_line

if (c_mt > 0) {
    set title 'Hoop moment M_theta (> 0 hogging)'
    set ylabel lab_mt
    plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_mt w l lw 2 lc rgb colour(i) dt dash(i) notitle, @zero_line
} else {
    set title 'Interface slip'
    set ylabel lab_slip
    plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_slip w l lw 2 lc rgb colour(i) dt dash(i) notitle, @zero_line
}

set title 'Shear force'
set ylabel lab_q
plot for [i=1:n] word(files, i) skip skip_rows u c_x:c_q w l lw 2 lc rgb colour(i) dt dash(i) notitle, @zero_line
unset multiplot
