!> Results at the report stations, evaluated from a solved case (read-only: nothing here
!! changes the solution). All values are stored in the deck's physical units; the column table
!! (station_columns) turns them into nondimensional or display units.
!!
!! How each quantity is evaluated, and why (README "Station values"):
!! * u_s, w, psi: the finite-element fields at the station.
!! * sigma_x, sigma_z: recovered as the mean traction over the elements that meet at the node
!!   (stations between nodes interpolate linearly). The element means are exactly the forces the
!!   discrete equations carry (the Gauss rule of the interface is exact for them); the nodal
!!   coefficients of a traction approximating an edge singularity oscillate from node to node,
!!   and in a lift-off zone they can be tensile although every Gauss point is at O(eta).
!! * state: the solver's interface law (interface_law) on the recovered tractions, with the
!!   threshold of the converged problem tau0 = f max(sigma_z, 0).
!! * gap: 0 where in contact (compatibility holds in the weak sense; its pointwise error is
!!   reported among the checks); the pointwise w_f - w_b where lifted off.
!! * slip: u_b - u_f where slipping or lifted off; the stick compliance c eps_bar sigma_x of
!!   the law where sticking.
!! * N, M, Q (beam) and N_r, M_r, Q_r (plate): from the statics of the part of the structure
!!   left of the section (inside the circle r), loaded by the loads and the computed tractions.
!!   They satisfy equilibrium at every station; Q_r(0) = 0 by symmetry. N_theta and M_theta
!!   (plate) are the finite-element values, which close the plate's equilibrium.
!! * Sigma_x^h, Sigma_z^h: the pointwise finite-element tractions at the station, unrecovered
!!   (the nodal values the paper prints; the data files keep them: .dat Sigma_z^h, CSV
!!   sigma_z_fe). Under a concentrated load and at an edge in contact they peak above the
!!   element means, and neither converges there (the pressure is singular).
!! Stations at the position of a concentrated load (beam POINT or MOMENT, plate RING) appear
!! twice: the left (inner) and the right (outer) limit, where Q, M or N jump.
module station_results
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use model, only: load_t, structure_t, model_t, MODEL_BEAM, LOAD_PATCH, LOAD_MOMENT, &
        friction_compliance, &
                     total_vertical_load, traction_measure
    use quadrature, only: gauss_legendre
    use discretization, only: discretization_t, locate_element
    use mindlin_structure, only: section_t, section_of, displacement_at, traction_at, &
                                 resultants, field_point_t
    use halfspace_operator, only: surface_displacement
    use contact_solver, only: solution_t
    use interface_law, only: STATE_LIFTOFF, STATE_STICK, contact_state, &
                             friction_threshold
    use station_columns, only: n_quantities, Q_X, Q_U, Q_W, Q_PSI, Q_SX, Q_SZ, Q_GAP, &
                               Q_SLIP, Q_STATE, Q_N, Q_NT, Q_M, Q_MT, Q_Q, Q_SX_FE, Q_SZ_FE
    implicit none
    private

    integer, parameter, public :: FLAG_TENSION = 1   !! sigma_z below -O(eta): not a contact value
    integer, parameter, public :: FLAG_OVERLAP = 2   !! lifted off with a negative pointwise gap

    !> Station table and the pointwise checks made with it.
    type, public :: station_table_t
        integer :: n = 0
        real(dp), allocatable :: val(:, :)      !! (n_quantities, n), physical deck units
        integer, allocatable :: state(:)        !! STATE_LIFTOFF / STICK / SLIP
        integer, allocatable :: side(:)         !! -1 left limit, +1 right limit, 0 plain
        integer, allocatable :: flag(:)         !! sum of FLAG_* bits
        real(dp) :: tension_tol = 0.0_dp        !! sigma_z below -tension_tol is flagged
        real(dp) :: complementarity = 0.0_dp    !! max |Sigma_z gap| (nondim) where lifted off
        real(dp) :: compatibility = 0.0_dp      !! max |pointwise gap| / max |w| where in contact
        real(dp) :: most_tensile = 0.0_dp       !! min sigma_z over the stations [F/L or F/L^2]
        real(dp) :: w_mean = 0.0_dp             !! mean settlement over the base (plate: by
                                                !! area) of the finite-element w, by Gauss
                                                !! rules: the same for any stations
    end type station_table_t

    public :: tabulate, tabulate_design, contact_extent

