!> The CHECK card (design checks, opt-in): one card per kind, the kind word in f1 and its
!! limit(s) from f2 on, in the deck's units (README "CHECK"; the model part: design_limits).
!!
!!     *...+....1....+....2....+....3....+....4....+....5
!!     *         kind      limit     edge      effective
!!     CHECK     BEARING   150.0     200.0
!!     CHECK     SETTLE    50.0E-3
!!     CHECK     DIFFSETTLE20.0E-3
!!     CHECK     ROTATION  2.0E-3
!!     CHECK     TILT      4.0E-3
!!     CHECK     SLIDING   1.5
!!     CHECK     CONTACT   1.0
!!
!! Errors (an unknown or missing kind, a missing, unreadable or out-of-range limit, a second
!! card of one kind, a CHECK in a NONDIM deck) are added to the deck's list at their columns
!! like every other input error (doc/ERRORS.md).
module check_cards
    use kinds, only: dp
    use design_limits, only: design_limits_t, n_check_kinds, check_kind_words, &
                             check_limit_count, CHECK_CONTACT
    use deck_fields, only: name_width, field_width, max_fields, FIELD_BLANK, FIELD_OK, &
                           FIELD_BAD, FIELD_RANGE, diagnostics_t, field_first_column, &
                           field_text, read_real_field, read_word_field, int_text, &
                           add_diagnostic, number_problem
    implicit none
    private

    public :: read_check_card

    !> What each limit is, for messages: (limit j, kind).
    character(len=*), parameter :: limit_words(3, n_check_kinds) = reshape([character(len=64) :: &
        'q_mean (allowable mean contact pressure)', &
        'q_edge (allowable pressure at d from an edge)', &
        'q_eff (allowable effective-area pressure)', &
        'w_max (largest settlement allowed)', '', '', &
        'dw (largest differential settlement allowed)', '', '', &
        'beta (largest relative rotation between loaded points)', '', '', &
        'omega (largest tilt allowed)', '', '', &
        'FS_min (smallest factor of safety against sliding, f V / H)', '', '', &
        'ratio (smallest contact area / base area)', '', ''], [3, n_check_kinds])

contains

    !> One CHECK card: its kind and limits into `limits`, or its errors into `diag`.
    subroutine read_check_card(text, line, nondim, limits, diag)
        character(len=*), intent(in) :: text               !! the card's 80 columns
        integer, intent(in) :: line                        !! its deck line
        logical, intent(in) :: nondim                      !! the deck is NONDIM
        type(design_limits_t), intent(inout) :: limits     !! the deck's CHECK cards so far
        type(diagnostics_t), intent(inout) :: diag         !! the deck's input errors
        character(len=field_width) :: word
        real(dp) :: values(3)
        integer :: kind, status, j, n_before
        if (nondim) then
            call add_diagnostic(diag, line, 1, name_width, 'CHECK needs a physical deck: its '// &
                'limits are pressures, settlements and rotations in the deck''s units, and a '// &
                'NONDIM deck''s results are nondimensional groups (give GEOMETRY, STRUCTURE '// &
                'and SOIL)', &
                trim(text))
            return
        end if
        kind = check_kind(text, line, word, diag)
        if (kind == 0) return
        n_before = diag%n
        if (limits%line(kind) > 0) call field_problem(text, line, 1, 'duplicate CHECK '// &
            trim(word)//' (first given at line '//int_text(limits%line(kind))//'): one CHECK '// &
            'card per kind', diag)
        values = 0.0_dp
        do j = 1, check_limit_count(kind)
            call limit_field(text, line, j, kind, values(j), status, diag)
            if (status == FIELD_BLANK) values(j) = values(1)
        end do
        do j = check_limit_count(kind) + 2, max_fields
            if (len_trim(field_text(text, j)) > 0) call field_problem(text, line, j, 'CHECK '// &
                trim(word)//' has '//int_text(check_limit_count(kind) + 1)//' field(s); '// &
                'columns '//int_text(field_first_column(j))//'-'// &
                int_text(field_first_column(j) + field_width - 1)//' must be blank, found '''// &
                trim(adjustl(field_text(text, j)))//'''', diag)
        end do
        if (diag%n > n_before) return
        limits%line(kind) = line
        limits%limit(:, kind) = values
    end subroutine read_check_card

    !> The kind of field f1 (0 with an error recorded when blank or unknown).
    integer function check_kind(text, line, word, diag) result(kind)
        character(len=*), intent(in) :: text
        integer, intent(in) :: line
        character(len=field_width), intent(out) :: word
        type(diagnostics_t), intent(inout) :: diag
        character(len=*), parameter :: expected = 'BEARING, SETTLE, DIFFSETTLE, ROTATION, '// &
                                                  'TILT, SLIDING or CONTACT'
        integer :: status
        call read_word_field(field_text(text, 1), word, status)
        kind = 0
        if (status == FIELD_OK) then
            do kind = n_check_kinds, 1, -1
                if (trim(word) == trim(check_kind_words(kind))) return
            end do
        end if
        if (status == FIELD_BLANK) then
            call field_problem(text, line, 1, 'CHECK kind is required but the field is '// &
                'blank (expected '//expected//')', diag)
        else
            call field_problem(text, line, 1, 'CHECK kind must be '//expected//', got '''// &
                trim(adjustl(field_text(text, 1)))//'''', diag)
        end if
    end function check_kind

    !> Limit j of a card of this kind, in field f(j+1): required for j = 1, > 0 (CONTACT:
    !! in (0, 1]); status FIELD_OK, FIELD_BLANK (an optional limit left blank) or FIELD_BAD.
    subroutine limit_field(text, line, j, kind, value, status, diag)
        character(len=*), intent(in) :: text
        integer, intent(in) :: line, j, kind
        real(dp), intent(out) :: value
        integer, intent(out) :: status
        type(diagnostics_t), intent(inout) :: diag
        character(len=:), allocatable :: what, got
        what = 'CHECK '//trim(check_kind_words(kind))//' '//trim(limit_words(j, kind))
        got = trim(adjustl(field_text(text, j + 1)))
        call read_real_field(field_text(text, j + 1), value, status)
        select case (status)
        case (FIELD_BAD, FIELD_RANGE)
            call field_problem(text, line, j + 1, what//': '//number_problem(status, got), diag)
            status = FIELD_BAD
        case (FIELD_BLANK)
            if (j > 1) return
            call field_problem(text, line, j + 1, what//' is required but the field is '// &
                               'blank (there is no default)', diag)
            status = FIELD_BAD
        case default
            if (kind == CHECK_CONTACT .and. (value <= 0.0_dp .or. value > 1.0_dp)) then
                call field_problem(text, line, j + 1, what//' must be in (0, 1], got '//got, diag)
                status = FIELD_BAD
            else if (value <= 0.0_dp) then
                call field_problem(text, line, j + 1, what//' must be > 0, got '//got, diag)
                status = FIELD_BAD
            end if
        end select
    end subroutine limit_field

    !> An error at field j of the card.
    subroutine field_problem(text, line, j, message, diag)
        character(len=*), intent(in) :: text, message
        integer, intent(in) :: line, j
        type(diagnostics_t), intent(inout) :: diag
        integer :: c1
        c1 = field_first_column(j)
        call add_diagnostic(diag, line, c1, c1 + field_width - 1, message, trim(text))
    end subroutine field_problem
end module check_cards
