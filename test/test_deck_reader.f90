!> Deck reader (SPEC §8): every error path (message names the deck, the line, the column range
!! and what was expected), defaults, case-insensitivity, comments, E-notation, SWEEP expansion,
!! NONDIM completion, the example decks under input/, and fuzzing with odd lines.
module test_deck_reader
    use deck_fields, only: int_text
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_INPUT
    use model, only: model_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, LOAD_PATCH, LOAD_RING, &
                     relative_stiffness, total_vertical_load, METHOD_NEWTON, METHOD_TWOLOOP
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2
    use deck_reader, only: deck_t, read_deck, parse_deck, case_count, case_model, &
                           default_deck_lines
    use plausibility, only: input_warnings, settlement_warnings, warning_length
    implicit none
    private
    public :: collect_deck_reader, card

    integer, parameter :: w = 200                          !! width of test lines
    character(len=*), parameter :: bad = 'test/bad.dat'    !! deck name of the error tests
    character(len=*), parameter :: nl = new_line('a')

contains

    subroutine collect_deck_reader(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('default_deck', test_default_deck), &
                 new_unittest('default_file_identical', test_default_file), &
                 new_unittest('example_decks_parse', test_example_decks), &
                 new_unittest('defaults', test_defaults), &
                 new_unittest('case_insensitive', test_case_insensitive), &
                 new_unittest('comment_cards', test_comments), &
                 new_unittest('e_notation', test_e_notation), &
                 new_unittest('physical_beam', test_physical_beam), &
                 new_unittest('nondim_completion_beam', test_nondim_beam), &
                 new_unittest('nondim_completion_plate', test_nondim_plate), &
                 new_unittest('nu_f_half_is_valid', test_nu_f_half), &
                 new_unittest('sweep_expansion', test_sweep_expansion), &
                 new_unittest('sweep_case_revalidated', test_sweep_revalidated), &
                 new_unittest('sweep_length_moves_load_off', test_sweep_length), &
                 new_unittest('file_cannot_open', test_missing_file), &
                 new_unittest('file_errors_named', test_file_errors), &
                 new_unittest('unknown_card', test_unknown_card), &
                 new_unittest('unreadable_number', test_unreadable_number), &
                 new_unittest('nan_inf_rejected', test_nan_inf), &
                 new_unittest('missing_model', test_missing_model), &
                 new_unittest('nu_too_large', test_nu_large), &
                 new_unittest('h_not_positive', test_h_zero), &
                 new_unittest('ne_zero', test_ne_zero), &
                 new_unittest('load_outside_beam', test_load_outside_beam), &
                 new_unittest('load_outside_plate_nondim', test_load_outside_plate), &
                 new_unittest('patch_reversed', test_patch_reversed), &
                 new_unittest('plate_horizontal_load', test_plate_horizontal), &
                 new_unittest('plate_moment', test_plate_moment), &
                 new_unittest('plate_point_off_axis', test_plate_point_off_axis), &
                 new_unittest('ring_on_beam', test_ring_on_beam), &
                 new_unittest('plate_has_no_width', test_plate_width), &
                 new_unittest('tab_character', test_tab), &
                 new_unittest('long_card', test_long_card), &
                 new_unittest('blank_required_field', test_blank_required), &
                 new_unittest('missing_end', test_missing_end), &
                 new_unittest('card_after_end', test_after_end), &
                 new_unittest('duplicate_card', test_duplicate), &
                 new_unittest('nondim_mixed_with_physical', test_mixed), &
                 new_unittest('missing_physical_card', test_missing_soil), &
                 new_unittest('unknown_words', test_unknown_words), &
                 new_unittest('stations_below_two', test_stations), &
                 new_unittest('eps_bar_range', test_eps_bar), &
                 new_unittest('solver_method', test_solver_method), &
                 new_unittest('name_columns', test_name_columns), &
                 new_unittest('extra_fields', test_extra_fields), &
                 new_unittest('sweep_incompatible', test_sweep_incompatible), &
                 new_unittest('sweep_bad_values', test_sweep_values), &
                 new_unittest('nondim_loads_add_to_one', test_nondim_total), &
                 new_unittest('several_errors_listed', test_several_errors), &
                 new_unittest('utf8_comment_width_and_bom', test_utf8_bom), &
                 new_unittest('non_ascii_in_card', test_non_ascii_card), &
                 new_unittest('hash_comment_hint', test_hash_hint), &
                 new_unittest('pressure_load_kind', test_pressure_load), &
                 new_unittest('plausibility_warnings', test_plausibility), &
                 new_unittest('fuzz_regression_decks', test_fuzz_regressions), &
                 new_unittest('free_format_hint', test_free_format), &
                 new_unittest('fuzz_odd_lines', test_fuzz_lines), &
                 new_unittest('fuzz_random_bytes', test_fuzz_random), &
                 new_unittest('beam_too_narrow', test_beam_too_narrow)]
    end subroutine collect_deck_reader

    ! ------------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------------

    !> A card with the name in columns 1-10 and the fields left-justified in f1..f7.
    pure function card(name, f1, f2, f3, f4, f5, f6, f7) result(line)
        character(len=*), intent(in) :: name
        character(len=*), intent(in), optional :: f1, f2, f3, f4, f5, f6, f7
        character(len=w) :: line
        character(len=10) :: field(7)
        field = ''
        if (present(f1)) field(1) = f1
        if (present(f2)) field(2) = f2
        if (present(f3)) field(3) = f3
        if (present(f4)) field(4) = f4
        if (present(f5)) field(5) = f5
        if (present(f6)) field(6) = f6
        if (present(f7)) field(7) = f7
        line = name
        line(11:80) = field(1)//field(2)//field(3)//field(4)//field(5)//field(6)//field(7)
    end function card

    !> Physical beam: l = 10, h = 0.5, b = 1 (lines 1-7).
    pure function beam_physical() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'BEAM'), &
                 card('GEOMETRY', '10.0', '0.5', '1.0'), &
                 card('STRUCTURE', '30.0E6', '0.2'), &
                 card('SOIL', '40.0E3', '0.3'), &
                 card('FRICTION', '0.5'), &
                 card('LOAD', 'POINT', '1000.0', '100.0', '0.0'), &
                 card('END')]
    end function beam_physical

    !> Physical plate: a = 6, h = 0.6 (lines 1-7).
    pure function plate_physical() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'PLATE'), &
                 card('GEOMETRY', '6.0', '0.6'), &
                 card('STRUCTURE', '30.0E6', '0.2'), &
                 card('SOIL', '40.0E3', '0.3'), &
                 card('FRICTION', '0.5'), &
                 card('LOAD', 'PATCH', '8000.0', '', '0.0', '0.4'), &
                 card('END')]
    end function plate_physical

    !> NONDIM beam of Table 1 (lines 1-5).
    pure function beam_nondim() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'BEAM'), &
                 card('NONDIM', '0.0025', '0.1', '0.3', '0.1', '0.05'), &
                 card('FRICTION', '0.6'), &
                 card('LOAD', 'POINT', '1.0', '0.1'), &
                 card('END')]
    end function beam_nondim

    !> NONDIM plate (lines 1-5).
    pure function plate_nondim() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'PLATE'), &
                 card('NONDIM', '0.01', '0.1', '0.3', '0.1'), &
                 card('FRICTION', '0.5'), &
                 card('LOAD', 'POINT', '1.0'), &
                 card('END')]
    end function plate_nondim

    !> Parse and require success.
    subroutine parse_ok(name, lines, deck, err)
        character(len=*), intent(in) :: name
        character(len=*), intent(in) :: lines(:)
        type(deck_t), intent(out) :: deck
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: perr
        call parse_deck(name, lines, deck, perr)
        if (allocated(perr)) call check(err, .false., 'unexpected input error:'//nl//perr%message)
    end subroutine parse_ok

    !> Parse `lines` as test/bad.dat and require an input error containing every fragment.
    subroutine expect_error(lines, fragments, err)
        character(len=*), intent(in) :: lines(:)
        character(len=*), intent(in) :: fragments(:)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call parse_deck(bad, lines, deck, perr)
        call check(err, allocated(perr), 'deck accepted; expected "'//trim(fragments(1))//'"')
        if (allocated(err)) return
        call check_message(perr, fragments, err)
    end subroutine expect_error

    !> The deck `lines` with line k replaced by new_line must be refused (expect_error).
    subroutine expect_card_error(lines, k, new_line, fragments, err)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: k
        character(len=*), intent(in) :: new_line
        character(len=*), intent(in) :: fragments(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=len(lines)) :: changed(size(lines))
        changed = lines
        changed(k) = new_line
        call expect_error(changed, fragments, err)
    end subroutine expect_card_error

    !> The error is an input error whose message contains every fragment.
    subroutine check_message(perr, fragments, err)
        type(error_t), intent(in) :: perr
        character(len=*), intent(in) :: fragments(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        call check(err, perr%code == EXIT_INPUT, 'exit code is not EXIT_INPUT')
        if (allocated(err)) return
        do k = 1, size(fragments)
            call check(err, index(perr%message, trim(fragments(k))) > 0, 'message lacks "'// &
                       trim(fragments(k))//'":'//nl//perr%message)
            if (allocated(err)) return
        end do
    end subroutine check_message

    ! ------------------------------------------------------------------------------------
    ! Positive tests
    ! ------------------------------------------------------------------------------------

    subroutine test_default_deck(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=80), allocatable :: lines(:)
        type(deck_t) :: deck
        call default_deck_lines(lines)
        call parse_ok('input/default.dat', lines, deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check(err, m%structure%kind == MODEL_PLATE .and. .not. m%nondim, &
                'default: physical PLATE')
            if (allocated(err)) return
            call check(err, deck%stem == 'default' .and. size(deck%lines) == size(lines), 'stem')
            if (allocated(err)) return
            call check(err, trim(m%units%force) == 'kN' .and. trim(m%units%length) == 'm', 'units')
            if (allocated(err)) return
            call check(err, size(m%loads) == 1 .and. m%loads(1)%kind == LOAD_PATCH, 'one PATCH')
            if (allocated(err)) return
            call check_close(err, m%loads(1)%fz, 8000.0_dp, 0.0_dp, 0.0_dp, 'F_z')
            if (allocated(err)) return
            call check_close(err, m%loads(1)%x2, 0.4_dp, 0.0_dp, 0.0_dp, 'x2')
            if (allocated(err)) return
            call check_close(err, m%structure%length, 6.0_dp, 0.0_dp, 0.0_dp, 'a')
            if (allocated(err)) return
            call check_close(err, m%structure%e, 30.0e6_dp, 0.0_dp, 0.0_dp, 'E')
            if (allocated(err)) return
            call check_close(err, m%ground%e_f, 40.0e3_dp, 0.0_dp, 0.0_dp, 'E_f')
            if (allocated(err)) return
            call check(err, m%mesh%ne == 40 .and. all(m%mesh%interp == INTERP_P1), 'MESH 40 P1')
            if (allocated(err)) return
            call check(err, index(m%title, 'Circular concrete raft') == 1, 'title')
            if (allocated(err)) return
            call check(err, case_count(deck) == 1, 'no sweep: one case')
        end associate
    end subroutine test_default_deck

    subroutine test_default_file(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=80), allocatable :: lines(:)
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        integer :: i
        call default_deck_lines(lines)
        call read_deck('input/default.dat', deck, perr)
        if (allocated(perr)) then
            call check(err, .false., 'input/default.dat: '//perr%message)
            return
        end if
        call check(err, size(deck%lines) == size(lines), 'input/default.dat has '// &
                   'a different number of lines than default_deck_lines')
        if (allocated(err)) return
        do i = 1, size(lines)
            call check(err, deck%lines(i) == lines(i), 'input/default.dat differs at line '// &
                       int_text(i)//': "'//trim(deck%lines(i))//'"')
            if (allocated(err)) return
        end do
        call check(err, deck%stem == 'default', 'stem of input/default.dat')
    end subroutine test_default_file

    !> Every input/*.dat parses (the list is taken with ls; the six shipped decks must be there).
    subroutine test_example_decks(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: listing = 'build/test_deck_reader_inputs.txt'
        character(len=*), parameter :: shipped(6) = [character(len=24) :: 'input/default.dat', &
            'input/beam_physical.dat', 'input/plate_physical.dat', 'input/beam_nondim.dat', &
            'input/plate_nondim.dat', 'input/sweep.dat']
        character(len=256), allocatable :: names(:)
        character(len=256) :: name
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        integer :: u, ios, k, n_ok
        call execute_command_line('ls input/*.dat > '//listing//' 2> /dev/null')
        allocate (names(0))
        open (newunit=u, file=listing, status='old', action='read', iostat=ios)
        if (ios == 0) then
            lines: do
                read (u, '(a)', iostat=ios) name
                if (ios /= 0) exit lines
                names = [character(len=256) :: names, name]
            end do lines
            close (u, status='delete')
        end if
        do k = 1, size(shipped)
            if (.not. any(names == shipped(k))) names = [character(len=256) :: names, shipped(k)]
        end do
        n_ok = 0
        decks: do k = 1, size(names)
            call read_deck(trim(names(k)), deck, perr)
            if (allocated(perr)) then
                call check(err, .false., perr%message)
                return
            end if
            n_ok = n_ok + 1
        end do decks
        call check(err, n_ok >= 6, 'fewer than six example decks')
    end subroutine test_example_decks

    subroutine test_defaults(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines(2) = card('NONDIM', '0.0025', '0.1', '', '', '0.05')
        lines(3) = card('FRICTION', '0.6')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check_close(err, m%interface%eps_bar, 1.0e-6_dp, 0.0_dp, 0.0_dp, 'eps_bar default')
            if (allocated(err)) return
            call check_close(err, m%structure%nu, 0.3_dp, 0.0_dp, 0.0_dp, 'NONDIM nu default')
            if (allocated(err)) return
            call check_close(err, m%ground%nu_f, 0.1_dp, 0.0_dp, 0.0_dp, 'NONDIM nu_f default')
            if (allocated(err)) return
            call check_close(err, m%structure%k_shear, 5.0_dp/6.0_dp, 1.0e-15_dp, 0.0_dp, &
                'k default')
            if (allocated(err)) return
            call check(err, m%mesh%ne == 20 .and. m%mesh%grading == 'UNIFORM' .and. &
                       all(m%mesh%interp == INTERP_P1), 'MESH defaults 20 UNIFORM P1')
            if (allocated(err)) return
            call check(err, m%solver%max_outer == 100 .and. m%solver%max_inner == 100, &
                'max iterations')
            if (allocated(err)) return
            call check_close(err, m%solver%tol_outer, 1.0e-8_dp, 0.0_dp, 0.0_dp, 'tol outer')
            if (allocated(err)) return
            call check_close(err, m%solver%tol_inner, 1.0e-10_dp, 0.0_dp, 0.0_dp, 'tol inner')
            if (allocated(err)) return
            call check_close(err, m%interface%eta_bar, 1.0e-9_dp, 0.0_dp, 0.0_dp, 'eta_bar')
            if (allocated(err)) return
            call check(err, m%solver%tau0_start < 0.0_dp .and. m%output%stations == 0, &
                'tau0 and stations')
            if (allocated(err)) return
            call check(err, m%solver%method == METHOD_NEWTON, 'SOLVER method defaults to NEWTON')
            if (allocated(err)) return
            call check(err, m%loads(1)%x1 == 0.0_dp .and. m%loads(1)%kind == LOAD_POINT, &
                       'POINT x1 defaults to the centre')
        end associate
    end subroutine test_defaults

    subroutine test_case_insensitive(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = [card('model', 'beam'), &
                 card('Nondim', '0.0025', '0.1', '0.3', '0.1', '0.05'), &
                 card('friction', '0.6'), &
                 card('load', 'point', '1.0', '0.1'), &
                 card('mesh', '10', 'edges', 'p2', 's2', 'p1', 'P1', 'p2'), &
                 card('solver', '1e-6', '1e-9', '50', '60', '1e-8', '0.2', 'twoloop'), &
                 card('output', '11'), &
                 card('end')]
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check(err, &
                m%structure%kind == MODEL_BEAM .and. m%mesh%ne == 10 .and. &
                m%mesh%grading == 'EDGES', &
                       'lower-case MODEL and MESH')
            if (allocated(err)) return
            call check(err, all(m%mesh%interp == [INTERP_P2, INTERP_S2, INTERP_P1, INTERP_P1, &
                                             INTERP_P2]), 'interpolation words')
            if (allocated(err)) return
            call check(err, &
                m%solver%max_outer == 50 .and. m%solver%max_inner == 60 .and. &
                m%output%stations == 11, &
                       'SOLVER counts and OUTPUT stations')
            if (allocated(err)) return
            call check_close(err, m%solver%tau0_start, 0.2_dp, 0.0_dp, 0.0_dp, 'tau0')
            if (allocated(err)) return
            call check(err, m%solver%method == METHOD_TWOLOOP, 'SOLVER method word twoloop')
        end associate
    end subroutine test_case_insensitive

    !> SOLVER f7: NEWTON (the default) or TWOLOOP; any other word is an input error.
    subroutine test_solver_method(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [lines(1:4), card('SOLVER', '', '', '', '', '', '', 'NEWTON'), lines(5)]
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%solver%method == METHOD_NEWTON, 'SOLVER method NEWTON')
        if (allocated(err)) return
        lines(5) = card('SOLVER', '', '', '', '', '', '', 'TWOLOOP')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%solver%method == METHOD_TWOLOOP, 'SOLVER method TWOLOOP')
        if (allocated(err)) return
        lines(5) = card('SOLVER', '', '', '', '', '', '', 'SECANT')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:71-80: SOLVER method', &
                          'must be NEWTON or TWOLOOP, got ''SECANT'''], err)
    end subroutine test_solver_method

    subroutine test_comments(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [character(len=w) :: '* a star comment', '$ a dollar comment', &
                 'C a C-blank comment', 'c lower-case c comment', 'C', '', '        ', &
                 lines(1:3), '* between cards '//char(195)//char(169)//' (non-ASCII ok)', &
                 lines(4:5), '* after END', '']
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%structure%kind == MODEL_BEAM .and. size(deck%base%loads) == 1, &
                   'comments and blank cards ignored')
    end subroutine test_comments

    subroutine test_e_notation(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(2) = card('GEOMETRY', '1.0E+1', '5.E-1', '+1')
        lines(3) = card('STRUCTURE', '  3.0e7', '2.0D-1', '.8')
        lines(4) = card('SOIL', '4E4', '0.3')
        lines(6) = card('LOAD', 'POINT', '1000', '-1.5E2', '-2.5')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check_close(err, m%structure%length, 10.0_dp, 0.0_dp, 0.0_dp, 'l = 1.0E+1')
            if (allocated(err)) return
            call check_close(err, m%structure%h, 0.5_dp, 0.0_dp, 0.0_dp, 'h = 5.E-1')
            if (allocated(err)) return
            call check_close(err, m%structure%b, 1.0_dp, 0.0_dp, 0.0_dp, 'b = +1')
            if (allocated(err)) return
            call check_close(err, m%structure%e, 3.0e7_dp, 0.0_dp, 0.0_dp, 'E = 3.0e7')
            if (allocated(err)) return
            call check_close(err, m%structure%nu, 0.2_dp, 0.0_dp, 0.0_dp, 'nu = 2.0D-1')
            if (allocated(err)) return
            call check_close(err, m%structure%k_shear, 0.8_dp, 0.0_dp, 0.0_dp, 'k = .8')
            if (allocated(err)) return
            call check_close(err, m%ground%e_f, 4.0e4_dp, 0.0_dp, 0.0_dp, 'E_f = 4E4')
            if (allocated(err)) return
            call check_close(err, m%loads(1)%fx, -150.0_dp, 0.0_dp, 0.0_dp, 'F_x = -1.5E2')
            if (allocated(err)) return
            call check_close(err, m%loads(1)%fz, 1000.0_dp, 0.0_dp, 0.0_dp, 'F_z = 1000')
        end associate
    end subroutine test_e_notation

    subroutine test_physical_beam(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [lines(1:6), card('LOAD', 'PATCH', '200.0', '', '-5.0', '-1.0'), &
                 card('LOAD', 'MOMENT', '50.0', '', '5.0'), lines(7)]
        call parse_ok('beam.dat', lines, deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check(err, m%structure%kind == MODEL_BEAM .and. size(m%loads) == 3, &
                'beam with 3 loads')
            if (allocated(err)) return
            call check(err, m%loads(2)%line == 7 .and. m%loads(3)%line == 8, 'load lines')
            if (allocated(err)) return
            call check_close(err, total_vertical_load(m%loads), 1200.0_dp, 1.0e-15_dp, 0.0_dp, &
                             'total vertical load (moment excluded)')
            if (allocated(err)) return
            call check_close(err, m%structure%b, 1.0_dp, 0.0_dp, 0.0_dp, 'b')
            if (allocated(err)) return
            call check(err, trim(m%units%force) == 'N' .and. trim(m%units%length) == 'm', &
                       'default unit labels N, m')
        end associate
    end subroutine test_physical_beam

    !> NONDIM beam: complete_model reproduces rho, zeta, beta; forces are used as they are.
    subroutine test_nondim_beam(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        call parse_ok('t.dat', beam_nondim(), deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check(err, m%nondim .and. m%structure%kind == MODEL_BEAM, 'NONDIM beam')
            if (allocated(err)) return
            call check_close(err, relative_stiffness(m%structure, m%ground), 0.0025_dp, &
                1.0e-13_dp, 0.0_dp, 'rho')
            if (allocated(err)) return
            call check_close(err, m%structure%h/m%structure%length, 0.1_dp, 1.0e-15_dp, 0.0_dp, &
                'zeta = h/l')
            if (allocated(err)) return
            call check_close(err, m%structure%b/m%structure%length, 0.05_dp, 1.0e-15_dp, 0.0_dp, &
                'beta = b/l')
            if (allocated(err)) return
            call check_close(err, total_vertical_load(m%loads), 1.0_dp, 0.0_dp, 0.0_dp, 'F = 1')
            if (allocated(err)) return
            call check_close(err, m%loads(1)%fx, 0.1_dp, 0.0_dp, 0.0_dp, 'F_x / F')
            if (allocated(err)) return
            call check_close(err, m%interface%f, 0.6_dp, 0.0_dp, 0.0_dp, 'f')
        end associate
    end subroutine test_nondim_beam

    subroutine test_nondim_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        call parse_ok('t.dat', plate_nondim(), deck, err)
        if (allocated(err)) return
        associate (m => deck%base)
            call check_close(err, relative_stiffness(m%structure, m%ground), 0.01_dp, 1.0e-13_dp, &
                0.0_dp, 'rho')
            if (allocated(err)) return
            call check_close(err, m%structure%h/m%structure%length, 0.1_dp, 1.0e-15_dp, 0.0_dp, &
                'zeta = h/a')
            if (allocated(err)) return
            call check(err, m%structure%length == 1.0_dp .and. m%structure%e == 1.0_dp, &
                'a = 1, E = 1')
        end associate
    end subroutine test_nondim_plate

    subroutine test_nu_f_half(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = plate_physical()
        lines(4) = card('SOIL', '40.0E3', '0.5')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check_close(err, deck%base%ground%nu_f, 0.5_dp, 0.0_dp, 0.0_dp, 'nu_f = 0.5 accepted')
    end subroutine test_nu_f_half

    subroutine test_sweep_expansion(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: cerr
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        character(len=w), allocatable :: lines(:)
        character(len=*), parameter :: expected(6) = [character(len=16) :: 'RHO=0.001 F=0.0', &
            'RHO=0.001 F=0.5', 'RHO=0.01 F=0.0', 'RHO=0.01 F=0.5', 'RHO=0.1 F=0.0', &
            'RHO=0.1 F=0.5']
        real(dp), parameter :: rho(3) = [0.001_dp, 0.01_dp, 0.1_dp], f(2) = [0.0_dp, 0.5_dp]
        integer :: i
        lines = plate_nondim()
        lines = [lines(1:4), card('SWEEP', 'RHO', '0.001', '0.01', '0.1'), &
                 card('SWEEP', 'f', '0.0', '0.5'), lines(5)]
        call parse_ok('test/sweep.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, case_count(deck) == 6 .and. size(deck%sweeps) == 2, 'six cases')
        if (allocated(err)) return
        call check(err, deck%sweeps(2)%name == 'F' .and. deck%sweeps(1)%line == 5, 'sweep_t')
        if (allocated(err)) return
        cases: do i = 1, 6
            call case_model(deck, i, m, label, err)
            if (allocated(err)) return
            call check(err, label == trim(expected(i)), 'label of case '//int_text(i)//': '//label)
            if (allocated(err)) return
            call check_close(err, relative_stiffness(m%structure, m%ground), &
                rho(1 + (i - 1)/size(f)), 1.0e-13_dp, &
                             0.0_dp, 'rho of case '//int_text(i))
            if (allocated(err)) return
            call check_close(err, m%interface%f, f(mod(i - 1, 2) + 1), 0.0_dp, 0.0_dp, &
                'f of case '//int_text(i))
            if (allocated(err)) return
        end do cases
        call case_model(deck, 7, m, label, cerr)
        call check(err, allocated(cerr), 'case 7 of 6 must fail')
    end subroutine test_sweep_expansion

    !> case_model re-validates: a swept value out of range names the SWEEP line and field.
    subroutine test_sweep_revalidated(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: cerr
        character(len=:), allocatable :: label
        character(len=w), allocatable :: lines(:)
        lines = plate_nondim()
        lines = [lines(1:4), card('SWEEP', 'RHO', '0.001', '0.01', '0.1'), lines(5)]
        call parse_ok('test/sweep.dat', lines, deck, err)
        if (allocated(err)) return
        deck%sweeps(1)%values(2) = -1.0_dp
        call case_model(deck, 1, m, label, cerr)
        call check(err, .not. allocated(cerr), 'case 1 is valid')
        if (allocated(err)) return
        call case_model(deck, 2, m, label, cerr)
        call check(err, allocated(cerr), 'case 2 (RHO = -1) must fail')
        if (allocated(err)) return
        call check_message(cerr, [character(len=120) :: 'test/sweep.dat:5:31-40:', &
                           'SWEEP RHO value v2 must be > 0', 'got -1', 'case 2'], err)
    end subroutine test_sweep_revalidated

    !> A beam narrower than 1E-12 l (the strip kernels then vary below the rounding of positions
    !! along the beam: the surface displacement came out infinite, an internal error) is an
    !! input error at the field that set the width: NONDIM beta, GEOMETRY b, or the SWEEP value
    !! of BETA, B or L. 1E-12 l itself is accepted.
    subroutine test_beam_too_narrow(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines(2) = card('NONDIM', '0.0025', '0.1', '0.3', '0.1', '1.0E-16')
        call expect_case_error(lines, 1, [character(len=120) :: 'test/narrow.dat:2:51-60:', &
            'NONDIM beta (width ratio b/l of the beam)', 'below the narrowest allowed', &
            'got 1.0E-16', 'execution not attempted'], err)
        if (allocated(err)) return
        lines(2) = card('NONDIM', '0.0025', '0.1', '0.3', '0.1', '1.0E-12')
        call expect_case_error(lines, 1, [character(len=120) :: ''], err)
        if (allocated(err)) return
        lines(2) = card('NONDIM', '0.0025', '0.1', '0.3', '0.1', '0.05')
        lines = [lines(1:4), card('SWEEP', 'BETA', '0.05', '9.9E-13'), lines(5)]
        call expect_case_error(lines, 2, [character(len=120) :: 'test/narrow.dat:5:31-40:', &
            'SWEEP BETA value v2', 'got 9.9E-13', 'case 2'], err)
        if (allocated(err)) return
        ! physical: b = 1E-12 on l = 10 is 1E-13 l
        lines = beam_physical()
        lines(2) = card('GEOMETRY', '10.0', '0.5', '1.0E-12')
        call expect_case_error(lines, 1, [character(len=120) :: 'test/narrow.dat:2:31-40:', &
            'GEOMETRY b (width of the beam)', 'b = 1.0E-13 l'], err)
        if (allocated(err)) return
        ! a swept length makes the beam too narrow: the SWEEP L value is named
        lines(2) = card('GEOMETRY', '10.0', '0.5', '1.0E-10')
        lines = [lines(1:6), card('SWEEP', 'L', '10.0', '1000.0'), lines(7)]
        call expect_case_error(lines, 2, [character(len=120) :: 'test/narrow.dat:7:31-40:', &
            'SWEEP L value v2', 'b = 1.0E-13 l'], err)
    end subroutine test_beam_too_narrow

    !> The deck parses and its case i is refused with every fragment in the message (no
    !! fragment, i.e. a single blank one: case i is accepted).
    subroutine expect_case_error(lines, i, fragments, err)
        character(len=*), intent(in) :: lines(:)
        integer, intent(in) :: i
        character(len=*), intent(in) :: fragments(:)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: cerr
        character(len=:), allocatable :: label
        call parse_ok('test/narrow.dat', lines, deck, err)
        if (allocated(err)) return
        call case_model(deck, i, m, label, cerr)
        if (len_trim(fragments(1)) == 0) then
            call check(err, .not. allocated(cerr), 'case '//int_text(i)//' must be accepted')
            return
        end if
        call check(err, allocated(cerr), 'case '//int_text(i)//' accepted; expected "'// &
                   trim(fragments(1))//'"')
        if (allocated(err)) return
        call check_message(cerr, fragments, err)
    end subroutine expect_case_error

    !> A physical SWEEP of the beam length that puts a load off the beam.
    subroutine test_sweep_length(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: cerr
        character(len=:), allocatable :: label
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(6) = card('LOAD', 'POINT', '1000.0', '', '4.0')
        lines = [lines(1:6), card('SWEEP', 'L', '10.0', '6.0'), lines(7)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:7:31-40:', &
                          'with L = 6 the LOAD of line 6 is off the structure', &
                          'must be in [-l/2, l/2] = [-3, 3], got 4'], err)
        if (allocated(err)) return
        lines(7) = card('SWEEP', 'L', '10.0', '12.0')
        call parse_ok('test/len.dat', lines, deck, err)
        if (allocated(err)) return
        deck%sweeps(1)%values(2) = 6.0_dp
        call case_model(deck, 2, m, label, cerr)
        call check(err, allocated(cerr), 'case with L = 6 must fail')
        if (allocated(err)) return
        call check_message(cerr, [character(len=120) :: 'test/len.dat:7:31-40:', &
                           'off the structure'], err)
    end subroutine test_sweep_length

    subroutine test_missing_file(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call read_deck('input/no_such_deck.dat', deck, perr)
        call check(err, allocated(perr), 'missing file accepted')
        if (allocated(err)) return
        call check_message(perr, [character(len=120) :: &
                           'input/no_such_deck.dat: cannot open the deck'], err)
        if (allocated(err)) return
        call read_deck('input', deck, perr)
        call check(err, allocated(perr), 'a directory accepted as a deck')
        if (allocated(err)) return
        call check(err, perr%code == EXIT_INPUT, 'directory: EXIT_INPUT')
    end subroutine test_missing_file

    !> A bad deck file: the messages carry its path.
    subroutine test_file_errors(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call read_deck('test/data/bad_structure.dat', deck, perr)
        call check(err, allocated(perr), 'test/data/bad_structure.dat accepted')
        if (allocated(err)) return
        call check_message(perr, [character(len=120) :: '2 input errors in '// &
            'test/data/bad_structure.dat; execution not attempted', &
            'test/data/bad_structure.dat:6:21-30: STRUCTURE nu (Poisson''s ratio of the '// &
            'structure) must be in [0, 0.5), got 0.62', &
            'test/data/bad_structure.dat:9:'], err)
        if (allocated(err)) return
        call check(err, deck%stem == 'bad_structure', 'stem')
    end subroutine test_file_errors

    ! ------------------------------------------------------------------------------------
    ! Error paths
    ! ------------------------------------------------------------------------------------

    subroutine test_unknown_card(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [lines(1:2), card('STRUKTUR', '1.0'), lines(3:)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:1-8: unknown card '// &
                          '''STRUKTUR''', 'expected TITLE, MODEL'], err)
        if (allocated(err)) return
        lines = beam_physical()
        lines = [lines(1:2), card('CX'), lines(3:)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:1-2: unknown card'], err)
    end subroutine test_unknown_card

    subroutine test_unreadable_number(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(3) = card('STRUCTURE', '30.0E6', '1.2.3')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:21-30: STRUCTURE nu', &
                          'expected a finite number', 'got ''1.2.3'''], err)
        if (allocated(err)) return
        lines(3) = card('STRUCTURE', 'E5', '0.2')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:11-20: STRUCTURE E', &
                          'expected a finite number', 'got ''E5'''], err)
        if (allocated(err)) return
        lines(3) = card('STRUCTURE', '+', '0.2')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:11-20:', 'got ''+'''], err)
        if (allocated(err)) return
        lines(3) = card('STRUCTURE', '3 0E6', '0.2')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:11-20:', &
                          'got ''3 0E6'''], err)
    end subroutine test_unreadable_number

    subroutine test_nan_inf(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        character(len=10), parameter :: odd(4) = [character(len=10) :: 'NaN', 'Inf', &
                                                  '-Infinity', 'nan(0x1)']
        ! the rule is 1E-30 <= |x| < 1E+30: 1E+30 itself is out, and the message says so
        character(len=10), parameter :: huge_or_tiny(5) = [character(len=10) :: '1e999', &
                                                           '-1D400', '10.0E29', '0.1E-30', '1E+30']
        integer :: k
        lines = beam_physical()
        do k = 1, size(odd)
            lines(2) = card('GEOMETRY', '10.0', odd(k), '1.0')
            call expect_error(lines, [character(len=120) :: 'test/bad.dat:2:21-30: GEOMETRY h', &
                              'expected a finite number'], err)
            if (allocated(err)) return
        end do
        do k = 1, size(huge_or_tiny)
            lines(2) = card('GEOMETRY', '10.0', huge_or_tiny(k), '1.0')
            call expect_error(lines, [character(len=120) :: 'test/bad.dat:2:21-30: GEOMETRY h', &
                              'a deck number is 0 or has a magnitude of at least 1E-30 '// &
                              'and below 1E+30'], err)
            if (allocated(err)) return
        end do
        lines(2) = card('GEOMETRY', '10.0', '0.00000E99', '1.0')
        call expect_error(lines, [character(len=120) :: 'GEOMETRY h (thickness of the '// &
                          'structure) must be > 0, got 0.00000E99'], err)
    end subroutine test_nan_inf

    subroutine test_missing_model(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        call expect_error(lines(2:), [character(len=120) :: 'test/bad.dat: missing MODEL card '// &
                          '(expected MODEL BEAM or MODEL PLATE)', '1 input error in '], err)
    end subroutine test_missing_model

    subroutine test_nu_large(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(3) = card('STRUCTURE', '30.0E6', '0.62')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:21-30: STRUCTURE nu '// &
                          '(Poisson''s ratio of the structure) must be in [0, 0.5), got 0.62', &
                          nl//'  STRUCTURE 30.0E6    0.62'//nl//repeat(' ', 22)//'^^^^^^^^^^'], err)
        if (allocated(err)) return
        lines(3) = card('STRUCTURE', '30.0E6', '0.5')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:21-30:', &
                          'must be in [0, 0.5), got 0.5'], err)
        if (allocated(err)) return
        lines(3) = card('STRUCTURE', '30.0E6', '0.2')
        lines(4) = card('SOIL', '40.0E3', '0.51')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:4:21-30: SOIL nu_f', &
                          'must be in [0, 0.5] (0.5, incompressible, is valid), got 0.51'], err)
    end subroutine test_nu_large

    subroutine test_h_zero(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(beam_physical(), 2, card('GEOMETRY', '10.0', '0.0', '1.0'), &
                               [character(len=120) :: 'test/bad.dat:2:21-30: GEOMETRY h '// &
                               '(thickness of the structure) must be > 0, got 0.0'], err)
        if (allocated(err)) return
        call expect_card_error(beam_nondim(), 2, &
                               card('NONDIM', '0.0025', '-0.1', '0.3', '0.1', '0.05'), &
                               [character(len=120) :: 'test/bad.dat:2:21-30: NONDIM zeta', &
                               'must be > 0, got -0.1'], err)
    end subroutine test_h_zero

    subroutine test_ne_zero(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [lines(1:4), card('MESH', '0'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:11-20: MESH N_e '// &
                          '(number of elements) must be a whole number in [1, 100000], got 0'], &
                          err)
        if (allocated(err)) return
        lines(5) = card('MESH', '10.5')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:11-20:', 'got 10.5'], err)
    end subroutine test_ne_zero

    subroutine test_load_outside_beam(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(6) = card('LOAD', 'POINT', '1000.0', '', '6.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:41-50: LOAD x1 lies '// &
                          'outside the beam: must be in [-l/2, l/2] = [-5, 5], got 6'], err)
        if (allocated(err)) return
        lines(6) = card('LOAD', 'PATCH', '1000.0', '', '-4.0', '5.5')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:51-60: LOAD x2 lies '// &
                          'outside the beam'], err)
        if (allocated(err)) return
        ! GEOMETRY after the LOAD: the check happens once the deck is read
        lines = beam_physical()
        lines = [lines(1), lines(3:6), lines(2), lines(7)]
        lines(5) = card('LOAD', 'POINT', '1000.0', '', '-5.01')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:41-50:', &
                          'got -5.01'], err)
    end subroutine test_load_outside_beam

    subroutine test_load_outside_plate(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(plate_nondim(), 4, card('LOAD', 'RING', '1.0', '', '1.5'), &
                               [character(len=120) :: 'test/bad.dat:4:41-50: LOAD x1 lies '// &
                               'outside the plate: must be in [0, a] = [0, 1] (NONDIM: in '// &
                               'units of a), got 1.5'], err)
    end subroutine test_load_outside_plate

    subroutine test_patch_reversed(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = plate_physical()
        lines(6) = card('LOAD', 'PATCH', '8000.0', '', '0.4', '0.4')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:51-60: LOAD x2 (end '// &
                          'of the patch) must be greater than x1 = 0.4'], err)
        if (allocated(err)) return
        lines(6) = card('LOAD', 'PATCH', '8000.0', '', '0.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:51-60: LOAD x2', &
                          'is required but the field is blank'], err)
    end subroutine test_patch_reversed

    subroutine test_plate_horizontal(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        type(deck_t) :: deck
        lines = plate_physical()
        lines(6) = card('LOAD', 'PATCH', '8000.0', '100.0', '0.0', '0.4')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:31-40: an '// &
                          'axisymmetric plate cannot carry a horizontal force', 'got 100.0', &
                          'a circular raft under an overturning moment or a horizontal force '// &
                          'is not modelled yet'], err)
        if (allocated(err)) return
        ! it points nowhere that does not carry the force (a RADIAL traction has no resultant)
        call expect_no_word(lines, 'RADIAL', err)
        if (allocated(err)) return
        ! the radial top traction of SPEC §7 is LOAD RADIAL
        lines(6) = card('LOAD', 'RADIAL', '', '100.0', '2.0', '6.0')
        lines = [lines(1:5), card('LOAD', 'PATCH', '8000.0', '', '0.0', '0.4'), lines(6:)]
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%loads(2)%kind == LOAD_PATCH .and. &
                   deck%base%loads(2)%fz == 0.0_dp .and. deck%base%loads(2)%fx == 100.0_dp, &
                   'RADIAL is a PATCH with F_x only')
    end subroutine test_plate_horizontal

    subroutine test_plate_moment(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = plate_physical()
        lines(6) = card('LOAD', 'MOMENT', '100.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:11-20: an '// &
                          'axisymmetric plate cannot carry an overturning moment', &
                          'a circular raft under an overturning moment or a horizontal force '// &
                          'is not modelled yet'], err)
        if (allocated(err)) return
        call expect_no_word(lines, 'RADIAL', err)
    end subroutine test_plate_moment

    !> The deck is refused and its message does not contain word.
    subroutine expect_no_word(lines, word, err)
        character(len=*), intent(in) :: lines(:)
        character(len=*), intent(in) :: word
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call parse_deck(bad, lines, deck, perr)
        call check(err, allocated(perr), 'deck accepted')
        if (allocated(err)) return
        call check(err, index(perr%message, word) == 0, 'the message names '//word//':'//nl// &
                   perr%message)
    end subroutine expect_no_word

    subroutine test_plate_point_off_axis(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(plate_nondim(), 4, card('LOAD', 'POINT', '1.0', '', '0.5'), &
                               [character(len=120) :: 'test/bad.dat:4:41-50: a POINT load '// &
                               'on the plate acts at the axis only', 'got 0.5'], err)
    end subroutine test_plate_point_off_axis

    subroutine test_ring_on_beam(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(beam_nondim(), 4, card('LOAD', 'RING', '1.0', '', '0.2'), &
                               [character(len=120) :: 'test/bad.dat:4:11-20: RING is a '// &
                               'plate load; a beam takes POINT, PATCH or MOMENT'], err)
    end subroutine test_ring_on_beam

    subroutine test_plate_width(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(plate_physical(), 2, card('GEOMETRY', '6.0', '0.6', '1.0'), &
                               [character(len=120) :: 'test/bad.dat:2:31-40: PLATE has no '// &
                               'width: GEOMETRY b must be blank'], err)
        if (allocated(err)) return
        call expect_card_error(plate_nondim(), 2, &
                               card('NONDIM', '0.01', '0.1', '0.3', '0.1', '0.05'), &
                               [character(len=120) :: 'test/bad.dat:2:51-60: PLATE has no '// &
                               'width: NONDIM beta must be blank'], err)
        if (allocated(err)) return
        call expect_card_error(beam_nondim(), 2, card('NONDIM', '0.0025', '0.1', '0.3', '0.1'), &
                               [character(len=120) :: 'test/bad.dat:2:51-60: NONDIM beta', &
                               'is required but the field is blank'], err)
    end subroutine test_plate_width

    subroutine test_tab(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(3) = 'STRUCTURE'//achar(9)//'30.0E6    0.2'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:10: TAB character '// &
                          'in column 10', nl//'  STRUCTURE?30.0E6'], err)
        if (allocated(err)) return
        lines = beam_physical()
        lines = [character(len=w) :: lines(1:2), '* comment with a'//achar(9)//'tab', lines(3:)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:17: TAB'], err)
    end subroutine test_tab

    !> Comment width in characters (UTF-8): a 76-character comment holding 'kN/m²' (77
    !! bytes, the ² is two) is accepted, an 81-character one is not; a UTF-8 byte-order mark
    !! before the first card is ignored.
    subroutine test_utf8_bom(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        character(len=*), parameter :: sq = char(194)//char(178)   ! U+00B2, 2 bytes
        character(len=*), parameter :: bom = char(239)//char(187)//char(191)
        lines = beam_physical()
        lines = [character(len=w) :: '* pressure in kN/m'//sq//' '//repeat('.', 56), lines]
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        lines(1) = '* pressure in kN/m'//sq//' '//repeat('.', 61)          ! 81 characters
        call expect_error(lines, [character(len=80) :: 'test/bad.dat:1:', &
                          'comment is 81 characters long'], err)
        if (allocated(err)) return
        lines = beam_physical()
        lines(1) = bom//lines(1)
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%structure%kind == MODEL_BEAM, 'MODEL after a BOM not read')
    end subroutine test_utf8_bom

    !> A non-ASCII character in a card (not a comment) is an error naming its column.
    subroutine test_non_ascii_card(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(3)(25:26) = char(194)//char(178)
        call expect_error(lines, [character(len=100) :: 'test/bad.dat:3:25: non-ASCII '// &
                          'character in column 25'], err)
    end subroutine test_non_ascii_card

    !> LOAD PRESSURE q x1 x2 is a PATCH of total q (x2 - x1) on a beam (100 kN/m over 2 m:
    !! 200 kN, with q_x 10 kN/m: 20 kN) and q pi (x2^2 - x1^2) on a plate (50 kPa over the disk
    !! r <= 2 m: 200 pi kN); q_x on a plate is an error.
    subroutine test_pressure_load(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(6) = card('LOAD', 'PRESSURE', '100.0', '10.0', '-1.0', '1.0')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check(err, deck%base%loads(1)%kind == LOAD_PATCH, 'PRESSURE is not a patch')
        if (allocated(err)) return
        call check_close(err, deck%base%loads(1)%fz, 200.0_dp, 1.0e-14_dp, 0.0_dp, 'beam total')
        if (allocated(err)) return
        call check_close(err, deck%base%loads(1)%fx, 20.0_dp, 1.0e-14_dp, 0.0_dp, 'beam F_x')
        if (allocated(err)) return
        lines = plate_physical()
        lines(6) = card('LOAD', 'PRESSURE', '50.0', '', '0.0', '2.0')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        call check_close(err, deck%base%loads(1)%fz, 200.0_dp*acos(-1.0_dp), 1.0e-14_dp, 0.0_dp, &
                         'plate total')
        if (allocated(err)) return
        lines(6) = card('LOAD', 'PRESSURE', '50.0', '5.0', '0.0', '2.0')
        call expect_error(lines, [character(len=80) :: 'test/bad.dat:6:31-40:', &
                          'cannot carry a horizontal force'], err)
    end subroutine test_pressure_load

    !> Plausible slips (README, Plausibility warnings): FRICTION 30.0 (an angle: tan 30 degrees =
    !! 0.577), E in GPa with E_f in MPa (30 and 30: E/E_f = 1), a settlement beyond the thickness
    !! (0.6 m on a 0.5 m beam): warnings, and none for the sound example deck; f = 1000 (no angle)
    !! is named a bonded base.
    subroutine test_plausibility(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=w), allocatable :: lines(:)
        character(len=warning_length), allocatable :: warn(:)
        lines = beam_physical()
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        warn = [input_warnings(deck%base), settlement_warnings(deck%base, 0.01_dp)]
        call check(err, size(warn) == 0, 'a sound deck got a warning')
        if (allocated(err)) return
        lines(5) = card('FRICTION', '30.0')
        lines(3) = card('STRUCTURE', '30.0', '0.2')
        lines(4) = card('SOIL', '30.0', '0.3')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        warn = input_warnings(deck%base)
        call check(err, size(warn) == 2, 'expected two warnings')
        if (allocated(err)) return
        call check(err, index(warn(1), 'f = 0.577') > 0 .and. index(warn(2), 'E/E_f') > 0, &
                   'warning text: '//trim(warn(1))//' / '//trim(warn(2)))
        if (allocated(err)) return
        warn = settlement_warnings(deck%base, 0.6_dp)
        call check(err, size(warn) == 1, 'a settlement of 0.6 m on a 0.5 m beam: no warning')
        if (allocated(err)) return
        ! f = 1000 is no angle (tan of 1000 degrees means nothing): a bonded base is named
        lines = beam_physical()
        lines(5) = card('FRICTION', '1000.0')
        call parse_ok('t.dat', lines, deck, err)
        if (allocated(err)) return
        warn = input_warnings(deck%base)
        call check(err, size(warn) == 1, 'f = 1000: expected one warning')
        if (allocated(err)) return
        call check(err, index(warn(1), 'bonded') > 0 .and. index(warn(1), 'degrees') == 0, &
                   'warning text: '//trim(warn(1)))
    end subroutine test_plausibility

    !> The decks the fuzzing campaign kept (test/data/fuzz, fuzz/CAMPAIGN.md) are valid decks
    !! that once tripped the harness's invariants: each reads, and every case of it builds a
    !! model (nondim_nu_f_half.dat: nu_f = 0.5, incompressible soil, is valid, SPEC §8).
    subroutine test_fuzz_regressions(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: perr
        character(len=:), allocatable :: label
        integer :: i
        call read_deck('test/data/fuzz/nondim_nu_f_half.dat', deck, perr)
        call check(err, .not. allocated(perr), 'fuzz regression deck refused')
        if (allocated(err)) return
        do i = 1, case_count(deck)
            call case_model(deck, i, m, label, perr)
            call check(err, .not. allocated(perr), 'fuzz regression deck: a case refused')
            if (allocated(err)) return
        end do
        call check(err, deck%base%ground%nu_f == 0.5_dp, 'nu_f = 0.5 not read')
    end subroutine test_fuzz_regressions

    !> '#' or '!' in column 1: an unknown card with a hint on the comment marks.
    subroutine test_hash_hint(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [character(len=w) :: '# my deck', '! another', lines]
        call expect_error(lines, [character(len=100) :: 'test/bad.dat:1:1: unknown card', &
                          'test/bad.dat:2:1: unknown card', 'a comment starts with * or $'], err)
    end subroutine test_hash_hint

    !> A free-format deck: each line says that fields are 10 columns wide, and no card it
    !! contains is reported missing as well (a reader without these hints gives 15 errors,
    !! among them a misleading 'missing MODEL card').
    subroutine test_free_format(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        lines = [character(len=w) :: 'MODEL BEAM', 'GEOMETRY 10.0 0.8 1.0', 'STRUCTURE 3.0E7 0.2', &
                 'SOIL 3.0E4 0.3', 'FRICTION 0.5', 'LOAD POINT 1000.0', 'END']
        call expect_error(lines, [character(len=100) :: 'test/bad.dat:1:7-10: MODEL', &
                          'test/bad.dat:2:10: GEOMETRY', 'fields are 10 columns wide: f1 is '// &
                          'columns 11-20', 'test/bad.dat:3:11-20: STRUCTURE E', &
                          'expected one number, got ''3.0E7 0.2'''], err)
        if (allocated(err)) return
        call parse_deck(bad, lines, deck, perr)
        call check(err, index(perr%message, 'missing') == 0, 'a card that is present was '// &
                   'also reported missing:'//nl//perr%message)
    end subroutine test_free_format

    subroutine test_long_card(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(3) = card('STRUCTURE', '30.0E6', '0.2')
        lines(3)(81:85) = '12345'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:81-85: card is 85 '// &
                          'columns long; a card has at most 80 columns'], err)
    end subroutine test_long_card

    subroutine test_blank_required(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        call expect_card_error(beam_physical(), 4, card('SOIL', '', '0.3'), &
                               [character(len=120) :: 'test/bad.dat:4:11-20: SOIL E_f '// &
                               '(Young''s modulus of the soil) is required but the field '// &
                               'is blank'], err)
        if (allocated(err)) return
        lines = beam_physical()
        lines(6) = card('LOAD', 'POINT', '', '100.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:21-30: LOAD F_z', &
                          'is required but the field is blank'], err)
        if (allocated(err)) return
        lines(6) = card('LOAD', '', '1000.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:11-20: LOAD kind is '// &
                          'required', 'POINT, PATCH, PRESSURE, MOMENT, RING or RADIAL'], err)
    end subroutine test_blank_required

    subroutine test_missing_end(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        call expect_error(lines(1:6), [character(len=120) :: 'test/bad.dat: missing END card '// &
                          '(the deck ends at line 6 without END)'], err)
    end subroutine test_missing_end

    subroutine test_after_end(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [lines, card('MODEL', 'PLATE')]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:8:1-15: card after END '// &
                          '(line 7): one problem per deck'], err)
    end subroutine test_after_end

    subroutine test_duplicate(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [lines(1:5), card('FRICTION', '0.6'), lines(6:)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:1-8: duplicate '// &
                          'FRICTION card (first given at line 5)'], err)
    end subroutine test_duplicate

    subroutine test_mixed(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [lines(1:2), card('GEOMETRY', '10.0', '0.5', '1.0'), card('UNITS', 'kN', 'm'), &
                 lines(3:)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:1-10: GEOMETRY cannot '// &
                          'be combined with NONDIM (line 2)', 'test/bad.dat:4:1-10: UNITS '// &
                          'cannot be combined with NONDIM'], err)
        if (allocated(err)) return
        lines = beam_nondim()
        lines(2) = '* no NONDIM'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat: missing problem data: '// &
                          'give NONDIM'], err)
    end subroutine test_mixed

    subroutine test_missing_soil(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines(4) = '$ SOIL removed'
        lines(5) = '$ FRICTION removed'
        lines(6) = '$ LOAD removed'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat: missing SOIL card', &
                          'test/bad.dat: missing FRICTION card', &
                          'test/bad.dat: missing LOAD card', '3 input errors in test/bad.dat'], &
                          err)
    end subroutine test_missing_soil

    subroutine test_unknown_words(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [lines(1:4), card('MESH', '20', 'GRADED', 'P1', 'P3'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:21-30: MESH grading '// &
                          'must be UNIFORM, EDGES or LOADS, got ''GRADED''', &
                          'test/bad.dat:5:41-50: '// &
                          'MESH interpolation of w must be P1, P2 or S2, got ''P3'''], err)
        if (allocated(err)) return
        lines = beam_nondim()
        lines(1) = card('MODEL', 'SHELL')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:1:11-20: MODEL kind '// &
                          'must be BEAM or PLATE, got ''SHELL'''], err)
        if (allocated(err)) return
        lines(1) = card('MODEL', 'BE AM')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:1:11-20: MODEL kind '// &
                          'must be one word'], err)
    end subroutine test_unknown_words

    subroutine test_stations(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines = [lines(1:4), card('OUTPUT', '1'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:11-20: OUTPUT stations', &
                          'must be a whole number in [2, 100000], got 1'], err)
    end subroutine test_stations

    subroutine test_eps_bar(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines(3) = card('FRICTION', '-0.1', '1.0')
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:3:11-20: FRICTION f', &
                          'must be >= 0, got -0.1', 'test/bad.dat:3:21-30: FRICTION eps_bar', &
                          'must be in (0, 1), got 1.0'], err)
        if (allocated(err)) return
        lines(3) = card('FRICTION', '0.6')
        lines = [lines(1:4), card('SOLVER', '0.0', '', '0', '', '-1e-9', '0.0'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:11-20: SOLVER tol_outer', &
                          'test/bad.dat:5:31-40: SOLVER max_outer', &
                          'test/bad.dat:5:51-60: SOLVER eta_bar', &
                          'test/bad.dat:5:61-70: SOLVER tau0', '4 input errors'], err)
    end subroutine test_eps_bar

    subroutine test_name_columns(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines(1) = '  MODEL   BEAM'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:1:3-10: card name '// &
                          '''MODEL'' starts in column 3', '1 input error'], err)
        if (allocated(err)) return
        lines(1) = 'MODEL BEAM'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:1:7-10: MODEL: text '// &
                          '''BEAM'' in columns 7-10 belongs in the fields'], err)
        if (allocated(err)) return
        lines(1) = '          BEAM'
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:1:1-10: card name '// &
                          'missing'], err)
    end subroutine test_name_columns

    subroutine test_extra_fields(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_card_error(beam_physical(), 4, card('SOIL', '40.0E3', '0.3', '0.1'), &
                               [character(len=120) :: 'test/bad.dat:4:31-40: SOIL has 2 '// &
                               'field(s); columns 31-40 must be blank, found ''0.1'''], err)
        if (allocated(err)) return
        call expect_card_error(beam_physical(), 7, card('END', 'now'), &
                               [character(len=120) :: 'test/bad.dat:7:11-20: END has 0'], err)
    end subroutine test_extra_fields

    subroutine test_sweep_incompatible(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_physical()
        lines = [lines(1:6), card('SWEEP', 'RHO', '0.01'), lines(7)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:7:11-20: SWEEP RHO needs '// &
                          'a NONDIM deck'], err)
        if (allocated(err)) return
        lines = plate_nondim()
        lines = [lines(1:4), card('SWEEP', 'E', '1.0'), card('SWEEP', 'BETA', '0.1'), &
                 card('SWEEP', 'ALPHA', '0.1'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:11-20: SWEEP E needs '// &
                          'a physical deck', 'test/bad.dat:6:11-20: SWEEP BETA does not apply '// &
                          'to a PLATE deck', 'test/bad.dat:7:11-20: SWEEP parameter must be '// &
                          'RHO, ZETA'], err)
        if (allocated(err)) return
        lines = plate_nondim()
        lines = [lines(1:4), card('SWEEP', 'F', '0.1'), card('SWEEP', 'F', '0.2'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:6:11-20: SWEEP F '// &
                          'already given at line 5'], err)
    end subroutine test_sweep_incompatible

    subroutine test_sweep_values(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = plate_nondim()
        lines = [lines(1:4), card('SWEEP', 'NU_F', '0.1', '0.6', 'x', '', '0.2'), &
                 card('SWEEP', 'NE'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:5:31-40: SWEEP NU_F '// &
                          'value v2 must be in [0, 0.5]', 'test/bad.dat:5:41-50: SWEEP NU_F '// &
                          'value v3: expected a finite number', 'test/bad.dat:5:51-60: SWEEP '// &
                          'values fill v1, v2, ... without gaps; v4 is blank', &
                          'test/bad.dat:6:21-30: SWEEP needs at least one value'], err)
    end subroutine test_sweep_values

    subroutine test_nondim_total(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        lines = beam_nondim()
        lines(4) = card('LOAD', 'POINT', '0.5', '0.1')
        lines = [lines(1:4), card('LOAD', 'PATCH', '0.3', '', '-0.5', '0.5'), lines(5)]
        call expect_error(lines, [character(len=120) :: 'test/bad.dat:4:21-30: in a NONDIM '// &
                          'deck forces are in units of the total vertical load F', &
                          'they add up to 0.8'], err)
    end subroutine test_nondim_total

    !> Three errors on three lines plus a missing card: all listed, in line order.
    subroutine test_several_errors(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: lines(:)
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        integer :: p(4)
        lines = beam_physical()
        lines(4) = card('SOIL', '-40.0E3', '0.3')
        lines(2) = card('GEOMETRY', '10.0', '0.5', 'wide')
        lines(6) = card('LOAD', 'POINT', '1000.0', '', '7.0')
        lines(5) = '* FRICTION forgotten'
        call parse_deck(bad, lines, deck, perr)
        call check(err, allocated(perr), 'bad deck accepted')
        if (allocated(err)) return
        call check_message(perr, [character(len=120) :: &
                           '4 input errors in test/bad.dat; execution not attempted'], err)
        if (allocated(err)) return
        p(1) = index(perr%message, 'test/bad.dat:2:31-40: GEOMETRY b')
        p(2) = index(perr%message, 'test/bad.dat:4:11-20: SOIL E_f')
        p(3) = index(perr%message, 'test/bad.dat:6:41-50: LOAD x1 lies outside the beam')
        p(4) = index(perr%message, 'test/bad.dat: missing FRICTION card')
        call check(err, all(p > 0), 'an error is not listed:'//nl//perr%message)
        if (allocated(err)) return
        call check(err, p(1) < p(2) .and. p(2) < p(3) .and. p(3) < p(4), &
                   'errors not in line order:'//nl//perr%message)
    end subroutine test_several_errors

    ! ------------------------------------------------------------------------------------
    ! Fuzzing: the reader never crashes and rejects odd input with EXIT_INPUT
    ! ------------------------------------------------------------------------------------

    subroutine test_fuzz_lines(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: base(:), odd(:)
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        integer :: k
        base = beam_physical()
        odd = [character(len=w) :: repeat('X', 150), 'MODEL     '//repeat('9', 190), &
               card('LOAD', 'POINT', '1.2.3'), card('LOAD', 'POINT', 'E5'), &
               card('LOAD', 'POINT', '+'), card('LOAD', 'POINT', '-'), card('LOAD', 'POINT', '.'), &
               card('LOAD', 'POINT', 'NaN'), card('LOAD', 'POINT', 'Inf'), &
               card('LOAD', 'POINT', '1e'), card('LOAD', 'POINT', '1e+'), &
               card('LOAD', 'POINT', '--1'), card('LOAD', 'POINT', '1.0+5'), &
               card('LOAD', 'POINT', '0x10'), card('LOAD', 'POINT', '1,5'), &
               card('LOAD', 'POINT', '1000.0', '', '1e308'), &
               card('LOAD', 'POINT', '1e-320'), &
               'MOD'//char(195)//char(136)//'L    BEAM', &
               card('LOAD', char(226)//char(128)//char(148), '1.0'), &
               card('SWEEP', 'NE', '1.5', '1e10'), card('SWEEP'), card('TITLE'), &
               'LOAD      '//achar(0)//'POINT', achar(27)//'[31m', '=', '*', &
               card('MESH', '2147483648'), card('MESH', '-2147483649'), &
               card('OUTPUT', '1e300'), card('SOLVER', '', '', '1e20'), &
               card('LOAD', 'MOMENT', '1e300', '1e300'), card('GEOMETRY', '1e308', '1e308', &
                                                               '1e308')]
        lines: do k = 1, size(odd)
            call parse_deck(bad, [base(1:6), odd(k), base(7)], deck, perr)
            if (k == 22 .or. k == 26) cycle lines   ! valid: TITLE, comment
            call check(err, allocated(perr), 'odd line '//int_text(k)//' accepted: '// &
                       trim(odd(k)(1:80)))
            if (allocated(err)) return
            call check(err, perr%code == EXIT_INPUT .and. index(perr%message, bad//':') > 0, &
                       'odd line '//int_text(k)//': no deck-named input error')
            if (allocated(err)) return
        end do lines
        call parse_deck(bad, [base(1:6), repeat(' ', w), base(7)], deck, perr)
        call check(err, .not. allocated(perr), 'a line of blanks must be ignored')
    end subroutine test_fuzz_lines

    !> Random bytes and random one-character mutations of a valid deck: no crash.
    subroutine test_fuzz_random(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=w), allocatable :: base(:), lines(:)
        type(deck_t) :: deck
        type(model_t) :: m
        type(error_t), allocatable :: perr, cerr
        character(len=:), allocatable :: label
        integer :: seed, trial, i, c, n_rejected
        seed = 12345
        n_rejected = 0
        allocate (lines(30))
        random_decks: do trial = 1, 50
            do i = 1, size(lines)
                lines(i) = ''
                do c = 1, next_int(seed, 100)
                    lines(i)(c:c) = achar(next_int(seed, 256) - 1)
                end do
            end do
            call parse_deck(bad, lines, deck, perr)
            if (allocated(perr)) n_rejected = n_rejected + 1
        end do random_decks
        call check(err, n_rejected == 50, 'a random deck was accepted')
        if (allocated(err)) return
        base = beam_physical()
        base = [base(1:6), card('SWEEP', 'F', '0.1', '0.2'), card('MESH', '10', 'EDGES'), base(7)]
        mutations: do trial = 1, 2000
            lines = base
            i = next_int(seed, size(lines))
            c = next_int(seed, 60)
            lines(i)(c:c) = achar(31 + next_int(seed, 96))
            call parse_deck(bad, lines, deck, perr)
            if (allocated(perr)) cycle mutations
            do i = 1, case_count(deck)
                call case_model(deck, i, m, label, cerr)
                call check(err, .not. allocated(cerr), 'a case of an accepted deck fails')
                if (allocated(err)) return
            end do
        end do mutations
    end subroutine test_fuzz_random

    !> Park-Miller minimal standard generator: 1..n.
    integer function next_int(seed, n)
        integer, intent(inout) :: seed
        integer, intent(in) :: n
        seed = int(mod(16807_int64*int(seed, int64), 2147483647_int64))
        next_int = mod(seed, n) + 1
    end function next_int

end module test_deck_reader
