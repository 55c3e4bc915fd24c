!> Benchmark of "model only what a scene needs" (model_reduction; doc/CHOICES.md,
!! Simplifications): each case solved with the full model (model_t%simplify = .false.) and
!! with the simplifications, on the same discretisation; prints a Markdown table: unknowns
!! solved, linear solves, processor seconds of the whole solve_contact and of its assembly
!! (build_system, the same for both: T is assembled for the full model), and the largest
!! station difference relative to the column's kind (test_simplifications).
!! Usage: `fpm run --profile release --example bench_simplifications [-- N_e ...]`
!! (default N_e 40 and 160).
!! `... -- accuracy` prints instead the size of the f = 0 simplification (sigma_x dropped,
!! exact Coulomb) against the full regularised model at eps_bar 1e-6 and 1e-8, against the
!! regularisation of the same case at f = 0.3 (the full model at eps_bar 1e-6 against
!! 1e-8), and against the discretisation error (the simplified W on N_e against 2 N_e),
!! all relative to max |W|, on soft and stiff beams and plates at N_e 40 and 160.
program bench_simplifications
    use iso_fortran_env, only: output_unit
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, LOAD_PATCH, &
                     complete_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact, contact_points
    use contact_system, only: system_t, build_system, contact_points_t
    use station_results, only: station_table_t, tabulate
    use station_columns, only: Q_X, Q_W, Q_PSI, Q_SZ, Q_STATE, Q_Q, Q_M, column_t, &
                               nondim_columns, column_index
    use model_reduction, only: reduction_t, plan_reduction
    use method_notes, only: simplification_text
    implicit none
    integer, allocatable :: ne_list(:)
    integer :: i
    character(len=16) :: arg
    call start_program()
    ne_list = [40, 160]
    if (command_argument_count() > 0) then
        call get_command_argument(1, arg)
        if (arg == 'accuracy') then
            call accuracy_table()
            stop
        end if
    end if
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

    !> The f = 0 simplification's size against the regularisation and the discretisation.
    subroutine accuracy_table()
        integer, parameter :: ne_acc(2) = [40, 160]
        integer :: k
        write (output_unit, '(a)') '| case | N_e | W(0) | simplified - full, eps 1e-6 | '// &
            'simplified - full, eps 1e-8 | ratio | f 0.3: full eps 1e-6 - eps 1e-8 | '// &
            'discretisation: max W(N_e) - W(2 N_e) | simplification / discretisation | '// &
            'discretisation there | simplification / discretisation there | '// &
            'where the difference is largest (t) | state there |'
        write (output_unit, '(a)') '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|'// &
            '---:|---|'
        do k = 1, size(ne_acc)
            call accuracy_case('BEAM rho 1e-6 zeta 0.5 beta 0.05, central load', &
                               beam_soft(1.0e-6_dp, 0.5_dp, 0.0_dp, ne_acc(k), 0.0_dp))
            call accuracy_case('BEAM rho 1e-4 zeta 0.3 beta 0.05, central load', &
                               beam_soft(1.0e-4_dp, 0.3_dp, 0.0_dp, ne_acc(k), 0.0_dp))
            call accuracy_case('BEAM rho 1e-4 zeta 0.3 beta 0.05, load at x = 0.1 l', &
                               beam_soft(1.0e-4_dp, 0.3_dp, 0.0_dp, ne_acc(k), 0.1_dp))
            call accuracy_case('BEAM rho 1e-3 zeta 0.1 beta 0.05, central load', &
                               beam_soft(1.0e-3_dp, 0.1_dp, 0.0_dp, ne_acc(k), 0.0_dp))
            call accuracy_case('BEAM rho 0.01 zeta 0.1 beta 0.05, load at x = 0.1 l', &
                               beam(0.0_dp, ne_acc(k), 0.1_dp))
            call accuracy_case('PLATE rho 1e-4 zeta 0.3, central point load', &
                               plate_soft(1.0e-4_dp, 0.3_dp, ne_acc(k), 0.0_dp))
            call accuracy_case('PLATE rho 1e-4 zeta 0.3, patch r <= 0.1 a', &
                               plate_soft(1.0e-4_dp, 0.3_dp, ne_acc(k), 0.1_dp))
            call accuracy_case('PLATE rho 1e-4 zeta 0.02, patch r <= 0.1 a', &
                               plate_soft(1.0e-4_dp, 0.02_dp, ne_acc(k), 0.1_dp))
            call accuracy_case('PLATE rho 1e-3 zeta 0.1, uniform pressure', &
                               plate_soft(1.0e-3_dp, 0.1_dp, ne_acc(k), 1.0_dp))
            call accuracy_case('PLATE rho 0.01 zeta 0.1, central point load', &
                               plate(0.01_dp, 0.0_dp, ne_acc(k)))
        end do
    end subroutine accuracy_table

    function beam_soft(rho, zeta, f, ne, x) result(m)
        real(dp), intent(in) :: rho, zeta, f, x
        integer, intent(in) :: ne
        type(model_t) :: m
        m = beam(f, ne, x)
        m%groups%rho = rho
        m%groups%zeta = zeta
        call complete_model(m)
    end function beam_soft

    !> A NONDIM plate under a point load on the axis (patch = 0) or a uniform patch
    !! r <= patch a.
    function plate_soft(rho, zeta, ne, patch) result(m)
        real(dp), intent(in) :: rho, zeta, patch
        integer, intent(in) :: ne
        type(model_t) :: m
        m = plate(rho, 0.0_dp, ne)
        m%groups%zeta = zeta
        if (patch > 0.0_dp) m%loads = [load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=patch)]
        call complete_model(m)
    end function plate_soft

    !> Stations of m solved (no timing), nondimensional W.
    subroutine solved_stations(m, tab)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(out) :: tab
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(error_t), allocatable :: err
        call new_discretization(m, d, err)
        if (allocated(err)) error stop 'bench_simplifications: discretisation failed'
        call solve_contact(m, d, sol, err)
        if (allocated(err)) error stop 'bench_simplifications: case not solved'
        call tabulate(m, d, sol, tab, err)
        if (allocated(err)) error stop 'bench_simplifications: stations failed'
    end subroutine solved_stations

    !> W of `fine` linearly interpolated at x (W is continuous: a doubled station is harmless).
    real(dp) function w_at(fine, x) result(w)
        type(station_table_t), intent(in) :: fine
        real(dp), intent(in) :: x
        integer :: i
        real(dp) :: s
        w = fine%val(Q_W, fine%n)
        do i = 1, fine%n - 1
            if (x > fine%val(Q_X, i + 1)) cycle
            if (fine%val(Q_X, i + 1) <= fine%val(Q_X, i)) cycle
            s = (x - fine%val(Q_X, i))/(fine%val(Q_X, i + 1) - fine%val(Q_X, i))
            w = (1.0_dp - s)*fine%val(Q_W, i) + s*fine%val(Q_W, i + 1)
            return
        end do
    end function w_at

    subroutine accuracy_case(name, m)
        character(len=*), intent(in) :: name
        type(model_t), intent(in) :: m
        type(model_t) :: full, fine, rough
        type(station_table_t) :: simple, f6, f8, fine_tab, r6, r8
        real(dp) :: w_scale, d6, d8, dr, disc, local
        integer :: i, at
        call solved_stations(m, simple)
        full = m
        full%solver%simplify = .false.
        call solved_stations(full, f6)
        full%interface%eps_bar = 1.0e-8_dp
        call solved_stations(full, f8)
        rough = full
        rough%interface%f = 0.3_dp
        call solved_stations(rough, r8)
        rough%interface%eps_bar = 1.0e-6_dp
        call solved_stations(rough, r6)
        fine = m
        fine%mesh%ne = 2*m%mesh%ne
        call solved_stations(fine, fine_tab)
        w_scale = maxval(abs(simple%val(Q_W, :)))
        at = maxloc(abs(simple%val(Q_W, :) - f6%val(Q_W, :)), dim=1)
        d6 = maxval(abs(simple%val(Q_W, :) - f6%val(Q_W, :)))/w_scale
        d8 = maxval(abs(simple%val(Q_W, :) - f8%val(Q_W, :)))/w_scale
        dr = maxval(abs(r6%val(Q_W, :) - r8%val(Q_W, :)))/maxval(abs(r8%val(Q_W, :)))
        disc = maxval([(abs(simple%val(Q_W, i) - w_at(fine_tab, simple%val(Q_X, i))), &
                        i=1, simple%n)])/w_scale
        local = abs(simple%val(Q_W, at) - w_at(fine_tab, simple%val(Q_X, at)))/w_scale
        write (output_unit, '(a,"|",i0,"|",es11.4,"|",8(es9.2,"|"),f7.3,"|",a,"|")') &
            '| '//name//' ', m%mesh%ne, w_at(simple, 0.0_dp)*w_scale_factor(m), d6, d8, d6/d8, &
            dr, disc, d6/disc, local, d6/max(local, tiny(1.0_dp)), &
            simple%val(Q_X, at)/m%structure%length, &
            trim(merge('lift-off', 'contact ', simple%state(at) == 0))
        flush (output_unit)
    end subroutine accuracy_case

    !> W = EI w/(F l^3) or D w/(F a^2): the nondimensional column's factor.
    real(dp) function w_scale_factor(m) result(k)
        type(model_t), intent(in) :: m
        type(column_t), allocatable :: cols(:)
        cols = nondim_columns(m)
        k = cols(column_index(cols, 'W'))%scale
    end function w_scale_factor

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
