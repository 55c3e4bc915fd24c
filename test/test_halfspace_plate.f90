!> Placeholder suite: replaced by the real tests of halfspace_plate.
module test_halfspace_plate
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_halfspace_plate
contains
    subroutine collect_halfspace_plate(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_halfspace_plate
end module test_halfspace_plate
