!> The layered ground through the whole program (deck -> model -> solve_case -> key results):
!!  * identical layers over a half-space of the same E and nu are the homogeneous half-space
!!    (an exact identity of elasticity: the interfaces carry nothing), so every deck of
!!    input/ with its SOIL card (NONDIM: its nu_f) replaced by three such layers and a
!!    HALFSPACE base, as deck text, must give today's solution and key results; the layered
!!    T equals the homogeneous one to about 1e-13 (suite layered_ground), so 1e-8 leaves the
!!    Newton solver's tolerances room and nothing else;
!!  * a rigid frictionless punch on a layer of thickness a on a rough base through the
!!    program (a NONDIM plate of rho = 1e4 under a central unit load, f = 0) against the
!!    independent Nystrom solution of the punch's Fredholm equation (test_layered_ground's
!!    punch_nystrom: the compliance alone, no basis, no T);
!!  * a flexible uniform circle (a plate of rho = 1.6e-11 under a PATCH load over its whole
!!    radius, f = 0) on two layers over a half-space through the program: its rim settlement
!!    against the program ELLEA1 as published in ALVA's validation data (the case and the
!!    source are in test_layered_ground's header, test ellea1_two_circles_surface_profile);
!!  * the same, NONDIM moduli and thicknesses: a deck with layers in units of a and moduli
!!    relative to the top layer equals the physical deck that it stands for;
!!  * a layered SWEEP deck through the driver (run_analysis, files in build/): the run's one
!!    flexibility cache keeps the grounds of its cases apart, and a SWEEP DEPTH value below
!!    a swept layer is refused for the cases it makes impossible, and for those only.
module test_layered_program
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: new_error, EXIT_INTERNAL, EXIT_OK, EXIT_INPUT
    use model, only: model_t, FIELD_W, layer_count
    use deck_reader, only: deck_t, read_deck, parse_deck, case_count, case_model
    use deck_fields, only: field_text, format_real, int_text
    use solved_case, only: case_t, solve_case
    use test_layered_ground, only: punch_nystrom
    use test_design_values, only: json_value
    use analysis_driver, only: run_analysis, run_options_t
    implicit none
    private
    public :: collect_layered_program

    character(len=*), parameter :: decks(9) = [character(len=24) :: 'beam_nondim.dat', &
        'beam_physical.dat', 'default.dat', 'plate_adapt.dat', 'plate_nondim.dat', &
        'plate_physical.dat', 'strip_footing.dat', 'sweep.dat', 'tank_raft.dat']
    real(dp), parameter :: tol = 1.0e-8_dp   !! identical layers vs SOIL

