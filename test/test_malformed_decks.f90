!> Malformed decks (doc/ERRORS.md): every file in test/data/malformed/ is read with the
!! public API (read_deck) and must be refused with EXIT_INPUT, a message naming the deck, its
!! first error at the line and columns where the fault really is (`path:LINE:COLS: text`,
!! worked out by hand from the deck: columns 1-10 the card name, f1 = 11-20, f2 = 21-30,
!! f3 = 31-40, f4 = 41-50, f5 = 51-60, f6 = 61-70, f7 = 71-80; README "Card layout"), and a
!! fragment of the explanation. Every deck also goes through the program's own path (read,
!! then run_analysis only if the deck parsed) into a fresh output folder that must stay empty.
!! Two decks are made at test time: a directory and an unreadable (chmod 000) file.
!!
!! Line numbers: each deck file starts with a comment card saying what is wrong (line 1) and
!! the column ruler (line 2), then the cards of one of three base decks (kept below as
!! base_beam, base_plate, base_nondim and checked to parse). In base_beam, line 3 is TITLE,
!! 4 MODEL, 5 UNITS, 6 GEOMETRY, 7 STRUCTURE, 8 SOIL, 9 FRICTION, 10 LOAD, 11 MESH, 12 END;
!! base_plate has the same lines; in base_nondim, 3 TITLE, 4 MODEL, 5 NONDIM, 6 FRICTION,
!! 7 LOAD, 8 MESH, 9 END. A deck that inserts a card shifts the lines after it.
module test_malformed_decks
    use harness, only: unittest_t, new_unittest, error_t, check
    use errors, only: EXIT_INPUT
    use deck_reader, only: deck_t, read_deck, parse_deck, case_count
    use deck_fields, only: rule_text, RULE_POSITIVE, RULE_STATIONS, RULE_COUNT, RULE_ELEMENTS, &
                           RULE_OPEN_UNIT
    use analysis_driver, only: run_analysis
    implicit none
    private
    public :: collect_malformed_decks, write_lines

    character(len=*), parameter :: dir = 'test/data/malformed/'   !! the deck files
    character(len=*), parameter :: out_root = 'build/malformed_out'   !! fresh output folders
    character(len=*), parameter :: dir_deck = 'build/malformed_dir.dat/'   !! made at test time
    character(len=*), parameter :: locked_deck = 'build/malformed_unreadable.dat'
    character(len=1), parameter :: nl = new_line('a')
    character(len=*), parameter :: ruler = '*...+....1....+....2....+....3....+....4....+'// &
                                           '....5....+....6....+....7....+....8'

    !> One malformed deck and its expected first error.
    type :: expect_t
        character(len=12) :: group = ''   !! test that checks it
        character(len=32) :: file = ''    !! name in test/data/malformed/
        character(len=12) :: where = ''   !! ':LINE:COLS:' after the path; ':' for a whole-deck
                                          !! error (no line); the message has a blank after it
        character(len=110) :: what = ''   !! fragment of the explanation
    end type expect_t

    integer, parameter :: n_decks = 113

