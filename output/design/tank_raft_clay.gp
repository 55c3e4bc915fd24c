# fricon figure of case tank_raft_clay: gnuplot tank_raft_clay.gp draws tank_raft_clay.png (from any folder)
gp_dir = ''
do for [i_ = strlen(ARG0):1:-1] { if (gp_dir eq '' && ARG0[i_:i_] eq '/') { gp_dir = ARG0[1:i_] } }
data = gp_dir.'tank_raft_clay.csv'
png = exists("png_override") ? png_override : gp_dir.'tank_raft_clay.png'
title = 'fricon: Tank raft on 12 m of clay over stiff gravel'
model = 'PLATE'
csv = 1
# columns of the data file (station column table)
c_x = 1
c_w = 3
c_gap = 7
c_p = 6
c_s = 5
c_state = 9
c_slip = 8
c_m = 12
c_mt = 13
c_q = 14
c_n = 10
c_nt = 11
# axis labels and legend names
lab_x = 'r [m]'
lab_w = 'settlement w [mm]'
lab_p = 'contact pressure sigma_z [kPa]'
lab_s = 'shear traction sigma_x [kPa]'
lab_slip = 'slip u_b - u_f [mm]'
lab_m = 'moments M_r, M_theta [kN.m/m]'
lab_q = 'radial shear force Q_r [kN/m]'
lab_n = 'membrane forces N_r, N_theta [kN/m]'
lab_mr = 'radial moment M_r [kN.m/m]'
lab_mt = 'hoop moment M_theta [kN.m/m]'
key_w = 'w'
key_p = 'sigma_z'
key_s = 'sigma_x'
key_slip = 'slip'
key_m = 'M_r'
key_mt = 'M_theta'
key_q = 'Q_r'
key_n = 'N_r'
key_nt = 'N_theta'
p_unit = 'kPa'
line_width = 0.00000000000000E+000
lab_line = ''
# clip rule: p_clip = max(clip_factor p_mean, clip_inner x the largest pressure
# at least edge_d from a free edge); p_mean = V / contact area, edge_d = h
p_mean = 1.03040093256555E+002
clip_factor = 1.50000000000000E+000
clip_inner = 1.25000000000000E+000
edge_d = 6.00000000000000E-001
friction = 5.00000000000000E-001
# loads: P point, M moment, R ring, D patch [load_x1, load_x2] (plotted unit)
n_loads = 2
array load_kind[2] = ['R', 'D']
array load_x1[2] = [9.60000000000000E+000, 0.00000000000000E+000]
array load_x2[2] = [9.60000000000000E+000, 1.00000000000000E+001]
# ground profile from the surface down: depth of each layer's top and bottom, E there, nu; the base
n_layers = 1
array layer_z1[1] = [0.00000000000000E+000]
array layer_z2[1] = [1.20000000000000E+001]
array layer_e1[1] = [8.00000000000000E+003]
array layer_e2[1] = [8.00000000000000E+003]
array layer_nu[1] = [4.50000000000000E-001]
base_kind = 'HALFSPACE'
base_e = 2.00000000000000E+005
base_nu = 3.00000000000000E-001
lab_depth = 'depth z [m]'
z_unit = ' m'
e_unit = ' kPa'
struct_h = 6.00000000000000E-001
# fricon figure of one case: six panels from the station file of the case.
# fricon writes output/CASE.gp: the settings below, then this template (embedded in the
# program, src/output/figure_templates.f90, by scripts/embed_templates.sh). The settings are:
#   data, png, title, model ('BEAM' or 'PLATE'), csv (1: comma-separated with one header line,
#   0: the whitespace .dat with '#' comments),
#   column numbers c_x c_w c_gap c_p c_s c_state c_m c_mt c_q c_slip c_n c_nt (0: no such column;
#   taken by fricon from its station column table),
#   axis labels lab_x lab_w lab_p lab_s lab_m (lab_mr, lab_mt: sweep) lab_q lab_slip lab_n,
#   legend names key_w key_p
#   key_s key_m key_mt key_q key_slip key_n key_nt, the pressure unit p_unit,
#   line_width (beam width b: right axis of the pressure panel in line load; 0: none), lab_line,
#   p_mean (mean contact pressure V / contact area, plotted unit), clip_factor, clip_inner,
#   edge_d (the summary's edge distance, plotted unit), friction (f),
#   n_loads and the arrays load_kind ('P' point, 'M' moment, 'R' ring, 'D' patch), load_x1,
#   load_x2 (plotted unit).
#
# Clip rule (pressure panel): the curve is clipped at
#   p_clip = max(clip_factor * p_mean, clip_inner * largest station pressure at least edge_d
#            from a free edge)
# so only the edge spike within edge_d of an edge (where the singularity of the half-space and
# the mesh decide the value) can be cut, and every pressure away from the edges stays whole;
# a clipped station is drawn as a red triangle on the clip line and the true peak of each
# clipped end is written in the legend. The shear traction is clipped the same way at
# max(f * p_clip, clip_inner * largest |traction| at least edge_d from a free edge).

