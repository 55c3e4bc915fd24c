!> The interface law at one point: unilateral contact and the regularised Coulomb threshold
!! (SPEC §4, paper 2.6-2.7, 4.6-4.7). This is the one place that decides stick / slip /
!! lift-off: the contact solver classifies its Gauss points with it, and the station table
!! labels its stations with it.
!!
!! Signs: sigma_z > 0 is compression on the soil; sigma_x the shear traction on the soil.
module interface_law
    use kinds, only: dp
    implicit none
    private

    integer, parameter, public :: STATE_LIFTOFF = 0, STATE_STICK = 1, STATE_SLIP = 2

    public :: friction_threshold, in_tension, is_slipping, contact_state
    public :: slip_excess, tensile_part, threshold_slope, admissible_excess

contains

    !> tau0 = f max(sigma_z, 0): the friction threshold of the complete problem.
    elemental real(dp) function friction_threshold(f, sigma_z) result(tau0)
        real(dp), intent(in) :: f        !! friction coefficient
        real(dp), intent(in) :: sigma_z  !! normal traction (compression > 0)
        tau0 = f*max(sigma_z, 0.0_dp)
    end function friction_threshold

    !> The tension set of the penalty (paper 4.6b/4.7b): sigma_z <= 0.
    elemental logical function in_tension(sigma_z)
        real(dp), intent(in) :: sigma_z   !! normal traction, compression positive
        in_tension = sigma_z <= 0.0_dp
    end function in_tension

    !> The slip set (paper 4.6a/4.7a): |sigma_x| > tau0.
    elemental logical function is_slipping(sigma_x, tau0)
        !> shear traction; friction threshold f max(sigma_z, 0)
        real(dp), intent(in) :: sigma_x, tau0
        is_slipping = abs(sigma_x) > tau0
    end function is_slipping

    !> The state a reader is told: lift-off where the point is in tension, else slip where the
    !! shear exceeds the threshold or there is no threshold (f = 0: nothing resists sliding,
    !! also where the frictionless model's sigma_x is exactly 0), else stick.
    elemental integer function contact_state(sigma_x, sigma_z, tau0) result(state)
        !> shear and normal traction; friction threshold
        real(dp), intent(in) :: sigma_x, sigma_z, tau0
        if (in_tension(sigma_z)) then
            state = STATE_LIFTOFF
        else if (is_slipping(sigma_x, tau0) .or. tau0 <= 0.0_dp) then
            state = STATE_SLIP
        else
            state = STATE_STICK
        end if
    end function contact_state

    !> (|sigma_x| - tau0)^+ sign(sigma_x): the part of the shear beyond the threshold, which the
    !! slip branch of the law turns into slip (SPEC §4; nonzero exactly on the slip set).
    elemental real(dp) function slip_excess(sigma_x, tau0)
        !> shear traction; friction threshold f max(sigma_z, 0)
        real(dp), intent(in) :: sigma_x, tau0
        slip_excess = 0.0_dp
        if (is_slipping(sigma_x, tau0)) slip_excess = sign(abs(sigma_x) - tau0, sigma_x)
    end function slip_excess

    !> The largest |sigma_x| - tau0 the regularised law allows at a slip delta (SPEC §4):
    !! delta = c [eps tau + ((1 - eps^2)/eps) (|tau| - tau0)^+ sign tau] gives
    !! |tau| - tau0 = eps (|delta|/c - eps |tau|)/(1 - eps^2) <= eps |delta| / (c (1 - eps^2)).
    !! The friction admissibility check measures the excess against this (Coulomb: 0).
    elemental real(dp) function admissible_excess(eps_bar, slip, c) result(excess)
        real(dp), intent(in) :: eps_bar   !! regularisation
        real(dp), intent(in) :: slip      !! slip delta [length]
        real(dp), intent(in) :: c         !! friction compliance (model friction_compliance)
        excess = eps_bar*abs(slip)/(c*(1.0_dp - eps_bar**2))
    end function admissible_excess

    !> The tensile part of sigma_z that the exterior penalty acts on (paper 3.7-3.9): sigma_z on
    !! the tension set, else 0.
    elemental real(dp) function tensile_part(sigma_z)
        real(dp), intent(in) :: sigma_z   !! normal traction, compression positive
        tensile_part = 0.0_dp
        if (in_tension(sigma_z)) tensile_part = sigma_z
    end function tensile_part

    !> d tau0 / d sigma_z of friction_threshold: f in compression, 0 on the tension set (the
    !! one-sided derivative the semismooth Newton method uses at sigma_z = 0).
    elemental real(dp) function threshold_slope(f, sigma_z)
        !> friction coefficient; normal traction, compression positive
        real(dp), intent(in) :: f, sigma_z
        threshold_slope = f
        if (in_tension(sigma_z)) threshold_slope = 0.0_dp
    end function threshold_slope
end module interface_law
