!> Plausibility warnings: values that are legal but likely slips (a friction angle typed as a
!! coefficient, moduli in different units, a load that sinks the structure by more than its
!! thickness). They are warnings, not errors: fricon solves the case and says so on standard
!! error and in the report.
!!
!! Ranges (README "Plausibility warnings"): f <= 2 (tan 63 degrees); 2 <= E/E_f <= 1e5 (a
!! concrete raft on soft clay is about 1e4, on rock about 1-10: below 2 the structure is hardly
!! stiffer than the soil); a settlement of at most the thickness h and a tenth of l (or a).
!!
!! Magnitudes, when a UNITS card's words are known units (physical_units), in SI: a
!! structure's E in 1e8 to 1e12 Pa (timber across the grain is about 3e8, steel 2.1e11); a
!! ground modulus in 1e5 to 1e11 Pa (very soft peat about 3e5, sound granite about 6e10); l
!! or a in 0.1 to 1000 m, h in 0.01 to 20 m, b in 0.01 to 1000 m; the mean pressure of the
!! vertical load on the base area in 1e3 Pa (the weight of 4 cm of concrete) to 1e7 Pa
!! (above the bearing resistance of all but sound rock). Each warning names the card and
!! field.
module plausibility
    use kinds, only: dp
    use kinds, only: pi
    use model, only: model_t, MODEL_BEAM, total_vertical_load, base_area, layer_count, &
                     GROUND_BASE_HALFSPACE
    use physical_units, only: force_in_newtons, length_in_metres
    use limit_warnings, only: check_limit_warnings
    implicit none
    private

    integer, parameter, public :: warning_length = 200

    real(dp), parameter :: f_max = 2.0_dp
    real(dp), parameter :: modulus_ratio_range(2) = [2.0_dp, 1.0e5_dp]
    ! plausible magnitudes in SI (module header)
    real(dp), parameter :: structure_modulus_range(2) = [1.0e8_dp, 1.0e12_dp]   ! Pa
    real(dp), parameter :: ground_modulus_range(2) = [1.0e5_dp, 1.0e11_dp]      ! Pa
    real(dp), parameter :: length_range(2) = [0.1_dp, 1.0e3_dp]                 ! m
    real(dp), parameter :: thickness_range(2) = [0.01_dp, 20.0_dp]              ! m
    real(dp), parameter :: width_range(2) = [0.01_dp, 1.0e3_dp]                 ! m
    real(dp), parameter :: pressure_range(2) = [1.0e3_dp, 1.0e7_dp]             ! Pa

    public :: input_warnings, settlement_warnings, tension_warnings

