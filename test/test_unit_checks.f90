!> The UNITS card's known words: a warning for each magnitude out of its plausible SI range
!! (plausibility, README "Plausibility warnings"), none for sound decks in SI or US units or
!! without a UNITS card, the display units of settlements and pressures (case_scales) with
!! factors from the definitions of the units, and the input errors of the display fields.
module test_unit_checks
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_INPUT
    use deck_reader, only: deck_t, parse_deck
    use plausibility, only: input_warnings, warning_length
    use case_scales, only: units_t, case_units
    use test_deck_reader, only: card
    implicit none
    private
    public :: collect_unit_checks

    integer, parameter :: w = 200   !! width of test lines (as test_deck_reader%card)

contains

    subroutine collect_unit_checks(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('moduli_in_kpa_with_mm', test_moduli_kpa_mm), &
                 new_unittest('lengths_in_mm_with_m', test_lengths_mm_m), &
                 new_unittest('newtons_for_kilonewtons', test_newtons), &
                 new_unittest('layered_moduli', test_layered), &
                 new_unittest('sound_decks_no_warning', test_sound_decks), &
                 new_unittest('display_factors', test_display_factors), &
                 new_unittest('display_word_errors', test_display_errors)]
    end subroutine collect_unit_checks


    !> A beam with the given UNITS card and numbers (l, h, b, E, E_f, F_z as text).
    pure function beam(units, geometry, e, e_f, f_z) result(lines)
        character(len=w), intent(in) :: units           !! the UNITS card
        character(len=*), intent(in) :: geometry(3)     !! l, h, b
        character(len=*), intent(in) :: e, e_f, f_z     !! STRUCTURE E, SOIL E_f, LOAD F_z
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'BEAM'), units, &
                 card('GEOMETRY', geometry(1), geometry(2), geometry(3)), &
                 card('STRUCTURE', e, '0.2'), card('SOIL', e_f, '0.3'), &
                 card('FRICTION', '0.5'), card('LOAD', 'POINT', f_z, '', '0.0'), card('END')]
    end function beam

    !> The input warnings of a deck that must parse.
    subroutine warnings_of(lines, warn, err)
        character(len=*), intent(in) :: lines(:)
        character(len=warning_length), allocatable, intent(out) :: warn(:)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call parse_deck('t.dat', lines, deck, perr)
        if (allocated(perr)) then
            call check(err, .false., 'unexpected input error: '//perr%message)
            return
        end if
        warn = input_warnings(deck%base)
    end subroutine warnings_of

    !> Exactly the warnings naming each field in names, in this order.
    subroutine check_named(warn, names, err)
        character(len=*), intent(in) :: warn(:)
        character(len=*), intent(in) :: names(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        character(len=:), allocatable :: all
        all = ''
        do k = 1, size(warn)
            all = all//' | '//trim(warn(k))
        end do
        call check(err, size(warn) == size(names), 'warnings:'//all)
        if (allocated(err)) return
        do k = 1, size(names)
            call check(err, index(warn(k), trim(names(k))//' = ') == 1 .and. &
                       index(warn(k), 'UNITS card') > 0, 'expected '//trim(names(k))// &
                       ' first in:'//all)
            if (allocated(err)) return
        end do
    end subroutine check_named

    !> The issue's slip: UNITS kN mm, lengths in mm, moduli still in kPa. E = 30e6 kN/mm^2
    !! = 30e6 * 1e3 N / 1e-6 m^2 = 3e16 Pa > 1e12 Pa; E_f = 40e3 kN/mm^2 = 4e13 Pa > 1e11
    !! Pa. Lengths 10 m, 0.5 m, 1 m and the mean pressure 1000 kN / (10 m * 1 m) = 1e5 Pa
    !! are plausible: two warnings, STRUCTURE E and SOIL E_f.
    subroutine test_moduli_kpa_mm(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=warning_length), allocatable :: warn(:)
        call warnings_of(beam(card('UNITS', 'kN', 'mm'), ['10000.0', '500.0  ', '1000.0 '], &
                              '30.0E6', '40.0E3', '1000.0'), warn, err)
        if (allocated(err)) return
        call check_named(warn, ['STRUCTURE E', 'SOIL E_f   '], err)
        if (allocated(err)) return
        call check(err, index(warn(1), '3.00E+16 Pa') > 0, 'SI value: '//trim(warn(1)))
    end subroutine test_moduli_kpa_mm

    !> Lengths in mm under UNITS kN m: l = 10000 m > 1000 m, h = 500 m > 20 m, b = 1200 m >
    !! 1000 m; the mean pressure 1000 kN / (10000 m * 1200 m) = 8.3e-5 kPa = 0.083 Pa <
    !! 1e3 Pa. The moduli (30 GPa, 40 MPa) are plausible: four warnings.
    subroutine test_lengths_mm_m(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=warning_length), allocatable :: warn(:)
        call warnings_of(beam(card('UNITS', 'kN', 'm'), ['10000.0', '500.0  ', '1200.0 '], &
                              '30.0E6', '40.0E3', '1000.0'), warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=40) :: 'GEOMETRY l', 'GEOMETRY h', &
                                'GEOMETRY b', 'LOAD F_z, their sum over the base area,'], err)
    end subroutine test_lengths_mm_m

    !> UNITS N m with the numbers of a kN deck: E = 30e6 N/m^2 = 3e7 Pa < 1e8 Pa, E_f = 4e4
    !! Pa < 1e5 Pa, the mean pressure 1000 N / (10 m * 1 m) = 100 Pa < 1e3 Pa: three
    !! warnings; the lengths are right.
    subroutine test_newtons(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=warning_length), allocatable :: warn(:)
        call warnings_of(beam(card('UNITS', 'N', 'm'), ['10.0', '0.5 ', '1.0 '], &
                              '30.0E6', '40.0E3', '1000.0'), warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=40) :: 'STRUCTURE E', 'SOIL E_f', &
                                'LOAD F_z, their sum over the base area,'], err)
    end subroutine test_newtons

    !> Layered ground in kN mm with moduli in kPa: every modulus is 1e9 times its SI value
    !! (8e3, 20e3, 30e3, 200e3 kN/mm^2 = 8e12 ... 2e14 Pa > 1e11 Pa), so the structure's E,
    !! the top layer's E (E_f) and E_bottom, the second layer's E and the base's E warn; the
    !! thicknesses 4000 and 6000 mm are no checked dimension.
    subroutine test_layered(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=warning_length), allocatable :: warn(:)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'PLATE'), card('UNITS', 'kN', 'mm'), &
                 card('GEOMETRY', '6000.0', '600.0'), card('STRUCTURE', '30.0E6', '0.2'), &
                 card('LAYER', '4000.0', '8.0E3', '0.45', '20.0E3'), &
                 card('LAYER', '6000.0', '30.0E3', '0.3'), &
                 card('BASE', 'HALFSPACE', '200.0E3', '0.3'), card('FRICTION', '0.5'), &
                 card('LOAD', 'PATCH', '8000.0', '', '0.0', '400.0'), card('END')]
        call warnings_of(lines, warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=20) :: 'STRUCTURE E', 'LAYER 1 E', &
                                'LAYER 1 E_bottom', 'LAYER 2 E', 'BASE E'], err)
    end subroutine test_layered

    !> No warning: a kip-ft strip footing (E = 432e3 ksf = 2.07e10 Pa, E_f = 600 ksf =
    !! 2.87e7 Pa, l = 40 ft = 12.2 m, h = 2.5 ft = 0.76 m, b = 4 ft = 1.22 m, 540 kip over
    !! 160 ft^2 = 3.375 ksf = 1.6e5 Pa), the same beam in kN m, and a deck without a UNITS
    !! card (N and m are then labels, not a statement: its kPa moduli are not checked).
    subroutine test_sound_decks(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=warning_length), allocatable :: warn(:)
        character(len=w), allocatable :: lines(:)
        call warnings_of(beam(card('UNITS', 'kip', 'ft', 'in', 'ksf'), ['40.0', '2.5 ', &
                              '4.0 '], '432.0E3', '600.0', '540.0'), warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=1) ::], err)
        if (allocated(err)) return
        call warnings_of(beam(card('UNITS', 'kN', 'm'), ['12.2', '0.76', '1.22'], '30.0E6', &
                              '30.0E3', '2400.0'), warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=1) ::], err)
        if (allocated(err)) return
        lines = beam(card('UNITS'), ['10.0', '0.5 ', '1.0 '], '30.0E6', '40.0E3', '1000.0')
        call warnings_of([lines(1), lines(3:)], warn, err)
        if (allocated(err)) return
        call check_named(warn, [character(len=1) ::], err)
    end subroutine test_sound_decks

    !> Display factors from the definitions of the units: 1 m = 1000 mm; 1 mm = 1e-3 m;
    !! 1 ft = 12 in; 1 m = 100 cm; kN/m^2 = kPa; kN/mm^2 = 1e9 Pa = 1e3 MPa; kip/ft^2 =
    !! 1000 lbf / 144 in^2 = 1000/144 psi; kip/ft^2 = ksf; N/m^2 = Pa.
    subroutine test_display_factors(err)
        type(error_t), allocatable, intent(out) :: err
        call check_units(card('UNITS', 'kN', 'm', 'mm', 'kPa'), 'mm', 1.0e3_dp, 'kPa', &
                         1.0_dp, err)
        if (allocated(err)) return
        call check_units(card('UNITS', 'kN', 'mm', 'm', 'MPa'), 'm', 1.0e-3_dp, 'MPa', &
                         1.0e3_dp, err)
        if (allocated(err)) return
        call check_units(card('UNITS', 'kip', 'ft', 'in', 'psi'), 'in', 12.0_dp, 'psi', &
                         1000.0_dp/144.0_dp, err)
        if (allocated(err)) return
        call check_units(card('UNITS', 'kip', 'ft', 'in', 'ksf'), 'in', 12.0_dp, 'ksf', &
                         1.0_dp, err)
        if (allocated(err)) return
        call check_units(card('UNITS', 'N', 'm', 'cm', 'Pa'), 'cm', 100.0_dp, 'Pa', 1.0_dp, &
                         err)
        if (allocated(err)) return
        ! without f3 and f4: the default display (mm from m, pressure force/length^2)
        call check_units(card('UNITS', 'kip', 'ft'), 'ft', 1.0_dp, 'kip/ft^2', 1.0_dp, err)
    end subroutine test_display_factors

    !> The display units of the deck beam(units, ...) are disp and pressure, with factors.
    subroutine check_units(units, disp, disp_factor, pressure, pressure_factor, err)
        character(len=w), intent(in) :: units
        character(len=*), intent(in) :: disp, pressure
        real(dp), intent(in) :: disp_factor, pressure_factor
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        type(units_t) :: un
        call parse_deck('t.dat', beam(units, ['10.0', '0.5 ', '1.0 '], '30.0E6', '40.0E3', &
                                      '1000.0'), deck, perr)
        call check(err, .not. allocated(perr), 'input error for '//trim(units))
        if (allocated(err)) return
        un = case_units(deck%base)
        call check(err, trim(un%disp) == disp .and. trim(un%pressure) == pressure, &
                   trim(units)//': units '//trim(un%disp)//' and '//trim(un%pressure))
        if (allocated(err)) return
        call check_close(err, un%disp_factor, disp_factor, 1.0e-14_dp, 0.0_dp, &
                         trim(units)//': settlement factor')
        if (allocated(err)) return
        call check_close(err, un%pressure_factor, pressure_factor, 1.0e-14_dp, 0.0_dp, &
                         trim(units)//': pressure factor')
    end subroutine check_units

    !> A display word fricon does not know, or a display unit without known deck units, is an
    !! input error naming the field's columns.
    subroutine test_display_errors(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_error(card('UNITS', 'kN', 'm', 'inch'), ':2:31-40: UNITS settlement '// &
                          'display unit must be one of mm, cm, m, in, ft, got ''inch''', err)
        if (allocated(err)) return
        call expect_error(card('UNITS', 'kN', 'metre', 'mm'), ':2:31-40: UNITS settlement '// &
                          'display unit needs a known length unit in f2', err)
        if (allocated(err)) return
        call expect_error(card('UNITS', 'kN', 'm', '', 'kN/m2'), ':2:41-50: UNITS pressure '// &
                          'display unit must be one of Pa, kPa', err)
        if (allocated(err)) return
        call expect_error(card('UNITS', 'tonne', 'm', '', 'kPa'), ':2:41-50: UNITS pressure '// &
                          'display unit needs known force and length units', err)
    end subroutine test_display_errors

    !> The beam with this UNITS card is refused with a message containing fragment.
    subroutine expect_error(units, fragment, err)
        character(len=w), intent(in) :: units
        character(len=*), intent(in) :: fragment
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(error_t), allocatable :: perr
        call parse_deck('t.dat', beam(units, ['10.0', '0.5 ', '1.0 '], '30.0E6', '40.0E3', &
                                      '1000.0'), deck, perr)
        call check(err, allocated(perr), trim(units)//': accepted')
        if (allocated(err)) return
        call check(err, perr%code == EXIT_INPUT .and. index(perr%message, fragment) > 0, &
                   'message lacks "'//fragment//'": '//perr%message)
    end subroutine expect_error
end module test_unit_checks