set terminal pngcairo size 1600,1100 font 'Sans,11' noenhanced
set output png
if (csv) { set datafile separator comma; skip_rows = 1 } else { set datafile separator whitespace; skip_rows = 0 }
set datafile missing NaN

# ---- edges, clip levels ------------------------------------------------------------------
stats data skip skip_rows u c_x nooutput
x_lo = STATS_min
x_hi = STATS_max
is_beam = (model eq 'BEAM')
near_edge(x) = (x > x_hi - edge_d) || (is_beam && x < x_lo + edge_d)
stats data skip skip_rows u (near_edge(column(c_x)) ? 0 : column(c_p)) nooutput
p_inner = clip_inner*STATS_max
stats data skip skip_rows u c_x:c_p nooutput
p_top = STATS_max_y
p_clip = (clip_factor*p_mean > p_inner) ? clip_factor*p_mean : p_inner
p_rule = (clip_factor*p_mean > p_inner) ? sprintf('%g x mean %.4g', clip_factor, p_mean) : sprintf('%g x largest value away from the edges', clip_inner)
p_cut = (p_top > p_clip*1.0001)
stats data skip skip_rows u (near_edge(column(c_x)) ? 0 : abs(column(c_s))) nooutput
s_inner = clip_inner*STATS_max
stats data skip skip_rows u (abs(column(c_s))) nooutput
s_top = STATS_max
s_clip = (friction*p_clip > s_inner) ? friction*p_clip : s_inner
s_cut = (s_top > s_clip*1.0001) && (s_clip > 1e-6*p_clip)
if (!s_cut && s_top > s_clip) s_clip = s_top
clip_p(v) = (v > p_clip) ? p_clip : v
clip_s(v) = (v > s_clip) ? s_clip : ((v < -s_clip) ? -s_clip : v)
x_mid = is_beam ? 0.5*(x_lo + x_hi) : x_lo - 1

# ---- lift-off zones (state 0), from one pass over the stations ------------------------------
zones = ''
prev_state = -1
prev_x = 0
zone_start = 0
stats data skip skip_rows u (st = column(c_state), xx = column(c_x), \
    ((st == 0 && prev_state != 0) ? (zone_start = (prev_state < 0) ? xx : 0.5*(xx + prev_x)) : 0), \
    ((st != 0 && prev_state == 0) ? (zones = zones.sprintf(' %.12e %.12e', zone_start, 0.5*(xx + prev_x))) : 0), \
    prev_state = st, prev_x = xx, 0) nooutput
if (prev_state == 0) { zones = zones.sprintf(' %.12e %.12e', zone_start, prev_x) }
n_zones = words(zones)/2
do for [k=1:n_zones] {
    set object k rect from first real(word(zones, 2*k-1)), graph 0 to first real(word(zones, 2*k)), graph 1 \
        behind fc rgb '#c8c8c8' fs solid 0.45 noborder
}

