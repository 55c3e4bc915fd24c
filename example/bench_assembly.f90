!> Benchmark of the half-space flexibility assembly (doc/METHOD.md, Assembly of the half-space
!! flexibility T): times the assembly of T for PLATE and BEAM meshes, the fast fixed-order assembly
!! and the adaptive reference (assemble_split_kernel_reference) in the same run, and prints a
!! Markdown table with the number of unknowns, processor seconds and wall seconds of the fast
!! assembly (least of repeated runs; with OMP_NUM_THREADS > 1 the processor time is that of all
!! threads), kernel evaluations and max |T_fast - T_ref| / max |T_ref|. Usage: `fpm run --profile
!! release --example bench_assembly [-- max_ne [ref_max_ne]]`.
program bench_assembly
    use iso_fortran_env, only: int64, output_unit, error_unit
    !$ use omp_lib, only: omp_get_max_threads
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1, INTERP_P2, INTERP_S2, interp_name
    use halfspace_plate, only: assemble_plate_flexibility
    use halfspace_beam, only: assemble_beam_flexibility
    implicit none
    integer, parameter :: n_case = 14
    integer, parameter :: ne_case(n_case) = [20, 50, 80, 100, 200, 320, 500, 1000, 80, &
                                             20, 80, 320, 1000, 80]
    logical, parameter :: plate_case(n_case) = [spread(.true., 1, 9), spread(.false., 1, 5)]
    logical, parameter :: quadratic_case(n_case) = [spread(.false., 1, 8), .true., &
                                                    spread(.false., 1, 4), .true.]
    integer, parameter :: fam_case(n_case) = merge(INTERP_P2, INTERP_P1, quadratic_case)
    integer, parameter :: fam_z_case(n_case) = merge(INTERP_S2, INTERP_P1, quadratic_case)
    integer :: i, max_ne, ref_max_ne, threads
    character(len=32) :: arg

    call start_program()
    max_ne = 1000
    ref_max_ne = 1000
    if (command_argument_count() >= 1) then
        call get_command_argument(1, arg)
        read (arg, *) max_ne
    end if
    if (command_argument_count() >= 2) then
        call get_command_argument(2, arg)
        read (arg, *) ref_max_ne
    end if
    threads = 1
    !$ threads = omp_get_max_threads()
    write (output_unit, '(a,i0)') 'OpenMP threads: ', threads
    write (output_unit, '(a)') '| model | N_e | sigma_x/sigma_z | unknowns | reference s | '// &
        'reference kernel evals | fast s | fast wall s | fast kernel evals | speed-up | '// &
        'max|dT|/max|T| |'
    write (output_unit, '(a)') '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|'
    cases: do i = 1, n_case
        if (ne_case(i) > max_ne) cycle cases
        call run_case(plate_case(i), ne_case(i), fam_case(i), fam_z_case(i), &
                      ne_case(i) <= ref_max_ne)
    end do cases

contains

    !> Assemble T both ways for one mesh and print one table row.
    subroutine run_case(plate, ne, fam_x, fam_z, with_reference)
        logical, intent(in) :: plate, with_reference
        integer, intent(in) :: ne, fam_x, fam_z
        type(mesh_t) :: msh
        type(basis_t) :: bx, bz
        type(error_t), allocatable :: err
        real(dp), allocatable :: t_fast(:, :), t_ref(:, :)
        real(dp) :: s_fast, s_ref, diff, w_fast, w_ref
        integer(int64) :: n_fast, n_ref
        character(len=5) :: model
        character(len=40) :: ref_s, ref_n, speed, diff_s
        if (plate) then
            call new_mesh(msh, 0.0_dp, 1.0_dp, ne, 'UNIFORM', err)
            model = 'PLATE'
        else
            call new_mesh(msh, -0.5_dp, 0.5_dp, ne, 'UNIFORM', err)
            model = 'BEAM'
        end if
        if (allocated(err)) error stop 'bench_assembly: mesh'
        call new_basis(bx, msh, fam_x)
        call new_basis(bz, msh, fam_z)
        call assemble(plate, bx, bz, .false., t_fast, s_fast, w_fast, n_fast)
        ref_s = '-'
        ref_n = '-'
        speed = '-'
        diff_s = '-'
        if (with_reference) then
            call assemble(plate, bx, bz, .true., t_ref, s_ref, w_ref, n_ref)
            diff = maxval(abs(t_fast - t_ref))/maxval(abs(t_ref))
            write (ref_s, '(f0.5)') s_ref
            write (ref_n, '(i0)') n_ref
            write (speed, '(f0.1)') s_ref/max(s_fast, 1.0e-9_dp)
            write (diff_s, '(es8.1)') diff
        end if
        write (output_unit, '("| ",a," | ",i0," | ",a,"/",a," | ",i0," | ",a," | ",a," | ",f0.5, &
               &" | ",f0.5," | ",i0," | ",a," | ",a," |")') trim(model), ne, &
            trim(interp_name(fam_x)), trim(interp_name(fam_z)), bx%n_dof + bz%n_dof, trim(ref_s), &
            trim(ref_n), s_fast, w_fast, n_fast, trim(speed), trim(diff_s)
        flush (output_unit)
    end subroutine run_case

    !> Assemble T, processor seconds of this process (cpu_time: the machine is shared, so wall
    !! time also measures the other jobs; on more than one thread it is the sum over the
    !! threads) and wall seconds, each the least of repeated runs (until 1 s has been spent or
    !! 15 runs), and kernel evaluations (paper soil nu_f = 0.1; beam width b/l = 0.0055 as in
    !! the paper's beam decks).
    subroutine assemble(plate, bx, bz, reference, t_mat, seconds, wall, n_kernel)
        logical, intent(in) :: plate, reference
        type(basis_t), intent(in) :: bx, bz
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        real(dp), intent(out) :: seconds, wall
        integer(int64), intent(out) :: n_kernel
        type(error_t), allocatable :: err
        real(dp) :: spent, once, c0, c1
        integer(int64) :: w0, w1, rate
        integer :: run
        seconds = huge(1.0_dp)
        wall = huge(1.0_dp)
        spent = 0.0_dp
        runs: do run = 1, 15
            if (allocated(t_mat)) deallocate (t_mat)
            call system_clock(w0, rate)
            call cpu_time(c0)
            if (plate) then
                call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t_mat, err, reference, &
                                                n_kernel)
            else
                call assemble_beam_flexibility(bx, bz, 1.0_dp, 0.1_dp, 0.0055_dp, t_mat, err, &
                                               reference, n_kernel)
            end if
            call cpu_time(c1)
            call system_clock(w1)
            wall = min(wall, real(w1 - w0, dp)/real(rate, dp))
            if (allocated(err)) then
                write (error_unit, '(a)') 'ERROR: '//err%message
                error stop 3
            end if
            once = c1 - c0
            seconds = min(seconds, once)
            spent = spent + once
            if (spent > 1.0_dp) exit runs
        end do runs
    end subroutine assemble
end program bench_assembly
