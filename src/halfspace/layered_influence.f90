!> Galerkin flexibility T of layered ground under a beam or a circular plate (SPEC §3a).
!!
!! T = T_hs(top layer's G_1, nu_1) (halfspace_beam / halfspace_plate: closed-form kernels,
!! every singularity) + T_corr, with T_corr from phi(s) = s (C(s) - C_hs(s))
!! (layered_compliance), which decays like exp(-2 s h_1). Blocks [T_xx T_xz; T_zx T_zz],
!! bx coefficients first, as in halfspace_beam and halfspace_plate.
!!
!! PLATE (rings, measure 2 pi r; kernel reference (C0) with the layered compliances): with the
!! Hankel transforms Bz_a(xi) = int g_a(r) J0(xi r) r dr (normal) and Bx_a(xi) =
!! int g_a(r) J1(xi r) r dr (radial),
!!     T_xx = 2 pi int phi_hh Bx Bx^T dxi,   T_zz = 2 pi int phi_zz Bz Bz^T dxi,
!!     T_xz = -2 pi int phi_zh Bx Bz^T dxi,  T_zx = T_xz^T.
!! BEAM (centre-line strip kernels (B9)–(B11): line loads spread uniformly over the width b,
!! displacement on the centre line): with c_a(k) = int g_a cos(k x) dx, s_a(k) = int g_a
!! sin(k x) dx, the 2-D transform of the traction of density 1/b across |y| <= b/2 being
!! sinc(k_y b/2), and s = sqrt(k^2 + y^2),
!!     K_zz(k) = (1/pi) int_0^inf phi_zz(s)/s sinc(y b/2) dy,
!!     K_xx(k) = (1/pi) int_0^inf [phi_SH y^2/s^2 + phi_hh k^2/s^2]/s sinc(y b/2) dy,
!!     K_q(k)  = (1/pi) int_0^inf phi_zh k/s^2 sinc(y b/2) dy,
!!     T_zz = (1/pi) int_0^inf K_zz (c c^T + s s^T) dk,  T_xx likewise with K_xx,
!!     T_zx = (1/pi) int_0^inf K_q (s_z c_x^T - c_z s_x^T) dk,  T_xz = T_zx^T.
!! The inner integral is taken in v, y = k sinh v (dy = s dv removes the 1/s of phi/s near
!! y = 0, k -> 0), up to y = dy_max/2, and plainly beyond; the outer one has a logarithmic
!! singularity at k = 0 (the far field of phi(0)/s), taken by the product rule of
!! layered_wavenumbers on [0, k_0].
!! Surface displacements at points x (layered_surface_displacement) from the same integrals
!! with the field function replaced by its kernel: plate u_z(r) = int [phi_zz P - phi_zh Q]
!! J0(xi r) dxi, u_r(r) = int [-phi_zh P + phi_hh Q] J1(xi r) dxi (P, Q the Hankel transforms
!! of sigma_z, sigma_x); beam u_z = (1/pi) int [K_zz (c_z cos kx + s_z sin kx) + K_q (c_x sin kx
!! - s_x cos kx)] dk, u_x = (1/pi) int [K_xx (c_x cos kx + s_x sin kx) + K_q (s_z cos kx -
!! c_z sin kx)] dk (c, s the transforms of sigma).
!! Each is a sum over wavenumber nodes of rank-one terms, assembled as products
!! B^T diag(w phi) B by dgemm straight into T (the blocks on the diagonal by column tiles,
!! lower triangle only; T_zx whole), then mirrored into the upper triangle. The transforms of
!! the basis functions come from Gauss–Legendre rules per element with enough points for the
!! highest wavenumber (element_points); the plate's Bessel functions from the table of
!! layered_bessel (Taylor polynomials per unit interval of the argument).
module layered_influence
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, add_context, EXIT_INPUT
    use quadrature, only: gauss_legendre
    use shape_functions, only: basis_t, eval_basis, max_local
    use lapack_interfaces, only: dgemm
    use halfspace_beam, only: assemble_beam_flexibility, beam_surface_displacement
    use halfspace_plate, only: assemble_plate_flexibility, plate_surface_displacement
    use layered_compliance, only: layered_ground_t, compliance_correction, total_depth, &
                                  halfspace_phi, BASE_SMOOTH
    use layered_wavenumbers, only: wavenumber_rule_t, graded_breaks, panel_rule, &
                                   log_product_rule, panel_phase, panel_points
    use layered_bessel, only: bessel_table_t, new_bessel_table, bessel_table_pair
    implicit none
    private

    public :: assemble_layered_flexibility, layered_correction, layered_surface_displacement

    real(dp), parameter :: x_end = 25.0_dp     !! s h_1 beyond which phi is round-off
                                               !! (layered_compliance x_thick)
    real(dp), parameter :: phi_floor = 1.0e-17_dp  !! trailing panels with |phi| below this
                                                   !! times its scale are dropped
    integer, parameter :: max_nodes = 40000    !! wavenumber nodes (outer rule), at most
    integer, parameter :: max_inner = 4000000  !! beam: compliance evaluations, at most

