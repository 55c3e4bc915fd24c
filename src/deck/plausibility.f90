!> Plausibility warnings: values that are legal but likely slips (a friction angle typed as a
!! coefficient, moduli in different units, a load that sinks the structure by more than its
!! thickness). They are warnings, not errors: fricon solves the case and says so on standard
!! error and in the report.
!!
!! Ranges (README "Plausibility warnings"): f <= 2 (tan 63 degrees); 2 <= E/E_f <= 1e5 (a
!! concrete raft on soft clay is about 1e4, on rock about 1-10: below 2 the structure is hardly
!! stiffer than the soil); a settlement of at most the thickness h and a tenth of l (or a).
module plausibility
    use kinds, only: dp
    use kinds, only: pi
    use model, only: model_t, MODEL_BEAM, total_vertical_load
    implicit none
    private

    integer, parameter, public :: warning_length = 200

    real(dp), parameter :: f_max = 2.0_dp
    real(dp), parameter :: modulus_ratio_range(2) = [2.0_dp, 1.0e5_dp]

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
        ratio = m%structure%e/m%ground%e_f
        if (ratio < modulus_ratio_range(1) .or. ratio > modulus_ratio_range(2)) then
            write (text, '(a,es9.2,a)') 'E/E_f = ', ratio, ' (STRUCTURE E over SOIL E_f) is '// &
                'outside 2 to 1e5: check that both moduli are in the same units'
            w = [character(len=warning_length) :: w, text]
        end if
    end function input_warnings

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
        mean = total_vertical_load(m%loads)/merge(m%structure%length, pi*m%structure%length**2, m%structure%kind == MODEL_BEAM)
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
