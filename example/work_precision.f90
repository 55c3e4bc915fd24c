!> Work-precision benchmark (issue 8 item 1): for a PLATE and a BEAM case with lift-off and
!! friction, each discretisation (interpolation x mesh family) over N_e = 10 ... 160, the error
!! of W(0), the centre and peak pressure, max |M| and the contact extent against a reference,
!! versus in-process solve time and versus unknowns.
!!
!! Reference: Richardson extrapolation of P1 / LOADS meshes at N_e = 320 and 640, with the
!! order observed from 160, 320, 640; its uncertainty (the extrapolation's change to the
!! finest value) is printed with it. Errors are relative to the reference value (the contact
!! extent: absolute, in t).
!!
!! Usage: fpm run --profile release --example work_precision [-- OUTDIR]   (default output/bench)
!! Writes OUTDIR/work_precision_{plate,beam}.txt and .png (gnuplot: log error against log time,
!! one curve per discretisation, one panel per quantity).
program work_precision
    use iso_fortran_env, only: int64, output_unit
    use kinds, only: dp
    use errors, only: error_t
    use gsl_wrappers, only: gsl_start
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, LOAD_PATCH, &
                     complete_model
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact
    use station_results, only: station_table_t, tabulate, contact_extent
    use station_columns, only: Q_X, Q_W, Q_SZ, Q_M, column_t, nondim_columns, column_index
    implicit none

    integer, parameter :: n_q = 5               !! W(0), Sigma_z(0), max Sigma_z, max |M|, extent
    character(len=*), parameter :: q_names(n_q) = [character(len=12) :: 'W(0)', 'Sigma_z(0)', &
                                                   'max_Sigma_z', 'max|M|', 'extent']
    integer, parameter :: n_disc = 6
    character(len=*), parameter :: disc_names(n_disc) = [character(len=14) :: 'P1-UNIFORM', &
        'P1-EDGES', 'P1-LOADS', 'P2-UNIFORM', 'S2-UNIFORM', 'S2w-P1tr-LOADS']
    integer, parameter :: ne_list(5) = [10, 20, 40, 80, 160]
    character(len=256) :: out_dir
    integer :: k

    out_dir = 'output/bench'
    if (command_argument_count() >= 1) call get_command_argument(1, out_dir)
    call gsl_start()
    call execute_command_line('mkdir -p '//trim(out_dir))
    do k = 1, 2
        call study(k == 1, trim(out_dir))
    end do

contains

    !> The case: plate rho 0.001, zeta 0.1, f 0.6, disk load r <= 0.1 a (issue 8's plate), or
    !! beam rho 0.001, zeta 0.1, beta 0.05, f 0.6, central point load with H = 0.1 V.
    function base_model(plate) result(m)
        logical, intent(in) :: plate
        type(model_t) :: m
        m%nondim = .true.
        m%rho_in = 1.0e-3_dp
        m%zeta_in = 0.1_dp
        m%f = 0.6_dp
        if (plate) then
            m%kind = MODEL_PLATE
            m%loads = [load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=0.1_dp)]
        else
            m%kind = MODEL_BEAM
            m%beta_in = 0.05_dp
            m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, fx=0.1_dp, x1=0.0_dp)]
        end if
    end function base_model

    !> Discretisation k of disc_names on ne elements.
    function discretised(plate, k, ne) result(m)
        logical, intent(in) :: plate
        integer, intent(in) :: k, ne
        type(model_t) :: m
        m = base_model(plate)
        m%ne = ne
        m%interp = INTERP_P1
        select case (k)
        case (2)
            m%grading = 'EDGES'
        case (3)
            m%grading = 'LOADS'
        case (4)
            m%interp = INTERP_P2
        case (5)
            m%interp = INTERP_S2
        case (6)
            m%grading = 'LOADS'
            m%interp(2:3) = INTERP_S2
        end select
        call complete_model(m)
    end function discretised

    !> Solve; q: the quantities (nondimensional), seconds: in-process wall time of the
    !! discretisation and the solve; unknowns; ok false if not solved.
    subroutine measure(m, q, seconds, unknowns, ok)
        type(model_t), intent(in) :: m
        real(dp), intent(out) :: q(n_q), seconds
        integer, intent(out) :: unknowns
        logical, intent(out) :: ok
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: err
        type(column_t), allocatable :: cols(:)
        integer(int64) :: t0, t1, rate
        integer :: i0
        call system_clock(t0, rate)
        call new_discretization(m, d, err)
        if (.not. allocated(err)) call solve_contact(m, d, sol, err)
        call system_clock(t1)
        seconds = real(t1 - t0, dp)/real(rate, dp)
        unknowns = d%n
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
        q(4) = maxval(abs(tab%val(Q_M, :)))*cols(column_index(cols, merge('M/(Fl)', 'M_r/F ', &
                                                                          m%kind == MODEL_BEAM)))%scale
        q(5) = contact_extent(tab, m%length)
    end subroutine measure

    !> Reference: Richardson from P1 LOADS at 160, 320, 640; uncertainty: |ref - q(640)|.
    subroutine reference(plate, q_ref, uncertainty)
        logical, intent(in) :: plate
        real(dp), intent(out) :: q_ref(n_q), uncertainty(n_q)
        real(dp) :: q(n_q, 3), seconds, p, d1, d2
        integer :: j, unknowns, i
        logical :: ok
        do j = 1, 3
            call measure(discretised(plate, 3, 160*2**(j - 1)), q(:, j), seconds, unknowns, ok)
            if (.not. ok) error stop 'work_precision: a reference solve failed'
        end do
        do i = 1, n_q
            d1 = q(i, 3) - q(i, 2)
            d2 = q(i, 2) - q(i, 1)
            p = 1.0_dp
            if (d1 /= 0.0_dp .and. d2 /= 0.0_dp .and. d1*d2 > 0.0_dp) &
                p = max(0.5_dp, min(4.0_dp, log(d2/d1)/log(2.0_dp)))
            q_ref(i) = q(i, 3) + d1/(2.0_dp**p - 1.0_dp)
            if (i == 5) q_ref(i) = q(i, 3)           ! the extent moves by stations: no extrapolation
            uncertainty(i) = abs(q_ref(i) - q(i, 3))
        end do
    end subroutine reference

    subroutine study(plate, out_dir)
        logical, intent(in) :: plate
        character(len=*), intent(in) :: out_dir
        character(len=:), allocatable :: stem
        real(dp) :: q_ref(n_q), unc(n_q), q(n_q), seconds, err_q(n_q)
        integer :: u, k, j, i, unknowns
        logical :: ok
        stem = out_dir//'/work_precision_'//trim(merge('plate', 'beam ', plate))
        call reference(plate, q_ref, unc)
        open (newunit=u, file=stem//'.txt', status='replace', action='write')
        write (u, '(a)') '# work-precision, '//trim(merge('PLATE rho 0.001 zeta 0.1 f 0.6, disk load r <= 0.1 a           ', &
            'BEAM rho 0.001 zeta 0.1 beta 0.05 f 0.6, central load H = 0.1 V', plate))
        write (u, '(a)') '# reference: Richardson of P1/LOADS N_e 320, 640 (order from 160/320/640)'
        do i = 1, n_q
            write (u, '(a,es14.6,a,es9.2)') '#   '//q_names(i), q_ref(i), '  uncertainty ', unc(i)
        end do
        write (u, '(a)') '# errors relative to the reference (extent: absolute, t); time: discretise + solve [s]'
        write (u, '(a)') '# disc            N_e  unknowns   time_s      err_W0      err_Sz0     err_Szmax   err_Mmax    err_extent'
        discretisations: do k = 1, n_disc
            do j = 1, size(ne_list)
                call measure(discretised(plate, k, ne_list(j)), q, seconds, unknowns, ok)
                if (.not. ok) then
                    write (u, '(a16,i5,i9,a)') disc_names(k), ne_list(j), unknowns, '   failed'
                    cycle
                end if
                err_q(1:4) = abs(q(1:4) - q_ref(1:4))/max(abs(q_ref(1:4)), tiny(1.0_dp))
                err_q(5) = abs(q(5) - q_ref(5))
                write (u, '(a16,i5,i9,es11.3,5es12.3)') disc_names(k), ne_list(j), unknowns, &
                    seconds, err_q
            end do
            write (u, '(a)') ''
            write (u, '(a)') ''
        end do discretisations
        close (u)
        write (output_unit, '(a)') 'work_precision: wrote '//stem//'.txt'
        call plot(stem, plate)
    end subroutine study

    !> stem.png: log error against log time, one curve per discretisation (gnuplot index
    !! blocks), one panel per quantity.
    subroutine plot(stem, plate)
        character(len=*), intent(in) :: stem
        logical, intent(in) :: plate
        integer :: u, i
        open (newunit=u, file=stem//'.gp', status='replace', action='write')
        write (u, '(a)') "set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced"
        write (u, '(a)') "set output '"//stem//".png'"
        write (u, '(a)') "set multiplot layout 2,3 title 'Work-precision, "// &
            trim(merge('PLATE (rho 0.001, f 0.6, disk load) ', 'BEAM (rho 0.001, f 0.6, H = 0.1 V)  ', &
                       plate))//": error against solve time' font 'Sans,14'"
        write (u, '(a)') 'set logscale xy; set grid; set format y "%.0e"; set format x "%.0e"'
        write (u, '(a)') "set xlabel 'discretise + solve time [s]'; set key bottom left font ',9'"
        write (u, '(a)') "names = '"//join(disc_names)//"'"
        do i = 1, n_q
            write (u, '(a,i0,a)') "set title 'error of "//trim(q_names(i))//"'; plot for [k=0:", &
                n_disc - 1, "] '"//stem//".txt' index k u 4:(($"//itoa(4 + i)// &
                ">0)?$"//itoa(4 + i)//":1/0) w lp pt 7 lw 2 t word(names, k+1)"
        end do
        write (u, '(a)') "unset logscale x; set logscale x; set xlabel 'unknowns'"
        write (u, '(a)') "set title 'error of W(0) against unknowns'; plot for [k=0:"//itoa(n_disc - 1)// &
            "] '"//stem//".txt' index k u 3:(($5>0)?$5:1/0) w lp pt 7 lw 2 t word(names, k+1)"
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

    pure function itoa(i) result(text)
        integer, intent(in) :: i
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') i
        text = trim(buf)
    end function itoa
end program work_precision
