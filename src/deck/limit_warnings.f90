!> Plausibility of the CHECK cards' limits (check_cards): legal values that are likely slips
!! of units. The limits are in the deck's units, so a settlement limit of 25 meant as mm in a
!! deck in m is 25 m, and a rotation of 500 meant as 1/500 is 500 rad; both would pass every
!! case. Warned: a settlement or differential settlement limit above a tenth of l (or a), the
!! rule of the settlement warning; a rotation or tilt limit above 0.1 rad (1/10; the codes'
!! limits are 1/150 to 1/1000); a factor of safety against sliding below 1 (it accepts a base
!! that slides).
module limit_warnings
    use kinds, only: dp
    use model, only: model_t
    use design_limits, only: has_check, check_kind_words, CHECK_SETTLE, CHECK_DIFFSETTLE, &
                             CHECK_ROTATION, CHECK_TILT, CHECK_SLIDING
    implicit none
    private

    public :: check_limit_warnings

contains

    !> One warning per implausible CHECK limit (none without CHECK cards).
    pure function check_limit_warnings(m, width) result(w)
        type(model_t), intent(in) :: m      !! the model (its CHECK limits and length)
        integer, intent(in) :: width        !! length of a warning
        character(len=width), allocatable :: w(:)
        character(len=width) :: text
        integer :: kind
        allocate (w(0))
        do kind = CHECK_SETTLE, CHECK_DIFFSETTLE
            if (.not. has_check(m%limits, kind)) cycle
            if (m%limits%limit(1, kind) <= 0.1_dp*m%structure%length) cycle
            write (text, '(a,g0.4,a)') 'CHECK '//trim(check_kind_words(kind))//' limit ', &
                m%limits%limit(1, kind), ' is above a tenth of the length: settlement limits '// &
                'are in the deck''s length unit (25 mm in a deck in m is 25.0E-3)'
            w = [character(len=width) :: w, text]
        end do
        do kind = CHECK_ROTATION, CHECK_TILT
            if (.not. has_check(m%limits, kind)) cycle
            if (m%limits%limit(1, kind) <= 0.1_dp) cycle
            write (text, '(a,g0.4,a)') 'CHECK '//trim(check_kind_words(kind))//' limit ', &
                m%limits%limit(1, kind), ' rad is above 1/10: a rotation limit is in rad '// &
                '(1/500 is 2.0E-3)'
            w = [character(len=width) :: w, text]
        end do
        if (.not. has_check(m%limits, CHECK_SLIDING)) return
        if (m%limits%limit(1, CHECK_SLIDING) >= 1.0_dp) return
        write (text, '(a,g0.4,a)') 'CHECK SLIDING FS_min ', m%limits%limit(1, CHECK_SLIDING), &
            ' is below 1: it accepts a base whose horizontal load exceeds its friction'
        w = [character(len=width) :: w, text]
    end function check_limit_warnings
end module limit_warnings