# ---- loads: dashed orange verticals (point, ring, moment), an orange band on top (patch) ----
c_load = '#e07000'
c_load_text = '#8a3b00'   # the load words: dark enough to read on the band's colour
do for [k=1:n_loads] {
    if (load_kind[k] eq 'D') {
        set object 100+k rect from first load_x1[k], graph 0.955 to first load_x2[k], graph 1 \
            front fc rgb c_load fs solid 0.55 noborder
        set arrow 100+2*k from first load_x1[k], graph 0 to first load_x1[k], graph 1 nohead back dt 3 lw 1 lc rgb c_load
        set arrow 101+2*k from first load_x2[k], graph 0 to first load_x2[k], graph 1 nohead back dt 3 lw 1 lc rgb c_load
    } else {
        set arrow 100+2*k from first load_x1[k], graph 0 to first load_x1[k], graph 1 nohead back dt 2 lw 1.5 lc rgb c_load
        set arrow 101+2*k from first load_x1[k], graph 1 to first load_x1[k], graph 0.93 head filled size graph 0.012,25 front lw 2 lc rgb c_load
    }
}
# the kind of each concentrated load, written beside its arrow on the settlement panel
load_word(k) = (load_kind[k] eq 'P') ? 'P' : (load_kind[k] eq 'R') ? 'ring' : (load_kind[k] eq 'M') ? 'M' : ''
# (a moment's left of its arrow, a force's right of it, so that both at one x stay apart; a
# force in the right tenth, where its word would run into the frame, goes left one line lower)
do for [k=1:n_loads] {
    if (load_kind[k] eq 'M') {
        set label 300+k load_word(k) at first load_x1[k], graph 0.955 right offset -0.6,0 front tc rgb c_load_text
    } else {
        if (load_x1[k] > x_hi - 0.1*(x_hi - x_lo)) {
            set label 300+k load_word(k) at first load_x1[k], graph 0.955 right offset -0.6,-1 front tc rgb c_load_text
        } else {
            set label 300+k load_word(k) at first load_x1[k], graph 0.955 left offset 0.6,0 front tc rgb c_load_text
        }
    }
}

# fricon figure of a case on layered ground: the panels of fricon_panels.gp in two columns and
# the ground profile beside them, in a third. fricon writes output/CASE.gp for such a case as
# the settings, then fricon_panels.gp with two changes taken from this template: the lines up
# to the marker line below stand in place of its `set multiplot layout` line, and the lines
# after the marker come just before its `unset multiplot`. (A case on a homogeneous
# half-space, SOIL, gets fricon_panels.gp unchanged.)
# Settings beside those of fricon_panels.gp (written for layered cases only):
#   n_layers and the arrays layer_z1, layer_z2 (depth of each layer's top and bottom, the
#   plotted length unit), layer_e1, layer_e2 (Young's modulus at them, e_unit), layer_nu;
#   base_kind ('ROUGH', 'SMOOTH' or 'HALFSPACE'), base_e, base_nu (of a HALFSPACE base);
#   lab_depth (depth axis label), z_unit and e_unit (written after a thickness or a modulus,
#   e.g. ' m' and ' kPa'; NONDIM: ' a' and ' E_f'), struct_h (the structure's thickness).
# The profile is a section: the structure on the ground's surface (x as in the panels, depth
# down), each layer shaded by its modulus (darker is stiffer; a modulus varying with depth
# as a gradient) and labelled with its thickness, modulus and Poisson's ratio, the base below.

set terminal pngcairo size 2200,1100 font 'Sans,11' noenhanced
set multiplot layout 3,3 columnsfirst title title."\n" font 'Sans,14'
set grid
set format y '%g'
set format y2 '%g'
set key outside top center horizontal samplen 2.5 font ',10' spacing 1.0 nobox
set autoscale xfix
set xrange [x_lo:x_hi]
set xlabel lab_x
set lmargin 12
set rmargin 11
set offsets 0, 0, graph 0.10, graph 0.06
zero_line = "0 w l lw 1 lc rgb '#606060' notitle"
dummy_zone = (n_zones > 0) ? "NaN w boxes fs solid 0.45 noborder fc rgb '#c8c8c8' t 'lift-off zone'" : "NaN notitle"
dummy_load = "NaN w l dt 2 lw 1.5 lc rgb c_load t 'load position'"

# 1 settlement, down positive; soil surface where it leaves the structure
set title 'Settlement (down positive)'
set ylabel lab_w
set yrange [*:*] reverse
plot data skip skip_rows u c_x:c_w w lp pt 7 ps 0.45 lw 2 lc rgb '#1f77b4' t key_w.' (structure)', \
     '' skip skip_rows u c_x:(column(c_w) + column(c_gap)) w l dt 2 lw 1.5 lc rgb '#404040' t 'soil surface', \
     @dummy_zone, @dummy_load
set yrange [*:*] noreverse
do for [k=1:n_loads] { unset label 300+k }

