!> Who wrote an output and when: the program's version and the run's date and time, stamped
!! on the report, the station and summary CSV files and the JSON summary. The time is taken
!! once, at start-up (start_up::start_program), so every file of a run carries the same
!! stamp; with the environment variable SOURCE_DATE_EPOCH set (seconds since 1970-01-01
!! UTC, the reproducible-builds convention) the stamp is that moment, in UTC, and two runs
!! give the same bytes.
module run_identity
    use iso_fortran_env, only: int64
    implicit none
    private

    character(len=*), parameter, public :: program_name = 'fricon'
    character(len=*), parameter, public :: program_version = '0.2.0'   !! as in fpm.toml

    !> The run's date and time, ISO 8601 with the offset from UTC ('' before start-up).
    character(len=25), protected, save, public :: run_time = ''

    public :: record_run_time, iso_time_of_epoch, run_stamp

contains

    !> Once, at start-up: run_time from SOURCE_DATE_EPOCH when it holds a whole number of
    !! seconds, else from the clock (local time and its offset).
    subroutine record_run_time()
        character(len=32) :: epoch_text
        integer(int64) :: epoch
        integer :: length, status, ios, v(8)
        call get_environment_variable('SOURCE_DATE_EPOCH', epoch_text, length, status)
        if (status == 0 .and. length > 0 .and. verify(trim(epoch_text), '0123456789') == 0) then
            read (epoch_text, *, iostat=ios) epoch
            if (ios == 0) then
                run_time = iso_time_of_epoch(epoch)
                return
            end if
        end if
        call date_and_time(values=v)
        write (run_time, '(i4.4,"-",i2.2,"-",i2.2,"T",i2.2,":",i2.2,":",i2.2,a1,i2.2,":",i2.2)') &
            v(1), v(2), v(3), v(5), v(6), v(7), merge('+', '-', v(4) >= 0), abs(v(4))/60, &
            mod(abs(v(4)), 60)
    end subroutine record_run_time

    !> 'fricon 0.2.0, run 2026-11-28T14:14:08+00:00': the stamp line of the outputs.
    pure function run_stamp() result(text)
        character(len=:), allocatable :: text
        text = program_name//' '//program_version//', run '//trim(run_time)
    end function run_stamp

    !> The UTC date and time of a moment given in seconds since 1970-01-01T00:00:00Z
    !! (0 <= seconds), ISO 8601: the civil date from the day count by H. Hinnant's
    !! days-to-civil algorithm (proleptic Gregorian calendar, eras of 400 years).
    pure function iso_time_of_epoch(seconds) result(text)
        integer(int64), intent(in) :: seconds   !! since the epoch, not negative
        character(len=25) :: text
        integer(int64) :: days, secs, z, era, doe, yoe, doy, mp, d, m, y
        days = seconds/86400_int64
        secs = mod(seconds, 86400_int64)
        z = days + 719468_int64
        era = z/146097_int64
        doe = z - era*146097_int64
        yoe = (doe - doe/1460_int64 + doe/36524_int64 - doe/146096_int64)/365_int64
        y = yoe + era*400_int64
        doy = doe - (365_int64*yoe + yoe/4_int64 - yoe/100_int64)
        mp = (5_int64*doy + 2_int64)/153_int64
        d = doy - (153_int64*mp + 2_int64)/5_int64 + 1_int64
        m = merge(mp + 3_int64, mp - 9_int64, mp < 10_int64)
        if (m <= 2_int64) y = y + 1_int64
        write (text, '(i4.4,"-",i2.2,"-",i2.2,"T",i2.2,":",i2.2,":",i2.2,"+00:00")') y, m, d, &
            secs/3600_int64, mod(secs, 3600_int64)/60_int64, mod(secs, 60_int64)
    end function iso_time_of_epoch
end module run_identity
