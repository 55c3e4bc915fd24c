!> An estimate of the discretisation error of a case's key results, from the same case solved
!! on two coarser meshes of the same family (N_e/2 and N_e/4 elements, same grading and
!! interpolation; nested for UNIFORM meshes). With Q_1, Q_2, Q_4 the results on N_e, N_e/2 and
!! N_e/4 elements, the observed order is p = log2(|Q_4 - Q_2| / |Q_2 - Q_1|) and the estimate
!! of the error of Q_1 is Roache's grid convergence index
!!     E = Fs |Q_2 - Q_1| / (2^p - 1),
!! with Fs = 1.25 when the three values converge monotonically with 0.5 <= p <= 4 (the
!! asymptotic range), else E = 3 max(|Q_2 - Q_1|, |Q_4 - Q_2|/2) (first order assumed; a
!! conservative band for erratic convergence: a load edge or contact boundary that each mesh
!! cuts at a different place inside an element). The contact
!! extent moves in steps of the stations, so its estimate is at least half the largest
!! element next to the contact boundary. The extra solves cost about 1/8 + 1/64 of the case's
!! dense solves; a coarse solve that fails leaves the estimate undefined, never the case.
module error_estimate
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t, LOAD_PATCH
    use shape_functions, only: INTERP_P1
    use discretization, only: discretization_t, new_discretization, loads_on_nodes
    use contact_solver, only: solution_t, solve_contact, coarse_solution_t
    use summary_table, only: entry_t
    use solved_case, only: case_t, solve_on, finish_case
    use flexibility_cache, only: flexibility_cache_t
    implicit none
    private

    !> The keys of summary_table that get an estimate.
    character(len=*), parameter :: estimated_keys(10) = [character(len=32) :: 'settlement_max', &
        'differential_settlement', 'contact_extent_t', 'moment_sagging', 'moment_hogging', &
        'pressure_near_left_end', 'pressure_near_right_end', 'pressure_near_rim', &
        'pressure_centre', 'shear_force_max']
    integer, parameter :: min_coarse_elements = 4

    public :: estimate_errors, coarse_case, attach_estimates, is_estimated, &
              formal_order

