!> One-dimensional mesh of the interface: beam axis x in [-l/2, l/2] or plate radius r in [0, a].
!!
!! Grading words (MESH card, field 2):
!!   UNIFORM  equal elements.
!!   EDGES    geometric grading towards both ends (beam) or the rim (plate), ratio 1.1 between
!!            neighbours; finer where the contact pressure is singular.
!!   LOADS    the interface cut at every load position and patch edge; each piece graded
!!            geometrically (ratio 1.1) towards both of its ends, elements shared among the
!!            pieces in proportion to their lengths (at least one each). Fine at the loads and
!!            at the ends of the structure.
module mesh
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INPUT
    implicit none
    private

    !> Nodes x(0:ne) in increasing order; element e spans [x(e-1), x(e)].
    type, public :: mesh_t
        integer :: ne = 0                    !! number of elements
        real(dp), allocatable :: x(:)        !! node coordinates x(0:ne) [length]
    end type mesh_t

    public :: new_mesh, element_length, loads_pieces

    real(dp), parameter :: grading_ratio = 1.1_dp  !! size ratio of neighbouring elements (EDGES)
    integer, parameter :: max_growth = 60           !! largest/smallest element <= 1.1**60 = 304

contains

    !> Mesh of [x_left, x_right] with ne elements and the named grading.
    subroutine new_mesh(msh, x_left, x_right, ne, grading, err, attractors)
        type(mesh_t), intent(out) :: msh              !! new mesh
        real(dp), intent(in) :: x_left, x_right       !! ends of the interface [length]
        integer, intent(in) :: ne                     !! number of elements >= 1
        character(len=*), intent(in) :: grading       !! UNIFORM, EDGES or LOADS
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp), intent(in), optional :: attractors(:)  !! load positions (LOADS) [length]
        real(dp), allocatable :: sizes(:), breaks(:)
        integer :: e

        if (ne < 1 .or. .not. x_right > x_left) then
            call new_error(err, EXIT_INPUT, 'mesh needs N_e >= 1 and a positive length')
            return
        end if
        select case (trim(grading))
        case ('UNIFORM', '')
            allocate (sizes(ne), source=1.0_dp)
        case ('EDGES')
            if (x_left < 0.0_dp) then
                sizes = graded_sizes(ne, .true., .true.)
            else
                sizes = graded_sizes(ne, .false., .true.)   ! plate: the axis is no edge
            end if
        case ('LOADS')
            breaks = [x_left, x_right]
            if (present(attractors)) breaks = break_points(x_left, x_right, attractors)
            call piecewise_sizes(breaks, ne, sizes, err)
            if (allocated(err)) return
        case default
            call new_error(err, EXIT_INPUT, 'unknown mesh grading "'//trim(grading)// &
                           '" (expected UNIFORM, EDGES or LOADS)')
            return
        end select
        msh%ne = ne
        allocate (msh%x(0:ne))
        msh%x(0) = 0.0_dp
        do e = 1, ne
            msh%x(e) = msh%x(e - 1) + sizes(e)
        end do
        msh%x = x_left + msh%x*(x_right - x_left)/msh%x(ne)
        msh%x(ne) = x_right
    end subroutine new_mesh

    !> Relative element sizes of n elements graded (ratio 1.1) towards the chosen ends.
    pure function graded_sizes(n, to_left, to_right) result(sizes)
        integer, intent(in) :: n
        logical, intent(in) :: to_left, to_right
        real(dp) :: sizes(n)
        integer :: e, from_left, from_right
        do e = 1, n
            from_left = merge(e - 1, max_growth, to_left)
            from_right = merge(n - e, max_growth, to_right)
            ! exponent capped so that thousands of elements cannot overflow
            sizes(e) = grading_ratio**min(from_left, from_right, max_growth)
        end do
    end function graded_sizes

    !> Sorted distinct cut points: the ends and the attractors strictly inside.
    !> The pieces LOADS grading cuts [x_left, x_right] into (it needs an element for each).
    pure integer function loads_pieces(x_left, x_right, attractors) result(n)
        real(dp), intent(in) :: x_left, x_right   !! the ends of the range cut [L]
        real(dp), intent(in) :: attractors(:)     !! load positions [L], any order
        n = size(break_points(x_left, x_right, attractors)) - 1
    end function loads_pieces

    pure function break_points(x_left, x_right, attractors) result(breaks)
        real(dp), intent(in) :: x_left, x_right, attractors(:)
        real(dp), allocatable :: breaks(:)
        real(dp) :: tol, a
        integer :: i, j
        tol = 1.0e-9_dp*(x_right - x_left)
        breaks = [x_left, x_right]
        do i = 1, size(attractors)
            a = attractors(i)
            if (a <= x_left + tol .or. a >= x_right - tol) cycle
            if (any(abs(breaks - a) <= tol)) cycle
            j = count(breaks < a)
            breaks = [breaks(1:j), a, breaks(j + 1:)]
        end do
    end function break_points

    !> Element sizes (absolute) for pieces between the breaks, each graded towards both ends.
    pure subroutine piecewise_sizes(breaks, ne, sizes, err)
        real(dp), intent(in) :: breaks(:)
        integer, intent(in) :: ne
        real(dp), allocatable, intent(out) :: sizes(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: n_piece, k, first
        integer, allocatable :: counts(:)
        real(dp), allocatable :: share(:)
        real(dp) :: length
        character(len=120) :: text
        n_piece = size(breaks) - 1
        if (ne < n_piece) then
            write (text, '(a,i0,a)') 'LOADS grading needs N_e >= ', n_piece, &
                ' (one element per piece between load positions)'
            call new_error(err, EXIT_INPUT, trim(text))
            return
        end if
        length = breaks(n_piece + 1) - breaks(1)
        share = real(ne, dp)*(breaks(2:) - breaks(:n_piece))/length
        counts = max(1, int(share))
        largest_remainder: do while (sum(counts) < ne)
            k = maxloc(share - real(counts, dp), dim=1)
            counts(k) = counts(k) + 1
        end do largest_remainder
        trim_excess: do while (sum(counts) > ne)
            k = maxloc(counts, dim=1)
            counts(k) = counts(k) - 1
        end do trim_excess
        allocate (sizes(ne))
        first = 1
        do k = 1, n_piece
            associate (s => sizes(first:first + counts(k) - 1))
                s = graded_sizes(counts(k), .true., .true.)
                s = s*(breaks(k + 1) - breaks(k))/sum(s)
            end associate
            first = first + counts(k)
        end do
    end subroutine piecewise_sizes

    !> Length of element e.
    pure real(dp) function element_length(msh, e)
        type(mesh_t), intent(in) :: msh   !! the mesh
        integer, intent(in) :: e          !! the element
        element_length = msh%x(e) - msh%x(e - 1)
    end function element_length
end module mesh
