!> The problem as the deck describes it, in parts, each a typed record with its own owner
!! module: the structure (foundation_structure), the ground (ground_model), the interface
!! (interface_properties), the loads (applied_loads), the mesh request (mesh_request), the
!! solver controls (solver_controls) and the output options (here). A procedure takes the
!! part it needs. Everything the solver needs is in physical units: a NONDIM deck is turned
!! into a consistent physical set by `complete_model`, so one code path solves both. The
!! model is read-only once the deck is read: a refined case is a new model.
module model
    use kinds, only: dp, pi
    use foundation_structure, only: structure_t, section_t, MODEL_BEAM, MODEL_PLATE, &
                                    flexural_rigidity, section_of, interface_ends, &
                                    base_area, traction_measure
    use ground_model, only: ground_t, soil_shear_modulus, GROUND_HOMOGENEOUS, GROUND_LAYERED, &
                            GROUND_BASE_ROUGH, GROUND_BASE_SMOOTH, GROUND_BASE_HALFSPACE, &
                            layer_count, layer_profile, ground_depth, base_name
    use interface_properties, only: interface_t
    use applied_loads, only: load_t, LOAD_POINT, LOAD_PATCH, LOAD_MOMENT, LOAD_RING, &
                             load_kind_words, &
                             total_vertical_load, has_concentrated_load, load_positions
    use mesh_request, only: mesh_request_t, FIELD_U, FIELD_W, FIELD_PSI, FIELD_SX, FIELD_SZ
    use solver_controls, only: solver_controls_t, METHOD_NEWTON, METHOD_TWOLOOP
    use design_limits, only: design_limits_t
    implicit none
    private

    ! the parts and their constants, for callers that hold the whole model
    public :: structure_t, section_t, MODEL_BEAM, MODEL_PLATE, flexural_rigidity, section_of
    public :: interface_ends, base_area, traction_measure
    public :: ground_t, soil_shear_modulus, GROUND_HOMOGENEOUS, GROUND_LAYERED
    public :: GROUND_BASE_ROUGH, GROUND_BASE_SMOOTH, GROUND_BASE_HALFSPACE
    public :: layer_count, layer_profile, ground_depth, base_name
    public :: interface_t
    public :: load_t, LOAD_POINT, LOAD_PATCH, LOAD_MOMENT, LOAD_RING, total_vertical_load
    public :: load_kind_words
    public :: has_concentrated_load, load_positions
    public :: mesh_request_t, FIELD_U, FIELD_W, FIELD_PSI, FIELD_SX, FIELD_SZ
    public :: solver_controls_t, METHOD_NEWTON, METHOD_TWOLOOP
    public :: design_limits_t

    !> The deck's unit words (UNITS card): labels of the deck's units, which fricon never
    !! converts, and the display units of settlements and pressures (physical_units).
    type, public :: unit_labels_t
        character(len=10) :: force = 'N'    !! force unit F
        character(len=10) :: length = 'm'   !! length unit L
        character(len=10) :: disp = ''      !! settlement display unit ('': by default)
        character(len=10) :: pressure = ''  !! pressure display unit ('': by default)
        logical :: stated = .false.         !! the deck has a UNITS card
    end type unit_labels_t

    !> The nondimensional groups of a NONDIM card (SPEC §6, paper 5.2).
    type, public :: nondim_groups_t
        real(dp) :: rho = 0.0_dp    !! relative stiffness rho (paper 5.2b)
        real(dp) :: zeta = 0.0_dp   !! thickness ratio h/l or h/a
        real(dp) :: beta = 0.0_dp   !! beam width ratio b/l
    end type nondim_groups_t

    !> OUTPUT card.
    type, public :: output_options_t
        integer :: stations = 0   !! stations of the tables; 0: every node of the mesh
    end type output_options_t

    !> The whole problem.
    type, public :: model_t
        character(len=70) :: title = ''
        logical :: nondim = .false.            !! the deck gave NONDIM groups instead of physics
        type(nondim_groups_t) :: groups        !! the NONDIM card's groups (nondim only)
        type(unit_labels_t) :: units
        type(structure_t) :: structure
        type(ground_t) :: ground
        type(interface_t) :: interface
        type(load_t), allocatable :: loads(:)
        type(mesh_request_t) :: mesh
        type(solver_controls_t) :: solver
        type(output_options_t) :: output
        type(design_limits_t) :: limits        !! the CHECK cards (design_limits)
    end type model_t

    public :: complete_model, friction_compliance, relative_stiffness

contains

    !> For a NONDIM deck, choose the physical set (l or a = 1, E = 1, F = 1) reproducing the
    !! groups.
    pure subroutine complete_model(m)
        type(model_t), intent(inout) :: m   !! the model as read; physical on return
        if (.not. m%nondim) return
        m%units%force = 'F'
        m%units%length = merge('l', 'a', m%structure%kind == MODEL_BEAM)
        m%structure%length = 1.0_dp
        m%structure%h = m%groups%zeta
        m%structure%e = 1.0_dp
        if (m%structure%kind == MODEL_BEAM) then
            m%structure%b = m%groups%beta
            m%ground%e_f = 32.0_dp*flexural_rigidity(m%structure)*(1.0_dp - m%ground%nu_f**2) &
                           /(pi*m%groups%rho)
        else
            m%structure%b = 1.0_dp
            m%ground%e_f = 2.0_dp*flexural_rigidity(m%structure)*(1.0_dp - m%ground%nu_f**2) &
                           /m%groups%rho
        end if
    end subroutine complete_model

    !> rho of paper 5.2b: the structure's bending stiffness relative to the ground's.
    pure real(dp) function relative_stiffness(s, g)
        type(structure_t), intent(in) :: s   !! the structure
        type(ground_t), intent(in) :: g      !! the ground
        if (s%kind == MODEL_BEAM) then
            relative_stiffness = 32.0_dp*flexural_rigidity(s)*(1.0_dp - g%nu_f**2) &
                                 /(pi*g%e_f*s%length**4)
        else
            relative_stiffness = 2.0_dp*flexural_rigidity(s)*(1.0_dp - g%nu_f**2) &
                                 /(g%e_f*s%length**3)
        end if
    end function relative_stiffness

    !> c of the friction law (SPEC §4): 1/(4 pi G_f) for the beam, a/(4 pi G_f) for the plate.
    pure real(dp) function friction_compliance(s, g)
        type(structure_t), intent(in) :: s   !! the structure
        type(ground_t), intent(in) :: g      !! the ground
        friction_compliance = 1.0_dp/(4.0_dp*pi*soil_shear_modulus(g))
        if (s%kind == MODEL_PLATE) friction_compliance = friction_compliance*s%length
    end function friction_compliance
end module model
