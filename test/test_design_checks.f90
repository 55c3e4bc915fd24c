!> The design checks of the CHECK cards (design_checks, check_cards, check_report): each
!! check's value against a hand calculation (statics, closed forms, the definition applied to
!! the station values by the test itself), utilisation and pass/fail, the loaded points, and a
!! deck whose check fails: exit status 0 and FAIL in the report and the JSON.
module test_design_checks
    use iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_OK
    use deck_reader, only: deck_t, parse_deck, read_deck
    use model, only: model_t, load_t, LOAD_POINT, LOAD_PATCH, LOAD_MOMENT, LOAD_RING, &
                     MODEL_BEAM, MODEL_PLATE
    use solved_case, only: case_t, solve_case
    use station_columns, only: Q_X, Q_W
    use loaded_points, only: loaded_positions
    use design_checks, only: design_check_t, evaluate_design_checks, circle_effective_area, &
                             check_entries, governing_check
    use summary_table, only: entry_t
    use design_limits, only: CHECK_BEARING
    use analysis_driver, only: run_analysis
    use test_deck_reader, only: card
    use test_design_values, only: json_value
    use plausibility, only: input_warnings, warning_length
    implicit none
    private
    public :: collect_design_checks

    integer, parameter :: w = 200   !! width of test lines (as test_deck_reader%card)

