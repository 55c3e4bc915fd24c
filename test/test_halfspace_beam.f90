!> Tests of halfspace_beam: centre-line strip kernels, surface displacements and the Galerkin
!! flexibility of the half-space under a beam of width b (line loads spread across the width).
!!
!! Closed forms used, uniform line load p (normal) or q (tangential) on the whole beam
!! [-l/2, l/2], X_+- = x +- l/2, h = b/2, c_L = (1-nu)/(pi G b), integrals of (B9)–(B11):
!!   w   (p) = c_L p [A(X_+) - A(X_-)],        A(X) = X asinh(h/|X|) + h asinh(X/h)
!!   u_x (p) = -(1-2nu) p/(2 pi G b) [B(X_+) - B(X_-)],   B(X) = X atan(h/X) + (h/2) ln(X^2+h^2)
!!   w   (q) = +(1-2nu) q/(2 pi G b) [B(X_+) - B(X_-)]
!!   u_x (q) = c_L q [A(X_+) - A(X_-)] + nu q h/(pi G b) [asinh(X_+/h) - asinh(X_-/h)]
!! (each antiderivative checked by differentiation; A, B continuous at X = 0).
module test_halfspace_beam
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, check, check_close, error_t
    use quadrature, only: gauss_legendre
    use gsl_wrappers, only: integrand_t, integrate_qags
    use mesh, only: mesh_t
    use shape_functions, only: basis_t, new_basis, INTERP_P1, INTERP_P2, INTERP_S2
    use halfspace_beam, only: assemble_beam_flexibility, beam_surface_displacement, &
                              strip_kernels
    use halfspace_test_support, only: basis_value, surface_t, strips, row_integrand_t, &
                                      beam_length, make_bases, nested_flexibility, &
                                      check_row_sums, check_symmetric, check_positive_definite, &
                                      check_incompressible, check_fast_vs_reference
    implicit none
    private
    public :: collect_halfspace_beam

    type(surface_t), parameter :: strip = surface_t(plate=.false.)   !! meshes only (no width)

    !> Closed-form displacements of the module header, in a type to share the data.
    type :: soil_t
        real(dp) :: g = 1.0_dp, nu = 0.3_dp, b = 0.2_dp
    end type soil_t

    !> g_a(x) f(x) on one element, f a closed-form displacement (component 1..4 =
    !! w(p), u_x(p), w(q), u_x(q)).
    type, extends(row_integrand_t) :: closed_row_t
        type(soil_t) :: soil
        integer :: component = 1
    contains
        procedure :: value => row_value
    end type closed_row_t

    !> Boussinesq/Cerruti (B1), (B2) at (x_field, 0) due to a unit force at (xi, eta), for the
    !! component 1..3 = w(normal), u_x(tangential), w(tangential); integrated over eta.
    type, extends(integrand_t) :: across_t
        type(soil_t) :: soil
        real(dp) :: x_dist = 1.0_dp      !! X = x_field - xi
        integer :: component = 1
    contains
        procedure :: value => across_value
    end type across_t

    !> Outer integrand of the 2-D rectangle integral: int over eta of across_t, as a function
    !! of xi, for a traction 1/b on the rectangle (unit line load).
    type, extends(integrand_t) :: along_t
        type(soil_t) :: soil
        real(dp) :: x_field = 0.0_dp
        integer :: component = 1
        logical :: failed = .false.
    contains
        procedure :: value => along_value
    end type along_t

