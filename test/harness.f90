!> Minimal test harness shaped like test-drive: named tests, checks that allocate an error,
!! a suite runner printing `ok name` / `FAIL name: message`.
module harness
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    implicit none
    private

    abstract interface
        subroutine test_interface(err)
            import :: error_t
            type(error_t), allocatable, intent(out) :: err
        end subroutine test_interface
    end interface

    !> A named test procedure.
    type, public :: unittest_t
        character(len=:), allocatable :: name
        procedure(test_interface), pointer, nopass :: test => null()
    end type unittest_t

    public :: error_t, test_interface, new_unittest, check, check_close, run_suite

contains

    function new_unittest(name, test) result(t)
        character(len=*), intent(in) :: name
        procedure(test_interface) :: test
        type(unittest_t) :: t
        t%name = name
        t%test => test
    end function new_unittest

    !> Fail with `message` unless `condition` holds.
    subroutine check(err, condition, message)
        type(error_t), allocatable, intent(out) :: err
        logical, intent(in) :: condition
        character(len=*), intent(in) :: message
        if (.not. condition) call new_error(err, EXIT_INTERNAL, message)
    end subroutine check

    !> Pass if |actual - expected| <= max(atol, rtol |expected|) and both are finite.
    subroutine check_close(err, actual, expected, rtol, atol, what)
        type(error_t), allocatable, intent(out) :: err
        real(dp), intent(in) :: actual, expected, rtol, atol
        character(len=*), intent(in) :: what
        character(len=200) :: text
        real(dp) :: diff
        diff = abs(actual - expected)
        if (diff <= max(atol, rtol*abs(expected)) .and. diff == diff) return
        write (text, '(a,": got ",es24.16," expected ",es24.16," (rel ",es9.2,")")') &
            trim(what), actual, expected, diff/max(abs(expected), tiny(1.0_dp))
        call new_error(err, EXIT_INTERNAL, trim(text))
    end subroutine check_close

    !> Run the tests of one suite (all, or only the one named `only`), counting results.
    subroutine run_suite(suite, tests, only, n_pass, n_fail)
        character(len=*), intent(in) :: suite
        type(unittest_t), intent(in) :: tests(:)
        character(len=*), intent(in) :: only          !! '' for all
        integer, intent(inout) :: n_pass, n_fail
        type(error_t), allocatable :: err
        integer :: i
        tests_loop: do i = 1, size(tests)
            if (len_trim(only) > 0 .and. tests(i)%name /= trim(only)) cycle tests_loop
            call tests(i)%test(err)
            if (allocated(err)) then
                n_fail = n_fail + 1
                write (*, '(a)') 'FAIL '//suite//'/'//tests(i)%name//': '//err%message
                deallocate (err)
            else
                n_pass = n_pass + 1
                write (*, '(a)') 'ok   '//suite//'/'//tests(i)%name
            end if
            flush (6)
        end do tests_loop
    end subroutine run_suite
end module harness
