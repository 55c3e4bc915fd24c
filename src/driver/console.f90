!> What a run says on the terminal: one line per case with its key results (or its error)
!! and warnings, and the progress of a long run.
module console
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use errors, only: EXIT_OK
    use summary_table, only: entry_t, entry_index
    use case_files, only: case_result_t
    use check_report, only: checks_line
    implicit none
    private

    public :: report_case, report_progress, seconds

contains

    !> The console line (or error) and the warnings of one case; status: the worst so far.
    subroutine report_case(log_unit, err_unit, deck_path, out_dir, r, status)
        !> the outcome's unit; the unit of errors and warnings
        integer, intent(in) :: log_unit, err_unit
        character(len=*), intent(in) :: deck_path, out_dir   !! the deck as given; the output folder
        type(case_result_t), intent(in) :: r                 !! the case's outcome
        integer, intent(inout) :: status   !! the worst exit status so far, raised by this case's
        integer :: k
        character(len=:), allocatable :: who
        who = r%name//swept_text(r%label)
        if (r%status == EXIT_OK) then
            write (log_unit, '(a)') who//': solved  '//console_summary(r%entries)// &
                '  -> '//out_dir//'/'//r%name//'.txt'
            if (allocated(r%checks)) then
                if (size(r%checks) > 0) write (log_unit, '(a)') who//': '//checks_line(r%checks)
            end if
        else
            write (err_unit, '(a)') 'ERROR: '//who//' ('//deck_path//'): '//r%message
        end if
        if (len(r%message) > 0 .and. r%status == EXIT_OK) &
            write (err_unit, '(a)') 'WARNING: '//r%name//': '//r%message
        do k = 1, size(r%warnings)
            write (err_unit, '(a)') 'WARNING: '//r%name//' ('//deck_path//'): '//trim(r%warnings(k))
        end do
        status = max(status, r%status)
    end subroutine report_case

    !> ' [RHO=0.01 F=0.5]': the swept values of a sweep's case from its label ('case 002 of
    !! 006: RHO=0.01 F=0.5'); '' for a deck without SWEEP ('case 1 of 1').
    pure function swept_text(label) result(text)
        character(len=*), intent(in) :: label   !! the case label
        character(len=:), allocatable :: text
        text = ''
        if (index(label, ':') == 0) return
        text = trim(adjustl(label(index(label, ':') + 1:)))
        if (len(text) > 0) text = ' ['//text//']'
    end function swept_text

    !> Standard-error progress: cases done of n, the elapsed time and an estimate of the time
    !! left (the mean time per case so far).
    subroutine report_progress(unit, done, n, name, clock_start)
        integer, intent(in) :: unit, done, n   !! standard error's unit; cases done; cases in all
        character(len=*), intent(in) :: name        !! the deck's name
        integer(int64), intent(in) :: clock_start   !! system_clock count at the start of the run
        integer(int64) :: now, rate
        real(dp) :: elapsed
        character(len=80) :: eta
        call system_clock(now, rate)
        elapsed = real(now - clock_start, dp)/real(rate, dp)
        eta = ''
        if (done < n) eta = ', about '//seconds(elapsed/real(done, dp)*real(n - done, dp))//' left'
        write (unit, '(a,i0,a,i0,a)') 'fricon: ', done, ' of ', n, ' done ('//name//'), '// &
            seconds(elapsed)//' elapsed'//trim(eta)
        flush (unit)
    end subroutine report_progress

    pure function seconds(t) result(text)
        real(dp), intent(in) :: t   !! a time [s]
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(f12.1)') t
        text = trim(adjustl(buf))//' s'
    end function seconds

    !> The console line: key results with their units; a beam's contact by both ends (the
    !! t of its leftmost and rightmost stations in contact, the lengths lifted off at the
    !! left and the right end), a plate's contact extent t.
    pure function console_summary(e) result(text)
        type(entry_t), intent(in) :: e(:)
        character(len=:), allocatable :: text
        character(len=*), parameter :: keys(4) = [character(len=24) :: 'settlement_max', &
                                                   'differential_settlement', 'pressure_mean', &
                                                   'contact_extent_t']
        character(len=*), parameter :: names(4) = [character(len=12) :: 'w_max', 'w_diff', &
                                                    'p_mean', 'extent t']
        integer :: k
        text = ''
        do k = 1, size(keys) - 1
            text = text//named_value(e, keys(k), names(k))//',  '
        end do
        if (entry_index(e, 'contact_extent_left_t') > 0) then
            text = text//'contact t = '//named_value(e, 'contact_extent_left_t', '')//' to '// &
                named_value(e, 'contact_extent_right_t', '')//',  lift-off = '// &
                named_value(e, 'liftoff_left', '')//' left, '// &
                named_value(e, 'liftoff_right', '')//' right'
        else
            text = text//named_value(e, keys(4), names(4))
        end if
    end function console_summary

    !> 'name = value unit' of the entry with the key ('value unit' without a name; '-' for a
    !! value that is not defined, '' for a key that is not there).
    pure function named_value(e, key, name) result(text)
        type(entry_t), intent(in) :: e(:)
        character(len=*), intent(in) :: key, name
        character(len=:), allocatable :: text
        character(len=24) :: buf
        integer :: i
        text = ''
        i = entry_index(e, key)
        if (i == 0) return
        buf = four_digits(e(i)%value)
        if (.not. e(i)%defined) buf = '-'
        if (len_trim(name) > 0) text = trim(name)//' = '
        text = text//trim(adjustl(buf))
        if (len_trim(e(i)%unit) > 0 .and. e(i)%defined) text = text//' '//trim(e(i)%unit)
    end function named_value

    !> x with four significant digits: fixed notation from 1e-3 to 1e5, else E notation.
    pure function four_digits(x) result(text)
        real(dp), intent(in) :: x
        character(len=24) :: text
        integer :: decimals
        if (x == 0.0_dp) then
            text = '0'
        else if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e5_dp) then
            decimals = max(0, 3 - floor(log10(abs(x))))
            write (text, '(f0.'//achar(iachar('0') + min(decimals, 9))//')') x
            if (text(1:1) == '.') text = '0'//text
            if (text(1:2) == '-.') text = '-0'//text(2:)
        else
            write (text, '(es10.3)') x
            text = adjustl(text)
        end if
    end function four_digits
end module console
