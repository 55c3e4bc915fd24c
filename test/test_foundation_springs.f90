!> The exported springs (foundation_springs) fed back as an independent Winkler bed: a beam of
!! the same stiffness K (mindlin_structure) on the nodal springs alone, under the same loads,
!! must settle as fricon's solution did (equilibrium K v + S v = q with S v = M^T r).
module test_foundation_springs
    use iso_fortran_env, only: output_unit
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use model, only: FIELD_U, FIELD_W, FIELD_PSI
    use mindlin_structure, only: section_of, assemble_stiffness, assemble_loads
    use lapack_interfaces, only: dgesv
    use solved_case, only: case_t
    use contact_test_support, only: solve_deck
    use foundation_springs, only: spring_table_t, nodal_springs
    implicit none
    private
    public :: collect_foundation_springs

contains

    subroutine collect_foundation_springs(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('springs_reproduce_settlement_strip', test_strip), &
                 new_unittest('springs_reproduce_settlement_liftoff', test_liftoff)]
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
end module test_foundation_springs
