program zz_prof2
    use kinds, only: dp
    use errors, only: error_t
    use gsl_wrappers, only: gsl_start
    use model, only: model_t
    use deck_reader, only: deck_t, read_deck, case_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact
    implicit none
    type(deck_t) :: deck
    type(model_t) :: m
    type(discretization_t) :: d
    type(solution_t) :: sol
    type(error_t), allocatable :: err
    character(len=:), allocatable :: label
    integer :: i, ne, nrep
    character(64) :: arg, path
    real(dp) :: c0, c1
    call gsl_start()
    call get_command_argument(1, path)
    call get_command_argument(2, arg); read (arg, *) ne
    call get_command_argument(3, arg); read (arg, *) nrep
    call read_deck(trim(path), deck, err)
    call case_model(deck, 1, m, label, err)
    m%ne = ne
    call new_discretization(m, d, err)
    call cpu_time(c0)
    do i = 1, nrep
        call solve_contact(m, d, sol, err)
        if (allocated(err)) error stop 'fail'
    end do
    call cpu_time(c1)
    print *, (c1 - c0)/nrep*1e3, ' ms', sol%n_solves, sol%n_factorisations
end program zz_prof2
