!> Newton steps by a Schur complement onto the traction unknowns (doc/METHOD.md, Solution
!! methods).
!!
!! The Jacobian of the complete problem is J = [K M^T; M B(sets)]: K (the structure) is
!! banded and constant, M constant, and only B = -(T + c eps0 S0) + (set terms at the
!! interface's Gauss points) changes between Newton steps. The system is in rigid coordinates
!! (rigid_body): the "pinned" displacement unknowns (plate: the first w; beam: the first u,
!! first and last w) are the amplitudes of the rigid-body modes, their rows and columns of K
!! are exactly 0 and their rows carry the load compatibility (M R)^T r = R^T q. They are
!! kept with the tractions, and the other displacement unknowns ("inner", ordered node by
!! node so that their K block is banded) are eliminated once per case:
!!   S0 = J(kept, kept) - J(kept, inner) K_ii^-1 J(inner, kept),
!! with K_ii = L L^T by banded Cholesky (dpbtrf); J(inner, pinned) = 0, so the pinned rows of
!! S0 are (M R)^T, not a difference of large numbers, and the pinned-pinned block is 0.
!! Each Newton step then adds the set terms to S0 and factorises the kept block only (LDL^T
!! when symmetric, else LU, after the symmetric diagonal scaling), about (nr/n)^3 of the
!! flops of factorising J; v follows by two banded solves. Two steps of iterative refinement
!! with the complete J, as the dense solves do.
!!
!! Settled lift-off (doc/CHOICES.md, Simplifications): the traction unknowns of a region that stays
!! in the tension set have rows dominated by the penalty c/eta_bar (and, for sigma_x, the slip term
!! c/eps_bar) and barely couple to the rest. When the caller names them (candidates), the
!! step's factorisation drops the couplings between them and the other kept unknowns: two
!! dense blocks factorised on their own, (nk - nd)^3 + nd^3 instead of nk^3. It is an inexact
!! factorisation of the exact J: the refinement with J restores the exact step (error
!! propagation -M^-1 E, E the dropped couplings, whose square is O(|S0| / penalty)), tested
!! like a low-rank update. The dropped couplings must hold no set term: the penalty is a
!! mass matrix (P1: neighbouring functions share a point), and dropping its entries (e.g.
!! keeping only the diagonal of the decoupled rows) leaves an error propagation of order 1
!! (measured: the refinement contracts by 0.5 a step). So the decoupled unknowns are whole
!! connected components of the set terms' graph, every one of whose unknowns the set terms
!! dominate, with at least one candidate: a lift-off region's sigma_z functions with the
!! partly lifted ones at its edges.
module schur_solver
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_ANALYSIS, EXIT_INTERNAL
    use model, only: FIELD_U, FIELD_PSI
    use discretization, only: discretization_t
    use contact_system, only: system_t, set_terms_t, a0_times, a0_lower_column, &
                              diagonal_scaling
    use band_solve, only: band_cholesky_solve, band_cholesky_solve_rows
    use sparse_matrix, only: packed_position, unpack_lower
    use lapack_interfaces, only: dpbtrf, dsytrf, dsytrs, dgetrf, dgetrs
    implicit none
    private

    !> The set-independent part of the reduction, built once per case.
    type, public :: schur_t
        logical :: ready = .false.           !! else: solve with the complete dense J
        integer :: ni = 0                    !! eliminated (inner) displacement unknowns
        integer :: nk = 0                    !! kept unknowns: pinned, then free tractions
        integer :: n_pinned = 0
        integer :: kd = 0                    !! half bandwidth of K_ii in the inner order
        integer, allocatable :: inner(:)     !! global numbers of the inner unknowns
        integer, allocatable :: kept(:)      !! global numbers of the kept unknowns
        integer, allocatable :: pos(:)       !! global -> position in kept (0: not kept)
        logical, allocatable :: fixed(:)     !! global: a constrained unknown (z_i = 0 rows)
        real(dp), allocatable :: kband(:, :) !! Cholesky factor of K_ii, LAPACK band storage
        real(dp), allocatable :: s0(:)       !! constant Schur complement (nk x nk), packed lower
        integer, allocatable :: c_row(:)     !! nonzeros of C = J(inner, kept): inner position,
        integer, allocatable :: c_col(:)     !! kept position,
        real(dp), allocatable :: c_val(:)    !! value (J is symmetric there: J(kept, inner) = C^T)
        logical :: decouple = .false.        !! settled lift-off tractions may be decoupled in
                                             !! the factorisation (model_t%simplify)
    end type schur_t

    !> The kept block of one Newton step: S0 + base set terms factorised, and the low-rank
    !! change to the present set terms (Woodbury): S = S_base + E D E^T, E the columns of the
    !! identity at the kept unknowns of the contact points whose terms changed.
    type, public :: schur_factor_t
        real(dp), allocatable :: lu(:, :)    !! LDL^T or LU factors of the scaled S_base (of
                                             !! its active rows and columns when decoupled)
        real(dp), allocatable :: scale(:)    !! 1/sqrt|diagonal| (1 where 0)
        integer, allocatable :: ipiv(:)
        logical :: symmetric = .true.        !! S_base symmetric: LDL^T, else LU
        type(set_terms_t) :: base            !! the set terms in S_base
        integer :: nu = 0                    !! rank of the update (0: S = S_base)
        integer, allocatable :: upos(:)      !! kept positions touched by the change
        real(dp), allocatable :: dmat(:, :)  !! D (nu x nu)
        real(dp), allocatable :: w(:, :)     !! S_base^-1 E (nk x nu)
        real(dp), allocatable :: cap(:, :)   !! LU of the capacitance I + D E^T W
        integer, allocatable :: cap_ipiv(:)
        real(dp), allocatable :: w_cache(:, :)  !! columns S_base^-1 e_p computed so far
        integer, allocatable :: cache_col(:)    !! kept position p -> its column (0: none)
        integer :: n_cached = 0
        integer :: n_decoupled = 0           !! decoupled kept unknowns (0: S_base is exact)
        integer, allocatable :: active(:)    !! kept positions in lu (with decoupling)
        integer, allocatable :: dec(:)       !! kept positions decoupled, factorised in
        real(dp), allocatable :: lu_dec(:, :)  !! lu_dec on their own
        integer, allocatable :: ipiv_dec(:)
    end type schur_factor_t

    integer, parameter :: block_columns = 64  !! columns of C per banded solve in new_schur

    !> Low-rank update while its rank u <= nk / this: the update costs u solves with the base
    !! factors (2 nk^2 u flops; BLAS 3 for LU, BLAS 2 in LAPACK's LDL^T solve), a new
    !! factorisation 2/3 nk^3 (LU) or 1/3 nk^3 (LDL^T).
    integer, parameter :: update_fraction(2) = [20, 5]   !! base LDL^T, LU

    !> Decoupling is used once at least nk / decouple_fraction kept unknowns qualify, and
    !! only from decouple_from kept unknowns on: below, the factorisation is too cheap for
    !! its saving to pay for the refinement steps it adds (measured with plate_nondim.dat and
    !! beam_nondim.dat, output/bench/simplifications.md: slower at N_e = 20 and 100, even at
    !! 200, faster from 500 on).
    integer, parameter :: decouple_fraction = 8
    integer, parameter :: decouple_from = 400
    !> A candidate is decoupled only where its set-term diagonal is at least this times its
    !! S0 diagonal: the contraction of the refinement is about the inverse ratio.
    real(dp), parameter :: dominance = 1.0e4_dp

    public :: new_schur, schur_factorise, schur_prepare, schur_solve

contains

    !> Order, factorise K_ii and form S0. sc%ready stays false (dense fallback) when K_ii is
    !! not positive definite (no rigid-body description of the structure fits).
    subroutine new_schur(d, sys, sc)
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(system_t), intent(in) :: sys         !! the assembled system (A0, q)
        type(schur_t), intent(out) :: sc          !! the Schur set-up (ordering, factor of K_ii, S0)
        integer, allocatable :: pinned(:)
        integer :: i
        allocate (sc%fixed(d%n))
        sc%fixed = .false.
        sc%fixed(d%fixed) = .true.
        pinned = sys%rigid%pinned
        if (any(sc%fixed(pinned))) return
        sc%n_pinned = size(pinned)
        sc%inner = inner_order(d, sc%fixed, pinned)
        sc%ni = size(sc%inner)
        sc%kept = [pinned, pack([(i, i=d%nv + 1, d%n)], .not. sc%fixed(d%nv + 1:d%n))]
        sc%nk = size(sc%kept)
        allocate (sc%pos(d%n))
        sc%pos = 0
        sc%pos(sc%kept) = [(i, i=1, sc%nk)]
        if (sc%ni == 0) return
        call factorise_inner(sys, sc)
        if (.not. sc%ready) return
        call coupling_nonzeros(sys, sc)
        call form_s0(sys, sc)
    end subroutine new_schur

    !> The free, unpinned displacement unknowns node by node: the fields u_s, w, psi merged
    !! by relative position in their own numbering (each field's coefficients are ordered
    !! along the mesh), which makes K_ii banded. A field's unknowns are counted from the
    !! offsets, not its basis: a reduced model (model_reduction: half a beam) numbers only
    !! the right half's coefficients, still in mesh order.
    pure function inner_order(d, fixed, pinned) result(order)
        type(discretization_t), intent(in) :: d
        logical, intent(in) :: fixed(:)
        integer, intent(in) :: pinned(:)
        integer, allocatable :: order(:)
        integer :: next(FIELD_U:FIELD_PSI), n_field(FIELD_U:FIELD_PSI), f, pick, k
        real(dp) :: key, best
        allocate (order(d%nv))
        n_field = d%offset(FIELD_U + 1:FIELD_PSI + 1) - d%offset(FIELD_U:FIELD_PSI)
        next = 1
        k = 0
        merge_fields: do
            pick = 0
            best = huge(1.0_dp)
            do f = FIELD_U, FIELD_PSI
                if (next(f) > n_field(f)) cycle
                key = real(next(f) - 1, dp)/real(max(n_field(f) - 1, 1), dp)
                if (key < best) then
                    best = key
                    pick = f
                end if
            end do
            if (pick == 0) exit merge_fields
            k = k + 1
            order(k) = d%offset(pick) + next(pick)
            next(pick) = next(pick) + 1
        end do merge_fields
        order = pack(order(1:k), .not. (fixed(order(1:k)) .or. in_list(order(1:k), pinned)))
    end function inner_order

    !> Element-wise: x(i) is one of list.
    pure function in_list(x, list) result(found)
        integer, intent(in) :: x(:), list(:)
        logical :: found(size(x))
        integer :: i
        do i = 1, size(x)
            found(i) = any(list == x(i))
        end do
    end function in_list

    !> K_ii in band storage (half bandwidth from its nonzeros) and its Cholesky factor.
    subroutine factorise_inner(sys, sc)
        type(system_t), intent(in) :: sys
        type(schur_t), intent(inout) :: sc
        real(dp), allocatable :: col(:)
        integer :: i, j, info
        allocate (col(sys%nv + sys%nr), source=0.0_dp)
        sc%kd = 0
        columns: do j = 1, sc%ni
            ! inner unknowns: whole columns
            call a0_lower_column(sys, sc%inner(j), col, clear=.false.)
            do i = sc%ni, j + sc%kd + 1, -1
                if (col(sc%inner(i)) /= 0.0_dp) then
                    sc%kd = i - j
                    exit
                end if
            end do
            call a0_lower_column(sys, sc%inner(j), col, clear=.true.)
        end do columns
        allocate (sc%kband(sc%kd + 1, sc%ni))
        do j = 1, sc%ni
            call a0_lower_column(sys, sc%inner(j), col, clear=.false.)
            sc%kband(:, j) = 0.0_dp
            do i = j, min(sc%ni, j + sc%kd)
                sc%kband(1 + i - j, j) = col(sc%inner(i))
            end do
            call a0_lower_column(sys, sc%inner(j), col, clear=.true.)
        end do
        call dpbtrf('L', sc%ni, sc%kd, sc%kband, sc%kd + 1, info)
        sc%ready = info == 0
    end subroutine factorise_inner

    !> The nonzeros of C = J(inner, kept) (M^T and the K coupling to the pinned unknowns).
    subroutine coupling_nonzeros(sys, sc)
        type(system_t), intent(in) :: sys
        type(schur_t), intent(inout) :: sc
        real(dp), allocatable :: col(:)
        integer :: i, l, nnz, pass
        allocate (col(sys%nv + sys%nr), source=0.0_dp)
        passes: do pass = 1, 2      ! count, then fill
            nnz = 0
            kept_columns: do l = 1, sc%nk
                ! only the inner rows are read
                call a0_lower_column(sys, sc%kept(l), col, clear=.false.)
                inner_rows: do i = 1, sc%ni
                    if (col(sc%inner(i)) == 0.0_dp) cycle inner_rows
                    nnz = nnz + 1
                    if (pass == 1) cycle inner_rows
                    sc%c_row(nnz) = i
                    sc%c_col(nnz) = l
                    sc%c_val(nnz) = col(sc%inner(i))
                end do inner_rows
                call a0_lower_column(sys, sc%kept(l), col, clear=.true.)
            end do kept_columns
            if (pass == 1) allocate (sc%c_row(nnz), sc%c_col(nnz), sc%c_val(nnz))
        end do passes
    end subroutine coupling_nonzeros

    !> S0 = J(kept, kept) - C^T K_ii^-1 C, block_columns columns at a time, stored as its
    !! lower triangle (packed: S0 is symmetric); the pinned-pinned block exactly 0.
    subroutine form_s0(sys, sc)
        type(system_t), intent(in) :: sys
        type(schur_t), intent(inout) :: sc
        real(dp), allocatable :: wt(:, :), col(:)
        integer, allocatable :: first(:)
        integer :: j1, j2, j, k
        allocate (sc%s0(sc%nk*(sc%nk + 1)/2))
        allocate (col(sys%nv + sys%nr), source=0.0_dp)
        ! C's nonzeros come by kept column (coupling_nonzeros): those of columns >= j start
        ! at first(j)
        allocate (first(sc%nk + 1))
        k = 1
        do j = 1, sc%nk + 1
            do while (k <= size(sc%c_col))
                if (sc%c_col(k) >= j) exit
                k = k + 1
            end do
            first(j) = k
        end do
        blocks: do j1 = 1, sc%nk, block_columns
            j2 = min(sc%nk, j1 + block_columns - 1)
            ! the block's columns of C as rows (band_cholesky_solve_rows: one vector operation
            ! across the block per step of the substitution)
            allocate (wt(j2 - j1 + 1, sc%ni))
            do j = j1, j2
                call a0_lower_column(sys, sc%kept(j), col, clear=.false.)   ! kept(j:) >= kept(j)
                wt(j - j1 + 1, :) = col(sc%inner)
                sc%s0(packed_position(sc%nk, j, j):packed_position(sc%nk, sc%nk, j)) = &
                    col(sc%kept(j:))
                call a0_lower_column(sys, sc%kept(j), col, clear=.true.)
            end do
            call band_cholesky_solve_rows(sc%kband, sc%kd, wt)
            columns: do j = j1, j2
                nonzeros: do k = first(j), size(sc%c_val)
                    associate (s => sc%s0(packed_position(sc%nk, sc%c_col(k), j)))
                        s = s - sc%c_val(k)*wt(j - j1 + 1, sc%c_row(k))
                    end associate
                end do nonzeros
            end do columns
            deallocate (wt)
        end do blocks
        do j = 1, sc%n_pinned
            sc%s0(packed_position(sc%nk, j, j):packed_position(sc%nk, sc%n_pinned, j)) = 0.0_dp
        end do
    end subroutine form_s0

    !> S0 plus the set terms, scaled and factorised (LDL^T when symmetric, else LU), into a
    !! fresh fac; the kept positions marked in decoupled (if any) factorised as a block of
    !! their own, their couplings to the others dropped.
    subroutine schur_factorise(sc, st, fac, err, decoupled)
        type(schur_t), intent(in) :: sc                 !! the Schur set-up (factor of K_ii, S0)
        type(set_terms_t), intent(in) :: st             !! the set-dependent entries of the Jacobian
        type(schur_factor_t), intent(out) :: fac        !! the factorised kept block
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        logical, intent(in), optional :: decoupled(:)   !! (nk)
        integer :: i
        logical :: split
        split = .false.
        if (present(decoupled)) split = any(decoupled)
        fac%symmetric = st%symmetric
        fac%base = st
        fac%nu = 0
        fac%scale = block_scaling(sc, st)
        if (split) then
            ! each block straight from the packed S0: the whole nk x nk matrix is never held
            fac%active = pack([(i, i=1, sc%nk)], .not. decoupled)
            fac%dec = pack([(i, i=1, sc%nk)], decoupled)
            fac%n_decoupled = size(fac%dec)
            call scaled_block(sc, st, fac%scale, fac%dec, fac%lu_dec, err)
            if (.not. allocated(err)) &
                call factorise_scaled(fac%symmetric, fac%lu_dec, fac%ipiv_dec, err)
            if (.not. allocated(err)) call scaled_block(sc, st, fac%scale, fac%active, fac%lu, err)
        else
            call scaled_block(sc, st, fac%scale, [(i, i=1, sc%nk)], fac%lu, err)
        end if
        if (allocated(err)) return
        call factorise_scaled(fac%symmetric, fac%lu, fac%ipiv, err)
    end subroutine schur_factorise

    !> 1/sqrt|diagonal| (1 where 0) of S0 plus the set terms: the symmetric scaling of the
    !! kept block.
    pure function block_scaling(sc, st) result(scale)
        type(schur_t), intent(in) :: sc
        type(set_terms_t), intent(in) :: st
        real(dp) :: scale(sc%nk)
        real(dp) :: dg(sc%nk)
        integer :: i, r, c
        do i = 1, sc%nk
            dg(i) = sc%s0(packed_position(sc%nk, i, i))
        end do
        do i = 1, st%n
            r = sc%pos(st%row(i))
            c = sc%pos(st%col(i))
            if (r /= 0 .and. r == c) dg(r) = dg(r) + st%val(i)
        end do
        scale = diagonal_scaling(dg)
    end function block_scaling

    !> The scaled S0 + set terms on the kept positions idx (rows and columns; idx ascending):
    !! set terms with a row or column outside idx are left out (the couplings a decoupled
    !! factorisation drops).
    subroutine scaled_block(sc, st, scale, idx, a, err)
        type(schur_t), intent(in) :: sc
        type(set_terms_t), intent(in) :: st
        real(dp), intent(in) :: scale(:)
        integer, intent(in) :: idx(:)
        real(dp), allocatable, intent(out) :: a(:, :)
        type(error_t), allocatable, intent(out) :: err
        integer :: loc(sc%nk), i, j, r, c
        allocate (a(size(idx), size(idx)))
        if (size(idx) == sc%nk) then
            call unpack_lower(sc%s0, a)
        else
            do j = 1, size(idx)
                do i = j, size(idx)
                    a(i, j) = sc%s0(packed_position(sc%nk, idx(i), idx(j)))
                    a(j, i) = a(i, j)
                end do
            end do
        end if
        loc = 0
        loc(idx) = [(i, i=1, size(idx))]
        entries: do i = 1, st%n
            r = sc%pos(st%row(i))
            c = sc%pos(st%col(i))
            if (r == 0 .or. c == 0) cycle entries
            if (loc(r) == 0 .or. loc(c) == 0) cycle entries
            a(loc(r), loc(c)) = a(loc(r), loc(c)) + st%val(i)
        end do entries
        if (.not. all(a == a)) then
            call new_error(err, EXIT_INTERNAL, 'schur_factorise: NaN in the system matrix')
            return
        end if
        do j = 1, size(idx)
            a(:, j) = a(:, j)*scale(idx)*scale(idx(j))
        end do
    end subroutine scaled_block

    !> LDL^T (symmetric) or LU of the scaled block a, in place.
    subroutine factorise_scaled(symmetric, a, ipiv, err)
        logical, intent(in) :: symmetric
        real(dp), intent(inout) :: a(:, :)
        integer, allocatable, intent(out) :: ipiv(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: query(1)
        real(dp), allocatable :: work(:)
        integer :: n, info
        character(len=160) :: text
        n = size(a, 1)
        allocate (ipiv(n))
        if (symmetric) then
            call dsytrf('L', n, a, n, ipiv, query, -1, info)
            allocate (work(max(1, int(query(1)))))
            call dsytrf('L', n, a, n, ipiv, work, size(work), info)
        else
            call dgetrf(n, n, a, n, ipiv, info)
        end if
        if (info > 0) then
            write (text, '(a,i0,a)') 'the contact system is singular (pivot ', info, &
                ' of its Schur complement onto the tractions is 0): the structure is not '// &
                'held (rigid-body motion)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
        else if (info < 0) then
            write (text, '(a,i0)') 'dsytrf/dgetrf: illegal argument ', -info
            call new_error(err, EXIT_INTERNAL, trim(text))
        end if
    end subroutine factorise_scaled

    !> The kept block for the set terms st: a low-rank (Woodbury) update of the factorised
    !! S_base when few contact points changed their terms since it was factorised (the sets
    !! change little between Newton steps; on a decoupled base too: an update that touches a
    !! decoupled unknown is not excluded, and if the dropped couplings then keep schur_solve's
    !! refinement from converging, accurate = .false. makes the caller factorise afresh); else a new
    !! factorisation (factorised = .true.), with the candidates (global unknowns: settled
    !! lift-off tractions) decoupled (dominated) when at least nk / decouple_fraction qualify.
    !! Decoupling only replaces new factorisations: refactorising the reduced block at every
    !! step instead of updating was measured slower (output/bench/simplifications.md).
    subroutine schur_prepare(sc, st, fac, factorised, err, candidates)
        type(schur_t), intent(in) :: sc                  !! the Schur set-up (factor of K_ii, S0)
        type(set_terms_t), intent(in) :: st   !! the set-dependent entries of the Jacobian
        type(schur_factor_t), intent(inout) :: fac   !! the factorised kept block: updated or new
        logical, intent(out) :: factorised               !! a new factorisation was made
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        !> per global unknown: a settled lift-off traction
        logical, intent(in), optional :: candidates(:)
        logical, allocatable :: changed(:), decoupled(:)
        factorised = .true.
        if (allocated(fac%lu) .and. allocated(fac%base%first)) then
            if (size(fac%base%first) == size(st%first)) then
                changed = changed_points(fac%base, st)
                call low_rank_update(sc, st, changed, fac, factorised)
                if (.not. factorised) return
            end if
        end if
        allocate (decoupled(sc%nk))
        decoupled = .false.
        if (present(candidates) .and. sc%decouple .and. sc%nk >= decouple_from) &
            decoupled = dominated(sc, st, candidates)
        if (count(decoupled) < sc%nk/decouple_fraction) decoupled = .false.
        call schur_factorise(sc, st, fac, err, decoupled)
    end subroutine schur_prepare

    !> Kept positions to decouple: unknowns whose set-term diagonal is nonzero and at least
    !! dominance times their S0 diagonal, less those whose row holds a set term in the column
    !! of an unknown not decoupled (repeated until none does), in the connected groups (set
    !! terms among them) that hold at least one candidate.
    pure function dominated(sc, st, candidates) result(dec)
        type(schur_t), intent(in) :: sc
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: candidates(:)   !! global unknowns
        logical :: dec(sc%nk)
        real(dp) :: set_diag(sc%nk)
        logical :: any_candidate(sc%nk), moved
        integer :: label(sc%nk), i, r, c
        set_diag = 0.0_dp
        do i = 1, st%n
            r = sc%pos(st%row(i))
            if (r /= 0 .and. st%row(i) == st%col(i)) set_diag(r) = set_diag(r) + st%val(i)
        end do
        do i = 1, sc%nk
            dec(i) = set_diag(i) /= 0.0_dp .and. &
                     abs(set_diag(i)) >= dominance*abs(sc%s0(packed_position(sc%nk, i, i)))
            label(i) = i
        end do
        moved = .true.
        do while (moved)
            moved = .false.
            entries: do i = 1, st%n
                r = sc%pos(st%row(i))
                c = sc%pos(st%col(i))
                if (r == 0 .or. c == 0) cycle entries
                if (.not. dec(r)) cycle entries
                if (.not. dec(c)) then
                    dec(r) = .false.
                else if (label(r) /= label(c)) then
                    label(r) = min(label(r), label(c))
                    label(c) = label(r)
                else
                    cycle entries
                end if
                moved = .true.
            end do entries
        end do
        any_candidate = .false.
        do i = 1, sc%nk
            if (dec(i)) any_candidate(label(i)) = any_candidate(label(i)) .or. &
                                                  candidates(sc%kept(i))
        end do
        dec = dec .and. any_candidate(label)
    end function dominated

    !> Contact points whose set-term entries differ between a and b.
    pure function changed_points(a, b) result(changed)
        type(set_terms_t), intent(in) :: a, b
        logical :: changed(size(a%first) - 1)
        integer :: p, na, nb
        points: do p = 1, size(changed)
            na = a%first(p + 1) - a%first(p)
            nb = b%first(p + 1) - b%first(p)
            changed(p) = na /= nb
            if (changed(p) .or. na == 0) cycle points
            associate (ia => a%first(p), ib => b%first(p))
                changed(p) = any(a%row(ia:ia + na - 1) /= b%row(ib:ib + nb - 1)) .or. &
                             any(a%col(ia:ia + na - 1) /= b%col(ib:ib + nb - 1)) .or. &
                             any(a%val(ia:ia + na - 1) /= b%val(ib:ib + nb - 1))
            end associate
        end do points
    end function changed_points

    !> D, W = S_base^-1 E and the factorised capacitance I + D W(U, :) for the changed
    !! points; refactorise = .true. when the rank exceeds nk / update_fraction or the
    !! capacitance is singular.
    subroutine low_rank_update(sc, st, changed, fac, refactorise)
        type(schur_t), intent(in) :: sc
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: changed(:)
        type(schur_factor_t), intent(inout) :: fac
        logical, intent(out) :: refactorise
        type(error_t), allocatable :: err
        integer, allocatable :: local(:)
        integer :: j, info
        refactorise = .true.
        if (allocated(fac%dmat)) deallocate (fac%dmat)
        if (allocated(fac%w)) deallocate (fac%w)
        if (allocated(fac%cap)) deallocate (fac%cap)
        if (allocated(fac%cap_ipiv)) deallocate (fac%cap_ipiv)
        allocate (local(sc%nk))
        local = 0
        fac%nu = 0
        fac%upos = [integer ::]
        call touched(fac%base, changed, sc%pos, local, fac%upos)
        call touched(st, changed, sc%pos, local, fac%upos)
        if (size(fac%upos) > sc%nk/update_fraction(merge(1, 2, fac%symmetric))) return
        fac%nu = size(fac%upos)
        refactorise = .false.
        if (fac%nu == 0) return
        allocate (fac%dmat(fac%nu, fac%nu))
        fac%dmat = 0.0_dp
        call add_changed(st, changed, sc%pos, local, 1.0_dp, fac%dmat)
        call add_changed(fac%base, changed, sc%pos, local, -1.0_dp, fac%dmat)
        call cached_columns(fac, err)
        if (allocated(err)) then
            fac%nu = 0
            refactorise = .true.
            return
        end if
        fac%cap = matmul(fac%dmat, fac%w(fac%upos, :))
        do j = 1, fac%nu
            fac%cap(j, j) = fac%cap(j, j) + 1.0_dp
        end do
        allocate (fac%cap_ipiv(fac%nu))
        call dgetrf(fac%nu, fac%nu, fac%cap, fac%nu, fac%cap_ipiv, info)
        if (info /= 0) then
            fac%nu = 0
            refactorise = .true.
        end if
    end subroutine low_rank_update

    !> W = S_base^-1 E from the columns computed for earlier updates of the same base, the
    !! missing ones by one multi-column solve (the sets of later Newton steps overlap). The
    !! cache grows as columns come (doubling), up to capacity columns: allocated at capacity
    !! at once it would be 19 MB at N_e = 1000 (plate: 1201 columns of 2002) for the 10 to 20
    !! columns a case uses, the largest item of the peak memory after T's copies.
    subroutine cached_columns(fac, err)
        type(schur_factor_t), intent(inout) :: fac
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: fresh(:, :), grown(:, :)
        integer, allocatable :: missing(:)
        integer :: nk, j, capacity, room
        nk = size(fac%scale)
        capacity = max(min(nk, 3*nk/update_fraction(2)), fac%nu)
        if (.not. allocated(fac%cache_col)) then
            allocate (fac%cache_col(nk), fac%w_cache(nk, 0))
            fac%cache_col = 0
            fac%n_cached = 0
        end if
        missing = pack(fac%upos, fac%cache_col(fac%upos) == 0)
        if (fac%n_cached + size(missing) > capacity) then
            fac%cache_col = 0
            fac%n_cached = 0
            missing = fac%upos
        end if
        if (fac%n_cached + size(missing) > size(fac%w_cache, 2)) then
            room = min(capacity, max(2*size(fac%w_cache, 2), fac%n_cached + size(missing), 16))
            allocate (grown(nk, room))
            grown(:, 1:fac%n_cached) = fac%w_cache(:, 1:fac%n_cached)
            call move_alloc(grown, fac%w_cache)
        end if
        allocate (fresh(nk, size(missing)))
        fresh = 0.0_dp
        do j = 1, size(missing)
            fresh(missing(j), j) = 1.0_dp
        end do
        if (size(missing) > 0) call kept_solve(fac, fresh, err)
        if (allocated(err)) return
        do j = 1, size(missing)
            fac%n_cached = fac%n_cached + 1
            fac%w_cache(:, fac%n_cached) = fresh(:, j)
            fac%cache_col(missing(j)) = fac%n_cached
        end do
        fac%w = fac%w_cache(:, fac%cache_col(fac%upos))
    end subroutine cached_columns

    !> Kept positions of the entries of the changed points, appended to upos once each
    !! (local: position -> index in upos).
    pure subroutine touched(st, changed, pos, local, upos)
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: changed(:)
        integer, intent(in) :: pos(:)
        integer, intent(inout) :: local(:)
        integer, allocatable, intent(inout) :: upos(:)
        integer :: p, i, k, q(2)
        points: do p = 1, size(changed)
            if (.not. changed(p)) cycle points
            entries: do i = st%first(p), st%first(p + 1) - 1
                q = [pos(st%row(i)), pos(st%col(i))]
                do k = 1, 2
                    if (q(k) == 0) cycle
                    if (local(q(k)) /= 0) cycle
                    upos = [upos, q(k)]
                    local(q(k)) = size(upos)
                end do
            end do entries
        end do points
    end subroutine touched

    !> dmat += factor * (entries of the changed points) in the local numbering.
    pure subroutine add_changed(st, changed, pos, local, factor, dmat)
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: changed(:)
        integer, intent(in) :: pos(:), local(:)
        real(dp), intent(in) :: factor
        real(dp), intent(inout) :: dmat(:, :)
        integer :: p, i, r, c
        points: do p = 1, size(changed)
            if (.not. changed(p)) cycle points
            entries: do i = st%first(p), st%first(p + 1) - 1
                r = pos(st%row(i))
                c = pos(st%col(i))
                if (r == 0 .or. c == 0) cycle entries
                dmat(local(r), local(c)) = dmat(local(r), local(c)) + factor*st%val(i)
            end do entries
        end do points
    end subroutine add_changed

    !> g = S_base^-1 g (columns) with the scaled factors (decoupled: block by block).
    subroutine kept_solve(fac, g, err)
        type(schur_factor_t), intent(in) :: fac
        real(dp), intent(inout) :: g(:, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: h(:, :)
        integer :: j
        do j = 1, size(g, 2)
            g(:, j) = g(:, j)*fac%scale
        end do
        if (fac%n_decoupled > 0) then
            h = g(fac%active, :)
            call factored_solve(fac%symmetric, fac%lu, fac%ipiv, h, err)
            g(fac%active, :) = h
            if (allocated(err)) return
            h = g(fac%dec, :)
            call factored_solve(fac%symmetric, fac%lu_dec, fac%ipiv_dec, h, err)
            g(fac%dec, :) = h
        else
            call factored_solve(fac%symmetric, fac%lu, fac%ipiv, g, err)
        end if
        if (allocated(err)) return
        do j = 1, size(g, 2)
            g(:, j) = g(:, j)*fac%scale
        end do
    end subroutine kept_solve

    !> g = a^-1 g, a factorised by factorise_scaled.
    subroutine factored_solve(symmetric, a, ipiv, g, err)
        logical, intent(in) :: symmetric
        real(dp), intent(in) :: a(:, :)
        integer, intent(in) :: ipiv(:)
        real(dp), intent(inout) :: g(:, :)
        type(error_t), allocatable, intent(out) :: err
        integer :: n, info
        character(len=80) :: text
        n = size(g, 1)
        if (symmetric) then
            call dsytrs('L', n, size(g, 2), a, n, ipiv, g, n, info)
        else
            call dgetrs('N', n, size(g, 2), a, n, ipiv, g, n, info)
        end if
        if (info /= 0) then
            write (text, '(a,i0)') 'dsytrs/dgetrs: illegal argument ', -info
            call new_error(err, EXIT_INTERNAL, trim(text))
        end if
    end subroutine factored_solve

    !> Solve J x = b (J = A0 + set terms, fixed unknowns with identity rows) with the
    !! factorised Schur complement; two steps of iterative refinement with J itself. With a
    !! low-rank update or decoupled unknowns in use, the factorisation is J's preconditioner:
    !! refinement until a step changes x by at most refine_limit of max |x|, or stops shrinking
    !! (but does not grow) below floor_limit (the round-off of J x - b in double: the plate at
    !! N_e = 1000 with 373 decoupled tractions shrank 15 times per step to 2e-10, then wandered
    !! between 1e-10 and 3e-10, and demanding 1e-10 there cost a fresh factorisation, 130 ms,
    !! where a step costs 3 ms), up to max_update_steps; accurate is false if neither
    !! happened, and the caller factorises afresh.
    !! Refinement does not stop after one converged step: that saves 10 % of the work at
    !! N_e = 20 but costs linear solves on a Newton path that cycles near a kink (doc/CHOICES.md,
    !! Newton solver).
    subroutine schur_solve(sys, sc, st, fac, b, x, err, accurate)
        type(system_t), intent(in) :: sys                !! the assembled system (A0, q)
        type(schur_t), intent(in) :: sc                  !! the Schur set-up (factor of K_ii, S0)
        type(set_terms_t), intent(in) :: st   !! the set-dependent entries of the Jacobian
        type(schur_factor_t), intent(in) :: fac          !! the factorised kept block
        real(dp), intent(in) :: b(:)                     !! right-hand side
        real(dp), intent(out) :: x(:)                    !! the solution of J x = b
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        !> the refinement converged (else factorise afresh)
        logical, intent(out), optional :: accurate
        real(dp), parameter :: refine_limit = 1.0e-10_dp
        real(dp), parameter :: floor_limit = 1.0e-9_dp
        integer, parameter :: max_update_steps = 12
        real(dp), allocatable :: dx(:)
        real(dp) :: change, previous
        logical :: converged, inexact
        integer :: step
        if (.not. all(b == b)) then
            call new_error(err, EXIT_INTERNAL, 'schur_solve: NaN in the right-hand side')
            return
        end if
        call apply_inverse(sc, fac, b, x, err)
        if (allocated(err)) return
        allocate (dx(size(x)))
        converged = .false.
        inexact = fac%nu > 0 .or. fac%n_decoupled > 0
        previous = huge(1.0_dp)
        refinement: do step = 1, merge(max_update_steps, 2, inexact)
            call apply_inverse(sc, fac, b - jacobian_times(sys, sc, st, x), dx, err)
            if (allocated(err)) return
            x = x + dx
            change = maxval(abs(dx))/max(maxval(abs(x)), tiny(1.0_dp))
            ! stagnation: no longer halving but not growing (a slowly diverging or wandering
            ! refinement is not accurate), at the round-off level
            converged = change <= refine_limit .or. (change <= floor_limit .and. &
                                                     change > 0.5_dp*previous .and. &
                                                     change <= previous)
            if (step >= 2 .and. converged) exit refinement
            previous = change
        end do refinement
        if (present(accurate)) accurate = .not. inexact .or. converged
        if (.not. all(abs(x) <= huge(1.0_dp))) then
            call new_error(err, EXIT_ANALYSIS, 'the contact system is numerically singular '// &
                           '(non-finite solution)')
        end if
    end subroutine schur_solve

    !> x = J^-1 b by block elimination: inner, kept (factorised), inner again.
    subroutine apply_inverse(sc, fac, b, x, err)
        type(schur_t), intent(in) :: sc
        type(schur_factor_t), intent(in) :: fac
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: x(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: y(:, :), g(:, :), z(:, :)
        integer :: k, info
        character(len=80) :: text
        y = reshape(b(sc%inner), [sc%ni, 1])
        call inner_solve(sc, y)
        g = reshape(b(sc%kept), [sc%nk, 1])
        do k = 1, size(sc%c_val)
            g(sc%c_col(k), 1) = g(sc%c_col(k), 1) - sc%c_val(k)*y(sc%c_row(k), 1)
        end do
        call kept_solve(fac, g, err)
        if (allocated(err)) return
        if (fac%nu > 0) then
            z = reshape(matmul(fac%dmat, g(fac%upos, 1)), [fac%nu, 1])
            call dgetrs('N', fac%nu, 1, fac%cap, fac%nu, fac%cap_ipiv, z, fac%nu, info)
            if (info /= 0) then
                write (text, '(a,i0)') 'dgetrs: illegal argument ', -info
                call new_error(err, EXIT_INTERNAL, trim(text))
                return
            end if
            g(:, 1) = g(:, 1) - matmul(fac%w, z(:, 1))
        end if
        y(:, 1) = b(sc%inner)
        do k = 1, size(sc%c_val)
            y(sc%c_row(k), 1) = y(sc%c_row(k), 1) - sc%c_val(k)*g(sc%c_col(k), 1)
        end do
        call inner_solve(sc, y)
        x = b
        x(sc%inner) = y(:, 1)
        x(sc%kept) = g(:, 1)
    end subroutine apply_inverse

    !> y <- K_ii^-1 y by the banded Cholesky factor (band_solve: contiguous loops, not dpbtrs,
    !! whose per-row BLAS calls cost more than the arithmetic on these narrow bands).
    pure subroutine inner_solve(sc, y)
        type(schur_t), intent(in) :: sc
        real(dp), intent(inout) :: y(:, :)
        call band_cholesky_solve(sc%kband, sc%kd, y)
    end subroutine inner_solve

    !> J x: A0 x with the fixed unknowns' rows and columns replaced by the identity, plus
    !! the set terms.
    function jacobian_times(sys, sc, st, x) result(jx)
        type(system_t), intent(in) :: sys
        type(schur_t), intent(in) :: sc
        type(set_terms_t), intent(in) :: st
        real(dp), intent(in) :: x(:)
        real(dp), allocatable :: jx(:), xf(:)
        integer :: i
        xf = merge(0.0_dp, x, sc%fixed)
        jx = a0_times(sys, xf, xf)
        entries: do i = 1, st%n
            if (sc%fixed(st%row(i)) .or. sc%fixed(st%col(i))) cycle entries
            jx(st%row(i)) = jx(st%row(i)) + st%val(i)*x(st%col(i))
        end do entries
        where (sc%fixed) jx = x
    end function jacobian_times
end module schur_solver
