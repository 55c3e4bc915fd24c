!> Placeholder suite: replaced by the real tests of convergence.
module test_convergence
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_convergence
contains
    subroutine collect_convergence(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_convergence
end module test_convergence
