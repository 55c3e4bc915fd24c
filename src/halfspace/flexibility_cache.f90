!> The half-space flexibility T of recent cases, for the next cases of a sweep with the same
!! interface discretisation and soil. T depends only on the traction bases (mesh, family,
!! knots), the soil (G_f, nu_f) and, for the beam, the width b: a sweep over the structure
!! (rho, zeta), the friction, the regularisation or the loads on one mesh assembles it once
!! per mesh instead of once per case (and the error estimate's coarse meshes with it). The
!! assembly is deterministic (the same T on any number of threads, bit for bit), so a case
!! gets the same T, and the same answer, with or without the cache.
!!
!! The cache is off unless the driver enables it (a deck with more than one case): a single
!! case would only hold one more copy of T. It keeps at most max_entries matrices of at most
!! max_unknowns tractions each (2.9 MB apiece): above that T is a small part of a case (under
!! 6 % from N_e = 500 on, output/bench/phases.md) and the copy would weigh on the memory
!! target. Cases of a sweep run in parallel threads: every look-up and store is one critical
!! section, and a look-up copies the matrix out inside it.
module flexibility_cache
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t, MODEL_BEAM, FIELD_SX, FIELD_SZ, soil_shear_modulus
    use discretization, only: discretization_t
    use shape_functions, only: basis_t
    use halfspace_operator, only: assemble_flexibility
    implicit none
    private
    public :: flexibility_of, enable_flexibility_cache, flexibility_cache_hits

    integer, parameter :: max_entries = 4      !! a mesh and its estimate's N_e/2 and N_e/4
    integer, parameter :: max_unknowns = 600   !! tractions (nr); T of nr^2 numbers

    !> What T depends on.
    type :: key_t
        integer :: kind = 0
        real(dp) :: g_f = 0.0_dp, nu_f = 0.0_dp, b = 0.0_dp
        type(basis_t) :: bx, bz
    end type key_t

    type :: entry_t
        type(key_t) :: key
        real(dp), allocatable :: t(:, :)
        integer :: last_use = 0
    end type entry_t

    ! the cache's state: one per process, shared by the threads of a sweep (critical sections)
    logical, save :: enabled = .false.
    type(entry_t), save :: entries(max_entries)
    integer, save :: n_entries = 0, clock = 0, hits = 0

contains

    !> Switch the cache on (a deck with several cases) or off; off empties it.
    subroutine enable_flexibility_cache(on)
        logical, intent(in) :: on
        integer :: k
        !$omp critical (flexibility_cache)
        enabled = on
        if (.not. on) then
            do k = 1, n_entries
                if (allocated(entries(k)%t)) deallocate (entries(k)%t)
            end do
            n_entries = 0
        end if
        hits = 0
        !$omp end critical (flexibility_cache)
    end subroutine enable_flexibility_cache

    !> Look-ups answered from the cache since it was enabled.
    integer function flexibility_cache_hits() result(n)
        !$omp critical (flexibility_cache)
        n = hits
        !$omp end critical (flexibility_cache)
    end function flexibility_cache_hits

    !> T of the case (m, d): a copy of a cached one with the same key, else assembled (and
    !! cached when the cache is on and T is small enough).
    subroutine flexibility_of(m, d, t_mat, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        type(error_t), allocatable, intent(out) :: err
        type(key_t) :: key
        logical :: use_cache, found
        !$omp critical (flexibility_cache)
        use_cache = enabled .and. d%nr <= max_unknowns
        !$omp end critical (flexibility_cache)
        found = .false.
        if (use_cache) then
            key = key_of(m, d)
            !$omp critical (flexibility_cache)
            call look_up(key, t_mat, found)
            !$omp end critical (flexibility_cache)
        end if
        if (found) return
        call assemble_flexibility(m, d, t_mat, err)
        if (allocated(err) .or. .not. use_cache) return
        !$omp critical (flexibility_cache)
        call store(key, t_mat)
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
    end function key_of

    !> Inside the critical section: t_mat from the entry with this key, if any.
    subroutine look_up(key, t_mat, found)
        type(key_t), intent(in) :: key
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        logical, intent(out) :: found
        integer :: k
        found = .false.
        do k = 1, n_entries
            if (.not. same_key(entries(k)%key, key)) cycle
            t_mat = entries(k)%t
            clock = clock + 1
            entries(k)%last_use = clock
            hits = hits + 1
            found = .true.
            return
        end do
    end subroutine look_up

    !> Inside the critical section: a new entry, in place of the least recently used when full.
    subroutine store(key, t_mat)
        type(key_t), intent(in) :: key
        real(dp), intent(in) :: t_mat(:, :)
        integer :: k
        do k = 1, n_entries
            if (same_key(entries(k)%key, key)) return      ! another thread was first
        end do
        if (n_entries < max_entries) then
            n_entries = n_entries + 1
            k = n_entries
        else
            k = minloc(entries(1:n_entries)%last_use, dim=1)
        end if
        clock = clock + 1
        entries(k) = entry_t(key=key, t=t_mat, last_use=clock)
    end subroutine store

    pure logical function same_key(a, b)
        type(key_t), intent(in) :: a, b
        same_key = a%kind == b%kind .and. a%g_f == b%g_f .and. a%nu_f == b%nu_f .and. &
                   a%b == b%b .and. same_basis(a%bx, b%bx) .and. same_basis(a%bz, b%bz)
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
