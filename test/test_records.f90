!> The records of a run an engineer files: the SHA-256 of the deck against FIPS 180's test
!! vectors, every traceability field of the JSON summary (deck, deck_identity, deck_sha256,
!! deck_text, inputs), no machine path in any output, the merge of a sweep's shards and the
!! width of the reports.
module test_records
    use iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_OK
    use sha256, only: sha256_hex
    use deck_reader, only: deck_t, read_deck
    use output_paths, only: canonical_path
    use analysis_driver, only: run_analysis, run_options_t
    use shard_merge, only: merge_shards, run_merge
    use report_folding, only: fold_table, report_width
    use text_files, only: read_lines
    implicit none
    private

    public :: collect_records

    character(len=*), parameter :: dir = 'build/test_records'

contains

    subroutine collect_records(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('sha256_fips_vectors', test_sha256), &
                 new_unittest('json_deck_name_only', test_deck_name), &
                 new_unittest('json_deck_sha256', test_deck_sha256), &
                 new_unittest('json_deck_text', test_deck_text), &
                 new_unittest('json_deck_identity', test_deck_identity), &
                 new_unittest('json_inputs', test_inputs), &
                 new_unittest('json_inputs_layered', test_inputs_layered), &
                 new_unittest('no_machine_path_in_outputs', test_no_machine_path), &
                 new_unittest('merge_equals_serial', test_merge_serial), &
                 new_unittest('merge_refusals', test_merge_refusals), &
                 new_unittest('fold_table_groups', test_fold_table), &
                 new_unittest('reports_of_input_decks_fit_132', test_report_width)]
    end subroutine collect_records

    !> FIPS 180-2 appendix B (and the NIST example values): SHA-256 of "abc" (B.1), of the
    !! 448-bit message "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq" (B.2, two
    !! blocks after padding), of one million 'a' (B.3), and of the empty message.
    subroutine test_sha256(err)
        type(error_t), allocatable, intent(out) :: err
        call check(err, sha256_hex('abc') == &
                   'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad', &
                   'SHA-256("abc"): '//sha256_hex('abc'))
        if (allocated(err)) return
        call check(err, sha256_hex('abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq') &
                   == '248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1', &
                   'SHA-256 of the 448-bit message')
        if (allocated(err)) return
        call check(err, sha256_hex(repeat('a', 1000000)) == &
                   'cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0', &
                   'SHA-256 of one million a')
        if (allocated(err)) return
        call check(err, sha256_hex('') == &
                   'e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855', &
                   'SHA-256 of the empty message')
    end subroutine test_sha256

    !> A beam deck in kN and m (two SWEEP values of F when sweep is true).
    function beam_lines(sweep) result(lines)
        logical, intent(in) :: sweep
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: '* a beam "quoted" \ backslash', &
                 'TITLE     records test', &
                 'MODEL     BEAM', 'UNITS     kN        m', &
                 'GEOMETRY  10.0      0.8       1.2', 'STRUCTURE 3.0E7     0.2', &
                 'SOIL      3.0E4     0.3', 'FRICTION  0.5', &
                 'LOAD      POINT     1000.0    50.0      1.5', &
                 'LOAD      PATCH     600.0               -4.0      -2.0', 'MESH      16']
        if (sweep) lines = [character(len=80) :: lines, 'SWEEP     F         0.2       0.6']
        lines = [character(len=80) :: lines, 'END']
    end function beam_lines

    !> Write lines to path (made with its folder).
    subroutine write_deck(path, lines)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: lines(:)
        integer :: u, k
        call execute_command_line('mkdir -p "$(dirname '//path//')"')
        open (newunit=u, file=path, status='replace', action='write')
        do k = 1, size(lines)
            write (u, '(a)') trim(lines(k))
        end do
        close (u)
    end subroutine write_deck

    !> Read the deck file at path and run it into out (no figures: faster; shard I of N).
    subroutine run_deck_file(path, out, status, err, figures, shard)
        character(len=*), intent(in) :: path, out
        integer, intent(out) :: status
        type(error_t), allocatable, intent(out) :: err
        logical, intent(in), optional :: figures
        integer, intent(in), optional :: shard(2)
        type(deck_t) :: deck
        type(run_options_t) :: opt
        opt%figures = .false.
        if (present(figures)) opt%figures = figures
        if (present(shard)) then
            opt%shard_index = shard(1)
            opt%shard_count = shard(2)
        end if
        opt%estimates = .false.
        status = -1
        call read_deck(path, deck, err)
        if (allocated(err)) return
        call run_analysis(deck, out, output_unit, error_unit, status, opt)
    end subroutine run_deck_file

    !> The value of a JSON line '  "key": value,' of the file (its first such line).
    function json_value(path, key) result(text)
        character(len=*), intent(in) :: path, key
        character(len=:), allocatable :: text
        character(len=20000) :: line
        integer :: u, ios, k
        text = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            k = index(line, '  "'//key//'": ')
            if (k /= 1) cycle
            text = trim(line(len(key) + 7:))
            if (text(len(text):) == ',') text = text(1:len(text) - 1)
            exit
        end do
        close (u)
    end function json_value

    !> The first line of a file ('' if none).
    function first_line(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        character(len=2000) :: line
        integer :: u, ios
        text = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (u, '(a)', iostat=ios) line
        if (ios == 0) text = trim(line)
        close (u)
    end function first_line

    !> The JSON's "deck" is the deck's file name, whatever path the deck was given by (an
    !! absolute one here), and the report names it so too.
    subroutine test_deck_name(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        character(len=:), allocatable :: deck_abs
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/decks/nm.dat', beam_lines(.false.))
        deck_abs = canonical_path(dir//'/decks/nm.dat')
        call run_deck_file(deck_abs, dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. deck_abs(1:1) == '/', 'the deck did not run')
        if (allocated(err)) return
        call check(err, json_value(dir//'/out/nm.json', 'deck') == '"nm.dat"', &
                   '"deck" is '//json_value(dir//'/out/nm.json', 'deck'))
        if (allocated(err)) return
        call check(err, report_names(dir//'/out/nm.txt', ' deck: nm.dat    case:'), &
                   'the report does not name the deck by its file name')
    end subroutine test_deck_name

    logical function report_names(path, start)
        character(len=*), intent(in) :: path, start
        character(len=2000) :: line
        integer :: u, ios
        report_names = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, start) == 1) report_names = .true.
        end do
        close (u)
    end function report_names

    !> "deck_sha256" is the SHA-256 of the deck file's bytes as `sha256sum` computes it (an
    !! independent program; the deck has no trailing blanks).
    subroutine test_deck_sha256(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        character(len=:), allocatable :: expected
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/h.dat', beam_lines(.false.))
        call execute_command_line('sha256sum '//dir//'/h.dat | cut -c1-64 > '//dir//'/h.sum')
        expected = first_line(dir//'/h.sum')
        call run_deck_file(dir//'/h.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. len(expected) == 64, 'no run or no sha256sum')
        if (allocated(err)) return
        call check(err, json_value(dir//'/out/h.json', 'deck_sha256') == '"'//expected//'"', &
                   'deck_sha256 '//json_value(dir//'/out/h.json', 'deck_sha256')// &
                   ', sha256sum '//expected)
    end subroutine test_deck_sha256

    !> "deck_text" is the deck file's text: Python's json module (an independent parser)
    !! reads the JSON and writes the string out; it equals the file byte for byte (quotes
    !! and a backslash in the deck's comment line escaped and restored).
    subroutine test_deck_text(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status, code
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/t.dat', beam_lines(.false.))
        call run_deck_file(dir//'/t.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK, 'the deck did not run')
        if (allocated(err)) return
        call execute_command_line('python3 -c "import json,sys; sys.stdout.write(json.load('// &
            'open(''' //dir//'/out/t.json''))[''deck_text''])" > '//dir//'/t.text && cmp -s '// &
            dir//'/t.text '//dir//'/t.dat', exitstat=code)
        call check(err, code == 0, 'deck_text is not the deck file''s text')
    end subroutine test_deck_text

    !> "deck_identity" is 'sha256:' and the SHA-256 of the deck's canonical path (realpath
    !! and sha256sum compute it here), and it keeps decks apart: a sweep of d1/s.dat (s_001,
    !! s_002) and then a one-case d2/s.dat in the same output folder leave s_001.* and
    !! s_002.* (d1's, not d2's to remove), while d1/s.dat run again as one case removes them.
    subroutine test_deck_identity(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        character(len=:), allocatable :: expected
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/d1/s.dat', beam_lines(.true.))
        call write_deck(dir//'/d2/s.dat', beam_lines(.false.))
        call execute_command_line('printf %s "$(realpath '//dir//'/d1/s.dat)" | sha256sum | '// &
                                  'cut -c1-64 > '//dir//'/id.sum')
        expected = first_line(dir//'/id.sum')
        call run_deck_file(dir//'/d1/s.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. json_value(dir//'/out/s_001.json', &
                   'deck_identity') == '"sha256:'//expected//'"', 'deck_identity '// &
                   json_value(dir//'/out/s_001.json', 'deck_identity')//', expected sha256:'// &
                   expected)
        if (allocated(err)) return
        call run_deck_file(dir//'/d2/s.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. exists(dir//'/out/s.json') .and. &
                   exists(dir//'/out/s_001.json') .and. exists(dir//'/out/s_002.txt') .and. &
                   exists(dir//'/out/s_summary.csv'), 'another deck of the same name removed '// &
                   'the sweep''s files')
        if (allocated(err)) return
        call write_deck(dir//'/d1/s.dat', beam_lines(.false.))
        call run_deck_file(dir//'/d1/s.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. .not. exists(dir//'/out/s_001.json') .and. &
                   .not. exists(dir//'/out/s_002.txt') .and. .not. &
                   exists(dir//'/out/s_summary.csv'), 'the deck''s own stale sweep was left')
    end subroutine test_deck_identity

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    !> "inputs": every value of the case's model after defaults, with units, read by Python's
    !! json module. Expected values from the deck (beam_lines) and README's defaults: k = 5/6,
    !! eps_bar 1E-6, N_e 16, P1 everywhere, NEWTON; case 2 of the sweep has f = 0.6; the
    !! PATCH's x2 = -2 m, the POINT's none (null); E in kPa, loads in kN and m.
    subroutine test_inputs(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status, code
        real(dp) :: v(9)
        character(len=200) :: words
        integer :: u, ios
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/i.dat', beam_lines(.true.))
        call run_deck_file(dir//'/i.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK, 'the deck did not run')
        if (allocated(err)) return
        call execute_command_line('python3 -c "import json; i = json.load(open('''//dir// &
            '/out/i_002.json''))[''inputs'']; s = i[''structure'']; l = i[''loads'']; '// &
            'print(s[''length_or_radius''], s[''modulus''], s[''shear_factor''], '// &
            'i[''ground''][''modulus''], i[''interface''][''friction''], '// &
            'i[''interface''][''eps_bar''], l[0][''f_x''], l[1][''x2''], '// &
            'i[''mesh''][''elements'']); print(s[''units''][''modulus''], '// &
            'l[0][''units''][''f_z''], l[0][''x2''], i[''mesh''][''interpolation''][''w''], '// &
            'i[''solver''][''method''], i[''units''][''settlement_shown_in''])" > '// &
            dir//'/inputs.txt', exitstat=code)
        call check(err, code == 0, 'python could not read the inputs')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/inputs.txt', status='old', action='read')
        read (u, *, iostat=ios) v
        if (ios == 0) read (u, '(a)', iostat=ios) words
        close (u)
        call check(err, ios == 0, 'the inputs could not be read back')
        if (allocated(err)) return
        call check(err, all(abs(v - [10.0_dp, 3.0e7_dp, 5.0_dp/6.0_dp, 3.0e4_dp, 0.6_dp, &
                   1.0e-6_dp, 50.0_dp, -2.0_dp, 16.0_dp]) <= 1.0e-12_dp*abs(v)), &
                   'input values differ from the deck''s')
        if (allocated(err)) return
        call check(err, trim(words) == 'kPa kN None P1 NEWTON mm', 'units and words: '// &
                   trim(words))
    end subroutine test_inputs

    !> "inputs" of a layered ground, input/strip_crust.dat: its LAYER cards (1.5 m of 40 MPa,
    !! nu 0.3, over 6 m of 5 MPa, nu 0.4, each E constant: bottom = top) on a ROUGH base
    !! (no base modulus: null), moduli in kPa (kN and m).
    subroutine test_inputs_layered(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status, code, u, ios
        real(dp) :: v(8)
        character(len=200) :: words
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call run_deck_file('input/strip_crust.dat', dir//'/out', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK, 'strip_crust did not run')
        if (allocated(err)) return
        call execute_command_line('python3 -c "import json; g = json.load(open('''//dir// &
            '/out/strip_crust.json''))[''inputs''][''ground'']; l = g[''layers'']; '// &
            'print(*[x[k] for x in l for k in (''thickness'', ''modulus_top'', '// &
            '''modulus_bottom'', ''poisson'')]); print(g[''kind''], g[''base''], '// &
            'g[''base_modulus''], g[''units''][''modulus''], len(l))" > '//dir//'/g.txt', &
            exitstat=code)
        call check(err, code == 0, 'python could not read the ground')
        if (allocated(err)) return
        open (newunit=u, file=dir//'/g.txt', status='old', action='read')
        read (u, *, iostat=ios) v
        if (ios == 0) read (u, '(a)', iostat=ios) words
        close (u)
        call check(err, ios == 0, 'the ground could not be read back')
        if (allocated(err)) return
        call check(err, all(abs(v - [1.5_dp, 40.0e3_dp, 40.0e3_dp, 0.3_dp, 6.0_dp, 5.0e3_dp, &
                   5.0e3_dp, 0.4_dp]) <= 1.0e-12_dp*abs(v)) .and. trim(words) == &
                   'layered ROUGH None kPa 2', 'layers differ from the deck''s: '//trim(words))
    end subroutine test_inputs_layered

    !> No output file holds a machine path: a deck given by its absolute path, with its
    !! figure, writes no byte of the working folder's canonical path (the report, CSV, JSON,
    !! .gp script, .dat header and PNG all searched).
    subroutine test_no_machine_path(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status, code
        character(len=:), allocatable :: here
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/p.dat', beam_lines(.true.))
        here = canonical_path('.')
        call run_deck_file(canonical_path(dir//'/p.dat'), canonical_path(dir)//'/out', status, &
                           err, figures=.true.)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. exists(dir//'/out/p_001.gp') .and. &
                   exists(dir//'/out/p_summary.csv'), 'the deck did not run')
        if (allocated(err)) return
        call execute_command_line('! grep -rlF "'//here//'" '//dir//'/out', exitstat=code)
        call check(err, code == 0, 'an output holds the path '//here)
    end subroutine test_no_machine_path
    !> A three-case sweep (f = 0.2, 0.4, 0.6) run in two shards (cases 1 and 3, case 2)
    !! and merged gives the serial run's summary CSV and response script byte for byte (one
    !! process: one run time), the figure drawn from them; the merge reads the shards in any
    !! order.
    subroutine test_merge_serial(err)
        type(error_t), allocatable, intent(out) :: err
        integer :: status, code
        character(len=:), allocatable :: merged
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/sw.dat', three_cases())
        call run_deck_file(dir//'/sw.dat', dir//'/serial', status, err)
        if (allocated(err)) return
        call check(err, status == EXIT_OK .and. exists(dir//'/serial/sw_response.gp'), &
                   'the serial sweep did not run')
        if (allocated(err)) return
        call run_shards(dir//'/sw.dat', dir//'/shards', err)
        if (allocated(err)) return
        call check(err, .not. exists(dir//'/shards/sw_summary.csv'), 'a shard wrote the summary')
        if (allocated(err)) return
        call merge_shards([character(len=80) :: dir//'/shards/sw_summary.shard-2-of-2.csv', &
                           dir//'/shards/sw_summary.shard-1-of-2.csv'], '', .true., merged, err)
        if (allocated(err)) return
        call execute_command_line('cmp -s '//dir//'/serial/sw_summary.csv '//merged// &
            ' && cmp -s '//dir//'/serial/sw_response.gp '//dir//'/shards/sw_response.gp', &
            exitstat=code)
        call check(err, code == 0 .and. merged == dir//'/shards/sw_summary.csv', &
                   'the merged summary or response script differs from the serial run''s')
        if (allocated(err)) return
        call check(err, exists(dir//'/shards/sw_response.png') .or. .not. has_gnuplot(), &
                   'no response figure after the merge')
    end subroutine test_merge_serial

    logical function has_gnuplot()
        integer :: code
        call execute_command_line('command -v gnuplot > /dev/null', exitstat=code)
        has_gnuplot = code == 0
    end function has_gnuplot

    function three_cases() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = beam_lines(.false.)
        lines(size(lines)) = 'SWEEP     F         0.2       0.4       0.6'
        lines = [character(len=80) :: lines, 'END']
    end function three_cases

    !> The two shards of the deck at path into out.
    subroutine run_shards(path, out, err)
        character(len=*), intent(in) :: path, out
        type(error_t), allocatable, intent(out) :: err
        integer :: status, i
        do i = 1, 2
            call run_deck_file(path, out, status, err, shard=[i, 2])
            if (allocated(err)) return
            call check(err, status == EXIT_OK .and. exists(out//'/sw_summary.shard-'// &
                       achar(48 + i)//'-of-2.csv'), 'shard did not run')
            if (allocated(err)) return
        end do
    end subroutine run_shards

    !> Bad shards are refused with a message naming the fault, exit status 1, and nothing
    !! written (no summary, no response script or figure): shard 2 of 2 missing; a shard 2
    !! of another deck (f = 0.2, 0.5, 0.6: another deck_sha256); overlapping shards (a file
    !! named shard 2 holding shard 1's cases); a shard given twice; a file that is no shard.
    subroutine test_merge_refusals(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: sh = dir//'/a/sw_summary.shard-'
        character(len=80), allocatable :: other(:)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call write_deck(dir//'/sw.dat', three_cases())
        call run_shards(dir//'/sw.dat', dir//'/a', err)
        if (allocated(err)) return
        other = three_cases()
        other(size(other) - 1) = 'SWEEP     F         0.2       0.5       0.6'
        call write_deck(dir//'/o/sw.dat', other)
        call run_shards(dir//'/o/sw.dat', dir//'/b', err)
        if (allocated(err)) return
        call expect_refusal([character(len=80) :: sh//'1-of-2.csv'], 'missing', err)
        if (allocated(err)) return
        call expect_refusal([character(len=80) :: sh//'1-of-2.csv', &
                            dir//'/b/sw_summary.shard-2-of-2.csv'], 'different decks', err)
        if (allocated(err)) return
        call execute_command_line('mkdir -p '//dir//'/c && cp '//dir//'/a/sw_* '//dir// &
            '/c/ && cp '//dir//'/c/sw_summary.shard-1-of-2.csv '//dir// &
            '/c/sw_summary.shard-2-of-2.csv')
        call expect_refusal([character(len=80) :: dir//'/c/sw_summary.shard-1-of-2.csv', &
                            dir//'/c/sw_summary.shard-2-of-2.csv'], 'overlapping', err)
        if (allocated(err)) return
        call expect_refusal([character(len=80) :: sh//'1-of-2.csv', sh//'1-of-2.csv'], &
                            'given twice', err)
        if (allocated(err)) return
        call expect_refusal([character(len=80) :: dir//'/sw.dat'], 'not a shard summary', err)
    end subroutine test_merge_refusals

    !> The merge of shards is refused with a message holding `words` and status 1, and no
    !! merged file is left in their folder.
    subroutine expect_refusal(shards, words, err)
        character(len=*), intent(in) :: shards(:), words
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: refusal
        character(len=:), allocatable :: merged, folder
        integer :: status
        folder = shards(1)(1:index(shards(1), '/', back=.true.) - 1)
        call merge_shards(shards, '', .true., merged, refusal)
        call check(err, allocated(refusal), 'refused nothing ('//words//')')
        if (allocated(err)) return
        call check(err, index(refusal%message, words) > 0, 'the refusal does not say '// &
                   words//': '//refusal%message)
        if (allocated(err)) return
        call run_merge(shards, '', .false., .true., status)
        call check(err, status == 1 .and. .not. exists(folder//'/sw_summary.csv') .and. &
                   .not. exists(folder//'/sw_response.gp') .and. .not. &
                   exists(folder//'/sw_response.png'), 'exit status not 1, or a file written ('// &
                   words//')')
    end subroutine expect_refusal
    !> A table of 18 columns of 13 characters (234 wide: the x column and 17 more), one
    !! header line and two rows, the second flagged ' !T': folded into two groups (9 and 8
    !! columns after x: 13 + 9 x 13 + 3 = 133 does not fit, 13 + 8 x 13 + 3 fits, balanced
    !! over ceil(17/8) = 3 groups of 6, 6 and 5), each line at most 132 wide, every cell
    !! once, the x cell in every group, the flag once, at the end of the first group's
    !! second row.
    subroutine test_fold_table(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=18*13 + 3) :: lines(3)
        character(len=:), allocatable :: folded(:)
        character(len=13) :: cell
        integer :: r, c, found
        do r = 1, 3
            lines(r) = ''
            do c = 1, 18
                write (cell, '(a9,i1,a1,i2.2)') 'r', r, 'c', c
                lines(r)(13*(c - 1) + 1:13*c) = cell
            end do
        end do
        lines(3) = trim(lines(3))//' !T'
        folded = fold_table(lines, 1, 13, 13, 18)
        ! 3 groups of 3 lines, and a blank and a "continued" line before groups 2 and 3
        call check(err, size(folded) == 3*3 + 2*2 .and. all(len_trim(folded) <= report_width), &
                   'folded table: not 3 groups of lines within 132 columns')
        if (allocated(err)) return
        do r = 1, 3
            do c = 1, 18
                write (cell, '(a9,i1,a1,i2.2)') 'r', r, 'c', c
                found = count(index(folded, trim(adjustl(cell))) > 0)
                call check(err, found == merge(3, 1, c == 1), 'cell '//trim(adjustl(cell))// &
                           ' not where expected')
                if (allocated(err)) return
            end do
        end do
        call check(err, count(index(folded, ' !T') > 0) == 1 .and. &
                   index(folded(3), ' !T') == len_trim(folded(3)) - 2, 'the flag is not once, '// &
                   'at the end of the first group''s flagged row')
    end subroutine test_fold_table

    !> No line of the report of any deck in input/ (its folders too) is wider than 132
    !! columns. Each deck runs the first and the last value of its first SWEEP and the first
    !! of the others (the report's layout depends on the model, not on the swept values;
    !! input/ holds failing cases too), without figures and estimates (they add no report
    !! lines wider than the solved case's).
    subroutine test_report_width(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: decks(:), reports(:), lines(:)
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: k, s, status, widest
        logical :: ok
        real(dp), allocatable :: v(:)
        opt%figures = .false.
        opt%estimates = .false.
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && find input -name '// &
                                  '"*.dat" | sort > '//dir//'/decks.txt')
        call read_lines(dir//'/decks.txt', decks, ok)
        call check(err, ok .and. size(decks) >= 20, 'the decks of input/ not found')
        if (allocated(err)) return
        do k = 1, size(decks)
            call read_deck(trim(decks(k)), deck, err)
            if (allocated(err)) return
            if (allocated(deck%sweeps)) then
                do s = 1, size(deck%sweeps)
                    v = deck%sweeps(s)%values
                    if (s == 1 .and. size(v) > 2) deck%sweeps(s)%values = [v(1), v(size(v))]
                    if (s > 1) deck%sweeps(s)%values = [v(1)]
                end do
            end if
            call run_analysis(deck, dir//'/out', output_unit, error_unit, status, opt)
        end do
        call execute_command_line('ls '//dir//'/out/*.txt > '//dir//'/reports.txt')
        call read_lines(dir//'/reports.txt', reports, ok)
        call check(err, ok .and. size(reports) >= size(decks), 'fewer reports than decks')
        if (allocated(err)) return
        do k = 1, size(reports)
            call read_lines(trim(reports(k)), lines, ok)
            widest = maxval(len_trim(lines))
            call check(err, ok .and. widest <= report_width, trim(reports(k))//': a line of '// &
                       'more than 132 columns')
            if (allocated(err)) return
        end do
    end subroutine test_report_width
end module test_records
