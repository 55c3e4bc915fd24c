!> Tests of the fast surface displacement at many points (singular_quadrature, submodule
!! station_displacement: far clusters of elements interpolated, one kernel call per point)
!! against the reference evaluation `displacement_split_kernel_reference` (a line rule of
!! graded Gauss pieces and a log-weighted piece for every (point, element) pair, itself checked
!! against closed forms and independent quadratures in the halfspace_plate and halfspace_beam
!! suites: uniform_pressure_displacements, uniform_load_closed_forms, galerkin_vs_nested...).
!!
!! The kernels' own types are private to halfspace_plate and halfspace_beam, so the reference is
!! run here with kernels built from their public point evaluations (ring_kernels,
!! elliptic_ke_agm, strip_kernels): the same formulas, so the same values to a few ulps. Two
!! comparisons: the program's path (plate_surface_displacement / beam_surface_displacement,
!! the real kernels, the fast evaluation) against the reference; and the fast against the
!! reference evaluation on the same kernel object (the quadratures alone). P1, P2 and S2
!! tractions, uniform and graded (EDGES) meshes, N_e 20 to 200, points at every node and
!! mid-element (and outside the disk or the beam); agreement to 1e-13 of the largest |u| and
!! of the largest |w| (measured: 5e-16 to 1.3e-14, growing with N_e as the rounding of the
!! reference's sums over its 500 to 2 000 points per station; N_e up to 1000 on the example
!! decks, and the sums in quadruple precision: output/bench/tabulation_before_after.md).
module test_station_displacement
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, check, check_close, error_t
    use errors, only: add_context
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1, INTERP_P2, INTERP_S2
    use singular_quadrature, only: split_kernel_t, displacement_split_kernel, &
                                   displacement_split_kernel_reference, gauss_tables_t, &
                                   new_gauss_tables, shared_gauss_tables, n_max, n_log
    use halfspace_plate, only: plate_surface_displacement, ring_kernels, elliptic_ke_agm
    use halfspace_beam, only: beam_surface_displacement, strip_kernels
    implicit none
    private
    public :: collect_station_displacement

    real(dp), parameter :: g_soil = 1.7_dp, nu_soil = 0.23_dp
    real(dp), parameter :: tolerance = 1.0e-13_dp
    integer, parameter :: sizes(3) = [20, 100, 200]
    integer, parameter :: families(2, 3) = reshape([INTERP_P1, INTERP_P1, INTERP_P2, INTERP_P1, &
                                                    INTERP_S2, INTERP_S2], [2, 3])
    character(len=*), parameter :: gradings(2) = [character(len=7) :: 'UNIFORM', 'EDGES']

    !> Ring kernels (C1)-(C4) from halfspace_plate's public point evaluations.
    type, extends(split_kernel_t) :: ring_test_kernel_t
        real(dp) :: g = g_soil, nu = nu_soil
    contains
        procedure :: values => ring_test_values
        procedure :: field_weight => ring_test_weight
        procedure :: log_length => ring_test_log_length
    end type ring_test_kernel_t

    !> Strip kernels (B9)-(B11) from halfspace_beam's public point evaluation.
    type, extends(split_kernel_t) :: strip_test_kernel_t
        real(dp) :: g = g_soil, nu = nu_soil, b = 0.05_dp
    contains
        procedure :: values => strip_test_values
        procedure :: field_weight => strip_test_weight
        procedure :: log_length => strip_test_log_length
    end type strip_test_kernel_t

