!> What a case needs, estimated from the deck before anything is solved, and the refusal of a
!! case the machine cannot hold (exit status 1 with the need and the limit) instead of an
!! allocation failure or a swap storm in the middle of a run.
!!
!! Memory, from peak resident sizes (GNU time) of one case per model kind and interpolation,
!! less the process's own 11 MB (doc/CHOICES.md, "Memory model"; scripts/memory_table.sh).
!! The Newton method (the default) keeps its dense blocks on the tractions: the peak grows
!! with nr^2, nr the traction unknowns, at 14 to 19.9 bytes per nr^2 from N_e = 1000 on, for
!! the beam and the plate alike (P1, P2, S2; the same in n^2, n all unknowns, ranges from 2.2
!! to 5.6 bytes, P2 tractions on P1 displacements the most); the estimate takes 21 nr^2 bytes
!! + 20 MB. The two-loop method keeps a few dense copies of the system of n unknowns (17 to
!! 18 bytes per n^2); the estimate takes 20 n^2 + 20 MB. Time: the Newton solve of the
!! frictional plate takes 0.9 s at n = 5005 on the 2-core development machine
!! (output/bench/phases_run.md), i.e. about 0.5 s at n = 4000, scaling as n^3 (a rough
!! guide, printed with the progress, never used to refuse). The limit is 80 % of the memory
!! the system reports available (MemAvailable of /proc/meminfo; 8 GB when it cannot be
!! read), shared by the cases a sweep solves at once.
module resource_limits
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INPUT
    use model, only: model_t, METHOD_TWOLOOP
    use discretization, only: discretization_t, new_discretization
    implicit none
    private

    real(dp), parameter :: newton_bytes_per_nr2 = 21.0_dp  !! Newton: per traction unknown^2
    real(dp), parameter :: dense_bytes_per_n2 = 20.0_dp    !! two-loop: per unknown^2
    real(dp), parameter :: base_bytes = 20.0e6_dp
    real(dp), parameter :: seconds_at_4000 = 0.5_dp
    real(dp), parameter :: usable_fraction = 0.8_dp
    real(dp), parameter :: fallback_available = 8.0e9_dp

    public :: case_unknowns, memory_needed, case_memory, time_needed, memory_available, &
              check_memory

contains

    !> Unknowns of the case (displacements + tractions), from its discretisation; with ADAPT,
    !! of the largest mesh it may reach (max_elements).
    integer function case_unknowns(m) result(n)
        type(model_t), intent(in) :: m   !! the case (its whole model is discretised)
        integer :: nr
        call case_size(m, n, nr)
    end function case_unknowns

    !> All unknowns n and traction unknowns nr of the case (0 if it cannot be discretised).
    subroutine case_size(m, n, nr)
        type(model_t), intent(in) :: m
        integer, intent(out) :: n, nr
        type(discretization_t) :: d
        type(error_t), allocatable :: err
        type(model_t) :: mc
        mc = m
        if (m%mesh%adapt_tol > 0.0_dp) mc%mesh%ne = max(m%mesh%ne, m%mesh%adapt_max_ne)
        call new_discretization(mc, d, err)
        n = 0
        nr = 0
        if (allocated(err)) return
        n = d%n
        nr = d%nr
    end subroutine case_size

    !> Peak memory of a case of n unknowns, nr of them tractions [bytes] (module header).
    pure real(dp) function memory_needed(n, nr, dense) result(bytes)
        integer, intent(in) :: n                 !! all unknowns
        integer, intent(in) :: nr                !! traction unknowns
        logical, intent(in) :: dense             !! the two-loop method (dense system)
        if (dense) then
            bytes = dense_bytes_per_n2*real(n, dp)**2 + base_bytes
        else
            bytes = newton_bytes_per_nr2*real(nr, dp)**2 + base_bytes
        end if
    end function memory_needed

    !> Peak memory of the case m [bytes].
    real(dp) function case_memory(m) result(bytes)
        type(model_t), intent(in) :: m   !! the model
        integer :: n, nr
        call case_size(m, n, nr)
        bytes = memory_needed(n, nr, m%solver%method == METHOD_TWOLOOP)
    end function case_memory

    pure real(dp) function time_needed(n) result(seconds)
        integer, intent(in) :: n   !! unknowns of the case
        seconds = seconds_at_4000*(real(n, dp)/4000.0_dp)**3
    end function time_needed

    !> MemAvailable of /proc/meminfo in bytes (the fallback when it cannot be read).
    real(dp) function memory_available() result(bytes)
        character(len=200) :: line
        integer :: u, ios
        real(dp) :: kb
        bytes = fallback_available
        open (newunit=u, file='/proc/meminfo', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'MemAvailable:') /= 1) cycle
            read (line(14:), *, iostat=ios) kb
            if (ios == 0 .and. kb > 0.0_dp) bytes = kb*1024.0_dp
            exit
        end do
        close (u)
    end function memory_available

    !> Refuse a case whose estimated memory, times the cases solved at once, exceeds the
    !! usable memory.
    subroutine check_memory(m, at_once, available, err)
        type(model_t), intent(in) :: m          !! the model
        integer, intent(in) :: at_once          !! cases of a sweep solved at the same time
        real(dp), intent(in) :: available       !! bytes
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp) :: need, limit
        character(len=400) :: text
        integer :: n, nr
        call case_size(m, n, nr)
        need = memory_needed(n, nr, m%solver%method == METHOD_TWOLOOP)*real(max(at_once, 1), dp)
        limit = usable_fraction*available
        if (need <= limit) return
        write (text, '(a,i0,a,i0,a,f0.1,a,i0,a,f0.1,a)') 'N_e = ', &
            merge(max(m%mesh%ne, m%mesh%adapt_max_ne), m%mesh%ne, m%mesh%adapt_tol > 0.0_dp), &
                ' gives ', n, &
            ' unknowns and needs about ', need/1.0e9_dp, ' GB (', max(at_once, 1), &
            ' case(s) at once), more than the ', limit/1.0e9_dp, ' GB usable on this machine '// &
            '(80 % of the memory available): use fewer elements'
        ! advice that applies: grading only where the mesh is uniform, fewer jobs only where
        ! several cases run at once
        if (trim(m%mesh%grading) == 'UNIFORM') text = trim(text)// &
            ' (a graded mesh, MESH EDGES or '// &
            'LOADS, needs fewer for the same accuracy)'
        if (at_once > 1) text = trim(text)//', or fewer --jobs'
        call new_error(err, EXIT_INPUT, trim(text))
    end subroutine check_memory
end module resource_limits