contains

    subroutine collect_design_checks(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('bearing_mean_uniform_beam', test_bearing_mean), &
                 new_unittest('effective_area_and_sliding', test_effective_sliding), &
                 new_unittest('circle_effective_area', test_circle_area), &
                 new_unittest('rigid_plate_settlement', test_rigid_plate), &
                 new_unittest('loaded_points', test_loaded_points), &
                 new_unittest('relative_rotation_columns', test_relative_rotation), &
                 new_unittest('contact_ratio_liftoff', test_contact_ratio), &
                 new_unittest('governing_check_has_a_margin', test_governing_with_margin), &
                 new_unittest('failed_check_is_a_result', test_failed_check), &
                 new_unittest('limits_in_wrong_units_warned', test_limit_warnings)]
    end subroutine collect_design_checks

    !> A beam l = 10 m, h, b = 2 m, E = 30 GPa, on E_f = 40 MPa, nu_f 0.3, f = 0.5, with the
    !! given LOAD and CHECK cards (kN and m).
    pure function beam_deck(h, loads, checks) result(lines)
        character(len=*), intent(in) :: h
        character(len=w), intent(in) :: loads(:), checks(:)
        character(len=w), allocatable :: lines(:)
        lines = [card('MODEL', 'BEAM'), card('UNITS', 'kN', 'm'), &
                 card('GEOMETRY', '10.0', h, '2.0'), card('STRUCTURE', '30.0E6', '0.2'), &
                 card('SOIL', '40.0E3', '0.3'), card('FRICTION', '0.5'), loads, checks, &
                 card('MESH', '40'), card('END')]
    end function beam_deck

    !> Parse and solve a deck; its checks.
    subroutine solve_lines(lines, c, checks, err)
        character(len=*), intent(in) :: lines(:)
        type(case_t), intent(out) :: c
        type(design_check_t), allocatable, intent(out) :: checks(:)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        call parse_deck('checks.dat', lines, deck, err)
        if (allocated(err)) return
        call solve_case(deck%base, c, err)
        if (allocated(err)) return
        checks = evaluate_design_checks(c%model, c%summary)
    end subroutine solve_lines

    !> The check named `name` must have this value (rtol), utilisation and verdict.
    subroutine check_one(checks, name, value, rtol, utilisation, pass, err)
        type(design_check_t), intent(in) :: checks(:)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: value, rtol, utilisation
        logical, intent(in) :: pass
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        do k = 1, size(checks)
            if (trim(checks(k)%name) /= name) cycle
            call check_close(err, checks(k)%value, value, rtol, 0.0_dp, name//' value')
            if (allocated(err)) return
            call check_close(err, checks(k)%utilisation, utilisation, max(rtol, 1.0e-14_dp), &
                             0.0_dp, name//' utilisation')
            if (allocated(err)) return
            call check(err, checks(k)%pass .eqv. pass, name//' pass/fail')
            return
        end do
        call check(err, .false., 'no check '//name)
    end subroutine check_one

    !> A uniform line load q = 200 kN/m over the whole beam (V = 2000 kN) keeps it in full
    !! contact: mean pressure V / (b l) = 2000 / (2 x 10) = 100 kPa, against 125 kPa:
    !! utilisation 0.8 (pass); no eccentricity, so the effective-area pressure is the same
    !! 100 kPa (its limit defaults to the first, 125). The edge check's limit 90 kPa: the
    !! pressure at d = h from an end of a beam on a half-space exceeds the mean (it rises
    !! towards the edges): FAIL, utilisation its value / 90.
    subroutine test_bearing_mean(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        integer :: k
        call solve_lines(beam_deck('0.5', [card('LOAD', 'PRESSURE', '200.0', '', '-5.0', &
            '5.0')], [card('CHECK', 'BEARING', '125.0', '90.0')]), c, checks, err)
        if (allocated(err)) return
        call check(err, size(checks) == 3, 'BEARING gives three checks')
        if (allocated(err)) return
        call check_one(checks, 'BEARING_MEAN', 100.0_dp, 1.0e-12_dp, 0.8_dp, .true., err)
        if (allocated(err)) return
        call check_one(checks, 'BEARING_EFFECTIVE', 100.0_dp, 1.0e-12_dp, 0.8_dp, .true., err)
        if (allocated(err)) return
        k = 2
        call check(err, trim(checks(k)%name) == 'BEARING_EDGE' .and. checks(k)%value > &
                   100.0_dp .and. .not. checks(k)%pass, 'BEARING_EDGE above the mean, FAIL')
        if (allocated(err)) return
        call check_close(err, checks(k)%value, max(c%summary%edge_pressure(1), &
                         c%summary%edge_pressure(2)), 1.0e-14_dp, 0.0_dp, 'edge = summary''s')
        if (allocated(err)) return
        call check_close(err, checks(k)%utilisation, checks(k)%value/90.0_dp, 1.0e-14_dp, &
                         0.0_dp, 'edge utilisation')
        if (allocated(err)) return
        call check(err, governing_check(checks) == 2, 'the failed edge check governs')
    end subroutine test_bearing_mean

    !> Meyerhof's effective width and the sliding factor of safety, by statics of the loads:
    !! V = 2000 kN spread over the beam with F_x = 100 kN on its top face (h = 0.5 m above
    !! the base), and a MOMENT of 1000 kN m. About the base's centre M = 1000 + 100 x 0.5 =
    !! 1050 kN m, e = 1050 / 2000 = 0.525 m, l' = 10 - 2 x 0.525 = 8.95 m, q' = 2000 /
    !! (2 x 8.95) = 111.7318 kPa: against 100 kPa a utilisation of 1.117318 (FAIL). Sliding:
    !! f V / H = 0.5 x 2000 / 100 = 10, against FS_min 1.5: utilisation 1.5 / 10 = 0.15.
    subroutine test_effective_sliding(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        type(entry_t), allocatable :: e(:)
        real(dp) :: q
        q = 2000.0_dp/(2.0_dp*(10.0_dp - 2.0_dp*1050.0_dp/2000.0_dp))
        call solve_lines(beam_deck('0.5', [card('LOAD', 'PATCH', '2000.0', '100.0', '-5.0', &
            '5.0'), card('LOAD', 'MOMENT', '1000.0')], [card('CHECK', 'BEARING', '200.0', &
            '', '100.0'), card('CHECK', 'SLIDING', '1.5')]), c, checks, err)
        if (allocated(err)) return
        call check_one(checks, 'BEARING_EFFECTIVE', 111.731843575419_dp, 1.0e-12_dp, &
                       q/100.0_dp, .false., err)
        if (allocated(err)) return
        call check_one(checks, 'SLIDING_FS', 10.0_dp, 1.0e-14_dp, 0.15_dp, .true., err)
        if (allocated(err)) return
        ! the values and utilisations as named design values: two entries per check
        e = check_entries(checks)
        call check(err, size(e) == 2*size(checks) .and. e(5)%key == &
                   'bearing_effective_value' .and. e(6)%key == &
                   'bearing_effective_utilisation', 'check_entries keys')
        if (allocated(err)) return
        call check_close(err, e(6)%value, q/100.0_dp, 1.0e-12_dp, 0.0_dp, 'entry utilisation')
    end subroutine test_effective_sliding

    !> EN 1997-1 Annex D's effective area of a circle, 2 (r^2 acos(e/r) - e sqrt(r^2 - e^2)):
    !! r = 10, e = 0: pi 100 = 314.159265; e = 5: 2 (100 pi/3 - 5 sqrt 75) = 2 (104.719755 -
    !! 43.301270) = 122.836970; e >= r: 0. A tank raft's effective-area pressure (the plate
    !! carries no moment, e = 0) is V / (pi a^2): input/tank_raft_clay.dat, V = 7238 + 25133
    !! kN on a = 10 m: 32371 / (100 pi) = 103.0404 kPa.
    subroutine test_circle_area(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        call check_close(err, circle_effective_area(10.0_dp, 0.0_dp), 100.0_dp*pi, &
                         1.0e-15_dp, 0.0_dp, 'A(e = 0)')
        if (allocated(err)) return
        call check_close(err, circle_effective_area(10.0_dp, 5.0_dp), 122.83696986087568_dp, &
                         1.0e-13_dp, 0.0_dp, 'A(e = r/2)')
        if (allocated(err)) return
        call check(err, circle_effective_area(10.0_dp, 10.0_dp) == 0.0_dp, 'A(e = r) = 0')
        if (allocated(err)) return
        call read_deck('input/tank_raft_clay.dat', deck, err)
        if (allocated(err)) return
        call solve_case(deck%base, c, err)
        if (allocated(err)) return
        checks = evaluate_design_checks(c%model, c%summary)
        call check_one(checks, 'BEARING_EFFECTIVE', 32371.0_dp/(100.0_dp*pi), 1.0e-12_dp, &
                       32371.0_dp/(100.0_dp*pi)/c%model%limits%limit(3, CHECK_BEARING), .true., err)
    end subroutine test_circle_area

    !> A very stiff circular plate (a = 5 m, h = 1 m, E = 30 GPa on E_f = 20 MPa, nu_f 0.3:
    !! rho = 2 D (1 - nu_f^2)/(E_f a^3) = 1.9e3), frictionless, under 1000 kN spread over it
    !! settles like a smooth rigid punch (Boussinesq): w = V (1 - nu_f^2)/(2 a E_f) = 1000 x
    !! 0.91/(2 x 5 x 20e3) = 4.55 mm, to the discretisation error (1 %); against 5 mm a
    !! utilisation of w / 5.
    !! An axisymmetric plate has no tilt (0 exactly), no horizontal load (sliding n/a) and
    !! here one loaded point only, the axis (relative rotation n/a): those pass with
    !! utilisation 0.
    subroutine test_rigid_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        integer :: k
        call solve_lines([card('MODEL', 'PLATE'), card('UNITS', 'kN', 'm'), &
            card('GEOMETRY', '5.0', '1.0'), card('STRUCTURE', '30.0E9', '0.2'), &
            card('SOIL', '20.0E3', '0.3'), card('FRICTION', '0.0'), &
            card('LOAD', 'PATCH', '1000.0', '', '0.0', '5.0'), card('CHECK', 'SETTLE', &
            '5.0E-3'), card('CHECK', 'ROTATION', '1.0E-3'), card('CHECK', 'TILT', '1.0E-3'), &
            card('CHECK', 'SLIDING', '1.5'), card('MESH', '40'), card('END')], c, checks, err)
        if (allocated(err)) return
        call check_close(err, checks(1)%value, 4.55_dp, 1.0e-2_dp, 0.0_dp, &
                         'SETTLEMENT against the rigid punch')
        if (allocated(err)) return
        call check_one(checks, 'SETTLEMENT', checks(1)%value, 0.0_dp, checks(1)%value/5.0_dp, &
                       .true., err)
        if (allocated(err)) return
        call check_one(checks, 'TILT', 0.0_dp, 0.0_dp, 0.0_dp, .true., err)
        if (allocated(err)) return
        do k = 2, 4, 2
            call check(err, .not. checks(k)%defined .and. checks(k)%pass .and. &
                       checks(k)%utilisation == 0.0_dp, trim(checks(k)%name)//' n/a, pass')
            if (allocated(err)) return
        end do
    end subroutine test_rigid_plate

    !> The loaded points by their rule (loaded_points): beam POINT at 1, MOMENT at 1 (the
    !! same point), PATCH [-3, -2] at its centre -2.5, a PATCH over the whole beam none:
    !! [-2.5, 1]. Plate: the axis, a disk PATCH (the axis), an annulus [4, 6] at 5, a RING at
    !! 9.6: [0, 5, 9.6].
    subroutine test_loaded_points(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        real(dp), allocatable :: x(:)
        m%structure%kind = MODEL_BEAM
        m%structure%length = 10.0_dp
        m%loads = [load_t(LOAD_POINT, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0), &
                   load_t(LOAD_PATCH, 1.0_dp, 0.0_dp, -3.0_dp, -2.0_dp, 0), &
                   load_t(LOAD_MOMENT, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0), &
                   load_t(LOAD_PATCH, 1.0_dp, 0.0_dp, -5.0_dp, 5.0_dp, 0)]
        x = loaded_positions(m%structure, m%loads)
        call check(err, size(x) == 2, 'two loaded points on the beam')
        if (allocated(err)) return
        call check(err, x(1) == -2.5_dp .and. x(2) == 1.0_dp, 'beam points -2.5 and 1')
        if (allocated(err)) return
        m%structure%kind = MODEL_PLATE
        m%loads = [load_t(LOAD_RING, 1.0_dp, 0.0_dp, 9.6_dp, 0.0_dp, 0), &
                   load_t(LOAD_PATCH, 1.0_dp, 0.0_dp, 0.0_dp, 10.0_dp, 0), &
                   load_t(LOAD_PATCH, 1.0_dp, 0.0_dp, 4.0_dp, 6.0_dp, 0)]
        x = loaded_positions(m%structure, m%loads)
        call check(err, size(x) == 3, 'three loaded points on the plate')
        if (allocated(err)) return
        call check(err, x(1) == 0.0_dp .and. x(2) == 5.0_dp .and. x(3) == 9.6_dp, &
                   'plate points 0, 5, 9.6')
    end subroutine test_loaded_points

    !> Three columns (900, 1500, 900 kN at x = -5, 0, 5 m, 0.4 m wide, the middle with 60 kN
    !! of wind) on a 12 m beam: the relative rotation by its definition (Burland & Wroth,
    !! EN 1997-1 Annex H), computed here from the design table's settlements interpolated at
    !! the columns: max over the two spans of |(w_k+1 - w_k)/5 - tilt|, tilt = (w(6) - w(-6))
    !! / 12. DIFF_SETTLEMENT and TILT are the summary's max - min and |tilt| (the same table).
    subroutine test_relative_rotation(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        real(dp), parameter :: xs(3) = [-5.0_dp, 0.0_dp, 5.0_dp]   !! the columns [m]
        real(dp) :: wc(3), tilt, beta
        integer :: k
        call solve_lines([card('MODEL', 'BEAM'), card('UNITS', 'kN', 'm'), &
            card('GEOMETRY', '12.0', '0.9', '1.5'), card('STRUCTURE', '30.0E6', '0.2'), &
            card('SOIL', '20.0E3', '0.3'), card('FRICTION', '0.5'), &
            card('LOAD', 'PATCH', '900.0', '', '-5.2', '-4.8'), &
            card('LOAD', 'PATCH', '1500.0', '60.0', '-0.2', '0.2'), &
            card('LOAD', 'PATCH', '900.0', '', '4.8', '5.2'), &
            card('CHECK', 'ROTATION', '1.0E-4'), card('CHECK', 'DIFFSETTLE', '0.5E-3'), &
            card('CHECK', 'TILT', '1.0E-3'), card('MESH', '40'), card('END')], c, checks, err)
        if (allocated(err)) return
        associate (x => c%design%val(Q_X, :), wv => c%design%val(Q_W, :), n => c%design%n)
            do k = 1, 3
                wc(k) = linear(x, wv, xs(k))
            end do
            tilt = (wv(n) - wv(1))/12.0_dp
            beta = max(abs((wc(2) - wc(1))/5.0_dp - tilt), abs((wc(3) - wc(2))/5.0_dp - tilt))
            call check_one(checks, 'RELATIVE_ROTATION', beta, 1.0e-12_dp, beta/1.0e-4_dp, &
                           beta <= 1.0e-4_dp, err)
            if (allocated(err)) return
            call check_one(checks, 'DIFF_SETTLEMENT', 1.0e3_dp*(maxval(wv) - minval(wv)), &
                           1.0e-12_dp, (maxval(wv) - minval(wv))/0.5e-3_dp, &
                           maxval(wv) - minval(wv) <= 0.5e-3_dp, err)
            if (allocated(err)) return
            call check_one(checks, 'TILT', abs(tilt), 1.0e-12_dp, abs(tilt)/1.0e-3_dp, .true., &
                           err)
        end associate
    end subroutine test_relative_rotation

    !> y(x) linearly interpolated between the points (xs ascending; the first bracket).
    pure real(dp) function linear(xs, ys, x) result(y)
        real(dp), intent(in) :: xs(:), ys(:), x
        integer :: i
        y = ys(size(ys))
        do i = 1, size(xs) - 1
            if (x < xs(i) .or. x > xs(i + 1) .or. xs(i + 1) <= xs(i)) cycle
            y = ys(i) + (ys(i + 1) - ys(i))*(x - xs(i))/(xs(i + 1) - xs(i))
            return
        end do
    end function linear

    !> A column of 1000 kN at x = 3 m on a flexible 10 m beam (h = 0.3 m) lifts off the far
    !! end: the contact ratio is the contact length over l, (l - lift-off left - lift-off
    !! right) / l from the summary's lift-off lengths, against the no-gapping limit 1: FAIL,
    !! utilisation 1 / ratio.
    subroutine test_contact_ratio(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        real(dp) :: ratio
        call solve_lines(beam_deck('0.3', [card('LOAD', 'POINT', '1000.0', '', '3.0')], &
            [card('CHECK', 'CONTACT', '1.0')]), c, checks, err)
        if (allocated(err)) return
        call check(err, c%summary%liftoff(1) > 0.5_dp, 'the left end lifts off')
        if (allocated(err)) return
        ratio = (10.0_dp - c%summary%liftoff(1) - c%summary%liftoff(2))/10.0_dp
        call check_one(checks, 'CONTACT_RATIO', ratio, 1.0e-12_dp, 1.0_dp/ratio, .false., err)
    end subroutine test_contact_ratio

    !> The governing check of a base in full contact under CONTACT 1.0 (no gapping): the
    !! contact ratio is 1 = its limit, utilisation exactly 1 by construction (it cannot be
    !! larger than 1 and pass), so the governing check is the one with a margin, the mean
    !! bearing pressure: 200 kN/m over a 10 m x 2 m beam, V/(b l) = 100 kPa against 400 kPa,
    !! utilisation 0.25. A gap makes the contact check fail and govern (utilisation 1/ratio).
    subroutine test_governing_with_margin(err)
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(design_check_t), allocatable :: checks(:)
        integer :: g
        call solve_lines(beam_deck('0.5', [card('LOAD', 'PRESSURE', '200.0', '', '-5.0', &
            '5.0')], [card('CHECK', 'BEARING', '400.0', '1.0E4', '1.0E4'), &
            card('CHECK', 'CONTACT', '1.0')]), c, checks, err)
        if (allocated(err)) return
        call check_one(checks, 'CONTACT_RATIO', 1.0_dp, 1.0e-12_dp, 1.0_dp, .true., err)
        if (allocated(err)) return
        g = governing_check(checks)
        call check(err, g > 0, 'a governing check')
        if (allocated(err)) return
        call check(err, trim(checks(g)%name) == 'BEARING_MEAN', 'BEARING_MEAN governs, not '// &
                   'the met no-gapping check: '//trim(checks(g)%name))
        if (allocated(err)) return
        call check_close(err, checks(g)%utilisation, 0.25_dp, 1.0e-12_dp, 0.0_dp, &
                         'governing utilisation 100/400')
        if (allocated(err)) return
        call solve_lines(beam_deck('0.3', [card('LOAD', 'POINT', '1000.0', '', '3.0')], &
            [card('CHECK', 'BEARING', '1.0E4'), card('CHECK', 'CONTACT', '1.0')]), c, checks, &
            err)
        if (allocated(err)) return
        g = governing_check(checks)
        call check(err, g > 0, 'a governing check with a gap')
        if (allocated(err)) return
        call check(err, trim(checks(g)%name) == 'CONTACT_RATIO' .and. .not. checks(g)%pass, &
                   'a gap: the failed no-gapping check governs')
    end subroutine test_governing_with_margin

    !> A deck whose bearing check fails (the 12 m strip footing's mean pressure 3300 kN /
    !! (1.5 x 12 m^2) = 183.3 kPa against 150) solves with exit status 0: the report's table
    !! says FAIL, the JSON's "pass" is false with the utilisation 183.33 / 150 = 1.2222.
    subroutine test_failed_check(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_design_checks'
        type(deck_t) :: deck
        integer :: status, u, ios
        character(len=400) :: line
        logical :: failed_row
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call parse_deck(dir//'_deck.dat', [card('MODEL', 'BEAM'), card('UNITS', 'kN', 'm'), &
            card('GEOMETRY', '12.0', '0.9', '1.5'), card('STRUCTURE', '30.0E6', '0.2'), &
            card('SOIL', '20.0E3', '0.3'), card('FRICTION', '0.5'), &
            card('LOAD', 'PATCH', '1650.0', '', '-5.2', '-4.8'), &
            card('LOAD', 'PATCH', '1650.0', '', '4.8', '5.2'), &
            card('CHECK', 'BEARING', '150.0', '1000.0', '1000.0'), card('MESH', '20'), &
            card('END')], deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status)
        call check(err, status == EXIT_OK, 'a failed design check is a result: exit 0')
        if (allocated(err)) return
        failed_row = .false.
        open (newunit=u, file=dir//'/test_design_checks_deck.txt', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'BEARING_MEAN') > 0) failed_row = index(line, 'FAIL') > 0
        end do
        close (u)
        call check(err, failed_row, 'the report''s BEARING_MEAN row says FAIL')
        if (allocated(err)) return
        call check_close(err, json_value(dir//'/test_design_checks_deck.json', &
                         '"utilisation":'), 3300.0_dp/18.0_dp/150.0_dp, 1.0e-12_dp, 0.0_dp, &
                         'JSON utilisation of BEARING_MEAN')
        if (allocated(err)) return
        call check(err, json_value(dir//'/test_design_checks_deck.json', '"status":') == &
                   0.0_dp, 'JSON status 0')
    end subroutine test_failed_check

    !> Limits that are legal but likely slips of units are warned (limit_warnings): on a 10 m
    !! beam a settlement limit of 25 (meant as mm, read as 25 m: above l/10 = 1 m), a relative
    !! rotation of 500 (meant as 1/500: above 0.1 rad) and FS_min 0.8 (below 1); the same
    !! limits written as meant (25.0E-3, 2.0E-3, 1.5) give no warning.
    subroutine test_limit_warnings(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        character(len=warning_length), allocatable :: warn(:)
        character(len=*), parameter :: kinds(3) = [character(len=8) :: 'SETTLE', 'ROTATION', &
                                                    'SLIDING']
        character(len=*), parameter :: slips(3) = [character(len=10) :: '25.0', '500.0', '0.8']
        character(len=*), parameter :: meant(3) = [character(len=10) :: '25.0E-3', '2.0E-3', &
                                                    '1.5']
        integer :: k
        call parse_deck('w.dat', beam_deck('0.5', [card('LOAD', 'POINT', '1000.0')], &
            [(card('CHECK', trim(kinds(k)), slips(k)), k=1, 3)]), deck, err)
        if (allocated(err)) return
        warn = input_warnings(deck%base)
        call check(err, size(warn) == 3, 'three warnings about the limits')
        if (allocated(err)) return
        do k = 1, 3
            call check(err, index(warn(k), 'CHECK '//trim(kinds(k))) == 1, &
                       'warning '//trim(warn(k))//' should name CHECK '//trim(kinds(k)))
            if (allocated(err)) return
        end do
        call parse_deck('w.dat', beam_deck('0.5', [card('LOAD', 'POINT', '1000.0')], &
            [(card('CHECK', trim(kinds(k)), meant(k)), k=1, 3)]), deck, err)
        if (allocated(err)) return
        warn = input_warnings(deck%base)
        call check(err, size(warn) == 0, 'no warning for limits as meant')
    end subroutine test_limit_warnings
end module test_design_checks
