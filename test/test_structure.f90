!> Placeholder suite: replaced by the real tests of structure.
module test_structure
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_structure
contains
    subroutine collect_structure(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_structure
end module test_structure
