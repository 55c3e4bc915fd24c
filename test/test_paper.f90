!> Placeholder suite: replaced by the real tests of paper.
module test_paper
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_paper
contains
    subroutine collect_paper(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_paper
end module test_paper
