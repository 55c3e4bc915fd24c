!> Solves with a banded Cholesky factor K = L L^T as LAPACK's dpbtrf leaves it ('L' band
!! storage: kband(1 + i - j, j) = L(i, j) for j <= i <= j + kd), for one or many right-hand
!! sides. LAPACK's dpbtrs does the same with one BLAS dtbsv per right-hand side, which calls
!! a dot or axpy kernel per row: for the narrow bands of a beam or plate (kd = 3 to 8) those
!! calls cost about ten times the arithmetic (measured: dpbtrs was a quarter of the Newton
!! iterations at N_e = 20 and a tenth of the whole solve at N_e = 1000;
!! output/bench/linalg_before_after.md). `band_cholesky_solve` runs down the columns of the
!! band for one right-hand side at a time; `band_cholesky_solve_rows` takes many right-hand
!! sides as the rows of one array, so that each step of the substitution is one vector
!! operation across all of them (the Schur complement's set-up: thousands of right-hand
!! sides), and starts the forward substitution at the first row where any of them is nonzero
!! (columns of a coupling block: zero above their element). Both do the operations of the
!! column-oriented substitution in its order. Two routines because one right-hand side
!! through the row form (a 1 x n array) made the plate at N_e = 1000 10 % slower (measured,
!! fifth session: vector statements of length 1 in the inner loops).
module band_solve
    use kinds, only: dp
    implicit none
    private
    public :: band_cholesky_solve, band_cholesky_solve_rows

contains

    !> y <- K^-1 y, K = L L^T (kband, kd as above), column by column of y.
    pure subroutine band_cholesky_solve(kband, kd, y)
        real(dp), intent(in) :: kband(:, :)     !! (kd + 1, n) the factor L, dpbtrf 'L'
        integer, intent(in) :: kd               !! half bandwidth
        real(dp), intent(inout) :: y(:, :)      !! (n, nrhs)
        integer :: c
        do c = 1, size(y, 2)
            call forward(kband, kd, y(:, c))
            call backward(kband, kd, y(:, c))
        end do
    end subroutine band_cholesky_solve

    !> yt <- (K^-1 yt^T)^T: right-hand side r is the row yt(r, :) (K, kband, kd as above).
    pure subroutine band_cholesky_solve_rows(kband, kd, yt)
        real(dp), intent(in) :: kband(:, :)     !! (kd + 1, n) the factor L, dpbtrf 'L'
        integer, intent(in) :: kd               !! half bandwidth
        real(dp), intent(inout) :: yt(:, :)     !! (nrhs, n)
        integer :: j, i, n, j0
        n = size(yt, 2)
        j0 = n + 1
        do j = 1, n
            if (any(yt(:, j) /= 0.0_dp)) then
                j0 = j
                exit
            end if
        end do
        do j = j0, n                             ! L^-1: rows above j0 stay 0
            yt(:, j) = yt(:, j)/kband(1, j)
            do i = 1, min(kd, n - j)
                yt(:, j + i) = yt(:, j + i) - kband(1 + i, j)*yt(:, j)
            end do
        end do
        do j = n, 1, -1                          ! L^-T
            do i = 1, min(kd, n - j)
                yt(:, j) = yt(:, j) - kband(1 + i, j)*yt(:, j + i)
            end do
            yt(:, j) = yt(:, j)/kband(1, j)
        end do
    end subroutine band_cholesky_solve_rows

    !> y <- L^-1 y: each solved entry is removed from the entries below it in its column.
    pure subroutine forward(kband, kd, y)
        real(dp), intent(in) :: kband(:, :)
        integer, intent(in) :: kd
        real(dp), intent(inout) :: y(:)
        integer :: j, i, n
        n = size(y)
        do j = 1, n
            y(j) = y(j)/kband(1, j)
            do i = 1, min(kd, n - j)
                y(j + i) = y(j + i) - kband(1 + i, j)*y(j)
            end do
        end do
    end subroutine forward

    !> y <- L^-T y: row j of L^T is column j of L.
    pure subroutine backward(kband, kd, y)
        real(dp), intent(in) :: kband(:, :)
        integer, intent(in) :: kd
        real(dp), intent(inout) :: y(:)
        integer :: j, i, n
        real(dp) :: s
        n = size(y)
        do j = n, 1, -1
            s = y(j)
            do i = 1, min(kd, n - j)
                s = s - kband(1 + i, j)*y(j + i)
            end do
            y(j) = s/kband(1, j)
        end do
    end subroutine backward
end module band_solve
