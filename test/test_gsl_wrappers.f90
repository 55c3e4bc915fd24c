!> Tests of gsl_wrappers: complete elliptic integrals from the complementary parameter, QAGS.
module test_gsl_wrappers
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, check, check_close, error_t
    use gsl_wrappers, only: elliptic_ke_m1, integrand_t, integrate_qags
    implicit none
    private
    public :: collect_gsl_wrappers

    !> x^power on (0, 1] (power > -1 integrable, power = -1 divergent).
    type, extends(integrand_t) :: power_t
        real(dp) :: power = 0.0_dp
    contains
        procedure :: value => power_value
    end type power_t

    !> ln(x) on (0, 1].
    type, extends(integrand_t) :: log_t
    contains
        procedure :: value => log_value
    end type log_t

    !> Gamma(1/4) = 3.62560990822190831193068515586767200299516768288... (OEIS A068466)
    real(dp), parameter :: gamma_quarter = 3.6256099082219083_dp

contains

    subroutine collect_gsl_wrappers(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('elliptic_k_zero', test_k_zero), &
                 new_unittest('elliptic_lemniscatic', test_lemniscatic), &
                 new_unittest('elliptic_tiny_m1', test_tiny_m1), &
                 new_unittest('elliptic_legendre_relation', test_legendre_relation), &
                 new_unittest('elliptic_domain_error', test_elliptic_domain), &
                 new_unittest('qags_singular_integrals', test_qags), &
                 new_unittest('qags_divergent_is_error', test_qags_divergent)]
    end subroutine collect_gsl_wrappers

    !> k = 0 (m1 = 1): K = E = pi/2 (DLMF 19.6.1).
    subroutine test_k_zero(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: k_val, e_val
        call elliptic_ke_m1(1.0_dp, k_val, e_val, err)
        if (allocated(err)) return
        call check_close(err, k_val, 0.5_dp*pi, 4.0e-16_dp, 0.0_dp, 'K(0)')
        if (allocated(err)) return
        call check_close(err, e_val, 0.5_dp*pi, 4.0e-16_dp, 0.0_dp, 'E(0)')
        if (allocated(err)) return
    end subroutine test_k_zero

    !> k^2 = 1/2: K = Gamma(1/4)^2/(4 sqrt(pi)) = 1.8540746773013719... (the classical lemniscatic
    !! value), and
    !! Legendre's relation (DLMF 19.7.1) with k = k' gives E = pi/(4K) + K/2.
    subroutine test_lemniscatic(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: k_val, e_val, k_ref
        call elliptic_ke_m1(0.5_dp, k_val, e_val, err)
        if (allocated(err)) return
        k_ref = gamma_quarter**2/(4.0_dp*sqrt(pi))
        call check_close(err, k_val, k_ref, 4.0e-16_dp, 0.0_dp, 'K(1/sqrt 2)')
        if (allocated(err)) return
        call check_close(err, e_val, pi/(4.0_dp*k_ref) + 0.5_dp*k_ref, 4.0e-16_dp, 0.0_dp, &
                         'E(1/sqrt 2)')
        if (allocated(err)) return
    end subroutine test_lemniscatic

    !> m1 -> 0 (k -> 1, ring at the field radius): DLMF 19.12.1–2 to first order in m1,
    !! K = L + (m1/4)(L - 1), E = 1 + (m1/2)(L - 1/2), L = ln(4/k'), k' = sqrt(m1); the omitted
    !! terms are O(m1^2 L), below 1e-16 relative for m1 <= 1e-9. A code forming 1 - k^2 from
    !! k^2 would lose 9 of 16 digits here (and E = R_F - (k^2/3) R_D would cancel to an
    !! absolute error ~ eps K).
    subroutine test_tiny_m1(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: k_val, e_val, m1, big_l
        integer :: i
        real(dp), parameter :: m1_list(4) = [1.0e-9_dp, 1.0e-13_dp, 1.0e-17_dp, 1.0e-250_dp]
        cases: do i = 1, size(m1_list)
            m1 = m1_list(i)
            big_l = log(4.0_dp/sqrt(m1))
            call elliptic_ke_m1(m1, k_val, e_val, err)
            if (allocated(err)) return
            call check_close(err, k_val, big_l + 0.25_dp*m1*(big_l - 1.0_dp), 4.0e-16_dp, &
                             0.0_dp, 'K near k = 1')
            if (allocated(err)) return
            call check_close(err, e_val, 1.0_dp + 0.5_dp*m1*(big_l - 0.5_dp), 4.0e-16_dp, &
                             0.0_dp, 'E near k = 1')
            if (allocated(err)) return
        end do cases
    end subroutine test_tiny_m1

    !> Legendre's relation E K' + E' K - K K' = pi/2 (DLMF 19.7.1) for several moduli.
    subroutine test_legendre_relation(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: m1, k_val, e_val, kp, ep
        integer :: i
        real(dp), parameter :: m1_list(5) = [1.0e-6_dp, 0.05_dp, 0.3_dp, 0.49_dp, 0.93_dp]
        cases: do i = 1, size(m1_list)
            m1 = m1_list(i)
            call elliptic_ke_m1(m1, k_val, e_val, err)
            if (allocated(err)) return
            call elliptic_ke_m1(1.0_dp - m1, kp, ep, err)
            if (allocated(err)) return
            call check_close(err, e_val*kp + ep*k_val - k_val*kp, 0.5_dp*pi, 2.0e-15_dp, &
                             0.0_dp, 'Legendre relation')
            if (allocated(err)) return
        end do cases
    end subroutine test_legendre_relation

    !> m1 = 0 (k = 1, K infinite) and m1 > 1 are reported as errors, never returned as numbers.
    subroutine test_elliptic_domain(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: call_err
        real(dp) :: k_val, e_val
        call elliptic_ke_m1(0.0_dp, k_val, e_val, call_err)
        call check(err, allocated(call_err), 'K(k = 1) returned a number')
        if (allocated(err)) return
        call elliptic_ke_m1(1.5_dp, k_val, e_val, call_err)
        call check(err, allocated(call_err), 'm1 > 1 returned a number')
        if (allocated(err)) return
    end subroutine test_elliptic_domain

    !> int_0^1 ln x dx = -1, int_0^1 x^(-1/2) dx = 2 (elementary antiderivatives).
    subroutine test_qags(err)
        type(error_t), allocatable, intent(out) :: err
        type(log_t) :: f_log
        type(power_t) :: f_pow
        real(dp) :: result, abserr
        call integrate_qags(f_log, 0.0_dp, 1.0_dp, 0.0_dp, 1.0e-12_dp, result, abserr, err)
        if (allocated(err)) return
        call check_close(err, result, -1.0_dp, 1.0e-13_dp, 0.0_dp, 'int ln x')
        if (allocated(err)) return
        f_pow%power = -0.5_dp
        call integrate_qags(f_pow, 0.0_dp, 1.0_dp, 0.0_dp, 1.0e-12_dp, result, abserr, err)
        if (allocated(err)) return
        call check_close(err, result, 2.0_dp, 1.0e-13_dp, 0.0_dp, 'int x^-1/2')
        if (allocated(err)) return
    end subroutine test_qags

    !> int_0^1 dx/x diverges: QAGS must report a failure, not a number.
    subroutine test_qags_divergent(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: qags_err
        type(power_t) :: f_pow
        real(dp) :: result, abserr
        f_pow%power = -1.0_dp
        call integrate_qags(f_pow, 0.0_dp, 1.0_dp, 0.0_dp, 1.0e-10_dp, result, abserr, qags_err)
        call check(err, allocated(qags_err), 'QAGS accepted a divergent integral')
        if (allocated(err)) return
    end subroutine test_qags_divergent

    function power_value(self, x) result(f)
        class(power_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        f = x**self%power
    end function power_value

    function log_value(self, x) result(f)
        class(log_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        f = log(x)
    end function log_value
end module test_gsl_wrappers
