!> Tests of halfspace_plate: ring kernels, surface displacements and the Galerkin flexibility of
!! the half-space under axisymmetric tractions on a disk of radius a.
!!
!! Closed forms used (kernel reference §C, Johnson 1985 ch. 3), uniform pressure p on the disk,
!! E = 2G(1+nu): w(0) = 2(1-nu^2) p a/E, w(a) = 4(1-nu^2) p a/(pi E),
!! w(r) = 4(1-nu^2) p a/(pi E) E(r/a), u_r(r) = -(1-2nu)(1+nu) p r/(2E) (r <= a);
!! uniform outward radial shear q: u_z(r) = -(1-2nu) q (a-r)/(2G) (r <= a).
module test_halfspace_plate
    !$ use omp_lib, only: omp_get_max_threads, omp_set_num_threads
    use blas_threads, only: blas_thread_count, set_blas_threads
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, check, check_close, error_t
    use errors, only: new_error, EXIT_INTERNAL
    use quadrature, only: gauss_legendre
    use gsl_wrappers, only: elliptic_ke_m1, integrand_t, integrate_qags
    use shape_functions, only: basis_t, INTERP_P1, INTERP_P2, INTERP_S2
    use halfspace_plate, only: assemble_plate_flexibility, plate_surface_displacement, &
                               ring_kernels, elliptic_ke_agm
    use lapack_interfaces, only: dpotrf
    use halfspace_test_support, only: basis_value, surface_t, row_integrand_t, make_bases, &
                                      nested_flexibility, check_row_sums, check_symmetric, &
                                      check_positive_definite, check_incompressible, &
                                      check_fast_vs_reference
    use model, only: model_t, FIELD_SZ
    use discretization, only: discretization_t, new_discretization
    use halfspace_operator, only: assemble_flexibility
    use flexibility_cache, only: flexibility_cache_t, flexibility_of, new_flexibility_cache, &
                                 flexibility_cache_hits
    use contact_test_support, only: nondim_plate, nondim_beam
    implicit none
    private
    public :: collect_halfspace_plate


    integer, parameter :: closed_w_pressure = 1   !! w(r) under uniform p = 1
    integer, parameter :: closed_u_pressure = 2   !! u_r(r) under uniform p = 1
    integer, parameter :: closed_w_shear = 3      !! u_z(r) under uniform q = 1

    type(surface_t), parameter :: disk = surface_t(plate=.true.)   !! the disk r <= 1.3

    !> g_a(r) 2 pi r f(r) on one element, f one of the closed forms above.
    type, extends(row_integrand_t) :: closed_row_t
        integer :: kind = closed_w_pressure
        real(dp) :: g = 1.0_dp, nu = 0.3_dp, a = 1.0_dp
    contains
        procedure :: value => row_value
    end type closed_row_t

    !> Boussinesq/Cerruti (B1), (B2) integrand around a ring, theta in [0, pi] (doubled).
    type, extends(integrand_t) :: ring_theta_t
        real(dp) :: r = 1.0_dp, s = 1.0_dp, g = 1.0_dp, nu = 0.3_dp
        integer :: component = 1       !! 1 zz, 2 rz, 3 zr, 4 rr
    contains
        procedure :: value => ring_theta_value
    end type ring_theta_t

