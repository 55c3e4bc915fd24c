!> Explicit interfaces to the LAPACK routines fricon calls (the only place with assumed size).
module lapack_interfaces
    use kinds, only: dp
    implicit none
    private
    public :: dsytrf, dsytrs, dpotrf, dlansy, dgesv, dgetrs, dgetrf, dpbtrf, dpbtrs
    public :: dspmv, dgemm

    interface
        subroutine dsytrf(uplo, n, a, lda, ipiv, work, lwork, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, lda, lwork
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*)
            real(dp), intent(inout) :: work(*)
            integer, intent(out) :: info
        end subroutine dsytrf

        subroutine dsytrs(uplo, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(in) :: a(lda, *)
            integer, intent(in) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dsytrs

        subroutine dpotrf(uplo, n, a, lda, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: info
        end subroutine dpotrf

        subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dgesv

        subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: trans
            integer, intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(in) :: a(lda, *)
            integer, intent(in) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dgetrs

        subroutine dgetrf(m, n, a, lda, ipiv, info)
            import :: dp
            integer, intent(in) :: m, n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer, intent(out) :: ipiv(*)
            integer, intent(out) :: info
        end subroutine dgetrf

        subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, kd, ldab
            real(dp), intent(inout) :: ab(ldab, *)
            integer, intent(out) :: info
        end subroutine dpbtrf

        subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, kd, nrhs, ldab, ldb
            real(dp), intent(in) :: ab(ldab, *)
            real(dp), intent(inout) :: b(ldb, *)
            integer, intent(out) :: info
        end subroutine dpbtrs

        function dlansy(norm, uplo, n, a, lda, work)
            import :: dp
            character(len=1), intent(in) :: norm, uplo
            integer, intent(in) :: n, lda
            real(dp), intent(in) :: a(lda, *)
            real(dp), intent(inout) :: work(*)
            real(dp) :: dlansy
        end function dlansy

        !> BLAS y := alpha A x + beta y, A symmetric in packed storage. Declared pure: it
        !! writes y only, so that the pure products of contact_system can use it.
        pure subroutine dspmv(uplo, n, alpha, ap, x, incx, beta, y, incy)
            import :: dp
            character(len=1), intent(in) :: uplo
            integer, intent(in) :: n, incx, incy
            real(dp), intent(in) :: alpha, beta
            real(dp), intent(in) :: ap(*), x(*)
            real(dp), intent(inout) :: y(*)
        end subroutine dspmv

        !> BLAS C := alpha op(A) op(B) + beta C (not pure: OpenBLAS may start threads).
        subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
            import :: dp
            character(len=1), intent(in) :: transa, transb
            integer, intent(in) :: m, n, k, lda, ldb, ldc
            real(dp), intent(in) :: alpha, beta
            real(dp), intent(in) :: a(lda, *), b(ldb, *)
            real(dp), intent(inout) :: c(ldc, *)
        end subroutine dgemm
    end interface
end module lapack_interfaces
