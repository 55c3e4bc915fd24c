!> What the error estimate costs: per case and N_e, the time of the case (solve_case:
!! discretise, solve, tabulate, summarise) and of its error estimate (error_estimate::
!! estimate_errors with the case's nested-start solutions and its solution, as the program
!! calls it), as processor time (the machine is shared: wall time varied by a factor 2
!! between runs), the least of five repetitions each, and their ratio. The cases are
!! bench_phases' (a plate and a beam under a central point load, lift-off and slip) and the
!! same beam with the load at x = 0.137 l, inside an element of every N_e measured and of
!! its neighbours N_e - 1 and N_e + 1 (the estimate solves those too: error_estimate,
!! neighbour_entries; under the central load, on a node of the even N_e measured, the odd
!! neighbours are not comparable and not solved).
!!
!! Usage: OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile release --example
!!        bench_estimate_cost [-- OUT.md]     (default output/bench/estimate_cost.md)
program bench_estimate_cost
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, complete_model
    use solved_case, only: case_t, solve_case
    use summary_table, only: entry_t
    use error_estimate, only: estimate_errors
    implicit none
    integer, parameter :: ne_list(9) = [10, 20, 40, 50, 64, 100, 128, 200, 400], reps = 5
    character(len=*), parameter :: case_names(3) = [character(len=24) :: 'plate', 'beam', &
                                                     'beam, load at 0.137 l']
    character(len=256) :: out_file
    integer :: u, kind_index, i
    real(dp) :: t_case, t_est
    out_file = 'output/bench/estimate_cost.md'
    if (command_argument_count() >= 1) call get_command_argument(1, out_file)
    call start_program()
    open (newunit=u, file=trim(out_file), status='replace', action='write')
    write (u, '(a)') '# What the error estimate costs (example/bench_estimate_cost.f90)'
    write (u, '(a)') ''
    write (u, '(a)') 'Processor time, least of 5 repetitions, one thread; case = solve_case '// &
        '(discretise, solve, tabulate, summarise), estimate = error_estimate::estimate_errors.'
    write (u, '(a)') ''
    write (u, '(a)') '| case | N_e | case s | estimate s | estimate / case |'
    write (u, '(a)') '|---|---:|---:|---:|---:|'
    do kind_index = 1, 3
        do i = 1, size(ne_list)
            call measure(bench_case(kind_index, ne_list(i)), t_case, t_est)
            write (u, '(a,i0,a,es10.3,a,es10.3,a,f6.2,a)') '| '// &
                trim(case_names(kind_index))//' | ', ne_list(i), ' | ', &
                t_case, ' | ', t_est, ' | ', t_est/t_case, ' |'
            flush (u)
        end do
    end do
    close (u)
    print '(a)', 'bench_estimate_cost: '//trim(out_file)

contains

    !> bench_phases' cases: 1 the plate (rho 0.01, zeta 0.1, f 0.5), 2 the beam (rho 0.0025,
    !! zeta 0.1, beta 0.05, f 0.6, H = 0.1 V), central point load, nondimensional; 3 the beam
    !! with the load at x = 0.137 l.
    function bench_case(k, ne) result(m)
        integer, intent(in) :: k, ne
        type(model_t) :: m
        m%nondim = .true.
        m%groups%zeta = 0.1_dp
        m%groups%beta = 0.05_dp
        if (k == 1) then
            m%structure%kind = MODEL_PLATE
            m%groups%rho = 1.0e-2_dp
            m%interface%f = 0.5_dp
            m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.0_dp)]
        else
            m%structure%kind = MODEL_BEAM
            m%groups%rho = 2.5e-3_dp
            m%interface%f = 0.6_dp
            m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, fx=0.1_dp, &
                              x1=merge(0.137_dp, 0.0_dp, k == 3))]
        end if
        m%mesh%ne = ne
        call complete_model(m)
    end function bench_case

    !> Least times of the case and of its estimate over reps repetitions.
    subroutine measure(m, t_case, t_est)
        type(model_t), intent(in) :: m
        real(dp), intent(out) :: t_case, t_est
        type(case_t) :: c
        type(error_t), allocatable :: err
        type(entry_t), allocatable :: e(:)
        real(dp) :: t0, t1, t2
        integer :: r
        t_case = huge(1.0_dp)
        t_est = huge(1.0_dp)
        do r = 1, reps
            call cpu_time(t0)
            call solve_case(m, c, err)
            call cpu_time(t1)
            if (allocated(err)) error stop 'bench_estimate_cost: a case failed'
            e = c%entries
            call estimate_errors(c%model, c%d, e, c%sol%coarse, c%summary%edge_in_contact, &
                                 solution=c%sol)
            call cpu_time(t2)
            t_case = min(t_case, t1 - t0)
            t_est = min(t_est, t2 - t1)
        end do
    end subroutine measure
end program bench_estimate_cost
