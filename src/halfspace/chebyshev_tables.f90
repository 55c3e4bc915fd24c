!> Chebyshev interpolation of the half-space kernels across a cluster of elements, shared by
!! the station displacements (singular_quadrature, submodule station_displacement: a point
!! against a cluster) and the interpolated far blocks of T (galerkin_assembly: a cluster
!! against a cluster): the orders, their points of the first kind, the least gap / length at
!! which each order interpolates to 10^-cheb_digits, and the matrices of the Lagrange
!! polynomials. The cluster trees are not shared: their leaves (3 and 4 elements) and split
!! rules suit the two uses.
!!
!! Order m serves a cluster whose Bernstein ellipse through the nearest singular point has
!! rho >= 10^(cheb_digits/m), i.e. gap / length >= (c - 1)/2 with c = (rho + 1/rho)/2. The
!! Lagrange polynomial of point i of the m points of the first kind is
!! l_i = (2/m) sum'_{q<m} T_q(x_i) T_q (the q = 0 term halved).
module chebyshev_tables
    use kinds, only: dp, pi
    implicit none
    private

    integer, parameter, public :: n_cheb = 28            !! interpolation points, the most
    integer, parameter, public :: orders(5) = [12, 16, 20, 24, n_cheb]  !! orders used
    integer, parameter, public :: n_orders = size(orders)
    real(dp), parameter, public :: cheb_digits = 16.0_dp !! rho^(-order) <= 10^(-cheb_digits)

    !> Points, least gap / length and Lagrange matrices of every order (new_chebyshev).
    type, public :: chebyshev_t
        real(dp) :: cosines(n_cheb, n_orders) = 0.0_dp   !! cosines(i, k): point i of orders(k)
        real(dp) :: min_ratio(n_orders) = 0.0_dp         !! least gap / length of orders(k)
        real(dp) :: to_weights(n_cheb, n_cheb, n_orders) = 0.0_dp  !! (i, q + 1, k): (2/m) T_q
                                                   !! at point i of m = orders(k), q = 0 halved
    end type chebyshev_t

    public :: new_chebyshev, chebyshev_values, order_for

contains

    !> The tables of every order (module header).
    pure subroutine new_chebyshev(cheb)
        type(chebyshev_t), intent(out) :: cheb   !! the tables
        real(dp) :: theta, rho
        integer :: i, k, m
        by_order: do k = 1, n_orders
            m = orders(k)
            nodes: do i = 1, m
                theta = real(2*i - 1, dp)*pi/real(2*m, dp)
                cheb%cosines(i, k) = cos(theta)
            end do nodes
            call chebyshev_values(cheb%cosines(1:m, k), cheb%to_weights(1:m, 1:m, k))
            cheb%to_weights(1:m, 1:m, k) = (2.0_dp/real(m, dp))*cheb%to_weights(1:m, 1:m, k)
            cheb%to_weights(1:m, 1, k) = 0.5_dp*cheb%to_weights(1:m, 1, k)
            rho = 10.0_dp**(cheb_digits/real(m, dp))
            cheb%min_ratio(k) = 0.25_dp*(rho + 1.0_dp/rho) - 0.5_dp
        end do by_order
    end subroutine new_chebyshev

    !> t(i, q + 1) = T_q(xi(i)), q = 0, ..., size(t, 2) - 1, by the three-term recurrence
    !! (stable on [-1, 1]), on the vector of points.
    pure subroutine chebyshev_values(xi, t)
        real(dp), intent(in) :: xi(:)      !! points in [-1, 1]
        real(dp), intent(out) :: t(:, :)   !! t(i, q + 1) = T_q(xi(i))
        integer :: q
        t(:, 1) = 1.0_dp
        if (size(t, 2) >= 2) t(:, 2) = xi
        recurrence: do q = 3, size(t, 2)
            t(:, q) = 2.0_dp*xi*t(:, q - 1) - t(:, q - 2)
        end do recurrence
    end subroutine chebyshev_values

    !> The lowest order (its index k in orders) accurate for a cluster at gap / length =
    !! ratio; 0 if none is.
    pure integer function order_for(cheb, ratio) result(k)
        type(chebyshev_t), intent(in) :: cheb   !! the tables
        real(dp), intent(in) :: ratio           !! gap / length of the cluster
        by_order: do k = 1, n_orders
            if (ratio >= cheb%min_ratio(k)) return
        end do by_order
        k = 0
    end function order_for
end module chebyshev_tables