# 2 contact pressure, edge spike clipped and marked
set title p_cut ? sprintf('Contact pressure (clipped at %.4g %s: %s)', p_clip, p_unit, p_rule) : 'Contact pressure'
set ylabel lab_p
if (line_width > 0) {
    set y2label lab_line
    # gnuplot 5.4 draws no automatic tics on a linked axis whose primary range is below 1
    # (a pressure in MPa): a step of 1, 2 or 5 times a power of ten, about 5 tics
    y2_top = line_width*((p_top < p_clip) ? p_top : p_clip)
    y2_raw = (y2_top > 0) ? y2_top/5.0 : 1.0
    y2_mag = 10.0**floor(log10(y2_raw))
    y2_step = y2_mag*((y2_raw/y2_mag < 1.5) ? 1 : (y2_raw/y2_mag < 3.5) ? 2 : \
                      (y2_raw/y2_mag < 7.5) ? 5 : 10)
    set y2tics y2_step
    set ytics nomirror
    set link y2 via y*line_width inverse y/line_width
}
# the true peaks are written in the legend, where no curve can cross them (beside their
# markers a steep curve did, and an opaque box hid the curve)
p_peaks = ''
if (p_cut) {
    stats data skip skip_rows u c_x:((column(c_x) < x_mid) ? 1/0 : column(c_p)) nooutput
    p_right = STATS_max_y
    p_left = 0
    if (is_beam) {
        stats data skip skip_rows u c_x:((column(c_x) < x_mid) ? column(c_p) : 1/0) nooutput
        p_left = STATS_max_y
    }
    # only the ends that are clipped: a beam loaded at one end has one spike
    if (p_left > p_clip*1.0001 && p_right > p_clip*1.0001) {
        p_peaks = sprintf('%.4g (left), %.4g %s (right)', p_left, p_right, p_unit)
    } else {
        p_peaks = sprintf('%.4g %s', (p_left > p_right) ? p_left : p_right, p_unit)
    }
}
clip_marks = p_cut ? "data skip skip_rows u c_x:((column(c_p) > p_clip*1.0001) ? p_clip : 1/0) w p pt 9 ps 1.8 lc rgb '#c00000' t 'clipped, peak '.p_peaks" : "NaN notitle"
plot data skip skip_rows u c_x:(clip_p(column(c_p))) w lp pt 7 ps 0.45 lw 2 lc rgb '#d62728' t key_p, \
     @clip_marks, @zero_line, @dummy_zone, @dummy_load
unset y2label
unset y2tics
unset link y2
set ytics mirror

# 3 shear traction with the friction limit +-f p. The limit is drawn unclipped in a y range
# fixed at 1.15 times the clip level: where it leaves the frame it is seen to lie above the
# clipped markers (both clipped to one level, a sticking station looked as if on the limit).
# The true peak is written in the legend; slipping stations are marked over clipped ones.
set title s_cut ? sprintf('Shear traction on the soil (clipped at %.4g %s)', s_clip, p_unit) : 'Shear traction on the soil'
set ylabel lab_s
s_peak = 0
if (s_cut) {
    stats data skip skip_rows u (abs(column(c_s))) nooutput
    s_peak = STATS_max
}
stats data skip skip_rows u (column(c_state) == 2 ? 1 : 0) nooutput
n_slip = STATS_sum
# (after the stats: stats keeps to the axis ranges)
s_span = (s_clip > 0) ? 1.15*s_clip : 1
set yrange [-s_span:s_span]
slip_marks = (n_slip > 0) ? "data skip skip_rows u c_x:((column(c_state) == 2) ? clip_s(column(c_s)) : 1/0) w p pt 6 ps 1.1 lc rgb '#ff7f0e' t 'slipping station'" : "NaN notitle"
clip_marks = s_cut ? "data skip skip_rows u c_x:((abs(column(c_s)) > s_clip*1.0001) ? clip_s(column(c_s)) : 1/0) w p pt 9 ps 1.8 lc rgb '#c00000' t sprintf('clipped, peak %.4g %s', s_peak, p_unit)" : "NaN notitle"
envelope = (friction > 0) ? "data skip skip_rows u c_x:(friction*column(c_p)) w l dt 3 lw 1.2 lc rgb '#505050' t sprintf('+-f %s (f = %g)', key_p, friction), data skip skip_rows u c_x:(-friction*column(c_p)) w l dt 3 lw 1.2 lc rgb '#505050' notitle" : "NaN notitle"
plot data skip skip_rows u c_x:(clip_s(column(c_s))) w lp pt 7 ps 0.45 lw 2 lc rgb '#2ca02c' t key_s, \
     @clip_marks, @slip_marks, @envelope, @zero_line, @dummy_zone, @dummy_load
