!> Fuzz driver for the deck reader (issue #10, item 1). Not part of `fpm test`: built by
!! scripts/fuzz.sh from fuzz/ and the reader's sources only.
!!
!!     fuzz_deck FILE
!!
!! Reads FILE with read_deck; for a readable deck builds every SWEEP case with case_model and
!! the plausibility warnings of each case. Contract (the fuzzing oracle):
!!   exit 0  the deck and all its cases are valid models (finite, in range)
!!   exit 1  an input error, reported as a non-empty message on standard error
!!   abort   (SIGABRT) a broken invariant of the reader: a bug. A gfortran runtime error
!!           (-fcheck=all: bounds, allocation, ...) ends with exit 2, which the campaign
!!           treats as a crash too (AFL_CRASH_EXITCODE=2).
!! A deck with more cases than max_cases_checked is checked on its first and last cases only
!! (case_model is pure bookkeeping; the cap keeps one execution well under the timeout).
program fuzz_deck
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use errors, only: error_t, EXIT_INPUT
    use model, only: model_t, MODEL_BEAM, MODEL_PLATE
    use deck_reader, only: deck_t, read_deck, case_count, case_model
    use plausibility, only: input_warnings
    implicit none

    interface
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
        subroutine c_abort() bind(c, name='abort')
        end subroutine c_abort
    end interface

    integer, parameter :: max_cases_checked = 2000
    character(len=:), allocatable :: path, label
    type(deck_t) :: deck
    type(error_t), allocatable :: err
    type(model_t) :: m
    integer :: n, i, plen

    if (command_argument_count() /= 1) then
        write (error_unit, '(a)') 'usage: fuzz_deck FILE'
        call c_exit(64_c_int)
    end if
    call get_command_argument(1, length=plen)
    allocate (character(len=plen) :: path)
    call get_command_argument(1, path)

    call read_deck(path, deck, err)
    if (allocated(err)) call input_error(err, 'read_deck')

    n = case_count(deck)
    if (n < 1) call bug('case_count < 1 for a valid deck')
    call check_model(deck%base, 'base model')
    do i = 1, n
        if (n > max_cases_checked .and. i > max_cases_checked/2 .and. &
            i <= n - max_cases_checked/2) cycle
        call case_model(deck, i, m, label, err)
        if (allocated(err)) call input_error(err, 'case_model')
        call check_model(m, 'case')
        if (size(input_warnings(m)) < 0) call bug('warnings')
    end do
    write (*, '(a,i0,a)') 'OK: ', n, ' case(s)'
    call c_exit(0_c_int)

contains

    !> An input error must be EXIT_INPUT with a message: then exit 1.
    subroutine input_error(e, where)
        type(error_t), intent(in) :: e
        character(len=*), intent(in) :: where
        if (e%code /= EXIT_INPUT) call bug(where//' returned a non-input error code')
        if (.not. allocated(e%message)) call bug(where//': error without a message')
        if (len_trim(e%message) == 0) call bug(where//': empty error message')
        write (error_unit, '(a)') 'ERROR: '//e%message
        flush (error_unit)
        call c_exit(1_c_int)
    end subroutine input_error

    !> A model accepted by the reader must be usable by the solver.
    subroutine check_model(mm, what)
        type(model_t), intent(in) :: mm
        character(len=*), intent(in) :: what
        integer :: k
        if (mm%structure%kind /= MODEL_BEAM .and. mm%structure%kind &
            /= MODEL_PLATE) call bug(what//': kind')
        call finite_positive(mm%structure%length, what//': length')
        call finite_positive(mm%structure%h, what//': h')
        call finite_positive(mm%structure%b, what//': b')
        call finite_positive(mm%structure%e, what//': E')
        call finite_positive(mm%ground%e_f, what//': E_f')
        call finite(mm%structure%nu, what//': nu')
        call finite(mm%ground%nu_f, what//': nu_f')
        call finite(mm%interface%f, what//': f')
        call finite(mm%interface%eps_bar, what//': eps_bar')
        call finite(mm%solver%tol_outer, what//': tol_outer')
        call finite(mm%solver%tol_inner, what//': tol_inner')
        call finite(mm%interface%eta_bar, what//': eta_bar')
        call finite(mm%solver%tau0_start, what//': tau0_start')
        if (mm%interface%f < 0.0_dp) call bug(what//': f < 0')
        ! the range rules of deck_fields (RULE_NU_STRUCTURE, RULE_NU_SOIL, RULE_ELEMENTS, ...):
        ! nu_f = 0.5 (incompressible soil) is valid, nu = 0.5 is not
        if (mm%structure%nu < 0.0_dp .or. mm%structure%nu >= 0.5_dp) call bug(what// &
            ': nu out of [0,0.5)')
        if (mm%ground%nu_f < 0.0_dp .or. mm%ground%nu_f > 0.5_dp) call bug(what// &
            ': nu_f out of [0,0.5]')
        if (mm%mesh%ne < 1 .or. mm%mesh%ne > 100000) call bug(what//': ne out of 1..100000')
        if (mm%output%stations == 1 .or. mm%output%stations > 100000) call bug(what//': stations')
        if (mm%solver%max_outer < 1 .or. mm%solver%max_inner < 1) call bug(what// &
            ': iteration limit < 1')
        if (mm%output%stations < 0) call bug(what//': stations < 0')
        if (.not. allocated(mm%loads)) call bug(what//': loads not allocated')
        if (size(mm%loads) < 1) call bug(what//': no load')
        do k = 1, size(mm%loads)
            call finite(mm%loads(k)%fz, what//': load fz')
            call finite(mm%loads(k)%fx, what//': load fx')
            call finite(mm%loads(k)%x1, what//': load x1')
            call finite(mm%loads(k)%x2, what//': load x2')
        end do
    end subroutine check_model

    subroutine finite(x, what)
        real(dp), intent(in) :: x
        character(len=*), intent(in) :: what
        if (.not. ieee_is_finite(x)) call bug(what//' is not finite')
    end subroutine finite

    subroutine finite_positive(x, what)
        real(dp), intent(in) :: x
        character(len=*), intent(in) :: what
        call finite(x, what)
        if (.not. (x > 0.0_dp)) call bug(what//' is not positive')
    end subroutine finite_positive

    !> A broken invariant: say what, then SIGABRT (a crash for AFL, a core for gdb).
    subroutine bug(what)
        character(len=*), intent(in) :: what
        write (error_unit, '(a)') 'FUZZ INVARIANT: '//what
        flush (error_unit)
        call c_abort()
    end subroutine bug
end program fuzz_deck
