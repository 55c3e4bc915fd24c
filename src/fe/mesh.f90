!> One-dimensional mesh of the interface: beam axis x in [-l/2, l/2] or plate radius r in [0, a].
!!
!! Grading words (MESH card, field 2):
!!   UNIFORM  equal elements.
!!   EDGES    geometric grading towards both ends (beam) or the rim (plate), ratio 1.1 between
!!            neighbours; finer where the contact pressure is singular.
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

    public :: new_mesh, element_length

    real(dp), parameter :: grading_ratio = 1.1_dp  !! size ratio of neighbouring elements (EDGES)
    integer, parameter :: max_growth = 60           !! largest/smallest element <= 1.1**60 = 304

contains

    !> Mesh of [x_left, x_right] with ne elements and the named grading.
    subroutine new_mesh(msh, x_left, x_right, ne, grading, err)
        type(mesh_t), intent(out) :: msh              !! new mesh
        real(dp), intent(in) :: x_left, x_right       !! ends of the interface [length]
        integer, intent(in) :: ne                     !! number of elements >= 1
        character(len=*), intent(in) :: grading       !! UNIFORM or EDGES
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: sizes(:)
        integer :: e
        logical :: both_ends

        if (ne < 1 .or. .not. x_right > x_left) then
            call new_error(err, EXIT_INPUT, 'mesh needs N_e >= 1 and a positive length')
            return
        end if
        allocate (sizes(ne))
        select case (trim(grading))
        case ('UNIFORM', '')
            sizes = 1.0_dp
        case ('EDGES')
            both_ends = x_left < 0.0_dp
            do e = 1, ne
                ! exponent capped so that thousands of elements cannot overflow
                if (both_ends) then
                    sizes(e) = grading_ratio**min(e - 1, ne - e, max_growth)
                else
                    sizes(e) = grading_ratio**min(ne - e, max_growth)
                end if
            end do
        case default
            call new_error(err, EXIT_INPUT, 'unknown mesh grading "'//trim(grading)// &
                           '" (expected UNIFORM or EDGES)')
            return
        end select
        msh%ne = ne
        allocate (msh%x(0:ne))
        msh%x(0) = x_left
        do e = 1, ne
            msh%x(e) = msh%x(e - 1) + sizes(e)
        end do
        msh%x = x_left + (msh%x - x_left)*(x_right - x_left)/(msh%x(ne) - x_left)
        msh%x(ne) = x_right
    end subroutine new_mesh

    !> Length of element e.
    pure real(dp) function element_length(msh, e)
        type(mesh_t), intent(in) :: msh
        integer, intent(in) :: e
        element_length = msh%x(e) - msh%x(e - 1)
    end function element_length
end module mesh
