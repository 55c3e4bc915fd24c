!> The problem as the deck describes it: structure, soil, interface law, loads, mesh, solver
!! controls. Everything the solver needs is here in physical units (a NONDIM deck is turned
!! into a consistent physical set by `complete_model`, so one code path solves both).
module model
    use kinds, only: dp, pi
    implicit none
    private

    integer, parameter, public :: MODEL_BEAM = 1, MODEL_PLATE = 2
    integer, parameter, public :: LOAD_POINT = 1, LOAD_PATCH = 2, LOAD_MOMENT = 3, LOAD_RING = 4
    integer, parameter, public :: FIELD_U = 1, FIELD_W = 2, FIELD_PSI = 3, &
                                  FIELD_SX = 4, FIELD_SZ = 5
    !> Solution methods of the contact problem (SOLVER field 7).
    integer, parameter, public :: METHOD_NEWTON = 1, METHOD_TWOLOOP = 2

    !> One LOAD card, in physical units (forces, lengths; moment in force*length).
    type, public :: load_t
        integer :: kind = LOAD_POINT   !! LOAD_POINT, LOAD_PATCH, LOAD_MOMENT, LOAD_RING
        real(dp) :: fz = 0.0_dp        !! vertical force, downward positive (moment for MOMENT)
        real(dp) :: fx = 0.0_dp        !! horizontal force, +x (beam only), on the top face
        real(dp) :: x1 = 0.0_dp        !! position, or start of a patch [length]
        real(dp) :: x2 = 0.0_dp        !! end of a patch [length]
        integer :: line = 0            !! deck line of the card (for messages)
    end type load_t

    !> The whole problem.
    type, public :: model_t
        character(len=70) :: title = ''
        integer :: kind = MODEL_PLATE
        logical :: nondim = .false.            !! deck gave NONDIM groups instead of physics
        character(len=10) :: force_unit = 'N'  !! label only
        character(len=10) :: length_unit = 'm'
        ! geometry and materials (physical)
        real(dp) :: length = 0.0_dp   !! beam length l or plate radius a
        real(dp) :: h = 0.0_dp        !! thickness
        real(dp) :: b = 1.0_dp        !! beam width
        real(dp) :: e = 0.0_dp        !! Young's modulus of the structure
        real(dp) :: nu = 0.3_dp       !! Poisson's ratio of the structure
        real(dp) :: k_shear = 5.0_dp/6.0_dp  !! shear correction factor
        real(dp) :: e_f = 0.0_dp      !! Young's modulus of the soil
        real(dp) :: nu_f = 0.1_dp     !! Poisson's ratio of the soil
        ! nondimensional input (NONDIM card)
        real(dp) :: rho_in = 0.0_dp, zeta_in = 0.0_dp, beta_in = 0.0_dp
        ! interface
        real(dp) :: f = 0.0_dp        !! friction coefficient
        real(dp) :: eps_bar = 1.0e-6_dp  !! regularisation of the friction law (SPEC §4)
        ! loads
        type(load_t), allocatable :: loads(:)
        ! mesh
        integer :: ne = 20
        character(len=10) :: grading = 'UNIFORM'
        integer :: interp(5) = 1      !! per field (FIELD_*): INTERP_P1/P2/S2
        ! adaptive meshing (ADAPT card; adapt_tol = 0: the MESH card's mesh as it is)
        real(dp) :: adapt_tol = 0.0_dp    !! relative tolerance of the estimated errors
        integer :: adapt_max_ne = 0       !! largest number of elements of an adapted mesh
        ! solver
        real(dp) :: tol_outer = 1.0e-8_dp
        real(dp) :: tol_inner = 1.0e-10_dp
        integer :: max_outer = 100
        integer :: max_inner = 100
        real(dp) :: eta_bar = 1.0e-9_dp   !! penalty of the tension zone (SPEC §4)
        real(dp) :: tau0_start = -1.0_dp  !! start threshold, nondim; < 0: f * mean pressure
        integer :: method = METHOD_NEWTON  !! METHOD_NEWTON (default) or METHOD_TWOLOOP (paper)
        logical :: simplify = .true.      !! solve only what the scene needs (model_reduction)
        ! output
        integer :: stations = 0           !! 0: every node of the mesh
    end type model_t

    public :: complete_model, flexural_rigidity, total_vertical_load, friction_compliance
    public :: relative_stiffness, soil_shear_modulus, has_concentrated_load

contains

    !> For a NONDIM deck, choose the physical set (l or a = 1, E = 1, F = 1) reproducing the groups.
    pure subroutine complete_model(m)
        type(model_t), intent(inout) :: m
        if (.not. m%nondim) return
        m%force_unit = 'F'
        m%length_unit = merge('l', 'a', m%kind == MODEL_BEAM)
        m%length = 1.0_dp
        m%h = m%zeta_in
        m%e = 1.0_dp
        if (m%kind == MODEL_BEAM) then
            m%b = m%beta_in
            m%e_f = 32.0_dp*flexural_rigidity(m)*(1.0_dp - m%nu_f**2)/(pi*m%rho_in)
        else
            m%b = 1.0_dp
            m%e_f = 2.0_dp*flexural_rigidity(m)*(1.0_dp - m%nu_f**2)/m%rho_in
        end if
    end subroutine complete_model

    !> Beam EI = E b h^3/12; plate D = E h^3/(12 (1 - nu^2)).
    pure real(dp) function flexural_rigidity(m)
        type(model_t), intent(in) :: m
        if (m%kind == MODEL_BEAM) then
            flexural_rigidity = m%e*m%b*m%h**3/12.0_dp
        else
            flexural_rigidity = m%e*m%h**3/(12.0_dp*(1.0_dp - m%nu**2))
        end if
    end function flexural_rigidity

    !> rho of paper 5.2b.
    pure real(dp) function relative_stiffness(m)
        type(model_t), intent(in) :: m
        if (m%kind == MODEL_BEAM) then
            relative_stiffness = 32.0_dp*flexural_rigidity(m)*(1.0_dp - m%nu_f**2) &
                                 /(pi*m%e_f*m%length**4)
        else
            relative_stiffness = 2.0_dp*flexural_rigidity(m)*(1.0_dp - m%nu_f**2) &
                                 /(m%e_f*m%length**3)
        end if
    end function relative_stiffness

    !> G_f = E_f / (2 (1 + nu_f)).
    pure real(dp) function soil_shear_modulus(m)
        type(model_t), intent(in) :: m
        soil_shear_modulus = m%e_f/(2.0_dp*(1.0_dp + m%nu_f))
    end function soil_shear_modulus

    !> c of the friction law (SPEC §4): 1/(4 pi G_f) for the beam, a/(4 pi G_f) for the plate.
    pure real(dp) function friction_compliance(m)
        type(model_t), intent(in) :: m
        friction_compliance = 1.0_dp/(4.0_dp*pi*soil_shear_modulus(m))
        if (m%kind == MODEL_PLATE) friction_compliance = friction_compliance*m%length
    end function friction_compliance

    !> A POINT or RING load acts: the contact pressure is singular under it (log), so its
    !! largest station value depends on the mesh.
    pure logical function has_concentrated_load(m)
        type(model_t), intent(in) :: m
        has_concentrated_load = .false.
        if (allocated(m%loads)) has_concentrated_load = &
            any(m%loads%kind == LOAD_POINT .or. m%loads%kind == LOAD_RING)
    end function has_concentrated_load

    !> Sum of the vertical forces of all loads (moments excluded).
    pure real(dp) function total_vertical_load(m)
        type(model_t), intent(in) :: m
        integer :: i
        total_vertical_load = 0.0_dp
        if (.not. allocated(m%loads)) return
        do i = 1, size(m%loads)
            if (m%loads(i)%kind /= LOAD_MOMENT) total_vertical_load = total_vertical_load + m%loads(i)%fz
        end do
    end function total_vertical_load
end module model
