!> The ground under the foundation: one homogeneous, isotropic, linear elastic half-space
!! (SOIL card; SPEC §3), or horizontal elastic layers over a base (LAYER and BASE cards;
!! SPEC §3a). Units: moduli in the deck's F/L^2, thicknesses in L.
!!
!! E_f and nu_f are the surface's: the SOIL card's, or the top layer's. They give the
!! friction compliance, rho and the NONDIM groups, and the top layer's constants are always
!! these two (`layer_profile`). The other layers' moduli are physical in a physical deck and
!! relative to E_f in a NONDIM deck (relative_moduli), where E_f comes from rho.
module ground_model
    use kinds, only: dp
    implicit none
    private

    integer, parameter, public :: GROUND_HOMOGENEOUS = 0   !! SOIL: one half-space
    integer, parameter, public :: GROUND_LAYERED = 1       !! LAYER cards over a BASE
    integer, parameter, public :: GROUND_BASE_ROUGH = 1      !! rigid base, bonded
    integer, parameter, public :: GROUND_BASE_SMOOTH = 2     !! rigid base, frictionless
    integer, parameter, public :: GROUND_BASE_HALFSPACE = 3  !! elastic half-space below

    !> The elastic ground.
    type, public :: ground_t
        real(dp) :: e_f = 0.0_dp    !! Young's modulus of the soil (of the top layer) [F/L^2]
        real(dp) :: nu_f = 0.1_dp   !! Poisson's ratio of the soil (of the top layer)
        integer :: kind = GROUND_HOMOGENEOUS
        !> Layers from the surface down (GROUND_LAYERED): thickness [L], E at the layer's
        !! top and bottom (e_bottom 0: constant in the layer), nu; layer 1's E at its top
        !! and nu are e_f and nu_f whatever these hold
        real(dp), allocatable :: thickness(:), e_top(:), e_bottom(:), poisson(:)
        logical :: relative_moduli = .false.     !! moduli in units of e_f (NONDIM deck)
        integer :: base = GROUND_BASE_ROUGH      !! GROUND_BASE_*
        real(dp) :: e_base = 0.0_dp              !! base modulus (GROUND_BASE_HALFSPACE)
        real(dp) :: nu_base = 0.0_dp             !! base Poisson's ratio (GROUND_BASE_HALFSPACE)
    end type ground_t

    public :: soil_shear_modulus, layer_count, layer_profile, ground_depth, base_name

contains

    !> G_f = E_f / (2 (1 + nu_f)) [F/L^2].
    pure real(dp) function soil_shear_modulus(g)
        type(ground_t), intent(in) :: g   !! the ground
        soil_shear_modulus = g%e_f/(2.0_dp*(1.0_dp + g%nu_f))
    end function soil_shear_modulus

    !> Number of layers (0 for the homogeneous half-space).
    pure integer function layer_count(g)
        type(ground_t), intent(in) :: g   !! the ground
        layer_count = 0
        if (g%kind /= GROUND_LAYERED) return
        if (allocated(g%thickness)) layer_count = size(g%thickness)
    end function layer_count

    !> Depth of the base below the surface [L] (0 for the homogeneous half-space).
    pure real(dp) function ground_depth(g)
        type(ground_t), intent(in) :: g   !! the ground
        ground_depth = 0.0_dp
        if (layer_count(g) > 0) ground_depth = sum(g%thickness)
    end function ground_depth

    !> The layers in physical units: E at each layer's top and bottom (equal for a constant
    !! layer), nu, and the base's E (0 for a rigid base); layer 1 from e_f and nu_f.
    pure subroutine layer_profile(g, thickness, e_top, e_bottom, poisson, e_base)
        type(ground_t), intent(in) :: g                    !! a layered ground
        real(dp), allocatable, intent(out) :: thickness(:) !! each layer's thickness [L]
        real(dp), allocatable, intent(out) :: e_top(:)     !! E at each layer's top [F/L^2]
        real(dp), allocatable, intent(out) :: e_bottom(:)  !! E at its bottom [F/L^2]
        real(dp), allocatable, intent(out) :: poisson(:)   !! each layer's Poisson's ratio
        real(dp), intent(out) :: e_base                    !! the base's E (0: rigid) [F/L^2]
        real(dp) :: scale
        integer :: n
        n = layer_count(g)
        scale = merge(g%e_f, 1.0_dp, g%relative_moduli)
        thickness = g%thickness(1:n)
        e_top = scale*g%e_top(1:n)
        poisson = g%poisson(1:n)
        if (n > 0) then
            e_top(1) = g%e_f
            poisson(1) = g%nu_f
        end if
        e_bottom = merge(scale*g%e_bottom(1:n), e_top, g%e_bottom(1:n) > 0.0_dp)
        e_base = 0.0_dp
        if (g%base == GROUND_BASE_HALFSPACE) e_base = scale*g%e_base
    end subroutine layer_profile

    !> The base's deck word: ROUGH, SMOOTH or HALFSPACE.
    pure function base_name(g) result(name)
        type(ground_t), intent(in) :: g   !! a layered ground
        character(len=:), allocatable :: name
        select case (g%base)
        case (GROUND_BASE_ROUGH)
            name = 'ROUGH'
        case (GROUND_BASE_SMOOTH)
            name = 'SMOOTH'
        case default
            name = 'HALFSPACE'
        end select
    end function base_name
end module ground_model