contains

    subroutine collect_malformed_decks(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('base_decks_parse', test_base_decks), &
                 new_unittest('all_files_listed', test_all_listed), &
                 new_unittest('truncated_cards', test_truncated), &
                 new_unittest('fields_in_wrong_columns', test_columns), &
                 new_unittest('bad_numbers', test_numbers), &
                 new_unittest('bad_counts', test_counts), &
                 new_unittest('adapt_card', test_adapt), &
                 new_unittest('tab_and_non_ascii', test_characters), &
                 new_unittest('long_lines', test_lines), &
                 new_unittest('end_duplicate_conflicting', test_card_set), &
                 new_unittest('not_a_deck', test_not_a_deck), &
                 new_unittest('missing_data', test_missing), &
                 new_unittest('out_of_range', test_ranges), &
                 new_unittest('loads', test_loads), &
                 new_unittest('load_combinations', test_combinations), &
                 new_unittest('sweeps', test_sweeps), &
                 new_unittest('layered_ground', test_ground), &
                 new_unittest('check_cards', test_check_cards), &
                 new_unittest('lone_cr_in_card', test_lone_cr), &
                 new_unittest('too_many_lines', test_too_many_lines), &
                 new_unittest('directory', test_directory), &
                 new_unittest('unreadable_file', test_unreadable), &
                 new_unittest('no_output_written', test_no_output), &
                 new_unittest('rules_documented', test_rules_documented)]
    end subroutine collect_malformed_decks

    ! ------------------------------------------------------------------------------------
    ! The table: one row a deck. `where` is worked out from the deck's own columns (the
    ! comment of each row says which card and field); `what` is the start or a telling part
    ! of the explanation.
    ! ------------------------------------------------------------------------------------

    function expected() result(t)
        type(expect_t) :: t(n_decks)
        integer :: k
        k = 0
        ! --- truncated cards and files
        ! line 7 'STRUCTURE 30.0E6': nu (f2, columns 21-30) is blank and required
        call add('truncated', 'truncated_structure.dat', ':7:21-30:', &
                 "STRUCTURE nu (Poisson's ratio of the structure) is required but the field "// &
                 "is blank")
        ! line 7 'STRUCT    30.0E6    0.2': the name in columns 1-6 is no card
        call add('truncated', 'truncated_name.dat', ':7:1-6:', "unknown card 'STRUCT'")
        ! line 10 'LOAD      POI' (last line, no newline): the kind in f1, columns 11-20
        call add('truncated', 'truncated_file.dat', ':10:11-20:', &
                 "LOAD kind must be POINT, PATCH, PRESSURE, MOMENT, RING or RADIAL, got 'POI'")
        ! line 6 GEOMETRY: h in f2 (columns 21-30) cut to '0.', which reads as 0
        call add('truncated', 'truncated_number.dat', ':6:21-30:', &
                 'GEOMETRY h (thickness of the structure) must be > 0, got 0.')
        ! --- fields in the wrong columns
        ! line 7: '30.0E6' in columns 17-22, so f1 (11-20) is '30.0' and f2 (21-30) 'E6    0.2'
        call add('columns', 'field_straddles.dat', ':7:21-30:', &
                 "STRUCTURE nu (Poisson's ratio of the structure): expected one number, got "// &
                 "'E6    0.2'")
        ! line 5 'UNITS     kilonewtonsm': f1 (columns 11-20) 'kilonewton' runs into f2 'sm'
        call add('columns', 'label_straddles.dat', ':5:11-20:', &
                 'UNITS force label runs past column 20 into the next field')
        ! line 6 '  GEOMETRY ...': the name starts in column 3; columns 3-10 marked
        call add('columns', 'name_indented.dat', ':6:3-10:', &
                 "card name 'GEOMETRY' starts in column 3")
        ! line 6 'GEOMETRY10.0 ...': columns 1-10 read 'GEOMETRY10'
        call add('columns', 'name_runs_into_field.dat', ':6:1-10:', "unknown card 'GEOMETRY10'")
        ! line 6 'GEOMETRY 10.0 0.5 1.0': the '1' of 10.0 sits in column 10 (name columns)
        call add('columns', 'free_format_name.dat', ':6:10:', &
                 "GEOMETRY: text '1' in columns 10-10 belongs in the fields")
        ! line 7 'STRUCTURE 30.0E6 0.2': f1 (columns 11-20) is '30.0E6 0.2'
        call add('columns', 'free_format_fields.dat', ':7:11-20:', &
                 "expected one number, got '30.0E6 0.2'; fields are 10 columns wide")
        ! line 8 'SOIL      40.0E3,0.3': f1 (columns 11-20) is '40.0E3,0.3'
        call add('columns', 'comma_separated.dat', ':8:11-20:', &
                 "SOIL E_f (Young's modulus of the soil): expected a finite number such as 0.3")
        ! line 9 (inserted): columns 1-10 blank, numbers in f1 and f2
        call add('columns', 'field_blank_name.dat', ':9:1-10:', &
                 'card name missing: columns 1-10 are blank but the card has fields')
        ! --- numbers
        ! line 8 SOIL: E_f (f1, columns 11-20) is '1.2.3'
        call add('numbers', 'number_1.2.3.dat', ':8:11-20:', &
                 "expected a finite number such as 0.3, 30.0E6 or 1.0D-6, got '1.2.3'")
        ! line 7 STRUCTURE: E (f1, columns 11-20) is 'NaN'
        call add('numbers', 'number_nan.dat', ':7:11-20:', &
                 "STRUCTURE E (Young's modulus of the structure): expected a finite number")
        ! line 9 FRICTION: f (f1, columns 11-20) is 'Inf'
        call add('numbers', 'number_inf.dat', ':9:11-20:', &
                 "FRICTION f (friction coefficient): expected a finite number such as 0.3")
        ! line 6 GEOMETRY: l (f1, columns 11-20) is '1e999'
        call add('numbers', 'number_1e999.dat', ':6:11-20:', &
                 "a deck number is 0 or has a magnitude of at least 1E-30 and below 1E+30, "// &
                     "got '1e999'")
        ! line 8 SOIL: nu_f (f2, columns 21-30) is '1e-999'
        call add('numbers', 'number_1e-999.dat', ':8:21-30:', &
                 "a deck number is 0 or has a magnitude of at least 1E-30 and below 1E+30, "// &
                     "got '1e-999'")
        ! line 10 LOAD: F_z (f2, columns 21-30) is 'E5'
        call add('numbers', 'number_exponent_only.dat', ':10:21-30:', &
                 "LOAD F_z (total vertical force, or the moment): expected a finite number")
        ! line 10 LOAD: F_x (f3, columns 31-40) is '10*10'
        call add('numbers', 'number_fortran_star.dat', ':10:31-40:', &
                 "LOAD F_x (total horizontal force): expected a finite number")
        ! --- counts (MESH N_e f1, SOLVER max_outer f3, OUTPUT stations f1)
        ! line 11 MESH: N_e (f1, columns 11-20) is 1e9
        call add('counts', 'mesh_ne_1e9.dat', ':11:11-20:', &
                 'MESH N_e (number of elements) must be a whole number in [1, 100000], got 1e9')
        ! line 11 MESH: N_e is -20
        call add('counts', 'mesh_ne_negative.dat', ':11:11-20:', &
                 'MESH N_e (number of elements) must be a whole number in [1, 100000], got -20')
        ! line 11 MESH: N_e is 0
        call add('counts', 'mesh_ne_zero.dat', ':11:11-20:', &
                 'MESH N_e (number of elements) must be a whole number in [1, 100000], got 0')
        ! line 11 MESH: N_e is 20.5
        call add('counts', 'mesh_ne_fraction.dat', ':11:11-20:', &
                 'must be a whole number in [1, 100000], got 20.5')
        ! line 12 (inserted SOLVER): max_outer (f3, columns 31-40) is -100
        call add('counts', 'solver_negative_count.dat', ':12:31-40:', &
                 'SOLVER max_outer (iterations of the friction loop) must be a whole number')
        ! line 12 (inserted OUTPUT): stations (f1, columns 11-20) is 1
        call add('counts', 'output_stations_one.dat', ':12:11-20:', &
                 'must be a whole number in [2, 100000], got 1')
        ! line 12 (inserted OUTPUT): stations is -5
        call add('counts', 'output_stations_negative.dat', ':12:11-20:', &
                 'must be a whole number in [2, 100000], got -5')
        ! --- ADAPT (line 12, inserted after MESH 20 on line 11)
        ! tol (f1, columns 11-20) = 0.0
        call add('adapt', 'adapt_tol_zero.dat', ':12:11-20:', &
                 'ADAPT tol (relative tolerance of the estimated errors) must be in (0, 1), '// &
                     'got 0.0')
        ! tol (f1, columns 11-20) blank
        call add('adapt', 'adapt_tol_missing.dat', ':12:11-20:', &
                 'ADAPT tol (relative tolerance of the estimated errors) is required but the '// &
                 'field is blank')
        ! max_elements (f2, columns 21-30) = 10 below MESH N_e = 20
        call add('adapt', 'adapt_max_below_ne.dat', ':12:21-30:', &
                 'ADAPT max_elements must be at least the MESH N_e = 20 it starts from, got 10')
        ! --- characters
        ! line 4 'MODEL<TAB>BEAM': the TAB is column 6
        call add('characters', 'tab_in_card.dat', ':4:6:', 'TAB character in column 6')
        ! line 3 '*<TAB>this comment ...': the TAB is column 2
        call add('characters', 'tab_in_comment.dat', ':3:2:', &
                 'in a comment (column 2): use blanks')
        ! line 3 'TITLE     Funda' is 15 columns; the first UTF-8 byte of c-cedilla is 16
        call add('characters', 'non_ascii_title.dat', ':3:16:', 'non-ASCII character in column 16')
        ! line 7 'STRUCTURE 30.0E6' is 16 columns; the no-break space starts in column 17
        call add('characters', 'non_ascii_nbsp.dat', ':7:17:', 'non-ASCII character in column 17')
        ! line 5 'UNITS     kN        ' is 20 columns; the Latin-1 micro sign is column 21
        call add('characters', 'latin1_micro.dat', ':5:21:', 'non-ASCII character in column 21')
        ! line 6 'GEOMETRY  10.0' is 14 columns; the NUL byte is column 15
        call add('characters', 'nul_byte.dat', ':6:15:', &
                 'control character (code 0) in column 15')
        ! gzip data: 34 of its 52 bytes are not printable text, one message for the file (not
        ! one per line, each echoing the bytes)
        call add('characters', 'binary_garbage.dat', ': ', 'not a text file')
        ! a BOM, then zip bytes: 10 of its 48 bytes are control characters, one message for
        ! the file (a UTF-8 text deck has none, or a stray one reported at its line and column)
        call add('characters', 'bom_then_garbage.dat', ': ', 'not a text file')
        ! --- lines
        ! line 3 TITLE: 95 columns, columns 81-95 marked
        call add('lines', 'line_over_80.dat', ':3:81-95:', &
                 'card is 95 columns long; a card has at most 80 columns')
        ! line 3 TITLE: 2000 columns; the reader keeps 1024, columns 81-1024 marked
        call add('lines', 'line_over_1024.dat', ':3:81-1024:', &
                 'card is more than 1024 columns long')
        ! line 3: a comment of 90 characters, columns 81-90 marked
        call add('lines', 'comment_over_80.dat', ':3:81-90:', 'comment is 90 characters long')
        ! --- END, duplicate and conflicting cards
        ! no END: a whole-deck error naming the last line (11, the MESH card)
        call add('card_set', 'missing_end.dat', ':', &
                 'missing END card (the deck ends at line 11 without END)')
        ! line 12 MESH after END (line 11): the whole card, columns 1-72 (its last P1 ends in 72)
        call add('card_set', 'card_after_end.dat', ':12:1-72:', 'card after END (line 11)')
        ! line 8 (inserted) second STRUCTURE: name columns 1-9
        call add('card_set', 'duplicate_structure.dat', ':8:1-9:', &
                 'duplicate STRUCTURE card (first given at line 7)')
        ! line 5 (inserted) second MODEL: name columns 1-5
        call add('card_set', 'duplicate_model.dat', ':5:1-5:', &
                 'duplicate MODEL card (first given at line 4)')
        ! line 6 (inserted) GEOMETRY in a NONDIM deck (NONDIM on line 5): name columns 1-10
        call add('card_set', 'nondim_and_geometry.dat', ':6:1-10:', &
                 'GEOMETRY cannot be combined with NONDIM (line 5)')
        ! line 5 UNITS is the first physical card; NONDIM comes on line 8
        call add('card_set', 'nondim_after_soil.dat', ':5:1-10:', &
                 'UNITS cannot be combined with NONDIM (line 8)')
        ! line 12 'END OF DECK': 'OF DEC' fills columns 5-10 of the name
        call add('card_set', 'end_with_text.dat', ':12:5-10:', &
                 "END: text 'OF DEC' in columns 5-10 belongs in the fields")
        ! line 3 '# fricon deck ...': column 1 is '#'
        call add('card_set', 'hash_comment.dat', ':3:1:', '(# and ! are not comment marks)')
        ! line 8 (inserted) 'MATERIAL  CONCRETE': name columns 1-8
        call add('card_set', 'unknown_card.dat', ':8:1-8:', "unknown card 'MATERIAL'")
        ! --- files that are no deck (whole-deck errors: no line)
        call add('not_a_deck', 'empty.dat', ':', 'the deck is empty')
        ! three blank lines: no card at all; the first whole-deck error is the missing MODEL
        call add('not_a_deck', 'blank_lines_only.dat', ':', 'missing MODEL card')
        call add('not_a_deck', 'comments_only.dat', ':', 'missing MODEL card')
        ! --- missing required data
        ! line 8 SOIL: E_f (f1, columns 11-20) blank
        call add('missing', 'missing_required_field.dat', ':8:11-20:', &
                 "SOIL E_f (Young's modulus of the soil) is required but the field is blank")
        ! line 10 LOAD: kind (f1, columns 11-20) blank
        call add('missing', 'missing_load_kind.dat', ':10:11-20:', &
                 'LOAD kind is required but the field is blank')
        call add('missing', 'missing_friction.dat', ':', 'missing FRICTION card')
        call add('missing', 'missing_model.dat', ':', 'missing MODEL card')
        ! line 5 NONDIM of a beam: beta (f5, columns 51-60) blank
        call add('missing', 'nondim_beta_missing.dat', ':5:51-60:', &
                 'NONDIM beta (width ratio b/l of the beam) is required but the field is blank')
        ! --- out of range
        ! line 7 STRUCTURE: nu (f2, columns 21-30) = 0.5
        call add('ranges', 'nu_half.dat', ':7:21-30:', &
                 "STRUCTURE nu (Poisson's ratio of the structure) must be in [0, 0.5), got 0.5")
        ! line 8 SOIL: nu_f (f2, columns 21-30) = 0.6
        call add('ranges', 'nu_f_06.dat', ':8:21-30:', &
                 "SOIL nu_f (Poisson's ratio of the soil) must be in [0, 0.5]")
        ! line 9 FRICTION: f (f1, columns 11-20) = -0.1
        call add('ranges', 'friction_negative.dat', ':9:11-20:', &
                 'FRICTION f (friction coefficient) must be >= 0, got -0.1')
        ! line 9 FRICTION: eps_bar (f2, columns 21-30) = 1.0
        call add('ranges', 'eps_bar_one.dat', ':9:21-30:', &
                 'FRICTION eps_bar (regularisation of the friction law) must be in (0, 1), got 1.0')
        ! line 4 MODEL: kind (f1, columns 11-20) = SHELL
        call add('ranges', 'model_shell.dat', ':4:11-20:', &
                 "MODEL kind must be BEAM or PLATE, got 'SHELL'")
        ! line 9 FRICTION: a third number in f3 (columns 31-40)
        call add('ranges', 'extra_field.dat', ':9:31-40:', &
                 "FRICTION has 2 field(s); columns 31-40 must be blank, found '0.3'")
        ! line 6 GEOMETRY of a PLATE: b in f3 (columns 31-40)
        call add('ranges', 'plate_with_width.dat', ':6:31-40:', &
                 'PLATE has no width: GEOMETRY b must be blank')
        ! --- loads (line 10 is the LOAD card)
        ! POINT at x1 (f4, columns 41-50) = 6 on a beam of l = 10
        call add('loads', 'load_off_beam.dat', ':10:41-50:', &
                 'LOAD x1 lies outside the beam: must be in [-l/2, l/2] = [-5, 5], got 6')
        ! PATCH to x2 (f5, columns 51-60) = 7 on a plate of a = 6
        call add('loads', 'patch_off_plate.dat', ':10:51-60:', &
                 'LOAD x2 lies outside the plate: must be in [0, a] = [0, 6], got 7')
        ! PATCH from x1 = 1 to x2 (f5, columns 51-60) = -1
        call add('loads', 'patch_reversed.dat', ':10:51-60:', &
                 'LOAD x2 (end of the patch) must be greater than x1 = 1, got -1')
        ! plate PATCH with F_x (f3, columns 31-40) = 100.0
        call add('loads', 'plate_horizontal_load.dat', ':10:31-40:', &
                 'an axisymmetric plate cannot carry a horizontal force')
        ! line 11 (inserted) LOAD MOMENT on a plate: the kind (f1, columns 11-20)
        call add('loads', 'plate_moment.dat', ':11:11-20:', &
                 'an axisymmetric plate cannot carry an overturning moment')
        ! NONDIM: F_z 0.6 (line 7) + 0.3 (line 8); F_z of the first LOAD (f2, columns 21-30)
        call add('loads', 'nondim_loads_not_one.dat', ':7:21-30:', &
                 'the LOAD F_z must add up to 1; they add up to 0.9')
        ! --- sweeps (line 12 is the SWEEP card unless said otherwise)
        ! the name (f1, columns 11-20) is GAMMA
        call add('sweeps', 'sweep_unknown_name.dat', ':12:11-20:', &
                 "SWEEP parameter must be RHO, ZETA, BETA")
        ! v2 (f3, columns 31-40) = 0.5 for NU
        call add('sweeps', 'sweep_out_of_range.dat', ':12:31-40:', &
                 'SWEEP NU value v2 must be in [0, 0.5), got 0.5')
        ! v2 (f3, columns 31-40) blank between v1 and v3
        call add('sweeps', 'sweep_gap.dat', ':12:31-40:', &
                 'SWEEP values fill v1, v2, ... without gaps; v2 is blank')
        ! RHO (f1, columns 11-20) in a physical deck
        call add('sweeps', 'sweep_rho_physical.dat', ':12:11-20:', &
                 'SWEEP RHO needs a NONDIM deck')
        ! line 13: the second SWEEP F (line 12 has the first); the name is f1
        call add('sweeps', 'sweep_duplicate.dat', ':13:11-20:', 'SWEEP F already given at line 12')
        ! the seventh SWEEP card (line 18) takes 6^6 = 46656 cases to 279936: its name f1
        call add('sweeps', 'sweep_too_many_cases.dat', ':18:11-20:', &
                 'too many SWEEP combinations (more than 100000 cases)')
        ! --- the layered ground (LAYER and BASE cards; the base beam deck with line 8 SOIL
        ! replaced or followed by the ground cards, the base NONDIM deck with them at line 6)
        ! line 9 LAYER after SOIL (line 8): the card name, columns 1-10
        call add('ground', 'layer_with_soil.dat', ':9:1-10:', &
                 'LAYER cannot be combined with SOIL (line 8)')
        ! line 9 BASE after SOIL, no LAYER: the card name
        call add('ground', 'base_without_layer.dat', ':9:1-10:', 'BASE without LAYER cards')
        ! lines 8-9 LAYER, no BASE: the name of the last LAYER (line 9)
        call add('ground', 'layer_without_base.dat', ':9:1-10:', &
                 'the LAYER cards need a BASE card after them')
        ! line 10 LAYER after BASE (line 9): its name
        call add('ground', 'layer_after_base.dat', ':10:1-10:', 'LAYER after BASE (line 9)')
        ! line 8 LAYER: h (f1, columns 11-20) = 0.0
        call add('ground', 'layer_thickness_zero.dat', ':8:11-20:', &
                 'LAYER h (thickness of the layer) must be > 0, got 0.0')
        ! line 8 LAYER of a physical deck: nu (f3, columns 31-40) blank
        call add('ground', 'layer_nu_missing.dat', ':8:31-40:', &
                 "LAYER nu (Poisson's ratio of the layer) is required but the field is blank")
        ! line 9 BASE ROUGH with E (f2, columns 21-30) = 1.0E6
        call add('ground', 'base_rigid_with_modulus.dat', ':9:21-30:', &
                 'a rigid base has no modulus: BASE E must be blank for ROUGH')
        ! line 9 BASE HALFSPACE without E (f2, columns 21-30)
        call add('ground', 'base_halfspace_no_modulus.dat', ':9:21-30:', &
                 "BASE E (Young's modulus of the half-space below the layers) is required")
        ! line 9 BASE SMOOTH under a beam: the kind (f1, columns 11-20)
        call add('ground', 'beam_smooth_base.dat', ':9:11-20:', &
                 'a beam on layers over a SMOOTH base is not modelled')
        ! NONDIM, line 6 LAYER: E (f2, columns 21-30) = 2.0, not 1
        call add('ground', 'nondim_layer_e_not_one.dat', ':6:21-30:', &
                 "the first LAYER's E must be 1 or blank, got 2.0")
        ! NONDIM (nu_f = 0.1), line 6 LAYER: nu (f3, columns 31-40) = 0.3
        call add('ground', 'nondim_layer_nu_differs.dat', ':6:31-40:', &
                 "the top layer's nu is the NONDIM card's nu_f = 0.1")
        ! line 12 SWEEP H1 in a SOIL deck: the name (f1, columns 11-20)
        call add('ground', 'sweep_h1_no_layers.dat', ':12:11-20:', &
                 'SWEEP H1 needs a layered ground')
        ! line 14 SWEEP E3 with two LAYER cards: the name
        call add('ground', 'sweep_e3_two_layers.dat', ':14:11-20:', &
                 'SWEEP E3 names layer 3; the deck has 2 LAYER card(s)')
        ! line 14 SWEEP DEPTH: v2 (f3, columns 31-40) = 1.5 above the 2 m of layer 1
        call add('ground', 'sweep_depth_shallow.dat', ':14:31-40:', &
                 'SWEEP DEPTH value v2 must be greater than the layers above the last, 2 deep')
        ! NONDIM, line 12 SWEEP E1: the name
        call add('ground', 'sweep_e1_nondim.dat', ':12:11-20:', &
                 'SWEEP E1 is not a parameter of a NONDIM deck')
        ! line 13 SWEEP E_F in a layered deck: the name
        call add('ground', 'sweep_e_f_layered.dat', ':13:11-20:', &
                 "SWEEP E_F is the SOIL card's modulus; in a layered deck sweep E1")
        ! line 13 SWEEP E_BASE over a ROUGH base: the name
        call add('ground', 'sweep_e_base_rigid.dat', ':13:11-20:', &
                 'SWEEP E_BASE needs BASE HALFSPACE')
        ! --- CHECK cards (line 12, after MESH on line 11; NONDIM: line 9, after MESH on 8)
        ! f1 (columns 11-20) 'BEARINGS'
        call add('checks', 'check_unknown_kind.dat', ':12:11-20:', "CHECK kind must be "// &
                 "BEARING, SETTLE, DIFFSETTLE, ROTATION, TILT, SLIDING or CONTACT, got 'BEARINGS'")
        ! f2 (columns 21-30) blank: the limit is required
        call add('checks', 'check_limit_missing.dat', ':12:21-30:', 'CHECK SETTLE w_max '// &
                 '(largest settlement allowed) is required but the field is blank')
        ! f3 (columns 31-40) '-10.0', the edge limit of BEARING
        call add('checks', 'check_limit_negative.dat', ':12:31-40:', 'CHECK BEARING q_edge '// &
                 '(allowable pressure at d from an edge) must be > 0, got -10.0')
        ! f2 (columns 21-30) '0.0'
        call add('checks', 'check_limit_zero.dat', ':12:21-30:', 'CHECK SLIDING FS_min '// &
                 '(smallest factor of safety against sliding, f V / H) must be > 0, got 0.0')
        ! f2 (columns 21-30) '1.5': a contact ratio is at most 1
        call add('checks', 'check_contact_above_one.dat', ':12:21-30:', 'CHECK CONTACT '// &
                 'ratio (smallest contact area / base area) must be in (0, 1], got 1.5')
        ! line 13, the second CHECK SETTLE: its kind (f1, columns 11-20)
        call add('checks', 'check_duplicate.dat', ':13:11-20:', 'duplicate CHECK SETTLE '// &
                 '(first given at line 12): one CHECK card per kind')
        ! f3 (columns 31-40) '2.0E-3': TILT has one limit
        call add('checks', 'check_extra_field.dat', ':12:31-40:', "CHECK TILT has 2 "// &
                 "field(s); columns 31-40 must be blank, found '2.0E-3'")
        ! NONDIM deck, line 9 CHECK: the card name (columns 1-10)
        call add('checks', 'check_nondim.dat', ':9:1-10:', 'CHECK needs a physical deck')
        ! --- known reader bug (reported, not fixed here): gfortran ends a record at a lone CR,
        ! so the reader splits line 9 'FRICTION  0.5<CR>      1.0E-6' into two lines and
        ! numbers every later line one too high. README: CR LF line ends are accepted, other
        ! control characters are errors; the CR is column 14 of line 9.
        call add('lone_cr', 'cr_inside_card.dat', ':9:14:', &
                 'control character (code 13) in column 14')
        ! LOADCASE and COMBINE cards: lines 10 on are the cards after FRICTION (line 9)
        ! COMBINE f4 (41-50) names X; only G is opened
        call add('combinations', 'combine_unknown_case.dat', ':12:41-50:', &
                 'COMBINE names the unknown load case ''X''')
        ! the LOAD of line 10 comes before the LOADCASE of line 11 (card name, 1-10)
        call add('combinations', 'load_outside_case.dat', ':10:1-10:', &
                 'LOAD outside any load case')
        ! the second LOADCASE G (line 12), its name in f1
        call add('combinations', 'loadcase_duplicate.dat', ':12:11-20:', &
                 'duplicate load case name ''G'' (first given at line 10)')
        ! f5 (51-60) of the COMBINE card of line 14 reads 1.5x
        call add('combinations', 'combine_factor_not_number.dat', ':14:51-60:', &
                 'COMBINE factor f5 of load case Q: expected a finite number such as 0.3, '// &
                 '30.0E6 or 1.0D-6, got ''1.5x''')
        ! f3 (31-40) of the COMBINE card of line 14 reads 1.0E308: a number, beyond 1E+30
        call add('combinations', 'combine_factor_range.dat', ':14:31-40:', &
                 'COMBINE factor f3 of load case G: a deck number is 0 or has a magnitude of '// &
                 'at least 1E-30 and below 1E+30, got ''1.0E308''')
        ! both factors of COMBINE ULS (line 14) are 0: the name in f1 (11-20) is marked
        call add('combinations', 'combine_all_zero.dat', ':14:11-20:', &
                 'combination ''ULS'' has every factor 0: it carries no load')
        ! f2 (21-30) of the LOADCASE card of line 10 reads 1.0E300: beyond 1E+30
        call add('combinations', 'loadcase_gamma_range.dat', ':10:21-30:', &
                 'positive or blank: a deck number is 0 or has a magnitude of at least 1E-30 '// &
                 'and below 1E+30, got ''1.0E300''')
        ! LOADCASE Q of line 12 is followed by COMBINE, not LOAD
        call add('combinations', 'loadcase_empty.dat', ':12:1-10:', &
                 'load case ''Q'' is empty')
        ! COMBINE of line 11 in a deck with no LOADCASE
        call add('combinations', 'combine_without_loadcase.dat', ':11:1-10:', &
                 'COMBINE without LOADCASE cards')
        ! the COMBINE name in f1 of line 12
        call add('combinations', 'combine_reserved_name.dat', ':12:11-20:', &
                 'cannot be SUMMARY')
        ! NONDIM base deck: LOADCASE inserted at line 7, before its LOAD
        call add('combinations', 'loadcase_nondim.dat', ':7:1-10:', &
                 'load cases need a physical deck')
    contains
        subroutine add(group, file, where, what)
            character(len=*), intent(in) :: group, file, where, what
            k = k + 1
            if (k > n_decks) error stop 'test_malformed_decks: n_decks too small'
            t(k) = expect_t(group, file, where, what)
        end subroutine add
    end function expected

    ! ------------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------------

    !> The line of `message` that carries the first error: the second line when the first is
    !! the count line ('N input errors in ...'), else the first line.
    pure function first_error(message) result(line)
        character(len=*), intent(in) :: message
        character(len=:), allocatable :: line, rest
        integer :: k
        k = index(message, nl)
        if (k == 0) then
            line = message
            return
        end if
        line = message(1:k - 1)
        if (index(line, ' input error') == 0 .or. scan(line(1:1), '0123456789') == 0) return
        rest = message(k + 1:)
        k = index(rest, nl)
        line = rest
        if (k > 0) line = rest(1:k - 1)
    end function first_error

    !> Read one deck and check code, path, first location and explanation; '' if all hold,
    !! else what is wrong.
    function check_deck(path, where, what) result(problem)
        character(len=*), intent(in) :: path, where, what
        character(len=:), allocatable :: problem, first, prefix
        type(deck_t) :: deck
        type(error_t), allocatable :: err
        problem = ''
        call read_deck(path, deck, err)
        if (.not. allocated(err)) then
            problem = path//': deck accepted (expected "'//path//where//' '//what//'")'
            return
        end if
        if (err%code /= EXIT_INPUT) then
            problem = path//': error code is not EXIT_INPUT'
            return
        end if
        if (index(err%message, path) == 0) then
            problem = path//': the message does not name the deck'
            return
        end if
        prefix = path//where//' '
        first = first_error(err%message)
        if (index(first, prefix) /= 1) then
            problem = path//': first error should start "'//prefix//'", got:'//nl//err%message
        else if (index(first, what) == 0) then
            problem = path//': first error lacks "'//what//'":'//nl//err%message
        end if
    end function check_deck

    !> Check every deck of one group; one failure lists all decks that went wrong.
    subroutine check_group(group, err)
        character(len=*), intent(in) :: group
        type(error_t), allocatable, intent(out) :: err
        type(expect_t) :: t(n_decks)
        character(len=:), allocatable :: problems, p
        integer :: k, n
        t = expected()
        problems = ''
        n = 0
        do k = 1, n_decks
            if (trim(t(k)%group) /= group) cycle
            n = n + 1
            p = check_deck(dir//trim(t(k)%file), trim(t(k)%where), trim(t(k)%what))
            if (len(p) > 0) problems = problems//nl//p
        end do
        call check(err, n > 0, 'no deck in group '//group)
        if (allocated(err)) return
        call check(err, len(problems) == 0, 'malformed decks misread:'//problems)
    end subroutine check_group

    !> Every range a deck field can be refused by (the deck reader's own rule_text) is listed
    !! in doc/ERRORS.md, and the limits of the whole-number fields are in README.md, so that a
    !! user reads the same rule the program applies.
    subroutine test_rules_documented(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: text, bracket
        integer :: rule
        rules: do rule = RULE_POSITIVE, RULE_STATIONS
            text = rule_text(rule)
            call check(err, shell('grep -qF -- "'//text//'" doc/ERRORS.md') == 0, &
                       'doc/ERRORS.md lacks the rule "'//text//'"')
            if (allocated(err)) return
            if (rule < RULE_COUNT .and. rule /= RULE_OPEN_UNIT) cycle rules
            ! README: 'must be ' dropped, as in its tables ("whole number in [1, 100000]")
            if (rule == RULE_OPEN_UNIT) then
                bracket = 'in (0, 1)'
            else
                bracket = text(index(text, 'whole number'):)
            end if
            call check(err, shell('grep -qF -- "'//bracket//'" README.md') == 0, &
                       'README.md lacks the rule "'//bracket//'"')
            if (allocated(err)) return
        end do rules
    end subroutine test_rules_documented

    !> Run a shell command; its exit status (-1 if it could not run).
    integer function shell(command)
        character(len=*), intent(in) :: command
        integer :: cmd_status
        shell = -1
        call execute_command_line(command, exitstat=shell, cmdstat=cmd_status)
        if (cmd_status /= 0) shell = -1
    end function shell

    !> Write lines to a file (LF line ends).
    subroutine write_lines(path, lines)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: lines(:)
        integer :: u, k
        open (newunit=u, file=path, status='replace', action='write')
        do k = 1, size(lines)
            write (u, '(a)') trim(lines(k))
        end do
        close (u)
    end subroutine write_lines

    subroutine test_ground(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('ground', err)
    end subroutine test_ground

    subroutine test_adapt(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('adapt', err)
    end subroutine test_adapt

    subroutine test_check_cards(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('checks', err)
    end subroutine test_check_cards

    ! The three base decks the malformed files are made from (each file = one comment card,
    ! the ruler, and one of these with one fault put in).

    pure function base_beam() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: '* base deck of the malformed decks: physical beam', ruler, &
            'TITLE     Malformed deck (physical beam)', &
            'MODEL     BEAM', &
            'UNITS     kN        m', &
            'GEOMETRY  10.0      0.5       1.0', &
            'STRUCTURE 30.0E6    0.2', &
            'SOIL      40.0E3    0.3', &
            'FRICTION  0.5       1.0E-6', &
            'LOAD      POINT     1000.0    100.0     0.0', &
            'MESH      20        UNIFORM   P1        P1        P1        P1        P1', &
            'END']
    end function base_beam

    pure function base_plate() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: '* base deck of the malformed decks: physical plate', &
            ruler, &
            'TITLE     Malformed deck (physical plate)', &
            'MODEL     PLATE', &
            'UNITS     kN        m', &
            'GEOMETRY  6.0       0.6', &
            'STRUCTURE 30.0E6    0.2', &
            'SOIL      40.0E3    0.3', &
            'FRICTION  0.5       1.0E-6', &
            'LOAD      PATCH     8000.0              0.0       0.4', &
            'MESH      20        UNIFORM   P1        P1        P1        P1        P1', &
            'END']
    end function base_plate

    pure function base_nondim() result(lines)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: '* base deck of the malformed decks: NONDIM beam', ruler, &
            'TITLE     Malformed deck (NONDIM beam)', &
            'MODEL     BEAM', &
            'NONDIM    0.0025    0.1       0.3       0.1       0.05', &
            'FRICTION  0.6       1.0E-6', &
            'LOAD      POINT     1.0       0.1       0.0', &
            'MESH      20        UNIFORM   P1        P1        P1        P1        P1', &
            'END']
    end function base_nondim

    ! ------------------------------------------------------------------------------------
    ! Tests
    ! ------------------------------------------------------------------------------------

    !> Control: the base decks are valid, so each malformed deck fails for its own fault.
    subroutine test_base_decks(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call parse_deck('base_beam.dat', base_beam(), deck, perr)
        if (allocated(perr)) call check(err, .false., 'base beam refused:'//nl//perr%message)
        if (allocated(err)) return
        call parse_deck('base_plate.dat', base_plate(), deck, perr)
        if (allocated(perr)) call check(err, .false., 'base plate refused:'//nl//perr%message)
        if (allocated(err)) return
        call parse_deck('base_nondim.dat', base_nondim(), deck, perr)
        if (allocated(perr)) call check(err, .false., 'base NONDIM refused:'//nl//perr%message)
    end subroutine test_base_decks

    !> At least 40 decks; every row names an existing file, and every file has a row.
    subroutine test_all_listed(err)
        type(error_t), allocatable, intent(out) :: err
        type(expect_t) :: t(n_decks)
        character(len=256) :: name
        character(len=:), allocatable :: problems
        logical :: there
        integer :: k, u, ios, n_files
        t = expected()
        problems = ''
        do k = 1, n_decks
            if (len_trim(t(k)%file) == 0) problems = problems//nl//'an empty row in the table'
            inquire (file=dir//trim(t(k)%file), exist=there)
            if (.not. there) problems = problems//nl//'missing file '//dir//trim(t(k)%file)
        end do
        call check(err, len(problems) == 0, 'table and files disagree:'//problems)
        if (allocated(err)) return
        ! every file in the folder is in the table (a deck without a row would go unchecked)
        call check(err, shell('ls -1 '//dir//' > build/malformed_list.txt') == 0, 'ls failed')
        if (allocated(err)) return
        open (newunit=u, file='build/malformed_list.txt', status='old', action='read')
        n_files = 0
        files: do
            read (u, '(a)', iostat=ios) name
            if (ios /= 0) exit files
            n_files = n_files + 1
            if (.not. any(t%file == name)) problems = problems//nl//'no table row for '//trim(name)
        end do files
        close (u, status='delete')
        call check(err, len(problems) == 0, 'files without a row:'//problems)
        if (allocated(err)) return
        call check(err, n_files == n_decks .and. n_decks >= 40, 'expected at least 40 decks, '// &
                   'one row each')
    end subroutine test_all_listed

    subroutine test_truncated(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('truncated', err)
    end subroutine test_truncated

    subroutine test_columns(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('columns', err)
    end subroutine test_columns

    subroutine test_numbers(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('numbers', err)
    end subroutine test_numbers

    subroutine test_counts(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('counts', err)
    end subroutine test_counts

    subroutine test_characters(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('characters', err)
    end subroutine test_characters

    subroutine test_lines(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('lines', err)
    end subroutine test_lines

    subroutine test_card_set(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('card_set', err)
    end subroutine test_card_set

    subroutine test_not_a_deck(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('not_a_deck', err)
    end subroutine test_not_a_deck

    subroutine test_missing(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('missing', err)
    end subroutine test_missing

    subroutine test_ranges(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('ranges', err)
    end subroutine test_ranges

    subroutine test_loads(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('loads', err)
    end subroutine test_loads

    subroutine test_combinations(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('combinations', err)
    end subroutine test_combinations

    subroutine test_sweeps(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('sweeps', err)
    end subroutine test_sweeps

    !> A lone CR inside a card is a control character of that line (see the table).
    subroutine test_lone_cr(err)
        type(error_t), allocatable, intent(out) :: err
        call check_group('lone_cr', err)
    end subroutine test_lone_cr

    !> A file of 100001 lines (made here: 100001 comment cards) is no deck: refused as a
    !! whole, without a line, before any card is read.
    subroutine test_too_many_lines(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: path = 'build/malformed_long_file.dat'
        character(len=:), allocatable :: first
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        integer :: u, k
        open (newunit=u, file=path, status='replace', action='write')
        do k = 1, 100001
            write (u, '(a)') '*'
        end do
        close (u)
        call read_deck(path, deck, perr)
        open (newunit=u, file=path, status='old')
        close (u, status='delete')
        call check(err, allocated(perr), path//' (100001 lines) accepted')
        if (allocated(err)) return
        first = first_error(perr%message)
        call check(err, perr%code == EXIT_INPUT .and. index(first, path//': ') == 1 .and. &
                   index(first, 'more than 100000 lines') > 0, '100001 lines: expected "'// &
                   path//': cannot read the deck: more than 100000 lines ...", got: '// &
                   perr%message)
    end subroutine test_too_many_lines

    !> A directory given as the deck (made here): refused with EXIT_INPUT, no line, and a
    !! message that names it. gfortran opens a directory without error and reads nothing from
    !! it, so the reader reports it as empty / not a text file.
    subroutine test_directory(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        character(len=:), allocatable :: first
        call check(err, shell('mkdir -p '//dir_deck) == 0, 'cannot make '//dir_deck)
        if (allocated(err)) return
        call read_deck(dir_deck, deck, perr)
        if (shell('rmdir '//dir_deck) /= 0) continue
        call check(err, allocated(perr), 'a directory accepted as a deck')
        if (allocated(err)) return
        call check(err, perr%code == EXIT_INPUT, 'directory: error code is not EXIT_INPUT')
        if (allocated(err)) return
        first = first_error(perr%message)
        ! a whole-file error: 'path: ' and no line number
        call check(err, index(first, dir_deck//': ') == 1, 'directory: message should start "'// &
                   dir_deck//': ", got: '//perr%message)
        if (allocated(err)) return
        call check(err, index(first, 'directory') > 0 .or. index(first, 'not a text file') > 0, &
                   'directory: message says neither "directory" nor "not a text file": '// &
                   perr%message)
    end subroutine test_directory

    !> A file with mode 000 (made here from the valid base beam). A normal user cannot open it:
    !! 'path: cannot open the deck: ... Permission denied'. As root (as in CI) chmod 000 does
    !! not stop reading: that case is detected with `test -r` and the deck must then be read
    !! normally (it is the valid base beam), which is what this test then asserts instead.
    subroutine test_unreadable(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        logical :: readable
        call write_lines(locked_deck, base_beam())
        call check(err, shell('chmod 000 '//locked_deck) == 0, 'chmod 000 failed')
        if (allocated(err)) return
        readable = shell('test -r '//locked_deck) == 0    ! true for root despite mode 000
        call read_deck(locked_deck, deck, perr)
        if (readable) then
            ! root: the file is read normally, and it is a valid deck
            if (allocated(perr)) call check(err, .false., 'running as root, '//locked_deck// &
                ' (mode 000) is readable but was refused:'//nl//perr%message)
        else
            call check(err, allocated(perr), locked_deck//' (mode 000) read without error')
            if (.not. allocated(err)) call check(err, perr%code == EXIT_INPUT .and. &
                index(perr%message, locked_deck//': cannot open the deck: ') == 1, &
                'unreadable deck: expected "'//locked_deck//': cannot open the deck: ...", '// &
                'got: '//perr%message)
        end if
        if (shell('chmod 600 '//locked_deck//' && rm -f '//locked_deck) /= 0) continue
    end subroutine test_unreadable

    !> The program's path for each deck, table-driven: read the deck and, only if it parses
    !! (none should), run the analysis into a fresh output folder made by this test; the
    !! folder must stay empty. A deck that parses is itself a failure (its case count is
    !! checked first so that an accepted huge sweep is not run).
    subroutine test_no_output(err)
        type(error_t), allocatable, intent(out) :: err
        type(expect_t) :: t(n_decks)
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        character(len=:), allocatable :: problems, out, stem
        integer :: k, status, null_unit
        t = expected()
        problems = ''
        call check(err, shell('rm -rf '//out_root//' && mkdir -p '//out_root) == 0, &
                   'cannot make '//out_root)
        if (allocated(err)) return
        open (newunit=null_unit, file='/dev/null', action='write')
        do k = 1, n_decks
            stem = trim(t(k)%file)
            stem = stem(1:index(stem, '.dat', back=.true.) - 1)
            out = out_root//'/'//stem
            if (shell('mkdir '//out) /= 0) then
                problems = problems//nl//'cannot make '//out
                cycle
            end if
            call read_deck(dir//trim(t(k)%file), deck, perr)
            if (.not. allocated(perr)) then
                problems = problems//nl//trim(t(k)%file)//': deck accepted'
                if (case_count(deck) <= 4) call run_analysis(deck, out, null_unit, null_unit, &
                                                             status)
            else if (perr%code /= EXIT_INPUT) then
                problems = problems//nl//trim(t(k)%file)//': error code is not EXIT_INPUT'
            end if
            ! the folder exists and holds nothing (no report, data, CSV, PNG or temporary file)
            if (shell('test -d '//out//' && test -z "$(ls -A '//out//')"') /= 0) &
                problems = problems//nl//trim(t(k)%file)//': files written to '//out
        end do
        close (null_unit)
        call check(err, len(problems) == 0, 'decks not refused cleanly:'//problems)
        if (allocated(err)) return
        if (shell('rm -rf '//out_root) /= 0) continue
    end subroutine test_no_output
end module test_malformed_decks
