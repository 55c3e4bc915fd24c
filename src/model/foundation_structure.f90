!> The foundation structure: a shear-deformable beam (strip footing of width b) or an
!! axisymmetric Mindlin plate (circular raft of radius a), its geometry and material, and the
!! one place where its section stiffnesses are computed (SPEC §2).
!!
!!   beam   EA = E b h,            EI = E b h^3/12,             kGA = k G b h
!!   plate  C = E h/(1 - nu^2),    D = E h^3/(12 (1 - nu^2)),   kGh = k G h
!! with G = E/(2 (1 + nu)). Units: the deck's force F and length L (E in F/L^2).
module foundation_structure
    use kinds, only: dp, pi
    implicit none
    private

    integer, parameter, public :: MODEL_BEAM = 1, MODEL_PLATE = 2

    !> Geometry and material of the structure (STRUCTURE and GEOMETRY cards).
    type, public :: structure_t
        integer :: kind = MODEL_PLATE         !! MODEL_BEAM or MODEL_PLATE
        real(dp) :: length = 0.0_dp           !! beam length l or plate radius a [L]
        real(dp) :: h = 0.0_dp                !! thickness [L]
        real(dp) :: b = 1.0_dp                !! beam width [L] (1 for the plate)
        real(dp) :: e = 0.0_dp                !! Young's modulus [F/L^2]
        real(dp) :: nu = 0.3_dp               !! Poisson's ratio
        real(dp) :: k_shear = 5.0_dp/6.0_dp   !! shear correction factor
    end type structure_t

    !> Section stiffnesses of the structure.
    type, public :: section_t
        real(dp) :: axial = 0.0_dp     !! beam EA [F], plate C = Eh/(1-nu^2) [F/L]
        real(dp) :: bending = 0.0_dp   !! beam EI [F L^2], plate D [F L]
        real(dp) :: shear = 0.0_dp     !! beam k G b h [F], plate k G h [F/L]
        real(dp) :: nu = 0.0_dp        !! plate Poisson coupling (0 for the beam)
        logical :: plate = .false.
    end type section_t

    public :: section_of, flexural_rigidity, interface_ends, base_area, traction_measure

contains

    !> The section stiffnesses of s (module header).
    pure function section_of(s) result(sec)
        type(structure_t), intent(in) :: s   !! the structure
        type(section_t) :: sec
        real(dp) :: g
        g = s%e/(2.0_dp*(1.0_dp + s%nu))
        if (s%kind == MODEL_BEAM) then
            sec%axial = s%e*s%b*s%h
            sec%bending = s%e*s%b*s%h**3/12.0_dp
            sec%shear = s%k_shear*g*s%b*s%h
        else
            sec%plate = .true.
            sec%nu = s%nu
            sec%axial = s%e*s%h/(1.0_dp - s%nu**2)
            sec%bending = s%e*s%h**3/(12.0_dp*(1.0_dp - s%nu**2))
            sec%shear = s%k_shear*g*s%h
        end if
    end function section_of

    !> Beam EI = E b h^3/12 [F L^2]; plate D = E h^3/(12 (1 - nu^2)) [F L].
    pure real(dp) function flexural_rigidity(s)
        type(structure_t), intent(in) :: s   !! the structure
        type(section_t) :: sec
        sec = section_of(s)
        flexural_rigidity = sec%bending
    end function flexural_rigidity

    !> The ends of the interface: [-l/2, l/2] (beam), [0, a] (plate).
    pure subroutine interface_ends(s, x_left, x_right)
        type(structure_t), intent(in) :: s   !! the structure
        real(dp), intent(out) :: x_left      !! -l/2 or 0 [L]
        real(dp), intent(out) :: x_right     !! l/2 or a [L]
        if (s%kind == MODEL_BEAM) then
            x_left = -0.5_dp*s%length
            x_right = 0.5_dp*s%length
        else
            x_left = 0.0_dp
            x_right = s%length
        end if
    end subroutine interface_ends

    !> The area of the base [L^2]: l b (beam), pi a^2 (plate).
    pure real(dp) function base_area(s)
        type(structure_t), intent(in) :: s   !! the structure
        if (s%kind == MODEL_BEAM) then
            base_area = s%length*s%b
        else
            base_area = pi*s%length**2
        end if
    end function base_area

    !> What a traction of the model integrates over to a force: l [L] for the beam (its
    !! tractions are line loads, force per length), pi a^2 [L^2] for the plate; the mean
    !! traction of a total load V is V / traction_measure.
    pure real(dp) function traction_measure(s)
        type(structure_t), intent(in) :: s   !! the structure
        if (s%kind == MODEL_BEAM) then
            traction_measure = s%length
        else
            traction_measure = pi*s%length**2
        end if
    end function traction_measure
end module foundation_structure
