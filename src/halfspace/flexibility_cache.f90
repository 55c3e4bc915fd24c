!> The half-space flexibility T of recent cases, for the next cases of a sweep with the same
!! interface discretisation and ground. T depends only on the traction bases (mesh, family,
!! knots), the ground (G_f, nu_f; and for layered ground every layer's thickness, moduli and
!! nu and the base) and, for the beam, the width b: a sweep over the structure
!! (rho, zeta), the friction, the regularisation or the loads on one mesh assembles it once
!! per mesh instead of once per case (and the error estimate's coarse meshes with it). The
!! assembly is deterministic (the same T on any number of threads, bit for bit), so a case
!! gets the same T, and the same answer, with or without the cache.
!!
!! The cache is an object owned by the run (analysis_driver: one per deck, enabled when the
!! deck has more than one case: a single case would only hold one more copy of T) and passed
!! down to where T is built (contact_system::build_system); a solve without a cache assembles
!! T. It keeps at most max_entries matrices of at most max_unknowns tractions each (2.9 MB
!! apiece): above that T is a small part of a case (under 6 % from N_e = 500 on,
!! output/bench/phases.md) and the copy would weigh on the memory target. Cases of a sweep
!! run in parallel threads sharing the run's cache: every look-up and store is one critical
!! section, and a look-up copies the matrix out inside it.
module flexibility_cache
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t, MODEL_BEAM, FIELD_SX, FIELD_SZ, soil_shear_modulus, &
                     GROUND_LAYERED, layer_profile
    use discretization, only: discretization_t
    use shape_functions, only: basis_t
    use halfspace_operator, only: assemble_flexibility
    implicit none
    private
    public :: flexibility_of, new_flexibility_cache, flexibility_cache_hits

    !> a case's mesh and its estimate's meshes (N_e/2, N_e/4, 2 N_e, N_e - 1 and N_e + 1 with
    !! a concentrated load inside the base or above 128 elements, and 4 N_e where 16 <= N_e <=
    !! 128: up to seven),
    !! for up to four grounds (or beam widths) of a sweep: a sweep over two grounds, such as
    !! the 1000-case benchmark, needs six to fourteen, and four entries evicted each before
    !! its next use. At most 28 T of 600^2 numbers: 81 MB (a T of more than max_unknowns
    !! tractions is not kept)
    integer, parameter :: max_entries = 28
    integer, parameter :: max_unknowns = 600   !! tractions (nr); T of nr^2 numbers

    !> What T depends on.
    type :: key_t
        integer :: kind = 0
        real(dp) :: g_f = 0.0_dp, nu_f = 0.0_dp, b = 0.0_dp
        type(basis_t) :: bx, bz
        !> layered ground: (thickness, E top, E bottom, nu) of each layer, then base kind,
        !! E_b and nu_b; empty for the homogeneous half-space
        real(dp), allocatable :: layers(:)
    end type key_t

    type :: entry_t
        type(key_t) :: key
        real(dp), allocatable :: t(:, :)
        integer :: last_use = 0
    end type entry_t

    !> A run's cache of T: shared by the threads of a sweep (critical sections).
    type, public :: flexibility_cache_t
        private
        logical :: enabled = .false.
        type(entry_t) :: entries(max_entries)
        integer :: n_entries = 0, clock = 0, hits = 0
    end type flexibility_cache_t

contains

    !> An empty cache, on (a deck with several cases) or off (it then stores nothing).
    pure function new_flexibility_cache(on) result(cache)
        logical, intent(in) :: on                  !! keep matrices for later cases
        type(flexibility_cache_t) :: cache
        cache%enabled = on
    end function new_flexibility_cache

    !> Look-ups answered from the cache since it was made.
    integer function flexibility_cache_hits(cache) result(n)
        type(flexibility_cache_t), intent(in) :: cache   !! the run's cache
        !$omp critical (flexibility_cache)
        n = cache%hits
        !$omp end critical (flexibility_cache)
    end function flexibility_cache_hits

    !> T of the case (m, d): a copy of a cached one with the same key, else assembled (and
    !! cached when the cache is on and T is small enough); without a cache, assembled.
    subroutine flexibility_of(m, d, t_mat, err, cache)
        type(model_t), intent(in) :: m                   !! structure kind, width and ground
        type(discretization_t), intent(in) :: d          !! the traction bases
        real(dp), allocatable, intent(out) :: t_mat(:, :)  !! T (nr x nr)
        type(error_t), allocatable, intent(out) :: err   !! the assembly failed
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache
        type(key_t) :: key
        logical :: use_cache, found
        use_cache = .false.
        if (present(cache)) then
            !$omp critical (flexibility_cache)
            use_cache = cache%enabled .and. d%nr <= max_unknowns
            !$omp end critical (flexibility_cache)
        end if
        found = .false.
        if (use_cache) then
            key = key_of(m, d)
            !$omp critical (flexibility_cache)
            call look_up(cache, key, t_mat, found)
            !$omp end critical (flexibility_cache)
        end if
        if (found) return
        call assemble_flexibility(m, d, t_mat, err)
        if (allocated(err) .or. .not. use_cache) return
        !$omp critical (flexibility_cache)
        call store(cache, key, t_mat)
        !$omp end critical (flexibility_cache)
    end subroutine flexibility_of

    function key_of(m, d) result(key)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(key_t) :: key
        key%kind = m%structure%kind
        key%g_f = soil_shear_modulus(m%ground)
        key%nu_f = m%ground%nu_f
        if (m%structure%kind == MODEL_BEAM) key%b = m%structure%b
        key%bx = d%basis(FIELD_SX)
        key%bz = d%basis(FIELD_SZ)
        key%layers = ground_key(m)
    end function key_of

    !> The layered ground as numbers (key_t%layers); empty for the homogeneous half-space.
    pure function ground_key(m) result(v)
        type(model_t), intent(in) :: m
        real(dp), allocatable :: v(:)
        real(dp), allocatable :: thickness(:), e_top(:), e_bottom(:), poisson(:)
        real(dp) :: e_base
        allocate (v(0))
        if (m%ground%kind /= GROUND_LAYERED) return
        call layer_profile(m%ground, thickness, e_top, e_bottom, poisson, e_base)
        v = [thickness, e_top, e_bottom, poisson, real(m%ground%base, dp), e_base, &
             m%ground%nu_base]
    end function ground_key

    !> Inside the critical section: t_mat from the entry with this key, if any.
    subroutine look_up(cache, key, t_mat, found)
        type(flexibility_cache_t), intent(inout) :: cache
        type(key_t), intent(in) :: key
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        logical, intent(out) :: found
        integer :: k
        found = .false.
        do k = 1, cache%n_entries
            if (.not. same_key(cache%entries(k)%key, key)) cycle
            t_mat = cache%entries(k)%t
            cache%clock = cache%clock + 1
            cache%entries(k)%last_use = cache%clock
            cache%hits = cache%hits + 1
            found = .true.
            return
        end do
    end subroutine look_up

    !> Inside the critical section: a new entry, in place of the least recently used when full.
    subroutine store(cache, key, t_mat)
        type(flexibility_cache_t), intent(inout) :: cache
        type(key_t), intent(in) :: key
        real(dp), intent(in) :: t_mat(:, :)
        integer :: k
        do k = 1, cache%n_entries
            if (same_key(cache%entries(k)%key, key)) return      ! another thread was first
        end do
        if (cache%n_entries < max_entries) then
            cache%n_entries = cache%n_entries + 1
            k = cache%n_entries
        else
            k = minloc(cache%entries(1:cache%n_entries)%last_use, dim=1)
        end if
        cache%clock = cache%clock + 1
        cache%entries(k) = entry_t(key=key, t=t_mat, last_use=cache%clock)
    end subroutine store

    pure logical function same_key(a, b)
        type(key_t), intent(in) :: a, b
        same_key = a%kind == b%kind .and. a%g_f == b%g_f .and. a%nu_f == b%nu_f .and. &
                   a%b == b%b .and. same_basis(a%bx, b%bx) .and. same_basis(a%bz, b%bz) .and. &
                   same_reals(a%layers, b%layers)
    end function same_key

    !> Exactly the same functions: family, numbering and every node and knot.
    pure logical function same_basis(a, b)
        type(basis_t), intent(in) :: a, b
        same_basis = a%family == b%family .and. a%ne == b%ne .and. a%n_dof == b%n_dof .and. &
                     a%n_local == b%n_local .and. a%degree == b%degree
        if (.not. same_basis) return
        same_basis = same_reals(a%x, b%x) .and. same_reals(a%knots, b%knots)
        if (.not. same_basis) return
        if (allocated(a%span) .neqv. allocated(b%span)) then
            same_basis = .false.
        else if (allocated(a%span)) then
            same_basis = size(a%span) == size(b%span)
            if (same_basis) same_basis = all(a%span == b%span)
        end if
    end function same_basis

    pure logical function same_reals(a, b)
        real(dp), allocatable, intent(in) :: a(:), b(:)
        if (allocated(a) .neqv. allocated(b)) then
            same_reals = .false.
        else if (.not. allocated(a)) then
            same_reals = .true.
        else
            same_reals = size(a) == size(b)
            if (same_reals) same_reals = all(a == b)
        end if
    end function same_reals
end module flexibility_cache
