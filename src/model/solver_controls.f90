!> How the contact problem is solved (SOLVER card): the method, its tolerances and caps,
!! the start of the two-loop method, and whether the scene may be simplified.
module solver_controls
    use kinds, only: dp
    implicit none
    private

    !> Solution methods of the contact problem (SOLVER field 7).
    integer, parameter, public :: METHOD_NEWTON = 1, METHOD_TWOLOOP = 2

    !> SOLVER card.
    type, public :: solver_controls_t
        real(dp) :: tol_outer = 1.0e-8_dp   !! outer (friction) tolerance, relative
        real(dp) :: tol_inner = 1.0e-10_dp  !! inner (contact) tolerance, relative
        integer :: max_outer = 100          !! cap of outer iterations
        integer :: max_inner = 100          !! cap of inner iterations
        real(dp) :: tau0_start = -1.0_dp    !! start threshold, nondim; < 0: f * mean pressure
        integer :: method = METHOD_NEWTON   !! METHOD_NEWTON (default) or METHOD_TWOLOOP (paper)
        logical :: simplify = .true.        !! solve only what the scene needs (model_reduction)
    end type solver_controls_t
end module solver_controls
