!> Decimal text of numbers exactly as Fortran's ES, F and I0 edit descriptors write them, byte
!! for byte, without the run-time library's formatted I/O. A run writes thousands of numbers
!! (the report's station table, the data files, the JSON, the HTML record) and gfortran's
!! formatted `write` costs 1,500 to 10,000 instructions a number (it goes through the C
!! library's printf); the digits here come from one exact integer division.
!!
!! The digits are the correctly rounded decimal digits of the binary value, ties to even,
!! which is what gfortran's default rounding mode gives through glibc. Where the exact
!! division does not fit in 128-bit integers (magnitudes beyond about 1e-17 .. 1e38 for the
!! digits asked), and for zero, subnormal, infinite or NaN values and fields too narrow, the
!! text comes from gfortran's own internal write, so the result is the same in every case.
module number_text
    use kinds, only: dp
    use iso_fortran_env, only: int64
    implicit none
    private

    public :: es_text, f_text, integer_text

    integer, parameter :: i16 = selected_int_kind(38)
    integer :: j_
    !> 10^j for j = 0 .. 38, the powers that fit in a signed 128-bit integer
    integer(i16), parameter :: pow10(0:38) = [(10_i16**j_, j_=0, 38)]
    !> bits that a product may use: 2^126 stays clear of the sign bit with a carry to spare
    integer, parameter :: max_bits = 125
    real(dp), parameter :: log2_10 = 3.321928094887362_dp
    real(dp), parameter :: log10_2 = 0.3010299956639812_dp
    !> significant digits of the fast path: n < 10^18 fits in 64 bits
    integer, parameter :: max_digits = 18
    integer, parameter :: buf_len = 64

contains

    !> x as '(ESw.dEe)' writes it (e = 0: '(ESw.d)'), w characters, right-justified.
    pure function es_text(x, w, d, e) result(text)
        real(dp), intent(in) :: x     !! the number
        integer, intent(in) :: w      !! field width
        integer, intent(in) :: d      !! digits after the decimal point (d + 1 significant)
        integer, intent(in) :: e      !! exponent digits; 0: Fortran's default exponent form
        character(len=w) :: text
        integer(i16) :: n
        integer :: p, k, n_exp
        logical :: ok
        character(len=buf_len) :: buf
        ok = d >= 0 .and. d <= max_digits - 1 .and. w <= buf_len .and. &
             (abs(x) >= tiny(x) .or. x == 0.0_dp) .and. abs(x) <= huge(x)
        if (ok .and. x == 0.0_dp) then
            ! Fortran writes zero with the exponent 0
            n = 0
            p = 0
        else if (ok) then
            ! 10^p <= |x| < 10^(p+1), p from the binary exponent (exact up to one step)
            p = floor(real(exponent(x) - 1, dp)*log10_2)
            call leading_digits(x, p, d, n, ok)
        end if
        if (ok) then
            ! E+pp or +ppp by default, else E and e digits
            n_exp = merge(e, merge(2, 3, abs(p) <= 99), e > 0)
            ok = abs(p) < pow10(min(n_exp, 9)) .and. n_exp <= 9
        end if
        if (.not. ok) then
            text = library_text(x, 'es', w, d, e)
            return
        end if
        ! filled from the right: exponent, fraction digits, point, leading digit, sign
        buf = ' '
        k = buf_len
        call put_digits(buf, k, int(abs(p), int64), n_exp)
        call put_char(buf, k, merge('-', '+', p < 0))
        if (e > 0 .or. n_exp == 2) call put_char(buf, k, 'E')
        ! n < 10^(d+1) <= 10^18 fits in 64 bits, where dividing is not a library call
        call put_digits(buf, k, mod(int(n, int64), int(pow10(d), int64)), d)
        call put_char(buf, k, '.')
        call put_digits(buf, k, int(n, int64)/int(pow10(d), int64), 1)
        ! the sign of a negative zero is written too
        if (sign(1.0_dp, x) < 0.0_dp) call put_char(buf, k, '-')
        if (buf_len - k > w) then
            text = library_text(x, 'es', w, d, e)
        else
            text = buf(buf_len - w + 1:)
        end if
    end function es_text

    !> x as '(Fw.d)' writes it, w characters, right-justified.
    pure function f_text(x, w, d) result(text)
        real(dp), intent(in) :: x     !! the number
        integer, intent(in) :: w      !! field width
        integer, intent(in) :: d      !! digits after the decimal point
        character(len=w) :: text
        integer(i16) :: n
        integer :: k
        logical :: ok
        character(len=buf_len) :: buf
        ok = d >= 0 .and. d <= 30 .and. w <= buf_len .and. &
             (abs(x) >= tiny(x) .or. x == 0.0_dp) .and. abs(x) < 1.0e17_dp
        n = 0
        if (ok .and. x /= 0.0_dp) call rounded_quotient(x, -d, n, ok)
        if (ok) ok = n < pow10(max_digits)
        if (.not. ok) then
            text = library_text(x, 'f', w, d, 0)
            return
        end if
        buf = ' '
        k = buf_len
        call put_digits(buf, k, int(mod(n, pow10(d)), int64), d)
        call put_char(buf, k, '.')
        call put_digits(buf, k, int(n/pow10(d), int64), max(1, count_digits(n) - d))
        ! a negative value keeps its sign even where it rounds to zero (-0.0000)
        if (sign(1.0_dp, x) < 0.0_dp) call put_char(buf, k, '-')
        if (buf_len - k > w) then
            text = library_text(x, 'f', w, d, 0)
        else
            text = buf(buf_len - w + 1:)
        end if
    end function f_text

    !> Writes the n_digits last decimal digits of v (zero-padded) to the left of buf(k+1:),
    !! moving k to the left.
    pure subroutine put_digits(buf, k, v, n_digits)
        character(len=*), intent(inout) :: buf
        integer, intent(inout) :: k
        integer(int64), intent(in) :: v
        integer, intent(in) :: n_digits
        integer(int64) :: rest
        integer :: j
        rest = v
        do j = 1, n_digits
            buf(k:k) = achar(iachar('0') + int(mod(rest, 10_int64)))
            rest = rest/10_int64
            k = k - 1
        end do
    end subroutine put_digits

    !> Writes c to the left of buf(k+1:), moving k to the left.
    pure subroutine put_char(buf, k, c)
        character(len=*), intent(inout) :: buf
        integer, intent(inout) :: k
        character(len=1), intent(in) :: c
        buf(k:k) = c
        k = k - 1
    end subroutine put_char

    !> i as '(I0)' writes it.
    pure function integer_text(i) result(text)
        integer, intent(in) :: i     !! the integer
        character(len=:), allocatable :: text
        character(len=12) :: buf
        integer :: k
        integer(int64) :: v
        v = abs(int(i, int64))
        k = len(buf) + 1
        do
            k = k - 1
            buf(k:k) = achar(iachar('0') + int(mod(v, 10_int64)))
            v = v/10_int64
            if (v == 0) exit
        end do
        if (i < 0) then
            k = k - 1
            buf(k:k) = '-'
        end if
        text = buf(k:)
    end function integer_text

    !> The d + 1 leading digits n of |x| (10^d <= n < 10^(d+1)) and its decimal exponent p,
    !! starting from an estimate of p that is at most one too small or too large.
    pure subroutine leading_digits(x, p, d, n, ok)
        real(dp), intent(in) :: x
        integer, intent(inout) :: p     !! in: the estimate; out: the exponent of the text
        integer, intent(in) :: d
        integer(i16), intent(out) :: n
        logical, intent(out) :: ok
        integer :: tries
        integer(i16) :: num, den, r
        ok = d + 1 <= 38
        if (.not. ok) return
        do tries = 1, 3
            ! the truncated quotient decides p; rounding it may then carry into 10^(d+1)
            call exact_ratio(x, p - d, num, den, ok)
            if (.not. ok) return
            call divide(num, den, n, r)
            if (n >= pow10(d + 1)) then
                p = p + 1
            else if (n < pow10(d)) then
                p = p - 1
            else
                if (2*r > den .or. (2*r == den .and. mod(n, 2_i16) == 1)) n = n + 1
                if (n == pow10(d + 1)) then
                    n = pow10(d)
                    p = p + 1
                end if
                return
            end if
        end do
        ok = .false.
    end subroutine leading_digits

    !> n = |x| / 10^k rounded to the nearest integer, ties to even.
    pure subroutine rounded_quotient(x, k, n, ok)
        real(dp), intent(in) :: x
        integer, intent(in) :: k
        integer(i16), intent(out) :: n
        logical, intent(out) :: ok
        integer(i16) :: num, den, r
        call exact_ratio(x, k, num, den, ok)
        if (.not. ok) return
        call divide(num, den, n, r)
        if (2*r > den .or. (2*r == den .and. mod(n, 2_i16) == 1)) n = n + 1
    end subroutine rounded_quotient

    !> n = num / den truncated and the remainder r (num >= 0, den > 0). A den that is a power
    !! of two (every number below 10^d written with d digits: den = 2^-q) is a shift: a
    !! 128-bit division is a library call of a hundred or more instructions.
    pure subroutine divide(num, den, n, r)
        integer(i16), intent(in) :: num, den
        integer(i16), intent(out) :: n, r
        integer :: s
        if (iand(den, den - 1_i16) == 0_i16) then
            s = trailz(den)
            n = shiftr(num, s)
            r = iand(num, den - 1_i16)
        else
            n = num/den
            r = num - n*den
        end if
    end subroutine divide

    !> |x| / 10^k = num / den exactly, with |x| = m 2^q (m an integer of 53 bits); ok is false
    !! where num or den would not fit in 125 bits.
    pure subroutine exact_ratio(x, k, num, den, ok)
        real(dp), intent(in) :: x
        integer, intent(in) :: k
        integer(i16), intent(out) :: num, den
        logical, intent(out) :: ok
        integer(i16) :: m
        integer :: q
        q = exponent(x) - digits(x)
        m = int(scale(fraction(abs(x)), digits(x)), i16)
        ok = abs(k) <= 38 .and. abs(q) <= max_bits .and. &
             digits(x) + max(q, 0) + power_bits(max(-k, 0)) <= max_bits .and. &
             max(-q, 0) + power_bits(max(k, 0)) <= max_bits
        if (.not. ok) return
        num = shiftl(m, max(q, 0))*pow10(max(-k, 0))
        den = shiftl(1_i16, max(-q, 0))*pow10(max(k, 0))
    end subroutine exact_ratio

    !> Bits of 10^j, rounded up.
    elemental integer function power_bits(j)
        integer, intent(in) :: j
        power_bits = ceiling(j*log2_10) + 1
    end function power_bits

    !> The number of decimal digits of n (1 for n = 0).
    pure integer function count_digits(n)
        integer(i16), intent(in) :: n
        count_digits = 1
        if (n <= 0) return
        do while (count_digits < 38)
            if (n < pow10(count_digits)) exit
            count_digits = count_digits + 1
        end do
    end function count_digits

    !> The run-time library's text of x: the reference the fast path reproduces, and the
    !! path for the values it does not take.
    pure function library_text(x, kind, w, d, e) result(text)
        real(dp), intent(in) :: x
        character(len=*), intent(in) :: kind     !! 'es' or 'f'
        integer, intent(in) :: w, d, e
        character(len=w) :: text
        character(len=32) :: form
        if (e > 0) then
            write (form, '(a,a,i0,a,i0,a,i0,a)') '(', kind, w, '.', d, 'e', e, ')'
        else
            write (form, '(a,a,i0,a,i0,a)') '(', kind, w, '.', d, ')'
        end if
        write (text, form) x
    end function library_text
end module number_text
