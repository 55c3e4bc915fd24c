!> Adaptive meshing to a tolerance (ADAPT card; README, ADAPT). The case is solved on the
!! MESH card's mesh, then in cycles:
!!
!!  1. the error of every key result (error_estimate's keys) is estimated from the same case
!!     on the mesh coarsened twice by removing every other node (mesh_refinement: the ends,
!!     the load positions and the nodes on the located boundaries are kept), with the
!!     observed order; the largest estimate relative to its scale (relative_errors) is the
!!     cycle's estimate. At or below tol the case is done. The two coarse solves are skipped
!!     while the last estimate cannot be near tol yet (estimate_due); the final mesh always
!!     gets its estimate.
!!  2. The contact (lift-off) and stick/slip boundaries are located between the Gauss points
!!     where the state changes: the zero of the pressure (or of the friction reserve
!!     tau0 - |sigma_x|) extrapolated from the side where it is positive, with the square-root
!!     law of a smooth contact edge (q^2 linear in x).
!!  3. Elements are marked where the solution moved most between the coarse (or, without
!!     the estimate, the previous cycle's) and the fine mesh (eta_e = h_e/L max of
!!     |dW|/W_s, |dSigma_z|/p_s, |dM|/M_s at its nodes; marked when eta_e >= theta max eta,
!!     and at least the min_fraction largest), where a key result that has not reached tol is
!!     measured (its position and the elements next to it), and next to the features where
!!     the solution is not smooth (boundaries, loads, the singular ends in contact) when
!!     their eta is not negligible.
!!  4. The node nearest each located boundary is moved onto it (snap), the marked elements
!!     are bisected and neighbours kept within a size ratio of 2 (a geometric grading
!!     towards singular ends and boundaries).
!!
!! It stops at the tolerance, or when the next mesh would exceed max_elements, or would have
!! to stay below it with fewer than a tenth more elements than the last (the report
!! then says the tolerance was not reached, with the estimate: a warning, status 0, since the
!! result and its error estimate are valid), or when a refined solve fails: the result is
!! then that of the last mesh solved, and the report says so. Refining never turns a solved
!! case into a failure.
module adaptive_solve
    use kinds, only: dp
    use errors, only: error_t
    use model, only: load_t, mesh_request_t, structure_t, model_t, MODEL_BEAM, total_vertical_load
    use mesh, only: mesh_t
    use mesh_refinement, only: bisected, balance_marks, snap_node, coarsened, pinned_nodes, &
                               nearest_node
    use applied_loads, only: load_positions
    use discretization, only: discretization_t, discretise_mesh, loads_on_nodes
    use contact_solver, only: solution_t, solve_contact, STATE_LIFTOFF, STATE_STICK, &
                              coarse_solution_t
    use station_results, only: station_table_t
    use station_columns, only: Q_X, Q_W, Q_SZ, Q_M
    use design_summary, only: summary_t
    use summary_table, only: entry_t
    use solved_case, only: case_t, finish_case
    use flexibility_cache, only: flexibility_cache_t
    use error_estimate, only: coarse_case, attach_estimates, is_estimated, min_estimate_elements
    implicit none
    private

    !> What the adaptation did, for the report, the JSON and the console.
    type, public :: adaptation_t
        logical :: adapted = .false.            !! the case was solved with ADAPT
        real(dp) :: tol = 0.0_dp                !! the deck's tolerance
        integer :: max_ne = 0                   !! the deck's max_elements
        integer :: cycles = 0                   !! meshes solved (the first is the MESH card's)
        integer :: ne = 0                       !! elements of the final mesh
        real(dp) :: estimate = -1.0_dp          !! largest relative estimate (-1: none)
        logical :: reached = .false.            !! estimate <= tol
        integer, allocatable :: history_ne(:)   !! per cycle: elements ...
        real(dp), allocatable :: history_estimate(:)  !! ... and estimate (-1: none)
        character(len=:), allocatable :: note   !! why it stopped short, or ''
        character(len=:), allocatable :: worst  !! the key with the largest relative estimate
        type(entry_t), allocatable :: entries(:)  !! final key results with their estimates
    end type adaptation_t

    !> One assessed solution: its key results, estimates, boundaries and indicators.
    type :: assessment_t
        type(entry_t), allocatable :: e(:)      !! key results with estimates
        real(dp), allocatable :: rel(:)         !! relative estimate per entry (-1: none)
        real(dp) :: estimate = -1.0_dp          !! largest relative estimate (huge: undefined)
        real(dp), allocatable :: boundary(:)    !! located contact and stick/slip boundaries
        logical, allocatable :: liftoff(:)      !! per boundary: a contact (lift-off) one
        real(dp), allocatable :: eta(:)         !! (ne) element indicators
        real(dp), allocatable :: targets(:)     !! positions of key results not yet at tol
        logical, allocatable :: rough(:)        !! (ne) next to a feature
    end type assessment_t

    integer, parameter :: max_cycles = 25
    integer, parameter :: min_coarse = 4        !! elements of the coarsest estimate mesh
    real(dp), parameter :: theta = 0.3_dp       !! marked: eta_e >= theta max eta
    !> smallest element, relative to l or a: grading towards a singular end stops there (the
    !! round-off of the solve grows like 1/h_e, doc/CHOICES.md "Accuracy guard"; the rim
    !! element's share of the error of W(0) is already O(h_min))
    real(dp), parameter :: h_min = 1.0e-4_dp
    real(dp), parameter :: theta_feature = 0.05_dp  !! features: eta_e >= this max eta
    !> a cycle skips the estimate while the last one, reduced like ne^-2, is above this
    !! times tol (estimate_due)
    real(dp), parameter :: skip_factor = 3.0_dp
    !> at least this fraction of the elements (the largest indicators) is cut in each
    !! cycle, so that the mesh grows geometrically and the cycles stay few
    real(dp), parameter :: min_fraction = 0.4_dp
    !> a cycle whose marks max_elements cuts to fewer than this fraction of the elements is
    !! not made (the adaptation stops: max_elements reached)
    real(dp), parameter :: min_growth = 0.1_dp

    public :: solve_adaptive, relative_errors

contains

    !> Solve the case by adaptive refinement of d (in: the MESH card's discretisation; out:
    !! the final one) and give its solution. err only if the first mesh cannot be solved.
    subroutine solve_adaptive(m, d, sol, info, err, cache)
        type(model_t), intent(in) :: m                               !! the model
        !> in: the MESH card's discretisation; out: the final one
        type(discretization_t), intent(inout) :: d
        type(solution_t), intent(out) :: sol                         !! the solution
        !> the cycles, final mesh and estimate (for the report)
        type(adaptation_t), intent(out) :: info
        type(error_t), allocatable, intent(out) :: err               !! allocated on failure
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(discretization_t) :: d_try
        type(solution_t) :: sol_try
        type(error_t), allocatable :: err_try
        type(assessment_t) :: a, a_prev
        type(mesh_t) :: next
        type(station_table_t) :: prev_nodes
        character(len=200) :: text
        integer :: k, ne_estimated
        real(dp) :: last_estimate
        logical :: short
        call start_record(m%mesh, info)
        d_try = d
        ne_estimated = 0
        last_estimate = huge(1.0_dp)
        cycles: do k = 1, max_cycles
            if (k == 1) then
                call solve_contact(m, d_try, sol_try, err_try, cache=cache)
            else   ! the Newton start predicted from the last mesh's solution
                call solve_contact(m, d_try, sol_try, err_try, cache=cache, &
                                   start=coarse_solution_t(x=d%msh%x, z=sol%z))
            end if
            if (allocated(err_try) .and. k == 1) then
                call move_alloc(err_try, err)
                return
            else if (allocated(err_try)) then
                write (text, '(a,i0,a,i0,a)') 'the solve on the refined mesh of N_e = ', &
                    d_try%msh%ne, ' failed; the result is that of the last mesh solved (N_e = ', &
                    d%msh%ne, '): '
                info%note = trim(text)//err_try%message
                exit cycles
            end if
            d = d_try
            sol = sol_try
            if (estimate_due(m%mesh, d%msh%ne, ne_estimated, last_estimate)) then
                call assess(m, d, sol, a, prev_nodes, cache=cache)
                ne_estimated = d%msh%ne
                last_estimate = a%estimate
            else
                a_prev = a
                call assess(m, d, sol, a, prev_nodes, a_prev, cache)
            end if
            call record_cycle(info, d%msh%ne, a)
            if (info%reached) exit cycles
            call next_mesh(m, d, a, next, short)
            if (same_mesh(next, d%msh)) then
                if (short) then
                    info%note = 'max_elements reached (the next refinement would exceed it)'
                else
                    info%note = 'no further refinement possible'
                end if
                exit cycles
            end if
            call discretise_mesh(m, next, d_try)
        end do cycles
        if (k > max_cycles) info%note = 'the largest number of cycles was reached'
        ! the result's mesh must carry an estimate: the last cycle may have skipped it
        if (ne_estimated /= d%msh%ne) then
            call assess(m, d, sol, a, prev_nodes, cache=cache)
            call record_final(info, a)
        end if
    end subroutine solve_adaptive

    !> Whether this cycle's mesh (ne elements) gets the estimate's two coarse solves: the
    !! first mesh, a mesh at least twice the last estimated one (ne_last), or one on which
    !! the last estimate (est_last), reduced as if the error fell like ne^-2 (faster than
    !! any key result falls here), could be within tol. The other cycles take their
    !! indicators from the difference to the previous cycle's solution and cost one solve.
    pure logical function estimate_due(mesh, ne, ne_last, est_last)
        type(mesh_request_t), intent(in) :: mesh   !! the mesh part of the model
        integer, intent(in) :: ne, ne_last
        real(dp), intent(in) :: est_last
        real(dp) :: predicted
        estimate_due = .true.
        if (ne_last <= 0 .or. ne >= 2*ne_last .or. est_last >= huge(1.0_dp)) return
        predicted = est_last*(real(ne_last, dp)/real(ne, dp))**2
        estimate_due = predicted <= skip_factor*mesh%adapt_tol
    end function estimate_due

    pure logical function same_mesh(a, b)
        type(mesh_t), intent(in) :: a, b
        same_mesh = a%ne == b%ne
        if (same_mesh) same_mesh = all(a%x == b%x)
    end function same_mesh

    subroutine start_record(mesh, info)
        type(mesh_request_t), intent(in) :: mesh   !! the mesh part of the model
        type(adaptation_t), intent(out) :: info
        info%adapted = .true.
        info%tol = mesh%adapt_tol
        info%max_ne = mesh%adapt_max_ne
        info%note = ''
        info%worst = ''
        allocate (info%history_ne(0), info%history_estimate(0), info%entries(0))
    end subroutine start_record

    !> The cycle's mesh size and estimate; the final values are those of the last cycle.
    subroutine record_cycle(info, ne, a)
        type(adaptation_t), intent(inout) :: info
        integer, intent(in) :: ne
        type(assessment_t), intent(in) :: a
        integer :: i
        info%cycles = info%cycles + 1
        info%ne = ne
        info%estimate = a%estimate
        if (a%estimate >= huge(1.0_dp)) info%estimate = -1.0_dp
        info%reached = info%estimate >= 0.0_dp .and. info%estimate <= info%tol
        info%history_ne = [info%history_ne, ne]
        info%history_estimate = [info%history_estimate, info%estimate]
        info%entries = a%e
        info%worst = ''
        if (info%estimate > 0.0_dp) then
            i = maxloc(a%rel, dim=1)
            info%worst = trim(a%e(i)%key)
        end if
    end subroutine record_cycle

    !> The estimate of the final mesh when its cycle skipped it (the history keeps -1 for
    !! that cycle).
    subroutine record_final(info, a)
        type(adaptation_t), intent(inout) :: info
        type(assessment_t), intent(in) :: a
        integer :: n
        n = size(info%history_ne)
        call record_cycle(info, info%ne, a)
        info%cycles = info%cycles - 1
        info%history_ne = info%history_ne(:n)
        info%history_estimate = [info%history_estimate(:n - 1), info%estimate]
        if (.not. info%reached .and. len(info%note) == 0) &
            info%note = 'no further refinement possible'
    end subroutine record_final

    !> Key results, their estimates on the coarsened meshes, the located boundaries and the
    !! element indicators of one solution; without the coarse solves when prev is given
    !! (the indicators then compare with prev_nodes, the previous cycle's solution, and the
    !! keys above tol are prev's). prev_nodes: out, this solution at its nodes.
    subroutine assess(m, d, sol, a, prev_nodes, prev, cache)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        type(assessment_t), intent(inout) :: a
        type(station_table_t), intent(inout) :: prev_nodes
        type(assessment_t), intent(in), optional :: prev   !! (not a itself)
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(case_t) :: c
        type(station_table_t) :: tab2
        type(entry_t), allocatable :: e2(:), e4(:)
        type(error_t), allocatable :: err
        logical :: ok
        ! the indicators compare values at the nodes, as the design values are read there
        call finish_case(m, d, sol, c, err)
        if (allocated(err)) error stop 'adaptive_solve: a solved case could not be tabulated'
        associate (s => c%summary, tab_nodes => c%design)
        a%e = c%entries
        call locate_boundaries(sol, a%boundary, a%liftoff)
        if (allocated(a%eta)) deallocate (a%eta)
        allocate (a%eta(d%msh%ne), source=1.0_dp)   ! no estimate: refine everywhere
        if (present(prev)) then
            a%eta = indicators(m%structure, d, s, tab_nodes, prev_nodes)
            a%rel = prev%rel                        ! the same keys, in the same order
            a%estimate = huge(1.0_dp)
        else
            call coarse_estimates(m, d, sol, a, e2, e4, tab2, ok, cache)
            if (ok) a%eta = indicators(m%structure, d, s, tab_nodes, tab2)
            a%rel = relative_errors(a%e)
            a%estimate = huge(1.0_dp)
            if (ok .and. all(a%rel >= 0.0_dp .or. .not. estimated_and_defined(a%e))) &
                a%estimate = maxval(a%rel)
        end if
        a%targets = target_positions(m%mesh, d, s, a)
        a%rough = feature_elements(m, d, tab_nodes, a%boundary)
        prev_nodes = tab_nodes
        end associate
    end subroutine assess

    !> Estimates attached to a%e from the coarsened meshes (ok false if they could not be
    !! made or solved, or the mesh has fewer than min_estimate_elements); tab2: the first
    !! coarse solution at its nodes. The coarse solves start from sol (solve_contact, start)
    !! instead of their own nested coarser meshes.
    subroutine coarse_estimates(m, d, sol, a, e2, e4, tab2, ok, cache)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol          !! the solution on d
        type(assessment_t), intent(inout) :: a
        type(entry_t), allocatable, intent(out) :: e2(:), e4(:)
        type(station_table_t), intent(out) :: tab2
        logical, intent(out) :: ok
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(mesh_t) :: c2, c4
        type(discretization_t) :: d2, d4
        type(case_t) :: c2_case, c4_case
        logical, allocatable :: p2(:), p4(:)
        real(dp) :: ratio
        ok = .false.
        ! no estimate on fewer elements than a MESH case gets one on (error_estimate)
        if (d%msh%ne < min_estimate_elements) return
        call coarsened(d%msh, pins(m%loads, d%msh, a%boundary), c2, p2)
        call coarsened(c2, p2, c4, p4)
        if (c4%ne < min_coarse .or. c2%ne >= d%msh%ne .or. c4%ne >= c2%ne) return
        call discretise_mesh(m, c2, d2)
        call discretise_mesh(m, c4, d4)
        call coarse_case(m, d2, c2_case, ok, cache=cache, &
                         start=coarse_solution_t(x=d%msh%x, z=sol%z))
        if (ok) call coarse_case(m, d4, c4_case, ok, cache=cache, &
                                 start=coarse_solution_t(x=d%msh%x, z=sol%z))
        if (.not. ok) return
        e2 = c2_case%entries
        e4 = c4_case%entries
        tab2 = c2_case%design
        ratio = sqrt(real(d%msh%ne, dp)/real(c4%ne, dp))
        call attach_estimates(m, a%e, e2, e4, ratio, &
                              extent_floors(m%structure, a%e, pack(a%boundary, a%liftoff)), &
                              loads_on_nodes(m%loads, d%msh) .and. &
                              loads_on_nodes(m%loads, c2) .and. loads_on_nodes(m%loads, c4))
    end subroutine coarse_estimates

    !> Pinned nodes: the ends, the load positions and the node nearest each boundary.
    pure function pins(loads, msh, boundary) result(pinned)
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        type(mesh_t), intent(in) :: msh
        real(dp), intent(in) :: boundary(:)
        logical :: pinned(0:msh%ne)
        integer :: k
        pinned = pinned_nodes(msh, load_positions(loads))
        do k = 1, size(boundary)
            pinned(nearest_node(msh, boundary(k))) = .true.
        end do
    end function pins

    !> Per entry, the least estimate: a contact extent is a node, and its error is at least
    !! the distance (as t) between that node and the nearest located lift-off boundary (0
    !! when there is none: full contact); 0 for the other keys.
    pure function extent_floors(structure, e, boundary) result(floor)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(entry_t), intent(in) :: e(:)
        real(dp), intent(in) :: boundary(:)
        real(dp) :: floor(size(e))
        real(dp) :: t
        integer :: i
        floor = 0.0_dp
        if (size(boundary) == 0) return
        do i = 1, size(e)
            if (.not. is_extent(e(i)%key) .or. .not. e(i)%defined) cycle
            t = e(i)%value*structure%length
            floor(i) = minval(abs(boundary - t))/structure%length
        end do
    end function extent_floors

    !> Whether a key of summary_table is a contact extent t.
    pure logical function is_extent(key)
        character(len=*), intent(in) :: key
        is_extent = key == 'contact_extent_t' .or. key == 'contact_extent_left_t' .or. &
                    key == 'contact_extent_right_t'
    end function is_extent

    !> Each estimated result's estimate relative to its scale (-1 where there is none):
    !! settlements to the largest |settlement|, moments to the largest |moment|, pressures
    !! at d from an edge to the mean contact pressure, the pressure at the centre to the
    !! larger of itself and the mean contact pressure, the largest shear force to itself, the
    !! contact extent t as it is (a fraction of l or a).
    pure function relative_errors(e) result(rel)
        type(entry_t), intent(in) :: e(:)   !! the key results with their estimates
        real(dp) :: rel(size(e))
        real(dp) :: scale
        integer :: i
        rel = -1.0_dp
        do i = 1, size(e)
            if (.not. (e(i)%has_error .and. e(i)%defined)) cycle
            select case (trim(e(i)%key))
            case ('settlement_max', 'differential_settlement')
                scale = max(abs(value_of(e, 'settlement_max')), abs(value_of(e, 'settlement_min')))
            case ('moment_sagging', 'moment_hogging')
                scale = max(abs(value_of(e, 'moment_sagging')), abs(value_of(e, 'moment_hogging')))
            case ('contact_extent_t', 'contact_extent_left_t', 'contact_extent_right_t')
                scale = 1.0_dp
            case ('liftoff_left', 'liftoff_right')
                cycle     ! its contact extent's estimate, in t, stands for it
            case ('pressure_centre')
                scale = max(abs(e(i)%value), abs(value_of(e, 'pressure_mean')))
            case ('shear_force_max')
                scale = abs(e(i)%value)
            case default
                scale = abs(value_of(e, 'pressure_mean'))
            end select
            rel(i) = e(i)%error/max(scale, tiny(1.0_dp))
        end do
    end function relative_errors

    !> Per entry: an estimated key with a defined value that is not singular (it must get an
    !! estimate; a singular one never does: summary_table::mark_singular).
    pure elemental logical function estimated_and_defined(e)
        type(entry_t), intent(in) :: e
        estimated_and_defined = e%defined .and. is_estimated(e%key) .and. .not. e%singular
    end function estimated_and_defined

    pure real(dp) function value_of(e, key)
        type(entry_t), intent(in) :: e(:)
        character(len=*), intent(in) :: key
        integer :: i
        value_of = 0.0_dp
        do i = 1, size(e)
            if (trim(e(i)%key) == key) value_of = e(i)%value
        end do
    end function value_of

    !> Contact and stick/slip boundaries between neighbouring Gauss points whose states
    !! differ (see the module header for the position within the gap between them).
    pure subroutine locate_boundaries(sol, x, liftoff)
        type(solution_t), intent(in) :: sol
        real(dp), allocatable, intent(out) :: x(:)
        logical, allocatable, intent(out) :: liftoff(:)   !! a contact (not stick/slip) boundary
        real(dp), allocatable :: q(:)
        logical, allocatable :: contact(:), stick(:)
        integer :: p
        allocate (x(0), liftoff(0))
        contact = sol%state /= STATE_LIFTOFF
        stick = sol%state == STATE_STICK
        q = max(sol%sigma(2, :), 0.0_dp)
        points: do p = 1, sol%pts%n - 1
            if (contact(p) .neqv. contact(p + 1)) then
                x = [x, zero_between(sol%pts%x, q, contact, p)]
                liftoff = [liftoff, .true.]
            else if (contact(p) .and. (stick(p) .neqv. stick(p + 1))) then
                x = [x, zero_between(sol%pts%x, max(sol%tau0 - abs(sol%sigma(1, :)), 0.0_dp), &
                                     stick, p)]
                liftoff = [liftoff, .false.]
            end if
        end do points
    end subroutine locate_boundaries

    !> Zero of q (positive where inside) between points p and p+1, extrapolated from the two
    !! points nearest to the boundary on the inside with q^2 linear in x (a square-root edge),
    !! kept inside [x(p), x(p+1)]; the midpoint when the two do not decrease towards it.
    pure real(dp) function zero_between(x, q, inside, p) result(xb)
        real(dp), intent(in) :: x(:), q(:)
        logical, intent(in) :: inside(:)
        integer, intent(in) :: p
        integer :: near, far
        real(dp) :: q1, q2
        xb = 0.5_dp*(x(p) + x(p + 1))
        if (inside(p)) then
            near = p
            far = p - 1
        else
            near = p + 1
            far = p + 2
        end if
        if (far < 1 .or. far > size(x)) return
        if (.not. inside(far)) return
        q1 = q(far)**2
        q2 = q(near)**2
        if (.not. (q1 > q2 .and. q2 >= 0.0_dp)) return
        xb = x(near) + (x(near) - x(far))*q2/(q1 - q2)
        xb = max(min(x(p), x(p + 1)), min(max(x(p), x(p + 1)), xb))
    end function zero_between

    !> eta_e: (h_e/L) times the largest scaled difference, at the element's nodes, between
    !! the solution and the first coarse solution (interpolated): W, Sigma_z and M.
    function indicators(structure, d, s, tab, tab2) result(eta)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(summary_t), intent(in) :: s
        type(station_table_t), intent(in) :: tab, tab2     !! fine and coarse, at nodes
        real(dp) :: eta(d%msh%ne)
        real(dp) :: node_diff(0:d%msh%ne), scales(3), diff
        integer, parameter :: q(3) = [Q_W, Q_SZ, Q_M]
        integer :: j, k, i
        scales(1) = maxval(abs(tab%val(Q_W, :)))
        scales(2) = s%mean_pressure*merge(structure%b, 1.0_dp, structure%kind == MODEL_BEAM)
        scales(3) = maxval(abs(tab%val(Q_M, :)))
        scales = max(scales, tiny(1.0_dp))
        node_diff = 0.0_dp
        stations: do j = 1, tab%n
            i = nearest_node(d%msh, tab%val(Q_X, j))
            do k = 1, 3
                diff = abs(tab%val(q(k), j) - interpolated(tab2, q(k), tab%val(Q_X, j)))/scales(k)
                node_diff(i) = max(node_diff(i), diff)
            end do
        end do stations
        eta = (d%msh%x(1:) - d%msh%x(:d%msh%ne - 1))/structure%length* &
              max(node_diff(:d%msh%ne - 1), node_diff(1:))
    end function indicators

    !> Quantity iq of a station table, linear between stations, at x.
    pure real(dp) function interpolated(tab, iq, x) result(v)
        type(station_table_t), intent(in) :: tab
        integer, intent(in) :: iq
        real(dp), intent(in) :: x
        integer :: j
        real(dp) :: x1, x2
        v = tab%val(iq, tab%n)
        if (x <= tab%val(Q_X, 1)) v = tab%val(iq, 1)
        if (x <= tab%val(Q_X, 1)) return
        do j = 1, tab%n - 1
            x1 = tab%val(Q_X, j)
            x2 = tab%val(Q_X, j + 1)
            if (x2 <= x1 .or. x < x1 .or. x > x2) cycle
            v = tab%val(iq, j) + (tab%val(iq, j + 1) - tab%val(iq, j))*(x - x1)/(x2 - x1)
            return
        end do
    end function interpolated

    !> Where the key results whose estimate is above tol are measured: the largest
    !! settlement and moments, the pressure at d from an edge and at the centre, the contact
    !! boundaries.
    pure function target_positions(mesh, d, s, a) result(x)
        type(mesh_request_t), intent(in) :: mesh   !! the mesh part of the model
        type(discretization_t), intent(in) :: d
        type(summary_t), intent(in) :: s
        type(assessment_t), intent(in) :: a
        real(dp), allocatable :: x(:)
        integer :: i
        allocate (x(0))
        do i = 1, size(a%e)
            if (a%rel(i) >= 0.0_dp .and. a%rel(i) <= mesh%adapt_tol) cycle
            if (.not. (estimated_and_defined(a%e(i)))) cycle
            select case (trim(a%e(i)%key))
            case ('settlement_max')
                x = [x, s%w_max%x]
            case ('differential_settlement')
                x = [x, s%w_max%x, s%w_min%x]
            case ('moment_sagging')
                x = [x, s%m_sag%x]
            case ('moment_hogging')
                x = [x, s%m_hog%x]
            case ('pressure_near_left_end')
                x = [x, d%msh%x(0) + s%edge_distance]
            case ('pressure_near_right_end', 'pressure_near_rim')
                x = [x, d%msh%x(d%msh%ne) - s%edge_distance]
            case ('contact_extent_t', 'contact_extent_left_t', 'contact_extent_right_t')
                x = [x, pack(a%boundary, a%liftoff)]
            case ('pressure_centre')
                x = [x, 0.0_dp]
            end select
        end do
    end function target_positions

    !> Elements next to a located boundary, a load position, or an end in contact (where
    !! the contact pressure is singular).
    pure function feature_elements(m, d, tab, boundary) result(rough)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: boundary(:)
        logical :: rough(d%msh%ne)
        real(dp), allocatable :: x(:)
        integer :: k, i, ne
        ne = d%msh%ne
        x = [load_positions(m%loads), boundary]
        rough = .false.
        do k = 1, size(x)
            i = nearest_node(d%msh, x(k))
            if (i >= 1) rough(i) = .true.
            if (i < ne) rough(i + 1) = .true.
        end do
        if (tab%state(tab%n) /= STATE_LIFTOFF) rough(ne) = .true.
        if (m%structure%kind == MODEL_BEAM .and. tab%state(1) /= STATE_LIFTOFF) rough(1) = .true.
    end function feature_elements

    !> The next mesh: nodes snapped onto the located boundaries, then the marked elements
    !! bisected (within the max_elements budget; the unchanged mesh when none is left).
    subroutine next_mesh(m, d, a, next, short)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(assessment_t), intent(in) :: a
        type(mesh_t), intent(out) :: next
        logical, intent(out) :: short        !! max_elements left no room for the marks
        logical, allocatable :: marked(:), pinned(:)
        integer :: k, node, budget, wanted
        next = d%msh
        budget = m%mesh%adapt_max_ne - d%msh%ne
        short = .true.
        if (budget <= 0) return
        marked = element_marks(d, a)
        short = .not. any(marked)
        wanted = count(marked)
        call fit_budget(d%msh, a%eta, budget, marked)
        ! a cycle cut short by max_elements to a few new elements costs a whole solve for
        ! little: the adaptation stops instead
        if (count(marked) < wanted .and. count(marked) < ceiling(min_growth*d%msh%ne)) &
            marked = .false.
        short = .not. (short .or. any(marked))
        if (.not. any(marked)) return
        allocate (pinned(0:next%ne))     ! node numbers from 0, as the mesh's
        pinned(:) = pinned_nodes(next, load_positions(m%loads))
        do k = 1, size(a%boundary)
            call snap_node(next, a%boundary(k), pinned, node)
            if (node >= 0) pinned(node) = .true.
        end do
        next = bisected(next, marked)
    end subroutine next_mesh

    !> Marks: large indicators, the targets of results above tol, the features; never an
    !! element shorter than 2 h_min (the indicators compared among the others).
    pure function element_marks(d, a) result(marked)
        type(discretization_t), intent(in) :: d
        type(assessment_t), intent(in) :: a
        logical :: marked(d%msh%ne)
        logical :: allowed(d%msh%ne)
        real(dp) :: eta_max
        integer :: k, e
        allowed = (d%msh%x(1:) - d%msh%x(:d%msh%ne - 1)) >= &
                  2.0_dp*h_min*(d%msh%x(d%msh%ne) - d%msh%x(0))
        eta_max = maxval(a%eta, mask=allowed)
        marked = a%eta >= min(theta*eta_max, &
                              kth_largest(pack(a%eta, allowed), ceiling(min_fraction*d%msh%ne)))
        marked = marked .or. (a%rough .and. a%eta >= theta_feature*eta_max)
        do k = 1, size(a%targets)
            e = min(d%msh%ne, max(1, count(d%msh%x(1:d%msh%ne - 1) < a%targets(k)) + 1))
            marked(max(1, e - 1):min(d%msh%ne, e + 1)) = .true.
        end do
        marked = marked .and. allowed
    end function element_marks

    !> Keep the marks (after the size-ratio balance) within the budget of new elements: the
    !! largest indicators first; no marks when even those do not fit.
    pure subroutine fit_budget(msh, eta, budget, marked)
        type(mesh_t), intent(in) :: msh
        real(dp), intent(in) :: eta(:)
        integer, intent(in) :: budget
        logical, intent(inout) :: marked(:)
        logical :: trial(size(marked))
        integer :: n_keep, e
        real(dp) :: cut
        trial = marked
        call balance_marks(msh, trial)
        n_keep = count(marked)
        shrink: do while (count(trial) > budget .and. n_keep > 0)
            n_keep = n_keep/2
            trial = .false.
            if (n_keep > 0) then
                cut = kth_largest(pack(eta, marked), n_keep)
                do e = 1, size(marked)
                    trial(e) = marked(e) .and. eta(e) >= cut
                end do
                call balance_marks(msh, trial)
            end if
        end do shrink
        marked = trial
        if (count(marked) > budget) marked = .false.
    end subroutine fit_budget

    pure real(dp) function kth_largest(v, k) result(cut)
        real(dp), intent(in) :: v(:)
        integer, intent(in) :: k
        real(dp) :: w(size(v))
        integer :: i
        w = v
        cut = -huge(1.0_dp)
        do i = 1, min(k, size(w))
            cut = maxval(w)
            w(maxloc(w, dim=1)) = -huge(1.0_dp)
        end do
    end function kth_largest

end module adaptive_solve
