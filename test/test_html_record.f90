!> The calculation record CASE.html (html_record) and its base64 encoder: the encoder against
!! the test vectors of RFC 4648 §10; the page well formed (every tag opened is closed, in
!! order), with the program's version and the run's time, the units of its values, no folder
!! of the machine, the figure's data URI decoding to the figure's bytes, the design checks
!! section only when there are checks; --no-html leaves no record.
module test_html_record
    use iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check
    use errors, only: EXIT_OK
    use base64_encoding, only: base64_encoded, base64_decoded
    use run_identity, only: program_version, run_time
    use deck_reader, only: deck_t, read_deck
    use analysis_driver, only: run_analysis, run_options_t
    use solved_case, only: case_t
    use contact_test_support, only: solve_deck
    use html_record, only: write_html_record, write_case_record
    use design_checks, only: design_check_t
    use output_paths, only: canonical_path
    implicit none
    private
    public :: collect_html_record

    character(len=*), parameter :: deck_file = 'input/strip_footing.dat'
    character(len=*), parameter :: dir = 'build/test_html'

contains

    subroutine collect_html_record(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('base64_rfc4648_vectors', test_rfc4648), &
                 new_unittest('base64_every_byte_round_trip', test_round_trip), &
                 new_unittest('base64_rejects_malformed', test_malformed), &
                 new_unittest('record_of_a_run_well_formed', test_run_record), &
                 new_unittest('record_figure_data_uri_decodes', test_figure_uri), &
                 new_unittest('record_checks_section_only_with_checks', test_checks_section), &
                 new_unittest('record_without_its_figure_file', test_missing_figure), &
                 new_unittest('no_html_option_leaves_no_record', test_no_html), &
                 new_unittest('failed_case_leaves_no_record', test_failed_case)]
    end subroutine collect_html_record

    !> RFC 4648 §10: BASE64("") = "", "f" = "Zg==", "fo" = "Zm8=", "foo" = "Zm9v",
    !! "foob" = "Zm9vYg==", "fooba" = "Zm9vYmE=", "foobar" = "Zm9vYmFy"; each decodes back.
    subroutine test_rfc4648(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: plain(7) = [character(len=6) :: '', 'f', 'fo', 'foo', &
            'foob', 'fooba', 'foobar']
        character(len=*), parameter :: coded(7) = [character(len=8) :: '', 'Zg==', 'Zm8=', &
            'Zm9v', 'Zm9vYg==', 'Zm9vYmE=', 'Zm9vYmFy']
        character(len=:), allocatable :: back
        logical :: ok
        integer :: k
        do k = 1, size(plain)
            call check(err, base64_encoded(trim(plain(k))) == trim(coded(k)), &
                       'BASE64("'//trim(plain(k))//'") is '//base64_encoded(trim(plain(k)))// &
                       ', RFC 4648 gives '//trim(coded(k)))
            if (allocated(err)) return
            call base64_decoded(trim(coded(k)), back, ok)
            call check(err, ok .and. back == trim(plain(k)), trim(coded(k))// &
                       ' does not decode to "'//trim(plain(k))//'"')
            if (allocated(err)) return
        end do
    end subroutine test_rfc4648

    !> All 256 byte values (the high ones are where a signed char would go wrong), at each
    !! of the three offsets in a group, decode back to themselves; bytes 0, 1, 2 are "AAEC"
    !! (000000 000000 000100 000010) and 255, 255, 255 is "////".
    subroutine test_round_trip(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=258) :: bytes
        character(len=:), allocatable :: back
        logical :: ok
        integer :: k, shift
        call check(err, base64_encoded(achar(0)//achar(1)//achar(2)) == 'AAEC', &
                   'bytes 0 1 2 do not encode to AAEC')
        if (allocated(err)) return
        call check(err, base64_encoded(repeat(achar(255), 3)) == '////', &
                   'bytes 255 255 255 do not encode to ////')
        if (allocated(err)) return
        do shift = 0, 2
            do k = 1, 256
                bytes(k:k) = achar(k - 1)
            end do
            call base64_decoded(base64_encoded(bytes(1:256 + shift)), back, ok)
            call check(err, ok .and. back == bytes(1:256 + shift), &
                       'the 256 byte values do not survive encoding and decoding')
            if (allocated(err)) return
        end do
    end subroutine test_round_trip

    !> Not canonical base64: a length not a multiple of 4, a character outside the alphabet,
    !! '=' inside, three '=', nonzero padding bits ("Zh==": h = 100001 leaves 0001).
    subroutine test_malformed(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: bad(6) = [character(len=8) :: 'Zg=', 'Zm9!', 'Z=9v', &
            'Z===', 'Zh==', 'Zm9vYmF=']
        character(len=:), allocatable :: back
        logical :: ok
        integer :: k
        do k = 1, size(bad)
            call base64_decoded(trim(bad(k)), back, ok)
            call check(err, .not. ok, '"'//trim(bad(k))//'" was accepted as base64')
            if (allocated(err)) return
        end do
    end subroutine test_malformed

    !> The strip footing run as the program runs it, its deck given by an absolute path and
    !! written to an absolute folder, without figures: the record is well formed, names the
    !! version and the run's time, the deck by its file name only, states the units of its
    !! inputs and results (kPa, m, mm, kN&#183;m, kN), says why there is no figure, and holds
    !! no absolute path.
    subroutine test_run_record(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: html, here
        character(len=*), parameter :: units(6) = [character(len=24) :: '<td class="key">kPa', &
            '<td class="key">m</td>', '<td class="key">mm</td>', 'kN&#183;m', &
            '<td class="key">kN</td>', 'x<sub>1</sub> [m]']
        type(deck_t) :: deck
        integer :: status, k
        here = canonical_path('.')
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call read_deck(here//'/'//deck_file, deck, err)
        if (allocated(err)) return
        call run_analysis(deck, here//'/'//dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false.))
        call check(err, status == EXIT_OK, deck_file//' did not solve')
        if (allocated(err)) return
        call read_text(dir//'/strip_footing.html', html, err)
        if (allocated(err)) return
        call check_page(html, err)
        if (allocated(err)) return
        call check(err, index(html, '<td>strip_footing.dat</td>') > 0, 'deck name missing')
        if (allocated(err)) return
        call check(err, index(html, here) == 0 .and. index(html, dir) == 0, &
                   'the record holds a folder of the machine: '//here)
        if (allocated(err)) return
        call check(err, index(html, 'No figure: the run was asked for no figures') > 0, &
                   'the record does not say why it has no figure')
        if (allocated(err)) return
        do k = 1, size(units)
            call check(err, index(html, trim(units(k))) > 0, 'no unit '//trim(units(k)))
            if (allocated(err)) return
        end do
        call check(err, index(html, 'Design checks') == 0, 'a design checks section '// &
                   'without checks')
    end subroutine test_run_record

    !> A figure of known bytes (every byte value, then PNG's IEND marker) embedded by
    !! write_case_record: its data URI decodes to those bytes; the output folder in the
    !! figure's note is taken out.
    subroutine test_figure_uri(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: html, uri, back, base
        character(len=*), parameter :: key = 'src="data:image/png;base64,'
        character(len=268) :: bytes
        type(deck_t) :: deck
        type(case_t) :: c
        character(len=80) :: notes(1)
        logical :: ok
        integer :: k, u, at
        do k = 1, 256
            bytes(k:k) = achar(k - 1)
        end do
        bytes(257:) = achar(0)//achar(0)//achar(0)//achar(0)//'IEND'//achar(174)//'B'// &
            achar(96)//achar(130)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        base = canonical_path(dir)//'/fig'
        open (newunit=u, file=base//'.png', access='stream', form='unformatted', &
              status='replace')
        write (u) bytes
        close (u)
        call read_deck(deck_file, deck, err)
        if (allocated(err)) return
        call solve_deck(deck_file, 10, c, err)
        if (allocated(err)) return
        notes(1) = 'NOTE: figure '//base//'.png is a test'
        call write_case_record(deck, c, base, '', c%entries, '', notes, err)
        if (allocated(err)) return
        call read_text(base//'.html', html, err)
        if (allocated(err)) return
        call check_page(html, err)
        if (allocated(err)) return
        at = index(html, key)
        call check(err, at > 0, 'no PNG data URI in the record')
        if (allocated(err)) return
        uri = html(at + len(key):)
        uri = uri(1:index(uri, '"') - 1)
        call base64_decoded(uri, back, ok)
        call check(err, ok .and. back == bytes, 'the data URI does not decode to the figure')
        if (allocated(err)) return
        call check(err, index(html, 'figure fig.png is a test') > 0 .and. &
                   index(html, canonical_path(dir)) == 0, 'the folder is left in a note')
    end subroutine test_figure_uri

    !> A figure said to be drawn but not there (removed behind fricon's back): the record is
    !! still written, well formed, and says the figure could not be read.
    subroutine test_missing_figure(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: html
        type(deck_t) :: deck
        type(case_t) :: c
        character(len=80) :: notes(0)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call read_deck(deck_file, deck, err)
        if (allocated(err)) return
        call solve_deck(deck_file, 10, c, err)
        if (allocated(err)) return
        call write_case_record(deck, c, dir//'/gone', '', c%entries, '', notes, err)
        if (allocated(err)) return
        call read_text(dir//'/gone.html', html, err)
        if (allocated(err)) return
        call check_page(html, err)
        if (allocated(err)) return
        call check(err, index(html, 'No figure: the figure gone.png could not be read') > 0 &
                   .and. index(html, 'data:image') == 0, 'no word on the missing figure')
    end subroutine test_missing_figure

    !> With two checks the record has a design checks section naming each, its utilisation
    !! and NOT MET for the failed one; with none (an empty array) there is no such section.
    subroutine test_checks_section(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: html
        type(case_t) :: c
        type(design_check_t) :: checks(2)
        character(len=80) :: notes(0)
        call solve_deck(deck_file, 10, c, err)
        if (allocated(err)) return
        call execute_command_line('mkdir -p '//dir)
        checks(1) = design_check_t('BEARING_MEAN', 'bearing pressure', 'kPa', 200.0_dp, 400.0_dp, &
                                   0.5_dp, .true., .false., .true.)
        checks(2) = design_check_t('SETTLEMENT', 'settlement', 'mm', 30.0_dp, 25.0_dp, 1.2_dp, &
                                   .true., .false., .false.)
        call write_html_record(dir//'/checks.html', 'x.dat', ['END'], '', c, c%entries, '', &
                               'none here', notes, err, checks)
        if (allocated(err)) return
        call read_text(dir//'/checks.html', html, err)
        if (allocated(err)) return
        call check_page(html, err)
        if (allocated(err)) return
        call check(err, index(html, '<h2>Design checks</h2>') > 0 .and. &
                   index(html, 'bearing pressure') > 0 .and. index(html, 'NOT MET') > 0 .and. &
                   index(html, '>1.20<') > 0, 'the design checks are not all shown')
        if (allocated(err)) return
        call write_html_record(dir//'/checks.html', 'x.dat', ['END'], '', c, c%entries, '', &
                               'none here', notes, err, checks(1:0))
        if (allocated(err)) return
        call read_text(dir//'/checks.html', html, err)
        if (allocated(err)) return
        call check(err, index(html, 'Design checks') == 0, 'a checks section without checks')
    end subroutine test_checks_section

    !> --no-html (run_options_t%record false): no record, and none of an earlier run left.
    subroutine test_no_html(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status
        logical :: there
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call read_deck(deck_file, deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false.))
        inquire (file=dir//'/strip_footing.html', exist=there)
        call check(err, status == EXIT_OK .and. there, 'no record by default')
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false., record=.false.))
        inquire (file=dir//'/strip_footing.html', exist=there)
        call check(err, status == EXIT_OK .and. .not. there, 'a record with --no-html')
    end subroutine test_no_html

    !> A case that fails (a horizontal load of 2000 kN above the friction capacity
    !! f V = 0.4 x 2400 kN = 960 kN: no equilibrium, exit status 2) removes the record an
    !! earlier, solved run of the same deck wrote: no stale record beside its report.
    subroutine test_failed_case(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: deck_dir = 'build/test_html_deck'
        type(deck_t) :: deck
        integer :: status
        logical :: there
        call execute_command_line('rm -rf '//dir//' '//deck_dir//' && mkdir -p '//dir//' '// &
                                  deck_dir)
        call write_strip(deck_dir//'/slide.dat', '0.0')
        call read_deck(deck_dir//'/slide.dat', deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false.))
        inquire (file=dir//'/slide.html', exist=there)
        call check(err, status == EXIT_OK .and. there, 'the solved deck wrote no record')
        if (allocated(err)) return
        call write_strip(deck_dir//'/slide.dat', '1000.0')
        call read_deck(deck_dir//'/slide.dat', deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false.))
        inquire (file=dir//'/slide.html', exist=there)
        call check(err, status == 2 .and. .not. there, 'a failed case left a record')
    end subroutine test_failed_case

    !> The strip footing deck with F_x on each of its two column loads.
    subroutine write_strip(path, f_x)
        character(len=*), intent(in) :: path, f_x
        integer :: u
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') 'MODEL     BEAM'
        write (u, '(a)') 'UNITS     kN        m'
        write (u, '(a)') 'GEOMETRY  10.0      0.8       1.2'
        write (u, '(a)') 'STRUCTURE 30.0E6    0.2'
        write (u, '(a)') 'SOIL      30.0E3    0.35'
        write (u, '(a)') 'FRICTION  0.4'
        write (u, '(a)') 'LOAD      PATCH     1200.0    '//f_x//repeat(' ', 10 - len(f_x))// &
                         '-3.7      -3.3'
        write (u, '(a)') 'LOAD      PATCH     1200.0    '//f_x//repeat(' ', 10 - len(f_x))// &
                         '3.3       3.7'
        write (u, '(a)') 'MESH      20'
        write (u, '(a)') 'END'
        close (u)
    end subroutine write_strip

    !> A record's common properties: the doctype, well formed, the version and run time.
    subroutine check_page(html, err)
        character(len=*), intent(in) :: html
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: problem
        call check(err, index(html, '<!DOCTYPE html>') == 1, 'no doctype first')
        if (allocated(err)) return
        problem = tag_problem(html)
        call check(err, len(problem) == 0, 'not well formed: '//problem)
        if (allocated(err)) return
        call check(err, index(html, 'version '//program_version) > 0 .and. &
                   index(html, trim(run_time)) > 0 .and. len_trim(run_time) > 0, &
                   'version or run time missing')
    end subroutine check_page

    !> '' when every tag opened is closed in order (void elements written <x ... />;
    !! <!...> declarations and comments skipped), else what is wrong.
    pure function tag_problem(html) result(problem)
        character(len=*), intent(in) :: html
        character(len=:), allocatable :: problem
        character(len=16) :: stack(64)
        character(len=:), allocatable :: name
        integer :: i, close_at, depth, k
        problem = ''
        depth = 0
        i = 1
        tags: do
            k = index(html(i:), '<')
            if (k == 0) exit tags
            i = i + k - 1
            close_at = index(html(i:), '>')
            if (close_at == 0) then
                problem = 'a tag never ends'
                return
            end if
            close_at = i + close_at - 1
            if (html(i + 1:i + 1) /= '!') then
                name = tag_name(html(i + 1:close_at - 1))
                if (len(name) == 0) then
                    problem = 'a bare < at character '//trim(number(i))
                    return
                end if
                if (html(i + 1:i + 1) == '/') then
                    if (depth == 0) then
                        problem = '</'//name//'> closes nothing'
                        return
                    end if
                    if (trim(stack(depth)) /= name) then
                        problem = '</'//name//'> closes <'//trim(stack(depth))//'>'
                        return
                    end if
                    depth = depth - 1
                else if (html(close_at - 1:close_at - 1) /= '/') then
                    depth = depth + 1
                    if (depth > size(stack)) then
                        problem = 'nested too deep'
                        return
                    end if
                    stack(depth) = name
                end if
            end if
            i = close_at + 1
        end do tags
        if (depth > 0) problem = '<'//trim(stack(depth))//'> never closed'
    end function tag_problem

    !> The element name at the start of a tag's text (after '<' or '</').
    pure function tag_name(text) result(name)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: name
        integer :: j, first
        first = 1
        if (len(text) > 0) then
            if (text(1:1) == '/') first = 2
        end if
        name = ''
        do j = first, len(text)
            if (index('abcdefghijklmnopqrstuvwxyz0123456789', text(j:j)) == 0) exit
            name = name//text(j:j)
        end do
    end function tag_name

    pure function number(i) result(text)
        integer, intent(in) :: i
        character(len=12) :: text
        write (text, '(i0)') i
    end function number

    !> The whole file as one string.
    subroutine read_text(path, text, err)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(error_t), allocatable, intent(out) :: err
        integer :: u, ios, n
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        call check(err, ios == 0, 'cannot open '//path)
        if (allocated(err)) return
        inquire (unit=u, size=n)
        allocate (character(len=n) :: text)
        read (u, iostat=ios) text
        close (u)
        call check(err, ios == 0, 'cannot read '//path)
    end subroutine read_text
end module test_html_record
