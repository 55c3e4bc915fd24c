!> The design checks (design_checks) as a reader sees them: the report's table (section 9,
!! only for a deck with CHECK cards), the JSON array "design_checks" and the console line.
!! Each check gives its value, limit, utilisation and PASS or FAIL; a FAIL is a result of the
!! case (exit status 0), not a failure of the analysis.
module check_report
    use kinds, only: dp
    use deck_fields, only: int_text
    use design_checks, only: design_check_t, governing_check
    use json_text, only: json_string, json_number
    use report_folding, only: write_wrapped
    implicit none
    private

    public :: write_check_table, write_check_json, checks_line

contains

    !> Report section 9: one row per check (nothing without CHECK cards).
    subroutine write_check_table(u, checks)
        integer, intent(in) :: u                           !! the open report
        type(design_check_t), intent(in) :: checks(:)      !! the case's checks
        integer :: k
        character(len=12) :: value_text, use_text
        if (size(checks) == 0) return
        write (u, '(/,a)') ' 9. DESIGN CHECKS (CHECK cards; a FAIL is a result of the case, '// &
            'not a failure of the analysis)'
        write (u, '(3x,a)') 'check              '//'quantity                                  '// &
            '       value       limit unit     utilisation  result'
        do k = 1, size(checks)
            associate (c => checks(k))
                value_text = '         n/a'
                use_text = '         n/a'
                if (c%defined) write (value_text, '(es12.4)') c%value
                if (c%defined) write (use_text, '(f12.3)') min(c%utilisation, 9.99e6_dp)
                write (u, '(3x,a18,1x,a42,a12,es12.4,1x,a8,a12,2x,a)') c%name, c%label, &
                    value_text, c%limit, c%unit, use_text, trim(verdict(c))
            end associate
        end do
        call write_wrapped(u, '   utilisation = value / limit; for a least value (>= limit: '// &
            'SLIDING_FS, CONTACT_RATIO) limit / value. A check passes at utilisation <= 1.')
        write (u, '(3x,a)') trim(checks_line(checks))
    end subroutine write_check_table

    !> PASS, FAIL, or PASS (n/a) for a value that does not exist.
    pure function verdict(c) result(text)
        type(design_check_t), intent(in) :: c
        character(len=:), allocatable :: text
        if (.not. c%defined) then
            text = 'PASS (n/a)'
        else if (c%pass) then
            text = 'PASS'
        else
            text = 'FAIL'
        end if
    end function verdict

    !> "design_checks": one object per check (an empty array without CHECK cards).
    subroutine write_check_json(u, checks)
        integer, intent(in) :: u                           !! the open JSON file
        type(design_check_t), intent(in) :: checks(:)      !! the case's checks
        integer :: k
        if (size(checks) == 0) then
            write (u, '(a)') '  "design_checks": [],'
            return
        end if
        write (u, '(a)') '  "design_checks": ['
        do k = 1, size(checks)
            associate (c => checks(k))
                write (u, '(a)') '    {"name": '//json_string(trim(c%name))//', "quantity": '// &
                    json_string(trim(c%label))//', "unit": '//json_string(trim(c%unit))// &
                    ', "value": '//json_number(c%value, c%defined)//', "limit": '// &
                    json_number(c%limit, .true.)//', "utilisation": '// &
                    json_number(c%utilisation, c%defined)//', "least_value": '// &
                    trim(merge('true ', 'false', c%minimum))//', "pass": '// &
                    trim(merge('true ', 'false', c%pass))//'}'//trim(merge(', ', '  ', &
                    k < size(checks)))
            end associate
        end do
        write (u, '(a)') '  ],'
    end subroutine write_check_json

    !> 'checks: 5 of 6 pass, governing BEARING_EFFECTIVE utilisation 1.12 (FAIL)'; '' without
    !! checks.
    function checks_line(checks) result(text)
        type(design_check_t), intent(in) :: checks(:)      !! the case's checks
        character(len=:), allocatable :: text
        character(len=16) :: buf
        integer :: g
        text = ''
        if (size(checks) == 0) return
        text = 'checks: '//int_text(count(checks%pass))//' of '//int_text(size(checks))// &
               ' pass'
        g = governing_check(checks)
        if (g == 0) return
        write (buf, '(f16.3)') min(checks(g)%utilisation, 9.99e6_dp)
        text = text//', governing '//trim(checks(g)%name)//' utilisation '// &
               trim(adjustl(buf))//' ('//trim(verdict(checks(g)))//')'
    end function checks_line
end module check_report
