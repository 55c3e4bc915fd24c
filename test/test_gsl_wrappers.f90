!> Placeholder suite: replaced by the real tests of gsl_wrappers.
module test_gsl_wrappers
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_gsl_wrappers
contains
    subroutine collect_gsl_wrappers(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_gsl_wrappers
end module test_gsl_wrappers
