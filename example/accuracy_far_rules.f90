!> Accuracy of the far rules of the half-space assembly (doc/METHOD.md, Assembly of the half-space
!! flexibility T): T assembled with the default far rules, with the far rules of 15 digits (the
!! rules of main c75ff9c) and with rules of 20 digits (a reference for the far pairs: every other
!! pair is integrated by the same rules in all three), on PLATE and BEAM meshes, uniform and graded
!! (EDGES), P1/P1 and P2/S2. Prints a Markdown table: kernel evaluations, max |T - T_20| / max
!! |T_20| (the accuracy contract: entries to about 1e-14 of the largest), the largest error of an
!! entry relative to itself (entries above 1e-8 of the largest), and for N_e <= ref_max_ne the
!! distance from the adaptive reference (assemble_split_kernel_reference). Usage: `fpm run --profile
!! release --example accuracy_far_rules [-- max_ne [ref_max_ne [digits]]]`; with digits the first
!! column is that of far rules of `digits` digits instead of the default rules.
program accuracy_far_rules
    use iso_fortran_env, only: int64, output_unit
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1, INTERP_P2, INTERP_S2, interp_name
    use halfspace_plate, only: assemble_plate_flexibility
    use halfspace_beam, only: assemble_beam_flexibility
    implicit none
    integer, parameter :: n_case = 14
    integer, parameter :: ne_case(n_case) = [20, 100, 200, 1000, 160, 1000, 80, 160, &
                                             20, 200, 1000, 160, 80, 160]
    logical, parameter :: plate_case(n_case) = [spread(.true., 1, 8), spread(.false., 1, 6)]
    character(len=7), parameter :: grading_case(n_case) = [character(len=7) :: &
        'UNIFORM', 'UNIFORM', 'UNIFORM', 'UNIFORM', 'EDGES', 'EDGES', 'UNIFORM', 'EDGES', &
        'UNIFORM', 'UNIFORM', 'UNIFORM', 'EDGES', 'UNIFORM', 'EDGES']
    logical, parameter :: quadratic_case(n_case) = [.false., .false., .false., .false., &
        .false., .false., .true., .true., .false., .false., .false., .false., .true., .true.]
    integer :: i, max_ne, ref_max_ne
    real(dp) :: trial_digits
    character(len=32) :: arg

    call start_program()
    max_ne = 1000
    ref_max_ne = 80
    trial_digits = -1.0_dp
    if (command_argument_count() >= 1) then
        call get_command_argument(1, arg)
        read (arg, *) max_ne
    end if
    if (command_argument_count() >= 2) then
        call get_command_argument(2, arg)
        read (arg, *) ref_max_ne
    end if
    if (command_argument_count() >= 3) then
        call get_command_argument(3, arg)
        read (arg, *) trial_digits
    end if
    write (output_unit, '(a)') '| model | mesh | N_e | sigma_x/sigma_z | kernel evals, default '// &
        '(15 digits) | max\|dT\|/max\|T\| against 20 digits, default (15 digits) | '// &
        'largest entry error / entry, default (15 digits) | max\|dT\|/max\|T\| against the '// &
        'adaptive reference, default (15 digits) |'
    write (output_unit, '(a)') '|---|---|---:|---|---:|---:|---:|---:|'
    cases: do i = 1, n_case
        if (ne_case(i) > max_ne) cycle cases
        call run_case(plate_case(i), trim(grading_case(i)), ne_case(i), quadratic_case(i), &
                      ne_case(i) <= ref_max_ne)
    end do cases

