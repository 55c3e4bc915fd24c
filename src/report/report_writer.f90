!> The tabulated report, the whitespace data file and the gnuplot script of one case (SPEC §9).
module report_writer
    use kinds, only: dp, pi
    use errors, only: error_t
    use atomic_files, only: open_temporary, commit_file
    use model, only: model_t, MODEL_BEAM, FIELD_U, FIELD_SZ, flexural_rigidity, &
                     relative_stiffness, soil_shear_modulus, friction_compliance, &
                     total_vertical_load
    use shape_functions, only: interp_name
    use discretization, only: discretization_t
    use contact_solver, only: solution_t, STATE_LIFTOFF, STATE_STICK, STATE_SLIP
    use station_results, only: station_table_t, contact_extent
    implicit none
    private

    public :: write_data_file, write_plot_script, write_report, shell_safe

    character(len=*), parameter :: state_word(0:2) = ['lift-off', 'stick   ', 'slip    ']

contains

    !> output/CASE.dat: `#` header naming every column, then one row per station.
    subroutine write_data_file(path, m, tab, err)
        character(len=*), intent(in) :: path
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        type(error_t), allocatable, intent(out) :: err
        integer :: u, i
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# fricon station data: '//trim(m%title)
        write (u, '(a)') '# all columns nondimensional (SPEC 6); state 0 = lift-off, 1 = stick, 2 = slip'
        if (m%kind == MODEL_BEAM) then
            write (u, '(a)') '# 1:t 2:U 3:W 4:Psi 5:Sigma_x 6:Sigma_z 7:gap 8:slip 9:state '// &
                '10:N/F 11:M/(F*l) 12:Q/F'
        else
            write (u, '(a)') '# 1:t 2:U 3:W 4:Psi 5:Sigma_x 6:Sigma_z 7:gap 8:slip 9:state '// &
                '10:N_r*a/F 11:N_theta*a/F 12:M_r/F 13:M_theta/F 14:Q_r*a/F'
        end if
        do i = 1, tab%n
            write (u, '(f12.8,7es16.7e3,i3,5es16.7e3)') tab%x(i)*tab%scale_x, &
                tab%field(1:5, i)*tab%scale(1:5), tab%field(6:7, i)*tab%scale(6:7), &
                tab%state(i), tab%res(1:tab%n_res, i)*tab%scale_res(1:tab%n_res)
        end do
        call commit_file(path, u, err)
    end subroutine write_data_file

    !> output/CASE.gp: calls the data-driven panel script (run gnuplot from the project root).
    subroutine write_plot_script(path, dat_path, png_path, m, err)
        character(len=*), intent(in) :: path, dat_path, png_path
        type(model_t), intent(in) :: m
        type(error_t), allocatable, intent(out) :: err
        integer :: u
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# fricon figure: run from the project root as  gnuplot '//path
        write (u, '(a)') "call 'scripts/gnuplot/fricon_panels.gp' '"//dat_path//"' '"// &
            png_path//"' '"//trim(shell_safe(m%title))//"' '"// &
            trim(merge('BEAM ', 'PLATE', m%kind == MODEL_BEAM))//"'"
        call commit_file(path, u, err)
    end subroutine write_plot_script

    !> Text safe inside single quotes of a shell or gnuplot command: quotes, backquote, $ and
    !! backslash become blanks.
    pure function shell_safe(text) result(safe)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: safe
        integer :: i
        safe = text
        do i = 1, len(safe)
            if (index("'""`$\", safe(i:i)) > 0) safe(i:i) = ' '
        end do
    end function shell_safe

    !> The text report. `failure` non-empty: ANALYSIS FAILED banner, log only.
    subroutine write_report(path, deck_path, lines, label, m, d, sol, tab, failure, note, err)
        character(len=*), intent(in) :: path, deck_path, label, failure, note
        character(len=*), intent(in) :: lines(:)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        type(error_t), allocatable, intent(out) :: err
        integer :: u
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') repeat('=', 100)
        write (u, '(a)') ' fricon - beam / circular raft on an elastic half-space with lift-off and friction'
        write (u, '(a)') ' deck: '//deck_path//'    case: '//label
        write (u, '(a)') ' title: '//trim(m%title)
        write (u, '(a)') repeat('=', 100)
        if (len_trim(failure) > 0) then
            write (u, '(/,a,/,a,/)') ' *** ANALYSIS FAILED ***', ' '//failure
        end if
        call write_echo(u, lines)
        call write_groups(u, m, d)
        call write_conventions(u, m)
        call write_log(u, sol)
        if (len_trim(failure) == 0) then
            call write_table(u, m, tab, .true.)
            if (.not. m%nondim) call write_table(u, m, tab, .false.)
            call write_summary(u, m, sol, tab)
        end if
        if (len_trim(note) > 0) write (u, '(/,a)') ' NOTE: '//note
        call commit_file(path, u, err)
    end subroutine write_report

    subroutine write_echo(u, lines)
        integer, intent(in) :: u
        character(len=*), intent(in) :: lines(:)
        integer :: i
        write (u, '(/,a)') ' 1. INPUT ECHO'
        write (u, '(a)') '  line |'//'....+....1....+....2....+....3....+....4....+....5....+....6'// &
            '....+....7....+....8'
        do i = 1, size(lines)
            write (u, '(i6,a,a)') i, ' |', trim(lines(i))
        end do
    end subroutine write_echo

    subroutine write_groups(u, m, d)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        character(len=*), parameter :: fmt = '(3x,a,t46,es14.6,2x,a)'
        integer :: field
        write (u, '(/,a)') ' 2. MODEL, NONDIMENSIONAL GROUPS AND PHYSICAL DATA'
        if (m%kind == MODEL_BEAM) then
            write (u, '(3x,a)') 'model: BEAM (Timoshenko) on a 3-D elastic half-space, '// &
                'tractions uniform across the width, compatibility on the centre line'
            write (u, fmt) 'rho = 32 EI (1-nu_f^2)/(pi E_f l^4)', relative_stiffness(m)
            write (u, fmt) 'beta = b/l', m%b/m%length
        else
            write (u, '(3x,a)') 'model: PLATE (axisymmetric Mindlin) on a 3-D elastic half-space'
            write (u, fmt) 'rho = 2 D (1-nu_f^2)/(E_f a^3)', relative_stiffness(m)
        end if
        write (u, fmt) 'zeta = h/l (beam) or h/a (plate)', m%h/m%length
        write (u, fmt) 'nu (structure)', m%nu
        write (u, fmt) 'nu_f (soil)', m%nu_f
        write (u, fmt) 'f (friction coefficient)', m%f
        write (u, fmt) 'eps_bar (friction regularisation)', m%eps_bar
        write (u, fmt) 'eta_bar (penalty of the tension zone)', m%eta_bar
        if (m%nondim) then
            write (u, '(3x,a)') 'physical set chosen to reproduce the groups: l (a) = 1, E = 1, F = 1'
        end if
        write (u, fmt) 'l (beam length) or a (plate radius)', m%length, trim(m%length_unit)
        write (u, fmt) 'h (thickness)', m%h, trim(m%length_unit)
        if (m%kind == MODEL_BEAM) write (u, fmt) 'b (width)', m%b, trim(m%length_unit)
        write (u, fmt) 'E (structure)', m%e, trim(m%force_unit)//'/'//trim(m%length_unit)//'^2'
        write (u, fmt) 'k (shear correction)', m%k_shear
        write (u, fmt) 'E_f (soil)', m%e_f, trim(m%force_unit)//'/'//trim(m%length_unit)//'^2'
        write (u, fmt) 'G_f (soil)', soil_shear_modulus(m), &
            trim(m%force_unit)//'/'//trim(m%length_unit)//'^2'
        write (u, fmt) 'EI (beam) or D (plate)', flexural_rigidity(m)
        write (u, fmt) 'c (friction compliance, SPEC 4)', friction_compliance(m)
        write (u, fmt) 'F (total vertical load)', total_vertical_load(m), trim(m%force_unit)
        write (u, fmt) 'H (total horizontal load)', sum(m%loads%fx), trim(m%force_unit)
        write (u, '(3x,a,i0,a,a,a)', advance='no') 'mesh: N_e = ', d%msh%ne, ', ', &
            trim(m%grading), ', interpolation u w psi sigma_x sigma_z:'
        do field = FIELD_U, FIELD_SZ
            write (u, '(1x,a)', advance='no') interp_name(m%interp(field))
        end do
        write (u, '(a,i0,a,i0)') ', unknowns: displacements ', d%nv, ', tractions ', d%nr
        write (u, '(3x,a,es9.2,a,es9.2,a,i0,a,i0)') 'solver: tol outer ', m%tol_outer, &
            ', tol inner ', m%tol_inner, ', max outer ', m%max_outer, ', max inner ', m%max_inner
    end subroutine write_groups

    subroutine write_conventions(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        write (u, '(/,a)') ' 3. SIGN CONVENTIONS AND UNITS'
        write (u, '(a)') '   z points down into the soil; w > 0 is settlement; x from the beam centre '// &
            '(plate: radius r).'
        write (u, '(a)') '   u_s: mid-plane horizontal displacement (+x / outward); psi: section '// &
            'rotation, psi = dw/dx in the thin limit.'
        write (u, '(a)') '   sigma_z > 0: compressive contact pressure on the soil; sigma_x: shear '// &
            'traction ON THE SOIL, +x (plate: outward);'
        write (u, '(a)') '   the structure receives -sigma. gap = w_f - w_b >= 0; slip = u_b - u_f, '// &
            'u_b = u_s - (h/2) psi.'
        if (m%kind == MODEL_BEAM) then
            write (u, '(a)') '   BEAM: sigma are line loads (force/length) over the width b; '// &
                'N = EA u_s'', M = EI psi'' (> 0: top fibre in tension, hogging), Q = kGbh (w''-psi).'
            write (u, '(a)') '   Nondimensional: t = x/l, U,W = EI u/(F l^3), Psi = EI psi/(F l^2), '// &
                'Sigma = l sigma/F, N/F, M/(F l), Q/F.'
        else
            write (u, '(a)') '   PLATE: sigma are stresses; resultants per unit length: '// &
                'N_r, N_theta, M_r = D(psi''+nu psi/r), M_theta = D(psi/r+nu psi'') '// &
                '(> 0: top in tension), Q_r = kGh(w''-psi).'
            write (u, '(a)') '   Nondimensional: t = r/a, U,W = D u/(F a^2), Psi = D psi/(F a), '// &
                'Sigma = pi a^2 sigma/F, N a/F, M/F, Q a/F.'
        end if
        write (u, '(a)') '   Physical units: force '//trim(m%force_unit)//', length '// &
            trim(m%length_unit)//(merge(' (labels of the NONDIM set)', '                           ', &
                                        m%nondim))
    end subroutine write_conventions

    subroutine write_log(u, sol)
        integer, intent(in) :: u
        type(solution_t), intent(in) :: sol
        integer :: i
        write (u, '(/,a)') ' 4. SOLVER LOG (outer: friction threshold tau0 <- f sigma_z; inner: '// &
            'slip / tension sets)'
        if (.not. allocated(sol%history)) then
            write (u, '(a)') '   (no iteration: the case was refused before solving)'
            return
        end if
        write (u, '(a)') '   outer inner  slip-pts  lift-pts  changed   rel.increment   rel.residual'// &
            '  note'
        do i = 1, size(sol%history)
            associate (h => sol%history(i))
                if (h%residual >= 0.0_dp) then
                    write (u, '(3x,i5,i6,3i10,2es16.4,2x,a)') h%outer, h%inner, h%n_slip, &
                        h%n_tension, h%n_changed, h%increment, h%residual, trim(h%note)
                else
                    write (u, '(3x,i5,i6,3i10,es16.4,16x,2x,a)') h%outer, h%inner, h%n_slip, &
                        h%n_tension, h%n_changed, h%increment, trim(h%note)
                end if
            end associate
        end do
        write (u, '(3x,a,i0,a,i0,a,i0)') 'iterations: ', sol%n_outer, ' outer, ', sol%n_inner, &
            ' inner; linear solves: ', sol%n_solves
    end subroutine write_log

    subroutine write_table(u, m, tab, nondim)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        logical, intent(in) :: nondim
        real(dp) :: sx, sres(5), sf(7)
        integer :: i
        sx = merge(tab%scale_x, 1.0_dp, nondim)
        sf = merge(tab%scale, [(1.0_dp, i=1, 7)], nondim)
        sres = merge(tab%scale_res, [(1.0_dp, i=1, 5)], nondim)
        if (nondim) then
            write (u, '(/,a)') ' 5. STATIONS (nondimensional)'
            if (m%kind == MODEL_BEAM) then
                write (u, '(a)') '         t          U            W            Psi         Sigma_x'// &
                    '      Sigma_z       gap          slip        state         N/F        M/(Fl)'// &
                    '         Q/F'
            else
                write (u, '(a)') '         t          U            W            Psi         Sigma_x'// &
                    '      Sigma_z       gap          slip        state       N_r a/F    '// &
                    'N_t a/F      M_r/F        M_t/F       Q_r a/F'
            end if
        else
            write (u, '(/,a)') ' 6. STATIONS (physical: '//trim(m%force_unit)//', '// &
                trim(m%length_unit)//', rad)'
            if (m%kind == MODEL_BEAM) then
                write (u, '(a)') '         x          u_s          w            psi         sigma_x'// &
                    '      sigma_z       gap          slip        state          N            M'// &
                    '             Q'
            else
                write (u, '(a)') '         r          u_s          w            psi         sigma_x'// &
                    '      sigma_z       gap          slip        state          N_r       N_t'// &
                    '          M_r          M_t           Q_r'
            end if
        end if
        do i = 1, tab%n
            write (u, '(f10.5,7es13.4,2x,a8,5es13.4)') tab%x(i)*sx, tab%field(1:7, i)*sf(1:7), &
                state_word(tab%state(i)), tab%res(1:tab%n_res, i)*sres(1:tab%n_res)
        end do
    end subroutine write_table

    subroutine write_summary(u, m, sol, tab)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        character(len=*), parameter :: fmt = '(3x,a,t52,es14.6,2x,es14.6,2x,a)'
        real(dp) :: w_max, w_min, p_max, m_max, area, w_mean, k_s, tol_adm, v
        integer :: i_m
        v = total_vertical_load(m)
        w_max = maxval(tab%field(2, :))
        w_min = minval(tab%field(2, :))
        p_max = maxval(tab%field(5, :))
        i_m = merge(2, 3, m%kind == MODEL_BEAM)
        m_max = maxval(abs(tab%res(i_m, :)))
        call mean_settlement(m, tab, area, w_mean)
        k_s = (v/area)/w_mean
        write (u, '(/,a)') ' 7. SUMMARY                                        '// &
            'nondimensional  physical'
        write (u, fmt) 'max settlement W', w_max*tab%scale(2), w_max, trim(m%length_unit)
        write (u, fmt) 'differential settlement (max - min)', (w_max - w_min)*tab%scale(2), &
            w_max - w_min, trim(m%length_unit)
        write (u, fmt) 'contact extent (largest t >= 0 in contact)', contact_extent(tab)
        write (u, fmt) 'max contact pressure Sigma_z (*)', p_max*tab%scale(5), p_max
        write (u, fmt) 'max |moment| (beam M, plate M_r)', m_max*tab%scale_res(i_m), m_max
        write (u, fmt) 'secant subgrade modulus (F/A)/w_mean', 1.0_dp/(w_mean*tab%scale(2)), &
            k_s, trim(m%force_unit)//'/'//trim(m%length_unit)//'^3'
        if (m%kind == MODEL_BEAM .and. m%f > 0.0_dp) then
            write (u, fmt) 'sliding utilisation H/(f V)', abs(sum(m%loads%fx))/(m%f*v)
        end if
        write (u, '(3x,a)') '(*) the pressure peaks at the edge of a stiff contact are singular '// &
            'in theory: their value is mesh dependent.'
        write (u, '(/,a)') ' 8. CHECKS'
        write (u, '(3x,a,es10.2,a,es10.2)') 'residual of 4.2a (equilibrium of the structure) ', &
            sol%residual(1), '   of 4.2b (interface law) ', sol%residual(2)
        write (u, '(3x,a,2es16.8,a,es9.2)') 'vertical:   reaction, load ', sol%reaction(1), &
            sol%applied(1), '  rel.diff ', rel_diff(sol%reaction(1), sol%applied(1), v)
        write (u, '(3x,a,2es16.8,a,es9.2)') 'horizontal: reaction, load ', sol%reaction(2), &
            sol%applied(2), '  rel.diff ', rel_diff(sol%reaction(2), sol%applied(2), v)
        if (m%kind == MODEL_BEAM) write (u, '(3x,a,2es16.8,a,es9.2)') &
            'moment:     reaction, load ', sol%reaction(3), sol%applied(3), '  rel.diff ', &
            rel_diff(sol%reaction(3), sol%applied(3), v*m%length)
        write (u, '(3x,a,es10.2,a)') 'complementarity max |Sigma_z * gap| over lift-off '// &
            'stations (nondim) ', sol%complementarity, '  (penalty: O(eta_bar))'
        write (u, '(3x,a,es10.2,a)') 'compatibility max |gap|/max W over contact stations ', &
            sol%compatibility, '  (pointwise error of the weak (Galerkin) contact condition)'
        write (u, '(3x,a,es10.2)') 'minimum Sigma_z (negative only where lifted off) ', &
            sol%min_sigma_z*tab%scale(5)
        tol_adm = 10.0_dp*m%eps_bar*max(1.0_dp, p_max*tab%scale(5))
        write (u, '(3x,a,es10.2,a,es9.2,a)') 'friction admissibility max(|Sigma_x| - f Sigma_z) ', &
            sol%admissibility*tab%scale(5), '  (tolerance ', tol_adm, &
            merge(': ok)      ', ': EXCEEDED)', sol%admissibility*tab%scale(5) <= tol_adm)
        write (u, '(3x,a,i0,a)') 'state counts at the stations: ', count(tab%state == STATE_STICK), &
            ' stick, '//itoa(count(tab%state == STATE_SLIP))//' slip, '// &
            itoa(count(tab%state == STATE_LIFTOFF))//' lift-off'
    end subroutine write_summary

    !> Mean settlement over the base (trapezoid over the stations; area-weighted for the plate).
    pure subroutine mean_settlement(m, tab, area, w_mean)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        real(dp), intent(out) :: area, w_mean
        real(dp) :: wt_sum, w_sum, wa, wb
        integer :: i
        w_sum = 0.0_dp
        wt_sum = 0.0_dp
        do i = 1, tab%n - 1
            wa = 1.0_dp
            wb = 1.0_dp
            if (m%kind /= MODEL_BEAM) then
                wa = tab%x(i)
                wb = tab%x(i + 1)
            end if
            w_sum = w_sum + 0.5_dp*(wa*tab%field(2, i) + wb*tab%field(2, i + 1))* &
                    (tab%x(i + 1) - tab%x(i))
            wt_sum = wt_sum + 0.5_dp*(wa + wb)*(tab%x(i + 1) - tab%x(i))
        end do
        w_mean = w_sum/wt_sum
        if (m%kind == MODEL_BEAM) then
            area = m%length*m%b
        else
            area = pi*m%length**2
        end if
    end subroutine mean_settlement

    pure real(dp) function rel_diff(a, b, scale)
        real(dp), intent(in) :: a, b, scale
        rel_diff = abs(a - b)/max(abs(scale), tiny(1.0_dp))
    end function rel_diff

    pure function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=12) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa
end module report_writer
