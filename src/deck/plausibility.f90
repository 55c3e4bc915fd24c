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
    use model, only: model_t
    implicit none
    private

    integer, parameter, public :: warning_length = 200

    real(dp), parameter :: f_max = 2.0_dp
    real(dp), parameter :: modulus_ratio_range(2) = [2.0_dp, 1.0e5_dp]

    public :: input_warnings, settlement_warnings

contains

    !> Warnings about the input of one case.
    pure function input_warnings(m) result(w)
        type(model_t), intent(in) :: m
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
        type(model_t), intent(in) :: m
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
