!> Wavenumber quadrature of the layered ground's correction (SPEC §3a): composite
!! Gauss–Legendre rules on panels chosen from the layer depths and the structure's size, and a
!! product rule for integrands with a logarithmic end-point singularity.
!!
!! The integrands are phi(s) (layered_compliance: analytic, its nearest complex singularities
!! at distances of the order of 1/depth of the interfaces, decaying like exp(-2 s h_1)) times
!! products of transforms of the basis functions, which oscillate with a frequency omega up to
!! the structure's extent (2a for the plate's Hankel transforms, l for the beam's Fourier
!! transforms). The panels are [0, k_0], then doubling in length (a singularity at distance
!! ~k from the real axis next to wavenumber k is seen by a panel [k, 2k] at a Bernstein
!! ellipse parameter 4.2: 20 points give 1e-25), until their length reaches
!! 2 panel_phase/omega_eff, then equal, up to the end of the range. With 20 points a panel
!! integrates exp(i omega_eff t) to 1e-15 for half-panel phases up to panel_phase = 11
!! (measured: 9e-16 at 10, 3e-16 at 12); omega_eff = omega + 2 h_1 counts the growth of
!! exp(-2 s h_1) off the real axis as extra phase.
module layered_wavenumbers
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use quadrature, only: gauss_legendre
    use lapack_interfaces, only: dgesv
    implicit none
    private

    integer, parameter, public :: panel_points = 20     !! Gauss–Legendre points per panel
    real(dp), parameter, public :: panel_phase = 11.0_dp !! half-panel phase of 20 points
    integer, parameter, public :: log_degree = 10       !! the product rule is exact for
                                                        !! P_k(u) and P_k(u) ln u, k < 10

    !> Nodes and weights of a rule.
    type, public :: wavenumber_rule_t
        real(dp), allocatable :: node(:)
        real(dp), allocatable :: weight(:)
    end type wavenumber_rule_t

    public :: graded_breaks, panel_rule, log_product_rule

contains

    !> Panel ends 0, k_0, then lengths doubling up to delta, then equal, up to k_max; at most
    !! max_panels panels (more: an empty array).
    pure function graded_breaks(k_0, delta, k_max, max_panels) result(breaks)
        real(dp), intent(in) :: k_0       !! end of the first panel (> 0)
        real(dp), intent(in) :: delta     !! longest panel (> 0)
        real(dp), intent(in) :: k_max     !! end of the range
        integer, intent(in) :: max_panels   !! most panels
        real(dp), allocatable :: breaks(:)
        real(dp) :: k
        integer :: n, n_doubling
        ! panels: the first, the doublings while k < delta, then equal ones of length delta
        k = min(k_0, k_max)
        n_doubling = 0
        doubling: do while (k < min(delta, k_max*(1.0_dp - 1.0e-12_dp)))
            k = 2.0_dp*k
            n_doubling = n_doubling + 1
        end do doubling
        n = 1 + n_doubling
        if (k < k_max*(1.0_dp - 1.0e-12_dp)) then
            if ((k_max - k)/delta > real(max_panels, dp)) then
                allocate (breaks(0))
                return
            end if
            n = n + ceiling((k_max - k)/delta - 1.0e-9_dp)
        end if
        if (n > max_panels) then
            allocate (breaks(0))
            return
        end if
        allocate (breaks(0:n))
        breaks(0) = 0.0_dp
        breaks(1) = min(k_0, k_max)
        fill: do n = 2, size(breaks) - 1
            breaks(n) = min(breaks(n - 1) + min(breaks(n - 1), delta), k_max)
        end do fill
        breaks(size(breaks) - 1) = k_max
    end function graded_breaks

    !> Composite Gauss–Legendre rule, panel_points per panel between the breaks.
    pure subroutine panel_rule(breaks, rule)
        real(dp), intent(in) :: breaks(:)              !! panel ends, increasing
        type(wavenumber_rule_t), intent(out) :: rule   !! the composite rule
        real(dp) :: xi(panel_points), w(panel_points), half
        integer :: p, n
        call gauss_legendre(panel_points, xi, w)
        n = panel_points*(size(breaks) - 1)
        allocate (rule%node(n), rule%weight(n))
        panels: do p = 1, size(breaks) - 1
            half = 0.5_dp*(breaks(p + 1) - breaks(p))
            associate (k => (p - 1)*panel_points)
                rule%node(k + 1:k + panel_points) = breaks(p) + half*(xi + 1.0_dp)
                rule%weight(k + 1:k + panel_points) = half*w
            end associate
        end do panels
    end subroutine panel_rule

    !> A rule on [0, k_0] for f(k) = A(k) ln k + B(k), A and B smooth: 2 log_degree nodes
    !! u = t^2 (t the Gauss–Legendre nodes of [0, 1]), weights from the moments
    !! int_0^1 P_k(2u-1) du = delta_k0 and int_0^1 P_k(2u-1) ln u du = -1 (k = 0),
    !! (-1)^(k+1)/(k (k+1)) (k >= 1), so that the rule is exact for P_k and P_k ln u, k <
    !! log_degree (then scaled to [0, k_0]: ln k = ln u + ln k_0).
    subroutine log_product_rule(k_0, rule, err)
        real(dp), intent(in) :: k_0                      !! end of the range (> 0)
        type(wavenumber_rule_t), intent(out) :: rule     !! the rule on [0, k_0]
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer, parameter :: n = 2*log_degree
        real(dp) :: t(n), wt(n), a(n, n), moment(n, 1), p(0:log_degree - 1)
        integer :: ipiv(n), info, i, k
        call gauss_legendre(n, t, wt)
        t = 0.5_dp*(t + 1.0_dp)
        nodes: do i = 1, n
            p = legendre_values(2.0_dp*t(i)**2 - 1.0_dp)
            a(1:log_degree, i) = p
            a(log_degree + 1:n, i) = p*2.0_dp*log(t(i))
        end do nodes
        moment = 0.0_dp
        moment(1, 1) = 1.0_dp
        moment(log_degree + 1, 1) = -1.0_dp
        do k = 1, log_degree - 1
            moment(log_degree + 1 + k, 1) = real((-1)**(k + 1), dp)/real(k*(k + 1), dp)
        end do
        call dgesv(n, 1, a, n, ipiv, moment, n, info)
        if (info /= 0) then
            call new_error(err, EXIT_INTERNAL, 'logarithmic product rule: singular moments')
            return
        end if
        rule%node = k_0*t**2
        rule%weight = k_0*moment(:, 1)
    end subroutine log_product_rule

    !> P_0(x) .. P_(log_degree-1)(x) by the three-term recurrence.
    pure function legendre_values(x) result(p)
        real(dp), intent(in) :: x
        real(dp) :: p(0:log_degree - 1)
        integer :: k
        p(0) = 1.0_dp
        p(1) = x
        do k = 2, log_degree - 1
            p(k) = (real(2*k - 1, dp)*x*p(k - 1) - real(k - 1, dp)*p(k - 2))/real(k, dp)
        end do
    end function legendre_values
end module layered_wavenumbers
