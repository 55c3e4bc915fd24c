!> J0 and J1 on [0, x_max] for the Hankel transforms of the layered plate (layered_influence):
!! a table of polynomials of degree table_degree, one per unit interval [i, i + 1], each the
!! Taylor polynomial of J0 or J1 about the interval's centre c = i + 1/2 in t = 2 (x - c),
!! summed by Estrin's scheme. The derivatives come from the intrinsic bessel_jn at c:
!!     J_nu^(k) = 2^(-k) sum_(m=0..k) (-1)^m C(k, m) J_(nu-k+2m),   J_(-n) = (-1)^n J_n,
!! a sum of terms below 2^k in all, so each coefficient a_k = J^(k)(c) 2^(-k)/k! carries an
!! absolute error of a few 1e-16 2^(-k)/k! (a power series from interpolation would not: its
!! coefficients cancel to 1e-12).
!!
!! Accuracy: every derivative of J0 and J1 is at most 1 in magnitude, so the remainder after
!! degree 15 is below 2^(-16)/16! = 7e-19 for |t| <= 1, and the values are within a few
!! 1e-16 of J (absolute) wherever the intrinsic is; test layered_ground/bessel_table measures
!! them against the intrinsic at 20000 points. Building a table costs 17 bessel_jn per unit of
!! x_max; a value then costs one polynomial instead of the intrinsic's argument reduction,
!! sine, cosine and rational approximations (output/bench/layered.md).
module layered_bessel
    use kinds, only: dp
    implicit none
    private

    integer, parameter, public :: table_degree = 15   !! degree of the polynomial of a piece

    !> Power-series coefficients of J0 and J1 on the pieces [i, i + 1], i = 0 .. n - 1.
    type, public :: bessel_table_t
        real(dp), allocatable :: j0(:, :)   !! (0:table_degree, 0:n - 1)
        real(dp), allocatable :: j1(:, :)   !! (0:table_degree, 0:n - 1)
    end type bessel_table_t

    public :: new_bessel_table, bessel_table_pair

contains

    !> The table of J0 and J1 on [0, x_max] (module header).
    pure subroutine new_bessel_table(x_max, table)
        real(dp), intent(in) :: x_max                !! largest argument to be evaluated (>= 0)
        type(bessel_table_t), intent(out) :: table   !! the table
        real(dp) :: jn(0:table_degree + 1), centre
        integer :: n, piece, k
        n = max(1, ceiling(max(x_max, 0.0_dp)) + 1)
        allocate (table%j0(0:table_degree, 0:n - 1), table%j1(0:table_degree, 0:n - 1))
        pieces: do piece = 0, n - 1
            centre = real(piece, dp) + 0.5_dp
            orders: do k = 0, table_degree + 1
                jn(k) = bessel_jn(k, centre)
            end do orders
            table%j0(:, piece) = taylor_coefficients(0, jn)
            table%j1(:, piece) = taylor_coefficients(1, jn)
        end do pieces
    end subroutine new_bessel_table

    !> a_k = J_nu^(k)(c) 2^(-k) / k!, k = 0 .. table_degree, from jn(n) = J_n(c) (module
    !! header).
    pure function taylor_coefficients(nu, jn) result(a)
        integer, intent(in) :: nu                        !! 0 or 1
        real(dp), intent(in) :: jn(0:)                   !! J_0(c) .. J_(table_degree+1)(c)
        real(dp) :: a(0:table_degree)
        real(dp) :: binomial, total, scale
        integer :: k, m, order
        scale = 1.0_dp
        derivatives: do k = 0, table_degree
            binomial = 1.0_dp
            total = 0.0_dp
            terms: do m = 0, k
                order = nu - k + 2*m
                total = total + real((-1)**m, dp)*binomial*real(merge(1, (-1)**abs(order), &
                        order >= 0), dp)*jn(abs(order))
                binomial = binomial*real(k - m, dp)/real(m + 1, dp)
            end do terms
            if (k > 0) scale = scale/(4.0_dp*real(k, dp))
            a(k) = total*scale
        end do derivatives
    end function taylor_coefficients

    !> j0(i) = J0(x(i)), j1(i) = J1(x(i)), 0 <= x(i) <= the table's x_max.
    pure subroutine bessel_table_pair(table, x, j0, j1)
        type(bessel_table_t), intent(in) :: table   !! the table (new_bessel_table)
        real(dp), intent(in) :: x(:)                !! arguments
        real(dp), intent(out) :: j0(:), j1(:)       !! J0(x), J1(x)
        real(dp) :: t
        integer :: i, piece, last
        last = ubound(table%j0, 2)
        arguments: do i = 1, size(x)
            piece = min(int(x(i)), last)
            t = 2.0_dp*(x(i) - real(piece, dp)) - 1.0_dp   ! 2 (x - centre)
            j0(i) = estrin(table%j0(:, piece), t)
            j1(i) = estrin(table%j1(:, piece), t)
        end do arguments
    end subroutine bessel_table_pair

    !> sum a_k t^k, k = 0 .. 15 (table_degree), by Estrin's scheme written out (pairs, then
    !! powers t^2, t^4, t^8: four dependent steps instead of Horner's fifteen; the terms fall
    !! off like 4^(-k)/k!, so either order of summation is exact to rounding). Measured:
    !! 8.5 ns for J0 and J1 together against 52 ns for the intrinsics (one thread, loaded).
    pure real(dp) function estrin(a, t) result(v)
        real(dp), intent(in) :: a(0:table_degree)
        real(dp), intent(in) :: t
        real(dp) :: t2, t4
        t2 = t*t
        t4 = t2*t2
        v = (((a(0) + a(1)*t) + (a(2) + a(3)*t)*t2) + ((a(4) + a(5)*t) + (a(6) + a(7)*t)*t2)*t4) &
            + (((a(8) + a(9)*t) + (a(10) + a(11)*t)*t2) + ((a(12) + a(13)*t) + &
               (a(14) + a(15)*t)*t2)*t4)*(t4*t4)
    end function estrin
end module layered_bessel
