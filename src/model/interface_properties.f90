!> The interface between the structure and the ground: Coulomb friction and the two small
!! parameters of the regularised unilateral law (SPEC §4; the law itself is interface_law).
module interface_properties
    use kinds, only: dp
    implicit none
    private

    !> FRICTION and SOLVER data of the interface law.
    type, public :: interface_t
        real(dp) :: f = 0.0_dp           !! Coulomb friction coefficient
        real(dp) :: eps_bar = 1.0e-6_dp  !! regularisation of the friction law (SPEC §4)
        real(dp) :: eta_bar = 1.0e-9_dp  !! penalty of the tension zone (SPEC §4)
    end type interface_t
end module interface_properties