set yrange [*:*]

# 4 bending moments
set title 'Bending moment (> 0 hogging, top in tension)'
set ylabel lab_m
if (c_mt > 0) {
    plot data skip skip_rows u c_x:c_m w lp pt 7 ps 0.45 lw 2 lc rgb '#9467bd' t key_m, \
         '' skip skip_rows u c_x:c_mt w lp pt 5 ps 0.45 lw 2 dt 2 lc rgb '#8c564b' t key_mt, \
         @zero_line, @dummy_zone, @dummy_load
} else {
    plot data skip skip_rows u c_x:c_m w lp pt 7 ps 0.45 lw 2 lc rgb '#9467bd' t key_m, \
         @zero_line, @dummy_zone, @dummy_load
}

# 5 shear force
set title 'Shear force'
set ylabel lab_q
plot data skip skip_rows u c_x:c_q w lp pt 7 ps 0.45 lw 2 lc rgb '#17becf' t key_q, \
     @zero_line, @dummy_zone, @dummy_load

# 6 slip (left axis) and membrane / axial force (right axis)
set title 'Interface slip and axial force'
set ylabel lab_slip
stats data skip skip_rows u (abs(column(c_w))) nooutput
slip_span = 0.01*STATS_max
set yrange [*<-slip_span:slip_span<*]
set y2label lab_n
set y2tics autofreq
set ytics nomirror
set autoscale y2
# a structure with no membrane force (f = 0: no shear traction) gets a fixed axis, not
# gnuplot's "empty y2 range" warning
stats data skip skip_rows u (abs(column(c_n)) + (c_nt > 0 ? abs(column(c_nt)) : 0)) nooutput
if (STATS_max == 0) { set y2range [-1:1] }
if (c_nt > 0) {
    plot data skip skip_rows u c_x:c_slip w lp pt 7 ps 0.45 lw 2 lc rgb '#bcbd22' t key_slip, \
         '' skip skip_rows u c_x:c_n axes x1y2 w l lw 1.5 lc rgb '#1f3f7f' t key_n, \
         '' skip skip_rows u c_x:c_nt axes x1y2 w l lw 1.5 dt 2 lc rgb '#7f1f3f' t key_nt, \
         @zero_line, @dummy_zone, @dummy_load
} else {
    plot data skip skip_rows u c_x:c_slip w lp pt 7 ps 0.45 lw 2 lc rgb '#bcbd22' t key_slip, \
         '' skip skip_rows u c_x:c_n axes x1y2 w l lw 1.5 lc rgb '#1f3f7f' t key_n, \
         @zero_line, @dummy_zone, @dummy_load
}
# ---- the profile panel (before the panels' unset multiplot) ----
unset object
unset arrow
unset label
unset key
unset y2label
unset y2tics
unset x2tics
set ytics mirror
set xtics mirror
set grid noxtics noytics
set lmargin at screen 0.712
set rmargin at screen 0.975
set tmargin at screen 0.885
set bmargin at screen 0.075
set offsets 0, 0, 0, 0
z_base = layer_z2[n_layers]
z_band = 0.12*z_base
x_span = x_hi - x_lo
g_lo = is_beam ? x_lo - 0.3*x_span : x_lo
g_hi = is_beam ? x_hi + 0.3*x_span : x_hi + 0.8*x_span
set xrange [g_lo:g_hi]
set yrange [z_base + z_band:-(struct_h + 0.06*z_base)]
set xlabel lab_x
set ylabel lab_depth
set title 'Ground profile (' . n_layers . (n_layers > 1 ? ' layers' : ' layer') . ' over ' . \
    ((base_kind eq 'HALFSPACE') ? 'an elastic half-space)' : 'a rigid base)')