contains

    subroutine collect_halfspace_plate(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('ring_kernels_vs_boussinesq_cerruti', test_ring_kernels), &
                 new_unittest('ring_kernel_axis_limits', test_axis_limits), &
                 new_unittest('uniform_pressure_displacements', test_uniform_pressure), &
                 new_unittest('uniform_pressure_outside_disk', test_outside), &
                 new_unittest('galerkin_row_sums_vs_closed_forms', test_row_sums), &
                 new_unittest('galerkin_vs_nested_displacement', test_nested), &
                 new_unittest('symmetric', test_symmetric), &
                 new_unittest('positive_definite', test_positive_definite), &
                 new_unittest('incompressible_no_coupling', test_incompressible), &
                 new_unittest('rigid_punch_convergence', test_punch), &
                 new_unittest('fast_vs_reference_assembly', test_fast_vs_reference), &
                 new_unittest('interpolated_blocks_vs_pairwise', test_blocks_vs_pairwise), &
                 new_unittest('agm_elliptic_vs_carlson', test_agm), &
                 new_unittest('flexibility_cache', test_flexibility_cache)]
    end subroutine collect_halfspace_plate

    ! ------------------------------------------------------------------ helpers

    function row_value(self, x) result(f)
        class(closed_row_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        real(dp) :: k_val, e_val, closed
        type(error_t), allocatable :: err
        select case (self%kind)
        case (closed_w_pressure)
            ! w = 2(1-nu) a/(pi G) E(r/a), 1 - (r/a)^2 formed as (a-r)(a+r)/a^2
            call elliptic_ke_m1(max((self%a - x)*(self%a + x)/self%a**2, tiny(1.0_dp)), &
                                k_val, e_val, err)
            if (allocated(err)) self%failed = .true.
            closed = 2.0_dp*(1.0_dp - self%nu)*self%a/(pi*self%g)*e_val
        case (closed_u_pressure)
            closed = -(1.0_dp - 2.0_dp*self%nu)*x/(4.0_dp*self%g)
        case default
            closed = -(1.0_dp - 2.0_dp*self%nu)*(self%a - x)/(2.0_dp*self%g)
        end select
        f = basis_value(self%basis, self%element, self%dof, x)*2.0_dp*pi*x*closed
    end function row_value

    !> Displacement component at (r, 0) of a unit line density on the ring of radius s, point
    !! (s cos t, s sin t), from (B1) (normal) or (B2) (radial force (cos t, sin t)).
    function ring_theta_value(self, x) result(f)
        class(ring_theta_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        real(dp) :: dx, dy, rho2, rho, g, nu
        g = self%g
        nu = self%nu
        dx = self%r - self%s*cos(x)
        dy = -self%s*sin(x)
        rho2 = dx*dx + dy*dy
        rho = sqrt(rho2)
        select case (self%component)
        case (1)
            f = (1.0_dp - nu)/(2.0_dp*pi*g*rho)
        case (2)
            f = -(1.0_dp - 2.0_dp*nu)*dx/(4.0_dp*pi*g*rho2)
        case (3)
            f = (1.0_dp - 2.0_dp*nu)*(dx*cos(x) + dy*sin(x))/(4.0_dp*pi*g*rho2)
        case default
            f = ((1.0_dp - nu)*cos(x) + nu*dx*(dx*cos(x) + dy*sin(x))/rho2)/(2.0_dp*pi*g*rho)
        end select
        f = 2.0_dp*f*self%s
    end function ring_theta_value

    !> sum over the points of a composite GL rule graded geometrically towards both ends of
    !! [a, b] (ratio 0.2, 12 levels, 20 points a piece): nodes and weights.

    ! ------------------------------------------------------------------ tests

    !> (C1)–(C4) against QAGS theta-integration of Boussinesq/Cerruti (B1), (B2) around the
    !! ring (an independent computation), including r/s = 0.99 and 1/16.
    subroutine test_ring_kernels(err)
        type(error_t), allocatable, intent(out) :: err
        type(ring_theta_t) :: f
        real(dp) :: g(4), expected, abserr
        real(dp), parameter :: rs(2, 5) = reshape([0.3_dp, 1.0_dp, 1.0_dp, 0.3_dp, &
            0.99_dp, 1.0_dp, 1.0_dp, 0.99_dp, 0.0625_dp, 1.0_dp], [2, 5])
        integer :: i, c
        character(len=80) :: what
        f%g = 7.5_dp
        f%nu = 0.27_dp
        pairs: do i = 1, size(rs, 2)
            call ring_kernels(rs(1, i), rs(2, i), f%g, f%nu, g(1), g(4), g(2), g(3), err)
            if (allocated(err)) return
            components: do c = 1, 4
                f%r = rs(1, i)
                f%s = rs(2, i)
                f%component = c
                call integrate_qags(f, 0.0_dp, pi, 1.0e-15_dp, 1.0e-13_dp, expected, abserr, err)
                if (allocated(err)) return
                write (what, '("ring kernel ",i0," at r = ",f6.4,", s = ",f6.4)') c, rs(:, i)
                call check_close(err, g(c), expected, 1.0e-11_dp, 1.0e-13_dp, trim(what))
                if (allocated(err)) return
            end do components
        end do pairs
    end subroutine test_ring_kernels

    !> Limits of the kernel reference: G_zz(0,s) = (1-nu)/G, G_rr ~ (1-nu) r/(2Gs) (r -> 0),
    !! G_rr ~ (1-nu) s^2/(2G r^2) (s -> 0), G_rz(0,s) = 0.
    subroutine test_axis_limits(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: g_zz, g_rr, g_rz, g_zr
        real(dp), parameter :: g = 2.0_dp, nu = 0.2_dp, eta = 1.0e-9_dp
        call ring_kernels(0.0_dp, 0.7_dp, g, nu, g_zz, g_rr, g_rz, g_zr, err)
        if (allocated(err)) return
        call check_close(err, g_zz, (1.0_dp - nu)/g, 1.0e-15_dp, 0.0_dp, 'G_zz(0, s)')
        if (allocated(err)) return
        call check(err, g_rr == 0.0_dp .and. g_rz == 0.0_dp, 'G_rr(0,s), G_rz(0,s) /= 0')
        if (allocated(err)) return
        call ring_kernels(eta*0.7_dp, 0.7_dp, g, nu, g_zz, g_rr, g_rz, g_zr, err)
        if (allocated(err)) return
        call check_close(err, g_rr, (1.0_dp - nu)*eta/(2.0_dp*g), 1.0e-8_dp, 0.0_dp, &
                         'G_rr, r -> 0')
        if (allocated(err)) return
        call ring_kernels(0.7_dp, eta*0.7_dp, g, nu, g_zz, g_rr, g_rz, g_zr, err)
        if (allocated(err)) return
        call check_close(err, g_rr, (1.0_dp - nu)*eta**2/(2.0_dp*g), 1.0e-8_dp, 0.0_dp, &
                         'G_rr, s -> 0')
        if (allocated(err)) return
    end subroutine test_axis_limits

    !> Uniform pressure on the whole disk, all bases, uniform and graded meshes, several nu:
    !! w(0), w(a), w(r), u_r(r) against the closed forms of the module header, 1e-10.
    subroutine test_uniform_pressure(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: rx(:), rz(:), u(:), w(:), r(:)
        real(dp) :: g, e_f, nu, a, p, k_val, e_val, w_ref
        integer :: fam, ig, inu, i
        character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']
        real(dp), parameter :: nus(3) = [0.0_dp, 0.3_dp, 0.49_dp]
        character(len=80) :: what
        a = 1.3_dp
        p = 2.5e3_dp
        e_f = 3.0e7_dp
        families: do fam = INTERP_P1, INTERP_S2
            meshes: do ig = 1, 2
                call make_bases(disk, 7, trim(gradings(ig)), fam, fam, bx, bz, err)
                if (allocated(err)) return
                r = [0.0_dp, bz%x(1), 0.37_dp*a, 0.5_dp*a, bz%x(5), 0.999_dp*a, a]
                allocate (rx(bx%n_dof), rz(bz%n_dof), u(size(r)), w(size(r)))
                rx = 0.0_dp
                rz = p          ! a constant is represented exactly (partition of unity)
                poisson: do inu = 1, size(nus)
                    nu = nus(inu)
                    g = e_f/(2.0_dp*(1.0_dp + nu))
                    call plate_surface_displacement(bx, bz, rx, rz, g, nu, r, u, w, err)
                    if (allocated(err)) return
                    write (what, '("family ",i0,", grading ",a,", nu = ",f4.2)') fam, &
                        trim(gradings(ig)), nu
                    call check_close(err, w(1), 2.0_dp*(1.0_dp - nu**2)*p*a/e_f, 1.0e-10_dp, &
                                     0.0_dp, 'w(0), '//trim(what))
                    if (allocated(err)) return
                    call check_close(err, w(size(r)), 4.0_dp*(1.0_dp - nu**2)*p*a/(pi*e_f), &
                                     1.0e-10_dp, 0.0_dp, 'w(a), '//trim(what))
                    if (allocated(err)) return
                    points: do i = 1, size(r)
                        call elliptic_ke_m1(max((a - r(i))*(a + r(i))/a**2, tiny(1.0_dp)), &
                                            k_val, e_val, err)
                        if (allocated(err)) return
                        w_ref = 4.0_dp*(1.0_dp - nu**2)*p*a/(pi*e_f)*e_val
                        call check_close(err, w(i), w_ref, 1.0e-10_dp, 0.0_dp, 'w(r), '//trim(what))
                        if (allocated(err)) return
                        ! inward radial displacement (kernel reference §C checks, sign confirmed)
                        call check_close(err, u(i), -(1.0_dp - 2.0_dp*nu)*(1.0_dp + nu)*p*r(i)/ &
                                         (2.0_dp*e_f), 1.0e-10_dp, 1.0e-10_dp*p*a/e_f, &
                                         'u_r(r), '//trim(what))
                        if (allocated(err)) return
                    end do points
                end do poisson
                deallocate (rx, rz, u, w)
            end do meshes
        end do families
    end subroutine test_uniform_pressure

    !> Outside the loaded disk (kernel reference §C checks, Johnson 1985 ch. 3), r > a:
    !! w(r) = 4(1-nu^2) p r/(pi E) [E(a/r) - (1 - a^2/r^2) K(a/r)],
    !! u_r(r) = -(1-2nu)(1+nu) p a^2/(2 E r); 1e-10.
    subroutine test_outside(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: rx(:), rz(:)
        real(dp) :: r(3), u(3), w(3), a, nu, e_f, g, k_val, e_val
        integer :: i
        call make_bases(disk, 6, 'EDGES', INTERP_P2, INTERP_S2, bx, bz, err)
        if (allocated(err)) return
        a = bx%x(bx%ne)
        nu = 0.25_dp
        e_f = 5.0_dp
        g = e_f/(2.0_dp*(1.0_dp + nu))
        allocate (rx(bx%n_dof), rz(bz%n_dof))
        rx = 0.0_dp
        rz = 1.0_dp
        r = [1.0001_dp*a, 1.7_dp*a, 6.0_dp*a]
        call plate_surface_displacement(bx, bz, rx, rz, g, nu, r, u, w, err)
        if (allocated(err)) return
        points: do i = 1, size(r)
            call elliptic_ke_m1((r(i) - a)*(r(i) + a)/r(i)**2, k_val, e_val, err)
            if (allocated(err)) return
            call check_close(err, w(i), 4.0_dp*(1.0_dp - nu**2)*r(i)/(pi*e_f)* &
                             (e_val - (1.0_dp - (a/r(i))**2)*k_val), 1.0e-10_dp, 0.0_dp, &
                             'w outside the disk')
            if (allocated(err)) return
            call check_close(err, u(i), &
                             -(1.0_dp - 2.0_dp*nu)*(1.0_dp + nu)*a**2/(2.0_dp*e_f*r(i)), &
                             1.0e-10_dp, 0.0_dp, 'u_r outside the disk')
            if (allocated(err)) return
        end do points
    end subroutine test_outside

    !> Galerkin form, all 9 pairs of bases, uniform and graded meshes: for a constant traction,
    !! sum_b T_ij(a, b) = int g_a(r) f(r) 2 pi r dr with f the closed-form displacement
    !! (w and u_r under p = 1, u_z under q = 1), integrated independently by QAGS; 1e-10 of
    !! the largest row sum.
    subroutine test_row_sums(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        real(dp) :: g, nu, scale
        integer :: fx, fz, ig, nx
        character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']
        character(len=60) :: what
        g = 4.0_dp
        nu = 0.3_dp
        meshes: do ig = 1, 2
            fam_x: do fx = INTERP_P1, INTERP_S2
                fam_z: do fz = INTERP_P1, INTERP_S2
                    call make_bases(disk, 5, trim(gradings(ig)), fx, fz, bx, bz, err)
                    if (allocated(err)) return
                    call assemble_plate_flexibility(bx, bz, g, nu, t, err)
                    if (allocated(err)) return
                    nx = bx%n_dof
                    scale = maxval(abs(sum(t, dim=2)))
                    write (what, '("bases ",i0,"/",i0,", ",a)') fx, fz, trim(gradings(ig))
                    ! T_zz: rows bz, constant sigma_z
                    call check_rows(bz, sum(t(nx + 1:, nx + 1:), dim=2), closed_w_pressure, &
                                    'T_zz '//trim(what), err)
                    if (allocated(err)) return
                    ! T_xz: rows bx, constant sigma_z
                    call check_rows(bx, sum(t(1:nx, nx + 1:), dim=2), closed_u_pressure, &
                                    'T_xz '//trim(what), err)
                    if (allocated(err)) return
                    ! T_zx: rows bz, constant sigma_x
                    call check_rows(bz, sum(t(nx + 1:, 1:nx), dim=2), closed_w_shear, &
                                    'T_zx '//trim(what), err)
                    if (allocated(err)) return
                end do fam_z
            end do fam_x
        end do meshes

    contains

        subroutine check_rows(basis, row_sum, kind, label, err)
            type(basis_t), intent(in) :: basis
            real(dp), intent(in) :: row_sum(:)
            integer, intent(in) :: kind
            character(len=*), intent(in) :: label
            type(error_t), allocatable, intent(out) :: err
            type(closed_row_t) :: f
            f%g = g
            f%nu = nu
            f%a = basis%x(basis%ne)
            f%kind = kind
            call check_row_sums(f, basis, row_sum, scale, label, err)
        end subroutine check_rows
    end subroutine test_row_sums

    !> Every entry of T (both triangles) against an independent nested computation:
    !! T_ab = int g_a(r) 2 pi r u_b(r) dr, u_b the displacement under the single function g_b
    !! from plate_surface_displacement, outer integral by graded composite Gauss; 1e-12 of the
    !! largest entry. Covers the axis element, adjacent and distant pairs and the coupling.
    subroutine test_nested(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_nested(:, :)
        real(dp), parameter :: g = 1.7_dp, nu = 0.23_dp
        call make_bases(disk, 3, 'EDGES', INTERP_P1, INTERP_S2, bx, bz, err)
        if (allocated(err)) return
        call assemble_plate_flexibility(bx, bz, g, nu, t, err)
        if (allocated(err)) return
        call nested_flexibility(disk, bx, bz, g, nu, t_nested, err)
        if (allocated(err)) return
        call check_close(err, maxval(abs(t - t_nested))/maxval(abs(t)), 0.0_dp, 0.0_dp, &
                         1.0e-12_dp, 'max |T - T_nested| / max |T|')
    end subroutine test_nested

    !> T symmetric, all base pairs, uniform and graded meshes: max |T - T^T| <= 1e-12 max |T|.
    !! (galerkin_assembly integrates one triangle and mirrors it by reciprocity; both triangles
    !! are checked independently by galerkin_vs_nested_displacement.)
    subroutine test_symmetric(err)
        type(error_t), allocatable, intent(out) :: err
        call check_symmetric(disk, 'plate T asymmetry', err)
    end subroutine test_symmetric

    !> T positive definite (elastic energy): dpotrf succeeds for several meshes, bases, nu.
    subroutine test_positive_definite(err)
        type(error_t), allocatable, intent(out) :: err
        call check_positive_definite([disk, disk, disk, disk], [1, 6, 15, 24], err)
    end subroutine test_positive_definite

    !> nu_f = 0.5: (1 - 2 nu) = 0, the coupling blocks vanish identically (kernel ref. §0.1).
    subroutine test_incompressible(err)
        type(error_t), allocatable, intent(out) :: err
        call check_incompressible(disk, err)
    end subroutine test_incompressible

    !> Mesh-independent quantity: stiffness of a rigid frictionless flat punch, P/delta =
    !! m^T T_zz^-1 m (m_a = int g_a 2 pi r dr), a Galerkin lower bound converging from below
    !! to the closed form 4 G a/(1-nu) (Boussinesq punch, Johnson 1985 §5.2: delta =
    !! P (1-nu^2)/(2 a E)) under refinement of nested meshes.
    subroutine test_punch(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), tzz(:, :), m(:), c(:)
        real(dp) :: exact, stiff, previous, rel, xi(3), wt(3), h, r
        integer :: level, ne, nx, nz, info, e, k, i, j
        real(dp), parameter :: g = 1.0_dp, nu = 0.3_dp
        character(len=80) :: what
        call gauss_legendre(3, xi, wt)
        exact = 4.0_dp*g*1.3_dp/(1.0_dp - nu)
        previous = 0.0_dp
        levels: do level = 1, 4
            ne = 4*2**(level - 1)
            call make_bases(disk, ne, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
            if (allocated(err)) return
            call assemble_plate_flexibility(bx, bz, g, nu, t, err)
            if (allocated(err)) return
            nx = bx%n_dof
            nz = bz%n_dof
            tzz = t(nx + 1:, nx + 1:)
            allocate (m(nz), c(nz))
            ! m_a = int g_a 2 pi r dr, 3-point GL exact (degree 2 on an element)
            m = 0.0_dp
            elements: do e = 1, ne
                h = bz%x(e) - bz%x(e - 1)
                gauss: do k = 1, 3
                    r = bz%x(e - 1) + 0.5_dp*(xi(k) + 1.0_dp)*h
                    do i = 1, nz
                        m(i) = m(i) + basis_value(bz, e, i, r)*0.5_dp*wt(k)*h*2.0_dp*pi*r
                    end do
                end do gauss
            end do elements
            call dpotrf('L', nz, tzz, nz, info)
            call check(err, info == 0, 'punch: T_zz not positive definite')
            if (allocated(err)) return
            ! solve L L^T c = m
            c = m
            do i = 1, nz
                c(i) = (c(i) - dot_product(tzz(i, 1:i - 1), c(1:i - 1)))/tzz(i, i)
            end do
            do j = nz, 1, -1
                c(j) = (c(j) - dot_product(tzz(j + 1:nz, j), c(j + 1:nz)))/tzz(j, j)
            end do
            stiff = dot_product(m, c)
            rel = (exact - stiff)/exact
            write (what, '("punch stiffness N_e = ",i0,": rel. error ",es10.3)') ne, rel
            ! measured: 1.2e-2, 5.9e-3, 3.0e-3, 1.5e-3 (first order, from below)
            call check(err, stiff > previous .and. rel > 0.0_dp .and. &
                       rel < 0.05_dp/real(2**level, dp), trim(what))
            if (allocated(err)) return
            previous = stiff
            deallocate (m, c)
        end do levels
    end subroutine test_punch

    !> The fixed-order assembly (galerkin_assembly) against the adaptive pair-by-pair reference
    !! (assemble_split_kernel_reference): N_e = 12 and 17, uniform and graded meshes, bases
    !! P1/P1, P2/P2, S2/S2, P2/S2, two nu; every entry within 1e-13 of the largest.
    subroutine test_fast_vs_reference(err)
        type(error_t), allocatable, intent(out) :: err
        call check_fast_vs_reference([disk, disk], 2.3_dp, [0.1_dp, 0.3_dp], err)
    end subroutine test_fast_vs_reference

    !> The interpolated far blocks (galerkin_assembly, add_blocks) against the pair-by-pair
    !! assembly of every far pair (pairwise = .true., the assembly of main fc09087, itself
    !! tested against the adaptive reference above): N_e = 150 and 230, uniform and graded
    !! meshes, P1/P1, P2/P2, S2/S2, P2/S2, and 64 (P1/P1) and 53 (P2/S2), just above
    !! min_blocks; every entry within 1e-14 of the largest (measured 1e-15 to 3.2e-15 at N_e 128
    !! to 1000, at most 1.8e-15 at 50 to 127, output/bench/assembly_before_after.md). T does not
    !! depend on the number of threads, bit for bit (1 and 2 OpenMP threads, 1 and 2 BLAS
    !! threads: the blocks' dgemm run on one), checked on P2, EDGES, N_e = 700, where
    !! OpenBLAS splits the products over its threads (without the one-thread guard of
    !! galerkin_assembly this check fails).
    subroutine test_blocks_vs_pairwise(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_pair(:, :), t_one(:, :)
        integer :: ic, ig, threads, blas
        integer, parameter :: fams(2, 6) = reshape([INTERP_P1, INTERP_P1, INTERP_P2, INTERP_P2, &
            INTERP_S2, INTERP_S2, INTERP_P2, INTERP_S2, INTERP_P1, INTERP_P1, INTERP_P2, &
            INTERP_S2], [2, 6])
        integer, parameter :: nes(6) = [230, 150, 150, 230, 64, 53]
        character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']
        character(len=80) :: what
        cases: do ic = 1, size(nes)
            meshes: do ig = 1, 2
                call make_bases(disk, nes(ic), trim(gradings(ig)), fams(1, ic), fams(2, ic), bx, &
                                bz, err)
                if (allocated(err)) return
                call assemble_plate_flexibility(bx, bz, 2.3_dp, 0.2_dp, t, err)
                if (allocated(err)) return
                call assemble_plate_flexibility(bx, bz, 2.3_dp, 0.2_dp, t_pair, err, &
                                                pairwise=.true.)
                if (allocated(err)) return
                write (what, '("blocks vs pairwise, case ",i0,", ",a)') ic, trim(gradings(ig))
                call check_close(err, maxval(abs(t - t_pair))/maxval(abs(t_pair)), 0.0_dp, &
                                 0.0_dp, 1.0e-14_dp, trim(what))
                if (allocated(err)) return
                call check(err, maxval(abs(t - transpose(t))) == 0.0_dp, &
                           trim(what)//': T exactly symmetric')
                if (allocated(err)) return
                threads = 1
                !$ threads = omp_get_max_threads()
                if (ic > 1 .or. ig > 1) cycle meshes
                ! large enough for OpenBLAS to split a dgemm over its threads (P2, N_e = 700)
                call make_bases(disk, 700, 'EDGES', INTERP_P2, INTERP_P2, bx, bz, err)
                if (allocated(err)) return
                blas = blas_thread_count()
                !$ call omp_set_num_threads(1)
                call set_blas_threads(1)
                call assemble_plate_flexibility(bx, bz, 2.3_dp, 0.2_dp, t_one, err)
                !$ call omp_set_num_threads(2)
                call set_blas_threads(2)
                if (.not. allocated(err)) call assemble_plate_flexibility(bx, bz, 2.3_dp, &
                                                                          0.2_dp, t, err)
                !$ call omp_set_num_threads(threads)
                call set_blas_threads(blas)
                if (allocated(err)) return
                call check(err, all(t == t_one), 'blocks: the same T on 1 and 2 threads '// &
                           '(OpenMP and BLAS)')
                if (allocated(err)) return
            end do meshes
        end do cases
    end subroutine test_blocks_vs_pairwise

    !> K, E by the arithmetic-geometric mean (used by the ring kernels) against GSL's Carlson
    !! forms (elliptic_ke_m1), m1 = 1 - k^2 from 1e-19 to 1: K to 1e-15 relative, E to
    !! 1e-15 relative plus 5e-16 K (the cancellation of 1 - sum as k -> 1, module header of
    !! halfspace_plate); measured 7.5e-16 and 5.3e-16 (GSL itself is good to a few ulps).
    subroutine test_agm(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: m1, k_ref, e_ref, k_agm, e_agm, worst_k, worst_e
        integer :: i
        character(len=80) :: what
        worst_k = 0.0_dp
        worst_e = 0.0_dp
        points: do i = 0, 380
            m1 = 10.0_dp**(-0.05_dp*real(i, dp))
            call elliptic_ke_m1(m1, k_ref, e_ref, err)
            if (allocated(err)) return
            call elliptic_ke_agm(sqrt(m1), 1.0_dp - m1, k_agm, e_agm)
            worst_k = max(worst_k, abs(k_agm - k_ref)/k_ref)
            worst_e = max(worst_e, abs(e_agm - e_ref)/(e_ref + 0.5_dp*k_ref))
        end do points
        write (what, '("AGM vs Carlson: K ",es9.2,", E ",es9.2)') worst_k, worst_e
        call check(err, worst_k <= 1.0e-15_dp .and. worst_e <= 1.0e-15_dp, trim(what))
        if (allocated(err)) return
    end subroutine test_agm

    !> A run's cache of T (flexibility_cache): off (a single case) it keeps nothing; on, a
    !! second look-up with the same mesh, bases and soil is answered from the cache with T
    !! bit for bit as assemble_flexibility gives it afresh, and a case that differs in nu_f,
    !! the mesh grading, the sigma_z interpolation, the beam width or the structure is
    !! assembled (the hit count does not move).
    subroutine test_flexibility_cache(err)
        type(error_t), allocatable, intent(out) :: err
        type(flexibility_cache_t) :: cache
        type(model_t) :: m, variant
        real(dp), allocatable :: t_ref(:, :), t_1(:, :)
        integer :: k
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 24)
        call assembled(m, t_ref, err)
        if (allocated(err)) return
        cache = new_flexibility_cache(.false.)
        call cached(m, cache, t_1, err)
        if (.not. allocated(err)) call cached(m, cache, t_1, err)
        if (allocated(err)) return
        call check(err, flexibility_cache_hits(cache) == 0, 'cache off: a look-up was answered')
        if (allocated(err)) return
        cache = new_flexibility_cache(.true.)
        call cached(m, cache, t_1, err)
        if (.not. allocated(err)) call cached(m, cache, t_1, err)
        if (allocated(err)) return
        call check(err, flexibility_cache_hits(cache) == 1 .and. all(t_1 == t_ref), &
                   'cache on: the second look-up is not the assembled T')
        if (allocated(err)) return
        do k = 1, 5
            select case (k)
            case (1)
                variant = nondim_plate(0.01_dp, 0.1_dp, 0.3_dp, 0.5_dp, 24)   ! nu_f
            case (2)
                variant = m
                variant%mesh%grading = 'EDGES'
            case (3)
                variant = m
                variant%mesh%interp(FIELD_SZ) = INTERP_S2
            case (4)
                variant = nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.5_dp, 0.0_dp, 24)
            case (5)
                variant = nondim_beam(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 0.0_dp, 24)  ! width
            end select
            call cached(variant, cache, t_1, err)
            if (allocated(err)) exit
            call check(err, flexibility_cache_hits(cache) == 1, 'a different case answered '// &
                'from '// &
                       'the cache (variant '//char(ichar('0') + k)//')')
            if (allocated(err)) exit
        end do
    end subroutine test_flexibility_cache

    subroutine assembled(m, t_mat, err)
        type(model_t), intent(in) :: m
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        type(error_t), allocatable, intent(out) :: err
        type(discretization_t) :: d
        call new_discretization(m, d, err)
        if (.not. allocated(err)) call assemble_flexibility(m, d, t_mat, err)
    end subroutine assembled

    subroutine cached(m, cache, t_mat, err)
        type(model_t), intent(in) :: m
        type(flexibility_cache_t), intent(inout) :: cache
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        type(error_t), allocatable, intent(out) :: err
        type(discretization_t) :: d
        call new_discretization(m, d, err)
        if (.not. allocated(err)) call flexibility_of(m, d, t_mat, err, cache)
    end subroutine cached
end module test_halfspace_plate
