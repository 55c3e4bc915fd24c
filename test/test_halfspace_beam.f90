!> Placeholder suite: replaced by the real tests of halfspace_beam.
module test_halfspace_beam
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_halfspace_beam
contains
    subroutine collect_halfspace_beam(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_halfspace_beam
end module test_halfspace_beam
