!> Timoshenko beam and axisymmetric Mindlin plate elements against closed forms.
module test_structure
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_PATCH, FIELD_U, FIELD_W, &
                     FIELD_PSI
    use discretization, only: discretization_t, new_discretization
    use mindlin_structure, only: section_t, section_of, assemble_stiffness, assemble_loads
    use linear_solve, only: solve_symmetric
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2
    implicit none
    private
    public :: collect_structure

contains

    subroutine collect_structure(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('beam_rigid_modes_null_space', test_rigid_modes), &
                 new_unittest('beam_simply_supported_timoshenko', test_beam_ss), &
                 new_unittest('beam_thin_no_locking', test_beam_locking), &
                 new_unittest('plate_clamped_mindlin', test_plate_clamped), &
                 new_unittest('plate_simply_supported_mindlin', test_plate_ss), &
                 new_unittest('plate_thin_no_locking', test_plate_locking)]
    end subroutine collect_structure

    !> A uniformly loaded beam (length 2, width 0.5) or plate (radius 1), E = 1000, nu = 0.3.
    function loaded_model(kind, h, ne, interp) result(m)
        integer, intent(in) :: kind, ne, interp
        real(dp), intent(in) :: h
        type(model_t) :: m
        m%structure%kind = kind
        m%structure%e = 1000.0_dp
        m%structure%nu = 0.3_dp
        m%structure%h = h
        m%mesh%ne = ne
        m%mesh%interp = interp
        if (kind == MODEL_BEAM) then
            m%structure%length = 2.0_dp
            m%structure%b = 0.5_dp
            m%loads = [load_t(kind=LOAD_PATCH, fz=2.0_dp, x1=-1.0_dp, x2=1.0_dp)] ! q = 1 per length
        else
            m%structure%length = 1.0_dp
            m%loads = [load_t(kind=LOAD_PATCH, fz=pi, x1=0.0_dp, x2=1.0_dp)]      ! p = 1
        end if
    end function loaded_model

    !> Solve K v = q with the listed coefficients held at zero; returns the field w.
    subroutine solve_supported(m, d, fixed, v, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        integer, intent(in) :: fixed(:)
        real(dp), allocatable, intent(out) :: v(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: k(:, :), q(:)
        integer :: i
        allocate (k(d%nv, d%nv), q(d%nv), v(d%nv))
        call assemble_stiffness(section_of(m%structure), d, k)
        call assemble_loads(m, d, q, err)
        if (allocated(err)) return
        do i = 1, size(fixed)
            k(fixed(i), :) = 0.0_dp
            k(:, fixed(i)) = 0.0_dp
            k(fixed(i), fixed(i)) = 1.0_dp
            q(fixed(i)) = 0.0_dp
        end do
        call solve_symmetric(k, q, v, err)
    end subroutine solve_supported

    subroutine test_rigid_modes(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(discretization_t) :: d
        real(dp), allocatable :: k(:, :), mode(:)
        integer :: imode, j
        m = loaded_model(MODEL_BEAM, 0.3_dp, 7, INTERP_P1)
        m%mesh%interp(FIELD_W) = INTERP_P2
        m%mesh%interp(FIELD_PSI) = INTERP_S2
        call new_discretization(m, d, err)
        if (allocated(err)) return
        allocate (k(d%nv, d%nv), mode(d%nv))
        call assemble_stiffness(section_of(m%structure), d, k)
        ! physical law: a free beam stores no energy in u = 1, w = 1, or (w = x, psi = 1)
        do imode = 1, 3
            mode = 0.0_dp
            select case (imode)
            case (1)
                mode(d%offset(FIELD_U) + 1:d%offset(FIELD_W)) = 1.0_dp
            case (2)
                mode(d%offset(FIELD_W) + 1:d%offset(FIELD_PSI)) = 1.0_dp
            case (3)
                ! P2 nodal values of w = x (nodes and mid-points), S2 control values of psi = 1
                do j = 1, d%basis(FIELD_W)%n_dof
                    mode(d%offset(FIELD_W) + j) = -1.0_dp + real(j - 1, dp)*2.0_dp &
                                                  /real(d%basis(FIELD_W)%n_dof - 1, dp)
                end do
                mode(d%offset(FIELD_PSI) + 1:d%nv) = 1.0_dp
            end select
            call check(err, maxval(abs(matmul(k, mode))) <= 1.0e-12_dp*maxval(abs(k)), &
                       'rigid-body mode not in the null space of K')
            if (allocated(err)) return
        end do
    end subroutine test_rigid_modes

    !> w(0) = 5 q L^4/(384 EI) + q L^2/(8 kGA) (Timoshenko 1921); O(h^2) convergence.
    subroutine test_beam_ss(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: interp
        do interp = INTERP_P1, INTERP_S2
            call beam_ss_case(0.4_dp, 64, interp, 1.0e-3_dp, err)
            if (allocated(err)) return
        end do
    end subroutine test_beam_ss

    subroutine test_beam_locking(err)
        type(error_t), allocatable, intent(out) :: err
        call beam_ss_case(2.0e-3_dp, 20, INTERP_P1, 5.0e-3_dp, err)
    end subroutine test_beam_locking

    subroutine beam_ss_case(h, ne, interp, rtol, err)
        real(dp), intent(in) :: h, rtol
        integer, intent(in) :: ne, interp
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(discretization_t) :: d
        type(section_t) :: sec
        real(dp), allocatable :: v(:)
        real(dp) :: exact, w_mid
        m = loaded_model(MODEL_BEAM, h, ne, interp)
        call new_discretization(m, d, err)
        if (allocated(err)) return
        call solve_supported(m, d, [d%offset(FIELD_U) + 1, d%offset(FIELD_W) + 1, &
                                    d%offset(FIELD_PSI)], v, err)
        if (allocated(err)) return
        sec = section_of(m%structure)
        exact = 5.0_dp*16.0_dp/(384.0_dp*sec%bending) + 4.0_dp/(8.0_dp*sec%shear)
        w_mid = middle_value(d, v, FIELD_W)
        call check_close(err, w_mid, exact, rtol, 0.0_dp, 'simply supported beam w(0)')
    end subroutine beam_ss_case

    !> Value of a field at the mesh centre (even ne: a node for P1/P2; S2 by its control values).
    real(dp) function middle_value(d, v, field) result(val)
        use mindlin_structure, only: displacement_at, field_point_t
        type(discretization_t), intent(in) :: d
        real(dp), intent(in) :: v(:)
        integer, intent(in) :: field
        type(field_point_t) :: p
        p = displacement_at(d, v, d%msh%ne/2, 1.0_dp)
        val = p%val(field)
    end function middle_value

    !> Clamped Mindlin plate: w(0) = q a^4/(64 D) + q a^2/(4 kGh) (Reddy, Wang & Lee relations).
    subroutine test_plate_clamped(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: interp
        do interp = INTERP_P1, INTERP_S2
            call plate_case(0.2_dp, 64, interp, .true., 1.0e-3_dp, err)
            if (allocated(err)) return
        end do
    end subroutine test_plate_clamped

    !> Simply supported: w(0) = q a^4 (5+nu)/(64 D (1+nu)) + q a^2/(4 kGh).
    subroutine test_plate_ss(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: interp
        do interp = INTERP_P1, INTERP_S2
            call plate_case(0.2_dp, 64, interp, .false., 1.0e-3_dp, err)
            if (allocated(err)) return
        end do
    end subroutine test_plate_ss

    !> h/a = 1e-3 with 20 P1 elements: within 0.5 % of Kirchhoff q a^4/(64 D) (locking test).
    subroutine test_plate_locking(err)
        type(error_t), allocatable, intent(out) :: err
        call plate_case(1.0e-3_dp, 20, INTERP_P1, .true., 5.0e-3_dp, err)
    end subroutine test_plate_locking

    subroutine plate_case(h, ne, interp, clamped, rtol, err)
        real(dp), intent(in) :: h, rtol
        integer, intent(in) :: ne, interp
        logical, intent(in) :: clamped
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(discretization_t) :: d
        type(section_t) :: sec
        real(dp), allocatable :: v(:)
        real(dp) :: exact, w0
        integer :: axis(2)
        m = loaded_model(MODEL_PLATE, h, ne, interp)
        call new_discretization(m, d, err)
        if (allocated(err)) return
        sec = section_of(m%structure)
        axis = [d%offset(FIELD_U) + 1, d%offset(FIELD_PSI) + 1]   ! u_s(0) = psi(0) = 0
        if (clamped) then
            call solve_supported(m, d, [axis, d%offset(FIELD_W), d%offset(FIELD_PSI), d%nv], &
                                 v, err)
            exact = 1.0_dp/(64.0_dp*sec%bending) + 1.0_dp/(4.0_dp*sec%shear)
        else
            call solve_supported(m, d, [axis, d%offset(FIELD_PSI)], v, err)
            exact = (5.0_dp + m%structure%nu)/((1.0_dp + m%structure%nu)*64.0_dp*sec%bending) &
                    + 1.0_dp/(4.0_dp*sec%shear)
        end if
        if (allocated(err)) return
        w0 = v(d%offset(FIELD_W) + 1)
        call check_close(err, w0, exact, rtol, 0.0_dp, 'circular plate w(0)')
    end subroutine plate_case
end module test_structure
