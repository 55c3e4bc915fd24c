!> An estimate of the discretisation error of a case's key results (a MESH case; ADAPT uses
!! attach_estimates on its own coarsened family, adaptive_solve).
!!
!! The case (Q_1, on its mesh of N_e elements) is solved again on the mesh with every element
!! cut in two (Q_f, 2 N_e elements) and on the mesh with every other node removed (Q_c, about
!! N_e/2; the ends and the load positions kept: mesh_refinement's coarsening, the
!! mesh the Newton method starts from, so usually known). The three meshes are nested and
!! halve every element, graded ones included. With the order p observed from Q_c, Q_1, Q_f
!! (where the three converge monotonically), limited to [1, 2] and to the key's formal order
!! (formal_order), the error of Q_1 is estimated as
!!     E = max(1.25 |Q_1 - Q_f| 2^p / (2^p - 1), |Q_c - Q_1| / 4).
!! The first term is the Richardson error of Q_1 from the finer pair with Roache's factor of safety
!! 1.25; the second keeps the estimate from collapsing where the fine pair happens to agree (a
!! boundary that stays in one element). The contact extent moves by whole nodes: its estimate is at
!! least half the element beyond the last node in contact (at an end of the base, the end element).
!! The keys that are extremes of a station field then get three additions (extreme_estimates, both
!! estimates): the shortfall of an extreme lying between two stations (the shear force's too), the
!! settlement at a load inside an element, and a wider estimate for an extreme moment the meshes do
!! not resolve. Where the mesh coarsened twice shows the coarse meshes short of the asymptotic
!! range, the estimate is at least the coarse difference (pre_asymptotic). Where a concentrated load
!! lies inside the base, or the mesh has more than 128 elements, the estimate is at least half the
!! change to the meshes of N_e - 1 and N_e + 1 elements of the same grading (neighbour_floor):
!! nested meshes keep the load's place in its element (and the point d's, a peak's or a lift-off
!! boundary's), and an error tied to that place does not show in them. Where the case's mesh has at
!! most 128 elements, it is also solved on the mesh cut in two twice (4 N_e, where that fits in
!! memory), and each estimate is at least the key's change to it (twice_refined_floor): on coarse
!! meshes N_e/4 to 2 N_e can stall before the values fall further. A mesh of fewer than 16 elements
!! gets no estimate (min_estimate_elements). Measured on 64 cases, 11335 results on 20, 40 and 80
!! elements (output/bench/estimate_effectivity.md): 93.4 % within 0.5 to 5 times the true error,
!! none below 0.2; none below 0.2 on 26 mesh sizes from 12 to 400 elements, 1 of 2262 on 260
!! (estimate_effectivity_other_meshes.md); the estimates from coarser meshes only gave 0.3 to 50
!! times the error (10th to 90th percentile).
!!
!! The refined solve starts its Newton method from the case's solution (solve_contact,
!! start) and costs 2 to 4 times the case, the two neighbours about one case each, the solve
!! on 4 N_e two to eight (output/bench/estimate_cost.md). Where
!! the refined case would not fit in memory (resource_limits), the estimate falls back to the
!! coarse family alone: N_e/2 and N_e/4 (every other node removed, twice) with Roache's grid
!! convergence index, E = 1.25 |Q_2 - Q_1| / (2^p - 1), p observed and capped by
!! formal_order when the three converge monotonically with 0.5 <= p <= 4, else the wide band
!! E = 3 max(|Q_2 - Q_1|, |Q_4 - Q_2|/2). A solve that fails leaves the estimate undefined,
!! never the case.
module error_estimate
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t, LOAD_PATCH
    use shape_functions, only: INTERP_P1
    use mesh, only: mesh_t
    use mesh_refinement, only: coarsened, pinned_nodes, bisected, same_nodes
    use applied_loads, only: load_positions
    use foundation_structure, only: interface_ends
    use discretization, only: discretization_t, discretise_mesh, loads_on_nodes, card_mesh
    use contact_solver, only: solution_t, solve_contact, coarse_solution_t
    use summary_table, only: entry_t, entry_index
    use case_scales, only: scales_t, case_scale_factors
    use solved_case, only: case_t, solve_on, finish_case
    use flexibility_cache, only: flexibility_cache_t
    use resource_limits, only: check_memory, memory_available
    use station_results, only: station_table_t
    use extreme_estimates, only: add_sampling_errors, widen_unresolved_moments
    implicit none
    private

    !> The keys of summary_table that get an estimate.
    character(len=*), parameter :: estimated_keys(12) = [character(len=32) :: 'settlement_max', &
        'differential_settlement', 'contact_extent_t', 'contact_extent_left_t', &
        'contact_extent_right_t', 'moment_sagging', 'moment_hogging', &
        'pressure_near_left_end', 'pressure_near_right_end', 'pressure_near_rim', &
        'pressure_centre', 'shear_force_max']
    integer, parameter :: min_coarse_elements = 4
    !> the smallest case mesh that gets an estimate: its mesh coarsened twice (N_e/4, the
    !! pre-asymptotic check) has min_coarse_elements; measured on 10 elements the estimates
    !! fell to 0.025 of the error (output/bench/estimate_effectivity_other_meshes.md)
    integer, parameter, public :: min_estimate_elements = 4*min_coarse_elements
    !> the observed order credited lies in [p_low, p_high] (and at most the formal order)
    real(dp), parameter :: p_low = 1.0_dp, p_high = 2.0_dp
    !> the coarse difference's share of the estimate's floor, |Q_c - Q_1| / coarse_share
    real(dp), parameter :: coarse_share = 4.0_dp
    !> Roache's factor of safety on a Richardson estimate with an observed order
    real(dp), parameter :: safety = 1.25_dp
    !> the least estimate relative to the value (computed_digits_floor): fricon's discrete
    !! solution agrees with an independent implementation of the same equations to 3.3e-7
    !! with friction (doc/CHOICES.md, "Error estimates, twelfth revision"), so an estimate
    !! below a millionth of the value would claim digits the computation does not hold
    real(dp), parameter :: relative_floor = 1.0e-6_dp
    !> the largest case mesh also solved on 4 N_e elements (twice_refined_entries, where it
    !! fits in memory): at 128 elements that solve adds about 30 ms to the estimate
    !! (output/bench/estimate_cost.md)
    integer, parameter :: twice_refined_max = 128

    !> The key results on a mesh of the case's grading that is not nested in the case's.
    type, public :: neighbour_t
        type(entry_t), allocatable :: e(:)
    end type neighbour_t

    !> The key results of a case on the other meshes of its estimate (estimate_family).
    type, public :: estimate_family_t
        logical :: ok = .false.        !! every solve succeeded
        logical :: refined = .false.   !! ef is the bisected mesh's (else N_e/4's)
        logical :: on_nodes = .false.  !! every concentrated load on a node of the meshes
        logical :: edge = .false.      !! a UNIFORM mesh with an end of the base in contact
        type(entry_t), allocatable :: ec(:)   !! the keys on the nested coarser mesh
        type(entry_t), allocatable :: ef(:)   !! on the bisected mesh (or on N_e/4)
        !> refined: the keys on the mesh coarsened twice (N_e/4), where it could be made and
        !! solved (pre_asymptotic)
        type(entry_t), allocatable :: e4(:)
        !> refined: the keys on the meshes of N_e - 1 and N_e + 1 elements of the case's
        !! grading whose concentrated loads lie on nodes exactly where the case's do (1 or 2
        !! of them; neighbour_floor), unallocated where none was solved
        type(neighbour_t), allocatable :: en(:)
        !> refined, N_e <= twice_refined_max: the keys on the mesh cut in two twice (4 N_e),
        !! where it could be solved (twice_refined_floor)
        type(entry_t), allocatable :: e4f(:)
    end type estimate_family_t


    public :: estimate_errors, estimate_family, extent_floors, coarse_case, attach_estimates, &
              is_estimated, formal_order, refined_estimate, liftoff_estimates, pre_asymptotic, &
              neighbour_floor, same_load_nodes, twice_refined_floor, computed_digits_floor

