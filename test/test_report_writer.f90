!> Placeholder suite: replaced by the real tests of report_writer.
module test_report_writer
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_report_writer
contains
    subroutine collect_report_writer(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_report_writer
end module test_report_writer
