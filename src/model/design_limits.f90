!> The design limits of the CHECK cards: one card per kind of check, its limit(s) in the
!! deck's units (pressures F/L^2, settlements L, rotations rad, the sliding factor of safety
!! and the contact ratio as pure numbers). A kind without a card is not checked.
!!
!!     *         kind      limit     edge      effective
!!     CHECK     BEARING   150.0     200.0
!!     CHECK     SETTLE    50.0E-3
!!     CHECK     CONTACT   1.0
!!
!! BEARING has three limits (the mean pressure over the contact area, the pressure at d = h
!! from an edge, the effective-area pressure of the codes); the last two default to the first.
!! Every other kind has one.
module design_limits
    use kinds, only: dp
    implicit none
    private

    !> The kinds of check, in the order the checks are reported.
    integer, parameter, public :: CHECK_BEARING = 1, CHECK_SETTLE = 2, CHECK_DIFFSETTLE = 3, &
                                  CHECK_ROTATION = 4, CHECK_TILT = 5, CHECK_SLIDING = 6, &
                                  CHECK_CONTACT = 7
    integer, parameter, public :: n_check_kinds = 7
    !> The CHECK card's kind words (field f1).
    character(len=10), parameter, public :: check_kind_words(n_check_kinds) = &
        [character(len=10) :: 'BEARING', 'SETTLE', 'DIFFSETTLE', 'ROTATION', 'TILT', &
        'SLIDING', 'CONTACT']
    !> Limits a card of each kind takes (fields f2, f3, f4).
    integer, parameter, public :: check_limit_count(n_check_kinds) = [3, 1, 1, 1, 1, 1, 1]

    !> The CHECK cards of a deck.
    type, public :: design_limits_t
        !> limit(j, kind): the card's j-th limit, deck units (BEARING: mean, edge, effective)
        real(dp) :: limit(3, n_check_kinds) = 0.0_dp
        integer :: line(n_check_kinds) = 0   !! deck line of the card; 0: no check of the kind
    end type design_limits_t

    public :: has_check, any_check

contains

    !> The deck has a CHECK card of this kind.
    pure logical function has_check(limits, kind)
        type(design_limits_t), intent(in) :: limits   !! the CHECK cards
        integer, intent(in) :: kind                    !! CHECK_BEARING, ...
        has_check = limits%line(kind) > 0
    end function has_check

    !> The deck has a CHECK card.
    pure logical function any_check(limits)
        type(design_limits_t), intent(in) :: limits   !! the CHECK cards
        any_check = any(limits%line > 0)
    end function any_check
end module design_limits
