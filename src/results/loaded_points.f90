!> The loaded points of a foundation: where the structure above stands on it (columns, walls),
!! the points between which the codes measure the relative rotation (angular distortion) of a
!! foundation (Burland & Wroth 1974; EN 1997-1 Annex H: the rotation of the line joining two
!! adjacent points relative to the tilt).
!!
!! Beam: every POINT and MOMENT load at its position, every PATCH at its centre (a column's
!! footprint), except a PATCH over the whole beam (a distributed load: no point of support).
!! Plate (along a radius): the axis r = 0, every RING at its radius, every PATCH annulus
!! (x1 > 0, a wall's footprint) at its mid radius; a disk PATCH (x1 = 0) is centred on the
!! axis. Positions closer than 1e-9 of the length are one point.
module loaded_points
    use kinds, only: dp
    use model, only: structure_t, load_t, MODEL_BEAM, LOAD_PATCH
    use sorting, only: ascending_order
    implicit none
    private

    public :: loaded_positions

contains

    !> The loaded points of the structure, in ascending order of x (beam) or r (plate) [L].
    pure function loaded_positions(structure, loads) result(x)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(load_t), intent(in) :: loads(:)         !! the loads part of the model
        real(dp), allocatable :: x(:)
        real(dp), allocatable :: raw(:)
        real(dp) :: tol
        integer :: k
        logical :: beam
        beam = structure%kind == MODEL_BEAM
        tol = 1.0e-9_dp*structure%length
        allocate (raw(0))
        if (.not. beam) raw = [0.0_dp]
        do k = 1, size(loads)
            associate (ld => loads(k))
                if (ld%kind /= LOAD_PATCH) then
                    raw = [raw, ld%x1]
                else if (beam .and. ld%x2 - ld%x1 >= structure%length - tol) then
                    cycle
                else if (.not. beam .and. ld%x1 <= tol) then
                    raw = [raw, 0.0_dp]
                else
                    raw = [raw, 0.5_dp*(ld%x1 + ld%x2)]
                end if
            end associate
        end do
        raw = raw(ascending_order(raw))
        allocate (x(0))
        do k = 1, size(raw)
            if (size(x) > 0) then
                if (raw(k) - x(size(x)) <= tol) cycle
            end if
            x = [x, raw(k)]
        end do
    end function loaded_positions
end module loaded_points
