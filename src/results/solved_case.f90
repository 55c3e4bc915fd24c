!> One case from model and mesh to results: the one pipeline every caller uses (the driver,
!! the refinement policies of src/quality, the tests and the benchmarks).
!!
!!   model + discretisation --solve_contact--> solution --tabulate--> station table (OUTPUT)
!!     --tabulate_design--> design table (every node, patch edge and load position)
!!     --summarise--> design summary --summary_entries--> key results (with their units)
!!
!! Everything after the solve is a pure function of the solution: results never change it.
module solved_case
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact, coarse_solution_t
    use flexibility_cache, only: flexibility_cache_t
    use station_results, only: station_table_t, tabulate, tabulate_design, contact_extent
    use design_summary, only: summary_t, summarise
    use summary_table, only: entry_t, summary_entries
    implicit none
    private

    !> A solved case and everything derived from its solution.
    type, public :: case_t
        type(model_t) :: model                !! the model solved (its mesh request: this mesh)
        type(discretization_t) :: d           !! mesh, bases and numbering
        type(solution_t) :: sol               !! the solution of the contact problem
        type(station_table_t) :: stations     !! the OUTPUT card's stations (reports, data)
        type(station_table_t) :: design       !! every node, patch edge and load position
        type(summary_t) :: summary            !! design values read from the design table
        real(dp) :: extent = -1.0_dp          !! contact extent t (contact_extent)
        type(entry_t), allocatable :: entries(:)  !! key results (summary_table)
    end type case_t

    public :: solve_case, solve_on, finish_case, failed_case

contains

    !> Discretise m by its MESH card and solve it (solve_on).
    subroutine solve_case(m, c, err, progress_unit, cache)
        type(model_t), intent(in) :: m                  !! the model
        type(case_t), intent(out) :: c                  !! the finished case
        type(error_t), allocatable, intent(out) :: err  !! solve or tabulation failed
        integer, intent(in), optional :: progress_unit  !! a unit for one line per Newton step
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(discretization_t) :: d
        call new_discretization(m, d, err)
        if (allocated(err)) return
        call solve_on(m, d, c, err, progress_unit, cache)
    end subroutine solve_case

    !> Solve m on the discretisation d and finish the case (finish_case).
    subroutine solve_on(m, d, c, err, progress_unit, cache, start, soil)
        type(model_t), intent(in) :: m                  !! the model
        type(discretization_t), intent(in) :: d         !! any mesh of m (MESH card, adapted)
        type(case_t), intent(out) :: c                  !! the finished case
        type(error_t), allocatable, intent(out) :: err  !! solve or tabulation failed
        integer, intent(in), optional :: progress_unit  !! a unit for one line per Newton step
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> a solution known on d's nested coarser mesh (contact_solver, solve_contact)
        type(coarse_solution_t), intent(in), optional :: start
        !> the soil's displacement at the stations too (default; finish_case)
        logical, intent(in), optional :: soil
        type(solution_t) :: sol
        if (present(progress_unit)) then
            if (progress_unit >= 0) then
                call solve_contact(m, d, sol, err, progress_unit, cache=cache, start=start)
            else
                call solve_contact(m, d, sol, err, cache=cache, start=start)
            end if
        else
            call solve_contact(m, d, sol, err, cache=cache, start=start)
        end if
        if (allocated(err)) then
            c = failed_case(m, d, sol)
            return
        end if
        call finish_case(m, d, sol, c, err, soil)
    end subroutine solve_on

    !> A case whose solve failed: what there is of it (the discretisation, the solver's counts
    !! and history) for the report of the failure; no tables and no key results.
    function failed_case(m, d, sol) result(c)
        type(model_t), intent(in) :: m              !! the model
        type(discretization_t), intent(in) :: d     !! its discretisation
        type(solution_t), intent(in) :: sol         !! the failed solve's state
        type(case_t) :: c
        c%model = m
        c%d = d
        c%sol = sol
        allocate (c%entries(0))
    end function failed_case

    !> The results of a solution: station and design tables, design summary, key results.
    subroutine finish_case(m, d, sol, c, err, soil)
        type(model_t), intent(in) :: m                  !! the model solved
        type(discretization_t), intent(in) :: d         !! its discretisation
        type(solution_t), intent(in) :: sol             !! its solution
        type(case_t), intent(out) :: c                  !! the finished case
        type(error_t), allocatable, intent(out) :: err  !! a station value not finite
        !> the soil's displacement at the stations too (default); .false. for a case only the
        !! key results of are read (station_results::tabulate)
        logical, intent(in), optional :: soil
        c%model = m
        c%d = d
        c%sol = sol
        allocate (c%entries(0))
        call tabulate(m, d, sol, c%stations, err, soil=soil)
        if (.not. allocated(err)) call tabulate_design(m, d, sol, c%stations, c%design, err, &
                                                       soil)
        if (allocated(err)) return
        c%summary = summarise(m, sol, c%design)
        c%extent = contact_extent(c%design, m%structure%length)
        c%entries = summary_entries(m, c%summary, c%extent)
    end subroutine finish_case
end module solved_case
