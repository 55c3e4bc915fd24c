!> Matrices stored by their nonzeros or by one triangle: as the finite-element assembly makes
!! them (triplets, duplicates add), as the products read them (compressed columns), and
!! symmetric dense blocks in LAPACK's packed lower storage (half the memory of a full array).
!!
!! The contact system keeps its base matrix in these forms (contact_system): the structure's K
!! and the coupling M have a few nonzeros per column, and of the dense half-space block only
!! one triangle is stored, so that a case of N_e = 1000 holds about two dense copies of its
!! largest block rather than the whole n x n matrix (the memory target of doc/CHOICES.md,
!! "The solver's performance targets").
module sparse_matrix
    use kinds, only: dp
    use double_double, only: two_sum, two_product
    use lapack_interfaces, only: dspmv
    implicit none
    private

    !> (row, col, val) entries in any order; repeated positions add.
    type, public :: triplets_t
        integer :: nrow = 0, ncol = 0
        integer :: n = 0                     !! entries in use
        integer, allocatable :: row(:), col(:)
        real(dp), allocatable :: val(:)
    end type triplets_t

    !> Compressed sparse columns: column j holds entries ptr(j):ptr(j+1)-1, one per row.
    type, public :: columns_t
        integer :: nrow = 0, ncol = 0
        integer, allocatable :: ptr(:)
        integer, allocatable :: row(:)
        real(dp), allocatable :: val(:)
    end type columns_t

    public :: new_triplets, add_entry, compressed, triplets_of, transposed
    public :: columns_times, columns_times_double_double, dense_column, dense_of
    public :: scatter_column
    public :: pack_lower, packed_column, packed_times, packed_add, packed_entry
    public :: packed_position, unpack_lower

