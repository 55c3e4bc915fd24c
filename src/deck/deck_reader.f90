!> Input decks (SPEC §8): card images -> the problem (`model_t`, physical units) and its SWEEP
!! cards. Every input error of the deck is collected and reported at once, in line order, as
!! `deck:line:columns: what was expected, got what was found`, followed by the line and a caret
!! marker (the fpm file_parse_error pattern); the run is then refused (EXIT_INPUT). Library
!! code: never prints or stops.
!!
!! Cards (columns 1-10 the name, fields f1..f7 in columns 11-20, 21-30, ..., 71-80; README's
!! "Input decks: reference" lists every field with its default, unit and rule, doc/ERRORS.md
!! every message):
!!
!!     *...+....1....+....2....+....3....+....4....+....5....+....6....+....7....+....8
!!     TITLE     Circular concrete raft, 8000 kN column load, elastic half-space
!!     MODEL     PLATE
!!     UNITS     kN        m         mm        kPa
!!     GEOMETRY  6.0       0.6
!!     STRUCTURE 30.0E6    0.2
!!     SOIL      40.0E3    0.3
!!     FRICTION  0.5       1.0E-6
!!     LOAD      PATCH     8000.0              0.0       0.4
!!     MESH      40        UNIFORM   P1        P1        P1        P1        P1
!!     ADAPT     1.0E-3    400
!!     SOLVER    1.0E-8    1.0E-10   100       100       1.0E-9              NEWTON
!!     OUTPUT
!!     CHECK     BEARING   150.0
!!     SWEEP     F         0.3       0.5       0.7
!!     END
!!
!! A NONDIM deck replaces GEOMETRY/STRUCTURE/SOIL/UNITS by `NONDIM rho zeta nu nu_f beta`;
!! its lengths are in units of l (beam) or a (plate), its forces in units of the total vertical
!! load F. `complete_model` then picks l = a = 1, E = 1, F = 1, so the deck's numbers are used
!! as they are; the reader checks that the vertical forces add up to 1.
!!
!! The ground is SOIL (a homogeneous half-space) or LAYER cards from the surface down and one
!! BASE card after them (`LAYER h E nu E_bottom`, `BASE ROUGH|SMOOTH|HALFSPACE E nu`); the top
!! layer's E and nu are the model's E_f and nu_f. In a NONDIM deck the layers' thicknesses
!! are in units of l or a and their moduli relative to the top layer's (which rho sets): the
!! first LAYER's E is 1 or blank and its nu blank or the NONDIM card's nu_f.
!!
!! SWEEP cases are numbered 1..case_count with the last SWEEP card varying fastest.
module deck_reader
    use iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, EXIT_INPUT, EXIT_INTERNAL
    use model, only: model_t, load_t, complete_model, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, &
                     GROUND_LAYERED, GROUND_BASE_ROUGH, GROUND_BASE_SMOOTH, &
                     GROUND_BASE_HALFSPACE, layer_count, ground_t, &
                     LOAD_PATCH, LOAD_MOMENT, LOAD_RING, METHOD_NEWTON, METHOD_TWOLOOP, &
                     FIELD_W, FIELD_PSI
    use physical_units, only: force_in_newtons, length_in_metres, disp_in_metres, &
                              pressure_in_pascals, force_words, length_words, disp_words, &
                              pressure_words
    use shape_functions, only: interp_code, INTERP_S2
    use discretization, only: fewest_elements
    use load_combinations, only: load_set_t, combination_count, combination_loads, &
                                 combination_text
    use deck_combinations, only: combination_cards_t, read_loadcase_card, read_combine_card, &
                                 note_load_card, accept_load_card, finish_load_set
    use check_cards, only: read_check_card
    use deck_fields, only: card_width, name_width, field_width, max_fields, FIELD_BLANK, &
                           number_problem, &
                           FIELD_OK, FIELD_BAD, FIELD_RANGE, RULE_POSITIVE, RULE_NONNEGATIVE, &
                           RULE_NU_STRUCTURE, RULE_NU_SOIL, RULE_OPEN_UNIT, RULE_COUNT, &
                           RULE_ELEMENTS, RULE_STATIONS, diagnostics_t, field_first_column, &
                           field_text, read_real_field, read_word_field, rule_ok, rule_text, &
                           to_upper, format_real, int_text, add_diagnostic, render_diagnostics
    implicit none
    private

    public :: read_deck, parse_deck, case_count, case_model, default_deck_lines
    public :: combination_names

    !> One SWEEP card: the parameter and its values (value k sits in field k+1, v_k).
    type, public :: sweep_t
        character(len=10) :: name = ''        !! parameter name, upper case (RHO, F, NE, ...)
        real(dp), allocatable :: values(:)    !! v1, v2, ... in the deck's units
        integer :: line = 0                   !! deck line of the card
    end type sweep_t

    !> A read deck: its text, the problem, and the sweeps.
    type, public :: deck_t
        character(len=:), allocatable :: path        !! as given (used in messages)
        character(len=:), allocatable :: stem        !! file stem: 'default' for input/default.dat
        character(len=80), allocatable :: lines(:)   !! raw lines, for the input echo (index = line)
        type(model_t) :: base                        !! the problem, after complete_model
        type(sweep_t), allocatable :: sweeps(:)      !! SWEEP cards in deck order
        type(load_set_t) :: load_set                 !! LOADCASE and COMBINE cards (or none)
        logical :: from_file = .false.               !! read from the file `path` (read_deck);
                                                     !! the built-in default is not
    end type deck_t

    ! Card identifiers: index into card_names.
    integer, parameter :: C_TITLE = 1, C_MODEL = 2, C_UNITS = 3, C_GEOMETRY = 4, &
                          C_STRUCTURE = 5, C_SOIL = 6, C_NONDIM = 7, C_FRICTION = 8, &
                          C_LOAD = 9, C_MESH = 10, C_SOLVER = 11, C_OUTPUT = 12, C_SWEEP = 13, &
                          C_END = 14, C_ADAPT = 15, C_LAYER = 16, C_BASE = 17, C_CHECK = 18, &
                          C_LOADCASE = 19, C_COMBINE = 20
    integer, parameter :: n_cards = 20
    character(len=9), parameter :: card_names(n_cards) = [character(len=9) :: 'TITLE', &
        'MODEL', 'UNITS', 'GEOMETRY', 'STRUCTURE', 'SOIL', 'NONDIM', 'FRICTION', 'LOAD', &
        'MESH', 'SOLVER', 'OUTPUT', 'SWEEP', 'END', 'ADAPT', 'LAYER', 'BASE', 'CHECK', &
        'LOADCASE', 'COMBINE']
    character(len=*), parameter :: card_list = 'TITLE, MODEL, UNITS, GEOMETRY, STRUCTURE, '// &
        'SOIL, LAYER, BASE, NONDIM, FRICTION, LOADCASE, LOAD, COMBINE, MESH, ADAPT, SOLVER, '// &
        'OUTPUT, CHECK, SWEEP or END'

    ! Sweepable parameters: name, range rule, deck kind (0 any, 1 NONDIM, 2 physical), model
    ! (0 any, MODEL_BEAM, MODEL_PLATE).
    ! The layer names (H1, E1, ... DEPTH, E_BASE) need LAYER cards (sweep_layer): Hn, En
    ! the thickness and the modulus at the top of layer n, DEPTH the depth to the base (the
    ! last layer's thickness follows), E_BASE the modulus of a HALFSPACE base.
    integer, parameter :: n_sweepable = 24
    character(len=7), parameter :: sweep_names(n_sweepable) = [character(len=7) :: 'RHO', &
        'ZETA', 'BETA', 'NU', 'NU_F', 'F', 'EPS_BAR', 'ETA_BAR', 'NE', 'K', 'E', 'E_F', 'H', &
        'L', 'A', 'B', 'H1', 'H2', 'H3', 'E1', 'E2', 'E3', 'DEPTH', 'E_BASE']
    integer, parameter :: sweep_rules(n_sweepable) = [RULE_POSITIVE, RULE_POSITIVE, &
        RULE_POSITIVE, RULE_NU_STRUCTURE, RULE_NU_SOIL, RULE_NONNEGATIVE, RULE_OPEN_UNIT, &
        RULE_POSITIVE, RULE_ELEMENTS, RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, &
        RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, &
        RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, RULE_POSITIVE, &
        RULE_POSITIVE, RULE_POSITIVE]
    integer, parameter :: sweep_decks(n_sweepable) = [1, 1, 1, 0, 0, 0, 0, 0, 0, 0, &
                                                      2, 2, 2, 2, 2, 2, 0, 0, 0, 0, 0, 0, 0, 0]
    integer, parameter :: sweep_models(n_sweepable) = [0, 0, MODEL_BEAM, 0, 0, 0, 0, 0, 0, &
        0, 0, 0, 0, MODEL_BEAM, MODEL_PLATE, MODEL_BEAM, 0, 0, 0, 0, 0, 0, 0, 0]
    !> Layer of a layer sweep name: n of Hn and En, -1 DEPTH, -2 E_BASE, 0 not a layer name.
    integer, parameter :: sweep_layer(n_sweepable) = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        0, 0, 0, 0, 1, 2, 3, 1, 2, 3, -1, -2]

    integer, parameter :: max_cases = 100000        !! largest number of SWEEP combinations
    integer, parameter :: max_line_kept = 1024      !! longer lines are cut (they are errors)
    integer(int64), parameter :: max_deck_bytes = 50000000_int64   !! a deck is text of cards
    character(len=*), parameter :: utf8_bom = achar(239)//achar(187)//achar(191)
    character(len=*), parameter :: field_hint = 'fields are 10 columns wide: f1 is columns '// &
        '11-20, f2 21-30, f3 31-40, ... (free format is not read; see the column ruler in README)'
    integer, parameter :: max_lines = 100000        !! longer files are not decks
    real(dp), parameter :: unit_load_tol = 1.0e-6_dp  !! NONDIM: |sum F_z - 1| allowed
    !> Narrowest beam, b/l: the strip kernels vary over X ~ b/2, and the points of their log
    !! rule near a station lie at a small fraction of b/2 from it; positions along the beam
    !! are rounded to about 1E-16 l, so below this ratio such points fall on the station
    !! (an infinite kernel value). Solved to b/l = 3E-13; failed from 1E-14.
    real(dp), parameter :: min_width_ratio = 1.0e-12_dp
    integer, parameter :: default_adapt_max_ne = 1000 !! ADAPT max_elements when blank

    !> One significant card (not blank, not a comment).
    type :: card_t
        integer :: id = 0                        !! C_* identifier
        integer :: line = 0                      !! deck line
        character(len=card_width) :: text = ''   !! the 80 columns
    end type card_t

    !> A raw line read from a file.
    type :: text_line_t
        character(len=:), allocatable :: text
    end type text_line_t

    !> Everything gathered while reading one deck.
    type :: state_t
        type(card_t), allocatable :: cards(:)
        integer :: n = 0                         !! cards(1:n) in use
        integer :: first_line(n_cards) = 0       !! line of the first card of each kind
        integer :: unreadable_line(n_cards) = 0  !! a card of that kind whose name line was bad
        integer :: end_line = 0                  !! line of END (0: none yet)
        integer :: last_line = 0                 !! number of lines of the deck
        type(diagnostics_t) :: diag              !! the input errors
        type(model_t) :: m                       !! the problem being filled
        logical :: kind_known = .false.          !! MODEL read correctly
        logical :: length_known = .false.        !! GEOMETRY l/a read correctly (or NONDIM)
        logical :: loads_ok = .true.             !! every LOAD card read without error
        integer, allocatable :: load_cards(:)    !! card index of each accepted load
        type(sweep_t), allocatable :: sweeps(:)
        integer, allocatable :: sweep_cards(:)   !! card index of each accepted sweep
        integer, allocatable :: layer_cards(:)   !! card index of each LAYER card
        real(dp) :: first_nu = -1.0_dp           !! NONDIM: the first LAYER's nu (-1 blank)
        type(combination_cards_t) :: combos      !! LOADCASE and COMBINE cards
    end type state_t