contains

    !> Warnings about the input of one case.
    pure function input_warnings(m) result(w)
        type(model_t), intent(in) :: m   !! the model
        character(len=warning_length), allocatable :: w(:)
        character(len=warning_length) :: text
        real(dp) :: ratio
        allocate (w(0))
        if (m%interface%f > f_max .and. m%interface%f < 90.0_dp) then
            write (text, '(a,g0.3,a,g0.3,a)') 'FRICTION f = ', m%interface%f, &
                ' is large: f is a '// &
                'coefficient, tan(phi) (an angle of ', m%interface%f, ' degrees would be f = '// &
                trim(degrees_to_coefficient(m%interface%f))//')'
            w = [character(len=warning_length) :: w, text]
        else if (m%interface%f >= 90.0_dp) then
            ! no angle is meant: such an f makes the interface bonded (stick everywhere)
            write (text, '(a,es9.2,a)') 'FRICTION f = ', m%interface%f, &
                ' is large: the base is '// &
                'practically bonded (slip only where the pressure tends to 0)'
            w = [character(len=warning_length) :: w, text]
        end if
        if (m%nondim .or. m%ground%e_f <= 0.0_dp) return
        w = [character(len=warning_length) :: w, check_limit_warnings(m, warning_length)]
        ratio = m%structure%e/m%ground%e_f
        if (ratio < modulus_ratio_range(1) .or. ratio > modulus_ratio_range(2)) then
            write (text, '(a,es9.2,a)') 'E/E_f = ', ratio, ' (STRUCTURE E over SOIL E_f) is '// &
                'outside 2 to 1e5: check that both moduli are in the same units'
            w = [character(len=warning_length) :: w, text]
        end if
        w = [character(len=warning_length) :: w, unit_warnings(m)]
    end function input_warnings

    !> Magnitudes out of their plausible SI range (module header), when the deck's UNITS
    !! words are known units: lengths need a known length word, moduli and the mean pressure
    !! both words. None for a NONDIM deck, a deck without a UNITS card (its N and m are
    !! labels by default, not a statement) or unknown words.
    pure function unit_warnings(m) result(w)
        type(model_t), intent(in) :: m   !! the model (physical)
        character(len=warning_length), allocatable :: w(:)
        real(dp) :: to_m, to_n, to_pa
        integer :: i
        character(len=4) :: layer
        character(len=:), allocatable :: l_unit, p_unit
        allocate (w(0))
        to_m = length_in_metres(m%units%length)
        to_n = force_in_newtons(m%units%force)
        if (m%nondim .or. .not. m%units%stated .or. to_m <= 0.0_dp) return
        l_unit = trim(m%units%length)
        p_unit = trim(m%units%force)//'/'//l_unit//'^2'
        call check_range(w, 'GEOMETRY '//trim(merge('l', 'a', m%structure%kind == MODEL_BEAM)), &
                         m%structure%length, l_unit, to_m, 'm', length_range)
        call check_range(w, 'GEOMETRY h', m%structure%h, l_unit, to_m, 'm', thickness_range)
        if (m%structure%kind == MODEL_BEAM) call check_range(w, 'GEOMETRY b', &
            m%structure%b, l_unit, to_m, 'm', width_range)
        if (to_n <= 0.0_dp) return
        to_pa = to_n/to_m**2
        call check_range(w, 'STRUCTURE E', m%structure%e, p_unit, to_pa, 'Pa', &
                         structure_modulus_range)
        call check_range(w, trim(merge('LAYER 1 E', 'SOIL E_f ', layer_count(m%ground) > 0)), &
                         m%ground%e_f, p_unit, to_pa, 'Pa', ground_modulus_range)
        layers: do i = 1, layer_count(m%ground)
            write (layer, '(i0)') i
            if (i > 1) call check_range(w, 'LAYER '//trim(layer)//' E', m%ground%e_top(i), &
                                        p_unit, to_pa, 'Pa', ground_modulus_range)
            if (m%ground%e_bottom(i) > 0.0_dp) call check_range(w, 'LAYER '//trim(layer)// &
                ' E_bottom', m%ground%e_bottom(i), p_unit, to_pa, 'Pa', ground_modulus_range)
        end do layers
        if (layer_count(m%ground) > 0 .and. m%ground%base == GROUND_BASE_HALFSPACE) &
            call check_range(w, 'BASE E', m%ground%e_base, p_unit, to_pa, 'Pa', &
                             ground_modulus_range)
        if (total_vertical_load(m%loads) > 0.0_dp) call check_range(w, &
            'LOAD F_z, their sum over the base area,', &
            total_vertical_load(m%loads)/base_area(m%structure), p_unit, to_pa, 'Pa', &
            pressure_range)
    end function unit_warnings

    !> Appends a warning when value*to_si lies outside range (SI).
    pure subroutine check_range(w, field, value, deck_unit, to_si, si_unit, range)
        character(len=warning_length), allocatable, intent(inout) :: w(:)  !! the warnings
        character(len=*), intent(in) :: field      !! card and field, e.g. 'STRUCTURE E'
        real(dp), intent(in) :: value              !! as the deck gives it
        real(dp), intent(in) :: to_si              !! deck unit -> SI unit
        character(len=*), intent(in) :: deck_unit  !! the value's unit as the deck says it
        character(len=*), intent(in) :: si_unit    !! 'm' or 'Pa'
        real(dp), intent(in) :: range(2)           !! plausible range [SI]
        character(len=warning_length) :: text
        if (value*to_si >= range(1) .and. value*to_si <= range(2)) return
        text = trim(field)//' = '//trim(sci(value, 3))//' '//deck_unit
        if (deck_unit /= si_unit) text = trim(text)//' is '//trim(sci(value*to_si, 3))//' '// &
                                         si_unit
        text = trim(text)//', outside the plausible '//trim(sci(range(1), 2))//' to '// &
               trim(sci(range(2), 2))//' '//si_unit//': check its units against the UNITS card'
        w = [character(len=warning_length) :: w, text]
    end subroutine check_range

    !> x in scientific notation with digits significant digits, no leading blank.
    !! (24 characters, blank-padded: a deferred-length result would not be thread-safe,
    !! scripts/check_thread_safety.py)
    pure function sci(x, digits) result(text)
        real(dp), intent(in) :: x         !! the value
        integer, intent(in) :: digits     !! significant digits (1 to 9)
        character(len=24) :: text
        character(len=16) :: form
        write (form, '(a,i0,a,i0,a)') '(es', digits + 8, '.', digits - 1, ')'
        write (text, form) x
        text = adjustl(text)
    end function sci

    !> Warnings about a solved case: a settlement larger than the thickness or l/10.
    pure function settlement_warnings(m, w_max) result(w)
        type(model_t), intent(in) :: m         !! the model
        real(dp), intent(in) :: w_max          !! largest settlement [length]
        character(len=warning_length), allocatable :: w(:)
        character(len=warning_length) :: text
        allocate (w(0))
        if (m%nondim) return
        if (w_max > m%structure%h .or. w_max > 0.1_dp*m%structure%length) then
            write (text, '(a,es9.2,a,es9.2,a,es9.2,a)') 'the largest settlement ', w_max, &
                ' '//trim(m%units%length)//' exceeds the thickness h = ', m%structure%h, &
                    ' or a tenth '// &
                'of the length/radius (', 0.1_dp*m%structure%length, &
                    '): linear elasticity does not '// &
                'hold there; check the units of the loads and moduli'
            w = [character(len=warning_length) :: w, text]
        end if
    end function settlement_warnings

    !> Warning about a solved case whose station table flags tension beyond the penalty's
    !! O(eta) (rows !T): the report alone showed it. On a very soft structure that lifts off
    !! far, the penalty pulls on the lifted part in proportion to its gap and to eta_bar (the
    !! flag count grows with the stations, the tension falls with eta_bar).
    pure function tension_warnings(m, n_flags, n_lifted, n_stations, most_tensile, &
                                   tension_tol) result(w)
        type(model_t), intent(in) :: m             !! the model
        integer, intent(in) :: n_flags             !! stations flagged !T
        integer, intent(in) :: n_lifted            !! of them lifted off
        integer, intent(in) :: n_stations          !! stations of the table
        real(dp), intent(in) :: most_tensile       !! least station sigma_z [force/length^k]
        real(dp), intent(in) :: tension_tol        !! the flag level, same unit (> 0)
        character(len=warning_length), allocatable :: w(:)
        character(len=warning_length) :: text
        character(len=40) :: where
        real(dp) :: mean
        allocate (w(0))
        if (n_flags <= 0) return
        mean = total_vertical_load(m%loads)/merge(m%structure%length, pi*m%structure%length**2, &
            m%structure%kind == MODEL_BEAM)
        where = ''
        if (n_lifted < n_flags) write (where, '(a,i0,a)') ', ', n_flags - n_lifted, &
            ' not lifted off'
        ! Sigma_z = sigma_z / mean pressure, as the report's CHECKS; at most 190 characters
        ! with seven-digit counts
        write (text, '(a,i0,a,i0,a,es9.2,a,es9.2,a)') 'tension at ', n_flags, ' of ', &
            n_stations, ' stations'//trim(where)//' (Sigma_z down to ', most_tensile/mean, &
            ', flag level', tension_tol/mean, '; rows !T): the penalty pulls where lifted '// &
            'off, less with a smaller SOLVER eta_bar'
        w = [character(len=warning_length) :: text]
    end function tension_warnings

    pure function degrees_to_coefficient(phi) result(text)
        real(dp), intent(in) :: phi
        character(len=16) :: text
        if (phi >= 90.0_dp) then
            text = 'undefined'
        else
            write (text, '(f0.3)') tan(phi*acos(-1.0_dp)/180.0_dp)
            if (text(1:1) == '.') text = '0'//text
        end if
    end function degrees_to_coefficient
end module plausibility
