!> A case's JSON summary (CASE.json, doc/OUTPUT.md) read back, for runs that use cases solved
!! by other runs (fricon --merge of a sweep's shards): a top-level string field, a JSON
!! number, and the case's status and design values (design_envelope) from its "status",
!! "results" and "design_checks". The file is read as report_writer and check_report write
!! it: one key per line at the top level and in "results", one check per line in
!! "design_checks":
!!
!!     "status": 0,
!!     "results": {
!!       "settlement_max": 2.354914977200433E+001,
!!       ...
!!     "design_checks": [
!!       {"name": "BEARING_MEAN", "quantity": "...", "unit": "kPa", "value": 1.89E+002, ...},
module case_json_reader
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INPUT
    use summary_table, only: entry_t
    use design_checks, only: design_check_t, check_entries
    use design_envelope, only: design_value_t, values_of_entries
    use text_files, only: read_lines
    implicit none
    private

    public :: json_field, read_json_number, read_case_values

contains

    !> The value of '  "key": "...",' in a JSON summary, its escapes undone ('' if none).
    subroutine json_field(path, key, value)
        character(len=*), intent(in) :: path                  !! the JSON summary
        character(len=*), intent(in) :: key                   !! a top-level key
        character(len=:), allocatable, intent(out) :: value   !! its string value, or ''
        character(len=:), allocatable :: lines(:)
        integer :: k, at, last
        logical :: ok
        value = ''
        call read_lines(path, lines, ok)
        if (.not. ok) return
        do k = 1, size(lines)
            if (index(lines(k), '  "'//key//'": "') /= 1) cycle
            at = len(key) + 7
            last = len_trim(lines(k))
            if (lines(k)(last:last) == ',') last = last - 1
            value = unescaped(lines(k)(at + 1:last - 1))
            return
        end do
    end subroutine json_field

    !> A JSON string's content with \n, \", \\ and \/ undone.
    pure function unescaped(text) result(plain)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: plain
        integer :: i, k
        allocate (character(len=len(text)) :: plain)
        i = 1
        k = 0
        do while (i <= len(text))
            k = k + 1
            if (text(i:i) == '\' .and. i < len(text)) then
                i = i + 1
                plain(k:k) = text(i:i)
                if (text(i:i) == 'n') plain(k:k) = achar(10)
            else
                plain(k:k) = text(i:i)
            end if
            i = i + 1
        end do
        plain = plain(1:k)
    end function unescaped

    !> The number a JSON number's text holds (json_text::json_number's), or not defined for
    !! null or text that is no number. A value beyond the largest double (the largest
    !! double rounded up to 16 digits) is read as the largest, with its sign.
    pure subroutine read_json_number(text, x, defined)
        character(len=*), intent(in) :: text   !! e.g. '2.354914977200433E+001' or 'null'
        real(dp), intent(out) :: x             !! the number (0 when not defined)
        logical, intent(out) :: defined        !! false: null or no number
        integer :: ios
        character(len=:), allocatable :: t
        x = 0.0_dp
        t = trim(adjustl(text))
        defined = len(t) > 0 .and. verify(t, '0123456789+-.Ee') == 0
        if (.not. defined) return
        read (t, *, iostat=ios) x
        if (ios == 0) return
        defined = scan(t, '0123456789') > 0 .and. scan(t, 'Ee') > 0
        x = merge(-huge(x), huge(x), t(1:1) == '-')
    end subroutine read_json_number

    !> The status and design values of a case from its JSON summary: its key results are
    !! read in the order of `keys` (the deck's key results, summary_table, whose labels and
    !! units they take), its design checks in file order, and they make the case's design
    !! values as design_envelope::design_values makes them from the solved case. A failed
    !! case (status not 0) has no values. err: the file cannot be read, or is not the summary
    !! of a case of the deck (other keys, a number that cannot be read).
    subroutine read_case_values(path, keys, status, values, err)
        character(len=*), intent(in) :: path                  !! CASE.json
        type(entry_t), intent(in) :: keys(:)                  !! the deck's key results
        integer, intent(out) :: status                        !! the case's exit status
        type(design_value_t), allocatable, intent(out) :: values(:)   !! solved: its values
        type(error_t), allocatable, intent(out) :: err        !! unreadable, or not the deck's
        character(len=:), allocatable :: lines(:)
        type(entry_t), allocatable :: entries(:)
        type(design_check_t), allocatable :: checks(:)
        logical :: ok
        integer :: at, ios
        status = -1
        call read_lines(path, lines, ok)
        if (.not. ok) then
            call new_error(err, EXIT_INPUT, 'cannot read the JSON summary '//path)
            return
        end if
        at = line_of(lines, '  "status": ')
        ios = 1
        if (at > 0) read (lines(at)(13:), *, iostat=ios) status
        if (ios /= 0 .or. status < 0) then
            call new_error(err, EXIT_INPUT, path//' has no "status": not a case''s JSON '// &
                           'summary, or cut short')
            return
        end if
        if (status /= 0) return
        call read_results(path, lines, keys, entries, err)
        if (.not. allocated(err)) call read_checks(path, lines, checks, err)
        if (allocated(err)) return
        values = values_of_entries([entries, check_entries(checks)])
    end subroutine read_case_values

    !> The key results of "results", one per line in the order of keys.
    subroutine read_results(path, lines, keys, entries, err)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: lines(:)
        type(entry_t), intent(in) :: keys(:)
        type(entry_t), allocatable, intent(out) :: entries(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: key, text
        integer :: at, i
        entries = keys
        at = line_of(lines, '  "results": {')
        if (at == 0 .or. at + size(keys) > size(lines)) then
            call new_error(err, EXIT_INPUT, path//' has no "results" of a solved case')
            return
        end if
        do i = 1, size(keys)
            call key_value(lines(at + i), key, text)
            if (key /= trim(keys(i)%key)) then
                call new_error(err, EXIT_INPUT, path//': "'//key//'" where its deck gives "'// &
                    trim(keys(i)%key)//'" (a summary of another deck or fricon version?)')
                return
            end if
            call read_json_number(text, entries(i)%value, entries(i)%defined)
            if (.not. entries(i)%defined .and. text /= 'null') then
                call new_error(err, EXIT_INPUT, path//': "'//key//'" is no number: '//text)
                return
            end if
        end do
    end subroutine read_results

    !> The design checks of "design_checks" (none for "[]").
    subroutine read_checks(path, lines, checks, err)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: lines(:)
        type(design_check_t), allocatable, intent(out) :: checks(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: at, k
        allocate (checks(0))
        if (line_of(lines, '  "design_checks": [],') > 0) return
        at = line_of(lines, '  "design_checks": [')
        if (at == 0) then
            call new_error(err, EXIT_INPUT, path//' has no "design_checks"')
            return
        end if
        do k = at + 1, size(lines)
            if (index(lines(k), '  ]') == 1) return
            checks = [checks, check_of_line(lines(k))]
            if (len_trim(checks(size(checks))%name) == 0) then
                call new_error(err, EXIT_INPUT, path//': a design check that cannot be read: '// &
                               trim(lines(k)))
                return
            end if
        end do
        call new_error(err, EXIT_INPUT, path//': "design_checks" is cut short')
    end subroutine read_checks

    !> One design check of its line '{"name": ..., "quantity": ..., "unit": ..., "value": ...,
    !! "limit": ..., "utilisation": ..., ...}' (name blank when it cannot be read).
    pure function check_of_line(line) result(c)
        character(len=*), intent(in) :: line
        type(design_check_t) :: c
        logical :: defined, limit_ok, use_ok
        c%name = member(line, 'name')
        c%label = member(line, 'quantity')
        c%unit = member(line, 'unit')
        call read_json_number(member(line, 'value'), c%value, defined)
        call read_json_number(member(line, 'limit'), c%limit, limit_ok)
        call read_json_number(member(line, 'utilisation'), c%utilisation, use_ok)
        c%defined = defined
        c%minimum = member(line, 'least_value') == 'true'
        c%pass = member(line, 'pass') == 'true'
        if (.not. limit_ok .or. (use_ok .neqv. defined)) c%name = ''
    end function check_of_line

    !> The value of "key" in a one-line JSON object: a string's content (escapes undone), or
    !! the text of a number, true, false or null ('' when the key is absent).
    pure function member(line, key) result(text)
        character(len=*), intent(in) :: line, key
        character(len=:), allocatable :: text
        integer :: at, k
        text = ''
        at = index(line, '"'//key//'": ')
        if (at == 0) return
        at = at + len(key) + 4
        if (line(at:at) == '"') then
            k = at + 1
            do while (k <= len(line))
                if (line(k:k) == '\') then
                    k = k + 2
                    cycle
                end if
                if (line(k:k) == '"') exit
                k = k + 1
            end do
            text = unescaped(line(at + 1:min(k, len(line) + 1) - 1))
        else
            k = scan(line(at:), ',}]')
            if (k == 0) k = len_trim(line(at:)) + 1
            text = trim(line(at:at + k - 2))
        end if
    end function member

    !> Key and value text of a line '    "key": value,' (the comma dropped).
    pure subroutine key_value(line, key, text)
        character(len=*), intent(in) :: line
        character(len=:), allocatable, intent(out) :: key, text
        integer :: open_quote, close_quote, last
        key = ''
        text = ''
        open_quote = index(line, '"')
        if (open_quote == 0) return
        close_quote = index(line(open_quote + 1:), '"') + open_quote
        if (close_quote == open_quote .or. line(close_quote + 1:close_quote + 2) /= ': ') return
        key = line(open_quote + 1:close_quote - 1)
        last = len_trim(line)
        if (line(last:last) == ',') last = last - 1
        text = trim(adjustl(line(close_quote + 3:last)))
    end subroutine key_value

    !> The first line starting with `head` (0: none).
    pure integer function line_of(lines, head) result(at)
        character(len=*), intent(in) :: lines(:), head
        integer :: k
        at = 0
        do k = 1, size(lines)
            if (index(lines(k), head) == 1) then
                at = k
                return
            end if
        end do
    end function line_of
end module case_json_reader
