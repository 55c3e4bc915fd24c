!> The ground's flexibility of a case, whichever the structure and the ground: dispatches to
!! `halfspace_plate` (axisymmetric rings) or `halfspace_beam` (centre-line strip kernels) for
!! the homogeneous half-space, and to `layered_influence` for layers over a base.
module halfspace_operator
    use kinds, only: dp
    use errors, only: error_t, add_context
    use model, only: model_t, MODEL_BEAM, FIELD_SX, FIELD_SZ, soil_shear_modulus, &
                     GROUND_LAYERED, GROUND_BASE_ROUGH, GROUND_BASE_SMOOTH, layer_profile
    use discretization, only: discretization_t
    use halfspace_plate, only: assemble_plate_flexibility, plate_surface_displacement
    use halfspace_beam, only: assemble_beam_flexibility, beam_surface_displacement
    use layered_compliance, only: layered_ground_t, new_layered_ground, BASE_ROUGH, &
                                  BASE_SMOOTH, BASE_HALFSPACE
    use layered_influence, only: assemble_layered_flexibility, layered_surface_displacement
    implicit none
    private
    public :: assemble_flexibility, surface_displacement

contains

    !> T (nr x nr), blocks [T_xx T_xz; T_zx T_zz] in the traction numbering of d.
    subroutine assemble_flexibility(m, d, t_mat, err)
        type(model_t), intent(in) :: m                      !! the model
        type(discretization_t), intent(in) :: d             !! the discretisation
        real(dp), allocatable, intent(out) :: t_mat(:, :)   !! T (nr x nr)
        type(error_t), allocatable, intent(out) :: err      !! allocated on failure
        type(layered_ground_t) :: layers
        if (m%ground%kind == GROUND_LAYERED) then
            call resolved_layers(m, layers, err)
            if (allocated(err)) return
            call assemble_layered_flexibility(d%basis(FIELD_SX), d%basis(FIELD_SZ), &
                m%structure%kind == MODEL_BEAM, m%structure%b, layers, t_mat, err)
        else if (m%structure%kind == MODEL_BEAM) then
            call assemble_beam_flexibility(d%basis(FIELD_SX), d%basis(FIELD_SZ), &
                                           soil_shear_modulus(m%ground), m%ground%nu_f, &
                                               m%structure%b, t_mat, err)
        else
            call assemble_plate_flexibility(d%basis(FIELD_SX), d%basis(FIELD_SZ), &
                                            soil_shear_modulus(m%ground), m%ground%nu_f, t_mat, err)
        end if
    end subroutine assemble_flexibility

    !> Surface displacements (u_x or u_r, w) of the ground at x_eval under the tractions r.
    subroutine surface_displacement(m, d, r, x_eval, u_f, w_f, err)
        type(model_t), intent(in) :: m        !! the model
        type(discretization_t), intent(in) :: d          !! the discretisation
        real(dp), intent(in) :: r(:)          !! traction coefficients [r_x; r_z]
        real(dp), intent(in) :: x_eval(:)     !! evaluation points on the surface [L]
        !> tangential and normal (down positive) displacement there
        real(dp), intent(out) :: u_f(:), w_f(:)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(layered_ground_t) :: layers
        integer :: nx
        nx = d%basis(FIELD_SX)%n_dof
        if (m%ground%kind == GROUND_LAYERED) then
            call resolved_layers(m, layers, err)
            if (allocated(err)) return
            call layered_surface_displacement(d%basis(FIELD_SX), d%basis(FIELD_SZ), &
                m%structure%kind == MODEL_BEAM, m%structure%b, layers, r(1:nx), r(nx + 1:), &
                x_eval, u_f, w_f, err)
        else if (m%structure%kind == MODEL_BEAM) then
            call beam_surface_displacement(d%basis(FIELD_SX), d%basis(FIELD_SZ), r(1:nx), &
                 r(nx + 1:), soil_shear_modulus(m%ground), m%ground%nu_f, m%structure%b, x_eval, &
                     u_f, w_f, err)
        else
            call plate_surface_displacement(d%basis(FIELD_SX), d%basis(FIELD_SZ), r(1:nx), &
                 r(nx + 1:), soil_shear_modulus(m%ground), m%ground%nu_f, x_eval, u_f, w_f, err)
        end if
    end subroutine surface_displacement

    !> The model's layers in physical units, resolved into sublayers of constant modulus.
    subroutine resolved_layers(m, layers, err)
        type(model_t), intent(in) :: m
        type(layered_ground_t), intent(out) :: layers
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: thickness(:), e_top(:), e_bottom(:), poisson(:)
        real(dp) :: e_base
        integer :: base
        call layer_profile(m%ground, thickness, e_top, e_bottom, poisson, e_base)
        select case (m%ground%base)
        case (GROUND_BASE_ROUGH)
            base = BASE_ROUGH
        case (GROUND_BASE_SMOOTH)
            base = BASE_SMOOTH
        case default
            base = BASE_HALFSPACE
        end select
        call new_layered_ground(layers, thickness, e_top, e_bottom, poisson, base, e_base, &
                                m%ground%nu_base, err)
        if (allocated(err)) call add_context(err, 'layered ground')
    end subroutine resolved_layers
end module halfspace_operator
