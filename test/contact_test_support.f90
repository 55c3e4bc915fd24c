!> The NONDIM problems and the solves shared by the test suites: plates and beams (nu = 0.3,
!! the paper's value) with a central point load F = 1 or the loads given; one call that
!! solves a model by the one pipeline (solved_case) and returns its solution and stations,
!! and one that solves a case of a deck file.
module contact_test_support
    use kinds, only: dp
    use harness, only: error_t
    use errors, only: new_error, EXIT_INTERNAL
    use deck_reader, only: deck_t, read_deck, case_count, case_model
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, complete_model
    use contact_solver, only: solution_t
    use station_results, only: station_table_t
    use solved_case, only: case_t, solve_case
    implicit none
    private
    public :: nondim_plate, nondim_beam, run, solve_deck

contains

    !> NONDIM plate (a = 1, F = 1): a central point load, or the loads given.
    function nondim_plate(rho, zeta, nu_f, f, ne, loads) result(m)
        real(dp), intent(in) :: rho, zeta                 !! the groups rho and h/a
        real(dp), intent(in) :: nu_f                      !! the soil's Poisson's ratio
        real(dp), intent(in) :: f                         !! the friction coefficient
        integer, intent(in), optional :: ne               !! N_e (absent: the MESH default)
        type(load_t), intent(in), optional :: loads(:)    !! the loads (absent: F at r = 0)
        type(model_t) :: m
        m%structure%kind = MODEL_PLATE
        m%groups%zeta = zeta
        m%ground%nu_f = nu_f
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.0_dp)]
        call complete_nondim(m, rho, f, ne, loads)
    end function nondim_plate

    !> NONDIM beam (l = 1, F = 1, nu_f = 0.1, the paper's value): a central point load V = 1
    !! with horizontal component h_load, or the loads given.
    function nondim_beam(rho, zeta, beta, f, h_load, ne, loads) result(m)
        real(dp), intent(in) :: rho, zeta, beta           !! the groups rho, h/l and b/l
        real(dp), intent(in) :: f                         !! the friction coefficient
        real(dp), intent(in), optional :: h_load          !! H of the central load (absent: 0)
        integer, intent(in), optional :: ne               !! N_e (absent: the MESH default)
        type(load_t), intent(in), optional :: loads(:)    !! the loads (absent: V, H at x = 0)
        type(model_t) :: m
        real(dp) :: h
        h = 0.0_dp
        if (present(h_load)) h = h_load
        m%structure%kind = MODEL_BEAM
        m%groups%zeta = zeta
        m%groups%beta = beta
        m%ground%nu_f = 0.1_dp
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, fx=h, x1=0.0_dp)]
        call complete_nondim(m, rho, f, ne, loads)
    end function nondim_beam

    !> The parts common to plate and beam, then complete_model.
    subroutine complete_nondim(m, rho, f, ne, loads)
        type(model_t), intent(inout) :: m
        real(dp), intent(in) :: rho, f
        integer, intent(in), optional :: ne
        type(load_t), intent(in), optional :: loads(:)
        m%nondim = .true.
        m%groups%rho = rho
        m%structure%nu = 0.3_dp
        m%interface%f = f
        if (present(ne)) m%mesh%ne = ne
        if (present(loads)) m%loads = loads
        call complete_model(m)
    end subroutine complete_nondim

    !> Solve m by its MESH card (solved_case::solve_case): its solution and its stations. On
    !! failure sol keeps what the solver reported (counts, history).
    subroutine run(m, sol, tab, err)
        type(model_t), intent(in) :: m
        type(solution_t), intent(out) :: sol
        type(station_table_t), intent(out) :: tab
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        call solve_case(m, c, err)
        sol = c%sol
        tab = c%stations
    end subroutine run

    !> Read a deck, take its case case_no (absent: 1), change N_e to ne if ne > 0, and solve
    !! it (solved_case::solve_case).
    subroutine solve_deck(path, ne, c, err, case_no)
        character(len=*), intent(in) :: path
        integer, intent(in) :: ne                       !! 0: the deck's MESH
        type(case_t), intent(out) :: c
        type(error_t), allocatable, intent(out) :: err
        integer, intent(in), optional :: case_no
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        integer :: i
        i = 1
        if (present(case_no)) i = case_no
        call read_deck(path, deck, err)
        if (allocated(err)) return
        if (i > case_count(deck)) then
            call new_error(err, EXIT_INTERNAL, path//' has fewer cases than the test expects')
            return
        end if
        call case_model(deck, i, m, label, err)
        if (allocated(err)) return
        if (ne > 0) m%mesh%ne = ne
        call solve_case(m, c, err)
    end subroutine solve_deck
end module contact_test_support
