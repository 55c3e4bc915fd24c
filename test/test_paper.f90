!> The paper's studies (output/paper/FINDINGS.md): the Table 1 deck and the parabolic interactions
!! of Fig. 7, solved from the decks in input/paper/ (no output file is written). Run from the
!! project root (fpm test -- paper): the decks are read by relative path.
module test_paper
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use model, only: model_t
    use station_results, only: station_table_t
    use solved_case, only: case_t
    use contact_test_support, only: solve_deck
    use station_test_support, only: nd, nd_all
    implicit none
    private
    public :: collect_paper

    ! Paper Table 1 (Bilotti & Olivito, section 5.1): W, Sigma_x, Sigma_z at the middle section
    ! for eps_bar = 1e-1, 1e-4, 1e-7 (rows), beam rho 0.0025, f 0.6, N_e 20, all linear.
    real(dp), parameter :: paper_table1(3, 3) = reshape([ &
        0.21138e-2_dp, 0.13397_dp, 2.3934_dp, &
        0.21235e-2_dp, 0.14348_dp, 2.4081_dp, &
        0.21235e-2_dp, 0.14348_dp, 2.4082_dp], [3, 3])

contains

    subroutine collect_paper(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('table1_deck_eps_trend', test_table1_deck), &
                 new_unittest('fig07_parabolic_interactions_error', test_parabolic_interactions)]
    end subroutine collect_paper

    !> Solve case i of a deck (contact_test_support::solve_deck): its model and stations.
    subroutine solve_deck_case(path, i, m, tab, err)
        character(len=*), intent(in) :: path
        integer, intent(in) :: i
        type(model_t), intent(out) :: m
        type(station_table_t), intent(out) :: tab
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        call solve_deck(path, 0, c, err, case_no=i)
        if (allocated(err)) return
        m = c%model
        tab = c%stations
    end subroutine solve_deck_case

    !> Nondimensional W and the finite-element Sigma_x, Sigma_z (the values the paper prints)
    !! at the station nearest t = 0 (the middle section).
    function middle_values(m, tab) result(v)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        real(dp) :: v(3)
        integer :: i
        i = minloc(abs(nd_all(m, tab, 't')), dim=1)
        v = [nd(m, tab, 'W', i), nd(m, tab, 'Sigma_x^h', i), nd(m, tab, 'Sigma_z^h', i)]
    end function middle_values

    !> input/paper/table1.dat (the reading of Fig. 5 chosen in output/paper/FINDINGS.md: central
    !! point load with H/V = 0.1, b/l = 0.0055, h/l = 0.1), cases eps_bar = 1e-1, 1e-4, 1e-7.
    !! Paper, section 5.1: "for values of eps < 1e-4 the solution is practically independent
    !! from this parameter". Asserted, with the values fricon wrote in output/paper/table1.txt
    !! (scripts/paper.sh) as the observations behind each tolerance:
    !! - W and Sigma_z at 1e-4 and 1e-7 agree to 1e-4 (observed 5.2e-5 and 4.5e-5);
    !! - Sigma_x at 1e-4 and 1e-7 agrees only to 3e-3 (observed 1.8e-3: with fricon's reading of
    !!   the law, SPEC 4, the slip branch has stiffness eps_bar/c, so the regularisation error
    !!   is first order in eps_bar and Sigma_x, decided by the slip zones, is the most
    !!   sensitive; README "Findings and known limits"; the paper's two rows agree to 5 digits);
    !! - eps_bar = 1e-1 differs: W and Sigma_z by more than 5e-3 (observed 1.3e-2 and 1.2e-2);
    !! - the 1e-4 and 1e-7 rows reproduce the paper's to 1 % (observed at most 0.79 %);
    !! - the 1e-1 row of Sigma_x does NOT: fricon's Sigma_x(1e-1)/Sigma_x(1e-7) is 0.661
    !!   (0.09563/0.14461), the paper's 0.934 (0.13397/0.14348); asserted below 0.8 so that a
    !!   change of the friction law that closes this gap is noticed (FINDINGS.md, Table 1).
    subroutine test_table1_deck(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: deck_path = 'input/paper/table1.dat'
        character(len=*), parameter :: names(3) = ['W      ', 'Sigma_x', 'Sigma_z']
        type(station_table_t) :: tab
        type(model_t) :: m
        real(dp) :: val(3, 3)
        integer :: k, j
        do k = 1, 3
            call solve_deck_case(deck_path, k, m, tab, err)
            if (allocated(err)) return
            val(:, k) = middle_values(m, tab)
        end do
        call check_close(err, val(1, 2), val(1, 3), 1.0e-4_dp, 0.0_dp, 'W eps_bar 1e-4 vs 1e-7')
        if (allocated(err)) return
        call check_close(err, val(3, 2), val(3, 3), 1.0e-4_dp, 0.0_dp, &
                         'Sigma_z eps_bar 1e-4 vs 1e-7')
        if (allocated(err)) return
        call check_close(err, val(2, 2), val(2, 3), 3.0e-3_dp, 0.0_dp, &
                         'Sigma_x eps_bar 1e-4 vs 1e-7')
        if (allocated(err)) return
        call check(err, abs(val(1, 1)/val(1, 3) - 1.0_dp) > 5.0e-3_dp .and. &
                   abs(val(3, 1)/val(3, 3) - 1.0_dp) > 5.0e-3_dp, &
                   'eps_bar = 1e-1 should change W and Sigma_z by more than 0.5 %')
        if (allocated(err)) return
        do k = 2, 3
            do j = 1, 3
                call check_close(err, val(j, k), paper_table1(j, k), 1.0e-2_dp, 0.0_dp, &
                                 'paper Table 1 '//trim(names(j)))
                if (allocated(err)) return
            end do
        end do
        call check(err, val(2, 1)/val(2, 3) < 0.8_dp, &
                   'Sigma_x(1e-1)/Sigma_x(1e-7) >= 0.8: the eps_bar = 1e-1 row now nears '// &
                   'the paper (0.934); update FINDINGS.md')
    end subroutine test_table1_deck

    !> Relative discrete L2 error of the finite-element Sigma_z over the stations against a
    !! reference table with the same stations.
    function sigma_z_error(m, tab, ref) result(e)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab, ref
        real(dp) :: e
        e = norm2(nd_all(m, tab, 'Sigma_z^h') - nd_all(m, ref, 'Sigma_z^h')) &
            /norm2(nd_all(m, ref, 'Sigma_z^h'))
    end function sigma_z_error

    !> Paper Fig. 7: interactions parabolic with a continuous first derivative (fricon S2) or
    !! linear (P1), 20 elements, displacements P1, against the fine-mesh reference N_e = 160,
    !! all P1 (input/paper/fig07_s2.dat, fig07_p1.dat, fig07_ref.dat; all three have 161
    !! equally spaced stations). What is true (output/paper/errors.txt, L2(Sz) column):
    !! - stiff beam, rho = 0.1 (case 5, full contact, smooth pressure inside): S2 reduces the
    !!   error, 7.334e-2 against 8.873e-2 for P1 (asserted: S2 < 0.95 P1);
    !! - flexible beam, rho = 0.00025 (case 1, the beam of Fig. 6: contact over 0.45 l, a cusp
    !!   of the pressure under the point load and a sharp contact edge): S2 does NOT reduce it,
    !!   4.847e-2 against 2.260e-2 for P1 (asserted: S2 > 1.5 P1). The C1 spline rounds the
    !!   cusp and overshoots at the contact edges (FINDINGS.md, Fig. 7).
    subroutine test_parabolic_interactions(err)
        type(error_t), allocatable, intent(out) :: err
        type(station_table_t) :: ref, p1, s2
        type(model_t) :: m
        real(dp) :: e_p1, e_s2
        integer :: k
        integer, parameter :: cases(2) = [5, 1]
        do k = 1, 2
            call solve_deck_case('input/paper/fig07_ref.dat', cases(k), m, ref, err)
            if (allocated(err)) return
            call solve_deck_case('input/paper/fig07_p1.dat', cases(k), m, p1, err)
            if (allocated(err)) return
            call solve_deck_case('input/paper/fig07_s2.dat', cases(k), m, s2, err)
            if (allocated(err)) return
            ! 161 OUTPUT stations, the one at the central point load listed twice
            call check(err, p1%n == ref%n .and. s2%n == ref%n .and. ref%n == 162, &
                       'fig07 decks: the three tables must share the 161 OUTPUT stations')
            if (allocated(err)) return
            e_p1 = sigma_z_error(m, p1, ref)
            e_s2 = sigma_z_error(m, s2, ref)
            if (cases(k) == 5) then
                call check(err, e_s2 < 0.95_dp*e_p1, 'rho = 0.1: S2 interactions should '// &
                           'reduce the Sigma_z error against N_e = 160 (errors.txt: 7.3e-2 vs '// &
                               '8.9e-2)')
            else
                call check(err, e_s2 > 1.5_dp*e_p1, 'rho = 0.00025: S2 interactions were '// &
                           'found to double the Sigma_z error (errors.txt: 4.8e-2 vs 2.3e-2)')
            end if
            if (allocated(err)) return
        end do
    end subroutine test_parabolic_interactions
end module test_paper
