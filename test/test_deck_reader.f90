!> Placeholder suite: replaced by the real tests of deck_reader.
module test_deck_reader
    use harness, only: unittest_t
    implicit none
    private
    public :: collect_deck_reader
contains
    subroutine collect_deck_reader(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        allocate (tests(0))
    end subroutine collect_deck_reader
end module test_deck_reader
