!> Interpolated far blocks of the plate's half-space flexibility (doc/METHOD.md, Assembly of the
!! half-space flexibility T): T assembled with the interpolated blocks (galerkin_assembly,
!! add_blocks) against T assembled pair by pair (`pairwise`: the assembly of main fc09087), PLATE on
!! uniform and graded (EDGES) meshes, P1/P1, P2/P2 and S2/S2, N_e 20 to 1000. Prints a Markdown
!! table: processor seconds of both (least of repeated runs, one thread advised), kernel evaluations
!! and max|dT|/max|T|. Usage: `fpm run --profile release --example accuracy_blocks [-- max_ne
!! [profile]]`; with a second argument the pairwise assembly runs once only (profiles of the
!! blocks).
program accuracy_blocks
    use iso_fortran_env, only: int64, output_unit
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1, INTERP_P2, INTERP_S2, interp_name
    use halfspace_plate, only: assemble_plate_flexibility
    implicit none
    integer, parameter :: ne_list(9) = [20, 50, 80, 100, 128, 200, 320, 500, 1000]
    integer, parameter :: fams(3) = [INTERP_P1, INTERP_P2, INTERP_S2]
    character(len=7), parameter :: gradings(2) = [character(len=7) :: 'UNIFORM', 'EDGES']
    integer :: i, j, k, max_ne
    logical :: blocks_only
    character(len=32) :: arg

    call start_program()
    max_ne = 1000
    if (command_argument_count() >= 1) then
        call get_command_argument(1, arg)
        read (arg, *) max_ne
    end if
    blocks_only = command_argument_count() >= 2   ! profiling: the pairwise assembly once
    write (output_unit, '(a)') '| mesh | N_e | sigma_x/sigma_z | pairwise s | blocks s | '// &
        'speed-up | pairwise kernel evals | blocks kernel evals | max\|dT\|/max\|T\| |'
    write (output_unit, '(a)') '|---|---:|---|---:|---:|---:|---:|---:|---:|'
    do k = 1, size(gradings)
        do j = 1, size(fams)
            do i = 1, size(ne_list)
                if (ne_list(i) > max_ne) cycle
                call run_case(trim(gradings(k)), ne_list(i), fams(j))
            end do
        end do
    end do

contains

    subroutine run_case(grading, ne, fam)
        character(len=*), intent(in) :: grading
        integer, intent(in) :: ne, fam
        type(mesh_t) :: msh
        type(basis_t) :: bx, bz
        type(error_t), allocatable :: err
        real(dp), allocatable :: t_pair(:, :), t_block(:, :)
        real(dp) :: s_pair, s_block
        integer(int64) :: n_pair, n_block
        call new_mesh(msh, 0.0_dp, 1.0_dp, ne, grading, err)
        if (allocated(err)) error stop 'accuracy_blocks: mesh'
        call new_basis(bx, msh, fam)
        call new_basis(bz, msh, fam)
        if (blocks_only) then
            call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t_pair, err, &
                                            n_kernel=n_pair, pairwise=.true.)
            s_pair = 0.0_dp
        else
            call assemble(bx, bz, .true., t_pair, s_pair, n_pair)
        end if
        call assemble(bx, bz, .false., t_block, s_block, n_block)
        write (output_unit, '("| ",a," | ",i0," | ",a,"/",a," | ",f0.5," | ",f0.5," | ",f0.2, &
            &" | ",i0," | ",i0," | ",es8.1," |")') grading, ne, trim(interp_name(fam)), &
            trim(interp_name(fam)), s_pair, s_block, s_pair/s_block, n_pair, n_block, &
            maxval(abs(t_block - t_pair))/maxval(abs(t_pair))
    end subroutine run_case

    !> Assemble T; least processor time of repeated runs (at least 0.2 s in all).
    subroutine assemble(bx, bz, pairwise, t_mat, seconds, n_kernel)
        type(basis_t), intent(in) :: bx, bz
        logical, intent(in) :: pairwise
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        real(dp), intent(out) :: seconds
        integer(int64), intent(out) :: n_kernel
        type(error_t), allocatable :: err
        real(dp) :: c0, c1, total
        integer :: runs
        seconds = huge(1.0_dp)
        total = 0.0_dp
        runs = 0
        do while (runs < 3 .or. (total < 0.2_dp .and. runs < 200))
            call cpu_time(c0)
            call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t_mat, err, &
                                            n_kernel=n_kernel, pairwise=pairwise)
            call cpu_time(c1)
            if (allocated(err)) error stop 'accuracy_blocks: assembly failed'
            seconds = min(seconds, c1 - c0)
            total = total + (c1 - c0)
            runs = runs + 1
        end do
    end subroutine assemble
end program accuracy_blocks