contains

    subroutine collect_station_displacement(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('plate_fast_vs_reference', test_plate), &
                 new_unittest('beam_fast_vs_reference', test_beam), &
                 new_unittest('same_kernel_fast_vs_reference', test_same_kernel), &
                 new_unittest('small_meshes', test_small_meshes), &
                 new_unittest('points_ulps_from_nodes', test_near_nodes), &
                 new_unittest('embedded_gauss_tables_match', test_embedded_tables), &
                 new_unittest('embedded_gauss_rules_exact', test_embedded_rules_exact)]
    end subroutine collect_station_displacement

    !> The GL tables embedded in the program (gauss_rule_tables, through shared_gauss_tables)
    !! are the tables new_gauss_tables computes (Newton's method on P_n, the product-log
    !! moments), bit for bit: the program's results do not depend on which it uses.
    subroutine test_embedded_tables(err)
        type(error_t), allocatable, intent(out) :: err
        type(gauss_tables_t) :: embedded, computed
        call shared_gauss_tables(embedded)
        call new_gauss_tables(computed)
        call check(err, all(embedded%v == computed%v) .and. all(embedded%w == computed%w) &
                   .and. all(embedded%wq == computed%wq), 'the embedded GL tables differ '// &
                   'from new_gauss_tables: run scripts/embed_gauss_tables.sh')
    end subroutine test_embedded_tables

    !> Closed forms for the embedded rules: the n-point rule integrates v^(2n-1) on [0, 1]
    !! exactly (1/(2n)); the product-log rule of n points, whose weights are
    !! wl_i = wq(i, n) + w(i, n) ln v_i, integrates v^(n-1) ln v exactly (-1/n^2).
    subroutine test_embedded_rules_exact(err)
        type(error_t), allocatable, intent(out) :: err
        type(gauss_tables_t) :: tab
        real(dp) :: total
        integer :: n
        character(len=40) :: what
        call shared_gauss_tables(tab)
        rules: do n = 1, n_max
            total = sum(tab%w(1:n, n)*tab%v(1:n, n)**(2*n - 1))
            write (what, '("int v^(2n-1), n = ",i0)') n
            call check_close(err, total, 1.0_dp/real(2*n, dp), 1.0e-14_dp, 0.0_dp, what)
            if (allocated(err)) return
            if (n > n_log) cycle
            total = sum((tab%wq(1:n, n) + tab%w(1:n, n)*log(tab%v(1:n, n))) &
                        *tab%v(1:n, n)**(n - 1))
            write (what, '("int v^(n-1) ln v, n = ",i0)') n
            call check_close(err, total, -1.0_dp/real(n*n, dp), 1.0e-13_dp, 0.0_dp, what)
            if (allocated(err)) return
        end do rules
    end subroutine test_embedded_rules_exact

    ! ------------------------------------------------------------------ test kernels

    subroutine ring_test_values(self, x, xi, with_log, f, p, err)
        class(ring_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), xi(:)
        logical, intent(in) :: with_log(:)
        real(dp), intent(out) :: f(:, :, :), p(:, :, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: r, s, total, m, m1, k_p, e_p, c_zz, c_rr
        integer :: k
        points: do k = 1, size(x)
            r = x(k)
            s = xi(k)
            call ring_kernels(r, s, self%g, self%nu, f(2, 2, k), f(1, 1, k), f(1, 2, k), &
                              f(2, 1, k), err)
            if (allocated(err)) return
            p(:, :, k) = 0.0_dp
            if (.not. with_log(k) .or. r <= 0.0_dp) cycle points
            ! coefficients of ln|r - s| (halfspace_plate header): K(k'), E(k') by the AGM
            total = r + s
            m1 = ((r - s)/total)**2
            m = min(1.0_dp, 4.0_dp*r*s/total**2)
            call elliptic_ke_agm(2.0_dp*sqrt(r*s)/total, m1, k_p, e_p)
            c_zz = 2.0_dp*(1.0_dp - self%nu)*s/(pi*self%g*total)
            c_rr = (1.0_dp - self%nu)*total/(2.0_dp*pi*self%g*r)
            p(2, 2, k) = -2.0_dp*c_zz*k_p/pi
            p(1, 1, k) = -2.0_dp*c_rr*(2.0_dp*e_p - m*k_p)/pi
        end do points
    end subroutine ring_test_values

    pure real(dp) function ring_test_weight(self, x)
        class(ring_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x
        ring_test_weight = 2.0_dp*pi*x
    end function ring_test_weight

    !> As halfspace_plate: the split is analytic for |r - s| <= r/2.
    pure real(dp) function ring_test_log_length(self, x_sing)
        class(ring_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x_sing
        ring_test_log_length = 0.5_dp*x_sing
    end function ring_test_log_length

    subroutine strip_test_values(self, x, xi, with_log, f, p, err)
        class(strip_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), xi(:)
        logical, intent(in) :: with_log(:)
        real(dp), intent(out) :: f(:, :, :), p(:, :, :)
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        points: do k = 1, size(x)
            call strip_kernels(x(k) - xi(k), self%g, self%nu, self%b, f(2, 2, k), f(1, 1, k), &
                               f(2, 1, k))
            f(1, 2, k) = -f(2, 1, k)
            p(:, :, k) = 0.0_dp
            if (.not. with_log(k)) cycle points
            p(1, 1, k) = -(1.0_dp - self%nu)/(pi*self%g*self%b)
            p(2, 2, k) = p(1, 1, k)
        end do points
    end subroutine strip_test_values

    pure real(dp) function strip_test_weight(self, x)
        class(strip_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x
        strip_test_weight = 1.0_dp
    end function strip_test_weight

    !> As halfspace_beam: analytic within |X| < b/2.
    pure real(dp) function strip_test_log_length(self, x_sing)
        class(strip_test_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x_sing
        strip_test_log_length = 0.5_dp*self%b
    end function strip_test_log_length

    ! ------------------------------------------------------------------ helpers

    !> Bases of sigma_x and sigma_z on a mesh of [x_left, x_right].
    subroutine make_bases(x_left, x_right, ne, grading, fam, bx, bz, err)
        real(dp), intent(in) :: x_left, x_right
        integer, intent(in) :: ne, fam(2)
        character(len=*), intent(in) :: grading
        type(basis_t), intent(out) :: bx, bz
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        call new_mesh(msh, x_left, x_right, ne, grading, err)
        if (allocated(err)) return
        call new_basis(bx, msh, fam(1))
        call new_basis(bz, msh, fam(2))
    end subroutine make_bases

    !> Traction coefficients: smooth parts and a part alternating from one coefficient to the
    !! next (kinks at every node, as the edge singularities give the computed tractions).
    pure function coefficients(n, phase) result(r)
        integer, intent(in) :: n
        real(dp), intent(in) :: phase
        real(dp) :: r(n)
        integer :: b
        do b = 1, n
            r(b) = phase + 0.3_dp*cos(7.0_dp*real(b, dp)/real(n, dp) + phase) + &
                   0.2_dp*real(1 - 2*mod(b, 2), dp)
        end do
    end function coefficients

    !> Every node and every element mid-point, plus the given extra points.
    pure function points_of(basis, extra) result(x)
        type(basis_t), intent(in) :: basis
        real(dp), intent(in) :: extra(:)
        real(dp), allocatable :: x(:)
        integer :: e
        x = [basis%x, (0.5_dp*(basis%x(e - 1) + basis%x(e)), e=1, basis%ne), extra]
    end function points_of

    !> Largest difference of u and of w, each relative to the largest of the reference.
    subroutine check_agreement(u, w, u_ref, w_ref, what, err, tol)
        real(dp), intent(in) :: u(:), w(:), u_ref(:), w_ref(:)
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: err
        real(dp), intent(in), optional :: tol    !! default: the module's tolerance
        real(dp) :: limit
        limit = tolerance
        if (present(tol)) limit = tol
        call check_close(err, maxval(abs(u - u_ref))/maxval(abs(u_ref)), 0.0_dp, 0.0_dp, &
                         limit, what//': max |u - u_ref| / max |u_ref|')
        if (allocated(err)) return
        call check_close(err, maxval(abs(w - w_ref))/maxval(abs(w_ref)), 0.0_dp, 0.0_dp, &
                         limit, what//': max |w - w_ref| / max |w_ref|')
    end subroutine check_agreement

    !> Case label.
    function label(kind, ne, grading, fam) result(text)
        character(len=*), intent(in) :: kind, grading
        integer, intent(in) :: ne, fam(2)
        character(len=:), allocatable :: text
        character(len=80) :: buf
        character(len=2), parameter :: names(3) = ['P1', 'P2', 'S2']
        write (buf, '(a," N_e ",i0," ",a," ",a,"/",a)') kind, ne, trim(grading), &
            names(fam(1)), names(fam(2))
        text = trim(buf)
    end function label

    ! ------------------------------------------------------------------ tests

    !> Plate on [0, 1.3]: plate_surface_displacement against the reference.
    subroutine test_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(ring_test_kernel_t) :: kernel
        type(basis_t) :: bx, bz
        real(dp), allocatable :: x(:), u(:), w(:), u_ref(:), w_ref(:), rx(:), rz(:)
        integer :: in, ig, ifam
        do in = 1, size(sizes)
            do ig = 1, size(gradings)
                do ifam = 1, size(families, 2)
                    call make_bases(0.0_dp, 1.3_dp, sizes(in), trim(gradings(ig)), &
                                    families(:, ifam), bx, bz, err)
                    if (allocated(err)) return
                    rx = coefficients(bx%n_dof, 0.4_dp)
                    rz = coefficients(bz%n_dof, 1.0_dp)
                    x = points_of(bx, [1.7_dp])
                    allocate (u(size(x)), w(size(x)), u_ref(size(x)), w_ref(size(x)))
                    call plate_surface_displacement(bx, bz, rx, rz, kernel%g, kernel%nu, x, u, &
                                                    w, err)
                    if (.not. allocated(err)) call displacement_split_kernel_reference( &
                        kernel, bx, bz, rx, rz, x, u_ref, w_ref, err)
                    if (.not. allocated(err)) call check_agreement(u, w, u_ref, w_ref, &
                        label('plate', sizes(in), gradings(ig), families(:, ifam)), err)
                    if (allocated(err)) return
                    deallocate (u, w, u_ref, w_ref)
                end do
            end do
        end do
    end subroutine test_plate

    !> Beam of length 1 (b = 0.05, narrower than the elements of N_e = 20; and b = 0.9):
    !! beam_surface_displacement against the reference, points also outside the beam.
    subroutine test_beam(err)
        type(error_t), allocatable, intent(out) :: err
        type(strip_test_kernel_t) :: kernel
        type(basis_t) :: bx, bz
        real(dp), allocatable :: x(:), u(:), w(:), u_ref(:), w_ref(:), rx(:), rz(:)
        real(dp), parameter :: widths(2) = [0.05_dp, 0.9_dp]
        integer :: in, ig, ifam, ib
        do ib = 1, size(widths)
            kernel%b = widths(ib)
            do in = 1, size(sizes)
                do ig = 1, size(gradings)
                    do ifam = 1, size(families, 2)
                        call make_bases(-0.5_dp, 0.5_dp, sizes(in), trim(gradings(ig)), &
                                        families(:, ifam), bx, bz, err)
                        if (allocated(err)) return
                        rx = coefficients(bx%n_dof, 0.4_dp)
                        rz = coefficients(bz%n_dof, 1.0_dp)
                        x = points_of(bx, [-0.8_dp, 0.61_dp])
                        allocate (u(size(x)), w(size(x)), u_ref(size(x)), w_ref(size(x)))
                        call beam_surface_displacement(bx, bz, rx, rz, kernel%g, kernel%nu, &
                                                       kernel%b, x, u, w, err)
                        if (.not. allocated(err)) call displacement_split_kernel_reference( &
                            kernel, bx, bz, rx, rz, x, u_ref, w_ref, err)
                        if (.not. allocated(err)) call check_agreement(u, w, u_ref, w_ref, &
                            label('beam', sizes(in), gradings(ig), families(:, ifam)), err)
                        if (allocated(err)) then
                            call add_context(err, 'b = '//merge('0.05', '0.9 ', ib == 1))
                            return
                        end if
                        deallocate (u, w, u_ref, w_ref)
                    end do
                end do
            end do
        end do
    end subroutine test_beam

    !> The fast and the reference evaluation on the same kernel object (the quadratures only),
    !! plate and beam, N_e 100, graded, S2/P2 tractions.
    subroutine test_same_kernel(err)
        type(error_t), allocatable, intent(out) :: err
        type(ring_test_kernel_t) :: ring
        type(strip_test_kernel_t) :: strip
        type(basis_t) :: bx, bz
        real(dp), allocatable :: x(:), u(:), w(:), u_ref(:), w_ref(:)
        integer :: k
        do k = 1, 2
            if (k == 1) then
                call make_bases(0.0_dp, 1.3_dp, 100, 'EDGES', [INTERP_S2, INTERP_P2], bx, bz, err)
            else
                call make_bases(-0.5_dp, 0.5_dp, 100, 'EDGES', [INTERP_S2, INTERP_P2], bx, bz, &
                                err)
            end if
            if (allocated(err)) return
            x = points_of(bx, [real(dp) ::])
            allocate (u(size(x)), w(size(x)), u_ref(size(x)), w_ref(size(x)))
            if (k == 1) then
                call displacement_split_kernel(ring, bx, bz, coefficients(bx%n_dof, 0.4_dp), &
                                               coefficients(bz%n_dof, 1.0_dp), x, u, w, err)
                if (.not. allocated(err)) call displacement_split_kernel_reference(ring, bx, &
                    bz, coefficients(bx%n_dof, 0.4_dp), coefficients(bz%n_dof, 1.0_dp), x, &
                    u_ref, w_ref, err)
            else
                call displacement_split_kernel(strip, bx, bz, coefficients(bx%n_dof, 0.4_dp), &
                                               coefficients(bz%n_dof, 1.0_dp), x, u, w, err)
                if (.not. allocated(err)) call displacement_split_kernel_reference(strip, bx, &
                    bz, coefficients(bx%n_dof, 0.4_dp), coefficients(bz%n_dof, 1.0_dp), x, &
                    u_ref, w_ref, err)
            end if
            if (.not. allocated(err)) call check_agreement(u, w, u_ref, w_ref, &
                                                           merge('plate', 'beam ', k == 1), err)
            if (allocated(err)) return
            deallocate (u, w, u_ref, w_ref)
        end do
    end subroutine test_same_kernel

    !> Meshes of 1 to 9 elements (the tree is one leaf, or a root with two leaves, ...): the
    !! program's path against the reference, plate and beam, P2/S2 tractions.
    subroutine test_small_meshes(err)
        type(error_t), allocatable, intent(out) :: err
        type(ring_test_kernel_t) :: ring
        type(strip_test_kernel_t) :: strip
        type(basis_t) :: bx, bz
        real(dp), allocatable :: x(:), u(:), w(:), u_ref(:), w_ref(:), rx(:), rz(:)
        integer :: ne
        character(len=20) :: what
        do ne = 1, 9
            write (what, '("N_e ",i0)') ne
            call make_bases(0.0_dp, 1.3_dp, ne, 'EDGES', [INTERP_P2, INTERP_S2], bx, bz, err)
            if (allocated(err)) return
            rx = coefficients(bx%n_dof, 0.4_dp)
            rz = coefficients(bz%n_dof, 1.0_dp)
            x = points_of(bx, [2.5_dp])
            allocate (u(size(x)), w(size(x)), u_ref(size(x)), w_ref(size(x)))
            call plate_surface_displacement(bx, bz, rx, rz, ring%g, ring%nu, x, u, w, err)
            if (.not. allocated(err)) call displacement_split_kernel_reference(ring, bx, bz, rx, &
                rz, x, u_ref, w_ref, err)
            if (.not. allocated(err)) call check_agreement(u, w, u_ref, w_ref, &
                                                           'plate '//trim(what), err)
            if (allocated(err)) return
            call make_bases(-0.5_dp, 0.5_dp, ne, 'EDGES', [INTERP_P2, INTERP_S2], bx, bz, err)
            if (allocated(err)) return
            x = points_of(bx, [-2.0_dp])
            call beam_surface_displacement(bx, bz, rx, rz, strip%g, strip%nu, strip%b, x, u, w, &
                                           err)
            if (.not. allocated(err)) call displacement_split_kernel_reference(strip, bx, bz, rx, &
                rz, x, u_ref, w_ref, err)
            if (.not. allocated(err)) call check_agreement(u, w, u_ref, w_ref, &
                                                           'beam '//trim(what), err)
            if (allocated(err)) return
            deallocate (u, w, u_ref, w_ref)
        end do
    end subroutine test_small_meshes

    !> Points a few to a thousand ulps from a node (a load position on a LOADS mesh is such a
    !! point: its node comes from sums of element lengths). Once these stopped the plate
    !! (elliptic integral at m1 = 0) and gave Inf for the beam. Expected: the displacement at
    !! the node itself (the points are moved onto it: singular_quadrature snapped_to_nodes),
    !! both evaluations; 1e-12 of the largest allows the reference's own rounding (1e-14) and
    !! would still catch a point left off the node with a wrong rule.
    subroutine test_near_nodes(err)
        type(error_t), allocatable, intent(out) :: err
        type(ring_test_kernel_t) :: ring
        type(strip_test_kernel_t) :: strip
        type(basis_t) :: bx, bz
        real(dp), allocatable :: x(:), u(:), w(:), u_ref(:), w_ref(:), rx(:), rz(:)
        real(dp), parameter :: offsets(8) = [-1000.0_dp, -300.0_dp, -20.0_dp, -3.0_dp, 3.0_dp, &
                                             20.0_dp, 300.0_dp, 1000.0_dp]
        integer :: k, node
        do k = 1, 2
            if (k == 1) then
                call make_bases(0.0_dp, 10.0_dp, 37, 'UNIFORM', [INTERP_P1, INTERP_P1], bx, bz, err)
            else
                call make_bases(-6.0_dp, 6.0_dp, 37, 'UNIFORM', [INTERP_P1, INTERP_P1], bx, bz, err)
            end if
            if (allocated(err)) return
            rx = coefficients(bx%n_dof, 0.4_dp)
            rz = coefficients(bz%n_dof, 1.0_dp)
            node = 11
            x = [bx%x(node), bx%x(node) + offsets*epsilon(1.0_dp)*abs(bx%x(node))]
            allocate (u(size(x)), w(size(x)), u_ref(size(x)), w_ref(size(x)))
            if (k == 1) then
                call plate_surface_displacement(bx, bz, rx, rz, ring%g, ring%nu, x, u, w, err)
                if (.not. allocated(err)) call displacement_split_kernel_reference(ring, bx, bz, &
                    rx, rz, x, u_ref, w_ref, err)
            else
                call beam_surface_displacement(bx, bz, rx, rz, strip%g, strip%nu, strip%b, x, u, &
                                               w, err)
                if (.not. allocated(err)) call displacement_split_kernel_reference(strip, bx, bz, &
                    rx, rz, x, u_ref, w_ref, err)
            end if
            if (allocated(err)) then
                call add_context(err, merge('plate', 'beam ', k == 1)//': points near a node')
                return
            end if
            call check_agreement(u, w, spread(u(1), 1, size(x)), spread(w(1), 1, size(x)), &
                                 merge('plate fast near a node     ', 'beam fast near a '// &
                                     'node      ', &
                                       k == 1), err, 1.0e-12_dp)
            if (.not. allocated(err)) call check_agreement(u_ref, w_ref, &
                spread(u(1), 1, size(x)), spread(w(1), 1, size(x)), &
                merge('plate reference near a node', 'beam reference near a node ', k == 1), err, &
                1.0e-12_dp)
            if (allocated(err)) return
            deallocate (u, w, u_ref, w_ref)
        end do
    end subroutine test_near_nodes
end module test_station_displacement
