!> Benchmark of "model only what a scene needs" (model_reduction; doc/CHOICES.md, Simplifications):
!! each case solved with the full model (model_t%simplify = .false.) and with the simplifications,
!! on the same discretisation; prints a Markdown table: unknowns solved, linear solves, processor
!! seconds of the whole solve_contact and of its assembly (build_system, the same for both: T is
!! assembled for the full model), and the largest station difference relative to the column's kind
!! (test_simplifications). Usage: `fpm run --profile release --example bench_simplifications [-- N_e
!! ...]` (default N_e 40 and 160).
program bench_simplifications
    use iso_fortran_env, only: output_unit
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, complete_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact, contact_points
    use contact_system, only: system_t, build_system, contact_points_t
    use station_results, only: station_table_t, tabulate
    use station_columns, only: Q_X, Q_W, Q_PSI, Q_SZ, Q_STATE, Q_Q, Q_M
    use model_reduction, only: reduction_t, plan_reduction
    use method_notes, only: simplification_text
    implicit none
    integer, allocatable :: ne_list(:)
    integer :: i
    character(len=16) :: arg
    call start_program()
    ne_list = [40, 160]
    if (command_argument_count() > 0) then
        deallocate (ne_list)
        allocate (ne_list(command_argument_count()))
        do i = 1, size(ne_list)
            call get_command_argument(i, arg)
            read (arg, *) ne_list(i)
        end do
    end if
    write (output_unit, &
        '(a)') '| case | N_e | simplification | unknowns full | unknowns solved '// &
        '| saved | linear solves full / simpl. | full s | simpl. s | assembly s | solve s full '// &
        '| solve s simpl. | time saved | max station diff |'
    write (output_unit, '(a)') '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|'// &
        '---:|---:|'
    do i = 1, size(ne_list)
        call run_case('PLATE rho 0.01 f 0', plate(0.01_dp, 0.0_dp, ne_list(i)))
        call run_case('BEAM rho 0.01 f 0, load at x = 0.1 l', beam(0.0_dp, ne_list(i), 0.1_dp))
        call run_case('BEAM rho 0.01 f 0.6, central load', beam(0.6_dp, ne_list(i), 0.0_dp))
        call run_case('BEAM rho 0.01 f 0, central load', beam(0.0_dp, ne_list(i), 0.0_dp))
    end do

contains

    function plate(rho, f, ne) result(m)
        real(dp), intent(in) :: rho, f
        integer, intent(in) :: ne
        type(model_t) :: m
        m%structure%kind = MODEL_PLATE
        m%nondim = .true.
        m%groups%rho = rho
        m%groups%zeta = 0.1_dp
        m%interface%f = f
        m%mesh%ne = ne
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.0_dp)]
        call complete_model(m)
    end function plate

    function beam(f, ne, x) result(m)
        real(dp), intent(in) :: f, x
        integer, intent(in) :: ne
        type(model_t) :: m
        m%structure%kind = MODEL_BEAM
        m%nondim = .true.
        m%groups%rho = 0.01_dp
        m%groups%zeta = 0.1_dp
        m%groups%beta = 0.05_dp
        m%interface%f = f
        m%mesh%ne = ne
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=x)]
        call complete_model(m)
    end function beam

    !> Least processor time of repeated solves (until 2 s spent or 10 runs).
    subroutine timed_solve(m, d, sol, tab, seconds)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(out) :: sol
        type(station_table_t), intent(out) :: tab
        real(dp), intent(out) :: seconds
        type(error_t), allocatable :: err
        real(dp) :: t0, t1, spent
        integer :: k
        seconds = huge(1.0_dp)
        spent = 0.0_dp
        repeats: do k = 1, 10
            call cpu_time(t0)
            call solve_contact(m, d, sol, err)
            call cpu_time(t1)
            if (allocated(err)) error stop 'bench_simplifications: case not solved'
            seconds = min(seconds, t1 - t0)
            spent = spent + t1 - t0
            if (spent > 2.0_dp) exit repeats
        end do repeats
        call tabulate(m, d, sol, tab, err)
        if (allocated(err)) error stop 'bench_simplifications: stations failed'
    end subroutine timed_solve

    real(dp) function assembly_seconds(m, d) result(seconds)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(contact_points_t) :: pts
        type(system_t) :: sys
        type(error_t), allocatable :: err
        real(dp) :: t0, t1
        integer :: k
        seconds = huge(1.0_dp)
        do k = 1, 5
            call cpu_time(t0)
            pts = contact_points(m%structure, d)
            call build_system(m, d, pts, sys, err)
            call cpu_time(t1)
            seconds = min(seconds, t1 - t0)
        end do
    end function assembly_seconds

    subroutine run_case(name, m)
        character(len=*), intent(in) :: name
        type(model_t), intent(in) :: m
        integer, parameter :: kind_of(16) = [Q_X, Q_W, Q_W, Q_PSI, Q_SZ, Q_SZ, Q_W, Q_W, &
                                             Q_STATE, Q_Q, Q_Q, Q_M, Q_M, Q_Q, Q_SZ, Q_SZ]
        type(model_t) :: full
        type(discretization_t) :: d
        type(solution_t) :: sol_s, sol_f
        type(station_table_t) :: tab_s, tab_f
        type(reduction_t) :: red
        type(error_t), allocatable :: err
        real(dp) :: t_s, t_f, t_a, diff, scale
        character(len=:), allocatable :: text
        integer :: q
        call new_discretization(m, d, err)
        red = plan_reduction(m, d)
        full = m
        full%solver%simplify = .false.
        call timed_solve(full, d, sol_f, tab_f, t_f)
        call timed_solve(m, d, sol_s, tab_s, t_s)
        t_a = assembly_seconds(m, d)
        diff = 0.0_dp
        do q = 1, size(tab_s%val, 1)
            if (q == Q_STATE) cycle
            scale = max(maxval(abs(tab_f%val(kind_of(q), :))), tiny(1.0_dp))
            diff = max(diff, maxval(abs(tab_s%val(q, :) - tab_f%val(q, :)))/scale)
        end do
        text = simplification_text(m, d)
        text = text(len('simplifications used: ') + 1:index(text, ', saved') - 1)
        write (output_unit, '(a,"|",i0,"|",a,"|",i0,"|",i0,"|",f0.1,"%|",i0," / ",i0,"|",'// &
            'es9.2,"|",es9.2,"|",es9.2,"|",es9.2,"|",es9.2,"|",f0.1,"%|",es9.2,"|")') &
            '| '//name//' ', m%mesh%ne, ' '//text//' ', red%n_full, red%n_reduced, &
            100.0_dp*real(red%n_full - red%n_reduced, dp)/real(red%n_full, dp), &
            sol_f%n_solves, sol_s%n_solves, t_f, t_s, t_a, t_f - t_a, t_s - t_a, &
            100.0_dp*(t_f - t_s)/t_f, diff
        flush (output_unit)
    end subroutine run_case
end program bench_simplifications