contains

    !> Evaluate everything at the stations (every node, or OUTPUT stations equally spaced,
    !! plus both sides of every concentrated load).
    subroutine tabulate(m, d, sol, tab, err, with_nodes, soil)
        type(model_t), intent(in) :: m                !! the model
        type(discretization_t), intent(in) :: d       !! the discretisation
        type(solution_t), intent(in) :: sol           !! the solution
        type(station_table_t), intent(out) :: tab     !! the station table
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        logical, intent(in), optional :: with_nodes   !! OUTPUT stations and every node
        !> the soil's surface displacement at the stations (default); .false.: not computed,
        !! and the columns made from it (gap, slip) and the overlap flags are left 0. For the
        !! error estimate's extra solves, which read the key results only (none of them is
        !! made from the soil's displacement); a tenth of a small case's work each
        logical, intent(in), optional :: soil
        real(dp), allocatable :: x(:), u_f(:), w_f(:), rec(:, :), gap_pw(:)
        logical :: nodes_too, with_soil
        integer :: i

        nodes_too = .false.
        if (present(with_nodes)) nodes_too = with_nodes
        with_soil = .true.
        if (present(soil)) with_soil = soil
        call station_positions(m, d, nodes_too, x, tab%side)
        tab%n = size(x)
        allocate (tab%val(n_quantities, tab%n), tab%state(tab%n), tab%flag(tab%n))
        allocate (u_f(tab%n), w_f(tab%n), gap_pw(tab%n))
        tab%val = 0.0_dp
        tab%val(Q_X, :) = x
        gap_pw = 0.0_dp
        if (with_soil) then
            call soil_displacement(m, d, sol, tab%val(Q_X, :), u_f, w_f, err)
            if (allocated(err)) return
        end if
        allocate (rec(2, 0:d%msh%ne))
        rec(:, :) = nodal_traction_means(d, sol%z(d%nv + 1:))
        if (m%structure%kind /= MODEL_BEAM) rec(1, 0) = 0.0_dp   ! radial shear vanishes on the axis
        stations: do i = 1, tab%n
            call fields_at(section_of(m%structure), d, sol, rec, tab%val(Q_X, i), tab%side(i), &
                tab%val(:, i))
            tab%state(i) = contact_state(tab%val(Q_SX, i), tab%val(Q_SZ, i), &
                                         friction_threshold(m%interface%f, tab%val(Q_SZ, i)))
            if (with_soil) then
                gap_pw(i) = w_f(i) - tab%val(Q_W, i)
                call gap_and_slip(m, tab%state(i), gap_pw(i), &
                                  tab%val(Q_U, i) - 0.5_dp*m%structure%h*tab%val(Q_PSI, i) - &
                                  u_f(i), tab%val(Q_SX, i), tab%val(Q_GAP, i), &
                                  tab%val(Q_SLIP, i))
            end if
            tab%val(Q_STATE, i) = real(tab%state(i), dp)
        end do stations
        call statics_resultants(m, d, sol, tab)
        call pointwise_checks(m, gap_pw, tab)
        tab%w_mean = mean_settlement(m%structure, d, sol)
    end subroutine tabulate

    !> The soil's surface displacement (u_f, w_f) at the points x under the solution's
    !! tractions; an error where it is not finite (a quadrature that met the kernel's
    !! singularity: no silent Inf or NaN in a report).
    subroutine soil_displacement(m, d, sol, x, u_f, w_f, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: u_f(:), w_f(:)
        type(error_t), allocatable, intent(out) :: err
        call surface_displacement(m, d, sol%z(d%nv + 1:), x, u_f, w_f, err)
        if (allocated(err)) return
        if (.not. (all(abs(u_f) <= huge(1.0_dp)) .and. all(abs(w_f) <= huge(1.0_dp)))) then
            call new_error(err, EXIT_INTERNAL, 'the soil surface displacement at a station is '// &
                           'not finite')
        end if
    end subroutine soil_displacement

    !> The mean of the finite-element settlement w over the base, weighted by 2 pi r for the
    !! plate: 4-point Gauss per element (exact for w of degree <= 5, 6 with the weight r).
    pure real(dp) function mean_settlement(structure, d, sol) result(w_mean)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp) :: xg(4), wg(4), h, wt, w_sum, wt_sum
        type(field_point_t) :: p
        integer :: e, g
        call gauss_legendre(4, xg, wg)
        w_sum = 0.0_dp
        wt_sum = 0.0_dp
        do e = 1, d%msh%ne
            h = d%msh%x(e) - d%msh%x(e - 1)
            do g = 1, 4
                p = displacement_at(d, sol%z(1:d%nv), e, xg(g))
                wt = 0.5_dp*h*wg(g)
                if (structure%kind /= MODEL_BEAM) wt = wt*p%x
                w_sum = w_sum + wt*p%val(2)
                wt_sum = wt_sum + wt
            end do
        end do
        w_mean = w_sum/wt_sum
    end function mean_settlement

    !> The table the design values are read from (design_summary): every node, every patch
    !! edge and both sides of every concentrated load, and the OUTPUT card's stations if it has
    !! any (a peak between two printed stations, e.g. a hogging moment over the wall of a tank,
    !! would otherwise be missed or read low; stations finer than the mesh keep locating the
    !! contact boundaries as finely as they did). The printed table itself when it already is
    !! that one.
    subroutine tabulate_design(m, d, sol, tab, design, err, soil)
        type(model_t), intent(in) :: m                 !! the model
        type(discretization_t), intent(in) :: d        !! the discretisation
        type(solution_t), intent(in) :: sol            !! the solution
        type(station_table_t), intent(in) :: tab       !! the printed table (tabulate)
        type(station_table_t), intent(out) :: design   !! the design table
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        logical, intent(in), optional :: soil   !! the soil's displacement too (tabulate)
        if (m%output%stations < 2) then
            design = tab
            return
        end if
        call tabulate(m, d, sol, design, err, with_nodes=.true., soil=soil)
    end subroutine tabulate_design

    !> Nodes of the mesh (or `stations` equally spaced points), with every patch edge inside
    !! the base inserted once (the shear force peaks there: the load stops growing with x)
    !! and every concentrated load position twice (left and right limit), each replacing a
    !! station that coincides. A node within rounding of x = 0 (a symmetric mesh's middle,
    !! -8.9e-16 from its sum of lengths) is the centre itself.
    pure subroutine station_positions(m, d, nodes_too, x, side)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        logical, intent(in) :: nodes_too     !! the OUTPUT stations and every node
        real(dp), allocatable, intent(out) :: x(:)
        integer, allocatable, intent(out) :: side(:)
        real(dp), allocatable :: jumps(:), edges(:)
        real(dp) :: x0, x1, tol
        integer :: i, j, n_same
        x0 = d%msh%x(0)
        x1 = d%msh%x(d%msh%ne)
        tol = position_tolerance(d)
        if (m%output%stations >= 2) then
            x = [(x0 + (x1 - x0)*real(i - 1, dp)/real(m%output%stations - 1, dp), i=1, &
                m%output%stations)]
            if (nodes_too) x = merged(x, d%msh%x, tol)
        else
            x = [d%msh%x]      ! (re-based to 1:n; the mesh is x(0:ne))
        end if
        where (abs(x) <= tol) x = 0.0_dp
        allocate (side(size(x)))
        side = 0
        edges = patch_edges(m%loads, x0 + tol, x1 - tol)
        edge_inserts: do j = 1, size(edges)
            if (any(abs(x - edges(j)) <= tol)) cycle edge_inserts
            i = count(x < edges(j))
            x = [x(1:i), edges(j), x(i + 1:)]
            side = [side(1:i), 0, side(i + 1:)]
        end do edge_inserts
        jumps = concentrated_positions(m, x0 + tol)
        inserts: do j = 1, size(jumps)
            if (any(abs(x - jumps(j)) <= tol .and. side /= 0)) cycle inserts  ! already split
            i = count(x < jumps(j) - tol)
            n_same = count(abs(x - jumps(j)) <= tol)
            x = [x(1:i), jumps(j), jumps(j), x(i + 1 + n_same:)]
            side = [side(1:i), -1, +1, side(i + 1 + n_same:)]
        end do inserts
    end subroutine station_positions

    !> Positions where a resultant jumps: beam POINT and MOMENT loads, plate RING loads (a load
    !! on the plate axis, x <= x_min, makes no jump at a station).
    pure function concentrated_positions(m, x_min) result(x)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: x_min
        real(dp), allocatable :: x(:)
        integer :: i
        allocate (x(0))
        do i = 1, size(m%loads)
            if (m%loads(i)%kind == LOAD_PATCH) cycle
            if (m%structure%kind /= MODEL_BEAM .and. m%loads(i)%x1 <= x_min) cycle
            x = [x, m%loads(i)%x1]
        end do
    end function concentrated_positions

    !> The union of two ascending lists, a point within tol of one already taken left out.
    pure function merged(a, b, tol) result(x)
        real(dp), intent(in) :: a(:), b(:), tol
        real(dp), allocatable :: x(:)
        real(dp) :: next
        integer :: i, j, n
        allocate (x(size(a) + size(b)))
        i = 1
        j = 1
        n = 0
        do while (i <= size(a) .or. j <= size(b))
            if (j > size(b)) then
                next = a(i)
                i = i + 1
            else if (i > size(a)) then
                next = b(j)
                j = j + 1
            else if (a(i) <= b(j)) then
                next = a(i)
                i = i + 1
            else
                next = b(j)
                j = j + 1
            end if
            if (n > 0) then
                if (next - x(n) <= tol) cycle
            end if
            n = n + 1
            x(n) = next
        end do
        x = x(1:n)
    end function merged

    !> The ends of the PATCH loads strictly inside (x_min, x_max).
    pure function patch_edges(loads, x_min, x_max) result(x)
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        real(dp), intent(in) :: x_min, x_max
        real(dp), allocatable :: x(:)
        integer :: i
        allocate (x(0))
        do i = 1, size(loads)
            if (loads(i)%kind /= LOAD_PATCH) cycle
            x = [x, pack([loads(i)%x1, loads(i)%x2], &
                         [loads(i)%x1, loads(i)%x2] > x_min .and. &
                         [loads(i)%x1, loads(i)%x2] < x_max)]
        end do
    end function patch_edges

    pure real(dp) function position_tolerance(d) result(tol)
        type(discretization_t), intent(in) :: d
        tol = 1.0e-9_dp*(d%msh%x(d%msh%ne) - d%msh%x(0))
    end function position_tolerance

    !> Mean (sigma_x, sigma_z) over the elements meeting at each node: (2, 0:ne).
    pure function nodal_traction_means(d, r) result(rec)
        type(discretization_t), intent(in) :: d
        real(dp), intent(in) :: r(:)       !! traction coefficients
        real(dp) :: rec(2, 0:d%msh%ne)
        real(dp) :: force(2, d%msh%ne), h(d%msh%ne), xg(4), wg(4)
        integer :: e, g
        call gauss_legendre(4, xg, wg)
        elements: do e = 1, d%msh%ne
            h(e) = d%msh%x(e) - d%msh%x(e - 1)
            force(:, e) = 0.0_dp
            do g = 1, 4
                force(:, e) = force(:, e) + 0.5_dp*wg(g)*h(e)*traction_at(d, r, e, xg(g))
            end do
        end do elements
        rec(:, 0) = force(:, 1)/h(1)
        rec(:, d%msh%ne) = force(:, d%msh%ne)/h(d%msh%ne)
        do e = 1, d%msh%ne - 1
            rec(:, e) = (force(:, e) + force(:, e + 1))/(h(e) + h(e + 1))
        end do
    end function nodal_traction_means

    !> u_s, w, psi, recovered tractions and the finite-element hoop resultants at x.
    pure subroutine fields_at(sec, d, sol, rec, x, side, val)
        type(section_t), intent(in) :: sec
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: rec(:, 0:)
        real(dp), intent(in) :: x
        integer, intent(in) :: side
        real(dp), intent(inout) :: val(:)
        type(field_point_t) :: p
        real(dp) :: xi, res(5), s
        integer :: e
        call locate_element(d%msh, x, e, xi)
        if (side > 0 .and. xi >= 1.0_dp .and. e < d%msh%ne) then
            e = e + 1
            xi = -1.0_dp
        end if
        p = displacement_at(d, sol%z(1:d%nv), e, xi)
        val([Q_U, Q_W, Q_PSI]) = p%val
        s = 0.5_dp*(xi + 1.0_dp)
        val([Q_SX, Q_SZ]) = (1.0_dp - s)*rec(:, e - 1) + s*rec(:, e)
        val([Q_SX_FE, Q_SZ_FE]) = traction_at(d, sol%z(d%nv + 1:), e, xi)
        res = node_averaged_resultants(sec, d, sol, e, xi)
        val(Q_NT) = res(2)
        val(Q_MT) = res(4)
    end subroutine fields_at

    !> Finite-element resultants at local xi of element e, averaged with the neighbouring
    !! element at an interior node (where psi' and u' jump).
    pure function node_averaged_resultants(sec, d, sol, e, xi) result(res)
        type(section_t), intent(in) :: sec
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        integer, intent(in) :: e
        real(dp), intent(in) :: xi
        real(dp) :: res(5)
        res = resultants(sec, displacement_at(d, sol%z(1:d%nv), e, xi))
        if (xi >= 1.0_dp .and. e < d%msh%ne) then
            res = 0.5_dp*(res + resultants(sec, displacement_at(d, sol%z(1:d%nv), e + 1, -1.0_dp)))
        else if (xi <= -1.0_dp .and. e > 1) then
            res = 0.5_dp*(res + resultants(sec, displacement_at(d, sol%z(1:d%nv), e - 1, 1.0_dp)))
        end if
    end function node_averaged_resultants

    !> Reported gap and slip of a station in the given state (see the module header).
    pure subroutine gap_and_slip(m, state, gap_pointwise, slip_pointwise, sigma_x, gap, slip)
        type(model_t), intent(in) :: m
        integer, intent(in) :: state
        real(dp), intent(in) :: gap_pointwise, slip_pointwise, sigma_x
        real(dp), intent(out) :: gap, slip
        gap = 0.0_dp
        slip = slip_pointwise
        select case (state)
        case (STATE_LIFTOFF)
            gap = gap_pointwise
        case (STATE_STICK)
            slip = friction_compliance(m%structure, m%ground)*m%interface%eps_bar*sigma_x
        end select
    end subroutine gap_and_slip

    !> N, M, Q (beam) or N_r, M_r, Q_r (plate) from the statics of the free body left of the
    !! station (inside the circle of radius r). With w = 1 (beam) or 2 pi s (plate) and
    !! I0[g](x) = int_x0^x w g ds, I1[g](x) = int_x0^x w g (x - s) ds (loads included as
    !! distributions, moments C as their sum left of x):
    !!   beam   Q = I0[sz] - I0[qz],  N = I0[sx] - I0[qx],
    !!          M = -(I1[sz] - I1[qz]) - (h/2)(I0[sx] + I0[qx]) - C (M' = -Q - (h/2)(qx+sx))
    !!   plate  2 pi r Q_r = I0[sz] - I0[qz],  r N_r = int N_t - (I0[qx] - I0[sx])/(2 pi),
    !!          r M_r = int M_t - (I1[sz] - I1[qz])/(2 pi) - (h/2)(I0[sx] + I0[qx])/(2 pi)
    !! from Q' = sz - qz, N' = sx - qx, M' = -Q - (h/2)(qx + sx) and their axisymmetric forms
    !! (r Q_r)' = r (sz - qz), (r N_r)' = N_t - r (qx - sx),
    !! (r M_r)' = M_t - r Q_r - r (h/2)(qx + sx).
    pure subroutine statics_resultants(m, d, sol, tab)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(inout) :: tab
        real(dp) :: t0(2), t1(2), hoop(2), ld(4), x, two_pi_r, xg(4), wg(4)
        real(dp) :: cum(6, 0:d%msh%ne)
        integer :: i
        call gauss_legendre(4, xg, wg)     ! once: element_integrals runs N_e + n times
        cum = cumulative_integrals(m%structure, d, sol, xg, wg)
        stations: do i = 1, tab%n
            x = tab%val(Q_X, i)
            call traction_integrals(m%structure, d, sol, cum, xg, wg, x, t0, t1, hoop)
            ld = load_integrals(m, x, tab%side(i), position_tolerance(d))
            if (m%structure%kind == MODEL_BEAM) then
                tab%val(Q_Q, i) = t0(2) - ld(1)
                tab%val(Q_N, i) = t0(1) - ld(3)
                tab%val(Q_M, i) = -(t1(2) - ld(2)) - 0.5_dp*m%structure%h*(t0(1) + ld(3)) - ld(4)
            else if (x > position_tolerance(d)) then
                two_pi_r = 2.0_dp*pi*x
                tab%val(Q_Q, i) = (t0(2) - ld(1))/two_pi_r
                tab%val(Q_N, i) = (hoop(1) - (ld(3) - t0(1))/(2.0_dp*pi))/x
                tab%val(Q_M, i) = (hoop(2) - (t1(2) - ld(2))/(2.0_dp*pi) &
                                   - 0.5_dp*m%structure%h*(t0(1) + ld(3))/(2.0_dp*pi))/x
            else
                ! the axis: Q_r = 0 by symmetry, N_r = N_t and M_r = M_t (isotropic centre)
                tab%val(Q_Q, i) = 0.0_dp
                tab%val(Q_N, i) = tab%val(Q_NT, i)
                tab%val(Q_M, i) = tab%val(Q_MT, i)
            end if
        end do stations
    end subroutine statics_resultants

    !> I0 and I1 of (sigma_x, sigma_z) from x0 to x, and (plate) int_0^x of N_t and M_t: the
    !! node totals of cumulative_integrals plus the part of the element that holds x, with
    !! I1(x) = x J0(x) - J1(x), J1 = int w g s ds.
    pure subroutine traction_integrals(structure, d, sol, cum, xg, wg, x, t0, t1, hoop)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: cum(:, 0:)      !! cumulative_integrals
        real(dp), intent(in) :: xg(4), wg(4)    !! 4-point Gauss rule on [-1, 1]
        real(dp), intent(in) :: x
        real(dp), intent(out) :: t0(2), t1(2), hoop(2)
        real(dp) :: total(6), xi
        integer :: e
        call locate_element(d%msh, x, e, xi)
        total = cum(:, e - 1) + element_integrals(structure, d, sol, xg, wg, e, d%msh%x(e - 1), &
                                                  max(d%msh%x(e - 1), min(x, d%msh%x(e))))
        t0 = total(1:2)
        t1 = x*total(1:2) - total(3:4)
        hoop = total(5:6)
    end subroutine traction_integrals

    !> At every node k, int_x0^x_k of w (sigma_x, sigma_z, s sigma_x, s sigma_z) and (plate)
    !! of N_t and M_t: (6, 0:ne), element by element, once per table.
    pure function cumulative_integrals(structure, d, sol, xg, wg) result(cum)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: xg(4), wg(4)    !! 4-point Gauss rule on [-1, 1]
        real(dp) :: cum(6, 0:d%msh%ne)
        integer :: e
        cum(:, 0) = 0.0_dp
        elements: do e = 1, d%msh%ne
            cum(:, e) = cum(:, e - 1) + element_integrals(structure, d, sol, xg, wg, e, &
                d%msh%x(e - 1), &
                                                          d%msh%x(e))
        end do elements
    end function cumulative_integrals

    !> The six integrals of cumulative_integrals over [lo, hi] inside element e, exact for the
    !! polynomial tractions (4-point Gauss; w = 1 for the beam, 2 pi s for the plate).
    pure function element_integrals(structure, d, sol, xg, wg, e, lo, hi) result(part)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: xg(4), wg(4)    !! 4-point Gauss rule on [-1, 1]
        integer, intent(in) :: e
        real(dp), intent(in) :: lo, hi
        real(dp) :: part(6)
        real(dp) :: s, wt, xi, sig(2), res(5)
        type(section_t) :: sec
        integer :: g
        part = 0.0_dp
        if (hi <= lo) return
        sec = section_of(structure)
        do g = 1, 4
            s = lo + 0.5_dp*(xg(g) + 1.0_dp)*(hi - lo)
            wt = 0.5_dp*wg(g)*(hi - lo)
            xi = 2.0_dp*(s - d%msh%x(e - 1))/(d%msh%x(e) - d%msh%x(e - 1)) - 1.0_dp
            sig = traction_at(d, sol%z(d%nv + 1:), e, xi)
            if (structure%kind /= MODEL_BEAM) then
                res = resultants(sec, displacement_at(d, sol%z(1:d%nv), e, xi))
                part(5:6) = part(5:6) + wt*res([2, 4])
                wt = wt*2.0_dp*pi*s
            end if
            part(1:2) = part(1:2) + wt*sig
            part(3:4) = part(3:4) + wt*sig*s
        end do
    end function element_integrals

    !> Integrals of the loads over [x0, x]: (I0[qz], I1[qz], I0[qx], sum of moments C). A
    !! concentrated load at x counts on the right side (side = +1) only.
    pure function load_integrals(m, x, side, tol) result(ld)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: x, tol
        integer, intent(in) :: side
        real(dp) :: ld(4)
        real(dp) :: lo, hi, a0, a1
        integer :: i
        ld = 0.0_dp
        loads: do i = 1, size(m%loads)
            associate (l => m%loads(i))
                if (l%kind == LOAD_PATCH) then
                    lo = l%x1
                    hi = min(x, l%x2)
                    if (hi <= lo) cycle loads
                    call patch_fractions(m%structure%kind == MODEL_BEAM, l%x1, l%x2, lo, hi, x, &
                        a0, a1)
                    ld(1:3) = ld(1:3) + [l%fz*a0, l%fz*a1, l%fx*a0]
                else if (l%x1 < x - tol .or. (abs(l%x1 - x) <= tol .and. side > 0)) then
                    if (l%kind == LOAD_MOMENT) then
                        ld(4) = ld(4) + l%fz
                    else
                        ld(1:3) = ld(1:3) + [l%fz, l%fz*(x - l%x1), l%fx]
                    end if
                end if
            end associate
        end do loads
    end function load_integrals

    !> Share of a uniform patch over [x1, x2] that lies in [x1, hi] (a0) and its first moment
    !! about x (a1), with weight 1 (beam) or 2 pi s (plate; the patch is then an annulus).
    pure subroutine patch_fractions(beam, x1, x2, lo, hi, x, a0, a1)
        logical, intent(in) :: beam
        real(dp), intent(in) :: x1, x2, lo, hi, x
        real(dp), intent(out) :: a0, a1
        if (beam) then
            a0 = (hi - lo)/(x2 - x1)
            a1 = (x*(hi - lo) - 0.5_dp*(hi**2 - lo**2))/(x2 - x1)
        else
            a0 = (hi**2 - lo**2)/(x2**2 - x1**2)
            a1 = (x*(hi**2 - lo**2) - 2.0_dp*(hi**3 - lo**3)/3.0_dp)/(x2**2 - x1**2)
        end if
    end subroutine patch_fractions

    !> Flags and the pointwise checks: tension beyond O(eta), interpenetration where lifted off,
    !! complementarity and the pointwise error of the weak compatibility.
    pure subroutine pointwise_checks(m, gap_pw, tab)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: gap_pw(:)
        type(station_table_t), intent(inout) :: tab
        real(dp) :: w_scale, mean_pressure, sigma_scale
        logical :: lifted(tab%n)
        w_scale = max(maxval(abs(tab%val(Q_W, :))), tiny(1.0_dp))
        mean_pressure = total_vertical_load(m%loads)/traction_measure(m%structure)
        ! the penalty leaves sigma_z ~ -eta_bar (nondimensional) where lifted off
        tab%tension_tol = max(1.0e3_dp*m%interface%eta_bar, 1.0e-12_dp)*mean_pressure
        lifted = tab%state == STATE_LIFTOFF
        tab%flag = 0
        where (tab%val(Q_SZ, :) < -tab%tension_tol) tab%flag = tab%flag + FLAG_TENSION
        where (lifted .and. gap_pw < -1.0e-3_dp*w_scale) tab%flag = tab%flag + FLAG_OVERLAP
        tab%most_tensile = minval(tab%val(Q_SZ, :))
        sigma_scale = 1.0_dp/mean_pressure       ! Sigma = sigma / mean pressure (SPEC §6)
        tab%complementarity = 0.0_dp
        if (any(lifted)) tab%complementarity = maxval(abs(tab%val(Q_SZ, :)*gap_pw), &
                                                      mask=lifted)*sigma_scale/w_scale
        tab%compatibility = 0.0_dp
        if (any(.not. lifted)) tab%compatibility = maxval(abs(gap_pw), mask=.not. lifted)/w_scale
    end subroutine pointwise_checks

    !> Largest t >= 0 of a station in contact (stick or slip); -1 if none.
    pure real(dp) function contact_extent(tab, length) result(t_max)
        type(station_table_t), intent(in) :: tab   !! the station table
        real(dp), intent(in) :: length       !! l (beam) or a (plate)
        integer :: i
        t_max = -1.0_dp
        do i = 1, tab%n
            if (tab%state(i) /= STATE_LIFTOFF .and. tab%val(Q_X, i) >= 0.0_dp) &
                t_max = max(t_max, tab%val(Q_X, i)/length)
        end do
    end function contact_extent
end module station_results
