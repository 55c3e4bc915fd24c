!> Gauss–Legendre rules on [-1, 1], computed to full double precision.
!!
!! Nodes are the roots of P_n found by Newton's method from the Tricomi initial guess
!! (Abramowitz & Stegun 25.4.29); weights w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2).
module quadrature
    use kinds, only: dp, pi
    implicit none
    private

    public :: gauss_legendre

contains

    !> n-point Gauss–Legendre nodes and weights on [-1, 1] (exact for degree 2n-1).
    pure subroutine gauss_legendre(n, xi, w)
        integer, intent(in) :: n          !! number of points, n >= 1
        real(dp), intent(out) :: xi(n)    !! nodes, increasing
        real(dp), intent(out) :: w(n)     !! weights, sum 2
        integer :: i, iter
        real(dp) :: x, p, dp_dx, dx

        roots: do i = 1, (n + 1)/2
            x = cos(pi*(real(i, dp) - 0.25_dp)/(real(n, dp) + 0.5_dp))
            newton: do iter = 1, 100
                call legendre_value(n, x, p, dp_dx)
                dx = p/dp_dx
                x = x - dx
                if (abs(dx) <= 2.0_dp*epsilon(1.0_dp)*abs(x)) exit newton
            end do newton
            call legendre_value(n, x, p, dp_dx)
            xi(i) = -x
            xi(n + 1 - i) = x
            w(i) = 2.0_dp/((1.0_dp - x*x)*dp_dx*dp_dx)
            w(n + 1 - i) = w(i)
        end do roots
        if (mod(n, 2) == 1) xi((n + 1)/2) = 0.0_dp
    end subroutine gauss_legendre

    !> P_n(x) and P_n'(x) by the three-term recurrence.
    pure subroutine legendre_value(n, x, p, dp_dx)
        integer, intent(in) :: n
        real(dp), intent(in) :: x
        real(dp), intent(out) :: p, dp_dx
        real(dp) :: p_prev, p_next
        integer :: k
        p_prev = 1.0_dp
        p = x
        if (n == 0) then
            p = 1.0_dp
            dp_dx = 0.0_dp
            return
        end if
        recurrence: do k = 2, n
            p_next = (real(2*k - 1, dp)*x*p - real(k - 1, dp)*p_prev)/real(k, dp)
            p_prev = p
            p = p_next
        end do recurrence
        dp_dx = real(n, dp)*(x*p - p_prev)/(x*x - 1.0_dp)
    end subroutine legendre_value
end module quadrature
