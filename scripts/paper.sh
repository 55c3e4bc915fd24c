#!/usr/bin/env bash
# Regenerate the paper studies of issue 3 (Bilotti & Olivito, figures 6-20 and Table 1).
#
#   bash scripts/paper.sh            (from anywhere; it works from the project root)
#
# 1. builds fricon (fpm build);
# 2. clears the generated files of output/paper/ (FINDINGS.md, hand-written, is kept);
# 3. runs every deck input/paper/*.dat as `fpm run -- DECK` would (one build, one private
#    copy of the executable); each deck writes its report, data, gnuplot script and PNG into
#    output/paper/ (a SWEEP deck: STEM_NNN.* per case, STEM_summary.csv and the overlay
#    STEM_sweep.png); the exit status of every deck is listed in output/paper/runs.txt
#    (0 solved, 2 a case failed: see its report);
# 4. post-processes the data files (awk, nothing is solved again) into
#      output/paper/key_values.txt   one line per case: parameters, values at t = 0,
#                                    extremes, contact region, unknowns;
#      output/paper/table1.txt       Table 1 of the paper against every Table 1 deck;
#      output/paper/errors.txt       Fig. 6 convergence, Fig. 7 and Fig. 9 errors against
#                                    the fine-mesh reference fig07_ref.dat;
#    and renders the cross-deck overlays fig07_compare_*.png and fig09_compare_*.png
#    (scripts/gnuplot/fricon_sweep.gp), table1_scan_fit.png (deviation from Table 1 over the
#    b/l, h/l scan) and plate_rho_zeta.png (plate settlement in soil units, rho vs zeta).
# output/paper/FINDINGS.md is written by hand from these files; this script does not touch it.
# Needs: fpm, gfortran, LAPACK, GSL, gnuplot (scripts/setup.sh), awk. Run time about a minute.
set -u
cd "$(dirname "$0")/.." || exit 1
out=output/paper
mkdir -p "$out"

# Build once and run every deck with a private copy of that executable, so that the whole set
# comes from one build even if the sources change while the script runs.
fpm build >/dev/null || { echo "paper.sh: fpm build failed" >&2; exit 1; }
exe=$(fpm run --runner echo 2>/dev/null | tail -n 1)
[ -x "$exe" ] || { echo "paper.sh: cannot locate the fricon executable ($exe)" >&2; exit 1; }
bin=$(mktemp "${TMPDIR:-/tmp}/fricon_paper.XXXXXX") || exit 1
trap 'rm -f "$bin"' EXIT
cp "$exe" "$bin" && chmod +x "$bin"

find "$out" -maxdepth 1 -type f \( -name '*.dat' -o -name '*.txt' -o -name '*.gp' \
    -o -name '*.png' -o -name '*.csv' -o -name '*.tmp' \) -delete

