!> Helpers shared by the half-space test suites (test_halfspace_beam, test_halfspace_plate):
!! a quadrature independent of the library's singular quadrature (so that the tests check it
!! rather than repeat it), basis values, and the checks both flexibilities must pass
!! (symmetry, positive definiteness, no coupling at nu = 1/2, fast against reference
!! assembly, row sums against closed forms, every entry against nested displacements).
module halfspace_test_support
    use kinds, only: dp, pi
    use harness, only: error_t, check, check_close
    use quadrature, only: gauss_legendre
    use gsl_wrappers, only: integrand_t, integrate_qags
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, eval_basis, max_local, INTERP_P1, &
                               INTERP_P2, INTERP_S2
    use halfspace_beam, only: assemble_beam_flexibility, beam_surface_displacement
    use halfspace_plate, only: assemble_plate_flexibility, plate_surface_displacement
    use lapack_interfaces, only: dpotrf
    implicit none
    private
    public :: graded_rule, basis_value
    public :: strips, make_bases, assemble, asymmetry, nested_flexibility, check_row_sums
    public :: check_symmetric, check_positive_definite, check_incompressible, &
              check_fast_vs_reference

    real(dp), parameter, public :: beam_length = 2.4_dp    !! l of every beam test mesh
    real(dp), parameter, public :: plate_radius = 1.3_dp   !! a of every plate test mesh

    !> The loaded surface: the plate's disk [0, a] or the beam's strip of width b on
    !! [-l/2, l/2].
    type, public :: surface_t
        logical :: plate = .true.
        real(dp) :: b = 0.0_dp        !! beam width (beam only)
    end type surface_t

    !> g_a(x) w(x) f(x) on one element, f a closed-form displacement of the suite; failed:
    !! the closed form could not be evaluated.
    type, abstract, extends(integrand_t), public :: row_integrand_t
        type(basis_t) :: basis
        integer :: element = 1, dof = 1
        logical :: failed = .false.
    end type row_integrand_t

    character(len=7), parameter :: gradings(2) = ['UNIFORM', 'EDGES  ']

