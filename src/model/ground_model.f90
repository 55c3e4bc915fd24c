!> The ground under the foundation: today one homogeneous, isotropic, linear elastic
!! half-space (SOIL card; SPEC §3). Units: E_f in the deck's F/L^2.
module ground_model
    use kinds, only: dp
    implicit none
    private

    !> The elastic ground.
    type, public :: ground_t
        real(dp) :: e_f = 0.0_dp    !! Young's modulus of the soil [F/L^2]
        real(dp) :: nu_f = 0.1_dp   !! Poisson's ratio of the soil
    end type ground_t

    public :: soil_shear_modulus

contains

    !> G_f = E_f / (2 (1 + nu_f)) [F/L^2].
    pure real(dp) function soil_shear_modulus(g)
        type(ground_t), intent(in) :: g   !! the ground
        soil_shear_modulus = g%e_f/(2.0_dp*(1.0_dp + g%nu_f))
    end function soil_shear_modulus
end module ground_model