contains

    subroutine collect_layered_program(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('identical_layers_every_input_deck', test_identical_layers), &
                 new_unittest('rigid_punch_on_layer_vs_nystrom', test_punch), &
                 new_unittest('nondim_layers_equal_physical', test_nondim_physical), &
                 new_unittest('layered_sweep_through_driver', test_sweep_driver), &
                 new_unittest('depth_error_only_for_its_cases', test_depth_error), &
                 new_unittest('flexible_circle_vs_ellea1', test_flexible_circle)]
    end subroutine collect_layered_program

    !> Every case of every deck of input/ (the layered example decks excepted: they have no
    !! SOIL card), SOIL and layered.
    subroutine test_identical_layers(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: soil, layered
        character(len=80), allocatable :: lines(:)
        integer :: k, i
        each_deck: do k = 1, size(decks)
            call read_deck('input/'//trim(decks(k)), soil, err)
            if (allocated(err)) return
            lines = layered_lines(soil)
            call parse_deck('layered_'//trim(decks(k)), lines, layered, err)
            if (allocated(err)) return
            call check(err, case_count(layered) == case_count(soil), trim(decks(k))//': cases')
            if (allocated(err)) return
            do i = 1, case_count(soil)
                call compare_case(soil, layered, i, trim(decks(k)), err)
                if (allocated(err)) return
            end do
        end do each_deck
    end subroutine test_identical_layers

    !> The deck's lines with SOIL (physical) replaced by, or after NONDIM (NONDIM) followed by,
    !! three identical layers (0.2, 0.3 and 0.5 of l or a) over a HALFSPACE of the same E, nu.
    function layered_lines(deck) result(lines)
        type(deck_t), intent(in) :: deck
        character(len=80), allocatable :: lines(:)
        character(len=10) :: e, nu, h(3)
        real(dp) :: length
        integer :: i, j
        allocate (lines(0))
        length = 1.0_dp
        if (.not. deck%base%nondim) length = deck%base%structure%length
        h(1) = format_real(0.2_dp*length)
        h(2) = format_real(0.3_dp*length)
        h(3) = format_real(0.5_dp*length)
        do i = 1, size(deck%lines)
            if (deck%lines(i)(1:4) == 'SOIL') then
                e = field_text(deck%lines(i), 1)
                nu = field_text(deck%lines(i), 2)
                lines = [character(len=80) :: lines, ('LAYER     '//h(j)//e//nu, j = 1, 3), &
                         'BASE      HALFSPACE '//e//nu]
            else if (deck%lines(i)(1:6) == 'NONDIM') then
                nu = format_real(deck%base%ground%nu_f)
                lines = [character(len=80) :: lines, deck%lines(i), 'LAYER     '//h(1), &
                         ('LAYER     '//h(j)//'1.0       '//nu, j = 2, 3), &
                         'BASE      HALFSPACE 1.0       '//nu]
            else
                lines = [character(len=80) :: lines, deck%lines(i)]
            end if
        end do
    end function layered_lines

    !> Case i of both decks: the solution [v; r] (each block relative to its largest entry)
    !! and every key result (relative to the largest of the same unit) within tol.
    subroutine compare_case(soil, layered, i, name, err)
        type(deck_t), intent(in) :: soil, layered
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m_soil, m_lay
        type(case_t) :: c_soil, c_lay
        character(len=:), allocatable :: label
        character(len=120) :: what
        real(dp) :: mirrored
        integer :: nv, k
        call case_model(soil, i, m_soil, label, err)
        if (allocated(err)) return
        call case_model(layered, i, m_lay, label, err)
        if (allocated(err)) return
        call solve_case(m_soil, c_soil, err)
        if (allocated(err)) return
        call solve_case(m_lay, c_lay, err)
        if (allocated(err)) return
        write (what, '(a,", case ",i0)') name, i
        call check(err, layer_count(m_lay%ground) == 3, trim(what)//': not three layers')
        if (allocated(err)) return
        nv = c_soil%d%nv
        call check(err, size(c_lay%sol%z) == size(c_soil%sol%z), trim(what)//': sizes')
        if (allocated(err)) return
        call check_close(err, block_diff(c_lay%sol%z(:nv), c_soil%sol%z(:nv)), 0.0_dp, &
                         0.0_dp, tol, trim(what)//': displacements')
        if (allocated(err)) return
        call check_close(err, block_diff(c_lay%sol%z(nv + 1:), c_soil%sol%z(nv + 1:)), 0.0_dp, &
                         0.0_dp, tol, trim(what)//': tractions')
        if (allocated(err)) return
        do k = 1, size(c_soil%entries)
            associate (a => c_lay%entries(k), b => c_soil%entries(k))
                if (.not. b%defined .or. b%integer_valued) cycle
                ! the place of a largest value: in a symmetric beam case (strip_footing) the
                ! largest moment is reached at x and -x alike, and round-off picks one
                mirrored = 1.0_dp
                if (is_place(b%key) .and. abs(a%value + b%value) < abs(a%value - b%value)) &
                    mirrored = -1.0_dp
                call check_close(err, mirrored*a%value, b%value, 0.0_dp, &
                                 tol*unit_scale(c_soil, k), trim(what)//': '//trim(b%key))
                if (allocated(err)) return
            end associate
        end do
    end subroutine compare_case

    !> A key result that is the place of another (settlement_max_x, moment_sagging_x, ...).
    pure logical function is_place(key)
        character(len=*), intent(in) :: key
        integer :: n
        n = len_trim(key)
        is_place = .false.
        if (n > 2) is_place = key(n - 1:n) == '_x'
    end function is_place

    !> max |a - b| / max |b|.
    pure real(dp) function block_diff(a, b)
        real(dp), intent(in) :: a(:), b(:)
        block_diff = maxval(abs(a - b))/max(maxval(abs(b)), tiny(1.0_dp))
    end function block_diff

    !> The largest |value| of the defined key results with the unit of entry k.
    pure real(dp) function unit_scale(c, k)
        type(case_t), intent(in) :: c
        integer, intent(in) :: k
        integer :: j
        unit_scale = tiny(1.0_dp)
        do j = 1, size(c%entries)
            if (.not. c%entries(j)%defined) cycle
            if (c%entries(j)%unit /= c%entries(k)%unit) cycle
            unit_scale = max(unit_scale, abs(c%entries(j)%value))
        end do
    end function unit_scale

    !> A rigid plate (rho = 1e4) under a central unit load, frictionless, on one layer of
    !! thickness a over a rough base: w_hs/w_layer, both through the program on the same
    !! EDGES mesh (the edge singularity's discretisation error cancels in the ratio, as in
    !! test_layered_ground), is the load ratio P_layer/P_hs at equal settlement of the
    !! Nystrom solution (nu_f = 0.3 and 0.5).
    subroutine test_punch(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: nus(2) = ['0.3', '0.5']
        real(dp) :: w_hs, w_layer, ratio
        integer :: i
        do i = 1, 2
            call punch_settlement(nus(i), .false., w_hs, err)
            if (allocated(err)) return
            call punch_settlement(nus(i), .true., w_layer, err)
            if (allocated(err)) return
            call punch_nystrom(merge(0.3_dp, 0.5_dp, i == 1), ratio, err)
            if (allocated(err)) return
            call check_close(err, w_hs/w_layer, ratio, 2.0e-4_dp, 0.0_dp, &
                             'w_hs/w_layer of the rigid plate, nu_f = '//nus(i))
            if (allocated(err)) return
        end do
    end subroutine test_punch

    !> Central settlement of the rigid plate of test_punch, on the half-space or the layer.
    subroutine punch_settlement(nu, layer, w, err)
        character(len=*), intent(in) :: nu
        logical, intent(in) :: layer
        real(dp), intent(out) :: w
        type(error_t), allocatable, intent(out) :: err
        character(len=80), allocatable :: lines(:)
        type(case_t) :: c
        lines = [character(len=80) :: 'MODEL     PLATE', &
                 'NONDIM    1.0E4     0.1       0.3       '//nu, &
                 'FRICTION  0.0', 'LOAD      POINT     1.0', 'MESH      48        EDGES', 'END']
        if (layer) lines = [character(len=80) :: lines(1:2), 'LAYER     1.0', &
                            'BASE      ROUGH', lines(3:)]
        call solve_lines('punch', lines, c, err)
        if (allocated(err)) return
        w = c%sol%z(settlement_dof(c))
    end subroutine punch_settlement

    !> The first case of a deck given as lines, solved.
    subroutine solve_lines(name, lines, c, err)
        character(len=*), intent(in) :: name
        character(len=80), intent(in) :: lines(:)
        type(case_t), intent(out) :: c
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        call parse_deck(name, lines, deck, err)
        if (allocated(err)) return
        call case_model(deck, 1, m, label, err)
        if (allocated(err)) return
        call solve_case(m, c, err)
    end subroutine solve_lines

    !> Index in z of the settlement w at the plate's centre (the first w coefficient).
    integer function settlement_dof(c) result(k)
        type(case_t), intent(in) :: c
        k = c%d%offset(FIELD_W) + 1
    end function settlement_dof

    !> A NONDIM beam deck on two layers (thicknesses in l, moduli relative to the top
    !! layer's) and the physical deck of the same numbers (l = 1, E = 1, F = 1 and the top
    !! layer's E_f that rho gives, each modulus rounded to the 5 digits of a deck field)
    !! have the same solution to the rounding (a modulus read as absolute, or thicknesses
    !! not in units of l, would differ by a factor of 4 to 20).
    subroutine test_nondim_physical(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: nondim, physical
        type(model_t) :: m_nd, m_ph
        type(case_t) :: c_nd, c_ph
        character(len=:), allocatable :: label
        character(len=10) :: e1, e2, e3, eb
        call parse_deck('nondim', [character(len=80) :: 'MODEL     BEAM', &
            'NONDIM    0.01      0.1       0.3       0.3       0.1', &
            'LAYER     0.2', 'LAYER     0.5       4.0       0.4       8.0', &
            'BASE      HALFSPACE 20.0      0.25', 'FRICTION  0.5', &
            'LOAD      POINT     1.0       0.1       0.1', 'MESH      20', 'END'], nondim, err)
        if (allocated(err)) return
        call case_model(nondim, 1, m_nd, label, err)
        if (allocated(err)) return
        write (e1, '(es10.4)') m_nd%ground%e_f
        write (e2, '(es10.4)') 4.0_dp*m_nd%ground%e_f
        write (e3, '(es10.4)') 8.0_dp*m_nd%ground%e_f
        write (eb, '(es10.4)') 20.0_dp*m_nd%ground%e_f
        call parse_deck('physical', [character(len=80) :: 'MODEL     BEAM', &
            'GEOMETRY  1.0       0.1       0.1', 'STRUCTURE 1.0       0.3', &
            'LAYER     0.2       '//e1//'0.3', 'LAYER     0.5       '//e2//'0.4       '//e3, &
            'BASE      HALFSPACE '//eb//'0.25', &
            'FRICTION  0.5', 'LOAD      POINT     1.0       0.1       0.1', 'MESH      20', &
            'END'], physical, err)
        if (allocated(err)) return
        call case_model(physical, 1, m_ph, label, err)
        if (allocated(err)) return
        call solve_case(m_nd, c_nd, err)
        if (allocated(err)) return
        call solve_case(m_ph, c_ph, err)
        if (allocated(err)) return
        ! the physical moduli are the NONDIM ones rounded to 5 digits (es10.4): 5e-5 of each
        call check_close(err, block_diff(c_ph%sol%z, c_nd%sol%z), 0.0_dp, 0.0_dp, 2.0e-4_dp, &
                         'NONDIM vs physical layered beam')
    end subroutine test_nondim_physical

    !> The cards of a raft (a = 6 m) on two layers over rock under a central patch; `extra`
    !! before END.
    function raft_deck(e1, extra) result(lines)
        character(len=*), intent(in) :: e1            !! the LAYER 1 modulus field
        character(len=*), intent(in) :: extra(:)      !! more cards (SWEEP)
        character(len=80), allocatable :: lines(:)
        lines = [character(len=80) :: 'MODEL     PLATE', 'UNITS     kN        m', &
                 'GEOMETRY  6.0       0.6', 'STRUCTURE 30.0E6    0.2', &
                 'LAYER     4.0       '//e1//'0.45', 'LAYER     6.0       20.0E3    0.35', &
                 'BASE      ROUGH', 'FRICTION  0.5', &
                 'LOAD      PATCH     8000.0              0.0       0.4', 'MESH      20']
        lines = [character(len=80) :: lines, extra, 'END']
    end function raft_deck

    !> A SWEEP over E1 (8 and 16 MPa) on one mesh through run_analysis: the two cases share
    !! the mesh and the top layer's constants but not the ground, so the run's flexibility
    !! cache must not hand the second case the first one's T. Expected: the stiffer top
    !! layer settles less (elasticity: a stiffer layer, the same loads; with a cache keyed
    !! on the mesh alone both would be equal), and each swept case's w_max equals that of
    !! the single-case deck of its E1 run alone (its own run, its own cache: an independent
    !! computation of the same case) to 1e-10.
    subroutine test_sweep_driver(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_layered_sweep'
        character(len=10), parameter :: moduli(2) = ['8.0E3     ', '16.0E3    ']
        type(deck_t) :: deck
        type(run_options_t) :: opt
        real(dp) :: w_sweep(2), w_single(2)
        integer :: status, k, nul
        opt%figures = .false.
        opt%estimates = .false.
        call execute_command_line('rm -rf '//dir)
        call parse_deck('lsweep.dat', raft_deck(moduli(1), &
            [character(len=80) :: 'SWEEP     E1        8.0E3     16.0E3']), deck, err)
        if (allocated(err)) return
        open (newunit=nul, file='/dev/null', action='write')
        call run_analysis(deck, dir, nul, nul, status, opt)
        call check(err, status == EXIT_OK, 'the sweep did not solve: status '// &
                   int_text(status))
        if (allocated(err)) return
        cases: do k = 1, 2
            w_sweep(k) = json_value(dir//'/lsweep_00'//achar(48 + k)//'.json', &
                                    '"settlement_max":')
            call parse_deck('lsingle.dat', raft_deck(moduli(k), [character(len=80) ::]), &
                            deck, err)
            if (allocated(err)) exit cases
            call run_analysis(deck, dir, nul, nul, status, opt)
            call check(err, status == EXIT_OK, 'a single case did not solve')
            if (allocated(err)) exit cases
            w_single(k) = json_value(dir//'/lsingle.json', '"settlement_max":')
            call check_close(err, w_sweep(k), w_single(k), 1.0e-10_dp, 0.0_dp, &
                             'swept w_max vs the single case of E1 = '//trim(moduli(k)))
            if (allocated(err)) exit cases
        end do cases
        close (nul)
        if (allocated(err)) return
        call check(err, w_sweep(2) < 0.95_dp*w_sweep(1), 'E1 = 16 MPa settles '// &
                   format_real(w_sweep(2))//' mm, E1 = 8 MPa '//format_real(w_sweep(1))// &
                   ' mm: the cache gave both cases one ground')
    end subroutine test_sweep_driver

    !> SWEEP H1 4, 8 with SWEEP DEPTH 7: the base at 7 m lies inside the 8 m top layer, a
    !! fault of cases 2 and 4 (H1 = 8) that only the case's model shows. The run is refused
    !! (status 1, no output: README, exit 1 writes none), and the error names cases 2 and 4,
    !! the SWEEP DEPTH card's line and columns (deck:13:21-30), and neither case 1 nor 3.
    subroutine test_depth_error(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_layered_depth'
        character(len=*), parameter :: log_path = 'build/test_layered_depth.log'
        character(len=400) :: line
        character(len=:), allocatable :: text
        type(deck_t) :: deck
        type(run_options_t) :: opt
        integer :: status, u, ios, nul
        logical :: written
        opt%figures = .false.
        opt%estimates = .false.
        call execute_command_line('rm -rf '//dir)
        call parse_deck('ldepth.dat', raft_deck('8.0E3     ', [character(len=80) :: &
            'SWEEP     E1        8.0E3     16.0E3', 'SWEEP     H1        4.0       8.0', &
            'SWEEP     DEPTH     7.0']), deck, err)
        if (allocated(err)) return
        open (newunit=nul, file='/dev/null', action='write')
        open (newunit=u, file=log_path, status='replace', action='readwrite')
        call run_analysis(deck, dir, nul, u, status, opt)
        close (nul)
        rewind (u)
        text = ''
        read_log: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit read_log
            text = text//trim(line)//new_line('a')
        end do read_log
        close (u, status='delete')
        call check(err, status == EXIT_INPUT, 'status '//int_text(status)// &
                   ', expected 1 (input error)')
        if (allocated(err)) return
        call check(err, index(text, 'case 2 (E1=8.0E3 H1=8.0 DEPTH=7.0)') > 0 .and. &
                   index(text, 'case 4 (E1=16.0E3 H1=8.0 DEPTH=7.0)') > 0, &
                   'cases 2 and 4 not named: '//text)
        if (allocated(err)) return
        call check(err, index(text, 'case 1 ') == 0 .and. index(text, 'case 3 ') == 0, &
                   'a valid case was reported: '//text)
        if (allocated(err)) return
        call check(err, index(text, 'ldepth.dat:13:21-30: SWEEP DEPTH value v1 must be '// &
                   'greater than the layers above the last, 8 deep, got 7') > 0, &
                   'no deck:line:columns message: '//text)
        if (allocated(err)) return
        inquire (file=dir//'/ldepth_001.json', exist=written)
        call check(err, .not. written, 'a case of a refused run wrote its files')
    end subroutine test_depth_error

    !> ELLEA1's settlement at the origin under two touching circles (q = 1.1 MPa, a = 150 mm,
    !! centres at y = +-150 mm; 150 mm of E = 3000 MPa, nu = 0.30 over 600 mm of E = 200 MPa,
    !! nu = 0.35 over E = 40 MPa, nu = 0.40): 1.9174 mm, i.e. twice one circle's settlement at
    !! its rim. Here the circle is a plate of E = 1 MPa, h = 1 mm (rho = 2 D (1 - nu_f^2) /
    !! (E_f a^3) = 1.6e-11: it carries nothing) under PATCH F_z = 1.1 pi 150^2 N over its
    !! radius, deck units N and mm, MESH 100 EDGES (rim settlement converged to 1e-6 mm:
    !! 0.958722 at N_e = 100 and 200). Tolerance 1e-4 mm, one unit of the table's last digit.
    subroutine test_flexible_circle(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=80), allocatable :: lines(:)
        type(case_t) :: c
        lines = [character(len=80) :: 'MODEL     PLATE', 'GEOMETRY  150.0     1.0', &
                 'STRUCTURE 1.0       0.3', 'LAYER     150.0     3000.0    0.30', &
                 'LAYER     600.0     200.0     0.35', 'BASE      HALFSPACE 40.0      0.40', &
                 'FRICTION  0.0', 'LOAD      PATCH     77754.4182          0.0       150.0', &
                 'MESH      100       EDGES', 'END']
        call solve_lines('flexible_circle', lines, c, err)
        if (allocated(err)) return
        call check_close(err, c%summary%w_min%x, 150.0_dp, 0.0_dp, 1.0e-12_dp, &
                         'least settlement at the rim')
        if (allocated(err)) return
        call check_close(err, 2.0_dp*c%summary%w_min%value, 1.9174_dp, 0.0_dp, 1.0e-4_dp, &
                         'twice the rim settlement of the flexible circle [mm]')
    end subroutine test_flexible_circle
end module test_layered_program