contains

    !> Beam surfaces of the widths b.
    pure function strips(b) result(s)
        real(dp), intent(in) :: b(:)
        type(surface_t) :: s(size(b))
        s%plate = .false.
        s%b = b
    end function strips

    !> Bases of sigma_x and sigma_z on a mesh of ne elements of the surface.
    subroutine make_bases(s, ne, grading, fam_x, fam_z, bx, bz, err)
        type(surface_t), intent(in) :: s
        integer, intent(in) :: ne, fam_x, fam_z
        character(len=*), intent(in) :: grading
        type(basis_t), intent(out) :: bx, bz
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        if (s%plate) then
            call new_mesh(msh, 0.0_dp, plate_radius, ne, grading, err)
        else
            call new_mesh(msh, -0.5_dp*beam_length, 0.5_dp*beam_length, ne, grading, err)
        end if
        if (allocated(err)) return
        call new_basis(bx, msh, fam_x)
        call new_basis(bz, msh, fam_z)
    end subroutine make_bases

    !> The flexibility T of the surface (halfspace_plate or halfspace_beam).
    subroutine assemble(s, bx, bz, g, nu, t, err, reference)
        type(surface_t), intent(in) :: s
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: g, nu
        real(dp), allocatable, intent(out) :: t(:, :)
        type(error_t), allocatable, intent(out) :: err
        logical, intent(in), optional :: reference     !! the pair-by-pair reference assembly
        if (s%plate) then
            call assemble_plate_flexibility(bx, bz, g, nu, t, err, reference=reference)
        else
            call assemble_beam_flexibility(bx, bz, g, nu, s%b, t, err, reference=reference)
        end if
    end subroutine assemble

    !> max |T - T^T| / max |T|.
    pure real(dp) function asymmetry(t)
        real(dp), intent(in) :: t(:, :)
        asymmetry = maxval(abs(t - transpose(t)))/maxval(abs(t))
    end function asymmetry

    !> T_ab = int g_a(x) u_b(x) w(x) dx (w = 1 beam, 2 pi r plate), u_b the displacement under
    !! the single function g_b (beam_ or plate_surface_displacement), outer integral by the
    !! graded composite Gauss rule on every element: T computed independently of the
    !! Galerkin assembly.
    subroutine nested_flexibility(s, bx, bz, g, nu, t_nested, err)
        type(surface_t), intent(in) :: s
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: g, nu
        real(dp), allocatable, intent(out) :: t_nested(:, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: nodes(:), weights(:), x(:), wx(:), u(:), w(:), rx(:), rz(:)
        integer :: e, nx, nz, col
        nx = bx%n_dof
        nz = bz%n_dof
        allocate (x(0), wx(0))
        elements: do e = 1, bx%ne
            call graded_rule(bx%x(e - 1), bx%x(e), nodes, weights)
            x = [x, nodes]
            wx = [wx, weights]
        end do elements
        if (s%plate) wx = wx*2.0_dp*pi*x
        allocate (u(size(x)), w(size(x)), rx(nx), rz(nz), t_nested(nx + nz, nx + nz))
        columns: do col = 1, nx + nz
            rx = 0.0_dp
            rz = 0.0_dp
            if (col <= nx) then
                rx(col) = 1.0_dp
            else
                rz(col - nx) = 1.0_dp
            end if
            if (s%plate) then
                call plate_surface_displacement(bx, bz, rx, rz, g, nu, x, u, w, err)
            else
                call beam_surface_displacement(bx, bz, rx, rz, g, nu, s%b, x, u, w, err)
            end if
            if (allocated(err)) return
            t_nested(:, col) = weighted_rows(bx, bz, x, wx, u, w)
        end do columns
    end subroutine nested_flexibility

    !> int g_a u w (rows of sigma_x) and int g_a w_z w (rows of sigma_z) by the rule x, wx.
    pure function weighted_rows(bx, bz, x, wx, u, w) result(col)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: x(:), wx(:), u(:), w(:)
        real(dp) :: col(bx%n_dof + bz%n_dof)
        integer :: row, k, e, nx
        nx = bx%n_dof
        rows: do row = 1, size(col)
            col(row) = 0.0_dp
            points: do k = 1, size(x)
                e = min(bx%ne, count(bx%x(1:bx%ne - 1) < x(k)) + 1)
                if (row <= nx) then
                    col(row) = col(row) + wx(k)*u(k)*basis_value(bx, e, row, x(k))
                else
                    col(row) = col(row) + wx(k)*w(k)*basis_value(bz, e, row - nx, x(k))
                end if
            end do points
        end do rows
    end function weighted_rows

    !> Row sums of a block of T against int g_a f (f%value, the suite's closed form) by QAGS
    !! on every element, 1e-10 of scale.
    subroutine check_row_sums(f, basis, row_sum, scale, label, err)
        class(row_integrand_t), intent(inout) :: f
        type(basis_t), intent(in) :: basis
        real(dp), intent(in) :: row_sum(:), scale
        character(len=*), intent(in) :: label
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: total, part, abserr
        integer :: a, e
        f%basis = basis
        rows: do a = 1, basis%n_dof
            total = 0.0_dp
            elements: do e = 1, basis%ne
                f%element = e
                f%dof = a
                call integrate_qags(f, basis%x(e - 1), basis%x(e), 1.0e-15_dp*scale, &
                                    1.0e-13_dp, part, abserr, err)
                if (allocated(err)) return
                total = total + part
            end do elements
            ! the plate's closed form needs an elliptic integral; the beam's cannot fail
            call check(err, .not. f%failed, 'elliptic integral failed in the reference')
            if (allocated(err)) return
            call check_close(err, row_sum(a), total, 0.0_dp, 1.0e-10_dp*scale, label)
            if (allocated(err)) return
        end do rows
    end subroutine check_row_sums

    !> T symmetric: all 9 base pairs, uniform and graded meshes of 9 elements, G = 3,
    !! nu = 0.1: max |T - T^T| <= 1e-12 max |T|.
    subroutine check_symmetric(s, label, err)
        type(surface_t), intent(in) :: s
        character(len=*), intent(in) :: label
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        integer :: fx, fz, ig
        meshes: do ig = 1, 2
            fam_x: do fx = INTERP_P1, INTERP_S2
                fam_z: do fz = INTERP_P1, INTERP_S2
                    call make_bases(s, 9, trim(gradings(ig)), fx, fz, bx, bz, err)
                    if (allocated(err)) return
                    call assemble(s, bx, bz, 3.0_dp, 0.1_dp, t, err)
                    if (allocated(err)) return
                    call check_close(err, asymmetry(t), 0.0_dp, 0.0_dp, 1.0e-12_dp, label)
                    if (allocated(err)) return
                end do fam_z
            end do fam_x
        end do meshes
    end subroutine check_symmetric

    !> T positive definite (elastic energy): dpotrf succeeds on case i (surface s(i), nes(i)
    !! elements, alternately uniform and graded, four base pairs), G = 1, four nu.
    subroutine check_positive_definite(s, nes, err)
        type(surface_t), intent(in) :: s(:)
        integer, intent(in) :: nes(:)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        integer :: i, inu, info
        real(dp), parameter :: nus(4) = [0.0_dp, 0.1_dp, 0.3_dp, 0.49_dp]
        integer, parameter :: fams(2, 4) = reshape([INTERP_P1, INTERP_P1, INTERP_P2, INTERP_S2, &
            INTERP_S2, INTERP_P2, INTERP_P1, INTERP_S2], [2, 4])
        character(len=60) :: what
        cases: do i = 1, size(nes)
            call make_bases(s(i), nes(i), trim(gradings(2 - mod(i, 2))), fams(1, i), fams(2, i), &
                            bx, bz, err)
            if (allocated(err)) return
            poisson: do inu = 1, size(nus)
                call assemble(s(i), bx, bz, 1.0_dp, nus(inu), t, err)
                if (allocated(err)) return
                call dpotrf('L', size(t, 1), t, size(t, 1), info)
                write (what, '("dpotrf info = ",i0," (case ",i0,", nu = ",f4.2,")")') info, i, &
                    nus(inu)
                call check(err, info == 0, trim(what))
                if (allocated(err)) return
            end do poisson
        end do cases
    end subroutine check_positive_definite

    !> nu_f = 0.5: (1 - 2 nu) = 0, the coupling blocks vanish identically (kernel ref. §0.1).
    subroutine check_incompressible(s, err)
        type(surface_t), intent(in) :: s
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        integer :: nx
        call make_bases(s, 6, 'EDGES', INTERP_P2, INTERP_S2, bx, bz, err)
        if (allocated(err)) return
        call assemble(s, bx, bz, 1.0_dp, 0.5_dp, t, err)
        if (allocated(err)) return
        nx = bx%n_dof
        call check(err, all(t(1:nx, nx + 1:) == 0.0_dp) .and. all(t(nx + 1:, 1:nx) == 0.0_dp), &
                   'coupling blocks not zero for nu_f = 0.5')
    end subroutine check_incompressible

    !> The fixed-order assembly (galerkin_assembly) against the adaptive pair-by-pair reference
    !! (assemble_split_kernel_reference): N_e = 12 and 17, uniform and graded meshes, bases
    !! P1/P1, P2/P2, S2/S2, P2/S2, parameter k the surface s(k) with nu = nus(k); every entry
    !! within 1e-13 of the largest.
    subroutine check_fast_vs_reference(s, g, nus, err)
        type(surface_t), intent(in) :: s(:)
        real(dp), intent(in) :: g, nus(:)
        type(error_t), allocatable, intent(out) :: err
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_ref(:, :)
        integer :: ic, ig, k
        integer, parameter :: fams(2, 4) = reshape([INTERP_P1, INTERP_P1, INTERP_P2, INTERP_P2, &
            INTERP_S2, INTERP_S2, INTERP_P2, INTERP_S2], [2, 4])
        integer, parameter :: nes(4) = [12, 17, 17, 12]
        character(len=80) :: what
        cases: do ic = 1, size(nes)
            meshes: do ig = 1, 2
                call make_bases(s(1), nes(ic), trim(gradings(ig)), fams(1, ic), fams(2, ic), bx, &
                                bz, err)
                if (allocated(err)) return
                parameters: do k = 1, size(s)
                    call assemble(s(k), bx, bz, g, nus(k), t, err)
                    if (allocated(err)) return
                    call assemble(s(k), bx, bz, g, nus(k), t_ref, err, reference=.true.)
                    if (allocated(err)) return
                    write (what, '("fast vs reference, case ",i0,", ",a,", parameter ",i0)') ic, &
                        trim(gradings(ig)), k
                    call check_close(err, maxval(abs(t - t_ref))/maxval(abs(t_ref)), 0.0_dp, &
                                     0.0_dp, 1.0e-13_dp, trim(what))
                    if (allocated(err)) return
                end do parameters
            end do meshes
        end do cases
    end subroutine check_fast_vs_reference

    !> Composite Gauss rule on [a, b] graded geometrically (factor 0.2, 12 levels, 20 points
    !! each) towards both ends, for integrands with end-point singularities.
    subroutine graded_rule(a, b, nodes, weights)
        real(dp), intent(in) :: a, b
        real(dp), allocatable, intent(out) :: nodes(:), weights(:)
        integer, parameter :: levels = 12, n_gl = 20
        real(dp) :: xi(n_gl), wt(n_gl), half, lo, hi
        integer :: side, k, n
        call gauss_legendre(n_gl, xi, wt)
        allocate (nodes(2*(levels + 1)*n_gl), weights(2*(levels + 1)*n_gl))
        half = 0.5_dp*(b - a)
        n = 0
        sides: do side = 1, 2
            levels_loop: do k = 0, levels
                hi = half*0.2_dp**k
                lo = merge(0.0_dp, half*0.2_dp**(k + 1), k == levels)
                if (side == 1) then
                    nodes(n + 1:n + n_gl) = a + lo + 0.5_dp*(xi + 1.0_dp)*(hi - lo)
                else
                    nodes(n + 1:n + n_gl) = b - lo - 0.5_dp*(xi + 1.0_dp)*(hi - lo)
                end if
                weights(n + 1:n + n_gl) = 0.5_dp*(hi - lo)*wt
                n = n + n_gl
            end do levels_loop
        end do sides
    end subroutine graded_rule

    !> Value of basis function `dof` at x on element e (0 if not supported there).
    pure real(dp) function basis_value(basis, e, dof, x)
        type(basis_t), intent(in) :: basis
        integer, intent(in) :: e, dof
        real(dp), intent(in) :: x
        integer :: idx(max_local), i
        real(dp) :: val(max_local), der(max_local), x_out
        call eval_basis(basis, e, (2.0_dp*x - basis%x(e - 1) - basis%x(e))/ &
                        (basis%x(e) - basis%x(e - 1)), idx, val, der, x_out)
        basis_value = 0.0_dp
        do i = 1, basis%n_local
            if (idx(i) == dof) basis_value = val(i)
        end do
    end function basis_value
end module halfspace_test_support
