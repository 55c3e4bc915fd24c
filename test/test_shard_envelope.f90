!> The envelope of a deck's load combinations from its shards (fricon --merge,
!! driver/shard_envelope): the same bytes as a single run of the deck, a refusal that writes
!! nothing when a combination did not solve or a case's JSON summary is missing, the shards'
!! time stamp, and the shards' own console line.
module test_shard_envelope
    use harness, only: unittest_t, new_unittest, error_t, check
    use errors, only: EXIT_OK
    use deck_reader, only: deck_t, read_deck
    use analysis_driver, only: run_analysis, run_options_t
    use shard_merge, only: merge_shards, run_merge
    use output_paths, only: canonical_path
    use text_files, only: read_lines
    use test_malformed_decks, only: write_lines
    implicit none
    private

    public :: collect_shard_envelope

    character(len=*), parameter :: dir = 'build/test_shard_envelope'
    character(len=*), parameter :: kinds(3) = ['.txt ', '.json', '.csv ']

contains

    subroutine collect_shard_envelope(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('merged_envelope_equals_serial', test_equals_serial), &
                 new_unittest('shard_says_no_envelope', test_shard_line), &
                 new_unittest('stamp_of_the_shards', test_stamp), &
                 new_unittest('failed_combination_refused', test_failed), &
                 new_unittest('missing_case_refused', test_missing)]
    end subroutine collect_shard_envelope

    !> A strip footing (l = 10 m, kN and m) with three load cases, three combinations (the
    !! third `last`) and two CHECK cards, at two soil moduli: 2 x 3 = 6 cases.
    function combination_sweep(last) result(lines)
        character(len=*), intent(in) :: last   !! the third COMBINE card
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: 'TITLE     shard envelope', 'MODEL     BEAM', &
                 'UNITS     kN        m', 'GEOMETRY  10.0      0.8       1.2', &
                 'STRUCTURE 30.0E6    0.2', 'SOIL      30.0E3    0.35', 'FRICTION  0.4', &
                 'MESH      24', 'CHECK     BEARING   400.0', 'CHECK     SETTLE    50.0E-3', &
                 'LOADCASE  G         25.0', &
                 'LOAD      PATCH     1000.0              -3.7      -3.3', &
                 'LOAD      PATCH     1000.0              3.3       3.7', &
                 'LOADCASE  Q', 'LOAD      PATCH     400.0               -3.7      -3.3', &
                 'LOADCASE  W', 'LOAD      POINT     0.0       50.0      3.5', &
                 'LOAD      MOMENT    150.0               3.5', &
                 'COMBINE   SLS       G         1.0       Q         1.0       W         0.6', &
                 'COMBINE   ULS       G         1.35      Q         1.5       W         0.9', &
                 last, 'SWEEP     E_F       15.0E3    60.0E3', 'END']
    end function combination_sweep

    function good_deck() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = combination_sweep('COMBINE   FAV       G         1.0       W         1.5')
    end function good_deck

    !> A deck whose third combination pulls the beam off the ground (G x -1: the weight and
    !! the columns upwards), which does not solve (test_load_combinations' failed case).
    function failing_deck() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = combination_sweep('COMBINE   UP        G         -1.0      W         1.0')
    end function failing_deck

    !> The deck run in one process and in two shards, the shards merged (given in the order
    !! 2, 1): the three envelope files are the single run's byte for byte (one process, one
    !! run time), as is the summary; the envelope covers the 6 cases (2 moduli x 3
    !! combinations) and names the deck by its file name, not by the absolute path it was
    !! given by.
    subroutine test_equals_serial(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: merged, envelope, deck
        integer :: k, code
        call fresh(dir//'/equal')
        call write_lines(dir//'/equal/ce.dat', good_deck())
        deck = canonical_path(dir//'/equal/ce.dat')
        call run_serial_and_shards(deck, dir//'/equal', err)
        if (allocated(err)) return
        call merge_shards(shard_paths(dir//'/equal/shards', 'ce', [2, 1]), '', .false., merged, &
                          err, envelope)
        if (allocated(err)) return
        call check(err, envelope == dir//'/equal/shards/ce_envelope.txt', &
                   'the merge names no envelope: "'//envelope//'"')
        if (allocated(err)) return
        do k = 1, size(kinds)
            call execute_command_line('cmp '//dir//'/equal/serial/ce_envelope'//trim(kinds(k))// &
                ' '//dir//'/equal/shards/ce_envelope'//trim(kinds(k)), exitstat=code)
            call check(err, code == 0, 'ce_envelope'//trim(kinds(k))//' differs from the '// &
                       'single run''s')
            if (allocated(err)) return
        end do
        call execute_command_line('cmp '//dir//'/equal/serial/ce_summary.csv '//merged, &
                                  exitstat=code)
        call check(err, code == 0, 'the merged summary differs from the single run''s')
        if (allocated(err)) return
        call check(err, index(first_line(dir//'/equal/shards/ce_envelope.csv'), &
                   '; envelope of 6 cases') > 0, 'not 6 cases: '// &
                   first_line(dir//'/equal/shards/ce_envelope.csv'))
        if (allocated(err)) return
        call execute_command_line('grep -q ''"deck": "ce.dat",'' '//dir// &
            '/equal/shards/ce_envelope.json && ! grep -qF "'//deck//'" '//dir// &
            '/equal/shards/ce_envelope.txt '//dir//'/equal/shards/ce_envelope.json', &
            exitstat=code)
        call check(err, code == 0, 'the envelope does not name the deck ce.dat, or names '// &
                   'the path it was given by')
    end subroutine test_equals_serial

    !> A shard of a deck with combinations writes no envelope and its console says so,
    !! naming the merge that writes it.
    subroutine test_shard_line(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: lines(:)
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: u, status
        logical :: ok
        call fresh(dir//'/line')
        call write_lines(dir//'/line/ce.dat', good_deck())
        call read_deck(dir//'/line/ce.dat', deck, err)
        if (allocated(err)) return
        opt = quick(1)
        open (newunit=u, file=dir//'/line/console.txt', status='replace', action='write')
        call run_analysis(deck, dir//'/line/out', u, u, status, opt)
        close (u)
        call read_lines(dir//'/line/console.txt', lines, ok)
        call check(err, ok .and. status == EXIT_OK .and. .not. exists(dir// &
                   '/line/out/ce_envelope.txt'), 'the shard did not run, or wrote an envelope')
        if (allocated(err)) return
        call check(err, any(index(lines, 'ce_envelope: none from a shard; fricon --merge '// &
                   dir//'/line/out/ce_summary.shard-*-of-2.csv writes it') == 1), &
                   'no console line saying the shard writes no envelope')
    end subroutine test_shard_line

    !> The merged envelope carries the shards' stamp (their version and run time, as the
    !! merged summary does), not the merge's: with the shard summaries' time set to
    !! 2001-02-03T04:05:06+00:00 the envelope's three files give that time. Shards stamped by
    !! another version of fricon are refused for the envelope.
    subroutine test_stamp(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: merged
        character(len=*), parameter :: time = '2001-02-03T04:05:06+00:00'
        character(len=*), parameter :: out = dir//'/stamp/shards'
        integer :: code
        call fresh(dir//'/stamp')
        call write_lines(dir//'/stamp/ce.dat', good_deck())
        call run_shards(dir//'/stamp/ce.dat', out, err)
        if (allocated(err)) return
        call execute_command_line('sed -i "1s/, run .*/, run '//time//'/" '//out// &
                                  '/ce_summary.shard-*-of-2.csv')
        call merge_shards(shard_paths(out, 'ce', [1, 2]), '', .false., merged, err)
        if (allocated(err)) return
        call execute_command_line('grep -q "^# fricon [^,]*, run '//time//'; envelope" '// &
            out//'/ce_envelope.csv && grep -q "^ fricon [^,]*, run '//time//'$" '//out// &
            '/ce_envelope.txt && grep -q ''"run_time": "'//time//'"'' '//out// &
            '/ce_envelope.json', exitstat=code)
        call check(err, code == 0, 'the envelope does not carry the shards'' time '//time)
        if (allocated(err)) return
        call execute_command_line('rm -f '//out//'/ce_summary.csv '//out//'/ce_response.* '// &
            out//'/ce_envelope.* && sed -i "1s/^# fricon [^,]*,/# fricon 0.0.1,/" '//out// &
            '/ce_summary.shard-*-of-2.csv')
        call expect_refusal(shard_paths(out, 'ce', [1, 2]), 'written by fricon 0.0.1', err)
    end subroutine test_stamp

    !> A combination that does not solve (UP, cases 3 and 6, one in each shard): the merge
    !! refuses, names the case, exits with status 1 and writes nothing (no summary, response
    !! script, nor envelope), as a single run of the deck writes no envelope (it exits 2
    !! there, test_load_combinations).
    subroutine test_failed(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        call fresh(dir//'/failed')
        call write_lines(dir//'/failed/ce.dat', failing_deck())
        call run_deck(dir//'/failed/ce.dat', dir//'/failed/shards', quick(1), status, err)
        if (allocated(err)) return
        call check(err, status == 2 .and. exists(dir//'/failed/shards/ce_001_UP.json'), &
                   'the combination UP solved, or shard 1 did not run')
        if (allocated(err)) return
        call run_deck(dir//'/failed/ce.dat', dir//'/failed/shards', quick(2), status, err)
        if (allocated(err)) return
        call expect_refusal(shard_paths(dir//'/failed/shards', 'ce', [1, 2]), &
                            'ce_001_UP (case 003 of 006: E_F=15.0E3 UP = -1.0 G + 1.0 W) did '// &
                                'not solve', &
                            err)
    end subroutine test_failed

    !> A case whose JSON summary is missing beside its shard: refused, nothing written.
    subroutine test_missing(err)
        type(error_t), allocatable, intent(out) :: err
        call fresh(dir//'/missing')
        call write_lines(dir//'/missing/ce.dat', good_deck())
        call run_shards(dir//'/missing/ce.dat', dir//'/missing/shards', err)
        if (allocated(err)) return
        call execute_command_line('rm '//dir//'/missing/shards/ce_002_ULS.json')
        call expect_refusal(shard_paths(dir//'/missing/shards', 'ce', [1, 2]), &
                            'ce_002_ULS.json is missing', err)
    end subroutine test_missing

    ! ------------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------------

    !> The merge is refused with a message holding `words`; fricon --merge exits with status
    !! 1 and leaves no merged summary, response script or envelope file.
    subroutine expect_refusal(shards, words, err)
        character(len=*), intent(in) :: shards(:), words
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        character(len=:), allocatable :: merged, folder
        integer :: status, k
        folder = shards(1)(1:index(shards(1), '/', back=.true.) - 1)
        call merge_shards(shards, '', .false., merged, refusal)
        call check(err, allocated(refusal), 'refused nothing ('//words//')')
        if (allocated(err)) return
        call check(err, index(refusal%message, words) > 0, 'the refusal does not say "'// &
                   words//'": '//refusal%message)
        if (allocated(err)) return
        call run_merge(shards, '', .false., .true., status)
        call check(err, status == 1 .and. .not. exists(folder//'/ce_summary.csv') .and. &
                   .not. exists(folder//'/ce_response.gp'), 'exit status not 1, or a '// &
                   'summary or response script written ('//words//')')
        if (allocated(err)) return
        do k = 1, size(kinds)
            call check(err, .not. exists(folder//'/ce_envelope'//trim(kinds(k))), &
                       'ce_envelope'//trim(kinds(k))//' written ('//words//')')
            if (allocated(err)) return
        end do
    end subroutine expect_refusal

    !> Run the deck in one process into DIR/serial and in two shards into DIR/shards.
    subroutine run_serial_and_shards(path, folder, err)
        character(len=*), intent(in) :: path, folder
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        call run_deck(path, folder//'/serial', quick(0), status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. exists(folder//'/serial/ce_envelope.txt'), &
                   'the single run wrote no envelope')
        if (allocated(err)) return
        call run_shards(path, folder//'/shards', err)
    end subroutine run_serial_and_shards

    !> The two shards of the deck into out.
    subroutine run_shards(path, out, err)
        character(len=*), intent(in) :: path, out
        type(error_t), allocatable, intent(out) :: err
        integer :: status, i
        do i = 1, 2
            call run_deck(path, out, quick(i), status, err)
            if (allocated(err)) return
            call check(err, status == EXIT_OK .and. .not. exists(out//'/ce_envelope.txt'), &
                       'a shard did not solve, or wrote an envelope')
            if (allocated(err)) return
        end do
    end subroutine run_shards

    !> Options of a quick run: no figures, HTML or estimates, one thread; shard i of 2 (0:
    !! the whole deck).
    function quick(i) result(opt)
        integer, intent(in) :: i
        type(run_options_t) :: opt
        opt%figures = .false.
        opt%record = .false.
        opt%estimates = .false.
        opt%threads = 1
        if (i > 0) then
            opt%shard_index = i
            opt%shard_count = 2
        end if
    end function quick

    !> Read the deck file and run it into out, its console lines to a scratch file.
    subroutine run_deck(path, out, opt, status, err)
        character(len=*), intent(in) :: path, out
        type(run_options_t), intent(in) :: opt
        integer, intent(out) :: status
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: u
        status = -1
        call read_deck(path, deck, err)
        if (allocated(err)) return
        open (newunit=u, status='scratch', action='readwrite')
        call run_analysis(deck, out, u, u, status, opt)
        close (u)
    end subroutine run_deck

    !> out/STEM_summary.shard-I-of-2.csv for each I of order.
    function shard_paths(out, stem, order) result(paths)
        character(len=*), intent(in) :: out, stem
        integer, intent(in) :: order(:)
        character(len=200), allocatable :: paths(:)
        integer :: k
        allocate (paths(size(order)))
        do k = 1, size(order)
            paths(k) = out//'/'//stem//'_summary.shard-'//achar(48 + order(k))//'-of-2.csv'
        end do
    end function shard_paths

    subroutine fresh(folder)
        character(len=*), intent(in) :: folder
        call execute_command_line('rm -rf '//folder//' && mkdir -p '//folder)
    end subroutine fresh

    function first_line(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        character(len=:), allocatable :: lines(:)
        logical :: ok
        call read_lines(path, lines, ok)
        text = ''
        if (ok .and. size(lines) > 0) text = trim(lines(1))
    end function first_line

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists
end module test_shard_envelope
