!> Reports and files: data columns read back numerically, nothing written on input errors,
!! a failed analysis leaves only its report (under a banner), atomic writes leave no .tmp.
module test_report_writer
    use deck_fields, only: int_text
    use iso_fortran_env, only: output_unit, error_unit, int64
    use run_identity, only: run_time, iso_time_of_epoch
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_OK, EXIT_INPUT, EXIT_ANALYSIS
    use deck_reader, only: deck_t, parse_deck, case_model
    use model, only: model_t
    use output_paths, only: writes_file, check_decks_apart, canonical_path
    use file_system, only: make_folder, folder_entries
    use atomic_files, only: open_temporary, commit_file
    use analysis_driver, only: run_analysis, run_options_t
    use figure_templates, only: panel_template, sweep_template, ground_template
    use blas_threads, only: set_blas_threads, blas_thread_count
    implicit none
    private
    public :: collect_report_writer, file_text

    character(len=*), parameter :: dir = 'build/test_output'

contains

    subroutine collect_report_writer(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('data_file_columns_and_equilibrium', test_data_file), &
                 new_unittest('input_error_writes_nothing', test_input_error), &
                 new_unittest('failed_case_report_only', test_failed_case), &
                 new_unittest('sweep_summary', test_sweep), &
                 new_unittest('sweep_ready_to_plot', test_sweep_ready_to_plot), &
                 new_unittest('sweep_first_case_fails', test_sweep_first_fails), &
                 new_unittest('embedded_templates_match', test_templates), &
                 new_unittest('parallel_and_sharded_sweeps_match_serial', test_parallel_sweep), &
                 new_unittest('single_case_independent_of_blas_threads', test_blas_threads), &
                 new_unittest('json_summary_parses_with_escaped_title', test_json_title), &
                 new_unittest('sweep_outputs_never_overwrite_a_deck', test_decks_apart), &
                 new_unittest('failed_write_leaves_no_file', test_failed_write), &
                 new_unittest('stale_outputs_of_the_deck_removed', test_stale_outputs), &
                 new_unittest('stale_outputs_found_in_one_listing', test_stale_listing), &
                 new_unittest('folders_made_and_listed_without_a_shell', test_file_system), &
                 new_unittest('loads_mesh_too_coarse_is_a_deck_error', test_loads_mesh), &
                 new_unittest('bad_card_line_not_also_reported_missing', test_no_follow_on), &
                 new_unittest('incomplete_file_not_committed', test_incomplete_file), &
                 new_unittest('positions_fit_their_columns', test_position_formats), &
                 new_unittest('tension_flags_warned', test_tension_warning), &
                 new_unittest('file_cut_at_line_end_not_committed', test_cut_at_line_end), &
                 new_unittest('sweep_with_unwritten_case_has_no_summary', test_unwritten_case), &
                 new_unittest('moments_about_mid_plane_and_base', test_moment_conventions), &
                 new_unittest('epoch_to_iso_time', test_epoch_time), &
                 new_unittest('version_and_run_time_in_every_file', test_traceability), &
                 new_unittest('springs_file_only_where_meaningful', test_springs_file), &
                 new_unittest('rewritten_output_reuses_its_file_not_its_links', &
                              test_rewritten_output)]
    end subroutine collect_report_writer

    function card(name, fields) result(line)
        character(len=*), intent(in) :: name
        character(len=*), intent(in) :: fields(:)
        character(len=80) :: line
        integer :: i
        line = name
        do i = 1, size(fields)
            line(11 + 10*(i - 1):20 + 10*(i - 1)) = adjustr(fields(i)(1:min(10, len(fields(i)))))
        end do
    end function card

    !> A NONDIM plate deck; `extra` cards inserted before END.
    function plate_deck(load_fx, extra) result(lines)
        character(len=*), intent(in) :: load_fx
        character(len=*), intent(in) :: extra(:)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: 'TITLE     report test', card('MODEL', ['PLATE']), &
                 card('NONDIM', ['0.01      ', '0.1       ', '0.3       ', '0.1       ']), &
                 card('FRICTION', ['0.5']), &
                 card('LOAD', [character(len=10) :: 'POINT', '1.0', load_fx, '0.0']), &
                 card('MESH', ['16']), extra, card('END', [' '])]
    end function plate_deck

    !> A small physical beam deck (one case), a SWEEP card appended when given.
    function beam_deck(sweep) result(lines)
        character(len=*), intent(in) :: sweep(:)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: card('MODEL', ['BEAM']), card('UNITS', ['kN', 'm ']), &
                 card('GEOMETRY', ['10.0', '0.8 ', '1.0 '// &
                     '']), card('STRUCTURE', ['3.0E7', '0.2  ']), &
                 card('SOIL', ['3.0E4', '0.3  ']), card('FRICTION', ['0.5']), &
                 card('LOAD', ['POINT ', '1000.0', '      ', '0.0   ']), &
                 card('MESH', ['16'])]
        if (size(sweep) > 0) lines = [character(len=80) :: lines, card('SWEEP', sweep)]
        lines = [character(len=80) :: lines, card('END', [' '])]
    end function beam_deck

    !> The files a deck writes (output_paths::writes_file): one case STEM.ext; a sweep of 12
    !! STEM_001.ext to STEM_012.ext (as wide as 12 needs, at least 3 digits), STEM_summary.csv,
    !! STEM_sweep.gp/.png, and their .tmp; nothing else. A sweep deck s.dat beside a deck
    !! s_001.dat in one output folder: the run is refused (s_001.dat would be overwritten by
    !! case 1's data file), and so are a sweep x and a deck x_001 writing into one folder
    !! (both would write x_001.txt); two decks apart pass.
    subroutine test_decks_apart(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        integer :: u
        call check(err, writes_file('s', 1, 's.dat') .and. writes_file('s', 1, 's.json.tmp') .and. &
                   .not. writes_file('s', 1, 's_001.dat') .and. writes_file('s', 12, 's_012.png') &
                   .and. .not. writes_file('s', 12, 's_013.png') .and. &
                   .not. writes_file('s', 12, 's_0012.png') .and. &
                   .not. writes_file('s', 12, 's.dat') .and. writes_file('s', 12, 's_summary.csv') &
                   .and. writes_file('s', 12, 's_sweep.gp') .and. .not. writes_file('s', 1, &
                   's_summary.csv') .and. writes_file('s', 1000, 's_0999.txt') .and. .not. &
                   writes_file('s', 1000, 's_999.txt'), 'writes_file: the output names')
        if (allocated(err)) return
        call clean_dir()
        open (newunit=u, file=dir//'/s_001.dat', status='replace', action='write')
        write (u, '(a)') '* a deck'
        close (u)
        open (newunit=u, file=dir//'/s.dat', status='replace', action='write')
        close (u)
        call check_decks_apart([character(len=40) :: dir//'/s.dat', dir//'/s_001.dat'], &
                               [character(len=40) :: dir, dir], ['s    ', 's_001'], [2, 1], refusal)
        call check(err, refused(refusal, 's_001.dat would be overwritten'), &
                   'a deck overwritten by a sweep case was not refused, or not for that')
        if (allocated(err)) return
        call check_decks_apart([character(len=40) :: 'a/x.dat', 'b/x_001.dat'], &
                               [character(len=40) :: dir, dir], ['x    ', 'x_001'], [3, 1], refusal)
        call check(err, refused(refusal, 'would both write'), &
                   'a sweep and a deck writing x_001.* were not refused, or not for that')
        if (allocated(err)) return
        call check_decks_apart([character(len=40) :: 'a/x.dat', 'b/y.dat'], &
                               [character(len=40) :: dir, dir], ['x', 'y'], [3, 1], refusal)
        call check(err, .not. allocated(refusal), 'decks apart were refused')
    end subroutine test_decks_apart

    !> An error that says why (text) was given.
    logical function refused(e, text)
        type(error_t), allocatable, intent(in) :: e
        character(len=*), intent(in) :: text
        refused = allocated(e)
        if (refused) refused = index(e%message, text) > 0
    end function refused

    !> A write that fails (the CSV's name is taken by a folder) ends with status 1 and leaves
    !! none of the case's files and no .tmp (README: an exit 1 writes no output).
    subroutine test_failed_write(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, k, u
        character(len=80) :: line
        character(len=*), parameter :: ext(6) = ['.txt ', '.dat ', '.json', '.gp  ', '.png ', &
                                                 '.tmp ']
        call clean_dir()
        call execute_command_line('mkdir -p '//dir//'/w.csv')
        call parse_deck('w.dat', beam_deck([character(len=4) ::]), deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
            run_options_t(figures=.false.))
        call check(err, status == EXIT_INPUT, 'a failed write did not end with status 1')
        if (allocated(err)) return
        do k = 1, size(ext)
            call check(err, .not. exists(dir//'/w'//trim(ext(k))) .and. .not. &
                       exists(dir//'/w'//trim(ext(k))//'.tmp') .and. .not. &
                       exists(dir//'/w.csv.tmp'), 'a file was left: w'//trim(ext(k)))
            if (allocated(err)) return
        end do
        ! a deck (or any file not fricon's) named like an output is neither replaced nor
        ! deleted: the case ends with status 1, the file is as it was
        call clean_dir()
        open (newunit=u, file=dir//'/w.dat', status='replace', action='write')
        write (u, '(a)') '* a deck named like the data file'
        close (u)
        call run_analysis(deck, dir, output_unit, error_unit, status, &
            run_options_t(figures=.false.))
        line = ''
        open (newunit=u, file=dir//'/w.dat', status='old', action='read')
        read (u, '(a)') line
        close (u)
        call check(err, status == EXIT_INPUT .and. line == '* a deck named like the data file', &
                   'a file that is not fricon''s output was replaced or deleted')
    end subroutine test_failed_write

    !> What an earlier run of the same deck wrote and this one does not is removed: a sweep of
    !! three, then of two (st_003.* go), then one case (st_001.*, st_002.*, the summary and the
    !! sweep script go; st.* come), then an input error (st.* go: an exit 1 leaves no output).
    !! A file of another deck (other_001.json names other.dat) stays.
    subroutine test_stale_outputs(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u
        type(run_options_t) :: opt
        character(len=*), parameter :: deck_path = 'build/test_stale/st.dat'
        opt%figures = .false.
        opt%estimates = .false.
        call clean_dir()
        ! the deck exists as a file: its canonical path is what the JSON records and matches
        call execute_command_line('rm -rf build/test_stale && mkdir -p build/test_stale && '// &
                                  'touch '//deck_path)
        open (newunit=u, file=dir//'/st_004.json', status='replace', action='write')
        write (u, '(a)') '{'
        write (u, '(a)') '  "deck": "other.dat",'
        write (u, '(a)') '  "deck_file": "/elsewhere/other.dat",'
        close (u)
        call parse_deck(deck_path, beam_deck(['F  ', '0.3', '0.4', '0.5']), deck, err)
        if (allocated(err)) return
        deck%from_file = .true.        ! as read_deck would: the deck is the file deck_path
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK .and. exists(dir//'/st_003.txt'), 'sweep of three')
        if (allocated(err)) return
        call parse_deck(deck_path, beam_deck(['F  ', '0.3', '0.4']), deck, err)
        if (allocated(err)) return
        deck%from_file = .true.
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK .and. exists(dir//'/st_002.txt') .and. .not. &
                   exists(dir//'/st_003.txt') .and. .not. exists(dir//'/st_003.json') .and. &
                   exists(dir//'/st_summary.csv'), 'sweep of two: case 3 of three left')
        if (allocated(err)) return
        call parse_deck(deck_path, beam_deck([character(len=4) ::]), deck, err)
        if (allocated(err)) return
        deck%from_file = .true.
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK .and. exists(dir//'/st.txt') .and. .not. &
                   exists(dir//'/st_001.txt') .and. .not. exists(dir//'/st_002.dat') .and. .not. &
                   exists(dir//'/st_summary.csv') .and. .not. exists(dir//'/st_sweep.gp'), &
                   'one case: the sweep''s files left')
        if (allocated(err)) return
        deck%path = deck_path
        call run_analysis_of_bad_deck(deck, status)
        call check(err, status == EXIT_INPUT .and. .not. exists(dir//'/st.txt') .and. .not. &
                   exists(dir//'/st.json') .and. exists(dir//'/st_004.json'), &
                   'input error: the earlier st.* left, or another deck''s file removed')
    end subroutine test_stale_outputs

    !> Folders without a shell (file_system): make_folder makes a folder and its parents,
    !! accepts one that exists, and fails where a file has the name; folder_entries lists the
    !! names with a prefix and a suffix (exactly those of the files made here), and says when
    !! there is no folder to list.
    subroutine test_file_system(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: made_names(5) = [character(len=10) :: 'x_001.json', &
            'x_002.json', 'x_001.txt', 'y_001.json', 'x_002.jsn']
        character(len=:), allocatable :: names(:)
        logical :: made, again, on_file, listed
        integer :: u, k
        call clean_dir()
        call make_folder(dir//'/a/b/c', made)
        call make_folder(dir//'/a/b/c', again)
        open (newunit=u, file=dir//'/f', status='replace', action='write')
        close (u)
        call make_folder(dir//'/f', on_file)
        call check(err, made .and. again .and. .not. on_file .and. exists(dir//'/a/b/c/.'), &
                   'make_folder: a new nested folder, an existing one, a file in the way')
        if (allocated(err)) return
        do k = 1, size(made_names)
            open (newunit=u, file=dir//'/a/'//trim(made_names(k)), status='replace', &
                  action='write')
            close (u)
        end do
        call folder_entries(dir//'/a', 'x_', '.json', names, listed)
        call check(err, listed .and. size(names) == 2, 'folder_entries: not the two x_*.json')
        if (allocated(err)) return
        call check(err, (names(1) == 'x_001.json' .and. names(2) == 'x_002.json') .or. &
                   (names(2) == 'x_001.json' .and. names(1) == 'x_002.json'), &
                   'folder_entries: not x_001.json and x_002.json')
        if (allocated(err)) return
        call folder_entries(dir//'/none', 'x_', '.json', names, listed)
        call check(err, .not. listed .and. size(names) == 0, 'folder_entries: a missing folder')
    end subroutine test_file_system

    !> The stale-output cleanup finds a deck's earlier cases wherever their numbers lie: a
    !! case st_1500 (after a gap of 1499 numbers) and the summaries of earlier splits into
    !! shards (st_summary.shard-2-of-3.csv) go when the deck now runs one case; a name fricon
    !! never writes (shard-02-of-3) and a deck of the user's named like a shard summary stay.
    subroutine test_stale_listing(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        character(len=*), parameter :: deck_path = 'build/test_stale/st.dat'
        integer :: status, u
        opt%figures = .false.
        opt%estimates = .false.
        call clean_dir()
        call execute_command_line('rm -rf build/test_stale && mkdir -p build/test_stale && '// &
                                  'touch '//deck_path)
        open (newunit=u, file=dir//'/st_1500.json', status='replace', action='write')
        write (u, '(a)') '{'
        write (u, '(a)') '  "deck_file": "'//canonical_path(deck_path)//'",'
        close (u)
        call write_line(dir//'/st_1500.txt', '= report')
        call write_line(dir//'/st_summary.shard-2-of-3.csv', 'case,parameters')
        call write_line(dir//'/st_summary.shard-02-of-3.csv', 'case,parameters')
        call write_line(dir//'/st_summary.shard-1-of-3.csv', '* a deck')
        call parse_deck(deck_path, beam_deck([character(len=4) ::]), deck, err)
        if (allocated(err)) return
        deck%from_file = .true.        ! as read_deck would: the deck is the file deck_path
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK .and. exists(dir//'/st.txt') .and. .not. &
                   exists(dir//'/st_1500.json') .and. .not. exists(dir//'/st_1500.txt') .and. &
                   .not. exists(dir//'/st_summary.shard-2-of-3.csv'), &
                   'a stale case after a gap, or a stale shard summary, was left')
        if (allocated(err)) return
        call check(err, exists(dir//'/st_summary.shard-02-of-3.csv') .and. &
                   exists(dir//'/st_summary.shard-1-of-3.csv'), &
                   'a file fricon does not write, or a deck, was removed')
    end subroutine test_stale_listing

    subroutine write_line(path, line)
        character(len=*), intent(in) :: path, line
        integer :: u
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') line
        close (u)
    end subroutine write_line

    !> Run a deck whose case 1 is invalid (status 1; case_model reports it).
    subroutine run_analysis_of_bad_deck(deck, status)
        type(deck_t), intent(in) :: deck
        integer, intent(out) :: status
        type(deck_t) :: bad
        type(error_t), allocatable :: err
        call parse_deck(deck%path, beam_deck(['L   ', '10.0']), bad, err)
        if (allocated(err)) then
            status = -1
            return
        end if
        bad%sweeps(1)%values(1) = -10.0_dp       ! a beam of negative length: case 1 invalid
        bad%from_file = .true.
        call run_analysis(bad, dir, output_unit, error_unit, status)
    end subroutine run_analysis_of_bad_deck

    !> LOADS grading needs an element for each piece between the load positions: a beam with a
    !! patch and a point load (4 pieces) on MESH 2 LOADS is a deck error at the MESH card's
    !! N_e field (line 8, columns 11-20), before anything is solved (not a failure while
    !! meshing, after the other cases of a sweep have been solved and written).
    subroutine test_loads_mesh(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        character(len=80), allocatable :: lines(:)
        lines = beam_deck([character(len=4) ::])
        lines(7) = card('LOAD', ['PATCH ', '1000.0', '      ', '-2.0  ', '1.0   '])
        lines(8) = card('MESH', ['2     ', 'LOADS '])
        lines = [character(len=80) :: lines(1:7), card('LOAD', ['POINT ', '500.0 ', '      ', &
                 '3.0   ']), lines(8:)]
        call parse_deck('coarse.dat', lines, deck, err)
        if (allocated(err)) return
        call case_model(deck, 1, m, label, refusal)
        call check(err, refused(refusal, 'coarse.dat:9:11-20') .and. &
                   refused(refusal, 'at least 4'), 'MESH 2 LOADS with 4 pieces not refused at '// &
                   'its N_e field')
    end subroutine test_loads_mesh

    !> A card line rejected for its characters or layout still counts as that card: a TAB
    !! after STRUCTURE (two TABs: one message, as TAB) and MODEL starting in column 2 each give
    !! their own error and no "missing STRUCTURE/MODEL card" besides (a reader would look for
    !! a card that is there).
    subroutine test_no_follow_on(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        type(deck_t) :: deck
        character(len=80), allocatable :: lines(:)
        lines = beam_deck([character(len=4) ::])
        lines(4) = 'STRUCTURE'//achar(9)//'3.0E7'//achar(9)//'0.2'
        lines(1) = ' MODEL    BEAM'
        call parse_deck('tabs.dat', lines, deck, refusal)
        call check(err, refused(refusal, 'TAB character in column 10') .and. &
                   refused(refusal, 'starts in column 2') .and. .not. &
                   refused(refusal, 'missing') .and. .not. refused(refusal, 'control character') &
                   .and. refused(refusal, '2 input errors'), 'follow-on errors or a TAB '// &
                   'reported twice')
    end subroutine test_no_follow_on

    !> A sweep one of whose cases cannot write its files (here case 2's CSV name is taken by a
    !! folder; on a full disk any file) ends with status 1 and leaves no summary CSV or
    !! overlay script, not even those of an earlier complete run: they would summarise part
    !! of the sweep. The other cases' files are written.
    subroutine test_unwritten_case(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: status
        opt%figures = .false.
        opt%estimates = .false.
        call clean_dir()
        call parse_deck('u.dat', beam_deck(['F  ', '0.3', '0.4', '0.5']), deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK .and. exists(dir//'/u_summary.csv') .and. &
                   exists(dir//'/u_sweep.gp'), 'the complete sweep has its summary')
        if (allocated(err)) return
        call execute_command_line('rm -f '//dir//'/u_002.csv && mkdir '//dir//'/u_002.csv')
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_INPUT .and. exists(dir//'/u_001.txt') .and. &
                   exists(dir//'/u_003.txt') .and. .not. exists(dir//'/u_002.txt'), &
                   'case 2 must fail (status 1), cases 1 and 3 be written')
        if (allocated(err)) return
        call check(err, .not. exists(dir//'/u_summary.csv') .and. .not. &
                   exists(dir//'/u_sweep.gp') .and. .not. exists(dir//'/u_summary.csv.tmp'), &
                   'a summary or overlay left beside a sweep with an unwritten case')
    end subroutine test_unwritten_case

    !> A full disk can cut a file at a block boundary that falls at a line end (a sweep's
    !! overlay script was committed with 4096 of its 8900 bytes on a 60 kB tmpfs): two lines
    !! written and flushed, the file then cut after the first (as the disk would), is not
    !! committed: an error, and neither the file nor its .tmp.
    subroutine test_cut_at_line_end(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        integer :: u
        call clean_dir()
        call open_temporary(dir//'/cut.txt', u, refusal)
        call check(err, .not. allocated(refusal), 'cannot open the temporary file')
        if (allocated(err)) return
        write (u, '(a)') '= line one'
        write (u, '(a)') '= line two'
        flush (u)
        ! 11 bytes: '= line one' and its line end
        call execute_command_line('truncate -s 11 '//dir//'/cut.txt.tmp')
        call commit_file(dir//'/cut.txt', u, refusal)
        call check(err, refused(refusal, 'incomplete') .and. .not. exists(dir//'/cut.txt') &
                   .and. .not. exists(dir//'/cut.txt.tmp'), 'a file cut at a line end was '// &
                   'committed')
    end subroutine test_cut_at_line_end

    !> A file whose last line is cut (what a full disk leaves: gfortran's buffered writes and
    !! close report nothing there; seen on a 40 kB tmpfs, where every case printed "solved"
    !! over empty files) is not committed: an error, and neither the file nor its .tmp. A
    !! complete one is.
    subroutine test_incomplete_file(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        integer :: u
        call clean_dir()
        ! (a stream, as the disk leaves it: a formatted file's close would end the line)
        open (newunit=u, file=dir//'/cut.txt.tmp', status='replace', access='stream', &
              form='unformatted', action='write')
        write (u) '= a report cut in its first line'
        call commit_file(dir//'/cut.txt', u, refusal)
        call check(err, refused(refusal, 'incomplete') .and. .not. exists(dir//'/cut.txt') &
                   .and. .not. exists(dir//'/cut.txt.tmp'), 'an incomplete file was committed')
        if (allocated(err)) return
        call open_temporary(dir//'/whole.txt', u, refusal)
        write (u, '(a)') '= a whole report'
        call commit_file(dir//'/whole.txt', u, refusal)
        call check(err, .not. allocated(refusal) .and. exists(dir//'/whole.txt'), &
                   'a complete file was not committed')
    end subroutine test_incomplete_file

    !> An output written again (atomic_files): a shorter text leaves nothing of the longer
    !! one behind (the file's bytes are exactly the new lines), the file is the same inode
    !! (rewritten in place: no inode allocated and freed), and an earlier output that has a
    !! second name (a hard link kept as a copy) is not rewritten: the link keeps the old text,
    !! the output gets a new file. Expected bytes: the lines written plus one line end each.
    subroutine test_rewritten_output(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: path = dir//'/again.txt'
        character(len=*), parameter :: long = '= a longer first report, two lines', &
                                       short = '= short'
        integer :: inode_before
        call clean_dir()
        call write_output(path, [long, long], err)
        if (allocated(err)) return
        inode_before = inode(path)
        call write_output(path, [short], err)
        if (allocated(err)) return
        call check(err, file_text(path) == short//achar(10), 'the rewritten file is not '// &
                   'exactly its new text: "'//file_text(path)//'"')
        if (allocated(err)) return
        call check(err, inode(path) == inode_before .and. inode_before > 0, 'the output '// &
                   'was not rewritten in place (a new inode)')
        if (allocated(err)) return
        call execute_command_line('ln '//path//' '//dir//'/kept.txt')
        call write_output(path, [long], err)
        if (allocated(err)) return
        call check(err, file_text(dir//'/kept.txt') == short//achar(10) .and. &
                   file_text(path) == long//achar(10) .and. inode(path) /= inode_before, &
                   'a hard-linked earlier output was rewritten through its other name')
    end subroutine test_rewritten_output

    !> Write lines to path through open_temporary and commit_file.
    subroutine write_output(path, lines, err)
        character(len=*), intent(in) :: path, lines(:)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        integer :: u, i
        call open_temporary(path, u, refusal)
        if (.not. allocated(refusal)) then
            do i = 1, size(lines)
                write (u, '(a)') trim(lines(i))
            end do
            call commit_file(path, u, refusal)
        end if
        call check(err, .not. allocated(refusal), 'cannot write '//path)
    end subroutine write_output

    !> The whole file as text ('' when it cannot be read).
    function file_text(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        integer :: u, ios, n
        text = ''
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=n)
        deallocate (text)
        allocate (character(len=n) :: text)
        if (n > 0) read (u, iostat=ios) text
        close (u)
    end function file_text

    !> The inode number of path, from stat(1) (-1 when it cannot be read).
    integer function inode(path)
        character(len=*), intent(in) :: path
        integer :: u, ios
        inode = -1
        call execute_command_line('stat -c %i '//path//' > '//dir//'/inode.out')
        open (newunit=u, file=dir//'/inode.out', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (u, *, iostat=ios) inode
        if (ios /= 0) inode = -1
        close (u)
    end function inode

    subroutine clean_dir()
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
    end subroutine clean_dir

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    !> Positions print as numbers for any allowed length (GEOMETRY l from 1E-30 to below
    !! 1E+30): the same beam (h = l/20, b = l/10) at l = 2E12, 1E-20 and 10 has its first
    !! physical station at x = -l/2 (stations at the nodes, the first at the left end) and its
    !! first contact or lift-off interval from -l/2, both read back from the report to 1e-4;
    !! no field of the report is all asterisks, and the figure is drawn (its script reads the
    !! lift-off zones back as numbers).
    subroutine test_position_formats(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=10), parameter :: geometry(3, 3) = reshape([character(len=10) :: &
            '2.0E12', '1.0E11', '2.0E11', '1.0E-20', '5.0E-22', '1.0E-21', '10.0', '0.5', &
            '1.0'], [3, 3])
        real(dp), parameter :: length(3) = [2.0e12_dp, 1.0e-20_dp, 10.0_dp]
        type(deck_t) :: deck
        type(run_options_t) :: opt
        character(len=80), allocatable :: lines(:)
        character(len=200) :: first_row, first_interval
        logical :: stars
        integer :: k, status, ios
        real(dp) :: x_row, x_interval
        opt%estimates = .false.
        sizes: do k = 1, 3
            call clean_dir()
            lines = beam_deck([character(len=4) ::])
            lines(3) = card('GEOMETRY', geometry(:, k))
            call parse_deck('pos.dat', lines, deck, err)
            if (allocated(err)) return
            call run_analysis(deck, dir, output_unit, error_unit, status, opt)
            call check(err, status == EXIT_OK .and. exists(dir//'/pos.png'), 'l = '// &
                       trim(geometry(1, k))//': not solved, or no figure')
            if (allocated(err)) return
            call report_positions(dir//'/pos.txt', first_row, first_interval, stars)
            call check(err, .not. stars, 'l = '//trim(geometry(1, k))//': a field of the '// &
                       'report is asterisks')
            if (allocated(err)) return
            read (first_row, *, iostat=ios) x_row
            if (ios == 0) read (first_interval(index(first_interval, 'from') + 4: &
                                index(first_interval, ' to') - 1), *, iostat=ios) x_interval
            call check(err, ios == 0, 'l = '//trim(geometry(1, k))//': unreadable position in "'// &
                       trim(first_row)//'" or "'//trim(first_interval)//'"')
            if (allocated(err)) return
            call check_close(err, x_row, -0.5_dp*length(k), 1.0e-4_dp, 0.0_dp, 'first station')
            if (allocated(err)) return
            call check_close(err, x_interval, -0.5_dp*length(k), 1.0e-4_dp, 0.0_dp, &
                             'first interval')
            if (allocated(err)) return
        end do sizes
    end subroutine test_position_formats

    !> A solved case whose station table flags tension (rows ending !T) says so in a WARNING
    !! naming their number, in the report and the JSON: a very soft thick beam (NONDIM rho 1e-6,
    !! zeta 0.5, f 0, N_e 20) lifts off nearly everywhere and the penalty pulls on it. A case
    !! without flags (the physical beam) has no such warning.
    subroutine test_tension_warning(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        character(len=80), allocatable :: lines(:)
        character(len=400) :: line
        character(len=16) :: count_text
        integer :: status, u, ios, n_flagged, n_warned
        logical :: in_json
        opt%figures = .false.
        opt%estimates = .false.
        call clean_dir()
        lines = [character(len=80) :: card('MODEL', ['BEAM']), card('NONDIM', [character(len=10) &
                 :: '1.0E-6', '0.5', '', '', '1.0']), card('FRICTION', ['0.0']), &
                 card('LOAD', ['POINT', '1.0  ']), card('MESH', ['20']), card('END', [' '])]
        call parse_deck('soft.dat', lines, deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK, 'the soft beam is solved (status 0)')
        if (allocated(err)) return
        n_flagged = 0
        n_warned = 0
        open (newunit=u, file=dir//'/soft.txt', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (len_trim(line) > 3) then
                if (line(len_trim(line) - 2:len_trim(line)) == ' !T') n_flagged = n_flagged + 1
            end if
            if (index(line, 'WARNING: tension at ') > 0) n_warned = n_warned + 1
            if (index(line, 'WARNING: tension at ') > 0) count_text = line(index(line, 'at ') + 3:)
        end do
        close (u)
        call check(err, n_flagged > 0 .and. n_warned == 1, 'rows !T: '//int_text(n_flagged)// &
                   ', tension warnings: '//int_text(n_warned))
        if (allocated(err)) return
        call check(err, count_text(1:index(count_text, ' ') - 1) == int_text(n_flagged), &
                   'the warning counts '//trim(count_text)//' flagged rows, the table '// &
                   int_text(n_flagged))
        if (allocated(err)) return
        in_json = .false.
        open (newunit=u, file=dir//'/soft.json', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            in_json = in_json .or. index(line, 'tension at '//int_text(n_flagged)) > 0
        end do
        close (u)
        call check(err, in_json, 'the JSON lacks the tension warning')
        if (allocated(err)) return
        call clean_dir()
        call parse_deck('firm.dat', beam_deck([character(len=4) ::]), deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        n_warned = 0
        open (newunit=u, file=dir//'/firm.txt', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'tension at ') > 0) n_warned = n_warned + 1
        end do
        close (u)
        call check(err, status == EXIT_OK .and. n_warned == 0, 'a case without !T rows warns '// &
                   'of tension')
    end subroutine test_tension_warning

    !> The first row of the physical station table (section 6, after its two heading lines),
    !! the first interval line ('from ... to ...'), and whether a run of four asterisks occurs.
    subroutine report_positions(path, first_row, first_interval, stars)
        character(len=*), intent(in) :: path
        character(len=*), intent(out) :: first_row, first_interval
        logical, intent(out) :: stars
        character(len=400) :: line
        integer :: u, ios, after_heading
        first_row = ''
        first_interval = ''
        stars = .false.
        after_heading = -1
        open (newunit=u, file=path, status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            stars = stars .or. index(line, '****') > 0
            if (index(line, 'STATIONS (physical units)') > 0) after_heading = 0
            if (after_heading >= 0) after_heading = after_heading + 1
            if (after_heading == 4 .and. len_trim(first_row) == 0) first_row = line
            if (len_trim(first_interval) == 0 .and. index(line, ' from') > 0 .and. &
                index(line, ' to') > 0) first_interval = line
        end do
        close (u)
    end subroutine report_positions

    !> The data file has 14 numeric columns per row (plate); integrating Sigma_z over the disk
    !! from the printed columns (trapezoid on 2 pi t dt / pi) gives ~1 (equilibrium, F = 1).
    subroutine test_data_file(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u, ios, n
        character(len=400) :: line
        real(dp) :: row(14), t_prev, s_prev, total
        call clean_dir()
        call parse_deck('rt.dat', plate_deck(' ', [character(len=80) ::]), deck, err)
        if (allocated(err)) return
        deck%stem = 'rt'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_OK, 'report test case did not solve')
        if (allocated(err)) return
        call check(err, exists(dir//'/rt.txt') .and. exists(dir//'/rt.dat') .and. &
                   exists(dir//'/rt.gp') .and. .not. exists(dir//'/rt.dat.tmp'), &
                   'missing output file or leftover .tmp')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/rt.dat', status='old', action='read')
        n = 0
        total = 0.0_dp
        rows: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit rows
            if (line(1:1) == '#') cycle rows
            read (line, *, iostat=ios) row
            if (ios /= 0) exit rows
            n = n + 1
            if (n > 1) total = total + &
                               0.5_dp*(row(6)*row(1) + s_prev*t_prev)*2.0_dp*(row(1) - t_prev)
            t_prev = row(1)
            s_prev = row(6)
        end do rows
        close (u)
        call check(err, ios <= 0 .and. n == 17, 'data file rows unreadable or wrong count')
        if (allocated(err)) return
        ! trapezoid on 16 elements: O(h^2) error, a few per cent near a lift-off edge
        call check_close(err, total, 1.0_dp, 5.0e-2_dp, 0.0_dp, 'int Sigma_z 2t dt from .dat')
    end subroutine test_data_file

    !> Seconds since 1970-01-01T00:00:00Z to ISO 8601 UTC, against dates counted by hand:
    !! 0 is the epoch; 951782400 = 11016 days (30 years with 7 leap days, 1972 ... 1996,
    !! plus January and 28 days of February 2000) is 2000-02-29, a leap day of a year
    !! divisible by 400; 1700000000 = 19675 days + 80000 s is 2023-11-14T22:13:20;
    !! 4107542399 is the last second of 2100-02-28 (2100 is no leap year).
    subroutine test_epoch_time(err)
        type(error_t), allocatable, intent(out) :: err
        integer(int64), parameter :: t(4) = [0_int64, 951782400_int64, 1700000000_int64, &
                                             4107542399_int64]
        character(len=25), parameter :: iso(4) = ['1970-01-01T00:00:00+00:00', &
            '2000-02-29T00:00:00+00:00', '2023-11-14T22:13:20+00:00', &
            '2100-02-28T23:59:59+00:00']
        integer :: k
        do k = 1, size(t)
            call check(err, iso_time_of_epoch(t(k)) == iso(k), 'epoch '//int_text(int(t(k) &
                       /86400_int64))//' days: '//iso_time_of_epoch(t(k))//' expected '//iso(k))
            if (allocated(err)) return
        end do
    end subroutine test_epoch_time

    !> Version and run time in the report, the station CSV and the JSON of a case: the version
    !! is fpm.toml's (read here), the time the run's (ISO 8601 with its offset, the same in
    !! every file); the summary CSV's stamp is checked in sweep_ready_to_plot.
    subroutine test_traceability(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status
        character(len=:), allocatable :: version, stamp
        version = fpm_version()
        call check(err, len(version) > 0 .and. iso_shape(run_time), 'fpm.toml version '// &
                   version//' / run time '//run_time)
        if (allocated(err)) return
        stamp = 'fricon '//version//', run '//trim(run_time)
        call clean_dir()
        call parse_deck('tr.dat', beam_deck([character(len=10) ::]), deck, err)
        if (allocated(err)) return
        deck%stem = 'tr'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_OK, 'the traceability case did not solve')
        if (allocated(err)) return
        call check(err, file_has_line(dir//'/tr.txt', ' '//stamp), 'report: no line " '// &
                   stamp//'"')
        if (allocated(err)) return
        call check(err, file_has_line(dir//'/tr.csv', '# '//stamp), 'CSV: no line "# '// &
                   stamp//'"')
        if (allocated(err)) return
        call check(err, file_has_line(dir//'/tr.json', '  "program": "fricon",') .and. &
                   file_has_line(dir//'/tr.json', '  "version": "'//version//'",') .and. &
                   file_has_line(dir//'/tr.json', '  "run_time": "'//trim(run_time)//'",'), &
                   'JSON: program, version or run_time missing')
    end subroutine test_traceability

    !> CASE_springs.csv is one of a deck's outputs (writes_file: the overwrite and
    !! stale-output checks know it); a solved physical deck writes it; the same case run
    !! again as a NONDIM deck, or failing (H = 600 kN above f V = 500 kN: no equilibrium),
    !! writes none and leaves no springs file of the earlier run.
    subroutine test_springs_file(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status
        character(len=80), allocatable :: lines(:)
        call check(err, writes_file('s', 1, 's_springs.csv') .and. writes_file('s', 1, &
                   's_springs.csv.tmp') .and. writes_file('s', 12, 's_003_springs.csv') .and. &
                   .not. writes_file('s', 12, 's_springs.csv') .and. .not. writes_file('s', 1, &
                   's_001_springs.csv'), 'writes_file: the springs file''s names')
        if (allocated(err)) return
        call clean_dir()
        call run_springs_deck(beam_deck([character(len=4) ::]), status)
        call check(err, status == EXIT_OK .and. exists(dir//'/sp_springs.csv'), &
                   'a solved physical deck wrote no springs file')
        if (allocated(err)) return
        call run_springs_deck([character(len=80) :: card('MODEL', ['BEAM']), card('NONDIM', &
            ['0.01 ', '0.1  ', '0.3  ', '0.1  ', '0.05 ']), card('FRICTION', ['0.5']), &
            card('LOAD', ['POINT', '1.0  ', '     ', '0.0  ']), card('END', [' '])], status)
        call check(err, status == EXIT_OK .and. .not. exists(dir//'/sp_springs.csv') .and. &
                   .not. exists(dir//'/sp.csv'), 'NONDIM deck: a springs file or CSV left')
        if (allocated(err)) return
        call run_springs_deck(beam_deck([character(len=4) ::]), status)
        call check(err, status == EXIT_OK .and. exists(dir//'/sp_springs.csv'), &
                   'the physical deck run again wrote no springs file')
        if (allocated(err)) return
        lines = beam_deck([character(len=4) ::])
        lines(7) = card('LOAD', ['POINT ', '1000.0', '600.0 ', '0.0   '])
        call run_springs_deck(lines, status)
        call check(err, status == EXIT_ANALYSIS .and. exists(dir//'/sp.txt') .and. .not. &
                   exists(dir//'/sp_springs.csv'), 'failed case: a springs file left')
    contains
        subroutine run_springs_deck(deck_lines, status)
            character(len=*), intent(in) :: deck_lines(:)
            integer, intent(out) :: status
            type(error_t), allocatable :: perr
            call parse_deck('sp.dat', deck_lines, deck, perr)
            status = -1
            if (allocated(perr)) return
            deck%stem = 'sp'
            call run_analysis(deck, dir, output_unit, error_unit, status, &
                              run_options_t(figures=.false.))
        end subroutine run_springs_deck
    end subroutine test_springs_file

    !> 'YYYY-MM-DDTHH:MM:SS+HH:MM' (or -HH:MM): digits and separators where ISO 8601 has them.
    pure logical function iso_shape(text)
        character(len=*), intent(in) :: text
        integer, parameter :: digits(14) = [1, 2, 3, 4, 6, 7, 9, 10, 12, 13, 15, 16, 18, 19]
        integer :: i
        iso_shape = len_trim(text) == 25
        if (.not. iso_shape) return
        do i = 1, size(digits)
            iso_shape = iso_shape .and. index('0123456789', text(digits(i):digits(i))) > 0
        end do
        iso_shape = iso_shape .and. text(5:5) == '-' .and. text(11:11) == 'T' .and. &
                    text(14:14) == ':' .and. index('+-', text(20:20)) > 0 .and. text(23:23) == ':'
    end function iso_shape

    !> The version line of fpm.toml, 'version = "0.2.0"' -> 0.2.0 ('' if none).
    function fpm_version() result(version)
        character(len=:), allocatable :: version
        character(len=200) :: line
        integer :: u, ios, a, b
        version = ''
        open (newunit=u, file='fpm.toml', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'version') /= 1) cycle
            a = index(line, '"')
            b = index(line, '"', back=.true.)
            if (b > a + 1) version = line(a + 1:b - 1)
            exit
        end do
        close (u)
    end function fpm_version

    !> The file holds this exact line.
    logical function file_has_line(path, text)
        character(len=*), intent(in) :: path, text
        character(len=2000) :: line
        integer :: u, ios
        file_has_line = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (trim(line) == text) then
                file_has_line = .true.
                exit
            end if
        end do
        close (u)
    end function file_has_line

    !> The stated conventions, by statics. Beam h = 0.8 m: a POINT load F_z = 1000 kN with
    !! F_x = 100 kN (top face) at x = 0 and a MOMENT M0 = 500 kN.m at x = 2.5 m. Moment of
    !! the loads about x = 0: on the mid-plane M0 + F_x h/2 = 540 kN.m, on the base (bottom
    !! face) M0 + F_x h = 580 kN.m; the reactions balance both. Across x = 0 the bending
    !! moment drops by F_x h/2 = 40 kN.m (the top-face load acts h/2 above the mid-plane),
    !! across x = 2.5 m by M0 = 500 kN.m; a positive MOMENT turns the beam clockwise as drawn
    !! (x right, w down), so w(+l/2) > w(-l/2).
    subroutine test_moment_conventions(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status
        real(dp) :: base(2), jump(2), w_ends(2)
        character(len=80), allocatable :: lines(:)
        call clean_dir()
        lines = beam_deck([character(len=10) ::])
        lines(7) = card('LOAD', ['POINT ', '1000.0', '100.0 ', '0.0   '])
        lines = [lines(1:7), card('LOAD', ['MOMENT', '500.0 ', '      ', '2.5   ']), lines(8:)]
        call parse_deck('rm.dat', lines, deck, err)
        if (allocated(err)) return
        deck%stem = 'rm'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_OK, 'the moment test case did not solve')
        if (allocated(err)) return
        call report_numbers(dir//'/rm.txt', 'the same about x = 0 on the base z = h/2', base, err)
        if (allocated(err)) return
        call check_close(err, base(2), 580.0_dp, 1.0e-12_dp, 0.0_dp, 'load moment about the base')
        if (allocated(err)) return
        call check_close(err, base(1), 580.0_dp, 1.0e-8_dp, 0.0_dp, 'reaction moment, base')
        if (allocated(err)) return
        call moment_jumps(dir//'/rm.csv', [0.0_dp, 2.5_dp], jump, w_ends, err)
        if (allocated(err)) return
        call check_close(err, jump(1), -40.0_dp, 1.0e-4_dp, 0.0_dp, 'M jump at the F_x load')
        if (allocated(err)) return
        call check_close(err, jump(2), -500.0_dp, 1.0e-4_dp, 0.0_dp, 'M jump at the MOMENT')
        if (allocated(err)) return
        call check(err, w_ends(2) > w_ends(1), 'a positive MOMENT did not press the +x end down')
    end subroutine test_moment_conventions

    !> The two numbers after `label` on its line of a report.
    subroutine report_numbers(path, label, values, err)
        character(len=*), intent(in) :: path, label
        real(dp), intent(out) :: values(2)
        type(error_t), allocatable, intent(out) :: err
        character(len=400) :: line
        integer :: u, ios, k
        values = 0.0_dp
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'cannot open '//path)
        if (allocated(err)) return
        k = 0
        find: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit find
            k = index(line, label)
            if (k > 0) exit find
        end do find
        close (u)
        call check(err, k > 0, 'no line "'//label//'" in '//path)
        if (allocated(err)) return
        read (line(k + len(label):), *, iostat=ios) values
        call check(err, ios == 0, 'unreadable numbers: '//trim(line))
    end subroutine report_numbers

    !> From a physical beam CSV: M after minus M before each position in at (each a station
    !! listed twice, before and after the jump), and w at both ends.
    subroutine moment_jumps(path, at, jump, w_ends, err)
        character(len=*), intent(in) :: path
        real(dp), intent(in) :: at(:)
        real(dp), intent(out) :: jump(size(at)), w_ends(2)
        type(error_t), allocatable, intent(out) :: err
        character(len=600) :: line
        real(dp) :: row(13)
        integer :: u, ios, k, seen(size(at))
        integer, parameter :: c_x = 1, c_w = 3, c_m = 13   ! x, w, M in the beam CSV
        jump = 0.0_dp
        w_ends = 0.0_dp
        seen = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'cannot open '//path)
        if (allocated(err)) return
        read (u, '(a)', iostat=ios) line      ! the stamp line '# fricon ...'
        read (u, '(a)', iostat=ios) line
        call check(err, index(line, 'M [kN.m]') > 0 .and. index(line, 'w [mm]') > 0, &
                   'CSV header: '//trim(line))
        if (allocated(err)) return
        rows: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit rows
            read (line, *) row
            do k = 1, size(at)
                if (abs(row(c_x) - at(k)) > 1.0e-9_dp) cycle
                seen(k) = seen(k) + 1
                jump(k) = jump(k) + merge(-row(c_m), row(c_m), seen(k) == 1)
            end do
            w_ends(2) = row(c_w)
            if (row(c_x) <= -5.0_dp + 1.0e-9_dp) w_ends(1) = row(c_w)
        end do rows
        close (u)
        call check(err, all(seen == 2), 'each position must be listed twice')
    end subroutine moment_jumps

    !> run_analysis validates every case before it solves any: a sweep whose second case puts
    !! its load off the beam (L = 6 m with a POINT load at x = 4 m, |x| <= 3 m) gives status 1
    !! and an empty output directory, not even case 1 is written. parse_deck refuses such a
    !! deck already (tested in deck_reader), so the test parses SWEEP L 10 8 and then sets the
    !! second value to 6: a deck the parser would not produce, reaching the driver's own check.
    subroutine test_input_error(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, n_files, u, ios
        character(len=80), allocatable :: lines(:)
        call clean_dir()
        lines = [character(len=80) :: card('MODEL', ['BEAM']), card('UNITS', ['kN', 'm ']), &
                 card('GEOMETRY', ['10.0', '0.8 ', '1.0 '// &
                     '']), card('STRUCTURE', ['3.0E7', '0.2  ']), &
                 card('SOIL', ['3.0E4', '0.3  ']), card('FRICTION', ['0.5']), &
                 card('LOAD', ['POINT ', '1000.0', '      ', '4.0   ']), &
                 card('SWEEP', ['L   ', '10.0', '8.0 ']), card('END', [' '])]
        call parse_deck('bad.dat', lines, deck, err)
        if (allocated(err)) then
            err%message = 'the valid sweep deck was refused by parse_deck: '//err%message
            return
        end if
        deck%sweeps(1)%values(2) = 6.0_dp
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_INPUT, 'a load off the beam in case 2 was not an input '// &
            'error')
        if (allocated(err)) return
        call execute_command_line('ls -A '//dir//' | wc -l > build/test_count.txt')
        open (newunit=u, file='build/test_count.txt', status='old', action='read')
        read (u, *, iostat=ios) n_files
        close (u)
        call check(err, ios == 0 .and. n_files == 0, 'output written for a bad deck')
    end subroutine test_input_error

    !> Sliding (H > f V): status 2, report with the banner, no data file or figure.
    subroutine test_failed_case(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u, ios
        character(len=200) :: line
        logical :: banner
        call clean_dir()
        call parse_deck('slide.dat', [character(len=80) :: 'TITLE     sliding beam', &
            card('MODEL', ['BEAM']), card('NONDIM', ['0.01 '// &
                '', '0.1  ', '0.3  ', '0.1  ', '0.05 ']), &
            card('FRICTION', ['0.3']), card('LOAD', ['POINT', '1.0  ', '0.5  ', '0.0  ']), &
            card('END', [' '])], deck, err)
        if (allocated(err)) return
        deck%stem = 'slide'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_ANALYSIS, 'sliding case did not end with status 2')
        if (allocated(err)) return
        call check(err, exists(dir//'/slide.txt') .and. .not. exists(dir//'/slide.dat') .and. &
                   .not. exists(dir//'/slide.png'), 'failed case: wrong set of files')
        if (allocated(err)) return
        banner = .false.
        open (newunit=u, file=dir//'/slide.txt', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'ANALYSIS FAILED') > 0) banner = .true.
        end do
        close (u)
        call check(err, banner, 'failed report lacks the ANALYSIS FAILED banner')
    end subroutine test_failed_case

    !> SWEEP F 0.0 0.5 x SWEEP RHO: 4 cases, 4 reports and a summary with 4 rows.
    subroutine test_sweep(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u, ios, n
        character(len=400) :: line
        call clean_dir()
        call parse_deck('sw.dat', plate_deck(' ', [card('SWEEP', ['F  ', '0.0', '0.5']), &
                                                   card('SWEEP', ['RHO ', '0.01', '1.0 '])]), &
                        deck, err)
        if (allocated(err)) return
        deck%stem = 'sw'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_OK .and. exists(dir//'/sw_004.txt') .and. &
                   exists(dir//'/sw_summary.csv'), 'sweep outputs missing')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/sw_summary.csv', status='old', action='read')
        n = 0
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            n = n + 1
        end do
        close (u)
        call check(err, n == 6, 'summary should have a stamp line, a header and 4 rows')
    end subroutine test_sweep

    !> A sweep ready to plot (SWEEP F 0.0 0.5 x SWEEP RHO 0.01 1.0, last fastest: case 2 is
    !! F = 0.0, RHO = 1.0, the deck's values): the summary has a column per swept parameter
    !! holding numbers; each console line names its case's values; the response script
    !! plots column 3 (F) with one curve per RHO value, and its key columns are the key
    !! results' columns of the summary header; the overlay's clip markers are drawn in the
    !! red its title names.
    subroutine test_sweep_ready_to_plot(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u, log_unit, ios
        character(len=2000) :: header, row, line
        character(len=:), allocatable :: field(:)
        real(dp) :: f, rho
        call clean_dir()
        call parse_deck('sw.dat', plate_deck(' ', [card('SWEEP', ['F  ', '0.0', '0.5']), &
                                                   card('SWEEP', ['RHO ', '0.01', '1.0 '])]), &
                        deck, err)
        if (allocated(err)) return
        deck%stem = 'sw'
        open (newunit=log_unit, file=dir//'/console.log', status='replace', action='readwrite')
        call run_analysis(deck, dir, log_unit, error_unit, status)
        rewind (log_unit)
        find: do
            read (log_unit, '(a)', iostat=ios) line
            if (ios /= 0 .or. index(line, 'sw_002') == 1) exit find
        end do find
        close (log_unit, status='delete')
        call check(err, status == EXIT_OK .and. index(line, 'sw_002 [F=0.0 RHO=1.0]: solved') &
                   == 1, 'console line of case 2: '//trim(line))
        if (allocated(err)) return
        open (newunit=u, file=dir//'/sw_summary.csv', status='old', action='read')
        read (u, '(a)') header
        call check(err, index(header, '# fricon ') == 1, 'summary stamp line: '//trim(header))
        if (allocated(err)) return
        read (u, '(a)') header
        read (u, '(a)') row
        read (u, '(a)') row
        close (u)
        call check(err, index(header, 'case,parameters,F,RHO,status,') == 1, &
                   'summary header: '//trim(header))
        if (allocated(err)) return
        field = csv_fields(row)
        read (field(3), *, iostat=ios) f
        if (ios == 0) read (field(4), *, iostat=ios) rho
        call check(err, ios == 0, 'swept columns not numbers: '//trim(row))
        if (allocated(err)) return
        call check(err, f == 0.0_dp .and. rho == 1.0_dp, 'swept values of case 2: '//trim(row))
        if (allocated(err)) return
        call check_response_script(dir//'/sw_response.gp', csv_fields(header), err)
        if (allocated(err)) return
        call check(err, exists(dir//'/sw_response.png') .or. .not. exists(dir//'/sw_sweep.png'), &
                   'response figure not drawn where the overlay was')
        if (allocated(err)) return
        call check_clip_markers(err)
    end subroutine test_sweep_ready_to_plot

    !> The response script's settings: x_col = 3, two curves RHO=0.01 and RHO=1.0, every
    !! key column a key result of the summary header (not a position _x, not a count).
    subroutine check_response_script(path, header, err)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: header(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=400) :: line
        integer :: u, ios, col, n_cols, at
        logical :: x3, groups
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'no response script '//path)
        if (allocated(err)) return
        x3 = .false.
        groups = .false.
        n_cols = 0
        lines: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit lines
            x3 = x3 .or. trim(line) == 'x_col = 3'
            groups = groups .or. trim(line) == "group_title[2] = 'RHO=1.0'"
            if (index(line, 'key_col[') /= 1) cycle lines
            at = index(line, '=')
            read (line(at + 1:), *) col
            n_cols = n_cols + 1
            call check(err, col > 8 .and. col <= size(header), 'key column '//trim(line))
            if (allocated(err)) exit lines
            call check(err, index(header(col), '_x') == 0 .and. &
                       index(header(col), 'linear_solves') == 0, 'key column '//trim(line)// &
                       ' is '//trim(header(col)))
            if (allocated(err)) exit lines
        end do lines
        close (u)
        if (allocated(err)) return
        call check(err, x3 .and. groups .and. n_cols > 3, 'response settings: x_col 3 '// &
                   'and the RHO curves, more than three keys')
    end subroutine check_response_script

    !> The overlay template's clip markers are red ('#c00000'), as its title says.
    subroutine check_clip_markers(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=400), allocatable :: lines(:)
        integer :: i
        logical :: named, red
        lines = sweep_template()
        named = .false.
        red = .false.
        do i = 1, size(lines)
            named = named .or. index(lines(i), 'red triangles') > 0
            if (index(lines(i), '? p_clip : 1/0) w p pt 9') > 0) &
                red = index(lines(i), "lc rgb '#c00000'") > 0
        end do
        call check(err, named .and. red, 'sweep overlay: clip markers not drawn red')
    end subroutine check_clip_markers

    !> The comma-separated fields of a CSV line (no field holds a comma).
    function csv_fields(line) result(field)
        character(len=*), intent(in) :: line
        character(len=:), allocatable :: field(:)
        integer :: i, start, n
        n = count([(line(i:i) == ',', i=1, len_trim(line))]) + 1
        allocate (character(len=len_trim(line)) :: field(n))
        start = 1
        n = 0
        do i = 1, len_trim(line) + 1
            if (i <= len_trim(line)) then
                if (line(i:i) /= ',') cycle
            end if
            n = n + 1
            field(n) = line(start:i - 1)
            start = i + 1
        end do
    end function csv_fields
    !> A beam sweep whose first case slides (F = 0 with H = 0.3 V) and whose second solves
    !! (F = 0.5): the run ends with status 2, the summary has both rows, the failed one with
    !! its message and empty result fields (not zeros), the solved one with numbers (the
    !! hard-case atlas crashed here when the first case had no results).
    subroutine test_sweep_first_fails(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: status, u, ios
        character(len=2000) :: header, row1, row2
        call clean_dir()
        call parse_deck('sb.dat', [character(len=80) :: card('MODEL', ['BEAM']), &
                 card('NONDIM', ['0.01 ', '0.1  ', '0.3  ', '0.1  ', '0.05 ']), &
                 card('FRICTION', ['0.5']), &
                 card('LOAD', [character(len=10) :: 'POINT', '1.0', '0.3', '0.0']), &
                 card('SWEEP', ['F  ', '0.0', '0.5']), card('END', [' '])], deck, err)
        if (allocated(err)) return
        deck%stem = 'sb'
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_ANALYSIS, 'a sweep with a sliding case must end with '// &
            'status 2')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/sb_summary.csv', status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'no summary for a sweep whose first case failed')
        if (allocated(err)) return
        read (u, '(a)') header      ! the stamp line
        read (u, '(a)') header
        read (u, '(a)') row1
        read (u, '(a)') row2
        close (u)
        call check(err, index(row1, ',2,') > 0 .and. index(row1, ',,') > 0 .and. &
                   index(row1, 'sliding') > 0 .and. index(row2, ',0,') > 0 .and. &
                   index(row2, 'E') > 0, 'summary rows: '//trim(row1)//' / '//trim(row2))
    end subroutine test_sweep_first_fails

    !> A sweep solved on one thread, on two (OpenMP), and in two shards merged by
    !! scripts/merge_shards.sh gives byte-identical summaries and case files: a case's result
    !! does not depend on the thread or the run that solved it (README, Sweeps on all cores).
    subroutine test_parallel_sweep(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: status, k, exit_status
        character(len=*), parameter :: runs(3) = ['build/test_sweep_j1', 'build/test_sweep_j2', &
                                                  'build/test_sweep_sh']
        call execute_command_line('rm -rf build/test_sweep_j1 build/test_sweep_j2 '// &
            'build/test_sweep_sh')
        call parse_deck('sw.dat', plate_deck(' ', [card('SWEEP', ['F  ', '0.0', '0.5']), &
                                                   card('SWEEP', ['RHO ', '0.01', '1.0 '])]), &
                        deck, err)
        if (allocated(err)) return
        deck%stem = 'sw'
        opt%figures = .false.
        do k = 1, 2
            opt%threads = k
            call run_analysis(deck, runs(k), output_unit, error_unit, status, opt)
            call check(err, status == EXIT_OK, 'sweep run failed')
            if (allocated(err)) return
        end do
        opt%threads = 1
        do k = 1, 2
            opt%shard_index = k
            opt%shard_count = 2
            call run_analysis(deck, runs(3), output_unit, error_unit, status, opt)
            call check(err, status == EXIT_OK, 'shard run failed')
            if (allocated(err)) return
        end do
        ! every file of the two-thread run equals the serial one (a race in writing once
        ! corrupted JSON files), and the merged shards give the serial summary and case files
        ! (shards draw no sweep overlay and no response figure)
        call execute_command_line('bash scripts/merge_shards.sh build/test_sweep_sh/sw > '// &
            '/dev/null '// &
            '&& for f in build/test_sweep_j1/*; do b=$(basename $f); '// &
            'cmp -s $f build/test_sweep_j2/$b || exit 1; '// &
            'case $b in *_sweep.* | *_response.*) continue;; esac; '// &
            'cmp -s $f build/test_sweep_sh/$b || exit 1; done', exitstat=exit_status)
        call check(err, exit_status == 0, 'parallel or sharded sweep differs from the serial one')
    end subroutine test_parallel_sweep

    !> A single case gives the same files, byte for byte, whatever number of threads OpenBLAS
    !! was given before the run: the driver runs every case's BLAS on one thread. Otherwise a
    !! plate on N_e = 100 differs in the last printed digit of 39 data rows between one and two
    !! BLAS threads (the threaded LDL^T sums in another order; doc/CHOICES.md, One BLAS thread
    !! per case). set_blas_threads(2)
    !! gives OpenBLAS two threads even on one core, so the test tells on any machine.
    subroutine test_blas_threads(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: status, k, exit_status, blas_before
        character(len=*), parameter :: runs(2) = ['build/test_blas_1', 'build/test_blas_2']
        character(len=80), allocatable :: lines(:)
        call execute_command_line('rm -rf '//runs(1)//' '//runs(2))
        lines = plate_deck(' ', [character(len=80) ::])
        where (lines(:)(1:4) == 'MESH') lines = card('MESH', ['100'])
        call parse_deck('bt.dat', lines, deck, err)
        if (allocated(err)) return
        deck%stem = 'bt'
        opt%figures = .false.
        blas_before = blas_thread_count()
        do k = 1, 2
            call set_blas_threads(merge(1, max(2, blas_before), k == 1))
            call run_analysis(deck, runs(k), output_unit, error_unit, status, opt)
            call check(err, status == EXIT_OK, 'plate case on N_e = 100 did not solve')
            if (allocated(err)) exit
        end do
        call set_blas_threads(blas_before)
        if (allocated(err)) return
        ! every file the case wrote (report, data, summary, figure script)
        call execute_command_line('for f in '//runs(1)//'/*; do cmp -s $f '//runs(2)// &
                                  '/$(basename $f) || exit 1; done', exitstat=exit_status)
        call check(err, exit_status == 0, 'the case''s files depend on the BLAS thread count')
    end subroutine test_blas_threads

    !> The JSON design summary of a case whose TITLE holds a double quote and a backslash is
    !! valid JSON and gives the title back: read by Python's json module (an independent
    !! parser; Python is on the CI machine, which installs fpm with pip).
    subroutine test_json_title(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: status, exit_status, u, ios
        character(len=*), parameter :: title = 'report "test" with a \ backslash'
        character(len=200) :: line
        character(len=80), allocatable :: lines(:)
        call clean_dir()
        lines = plate_deck(' ', [character(len=80) ::])
        lines(1) = 'TITLE     '//title
        call parse_deck('js.dat', lines, deck, err)
        if (allocated(err)) return
        deck%stem = 'js'
        opt%figures = .false.
        call run_analysis(deck, dir, output_unit, error_unit, status, opt)
        call check(err, status == EXIT_OK, 'the case did not solve')
        if (allocated(err)) return
        call execute_command_line('python3 -c "import json, sys; '// &
            'print(json.load(open(sys.argv[1]))[''title''])" '//dir//'/js.json > '// &
            dir//'/js_title.txt', exitstat=exit_status)
        call check(err, exit_status == 0, 'js.json is not valid JSON (Python''s json module)')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/js_title.txt', status='old', action='read', iostat=ios)
        if (ios == 0) read (u, '(a)', iostat=ios) line
        if (ios == 0) close (u)
        call check(err, ios == 0 .and. trim(line) == title, &
                   'title from the JSON: '//trim(line)//' (expected '//title//')')
    end subroutine test_json_title

    !> The gnuplot templates embedded in the program (src/output/figure_templates.f90) are the
    !! files scripts/gnuplot/*.gp line for line: after editing a template, run
    !! scripts/embed_templates.sh.
    subroutine test_templates(err)
        type(error_t), allocatable, intent(out) :: err
        call compare_file('scripts/gnuplot/fricon_panels.gp', panel_template(), err)
        if (allocated(err)) return
        call compare_file('scripts/gnuplot/fricon_sweep.gp', sweep_template(), err)
        if (allocated(err)) return
        call compare_file('scripts/gnuplot/fricon_ground.gp', ground_template(), err)
    end subroutine test_templates

    subroutine compare_file(path, lines, err)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: lines(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=1000) :: line
        integer :: u, ios, n
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'cannot open '//path)
        if (allocated(err)) return
        n = 0
        lines_loop: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit lines_loop
            n = n + 1
            if (n > size(lines)) exit lines_loop
            if (trim(line) /= trim(lines(n))) exit lines_loop
        end do lines_loop
        close (u)
        call check(err, ios /= 0 .and. n == size(lines), path//' differs from the embedded '// &
                   'template at line '//trim(int_text(n))//': run scripts/embed_templates.sh')
    end subroutine compare_file

end module test_report_writer
