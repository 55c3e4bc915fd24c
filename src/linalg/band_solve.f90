!> Solves with a banded Cholesky factor K = L L^T as LAPACK's dpbtrf leaves it ('L' band
!! storage: kband(1 + i - j, j) = L(i, j) for j <= i <= j + kd), for one or many right-hand
!! sides. LAPACK's dpbtrs does the same with one BLAS dtbsv per right-hand side, which calls
!! a dot or axpy kernel per row: for the narrow bands of a beam or plate (kd = 3 to 8) those
!! calls cost about ten times the arithmetic (measured: dpbtrs was a quarter of the Newton
!! iterations at N_e = 20 and a tenth of the whole solve at N_e = 1000;
!! output/bench/linalg_before_after.md). The loops here run down the columns of the band, so
!! every access is contiguous, with the same operations in the same order as the
!! column-oriented substitution.
module band_solve
    use kinds, only: dp
    implicit none
    private
    public :: band_cholesky_solve

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