: >"$out/runs.txt"
failed=0
for deck in input/paper/*.dat; do
    echo "== $deck"
    "$bin" "$deck"
    status=$?
    printf '%-36s exit status %d\n' "$deck" "$status" >>"$out/runs.txt"
    [ "$status" -eq 0 ] || failed=$((failed + 1))
done

# ---------------------------------------------------------------------------------------
# key_values.txt: one line per case data file.
# ---------------------------------------------------------------------------------------
param() { # param REPORT PATTERN -> the number at the end of the first matching line
    awk -v p="$2" 'index($0, p) == 1 { print $NF; exit }' "$1"
}
{
    echo "# One line per solved case (output/paper/*.dat), written by scripts/paper.sh from the"
    echo "# reports and data files. t = 0 is the beam's middle section or the plate's axis."
    echo "# w_soil = settlement at t = 0 in soil units w E_f L/((1-nu_f^2) F) = 2 W(0)/rho (plate,"
    echo "# L = a) or 32 W(0)/(pi rho) (beam, L = l). extent: contact region [t_min, t_max] of the"
    echo "# stations whose finite-element pressure Sigma_z^h is positive; Sigma_x, Sigma_z are the"
    echo "# finite-element (nodal) values. dof: displacement unknowns (report 'unknowns')."
    printf '%-22s %-5s %-9s %-9s %-9s %-5s %-8s %-12s %-12s %-12s %-12s %-12s %-12s %-12s %-17s %s\n' \
        case model rho beta zeta f eps_bar 'W(0)' 'Sigma_x(0)' 'Sigma_z(0)' 'U(0)' \
        'max|Sigma_x|' 'max Sigma_z' w_soil extent dof
    for dat in "$out"/*_[0-9][0-9][0-9].dat "$out"/*[!0-9].dat; do
        [ -f "$dat" ] || continue
        rep=${dat%.dat}.txt
        [ -f "$rep" ] || continue
        case_name=$(basename "${dat%.dat}")
        model=$(awk '/^   model: /{print $2; exit}' "$rep")
        rho=$(param "$rep" '   rho = ')
        beta=$(param "$rep" '   beta = b/l')
        zeta=$(param "$rep" '   zeta = ')
        f=$(param "$rep" '   f (friction')
        eps=$(param "$rep" '   eps_bar (friction')
        dof=$(awk -F'displacements ' '/unknowns: displacements/{split($2, a, ","); print a[1]; exit}' "$rep")
        awk -v name="$case_name" -v model="$model" -v rho="$rho" -v beta="${beta:--}" \
            -v zeta="$zeta" -v f="$f" -v eps="$eps" -v dof="$dof" '
            # columns by name from the header line of symbols; the tractions are the
            # finite-element values Sigma_x^h, Sigma_z^h (the nodal values the paper prints)
            $1 == "#" && $2 == "t" { for (i = 2; i <= NF; i++) col[$i] = i - 1; next }
            /^#/ { next }
            $1 == t_prev && n > 0 { next }          # a load station listed twice
            {
                t_prev = $1
                U = $(col["U"]); W = $(col["W"]); SX = $(col["Sigma_x^h"]); SZ = $(col["Sigma_z^h"])
                t = $1 + 0; a = (t < 0 ? -t : t)
                if (n == 0 || a < best) { best = a; w0 = W; sx0 = SX; sz0 = SZ; u0 = U }
                sx = (SX < 0 ? -SX : SX); if (n == 0 || sx > mx) mx = sx
                if (n == 0 || SZ > mz) mz = SZ
                # contact extent from the finite-element nodal pressure (as the paper reads it)
                if (SZ > 0) { if (!c || t < lo) lo = t; if (!c || t > hi) hi = t; c = 1 }
                n++
            }
            END {
                ws = (model == "BEAM" ? 32 * w0 / (3.14159265358979 * rho) : 2 * w0 / rho)
                printf "%-22s %-5s %-9.4g %-9s %-9.4g %-5.3g %-8.1e %-12.5e %-12.5e %-12.5e %-12.5e %-12.5e %-12.5e %-12.5e [%6.3f,%6.3f] %s\n", \
                    name, model, rho, (beta == "-" ? "-" : sprintf("%.4g", beta)), zeta, f, eps, \
                    w0, sx0, sz0, u0, mx, mz, ws, lo, hi, dof
            }' "$dat"
    done
} >"$out/key_values.txt"

# ---------------------------------------------------------------------------------------
# table1.txt: Table 1 of the paper against the Table 1 decks (values at t = 0).
# ---------------------------------------------------------------------------------------
awk '
    BEGIN {
        # Paper Table 1 (eps_bar, W, Sigma_x, Sigma_z), middle section.
        pe[1] = 1e-1; pw[1] = 0.21138e-2; px[1] = 0.13397; pz[1] = 2.3934
        pe[2] = 1e-4; pw[2] = 0.21235e-2; px[2] = 0.14348; pz[2] = 2.4081
        pe[3] = 1e-7; pw[3] = 0.21235e-2; px[3] = 0.14348; pz[3] = 2.4082
        print "# Paper Table 1 (rho 0.0025, f 0.6, \"alpha = 0.1\", N_e 20, all P1) against fricon at t = 0."
        print "# dW, dSx, dSz: relative deviation (fricon/paper - 1) from the paper row of the same"
        print "# eps_bar; max: the largest |d|. Cases with an eps_bar that is not in Table 1"
        print "# (table1_eps_scale_002..006) are listed in the eps-scale block below."
        printf "%-22s %-9s %-9s %-8s %-12s %-10s %-10s %8s %8s %8s %7s\n", "case", "beta", "zeta", \
            "eps_bar", "W", "Sigma_x", "Sigma_z", "dW%", "dSx%", "dSz%", "max%"
        for (k = 1; k <= 3; k++)
            printf "%-22s %-9s %-9s %-8.0e %-12.5e %-10.5f %-10.4f\n", "paper", "?", "?", pe[k], pw[k], px[k], pz[k]
    }
    /^#/ || $1 !~ /^table1/ { next }
    {
        name = $1; beta = $4; zeta = $5; eps = $7 + 0; w = $8; sx = $9; sz = $10
        k = 0
        for (j = 1; j <= 3; j++) if (eps > 0.99 * pe[j] && eps < 1.01 * pe[j]) k = j
        if (k == 0) { extra[++ne] = $0; next }
        dw = 100 * (w / pw[k] - 1); dx = 100 * (sx / px[k] - 1); dz = 100 * (sz / pz[k] - 1)
        m = (dw < 0 ? -dw : dw); if ((dx < 0 ? -dx : dx) > m) m = (dx < 0 ? -dx : dx)
        if ((dz < 0 ? -dz : dz) > m) m = (dz < 0 ? -dz : dz)
        printf "%-22s %-9s %-9s %-8.0e %-12.5e %-10.5f %-10.4f %+8.2f %+8.2f %+8.2f %7.2f\n", \
            name, beta, zeta, eps, w, sx, sz, dw, dx, dz, m
        if (name == "table1_003") { w7 = w; x7 = sx; z7 = sz }
    }
    END {
        print ""
        print "# eps scale (table1_eps_scale.dat, the chosen reading): ratios to fricon eps_bar = 1e-7"
        print "# (table1_003) against the paper ratios row 1e-1 / row 1e-7, and the deviation of each"
        print "# case from the paper row eps_bar = 1e-1 (does the row fit at another eps_bar scale?)."
        printf "%-22s %-8s %-10s %-10s %-10s %8s %8s %8s %7s\n", "case", "eps_bar", "W/W7", "Sx/Sx7", \
            "Sz/Sz7", "dW%", "dSx%", "dSz%", "max%"
        printf "%-22s %-8s %-10.5f %-10.5f %-10.5f\n", "paper 1e-1/1e-7", "1e-1", pw[1] / pw[3], px[1] / px[3], pz[1] / pz[3]
        if (w7 != 0) {
            for (i = 1; i <= ne; i++) {
                split(extra[i], f, " ")
                if (f[1] !~ /^table1_eps_scale/) continue
                dw = 100 * (f[8] / pw[1] - 1); dx = 100 * (f[9] / px[1] - 1); dz = 100 * (f[10] / pz[1] - 1)
                m = (dw < 0 ? -dw : dw); if ((dx < 0 ? -dx : dx) > m) m = (dx < 0 ? -dx : dx)
                if ((dz < 0 ? -dz : dz) > m) m = (dz < 0 ? -dz : dz)
                printf "%-22s %-8.0e %-10.5f %-10.5f %-10.5f %+8.2f %+8.2f %+8.2f %7.2f\n", f[1], f[7], \
                    f[8] / w7, f[9] / x7, f[10] / z7, dw, dx, dz, m
            }
        }
    }' "$out/key_values.txt" >"$out/table1.txt"

# ---------------------------------------------------------------------------------------
# errors.txt: relative errors against a reference data file at the common stations.
# ---------------------------------------------------------------------------------------
errors() { # errors REF CASE [GRID] -> n L2(U W Sx Sz) L1(U W Sx Sz) L2in(W Sz)
    # GRID > 0: only the common stations with t a multiple of 1/GRID.
    # L2in: the L2 error over the common stations with |t| <= 0.4 (away from the beam ends).
    awk -v grid="${3:-0}" 'FNR == 1 { nf++; t_prev = "" }
        # columns 2..6 = U W Psi Sigma_x Sigma_z, the tractions taken as the finite-element
        # values Sigma_x^h, Sigma_z^h (found by name in the header line of symbols)
        $1 == "#" && $2 == "t" { for (i = 2; i <= NF; i++) col[$i] = i - 1
                                 pick[2] = col["U"]; pick[3] = col["W"]; pick[4] = col["Psi"]
                                 pick[5] = col["Sigma_x^h"]; pick[6] = col["Sigma_z^h"]; next }
        /^#/ { next }
        $1 == t_prev { next }                    # a load station listed twice
        { t_prev = $1 }
        nf == 1 { k = sprintf("%.6f", $1); for (c = 2; c <= 6; c++) r[k, c] = $(pick[c]); have[k] = 1; next }
        {
            k = sprintf("%.6f", $1); if (!(k in have)) next
            if (grid > 0) { g = $1 * grid; g = g - int(g + (g < 0 ? -0.5 : 0.5)); if (g > 1e-6 || g < -1e-6) next }
            n++
            inner = ($1 <= 0.400001 && $1 >= -0.400001)
            for (c = 2; c <= 6; c++) {
                v = $(pick[c])
                d = v - r[k, c]; a2[c] += d * d; b2[c] += r[k, c] * r[k, c]
                a1[c] += (d < 0 ? -d : d); b1[c] += (r[k, c] < 0 ? -r[k, c] : r[k, c])
                if (inner) { i2[c] += d * d; j2[c] += r[k, c] * r[k, c] }
            }
        }
        END {
            printf "%4d", n
            for (c = 2; c <= 6; c++) if (c != 4) printf " %9.3e", sqrt(a2[c] / b2[c])
            for (c = 2; c <= 6; c++) if (c != 4) printf " %9.3e", a1[c] / b1[c]
            printf " %9.3e %9.3e\n", sqrt(i2[3] / j2[3]), sqrt(i2[6] / j2[6])
        }' "$1" "$2"
}
{
    echo "# Relative errors against a reference, at the stations common to both data files."
    echo "# L2 = sqrt(sum (x - x_ref)^2 / sum x_ref^2), L1 = sum |x - x_ref| / sum |x_ref| over the"
    echo "# common stations, for U, W, Sigma_x, Sigma_z; L2in(W), L2in(Sz): the L2 error over the common"
    echo "# stations with |t| <= 0.4 (leaves out the beam ends, where a stiff beam's pressure is"
    echo "# singular). Written by scripts/paper.sh from the data files."
    hdr="case                   n    L2(U)     L2(W)     L2(Sx)    L2(Sz)    L1(U)     L1(W)     L1(Sx)    L1(Sz)    L2in(W)   L2in(Sz)"
    echo
    echo "## Fig. 6 (fig06.dat, rho 0.00025, all P1): N_e = 10 ... 80 against N_e = 160 (fig06_005),"
    echo "## at the nodes of N_e = 10 (t = k/10)."
    echo "$hdr"
    for i in 001 002 003 004; do
        [ -f "$out/fig06_$i.dat" ] && [ -f "$out/fig06_005.dat" ] && \
            printf '%-20s %s\n' "fig06_$i" "$(errors "$out/fig06_005.dat" "$out/fig06_$i.dat" 10)"
    done
    echo
    echo "## Fig. 7: N_e = 20, displacements P1, interactions P1 (fig07_p1) or S2 (fig07_s2), against"
    echo "## N_e = 160 all P1 (fig07_ref), same rho (cases 001..005: rho 0.00025 0.001 0.0025 0.01 0.1),"
    echo "## 161 common stations."
    echo "$hdr"
    for i in 001 002 003 004 005; do
        for v in p1 s2; do
            [ -f "$out/fig07_${v}_$i.dat" ] && [ -f "$out/fig07_ref_$i.dat" ] && \
                printf '%-20s %s\n' "fig07_${v}_$i" "$(errors "$out/fig07_ref_$i.dat" "$out/fig07_${v}_$i.dat")"
        done
    done
    echo
    echo "## Fig. 9: displacement interpolations, interactions P1, against fig07_ref (case 001 ="
    echo "## rho 0.00025 -> fig07_ref_001, case 002 = rho 0.0025 -> fig07_ref_003), 161 stations."
    echo "$hdr"
    for v in fig09a fig09b fig09c fig09_p2_18 fig09_p2_22; do
        for pair in "001 001" "002 003"; do
            set -- $pair
            [ -f "$out/${v}_$1.dat" ] && [ -f "$out/fig07_ref_$2.dat" ] && \
                printf '%-20s %s\n' "${v}_$1" "$(errors "$out/fig07_ref_$2.dat" "$out/${v}_$1.dat")"
        done
    done
} >"$out/errors.txt"

# ---------------------------------------------------------------------------------------
# Cross-deck overlays (the six panels of the sweep figures; tractions: finite-element values).
# ---------------------------------------------------------------------------------------
overlay() { # overlay NAME TITLE "file label file label ..."
    local name=$1 title=$2 files="" labels="" gp
    set -- $3
    while [ $# -ge 2 ]; do
        [ -f "$out/$1.dat" ] && { files="$files $out/$1.dat"; labels="$labels $2"; }
        shift 2
    done
    [ -n "$files" ] || return 0
    gp="$out/$name.gp"
    # the finite-element tractions Sigma_x^h, Sigma_z^h (what the interpolations compare),
    # found by name in the header line of symbols of the first file
    set -- $files
    cols=$(awk '$1 == "#" && $2 == "t" { for (i = 2; i <= NF; i++) c[$i] = i - 1
                                         print c["Sigma_x^h"], c["Sigma_z^h"]; exit }' "$1")
    set -- $cols
    {
        echo "# cross-deck overlay written by scripts/paper.sh: gnuplot $gp (from the project root)"
        echo "# tractions: the finite-element values Sigma_x^h (column $1), Sigma_z^h (column $2)"
        echo "c_s = $1; c_p = $2"
        echo "files = \"${files# }\""
        echo "labels = \"${labels# }\""
        echo "call 'scripts/gnuplot/fricon_sweep.gp' '$out/$name.png' '$title' 'BEAM'"
    } >"$gp"
    gnuplot "$gp" || echo "paper.sh: gnuplot failed on $gp" >&2
}
overlay fig07_compare_rho0.00025 "Fig. 7, rho 0.00025: interactions P1 vs S2 (N_e 20) and reference (N_e 160)" \
    "fig07_p1_001 P1,N_e=20 fig07_s2_001 S2,N_e=20 fig07_ref_001 P1,N_e=160"
overlay fig07_compare_rho0.0025 "Fig. 7, rho 0.0025: interactions P1 vs S2 (N_e 20) and reference (N_e 160)" \
    "fig07_p1_003 P1,N_e=20 fig07_s2_003 S2,N_e=20 fig07_ref_003 P1,N_e=160"
overlay fig07_compare_rho0.1 "Fig. 7, rho 0.1: interactions P1 vs S2 (N_e 20) and reference (N_e 160)" \
    "fig07_p1_005 P1,N_e=20 fig07_s2_005 S2,N_e=20 fig07_ref_005 P1,N_e=160"
overlay fig09_compare_rho0.00025 "Fig. 9, rho 0.00025: displacement interpolations (interactions P1)" \
    "fig09a_001 (a)P1,N_e=30 fig09b_001 (b)W:S2,N_e=18 fig09c_001 (c)W,psi:S2,N_e=22 fig09_p2_18_001 W,psi:P2,N_e=18 fig09_p2_22_001 W:P2,N_e=22 fig07_ref_001 ref,P1,N_e=160"
overlay fig09_compare_rho0.0025 "Fig. 9, rho 0.0025: displacement interpolations (interactions P1)" \
    "fig09a_002 (a)P1,N_e=30 fig09b_002 (b)W:S2,N_e=18 fig09c_002 (c)W,psi:S2,N_e=22 fig09_p2_18_002 W,psi:P2,N_e=18 fig09_p2_22_002 W:P2,N_e=22 fig07_ref_003 ref,P1,N_e=160"

# Table 1 scan: deviation from the paper's eps_bar = 1e-4 row against b/l, one curve per h/l.
scan="$out/table1_scan_fit"
awk '$1 ~ /^table1_scan_/ { print $3, $2, $8, $9, $10, $11 }' "$out/table1.txt" | sort -g -k1,1 -k2,2 \
    | awk 'NR > 1 && $1 != z { print ""; print "" } { z = $1; print }' >"$scan.dat"
if [ -s "$scan.dat" ]; then
    cat >"$scan.gp" <<EOF
# written by scripts/paper.sh: gnuplot $scan.gp (from the project root)
# $scan.dat: blocks per h/l; columns zeta, b/l, dW%, dSx%, dSz%, max% (from table1.txt)
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output '$scan.png'
set multiplot layout 2,2 title 'Table 1, reading H/V = 0.1 (table1_scan.dat): deviation from the paper row eps_bar = 1e-4' font 'Sans,14'
set grid
set key box opaque font ',9'
set xlabel 'beta = b/l'
set xzeroaxis lt -1
titles = "'W(0): fricon/paper - 1 (%)' 'Sigma_x(0): fricon/paper - 1 (%)' 'Sigma_z(0): fricon/paper - 1 (%)' 'largest |deviation| of the three (%)'"
do for [c = 3:6] {
    set title word(titles, c - 2)
    set ylabel '%'
    plot for [i = 0:4] '$scan.dat' index i u 2:c w lp lw 2 pt 7 t sprintf('h/l = %s', word('0.09 0.095 0.1 0.105 0.11', i + 1))
}
unset multiplot
EOF
    gnuplot "$scan.gp" || echo "paper.sh: gnuplot failed on $scan.gp" >&2
fi

# Plate: settlement in soil units, 2 W/rho = w E_f a/((1-nu_f^2) F), for the rho sweep and the
# zeta sweep side by side (the paper's W = D w/(F a^2) hides the rho-dependence of w).
plate="$out/plate_rho_zeta"
if [ -f "$out/fig11_18_001.dat" ] && [ -f "$out/fig20_001.dat" ]; then
    cat >"$plate.gp" <<EOF
# written by scripts/paper.sh: gnuplot $plate.gp (from the project root)
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output '$plate.png'
set multiplot layout 2,2 title 'Plate: rho sweep (fig11_18, h/a 0.1) against zeta sweep (fig20, rho 0.01); f 0.6' font 'Sans,14'
set grid
set key box opaque font ',9'
set xlabel 't = r/a'
rhos = '0.001 0.01 0.1 1.0 10.0'
zetas = '0.025 0.05 0.1 0.2 0.3'
set title 'settlement in soil units 2 W/rho = w E_f a/((1-nu_f^2) F), rho sweep'
set ylabel '2 W / rho'
set yrange [*:*] reverse
plot for [i = 1:5] sprintf('$out/fig11_18_%03d.dat', i) u 1:(2*\$3/word(rhos, i)) w l lw 2 t 'rho = '.word(rhos, i)
set title 'settlement in soil units 2 W/rho, zeta sweep at rho = 0.01'
plot for [i = 1:5] sprintf('$out/fig20_%03d.dat', i) u 1:(2*\$3/0.01) w l lw 2 t 'h/a = '.word(zetas, i)
set yrange [*:*] noreverse
set title 'contact pressure Sigma_z, rho sweep'
set ylabel 'Sigma_z'
set yrange [-2:110]
plot for [i = 1:5] sprintf('$out/fig11_18_%03d.dat', i) u 1:6 w l lw 2 t 'rho = '.word(rhos, i)
set title 'contact pressure Sigma_z, zeta sweep at rho = 0.01'
plot for [i = 1:5] sprintf('$out/fig20_%03d.dat', i) u 1:6 w l lw 2 t 'h/a = '.word(zetas, i)
unset multiplot
EOF
    gnuplot "$plate.gp" || echo "paper.sh: gnuplot failed on $plate.gp" >&2
fi

echo
cat "$out/runs.txt"
echo "paper.sh: $failed deck(s) with a failed case; results in $out (key_values.txt, table1.txt, errors.txt)"
[ "$failed" -eq 0 ]
