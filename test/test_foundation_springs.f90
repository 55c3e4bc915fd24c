!> The exported springs (foundation_springs) fed back as an independent Winkler bed: a beam of
!! the same stiffness K (mindlin_structure) on the nodal springs alone, under the same loads,
!! must settle as fricon's solution did (equilibrium K v + S v = q with S v = M^T r).
module test_foundation_springs
    use iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use model, only: FIELD_U, FIELD_W, FIELD_PSI
    use mindlin_structure, only: section_of, assemble_stiffness, assemble_loads
    use lapack_interfaces, only: dgesv
    use solved_case, only: case_t
    use contact_test_support, only: solve_deck
    use foundation_springs, only: spring_table_t, nodal_springs
    use errors, only: EXIT_OK
    use model, only: total_vertical_load
    use deck_reader, only: deck_t, read_deck
    use analysis_driver, only: run_analysis, run_options_t
    implicit none
    private
    public :: collect_foundation_springs

contains

    subroutine collect_foundation_springs(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('springs_reproduce_settlement_strip', test_strip), &
                 new_unittest('springs_reproduce_settlement_liftoff', test_liftoff), &
                 new_unittest('springs_csv_read_back', test_csv_strip), &
                 new_unittest('springs_csv_read_back_liftoff', test_csv_liftoff)]
    end subroutine collect_foundation_springs

    !> The strip footing (input/strip_footing.dat: full contact, friction 0.4).
    subroutine test_strip(err)
        type(error_t), allocatable, intent(out) :: err
        call winkler_reproduces('input/strip_footing.dat', err)
    end subroutine test_strip

    !> A beam loaded beyond its kern with H (input/beam_physical.dat: its left end lifts off,
    !! zero springs there).
    subroutine test_liftoff(err)
        type(error_t), allocatable, intent(out) :: err
        call winkler_reproduces('input/beam_physical.dat', err)
    end subroutine test_liftoff

    !> Solve (K + S) v = q by LU (dgesv), S: k_v on each node's w, k_h on its bottom-face
    !! displacement u_b = u_s - (h/2) psi (the stiffness k_h [1, -h/2]^T [1, -h/2] on u_s,
    !! psi), and compare w with fricon's to 1e-6 of the largest settlement.
    subroutine winkler_reproduces(deck, err)
        character(len=*), intent(in) :: deck
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(spring_table_t) :: s
        real(dp), allocatable :: k(:, :), q(:, :)
        integer, allocatable :: ipiv(:)
        real(dp) :: hh, w_scale, rel
        integer :: i, iu, iw, ip, info, nv
        call solve_deck(deck, 0, c, err)
        if (allocated(err)) return
        call nodal_springs(c%model, c%d, c%sol, s, err)
        if (allocated(err)) return
        nv = c%d%nv
        allocate (k(nv, nv), q(nv, 1), ipiv(nv))
        call assemble_stiffness(section_of(c%model%structure), c%d, k)
        call assemble_loads(c%model, c%d, q(:, 1), err)
        if (allocated(err)) return
        hh = 0.5_dp*c%model%structure%h
        do i = 1, s%n
            iu = c%d%offset(FIELD_U) + i
            iw = c%d%offset(FIELD_W) + i
            ip = c%d%offset(FIELD_PSI) + i
            k(iw, iw) = k(iw, iw) + s%k_v(i)
            k(iu, iu) = k(iu, iu) + s%k_h(i)
            k(iu, ip) = k(iu, ip) - hh*s%k_h(i)
            k(ip, iu) = k(ip, iu) - hh*s%k_h(i)
            k(ip, ip) = k(ip, ip) + hh**2*s%k_h(i)
        end do
        call dgesv(nv, 1, k, nv, ipiv, q, nv, info)
        call check(err, info == 0, 'beam on the springs singular, dgesv info /= 0')
        if (allocated(err)) return
        w_scale = maxval(abs(s%w))
        rel = maxval(abs(q(c%d%offset(FIELD_W) + 1:c%d%offset(FIELD_W) + s%n, 1) - s%w))/w_scale
        write (output_unit, '(4x,a,es9.2)') deck//': max |w on springs - w| / max |w| = ', rel
        call check(err, count(s%k_v > 0.0_dp) >= 2, 'fewer than two vertical springs')
        if (allocated(err)) return
        call check_close(err, rel, 0.0_dp, 0.0_dp, 1.0e-6_dp, &
                         'settlement on the springs vs fricon (relative)')
    end subroutine winkler_reproduces

    !> The strip footing's CASE_springs.csv read back (test_csv_matches).
    subroutine test_csv_strip(err)
        type(error_t), allocatable, intent(out) :: err
        call csv_matches('input/strip_footing.dat', 'strip_footing', err)
    end subroutine test_csv_strip

    !> The lifting beam's CASE_springs.csv read back: zero springs where lifted off.
    subroutine test_csv_liftoff(err)
        type(error_t), allocatable, intent(out) :: err
        call csv_matches('input/beam_physical.dat', 'beam_physical', err)
    end subroutine test_csv_liftoff

    !> Run the deck (as the program does) and read STEM_springs.csv back: one row per node;
    !! x, w (mm), u_b (mm), F_z, F_x, k_v, k_h equal nodal_springs of the case solved here
    !! (to the 8 printed digits); the nodal forces balance the loads (sum F_z = V, statics);
    !! and k_s = p_z/w recomputed from the station CSV STEM.csv of the same run (its p_z [kPa]
    !! and w [mm] at the node's x: an independent file and path), 0 where p_z is not positive
    !! (lifted off).
    subroutine csv_matches(deck_path, stem, err)
        character(len=*), intent(in) :: deck_path, stem
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_springs'
        type(deck_t) :: deck
        type(case_t) :: c
        type(spring_table_t) :: s
        real(dp), allocatable :: rows(:, :), st(:, :)
        real(dp) :: k_s, scale(7)
        integer :: status, i, j, n_st, k
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir)
        call read_deck(deck_path, deck, err)
        if (allocated(err)) return
        call run_analysis(deck, dir, output_unit, error_unit, status, &
                          run_options_t(figures=.false.))
        call check(err, status == EXIT_OK, deck_path//' did not solve')
        if (allocated(err)) return
        call solve_deck(deck_path, 0, c, err)
        if (allocated(err)) return
        call nodal_springs(c%model, c%d, c%sol, s, err)
        if (allocated(err)) return
        call read_csv(dir//'/'//stem//'_springs.csv', 3, 'x [m],w [mm],u_b [mm],F_z [kN],'// &
                      'F_x [kN],k_v [kN/m],k_h [kN/m],p_z [kPa],k_s [kN/m^3]', rows, err)
        if (allocated(err)) return
        call check(err, size(rows, 2) == s%n .and. size(rows, 1) == 9, 'springs CSV: '// &
                   'not one row of 9 fields per node')
        if (allocated(err)) return
        ! column by column against nodal_springs, relative to the column's largest value
        scale = [1.0_dp, 1.0e3_dp, 1.0e3_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp]
        do k = 1, 7
            call check_close(err, maxval(abs(rows(k, :) - scale(k)*column(s, k)))/ &
                             maxval(abs(scale(k)*column(s, k))), 0.0_dp, 0.0_dp, 1.0e-6_dp, &
                             'springs CSV column '//char(48 + k)//' vs nodal_springs')
            if (allocated(err)) return
        end do
        call check_close(err, sum(rows(4, :)), total_vertical_load(c%model%loads), 1.0e-6_dp, &
                         0.0_dp, 'sum F_z vs the vertical load (statics)')
        if (allocated(err)) return
        ! the station CSV: x first, w third, p_z the 8th column of a beam
        call read_csv(dir//'/'//stem//'.csv', 2, '', st, err)
        if (allocated(err)) return
        n_st = size(st, 2)
        do i = 1, size(rows, 2)
            j = findloc(abs(st(1, :) - rows(1, i)) < 1.0e-6_dp, .true., dim=1)
            call check(err, j > 0, 'no station at a node')
            if (allocated(err)) return
            k_s = 0.0_dp
            if (st(8, j) > 0.0_dp) k_s = st(8, j)/(st(3, j)*1.0e-3_dp)
            call check_close(err, rows(9, i), k_s, 1.0e-6_dp, 1.0e-9_dp*maxval(abs(rows(9, :))), &
                             'k_s vs p_z/w of the station CSV')
            if (allocated(err)) return
        end do
        call check(err, n_st >= size(rows, 2), 'fewer stations than nodes')
    end subroutine csv_matches

    !> Column k of the springs table (x, w, u_b, F_z, F_x, k_v, k_h), deck units.
    pure function column(s, k) result(v)
        type(spring_table_t), intent(in) :: s
        integer, intent(in) :: k
        real(dp) :: v(s%n)
        select case (k)
        case (1)
            v = s%x
        case (2)
            v = s%w
        case (3)
            v = s%u_b
        case (4)
            v = s%f_z
        case (5)
            v = s%f_x
        case (6)
            v = s%k_v
        case default
            v = s%k_h
        end select
    end function column

    !> The numeric rows of a CSV after `skip` lines (rows(field, row)); the last skipped line
    !! must equal `header` unless that is ''.
    subroutine read_csv(path, skip, header, rows, err)
        character(len=*), intent(in) :: path, header
        integer, intent(in) :: skip
        real(dp), allocatable, intent(out) :: rows(:, :)
        type(error_t), allocatable, intent(out) :: err
        character(len=4000) :: line
        real(dp) :: buf(40)
        integer :: u, ios, i, n_fields
        real(dp), allocatable :: row(:)
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        call check(err, ios == 0, 'cannot open '//path)
        if (allocated(err)) return
        do i = 1, skip
            read (u, '(a)') line
        end do
        if (len(header) > 0) call check(err, trim(line) == header, path//': header '//trim(line))
        if (allocated(err)) return
        allocate (rows(0, 0))
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            n_fields = count([(line(i:i) == ',', i=1, len_trim(line))]) + 1
            read (line, *, iostat=ios) buf(1:n_fields)
            call check(err, ios == 0, path//': unreadable row '//trim(line))
            if (allocated(err)) exit
            row = buf(1:n_fields)
            if (size(rows, 2) == 0) then
                rows = reshape(row, [n_fields, 1])
            else
                rows = reshape([rows, row], [size(rows, 1), size(rows, 2) + 1])
            end if
        end do
        close (u)
    end subroutine read_csv
end module test_foundation_springs
