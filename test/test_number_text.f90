!> number_text against the run-time library's formatted write, which takes its digits from the
!! C library's printf (an independent, correctly rounding implementation): the same text byte
!! for byte for every edit descriptor the outputs use, over magnitudes from 1e-30 to 1e30,
!! exact decimal ties, zeros of both signs, powers of ten and the extremes of double precision.
module test_number_text
    use kinds, only: dp
    use iso_fortran_env, only: int64
    use harness, only: unittest_t, new_unittest, error_t, check
    use number_text, only: es_text, f_text, integer_text
    implicit none
    private
    public :: collect_number_text

    !> the ES descriptors of the outputs: w, d, e (e = 0: the default exponent)
    integer, parameter :: n_es = 11
    integer, parameter :: es_w(n_es) = [13, 16, 23, 30, 30, 30, 10, 9, 14, 12, 10]
    integer, parameter :: es_d(n_es) = [4, 7, 15, 0, 3, 11, 2, 2, 5, 4, 3]
    integer, parameter :: es_e(n_es) = [0, 3, 3, 3, 3, 3, 0, 0, 0, 0, 0]

contains

    subroutine collect_number_text(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('es_text_equals_library_write', test_es), &
                 new_unittest('f_text_equals_library_write', test_f), &
                 new_unittest('exact_ties_round_to_even_as_library', test_ties), &
                 new_unittest('zero_extremes_and_narrow_fields', test_special), &
                 new_unittest('integer_text_equals_i0', test_integers)]
    end subroutine collect_number_text

    !> A reproducible sample: magnitudes log-uniform in [1e-30, 1e30], both signs (a
    !! multiplicative congruential generator, so the sample is the same on every machine).
    function sample(n) result(x)
        integer, intent(in) :: n
        real(dp) :: x(n)
        integer(int64) :: state
        integer :: i
        state = 12345_int64
        do i = 1, n
            state = mod(state*48271_int64, 2147483647_int64)
            x(i) = 10.0_dp**(60.0_dp*real(state, dp)/2147483647.0_dp - 30.0_dp)
            state = mod(state*48271_int64, 2147483647_int64)
            if (mod(state, 2_int64) == 0) x(i) = -x(i)
        end do
    end function sample

    function es_form(w, d, e) result(form)
        integer, intent(in) :: w, d, e
        character(len=24) :: form
        if (e > 0) then
            write (form, '(a,i0,a,i0,a,i0,a)') '(es', w, '.', d, 'e', e, ')'
        else
            write (form, '(a,i0,a,i0,a)') '(es', w, '.', d, ')'
        end if
    end function es_form

    !> Counts the values of x whose es_text differs from the library's text, every descriptor.
    integer function es_mismatches(x) result(bad)
        real(dp), intent(in) :: x(:)
        character(len=40) :: expected
        integer :: i, k
        bad = 0
        do i = 1, size(x)
            do k = 1, n_es
                write (expected(1:es_w(k)), es_form(es_w(k), es_d(k), es_e(k))) x(i)
                if (es_text(x(i), es_w(k), es_d(k), es_e(k)) /= expected(1:es_w(k))) bad = bad + 1
            end do
        end do
    end function es_mismatches

    !> Counts the values of x whose f_text differs from the library's (Fw.d, d = 0 .. 8).
    integer function f_mismatches(x, w) result(bad)
        real(dp), intent(in) :: x(:)
        integer, intent(in) :: w
        character(len=40) :: expected, form
        integer :: i, d
        bad = 0
        do i = 1, size(x)
            do d = 0, 8
                write (form, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
                write (expected(1:w), form) x(i)
                if (f_text(x(i), w, d) /= expected(1:w)) bad = bad + 1
            end do
        end do
    end function f_mismatches

    subroutine test_es(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: bad
        bad = es_mismatches(sample(20000))
        call check(err, bad == 0, 'es_text differs from the library in '//integer_text(bad)// &
                   ' of 220000 texts')
    end subroutine test_es

    subroutine test_f(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: bad
        ! F fields of 30 hold every sampled magnitude up to 1e20; wider ones give asterisks
        bad = f_mismatches(sample(20000), 30) + f_mismatches(sample(2000), 13)
        call check(err, bad == 0, 'f_text differs from the library in '//integer_text(bad)// &
                   ' texts')
    end subroutine test_f

    !> Values exactly halfway between two decimal texts: n + 1/2 and (n + 1/2)/1024 are exact
    !! in binary, so the library rounds a true tie (to even, in glibc).
    subroutine test_ties(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: x(4000)
        integer :: i, bad
        do i = 1, 2000
            x(i) = real(2*i + 1, dp)/2.0_dp
            x(2000 + i) = -x(i)/1024.0_dp
        end do
        bad = es_mismatches(x) + f_mismatches(x, 20)
        call check(err, bad == 0, 'ties: '//integer_text(bad)//' texts differ from the library')
    end subroutine test_ties

    subroutine test_special(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: x(14)
        integer :: bad, j
        x = [0.0_dp, -0.0_dp, huge(1.0_dp), -huge(1.0_dp), tiny(1.0_dp), -tiny(1.0_dp)/8.0_dp, &
             1.0e-300_dp, 9.99995e99_dp, 9.99995e-100_dp, 1.0e100_dp, -1.0e-5_dp, &
             0.99999999_dp, -4.9e-6_dp, 123456789.0_dp]
        bad = es_mismatches(x) + f_mismatches(x, 30) + f_mismatches(x, 5)
        ! powers of ten either side of every exponent the fast path takes
        do j = -40, 40
            bad = bad + es_mismatches([10.0_dp**j, nearest(10.0_dp**j, -1.0_dp)])
        end do
        call check(err, bad == 0, 'special values: '//integer_text(bad)//' texts differ')
    end subroutine test_special

    subroutine test_integers(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=12) :: expected
        integer :: values(9), i, bad
        values = [0, 1, -1, 9, 10, -10, 2147483647, -2147483647 - 1, 1000000]
        bad = 0
        do i = 1, size(values)
            write (expected, '(i0)') values(i)
            if (integer_text(values(i)) /= trim(expected)) bad = bad + 1
        end do
        call check(err, bad == 0, 'integer_text differs from I0 for '//integer_text(bad)// &
                   ' values')
    end subroutine test_integers
end module test_number_text