contains

    ! ---------------------------------------------------------------------------------------
    ! Public API
    ! ---------------------------------------------------------------------------------------

    !> Read a deck file. A file that cannot be opened or read, or any input error, gives
    !! err%code = EXIT_INPUT with all errors listed in one message.
    subroutine read_deck(path, deck, err)
        character(len=*), intent(in) :: path       !! file name, as given by the user
        type(deck_t), intent(out) :: deck          !! the deck (partial on error)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(text_line_t), allocatable :: raw(:)
        character(len=:), allocatable :: lines(:)
        character(len=256) :: msg
        integer :: u, ios, n, i, width

        deck%path = path
        deck%stem = stem_of(path)
        allocate (deck%lines(0), deck%sweeps(0))
        msg = ''
        open (newunit=u, file=path, status='old', action='read', form='unformatted', &
              access='stream', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call new_error(err, EXIT_INPUT, path//': cannot open the deck: '//trim(msg))
            return
        end if
        call read_all_lines(u, raw, n, ios, msg)
        close (u)
        if (ios /= 0) then
            call new_error(err, EXIT_INPUT, path//': cannot read the deck: '//trim(msg))
            return
        end if
        if (n == 0) then
            call new_error(err, EXIT_INPUT, path//': the deck is empty (or not a text file)')
            return
        end if
        if (binary(raw)) then
            ! one message, not one per line echoing a kilobyte of unprintable bytes
            call new_error(err, EXIT_INPUT, path//': not a text file (many control bytes; a '// &
                           'UTF-16 file is not read either): a deck is a text file of cards, '// &
                           'ASCII or UTF-8')
            return
        end if
        width = card_width
        do i = 1, n
            width = max(width, len(raw(i)%text))
        end do
        allocate (character(len=width) :: lines(n))
        do i = 1, n
            lines(i) = raw(i)%text
        end do
        call parse_deck(path, lines, deck, err)
        deck%from_file = .true.
    end subroutine read_deck

    !> Binary data rather than text: more than a fifth of the first 4096 bytes control
    !! characters other than tab, carriage return and form feed (UTF-8 text, whose bytes above
    !! 127 are letters, is text: a Cyrillic comment is no reason to refuse a deck; a text deck
    !! with a stray control character, a NUL say, gets its per-line message, which says
    !! where; UTF-16 has a NUL in every other byte).
    pure logical function binary(raw)
        type(text_line_t), intent(in) :: raw(:)
        integer :: i, k, c, seen, odd
        seen = 0
        odd = 0
        lines: do i = 1, size(raw)
            do k = 1, len(raw(i)%text)
                if (seen >= 4096) exit lines
                c = iachar(raw(i)%text(k:k))
                seen = seen + 1
                if ((c < 32 .and. c /= 9 .and. c /= 13 .and. c /= 12) .or. c == 127) odd = odd + 1
            end do
        end do lines
        binary = seen > 0 .and. 5*odd > seen
    end function binary

    !> Parse a deck given as lines of text (line i of the deck is text_lines(i)).
    subroutine parse_deck(name, text_lines, deck, err)
        character(len=*), intent(in) :: name            !! deck name for messages and the stem
        character(len=*), intent(in) :: text_lines(:)   !! the lines, any length
        type(deck_t), intent(out) :: deck               !! the deck (partial on error)
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        type(state_t) :: st
        character(len=len(text_lines)), allocatable :: lines(:)
        integer :: i

        deck%path = name
        deck%stem = stem_of(name)
        allocate (deck%lines(size(text_lines)))
        lines = text_lines
        ! a UTF-8 byte-order mark (some editors write one) is not part of the first card
        if (size(lines) > 0) then
            if (lines(1)(1:min(3, len(lines(1)))) == utf8_bom) lines(1) = lines(1)(4:)
        end if
        do i = 1, size(lines)
            deck%lines(i) = lines(i)
        end do
        allocate (st%cards(16), st%load_cards(0), st%sweeps(0), st%sweep_cards(0), &
                  st%layer_cards(0))
        allocate (st%m%loads(0))
        call scan_lines(st, lines)
        call read_model_card(st)
        call check_card_set(st)
        call read_cards(st)
        call finish_load_set(st%combos, st%m%nondim, st%diag)
        call check_ground_cards(st)
        call check_layer_sweeps(st)
        call check_adapt(st)
        call check_loads(st)
        call check_sweep_lengths(st)
        call check_case_total(st)
        if (st%diag%n == 0) call complete_model(st%m)
        deck%base = st%m
        deck%sweeps = st%sweeps
        deck%load_set = st%combos%set
        if (st%diag%n > 0) call new_error(err, EXIT_INPUT, &
            render_diagnostics(st%diag, name, '; execution not attempted'))
    end subroutine parse_deck

    !> Number of cases: the product of the sizes of the SWEEP cards (1 without SWEEP).
    pure integer function case_count(deck)
        type(deck_t), intent(in) :: deck   !! a parsed deck
        integer :: s
        case_count = max(1, combination_count(deck%load_set))
        if (.not. allocated(deck%sweeps)) return
        do s = 1, size(deck%sweeps)
            case_count = case_count*size(deck%sweeps(s)%values)
        end do
    end function case_count

    !> The names of the deck's combinations, in order (none without LOADCASE cards); case i
    !! of the deck solves combination mod(i - 1, n) + 1 of sweep point (i - 1)/n + 1.
    pure function combination_names(deck) result(names)
        type(deck_t), intent(in) :: deck   !! a parsed deck
        character(len=10), allocatable :: names(:)
        integer :: k
        allocate (names(combination_count(deck%load_set)))
        do k = 1, size(names)
            names(k) = deck%load_set%combinations(k)%name
        end do
    end function combination_names

    !> The i-th combination of the sweeps applied to the base problem (last SWEEP fastest,
    !! the load combinations faster still), completed and re-validated; label lists the swept
    !! values and the load combination ('RHO=0.0025 F=0.6', 'E_F=2.0E4 ULS = 1.35 G + 1.5 Q',
    !! '' if neither). A swept value out of range is an input error naming the SWEEP line and
    !! field.
    subroutine case_model(deck, i, m, label, err)
        type(deck_t), intent(in) :: deck                       !! a parsed deck
        integer, intent(in) :: i                               !! case number 1..case_count
        type(model_t), intent(out) :: m                        !! the problem of case i
        character(len=:), allocatable, intent(out) :: label    !! e.g. 'RHO=0.0025 F=0.6'
        type(error_t), allocatable, intent(out) :: err         !! allocated on failure
        type(diagnostics_t) :: diag
        integer, allocatable :: pick(:)
        integer :: s, n_comb

        label = ''
        m = deck%base
        if (i < 1 .or. i > case_count(deck)) then
            call new_error(err, EXIT_INTERNAL, 'case_model: case '//int_text(i)// &
                           ' outside 1..'//int_text(case_count(deck)))
            return
        end if
        n_comb = max(1, combination_count(deck%load_set))
        pick = case_indices(deck, (i - 1)/n_comb + 1)
        do s = 1, size(pick)
            associate (sw => deck%sweeps(s))
                if (trim(sw%name) /= 'DEPTH') call apply_sweep(m, sw%name, sw%values(pick(s)))
                if (s > 1) label = label//' '
                label = label//trim(sw%name)//'='//sweep_value_text(deck, sw, pick(s))
                call check_swept_value(deck, m, sw, pick(s), diag)
            end associate
        end do
        ! the depth to the base last: the last layer's thickness makes up the rest
        do s = 1, size(pick)
            if (trim(deck%sweeps(s)%name) /= 'DEPTH') cycle
            call apply_sweep(m, 'DEPTH', deck%sweeps(s)%values(pick(s)))
            call check_layer_depth(deck, m, deck%sweeps(s), pick(s), diag)
        end do
        if (combination_count(deck%load_set) > 0) then
            ! the factored loads on the structure of this sweep point (its self-weight)
            m%loads = combination_loads(deck%load_set, deck%base%loads, m%structure, &
                                        mod(i - 1, n_comb) + 1)
            if (len(label) > 0) label = label//' '
            label = label//combination_text(deck%load_set, mod(i - 1, n_comb) + 1)
        end if
        call complete_model(m)
        call check_element_count(deck, m, pick, diag)
        call check_beam_width(deck, m, pick, diag)
        if (diag%n == 0) return
        if (len(label) == 0) then
            call new_error(err, EXIT_INPUT, render_diagnostics(diag, deck%path, &
                '; execution not attempted'))
        else
            call new_error(err, EXIT_INPUT, render_diagnostics(diag, deck%path, &
                ', case '//int_text(i)//' ('//label//'); case not run'))
        end if
    end subroutine case_model

    !> N_e at least the fewest elements the grading can make (LOADS: one per piece between
    !! the load positions; discretization::fewest_elements), reported at the MESH card's N_e
    !! field, or at the SWEEP NE value that set it.
    subroutine check_element_count(deck, m, pick, diag)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m
        integer, intent(in) :: pick(:)              !! the case's value of each SWEEP card
        type(diagnostics_t), intent(inout) :: diag
        integer :: fewest, line, first, s
        fewest = fewest_elements(m)
        if (m%mesh%ne >= fewest) return
        line = 0
        first = field_first_column(1)
        do s = 1, size(deck%sweeps)
            if (trim(deck%sweeps(s)%name) /= 'NE') cycle
            line = deck%sweeps(s)%line
            first = field_first_column(pick(s) + 1)
        end do
        if (line == 0) then
            do s = 1, size(deck%lines)
                if (to_upper(adjustl(deck%lines(s)(1:name_width))) == 'MESH') line = s
            end do
        end if
        if (line < 1) return
        call add_diagnostic(diag, line, first, first + field_width - 1, 'MESH N_e must be at '// &
            'least '//int_text(fewest)//' with LOADS grading (an element for each piece '// &
            'between the load positions and patch edges), got '//int_text(m%mesh%ne), &
            echo_text(deck%lines(line)))
    end subroutine check_element_count

    !> A beam at least min_width_ratio l wide, reported at the SWEEP BETA, B or L value that
    !! made it narrower, else at NONDIM beta or GEOMETRY b.
    subroutine check_beam_width(deck, m, pick, diag)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m                !! the case, completed
        integer, intent(in) :: pick(:)                !! the case's value of each SWEEP card
        type(diagnostics_t), intent(inout) :: diag
        character(len=:), allocatable :: what, got
        integer :: line, first, s
        if (m%structure%kind /= MODEL_BEAM .or. &
            m%structure%b >= min_width_ratio*m%structure%length) return
        line = 0
        first = field_first_column(merge(5, 3, m%nondim))
        what = 'GEOMETRY b (width of the beam)'
        if (m%nondim) what = 'NONDIM beta (width ratio b/l of the beam)'
        got = format_real(merge(m%structure%b/m%structure%length, m%structure%b, m%nondim))
        do s = 1, size(deck%sweeps)
            select case (trim(deck%sweeps(s)%name))
            case ('BETA', 'B', 'L')
                line = deck%sweeps(s)%line
                first = field_first_column(pick(s) + 1)
                what = 'SWEEP '//trim(deck%sweeps(s)%name)//' value v'//int_text(pick(s))
                got = format_real(deck%sweeps(s)%values(pick(s)))
            end select
        end do
        if (line == 0) line = card_line(deck, merge('NONDIM  ', 'GEOMETRY', m%nondim))
        if (line < 1) return
        call add_diagnostic(diag, line, first, first + field_width - 1, trim(what)// &
            ' gives a beam of width b = '//format_real(m%structure%b/m%structure%length)// &
            ' l, below the '// &
            'narrowest allowed, b = '//format_real(min_width_ratio)//' l (the soil kernel '// &
            'under a beam varies over b/2, finer than positions along the beam are resolved), '// &
            'got '//got, echo_text(deck%lines(line)))
    end subroutine check_beam_width

    !> Line of the first card named name (0: none).
    pure integer function card_line(deck, name) result(line)
        type(deck_t), intent(in) :: deck
        character(len=*), intent(in) :: name
        integer :: s
        line = 0
        do s = size(deck%lines), 1, -1
            if (to_upper(adjustl(deck%lines(s)(1:name_width))) == trim(name)) line = s
        end do
    end function card_line

    !> The built-in default case (identical to input/default.dat): a circular concrete raft
    !! under a column load on an elastic half-space, physical data in kN and m.
    subroutine default_deck_lines(text_lines)
        character(len=80), allocatable, intent(out) :: text_lines(:)  !! the deck's lines
        text_lines = [character(len=80) :: &
            '* fricon built-in default case (the same text as input/default.dat).', &
            '* Circular concrete raft, radius 6 m, thickness 0.6 m, on a stiff soil; a', &
            '* column load of 8000 kN spread over the column footprint r <= 0.4 m.', &
            '*...+....1....+....2....+....3....+....4....+....5....+....6....+....7....+....8', &
            'TITLE     Circular concrete raft, 8000 kN column load, elastic half-space', &
            'MODEL     PLATE', &
            'UNITS     kN        m', &
            '*         a [m]     h [m]', &
            'GEOMETRY  6.0       0.6', &
            '*         E [kPa]   nu        k (blank: 5/6)', &
            'STRUCTURE 30.0E6    0.2', &
            '*         E_f [kPa] nu_f', &
            'SOIL      40.0E3    0.3', &
            '*         f         eps_bar', &
            'FRICTION  0.5       1.0E-6', &
            '*         kind      F_z [kN]  F_x [kN]  x1 [m]    x2 [m]', &
            'LOAD      PATCH     8000.0              0.0       0.4', &
            '*         N_e       grading   u_s       w         psi       sigma_x   sigma_z', &
            'MESH      40        UNIFORM   P1        P1        P1        P1        P1', &
            '*         stations (blank: every node of the mesh)', &
            'OUTPUT', &
            'END']
    end subroutine default_deck_lines

    ! ---------------------------------------------------------------------------------------
    ! Lines -> cards
    ! ---------------------------------------------------------------------------------------

    !> First pass: reject bad lines, skip comments and blanks, identify the cards.
    subroutine scan_lines(st, text_lines)
        type(state_t), intent(inout) :: st
        character(len=*), intent(in) :: text_lines(:)
        integer :: i
        st%last_line = size(text_lines)
        lines: do i = 1, size(text_lines)
            if (len_trim(text_lines(i)) == 0) cycle lines
            if (is_comment(text_lines(i))) then
                call check_comment(st, i, text_lines(i))
                cycle lines
            end if
            if (.not. line_is_clean(st, i, text_lines(i))) then
                call note_unreadable(st, i, text_lines(i))
                cycle lines
            end if
            if (st%end_line > 0) then
                call add_diagnostic(st%diag, i, 1, len_trim(text_lines(i)), 'card after END '// &
                    '(line '//int_text(st%end_line)//'): one problem per deck, END is the '// &
                    'last card', echo_text(text_lines(i)))
                cycle lines
            end if
            call classify_card(st, i, text_lines(i))
        end do lines
    end subroutine scan_lines

    !> A comment card: column 1 is '*' or '$', or 'C' (either case) followed by a blank.
    pure logical function is_comment(text)
        character(len=*), intent(in) :: text
        is_comment = .false.
        if (len(text) < 1) return
        if (text(1:1) == '*' .or. text(1:1) == '$') then
            is_comment = .true.
        else if (text(1:1) == 'C' .or. text(1:1) == 'c') then
            is_comment = .true.
            if (len(text) >= 2) is_comment = text(2:2) == ' '
        end if
    end function is_comment

    !> A comment may hold any text (UTF-8 too) but no TAB or control character, in at most 80
    !! characters (counted as characters, not bytes: a UTF-8 continuation byte adds none).
    subroutine check_comment(st, i, text)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: i
        character(len=*), intent(in) :: text
        integer :: c, n_chars, code
        n_chars = 0
        chars: do c = 1, len_trim(text)
            code = iachar(text(c:c))
            if (code == 9 .or. code < 32 .or. code == 127) then
                call add_diagnostic(st%diag, i, c, c, trim(merge('TAB character    ', &
                    'control character', code == 9))//' in a comment (column '//int_text(c)// &
                    '): use blanks', echo_text(text))
                return
            end if
            if (code < 128 .or. code >= 192) n_chars = n_chars + 1   ! not a continuation byte
        end do chars
        if (n_chars > card_width) call add_diagnostic(st%diag, i, card_width + 1, &
            len_trim(text), 'comment is '//int_text(n_chars)//' characters long; a card '// &
            'has at most 80', echo_text(text))
    end subroutine check_comment

    !> TAB, control characters and cards longer than 80 columns are errors of the line.
    logical function line_is_clean(st, i, text)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: i                 !! line number
        character(len=*), intent(in) :: text     !! the line
        integer :: n, c, tab, ctrl, k
        n = len_trim(text)
        tab = index(text(1:n), achar(9))
        ctrl = 0
        chars: do c = 1, n
            if (iachar(text(c:c)) == 9) cycle chars      ! every TAB: reported once, as a TAB
            if (iachar(text(c:c)) < 32 .or. iachar(text(c:c)) == 127) then
                ctrl = c
                exit chars
            end if
        end do chars
        if (tab > 0) call add_diagnostic(st%diag, i, tab, tab, 'TAB character in column '// &
            int_text(tab)//': cards have fixed columns, use blanks', echo_text(text))
        if (ctrl > 0) call add_diagnostic(st%diag, i, ctrl, ctrl, 'control character (code '// &
            int_text(iachar(text(ctrl:ctrl)))//') in column '//int_text(ctrl), echo_text(text))
        ! (a loop, not scan with the 128 characters above 127: that compares each column with
        ! each of them)
        c = 0
        high: do k = 1, n
            if (iachar(text(k:k)) > 127) then
                c = k
                exit high
            end if
        end do high
        if (c > 0) then
            call add_diagnostic(st%diag, i, c, c, 'non-ASCII character in column '// &
                int_text(c)//': cards hold ASCII only (a comment, * in column 1, may hold '// &
                'any text)', echo_text(text))
            ctrl = c
        end if
        if (n > max_line_kept) then
            call add_diagnostic(st%diag, i, card_width + 1, max_line_kept, 'card is more '// &
                'than '//int_text(max_line_kept)//' columns long; a card has at most 80 '// &
                'columns', echo_text(text))
        else if (n > card_width) then
            call add_diagnostic(st%diag, i, card_width + 1, n, 'card is '//int_text(n)// &
                ' columns long; a card has at most 80 columns', echo_text(text))
        end if
        line_is_clean = tab == 0 .and. ctrl == 0 .and. n <= card_width
    end function line_is_clean

    !> Identify the card name of a clean line (columns 1-10) and record the card.
    subroutine classify_card(st, i, text)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: i
        character(len=*), intent(in) :: text
        character(len=card_width) :: card
        character(len=name_width) :: name
        integer :: p, id
        card = text
        name = card(1:name_width)
        if (name(1:1) == ' ') then
            call name_not_left_justified(st, i, card)
            return
        end if
        p = index(name, ' ')
        if (p == 0) p = name_width + 1
        id = card_id(to_upper(name(1:p - 1)))
        if (id == 0 .and. index('#!/', name(1:1)) > 0) then
            call add_diagnostic(st%diag, i, 1, 1, 'unknown card '''//trim(name)//''': a '// &
                'comment starts with * or $ in column 1, or C and a blank (# and ! are not '// &
                'comment marks)', echo_text(card))
        else if (id == 0) then
            call add_diagnostic(st%diag, i, 1, len_trim(name), 'unknown card '''//trim(name)// &
                ''' (expected '//card_list//')', echo_text(card))
        else if (len_trim(name(p:)) > 0) then
            p = p - 1 + verify(name(p:), ' ')
            call add_diagnostic(st%diag, i, p, name_width, trim(card_names(id))//': text '''// &
                trim(name(p:))//''' in columns '//int_text(p)//'-10 belongs in the fields; '// &
                field_hint, echo_text(card))
            if (st%unreadable_line(id) == 0) st%unreadable_line(id) = i
        else if (st%first_line(id) > 0 .and. id /= C_LOAD .and. id /= C_SWEEP .and. &
                 id /= C_LAYER .and. id /= C_CHECK .and. id /= C_LOADCASE .and. &
                 id /= C_COMBINE) then
            call add_diagnostic(st%diag, i, 1, len_trim(name), 'duplicate '// &
                trim(card_names(id))//' card (first given at line '// &
                int_text(st%first_line(id))//'); only LOADCASE, LOAD, COMBINE, SWEEP, LAYER '// &
                'and CHECK may repeat', &
                echo_text(card))
        else
            call append_card(st, card_t(id=id, line=i, text=card))
        end if
    end subroutine classify_card

    !> A line rejected for its characters or its layout may still name a card (STRUCTURE
    !! followed by a TAB, MODEL in column 2): that card is not reported missing as well, which
    !! would send the reader looking for a card that is there.
    subroutine note_unreadable(st, i, text)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: i
        character(len=*), intent(in) :: text
        character(len=name_width) :: head
        integer :: id, cut
        head = text(1:min(len(text), name_width))
        head = adjustl(head)
        cut = scan(head, achar(9)//' ')
        if (cut > 0) head(cut:) = ' '
        id = card_id(to_upper(head))
        if (id == 0) return
        if (st%unreadable_line(id) == 0) st%unreadable_line(id) = i
    end subroutine note_unreadable

    !> Columns 1-10 start with a blank: the name is missing or not left-justified.
    subroutine name_not_left_justified(st, i, card)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: i
        character(len=*), intent(in) :: card
        integer :: p
        call note_unreadable(st, i, card)
        if (len_trim(card(1:name_width)) == 0) then
            call add_diagnostic(st%diag, i, 1, name_width, 'card name missing: columns 1-10 '// &
                'are blank but the card has fields', echo_text(card))
        else
            p = verify(card(1:name_width), ' ')
            call add_diagnostic(st%diag, i, p, name_width, 'card name '''// &
                trim(adjustl(card(1:name_width)))//''' starts in column '//int_text(p)// &
                '; a card name is left-justified in columns 1-10', echo_text(card))
        end if
    end subroutine name_not_left_justified

    !> C_* identifier of an upper-case card name; 0 when unknown.
    pure integer function card_id(name)
        character(len=*), intent(in) :: name   !! upper-case card name
        card_id = name_index(name, card_names)
    end function card_id

    !> Position of name in a list of names (trailing blanks ignored); 0 when absent.
    pure integer function name_index(name, names) result(k)
        character(len=*), intent(in) :: name       !! the name looked for
        character(len=*), intent(in) :: names(:)   !! the list
        do k = size(names), 1, -1
            if (trim(name) == trim(names(k))) return
        end do
    end function name_index

    !> Add a card to the list (growing it as needed).
    subroutine append_card(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        type(card_t), allocatable :: grown(:)
        if (st%n == size(st%cards)) then
            allocate (grown(2*st%n))
            grown(1:st%n) = st%cards(1:st%n)
            call move_alloc(grown, st%cards)
        end if
        st%n = st%n + 1
        st%cards(st%n) = cd
        if (st%first_line(cd%id) == 0) st%first_line(cd%id) = cd%line
        if (cd%id == C_END) st%end_line = cd%line
    end subroutine append_card

    ! ---------------------------------------------------------------------------------------
    ! Card set: required, exclusive and missing cards
    ! ---------------------------------------------------------------------------------------

    !> MODEL first: the other cards depend on BEAM or PLATE.
    subroutine read_model_card(st)
        type(state_t), intent(inout) :: st
        character(len=field_width) :: word
        integer :: k, s
        k = first_card(st, C_MODEL)
        if (k == 0) then
            if (missing(st, C_MODEL)) call deck_error(st, 'missing MODEL card (expected '// &
                                                      'MODEL BEAM or MODEL PLATE)')
            return
        end if
        call take_word(st, st%cards(k), 1, 'MODEL kind', 'BEAM PLATE', .true., word, s)
        if (s == FIELD_OK) then
            st%kind_known = .true.
            st%m%structure%kind = MODEL_PLATE
            if (word == 'BEAM') st%m%structure%kind = MODEL_BEAM
        end if
        call check_unused(st, st%cards(k), 1)
    end subroutine read_model_card

    !> Either NONDIM or GEOMETRY + STRUCTURE + SOIL; FRICTION, a LOAD and END are required.
    subroutine check_card_set(st)
        type(state_t), intent(inout) :: st
        integer, parameter :: physical(4) = [C_GEOMETRY, C_STRUCTURE, C_SOIL, C_UNITS]
        integer :: k, id
        st%m%nondim = st%first_line(C_NONDIM) > 0
        if (st%m%nondim) then
            st%length_known = .true.
            do k = 1, size(physical)
                id = physical(k)
                if (st%first_line(id) > 0) call card_error(st, st%cards(first_card(st, id)), &
                    trim(card_names(id))//' cannot be combined with NONDIM (line '// &
                    int_text(st%first_line(C_NONDIM))//'): a deck gives either the '// &
                    'nondimensional groups or physical GEOMETRY, STRUCTURE and SOIL')
            end do
        else if (all(st%first_line(physical(1:3)) == 0) .and. &
                 all(st%unreadable_line(physical(1:3)) == 0) .and. &
                 st%unreadable_line(C_NONDIM) == 0 .and. missing(st, C_LAYER)) then
            ! (a NONDIM, GEOMETRY, ... line with an error of its own is there: not missing)
            call deck_error(st, 'missing problem data: give NONDIM (nondimensional groups) '// &
                            'or GEOMETRY, STRUCTURE and SOIL (physical data)')
        else if (st%unreadable_line(C_NONDIM) == 0) then
            do k = 1, 3
                if (physical(k) == C_SOIL .and. .not. missing(st, C_LAYER)) cycle
                if (missing(st, physical(k))) call deck_error(st, 'missing '// &
                    trim(card_names(physical(k)))//' card (a physical deck needs GEOMETRY, '// &
                    'STRUCTURE and SOIL, or LAYER cards and a BASE instead of SOIL)')
            end do
        end if
        if (missing(st, C_FRICTION)) call deck_error(st, 'missing FRICTION card '// &
            '(FRICTION f eps_bar; f = 0 for a frictionless interface)')
        ! (a deck of load cases may hold the self-weight only: an empty case is its error)
        if (missing(st, C_LOAD) .and. missing(st, C_LOADCASE)) call deck_error(st, &
            'missing LOAD card (at least '// &
            'one load is required)')
        if (st%unreadable_line(C_END) > 0) then
            continue     ! an END whose name line could not be read has its own error
        else if (st%end_line == 0 .and. st%last_line == 0) then
            call deck_error(st, 'missing END card (the deck is empty)')
        else if (st%end_line == 0) then
            call deck_error(st, 'missing END card (the deck ends at line '// &
                            int_text(st%last_line)//' without END)')
        end if
    end subroutine check_card_set

    !> No card of this kind, not even one whose name line could not be read (that one has its
    !! own error already; a second 'missing' error would mislead).
    pure logical function missing(st, id)
        type(state_t), intent(in) :: st
        integer, intent(in) :: id
        missing = st%first_line(id) == 0 .and. st%unreadable_line(id) == 0
    end function missing

    !> Second pass: read every card's fields.
    subroutine read_cards(st)
        type(state_t), intent(inout) :: st
        integer :: k
        cards: do k = 1, st%n
            select case (st%cards(k)%id)
            case (C_TITLE)
                st%m%title = st%cards(k)%text(name_width + 1:)
            case (C_UNITS)
                if (.not. st%m%nondim) call read_units(st, st%cards(k))
            case (C_GEOMETRY)
                if (.not. st%m%nondim) call read_geometry(st, st%cards(k))
            case (C_STRUCTURE)
                if (.not. st%m%nondim) call read_structure(st, st%cards(k))
            case (C_SOIL)
                if (.not. st%m%nondim) call read_soil(st, st%cards(k))
            case (C_NONDIM)
                call read_nondim(st, st%cards(k))
            case (C_LAYER)
                call read_layer(st, k)
            case (C_BASE)
                call read_base(st, st%cards(k))
            case (C_FRICTION)
                call read_friction(st, st%cards(k))
            case (C_LOAD)
                call read_load(st, k)
            case (C_MESH)
                call read_mesh(st, st%cards(k))
            case (C_ADAPT)
                call read_adapt(st, st%cards(k))
            case (C_SOLVER)
                call read_solver(st, st%cards(k))
            case (C_OUTPUT)
                call take_count(st, st%cards(k), 1, 'OUTPUT stations (number of equally '// &
                                'spaced output stations)', RULE_STATIONS, .false., &
                                    st%m%output%stations)
                call check_unused(st, st%cards(k), 1)
            case (C_SWEEP)
                call read_sweep(st, k)
            case (C_LOADCASE)
                call read_loadcase_card(st%combos, st%cards(k)%line, st%cards(k)%text, st%diag)
            case (C_COMBINE)
                call read_combine_card(st%combos, st%cards(k)%line, st%cards(k)%text, &
                                       st%cards(max(k - 1, 1))%id == C_COMBINE .and. k > 1, &
                                       st%diag)
            case (C_CHECK)
                call read_check_card(st%cards(k)%text, st%cards(k)%line, st%m%nondim, &
                                     st%m%limits, st%diag)
            case (C_END)
                call check_unused(st, st%cards(k), 0)
            end select
        end do cards
    end subroutine read_cards

    ! ---------------------------------------------------------------------------------------
    ! The cards
    ! ---------------------------------------------------------------------------------------

    !> UNITS force length [settlement-display pressure-display]: the deck's unit labels
    !! (default N and m; never converted) and, where the deck's words are known units
    !! (physical_units), the display units of settlements and pressures.
    subroutine read_units(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        logical :: length_known, force_known
        st%m%units%stated = .true.
        call take_label(st, cd, 1, 'UNITS force label', st%m%units%force)
        call take_label(st, cd, 2, 'UNITS length label', st%m%units%length)
        call take_label(st, cd, 3, 'UNITS settlement display unit', st%m%units%disp)
        call take_label(st, cd, 4, 'UNITS pressure display unit', st%m%units%pressure)
        call check_unused(st, cd, 4)
        length_known = length_in_metres(st%m%units%length) > 0.0_dp
        force_known = force_in_newtons(st%m%units%force) > 0.0_dp
        if (len_trim(st%m%units%disp) > 0) then
            if (disp_in_metres(st%m%units%disp) <= 0.0_dp) then
                call field_error(st, cd, 3, 'UNITS settlement display unit must be one of '// &
                                 disp_words//', got '''//trim(st%m%units%disp)//'''')
            else if (.not. length_known) then
                call field_error(st, cd, 3, 'UNITS settlement display unit needs a known '// &
                                 'length unit in f2 ('//length_words//'), got '''// &
                                 trim(st%m%units%length)//'''')
            end if
        end if
        if (len_trim(st%m%units%pressure) == 0) return
        if (pressure_in_pascals(st%m%units%pressure) <= 0.0_dp) then
            call field_error(st, cd, 4, 'UNITS pressure display unit must be one of '// &
                             pressure_words//', got '''//trim(st%m%units%pressure)//'''')
        else if (.not. (length_known .and. force_known)) then
            call field_error(st, cd, 4, 'UNITS pressure display unit needs known force and '// &
                             'length units in f1 and f2 ('//force_words//'; '//length_words// &
                             '), got '''//trim(st%m%units%force)//''' and '''// &
                             trim(st%m%units%length)//'''')
        end if
    end subroutine read_units

    !> GEOMETRY l|a h b: b required for BEAM, must be blank for PLATE.
    subroutine read_geometry(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=:), allocatable :: what
        integer :: s
        what = 'GEOMETRY l or a (beam length or plate radius)'
        if (st%kind_known .and. st%m%structure%kind == MODEL_BEAM) &
            what = 'GEOMETRY l (length of the beam)'
        if (st%kind_known .and. st%m%structure%kind == MODEL_PLATE) &
            what = 'GEOMETRY a (radius of the plate)'
        call take_real(st, cd, 1, what, RULE_POSITIVE, .true., st%m%structure%length, s)
        st%length_known = s == FIELD_OK
        call take_real(st, cd, 2, 'GEOMETRY h (thickness of the structure)', RULE_POSITIVE, &
                       .true., st%m%structure%h)
        if (st%kind_known .and. st%m%structure%kind == MODEL_PLATE) then
            call forbid_field(st, cd, 3, 'PLATE has no width: GEOMETRY b must be blank')
        else
            call take_real(st, cd, 3, 'GEOMETRY b (width of the beam)', RULE_POSITIVE, &
                           st%kind_known, st%m%structure%b)
        end if
        call check_unused(st, cd, 3)
    end subroutine read_geometry

    !> STRUCTURE E nu k.
    subroutine read_structure(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        call take_real(st, cd, 1, 'STRUCTURE E (Young''s modulus of the structure)', &
                       RULE_POSITIVE, .true., st%m%structure%e)
        call take_real(st, cd, 2, 'STRUCTURE nu (Poisson''s ratio of the structure)', &
                       RULE_NU_STRUCTURE, .true., st%m%structure%nu)
        call take_real(st, cd, 3, 'STRUCTURE k (shear correction factor)', RULE_POSITIVE, &
                       .false., st%m%structure%k_shear)
        call check_unused(st, cd, 3)
    end subroutine read_structure

    !> SOIL E_f nu_f.
    subroutine read_soil(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        call take_real(st, cd, 1, 'SOIL E_f (Young''s modulus of the soil)', RULE_POSITIVE, &
                       .true., st%m%ground%e_f)
        call take_real(st, cd, 2, 'SOIL nu_f (Poisson''s ratio of the soil)', RULE_NU_SOIL, &
                       .true., st%m%ground%nu_f)
        call check_unused(st, cd, 2)
    end subroutine read_soil

    !> LAYER h E nu E_bottom, the next layer down (E_bottom blank: E constant in the layer).
    !! The first LAYER's E and nu are the model's E_f and nu_f; in a NONDIM deck its E is 1 or
    !! blank and its nu is checked against the NONDIM card's (check_ground_cards).
    subroutine read_layer(st, k)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: k                 !! card index
        real(dp) :: h, e_top, e_bottom, nu
        logical :: first
        integer :: s
        first = size(st%layer_cards) == 0
        st%layer_cards = [st%layer_cards, k]
        h = 0.0_dp
        e_top = 1.0_dp
        e_bottom = 0.0_dp
        nu = -1.0_dp
        associate (cd => st%cards(k))
            call take_real(st, cd, 1, 'LAYER h (thickness of the layer)', RULE_POSITIVE, &
                           .true., h)
            if (first .and. st%m%nondim) then
                call take_real(st, cd, 2, 'LAYER E (modulus of the top layer)', &
                               RULE_POSITIVE, .false., e_top, s)
                if (s == FIELD_OK .and. e_top /= 1.0_dp) call field_error(st, cd, 2, 'in a '// &
                    'NONDIM deck the moduli are relative to the top layer''s (which rho '// &
                    'sets): the first LAYER''s E must be 1 or blank, got '//field_value(cd, 2))
                call take_real(st, cd, 3, 'LAYER nu (Poisson''s ratio of the layer)', &
                               RULE_NU_SOIL, .false., nu)
                st%first_nu = nu
            else
                call take_real(st, cd, 2, 'LAYER E (Young''s modulus at the top of the '// &
                               'layer)', RULE_POSITIVE, .true., e_top)
                call take_real(st, cd, 3, 'LAYER nu (Poisson''s ratio of the layer)', &
                               RULE_NU_SOIL, .true., nu)
            end if
            call take_real(st, cd, 4, 'LAYER E_bottom (Young''s modulus at the bottom of '// &
                           'the layer)', RULE_POSITIVE, .false., e_bottom)
            call check_unused(st, cd, 4)
        end associate
        call add_layer(st%m, h, e_top, e_bottom, nu, first)
    end subroutine read_layer

    !> Append a layer to the model's ground; the first sets E_f and nu_f (physical deck).
    pure subroutine add_layer(m, h, e_top, e_bottom, nu, first)
        type(model_t), intent(inout) :: m
        real(dp), intent(in) :: h, e_top, e_bottom, nu
        logical, intent(in) :: first
        m%ground%kind = GROUND_LAYERED
        m%ground%relative_moduli = m%nondim
        if (.not. allocated(m%ground%thickness)) allocate (m%ground%thickness(0), &
            m%ground%e_top(0), m%ground%e_bottom(0), m%ground%poisson(0))
        m%ground%thickness = [m%ground%thickness, h]
        m%ground%e_top = [m%ground%e_top, e_top]
        m%ground%e_bottom = [m%ground%e_bottom, e_bottom]
        m%ground%poisson = [m%ground%poisson, nu]
        if (first .and. .not. m%nondim) then
            m%ground%e_f = e_top
            m%ground%nu_f = nu
        end if
    end subroutine add_layer

    !> BASE kind E nu: ROUGH or SMOOTH (rigid; E and nu blank) or HALFSPACE E nu.
    subroutine read_base(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=field_width) :: word
        integer :: s
        call take_word(st, cd, 1, 'BASE kind', 'ROUGH SMOOTH HALFSPACE', .true., word, s)
        select case (word)
        case ('ROUGH')
            st%m%ground%base = GROUND_BASE_ROUGH
        case ('SMOOTH')
            st%m%ground%base = GROUND_BASE_SMOOTH
        case ('HALFSPACE')
            st%m%ground%base = GROUND_BASE_HALFSPACE
        end select
        if (word == 'HALFSPACE' .or. s /= FIELD_OK) then
            call take_real(st, cd, 2, 'BASE E (Young''s modulus of the half-space below '// &
                           'the layers)', RULE_POSITIVE, word == 'HALFSPACE', st%m%ground%e_base)
            call take_real(st, cd, 3, 'BASE nu (Poisson''s ratio of the half-space below '// &
                           'the layers)', RULE_NU_SOIL, word == 'HALFSPACE', st%m%ground%nu_base)
        else
            call forbid_field(st, cd, 2, 'a rigid base has no modulus: BASE E must be blank '// &
                              'for '//trim(word))
            call forbid_field(st, cd, 3, 'a rigid base has no Poisson''s ratio: BASE nu '// &
                              'must be blank for '//trim(word))
        end if
        if (word == 'SMOOTH' .and. st%kind_known .and. st%m%structure%kind == MODEL_BEAM) &
            call field_error(st, cd, 1, 'a beam on layers over a SMOOTH base is not '// &
                'modelled: a net horizontal load would slide the layers on the base without '// &
                'bound (plane strain); use ROUGH or HALFSPACE E nu')
        call check_unused(st, cd, 3)
    end subroutine read_base

    !> SOIL or LAYER cards, never both; the layers need one BASE, after them; in a NONDIM
    !! deck the first LAYER's nu is blank or nu_f.
    subroutine check_ground_cards(st)
        type(state_t), intent(inout) :: st
        integer :: k, n_layers, last
        n_layers = size(st%layer_cards)
        if (n_layers > 0 .and. st%first_line(C_SOIL) > 0 .and. .not. st%m%nondim) &
            call card_error(st, st%cards(st%layer_cards(1)), 'LAYER cannot be combined '// &
                'with SOIL (line '//int_text(st%first_line(C_SOIL))//'): a deck gives either '// &
                'SOIL (a homogeneous half-space) or LAYER cards over a BASE')
        k = first_card(st, C_BASE)
        if (k > 0 .and. n_layers == 0 .and. missing(st, C_LAYER)) call card_error(st, &
            st%cards(k), 'BASE without LAYER cards: BASE ends a profile of LAYER cards '// &
            '(a homogeneous half-space is the SOIL card)')
        if (n_layers == 0) return
        last = st%layer_cards(n_layers)
        if (k == 0 .and. missing(st, C_BASE)) call card_error(st, st%cards(last), &
            'the LAYER cards need a BASE card after them (BASE ROUGH, BASE SMOOTH or '// &
            'BASE HALFSPACE E nu: what lies below the last layer)')
        if (k > 0) then
            if (k < last) call card_error(st, st%cards(last), 'LAYER after BASE (line '// &
                int_text(st%cards(k)%line)//'): the LAYER cards go from the surface down '// &
                'and BASE ends the profile')
        end if
        if (st%m%nondim .and. st%first_nu >= 0.0_dp .and. &
            st%first_nu /= st%m%ground%nu_f) call field_error(st, st%cards(st%layer_cards(1)), &
            3, 'in a NONDIM deck the top layer''s nu is the NONDIM card''s nu_f = '// &
            format_real(st%m%ground%nu_f)//': the first LAYER''s nu must be blank or equal '// &
            'to it, got '//format_real(st%first_nu))
    end subroutine check_ground_cards

    !> SWEEP names of the layered ground: they need LAYER cards, a layer that exists, a
    !! HALFSPACE base (E_BASE); E1 is not a NONDIM parameter and E_F not a layered one.
    subroutine check_layer_sweeps(st)
        type(state_t), intent(inout) :: st
        character(len=:), allocatable :: name
        integer :: s, p, n_layers, n
        n_layers = size(st%layer_cards)
        sweeps: do s = 1, size(st%sweeps)
            name = trim(st%sweeps(s)%name)
            p = sweep_index(name)
            if (p == 0) cycle sweeps
            n = sweep_layer(p)
            associate (cd => st%cards(st%sweep_cards(s)))
                if (name == 'E_F' .and. n_layers > 0) then
                    call field_error(st, cd, 1, 'SWEEP E_F is the SOIL card''s modulus; in '// &
                        'a layered deck sweep E1 (the top layer''s modulus)')
                else if (n == 0) then
                    cycle sweeps
                else if (n_layers == 0) then
                    call field_error(st, cd, 1, 'SWEEP '//name//' needs a layered ground '// &
                        '(LAYER cards and a BASE); this deck''s ground is one half-space')
                else if (n > n_layers) then
                    call field_error(st, cd, 1, 'SWEEP '//name//' names layer '// &
                        int_text(n)//'; the deck has '//int_text(n_layers)//' LAYER card(s)')
                else if (name == 'E1' .and. st%m%nondim) then
                    call field_error(st, cd, 1, 'SWEEP E1 is not a parameter of a NONDIM '// &
                        'deck: its moduli are relative to the top layer''s, which rho sets '// &
                        '(sweep RHO, or E2, E3 for the layers below)')
                else if (n == -2 .and. st%m%ground%base /= GROUND_BASE_HALFSPACE) then
                    call field_error(st, cd, 1, 'SWEEP E_BASE needs BASE HALFSPACE E nu '// &
                        '(a rigid base has no modulus)')
                else if (n == -1) then
                    call check_depth_sweep(st, cd, st%sweeps(s))
                end if
            end associate
        end do sweeps
    end subroutine check_layer_sweeps

    !> SWEEP DEPTH sets the last layer's thickness: not with a sweep of it, and below the
    !! layers above it.
    subroutine check_depth_sweep(st, cd, sw)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        type(sweep_t), intent(in) :: sw
        real(dp) :: above
        integer :: n, s, v
        n = size(st%layer_cards)
        do s = 1, size(st%sweeps)
            if (trim(st%sweeps(s)%name) == 'H'//int_text(n)) then
                call field_error(st, cd, 1, 'SWEEP DEPTH sets the last layer''s thickness; '// &
                    'it cannot be swept with H'//int_text(n)//' (line '// &
                    int_text(st%sweeps(s)%line)//')')
                return
            end if
        end do
        above = sum(st%m%ground%thickness(1:n - 1))
        do v = 1, size(sw%values)
            if (sw%values(v) > above) cycle
            call field_error(st, cd, v + 1, 'SWEEP DEPTH value v'//int_text(v)//' must '// &
                'be greater than the layers above the last, '//format_real(above)// &
                ' deep, got '//format_real(sw%values(v)))
        end do
    end subroutine check_depth_sweep

    !> NONDIM rho zeta nu nu_f beta (nu, nu_f default to the paper's 0.3, 0.1).
    subroutine read_nondim(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        call take_real(st, cd, 1, 'NONDIM rho (relative stiffness of structure and soil)', &
                       RULE_POSITIVE, .true., st%m%groups%rho)
        call take_real(st, cd, 2, 'NONDIM zeta (thickness ratio h/l or h/a)', RULE_POSITIVE, &
                       .true., st%m%groups%zeta)
        st%m%structure%nu = 0.3_dp
        st%m%ground%nu_f = 0.1_dp
        call take_real(st, cd, 3, 'NONDIM nu (Poisson''s ratio of the structure)', &
                       RULE_NU_STRUCTURE, .false., st%m%structure%nu)
        call take_real(st, cd, 4, 'NONDIM nu_f (Poisson''s ratio of the soil)', RULE_NU_SOIL, &
                       .false., st%m%ground%nu_f)
        if (st%kind_known .and. st%m%structure%kind == MODEL_PLATE) then
            call forbid_field(st, cd, 5, 'PLATE has no width: NONDIM beta must be blank')
        else
            call take_real(st, cd, 5, 'NONDIM beta (width ratio b/l of the beam)', &
                           RULE_POSITIVE, st%kind_known, st%m%groups%beta)
        end if
        call check_unused(st, cd, 5)
    end subroutine read_nondim

    !> FRICTION f eps_bar.
    subroutine read_friction(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        call take_real(st, cd, 1, 'FRICTION f (friction coefficient)', RULE_NONNEGATIVE, &
                       .true., st%m%interface%f)
        call take_real(st, cd, 2, 'FRICTION eps_bar (regularisation of the friction law)', &
                       RULE_OPEN_UNIT, .false., st%m%interface%eps_bar)
        call check_unused(st, cd, 2)
    end subroutine read_friction

    !> MESH N_e grading interp(u_s) interp(w) interp(psi) interp(sigma_x) interp(sigma_z).
    subroutine read_mesh(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=7), parameter :: field_label(5) = [character(len=7) :: 'u_s', 'w', &
                                                         'psi', 'sigma_x', 'sigma_z']
        character(len=field_width) :: word
        integer :: s, j
        call take_count(st, cd, 1, 'MESH N_e (number of elements)', RULE_ELEMENTS, .false., &
                        st%m%mesh%ne)
        ! grading words of mesh.f90 (new_mesh)
        call take_word(st, cd, 2, 'MESH grading', 'UNIFORM EDGES LOADS', .false., word, s)
        if (s == FIELD_OK) st%m%mesh%grading = word
        do j = 1, 5
            call take_word(st, cd, j + 2, 'MESH interpolation of '//trim(field_label(j)), &
                           'P1 P2 S2', .false., word, s)
            if (s == FIELD_OK) st%m%mesh%interp(j) = interp_code(word)
            if (s == FIELD_OK) st%m%mesh%interp_given = .true.
        end do
    end subroutine read_mesh

    !> ADAPT tol max_elements: refine the MESH card's mesh until the estimated error of every
    !! key result is below tol (relative to its scale, README "ADAPT") or the mesh has
    !! max_elements elements (default 1000).
    subroutine read_adapt(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        st%m%mesh%adapt_max_ne = default_adapt_max_ne
        call take_real(st, cd, 1, 'ADAPT tol (relative tolerance of the estimated errors)', &
                       RULE_OPEN_UNIT, .true., st%m%mesh%adapt_tol)
        call take_count(st, cd, 2, 'ADAPT max_elements (largest number of elements)', &
                        RULE_ELEMENTS, .false., st%m%mesh%adapt_max_ne)
        call check_unused(st, cd, 2)
    end subroutine read_adapt

    !> ADAPT may only refine: its max_elements is at least the MESH card's N_e.
    subroutine check_adapt(st)
        type(state_t), intent(inout) :: st
        integer :: k
        k = first_card(st, C_ADAPT)
        if (k == 0 .or. st%m%mesh%adapt_tol <= 0.0_dp) return
        ! no interpolation on the MESH card: S2 w and psi, whose uniform family is the
        ! cheapest to a tolerance (README, ADAPT)
        if (.not. st%m%mesh%interp_given) st%m%mesh%interp([FIELD_W, FIELD_PSI]) = INTERP_S2
        if (st%m%mesh%adapt_max_ne >= st%m%mesh%ne) return
        call field_error(st, st%cards(k), 2, 'ADAPT max_elements must be at least the MESH '// &
            'N_e = '//int_text(st%m%mesh%ne)//' it starts from, got '// &
                int_text(st%m%mesh%adapt_max_ne))
    end subroutine check_adapt

    !> SOLVER tol_outer tol_inner max_outer max_inner eta_bar tau0 method.
    subroutine read_solver(st, cd)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=field_width) :: word
        integer :: s
        call take_real(st, cd, 1, 'SOLVER tol_outer (tolerance of the friction loop)', &
                       RULE_POSITIVE, .false., st%m%solver%tol_outer)
        call take_real(st, cd, 2, 'SOLVER tol_inner (tolerance of the contact loop)', &
                       RULE_POSITIVE, .false., st%m%solver%tol_inner)
        call take_count(st, cd, 3, 'SOLVER max_outer (iterations of the friction loop)', &
                        RULE_COUNT, .false., st%m%solver%max_outer)
        call take_count(st, cd, 4, 'SOLVER max_inner (iterations of the contact loop)', &
                        RULE_COUNT, .false., st%m%solver%max_inner)
        call take_real(st, cd, 5, 'SOLVER eta_bar (penalty of the tension zone)', &
                       RULE_POSITIVE, .false., st%m%interface%eta_bar)
        call take_real(st, cd, 6, 'SOLVER tau0 (starting friction threshold, nondimensional)', &
                       RULE_POSITIVE, .false., st%m%solver%tau0_start)
        call take_word(st, cd, 7, 'SOLVER method', 'NEWTON TWOLOOP', .false., word, s)
        if (s == FIELD_OK) st%m%solver%method = merge(METHOD_TWOLOOP, METHOD_NEWTON, &
            word == 'TWOLOOP')
        call check_unused(st, cd, 7)
    end subroutine read_solver

    !> LOAD kind F_z F_x x1 x2; accepted (appended) only when the card has no error.
    subroutine read_load(st, k)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: k               !! card index
        character(len=field_width) :: word
        type(load_t) :: ld
        integer :: s, n_before
        call note_load_card(st%combos, .not. missing(st, C_LOADCASE), st%cards(k)%line, &
                            st%cards(k)%text, st%diag)
        n_before = st%diag%n
        associate (cd => st%cards(k))
            ld%line = cd%line
            call take_word(st, cd, 1, 'LOAD kind', 'POINT PATCH PRESSURE MOMENT RING RADIAL', &
                           .true., word, s)
            call read_load_numbers(st, cd, word, ld)
            if (s == FIELD_OK .and. st%kind_known) call check_load_on_model(st, cd, word, ld)
            call check_unused(st, cd, 5)
        end associate
        if (st%diag%n > n_before) then
            st%loads_ok = .false.
            return
        end if
        st%m%loads = [st%m%loads, ld]
        st%load_cards = [st%load_cards, k]
        call accept_load_card(st%combos)
    end subroutine read_load

    !> The numbers of a LOAD card; which are required depends on the kind.
    subroutine read_load_numbers(st, cd, word, ld)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=*), intent(in) :: word    !! load kind ('' if unreadable)
        type(load_t), intent(inout) :: ld
        logical :: patch
        patch = word == 'PATCH' .or. word == 'RADIAL' .or. word == 'PRESSURE'
        select case (word)
        case ('POINT', 'MOMENT')
            ld%kind = merge(LOAD_MOMENT, LOAD_POINT, word == 'MOMENT')
        case ('RING')
            ld%kind = LOAD_RING
        case default
            ld%kind = LOAD_PATCH
        end select
        if (word == 'PRESSURE') then
            call take_real(st, cd, 2, 'LOAD q_z (vertical load per unit length (beam) or area '// &
                           '(plate))', 0, .true., ld%fz)
            call take_real(st, cd, 3, 'LOAD q_x (horizontal load per unit length)', 0, .false., &
                           ld%fx)
        else if (word == 'RADIAL') then
            call take_real(st, cd, 2, 'LOAD F_z (total vertical force)', 0, .false., ld%fz)
            call take_real(st, cd, 3, 'LOAD F_x (total radial traction of the annulus)', 0, &
                           .true., ld%fx)
        else
            call take_real(st, cd, 2, 'LOAD F_z (total vertical force, or the moment)', 0, &
                           .true., ld%fz)
            call take_real(st, cd, 3, 'LOAD F_x (total horizontal force)', 0, .false., ld%fx)
        end if
        call take_real(st, cd, 4, 'LOAD x1 (position, or start of the patch)', 0, &
                       patch .or. word == 'RING', ld%x1)
        if (patch .or. len_trim(word) == 0) then
            call take_real(st, cd, 5, 'LOAD x2 (end of the patch)', 0, patch, ld%x2)
        else
            call forbid_field(st, cd, 5, 'LOAD x2 is used only by PATCH, PRESSURE and RADIAL; '// &
                              'it must be blank for '//trim(word))
        end if
    end subroutine read_load_numbers

    !> Loads the model cannot carry: horizontal force or moment on the plate, RING on a beam.
    subroutine check_load_on_model(st, cd, word, ld)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=*), intent(in) :: word
        type(load_t), intent(inout) :: ld
        if (word == 'MOMENT' .and. ld%fx /= 0.0_dp) call field_error(st, cd, 3, 'a MOMENT has '// &
            'no horizontal force: LOAD F_x must be blank or 0')
        if (word == 'RADIAL' .and. ld%fz /= 0.0_dp) call field_error(st, cd, 2, 'a RADIAL load '// &
            'is a radial top traction only: LOAD F_z must be blank or 0')
        if (word == 'PRESSURE') call pressure_to_patch(st%m%structure%kind, ld)
        if (st%m%structure%kind == MODEL_BEAM) then
            if (word == 'RING' .or. word == 'RADIAL') call field_error(st, cd, 1, trim(word)// &
                ' is a plate load; a beam takes POINT, PATCH or MOMENT')
            return
        end if
        if (word == 'MOMENT') then
            call field_error(st, cd, 1, 'an axisymmetric plate cannot carry an overturning '// &
                             'moment (MOMENT is a beam load): '//raft_not_modelled())
        else if (word /= 'RADIAL' .and. ld%fx /= 0.0_dp) then
            call field_error(st, cd, 3, 'an axisymmetric plate cannot carry a horizontal '// &
                'force: LOAD F_x must be blank or 0, got '//field_value(cd, 3)//'; '// &
                raft_not_modelled())
        end if
        if (word == 'POINT' .and. ld%x1 /= 0.0_dp) call field_error(st, cd, 4, 'a POINT load '// &
            'on the plate acts at the axis only: LOAD x1 must be blank or 0, got '// &
            field_value(cd, 4)//' (a load on the circle r = x1 is LOAD RING)')
        if (word == 'RADIAL') ld%fz = 0.0_dp
    end subroutine check_load_on_model

    !> What the refusal of an overturning moment or a horizontal force on the plate says: no
    !! card models it (a RADIAL traction has zero resultant, a square "beam" is a strip).
    pure function raft_not_modelled() result(text)
        character(len=:), allocatable :: text
        text = 'a circular raft under an overturning moment or a horizontal force is not '// &
               'modelled yet (the raft is axisymmetric, and no other card gives that load)'
    end function raft_not_modelled

    !> LOAD PRESSURE gives intensities; the model keeps a PATCH of the same totals: q (x2 - x1)
    !! on the beam (force per length), q pi (x2^2 - x1^2) on the plate (force per area).
    pure subroutine pressure_to_patch(kind, ld)
        integer, intent(in) :: kind
        type(load_t), intent(inout) :: ld
        real(dp) :: extent
        if (kind == MODEL_BEAM) then
            extent = ld%x2 - ld%x1
        else
            extent = pi*(ld%x2**2 - ld%x1**2)
        end if
        ld%fz = ld%fz*extent
        ld%fx = ld%fx*extent
    end subroutine pressure_to_patch

    !> SWEEP name v1 .. v6: accepted (appended) only when the card has no error.
    subroutine read_sweep(st, k)
        type(state_t), intent(inout) :: st
        integer, intent(in) :: k                !! card index
        character(len=field_width) :: word
        type(sweep_t) :: sw
        integer :: s, p, n_before
        n_before = st%diag%n
        associate (cd => st%cards(k))
            sw%line = cd%line
            call take_word(st, cd, 1, 'SWEEP parameter', sweepable_list(), .true., word, s)
            p = 0
            if (s == FIELD_OK) p = sweep_index(word)
            if (p > 0) call check_sweep_name(st, cd, p)
            sw%name = word
            call read_sweep_values(st, cd, p, sw)
        end associate
        if (st%diag%n > n_before) return
        st%sweeps = [st%sweeps, sw]
        st%sweep_cards = [st%sweep_cards, k]
    end subroutine read_sweep

    !> A sweepable name must suit the deck (NONDIM or physical, BEAM or PLATE) and be new.
    subroutine check_sweep_name(st, cd, p)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: p                !! index into sweep_names
        character(len=:), allocatable :: name
        integer :: s
        name = trim(sweep_names(p))
        if (sweep_decks(p) == 1 .and. .not. st%m%nondim) then
            call field_error(st, cd, 1, 'SWEEP '//name//' needs a NONDIM deck; this deck '// &
                             'gives physical data (sweep E, E_F, H, L, A or B instead)')
        else if (sweep_decks(p) == 2 .and. st%m%nondim) then
            call field_error(st, cd, 1, 'SWEEP '//name//' needs a physical deck; this deck '// &
                             'gives NONDIM groups (sweep RHO, ZETA or BETA instead)')
        else if (st%kind_known .and. sweep_models(p) /= 0 .and. &
                 sweep_models(p) /= st%m%structure%kind) then
            call field_error(st, cd, 1, 'SWEEP '//name//' does not apply to a '// &
                             trim(merge('BEAM ', 'PLATE', st%m%structure%kind == MODEL_BEAM))// &
                             ' deck'//sweep_hint(name))
        end if
        do s = 1, size(st%sweeps)
            if (trim(st%sweeps(s)%name) == name) call field_error(st, cd, 1, 'SWEEP '//name// &
                ' already given at line '//int_text(st%sweeps(s)%line))
        end do
    end subroutine check_sweep_name

    !> Suggestion for a sweep name of the other model.
    pure function sweep_hint(name) result(hint)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: hint
        select case (name)
        case ('L')
            hint = ' (the plate radius is A)'
        case ('A')
            hint = ' (the beam length is L)'
        case default
            hint = ' (a plate has no width)'
        end select
    end function sweep_hint

    !> Values v1.. of a SWEEP card: contiguous fields from f2, at least one, each in range.
    subroutine read_sweep_values(st, cd, p, sw)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: p                 !! index into sweep_names (0 if unknown)
        type(sweep_t), intent(inout) :: sw
        character(len=:), allocatable :: what
        real(dp) :: x
        integer :: j, s, first_blank, rule
        allocate (sw%values(0))
        first_blank = 0
        rule = 0
        if (p > 0) rule = sweep_rules(p)
        fields: do j = 2, max_fields
            what = 'SWEEP '//trim(sw%name)//' value v'//int_text(j - 1)
            call read_real_field(field_text(cd%text, j), x, s)
            if (s == FIELD_BLANK) then
                if (first_blank == 0) first_blank = j
                cycle fields
            end if
            if (first_blank > 0) then
                call field_error(st, cd, first_blank, 'SWEEP values fill v1, v2, ... without '// &
                                 'gaps; v'//int_text(first_blank - 1)//' is blank')
                first_blank = -1
            end if
            call take_real(st, cd, j, what, rule, .true., x, s)
            if (s == FIELD_OK) sw%values = [sw%values, x]
        end do fields
        if (first_blank == 2) call field_error(st, cd, 2, 'SWEEP needs at least one value: '// &
                                               'v1 is blank')
    end subroutine read_sweep_values

    ! ---------------------------------------------------------------------------------------
    ! Checks across cards
    ! ---------------------------------------------------------------------------------------

    !> Loads on the structure; in a NONDIM deck the vertical forces add up to 1.
    subroutine check_loads(st)
        type(state_t), intent(inout) :: st
        character(len=:), allocatable :: why
        real(dp) :: total
        integer :: k, field
        if (.not. (st%kind_known .and. st%length_known)) return
        do k = 1, size(st%m%loads)
            call load_position_problem(st%m, structure_length(st%m), st%m%loads(k), field, why)
            if (len(why) > 0) call field_error(st, st%cards(st%load_cards(k)), field, why)
        end do
        if (.not. (st%m%nondim .and. st%loads_ok .and. size(st%m%loads) > 0)) return
        total = sum(st%m%loads%fz, mask=st%m%loads%kind /= LOAD_MOMENT)
        if (abs(total - 1.0_dp) > unit_load_tol) call field_error(st, &
            st%cards(st%load_cards(1)), 2, 'in a NONDIM deck forces are in units of the '// &
            'total vertical load F, so the LOAD F_z must add up to 1; they add up to '// &
            format_real(total))
    end subroutine check_loads

    !> Physical sweeps of the length (L, A) must keep every load on the structure.
    subroutine check_sweep_lengths(st)
        type(state_t), intent(inout) :: st
        character(len=:), allocatable :: why
        integer :: s, v, k, field
        if (.not. st%kind_known .or. st%m%nondim) return
        sweeps: do s = 1, size(st%sweeps)
            if (trim(st%sweeps(s)%name) /= 'L' .and. trim(st%sweeps(s)%name) /= 'A') cycle sweeps
            do v = 1, size(st%sweeps(s)%values)
                loads: do k = 1, size(st%m%loads)
                    call load_position_problem(st%m, st%sweeps(s)%values(v), st%m%loads(k), &
                                               field, why)
                    if (len(why) == 0) cycle loads
                    call field_error(st, st%cards(st%sweep_cards(s)), v + 1, 'with '// &
                        trim(st%sweeps(s)%name)//' = '//format_real(st%sweeps(s)%values(v))// &
                        ' the LOAD of line '//int_text(st%m%loads(k)%line)//' is off the '// &
                        'structure: '//why)
                end do loads
            end do
        end do sweeps
    end subroutine check_sweep_lengths

    !> The number of SWEEP combinations stays below max_cases.
    subroutine check_case_total(st)
        type(state_t), intent(inout) :: st
        integer :: s, total
        total = max(1, combination_count(st%combos%set))    ! every combination at each point
        do s = 1, size(st%sweeps)
            total = total*size(st%sweeps(s)%values)
            if (total > max_cases) then
                call field_error(st, st%cards(st%sweep_cards(s)), 1, 'too many SWEEP '// &
                    'combinations (more than '//int_text(max_cases)//' cases)')
                return
            end if
        end do
    end subroutine check_case_total

    !> Length in the units of the load positions: l or a, 1 in a NONDIM deck.
    pure real(dp) function structure_length(m)
        type(model_t), intent(in) :: m
        structure_length = m%structure%length
        if (m%nondim) structure_length = 1.0_dp
    end function structure_length

    !> Why a load is not on the structure of the given length ('' if it is); field 4 or 5.
    pure subroutine load_position_problem(m, length, ld, field, why)
        type(model_t), intent(in) :: m               !! kind, nondim
        real(dp), intent(in) :: length               !! l (beam) or a (plate)
        type(load_t), intent(in) :: ld
        integer, intent(out) :: field                !! 4 (x1) or 5 (x2)
        character(len=:), allocatable, intent(out) :: why
        character(len=:), allocatable :: range, where
        real(dp) :: lo, hi
        if (m%structure%kind == MODEL_BEAM) then
            lo = -0.5_dp*length
            hi = 0.5_dp*length
            where = 'the beam'
            range = '[-l/2, l/2] = ['//format_real(lo)//', '//format_real(hi)//']'
        else
            lo = 0.0_dp
            hi = length
            where = 'the plate'
            range = '[0, a] = [0, '//format_real(hi)//']'
        end if
        if (m%nondim) range = range//' (NONDIM: in units of '// &
                              trim(merge('l', 'a', m%structure%kind == MODEL_BEAM))//')'
        why = ''
        field = 4
        if (.not. (ld%x1 >= lo .and. ld%x1 <= hi)) then
            why = 'LOAD x1 lies outside '//where//': must be in '//range//', got '// &
                  format_real(ld%x1)
        else if (ld%kind == LOAD_PATCH) then
            field = 5
            if (.not. (ld%x2 >= lo .and. ld%x2 <= hi)) then
                why = 'LOAD x2 lies outside '//where//': must be in '//range//', got '// &
                      format_real(ld%x2)
            else if (.not. ld%x2 > ld%x1) then
                why = 'LOAD x2 (end of the patch) must be greater than x1 = '// &
                      format_real(ld%x1)//', got '//format_real(ld%x2)
            end if
        end if
    end subroutine load_position_problem

    ! ---------------------------------------------------------------------------------------
    ! Sweeps
    ! ---------------------------------------------------------------------------------------

    !> Index of each sweep's value in case i (1-based; last sweep fastest).
    pure function case_indices(deck, i) result(pick)
        type(deck_t), intent(in) :: deck
        integer, intent(in) :: i
        integer, allocatable :: pick(:)
        integer :: s, rest, n
        allocate (pick(size(deck%sweeps)))
        rest = i - 1
        do s = size(deck%sweeps), 1, -1
            n = size(deck%sweeps(s)%values)
            pick(s) = mod(rest, n) + 1
            rest = rest/n
        end do
    end function case_indices

    !> Set one swept parameter (complete_model is applied afterwards).
    pure subroutine apply_sweep(m, name, v)
        type(model_t), intent(inout) :: m
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: v
        select case (trim(name))
        case ('RHO')
            m%groups%rho = v
        case ('ZETA')
            m%groups%zeta = v
        case ('BETA')
            m%groups%beta = v
        case ('NU')
            m%structure%nu = v
        case ('NU_F')
            m%ground%nu_f = v
        case ('F')
            m%interface%f = v
        case ('EPS_BAR')
            m%interface%eps_bar = v
        case ('ETA_BAR')
            m%interface%eta_bar = v
        case ('NE')
            if (abs(v) < real(huge(1), dp)) m%mesh%ne = nint(v)
        case ('K')
            m%structure%k_shear = v
        case ('E')
            m%structure%e = v
        case ('E_F')
            m%ground%e_f = v
        case ('H')
            m%structure%h = v
        case ('L', 'A')
            m%structure%length = v
        case ('B')
            m%structure%b = v
        case ('H1', 'H2', 'H3', 'E1', 'E2', 'E3', 'DEPTH', 'E_BASE')
            call apply_layer_sweep(m%ground, name, sweep_layer(sweep_index(name)), v)
        end select
    end subroutine apply_sweep

    !> Set a layered ground's swept parameter: Hn, En (n >= 1), DEPTH (n = -1), E_BASE (-2).
    pure subroutine apply_layer_sweep(g, name, n, v)
        type(ground_t), intent(inout) :: g
        character(len=*), intent(in) :: name
        integer, intent(in) :: n                 !! sweep_layer of the name
        real(dp), intent(in) :: v
        integer :: last
        last = layer_count(g)
        if (n > last) return
        if (n == -2) then
            g%e_base = v
        else if (n == -1) then
            if (last > 0) g%thickness(last) = v - sum(g%thickness(1:last - 1))
        else if (name(1:1) == 'H') then
            g%thickness(n) = v
        else
            g%e_top(n) = v
            if (n == 1) g%e_f = v
        end if
    end subroutine apply_layer_sweep

    !> The case's depth to the base below the layers above the last (SWEEP DEPTH).
    subroutine check_layer_depth(deck, m, sw, k, diag)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m
        type(sweep_t), intent(in) :: sw
        integer, intent(in) :: k                 !! value index
        type(diagnostics_t), intent(inout) :: diag
        character(len=:), allocatable :: echo
        integer :: c1, n
        n = layer_count(m%ground)
        if (n < 1) return
        if (m%ground%thickness(n) > 0.0_dp) return
        c1 = field_first_column(k + 1)
        echo = ''
        if (sw%line >= 1 .and. sw%line <= size(deck%lines)) echo = echo_text(deck%lines(sw%line))
        call add_diagnostic(diag, sw%line, c1, c1 + field_width - 1, 'SWEEP DEPTH value v'// &
            int_text(k)//' must be greater than the layers above the last, '// &
            format_real(sum(m%ground%thickness(1:n - 1)))//' deep, got '// &
            format_real(sw%values(k)), echo)
    end subroutine check_layer_depth

    !> Re-validate a swept value: its range and, for L/A, the load positions.
    subroutine check_swept_value(deck, m, sw, k, diag)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m           !! the case (kind, nondim, loads)
        type(sweep_t), intent(in) :: sw
        integer, intent(in) :: k                 !! value index
        type(diagnostics_t), intent(inout) :: diag
        character(len=:), allocatable :: why, echo
        integer :: p, c1, field, l
        p = sweep_index(sw%name)
        c1 = field_first_column(k + 1)
        echo = ''
        if (sw%line >= 1 .and. sw%line <= size(deck%lines)) echo = echo_text(deck%lines(sw%line))
        if (p == 0) then
            call add_diagnostic(diag, sw%line, 11, 20, 'unknown SWEEP parameter '''// &
                                trim(sw%name)//'''', echo)
            return
        end if
        if (.not. rule_ok(sweep_rules(p), sw%values(k))) call add_diagnostic(diag, sw%line, &
            c1, c1 + field_width - 1, 'SWEEP '//trim(sw%name)//' value v'//int_text(k)//' '// &
            rule_text(sweep_rules(p))//', got '//format_real(sw%values(k)), echo)
        if (m%nondim .or. (trim(sw%name) /= 'L' .and. trim(sw%name) /= 'A')) return
        if (.not. allocated(m%loads)) return
        do l = 1, size(m%loads)
            call load_position_problem(m, sw%values(k), m%loads(l), field, why)
            if (len(why) > 0) call add_diagnostic(diag, sw%line, c1, c1 + field_width - 1, &
                'with '//trim(sw%name)//' = '//format_real(sw%values(k))//' the LOAD of line '// &
                int_text(m%loads(l)%line)//' is off the structure: '//why, echo)
        end do
    end subroutine check_swept_value

    !> The text of value k as written in the deck (formatted if the line is not available).
    function sweep_value_text(deck, sw, k) result(text)
        type(deck_t), intent(in) :: deck
        type(sweep_t), intent(in) :: sw
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        real(dp) :: x
        integer :: s
        text = format_real(sw%values(k))
        if (sw%line < 1 .or. sw%line > size(deck%lines) .or. k + 1 > max_fields) return
        call read_real_field(field_text(deck%lines(sw%line), k + 1), x, s)
        if (s == FIELD_OK .and. x == sw%values(k)) &
            text = trim(adjustl(field_text(deck%lines(sw%line), k + 1)))
    end function sweep_value_text

    !> Index of a sweepable name; 0 if unknown.
    pure integer function sweep_index(name)
        character(len=*), intent(in) :: name   !! upper-case SWEEP name
        sweep_index = name_index(name, sweep_names)
    end function sweep_index

    !> The sweepable names, blank-separated.
    pure function sweepable_list() result(list)
        character(len=:), allocatable :: list
        integer :: p
        list = trim(sweep_names(1))
        do p = 2, n_sweepable
            list = list//' '//trim(sweep_names(p))
        end do
    end function sweepable_list

    ! ---------------------------------------------------------------------------------------
    ! Fields of a card
    ! ---------------------------------------------------------------------------------------

    !> A numeric field with a range rule: blank keeps `value` (the default) unless required.
    !! status: FIELD_OK (value set), FIELD_BLANK (default kept) or FIELD_BAD (error recorded).
    subroutine take_real(st, cd, j, what, rule, required, value, status)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j                 !! field number 1..7
        character(len=*), intent(in) :: what     !! 'STRUCTURE nu (Poisson''s ratio ...)'
        integer, intent(in) :: rule              !! RULE_*, 0 for any finite number
        logical, intent(in) :: required          !! blank is an error
        real(dp), intent(inout) :: value         !! default in, value out
        integer, intent(out), optional :: status
        real(dp) :: x
        integer :: s
        call read_real_field(field_text(cd%text, j), x, s)
        if (s == FIELD_BAD .and. index(field_value(cd, j), ' ') > 0) then
            call field_error(st, cd, j, what//': expected one number, got '''// &
                             field_value(cd, j)//'''; '//field_hint)
        else if (s == FIELD_BAD .or. s == FIELD_RANGE) then
            call field_error(st, cd, j, what//': '//number_problem(s, field_value(cd, j)))
            s = FIELD_BAD
        else if (s == FIELD_BLANK .and. required) then
            call field_error(st, cd, j, what//' is required but the field is blank '// &
                             '(there is no default)')
            s = FIELD_BAD
        else if (s == FIELD_OK) then
            if (rule_ok(rule, x)) then
                value = x
            else
                call field_error(st, cd, j, what//' '//rule_text(rule)//', got '// &
                                 field_value(cd, j))
                s = FIELD_BAD
            end if
        end if
        if (present(status)) status = s
    end subroutine take_real

    !> A whole-number field (read like F10.0, then required to be whole by the rule).
    subroutine take_count(st, cd, j, what, rule, required, value)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j, rule
        character(len=*), intent(in) :: what
        logical, intent(in) :: required
        integer, intent(inout) :: value          !! default in, value out
        real(dp) :: x
        integer :: s
        x = real(value, dp)
        call take_real(st, cd, j, what, rule, required, x, s)
        if (s == FIELD_OK) value = nint(x)
    end subroutine take_count

    !> A one-word field, upper case, one of `allowed` (blank-separated; '' for any word).
    subroutine take_word(st, cd, j, what, allowed, required, word, status)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j
        character(len=*), intent(in) :: what, allowed
        logical, intent(in) :: required
        character(len=field_width), intent(out) :: word   !! '' unless FIELD_OK
        integer, intent(out) :: status
        call read_word_field(field_text(cd%text, j), word, status)
        if (status == FIELD_BLANK .and. required) then
            call field_error(st, cd, j, what//' is required but the field is blank '// &
                             '(expected '//comma_list(allowed)//')')
            status = FIELD_BAD
        else if (status == FIELD_BAD) then
            call field_error(st, cd, j, what//' must be one word, got '''// &
                             field_value(cd, j)//'''')
        else if (status == FIELD_OK .and. len(allowed) > 0) then
            if (index(' '//allowed//' ', ' '//trim(word)//' ') == 0) then
                call field_error(st, cd, j, what//' must be '//comma_list(allowed)//', got '''// &
                                 field_value(cd, j)//'''')
                status = FIELD_BAD
            end if
        end if
        if (status /= FIELD_OK) word = ''
    end subroutine take_word

    !> A unit label (one word, case kept); blank keeps the default.
    subroutine take_label(st, cd, j, what, label)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j
        character(len=*), intent(in) :: what
        character(len=*), intent(inout) :: label
        character(len=field_width) :: word, this, next
        integer :: s
        this = field_text(cd%text, j)
        call read_word_field(this, word, s)
        next = ''
        if (j < max_fields) next = field_text(cd%text, j + 1)
        if (this(field_width:field_width) /= ' ' .and. next(1:1) /= ' ') then
            ! a longer word would be cut at the field's end and its tail read as the next
            ! field (UNITS kilonewtonsm: 'kilonewton' and 'sm')
            call field_error(st, cd, j, what//' runs past column '// &
                             int_text(field_first_column(j) + field_width - 1)// &
                             ' into the next field ('''//trim(field_value(cd, j))// &
                             trim(next)//'''...): a label has at most 10 characters')
        else if (s == FIELD_BAD) then
            call field_error(st, cd, j, what//' must be one word, got '''// &
                             field_value(cd, j)//'''')
        else if (s == FIELD_OK) then
            label = adjustl(field_text(cd%text, j))
        end if
    end subroutine take_label

    !> A field that must be blank for this card.
    subroutine forbid_field(st, cd, j, why)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j
        character(len=*), intent(in) :: why
        if (len_trim(field_text(cd%text, j)) > 0) call field_error(st, cd, j, why// &
            ', found '''//field_value(cd, j)//'''')
    end subroutine forbid_field

    !> Fields beyond the n_used of the card must be blank.
    subroutine check_unused(st, cd, n_used)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: n_used
        integer :: j, c1
        do j = n_used + 1, max_fields
            c1 = field_first_column(j)
            if (len_trim(field_text(cd%text, j)) > 0) call field_error(st, cd, j, &
                trim(card_names(cd%id))//' has '//int_text(n_used)//' field(s); columns '// &
                int_text(c1)//'-'//int_text(c1 + field_width - 1)//' must be blank, found '''// &
                field_value(cd, j)//'''')
        end do
    end subroutine check_unused

    !> The text of field j, trimmed (for messages).
    pure function field_value(cd, j) result(text)
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j
        character(len=:), allocatable :: text
        text = trim(adjustl(echo_text(field_text(cd%text, j))))
    end function field_value

    !> 'A B C' -> 'A, B or C'.
    pure function comma_list(words) result(text)
        character(len=*), intent(in) :: words
        character(len=:), allocatable :: text, rest, word
        integer :: p, n
        text = ''
        rest = trim(adjustl(words))
        n = 0
        split: do while (len(rest) > 0)
            p = index(rest, ' ')
            if (p == 0) p = len(rest) + 1
            word = rest(1:p - 1)
            rest = trim(adjustl(rest(min(p, len(rest)) + 1:)))
            if (n == 0) then
                text = word
            else if (len(rest) == 0) then
                text = text//' or '//word
            else
                text = text//', '//word
            end if
            n = n + 1
        end do split
        if (n == 0) text = 'any word'
    end function comma_list

    ! ---------------------------------------------------------------------------------------
    ! Errors
    ! ---------------------------------------------------------------------------------------

    !> Error on field j of a card.
    subroutine field_error(st, cd, j, text)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        integer, intent(in) :: j
        character(len=*), intent(in) :: text
        integer :: c1
        c1 = field_first_column(j)
        call add_diagnostic(st%diag, cd%line, c1, c1 + field_width - 1, text, echo_text(cd%text))
    end subroutine field_error

    !> Error on the name (columns 1-10) of a card.
    subroutine card_error(st, cd, text)
        type(state_t), intent(inout) :: st
        type(card_t), intent(in) :: cd
        character(len=*), intent(in) :: text
        call add_diagnostic(st%diag, cd%line, 1, name_width, text, echo_text(cd%text))
    end subroutine card_error

    !> Error of the deck as a whole (no line).
    subroutine deck_error(st, text)
        type(state_t), intent(inout) :: st
        character(len=*), intent(in) :: text
        call add_diagnostic(st%diag, 0, 0, 0, text, '')
    end subroutine deck_error

    !> Index of the first card of a kind; 0 if absent.
    pure integer function first_card(st, id)
        type(state_t), intent(in) :: st
        integer, intent(in) :: id
        integer :: k
        first_card = 0
        do k = st%n, 1, -1
            if (st%cards(k)%id == id) first_card = k
        end do
    end function first_card

    !> A line made safe to print, one character a column: control characters and non-ASCII
    !! bytes shown as '?', trailing blanks removed.
    pure function echo_text(text) result(echo)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: echo
        integer :: c
        echo = trim(text(1:min(len(text), max_line_kept)))
        do c = 1, len(echo)
            if (iachar(echo(c:c)) < 32 .or. iachar(echo(c:c)) > 126) echo(c:c) = '?'
        end do
    end function echo_text

    ! ---------------------------------------------------------------------------------------
    ! Files
    ! ---------------------------------------------------------------------------------------

    !> File stem: directory and last extension removed ('input/default.dat' -> 'default').
    pure function stem_of(path) result(stem)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: stem
        integer :: p
        stem = trim(path(index(path, '/', back=.true.) + 1:))
        p = index(stem, '.', back=.true.)
        if (p > 1) stem = stem(1:p - 1)
        if (len(stem) == 0) stem = 'deck'
    end function stem_of

    !> All lines of a deck opened for stream input: the bytes split at LF only (a CR before
    !! the LF, a DOS line end, is dropped; a lone CR stays in its line, where it is an error
    !! with its column, instead of silently ending a record as a formatted read would). A line
    !! is kept up to max_line_kept + 1 characters (longer is an error).
    subroutine read_all_lines(u, raw, n, ios, msg)
        integer, intent(in) :: u
        type(text_line_t), allocatable, intent(out) :: raw(:)
        integer, intent(out) :: n               !! lines read
        integer, intent(out) :: ios             !! 0, or the failing iostat
        character(len=*), intent(inout) :: msg  !! iomsg on failure
        character(len=:), allocatable :: bytes
        integer(int64) :: size_bytes
        integer :: start, stop_at, k
        n = 0
        allocate (raw(0))
        inquire (unit=u, size=size_bytes)
        if (size_bytes > max_deck_bytes) then
            ios = 1
            msg = 'larger than '//int_text(int(max_deck_bytes/1000000))//' MB: not a deck'
            return
        end if
        if (size_bytes <= 0) then
            ios = 0
            return
        end if
        allocate (character(len=size_bytes) :: bytes)
        read (u, iostat=ios, iomsg=msg) bytes
        if (ios /= 0) return
        k = count_lines(bytes)
        if (k > max_lines) then
            ios = 1
            msg = 'more than '//int_text(max_lines)//' lines: not a deck'
            return
        end if
        deallocate (raw)
        allocate (raw(k))
        start = 1
        lines: do n = 1, k
            stop_at = index(bytes(start:), achar(10))
            if (stop_at == 0) then
                stop_at = len(bytes) + 1
            else
                stop_at = start + stop_at - 1
            end if
            raw(n)%text = bytes(start:min(stop_at - 1, start + max_line_kept))
            if (stop_at - 1 >= start .and. stop_at - 1 <= start + max_line_kept) then
                if (bytes(stop_at - 1:stop_at - 1) == achar(13)) &
                    raw(n)%text = bytes(start:stop_at - 2)          ! CR LF
            end if
            start = stop_at + 1
        end do lines
        n = k
    end subroutine read_all_lines

    !> Lines of a text: the LFs, plus one for a last line without LF.
    pure integer function count_lines(bytes) result(k)
        character(len=*), intent(in) :: bytes
        integer :: i
        k = 0
        do i = 1, len(bytes)
            if (bytes(i:i) == achar(10)) k = k + 1
        end do
        if (len(bytes) > 0) then
            if (bytes(len(bytes):len(bytes)) /= achar(10)) k = k + 1
        end if
    end function count_lines
end module deck_reader