contains

    !> One table row.
    subroutine run_case(plate, grading, ne, quadratic, with_reference)
        logical, intent(in) :: plate, quadratic, with_reference
        character(len=*), intent(in) :: grading
        integer, intent(in) :: ne
        type(mesh_t) :: msh
        type(basis_t) :: bx, bz
        type(error_t), allocatable :: err
        real(dp), allocatable :: t_new(:, :), t_15(:, :), t_20(:, :), t_ref(:, :)
        integer(int64) :: n_new, n_15, n_20, n_ref
        character(len=5) :: model
        character(len=40) :: ref_text
        if (plate) then
            call new_mesh(msh, 0.0_dp, 1.0_dp, ne, grading, err)
            model = 'PLATE'
        else
            call new_mesh(msh, -0.5_dp, 0.5_dp, ne, grading, err)
            model = 'BEAM'
        end if
        if (allocated(err)) error stop 'accuracy_far_rules: mesh'
        if (quadratic) then
            call new_basis(bx, msh, INTERP_P2)
            call new_basis(bz, msh, INTERP_S2)
        else
            call new_basis(bx, msh, INTERP_P1)
            call new_basis(bz, msh, INTERP_P1)
        end if
        call assemble(plate, bx, bz, trial_digits, t_new, n_new)
        call assemble(plate, bx, bz, 15.0_dp, t_15, n_15)
        call assemble(plate, bx, bz, 20.0_dp, t_20, n_20)
        ref_text = '-'
        if (with_reference) then
            call assemble(plate, bx, bz, 0.0_dp, t_ref, n_ref)
            write (ref_text, '(es8.1," (",es8.1,")")') relative_max(t_new, t_ref), &
                relative_max(t_15, t_ref)
        end if
        if (any(t_new /= transpose(t_new))) error stop 'accuracy_far_rules: T not symmetric'
        write (output_unit, '("| ",a," | ",a," | ",i0," | ",a,"/",a," | ",i0," (",i0,") | ", &
               &es8.1," (",es8.1,") | ",es8.1," (",es8.1,") | ",a," |")') trim(model), grading, &
            ne, trim(interp_name(bx%family)), trim(interp_name(bz%family)), n_new, n_15, &
            relative_max(t_new, t_20), relative_max(t_15, t_20), entry_max(t_new, t_20), &
            entry_max(t_15, t_20), trim(ref_text)
        flush (output_unit)
    end subroutine run_case

    !> max |a - b| / max |b|.
    pure real(dp) function relative_max(a, b)
        real(dp), intent(in) :: a(:, :), b(:, :)
        relative_max = maxval(abs(a - b))/maxval(abs(b))
    end function relative_max

    !> max |a - b| / |b| over the entries of b above 1e-8 of its largest.
    pure real(dp) function entry_max(a, b)
        real(dp), intent(in) :: a(:, :), b(:, :)
        entry_max = maxval(abs(a - b)/abs(b), mask=abs(b) > 1.0e-8_dp*maxval(abs(b)))
    end function entry_max

    !> T with the far rules of `digits` (negative: the default; 0: the adaptive reference);
    !! paper soil nu_f = 0.1, beam width b/l = 0.0055 as in bench_assembly.
    subroutine assemble(plate, bx, bz, digits, t_mat, n_kernel)
        logical, intent(in) :: plate
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: digits
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        integer(int64), intent(out) :: n_kernel
        type(error_t), allocatable :: err
        if (plate) then
            if (digits < 0.0_dp) then
                call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t_mat, err, .false., &
                                                n_kernel)
            else
                call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t_mat, err, &
                                                digits == 0.0_dp, n_kernel, digits)
            end if
        else
            if (digits < 0.0_dp) then
                call assemble_beam_flexibility(bx, bz, 1.0_dp, 0.1_dp, 0.0055_dp, t_mat, err, &
                                               .false., n_kernel)
            else
                call assemble_beam_flexibility(bx, bz, 1.0_dp, 0.1_dp, 0.0055_dp, t_mat, err, &
                                               digits == 0.0_dp, n_kernel, digits)
            end if
        end if
        if (allocated(err)) error stop 'accuracy_far_rules: assembly failed'
    end subroutine assemble
end program accuracy_far_rules