contains

    !> T of the layered ground (module header): the entry point. The correction's lower
    !! triangle is added to the homogeneous T (exactly symmetric) in place, then mirrored.
    subroutine assemble_layered_flexibility(bx, bz, beam, width, ground, t_mat, err)
        type(basis_t), intent(in) :: bx                   !! basis of sigma_x
        type(basis_t), intent(in) :: bz                   !! basis of sigma_z, same mesh
        logical, intent(in) :: beam                       !! .true. beam, .false. plate
        real(dp), intent(in) :: width                     !! beam width b [length] (beam)
        type(layered_ground_t), intent(in) :: ground      !! resolved layers and base
        real(dp), allocatable, intent(out) :: t_mat(:, :) !! (nx+nz)^2
        type(error_t), allocatable, intent(out) :: err    !! allocated on failure
        integer :: nodes
        call check_problem(bx, bz, beam, width, ground, err)
        if (allocated(err)) then
            call add_context(err, 'layered ground')
            return
        end if
        if (beam) then
            call assemble_beam_flexibility(bx, bz, ground%shear_modulus(1), ground%poisson(1), &
                                           width, t_mat, err)
        else
            call assemble_plate_flexibility(bx, bz, ground%shear_modulus(1), ground%poisson(1), &
                                            t_mat, err)
        end if
        if (allocated(err)) return
        call add_correction(bx, bz, beam, width, ground, 1.0_dp, t_mat, nodes, err)
        if (allocated(err)) return
        call mirror_lower(t_mat)
    end subroutine assemble_layered_flexibility

    !> T_corr = T - T_hs(top layer) (module header).
    subroutine layered_correction(bx, bz, beam, width, ground, t_corr, err, refine, n_nodes)
        type(basis_t), intent(in) :: bx, bz        !! the bases of sigma_x and sigma_z
        logical, intent(in) :: beam                !! a beam (strip kernels), else a plate (rings)
        real(dp), intent(in) :: width              !! beam width [L] (unused for a plate)
        type(layered_ground_t), intent(in) :: ground         !! the layered ground
        real(dp), allocatable, intent(out) :: t_corr(:, :)   !! T_corr (nr x nr)
        type(error_t), allocatable, intent(out) :: err       !! allocated on failure
        real(dp), intent(in), optional :: refine   !! accuracy studies: panels and element
                                                   !! rules refine times finer (default 1)
        integer, intent(out), optional :: n_nodes  !! wavenumber nodes of the outer rule
        real(dp) :: factor
        integer :: nodes
        factor = 1.0_dp
        if (present(refine)) factor = max(1.0_dp, refine)
        nodes = 0
        call check_problem(bx, bz, beam, width, ground, err)
        if (allocated(err)) then
            call add_context(err, 'layered ground')
            return
        end if
        allocate (t_corr(bx%n_dof + bz%n_dof, bx%n_dof + bz%n_dof), source=0.0_dp)
        call add_correction(bx, bz, beam, width, ground, factor, t_corr, nodes, err)
        if (present(n_nodes)) n_nodes = nodes
        if (allocated(err)) return
        call mirror_lower(t_corr)
    end subroutine layered_correction

    !> t_mat's lower triangle (with its diagonal tiles) += T_corr (module header); the upper
    !! triangle is left to mirror_lower.
    subroutine add_correction(bx, bz, beam, width, ground, factor, t_mat, nodes, err)
        type(basis_t), intent(in) :: bx, bz
        logical, intent(in) :: beam
        real(dp), intent(in) :: width
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: factor
        real(dp), intent(inout) :: t_mat(:, :)
        integer, intent(out) :: nodes
        type(error_t), allocatable, intent(out) :: err
        if (beam) then
            call beam_correction(bx, bz, width, ground, factor, t_mat, nodes, err)
        else
            call plate_correction(bx, bz, ground, factor, t_mat, nodes, err)
        end if
        if (allocated(err)) call add_context(err, 'layered ground')
    end subroutine add_correction

    !> t(j, i) = t(i, j) for i > j, by tiles (the correction is assembled in the lower
    !! triangle; a symmetric result by construction, as (T + T^T)/2 was).
    subroutine mirror_lower(t)
        real(dp), intent(inout) :: t(:, :)
        integer, parameter :: tile = 64
        integer :: n, ib, jb, i, j
        n = size(t, 1)
        column_tiles: do jb = 1, n, tile
            row_tiles: do ib = jb, n, tile
                columns: do j = jb, min(jb + tile - 1, n)
                    rows: do i = max(ib, j + 1), min(ib + tile - 1, n)
                        t(j, i) = t(i, j)
                    end do rows
                end do columns
            end do row_tiles
        end do column_tiles
    end subroutine mirror_lower

    !> Grounds and structures the correction cannot take, with the reason.
    pure subroutine check_problem(bx, bz, beam, width, ground, err)
        type(basis_t), intent(in) :: bx, bz
        logical, intent(in) :: beam
        real(dp), intent(in) :: width
        type(layered_ground_t), intent(in) :: ground
        type(error_t), allocatable, intent(out) :: err
        if (.not. allocated(ground%thickness)) then
            call new_error(err, EXIT_INPUT, 'no layers')
        else if (size(ground%thickness) < 1) then
            call new_error(err, EXIT_INPUT, 'no layers')
        else if (bx%ne < 1 .or. bz%ne /= bx%ne .or. .not. allocated(bx%x)) then
            call new_error(err, EXIT_INPUT, 'the two traction bases need one mesh')
        else if (beam .and. .not. width > 0.0_dp) then
            call new_error(err, EXIT_INPUT, 'the beam width must be positive')
        else if (beam .and. ground%base == BASE_SMOOTH) then
            call new_error(err, EXIT_INPUT, 'a beam on layers over a SMOOTH base: a net '// &
                'horizontal load slides the layers on the base without bound (the '// &
                'tangential compliance grows like 1/k^2 at small wavenumbers k); use a '// &
                'ROUGH base or an elastic HALFSPACE base')
        else if (.not. beam .and. bx%x(0) /= 0.0_dp) then
            call new_error(err, EXIT_INPUT, 'plate mesh must start at r = 0')
        end if
    end subroutine check_problem

    !> Plate: Hankel transforms and the three blocks (module header).
    subroutine plate_correction(bx, bz, ground, refine, t_corr, n_nodes, err)
        type(basis_t), intent(in) :: bx, bz
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: refine
        real(dp), intent(inout) :: t_corr(:, :)
        integer, intent(out) :: n_nodes
        type(error_t), allocatable, intent(out) :: err
        type(wavenumber_rule_t) :: rule
        type(bessel_table_t) :: table
        real(dp), allocatable :: phi(:, :), hx(:, :), hz(:, :), w(:)
        real(dp) :: radius, omega
        integer :: nx, n, ld
        radius = bx%x(bx%ne)
        omega = 2.0_dp*radius + 2.0_dp*ground%thickness(1)
        call outer_rule(ground, refine*omega, .false., rule, err)
        if (allocated(err)) return
        allocate (phi(size(rule%node), 4))
        call compliance_correction(ground, rule%node, phi)
        call drop_tail(ground, phi, rule)
        n = size(rule%node)
        n_nodes = n
        call new_bessel_table(maxval(rule%node)*radius, table)
        call hankel_transforms(bx, bz, rule%node, refine, table, hx, hz)
        nx = bx%n_dof
        ld = size(t_corr, 1)
        w = 2.0_dp*pi*rule%weight
        call add_products(t_corr, ld, 1, 1, hx, w*phi(1:n, 3), hx, .true.)
        call add_products(t_corr, ld, nx + 1, nx + 1, hz, w*phi(1:n, 1), hz, .true.)
        call add_products(t_corr, ld, nx + 1, 1, hz, -w*phi(1:n, 2), hx, .false.)
    end subroutine plate_correction

    !> Beam: inner integrals K_zz, K_xx, K_q per wavenumber, Fourier transforms, the blocks.
    subroutine beam_correction(bx, bz, width, ground, refine, t_corr, n_nodes, err)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: width
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: refine
        real(dp), intent(inout) :: t_corr(:, :)
        integer, intent(out) :: n_nodes
        type(error_t), allocatable, intent(out) :: err
        type(wavenumber_rule_t) :: rule
        real(dp), allocatable :: kernel(:, :), cx(:, :), sx(:, :), cz(:, :), sz(:, :), w(:)
        real(dp) :: length, omega
        integer :: nx, ld
        length = bx%x(bx%ne) - bx%x(0)
        omega = length + 2.0_dp*ground%thickness(1)
        call outer_rule(ground, refine*omega, .true., rule, err)
        if (allocated(err)) return
        n_nodes = size(rule%node)
        call strip_kernels(ground, width, refine, rule%node, kernel, err)
        if (allocated(err)) return
        call fourier_transforms(bx, rule%node, refine, cx, sx)
        call fourier_transforms(bz, rule%node, refine, cz, sz)
        nx = bx%n_dof
        w = rule%weight/pi
        ld = size(t_corr, 1)
        call add_products(t_corr, ld, 1, 1, cx, w*kernel(:, 2), cx, .true.)
        call add_products(t_corr, ld, 1, 1, sx, w*kernel(:, 2), sx, .true.)
        call add_products(t_corr, ld, nx + 1, nx + 1, cz, w*kernel(:, 1), cz, .true.)
        call add_products(t_corr, ld, nx + 1, nx + 1, sz, w*kernel(:, 1), sz, .true.)
        call add_products(t_corr, ld, nx + 1, 1, sz, w*kernel(:, 3), cx, .false.)
        call add_products(t_corr, ld, nx + 1, 1, cz, -w*kernel(:, 3), sx, .false.)
    end subroutine beam_correction

    !> Surface displacements of the layered ground at x_eval under sigma_x = sum rx_b g_b,
    !! sigma_z = sum rz_b g_b: the top layer's half-space (halfspace_beam, halfspace_plate)
    !! plus the correction (module header).
    subroutine layered_surface_displacement(bx, bz, beam, width, ground, rx, rz, x_eval, u_h, &
                                            u_z, err)
        type(basis_t), intent(in) :: bx, bz               !! traction bases, one mesh
        logical, intent(in) :: beam                       !! .true. beam, .false. plate
        real(dp), intent(in) :: width                     !! beam width b (beam)
        type(layered_ground_t), intent(in) :: ground      !! the layered ground
        real(dp), intent(in) :: rx(:), rz(:)              !! traction coefficients
        real(dp), intent(in) :: x_eval(:)                 !! points (beam x, plate r >= 0)
        real(dp), intent(out) :: u_h(:)                   !! u_x (beam) or u_r (plate)
        real(dp), intent(out) :: u_z(:)                   !! settlement, down positive
        type(error_t), allocatable, intent(out) :: err    !! allocated on failure
        real(dp), allocatable :: du_h(:), du_z(:)
        call check_problem(bx, bz, beam, width, ground, err)
        if (allocated(err)) then
            call add_context(err, 'layered ground')
            return
        end if
        if (beam) then
            call beam_surface_displacement(bx, bz, rx, rz, ground%shear_modulus(1), &
                 ground%poisson(1), width, x_eval, u_h, u_z, err)
            if (allocated(err)) return
            call beam_displacement_correction(bx, bz, width, ground, rx, rz, x_eval, du_h, &
                                              du_z, err)
        else
            call plate_surface_displacement(bx, bz, rx, rz, ground%shear_modulus(1), &
                 ground%poisson(1), x_eval, u_h, u_z, err)
            if (allocated(err)) return
            call plate_displacement_correction(bx, bz, ground, rx, rz, x_eval, du_h, du_z, err)
        end if
        if (allocated(err)) then
            call add_context(err, 'layered ground')
            return
        end if
        u_h = u_h + du_h
        u_z = u_z + du_z
    end subroutine layered_surface_displacement

    !> The plate's displacement correction (module header).
    subroutine plate_displacement_correction(bx, bz, ground, rx, rz, x_eval, du_r, du_z, err)
        type(basis_t), intent(in) :: bx, bz
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: rx(:), rz(:), x_eval(:)
        real(dp), allocatable, intent(out) :: du_r(:), du_z(:)
        type(error_t), allocatable, intent(out) :: err
        type(wavenumber_rule_t) :: rule
        type(bessel_table_t) :: table
        real(dp), allocatable :: phi(:, :), hx(:, :), hz(:, :), p(:), q(:), a_z(:), a_r(:)
        real(dp), allocatable :: j0(:), j1(:)
        real(dp) :: omega
        integer :: i, n
        omega = bx%x(bx%ne) + maxval(abs(x_eval)) + 2.0_dp*ground%thickness(1)
        call outer_rule(ground, omega, .false., rule, err)
        if (allocated(err)) return
        allocate (phi(size(rule%node), 4))
        call compliance_correction(ground, rule%node, phi)
        call drop_tail(ground, phi, rule)
        n = size(rule%node)
        call new_bessel_table(maxval(rule%node)*max(bx%x(bx%ne), maxval(abs(x_eval))), table)
        call hankel_transforms(bx, bz, rule%node, 1.0_dp, table, hx, hz)
        q = matmul(hx, rx)
        p = matmul(hz, rz)
        a_z = rule%weight*(phi(1:n, 1)*p - phi(1:n, 2)*q)
        a_r = rule%weight*(-phi(1:n, 2)*p + phi(1:n, 3)*q)
        allocate (du_r(size(x_eval)), du_z(size(x_eval)), j0(n), j1(n))
        points: do i = 1, size(x_eval)
            call bessel_table_pair(table, rule%node*abs(x_eval(i)), j0, j1)
            du_z(i) = sum(a_z*j0)
            du_r(i) = sign(1.0_dp, x_eval(i))*sum(a_r*j1)   ! J1 is odd
        end do points
    end subroutine plate_displacement_correction

    !> The beam's displacement correction (module header).
    subroutine beam_displacement_correction(bx, bz, width, ground, rx, rz, x_eval, du_x, du_z, &
                                            err)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: width
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: rx(:), rz(:), x_eval(:)
        real(dp), allocatable, intent(out) :: du_x(:), du_z(:)
        type(error_t), allocatable, intent(out) :: err
        type(wavenumber_rule_t) :: rule
        real(dp), allocatable :: kernel(:, :), cx(:, :), sx(:, :), cz(:, :), sz(:, :)
        real(dp), allocatable :: w(:), c_x(:), s_x(:), c_z(:), s_z(:), cosine(:), sine(:)
        real(dp) :: omega
        integer :: i
        omega = 0.5_dp*(bx%x(bx%ne) - bx%x(0)) + maxval(abs(x_eval)) + &
                2.0_dp*ground%thickness(1)
        call outer_rule(ground, omega, .true., rule, err)
        if (allocated(err)) return
        call strip_kernels(ground, width, 1.0_dp, rule%node, kernel, err)
        if (allocated(err)) return
        call fourier_transforms(bx, rule%node, 1.0_dp, cx, sx)
        call fourier_transforms(bz, rule%node, 1.0_dp, cz, sz)
        w = rule%weight/pi
        c_x = matmul(cx, rx)
        s_x = matmul(sx, rx)
        c_z = matmul(cz, rz)
        s_z = matmul(sz, rz)
        allocate (du_x(size(x_eval)), du_z(size(x_eval)))
        points: do i = 1, size(x_eval)
            cosine = cos(rule%node*x_eval(i))
            sine = sin(rule%node*x_eval(i))
            du_z(i) = sum(w*(kernel(:, 1)*(c_z*cosine + s_z*sine) + &
                             kernel(:, 3)*(c_x*sine - s_x*cosine)))
            du_x(i) = sum(w*(kernel(:, 2)*(c_x*cosine + s_x*sine) + &
                             kernel(:, 3)*(s_z*cosine - c_z*sine)))
        end do points
    end subroutine beam_displacement_correction

    !> The outer wavenumber rule (layered_wavenumbers): panels up to x_end/h_1, the first
    !! [0, k_0] by the logarithmic product rule for the beam (log_first).
    subroutine outer_rule(ground, omega, log_first, rule, err)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: omega          !! largest frequency of the transforms' products
        logical, intent(in) :: log_first
        type(wavenumber_rule_t), intent(out) :: rule
        type(error_t), allocatable, intent(out) :: err
        type(wavenumber_rule_t) :: first, rest
        real(dp), allocatable :: breaks(:)
        real(dp) :: k_max, k_0, delta
        character(len=160) :: text
        k_max = x_end/ground%thickness(1)
        delta = 2.0_dp*panel_phase/omega
        k_0 = min(0.5_dp*delta, 0.25_dp/total_depth(ground))
        breaks = graded_breaks(k_0, delta, k_max, max_nodes/panel_points)
        if (size(breaks) < 2) then
            write (text, '(a,es9.2,a,es9.2,a)') 'the top layer (h = ', ground%thickness(1), &
                ') is too thin for a structure of extent ', 0.5_dp*omega, &
                ': more than 40000 wavenumbers; merge it into the layer below'
            call new_error(err, EXIT_INPUT, trim(text))
            return
        end if
        call panel_rule(breaks(2:), rest)
        if (log_first) then
            call log_product_rule(breaks(2), first, err)
            if (allocated(err)) return
        else
            call panel_rule(breaks(1:2), first)
        end if
        rule%node = [first%node, rest%node]
        rule%weight = [first%weight, rest%weight]
    end subroutine outer_rule

    !> Drop the trailing panels where |phi| is below phi_floor of its scale (round-off).
    pure subroutine drop_tail(ground, phi, rule)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: phi(:, :)
        type(wavenumber_rule_t), intent(inout) :: rule
        real(dp) :: scale
        integer :: n
        scale = max(maxval(abs(halfspace_phi(ground%shear_modulus(1), ground%poisson(1)))), &
                    maxval(abs(phi)))
        n = size(rule%node)
        trailing: do while (n > panel_points)
            if (maxval(abs(phi(n - panel_points + 1:n, :))) > phi_floor*scale) exit trailing
            n = n - panel_points
        end do trailing
        rule%node = rule%node(1:n)
        rule%weight = rule%weight(1:n)
    end subroutine drop_tail

    !> kernel(k, :) = [K_zz, K_xx, K_q](node(k)) of the strip (module header).
    subroutine strip_kernels(ground, width, refine, node, kernel, err)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: width
        real(dp), intent(in) :: refine
        real(dp), intent(in) :: node(:)
        real(dp), allocatable, intent(out) :: kernel(:, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: s(:), y(:), wy(:), phi(:, :)
        integer, allocatable :: first(:)
        real(dp) :: dy_max, k_max
        integer :: k, i
        k_max = x_end/ground%thickness(1)
        dy_max = 2.0_dp*panel_phase/(refine*(0.5_dp*width + 2.0_dp*ground%thickness(1)))
        call inner_nodes(node, k_max, dy_max, s, y, wy, first, err)
        if (allocated(err)) return
        allocate (phi(size(s), 4))
        call compliance_correction(ground, s, phi)
        allocate (kernel(size(node), 3))
        outer: do k = 1, size(node)
            kernel(k, :) = 0.0_dp
            inner: do i = first(k), first(k + 1) - 1
                associate (sinc => strip_sinc(0.5_dp*width*y(i)), w => wy(i)/(pi*s(i)))
                    kernel(k, 1) = kernel(k, 1) + w*sinc*phi(i, 1)
                    kernel(k, 2) = kernel(k, 2) + w*sinc*(phi(i, 4)*(y(i)/s(i))**2 + &
                                                          phi(i, 3)*(node(k)/s(i))**2)
                    kernel(k, 3) = kernel(k, 3) + w*sinc*phi(i, 2)*node(k)/s(i)
                end associate
            end do inner
        end do outer
    end subroutine strip_kernels

    !> The inner nodes y (and s = sqrt(k^2 + y^2), weight in y) of every outer node k:
    !! [0, y_g] in v = asinh(y/k) (panels of length <= 1), [y_g, y_max] in y (panels
    !! <= dy_max), y_g = min(dy_max/2, y_max), y_max = sqrt(k_max^2 - k^2). first(k) is the
    !! first of node k's inner nodes.
    subroutine inner_nodes(node, k_max, dy_max, s, y, wy, first, err)
        real(dp), intent(in) :: node(:), k_max, dy_max
        real(dp), allocatable, intent(out) :: s(:), y(:), wy(:)
        integer, allocatable, intent(out) :: first(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: xi(panel_points), w(panel_points), y_max, y_g, v_g
        integer :: k, n_v, n_y, n, total
        call gauss_legendre(panel_points, xi, w)
        allocate (first(size(node) + 1))
        total = 0
        count: do k = 1, size(node)
            first(k) = total + 1
            call inner_sizes(node(k), k_max, dy_max, y_max, y_g, v_g, n_v, n_y)
            total = total + panel_points*(n_v + n_y)
        end do count
        first(size(node) + 1) = total + 1
        if (total > max_inner) then
            call new_error(err, EXIT_INPUT, 'the top layer is too thin for the beam''s '// &
                           'width: more than 4e6 wavenumbers; merge it into the layer below')
            return
        end if
        allocate (s(total), y(total), wy(total))
        fill: do k = 1, size(node)
            call inner_sizes(node(k), k_max, dy_max, y_max, y_g, v_g, n_v, n_y)
            n = first(k) - 1
            call sinh_panels(node(k), v_g, n_v, xi, w, y(n + 1:), wy(n + 1:))
            n = n + panel_points*n_v
            call plain_panels(y_g, y_max, n_y, xi, w, y(n + 1:), wy(n + 1:))
            s(first(k):first(k + 1) - 1) = hypot(node(k), y(first(k):first(k + 1) - 1))
        end do fill
    end subroutine inner_nodes

    !> Sizes of the inner rule of outer node k (inner_nodes).
    pure subroutine inner_sizes(k, k_max, dy_max, y_max, y_g, v_g, n_v, n_y)
        real(dp), intent(in) :: k, k_max, dy_max
        real(dp), intent(out) :: y_max, y_g, v_g
        integer, intent(out) :: n_v, n_y
        y_max = sqrt(max(k_max**2 - k**2, 0.0_dp))
        y_g = min(0.5_dp*dy_max, y_max)
        v_g = asinh(y_g/k)
        n_v = max(1, ceiling(v_g))
        n_y = 0
        if (y_max > y_g) n_y = ceiling((y_max - y_g)/dy_max)
    end subroutine inner_sizes

    !> n_v equal panels of v in [0, v_g], y = k sinh v, weight dy = k cosh v dv.
    pure subroutine sinh_panels(k, v_g, n_v, xi, w, y, wy)
        real(dp), intent(in) :: k, v_g
        integer, intent(in) :: n_v
        real(dp), intent(in) :: xi(:), w(:)
        real(dp), intent(inout) :: y(:), wy(:)
        real(dp) :: half, v(size(xi))
        integer :: p, m
        half = 0.5_dp*v_g/real(n_v, dp)
        m = size(xi)
        panels: do p = 1, n_v
            v = real(2*(p - 1) + 1, dp)*half + half*xi
            y((p - 1)*m + 1:p*m) = k*sinh(v)
            wy((p - 1)*m + 1:p*m) = half*w*k*cosh(v)
        end do panels
    end subroutine sinh_panels

    !> n_y equal panels of y in [y_g, y_max].
    pure subroutine plain_panels(y_g, y_max, n_y, xi, w, y, wy)
        real(dp), intent(in) :: y_g, y_max
        integer, intent(in) :: n_y
        real(dp), intent(in) :: xi(:), w(:)
        real(dp), intent(inout) :: y(:), wy(:)
        real(dp) :: half
        integer :: p, m
        if (n_y < 1) return
        half = 0.5_dp*(y_max - y_g)/real(n_y, dp)
        m = size(xi)
        panels: do p = 1, n_y
            y((p - 1)*m + 1:p*m) = y_g + real(2*(p - 1) + 1, dp)*half + half*xi
            wy((p - 1)*m + 1:p*m) = half*w
        end do panels
    end subroutine plain_panels

    !> sin(t)/t.
    elemental real(dp) function strip_sinc(t)
        real(dp), intent(in) :: t
        if (abs(t) < 1.0e-4_dp) then
            strip_sinc = 1.0_dp - t*t/6.0_dp
        else
            strip_sinc = sin(t)/t
        end if
    end function strip_sinc

    !> hx(k, a) = int gx_a(r) J1(node(k) r) r dr and hz(k, a) = int gz_a(r) J0(node(k) r) r dr
    !! for the bases bx, bz of one mesh: one pass, J0 and J1 from the table at each point.
    subroutine hankel_transforms(bx, bz, node, refine, table, hx, hz)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: node(:)
        real(dp), intent(in) :: refine
        type(bessel_table_t), intent(in) :: table   !! J0, J1 up to maxval(node) r_max
        real(dp), allocatable, intent(out) :: hx(:, :), hz(:, :)
        real(dp), allocatable :: xi(:), w(:)
        real(dp) :: x, val(max_local), der(max_local), j0(size(node)), j1(size(node)), half
        integer :: e, q, i, m, idx(max_local)
        allocate (hx(size(node), bx%n_dof), hz(size(node), bz%n_dof), source=0.0_dp)
        elements: do e = 1, bx%ne
            half = 0.5_dp*(bx%x(e) - bx%x(e - 1))
            m = element_points(refine*maxval(node)*(bx%x(e) - bx%x(e - 1)))
            call element_rule(m, xi, w)
            points: do q = 1, m
                call eval_basis(bz, e, xi(q), idx, val, der, x)
                call bessel_table_pair(table, node*x, j0, j1)
                normal: do i = 1, bz%n_local
                    hz(:, idx(i)) = hz(:, idx(i)) + (half*w(q)*val(i)*x)*j0
                end do normal
                call eval_basis(bx, e, xi(q), idx, val, der, x)
                radial: do i = 1, bx%n_local
                    hx(:, idx(i)) = hx(:, idx(i)) + (half*w(q)*val(i)*x)*j1
                end do radial
            end do points
        end do elements
    end subroutine hankel_transforms

    !> c(k, a) = int g_a cos(node(k) x) dx, s(k, a) = int g_a sin(node(k) x) dx.
    subroutine fourier_transforms(basis, node, refine, c, s)
        type(basis_t), intent(in) :: basis
        real(dp), intent(in) :: node(:)
        real(dp), intent(in) :: refine
        real(dp), allocatable, intent(out) :: c(:, :), s(:, :)
        real(dp), allocatable :: xi(:), w(:)
        real(dp) :: x, val(max_local), der(max_local), cosine(size(node)), sine(size(node))
        real(dp) :: factor
        integer :: e, q, i, m, idx(max_local)
        allocate (c(size(node), basis%n_dof), s(size(node), basis%n_dof), source=0.0_dp)
        elements: do e = 1, basis%ne
            m = element_points(refine*maxval(node)*(basis%x(e) - basis%x(e - 1)))
            call element_rule(m, xi, w)
            points: do q = 1, m
                call eval_basis(basis, e, xi(q), idx, val, der, x)
                cosine = cos(node*x)
                sine = sin(node*x)
                locals: do i = 1, basis%n_local
                    factor = 0.5_dp*(basis%x(e) - basis%x(e - 1))*w(q)*val(i)
                    c(:, idx(i)) = c(:, idx(i)) + factor*cosine
                    s(:, idx(i)) = s(:, idx(i)) + factor*sine
                end do locals
            end do points
        end do elements
    end subroutine fourier_transforms

    !> Gauss points per element for integrands (polynomial of degree <= 3) x (a function of
    !! bandwidth k_max) over an element of length h, phase = k_max h: the fewest n >= 4 with
    !! (phase/2)^(2(n-2))/(2(n-2))! <= 1e-17 (the Taylor bound of the Gauss error of
    !! exp(i omega t) on [-1, 1] with two orders left for the polynomial).
    pure integer function element_points(phase) result(n)
        real(dp), intent(in) :: phase
        real(dp) :: half
        half = max(0.5_dp*phase, 1.0e-300_dp)
        n = 4
        points: do while (real(2*(n - 2), dp)*log(half) - log_gamma(real(2*(n - 2) + 1, dp)) > &
                          log(1.0e-17_dp))
            n = n + 1
        end do points
    end function element_points

    !> Gauss–Legendre rule of m points on [-1, 1].
    pure subroutine element_rule(m, xi, w)
        integer, intent(in) :: m
        real(dp), allocatable, intent(inout) :: xi(:), w(:)
        if (allocated(xi)) then
            if (size(xi) == m) return
            deallocate (xi, w)
        end if
        allocate (xi(m), w(m))
        call gauss_legendre(m, xi, w)
    end subroutine element_rule

    !> t(row0:, col0:) += a^T diag(d) b (dgemm into t in place), a (n, na), b (n, nb); for a
    !! block on the diagonal (lower, a = b) only the lower triangle, by column tiles, with the
    !! tiles on the diagonal whole (mirror_lower overwrites the upper triangle).
    subroutine add_products(t_mat, ld, row0, col0, a, d, b, lower)
        integer, intent(in) :: ld                   !! rows of t_mat
        real(dp), intent(inout) :: t_mat(ld, ld)    !! explicit shape: dgemm writes into it
        integer, intent(in) :: row0, col0
        real(dp), intent(in) :: a(:, :), d(:), b(:, :)
        logical, intent(in) :: lower
        integer, parameter :: tile = 128
        real(dp), allocatable :: ad(:, :)
        integer :: j, n, k
        allocate (ad(size(a, 1), size(a, 2)))
        columns: do j = 1, size(a, 2)
            ad(:, j) = a(:, j)*d
        end do columns
        n = size(a, 1)
        if (.not. lower) then
            call dgemm('T', 'N', size(a, 2), size(b, 2), n, 1.0_dp, ad, n, b, size(b, 1), &
                       1.0_dp, t_mat(row0, col0), ld)
            return
        end if
        column_tiles: do j = 1, size(b, 2), tile
            k = min(tile, size(b, 2) - j + 1)
            call dgemm('T', 'N', size(a, 2) - j + 1, k, n, 1.0_dp, ad(1, j), n, b(:, j:), &
                       size(b, 1), 1.0_dp, t_mat(row0 + j - 1, col0 + j - 1), ld)
        end do column_tiles
    end subroutine add_products
end module layered_influence
