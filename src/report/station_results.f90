!> Results at the report stations: fields, gap, slip, contact state and stress resultants,
!! in physical units, plus the factors that make them nondimensional (SPEC §6, paper 5.1).
module station_results
    use kinds, only: dp, pi
    use errors, only: error_t
    use model, only: model_t, MODEL_BEAM, flexural_rigidity, total_vertical_load
    use discretization, only: discretization_t, locate_element
    use mindlin_structure, only: section_t, section_of, displacement_at, traction_at, &
                                 resultants, field_point_t
    use halfspace_operator, only: surface_displacement
    use contact_solver, only: solution_t, STATE_LIFTOFF, STATE_STICK, STATE_SLIP
    implicit none
    private

    !> Station table. Physical arrays; multiply by the scale_* factors for nondimensional ones.
    type, public :: station_table_t
        integer :: n = 0
        integer :: n_res = 3                    !! beam N M Q; plate N_r N_t M_r M_t Q_r
        real(dp), allocatable :: x(:)           !! x or r [length]
        real(dp), allocatable :: field(:, :)    !! (7, n): u_s w psi sigma_x sigma_z gap slip
        integer, allocatable :: state(:)        !! 0 lift-off, 1 stick, 2 slip
        real(dp), allocatable :: res(:, :)      !! (n_res, n)
        real(dp) :: scale_x = 1.0_dp            !! t = x * scale_x
        real(dp) :: scale(7) = 1.0_dp           !! nondim = physical * scale (field columns)
        real(dp) :: scale_res(5) = 1.0_dp
    end type station_table_t

    public :: tabulate, contact_extent

contains

    !> Evaluate everything at the stations (every node, or OUTPUT stations equally spaced).
    subroutine tabulate(m, d, sol, tab, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(inout) :: sol
        type(station_table_t), intent(out) :: tab
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: u_f(:), w_f(:)
        integer :: i

        call station_positions(m, d, tab)
        allocate (tab%field(7, tab%n), tab%state(tab%n), tab%res(5, tab%n))
        allocate (u_f(tab%n), w_f(tab%n))
        call surface_displacement(m, d, sol%z(d%nv + 1:), tab%x, u_f, w_f, err)
        if (allocated(err)) return
        tab%n_res = merge(3, 5, m%kind == MODEL_BEAM)
        stations: do i = 1, tab%n
            call evaluate_station(m, d, sol, tab%x(i), tab%field(:, i), tab%res(:, i))
            tab%field(6, i) = w_f(i) - tab%field(2, i)                  ! gap = w_f - w_b
            tab%field(7, i) = tab%field(1, i) - 0.5_dp*m%h*tab%field(3, i) - u_f(i) ! slip
            tab%state(i) = station_state(tab%field(4, i), tab%field(5, i), m%f)
        end do stations
        call set_scales(m, tab)
        ! complementarity proper: where the structure has lifted off, sigma_z * gap ~ 0
        sol%complementarity = 0.0_dp
        if (any(tab%state == STATE_LIFTOFF)) sol%complementarity = &
            maxval(abs(tab%field(5, :)*tab%field(6, :)), mask=tab%state == STATE_LIFTOFF) &
            *tab%scale(5)*tab%scale(2)
        ! where in contact, the pointwise gap is the error of the weak (Galerkin) compatibility
        sol%compatibility = 0.0_dp
        if (any(tab%state /= STATE_LIFTOFF)) sol%compatibility = &
            maxval(abs(tab%field(6, :)), mask=tab%state /= STATE_LIFTOFF) &
            /max(maxval(abs(tab%field(2, :))), tiny(1.0_dp))
    end subroutine tabulate

    !> Nodes of the mesh, or `stations` equally spaced points.
    subroutine station_positions(m, d, tab)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(station_table_t), intent(inout) :: tab
        integer :: i
        if (m%stations >= 2) then
            tab%n = m%stations
            allocate (tab%x(tab%n))
            do i = 1, tab%n
                tab%x(i) = d%msh%x(0) + (d%msh%x(d%msh%ne) - d%msh%x(0))*real(i - 1, dp) &
                           /real(tab%n - 1, dp)
            end do
        else
            tab%n = d%msh%ne + 1
            allocate (tab%x(tab%n))
            tab%x(:) = d%msh%x     ! (re-based to 1:n)
        end if
    end subroutine station_positions

    !> Fields at x; resultants averaged over the two elements when x is an interior node.
    subroutine evaluate_station(m, d, sol, x, field, res)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: x
        real(dp), intent(out) :: field(7), res(5)
        type(section_t) :: sec
        type(field_point_t) :: p, p_right
        integer :: e
        real(dp) :: xi, s(2)
        sec = section_of(m)
        call locate_element(d%msh, x, e, xi)
        p = displacement_at(d, sol%z(1:d%nv), e, xi)
        s = traction_at(d, sol%z(d%nv + 1:), e, xi)
        field(1:3) = p%val
        field(4:5) = s
        field(6:7) = 0.0_dp
        res = resultants(sec, p)
        if (xi >= 1.0_dp .and. e < d%msh%ne) then
            p_right = displacement_at(d, sol%z(1:d%nv), e + 1, -1.0_dp)
            res = 0.5_dp*(res + resultants(sec, p_right))
        end if
    end subroutine evaluate_station

    !> Contact state from the tractions: lift-off where sigma_z <= 0, slip where
    !! |sigma_x| > f sigma_z, else stick.
    pure integer function station_state(sigma_x, sigma_z, f) result(state)
        real(dp), intent(in) :: sigma_x, sigma_z, f
        if (sigma_z <= 0.0_dp) then
            state = STATE_LIFTOFF
        else if (abs(sigma_x) > f*sigma_z) then
            state = STATE_SLIP
        else
            state = STATE_STICK
        end if
    end function station_state

    !> Paper 5.1: beam U, W = EI u/(F l^3), Psi = EI psi/(F l^2), Sigma = l sigma/F;
    !! plate U, W = D u/(F a^2), Psi = D psi/(F a), Sigma = pi a^2 sigma/F.
    !! Resultants: beam N/F, M/(F l), Q/F; plate N a/F, M/F, Q a/F.
    pure subroutine set_scales(m, tab)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(inout) :: tab
        real(dp) :: f, l, rigidity
        f = total_vertical_load(m)
        l = m%length
        rigidity = flexural_rigidity(m)
        tab%scale_x = 1.0_dp/l
        if (m%kind == MODEL_BEAM) then
            tab%scale([1, 2, 6, 7]) = rigidity/(f*l**3)
            tab%scale(3) = rigidity/(f*l**2)
            tab%scale(4:5) = l/f
            tab%scale_res(1:3) = [1.0_dp/f, 1.0_dp/(f*l), 1.0_dp/f]
        else
            tab%scale([1, 2, 6, 7]) = rigidity/(f*l**2)
            tab%scale(3) = rigidity/(f*l)
            tab%scale(4:5) = pi*l**2/f
            tab%scale_res = [l/f, l/f, 1.0_dp/f, 1.0_dp/f, l/f]
        end if
    end subroutine set_scales

    !> Largest t >= 0 of a station in contact (stick or slip); -1 if none.
    pure real(dp) function contact_extent(tab) result(t_max)
        type(station_table_t), intent(in) :: tab
        integer :: i
        t_max = -1.0_dp
        do i = 1, tab%n
            if (tab%state(i) /= STATE_LIFTOFF .and. tab%x(i) >= 0.0_dp) &
                t_max = max(t_max, tab%x(i)*tab%scale_x)
        end do
    end function contact_extent
end module station_results
