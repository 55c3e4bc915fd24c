!> fricon_bench: linear solves, time and outcome of both solution methods (SOLVER f7) over
!! decks and a hard-case grid (doc/METHOD.md, Benchmark). Not a test: it measures.
!!
!!     fpm run --profile release --example fricon_bench -- input/paper/*.dat
!!
!! Every case of every deck given (SWEEP cases included), then the built-in grid, is solved by
!! NEWTON and by TWOLOOP. Writes output/bench/bench_table.txt (one line per case and method)
!! and output/bench/bench_summary.txt (per set and method: cases, failures, median / 90th
!! percentile / maximum of the linear solves, total time), and prints the summary.
program fricon_bench
    use, intrinsic :: iso_fortran_env, only: int64, compiler_version, compiler_options
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, complete_model, &
                     METHOD_NEWTON, METHOD_TWOLOOP
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact
    use station_results, only: station_table_t, tabulate
    use design_summary, only: summary_t, summarise
    use deck_reader, only: deck_t, read_deck, case_count, case_model
    use shape_functions, only: INTERP_P2
    implicit none

    !> One solved (or failed) case.
    type :: run_t
        character(len=48) :: label = ''
        character(len=5) :: set = ''       !! paper or grid
        integer :: method = METHOD_NEWTON
        integer :: ne = 0
        integer :: solves = 0
        integer :: nested = 0              !! linear solves on the nested coarser meshes (start)
        integer :: factorisations = 0
        real(dp) :: phase(6) = 0.0_dp      !! T (with its restriction to the nested mesh),
                                           !! K + M + set-up, nested start, iterations,
                                           !! checks (solution_t%seconds), output (stations
                                           !! and design summary) [s]
        real(dp) :: seconds = 0.0_dp
        character(len=90) :: outcome = ''
    end type run_t

    character(len=*), parameter :: out_dir = 'output/bench'
    type(run_t), allocatable :: runs(:)
    character(len=512) :: path
    integer :: i

    call start_program()
    call execute_command_line('mkdir -p '//out_dir)
    allocate (runs(0))
    do i = 1, command_argument_count()
        call get_command_argument(i, path)
        call bench_deck(trim(path), runs)
    end do
    call bench_grid(runs)
    call write_table(runs)
    call write_summary(runs)

contains

    !> Both methods on every case of one deck.
    subroutine bench_deck(deck_path, runs)
        character(len=*), intent(in) :: deck_path
        type(run_t), allocatable, intent(inout) :: runs(:)
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: err
        character(len=:), allocatable :: label
        character(len=48) :: name
        integer :: k
        call read_deck(deck_path, deck, err)
        if (allocated(err)) then
            write (*, '(a)') 'skipped '//deck_path//': '//err%message
            return
        end if
        cases: do k = 1, case_count(deck)
            call case_model(deck, k, m, label, err)
            if (allocated(err)) cycle cases
            write (name, '(a,a,i0)') deck%stem, '#', k
            call bench_both(m, name, 'paper', runs)
        end do cases
    end subroutine bench_deck

    !> Hard-case grid: beam (b/l = 0.05, H = f V/4) and plate, central load; rho 1e-6 .. 1e3,
    !! zeta 0.001 .. 0.5, f 0 .. 2, N_e 40; and the practical cases the two-loop iteration failed.
    subroutine bench_grid(runs)
        type(run_t), allocatable, intent(inout) :: runs(:)
        real(dp), parameter :: rhos(4) = [1.0e-6_dp, 1.0e-3_dp, 1.0_dp, 1.0e3_dp]
        real(dp), parameter :: zetas(3) = [1.0e-3_dp, 0.1_dp, 0.5_dp]
        real(dp), parameter :: fs(3) = [0.0_dp, 0.6_dp, 2.0_dp]
        type(model_t) :: m
        character(len=48) :: name
        integer :: kind, i, j, k
        kinds_loop: do kind = MODEL_BEAM, MODEL_PLATE
            do i = 1, size(rhos)
                do j = 1, size(zetas)
                    do k = 1, size(fs)
                        m = grid_model(kind, rhos(i), zetas(j), fs(k), 40)
                        write (name, '(a,3(a,es7.0))') merge('beam ', 'plate', &
                            kind == MODEL_BEAM), ' rho', rhos(i), ' zeta', zetas(j), ' f', fs(k)
                        call bench_both(m, name, 'grid', runs)
                    end do
                end do
            end do
        end do kinds_loop
        call bench_both(grid_model(MODEL_BEAM, 0.01_dp, 0.1_dp, 0.6_dp, 40, 0.3_dp), &
                        'beam H = 0.3 V f 0.6', 'grid', runs)
        call bench_both(grid_model(MODEL_BEAM, 0.01_dp, 0.1_dp, 0.6_dp, 40, 0.1_dp, 1.0_dp), &
                        'wide beam b/l = 1', 'grid', runs)
        do k = 20, 80, 60
            m = grid_model(MODEL_PLATE, 1.0e-3_dp, 0.1_dp, 0.6_dp, k)
            m%mesh%interp = INTERP_P2
            write (name, '(a,i0)') 'plate P2 rho 1e-3 f 0.6 N_e ', k
            call bench_both(m, name, 'grid', runs)
        end do
    end subroutine bench_grid

    !> A NONDIM case with a central point load (nu = 0.3, nu_f = 0.1).
    function grid_model(kind, rho, zeta, f, ne, h_load, beta) result(m)
        integer, intent(in) :: kind, ne
        real(dp), intent(in) :: rho, zeta, f
        real(dp), intent(in), optional :: h_load   !! beam: horizontal load (default f V/4)
        real(dp), intent(in), optional :: beta     !! beam: b/l (default 0.05)
        type(model_t) :: m
        m%structure%kind = kind
        m%nondim = .true.
        m%groups%rho = rho
        m%groups%zeta = zeta
        m%groups%beta = 0.05_dp
        if (present(beta)) m%groups%beta = beta
        m%interface%f = f
        m%mesh%ne = ne
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.0_dp)]
        if (kind == MODEL_BEAM) m%loads(1)%fx = 0.25_dp*f
        if (present(h_load)) m%loads(1)%fx = h_load
        call complete_model(m)
    end function grid_model

    subroutine bench_both(m, name, set, runs)
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: name, set
        type(run_t), allocatable, intent(inout) :: runs(:)
        integer :: method
        do method = METHOD_NEWTON, METHOD_TWOLOOP
            runs = [runs, bench_case(m, method, name, set)]
        end do
    end subroutine bench_both

    !> Discretise and solve (timed: assembly of K, M, T and the iterations).
    function bench_case(m0, method, name, set) result(r)
        type(model_t), intent(in) :: m0
        integer, intent(in) :: method
        character(len=*), intent(in) :: name, set
        type(run_t) :: r
        type(model_t) :: m
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(summary_t) :: summary
        type(error_t), allocatable :: err
        integer(int64) :: t0, t1, t2, rate
        m = m0
        m%solver%method = method
        r%label = name
        r%set = set
        r%method = method
        r%ne = m%mesh%ne
        call system_clock(t0, rate)
        call new_discretization(m, d, err)
        if (.not. allocated(err)) call solve_contact(m, d, sol, err)
        call system_clock(t1)
        r%seconds = real(t1 - t0, dp)/real(rate, dp)
        r%solves = sol%n_solves
        r%nested = sol%n_nested_solves
        r%factorisations = sol%n_factorisations
        r%phase(1:5) = sol%seconds
        r%outcome = 'solved'
        if (allocated(err)) then
            r%outcome = 'status 2: '//err%message
            return
        end if
        call tabulate(m, d, sol, tab, err)
        if (.not. allocated(err)) summary = summarise(m, sol, tab)
        call system_clock(t2)
        r%phase(6) = real(t2 - t1, dp)/real(rate, dp)
    end function bench_case

    subroutine write_table(runs)
        type(run_t), intent(in) :: runs(:)
        integer :: u, i
        open (newunit=u, file=out_dir//'/bench_table.txt', status='replace', action='write')
        call write_machine(u)
        write (u, '(a)') '# set   case                                             N_e  method'// &
            '   solves   nested   time_s  outcome'//repeat(' ', 60)// &
            '  factorisations  T_s  K_M_setup_s  nested_s  iterations_s  checks_s  output_s'
        do i = 1, size(runs)
            write (u, '(a5,2x,a48,i5,2x,a7,2i9,es10.3,2x,a90,i16,6es11.3)') runs(i)%set, &
                runs(i)%label, runs(i)%ne, method_name(runs(i)%method), runs(i)%solves, &
                runs(i)%nested, runs(i)%seconds, runs(i)%outcome, runs(i)%factorisations, &
                runs(i)%phase
        end do
        close (u)
    end subroutine write_table

    subroutine write_summary(runs)
        type(run_t), intent(in) :: runs(:)
        character(len=5), parameter :: sets(3) = [character(len=5) :: 'paper', 'grid', 'all']
        integer :: u, s, method
        open (newunit=u, file=out_dir//'/bench_summary.txt', status='replace', action='write')
        call write_machine(u)
        write (u, '(a)') '# set    method   cases  failed  median  p90  max solves'// &
            '  max with nested  total_s'
        write (*, '(a)') '# set    method   cases  failed  median  p90  max solves'// &
            '  max with nested  total_s'
        do s = 1, size(sets)
            do method = METHOD_NEWTON, METHOD_TWOLOOP
                call summary_line(u, runs, sets(s), method)
            end do
        end do
        close (u)
    end subroutine write_summary

    subroutine summary_line(u, runs, set, method)
        integer, intent(in) :: u
        type(run_t), intent(in) :: runs(:)
        character(len=*), intent(in) :: set
        integer, intent(in) :: method
        logical, allocatable :: pick(:)
        integer, allocatable :: solves(:)
        character(len=100) :: line
        integer :: n
        pick = runs%method == method .and. (runs%set == set .or. set == 'all')
        n = count(pick)
        if (n == 0) return
        solves = pack(runs%solves, pick)
        call sort_integers(solves)
        write (line, '(a5,2x,a7,2i8,i8,i5,i5,i17,f15.2)') set, method_name(method), n, &
            count(pick .and. runs%outcome /= 'solved'), solves((n + 1)/2), &
            solves(max(1, ceiling(0.9_dp*n))), solves(n), &
            maxval(pack(runs%solves + runs%nested, pick)), sum(pack(runs%seconds, pick))
        write (u, '(a)') trim(line)
        write (*, '(a)') trim(line)
    end subroutine summary_line

    subroutine write_machine(u)
        integer, intent(in) :: u
        character(len=200) :: cpu
        integer :: v, ios
        cpu = 'unknown'
        open (newunit=v, file='/proc/cpuinfo', action='read', status='old', iostat=ios)
        if (ios == 0) then
            find_model: do
                read (v, '(a)', iostat=ios) cpu
                if (ios /= 0) exit find_model
                if (index(cpu, 'model name') == 1) exit find_model
            end do find_model
            close (v)
        end if
        write (u, '(a)') '# machine: '//trim(cpu(index(cpu, ':') + 1:))
        write (u, '(a)') '# compiler: '//compiler_version()
        write (u, '(a)') '# options: '//compiler_options()
        write (u, '(a)') '# time: wall clock of discretisation + solve_contact (T, K, M '// &
            'assembly, iterations, checks); solves: linear solves of the case; nested: '// &
            'those on the nested coarser meshes that gave the start (N_e > 48); after the '// &
            'outcome: factorisations and the wall time of each phase (solution_t%seconds; '// &
            'output: station table and design summary, not part of time_s)'
    end subroutine write_machine

    pure function method_name(method) result(name)
        integer, intent(in) :: method
        character(len=7) :: name
        name = merge('NEWTON ', 'TWOLOOP', method == METHOD_NEWTON)
    end function method_name

    pure subroutine sort_integers(x)
        integer, intent(inout) :: x(:)
        integer :: i, j, key
        do i = 2, size(x)
            key = x(i)
            j = i - 1
            do while (j >= 1)
                if (x(j) <= key) exit
                x(j + 1) = x(j)
                j = j - 1
            end do
            x(j + 1) = key
        end do
    end subroutine sort_integers
end program fricon_bench
