!> Dense solves with INFO in words: symmetric indefinite (Bunch–Kaufman LDL^T, LAPACK
!! dsytrf/dsytrs) and general (LU with partial pivoting, dgesv/dgetrs).
module linear_solve
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_ANALYSIS, EXIT_INTERNAL
    use lapack_interfaces, only: dsytrf, dsytrs, dgesv, dgetrs
    implicit none
    private
    public :: solve_symmetric, solve_general, solve_equilibrated

contains

    !> Solve A x = b for symmetric A (lower triangle used). A is overwritten by its factors.
    !! Two steps of iterative refinement with the same factors recover the accuracy that
    !! ill-conditioning (a stiff structure held only by the soil) costs the plain solve.
    subroutine solve_symmetric(a, b, x, err)
        real(dp), intent(inout) :: a(:, :)   !! n x n symmetric matrix
        real(dp), intent(in) :: b(:)         !! right-hand side
        real(dp), intent(out) :: x(:)        !! solution
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer, allocatable :: ipiv(:)
        real(dp), allocatable :: work(:), rhs(:, :), a_copy(:, :)
        real(dp) :: query(1)
        integer :: n, info, step
        character(len=160) :: text

        n = size(a, 1)
        call check_system('solve_symmetric', a, b, x, err)
        if (allocated(err)) return
        allocate (ipiv(n), rhs(n, 1))
        a_copy = a
        call dsytrf('L', n, a, n, ipiv, query, -1, info)
        allocate (work(max(1, int(query(1)))))
        call dsytrf('L', n, a, n, ipiv, work, size(work), info)
        call factorisation_info('dsytrf', 'D', 'LDL^T', info, err)
        if (allocated(err)) return
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

    !> The words for a factorisation's info: > 0 a zero pivot (the structure is not held),
    !! < 0 an illegal argument (a broken invariant of ours).
    subroutine factorisation_info(routine, factor, method, info, err)
        character(len=*), intent(in) :: routine          !! LAPACK routine, e.g. 'dgesv'
        character(len=*), intent(in) :: factor           !! the factor with the zero pivot
        character(len=*), intent(in) :: method           !! 'LU' or 'LDL^T'
        integer, intent(in) :: info                      !! its info
        type(error_t), allocatable, intent(out) :: err   !! none for info = 0
        character(len=160) :: text
        if (info > 0) then
            write (text, '(a,i0,a,i0,a)') 'the contact system is singular ('//factor//'(', info, &
                ',', info, ') = 0 in '//method//'): the structure is not held (rigid-body motion)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
        else if (info < 0) then
            write (text, '(a,i0)') routine//': illegal argument ', -info
            call new_error(err, EXIT_INTERNAL, trim(text))
        end if
    end subroutine factorisation_info

    !> Square, consistent sizes and no NaN: the preconditions of both solvers (LAPACK's XERBLA,
    !! which stops the program, is never reached).
    subroutine check_system(who, a, b, x, err)
        character(len=*), intent(in) :: who
        real(dp), intent(in) :: a(:, :), b(:), x(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: n
        n = size(a, 1)
        if (size(a, 2) /= n .or. size(b) /= n .or. size(x) /= n .or. n < 1) then
            call new_error(err, EXIT_INTERNAL, who//': inconsistent array sizes')
        else if (.not. all(a == a) .or. .not. all(b == b)) then
            call new_error(err, EXIT_INTERNAL, who//': NaN in the system matrix or load')
        end if
    end subroutine check_system

    !> Solve A x = b for a general square A (LU, dgesv); A is overwritten by its factors. Two
    !! steps of iterative refinement, as in solve_symmetric.
    subroutine solve_general(a, b, x, err)
        real(dp), intent(inout) :: a(:, :)   !! n x n matrix
        real(dp), intent(in) :: b(:)         !! right-hand side
        real(dp), intent(out) :: x(:)        !! solution
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer, allocatable :: ipiv(:)
        real(dp), allocatable :: rhs(:, :), a_copy(:, :)
        integer :: n, info, step
        character(len=160) :: text

        n = size(a, 1)
        call check_system('solve_general', a, b, x, err)
        if (allocated(err)) return
        allocate (ipiv(n), rhs(n, 1))
        a_copy = a
        rhs(:, 1) = b
        call dgesv(n, 1, a, n, ipiv, rhs, n, info)
        call factorisation_info('dgesv', 'U', 'LU', info, err)
        if (allocated(err)) return
        x = rhs(:, 1)
        refinement: do step = 1, 2
            rhs(:, 1) = b - matmul(a_copy, x)
            call dgetrs('N', n, 1, a, n, ipiv, rhs, n, info)
            if (info /= 0) then
                write (text, '(a,i0)') 'dgetrs: illegal argument ', -info
                call new_error(err, EXIT_INTERNAL, trim(text))
                return
            end if
            x = x + rhs(:, 1)
        end do refinement
        if (.not. all(abs(x) <= huge(1.0_dp))) then
            call new_error(err, EXIT_ANALYSIS, 'the contact system is numerically singular '// &
                           '(non-finite solution)')
        end if
    end subroutine solve_general

    !> Solve A x = b after the symmetric diagonal scaling D A D (D = 1/sqrt|diag A|, 1 where
    !! the diagonal is 0): LDL^T when A is symmetric, else LU. A is overwritten.
    subroutine solve_equilibrated(a, b, x, symmetric, err)
        real(dp), intent(inout) :: a(:, :)   !! n x n matrix
        real(dp), intent(in) :: b(:)         !! right-hand side
        real(dp), intent(out) :: x(:)        !! solution
        logical, intent(in) :: symmetric     !! A = A^T (then only the lower triangle is used)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp), allocatable :: s(:), y(:)
        integer :: i, n
        n = size(a, 1)
        allocate (s(n), y(n))
        do i = 1, n
            s(i) = 1.0_dp
            if (a(i, i) /= 0.0_dp) s(i) = 1.0_dp/sqrt(abs(a(i, i)))
        end do
        do i = 1, n
            a(:, i) = a(:, i)*s*s(i)
        end do
        if (symmetric) then
            call solve_symmetric(a, b*s, y, err)
        else
            call solve_general(a, b*s, y, err)
        end if
        if (allocated(err)) return
        x = s*y
    end subroutine solve_equilibrated

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
