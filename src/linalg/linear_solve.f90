!> Symmetric indefinite solve (Bunch–Kaufman LDL^T, LAPACK dsytrf/dsytrs) with INFO in words.
module linear_solve
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_ANALYSIS, EXIT_INTERNAL
    use lapack_interfaces, only: dsytrf, dsytrs
    implicit none
    private
    public :: solve_symmetric

contains

    !> Solve A x = b for symmetric A (lower triangle used). A is overwritten by its factors.
    !! Two steps of iterative refinement with the same factors recover the accuracy that
    !! ill-conditioning (a stiff structure held only by the soil) costs the plain solve.
    subroutine solve_symmetric(a, b, x, err)
        real(dp), intent(inout) :: a(:, :)   !! n x n symmetric matrix
        real(dp), intent(in) :: b(:)         !! right-hand side
        real(dp), intent(out) :: x(:)        !! solution
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: ipiv(:)
        real(dp), allocatable :: work(:), rhs(:, :), a_copy(:, :)
        real(dp) :: query(1)
        integer :: n, info, step
        character(len=160) :: text

        n = size(a, 1)
        if (size(a, 2) /= n .or. size(b) /= n .or. size(x) /= n .or. n < 1) then
            call new_error(err, EXIT_INTERNAL, 'solve_symmetric: inconsistent array sizes')
            return
        end if
        if (.not. all(a == a) .or. .not. all(b == b)) then
            call new_error(err, EXIT_INTERNAL, 'solve_symmetric: NaN in the system matrix or load')
            return
        end if
        allocate (ipiv(n), rhs(n, 1))
        a_copy = a
        call dsytrf('L', n, a, n, ipiv, query, -1, info)
        allocate (work(max(1, int(query(1)))))
        call dsytrf('L', n, a, n, ipiv, work, size(work), info)
        if (info > 0) then
            write (text, '(a,i0,a,i0,a)') 'the contact system is singular (D(', info, &
                ',', info, ') = 0 in LDL^T): the structure is not held (rigid-body motion)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        else if (info < 0) then
            write (text, '(a,i0)') 'dsytrf: illegal argument ', -info
            call new_error(err, EXIT_INTERNAL, trim(text))
            return
        end if
        rhs(:, 1) = b
        call dsytrs('L', n, 1, a, n, ipiv, rhs, n, info)
        if (info /= 0) then
            write (text, '(a,i0)') 'dsytrs: illegal argument ', -info
            call new_error(err, EXIT_INTERNAL, trim(text))
            return
        end if
        x = rhs(:, 1)
        refinement: do step = 1, 2
            call symmetric_residual(a_copy, x, b, rhs(:, 1))
            call dsytrs('L', n, 1, a, n, ipiv, rhs, n, info)
            x = x + rhs(:, 1)
        end do refinement
        if (.not. all(abs(x) <= huge(1.0_dp))) then
            call new_error(err, EXIT_ANALYSIS, 'the contact system is numerically singular '// &
                           '(non-finite solution)')
        end if
    end subroutine solve_symmetric

    !> r = b - A x with A symmetric, only its lower triangle defined (as dsytrf used it).
    pure subroutine symmetric_residual(a, x, b, r)
        real(dp), intent(in) :: a(:, :), x(:), b(:)
        real(dp), intent(out) :: r(:)
        integer :: j, n
        n = size(x)
        r = b
        do j = 1, n
            r(j:n) = r(j:n) - a(j:n, j)*x(j)
            r(j) = r(j) - dot_product(a(j + 1:n, j), x(j + 1:n))
        end do
    end subroutine symmetric_residual
end module linear_solve
