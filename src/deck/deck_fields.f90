!> Low-level card-image parsing (doc/SPEC.md §8): column ranges, numbers read like Fortran
!! F10.0, words, the range rules of the deck fields, and the list of input errors with its
!! rendering (`deck:line:columns: text`, then the line and a caret marker under the field).
!!
!! Card layout (80 columns at most):
!!
!!     columns  1-10  card name, left-justified, case-insensitive
!!     columns 11-20  field f1
!!     columns 21-30  field f2   ...   columns 71-80  field f7
!!
!! Example (`*` in column 1 is a comment):
!!
!!     *...+....1....+....2....+....3
!!     STRUCTURE 30.0E6    0.2
!!
!! A numeric field is the 10-column substring: an optional sign, digits with an optional
!! decimal point, an optional exponent (E or D, optional sign, digits); blanks around it are
!! ignored, blanks inside, NaN, Inf and anything else are rejected. Without a decimal point the
!! number is an integer value (F10.0 has no implied decimals). A number is 0 or has a magnitude
!! in [1E-30, 1E+30): nothing derived from the deck can then overflow.
module deck_fields
    use kinds, only: dp
    use sorting, only: ascending_order
    ! decimal text of an integer (number_text's rule) under the name the deck's users know
    use number_text, only: int_text => integer_text
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    integer, parameter, public :: card_width = 80     !! columns of a card
    integer, parameter, public :: name_width = 10     !! columns 1-10: card name
    integer, parameter, public :: field_width = 10    !! each field f1..f7
    integer, parameter, public :: max_fields = 7      !! fields f1..f7

    !> Status of a field read.
    integer, parameter, public :: FIELD_BLANK = 0, FIELD_OK = 1, FIELD_BAD = 2, FIELD_RANGE = 3
    integer, parameter, public :: max_decade = 30   !! numbers are 0 or 1E-30 <= |x| < 1E+30

    !> Range rules of numeric fields (and SWEEP values).
    integer, parameter, public :: RULE_ANY = 0, RULE_POSITIVE = 1, RULE_NONNEGATIVE = 2, &
                                  RULE_NU_STRUCTURE = 3, RULE_NU_SOIL = 4, RULE_OPEN_UNIT = 5, &
                                  RULE_COUNT = 6, RULE_ELEMENTS = 7, RULE_STATIONS = 8

    integer, parameter, public :: max_elements = 100000   !! largest N_e accepted
    integer, parameter, public :: max_stations = 100000   !! largest OUTPUT stations accepted
    integer, parameter, public :: max_count = 1000000000  !! largest iteration count accepted
    integer, parameter :: max_listed = 200                 !! errors listed in one message

    !> One input error: where (line 0: the deck as a whole) and what.
    type :: diagnostic_t
        integer :: line = 0                       !! deck line, 0 for a card-level error
        integer :: first = 0                      !! first column of the offending text
        integer :: last = 0                       !! last column
        character(len=:), allocatable :: text     !! what was expected, what was found
        character(len=:), allocatable :: echo     !! the line as read (for the caret marker)
    end type diagnostic_t

    !> All input errors of a deck, in the order found (sorted when rendered).
    type, public :: diagnostics_t
        integer :: n = 0                               !! number of errors
        type(diagnostic_t), allocatable :: items(:)    !! items(1:n)
    end type diagnostics_t

    public :: field_first_column, field_text, read_real_field, read_word_field
    public :: rule_ok, rule_text, to_upper, format_real, int_text
    public :: add_diagnostic, render_diagnostics, number_problem

contains

    !> What is wrong with a number field read with status FIELD_BAD or FIELD_RANGE (the one
    !! wording of every card), quoting the field's text got.
    pure function number_problem(status, got) result(text)
        integer, intent(in) :: status          !! FIELD_BAD or FIELD_RANGE from read_real_field
        character(len=*), intent(in) :: got    !! the field as written
        character(len=:), allocatable :: text
        if (status == FIELD_RANGE) then
            text = 'a deck number is 0 or has a magnitude of at least 1E-30 and below 1E+30, '// &
                   'got '''//got//''''
        else
            text = 'expected a finite number such as 0.3, 30.0E6 or 1.0D-6, got '''//got//''''
        end if
    end function number_problem

    !> First column of field j (f1 = 11, f2 = 21, ..., f7 = 71).
    pure integer function field_first_column(j)
        integer, intent(in) :: j   !! field number 1..7
        field_first_column = name_width + 1 + (j - 1)*field_width
    end function field_first_column

    !> The 10 columns of field j of a card (blank beyond the end of the text).
    pure function field_text(card, j) result(text)
        character(len=*), intent(in) :: card   !! the card text
        integer, intent(in) :: j               !! field number 1..7
        character(len=field_width) :: text
        integer :: c1, c2
        c1 = field_first_column(j)
        c2 = min(c1 + field_width - 1, len(card))
        text = ''
        if (c2 >= c1) text = card(c1:c2)
    end function field_text

    !> Read a numeric field like F10.0 (see the module header). Numbers are 0 or of magnitude
    !! 1E-30 <= |x| < 1E+30 (FIELD_RANGE otherwise), so that nothing the model derives from
    !! them (h^3, l^4, products of moduli) can overflow.
    subroutine read_real_field(text, value, status)
        character(len=*), intent(in) :: text   !! the field's columns
        real(dp), intent(out) :: value         !! the number (0 unless FIELD_OK)
        integer, intent(out) :: status         !! FIELD_OK, FIELD_BLANK, FIELD_BAD, FIELD_RANGE
        character(len=len(text)) :: s
        logical :: ok, zero
        integer :: ios, decade
        value = 0.0_dp
        s = adjustl(text)
        if (len_trim(s) == 0) then
            status = FIELD_BLANK
            return
        end if
        status = FIELD_BAD
        call scan_number(trim(s), ok, zero, decade)
        if (.not. ok) return
        if (.not. zero .and. (decade >= max_decade .or. decade < -max_decade)) then
            status = FIELD_RANGE
            return
        end if
        read (s, '(f'//int_text(len(s))//'.0)', iostat=ios) value
        if (ios /= 0 .or. .not. ieee_is_finite(value)) then
            value = 0.0_dp
            return
        end if
        status = FIELD_OK
    end subroutine read_real_field

    !> Check s = [sign] digits [. digits] [(E|D) [sign] digits] (one mantissa digit at least);
    !! decade is the power of ten of the leading nonzero digit (0 and zero = .true. for 0).
    pure subroutine scan_number(s, ok, zero, decade)
        character(len=*), intent(in) :: s   !! trimmed text, no leading blank
        logical, intent(out) :: ok          !! s is a number
        logical, intent(out) :: zero        !! all mantissa digits are 0
        integer, intent(out) :: decade      !! floor(log10 |x|)
        integer :: i, start, n_int, n_frac, n_exp, k, e
        logical :: negative
        ok = .false.
        zero = .true.
        decade = 0
        i = 1
        call skip_sign(s, i, negative)
        start = i
        n_int = 0
        call skip_digits(s, i, n_int)
        call first_nonzero(s, start, n_int, n_int - 1, zero, decade)
        n_frac = 0
        if (i <= len(s)) then
            if (s(i:i) == '.') then
                i = i + 1
                start = i
                call skip_digits(s, i, n_frac)
                call first_nonzero(s, start, n_frac, -1, zero, decade)
            end if
        end if
        if (n_int + n_frac == 0) return
        if (i > len(s)) then
            ok = .true.
            return
        end if
        if (index('EeDd', s(i:i)) == 0) return
        i = i + 1
        call skip_sign(s, i, negative)
        start = i
        n_exp = 0
        call skip_digits(s, i, n_exp)
        if (n_exp == 0 .or. i <= len(s)) return
        ok = .true.
        e = 0
        do k = start, start + n_exp - 1
            e = min(10*e + iachar(s(k:k)) - iachar('0'), 100000)
        end do
        if (negative) e = -e
        decade = decade + e
    end subroutine scan_number

    !> Decade of the first nonzero digit of s(start:start+n-1), whose first digit has decade
    !! top; nothing changes if an earlier digit was nonzero already (zero = .false.).
    pure subroutine first_nonzero(s, start, n, top, zero, decade)
        character(len=*), intent(in) :: s
        integer, intent(in) :: start, n, top
        logical, intent(inout) :: zero       !! no nonzero digit yet
        integer, intent(inout) :: decade     !! set at the first nonzero digit
        integer :: k
        if (.not. zero) return
        digits: do k = start, start + n - 1
            if (s(k:k) /= '0') then
                decade = top - (k - start)
                zero = .false.
                exit digits
            end if
        end do digits
    end subroutine first_nonzero

    !> Skip an optional sign at position i.
    pure subroutine skip_sign(s, i, negative)
        character(len=*), intent(in) :: s
        integer, intent(inout) :: i
        logical, intent(out) :: negative
        negative = .false.
        if (i > len(s)) return
        negative = s(i:i) == '-'
        if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
    end subroutine skip_sign

    !> Skip the decimal digits from position i on, counting them into n.
    pure subroutine skip_digits(s, i, n)
        character(len=*), intent(in) :: s
        integer, intent(inout) :: i        !! position, left after the digits
        integer, intent(inout) :: n        !! digit count, incremented
        digits: do while (i <= len(s))
            if (s(i:i) < '0' .or. s(i:i) > '9') exit digits
            n = n + 1
            i = i + 1
        end do digits
    end subroutine skip_digits

    !> Read a one-word field, upper-cased; a blank inside the word is FIELD_BAD.
    pure subroutine read_word_field(text, word, status)
        character(len=*), intent(in) :: text       !! the field's columns
        character(len=len(text)), intent(out) :: word  !! upper case, left-justified
        integer, intent(out) :: status             !! FIELD_OK, FIELD_BLANK or FIELD_BAD
        word = to_upper(adjustl(text))
        if (len_trim(word) == 0) then
            status = FIELD_BLANK
        else if (index(trim(word), ' ') > 0) then
            status = FIELD_BAD
        else
            status = FIELD_OK
        end if
    end subroutine read_word_field

    !> Does x satisfy the rule?
    pure logical function rule_ok(rule, x)
        integer, intent(in) :: rule   !! RULE_*
        real(dp), intent(in) :: x     !! the value
        select case (rule)
        case (RULE_POSITIVE)
            rule_ok = x > 0.0_dp
        case (RULE_NONNEGATIVE)
            rule_ok = x >= 0.0_dp
        case (RULE_NU_STRUCTURE)
            rule_ok = x >= 0.0_dp .and. x < 0.5_dp
        case (RULE_NU_SOIL)
            rule_ok = x >= 0.0_dp .and. x <= 0.5_dp
        case (RULE_OPEN_UNIT)
            rule_ok = x > 0.0_dp .and. x < 1.0_dp
        case (RULE_COUNT)
            rule_ok = whole_in(x, 1, max_count)
        case (RULE_ELEMENTS)
            rule_ok = whole_in(x, 1, max_elements)
        case (RULE_STATIONS)
            rule_ok = whole_in(x, 2, max_stations)
        case default
            rule_ok = .true.
        end select
    end function rule_ok

    !> x is a whole number in [lo, hi].
    pure logical function whole_in(x, lo, hi)
        real(dp), intent(in) :: x
        integer, intent(in) :: lo, hi
        whole_in = x >= real(lo, dp) .and. x <= real(hi, dp)
        if (whole_in) whole_in = x == aint(x)
    end function whole_in

    !> The expectation of a rule, for messages ("must be > 0").
    pure function rule_text(rule) result(text)
        integer, intent(in) :: rule   !! RULE_*
        character(len=:), allocatable :: text
        select case (rule)
        case (RULE_POSITIVE)
            text = 'must be > 0'
        case (RULE_NONNEGATIVE)
            text = 'must be >= 0'
        case (RULE_NU_STRUCTURE)
            text = 'must be in [0, 0.5)'
        case (RULE_NU_SOIL)
            text = 'must be in [0, 0.5] (0.5, incompressible, is valid)'
        case (RULE_OPEN_UNIT)
            text = 'must be in (0, 1)'
        case (RULE_COUNT)
            text = 'must be a whole number in [1, '//int_text(max_count)//']'
        case (RULE_ELEMENTS)
            text = 'must be a whole number in [1, '//int_text(max_elements)//']'
        case (RULE_STATIONS)
            text = 'must be a whole number in [2, '//int_text(max_stations)//']'
        case default
            text = 'may be any number'
        end select
    end function rule_text

    !> Upper-case copy (ASCII letters only).
    pure function to_upper(s) result(u)
        character(len=*), intent(in) :: s   !! any text
        character(len=len(s)) :: u
        integer :: i, c
        u = s
        do i = 1, len(s)
            c = iachar(s(i:i))
            if (c >= iachar('a') .and. c <= iachar('z')) u(i:i) = achar(c - 32)
        end do
    end function to_upper

    !> Short text of a real with up to 10 significant digits: 0.0025, 6, -1.5E-12, 3.0E7.
    pure function format_real(x) result(text)
        real(dp), intent(in) :: x   !! the number
        character(len=:), allocatable :: text
        character(len=24) :: buf
        character(len=:), allocatable :: digits
        integer :: e, n
        if (x == 0.0_dp) then
            text = '0'
            return
        end if
        write (buf, '(es18.9e3)') abs(x)            ! d.ddddddddd E+eee
        buf = adjustl(buf)
        read (buf(13:16), '(i4)') e
        digits = buf(1:1)//buf(3:11)
        n = len_trim(digits)
        trailing: do while (n > 1)
            if (digits(n:n) /= '0') exit trailing
            n = n - 1
        end do trailing
        digits = digits(1:n)
        if (e >= 0 .and. e <= 6) then
            if (n <= e + 1) then
                text = digits//repeat('0', e + 1 - n)
            else
                text = digits(1:e + 1)//'.'//digits(e + 2:)
            end if
        else if (e < 0 .and. e >= -4) then
            text = '0.'//repeat('0', -e - 1)//digits
        else
            text = digits(1:1)//'.'//digits(2:)
            if (n == 1) text = text//'0'
            text = text//'E'//int_text(e)
        end if
        if (x < 0.0_dp) text = '-'//text
    end function format_real

    !> Record one input error (line 0 for a card-level error without a line).
    pure subroutine add_diagnostic(diag, line, first, last, text, echo)
        type(diagnostics_t), intent(inout) :: diag   !! the list
        integer, intent(in) :: line                  !! deck line, 0 if none
        integer, intent(in) :: first, last           !! column range (0 if none)
        character(len=*), intent(in) :: text         !! message
        character(len=*), intent(in) :: echo         !! the line's text ('' if none)
        type(diagnostic_t), allocatable :: grown(:)
        if (.not. allocated(diag%items)) allocate (diag%items(8))
        if (diag%n == size(diag%items)) then
            allocate (grown(2*diag%n))
            grown(1:diag%n) = diag%items(1:diag%n)
            call move_alloc(grown, diag%items)
        end if
        diag%n = diag%n + 1
        diag%items(diag%n)%line = line
        diag%items(diag%n)%first = first
        diag%items(diag%n)%last = last
        diag%items(diag%n)%text = text
        diag%items(diag%n)%echo = echo
    end subroutine add_diagnostic

    !> All errors in line order (card-level errors last), under a count line.
    pure function render_diagnostics(diag, deck_name, headline) result(message)
        type(diagnostics_t), intent(in) :: diag      !! the errors (n >= 1)
        character(len=*), intent(in) :: deck_name    !! deck name as given
        character(len=*), intent(in) :: headline     !! end of the count line
        character(len=:), allocatable :: message
        integer, allocatable :: order(:)
        integer :: k, shown
        character(len=1), parameter :: nl = new_line('a')
        order = line_order(diag)
        message = int_text(diag%n)//' input error'
        if (diag%n /= 1) message = message//'s'
        message = message//' in '//deck_name//headline
        shown = min(diag%n, max_listed)
        do k = 1, shown
            message = message//nl//render_one(diag%items(order(k)), deck_name)
        end do
        if (diag%n > shown) message = message//nl//'... '//int_text(diag%n - shown)// &
                                      ' more errors not listed'
    end function render_diagnostics

    !> Stable sort of the errors by (line, first column); line 0 goes last. The key line *
    !! 10^4 + column is exact in double precision for any line below 10^11.
    pure function line_order(diag) result(order)
        type(diagnostics_t), intent(in) :: diag   !! the errors
        integer, allocatable :: order(:)
        real(dp) :: key(diag%n)
        integer :: i
        do i = 1, diag%n
            key(i) = real(diag%items(i)%line, dp)
            if (diag%items(i)%line == 0) key(i) = 1.0e10_dp
            key(i) = key(i)*1.0e4_dp + real(diag%items(i)%first, dp)
        end do
        order = ascending_order(key)
    end function line_order

    !> `deck:line:c1-c2: text`, the line and the carets (or `deck: text` without a line).
    pure function render_one(d, deck_name) result(text)
        type(diagnostic_t), intent(in) :: d
        character(len=*), intent(in) :: deck_name
        character(len=:), allocatable :: text
        character(len=1), parameter :: nl = new_line('a')
        if (d%line <= 0) then
            text = deck_name//': '//d%text
            return
        end if
        text = deck_name//':'//int_text(d%line)//':'
        if (d%first > 0) then
            text = text//int_text(d%first)
            if (d%last > d%first) text = text//'-'//int_text(d%last)
            text = text//':'
        end if
        text = text//' '//d%text
        if (len_trim(d%echo) > 0 .or. d%first > 0) then
            text = text//nl//'  '//trim(d%echo)
            if (d%first > 0) text = text//nl//'  '//repeat(' ', d%first - 1)// &
                                    repeat('^', max(1, d%last - d%first + 1))
        end if
    end function render_one
end module deck_fields
