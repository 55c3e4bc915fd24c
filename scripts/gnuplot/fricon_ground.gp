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
