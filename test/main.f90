!> Single test driver: `fpm test [-- suite [test]]`. Ends with `N passed, N failed`;
!! exits 1 if anything failed.
program tester
    use start_up, only: start_program
    use harness, only: unittest_t, run_suite
    use test_shape_functions, only: collect_shape_functions
    use test_gsl_wrappers, only: collect_gsl_wrappers
    use test_halfspace_plate, only: collect_halfspace_plate
    use test_halfspace_beam, only: collect_halfspace_beam
    use test_station_displacement, only: collect_station_displacement
    use test_structure, only: collect_structure
    use test_deck_reader, only: collect_deck_reader
    use test_contact_solver, only: collect_contact_solver
    use test_newton, only: collect_newton
    use test_report_writer, only: collect_report_writer
    use test_convergence, only: collect_convergence
    use test_paper, only: collect_paper
    use test_design_values, only: collect_design_values
    use test_foundation_springs, only: collect_foundation_springs
    use test_properties, only: collect_properties
    use test_malformed_decks, only: collect_malformed_decks
    use test_simplifications, only: collect_simplifications
    use test_adaptive, only: collect_adaptive
    use test_nested_spaces, only: collect_nested_spaces
    use test_architecture, only: collect_architecture
    use test_layered_ground, only: collect_layered_ground
    use test_layered_program, only: collect_layered_program
    use test_unit_checks, only: collect_unit_checks
    use test_load_combinations, only: collect_load_combinations
    use test_design_checks, only: collect_design_checks
    use test_records, only: collect_records
    use test_shard_envelope, only: collect_shard_envelope
    use test_html_record, only: collect_html_record
    use test_number_text, only: collect_number_text
    implicit none
    type(unittest_t), allocatable :: tests(:)
    character(len=64) :: want_suite, want_test
    integer :: n_pass, n_fail
    character(len=*), parameter :: suites = ' shape_functions gsl_wrappers halfspace_plate '// &
        'halfspace_beam station_displacement structure deck_reader contact_solver '// &
        'report_writer convergence design_values paper malformed_decks newton properties '// &
        'simplifications adaptive nested_spaces architecture layered_ground layered_program '// &
        'foundation_springs unit_checks design_checks records html_record load_combinations '// &
        'shard_envelope number_text '

    want_suite = ''
    want_test = ''
    if (command_argument_count() >= 1) call get_command_argument(1, want_suite)
    if (command_argument_count() >= 2) call get_command_argument(2, want_test)
    if (len_trim(want_suite) > 0 .and. index(suites, ' '//trim(want_suite)//' ') == 0) then
        write (*, '(a)') 'unknown test suite "'//trim(want_suite)//'"; suites:'//suites
        write (*, '(a)') '0 passed, 1 failed'
        stop 1
    end if
    call start_program()
    n_pass = 0
    n_fail = 0

    if (wanted('architecture')) then
        call collect_architecture(tests)
        call run_suite('architecture', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('number_text')) then
        call collect_number_text(tests)
        call run_suite('number_text', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('shape_functions')) then
        call collect_shape_functions(tests)
        call run_suite('shape_functions', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('gsl_wrappers')) then
        call collect_gsl_wrappers(tests)
        call run_suite('gsl_wrappers', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('halfspace_plate')) then
        call collect_halfspace_plate(tests)
        call run_suite('halfspace_plate', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('halfspace_beam')) then
        call collect_halfspace_beam(tests)
        call run_suite('halfspace_beam', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('station_displacement')) then
        call collect_station_displacement(tests)
        call run_suite('station_displacement', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('layered_ground')) then
        call collect_layered_ground(tests)
        call run_suite('layered_ground', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('layered_program')) then
        call collect_layered_program(tests)
        call run_suite('layered_program', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('nested_spaces')) then
        call collect_nested_spaces(tests)
        call run_suite('nested_spaces', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('structure')) then
        call collect_structure(tests)
        call run_suite('structure', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('deck_reader')) then
        call collect_deck_reader(tests)
        call run_suite('deck_reader', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('contact_solver')) then
        call collect_contact_solver(tests)
        call run_suite('contact_solver', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('simplifications')) then
        call collect_simplifications(tests)
        call run_suite('simplifications', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('newton')) then
        call collect_newton(tests)
        call run_suite('newton', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('report_writer')) then
        call collect_report_writer(tests)
        call run_suite('report_writer', tests, want_test, n_pass, n_fail)
    end if

    if (wanted('convergence')) then
        call collect_convergence(tests)
        call run_suite('convergence', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('design_values')) then
        call collect_design_values(tests)
        call run_suite('design_values', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('foundation_springs')) then
        call collect_foundation_springs(tests)
        call run_suite('foundation_springs', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('malformed_decks')) then
        call collect_malformed_decks(tests)
        call run_suite('malformed_decks', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('properties')) then
        call collect_properties(tests)
        call run_suite('properties', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('adaptive')) then
        call collect_adaptive(tests)
        call run_suite('adaptive', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('unit_checks')) then
        call collect_unit_checks(tests)
        call run_suite('unit_checks', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('load_combinations')) then
        call collect_load_combinations(tests)
        call run_suite('load_combinations', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('design_checks')) then
        call collect_design_checks(tests)
        call run_suite('design_checks', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('records')) then
        call collect_records(tests)
        call run_suite('records', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('shard_envelope')) then
        call collect_shard_envelope(tests)
        call run_suite('shard_envelope', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('html_record')) then
        call collect_html_record(tests)
        call run_suite('html_record', tests, want_test, n_pass, n_fail)
    end if
    if (wanted('paper')) then
        call collect_paper(tests)
        call run_suite('paper', tests, want_test, n_pass, n_fail)
    end if

    write (*, '(i0," passed, ",i0," failed")') n_pass, n_fail
    if (n_fail > 0) stop 1

contains

    logical function wanted(suite)
        character(len=*), intent(in) :: suite
        wanted = len_trim(want_suite) == 0 .or. trim(want_suite) == suite
    end function wanted
end program tester