# shade of a modulus: 0 for the softest of the profile, 1 for the stiffest (log scale)
e_lo = layer_e1[1]
e_hi = layer_e1[1]
do for [k=1:n_layers] {
    e_lo = (layer_e1[k] < e_lo) ? layer_e1[k] : e_lo
    e_lo = (layer_e2[k] < e_lo) ? layer_e2[k] : e_lo
    e_hi = (layer_e1[k] > e_hi) ? layer_e1[k] : e_hi
    e_hi = (layer_e2[k] > e_hi) ? layer_e2[k] : e_hi
}
if (base_kind eq 'HALFSPACE') {
    e_lo = (base_e < e_lo) ? base_e : e_lo
    e_hi = (base_e > e_hi) ? base_e : e_hi
}
shade(e) = (e_hi > e_lo*1.0001) ? log(e/e_lo)/log(e_hi/e_lo) : 0.5
# from a light sand colour (soft) to a slate blue (stiff)
mix(a, b, t) = int(a + (b - a)*t + 0.5)
soil_rgb(t) = mix(236, 96, t)*65536 + mix(214, 118, t)*256 + mix(170, 150, t)
# a layer of constant modulus is one strip, a varying one 24 (each drawn over the top of the
# next, so that no seam shows between them)
do for [k=1:n_layers] {
    n_strips = (layer_e2[k] != layer_e1[k]) ? 24 : 1
    do for [j=1:n_strips] {
        za = layer_z1[k] + (j - 1)*(layer_z2[k] - layer_z1[k])/n_strips
        zb = layer_z1[k] + ((j < n_strips) ? j + 0.5 : j)*(layer_z2[k] - layer_z1[k])/n_strips
        ej = layer_e1[k] + (j - 0.5)*(layer_e2[k] - layer_e1[k])/n_strips
        set object (1000 + 24*k + j) rect from graph 0, first za to graph 1, first zb \
            behind fc rgb soil_rgb(shade(ej)) fs solid 1.0 noborder
    }
    if (k > 1) {
        set arrow (2000 + k) from graph 0, first layer_z1[k] to graph 1, first layer_z1[k] \
            nohead front lw 1 lc rgb '#404040'
    }
    e_words = (layer_e2[k] != layer_e1[k]) ? \
        sprintf('E = %g to %g%s (linear)', layer_e1[k], layer_e2[k], e_unit) : \
        sprintf('E = %g%s', layer_e1[k], e_unit)
    set label (2000 + k) sprintf("layer %d: h = %g%s\n%s, nu = %g", k, \
        layer_z2[k] - layer_z1[k], z_unit, e_words, layer_nu[k]) \
        at graph 0.03, first 0.5*(layer_z1[k] + layer_z2[k]) left front \
        textcolor rgb ((shade(0.5*(layer_e1[k] + layer_e2[k])) > 0.6) ? '#ffffff' : '#000000')
}
if (base_kind eq 'HALFSPACE') {
    set object 1999 rect from graph 0, first z_base to graph 1, graph 0 behind \
        fc rgb soil_rgb(shade(base_e)) fs solid 1.0 noborder
    base_words = sprintf('elastic half-space below %g%s: E = %g%s, nu = %g', z_base, z_unit, \
        base_e, e_unit, base_nu)
} else {
    set object 1999 rect from graph 0, first z_base to graph 1, graph 0 behind \
        fc rgb '#5a5a5a' fs solid 1.0 noborder
    base_words = sprintf('rigid base at %g%s, %s', z_base, z_unit, \
        (base_kind eq 'ROUGH') ? 'rough (bonded)' : 'smooth (frictionless)')
}
set arrow 2000 from graph 0, first z_base to graph 1, first z_base nohead front lw 2 lc rgb '#202020'
dark_base = (base_kind ne 'HALFSPACE') || (shade(base_e) > 0.5)
set label 2000 base_words at graph 0.03, first z_base + 0.5*z_band left front \
    textcolor rgb (dark_base ? '#ffffff' : '#000000')
# the structure on the surface, drawn to the depth scale (its thickness h)
set object 1998 rect from first x_lo, first -struct_h to first x_hi, first 0 front \
    fc rgb '#707070' fs solid 1.0 border lc rgb '#202020'
set label 1998 (is_beam ? 'beam' : 'plate') at first x_hi, first -0.5*struct_h \
    left offset 0.6,0 front
# the ground surface beyond the structure
set arrow 1998 from graph 0, first 0 to graph 1, first 0 nohead front lw 1.5 lc rgb '#202020'
plot NaN notitle
unset multiplot
