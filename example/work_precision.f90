!> Work-precision benchmark (doc/OUTPUT.md, Error estimates): for a PLATE and a BEAM case with
!! lift-off and friction, each discretisation (interpolation x mesh family) over N_e = 10 ... 160
!! (the fixed families on to 1280, and doubled beyond while they have not reached the smallest
!! ADAPT error and have at most max_unknowns unknowns), and the three ADAPT families (P1, S2
!! everywhere, and S2 displacements with P1 tractions, from 16 elements, tol 1e-2 ... 1e-4), the
!! error of W(0), the centre and peak pressure, max |M| and the contact extent against a reference,
!! versus processor time and versus unknowns.
!!
!! Reference (subroutine reference): per quantity the best of three Richardson extrapolations,
!! (a) P1 on LOADS meshes, (b) P1 on a P1-adapted mesh bisected uniformly, (c) S2w-P1tr on an
!! S2w-P1tr-adapted mesh bisected uniformly; its uncertainty
!! (the extrapolation's change to the finest value) is printed with it. Errors are relative
!! to the reference value (the contact extent: absolute, in t).
!!
!! Usage: fpm run --profile release --example work_precision [-- OUTDIR [GRADING]]
!! (default output/bench; GRADING of the ADAPT families' 16-element first mesh, default UNIFORM)
!! Writes OUTDIR/work_precision_{plate,beam}.txt and .png (gnuplot: log error against log time,
!! one curve per discretisation, one panel per quantity).
program work_precision
    use deck_fields, only: int_text
    use iso_fortran_env, only: output_unit
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, LOAD_PATCH, &
                     complete_model
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2
    use discretization, only: discretization_t, new_discretization, discretise_mesh
    use mesh, only: mesh_t
    use mesh_refinement, only: bisected
    use contact_solver, only: solution_t, solve_contact
    use adaptive_solve, only: adaptation_t, solve_adaptive
    use station_results, only: station_table_t, tabulate, contact_extent
    use station_columns, only: Q_X, Q_W, Q_SZ, Q_M, column_t, nondim_columns, column_index
    implicit none

    integer, parameter :: n_q = 5               !! W(0), Sigma_z(0), max Sigma_z, max |M|, extent
    character(len=*), parameter :: q_names(n_q) = [character(len=12) :: 'W(0)', 'Sigma_z(0)', &
                                                   'max_Sigma_z', 'max|M|', 'extent']
    integer, parameter :: n_disc = 10
    character(len=*), parameter :: disc_names(n_disc) = [character(len=16) :: 'P1-UNIFORM', &
        'P1-EDGES', 'P1-LOADS', 'P2-UNIFORM', 'S2-UNIFORM', 'S2w-P1tr-LOADS', &
        'S2w-P1tr-UNIFORM', 'P1-ADAPT', 'S2w-P1tr-ADAPT', 'S2-ADAPT']
    integer, parameter :: adapt_families(3) = [8, 9, 10]   !! the ADAPT discretisations
    !> the fixed families: continued over ne_long, then doubled while their compared error is
    !! above the smallest ADAPT error of the case (fixed_continuation)
    integer, parameter :: long_families(7) = [1, 2, 3, 4, 5, 6, 7]
    !> the error level of the work-precision target, in both W(0) and Sigma_z(0)
    real(dp), parameter :: target_error = 1.0e-4_dp
    integer, parameter :: ne_list(5) = [10, 20, 40, 80, 160]
    !> the adaptive families: ADAPT tolerances, from a 16-element uniform mesh
    real(dp), parameter :: tol_list(5) = [1.0e-2_dp, 3.0e-3_dp, 1.0e-3_dp, 3.0e-4_dp, 1.0e-4_dp]
    integer, parameter :: adapt_start = 16, adapt_max = 2000
    !> the mesh of reference (b): P1-ADAPT to 1e-4, at most this many elements (it is bisected
    !! twice; with the centre pressure among ADAPT's key results, P1 at 1e-4 would go on to
    !! adapt_max, and 4 adapt_max elements cannot be solved here)
    integer, parameter :: reference_max = 700
    !> the fixed families continued to where they reach 1e-4 (the work-precision comparison)
    integer, parameter :: ne_long(3) = [320, 640, 1280]
    integer, parameter :: all_ne(size(ne_list) + size(ne_long)) = [ne_list, ne_long]
    !> a fixed family is doubled beyond ne_long while it has at most this many unknowns
    !! (one dense solve of a few seconds here) and has not reached the smallest ADAPT error
    integer, parameter :: max_unknowns = 13000, max_extra_rows = 2
    character(len=256) :: out_dir
    !> the grading of the ADAPT families' first mesh (second argument; output/bench/adapt_start.md)
    character(len=16) :: adapt_grading
    integer :: k

    out_dir = 'output/bench'
    if (command_argument_count() >= 1) call get_command_argument(1, out_dir)
    adapt_grading = 'UNIFORM'
    if (command_argument_count() >= 2) call get_command_argument(2, adapt_grading)
    call start_program()
    call execute_command_line('mkdir -p '//trim(out_dir))
    do k = 1, 2
        call study(k == 1, trim(out_dir))
    end do

contains

    !> The case: plate rho 0.001, zeta 0.1, f 0.6, disk load r <= 0.1 a (the work-precision plate),
    !! or beam rho 0.001, zeta 0.1, beta 0.05, f 0.6, central point load with H = 0.1 V.
    function base_model(plate) result(m)
        logical, intent(in) :: plate
        type(model_t) :: m
        m%nondim = .true.
        m%groups%rho = 1.0e-3_dp
        m%groups%zeta = 0.1_dp
        m%interface%f = 0.6_dp
        if (plate) then
            m%structure%kind = MODEL_PLATE
            m%loads = [load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=0.1_dp)]
        else
            m%structure%kind = MODEL_BEAM
            m%groups%beta = 0.05_dp
            m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, fx=0.1_dp, x1=0.0_dp)]
        end if
    end function base_model

    !> Discretisation k of disc_names on ne elements.
    function discretised(plate, k, ne) result(m)
        logical, intent(in) :: plate
        integer, intent(in) :: k, ne
        type(model_t) :: m
        m = base_model(plate)
        m%mesh%ne = ne
        m%mesh%interp = INTERP_P1
        select case (k)
        case (2)
            m%mesh%grading = 'EDGES'
        case (3)
            m%mesh%grading = 'LOADS'
        case (4)
            m%mesh%interp = INTERP_P2
        case (5)
            m%mesh%interp = INTERP_S2
        case (6)
            m%mesh%grading = 'LOADS'
            m%mesh%interp(2:3) = INTERP_S2
        case (7)
            m%mesh%interp(2:3) = INTERP_S2
        case (8, 9, 10)
            m%mesh%ne = adapt_start
            m%mesh%adapt_tol = tol_list(ne)      ! ne: the index into tol_list
            m%mesh%adapt_max_ne = adapt_max
            m%mesh%grading = trim(adapt_grading)
            if (k == 9) m%mesh%interp(2:3) = INTERP_S2
            if (k == 10) m%mesh%interp = INTERP_S2
        end select
        call complete_model(m)
    end function discretised

    !> Solve; q: the quantities (nondimensional), seconds: processor time of the
    !! discretisation and the solve; unknowns; ok false if not solved.
    subroutine measure(m, q, seconds, unknowns, ok, ne_final, given, final_mesh)
        type(model_t), intent(in) :: m
        real(dp), intent(out) :: q(n_q), seconds
        integer, intent(out) :: unknowns
        logical, intent(out) :: ok
        integer, intent(out), optional :: ne_final      !! elements of the (final) mesh
        type(mesh_t), intent(in), optional :: given     !! solve on this mesh instead
        type(mesh_t), intent(out), optional :: final_mesh
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: err
        type(column_t), allocatable :: cols(:)
        type(adaptation_t) :: info
        real(dp) :: t0, t1
        integer :: i0
        call cpu_time(t0)
        if (present(given)) then
            call discretise_mesh(m, given, d)
        else
            call new_discretization(m, d, err)
        end if
        if (.not. allocated(err)) then
            if (m%mesh%adapt_tol > 0.0_dp) then
                ! the whole adaptation: every cycle's solve and its two estimate solves
                call solve_adaptive(m, d, sol, info, err)
            else
                call solve_contact(m, d, sol, err)
            end if
        end if
        call cpu_time(t1)
        seconds = t1 - t0
        unknowns = d%n
        if (present(ne_final)) ne_final = d%msh%ne
        if (present(final_mesh)) final_mesh = d%msh
        ok = .not. allocated(err)
        q = 0.0_dp
        if (.not. ok) return
        call tabulate(m, d, sol, tab, err)
        ok = .not. allocated(err)
        if (.not. ok) return
        cols = nondim_columns(m)
        i0 = minloc(abs(tab%val(Q_X, :)), dim=1)
        q(1) = tab%val(Q_W, i0)*cols(column_index(cols, 'W'))%scale
        q(2) = tab%val(Q_SZ, i0)*cols(column_index(cols, 'Sigma_z'))%scale
        q(3) = maxval(tab%val(Q_SZ, :))*cols(column_index(cols, 'Sigma_z'))%scale
        q(4) = maxval(abs(tab%val(Q_M, :)))* &
               cols(column_index(cols, merge('M/(Fl)', 'M_r/F ', &
                                             m%structure%kind == MODEL_BEAM)))%scale
        q(5) = contact_extent(tab, m%structure%length)
    end subroutine measure

    !> Reference, three ways, each quantity taken from the one with the smaller uncertainty:
    !! (a) Richardson from P1 LOADS at 160, 320, 640; (b) the P1 mesh adapted to 1e-4 (at
    !! most reference_max elements), then bisected uniformly once and twice (nested; its
    !! contact, slip and load nodes stay nodes), solved with P1, Richardson with the observed
    !! order; (c) as (b) with S2 w and psi (the S2w-P1tr-ADAPT mesh, solved S2w-P1tr: the
    !! centre pressure converges at second order, where P1's is first order).
    !! Uncertainty: |reference - finest value|.
    subroutine reference(plate, q_ref, uncertainty, source)
        logical, intent(in) :: plate
        real(dp), intent(out) :: q_ref(n_q), uncertainty(n_q)
        character(len=1), intent(out) :: source(n_q)     !! 'a', 'b' or 'c'
        real(dp) :: q(n_q, 3), seconds, ref_b(n_q), unc_b(n_q)
        integer :: j, unknowns
        logical :: ok
        do j = 1, 3
            call measure(discretised(plate, 3, 160*2**(j - 1)), q(:, j), seconds, unknowns, ok)
            if (.not. ok) error stop 'work_precision: a reference solve failed'
        end do
        call extrapolate(q, q_ref, uncertainty)
        source = 'a'
        do j = 1, 2
            call adapted_reference(plate, 7 + j, merge(1, 7, j == 1), ref_b, unc_b, ok)
            if (.not. ok) cycle
            where (unc_b < uncertainty)
                q_ref = ref_b
                uncertainty = unc_b
                source = merge('b', 'c', j == 1)
            end where
        end do
    end subroutine reference

    !> The mesh of ADAPT family k_adapt at tol 1e-4 from the uniform start (at most
    !! reference_max elements), bisected uniformly once and twice and solved with the
    !! interpolation of family k_fixed, Richardson (extrapolate); ok false if a solve failed.
    subroutine adapted_reference(plate, k_adapt, k_fixed, ref, unc, ok)
        logical, intent(in) :: plate
        integer, intent(in) :: k_adapt, k_fixed
        real(dp), intent(out) :: ref(n_q), unc(n_q)
        logical, intent(out) :: ok
        character(len=len(adapt_grading)) :: start
        real(dp) :: q(n_q, 3), seconds
        type(mesh_t) :: msh
        type(model_t) :: m
        integer :: j, unknowns
        start = adapt_grading
        adapt_grading = 'UNIFORM'
        m = discretised(plate, k_adapt, size(tol_list))
        adapt_grading = start
        m%mesh%adapt_max_ne = reference_max
        call measure(m, q(:, 1), seconds, unknowns, ok, final_mesh=msh)
        if (.not. ok) return
        do j = 2, 3
            msh = bisected(msh, spread(.true., 1, msh%ne))
            call measure(discretised(plate, k_fixed, msh%ne), q(:, j), seconds, unknowns, ok, &
                         given=msh)
            if (.not. ok) return
        end do
        call extrapolate(q, ref, unc)
    end subroutine adapted_reference

    !> Richardson from three nested meshes (ratio 2) with the observed order in [0.5, 4]
    !! (1 if not monotone); the extent, which moves by nodes, is not extrapolated.
    subroutine extrapolate(q, q_ref, uncertainty)
        real(dp), intent(in) :: q(n_q, 3)
        real(dp), intent(out) :: q_ref(n_q), uncertainty(n_q)
        real(dp) :: p, d1, d2
        integer :: i
        do i = 1, n_q
            d1 = q(i, 3) - q(i, 2)
            d2 = q(i, 2) - q(i, 1)
            p = 1.0_dp
            if (d1 /= 0.0_dp .and. d2 /= 0.0_dp .and. d1*d2 > 0.0_dp) &
                p = max(0.5_dp, min(4.0_dp, log(d2/d1)/log(2.0_dp)))
            q_ref(i) = q(i, 3) + d1/(2.0_dp**p - 1.0_dp)
            if (i == 5) q_ref(i) = q(i, &
                3)           ! the extent moves by stations: no extrapolation
            uncertainty(i) = abs(q_ref(i) - q(i, 3))
            if (i == 5) uncertainty(i) = abs(q(i, 3) - q(i, 2))
        end do
    end subroutine extrapolate

    subroutine study(plate, out_dir)
        logical, intent(in) :: plate
        character(len=*), intent(in) :: out_dir
        integer, parameter :: max_rows = size(ne_list) + size(ne_long) + max_extra_rows
        character(len=:), allocatable :: stem
        real(dp) :: q_ref(n_q), unc(n_q), q(n_q)
        real(dp) :: seconds(max_rows, n_disc), errors(n_q, max_rows, n_disc)
        integer :: ne(max_rows, n_disc), unknowns(max_rows, n_disc), rows(n_disc)
        logical :: ok(max_rows, n_disc)
        character(len=1) :: source(n_q)
        integer :: u, k, j, i
        stem = out_dir//'/work_precision_'//trim(merge('plate', 'beam ', plate))
        call reference(plate, q_ref, unc, source)
        rows = 0
        discretisations: do k = 1, n_disc
            do j = 1, size(ne_list) + merge(size(ne_long), 0, any(long_families == k))
                i = j
                if (.not. any(adapt_families == k)) i = all_ne(j)
                call measure(discretised(plate, k, i), q, seconds(j, k), unknowns(j, k), &
                             ok(j, k), ne(j, k))
                errors(1:4, j, k) = abs(q(1:4) - q_ref(1:4))/max(abs(q_ref(1:4)), tiny(1.0_dp))
                errors(5, j, k) = abs(q(5) - q_ref(5))
                rows(k) = j
            end do
        end do discretisations
        call fixed_continuation(plate, q_ref, rows, ne, unknowns, seconds, errors, ok)
        open (newunit=u, file=stem//'.txt', status='replace', action='write')
        write (u, '(a)') '# work-precision, '// &
            trim(merge('PLATE rho 0.001 zeta 0.1 f 0.6, disk load r <= 0.1 a           ', &
            'BEAM rho 0.001 zeta 0.1 beta 0.05 f 0.6, central load H = 0.1 V', plate))
        write (u, '(a)') '# reference (a): Richardson of P1/LOADS N_e 320, 640 (order from '// &
            '160/320/640)'
        write (u, '(a,i0,a)') '# reference (b): the P1-ADAPT mesh of tol 1e-4 (at most ', &
            reference_max, ' elements) bisected once and twice, Richardson (observed order)'
        write (u, '(a,i0,a)') '# reference (c): the S2w-P1tr-ADAPT mesh of tol 1e-4 (at most ', &
            reference_max, ' elements) bisected once and twice, solved S2w-P1tr, Richardson'
        write (u, '(a)') '# each quantity from the one with the smallest uncertainty |ref - finest|'
        do i = 1, n_q
            write (u, '(a,es14.6,a,es9.2,a)') '#   '//q_names(i), q_ref(i), '  uncertainty ', &
                unc(i), '  ('//source(i)//')'
        end do
        call write_costs(u, plate, rows, unknowns, seconds, errors, ok)
        write (u, '(a)') '# errors relative to the reference (extent: absolute, t); '// &
            'time: discretise + solve, processor time [s]'
        write (u, '(a)') '# '// &
            'disc              N_e  unknowns   time_s      err_W0      err_Sz0     '// &
            'err_Szmax   err_Mmax    err_extent'
        do k = 1, n_disc
            do j = 1, rows(k)
                call write_row(u, disc_names(k), ne(j, k), unknowns(j, k), seconds(j, k), &
                               errors(:, j, k), ok(j, k))
            end do
            write (u, '(a)') ''
            write (u, '(a)') ''
        end do
        close (u)
        write (output_unit, '(a)') 'work_precision: wrote '//stem//'.txt'
        call plot(stem, plate)
    end subroutine study

    !> The fixed families doubled beyond their last row while their compared error
    !! (compared_error) is above the smallest of the ADAPT families' and the doubled mesh has at
    !! most max_unknowns unknowns (estimated as twice the last row's), so that the cheapest
    !! fixed family at an ADAPT error comes from its rows, not an extrapolation.
    subroutine fixed_continuation(plate, q_ref, rows, ne, unknowns, seconds, errors, ok)
        logical, intent(in) :: plate
        real(dp), intent(in) :: q_ref(n_q)
        integer, intent(inout) :: rows(:), ne(:, :), unknowns(:, :)
        real(dp), intent(inout) :: seconds(:, :), errors(:, :, :)
        logical, intent(inout) :: ok(:, :)
        real(dp) :: q(n_q), smallest
        integer :: i, j, k
        smallest = huge(1.0_dp)
        do i = 1, size(adapt_families)
            k = adapt_families(i)
            do j = 1, rows(k)
                if (ok(j, k)) smallest = min(smallest, compared_error(plate, errors(:, j, k)))
            end do
        end do
        do i = 1, size(long_families)
            k = long_families(i)
            do while (rows(k) < size(seconds, 1) .and. 2*unknowns(rows(k), k) <= max_unknowns)
                j = rows(k)
                if (.not. ok(j, k) .or. compared_error(plate, errors(:, j, k)) <= smallest) exit
                call measure(discretised(plate, k, 2*ne(j, k)), q, seconds(j + 1, k), &
                             unknowns(j + 1, k), ok(j + 1, k), ne(j + 1, k))
                errors(1:4, j + 1, k) = abs(q(1:4) - q_ref(1:4))/max(abs(q_ref(1:4)), tiny(1.0_dp))
                errors(5, j + 1, k) = abs(q(5) - q_ref(5))
                rows(k) = j + 1
            end do
        end do
    end subroutine fixed_continuation

    !> The error scripts/adapt_pays.py compares: plate max(err W(0), err Sigma_z(0)), beam
    !! max(err W(0), err max |M|) (its Sigma_z(0) under the point load is singular).
    pure real(dp) function compared_error(plate, err_q)
        logical, intent(in) :: plate
        real(dp), intent(in) :: err_q(n_q)
        compared_error = max(err_q(1), merge(err_q(2), err_q(4), plate))
    end function compared_error

    !> For each family, the unknowns and time at which the error (plate: max(err W(0), err
    !! Sigma_z(0)); beam: err W(0), its Sigma_z(0) under the point load being singular) first
    !! reaches target_error: log-log interpolation between the two rows around the first row
    !! at or below it; when no row reaches it, extrapolated from the last two rows (marked),
    !! unless that needs more than 10 times the last row's unknowns.
    subroutine write_costs(u, plate, rows, unknowns, seconds, errors, ok)
        integer, intent(in) :: u, rows(:), unknowns(:, :)
        logical, intent(in) :: plate
        real(dp), intent(in) :: seconds(:, :), errors(:, :, :)
        logical, intent(in) :: ok(:, :)
        real(dp) :: e(size(seconds, 1)), s, n_at, t_at
        integer :: k, j, a
        character(len=14) :: how
        write (u, '(a,es8.1,a)') '# cost at '//trim(merge('max(err W(0), err Sigma_z(0))', &
            'err W(0)                     ', plate))//' = ', target_error, &
            ' (log-log interpolation along the rows, first crossing; '// &
            'extrapolated: beyond the last row)'
        families: do k = 1, size(rows)
            e(:rows(k)) = errors(1, :rows(k), k)
            if (plate) e(:rows(k)) = max(e(:rows(k)), errors(2, :rows(k), k))
            where (.not. ok(:rows(k), k)) e(:rows(k)) = huge(1.0_dp)
            j = findloc(e(:rows(k)) <= target_error, .true., dim=1)
            how = ''
            if (j == 1) then
                write (u, '(a,a18,a,i7,a,es9.2,a)') '#   ', disc_names(k), ' unknowns <=', &
                    unknowns(1, k), '   time <=', seconds(1, k), ' s (first row)'
                cycle families
            else if (j == 0) then
                j = rows(k)
                how = ' extrapolated'
            end if
            a = j - 1
            s = -1.0_dp
            if (e(j) < e(a)) s = log(target_error/e(a))/log(e(j)/e(a))
            n_at = -1.0_dp
            if (s >= 0.0_dp) n_at = exp(log(real(unknowns(a, k), dp)) + &
                                        s*log(real(unknowns(j, k), dp)/unknowns(a, k)))
            if (n_at < 0.0_dp .or. n_at > 10.0_dp*unknowns(rows(k), k)) then
                write (u, '(a,a18,a)') '#   ', disc_names(k), ' not reached'
                cycle families
            end if
            t_at = exp(log(seconds(a, k)) + s*log(seconds(j, k)/seconds(a, k)))
            write (u, '(a,a18,a,i7,a,es9.2,a)') '#   ', disc_names(k), ' unknowns ', nint(n_at), &
                '   time ', t_at, ' s'//how
        end do families
    end subroutine write_costs

    !> One row of the table: errors relative to the reference (the extent: absolute).
    subroutine write_row(u, name, ne, unknowns, seconds, err_q, ok)
        integer, intent(in) :: u, ne, unknowns
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: seconds, err_q(n_q)
        logical, intent(in) :: ok
        if (.not. ok) then
            write (u, '(a18,i5,i9,a)') name, ne, unknowns, '   failed'
            return
        end if
        write (u, '(a18,i5,i9,es11.3,5es12.3)') name, ne, unknowns, seconds, err_q
    end subroutine write_row

    !> stem.png: log error against log time, one curve per discretisation (gnuplot index
    !! blocks), one panel per quantity.
    subroutine plot(stem, plate)
        character(len=*), intent(in) :: stem
        logical, intent(in) :: plate
        integer :: u, i
        open (newunit=u, file=stem//'.gp', status='replace', action='write')
        write (u, '(a)') "set terminal pngcairo size 2100,1000 font 'Sans,11' noenhanced"
        write (u, '(a)') "set output '"//stem//".png'"
        write (u, '(a)') "set multiplot layout 2,4 title 'Work-precision, "// &
            trim(merge('PLATE (rho 0.001, f 0.6, disk load) ', &
                'BEAM (rho 0.001, f 0.6, H = 0.1 V)  ', &
                       plate))//": error against solve time' font 'Sans,14'"
        write (u, '(a)') 'set logscale xy; set grid; set format y "%.0e"; set format x "%.0e"'
        write (u, '(a)') "set linetype 9 lc rgb '#e0007a' lw 3    # the ninth family: magenta "// &
            "(8 is black)"
        write (u, '(a)') "set xlabel 'discretise + solve time [s]'; set key bottom left font ',9'"
        write (u, '(a)') "names = '"//join(disc_names)//"'"
        do i = 1, n_q
            write (u, '(a,i0,a)') "set title 'error of "//trim(q_names(i))//"'; plot for [k=0:", &
                n_disc - 1, "] '"//stem//".txt' index k u 4:(($"//int_text(4 + i)// &
                ">0)?$"//int_text(4 + i)//":1/0) w lp pt 7 lw 2 t word(names, k+1)"
        end do
        write (u, '(a)') "unset logscale x; set logscale x; set xlabel 'unknowns'"
        write (u, '(a)') "set title 'error of W(0) against unknowns'; plot for [k=0:"// &
            int_text(n_disc - 1)// &
            "] '"//stem//".txt' index k u 3:(($5>0)?$5:1/0) w lp pt 7 lw 2 t word(names, k+1)"
        write (u, '(a)') "set title 'error of Sigma_z(0) against unknowns'; plot for [k=0:"// &
            int_text(n_disc - 1)//"] '"//stem// &
                ".txt' index k u 3:(($6>0)?$6:1/0) w lp pt 7 lw 2 "// &
            "t word(names, k+1)"
        write (u, '(a)') 'unset multiplot'
        close (u)
        call execute_command_line('gnuplot '//stem//'.gp')
    end subroutine plot

    pure function join(words) result(text)
        character(len=*), intent(in) :: words(:)
        character(len=:), allocatable :: text
        integer :: i
        text = trim(words(1))
        do i = 2, size(words)
            text = text//' '//trim(words(i))
        end do
    end function join

end program work_precision