contains

    !> Fill e(:)%error (and %has_error, %order) for the estimated keys of a solved case.
    !! known: the solutions on the nested coarser meshes of the Newton start
    !! (solution_t%coarse); one whose mesh is that of N_e/2 or N_e/4 elements is not solved
    !! again. edge_in_contact: an end of the base is in contact (summary_t), which limits a
    !! uniform mesh to first order (formal_order).
    subroutine estimate_errors(m, d, e, known, edge_in_contact, cache)
        type(model_t), intent(in) :: m            !! the model
        type(discretization_t), intent(in) :: d   !! the case's own discretisation
        type(entry_t), intent(inout) :: e(:)      !! the key results, updated
        !> the coarse solutions of the Newton start
        type(coarse_solution_t), intent(in), optional :: known(:)
        !> an end of the base is in contact (default false)
        logical, intent(in), optional :: edge_in_contact
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(coarse_solution_t), allocatable :: reuse(:)
        type(entry_t), allocatable :: e2(:), e4(:)
        real(dp) :: h_edge
        logical :: ok2, ok4, nodes2, nodes4, singular_edge
        if (m%mesh%ne/4 < min_coarse_elements) return
        allocate (reuse(0))
        if (present(known)) reuse = known
        call coarse_entries(m, m%mesh%ne/2, reuse, e2, ok2, nodes2, cache)
        if (.not. ok2) return
        call coarse_entries(m, m%mesh%ne/4, reuse, e4, ok4, nodes4, cache)
        if (.not. ok4) return
        ! the contact extent moves by whole stations: at least half the largest element (as t)
        h_edge = maxval(d%msh%x(1:) - d%msh%x(:d%msh%ne - 1))/m%structure%length
        singular_edge = .false.
        if (present(edge_in_contact)) singular_edge = edge_in_contact .and. &
                                                      trim(m%mesh%grading) == 'UNIFORM'
        call attach_estimates(m, e, e2, e4, 2.0_dp, 0.5_dp*h_edge, &
                              loads_on_nodes(m%loads, d%msh) .and. nodes2 .and. nodes4, &
                                  singular_edge)
    end subroutine estimate_errors

    !> Estimates of the estimated keys of e from the same keys on two coarser meshes of a
    !! nested family (e2 about N_e/ratio, e4 about N_e/ratio^2 elements); the contact
    !! extent's estimate is at least extent_floor (t). Each key is credited with at most the
    !! order of convergence the method has for it (formal_order): three coarse meshes are
    !! often short of the asymptotic range and show a higher order than that.
    pure subroutine attach_estimates(m, e, e2, e4, ratio, extent_floor, kinks_on_nodes, &
                                     singular_edge)
        type(model_t), intent(in) :: m             !! the model
        type(entry_t), intent(inout) :: e(:)       !! the key results, updated
        !> the keys on about N_e/ratio and N_e/ratio^2 elements
        type(entry_t), intent(in) :: e2(:), e4(:)
        real(dp), intent(in) :: ratio              !! refinement ratio between the meshes
        real(dp), intent(in) :: extent_floor       !! least estimate of the contact extent t
        logical, intent(in) :: kinks_on_nodes      !! see formal_order
        logical, intent(in), optional :: singular_edge  !! see formal_order
        logical :: edge
        integer :: i
        edge = .false.
        if (present(singular_edge)) edge = singular_edge
        do i = 1, size(e)
            if (.not. is_estimated(e(i)%key) .or. e(i)%singular) cycle
            if (.not. (e(i)%defined .and. e2(i)%defined .and. e4(i)%defined)) cycle
            call richardson(compared(e(i)), compared(e2(i)), compared(e4(i)), ratio, &
                            formal_order(m, e(i)%key, kinks_on_nodes, edge), e(i)%error, &
                            e(i)%order)
            if (trim(e(i)%key) == 'contact_extent_t') e(i)%error = max(e(i)%error, extent_floor)
            e(i)%has_error = .true.
        end do
    end subroutine attach_estimates

    !> The value an estimate compares across the meshes: the magnitude of the largest shear
    !! force, which is printed with its sign (a symmetric footing's largest |Q| may be at its
    !! left column face on one mesh and at its right one on the next, with opposite signs).
    pure real(dp) function compared(e)
        type(entry_t), intent(in) :: e
        compared = e%value
        if (trim(e%key) == 'shear_force_max') compared = abs(e%value)
    end function compared

    !> The largest order of convergence an estimate may credit to a key (Roache: p =
    !! min(observed, formal)); 4, the observed order's upper limit, where no lower one is
    !! known:
    !!  * a concentrated load (POINT, MOMENT, RING) that is not on a node of all three meshes,
    !!    any family: 1 for every key. The Mindlin structure's slope jumps there, and no
    !!    element polynomial has a kink inside the element: an S2 basis is made C0 at a node
    !!    with such a load (shape_functions), but between nodes C1 shape functions smear the
    !!    jump over the elements at the load (work_precision beam with C1 knots at the load: order
    !!    1.00 in W(0) on uniform meshes; adapted to 1e-4, three coarsened meshes showed 2.5
    !!    and an estimate 10 times low), and P1 or P2 ones cannot place it either
    !!    (input/tank_raft.dat, P1, ring at r = 7.5 m between the nodes of N_e = 40, 20, 10:
    !!    those meshes showed order 3.2 for the largest sagging M_r and an estimate of 0.099
    !!    kN m/m, the error being 0.92: N_e = 80 to 640, whose nodes hold the ring, converge
    !!    at order 1 to -21.67).
    !!  * the pressure at the centre: 1 with P1 deflection or rotation, 2 with P2 or S2 (a
    !!    pointwise traction converges one order below the slope; measured 1.0 for P1 and 2.0
    !!    for S2 on the work-precision plate, 1.0 for P1 on the frictionless punch, where the
    !!    coarse meshes of an adaptation showed 2.6 and an estimate 3.5 times low).
    !!  * every key on a UNIFORM mesh with an end of the base in contact: 1. The pressure is
    !!    singular at the edge (1/sqrt), which limits uniform meshes to first order (CHOICES,
    !!    convergence orders); their three coarsest meshes often show more. Measured, N_e = 20
    !!    to 1280 (eighth session, doc/OUTPUT.md): input/strip_footing.dat, tank_raft.dat
    !!    and default.dat converge at 0.9 to 1.2 from N_e = 160 on in every key but the
    !!    shear force (1.8 on the default raft), while N_e = 40, 20, 10 showed up to 3.2
    !!    (strip footing's sagging M: an estimate 7.5 times below its error). Graded meshes
    !!    (EDGES, LOADS) are not limited: input/plate_physical.dat (EDGES) converges at 2 to 4.
    pure real(dp) function formal_order(m, key, kinks_on_nodes, singular_edge) result(p)
        type(model_t), intent(in) :: m         !! the model
        character(len=*), intent(in) :: key    !! a key of summary_table
        logical, intent(in) :: kinks_on_nodes  !! every concentrated load on a node of the
                                               !! three meshes (discretization, loads_on_nodes)
        logical, intent(in), optional :: singular_edge  !! a uniform mesh with an end of the
                                                        !! base in contact
        logical :: p1
        p = 4.0_dp
        p1 = m%mesh%interp(2) == INTERP_P1 .or. m%mesh%interp(3) == INTERP_P1
        if (trim(key) == 'pressure_centre') p = merge(1.0_dp, 2.0_dp, p1)
        if (.not. kinks_on_nodes .and. any(m%loads%kind /= LOAD_PATCH)) p = 1.0_dp
        if (present(singular_edge)) then
            if (singular_edge) p = 1.0_dp
        end if
    end function formal_order

    !> Whether a key of summary_table gets an error estimate.
    pure logical function is_estimated(key)
        character(len=*), intent(in) :: key   !! a key of summary_table
        is_estimated = any(estimated_keys == key)
    end function is_estimated

    !> The key results of the case on ne elements (ok false when the solve fails), from a
    !! known solution on that mesh if there is one.
    subroutine coarse_entries(m, ne, known, e, ok, on_nodes, cache)
        type(model_t), intent(in) :: m
        integer, intent(in) :: ne
        type(coarse_solution_t), intent(in) :: known(:)
        type(entry_t), allocatable, intent(out) :: e(:)
        logical, intent(out) :: ok
        logical, intent(out) :: on_nodes    !! every concentrated load on a node of this mesh
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(model_t) :: mc
        type(discretization_t) :: d
        type(case_t) :: c
        type(error_t), allocatable :: err
        integer :: k
        mc = m
        mc%mesh%ne = ne
        ok = .false.
        on_nodes = .false.
        call new_discretization(mc, d, err)
        if (allocated(err)) return
        on_nodes = loads_on_nodes(m%loads, d%msh)
        do k = 1, size(known)
            if (same_nodes(known(k)%x, d%msh%x)) then
                call coarse_case(mc, d, c, ok, known(k))
                if (ok) e = c%entries
                return
            end if
        end do
        call coarse_case(mc, d, c, ok, cache=cache)
        if (ok) e = c%entries
    end subroutine coarse_entries

    !> Whether two meshes have the same nodes (to 1e-12 of the length).
    pure logical function same_nodes(x1, x2)
        real(dp), intent(in) :: x1(:), x2(:)
        same_nodes = size(x1) == size(x2)
        if (same_nodes) same_nodes = all(abs(x1 - x2) <= 1.0e-12_dp*(x2(size(x2)) - x2(1)))
    end function same_nodes

    !> The case solved on the discretisation d, or finished from a known solution on d; ok
    !! false when the solve fails.
    subroutine coarse_case(m, d, c, ok, known, cache)
        type(model_t), intent(in) :: m                 !! the model
        type(discretization_t), intent(in) :: d        !! a coarser mesh of it
        type(case_t), intent(out) :: c                 !! the case on d
        logical, intent(out) :: ok                     !! solved and tabulated
        type(coarse_solution_t), intent(in), optional :: known   !! the solution on d
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(solution_t) :: sol
        type(error_t), allocatable :: err
        if (present(known)) then
            sol%z = known%z
            sol%admissibility = known%admissibility
            sol%reaction = known%reaction
            sol%applied = known%applied
            sol%n_solves = known%n_solves
            call finish_case(m, d, sol, c, err)
        else
            call solve_on(m, d, c, err, cache=cache)
        end if
        ok = .not. allocated(err)
    end subroutine coarse_case

    !> GCI estimate of the error of q1 from q1, q2, q4 (fine, medium, coarse; refinement
    !! ratio r between them); order: the observed p, or -1 when p = 1 was assumed.
    pure subroutine richardson(q1, q2, q4, r, p_max, error, order)
        real(dp), intent(in) :: q1, q2, q4, r
        real(dp), intent(in) :: p_max              !! largest order credited (formal order)
        real(dp), intent(out) :: error, order
        real(dp) :: d12, d24, p
        d12 = q2 - q1
        d24 = q4 - q2
        order = -1.0_dp
        ! not (yet) regular: first order assumed, the larger of the two differences (a
        ! difference that happens to be small must not make the band small), Fs = 3
        error = 3.0_dp*max(abs(d12), abs(d24)/r)/(r - 1.0_dp)
        if (d12 == 0.0_dp .or. d24 == 0.0_dp) return
        if (sign(1.0_dp, d12) /= sign(1.0_dp, d24)) return
        p = log(abs(d24)/abs(d12))/log(r)
        if (p < 0.5_dp .or. p > 4.0_dp) return
        order = min(p, p_max)
        p = order
        error = 1.25_dp*abs(d12)/(r**p - 1.0_dp)
    end subroutine richardson

end module error_estimate
