!> Load cases and combinations in one deck (LOADCASE, COMBINE; README "Load cases and
!! combinations"): the cards, each combination solved as its own case, the envelope against
!! the combinations solved one by one from decks with the factored loads written out by hand,
!! the self-weight against statics, sweeps with combinations, and the plate.
module test_load_combinations
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_OK
    use model, only: model_t, LOAD_PATCH, LOAD_MOMENT
    use deck_reader, only: deck_t, parse_deck, read_deck, case_count, case_model, &
                           combination_names
    use output_paths, only: case_name, writes_file, check_decks_apart
    use analysis_driver, only: run_analysis, run_options_t
    use solved_case, only: case_t, solve_case
    use case_quality, only: solve_to_quality
    use adaptive_solve, only: adaptation_t
    use plausibility, only: warning_length
    use summary_table, only: entry_index
    use test_deck_reader, only: card
    implicit none
    private
    public :: collect_load_combinations

    integer, parameter :: w = 200   !! the length of test_deck_reader::card
    character(len=*), parameter :: out_dir = 'build/test_combinations'
    !> The design values compared with the envelope (a settlement, a pressure, both moments,
    !! the shear force, the tilt and the sliding utilisation).
    character(len=*), parameter :: keys(7) = [character(len=24) :: 'settlement_max', &
        'pressure_max', 'moment_sagging', 'moment_hogging', 'shear_force_max', 'tilt', &
        'sliding_utilisation']

contains

    subroutine collect_load_combinations(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('cards_and_factored_loads', test_cards), &
                 new_unittest('envelope_equals_combinations_solved_alone', test_envelope), &
                 new_unittest('self_weight_by_statics', test_self_weight), &
                 new_unittest('sweep_with_combinations', test_sweep), &
                 new_unittest('cases_alone_without_combine', test_cases_alone), &
                 new_unittest('plate_combinations', test_plate), &
                 new_unittest('file_names_and_collisions', test_file_names), &
                 new_unittest('stale_combination_files_removed', test_stale), &
                 new_unittest('no_envelope_when_a_case_fails', test_failed_case)]
    end subroutine collect_load_combinations

    ! ------------------------------------------------------------------------------------
    ! Decks
    ! ------------------------------------------------------------------------------------

    !> Strip footing l = 10 m, h = 0.8 m, b = 1.2 m (kN, m); self-weight 240 kN = 25 kN/m3
    !! x 0.8 x 1.2 x 10 (per unit factor of G).
    pure function beam_head() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [character(len=w) :: card('TITLE', 'combinations'), card('MODEL', 'BEAM'), &
                 card('UNITS', 'kN', 'm'), &
                 card('GEOMETRY', '10.0', '0.8', '1.2'), card('STRUCTURE', '30.0E6', '0.2'), &
                 card('SOIL', '30.0E3', '0.35'), card('FRICTION', '0.4'), card('MESH', '24')]
    end function beam_head

    !> Three load cases (G with self-weight, Q, W: a horizontal force and a moment) and four
    !! combinations, ULS2 on two cards; a bearing check (allowable 400 kPa).
    pure function combination_deck() result(lines)
        character(len=w), allocatable :: lines(:)
        lines = [character(len=w) :: beam_head(), card('CHECK', 'BEARING', '400.0'), &
                 card('LOADCASE', 'G', '25.0'), &
                 card('LOAD', 'PATCH', '1000.0', '', '-3.7', '-3.3'), &
                 card('LOAD', 'PATCH', '1000.0', '', '3.3', '3.7'), &
                 card('LOADCASE', 'Q'), &
                 card('LOAD', 'PATCH', '400.0', '', '-3.7', '-3.3'), &
                 card('LOADCASE', 'W'), &
                 card('LOAD', 'POINT', '0.0', '50.0', '3.5'), &
                 card('LOAD', 'MOMENT', '150.0', '', '3.5'), &
                 card('COMBINE', 'SLS', 'G', '1.0', 'Q', '1.0', 'W', '0.6'), &
                 card('COMBINE', 'ULS1', 'G', '1.35', 'Q', '1.5', 'W', '0.9'), &
                 card('COMBINE', 'ULS2', 'G', '1.35', 'Q', '1.05'), &
                 card('COMBINE', 'ULS2', 'W', '1.5'), &
                 card('COMBINE', 'FAV', 'G', '1.0', 'W', '1.5'), card('END')]
    end function combination_deck

    !> Combination k of combination_deck with its loads written out by hand: F = factor x
    !! the card's value; the self-weight 240 kN x the factor of G as a PATCH over the beam.
    pure function hand_deck(k) result(lines)
        integer, intent(in) :: k   !! 1 SLS, 2 ULS1, 3 ULS2, 4 FAV
        character(len=w), allocatable :: lines(:)
        character(len=10), parameter :: g_left(4) = [character(len=10) :: '1000.0', '1350.0', &
            '1350.0', '1000.0']
        character(len=10), parameter :: q_left(4) = [character(len=10) :: '400.0', '600.0', &
            '420.0', '0.0']
        character(len=10), parameter :: w_h(4) = [character(len=10) :: '30.0', '45.0', '75.0', &
            '75.0']
        character(len=10), parameter :: w_m(4) = [character(len=10) :: '90.0', '135.0', &
            '225.0', '225.0']
        character(len=10), parameter :: weight(4) = [character(len=10) :: '240.0', '324.0', &
            '324.0', '240.0']
        lines = [character(len=w) :: beam_head(), &
                 card('LOAD', 'PATCH', g_left(k), '', '-3.7', '-3.3'), &
                 card('LOAD', 'PATCH', g_left(k), '', '3.3', '3.7'), &
                 card('LOAD', 'PATCH', q_left(k), '', '-3.7', '-3.3'), &
                 card('LOAD', 'POINT', '0.0', w_h(k), '3.5'), &
                 card('LOAD', 'MOMENT', w_m(k), '', '3.5'), &
                 card('LOAD', 'PATCH', weight(k), '', '-5.0', '5.0'), card('END')]
    end function hand_deck

    ! ------------------------------------------------------------------------------------
    ! Tests
    ! ------------------------------------------------------------------------------------

    !> The cards: 4 cases of the deck, named by the combinations; combination ULS2's loads
    !! are the cards' values times 1.35, 1.05 and 1.5 (factors of the deck, written by hand),
    !! plus the self-weight 1.35 x 240 kN.
    subroutine test_cards(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        call parse_deck('combos.dat', combination_deck(), deck, err)
        if (allocated(err)) return
        call check(err, case_count(deck) == 4, 'four combinations, four cases')
        if (allocated(err)) return
        call check(err, all(combination_names(deck) == [character(len=10) :: 'SLS', 'ULS1', &
                   'ULS2', 'FAV']), 'the combinations in deck order')
        if (allocated(err)) return
        call case_model(deck, 3, m, label, err)
        if (allocated(err)) return
        call check(err, label == 'ULS2 = 1.35 G + 1.05 Q + 1.5 W', 'label '//label)
        if (allocated(err)) return
        call check(err, size(m%loads) == 6, 'five LOAD cards and the self-weight')
        if (allocated(err)) return
        call check_close(err, m%loads(1)%fz, 1350.0_dp, 1.0e-14_dp, 0.0_dp, 'G left 1.35 x 1000')
        if (allocated(err)) return
        call check_close(err, m%loads(3)%fz, 420.0_dp, 1.0e-14_dp, 0.0_dp, 'Q 1.05 x 400')
        if (allocated(err)) return
        call check_close(err, m%loads(4)%fx, 75.0_dp, 1.0e-14_dp, 0.0_dp, 'W 1.5 x 50')
        if (allocated(err)) return
        call check(err, m%loads(5)%kind == LOAD_MOMENT, 'the moment stays a moment')
        if (allocated(err)) return
        call check_close(err, m%loads(5)%fz, 225.0_dp, 1.0e-14_dp, 0.0_dp, 'W 1.5 x 150 kNm')
        if (allocated(err)) return
        call check(err, m%loads(6)%kind == LOAD_PATCH .and. m%loads(6)%x1 == -5.0_dp .and. &
                   m%loads(6)%x2 == 5.0_dp, 'self-weight over the whole beam')
        if (allocated(err)) return
        call check_close(err, m%loads(6)%fz, 1.35_dp*25.0_dp*0.8_dp*1.2_dp*10.0_dp, 1.0e-14_dp, &
                         0.0_dp, 'self-weight 1.35 gamma h b l')
    end subroutine test_cards

    !> One run of the deck: four case files and the envelope; every enveloped value's max and
    !! min, and the combination giving each, equal those of the four hand decks solved one
    !! by one (solve_to_quality, the run's own pipeline, on decks without LOADCASE).
    subroutine test_envelope(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        real(dp) :: alone(size(keys), 4)
        character(len=*), parameter :: names(4) = [character(len=4) :: 'SLS', 'ULS1', 'ULS2', &
                                                   'FAV']
        integer :: k, i, status
        logical :: there
        do k = 1, 4
            call solve_hand_deck(k, alone(:, k), err)
            if (allocated(err)) return
        end do
        call parse_deck(out_dir//'/combos.dat', combination_deck(), deck, err)
        if (allocated(err)) return
        call run_quietly(deck, out_dir, status)
        call check(err, status == EXIT_OK, 'the combination deck solves')
        if (allocated(err)) return
        do k = 1, 4
            inquire (file=out_dir//'/combos_'//trim(names(k))//'.txt', exist=there)
            call check(err, there, 'report of combination '//trim(names(k)))
            if (allocated(err)) return
        end do
        do i = 1, size(keys)
            call check_envelope_row(out_dir//'/combos_envelope.csv', trim(keys(i)), alone(i, :), &
                                    names, err)
            if (allocated(err)) return
        end do
        ! the design checks join the envelope: the bearing check's utilisation is the mean
        ! pressure V/(b l) (the base in full contact) over 400 kPa, V by statics: SLS 2000 +
        ! 240 + 400 = 2640 kN, ULS1 1.35 x 2240 + 1.5 x 400 = 3624, ULS2 3024 + 1.05 x 400 =
        ! 3444, FAV 2240 (W's vertical force is 0)
        call check_envelope_row(out_dir//'/combos_envelope.csv', 'bearing_mean_utilisation', &
                                [2640.0_dp, 3624.0_dp, 3444.0_dp, 2240.0_dp]/(1.2_dp*10.0_dp* &
                                400.0_dp), names, err)
    end subroutine test_envelope

    !> Hand deck k solved alone: the values of keys.
    subroutine solve_hand_deck(k, values, err)
        integer, intent(in) :: k
        real(dp), intent(out) :: values(:)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(case_t) :: c
        type(adaptation_t) :: adaptation
        character(len=warning_length), allocatable :: warnings(:)
        integer :: i, e
        call parse_deck('hand.dat', hand_deck(k), deck, err)
        if (allocated(err)) return
        call solve_to_quality(deck%base, .false., -1, c, adaptation, warnings, err)
        if (allocated(err)) return
        do i = 1, size(keys)
            e = entry_index(c%entries, trim(keys(i)))
            values(i) = c%entries(e)%value
        end do
    end subroutine solve_hand_deck

    !> The envelope CSV's column key: max and min rows against the largest and smallest of
    !! the values solved alone, and the combination named in max_case, min_case.
    subroutine check_envelope_row(path, key, alone, names, err)
        character(len=*), intent(in) :: path, key
        real(dp), intent(in) :: alone(:)
        character(len=*), intent(in) :: names(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=32) :: cell(4)
        real(dp) :: x
        integer :: ios
        call csv_cells(path, key, cell, err)
        if (allocated(err)) return
        read (cell(1), *, iostat=ios) x
        call check_close(err, x, maxval(alone), 1.0e-6_dp, 0.0_dp, 'max '//key)
        if (allocated(err)) return
        call check(err, trim(cell(2)) == trim(names(maxloc(alone, 1))), 'max_case of '//key// &
                   ': '//trim(cell(2)))
        if (allocated(err)) return
        read (cell(3), *, iostat=ios) x
        call check_close(err, x, minval(alone), 1.0e-6_dp, 0.0_dp, 'min '//key)
        if (allocated(err)) return
        call check(err, trim(cell(4)) == trim(names(minloc(alone, 1))), 'min_case of '//key// &
                   ': '//trim(cell(4)))
    end subroutine check_envelope_row

    !> Rows max, max_case, min, min_case of the envelope CSV in the column whose header
    !! starts with key (then ' [unit]' or nothing).
    subroutine csv_cells(path, key, cell, err)
        character(len=*), intent(in) :: path, key
        character(len=32), intent(out) :: cell(4)
        type(error_t), allocatable, intent(out) :: err
        character(len=4000) :: line
        integer :: u, ios, col, r
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'no envelope file '//path)
        if (allocated(err)) return
        read (u, '(a)') line                     ! '# fricon ...'
        read (u, '(a)') line
        col = column_of(line, key)
        do r = 1, 4
            read (u, '(a)', iostat=ios) line
            cell(r) = field_of(line, col)
        end do
        close (u)
        call check(err, col > 0 .and. ios == 0, 'envelope column '//key)
    end subroutine csv_cells

    pure integer function column_of(header, key) result(col)
        character(len=*), intent(in) :: header, key
        integer :: k
        do col = 1, 200
            k = len_trim(field_of(header, col))
            if (k == 0) exit
            if (field_of(header, col) == key .or. index(field_of(header, col), key//' [') == 1) &
                return
        end do
        col = 0
    end function column_of

    pure function field_of(line, col) result(f)
        character(len=*), intent(in) :: line
        integer, intent(in) :: col
        character(len=32) :: f
        integer :: start, k, c
        f = ''
        start = 1
        do c = 1, col - 1
            k = index(line(start:), ',')
            if (k == 0) return
            start = start + k
        end do
        k = index(line(start:), ',')
        if (k == 0) then
            f = adjustl(line(start:))
        else
            f = adjustl(line(start:start + k - 2))
        end if
    end function field_of

    !> Self-weight: the total vertical reaction of combination 1.35 G equals 1.35 (sum of
    !! the LOAD cards + gamma h b l) = 1.35 (2000 + 25 x 0.8 x 1.2 x 10) = 3024 kN (statics).
    subroutine test_self_weight(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(case_t) :: c
        character(len=:), allocatable :: label
        call parse_deck('weight.dat', [character(len=w) :: beam_head(), &
            card('LOADCASE', 'G', '25.0'), &
            card('LOAD', 'PATCH', '1000.0', '', '-3.7', '-3.3'), &
            card('LOAD', 'PATCH', '1000.0', '', '3.3', '3.7'), &
            card('COMBINE', 'ULS', 'G', '1.35'), card('END')], deck, err)
        if (allocated(err)) return
        call case_model(deck, 1, m, label, err)
        if (allocated(err)) return
        call solve_case(m, c, err)
        if (allocated(err)) return
        call check_close(err, c%sol%reaction(1), 1.35_dp*(2000.0_dp + 25.0_dp*0.8_dp*1.2_dp* &
                         10.0_dp), 1.0e-8_dp, 0.0_dp, 'total vertical reaction')
        if (allocated(err)) return
        ! the footing's weight alone, 25 x 0.8 x 1.2 x 10 = 240 kN: a deck without LOAD cards
        call parse_deck('weight_only.dat', [character(len=w) :: beam_head(), &
            card('LOADCASE', 'G', '25.0'), card('END')], deck, err)
        if (allocated(err)) return
        call case_model(deck, 1, m, label, err)
        if (allocated(err)) return
        call solve_case(m, c, err)
        if (allocated(err)) return
        call check_close(err, c%sol%reaction(1), 240.0_dp, 1.0e-8_dp, 0.0_dp, &
                         'reaction to the weight alone')
    end subroutine test_self_weight

    !> SWEEP E_F 15E3 60E3 with two combinations: four cases STEM_001_LOW ... STEM_002_HIGH;
    !! the envelope over all four. The largest settlement comes from the softer soil under
    !! the larger load (settlement grows with the load and falls with the soil's modulus),
    !! the smallest from the stiffer soil under the smaller load.
    subroutine test_sweep(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=32) :: cell(4)
        character(len=*), parameter :: files(4) = [character(len=9) :: '001_LOW', '001_HIGH', &
                                                   '002_LOW', '002_HIGH']
        integer :: k, status
        logical :: there
        call parse_deck(out_dir//'/swept.dat', [character(len=w) :: beam_head(), &
            card('LOADCASE', 'G'), &
            card('LOAD', 'PATCH', '1000.0', '', '-3.7', '-3.3'), &
            card('LOAD', 'PATCH', '1000.0', '', '3.3', '3.7'), &
            card('COMBINE', 'LOW', 'G', '1.0'), card('COMBINE', 'HIGH', 'G', '1.5'), &
            card('SWEEP', 'E_F', '15.0E3', '60.0E3'), card('END')], deck, err)
        if (allocated(err)) return
        call check(err, case_count(deck) == 4, 'two sweep points times two combinations')
        if (allocated(err)) return
        call run_quietly(deck, out_dir, status)
        call check(err, status == EXIT_OK, 'the swept deck solves')
        if (allocated(err)) return
        do k = 1, 4
            inquire (file=out_dir//'/swept_'//trim(files(k))//'.json', exist=there)
            call check(err, there, 'case files swept_'//trim(files(k)))
            if (allocated(err)) return
        end do
        call csv_cells(out_dir//'/swept_envelope.csv', 'settlement_max', cell, err)
        if (allocated(err)) return
        call check(err, trim(cell(2)) == '001_HIGH' .and. trim(cell(4)) == '002_LOW', &
                   'governing cases '//trim(cell(2))//', '//trim(cell(4)))
        if (allocated(err)) return
        ! the response figure: one curve per combination (README, doc/OUTPUT.md)
        call check(err, has_line(out_dir//'/swept_response.gp', "group_title[1] = 'LOW'") &
                   .and. has_line(out_dir//'/swept_response.gp', "group_title[2] = 'HIGH'") &
                   .and. has_line(out_dir//'/swept_response.gp', 'n_groups = 2'), &
                   'response curves LOW and HIGH')
    end subroutine test_sweep

    !> The text file has the line.
    logical function has_line(path, text)
        character(len=*), intent(in) :: path, text
        character(len=400) :: line
        integer :: u, ios
        has_line = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            has_line = has_line .or. trim(line) == text
        end do
        close (u)
    end function has_line

    !> LOADCASE cards without COMBINE: each case solved alone (factor 1), named by the case.
    subroutine test_cases_alone(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        call parse_deck('alone.dat', [character(len=w) :: beam_head(), card('LOADCASE', 'DEAD'), &
            card('LOAD', 'PATCH', '1000.0', '', '-3.7', '-3.3'), card('LOADCASE', 'LIVE'), &
            card('LOAD', 'PATCH', '300.0', '', '3.3', '3.7'), card('END')], deck, err)
        if (allocated(err)) return
        call check(err, case_count(deck) == 2, 'one case per load case')
        if (allocated(err)) return
        call case_model(deck, 2, m, label, err)
        if (allocated(err)) return
        call check(err, label == 'LIVE' .and. m%loads(1)%fz == 0.0_dp .and. &
                   m%loads(2)%fz == 300.0_dp, 'LIVE alone: DEAD x 0, LIVE x 1; '//label)
    end subroutine test_cases_alone

    !> The plate takes combinations: 2 of them, the second's total vertical reaction 1.5 x
    !! 8000 + 1.2 x 25 x 0.6 x pi 6^2 kN (statics: the column and the raft's weight).
    subroutine test_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(case_t) :: c
        character(len=:), allocatable :: label
        real(dp), parameter :: pi = acos(-1.0_dp)
        call parse_deck('plate.dat', [character(len=w) :: card('MODEL', 'PLATE'), &
            card('UNITS', 'kN', 'm'), &
            card('GEOMETRY', '6.0', '0.6'), card('STRUCTURE', '30.0E6', '0.2'), &
            card('SOIL', '40.0E3', '0.3'), card('FRICTION', '0.5'), card('MESH', '20'), &
            card('LOADCASE', 'G', '25.0'), card('LOADCASE', 'Q'), &
            card('LOAD', 'PATCH', '8000.0', '', '0.0', '0.4'), &
            card('COMBINE', 'SLS', 'G', '1.0', 'Q', '1.0'), &
            card('COMBINE', 'ULS', 'G', '1.2', 'Q', '1.5'), card('END')], deck, err)
        if (allocated(err)) return
        call case_model(deck, 2, m, label, err)
        if (allocated(err)) return
        call solve_case(m, c, err)
        if (allocated(err)) return
        call check_close(err, c%sol%reaction(1), 1.5_dp*8000.0_dp + 1.2_dp*25.0_dp*0.6_dp*pi* &
                         36.0_dp, 1.0e-8_dp, 0.0_dp, 'plate total vertical reaction')
    end subroutine test_plate

    !> The names of a deck's files with combinations SLS, ULS, W, FAV (by hand from README
    !! "LOADCASE and COMBINE": STEM_NAME, STEM_NNN_NAME at sweep point NNN, combinations
    !! fastest), and decks of one call whose files would collide.
    subroutine test_file_names(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=10), parameter :: tags(4) = [character(len=10) :: 'SLS', 'ULS', 'W', &
                                                   'FAV']
        character(len=10) :: table(4, 2)
        type(error_t), allocatable :: collision
        call check(err, case_name('s', 2, 4, tags) == 's_ULS', 'case 2 of 4: '// &
                   case_name('s', 2, 4, tags))
        if (allocated(err)) return
        ! case 5 of 8: sweep point (5 - 1)/4 + 1 = 2, combination mod(5 - 1, 4) + 1 = 1
        call check(err, case_name('s', 5, 8, tags) == 's_002_SLS', 'case 5 of 8: '// &
                   case_name('s', 5, 8, tags))
        if (allocated(err)) return
        call check(err, writes_file('s', 4, 's_FAV.json', tags) .and. &
                   writes_file('s', 4, 's_envelope.csv', tags) .and. &
                   writes_file('s', 4, 's_summary.csv', tags) .and. &
                   .not. writes_file('s', 4, 's_001.json', tags) .and. &
                   .not. writes_file('s', 4, 's.txt', tags), 'the files of s with combinations')
        if (allocated(err)) return
        ! deck x with combination ULS writes x_ULS.txt, which deck x_ULS writes too
        table = ''
        table(:, 1) = tags
        call check_decks_apart([character(len=12) :: 'a/x.dat', 'b/x_ULS.dat'], &
                               [character(len=4) :: 'out', 'out'], [character(len=8) :: 'x', &
                               'x_ULS'], [4, 1], collision, table, [4, 0])
        call check(err, allocated(collision), 'x (combination ULS) and x_ULS both write '// &
                   'x_ULS.txt')
    end subroutine test_file_names

    !> A deck run from its file, then run again with a combination renamed, then without
    !! load cases: each run leaves its own files and none of the earlier run's.
    subroutine test_stale(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = out_dir//'/stale'
        character(len=w), allocatable :: lines(:)
        integer :: status
        lines = combination_deck()
        call run_file(dir, lines, status, err)
        if (allocated(err)) return
        call check(err, exists(dir//'/d_FAV.txt') .and. exists(dir//'/d_envelope.csv'), &
                   'first run: d_FAV and the envelope')
        if (allocated(err)) return
        lines(size(lines) - 1) = card('COMBINE', 'PERM', 'G', '1.0', 'W', '1.5')
        call run_file(dir, lines, status, err)
        if (allocated(err)) return
        call check(err, exists(dir//'/d_PERM.json') .and. .not. exists(dir//'/d_FAV.json') &
                   .and. .not. exists(dir//'/d_FAV.csv'), 'FAV renamed PERM: no d_FAV left')
        if (allocated(err)) return
        call run_file(dir, hand_deck(1), status, err)
        if (allocated(err)) return
        call check(err, exists(dir//'/d.txt') .and. .not. exists(dir//'/d_SLS.txt') .and. &
                   .not. exists(dir//'/d_envelope.csv') .and. &
                   .not. exists(dir//'/d_envelope.json') .and. &
                   .not. exists(dir//'/d_summary.csv'), 'no load cases: one case, no '// &
                   'combination or envelope files left')
    end subroutine test_stale

    !> A combination that cannot solve (-1.0 G: the net vertical load is upward, the soil
    !! takes no tension): its case fails (status 2), the others solve, no envelope is left.
    subroutine test_failed_case(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = out_dir//'/failed'
        character(len=w), allocatable :: lines(:)
        integer :: status
        lines = combination_deck()
        call run_file(dir, lines, status, err)
        if (allocated(err)) return
        lines(size(lines) - 1) = card('COMBINE', 'UP', 'G', '-1.0', 'W', '1.0')
        call run_file(dir, lines, status, err)
        if (allocated(err)) return
        call check(err, status == 2, 'a failed combination: exit status 2')
        if (allocated(err)) return
        call check(err, exists(dir//'/d_SLS.csv') .and. exists(dir//'/d_UP.txt') .and. &
                   .not. exists(dir//'/d_envelope.csv') .and. &
                   .not. exists(dir//'/d_envelope.txt'), 'the cases, no envelope')
    end subroutine test_failed_case

    !> Write the deck DIR_deck/d.dat and run it from the file into dir (read_deck: its
    !! outputs record it; outside dir, where a single case's d.dat would be its own output).
    subroutine run_file(dir, lines, status, err)
        character(len=*), intent(in) :: dir
        character(len=*), intent(in) :: lines(:)
        integer, intent(out) :: status
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        integer :: u, k
        call execute_command_line('mkdir -p '//dir//'_deck')
        open (newunit=u, file=dir//'_deck/d.dat', status='replace', action='write')
        do k = 1, size(lines)
            write (u, '(a)') trim(lines(k))
        end do
        close (u)
        call read_deck(dir//'_deck/d.dat', deck, err)
        if (allocated(err)) return
        call run_quietly(deck, dir, status)
    end subroutine run_file

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    !> run_analysis without figures or estimates, its console lines to a scratch file.
    subroutine run_quietly(deck, dir, status)
        type(deck_t), intent(in) :: deck
        character(len=*), intent(in) :: dir
        integer, intent(out) :: status
        type(run_options_t) :: options
        integer :: u
        options%figures = .false.
        options%estimates = .false.
        options%threads = 1
        open (newunit=u, status='scratch', action='readwrite')
        call run_analysis(deck, dir, u, u, status, options)
        close (u)
    end subroutine run_quietly
end module test_load_combinations
