!> Placeholder suite: replaced by the real tests of shape_functions.
module test_shape_functions
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_shape_functions
contains
    subroutine collect_shape_functions(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_shape_functions
end module test_shape_functions
