!> The loads on the structure's top face (LOAD cards), in the deck's units: forces F,
!! lengths L, moments F L. Vertical forces are positive downward, horizontal ones along +x.
module applied_loads
    use kinds, only: dp
    implicit none
    private

    integer, parameter, public :: LOAD_POINT = 1, LOAD_PATCH = 2, LOAD_MOMENT = 3, LOAD_RING = 4
    !> The LOAD card's word of each kind, indexed by LOAD_* (PRESSURE and RADIAL become PATCH).
    character(len=6), parameter, public :: load_kind_words(4) = ['POINT ', 'PATCH ', 'MOMENT', &
                                                                 'RING  ']

    !> One LOAD card.
    type, public :: load_t
        integer :: kind = LOAD_POINT   !! LOAD_POINT, LOAD_PATCH, LOAD_MOMENT, LOAD_RING
        real(dp) :: fz = 0.0_dp        !! vertical force, downward positive (moment for MOMENT)
        real(dp) :: fx = 0.0_dp        !! horizontal force, +x (beam only), on the top face
        real(dp) :: x1 = 0.0_dp        !! position, or start of a patch [L]
        real(dp) :: x2 = 0.0_dp        !! end of a patch [L]
        integer :: line = 0            !! deck line of the card (for messages)
    end type load_t

    public :: total_vertical_load, has_concentrated_load, load_positions

contains

    !> A POINT or RING load acts: the contact pressure is singular under it (log), so its
    !! largest station value depends on the mesh.
    pure logical function has_concentrated_load(loads)
        type(load_t), intent(in) :: loads(:)   !! the LOAD cards
        has_concentrated_load = any(loads%kind == LOAD_POINT .or. loads%kind == LOAD_RING)
    end function has_concentrated_load

    !> Sum of the vertical forces of all loads (moments excluded) [F].
    pure real(dp) function total_vertical_load(loads)
        type(load_t), intent(in) :: loads(:)   !! the LOAD cards
        integer :: i
        total_vertical_load = 0.0_dp
        do i = 1, size(loads)
            if (loads(i)%kind /= LOAD_MOMENT) total_vertical_load = total_vertical_load &
                                                                    + loads(i)%fz
        end do
    end function total_vertical_load

    !> Positions of point loads, rings, moments and patch edges (attractors of LOADS grading)
    !! [L], in card order; without the patch edges where patches is false (the POINT, RING and
    !! MOMENT loads alone: a kink or a jump of the fields there).
    pure function load_positions(loads, patches) result(x)
        type(load_t), intent(in) :: loads(:)   !! the LOAD cards
        logical, intent(in), optional :: patches   !! with the patch edges (default true)
        real(dp), allocatable :: x(:)
        logical :: with_patches
        integer :: i
        with_patches = .true.
        if (present(patches)) with_patches = patches
        allocate (x(0))
        do i = 1, size(loads)
            if (loads(i)%kind /= LOAD_PATCH) then
                x = [x, loads(i)%x1]
            else if (with_patches) then
                x = [x, loads(i)%x1, loads(i)%x2]
            end if
        end do
    end function load_positions
end module applied_loads
