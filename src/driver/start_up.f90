!> What every program of the project does once before any work, while it runs one thread:
!! GSL's error handler off (its default aborts the process; every GSL status is checked
!! instead) and the run's date and time recorded (run_identity). The quadrature tables are
!! constants of the program (gauss_rule_tables).
module start_up
    use gsl_wrappers, only: gsl_start
    use run_identity, only: record_run_time
    implicit none
    private

    public :: start_program

contains

    !> Once, first thing in a program.
    subroutine start_program()
        call gsl_start()
        call record_run_time()
    end subroutine start_program
end module start_up
