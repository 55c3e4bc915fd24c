!> Placeholder suite: replaced by the real tests of contact_solver.
module test_contact_solver
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_contact_solver
contains
    subroutine collect_contact_solver(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_contact_solver
end module test_contact_solver