contains

    !> An empty nrow x ncol matrix with room for `room` entries.
    pure function new_triplets(nrow, ncol, room) result(t)
        integer, intent(in) :: nrow, ncol, room   !! rows, columns, entries to make room for
        type(triplets_t) :: t
        t%nrow = nrow
        t%ncol = ncol
        allocate (t%row(max(room, 16)), t%col(max(room, 16)), t%val(max(room, 16)))
    end function new_triplets

    !> t(i, j) += v (the storage doubles when full).
    pure subroutine add_entry(t, i, j, v)
        type(triplets_t), intent(inout) :: t   !! the matrix
        integer, intent(in) :: i, j            !! row, column
        real(dp), intent(in) :: v              !! the value added
        if (t%n == size(t%row)) then
            t%row = [t%row, t%row]
            t%col = [t%col, t%col]
            t%val = [t%val, t%val]
        end if
        t%n = t%n + 1
        t%row(t%n) = i
        t%col(t%n) = j
        t%val(t%n) = v
    end subroutine add_entry

    !> The columns of t: repeated positions summed, entries that sum to exactly 0 left out.
    pure function compressed(t) result(c)
        type(triplets_t), intent(in) :: t   !! the entries
        type(columns_t) :: c
        integer, allocatable :: slot(:), next(:), first(:)
        integer :: k, j, nnz
        c%nrow = t%nrow
        c%ncol = t%ncol
        ! entries chained by column (first(j), next(k)), then merged column by column with
        ! slot(row) = its place in the column being built
        allocate (first(t%ncol), next(t%n), slot(t%nrow), c%ptr(t%ncol + 1))
        first = 0
        do k = t%n, 1, -1
            next(k) = first(t%col(k))
            first(t%col(k)) = k
        end do
        allocate (c%row(t%n), c%val(t%n))
        slot = 0
        nnz = 0
        columns: do j = 1, t%ncol
            c%ptr(j) = nnz + 1
            k = first(j)
            entries: do while (k > 0)
                if (slot(t%row(k)) == 0) then
                    nnz = nnz + 1
                    slot(t%row(k)) = nnz
                    c%row(nnz) = t%row(k)
                    c%val(nnz) = 0.0_dp
                end if
                c%val(slot(t%row(k))) = c%val(slot(t%row(k))) + t%val(k)
                k = next(k)
            end do entries
            do k = c%ptr(j), nnz        ! (a loop: the vector subscript made a heap temporary)
                slot(c%row(k)) = 0
            end do
            call drop_zeros(c, j, nnz)
        end do columns
        c%ptr(t%ncol + 1) = nnz + 1
        c%row = c%row(1:nnz)
        c%val = c%val(1:nnz)
    end function compressed

    !> Remove the exact zeros of column j (entries c%ptr(j):nnz, the last column built).
    pure subroutine drop_zeros(c, j, nnz)
        type(columns_t), intent(inout) :: c
        integer, intent(in) :: j
        integer, intent(inout) :: nnz
        integer :: k, kept
        kept = c%ptr(j) - 1
        do k = c%ptr(j), nnz
            if (c%val(k) == 0.0_dp) cycle
            kept = kept + 1
            c%row(kept) = c%row(k)
            c%val(kept) = c%val(k)
        end do
        nnz = kept
    end subroutine drop_zeros

    !> The entries of c as triplets (room for `extra` more).
    pure function triplets_of(c, extra) result(t)
        type(columns_t), intent(in) :: c   !! the sparse matrix (compressed columns)
        integer, intent(in) :: extra       !! room for this many more entries
        type(triplets_t) :: t
        integer :: j
        t = new_triplets(c%nrow, c%ncol, size(c%val) + extra)
        do j = 1, c%ncol
            t%row(c%ptr(j):c%ptr(j + 1) - 1) = c%row(c%ptr(j):c%ptr(j + 1) - 1)
            t%col(c%ptr(j):c%ptr(j + 1) - 1) = j
        end do
        t%n = size(c%val)
        t%val(1:t%n) = c%val
    end function triplets_of

    !> c^T.
    pure function transposed(c) result(ct)
        type(columns_t), intent(in) :: c   !! the sparse matrix (compressed columns)
        type(columns_t) :: ct
        type(triplets_t) :: t
        integer, allocatable :: rows(:)
        t = triplets_of(c, 0)
        rows = t%row
        t%row = t%col
        t%col = rows
        t%nrow = c%ncol
        t%ncol = c%nrow
        ct = compressed(t)
    end function transposed

    !> c x.
    pure function columns_times(c, x) result(y)
        type(columns_t), intent(in) :: c   !! the sparse matrix (compressed columns)
        real(dp), intent(in) :: x(:)       !! the vector (ncol)
        real(dp) :: y(c%nrow)
        integer :: j, k
        ! a scalar loop: the array form y(row(k1:k2)) = y(row(k1:k2)) + ... makes the compiler
        ! allocate a temporary per column (it cannot rule out repeated rows), which cost more
        ! than the products on small meshes
        y = 0.0_dp
        do j = 1, c%ncol
            do k = c%ptr(j), c%ptr(j + 1) - 1
                y(c%row(k)) = y(c%row(k)) + c%val(k)*x(j)
            end do
        end do
    end function columns_times

    !> c (x + x_lo) in double-double, y + y_lo: each product c_ij x_j and its sum exact
    !! (two_product, two_sum), their errors and the small c_ij x_lo_j added into y_lo
    !! (module double_double: as accurate as twice the working precision).
    pure subroutine columns_times_double_double(c, x, x_lo, y, y_lo)
        type(columns_t), intent(in) :: c      !! the sparse matrix (compressed columns)
        real(dp), intent(in) :: x(:), x_lo(:) !! the vector (ncol), x + x_lo
        real(dp), intent(out) :: y(:), y_lo(:) !! the product (nrow), y + y_lo
        real(dp) :: p, p_err, s, s_err
        integer :: i, j, k
        y = 0.0_dp
        y_lo = 0.0_dp
        do j = 1, c%ncol
            do k = c%ptr(j), c%ptr(j + 1) - 1
                i = c%row(k)
                call two_product(c%val(k), x(j), p, p_err)
                call two_sum(y(i), p, s, s_err)
                y(i) = s
                y_lo(i) = y_lo(i) + (s_err + (p_err + c%val(k)*x_lo(j)))
            end do
        end do
    end subroutine columns_times_double_double

    !> Column j of c as a dense vector.
    pure function dense_column(c, j) result(col)
        type(columns_t), intent(in) :: c   !! the sparse matrix (compressed columns)
        integer, intent(in) :: j           !! the column
        real(dp) :: col(c%nrow)
        col = 0.0_dp
        col(c%row(c%ptr(j):c%ptr(j + 1) - 1)) = c%val(c%ptr(j):c%ptr(j + 1) - 1)
    end function dense_column

    !> Column j of c written into col at its nonzero rows only (col holds the caller's zeros
    !! elsewhere): O(nonzeros) where dense_column is O(nrow). With clear, those rows are set
    !! to zero again instead.
    pure subroutine scatter_column(c, j, col, clear)
        type(columns_t), intent(in) :: c    !! the sparse matrix (compressed columns)
        integer, intent(in) :: j            !! the column
        real(dp), intent(inout) :: col(:)   !! (c%nrow)
        logical, intent(in) :: clear        !! zero those rows instead
        integer :: k
        do k = c%ptr(j), c%ptr(j + 1) - 1
            col(c%row(k)) = merge(0.0_dp, c%val(k), clear)
        end do
    end subroutine scatter_column

    !> c as a dense array.
    pure function dense_of(c) result(a)
        type(columns_t), intent(in) :: c   !! the sparse matrix (compressed columns)
        real(dp) :: a(c%nrow, c%ncol)
        integer :: j
        do j = 1, c%ncol
            a(:, j) = dense_column(c, j)
        end do
    end function dense_of

    !> The lower triangle of the symmetric a, packed by columns (LAPACK 'L' packed storage).
    !! A subroutine, not a function: `ap = f(a)` held the result twice (a temporary and its
    !! copy), 32 MB at N_e = 1000 next to T, the peak of a plate case's memory.
    pure subroutine pack_lower(a, ap)
        real(dp), intent(in) :: a(:, :)               !! symmetric n x n matrix
        real(dp), allocatable, intent(out) :: ap(:)   !! its lower triangle, packed by columns
        integer :: j, n, k
        n = size(a, 1)
        allocate (ap(n*(n + 1)/2))
        k = 0
        do j = 1, n
            ap(k + 1:k + n - j + 1) = a(j:n, j)
            k = k + n - j + 1
        end do
    end subroutine pack_lower

    !> The symmetric matrix held in ap (n x n, lower packed) into a full n x n array.
    pure subroutine unpack_lower(ap, a)
        real(dp), intent(in) :: ap(:)      !! lower triangle, packed by columns
        real(dp), intent(out) :: a(:, :)   !! the full n x n matrix
        integer :: j, n
        n = size(a, 1)
        do j = 1, n
            a(j:n, j) = ap(packed_position(n, j, j):packed_position(n, n, j))
            a(j, j + 1:n) = a(j + 1:n, j)
        end do
    end subroutine unpack_lower

    !> Position of entry (i, j), i >= j, of an n x n lower triangle in packed storage.
    pure integer function packed_position(n, i, j) result(k)
        integer, intent(in) :: n, i, j   !! order; row, column (i >= j)
        k = i + (j - 1)*(2*n - j)/2
    end function packed_position

    !> Entry (i, j) of the symmetric n x n matrix held in ap.
    pure real(dp) function packed_entry(ap, n, i, j) result(v)
        real(dp), intent(in) :: ap(:)    !! lower triangle, packed by columns
        integer, intent(in) :: n, i, j   !! order; row, column
        v = ap(packed_position(n, max(i, j), min(i, j)))
    end function packed_entry

    !> Column j of the symmetric n x n matrix held in ap (row j of the triangle above it).
    pure function packed_column(ap, n, j) result(col)
        real(dp), intent(in) :: ap(:)   !! lower triangle, packed by columns
        integer, intent(in) :: n, j     !! order; column
        real(dp) :: col(n)
        integer :: i
        do i = 1, j - 1
            col(i) = ap(packed_position(n, j, i))
        end do
        col(j:n) = ap(packed_position(n, j, j):packed_position(n, n, j))
    end function packed_column

    !> ap(i, j) += v (and so (j, i): the matrix is symmetric).
    pure subroutine packed_add(ap, n, i, j, v)
        real(dp), intent(inout) :: ap(:)   !! lower triangle, packed by columns
        integer, intent(in) :: n, i, j     !! order; row, column
        real(dp), intent(in) :: v          !! the value added
        associate (k => packed_position(n, max(i, j), min(i, j)))
            ap(k) = ap(k) + v
        end associate
    end subroutine packed_add

    !> The symmetric n x n matrix held in ap times x (BLAS dspmv).
    pure function packed_times(ap, x) result(y)
        real(dp), intent(in) :: ap(:)   !! lower triangle, packed by columns
        real(dp), intent(in) :: x(:)    !! the vector (n)
        real(dp) :: y(size(x))
        y = 0.0_dp
        if (size(x) == 0) return
        call dspmv('L', size(x), 1.0_dp, ap, x, 1, 0.0_dp, y, 1)
    end function packed_times
end module sparse_matrix
