program zz_prof
    use kinds, only: dp
    use errors, only: error_t
    use gsl_wrappers, only: gsl_start
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1
    use halfspace_plate, only: assemble_plate_flexibility
    implicit none
    type(mesh_t) :: msh
    type(basis_t) :: bx, bz
    type(error_t), allocatable :: err
    real(dp), allocatable :: t(:, :)
    integer :: i, ne, nrep
    character(32) :: arg
    real(dp) :: c0, c1
    call gsl_start()
    call get_command_argument(1, arg); read (arg, *) ne
    call get_command_argument(2, arg); read (arg, *) nrep
    call new_mesh(msh, 0.0_dp, 1.0_dp, ne, 'UNIFORM', err)
    call new_basis(bx, msh, INTERP_P1)
    call new_basis(bz, msh, INTERP_P1)
    call cpu_time(c0)
    do i = 1, nrep
        call assemble_plate_flexibility(bx, bz, 1.0_dp, 0.1_dp, t, err)
    end do
    call cpu_time(c1)
    print *, (c1 - c0)/nrep*1e3, ' ms'
end program zz_prof
