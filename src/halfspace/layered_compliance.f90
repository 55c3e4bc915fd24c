!> Surface compliance of horizontally layered elastic ground per wavenumber (SPEC §3a).
!!
!! Layers j = 1..n from the surface down (thickness h_j, shear modulus G_j, Poisson's ratio
!! nu_j, kappa_j = 3 - 4 nu_j) over a base: ROUGH (rigid, u = 0), SMOOTH (rigid, u_z = 0 and
!! no shear) or HALFSPACE (G_b, nu_b). Conventions of the kernel reference §0: z down into the
!! ground, p > 0 compressive, q the tangential traction on the ground. A surface mode of
!! wavenumber s > 0 (P-SV: p = P cos sx, q_x = Q sin sx; SH: q_y = Q_y cos sx) gives
!!     [U_x; U_z] = [C_hh, -C_zh; -C_zh, C_zz] [Q; P],      U_y = C_SH Q_y,
!! the four compliances of SPEC §3a; the homogeneous half-space has C_zz = C_hh = (1-nu)/(G s),
!! C_zh = (1-2nu)/(2 G s), C_SH = 1/(G s) (kernel reference (0.1)).
!!
!! Method. Per s, with zeta = s z and the state y = [U_x, U_z, S_x/(G_1 s), S_z/(G_1 s)]
!! (S_x = sigma_xz, S_z = sigma_zz; G_1 the top layer's), the Navier equations in layer j are
!! dy/dzeta = A_j y with, g = G_j/G_1, a1 = (3-kappa)/(kappa+1), a2 = (kappa-1)/(kappa+1),
!!     A_j = [0, 1, 1/g, 0;  -a1, 0, 0, a2/g;  8g/(kappa+1), 0, 0, a1;  0, 0, -1, 0]
!! (regular at nu = 0.5: a2 = 0). A_j has the eigenvalues +-1, each a 2x2 Jordan block, so
!! (A^2 - I)^2 = 0 and, by Hermite interpolation of e^(x lambda) at +-1,
!!     exp(-x A) = c0 I - c1 A + c2 A^2 - c3 A^3,   c0 = cosh x - (x/2) sinh x,
!!     c1 = (3 sinh x - x cosh x)/2,  c2 = (x/2) sinh x,  c3 = (x cosh x - sinh x)/2,
!! x = s h_j (c3 by its series below x = 1). The states the ground below an interface admits
!! form a two-dimensional subspace, carried upwards layer by layer (y_top = exp(-x A) y_bottom)
!! as an orthonormal 4x2 basis Y: ROUGH [0; I], SMOOTH span(e1, e4), HALFSPACE the decaying
!! solutions U = -(G_1/G_b) N_b S/(G_1 s), N = [1-nu, -(1-2nu)/2; -(1-2nu)/2, 1-nu]. Only the
!! subspace matters, so every step is scaled by e^(-x) (coefficients written with e^(-2x), no
!! growing exponential: nothing overflows) and re-orthonormalised; a layer with x > x_thick
!! (25) is a half-space to double precision (its reflections carry e^(-2x) x^2 < 1e-19) and
!! replaces Y by its own decaying subspace. At the surface [S_x, S_z] = -[Q, P], so
!! s [C_hh, -C_zh; -C_zh, C_zz] = -Y_u Y_t^(-1)/G_1 (Y_u, Y_t the rows of U and of S).
!! Thin layers (x -> 0) step by exp(-x A) = I - x A + ..., exactly: there is no mode matrix
!! to invert, so nothing cancels as x -> 0. Thick ones (x >= 1) split off their decaying
!! states (split_step). SH likewise with
!! y = [U_y, S_y/(G_1 s)], A = [0, 1/g; g, 0].
!!
!! The correction phi = s (C - C_hs(top layer)) is finite as s -> 0 for the ROUGH and
!! HALFSPACE bases; with a SMOOTH base phi_hh and phi_SH grow like 1/s (the layers slide on the
!! base) and phi_zz, phi_zh stay finite. phi decays like exp(-2 s h_1).
!!
!! A layer whose modulus varies linearly with depth (E_top to E_bottom) is resolved into
!! sublayers of constant modulus whose E changes by at most the factor 1 + sublayer_ratio
!! (5 %) across each, each with the logarithmic mean of E over it (exact for the series
!! compliance int dz/E of the sublayer). The sublayers are a midpoint rule of second order:
!! the compliance is within about 0.12 (5 %)^2 = 3e-4 of the continuous profile's at
!! wavenumbers below 1/(top sublayer's thickness), and within 2.5 % above (where the top
!! sublayer alone answers); doc/CHOICES.md.
module layered_compliance
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INPUT
    implicit none
    private

    integer, parameter, public :: BASE_ROUGH = 1      !! rigid base, bonded (u = 0)
    integer, parameter, public :: BASE_SMOOTH = 2     !! rigid base, frictionless
    integer, parameter, public :: BASE_HALFSPACE = 3  !! elastic half-space below the layers

    real(dp), parameter, public :: sublayer_ratio = 0.05_dp  !! largest relative change of E
                                                             !! across one sublayer
    integer, parameter, public :: max_sublayers = 20000      !! all layers together, at most
    real(dp), parameter :: x_thick = 25.0_dp  !! s h beyond which a layer is a half-space
    real(dp), parameter :: x_series = 1.0_dp  !! s h below which c3 comes from its series
    real(dp), parameter :: x_split = 1.0_dp   !! s h from which a step splits off the
                                              !! decaying states (split_step)

    !> Layers of constant properties over a base (the resolved profile).
    type, public :: layered_ground_t
        real(dp), allocatable :: thickness(:)       !! h_j, surface first [length]
        real(dp), allocatable :: shear_modulus(:)   !! G_j [force/length^2]
        real(dp), allocatable :: poisson(:)         !! nu_j, [0, 0.5]
        integer, allocatable :: card(:)             !! the input layer each layer comes from
        integer :: base = BASE_ROUGH                !! BASE_ROUGH, BASE_SMOOTH, BASE_HALFSPACE
        real(dp) :: base_shear_modulus = 0.0_dp     !! G_b (BASE_HALFSPACE) [force/length^2]
        real(dp) :: base_poisson = 0.0_dp           !! nu_b (BASE_HALFSPACE)
    end type layered_ground_t

    public :: new_layered_ground, surface_compliance, compliance_correction
    public :: halfspace_phi, total_depth

contains

    !> The resolved ground of input layers (thickness, E at top and bottom, nu) over a base.
    !! E_bottom = E_top is a constant layer; otherwise sublayers (module header).
    pure subroutine new_layered_ground(ground, thickness, e_top, e_bottom, poisson, base, &
                                       e_base, nu_base, err)
        type(layered_ground_t), intent(out) :: ground    !! the resolved ground
        real(dp), intent(in) :: thickness(:)   !! input layers' thicknesses, surface first
        real(dp), intent(in) :: e_top(:)       !! Young's modulus at each layer's top
        real(dp), intent(in) :: e_bottom(:)    !! Young's modulus at each layer's bottom
        real(dp), intent(in) :: poisson(:)     !! Poisson's ratio of each layer
        integer, intent(in) :: base            !! BASE_ROUGH, BASE_SMOOTH or BASE_HALFSPACE
        real(dp), intent(in) :: e_base         !! base modulus (BASE_HALFSPACE)
        real(dp), intent(in) :: nu_base        !! base Poisson's ratio (BASE_HALFSPACE)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer :: j, n_sub(size(thickness))
        call check_layers(thickness, e_top, e_bottom, poisson, err)
        if (allocated(err)) return
        call check_base(base, e_base, nu_base, err)
        if (allocated(err)) return
        do j = 1, size(thickness)
            n_sub(j) = sublayer_count(e_top(j), e_bottom(j))
        end do
        if (sum(n_sub) > max_sublayers) then
            call new_error(err, EXIT_INPUT, 'the moduli vary too much within the layers '// &
                           '(more than 20000 sublayers of 5 % would be needed)')
            return
        end if
        allocate (ground%thickness(0), ground%shear_modulus(0), ground%poisson(0), &
                  ground%card(0))
        do j = 1, size(thickness)
            call append_sublayers(ground, j, n_sub(j), thickness(j), e_top(j), e_bottom(j), &
                                  poisson(j))
        end do
        ground%base = base
        if (base == BASE_HALFSPACE) then
            ground%base_shear_modulus = e_base/(2.0_dp*(1.0_dp + nu_base))
            ground%base_poisson = nu_base
        end if
    end subroutine new_layered_ground

    !> Input layers: at least one, positive finite thicknesses and moduli, nu in [0, 0.5].
    pure subroutine check_layers(thickness, e_top, e_bottom, poisson, err)
        real(dp), intent(in) :: thickness(:), e_top(:), e_bottom(:), poisson(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=12) :: label
        integer :: j, n
        n = size(thickness)
        if (n < 1 .or. size(e_top) /= n .or. size(e_bottom) /= n .or. size(poisson) /= n) then
            call new_error(err, EXIT_INPUT, 'layered ground needs at least one layer')
            return
        end if
        layers: do j = 1, n
            write (label, '(a,i0)') 'layer ', j
            if (.not. (thickness(j) > 0.0_dp .and. thickness(j) <= huge(1.0_dp))) then
                call new_error(err, EXIT_INPUT, trim(label)//': thickness must be positive')
            else if (.not. (e_top(j) > 0.0_dp .and. e_top(j) <= huge(1.0_dp))) then
                call new_error(err, EXIT_INPUT, trim(label)//': modulus E must be positive '// &
                    '(a modulus growing from zero at the surface: give a small positive E)')
            else if (.not. (e_bottom(j) > 0.0_dp .and. e_bottom(j) <= huge(1.0_dp))) then
                call new_error(err, EXIT_INPUT, trim(label)//': bottom modulus must be positive')
            else if (.not. (poisson(j) >= 0.0_dp .and. poisson(j) <= 0.5_dp)) then
                call new_error(err, EXIT_INPUT, trim(label)//': Poisson ratio must be in [0, 0.5]')
            end if
            if (allocated(err)) return
        end do layers
    end subroutine check_layers

    !> Base kind and, for an elastic base, its constants.
    pure subroutine check_base(base, e_base, nu_base, err)
        integer, intent(in) :: base
        real(dp), intent(in) :: e_base, nu_base
        type(error_t), allocatable, intent(out) :: err
        select case (base)
        case (BASE_ROUGH, BASE_SMOOTH)
        case (BASE_HALFSPACE)
            if (.not. (e_base > 0.0_dp .and. e_base <= huge(1.0_dp))) then
                call new_error(err, EXIT_INPUT, 'base: modulus E must be positive')
            else if (.not. (nu_base >= 0.0_dp .and. nu_base <= 0.5_dp)) then
                call new_error(err, EXIT_INPUT, 'base: Poisson ratio must be in [0, 0.5]')
            end if
        case default
            call new_error(err, EXIT_INPUT, 'base must be ROUGH, SMOOTH or HALFSPACE')
        end select
    end subroutine check_base

    !> Sublayers of a layer from E_top to E_bottom: E changes by at most 1 + sublayer_ratio.
    pure integer function sublayer_count(e_top, e_bottom) result(n)
        real(dp), intent(in) :: e_top, e_bottom
        real(dp) :: steps
        steps = abs(log(e_bottom/e_top))/log(1.0_dp + sublayer_ratio)
        n = 1
        if (steps > 1.0e-12_dp) n = max(1, ceiling(steps - 1.0e-9_dp))
        if (steps > real(max_sublayers, dp)) n = max_sublayers + 1
    end function sublayer_count

    !> Append the n sublayers of input layer `card`: E linear in depth, equal ratios of E
    !! between their boundaries, each the logarithmic mean of E over it.
    pure subroutine append_sublayers(ground, card, n, thickness, e_top, e_bottom, poisson)
        type(layered_ground_t), intent(inout) :: ground
        integer, intent(in) :: card, n
        real(dp), intent(in) :: thickness, e_top, e_bottom, poisson
        real(dp) :: e_hi, e_lo, z_hi, z_lo, slope, e_mean
        integer :: i
        slope = (e_bottom - e_top)/thickness
        z_hi = 0.0_dp
        e_hi = e_top
        sublayers: do i = 1, n
            if (i == n) then
                e_lo = e_bottom
                z_lo = thickness
            else
                e_lo = e_top*(e_bottom/e_top)**(real(i, dp)/real(n, dp))
                z_lo = (e_lo - e_top)/slope
            end if
            if (abs(e_lo - e_hi) <= 1.0e-6_dp*e_hi) then
                e_mean = 0.5_dp*(e_lo + e_hi)     ! the log mean to 1e-13
            else
                e_mean = (e_lo - e_hi)/log(e_lo/e_hi)
            end if
            ground%thickness = [ground%thickness, z_lo - z_hi]
            ground%shear_modulus = [ground%shear_modulus, e_mean/(2.0_dp*(1.0_dp + poisson))]
            ground%poisson = [ground%poisson, poisson]
            ground%card = [ground%card, card]
            z_hi = z_lo
            e_hi = e_lo
        end do sublayers
    end subroutine append_sublayers

    !> Depth of the base below the surface [length].
    pure real(dp) function total_depth(ground)
        type(layered_ground_t), intent(in) :: ground   !! the layered ground
        total_depth = sum(ground%thickness)
    end function total_depth

    !> s C of the homogeneous half-space (G, nu): zz, zh, hh, SH (module header).
    pure function halfspace_phi(g, nu) result(phi)
        real(dp), intent(in) :: g, nu   !! shear modulus G [F/L^2]; Poisson's ratio nu
        real(dp) :: phi(4)
        phi = [1.0_dp - nu, 0.5_dp*(1.0_dp - 2.0_dp*nu), 1.0_dp - nu, 1.0_dp]/g
    end function halfspace_phi

    !> The four compliances C_zz, C_zh, C_hh, C_SH at the wavenumbers s > 0 (module header).
    pure subroutine surface_compliance(ground, s, c_zz, c_zh, c_hh, c_sh)
        type(layered_ground_t), intent(in) :: ground   !! the layered ground
        real(dp), intent(in) :: s(:)                 !! wavenumbers > 0 [1/length]
        real(dp), intent(out) :: c_zz(:), c_zh(:), c_hh(:), c_sh(:)  !! [length^3/force]
        real(dp) :: phi(4)
        integer :: k
        wavenumbers: do k = 1, size(s)
            call scaled_compliance(ground, s(k), phi)
            c_zz(k) = phi(1)/s(k)
            c_zh(k) = phi(2)/s(k)
            c_hh(k) = phi(3)/s(k)
            c_sh(k) = phi(4)/s(k)
        end do wavenumbers
    end subroutine surface_compliance

    !> phi(k, :) = s_k (C - C_hs(top layer)) for zz, zh, hh, SH at the wavenumbers s > 0.
    pure subroutine compliance_correction(ground, s, phi)
        type(layered_ground_t), intent(in) :: ground   !! the layered ground
        real(dp), intent(in) :: s(:)                 !! wavenumbers > 0 [1/length]
        real(dp), intent(out) :: phi(:, :)           !! (size(s), 4) [length^2/force]
        real(dp) :: phi_hs(4), phi_k(4)
        integer :: k
        phi_hs = halfspace_phi(ground%shear_modulus(1), ground%poisson(1))
        wavenumbers: do k = 1, size(s)
            call scaled_compliance(ground, s(k), phi_k)
            phi(k, :) = phi_k - phi_hs
        end do wavenumbers
    end subroutine compliance_correction

    !> s C (zz, zh, hh, SH) at one wavenumber s > 0.
    pure subroutine scaled_compliance(ground, s, phi)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: s
        real(dp), intent(out) :: phi(4)
        real(dp) :: y(4, 2), m(2, 2), v(2), det, g_1
        g_1 = ground%shear_modulus(1)
        call psv_subspace(ground, s, y)
        det = y(3, 1)*y(4, 2) - y(3, 2)*y(4, 1)
        ! -Y_u Y_t^(-1)
        m(:, 1) = -(y(1:2, 1)*y(4, 2) - y(1:2, 2)*y(4, 1))/det
        m(:, 2) = -(y(1:2, 2)*y(3, 1) - y(1:2, 1)*y(3, 2))/det
        phi(1) = m(2, 2)/g_1
        phi(2) = -0.5_dp*(m(1, 2) + m(2, 1))/g_1
        phi(3) = m(1, 1)/g_1
        call sh_subspace(ground, s, v)
        phi(4) = -v(1)/(v(2)*g_1)
    end subroutine scaled_compliance

    !> Orthonormal basis of the P-SV states admitted at the surface (module header).
    pure subroutine psv_subspace(ground, s, y)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: s
        real(dp), intent(out) :: y(4, 2)
        real(dp) :: g_1, g, kappa, x, c(4), ay(4, 2), a2y(4, 2), a3y(4, 2)
        logical :: done
        integer :: j
        g_1 = ground%shear_modulus(1)
        y = 0.0_dp
        select case (ground%base)
        case (BASE_ROUGH)
            y(3, 1) = 1.0_dp
            y(4, 2) = 1.0_dp
        case (BASE_SMOOTH)
            y(1, 1) = 1.0_dp
            y(4, 2) = 1.0_dp
        case default
            call halfspace_states(ground%base_shear_modulus/g_1, ground%base_poisson, y)
        end select
        layers: do j = size(ground%thickness), 1, -1
            g = ground%shear_modulus(j)/g_1
            kappa = 3.0_dp - 4.0_dp*ground%poisson(j)
            x = s*ground%thickness(j)
            if (x > x_thick) then
                call halfspace_states(g, ground%poisson(j), y)
                cycle layers
            end if
            ay = apply_a(y, g, kappa)
            a2y = apply_a(ay, g, kappa)
            a3y = apply_a(a2y, g, kappa)
            if (x >= x_split) then
                call split_step(x, g, ground%poisson(j), y, ay, a2y, a3y, done)
                if (done) cycle layers
            end if
            c = step_coefficients(x)
            y = c(1)*y - c(2)*ay + c(3)*a2y - c(4)*a3y
            call orthonormalise(y)
        end do layers
    end subroutine psv_subspace

    !> exp(-x A) Y for x >= x_split by the spectral projectors of A: with Pi = (A - I)^2
    !! (A + 2I)/4 the projector on the decaying states H of the layer (Hermite: p(-1) = 1,
    !! p'(-1) = p(1) = p'(1) = 0) and A Pi = -(A - I)^2/4 (as (A^2 - I)^2 = 0),
    !!     e^(-x) exp(-x A) Y = (I - x (A + I)) Pi Y + e^(-2x) (I - x (A - I)) (I - Pi) Y.
    !! The first term lies in H, = Q_H R with Q_H the closed-form basis of H, so the plane
    !! is span(Q_H + e^(-2x) W R^(-1)), W the second bracket: the half-space part exact and
    !! the reflection added as a small term, which keeps C - C_hs to round-off of C_hs where
    !! the direct sum of four O(x) terms loses digits (1e-13 at x = 17). R = H^T (I - x N) Pi Y
    !! with a unipotent middle factor, so its inverse is as good as that of H^T Pi Y (and
    !! enters multiplied by e^(-2x)); done = .false. when H^T Pi Y is ill-conditioned (Y almost
    !! free of decaying states): then the direct sum is used.
    pure subroutine split_step(x, g, nu, y, ay, a2y, a3y, done)
        real(dp), intent(in) :: x, g, nu
        real(dp), intent(inout) :: y(4, 2)
        real(dp), intent(in) :: ay(4, 2), a2y(4, 2), a3y(4, 2)
        logical, intent(out) :: done
        real(dp) :: py(4, 2), apy(4, 2), qy(4, 2), aqy(4, 2), h(4, 2), r(2, 2), r_inv(2, 2)
        real(dp) :: det
        py = 0.25_dp*(a3y - 3.0_dp*ay + 2.0_dp*y)
        apy = -0.25_dp*(a2y - 2.0_dp*ay + y)
        qy = y - py
        aqy = ay - apy
        call halfspace_states(g, nu, h)
        r = matmul(transpose(h), py)
        done = abs(r(1, 1)*r(2, 2) - r(1, 2)*r(2, 1)) > 1.0e-6_dp*sum(r**2)
        if (.not. done) return
        r = matmul(transpose(h), py - x*(apy + py))
        det = r(1, 1)*r(2, 2) - r(1, 2)*r(2, 1)
        r_inv = reshape([r(2, 2), -r(2, 1), -r(1, 2), r(1, 1)], [2, 2])/det
        y = h + exp(-2.0_dp*x)*matmul(qy - x*(aqy - qy), r_inv)
        call orthonormalise(y)
    end subroutine split_step

    !> The decaying states of a half-space of relative modulus g = G/G_1 (module header).
    pure subroutine halfspace_states(g, nu, y)
        real(dp), intent(in) :: g, nu
        real(dp), intent(out) :: y(4, 2)
        y(1, :) = -[1.0_dp - nu, -0.5_dp*(1.0_dp - 2.0_dp*nu)]/g
        y(2, :) = -[-0.5_dp*(1.0_dp - 2.0_dp*nu), 1.0_dp - nu]/g
        y(3, :) = [1.0_dp, 0.0_dp]
        y(4, :) = [0.0_dp, 1.0_dp]
        call orthonormalise(y)
    end subroutine halfspace_states

    !> A_j y for the layer of relative modulus g and kappa = 3 - 4 nu (module header).
    pure function apply_a(y, g, kappa) result(ay)
        real(dp), intent(in) :: y(4, 2), g, kappa
        real(dp) :: ay(4, 2)
        real(dp) :: a1, a2, a3
        a1 = (3.0_dp - kappa)/(kappa + 1.0_dp)
        a2 = (kappa - 1.0_dp)/(kappa + 1.0_dp)
        a3 = 8.0_dp/(kappa + 1.0_dp)
        ay(1, :) = y(2, :) + y(3, :)/g
        ay(2, :) = -a1*y(1, :) + a2*y(4, :)/g
        ay(3, :) = a3*g*y(1, :) + a1*y(4, :)
        ay(4, :) = -y(3, :)
    end function apply_a

    !> c0..c3 of exp(-x A) (module header), all times one positive factor (1 or e^(-x)).
    pure function step_coefficients(x) result(c)
        real(dp), intent(in) :: x
        real(dp) :: c(4)
        real(dp) :: ch, sh, e2
        if (x < x_series) then
            ch = cosh(x)
            sh = sinh(x)
            c(4) = 0.5_dp*cubic_series(x)
        else
            e2 = exp(-2.0_dp*x)
            ch = 0.5_dp*(1.0_dp + e2)
            sh = 0.5_dp*(1.0_dp - e2)
            c(4) = 0.5_dp*(x*ch - sh)
        end if
        c(1) = ch - 0.5_dp*x*sh
        c(2) = sh - c(4)
        c(3) = 0.5_dp*x*sh
    end function step_coefficients

    !> x cosh x - sinh x = sum_{n>=1} 2n x^(2n+1)/(2n+1)! for 0 <= x < 1 (to round-off).
    pure real(dp) function cubic_series(x) result(total)
        real(dp), intent(in) :: x
        real(dp) :: term, x2
        integer :: n
        x2 = x*x
        term = x       ! x^(2n+1)/(2n+1)! for n = 0
        total = 0.0_dp
        terms: do n = 1, 12
            term = term*x2/real((2*n)*(2*n + 1), dp)
            total = total + real(2*n, dp)*term
        end do terms
    end function cubic_series

    !> Orthonormal columns spanning the same plane (Gram–Schmidt, twice).
    pure subroutine orthonormalise(y)
        real(dp), intent(inout) :: y(4, 2)
        integer :: pass
        y(:, 1) = y(:, 1)/norm2(y(:, 1))
        passes: do pass = 1, 2
            y(:, 2) = y(:, 2) - dot_product(y(:, 1), y(:, 2))*y(:, 1)
        end do passes
        y(:, 2) = y(:, 2)/norm2(y(:, 2))
    end subroutine orthonormalise

    !> Unit vector of the SH states admitted at the surface (module header).
    pure subroutine sh_subspace(ground, s, v)
        type(layered_ground_t), intent(in) :: ground
        real(dp), intent(in) :: s
        real(dp), intent(out) :: v(2)
        real(dp) :: g_1, g, x, ch, sh, e2, w(2)
        integer :: j
        g_1 = ground%shear_modulus(1)
        select case (ground%base)
        case (BASE_ROUGH)
            v = [0.0_dp, 1.0_dp]
        case (BASE_SMOOTH)
            v = [1.0_dp, 0.0_dp]
        case default
            v = [-g_1/ground%base_shear_modulus, 1.0_dp]
        end select
        layers: do j = size(ground%thickness), 1, -1
            g = ground%shear_modulus(j)/g_1
            x = s*ground%thickness(j)
            if (x > x_thick) then
                v = [-1.0_dp/g, 1.0_dp]
            else
                e2 = exp(-2.0_dp*x)
                ch = 0.5_dp*(1.0_dp + e2)
                sh = -0.5_dp*expm1_neg(2.0_dp*x)
                w = [ch*v(1) - sh*v(2)/g, -g*sh*v(1) + ch*v(2)]
                v = w
            end if
            v = v/norm2(v)
        end do layers
    end subroutine sh_subspace

    !> exp(-t) - 1 without cancellation for t >= 0.
    pure real(dp) function expm1_neg(t)
        real(dp), intent(in) :: t
        real(dp) :: term
        integer :: n
        if (t > 0.5_dp) then
            expm1_neg = exp(-t) - 1.0_dp
            return
        end if
        term = 1.0_dp
        expm1_neg = 0.0_dp
        terms: do n = 1, 20
            term = -term*t/real(n, dp)
            expm1_neg = expm1_neg + term
        end do terms
    end function expm1_neg
end module layered_compliance
