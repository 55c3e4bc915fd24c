!> bench_tabulation: processor time of the station tabulation (station_results::tabulate, whose
!! cost is the half-space surface displacement at every station) and of the whole case
!! (analysis_driver::run_case: solve, tabulation, summary, error estimate, files; no figure)
!! for the plate and beam decks at several N_e; and the station displacements themselves, written
!! to files so that two builds (before and after a change) can be compared. Not a test: it
!! measures.
!!
!!     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile release \
!!         --example bench_tabulation [-- OUTDIR [N_e ...]]
!!
!! (default OUTDIR output/bench/tabulation_run, N_e 20 100 500 1000). Writes OUTDIR/times.md
!! (one row per case and mesh) and OUTDIR/<deck>_<N_e>.txt: station x, u_f, w_f (es25.17).
!! It uses only procedures whose interfaces predate the fast tabulation, so the same file
!! builds in a checkout of the older commit.
program bench_tabulation
    use iso_fortran_env, only: output_unit, compiler_version
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t
    use deck_reader, only: deck_t, read_deck, case_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact
    use halfspace_operator, only: surface_displacement
    use station_results, only: station_table_t, tabulate
    use station_columns, only: Q_X
    use analysis_driver, only: case_result_t, run_case
    implicit none

    character(len=*), parameter :: decks(2) = [character(len=24) :: 'input/plate_nondim.dat', &
                                               'input/beam_nondim.dat']
    character(len=*), parameter :: stems(2) = [character(len=5) :: 'plate', 'beam']
    character(len=256) :: out_dir
    integer, allocatable :: ne_list(:)
    integer :: k, i, u

    call start_program()
    call read_arguments(out_dir, ne_list)
    call execute_command_line('mkdir -p '//trim(out_dir)//'/tmp')
    open (newunit=u, file=trim(out_dir)//'/times.md', status='replace', action='write')
    write (u, '(a)') '<!-- '//compiler_version()//'; load before: '//load_average()//' -->'
    write (u, '(a)') '| case | N_e | stations | tabulation ms | reps | whole case ms | reps |'
    write (u, '(a)') '|---|---:|---:|---:|---:|---:|---:|'
    do k = 1, 2
        do i = 1, size(ne_list)
            call measure(k, ne_list(i), trim(out_dir), u)
        end do
    end do
    write (u, '(a)') '<!-- load after: '//load_average()//' -->'
    close (u)
    call execute_command_line('rm -rf '//trim(out_dir)//'/tmp')

contains

    subroutine read_arguments(out_dir, ne_list)
        character(len=*), intent(out) :: out_dir
        integer, allocatable, intent(out) :: ne_list(:)
        character(len=32) :: arg
        integer :: i
        out_dir = 'output/bench/tabulation_run'
        if (command_argument_count() >= 1) call get_command_argument(1, out_dir)
        if (command_argument_count() < 2) then
            ne_list = [20, 100, 500, 1000]
            return
        end if
        allocate (ne_list(command_argument_count() - 1))
        do i = 2, command_argument_count()
            call get_command_argument(i, arg)
            read (arg, *) ne_list(i - 1)
        end do
    end subroutine read_arguments

    !> Processor time (the machine is shared: wall time would count the other jobs).
    real(dp) function now()
        call cpu_time(now)
    end function now

    function load_average() result(text)
        character(len=:), allocatable :: text
        character(len=64) :: line
        integer :: v, ios
        open (newunit=v, file='/proc/loadavg', action='read', iostat=ios)
        line = '?'
        if (ios == 0) read (v, '(a)', iostat=ios) line
        if (ios == 0) close (v)
        text = trim(line)
    end function load_average

    !> One deck at one mesh: solve once, time tabulate (least of the repetitions), time the whole
    !! case, write the station displacements.
    subroutine measure(k, ne, dir, u)
        integer, intent(in) :: k, ne, u
        character(len=*), intent(in) :: dir
        type(deck_t) :: deck
        type(model_t) :: m, mc
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(case_result_t) :: res
        type(error_t), allocatable :: err
        character(len=:), allocatable :: label
        real(dp), allocatable :: u_f(:), w_f(:)
        real(dp) :: t0, t_tab, t_case
        integer :: rep, reps_tab, reps_case, v, i
        character(len=16) :: name
        call read_deck(decks(k), deck, err)
        if (allocated(err)) error stop 'bench_tabulation: cannot read the deck'
        call case_model(deck, 1, m, label, err)
        if (allocated(err)) error stop 'bench_tabulation: cannot build the case'
        m%mesh%ne = ne
        call new_discretization(m, d, err)
        if (allocated(err)) error stop 'bench_tabulation: discretisation failed'
        call solve_contact(m, d, sol, err)
        if (allocated(err)) error stop 'bench_tabulation: solve failed'
        reps_tab = max(5, min(200, 2000000/(ne*ne)))
        t_tab = huge(1.0_dp)
        do rep = 1, reps_tab
            t0 = now()
            call tabulate(m, d, sol, tab, err)
            t_tab = min(t_tab, now() - t0)
            if (allocated(err)) error stop 'bench_tabulation: tabulate failed'
        end do
        reps_case = max(3, min(20, 200000/(ne*ne)))
        t_case = huge(1.0_dp)
        do rep = 1, reps_case
            mc = m
            t0 = now()
            call run_case(deck, mc, label, dir//'/tmp', 'case', .false., .true., -1, res)
            t_case = min(t_case, now() - t0)
            if (res%status /= 0) error stop 'bench_tabulation: run_case failed'
        end do
        write (u, '("| ",a," | ",i0," | ",i0," | ",f0.3," | ",i0," | ",f0.2," | ",i0," |")') &
            trim(stems(k)), ne, tab%n, 1.0e3_dp*t_tab, reps_tab, 1.0e3_dp*t_case, reps_case
        flush (u)
        write (output_unit, '(a,i6,a,f10.3,a,f10.2,a)') trim(stems(k))//' N_e', ne, &
            ': tabulation', 1.0e3_dp*t_tab, ' ms, whole case', 1.0e3_dp*t_case, ' ms'
        flush (output_unit)
        allocate (u_f(tab%n), w_f(tab%n))
        call surface_displacement(m, d, sol%z(d%nv + 1:), tab%val(Q_X, :), u_f, w_f, err)
        if (allocated(err)) error stop 'bench_tabulation: surface_displacement failed'
        write (name, '(a,"_",i0,".txt")') trim(stems(k)), ne
        open (newunit=v, file=dir//'/'//trim(name), status='replace', action='write')
        do i = 1, tab%n
            write (v, '(3es25.17)') tab%val(Q_X, i), u_f(i), w_f(i)
        end do
        close (v)
    end subroutine measure
end program bench_tabulation