contains

    subroutine collect_halfspace_beam(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('kernels_vs_boussinesq_cerruti', test_kernels), &
                 new_unittest('jump_and_far_field', test_jump_far_field), &
                 new_unittest('uniform_load_closed_forms', test_uniform_load), &
                 new_unittest('rectangle_vs_2d_quadrature', test_rectangle), &
                 new_unittest('galerkin_row_sums_vs_closed_forms', test_row_sums), &
                 new_unittest('galerkin_vs_nested_displacement', test_nested), &
                 new_unittest('symmetric', test_symmetric), &
                 new_unittest('positive_definite', test_positive_definite), &
                 new_unittest('incompressible_no_coupling', test_incompressible), &
                 new_unittest('fast_vs_reference_assembly', test_fast_vs_reference), &
                 new_unittest('fast_vs_reference_piecewise_uniform', test_piecewise_uniform)]
    end subroutine collect_halfspace_beam

    ! ------------------------------------------------------------------ helpers

    pure real(dp) function anti_a(x, h)
        real(dp), intent(in) :: x, h
        anti_a = h*asinh(x/h)
        if (x /= 0.0_dp) anti_a = anti_a + x*asinh(h/abs(x))
    end function anti_a

    pure real(dp) function anti_b(x, h)
        real(dp), intent(in) :: x, h
        anti_b = 0.5_dp*h*log(x*x + h*h)
        if (x /= 0.0_dp) anti_b = anti_b + x*atan(h/x)
    end function anti_b

    !> Closed-form displacement component (module header) at x under a unit uniform load.
    pure real(dp) function closed_form(soil, component, x)
        type(soil_t), intent(in) :: soil
        integer, intent(in) :: component
        real(dp), intent(in) :: x
        real(dp) :: xp, xm, h, g, nu, b
        g = soil%g
        nu = soil%nu
        b = soil%b
        h = 0.5_dp*b
        xp = x + 0.5_dp*beam_length
        xm = x - 0.5_dp*beam_length
        select case (component)
        case (1)
            closed_form = (1.0_dp - nu)/(pi*g*b)*(anti_a(xp, h) - anti_a(xm, h))
        case (2)
            closed_form = -(1.0_dp - 2.0_dp*nu)/(2.0_dp*pi*g*b)*(anti_b(xp, h) - anti_b(xm, h))
        case (3)
            closed_form = (1.0_dp - 2.0_dp*nu)/(2.0_dp*pi*g*b)*(anti_b(xp, h) - anti_b(xm, h))
        case default
            closed_form = (1.0_dp - nu)/(pi*g*b)*(anti_a(xp, h) - anti_a(xm, h)) + &
                          nu*h/(pi*g*b)*(asinh(xp/h) - asinh(xm/h))
        end select
    end function closed_form

    function row_value(self, x) result(f)
        class(closed_row_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        f = basis_value(self%basis, self%element, self%dof, x)* &
            closed_form(self%soil, self%component, x)
    end function row_value

    function across_value(self, x) result(f)
        class(across_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        real(dp) :: xd, rho2, rho, g, nu
        g = self%soil%g
        nu = self%soil%nu
        xd = self%x_dist
        rho2 = xd*xd + x*x
        rho = sqrt(rho2)
        select case (self%component)
        case (1)
            f = (1.0_dp - nu)/(2.0_dp*pi*g*rho)                              ! (B1) u_z
        case (2)
            f = ((1.0_dp - nu) + nu*xd*xd/rho2)/(2.0_dp*pi*g*rho)              ! (B2) u_x
        case default
            f = (1.0_dp - 2.0_dp*nu)*xd/(4.0_dp*pi*g*rho2)                   ! (B2) u_z
        end select
        f = f/self%soil%b                  ! traction 1/b of a unit line load
    end function across_value

    function along_value(self, x) result(f)
        class(along_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: f
        type(across_t) :: inner
        type(error_t), allocatable :: err
        real(dp) :: abserr
        inner%soil = self%soil
        inner%component = self%component
        inner%x_dist = self%x_field - x
        call integrate_qags(inner, -0.5_dp*self%soil%b, 0.5_dp*self%soil%b, 0.0_dp, 1.0e-13_dp, &
                            f, abserr, err)
        if (allocated(err)) self%failed = .true.
    end function along_value


    ! ------------------------------------------------------------------ tests

    !> (B9)–(B11) against QAGS integration of Boussinesq/Cerruti (B1), (B2) across the width
    !! (an independent computation), near and far, both signs of X.
    subroutine test_kernels(err)
        type(error_t), allocatable, intent(out) :: err
        type(across_t) :: f
        real(dp) :: k(3), expected, abserr
        real(dp), parameter :: x_over_b(6) = [0.01_dp, -0.01_dp, 0.3_dp, -2.0_dp, 17.0_dp, &
                                              -0.7_dp]
        integer :: i, c
        character(len=60) :: what
        f%soil = soil_t(g=3.1_dp, nu=0.27_dp, b=0.4_dp)
        distances: do i = 1, size(x_over_b)
            f%x_dist = x_over_b(i)*f%soil%b
            call strip_kernels(f%x_dist, f%soil%g, f%soil%nu, f%soil%b, k(1), k(2), k(3))
            components: do c = 1, 3
                f%component = c
                call integrate_qags(f, -0.5_dp*f%soil%b, 0.5_dp*f%soil%b, 0.0_dp, 1.0e-13_dp, &
                                    expected, abserr, err)
                if (allocated(err)) return
                write (what, '("strip kernel ",i0," at X/b = ",f6.2)') c, x_over_b(i)
                call check_close(err, k(c), expected, 1.0e-12_dp, 0.0_dp, trim(what))
                if (allocated(err)) return
            end do components
        end do distances
    end subroutine test_kernels

    !> Plane-strain jump b k_zx(0+-) = +-(1-2nu)/(4G) (A4); far field X = 250 b: point-load
    !! values (B1), (B2) on the axis, (1-nu)/(2 pi G X), 1/(2 pi G X), (1-2nu)/(4 pi G X), to
    !! 1.5e-6 (the largest first correction is z^2/3 = 1.33e-6), and to 1e-13 with two
    !! corrections of the Taylor series asinh z = z - z^3/6 + 3z^5/40, atan z = z - z^3/3 +
    !! z^5/5, 1/sqrt(1+z^2) = 1 - z^2/2 + 3z^4/8 (z = h/X, omitted terms O(z^6) = 6e-17).
    subroutine test_jump_far_field(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: k_zz, k_xx, k_zx, x_dist, z, point(3), corrected(3), k(3)
        real(dp), parameter :: g = 2.0_dp, nu = 0.15_dp, b = 0.3_dp
        character(len=4), parameter :: names(3) = ['k_zz', 'k_xx', 'k_zx']
        integer :: side, c
        sides: do side = -1, 1, 2
            call strip_kernels(real(side, dp)*1.0e-13_dp*b, g, nu, b, k_zz, k_xx, k_zx)
            call check_close(err, b*k_zx, real(side, dp)*(1.0_dp - 2.0_dp*nu)/(4.0_dp*g), &
                             1.0e-12_dp, 0.0_dp, 'b k_zx(0+-)')
            if (allocated(err)) return
        end do sides
        x_dist = 250.0_dp*b
        z = 0.5_dp*b/x_dist
        call strip_kernels(x_dist, g, nu, b, k_zz, k_xx, k_zx)
        point = [(1.0_dp - nu), 1.0_dp, 0.5_dp*(1.0_dp - 2.0_dp*nu)]/(2.0_dp*pi*g*x_dist)
        corrected = point*[1.0_dp - z**2/6.0_dp + 3.0_dp*z**4/40.0_dp, &
                           (1.0_dp - nu)*(1.0_dp - z**2/6.0_dp + 3.0_dp*z**4/40.0_dp) + &
                           nu*(1.0_dp - z**2/2.0_dp + 3.0_dp*z**4/8.0_dp), &
                           1.0_dp - z**2/3.0_dp + z**4/5.0_dp]
        k = [k_zz, k_xx, k_zx]
        point_values: do c = 1, 3
            call check_close(err, k(c), point(c), 1.5e-6_dp, 0.0_dp, 'far '//names(c))
            if (allocated(err)) return
        end do point_values
        corrected_values: do c = 1, 3
            call check_close(err, k(c), corrected(c), 1.0e-13_dp, 0.0_dp, &
                             'far '//names(c)//', corrected')
            if (allocated(err)) return
        end do corrected_values
    end subroutine test_jump_far_field

    !> Uniform line loads on the whole beam, all bases, uniform and graded meshes, widths from
    !! much narrower to wider than an element: beam_surface_displacement against the closed
    !! forms of the module header at the centre, nodes, ends, inner points and a point beyond
    !! the end, 1e-10.
    subroutine test_uniform_load(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        type(soil_t) :: soil
        real(dp), allocatable :: ones_x(:), ones_z(:), zero_x(:), zero_z(:), x(:), u(:), w(:)
        real(dp) :: scale
        integer :: fam, ig, ib, i
        character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']
        real(dp), parameter :: widths(3) = [0.004_dp, 0.3_dp, 5.0_dp]
        character(len=80) :: what
        families: do fam = INTERP_P1, INTERP_S2
            meshes: do ig = 1, 2
                call make_bases(strip, 8, trim(gradings(ig)), fam, fam, bx, bz, err)
                if (allocated(err)) return
                x = [0.0_dp, bx%x(0), bx%x(1), bx%x(3), 0.123_dp, 0.77_dp*bx%x(8), bx%x(8), &
                     1.4_dp*bx%x(8)]
                allocate (u(size(x)), w(size(x)))
                allocate (ones_x(bx%n_dof), zero_x(bx%n_dof), ones_z(bz%n_dof), zero_z(bz%n_dof))
                ones_x = 1.0_dp
                ones_z = 1.0_dp
                zero_x = 0.0_dp
                zero_z = 0.0_dp
                widths_loop: do ib = 1, size(widths)
                    soil = soil_t(g=1.0e4_dp, nu=0.3_dp, b=widths(ib))
                    scale = closed_form(soil, 1, 0.0_dp)
                    write (what, '("family ",i0,", ",a,", b = ",f5.3)') fam, trim(gradings(ig)), &
                        widths(ib)
                    call beam_surface_displacement(bx, bz, zero_x, ones_z, soil%g, soil%nu, &
                                                   soil%b, x, u, w, err)
                    if (allocated(err)) return
                    normal_load: do i = 1, size(x)
                        call check_close(err, w(i), closed_form(soil, 1, x(i)), 1.0e-10_dp, &
                                         0.0_dp, 'w under p, '//trim(what))
                        if (allocated(err)) return
                        call check_close(err, u(i), closed_form(soil, 2, x(i)), 0.0_dp, &
                                         1.0e-10_dp*scale, 'u_x under p, '//trim(what))
                        if (allocated(err)) return
                    end do normal_load
                    call beam_surface_displacement(bx, bz, ones_x, zero_z, soil%g, soil%nu, &
                                                   soil%b, x, u, w, err)
                    if (allocated(err)) return
                    shear_load: do i = 1, size(x)
                        call check_close(err, w(i), closed_form(soil, 3, x(i)), 0.0_dp, &
                                         1.0e-10_dp*scale, 'w under q, '//trim(what))
                        if (allocated(err)) return
                        call check_close(err, u(i), closed_form(soil, 4, x(i)), 1.0e-10_dp, &
                                         0.0_dp, 'u_x under q, '//trim(what))
                        if (allocated(err)) return
                    end do shear_load
                end do widths_loop
                deallocate (u, w, ones_x, ones_z, zero_x, zero_z)
            end do meshes
        end do families
    end subroutine test_uniform_load

    !> Unit uniform line load on the whole beam = traction 1/b on the rectangle
    !! [-l/2, l/2] x [-b/2, b/2]: centre-line displacements from beam_surface_displacement
    !! against nested QAGS (2-D adaptive quadrature) of (B1), (B2) over the rectangle, 1e-10.
    subroutine test_rectangle(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        type(along_t) :: f
        real(dp), allocatable :: ones_x(:), ones_z(:), zero_x(:), zero_z(:)
        real(dp) :: x(3), u(3), w(3), left, right, abserr, expected, got, scale
        integer :: i, c
        character(len=60) :: what
        call make_bases(strip, 6, 'EDGES', INTERP_P2, INTERP_S2, bx, bz, err)
        if (allocated(err)) return
        f%soil = soil_t(g=0.8_dp, nu=0.35_dp, b=0.5_dp)
        x = [0.0_dp, 0.3_dp*beam_length, 0.5_dp*beam_length]
        allocate (ones_x(bx%n_dof), zero_x(bx%n_dof), ones_z(bz%n_dof), zero_z(bz%n_dof))
        ones_x = 1.0_dp
        ones_z = 1.0_dp
        zero_x = 0.0_dp
        zero_z = 0.0_dp
        components: do c = 1, 3
            if (c == 1) then
                call beam_surface_displacement(bx, bz, zero_x, ones_z, f%soil%g, f%soil%nu, &
                                               f%soil%b, x, u, w, err)
            else
                call beam_surface_displacement(bx, bz, ones_x, zero_z, f%soil%g, f%soil%nu, &
                                               f%soil%b, x, u, w, err)
            end if
            if (allocated(err)) return
            points: do i = 1, size(x)
                f%component = c
                f%x_field = x(i)
                ! split at the field point: the inner integral is log-singular there
                left = 0.0_dp
                right = 0.0_dp
                if (x(i) > -0.5_dp*beam_length) call integrate_qags(f, -0.5_dp*beam_length, &
                    x(i), 0.0_dp, 1.0e-13_dp, left, abserr, err)
                if (allocated(err)) return
                if (x(i) < 0.5_dp*beam_length) call integrate_qags(f, x(i), 0.5_dp*beam_length, &
                    0.0_dp, 1.0e-13_dp, right, abserr, err)
                if (allocated(err)) return
                call check(err, .not. f%failed, 'inner QAGS failed')
                if (allocated(err)) return
                expected = left + right
                if (c == 1 .and. i == 1) scale = w(1)
                got = merge(w(i), u(i), c /= 2)
                write (what, '("component ",i0," at x = ",f6.3)') c, x(i)
                call check_close(err, got, expected, 1.0e-10_dp, 1.0e-12_dp*scale, trim(what))
                if (allocated(err)) return
            end do points
        end do components
    end subroutine test_rectangle

    !> Galerkin form, all 9 pairs of bases, uniform and graded meshes, narrow and wide beams:
    !! for a constant traction, sum_b T_ij(a, b) = int g_a f dx with f the closed form of the
    !! module header (all four blocks), integrated independently by QAGS; 1e-10 of the
    !! largest row sum.
    subroutine test_row_sums(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        type(soil_t) :: soil
        real(dp), allocatable :: t(:, :)
        real(dp) :: scale
        integer :: fx, fz, ig, ib, nx
        character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']
        real(dp), parameter :: widths(2) = [0.02_dp, 1.5_dp]
        character(len=60) :: what
        widths_loop: do ib = 1, size(widths)
            soil = soil_t(g=3.0_dp, nu=0.2_dp, b=widths(ib))
            meshes: do ig = 1, 2
                fam_x: do fx = INTERP_P1, INTERP_S2
                    fam_z: do fz = INTERP_P1, INTERP_S2
                        call make_bases(strip, 5, trim(gradings(ig)), fx, fz, bx, bz, err)
                        if (allocated(err)) return
                        call assemble_beam_flexibility(bx, bz, soil%g, soil%nu, soil%b, t, err)
                        if (allocated(err)) return
                        nx = bx%n_dof
                        scale = maxval(abs(sum(t, dim=2)))
                        write (what, '("bases ",i0,"/",i0,", ",a,", b = ",f4.2)') fx, fz, &
                            trim(gradings(ig)), soil%b
                        call check_rows(bz, sum(t(nx + 1:, nx + 1:), dim=2), 1, &
                                        'T_zz '//trim(what), err)
                        if (allocated(err)) return
                        call check_rows(bx, sum(t(1:nx, nx + 1:), dim=2), 2, &
                                        'T_xz '//trim(what), err)
                        if (allocated(err)) return
                        call check_rows(bz, sum(t(nx + 1:, 1:nx), dim=2), 3, &
                                        'T_zx '//trim(what), err)
                        if (allocated(err)) return
                        call check_rows(bx, sum(t(1:nx, 1:nx), dim=2), 4, 'T_xx '//trim(what), err)
                        if (allocated(err)) return
                    end do fam_z
                end do fam_x
            end do meshes
        end do widths_loop

    contains

        subroutine check_rows(basis, row_sum, component, label, err)
            type(basis_t), intent(in) :: basis
            real(dp), intent(in) :: row_sum(:)
            integer, intent(in) :: component
            character(len=*), intent(in) :: label
            type(error_t), allocatable, intent(out) :: err
            type(closed_row_t) :: f
            f%soil = soil
            f%component = component
            call check_row_sums(f, basis, row_sum, scale, label, err)
        end subroutine check_rows
    end subroutine test_row_sums

    !> Every entry of T (both triangles) against an independent nested computation:
    !! T_ab = int g_a(x) u_b(x) dx, u_b the displacement under the single function g_b from
    !! beam_surface_displacement, outer integral by graded composite Gauss; 1e-12 of the
    !! largest entry. Elements longer than the width (b = 0.05, h_e ~ 0.5) and shorter.
    subroutine test_nested(err)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_nested(:, :)
        integer :: ib
        real(dp), parameter :: g = 1.7_dp, nu = 0.23_dp, widths(2) = [0.05_dp, 0.9_dp]
        character(len=60) :: what
        call make_bases(strip, 4, 'EDGES', INTERP_P2, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        widths_loop: do ib = 1, size(widths)
            call assemble_beam_flexibility(bx, bz, g, nu, widths(ib), t, err)
            if (allocated(err)) return
            call nested_flexibility(surface_t(plate=.false., b=widths(ib)), bx, bz, g, nu, &
                                    t_nested, err)
            if (allocated(err)) return
            write (what, '("max |T - T_nested| / max |T|, b = ",f4.2)') widths(ib)
            call check_close(err, maxval(abs(t - t_nested))/maxval(abs(t)), 0.0_dp, 0.0_dp, &
                             1.0e-12_dp, trim(what))
            if (allocated(err)) return
        end do widths_loop
    end subroutine test_nested

    !> T symmetric: all base pairs, both gradings, narrow and wide beams, max |T - T^T| <=
    !! 1e-12 max |T|. (galerkin_assembly integrates one triangle and mirrors it by reciprocity;
    !! both triangles are checked independently by galerkin_vs_nested_displacement.)
    subroutine test_symmetric(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: widths(2) = [0.01_dp, 2.0_dp]
        integer :: ib
        widths_loop: do ib = 1, size(widths)
            call check_symmetric(surface_t(plate=.false., b=widths(ib)), 'beam T asymmetry', err)
            if (allocated(err)) return
        end do widths_loop
    end subroutine test_symmetric

    !> T positive definite: dpotrf succeeds for several meshes, bases, widths and nu.
    subroutine test_positive_definite(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: widths(4) = [0.5_dp, 0.02_dp, 3.0_dp, 0.1_dp]
        call check_positive_definite(strips(widths), [1, 6, 15, 30], err)
    end subroutine test_positive_definite

    !> nu_f = 0.5: the coupling blocks vanish identically (factor 1 - 2 nu, kernel ref. §0.1).
    subroutine test_incompressible(err)
        type(error_t), allocatable, intent(out) :: err
        call check_incompressible(surface_t(plate=.false., b=0.3_dp), err)
    end subroutine test_incompressible

    !> The fixed-order assembly (galerkin_assembly) against the adaptive pair-by-pair reference
    !! (assemble_split_kernel_reference): N_e = 12 and 17, uniform and graded meshes, bases
    !! P1/P1, P2/P2, S2/S2, P2/S2, widths much narrower than, like and wider than an element;
    !! every entry within 1e-13 of the largest.
    subroutine test_fast_vs_reference(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: widths(3) = [0.0055_dp, 0.15_dp, 3.0_dp]
        call check_fast_vs_reference(strips(widths), 1.3_dp, &
                                     [0.2_dp, 0.2_dp, 0.2_dp], err)
    end subroutine test_fast_vs_reference

    !> The translated-pair reuse of galerkin_assembly on a mesh of two uniform zones (10
    !! elements of 0.1, then 6 of 0.2333..., the second zone's nodes rounded as a deck would
    !! give them): fast against reference for P1, P2, S2, entries within 1e-13 of the largest.
    subroutine test_piecewise_uniform(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_ref(:, :)
        integer :: fam, e
        character(len=60) :: what
        msh%ne = 16
        allocate (msh%x(0:16))
        do e = 0, 10
            msh%x(e) = -1.2_dp + 0.1_dp*real(e, dp)
        end do
        do e = 11, 16
            msh%x(e) = msh%x(10) + (1.2_dp - msh%x(10))*real(e - 10, dp)/6.0_dp
        end do
        families: do fam = INTERP_P1, INTERP_S2
            call new_basis(bx, msh, fam)
            call new_basis(bz, msh, fam)
            call assemble_beam_flexibility(bx, bz, 1.3_dp, 0.2_dp, 0.05_dp, t, err)
            if (allocated(err)) return
            call assemble_beam_flexibility(bx, bz, 1.3_dp, 0.2_dp, 0.05_dp, t_ref, err, &
                                           reference=.true.)
            if (allocated(err)) return
            write (what, '("fast vs reference, two zones, family ",i0)') fam
            call check_close(err, maxval(abs(t - t_ref))/maxval(abs(t_ref)), 0.0_dp, 0.0_dp, &
                             1.0e-13_dp, trim(what))
            if (allocated(err)) return
        end do families
    end subroutine test_piecewise_uniform
end module test_halfspace_beam