contains

    !> Fill e(:)%error (and %has_error, %order) for the estimated keys of a solved case.
    !! known: the solutions on the nested coarser meshes of the Newton start
    !! (solution_t%coarse); one whose mesh is the coarse mesh is not solved again.
    !! edge_in_contact: an end of the base is in contact (summary_t), which limits a
    !! uniform mesh to first order (formal_order). A mesh of fewer than min_estimate_elements
    !! elements gets no estimate.
    subroutine estimate_errors(m, d, e, known, edge_in_contact, cache, solution, design)
        type(model_t), intent(in) :: m            !! the model
        type(discretization_t), intent(in) :: d   !! the case's own discretisation
        type(entry_t), intent(inout) :: e(:)      !! the key results, updated
        !> the coarse solutions of the Newton start
        type(coarse_solution_t), intent(in), optional :: known(:)
        !> an end of the base is in contact (default false)
        logical, intent(in), optional :: edge_in_contact
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> the case's solution on d: the refined solve's Newton start is predicted from it
        type(solution_t), intent(in), optional :: solution
        !> the case's design table: the shortfall of its station extremes is added
        !! (extreme_estimates)
        type(station_table_t), intent(in), optional :: design
        type(estimate_family_t) :: fam
        logical :: edge
        if (d%msh%ne < min_estimate_elements) return
        edge = .false.
        if (present(edge_in_contact)) edge = edge_in_contact
        call estimate_family(m, d, edge, fam, known, cache, solution)
        if (.not. fam%ok) return
        if (fam%refined) then
            call refined_estimate(m, e, fam%ec, fam%ef, extent_floors(m, d%msh, e), &
                                  fam%on_nodes, fam%edge)
            if (allocated(fam%e4)) call pre_asymptotic(m, e, fam%ec, fam%e4, fam%on_nodes, &
                                                       fam%edge)
        else
            call attach_estimates(m, e, fam%ec, fam%ef, 2.0_dp, extent_floors(m, d%msh, e), &
                                  fam%on_nodes, fam%edge)
        end if
        if (present(design)) call add_sampling_errors(m, design, e, fam%ef, d%msh%x)
        call widen_unresolved_moments(e)
        ! after the moment rule, as measured (output/bench/estimate_effectivity.md): a moment
        ! the neighbours raise above its size is not widened further
        if (allocated(fam%en)) call neighbour_floor(e, fam%en)
        if (allocated(fam%e4f)) call twice_refined_floor(e, fam%e4f)
        if (allocated(fam%en) .or. allocated(fam%e4f)) call liftoff_estimates(m, e)
        call computed_digits_floor(e)
    end subroutine estimate_errors

    !> Every estimate is at least relative_floor times its value: no estimate claims more
    !! digits than the discrete solution holds (on 150 elements, a settlement of 3.4964087e-3
    !! whose error is 9.6e-9, 2.7e-6 of it, was estimated at 1.3e-9 from meshes that agree to
    !! 5e-10).
    pure subroutine computed_digits_floor(e)
        type(entry_t), intent(inout) :: e(:)       !! key results with their estimates
        integer :: i
        do i = 1, size(e)
            if (.not. (is_estimated(e(i)%key) .and. e(i)%has_error)) cycle
            e(i)%error = max(e(i)%error, relative_floor*abs(compared(e(i))))
        end do
    end subroutine computed_digits_floor

    !> The key results of the case on the meshes its estimate compares (module header): the
    !! nested coarser mesh and the bisected one (refined) or, where the bisected case does
    !! not fit in memory, the coarser meshes N_e/2 and N_e/4 (the second in fam%ef).
    subroutine estimate_family(m, d, edge_in_contact, fam, known, cache, solution)
        type(model_t), intent(in) :: m            !! the model
        type(discretization_t), intent(in) :: d   !! the case's own discretisation
        logical, intent(in) :: edge_in_contact    !! an end of the base is in contact
        type(estimate_family_t), intent(out) :: fam  !! the keys on the other meshes
        !> the coarse solutions of the Newton start
        type(coarse_solution_t), intent(in), optional :: known(:)
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> the case's solution on d (the refined solve starts from it)
        type(solution_t), intent(in), optional :: solution
        type(coarse_solution_t), allocatable :: reuse(:), own(:)
        type(coarse_solution_t) :: fine
        type(mesh_t) :: c2, c4, f2
        logical, allocatable :: p2(:), p4(:)
        allocate (reuse(0))
        if (present(known)) reuse = known
        fam%ok = .false.
        fam%edge = edge_in_contact .and. trim(m%mesh%grading) == 'UNIFORM'
        call coarsened(d%msh, pinned_nodes(d%msh, load_positions(m%loads)), c2, p2)
        if (c2%ne >= d%msh%ne .or. c2%ne < min_coarse_elements) return
        call mesh_entries(m, c2, reuse, fam%ec, fam%ok, cache)
        if (.not. fam%ok) return
        fam%on_nodes = loads_on_nodes(m%loads, d%msh) .and. loads_on_nodes(m%loads, c2)
        fam%refined = refined_fits(m, 2)
        if (fam%refined) then
            allocate (own(0))
            if (present(solution)) own = [coarse_solution_t(x=d%msh%x, z=solution%z, &
                admissibility=solution%admissibility, reaction=solution%reaction, &
                applied=solution%applied, n_solves=solution%n_solves)]
            f2 = bisected(d%msh, spread(.true., 1, d%msh%ne))
            call mesh_entries(m, f2, reuse, fam%ef, fam%ok, cache, own, fine)
            if (fam%ok) call twice_coarsened_entries(m, c2, p2, reuse, fam, cache)
            if (fam%ok) call neighbour_entries(m, d%msh, fam, cache)
            if (fam%ok .and. d%msh%ne <= twice_refined_max) then
                if (refined_fits(m, 4)) call twice_refined_entries(m, f2, fine, fam, cache)
            end if
            return
        end if
        fam%ok = .false.
        call coarsened(c2, p2, c4, p4)
        if (c4%ne >= c2%ne .or. c4%ne < min_coarse_elements) return
        call mesh_entries(m, c4, reuse, fam%ef, fam%ok, cache)
        fam%on_nodes = fam%on_nodes .and. loads_on_nodes(m%loads, c4)
    end subroutine estimate_family

    !> fam%e4: the keys on the mesh coarsened twice (a cheap solve: a sixteenth of the case's
    !! unknowns squared), left unallocated where that mesh cannot be made or solved.
    subroutine twice_coarsened_entries(m, c2, p2, reuse, fam, cache)
        type(model_t), intent(in) :: m
        type(mesh_t), intent(in) :: c2               !! the nested coarser mesh
        logical, intent(in) :: p2(:)                 !! its pinned nodes
        type(coarse_solution_t), intent(in) :: reuse(:)
        type(estimate_family_t), intent(inout) :: fam
        type(flexibility_cache_t), intent(inout), optional :: cache
        type(mesh_t) :: c4
        logical, allocatable :: p4(:)
        type(entry_t), allocatable :: e4(:)
        logical :: ok
        call coarsened(c2, p2, c4, p4)
        if (c4%ne >= c2%ne .or. c4%ne < min_coarse_elements) return
        call mesh_entries(m, c4, reuse, e4, ok, cache)
        if (ok) call move_alloc(e4, fam%e4)
    end subroutine twice_coarsened_entries

    !> fam%e4f: the keys on the bisected mesh f2 cut in two again (4 N_e elements), its
    !! Newton method started from the solution on f2; left unallocated where it cannot be
    !! solved.
    subroutine twice_refined_entries(m, f2, fine, fam, cache)
        type(model_t), intent(in) :: m
        type(mesh_t), intent(in) :: f2                !! the bisected mesh (2 N_e)
        type(coarse_solution_t), intent(in) :: fine   !! the solution on f2
        type(estimate_family_t), intent(inout) :: fam
        type(flexibility_cache_t), intent(inout), optional :: cache
        type(coarse_solution_t) :: none(0)
        type(entry_t), allocatable :: e4f(:)
        logical :: ok
        call mesh_entries(m, bisected(f2, spread(.true., 1, f2%ne)), none, e4f, ok, cache, &
                          [fine])
        if (ok) call move_alloc(e4f, fam%e4f)
    end subroutine twice_refined_entries

    !> fam%en: the keys on the meshes of N_e - 1 and N_e + 1 elements of the case's grading
    !! (MESH card), each where its concentrated loads lie on nodes exactly where the case's
    !! do and it could be solved. Solved where a concentrated load (POINT, RING, MOMENT) lies
    !! inside the base, and on every mesh of more than twice_refined_max elements: there is
    !! no solve on 4 N_e there, and the nested meshes keep the place in its parent element of
    !! whatever the error follows: the point d of the pressures near the ends, a peak between
    !! stations, a lift-off boundary (on 200 elements the hogging moment of a soft plate with
    !! lift-off, P2 on LOADS meshes, is 4.70339, 4.70209, 4.70187 e-3 on N_e/2, N_e, 2 N_e,
    !! converged 4.70444 e-3; 4.69643 and 4.70381 e-3 on 199 and 201 elements). None where
    !! the case's mesh is not the grading's own mesh of N_e elements (a mesh refined for
    !! friction), where N_e - 1 < min_coarse_elements, or on up to twice_refined_max elements
    !! without a concentrated load inside the base (patches only, or a point load on a
    !! plate's axis: nothing whose place in its element the neighbours could move that the
    !! solve on 4 N_e does not see; a sweep of small cases of patch loads pays nothing);
    !! fam%en then stays unallocated.
    subroutine neighbour_entries(m, msh, fam, cache)
        type(model_t), intent(in) :: m
        type(mesh_t), intent(in) :: msh              !! the case's mesh
        type(estimate_family_t), intent(inout) :: fam
        type(flexibility_cache_t), intent(inout), optional :: cache
        type(mesh_t) :: own, other
        type(error_t), allocatable :: err
        type(coarse_solution_t) :: none(0)
        type(entry_t), allocatable :: en(:)
        type(neighbour_t), allocatable :: solved(:)
        real(dp) :: x_left, x_right
        logical :: ok
        integer :: step
        if (msh%ne - 1 < min_coarse_elements) return
        call interface_ends(m%structure, x_left, x_right)
        if (msh%ne <= twice_refined_max .and. .not. any(m%loads%kind /= LOAD_PATCH .and. &
            m%loads%x1 > x_left .and. m%loads%x1 < x_right)) return
        call card_mesh(m, msh%ne, own, err)
        if (allocated(err)) return
        if (.not. same_nodes(own%x, msh%x)) return
        allocate (solved(0))
        do step = -1, 1, 2
            call card_mesh(m, msh%ne + step, other, err)
            if (allocated(err)) cycle
            if (.not. same_load_nodes(m, other, msh)) cycle
            call mesh_entries(m, other, none, en, ok, cache)
            if (ok) solved = [solved, neighbour_t(en)]
        end do
        if (size(solved) > 0) call move_alloc(solved, fam%en)
    end subroutine neighbour_entries

    !> Whether every concentrated load is on a node of mesh a exactly where it is on a node of
    !! mesh b (load by load: a load on a node converges at another order than one inside an
    !! element).
    pure logical function same_load_nodes(m, a, b)
        type(model_t), intent(in) :: m        !! the model (its loads)
        type(mesh_t), intent(in) :: a, b      !! the two meshes
        integer :: i
        same_load_nodes = .true.
        do i = 1, size(m%loads)
            if (m%loads(i)%kind == LOAD_PATCH) cycle
            if (loads_on_nodes(m%loads(i:i), a) .neqv. loads_on_nodes(m%loads(i:i), b)) then
                same_load_nodes = .false.
                return
            end if
        end do
    end function same_load_nodes

    !> The error of a key result is at least half its change to a mesh of the same grading
    !! with one element more or fewer (neighbour_entries): of two results whose errors are
    !! of one size, each error is at least half their difference (the triangle inequality).
    !! The nested meshes of the estimate keep a concentrated load's place in its element
    !! (N_e/2, N_e, 2 N_e: a load at 0.21 sits 0.01 beyond the node 0.2 on 20, 40 and 80
    !! elements), and where the error follows that place they can agree while the error does
    !! not fall (a moment load inside an element: the hogging moment's error 2.2, 2.3, 2.4
    !! e-5 on 20, 40, 80; 3.5, 5.4, 2.3, 3.3, 4.5 e-5 on 38 to 42). The neighbours move the
    !! load within its element; a neighbour whose loads lie on nodes where the case's do not
    !! (or the reverse) converges at another order and is not compared (neighbour_entries).
    pure subroutine neighbour_floor(e, en)
        type(entry_t), intent(inout) :: e(:)       !! key results with their estimates
        type(neighbour_t), intent(in) :: en(:)     !! the same keys on the neighbours
        integer :: k
        do k = 1, size(en)
            call change_floor(e, en(k)%e, 0.5_dp)
        end do
    end subroutine neighbour_floor

    !> The error of a key result on N_e elements is at least its change to the mesh cut in
    !! two twice (4 N_e; twice_refined_entries, on meshes of up to twice_refined_max
    !! elements). Where the error converges monotonically at an order p >= 1 from N_e on,
    !! that change is 1 - 4^-p, 0.75 to 1 times the error, so the floor neither overstates a
    !! converging error nor lets the estimate fall far below it. On coarse meshes the meshes
    !! N_e/4 to 2 N_e can show a sequence that stalls before it falls further
    !! (a stiff beam in full contact whose slip zone at one end grows from one node on N_e
    !! = 20 to two on 40 and four on 80: differential settlement 3.6467, 3.6440, 3.6419,
    !! then 3.6088 e-2 on N_e = 10 to 80, converged 3.5966; the meshes up to 2 N_e alone
    !! estimate a ninth of the error on 20); the solve on 4 N_e sees the fall.
    pure subroutine twice_refined_floor(e, e4f)
        type(entry_t), intent(inout) :: e(:)       !! key results with their estimates
        type(entry_t), intent(in) :: e4f(:)        !! the same keys on 4 N_e elements
        call change_floor(e, e4f, 1.0_dp)
    end subroutine twice_refined_floor

    !> Each estimated key's estimate is at least share times its change to the same key on
    !! another mesh (other; matched by name, skipped where undefined there).
    pure subroutine change_floor(e, other, share)
        type(entry_t), intent(inout) :: e(:)       !! key results with their estimates
        type(entry_t), intent(in) :: other(:)      !! the same keys on another mesh
        real(dp), intent(in) :: share              !! the share of the change
        integer :: i
        do i = 1, min(size(e), size(other))
            if (.not. (is_estimated(e(i)%key) .and. e(i)%has_error)) cycle
            if (.not. other(i)%defined) cycle
            if (trim(other(i)%key) /= trim(e(i)%key)) cycle
            e(i)%error = max(e(i)%error, share*abs(compared(other(i)) - compared(e(i))))
        end do
    end subroutine change_floor

    !> Whether the case on times its elements fits in the memory available.
    logical function refined_fits(m, times)
        type(model_t), intent(in) :: m
        integer, intent(in) :: times   !! the refined mesh's elements per element of m's
        type(model_t) :: mf
        type(error_t), allocatable :: err
        mf = m
        mf%mesh%ne = times*m%mesh%ne
        call check_memory(mf, 1, memory_available(), err)
        refined_fits = .not. allocated(err)
    end function refined_fits

    !> Per entry, the least estimate: a contact extent is a node, and the boundary lies in
    !! the element beyond it (before it, for the leftmost station in contact), so its error
    !! is taken as at least half that element (as t); 0 for the other keys. An extent at an
    !! end of the base gets half the element at that end: a lift-off shorter than that
    !! element leaves the end node in contact on the mesh and on its coarser and bisected
    !! neighbours alike (two point loads on a soft beam: extent 0.5 on N_e = 10, 20, 40,
    !! 0.4855 converged), so the meshes cannot tell it from contact up to the end.
    pure function extent_floors(m, msh, e) result(floor)
        type(model_t), intent(in) :: m        !! the model
        type(mesh_t), intent(in) :: msh       !! the case's mesh
        type(entry_t), intent(in) :: e(:)     !! its key results
        real(dp) :: floor(size(e))
        real(dp) :: x
        integer :: i, k
        floor = 0.0_dp
        do i = 1, size(e)
            if (.not. e(i)%defined) cycle
            x = e(i)%value*m%structure%length
            k = count(msh%x(1:) <= x + 1.0e-9_dp*m%structure%length)  ! nodes at or before x
            select case (trim(e(i)%key))
            case ('contact_extent_t', 'contact_extent_right_t')
                k = min(k + 1, msh%ne)    ! the element beyond, or the last one
                floor(i) = 0.5_dp*(msh%x(k) - msh%x(k - 1))/m%structure%length
            case ('contact_extent_left_t')
                k = max(k, 1)             ! the element before, or the first one
                floor(i) = 0.5_dp*(msh%x(k) - msh%x(k - 1))/m%structure%length
            end select
        end do
    end function extent_floors

    !> The lengths lifted off at the beam's ends move with the contact extents beside them
    !! (summary_table: liftoff_left and contact_extent_left_t, liftoff_right and
    !! contact_extent_right_t; a length = (t_left + 1/2) l or (1/2 - t_right) l, less half
    !! a station spacing): each gets the estimate of its extent times l, in its unit.
    pure subroutine liftoff_estimates(m, e)
        type(model_t), intent(in) :: m        !! the model
        type(entry_t), intent(inout) :: e(:)  !! the key results with their estimates, updated
        character(len=*), parameter :: lengths(2) = [character(len=32) :: 'liftoff_left', &
            'liftoff_right'], extents(2) = [character(len=32) :: 'contact_extent_left_t', &
            'contact_extent_right_t']
        type(scales_t) :: scales
        real(dp) :: factor
        integer :: i, j, k
        scales = case_scale_factors(m)
        factor = m%structure%length*scales%length
        do k = 1, 2
            i = entry_index(e, trim(lengths(k)))
            j = entry_index(e, trim(extents(k)))
            if (i == 0 .or. j == 0) cycle
            if (.not. (e(j)%has_error .and. e(i)%defined)) cycle
            e(i)%has_error = .true.
            e(i)%error = e(j)%error*factor
            e(i)%order = e(j)%order
        end do
    end subroutine liftoff_estimates

    !> Estimates of the estimated keys of e (on N_e elements) from the same keys on the
    !! nested coarser mesh (ec, every other node removed) and on the mesh with every element
    !! cut in two (ef): the module header's E, the observed order in [p_low, p_high] and at
    !! most formal_order; each estimate is at least its floor (the contact extents':
    !! extent_floors); the lift-off lengths get their extents' (liftoff_estimates).
    pure subroutine refined_estimate(m, e, ec, ef, floors, kinks_on_nodes, singular_edge)
        type(model_t), intent(in) :: m             !! the case (formal orders by model kind)
        type(entry_t), intent(inout) :: e(:)       !! key results on N_e elements; their
                                                   !! estimates and orders are set
        type(entry_t), intent(in) :: ec(:)         !! the same keys on the nested coarser mesh
        type(entry_t), intent(in) :: ef(:)         !! the same keys on the mesh cut in two
        real(dp), intent(in) :: floors(:)          !! least estimate per entry (extent_floors)
        logical, intent(in) :: kinks_on_nodes      !! see formal_order
        logical, intent(in) :: singular_edge       !! see formal_order
        real(dp) :: q1, dc, df, p, p_max
        integer :: i
        do i = 1, size(e)
            if (.not. is_estimated(e(i)%key) .or. e(i)%singular) cycle
            if (.not. (e(i)%defined .and. ec(i)%defined .and. ef(i)%defined)) cycle
            q1 = compared(e(i))
            dc = compared(ec(i)) - q1
            df = q1 - compared(ef(i))
            p_max = max(p_low, min(p_high, formal_order(m, e(i)%key, kinks_on_nodes, &
                                                        singular_edge)))
            e(i)%order = -1.0_dp
            p = p_low
            if (dc /= 0.0_dp .and. df /= 0.0_dp .and. sign(1.0_dp, dc) == sign(1.0_dp, df)) then
                p = min(max(log(abs(dc)/abs(df))/log(2.0_dp), p_low), p_max)
                e(i)%order = p
            end if
            e(i)%error = max(safety*abs(df)*2.0_dp**p/(2.0_dp**p - 1.0_dp), &
                             abs(dc)/coarse_share, floors(i))
            e(i)%has_error = .true.
        end do
        call liftoff_estimates(m, e)
    end subroutine refined_estimate

    !> Widen the estimates where the nested coarser meshes are short of the asymptotic range
    !! (module header): where the change from the mesh coarsened twice (e4) to the coarser
    !! one (ec) is more than 2^(p + 2) times the change from ec to the case's mesh, p the
    !! largest order the method can have for the key (formal_order), the three meshes show an
    !! order more than two above any the method has: the coarsest is outside the asymptotic
    !! range, and the refined estimate, made from the two finer differences as if the case's
    !! mesh were inside it, is no measure of the error (a soft thick beam under a point load,
    !! P2: settlement 3.35, 2.562, 2.569, 2.570 e-4 on N_e = 5, 10, 20, 40 and 2.549e-4
    !! converged, an estimate of 1.8e-7 for an error of 2.0e-6). The estimate is then at least
    !! the whole coarse difference |Q_c - Q|. Contact extents keep theirs (their floors).
    pure subroutine pre_asymptotic(m, e, ec, e4, kinks_on_nodes, singular_edge)
        type(model_t), intent(in) :: m            !! the model (formal orders by its kind)
        type(entry_t), intent(inout) :: e(:)      !! key results with their estimates
        type(entry_t), intent(in) :: ec(:), e4(:) !! the keys on N_e/2 and N_e/4
        logical, intent(in) :: kinks_on_nodes     !! see formal_order
        logical, intent(in) :: singular_edge      !! see formal_order
        real(dp) :: dc, d4
        integer :: i
        do i = 1, size(e)
            if (.not. e(i)%has_error .or. trim(e(i)%key) == 'contact_extent_t') cycle
            if (i > size(e4)) cycle
            if (.not. (ec(i)%defined .and. e4(i)%defined)) cycle
            dc = abs(compared(ec(i)) - compared(e(i)))
            d4 = abs(compared(e4(i)) - compared(ec(i)))
            if (.not. d4 > 2.0_dp**(formal_order(m, e(i)%key, kinks_on_nodes, &
                                                 singular_edge) + 2.0_dp)*dc) cycle
            e(i)%error = max(e(i)%error, dc)
        end do
    end subroutine pre_asymptotic

    !> Estimates of the estimated keys of e from the same keys on two coarser meshes of a
    !! nested family (e2 about N_e/ratio, e4 about N_e/ratio^2 elements); each estimate is
    !! at least its floor (the contact extents' t); the lift-off lengths get their extents'
    !! (liftoff_estimates). Each key is credited with at most the
    !! order of convergence the method has for it (formal_order): three coarse meshes are
    !! often short of the asymptotic range and show a higher order than that.
    pure subroutine attach_estimates(m, e, e2, e4, ratio, floors, kinks_on_nodes, &
                                     singular_edge)
        type(model_t), intent(in) :: m             !! the model
        type(entry_t), intent(inout) :: e(:)       !! the key results, updated
        !> the keys on about N_e/ratio and N_e/ratio^2 elements
        type(entry_t), intent(in) :: e2(:), e4(:)
        real(dp), intent(in) :: ratio              !! refinement ratio between the meshes
        real(dp), intent(in) :: floors(:)          !! least estimate per entry (the contact
                                                   !! extents' t; 0 for the others)
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
            e(i)%error = max(e(i)%error, floors(i))
            e(i)%has_error = .true.
        end do
        call liftoff_estimates(m, e)
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

    !> The key results of the case on the mesh msh (ok false when the solve fails), from a
    !! known solution on that mesh if there is one.
    subroutine mesh_entries(m, msh, known, e, ok, cache, start, solved)
        type(model_t), intent(in) :: m
        type(mesh_t), intent(in) :: msh
        type(coarse_solution_t), intent(in) :: known(:)
        type(entry_t), allocatable, intent(out) :: e(:)
        logical, intent(out) :: ok
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> (0 or 1) a solution on msh's nested coarser mesh, the Newton start's (solve_contact)
        type(coarse_solution_t), intent(in), optional :: start(:)
        !> the solution on msh, as a Newton start for a mesh cut from it (where ok)
        type(coarse_solution_t), intent(out), optional :: solved
        type(model_t) :: mc
        type(discretization_t) :: d
        type(case_t) :: c
        integer :: k
        mc = m
        mc%mesh%ne = msh%ne
        call discretise_mesh(mc, msh, d)
        do k = 1, size(known)
            if (same_nodes(known(k)%x, d%msh%x)) then
                call coarse_case(mc, d, c, ok, known(k))
                call take(c)
                return
            end if
        end do
        if (present(start)) then
            if (size(start) == 1) then
                call coarse_case(mc, d, c, ok, cache=cache, start=start(1))
                call take(c)
                return
            end if
        end if
        call coarse_case(mc, d, c, ok, cache=cache)
        call take(c)
    contains
        !> The entries (and the solution, if asked) of the case solved on msh, where ok.
        subroutine take(solved_case)
            type(case_t), intent(in) :: solved_case
            if (.not. ok) return
            e = solved_case%entries
            if (present(solved)) solved = coarse_solution_t(x=d%msh%x, z=solved_case%sol%z)
        end subroutine take
    end subroutine mesh_entries

    !> The case solved on the discretisation d, or finished from a known solution on d; ok
    !! false when the solve fails.
    subroutine coarse_case(m, d, c, ok, known, cache, start)
        type(model_t), intent(in) :: m                 !! the model
        type(discretization_t), intent(in) :: d        !! a coarser mesh of it
        type(case_t), intent(out) :: c                 !! the case on d
        logical, intent(out) :: ok                     !! solved and tabulated
        type(coarse_solution_t), intent(in), optional :: known   !! the solution on d
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> a solution on d's nested coarser mesh, for the Newton start (solve_contact)
        type(coarse_solution_t), intent(in), optional :: start
        type(solution_t) :: sol
        type(error_t), allocatable :: err
        if (present(known)) then
            sol%z = known%z
            sol%admissibility = known%admissibility
            sol%reaction = known%reaction
            sol%applied = known%applied
            sol%n_solves = known%n_solves
            call finish_case(m, d, sol, c, err, soil=.false.)
        else
            call solve_on(m, d, c, err, cache=cache, start=start, soil=.false.)
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
