!> The problems and the solve shared by the contact-solver and Newton test suites:
!! NONDIM plates and beams with a central point load (nu = 0.3, the paper's value), and one
!! call that discretises, solves and tabulates.
module contact_test_support
    use kinds, only: dp
    use harness, only: error_t
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, complete_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact
    use station_results, only: station_table_t, tabulate
    implicit none
    private
    public :: nondim_plate, nondim_beam, run

contains

    !> NONDIM plate (a = 1, F = 1): central point load.
    function nondim_plate(rho, zeta, nu_f, f, ne) result(m)
        real(dp), intent(in) :: rho, zeta, nu_f, f
        integer, intent(in) :: ne
        type(model_t) :: m
        m%structure%kind = MODEL_PLATE
        m%nondim = .true.
        m%groups%rho = rho
        m%groups%zeta = zeta
        m%structure%nu = 0.3_dp
        m%ground%nu_f = nu_f
        m%interface%f = f
        m%mesh%ne = ne
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.0_dp)]
        call complete_model(m)
    end function nondim_plate

    !> NONDIM beam (l = 1, F = 1): central point load V = 1 with horizontal component h_load;
    !! nu_f = 0.1 (the paper's value).
    function nondim_beam(rho, zeta, beta, f, h_load, ne) result(m)
        real(dp), intent(in) :: rho, zeta, beta, f, h_load
        integer, intent(in) :: ne
        type(model_t) :: m
        m%structure%kind = MODEL_BEAM
        m%nondim = .true.
        m%groups%rho = rho
        m%groups%zeta = zeta
        m%groups%beta = beta
        m%structure%nu = 0.3_dp
        m%ground%nu_f = 0.1_dp
        m%interface%f = f
        m%mesh%ne = ne
        m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, fx=h_load, x1=0.0_dp)]
        call complete_model(m)
    end function nondim_beam

    !> Discretise, solve and tabulate m.
    subroutine run(m, sol, tab, err)
        type(model_t), intent(in) :: m
        type(solution_t), intent(out) :: sol
        type(station_table_t), intent(out) :: tab
        type(error_t), allocatable, intent(out) :: err
        type(discretization_t) :: d
        call new_discretization(m, d, err)
        if (allocated(err)) return
        call solve_contact(m, d, sol, err)
        if (allocated(err)) return
        call tabulate(m, d, sol, tab, err)
    end subroutine run
end module contact_test_support
