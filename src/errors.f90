!> Error type carried up from library code to the single place that stops (app/main.f90).
!!
!! Library procedures take `type(error_t), allocatable, intent(out) :: err` as last argument;
!! allocated means failed. Exit codes follow SPEC §8.
module errors
    implicit none
    private

    integer, parameter, public :: EXIT_OK = 0        !! solved
    integer, parameter, public :: EXIT_INPUT = 1     !! input or file error
    integer, parameter, public :: EXIT_ANALYSIS = 2  !! no equilibrium, no convergence
    integer, parameter, public :: EXIT_INTERNAL = 3  !! broken invariant, library failure

    !> A failure: exit code and a human-readable message (may span lines).
    type, public :: error_t
        integer :: code = EXIT_INTERNAL    !! one of the EXIT_* codes
        character(len=:), allocatable :: message  !! what went wrong, for the user
    end type error_t

    public :: new_error, add_context

contains

    !> Allocate `err` with a code and a message.
    pure subroutine new_error(err, code, message)
        type(error_t), allocatable, intent(out) :: err  !! the new error
        integer, intent(in) :: code                      !! EXIT_* code
        character(len=*), intent(in) :: message          !! text
        allocate (err)
        err%code = code
        err%message = message
    end subroutine new_error

    !> Prefix the message of an existing error with where it happened.
    pure subroutine add_context(err, context)
        type(error_t), intent(inout) :: err      !! error travelling up
        character(len=*), intent(in) :: context  !! e.g. "assembling T"
        err%message = context//': '//err%message
    end subroutine add_context
end module errors
