!> Model only what a scene needs (doc/CHOICES.md, Simplifications): the discrete contact problem
!! restricted to a subspace of the full one that provably holds its solution, solved there, and
!! expanded back to the full coefficient vector, so that every later stage (stations, summary,
!! files, checks) sees the full model's numbering.
!!
!! The restriction is z = P y: every full coefficient j is k(j) (0: zero) times s(j) (+-1).
!! The reduced problem is P^T F(P y) = 0: A0 -> P^T A0 P, q -> P^T q, and the interface terms
!! of every contact point with its basis values mapped through P (all points kept, so the
!! interface sums are exactly P^T N(P y)). Two simplifications:
!! * frictionless (f = 0): Coulomb's law gives sigma_x = 0, so the sigma_x coefficients are
!!   dropped. The regularised law (SPEC §4) leaves a stick compliance c eps_bar on the full
!!   model, hence |sigma_x| = O(eps_bar) there: the two differ by the regularisation, which
!!   vanishes linearly with eps_bar (test_simplifications measures it; the dropped model is
!!   the eps_bar -> 0 limit of the full one: up to 6.5e-4 of max |W| at eps_bar 1e-6 on a soft
!!   thick beam, doc/CHOICES.md "Simplifications"). A beam (not halved)
!!   keeps one shear unknown, a constant sigma_x = lambda: without it nothing fixes its
!!   horizontal rigid translation; with it the equations hold the eps_bar -> 0 limit of the
!!   full model, mean slip = 0 (lambda's row) and int sigma_x = 0 (so lambda = 0);
!! * half beam: a beam whose mesh and loads are symmetric about x = 0 (vertical loads, no
!!   MOMENT) has a symmetric solution: w and sigma_z even, u_s, psi and sigma_x odd. The
!!   bases on a symmetric mesh are mirror images (function j and n_dof + 1 - j), so only the
!!   coefficients of the right half are unknowns; an odd field's own mirror (centre node) is
!!   zero. The result equals the full model's to round-off (the same discrete problem).
!! Only for the Newton method (the two-loop method keeps its own bookkeeping).
module model_reduction
    use kinds, only: dp
    use model, only: model_t, MODEL_BEAM, LOAD_PATCH, LOAD_MOMENT, METHOD_NEWTON, &
                     FIELD_U, FIELD_W, FIELD_PSI, FIELD_SX, FIELD_SZ
    use mesh, only: mesh_t
    use discretization, only: discretization_t
    use contact_system, only: system_t, contact_points_t, set_base_matrix, a0_diagonal, &
                              diagonal_scaling
    use sparse_matrix, only: columns_t, triplets_t, new_triplets, add_entry, packed_column, &
                             pack_lower
    use rigid_body, only: new_rigid
    implicit none
    private

    real(dp), parameter :: symmetry_tol = 1.0e-12_dp  !! of the length: mirror positions

    !> Which simplifications a case uses, and the map P from reduced to full coefficients.
    type, public :: reduction_t
        logical :: frictionless = .false.   !! sigma_x coefficients dropped (f = 0)
        logical :: half = .false.           !! symmetric beam: right half only
        logical :: mean_shear = .false.     !! frictionless beam: sigma_x = constant kept
        integer :: n_full = 0, n_reduced = 0
        integer, allocatable :: k(:)        !! reduced index of full coefficient j (0: zero)
        real(dp), allocatable :: s(:)       !! its sign
    end type reduction_t

    public :: plan_reduction, is_active
    public :: reduced_discretization, reduced_system, reduced_points, expand

contains

    !> The simplifications that apply to case m on discretisation d, and their map.
    pure function plan_reduction(m, d) result(red)
        type(model_t), intent(in) :: m            !! the model
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(reduction_t) :: red
        if (m%solver%simplify .and. m%solver%method == METHOD_NEWTON) then
            red%frictionless = m%interface%f == 0.0_dp
            red%half = m%structure%kind == MODEL_BEAM .and. symmetric_loads(m) &
                       .and. symmetric_mesh(d%msh, m%structure%length)
            red%mean_shear = red%frictionless .and. m%structure%kind == MODEL_BEAM .and. &
                             .not. red%half
        end if
        call build_map(d, red)
    end function plan_reduction

    !> Any simplification in use.
    elemental logical function is_active(red)
        type(reduction_t), intent(in) :: red   !! the simplifications in use and their map P
        is_active = red%frictionless .or. red%half
    end function is_active

    !> Every load vertical and mirrored by another of the same kind and force (or itself).
    pure logical function symmetric_loads(m)
        type(model_t), intent(in) :: m
        logical, allocatable :: used(:)
        integer :: i, j
        real(dp) :: tol
        symmetric_loads = .false.
        if (.not. allocated(m%loads)) return
        if (size(m%loads) == 0) return
        if (any(m%loads%fx /= 0.0_dp) .or. any(m%loads%kind == LOAD_MOMENT)) return
        tol = symmetry_tol*m%structure%length
        allocate (used(size(m%loads)), source=.false.)
        loads: do i = 1, size(m%loads)
            if (used(i)) cycle loads
            partners: do j = 1, size(m%loads)
                if (used(j)) cycle partners
                if (mirrors(m%loads(i), m%loads(j))) then
                    used(i) = .true.
                    used(j) = .true.
                    cycle loads
                end if
            end do partners
            return
        end do loads
        symmetric_loads = .true.
    contains
        pure logical function mirrors(a, b)
            use model, only: load_t
            type(load_t), intent(in) :: a, b
            mirrors = a%kind == b%kind .and. abs(a%fz - b%fz) <= symmetry_tol*abs(a%fz)
            if (a%kind == LOAD_PATCH) then
                mirrors = mirrors .and. abs(a%x1 + b%x2) <= tol .and. abs(a%x2 + b%x1) <= tol
            else
                mirrors = mirrors .and. abs(a%x1 + b%x1) <= tol
            end if
        end function mirrors
    end function symmetric_loads

    !> Nodes mirrored about x = 0.
    pure logical function symmetric_mesh(msh, length)
        type(mesh_t), intent(in) :: msh
        real(dp), intent(in) :: length
        integer :: i
        symmetric_mesh = all([(abs(msh%x(i) + msh%x(msh%ne - i)) <= symmetry_tol*length, &
                               i=0, msh%ne)])
    end function symmetric_mesh

    !> k and s of every full coefficient; reduced unknowns numbered field by field (so the
    !! reduced vector keeps the order [v; r] and contiguous field blocks).
    pure subroutine build_map(d, red)
        type(discretization_t), intent(in) :: d
        type(reduction_t), intent(inout) :: red
        real(dp), parameter :: parity(5) = [-1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp]
        integer :: field, j, jp, nf, off, n
        red%n_full = d%n
        allocate (red%k(d%n), red%s(d%n))
        red%k = 0
        red%s = 1.0_dp
        n = 0
        fields: do field = FIELD_U, FIELD_SZ
            nf = d%basis(field)%n_dof
            off = d%offset(field)
            if (field == FIELD_SX .and. red%frictionless) then
                if (red%mean_shear) then
                    ! one unknown for all: sigma_x = constant (partition of unity)
                    n = n + 1
                    red%k(off + 1:off + nf) = n
                end if
                cycle fields
            end if
            representatives: do j = 1, nf
                jp = partner(j, nf)
                if (j < jp) cycle representatives
                if (j == jp .and. red%half .and. parity(field) < 0.0_dp) cycle representatives
                n = n + 1
                red%k(off + j) = n
            end do representatives
            if (.not. red%half) cycle fields
            mirrored: do j = 1, nf
                jp = partner(j, nf)
                if (j >= jp) cycle mirrored
                red%k(off + j) = red%k(off + jp)
                red%s(off + j) = parity(field)
            end do mirrored
        end do fields
        red%n_reduced = n
    contains
        pure integer function partner(j, nf)
            integer, intent(in) :: j, nf
            partner = j
            if (red%half) partner = nf + 1 - j
        end function partner
    end subroutine build_map

    !> The numbering of the reduced problem (the mesh and bases stay the full ones: the
    !! Newton method only uses nv, nr, n and fixed).
    pure function reduced_discretization(d, red) result(dr)
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(reduction_t), intent(in) :: red      !! the simplifications in use and their map P
        type(discretization_t) :: dr
        integer :: field, i
        dr = d
        do field = FIELD_U, FIELD_SZ
            ! reduced unknowns are numbered field by field: those before this field
            dr%offset(field) = maxval([0, red%k(1:d%offset(field))])
        end do
        dr%nv = dr%offset(FIELD_SX)
        dr%n = red%n_reduced
        dr%nr = dr%n - dr%nv
        dr%fixed = [(red%k(d%fixed(i)), i=1, size(d%fixed))]
        dr%fixed = pack(dr%fixed, dr%fixed > 0)
    end function reduced_discretization

    !> P^T A0 P (by blocks), P^T q and the rigid-body bookkeeping of the reduced problem.
    function reduced_system(sys, d, dr, red) result(sr)
        type(system_t), intent(in) :: sys             !! the assembled system (A0, q)
        type(discretization_t), intent(in) :: d, dr   !! the full and the reduced discretisation
        type(reduction_t), intent(in) :: red          !! the simplifications in use and their map P
        type(system_t) :: sr
        real(dp), allocatable :: b0(:, :), b0_packed(:)
        integer :: i, j
        allocate (sr%q(dr%nv), b0(dr%nr, dr%nr))
        sr%q = 0.0_dp
        do i = 1, d%nv
            if (red%k(i) > 0) sr%q(red%k(i)) = sr%q(red%k(i)) + red%s(i)*sys%q(i)
        end do
        b0 = 0.0_dp
        columns: do j = 1, d%nr
            if (red%k(d%nv + j) == 0) cycle columns
            associate (col => packed_column(sys%b0, d%nr, j), jr => red%k(d%nv + j) - dr%nv)
                rows: do i = 1, d%nr
                    if (red%k(d%nv + i) == 0) cycle rows
                    b0(red%k(d%nv + i) - dr%nv, jr) = b0(red%k(d%nv + i) - dr%nv, jr) &
                                                      + red%s(d%nv + i)*red%s(d%nv + j)*col(i)
                end do rows
            end associate
        end do columns
        call pack_lower(b0, b0_packed)
        deallocate (b0)
        call set_base_matrix(sr, dr%nv, restricted(sys%k, red, 0, 0, 0, 0), &
                             restricted(sys%mm, red, d%nv, 0, dr%nv, 0), b0_packed)
        sr%row_scale = diagonal_scaling(a0_diagonal(sr))
        sr%c = sys%c
        sr%kappa = sys%kappa
        sr%penalty = sys%penalty
        sr%law = sys%law
        if (red%half) then
            ! only the translation of w is symmetric (u_s odd, the rotation antisymmetric)
            sr%rigid = new_rigid(dr%nv, reshape([dr%offset(FIELD_W) + 1, dr%offset(FIELD_PSI)], &
                                                [2, 1]), [0, 0])
        else
            ! only tractions dropped: the displacement numbering is the full one
            sr%rigid = sys%rigid
        end if
    end function reduced_system

    !> The entries of the block c of A0 mapped through P: c(i, j) is A0(row0 + i, col0 + j)
    !! in the full numbering, the result's (i', j') is the reduced A0(row0r + i', col0r + j').
    pure function restricted(c, red, row0, col0, row0r, col0r) result(t)
        type(columns_t), intent(in) :: c
        type(reduction_t), intent(in) :: red
        integer, intent(in) :: row0, col0, row0r, col0r
        type(triplets_t) :: t
        integer :: j, l
        t = new_triplets(c%nrow, c%ncol, size(c%val))
        ! (mirror pairs share one reduced unknown: the size is the largest reduced number)
        t%nrow = maxval([row0r, red%k(row0 + 1:row0 + c%nrow)]) - row0r
        t%ncol = maxval([col0r, red%k(col0 + 1:col0 + c%ncol)]) - col0r
        columns: do j = 1, c%ncol
            if (red%k(col0 + j) == 0) cycle columns
            entries: do l = c%ptr(j), c%ptr(j + 1) - 1
                associate (i => c%row(l))
                    if (red%k(row0 + i) == 0) cycle entries
                    call add_entry(t, red%k(row0 + i) - row0r, red%k(col0 + j) - col0r, &
                                   red%s(row0 + i)*red%s(col0 + j)*c%val(l))
                end associate
            end do entries
        end do columns
    end function restricted

    !> The contact points with their traction basis mapped through P (entries of one point
    !! that map to the same reduced unknown merged, so no index repeats within a point;
    !! unused slots padded with value 0 at distinct indices).
    pure function reduced_points(pts, red) result(pr)
        type(contact_points_t), intent(in) :: pts   !! the contact points
        type(reduction_t), intent(in) :: red        !! the simplifications in use and their map P
        type(contact_points_t) :: pr
        integer :: p, k, l, n, c, g
        pr = pts
        points: do p = 1, pts%n
            traction_fields: do k = 1, 2
                n = 0
                locals: do l = 1, pts%nl(k)
                    g = pts%idx(l, k, p)
                    if (red%k(g) == 0) cycle locals
                    c = findloc(pr%idx(1:n, k, p), red%k(g), dim=1)
                    if (c == 0) then
                        n = n + 1
                        c = n
                        pr%idx(c, k, p) = red%k(g)
                        pr%val(c, k, p) = 0.0_dp
                    end if
                    pr%val(c, k, p) = pr%val(c, k, p) + red%s(g)*pts%val(l, k, p)
                end do locals
                g = 0
                padding: do while (n < pts%nl(k))
                    g = g + 1
                    if (any(pr%idx(1:n, k, p) == g)) cycle padding
                    n = n + 1
                    pr%idx(n, k, p) = g
                    pr%val(n, k, p) = 0.0_dp
                end do padding
            end do traction_fields
        end do points
    end function reduced_points

    !> z = P y.
    pure function expand(red, y) result(z)
        type(reduction_t), intent(in) :: red   !! the simplifications in use and their map P
        real(dp), intent(in) :: y(:)           !! the unknowns of the reduced problem
        real(dp) :: z(red%n_full)
        integer :: j
        do j = 1, red%n_full
            z(j) = 0.0_dp
            if (red%k(j) > 0) z(j) = red%s(j)*y(red%k(j))
        end do
    end function expand
end module model_reduction
