!> Tests of layered_compliance and layered_influence: the surface compliances of layered ground
!! per wavenumber and the Galerkin flexibility T = T_hs(top layer) + T_corr (SPEC §3a).
!!
!! Where the expected numbers come from:
!!  * one layer (h, G, nu) bonded to a rigid base, derived here from the Navier equations in
!!    a layer (kernel reference §0.1 conventions, the four free constants fixed by u = 0 at
!!    z = h and the surface tractions), t = s h, kappa = 3 - 4 nu:
!!        C_zz = (1-nu)/(G s) F(t),  F(t) = [kappa sinh 2t - 2t]/[kappa cosh 2t + 2t^2
!!               + (1-2nu)^2 + 4(1-nu)^2],
!!    normalised so that F -> 1 as t -> oo (the half-space) and F -> t (1-2nu)/(2(1-nu)^2) as
!!    t -> 0, i.e. C_zz -> h/M with the oedometric modulus M = 2G(1-nu)/(1-2nu) (checked by
!!    expanding: kappa - 1 = 2(1-2nu), kappa + (1-2nu)^2 + 4(1-nu)^2 = 8(1-nu)^2);
!!    antiplane: G U'' = G s^2 U, U(h) = 0, G U'(0) = -q gives C_SH = tanh(t)/(G s);
!!  * thin layer: simple shear C_hh, C_SH -> h/G, oedometer C_zz -> h/M;
!!  * the homogeneous half-space: C_zz = C_hh = (1-nu)/(G s), C_zh = (1-2nu)/(2 G s),
!!    C_SH = 1/(G s) (kernel reference (0.1)), and its T from halfspace_beam/halfspace_plate;
!!  * Gibson (1967): incompressible soil with G = m z is a Winkler bed, w = q/(2m) under any
!!    load, i.e. C_zz = 1/(2m) at every wavenumber;
!!  * the rigid frictionless punch on a layer: an independent Nystrom solution of the
!!    Fredholm equation of the second kind of the dual integral equations (Lebedev & Ufliand
!!    1958; Sneddon's method), built here from the compliance alone (no basis, no T);
!!  * the table of J0 and J1 of the plate's Hankel transforms (layered_bessel): Fortran's
!!    intrinsic bessel_j0 / bessel_j1;
!!  * surface displacements under two uniform circles on two layers over a half-space: the
!!    program ELLEA1 (Levenberg 2016, "ELLEA1: Isotropic layered elasticity in Excel"), as
!!    published in the validation data of ALVA (Skar, Andersen & Nielsen 2020, repository
!!    github.com/asmusskar/ALVA, commit 258c6ad: validation/validation_let.m, table
!!    'duallength', the case of examples/ALVA_let_validation3.m), printed to 1e-4 mm.
module test_layered_ground
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, check, check_close, error_t
    use quadrature, only: gauss_legendre
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, eval_basis, max_local, INTERP_P1, &
                               INTERP_P2, INTERP_S2
    use lapack_interfaces, only: dpotrf, dgesv
    use halfspace_plate, only: assemble_plate_flexibility, plate_surface_displacement
    use halfspace_beam, only: assemble_beam_flexibility, beam_surface_displacement
    use layered_compliance, only: layered_ground_t, new_layered_ground, surface_compliance, &
                                  compliance_correction, BASE_ROUGH, BASE_SMOOTH, &
                                  BASE_HALFSPACE
    use layered_influence, only: assemble_layered_flexibility, layered_correction, &
                                 layered_surface_displacement
    use layered_bessel, only: bessel_table_t, new_bessel_table, bessel_table_pair
    implicit none
    private
    public :: collect_layered_ground, punch_nystrom

contains

    subroutine collect_layered_ground(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('one_layer_rough_base_closed_form', test_one_layer), &
                 new_unittest('thin_layer_oedometer_and_shear', test_thin_layer_compliance), &
                 new_unittest('identical_layers_are_the_halfspace', test_identical_compliance), &
                 new_unittest('gibson_winkler_compliance', test_gibson_compliance), &
                 new_unittest('identical_layers_reproduce_t', test_identical_t), &
                 new_unittest('thin_top_layer_gives_base_t', test_thin_top_layer), &
                 new_unittest('deep_rough_base_gives_halfspace_t', test_deep_base), &
                 new_unittest('uniform_load_on_thin_layer_oedometer', test_oedometer_plate), &
                 new_unittest('gibson_uniform_load_plate', test_gibson_plate), &
                 new_unittest('rigid_punch_vs_nystrom', test_punch_nystrom), &
                 new_unittest('quadrature_converged', test_quadrature_converged), &
                 new_unittest('symmetric_positive_definite', test_spd), &
                 new_unittest('linear_modulus_sublayers', test_linear_modulus), &
                 new_unittest('displacements_consistent_with_t', test_displacement_vs_t), &
                 new_unittest('no_far_field_over_rock', test_no_far_field), &
                 new_unittest('bad_grounds_refused', test_bad_grounds), &
                 new_unittest('bessel_table', test_bessel_table), &
                 new_unittest('ellea1_two_circles_surface_profile', test_ellea1_profile)]
    end subroutine collect_layered_ground

    ! ------------------------------------------------------------------ helpers

    !> Bases of one family pair on a mesh of [x0, x1].
    subroutine make_bases(x0, x1, ne, grading, fam_x, fam_z, bx, bz, err)
        real(dp), intent(in) :: x0, x1
        integer, intent(in) :: ne, fam_x, fam_z
        character(len=*), intent(in) :: grading
        type(basis_t), intent(out) :: bx, bz
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        call new_mesh(msh, x0, x1, ne, grading, err, [x0 + 0.3_dp*(x1 - x0)])
        if (allocated(err)) return
        call new_basis(bx, msh, fam_x)
        call new_basis(bz, msh, fam_z)
    end subroutine make_bases

    !> One constant layer over a base.
    subroutine one_layer(h, e, nu, base, e_b, nu_b, ground, err)
        real(dp), intent(in) :: h, e, nu, e_b, nu_b
        integer, intent(in) :: base
        type(layered_ground_t), intent(out) :: ground
        type(error_t), allocatable, intent(out) :: err
        call new_layered_ground(ground, [h], [e], [e], [nu], base, e_b, nu_b, err)
    end subroutine one_layer

    !> max |a - b| / max |b|.
    pure real(dp) function rel_diff(a, b)
        real(dp), intent(in) :: a(:, :), b(:, :)
        rel_diff = maxval(abs(a - b))/maxval(abs(b))
    end function rel_diff

    !> Gibson's profile G = m z (nu = 0.5) to depth d as sublayers growing by the factor q
    !! from a top sublayer of thickness delta, each with G at its mid-depth, on a rough base.
    subroutine gibson_ground(m, delta, q, d, ground, err)
        real(dp), intent(in) :: m, delta, q, d
        type(layered_ground_t), intent(out) :: ground
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: z(:), e(:)
        integer :: n
        z = [0.0_dp, delta]
        grow: do while (z(size(z)) < d)
            z = [z, z(size(z))*q]
        end do grow
        n = size(z) - 1
        e = 3.0_dp*m*0.5_dp*(z(2:) + z(1:n))      ! E = 2 G (1 + nu) = 3 G
        call new_layered_ground(ground, z(2:) - z(1:n), e, e, [(0.5_dp, n = 1, size(e))], &
                                BASE_ROUGH, 0.0_dp, 0.0_dp, err)
    end subroutine gibson_ground

    !> Plate: f_a = int g_a 2 pi r dr (load vector of a unit uniform traction) and the mass
    !! matrix M_ab = int g_a g_b 2 pi r dr, exact by 4-point Gauss (degree <= 5).
    subroutine plate_mass(basis, f, mass)
        type(basis_t), intent(in) :: basis
        real(dp), allocatable, intent(out) :: f(:), mass(:, :)
        real(dp) :: xi(4), w(4), val(max_local), der(max_local), x, wt
        integer :: e, q, i, j, idx(max_local)
        call gauss_legendre(4, xi, w)
        allocate (f(basis%n_dof), source=0.0_dp)
        allocate (mass(basis%n_dof, basis%n_dof), source=0.0_dp)
        elements: do e = 1, basis%ne
            points: do q = 1, 4
                call eval_basis(basis, e, xi(q), idx, val, der, x)
                wt = 0.5_dp*(basis%x(e) - basis%x(e - 1))*w(q)*2.0_dp*pi*x
                do i = 1, basis%n_local
                    f(idx(i)) = f(idx(i)) + wt*val(i)
                    do j = 1, basis%n_local
                        mass(idx(i), idx(j)) = mass(idx(i), idx(j)) + wt*val(i)*val(j)
                    end do
                end do
            end do points
        end do elements
    end subroutine plate_mass

    !> Solve a x = b (a copied), info checked.
    subroutine solve(a, b, x, err)
        real(dp), intent(in) :: a(:, :), b(:)
        real(dp), allocatable, intent(out) :: x(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: lu(size(a, 1), size(a, 2)), rhs(size(b), 1)
        integer :: ipiv(size(b)), info
        lu = a
        rhs(:, 1) = b
        call dgesv(size(b), 1, lu, size(b), ipiv, rhs, size(b), info)
        call check(err, info == 0, 'dgesv failed')
        x = rhs(:, 1)
    end subroutine solve

    !> sinh x - x, by its series below x = 1.
    pure real(dp) function sinh_minus_x(x) result(total)
        real(dp), intent(in) :: x
        real(dp) :: term
        integer :: n
        if (x >= 1.0_dp) then
            total = sinh(x) - x
            return
        end if
        term = x
        total = 0.0_dp
        do n = 1, 12
            term = term*x*x/real((2*n)*(2*n + 1), dp)
            total = total + term
        end do
    end function sinh_minus_x

    ! ------------------------------------------------------------------ compliance

    !> C_zz = (1-nu)/(G s) F(s h) and C_SH = tanh(s h)/(G s) (module header), 1e-12.
    subroutine test_one_layer(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        real(dp), parameter :: nus(3) = [0.0_dp, 0.3_dp, 0.5_dp], h = 1.7_dp
        real(dp) :: s(1), c_zz(1), c_zh(1), c_hh(1), c_sh(1), g, t, kappa, f, nu
        integer :: i, k
        character(len=60) :: what
        poisson: do i = 1, size(nus)
            nu = nus(i)
            call one_layer(h, 2.6_dp, nu, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
            if (allocated(err)) return
            g = 2.6_dp/(2.0_dp*(1.0_dp + nu))
            kappa = 3.0_dp - 4.0_dp*nu
            wavenumbers: do k = -16, 14
                t = 10.0_dp**(real(k, dp)/4.0_dp)          ! 1e-4 .. 3162 (half-space regime)
                s(1) = t/h
                call surface_compliance(ground, s, c_zz, c_zh, c_hh, c_sh)
                ! numerator as (kappa - 1) 2t + kappa (sinh 2t - 2t), the bracket by its
                ! series below 2t = 1 (no cancellation when kappa = 1, nu = 0.5)
                f = ((kappa - 1.0_dp)*2.0_dp*t + kappa*sinh_minus_x(2.0_dp*min(t, 300.0_dp)))/ &
                    (kappa*cosh(2.0_dp*min(t, 300.0_dp)) + 2.0_dp*t*t + &
                     (1.0_dp - 2.0_dp*nu)**2 + 4.0_dp*(1.0_dp - nu)**2)
                write (what, '("C_zz, nu = ",f3.1,", t = ",es9.2)') nu, t
                call check_close(err, c_zz(1), (1.0_dp - nu)/(g*s(1))*f, 1.0e-12_dp, 0.0_dp, &
                                 trim(what))
                if (allocated(err)) return
                write (what, '("C_SH, nu = ",f3.1,", t = ",es9.2)') nu, t
                call check_close(err, c_sh(1), tanh(t)/(g*s(1)), 1.0e-12_dp, 0.0_dp, trim(what))
                if (allocated(err)) return
            end do wavenumbers
        end do poisson
    end subroutine test_one_layer

    !> s h = 1e-4 on a rough base: C_zz = h/M, C_hh = C_SH = h/G, C_zh = O(s h^2): to the
    !! O(t^2) = 1e-8 of the expansion.
    subroutine test_thin_layer_compliance(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        real(dp), parameter :: h = 0.8_dp, e = 5.0_dp, nu = 0.35_dp
        real(dp) :: s(1), c_zz(1), c_zh(1), c_hh(1), c_sh(1), g, oedometric
        call one_layer(h, e, nu, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        g = e/(2.0_dp*(1.0_dp + nu))
        oedometric = 2.0_dp*g*(1.0_dp - nu)/(1.0_dp - 2.0_dp*nu)
        s(1) = 1.0e-4_dp/h
        call surface_compliance(ground, s, c_zz, c_zh, c_hh, c_sh)
        call check_close(err, c_zz(1), h/oedometric, 1.0e-7_dp, 0.0_dp, 'C_zz = h/M')
        if (allocated(err)) return
        call check_close(err, c_hh(1), h/g, 1.0e-7_dp, 0.0_dp, 'C_hh = h/G')
        if (allocated(err)) return
        call check_close(err, c_sh(1), h/g, 1.0e-7_dp, 0.0_dp, 'C_SH = h/G')
        if (allocated(err)) return
        call check(err, abs(c_zh(1)) < 1.0e-3_dp*h/g, 'C_zh not small in a thin bonded layer')
    end subroutine test_thin_layer_compliance

    !> Layers of one material over a half-space of the same: the half-space compliances to
    !! round-off at every wavenumber, nu = 0, 0.25, 0.5 (module header).
    subroutine test_identical_compliance(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        real(dp), parameter :: nus(3) = [0.0_dp, 0.25_dp, 0.5_dp], e = 3.0_dp
        real(dp) :: s(9), c_zz(9), c_zh(9), c_hh(9), c_sh(9), g, nu, expect(4), got(4)
        integer :: i, k, j
        s = [1.0e-6_dp, 1.0e-3_dp, 0.1_dp, 0.7_dp, 2.0_dp, 9.0_dp, 30.0_dp, 1.0e3_dp, 1.0e6_dp]
        poisson: do i = 1, size(nus)
            nu = nus(i)
            call new_layered_ground(ground, [0.2_dp, 1.0_dp, 3.0_dp, 0.05_dp], [e, e, e, e], &
                                    [e, e, e, e], [nu, nu, nu, nu], BASE_HALFSPACE, e, nu, err)
            if (allocated(err)) return
            g = e/(2.0_dp*(1.0_dp + nu))
            call surface_compliance(ground, s, c_zz, c_zh, c_hh, c_sh)
            wavenumbers: do k = 1, size(s)
                expect = [1.0_dp - nu, 0.5_dp*(1.0_dp - 2.0_dp*nu), 1.0_dp - nu, 1.0_dp]/g
                got = s(k)*[c_zz(k), c_zh(k), c_hh(k), c_sh(k)]
                do j = 1, 4
                    call check_close(err, got(j), expect(j), 1.0e-14_dp, 1.0e-15_dp/g, &
                                     's C of identical layers')
                    if (allocated(err)) return
                end do
            end do wavenumbers
        end do poisson
    end subroutine test_identical_compliance

    !> Gibson's G = m z (nu = 0.5) by sublayers (ratio q, G at mid-depth) from 1e-3 to 200 on a
    !! rough base: 2 m C_zz = 1 for 0.1 <= s <= 10 (away from the base, 1/s << 200, and from
    !! the top sublayer, s << 1/1e-3); the sublayers are a midpoint rule of second order in
    !! q - 1 (the error must fall 4 times when q - 1 halves), 5e-5 at q = 1.02.
    subroutine test_gibson_compliance(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        real(dp), parameter :: m = 1.0_dp
        real(dp) :: s(5), c_zz(5), c_zh(5), c_hh(5), c_sh(5), dev(2)
        integer :: i
        s = [0.1_dp, 0.3_dp, 1.0_dp, 3.0_dp, 10.0_dp]
        ratios: do i = 1, 2
            call gibson_ground(m, 1.0e-3_dp, 1.0_dp + 0.04_dp/real(i, dp), 200.0_dp, ground, err)
            if (allocated(err)) return
            call surface_compliance(ground, s, c_zz, c_zh, c_hh, c_sh)
            dev(i) = maxval(abs(2.0_dp*m*c_zz - 1.0_dp))
        end do ratios
        call check(err, dev(2) < 1.0e-4_dp, 'Gibson: 2 m C_zz /= 1 at q = 1.02')
        if (allocated(err)) return
        call check(err, dev(1)/dev(2) > 3.5_dp .and. dev(1)/dev(2) < 4.5_dp, &
                   'Gibson: sublayering not of second order')
    end subroutine test_gibson_compliance

    ! ------------------------------------------------------------------ T

    !> Identical layers over the same half-space: T equals today's T (halfspace_beam /
    !! halfspace_plate with the same G, nu) to 1e-10 of its largest entry.
    subroutine test_identical_t(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t_lay(:, :), t_hs(:, :)
        real(dp), parameter :: e = 2.0_dp, nus(2) = [0.3_dp, 0.5_dp]
        integer, parameter :: fams(3) = [INTERP_P1, INTERP_P2, INTERP_S2]
        integer :: i, j
        character(len=60) :: what
        poisson: do j = 1, 2
            call new_layered_ground(ground, [0.3_dp, 0.5_dp, 1.0_dp], [e, e, e], [e, e, e], &
                                    [nus(j), nus(j), nus(j)], BASE_HALFSPACE, e, nus(j), err)
            if (allocated(err)) return
            families: do i = 1, 3
                call make_bases(0.0_dp, 1.0_dp, 12, 'EDGES', fams(i), fams(i), bx, bz, err)
                if (allocated(err)) return
                call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t_lay, err)
                if (allocated(err)) return
                call assemble_plate_flexibility(bx, bz, e/(2.0_dp*(1.0_dp + nus(j))), nus(j), &
                                                t_hs, err)
                if (allocated(err)) return
                write (what, '("plate, family ",i0,", nu ",f3.1)') fams(i), nus(j)
                call check_close(err, rel_diff(t_lay, t_hs), 0.0_dp, 0.0_dp, 1.0e-10_dp, trim(what))
                if (allocated(err)) return
                call make_bases(-1.0_dp, 1.0_dp, 12, 'UNIFORM', fams(i), fams(i), bx, bz, err)
                if (allocated(err)) return
                call assemble_layered_flexibility(bx, bz, .true., 0.4_dp, ground, t_lay, err)
                if (allocated(err)) return
                call assemble_beam_flexibility(bx, bz, e/(2.0_dp*(1.0_dp + nus(j))), nus(j), &
                                               0.4_dp, t_hs, err)
                if (allocated(err)) return
                write (what, '("beam, family ",i0,", nu ",f3.1)') fams(i), nus(j)
                call check_close(err, rel_diff(t_lay, t_hs), 0.0_dp, 0.0_dp, 1.0e-10_dp, trim(what))
                if (allocated(err)) return
            end do families
        end do poisson
    end subroutine test_identical_t

    !> A thin incompressible top layer (no coupling in its own T_hs) over a half-space with
    !! nu_b = 0.2 and another modulus: T -> T_hs(base) as h -> 0 in all four blocks, the
    !! couplings coming from T_corr alone. The distance falls like h ln(1/h) (the layer
    !! changes the logarithmic kernel within h of each point): 1.35 to 2.5 times per halving
    !! at these h (h ln(1/h) alone gives 1.6 to 1.7), below 20 % at h = l/100. A wrong sign or
    !! normalisation of any block of the beam's or the plate's correction leaves an O(1)
    !! distance.
    subroutine test_thin_top_layer(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_hs(:, :)
        real(dp), parameter :: e_b = 1.6_dp, nu_b = 0.2_dp, width = 0.3_dp
        real(dp) :: g_b, d(3), d_couple(3)
        integer :: structure, nx, i, n_h
        character(len=100) :: what
        g_b = e_b/(2.0_dp*(1.0_dp + nu_b))
        structures: do structure = 1, 2
            if (structure == 1) then
                call make_bases(0.0_dp, 1.0_dp, 8, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
                if (allocated(err)) return
                call assemble_plate_flexibility(bx, bz, g_b, nu_b, t_hs, err)
                n_h = 3
            else
                call make_bases(-1.0_dp, 1.0_dp, 8, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
                if (allocated(err)) return
                call assemble_beam_flexibility(bx, bz, g_b, nu_b, width, t_hs, err)
                n_h = 2
            end if
            if (allocated(err)) return
            nx = bx%n_dof
            thicknesses: do i = 1, n_h
                call one_layer(0.04_dp/2.0_dp**(i - 1), 1.0_dp, 0.5_dp, BASE_HALFSPACE, e_b, &
                               nu_b, ground, err)
                if (allocated(err)) return
                call assemble_layered_flexibility(bx, bz, structure == 2, width, ground, t, err)
                if (allocated(err)) return
                d(i) = rel_diff(t, t_hs)
                d_couple(i) = rel_diff(t(nx + 1:, 1:nx), t_hs(nx + 1:, 1:nx))
            end do thicknesses
            write (what, '("structure ",i0,": distances ",3es9.2)') structure, d(1:n_h)
            write (what, '(a,", couplings ",3es9.2)') trim(what), d_couple(1:n_h)
            call check(err, all(d(1:n_h - 1)/d(2:n_h) > 1.35_dp) .and. &
                       all(d(1:n_h - 1)/d(2:n_h) < 2.5_dp) .and. &
                       all(d_couple(1:n_h - 1)/d_couple(2:n_h) > 1.35_dp) .and. &
                       all(d_couple(1:n_h - 1)/d_couple(2:n_h) < 2.5_dp) .and. &
                       d(n_h) < 0.2_dp, trim(what))
            if (allocated(err)) return
        end do structures
    end subroutine test_thin_top_layer

    !> A rough rigid base ever deeper (H = 10, 20, 40 a): T -> T_hs; its influence falls like
    !! 1/H (the far field of a rigid boundary; ratio 1.6 to 2.4 per doubling), below 5 % at
    !! H = 40 a.
    subroutine test_deep_base(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_hs(:, :)
        real(dp) :: d(3)
        integer :: i
        character(len=80) :: what
        call make_bases(0.0_dp, 1.0_dp, 8, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call assemble_plate_flexibility(bx, bz, 1.0_dp/2.6_dp, 0.3_dp, t_hs, err)
        if (allocated(err)) return
        depths: do i = 1, 3
            call one_layer(10.0_dp*2.0_dp**(i - 1), 1.0_dp, 0.3_dp, BASE_ROUGH, 0.0_dp, 0.0_dp, &
                           ground, err)
            if (allocated(err)) return
            call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t, err)
            if (allocated(err)) return
            d(i) = rel_diff(t, t_hs)
        end do depths
        write (what, '("distances ",3es9.2)') d
        call check(err, d(1)/d(2) > 1.6_dp .and. d(1)/d(2) < 2.4_dp .and. &
                   d(2)/d(3) > 1.6_dp .and. d(2)/d(3) < 2.4_dp .and. d(3) < 0.05_dp, trim(what))
    end subroutine test_deep_base

    !> Uniform pressure p on a plate of radius a over a thin layer (H = a/20) bonded to rock:
    !! far from the rim the layer is an oedometer, w(0) = p H/M. w from T by the Galerkin
    !! projection (mass matrix); the rim's disturbance at the centre is below exp(-pi a/H).
    subroutine test_oedometer_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), f(:), mass(:, :), w(:), rhs(:)
        real(dp), parameter :: h = 0.05_dp, e = 1.0_dp, nu = 0.3_dp, p = 1.0_dp
        real(dp) :: oedometric
        integer :: nx
        call make_bases(0.0_dp, 1.0_dp, 20, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call one_layer(h, e, nu, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t, err)
        if (allocated(err)) return
        nx = bx%n_dof
        call plate_mass(bz, f, mass)
        rhs = matmul(t(nx + 1:, nx + 1:), [(p, nx = 1, bz%n_dof)])
        call solve(mass, rhs, w, err)
        if (allocated(err)) return
        oedometric = e*(1.0_dp - nu)/((1.0_dp + nu)*(1.0_dp - 2.0_dp*nu))
        call check_close(err, w(1), p*h/oedometric, 1.0e-6_dp, 0.0_dp, 'w(0) = p H/M')
    end subroutine test_oedometer_plate

    !> Gibson soil (m = 1, sublayers from 0.01 a, ratio 1.02, to 40 a) under a uniform load on
    !! a plate of radius a: w(0) = q/(2m) (Winkler), to 1 %: the sublayers' 5e-5, the base at
    !! 40 a (a^2/D^2 ~ 6e-4) and the top sublayer (0.01 a) under the load's wavenumbers ~1/a.
    subroutine test_gibson_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), f(:), mass(:, :), w(:), rhs(:)
        integer :: nx, k
        call make_bases(0.0_dp, 1.0_dp, 16, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call gibson_ground(1.0_dp, 0.01_dp, 1.02_dp, 40.0_dp, ground, err)
        if (allocated(err)) return
        call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t, err)
        if (allocated(err)) return
        nx = bx%n_dof
        call plate_mass(bz, f, mass)
        rhs = matmul(t(nx + 1:, nx + 1:), [(1.0_dp, k = 1, bz%n_dof)])
        call solve(mass, rhs, w, err)
        if (allocated(err)) return
        call check_close(err, w(1), 0.5_dp, 1.0e-2_dp, 0.0_dp, 'Gibson w(0) = q/(2m)')
    end subroutine test_gibson_plate

    !> Rigid frictionless punch (radius a = 1) on a layer H = a on a rough base, nu = 0.3 and
    !! 0.5: the load ratio P_layer/P_hs at equal settlement from T_zz (P = f^T T_zz^(-1) f,
    !! same EDGES mesh for both, so that the edge singularity's discretisation error cancels;
    !! the ratio moves by 4e-5 from N_e = 48 to 96) vs the Nystrom solution of
    !! theta(t) + (1/pi) int_0^1 [k(t-u) + k(t+u)] theta(u) du = 1,
    !! k(x) = int_0^oo (F(s) - 1) cos(s x) ds, F - 1 = G phi_zz/(1-nu), P/P_hs = int_0^1 theta
    !! (Sneddon's representation of the pressure; half-space: theta = 1, P = 4 G a w/(1-nu)).
    !! For nu = 0.5 the ratio is 3.62, 1.59 times the textbook fit 1 + 1.28 a/H.
    subroutine test_punch_nystrom(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: nus(2) = [0.3_dp, 0.5_dp]
        real(dp) :: ratio_nystrom, ratio_t
        integer :: i
        character(len=40) :: what
        poisson: do i = 1, 2
            call punch_nystrom(nus(i), ratio_nystrom, err)
            if (allocated(err)) return
            call punch_galerkin(nus(i), ratio_t, err)
            if (allocated(err)) return
            write (what, '("P_layer/P_hs, nu = ",f3.1)') nus(i)
            call check_close(err, ratio_t, ratio_nystrom, 2.0e-4_dp, 0.0_dp, trim(what))
            if (allocated(err)) return
        end do poisson
    end subroutine test_punch_nystrom

    subroutine punch_nystrom(nu, ratio, err)
        real(dp), intent(in) :: nu
        real(dp), intent(out) :: ratio
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: n = 40, n_panels = 300, n_gl = 20
        type(layered_ground_t) :: ground
        real(dp) :: t(n), wt(n), a(n, n), rhs(n, 1), xi(n_gl), w_gl(n_gl), g
        real(dp), allocatable :: s(:), ws(:), phi(:, :)
        integer :: i, j, p, ipiv(n), info
        g = 1.0_dp/(2.0_dp*(1.0_dp + nu))
        call one_layer(1.0_dp, 1.0_dp, nu, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        ! s in [0, 40] (phi ~ exp(-2 s)), panels of 40/300 with 20 points
        call gauss_legendre(n_gl, xi, w_gl)
        allocate (s(n_panels*n_gl), ws(n_panels*n_gl), phi(n_panels*n_gl, 4))
        do p = 1, n_panels
            s((p - 1)*n_gl + 1:p*n_gl) = (real(p - 1, dp) + 0.5_dp*(xi + 1.0_dp))*40.0_dp/n_panels
            ws((p - 1)*n_gl + 1:p*n_gl) = 0.5_dp*w_gl*40.0_dp/n_panels
        end do
        call compliance_correction(ground, s, phi)
        ws = ws*phi(:, 1)*g/(1.0_dp - nu)
        call gauss_legendre(n, t, wt)
        t = 0.5_dp*(t + 1.0_dp)
        wt = 0.5_dp*wt
        do j = 1, n
            do i = 1, n
                a(i, j) = wt(j)/pi*(sum(ws*cos(s*(t(i) - t(j)))) + sum(ws*cos(s*(t(i) + t(j)))))
            end do
            a(j, j) = a(j, j) + 1.0_dp
        end do
        rhs = 1.0_dp
        call dgesv(n, 1, a, n, ipiv, rhs, n, info)
        call check(err, info == 0, 'Nystrom system singular')
        if (allocated(err)) return
        ratio = sum(wt*rhs(:, 1))
    end subroutine punch_nystrom

    subroutine punch_galerkin(nu, ratio, err)
        real(dp), intent(in) :: nu
        real(dp), intent(out) :: ratio
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), t_hs(:, :), f(:), mass(:, :), x(:)
        real(dp) :: p_layer, p_hs
        integer :: nx
        call make_bases(0.0_dp, 1.0_dp, 48, 'EDGES', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call one_layer(1.0_dp, 1.0_dp, nu, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t, err)
        if (allocated(err)) return
        call assemble_plate_flexibility(bx, bz, 1.0_dp/(2.0_dp*(1.0_dp + nu)), nu, t_hs, err)
        if (allocated(err)) return
        nx = bx%n_dof
        call plate_mass(bz, f, mass)
        call solve(t(nx + 1:, nx + 1:), f, x, err)
        if (allocated(err)) return
        p_layer = dot_product(f, x)
        call solve(t_hs(nx + 1:, nx + 1:), f, x, err)
        if (allocated(err)) return
        p_hs = dot_product(f, x)
        ratio = p_layer/p_hs
    end subroutine punch_galerkin

    !> The correction with every panel and element rule twice as fine agrees to 1e-13 of the
    !! largest entry of T (plate and beam, three layers with a contrast of 100, rough base).
    subroutine test_quadrature_converged(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :), c1(:, :), c2(:, :)
        integer :: structure
        character(len=40) :: what
        call new_layered_ground(ground, [0.4_dp, 0.6_dp, 1.5_dp], [1.0_dp, 100.0_dp, 3.0_dp], &
                                [1.0_dp, 100.0_dp, 3.0_dp], [0.3_dp, 0.45_dp, 0.2_dp], &
                                BASE_ROUGH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) return
        structures: do structure = 1, 2
            if (structure == 1) then
                call make_bases(0.0_dp, 1.0_dp, 10, 'EDGES', INTERP_P2, INTERP_S2, bx, bz, err)
            else
                call make_bases(-1.0_dp, 1.0_dp, 10, 'EDGES', INTERP_P2, INTERP_S2, bx, bz, err)
            end if
            if (allocated(err)) return
            call assemble_layered_flexibility(bx, bz, structure == 2, 0.5_dp, ground, t, err)
            if (allocated(err)) return
            call layered_correction(bx, bz, structure == 2, 0.5_dp, ground, c1, err)
            if (allocated(err)) return
            call layered_correction(bx, bz, structure == 2, 0.5_dp, ground, c2, err, refine=2.0_dp)
            if (allocated(err)) return
            write (what, '("structure ",i0)') structure
            call check_close(err, maxval(abs(c1 - c2))/maxval(abs(t)), 0.0_dp, 0.0_dp, &
                             1.0e-13_dp, trim(what))
            if (allocated(err)) return
        end do structures
    end subroutine test_quadrature_converged

    !> T symmetric and positive definite (dpotrf) on P1, P2, S2 x UNIFORM, EDGES, LOADS, beam
    !! and plate, for soft-over-stiff and stiff-over-soft grounds (contrast 1e4) on each base.
    subroutine test_spd(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: grounds(3)
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        integer, parameter :: fams(3) = [INTERP_P1, INTERP_P2, INTERP_S2]
        character(len=7), parameter :: gradings(3) = ['UNIFORM', 'EDGES  ', 'LOADS  ']
        integer :: i, ig, structure, info
        character(len=80) :: what
        call new_layered_ground(grounds(1), [0.5_dp, 1.0_dp], [1.0_dp, 1.0e4_dp], &
                                [1.0_dp, 1.0e4_dp], [0.3_dp, 0.5_dp], BASE_ROUGH, 0.0_dp, &
                                0.0_dp, err)
        if (allocated(err)) return
        call new_layered_ground(grounds(2), [0.3_dp, 2.0_dp], [1.0e4_dp, 1.0_dp], &
                                [1.0e4_dp, 1.0_dp], [0.2_dp, 0.45_dp], BASE_HALFSPACE, 5.0_dp, &
                                0.3_dp, err)
        if (allocated(err)) return
        call new_layered_ground(grounds(3), [0.6_dp], [1.0_dp], [1.5_dp], [0.5_dp], &
                                BASE_SMOOTH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) return
        cases: do i = 1, 3
            structures: do structure = 1, 2
                if (structure == 1) then
                    call make_bases(0.0_dp, 1.0_dp, 9, trim(gradings(i)), fams(i), &
                                    fams(mod(i, 3) + 1), bx, bz, err)
                else
                    call make_bases(-1.0_dp, 1.0_dp, 9, trim(gradings(i)), fams(i), fams(i), &
                                    bx, bz, err)
                end if
                if (allocated(err)) return
                ground_loop: do ig = 1, 3
                    if (structure == 2 .and. ig == 3) cycle ground_loop  ! smooth: refused
                    call assemble_layered_flexibility(bx, bz, structure == 2, 0.3_dp, &
                                                      grounds(ig), t, err)
                    if (allocated(err)) return
                    write (what, '("case ",i0,", structure ",i0,", ground ",i0)') i, &
                        structure, ig
                    call check(err, maxval(abs(t - transpose(t))) <= 1.0e-14_dp*maxval(abs(t)), &
                               'not symmetric: '//trim(what))
                    if (allocated(err)) return
                    call dpotrf('L', size(t, 1), t, size(t, 1), info)
                    call check(err, info == 0, 'not positive definite: '//trim(what))
                    if (allocated(err)) return
                end do ground_loop
            end do structures
        end do cases
    end subroutine test_spd

    !> A layer with E linear in depth (card E_top, E_bottom) is resolved into sublayers: 5 %
    !! steps, the total thickness kept, a constant layer stays one layer; the compliance of
    !! the sublayered profile against one with 1/8 of its steps (160 sublayers; the midpoint
    !! rule of second order, so that the reference is 64 times closer to the continuous
    !! profile) differs by about 0.12 (5 %)^2 = 3e-4 (Gibson's case above): below 1e-3.
    subroutine test_linear_modulus(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground, fine
        real(dp) :: s(4), c(4, 4), c_fine(4, 4), z(161), e(160)
        integer :: i
        call new_layered_ground(ground, [2.0_dp, 3.0_dp], [10.0_dp, 20.0_dp], [10.0_dp, 40.0_dp], &
                                [0.3_dp, 0.4_dp], BASE_ROUGH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) return
        call check(err, size(ground%thickness) == 1 + ceiling(log(2.0_dp)/log(1.05_dp)) .and. &
                   abs(sum(ground%thickness) - 5.0_dp) < 1.0e-13_dp .and. &
                   ground%card(1) == 1 .and. ground%card(2) == 2, 'sublayer count or depth')
        if (allocated(err)) return
        ! the reference: 160 sublayers of equal E ratio with the log mean of E in each
        z(1) = 0.0_dp
        do i = 1, 160
            e(i) = 20.0_dp*2.0_dp**(real(i - 1, dp)/160.0_dp)
            z(i + 1) = (20.0_dp*2.0_dp**(real(i, dp)/160.0_dp) - 20.0_dp)/(20.0_dp/3.0_dp)
            e(i) = (20.0_dp*2.0_dp**(real(i, dp)/160.0_dp) - e(i))/log(2.0_dp**(1.0_dp/160.0_dp))
        end do
        call new_layered_ground(fine, [2.0_dp, z(2:) - z(1:160)], [10.0_dp, e], [10.0_dp, e], &
                                [0.3_dp, [(0.4_dp, i = 1, 160)]], BASE_ROUGH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) return
        s = [0.05_dp, 0.3_dp, 1.0_dp, 3.0_dp]
        call surface_compliance(ground, s, c(:, 1), c(:, 2), c(:, 3), c(:, 4))
        call surface_compliance(fine, s, c_fine(:, 1), c_fine(:, 2), c_fine(:, 3), c_fine(:, 4))
        call check(err, maxval(abs(c - c_fine)/abs(c_fine)) < 1.0e-3_dp, &
                   'sublayered linear modulus off its refined value')
    end subroutine test_linear_modulus

    !> The displacement correction u - u_hs(top) at points, projected on the basis
    !! (int g_a du W dx by 16-point Gauss per element: du is analytic), equals T_corr r: the
    !! same integrals taken the other way round (kernel at points vs transforms of both
    !! functions), to 1e-11 of max |T_corr r|; plate and beam, tractions in both fields.
    subroutine test_displacement_vs_t(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: c(:, :), r(:), x(:), wq(:), u_h(:), u_z(:), v_h(:), v_z(:)
        real(dp), allocatable :: proj(:), t_r(:)
        real(dp) :: xi(16), w(16), val(max_local), der(max_local), xq, weight
        integer :: structure, nx, e, q, i, k, idx(max_local)
        character(len=40) :: what
        call new_layered_ground(ground, [0.4_dp, 1.0_dp], [1.0_dp, 5.0_dp], [1.0_dp, 5.0_dp], &
                                [0.3_dp, 0.45_dp], BASE_HALFSPACE, 20.0_dp, 0.2_dp, err)
        if (allocated(err)) return
        call gauss_legendre(16, xi, w)
        structures: do structure = 1, 2
            if (structure == 1) then
                call make_bases(0.0_dp, 1.0_dp, 6, 'EDGES', INTERP_P2, INTERP_P1, bx, bz, err)
            else
                call make_bases(-1.0_dp, 1.0_dp, 6, 'EDGES', INTERP_P1, INTERP_S2, bx, bz, err)
            end if
            if (allocated(err)) return
            nx = bx%n_dof
            r = [(cos(1.3_dp*real(i, dp)) + 0.2_dp, i = 1, nx + bz%n_dof)]
            call layered_correction(bx, bz, structure == 2, 0.3_dp, ground, c, err)
            if (allocated(err)) return
            t_r = matmul(c, r)
            allocate (x(16*bx%ne), wq(16*bx%ne))
            do e = 1, bx%ne
                x(16*(e - 1) + 1:16*e) = bx%x(e - 1) + 0.5_dp*(xi + 1.0_dp)*(bx%x(e) - bx%x(e - 1))
                wq(16*(e - 1) + 1:16*e) = 0.5_dp*w*(bx%x(e) - bx%x(e - 1))
            end do
            allocate (u_h(size(x)), u_z(size(x)), v_h(size(x)), v_z(size(x)))
            call layered_surface_displacement(bx, bz, structure == 2, 0.3_dp, ground, r(1:nx), &
                                              r(nx + 1:), x, u_h, u_z, err)
            if (allocated(err)) return
            if (structure == 1) then
                call plate_surface_displacement(bx, bz, r(1:nx), r(nx + 1:), &
                     ground%shear_modulus(1), ground%poisson(1), x, v_h, v_z, err)
            else
                call beam_surface_displacement(bx, bz, r(1:nx), r(nx + 1:), &
                     ground%shear_modulus(1), ground%poisson(1), 0.3_dp, x, v_h, v_z, err)
            end if
            if (allocated(err)) return
            u_h = u_h - v_h
            u_z = u_z - v_z
            allocate (proj(size(r)), source=0.0_dp)
            do e = 1, bx%ne
                do q = 1, 16
                    k = 16*(e - 1) + q
                    weight = wq(k)
                    if (structure == 1) weight = weight*2.0_dp*pi*x(k)
                    call eval_basis(bx, e, xi(q), idx, val, der, xq)
                    do i = 1, bx%n_local
                        proj(idx(i)) = proj(idx(i)) + weight*val(i)*u_h(k)
                    end do
                    call eval_basis(bz, e, xi(q), idx, val, der, xq)
                    do i = 1, bz%n_local
                        proj(nx + idx(i)) = proj(nx + idx(i)) + weight*val(i)*u_z(k)
                    end do
                end do
            end do
            write (what, '("structure ",i0)') structure
            call check_close(err, maxval(abs(proj - t_r))/maxval(abs(t_r)), 0.0_dp, 0.0_dp, &
                             1.0e-11_dp, trim(what))
            if (allocated(err)) return
            deallocate (x, wq, u_h, u_z, v_h, v_z, proj)
        end do structures
    end subroutine test_displacement_vs_t

    !> A uniform pressure on a plate (radius a) over one layer H = a bonded to rock: the
    !! layered compliance is analytic at s = 0 (no 1/s), so the settlement outside decays
    !! exponentially, while the half-space's decays like 1/r: at r = 10 a below 1e-4 of w(0)
    !! (the half-space: w(r)/w(0) -> a/(2r) = 0.05, the far field P (1-nu^2)/(pi E r) of the
    !! load P = pi a^2 p over w(0) = 2 (1-nu^2) p a/E, Johnson 1985 ch. 3).
    subroutine test_no_far_field(err)
        type(error_t), allocatable, intent(out) :: err
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp) :: u_r(2), u_z(2)
        integer :: i
        call one_layer(1.0_dp, 1.0_dp, 0.3_dp, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        call make_bases(0.0_dp, 1.0_dp, 8, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call layered_surface_displacement(bx, bz, .false., 0.0_dp, ground, &
             [(0.0_dp, i = 1, bx%n_dof)], [(1.0_dp, i = 1, bz%n_dof)], [0.0_dp, 10.0_dp], &
             u_r, u_z, err)
        if (allocated(err)) return
        call check(err, u_z(1) > 0.0_dp .and. abs(u_z(2)) < 1.0e-4_dp*u_z(1), &
                   'settlement far outside a plate on a layer over rock not ~0')
    end subroutine test_no_far_field

    !> Bad grounds are refused with a reason: zero modulus at the surface, nu > 0.5, a beam
    !! over a SMOOTH base, a top layer far too thin for the structure.
    subroutine test_bad_grounds(err)
        type(error_t), allocatable, intent(out) :: err
        type(error_t), allocatable :: failure
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp), allocatable :: t(:, :)
        call new_layered_ground(ground, [1.0_dp], [0.0_dp], [5.0_dp], [0.5_dp], BASE_ROUGH, &
                                0.0_dp, 0.0_dp, failure)
        call check(err, allocated(failure), 'E = 0 at the surface accepted')
        if (allocated(err)) return
        call check(err, index(failure%message, 'layer 1') > 0, 'message names no layer')
        if (allocated(err)) return
        deallocate (failure)
        call new_layered_ground(ground, [1.0_dp, 1.0_dp], [1.0_dp, 1.0_dp], [1.0_dp, 1.0_dp], &
                                [0.3_dp, 0.6_dp], BASE_ROUGH, 0.0_dp, 0.0_dp, failure)
        call check(err, allocated(failure), 'nu = 0.6 accepted')
        if (allocated(err)) return
        call check(err, index(failure%message, 'layer 2') > 0, 'message names no layer 2')
        if (allocated(err)) return
        deallocate (failure)
        call one_layer(1.0_dp, 1.0_dp, 0.3_dp, BASE_SMOOTH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        call make_bases(-1.0_dp, 1.0_dp, 4, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call assemble_layered_flexibility(bx, bz, .true., 0.3_dp, ground, t, failure)
        call check(err, allocated(failure), 'beam over a smooth base accepted')
        if (allocated(err)) return
        call check(err, index(failure%message, 'SMOOTH') > 0, 'smooth-base message')
        if (allocated(err)) return
        deallocate (failure)
        call one_layer(1.0e-5_dp, 1.0_dp, 0.3_dp, BASE_ROUGH, 0.0_dp, 0.0_dp, ground, err)
        if (allocated(err)) return
        call make_bases(0.0_dp, 1.0_dp, 4, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        call assemble_layered_flexibility(bx, bz, .false., 0.0_dp, ground, t, failure)
        call check(err, allocated(failure), 'top layer of 1e-5 a accepted')
        if (allocated(err)) return
        call check(err, index(failure%message, 'too thin') > 0, 'thin-layer message')
    end subroutine test_bad_grounds

    !> The piecewise Taylor polynomials of layered_bessel against the intrinsic bessel_j0 /
    !! bessel_j1 (a different algorithm: rational approximations and the asymptotic form) at
    !! 20000 points of [0, 200] (irrational steps, every part of a piece), to 1e-15 absolute
    !! (|J| <= 1; the truncation bound is 7e-19, the rest is rounding of both), and at the
    !! ends of the table.
    subroutine test_bessel_table(err)
        type(error_t), allocatable, intent(out) :: err
        type(bessel_table_t) :: table
        integer, parameter :: n = 20000
        real(dp) :: x(n), j0(n), j1(n)
        integer :: i
        call new_bessel_table(200.0_dp, table)
        points: do i = 1, n
            x(i) = min(200.0_dp, real(i, dp)*sqrt(2.0_dp)/141.4_dp)
        end do points
        call bessel_table_pair(table, x, j0, j1)
        call check(err, maxval(abs(j0 - bessel_j0(x))) <= 1.0e-15_dp, 'J0 from the table')
        if (allocated(err)) return
        call check(err, maxval(abs(j1 - bessel_j1(x))) <= 1.0e-15_dp, 'J1 from the table')
        if (allocated(err)) return
        call bessel_table_pair(table, [0.0_dp, 200.0_dp], j0(1:2), j1(1:2))
        call check_close(err, j0(1), 1.0_dp, 0.0_dp, 1.0e-15_dp, 'J0(0)')
        if (allocated(err)) return
        call check_close(err, j1(1), 0.0_dp, 0.0_dp, 1.0e-15_dp, 'J1(0)')
        if (allocated(err)) return
        call check_close(err, j0(2), bessel_j0(200.0_dp), 0.0_dp, 1.0e-15_dp, 'J0(200)')
    end subroutine test_bessel_table

    !> ELLEA1's surface displacements (module header) under two uniform circles, q = 1.1 MPa,
    !! a = 150 mm, centred at (0, -150) and (0, 150) mm, on 150 mm of E = 3000 MPa, nu = 0.30
    !! over 600 mm of E = 200 MPa, nu = 0.35 over a half-space of E = 40 MPa, nu = 0.40, all
    !! bonded; points (x, 0) on the surface. By superposition each is the sum of the two
    !! circles' axisymmetric fields at r = sqrt(x^2 + 150^2): u_z = 2 w(r), u_x = 2 u_r(r) x/r.
    !! The uniform traction is exact in P1, so the layered ground's surface displacement is
    !! the only thing tested. Tolerance 1e-4 mm: one unit of the table's last printed digit
    !! (its rounding, 5e-5, and ELLEA1's own quadrature, which scatters by about as much about
    !! a smooth curve).
    subroutine test_ellea1_profile(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: x(16) = [0.0_dp, 50.0_dp, 100.0_dp, 150.0_dp, 200.0_dp, &
            250.0_dp, 300.0_dp, 350.0_dp, 400.0_dp, 450.0_dp, 500.0_dp, 750.0_dp, 1000.0_dp, &
            1500.0_dp, 2000.0_dp, 3000.0_dp]                                        ! [mm]
        real(dp), parameter :: u_z(16) = [1.9174_dp, 1.8929_dp, 1.8416_dp, 1.7772_dp, &
            1.7063_dp, 1.6333_dp, 1.5614_dp, 1.4923_dp, 1.4272_dp, 1.3665_dp, 1.3101_dp, &
            1.0843_dp, 0.9232_dp, 0.6995_dp, 0.5484_dp, 0.3657_dp]                  ! [mm]
        real(dp), parameter :: u_x(16) = [0.0_dp, -0.0365_dp, -0.0660_dp, -0.0866_dp, &
            -0.0994_dp, -0.1060_dp, -0.1082_dp, -0.1073_dp, -0.1047_dp, -0.1011_dp, &
            -0.0970_dp, -0.0782_dp, -0.0658_dp, -0.0506_dp, -0.0398_dp, -0.0254_dp]  ! [mm]
        type(layered_ground_t) :: ground
        type(basis_t) :: bx, bz
        real(dp) :: r(16), u_r(16), w(16)
        character(len=60) :: what
        integer :: i
        call new_layered_ground(ground, [150.0_dp, 600.0_dp], [3000.0_dp, 200.0_dp], &
                                [3000.0_dp, 200.0_dp], [0.30_dp, 0.35_dp], BASE_HALFSPACE, &
                                40.0_dp, 0.40_dp, err)
        if (allocated(err)) return
        call make_bases(0.0_dp, 150.0_dp, 20, 'UNIFORM', INTERP_P1, INTERP_P1, bx, bz, err)
        if (allocated(err)) return
        r = sqrt(x**2 + 150.0_dp**2)
        call layered_surface_displacement(bx, bz, .false., 0.0_dp, ground, &
                                          spread(0.0_dp, 1, bx%n_dof), &
                                          spread(1.1_dp, 1, bz%n_dof), r, u_r, w, err)
        if (allocated(err)) return
        points: do i = 1, size(x)
            write (what, '("u_z at x = ",f6.0," mm")') x(i)
            call check_close(err, 2.0_dp*w(i), u_z(i), 0.0_dp, 1.0e-4_dp, trim(what))
            if (allocated(err)) return
            write (what, '("u_x at x = ",f6.0," mm")') x(i)
            call check_close(err, 2.0_dp*u_r(i)*x(i)/r(i), u_x(i), 0.0_dp, 1.0e-4_dp, &
                             trim(what))
            if (allocated(err)) return
        end do points
    end subroutine test_ellea1_profile
end module test_layered_ground
