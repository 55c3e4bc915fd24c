!> Galerkin flexibility of an elastic half-space under axisymmetric surface tractions (PLATE).
!!
!! Conventions (SPEC §1, kernel reference §0): z down into the soil; sigma_z = p > 0 compressive
!! traction exerted by the plate on the half-space, sigma_x = q radial traction on the
!! half-space (outward positive); u_r outward, w down positive. Units: G_f [force/length^2],
!! r [length], tractions [force/length^2], displacements [length].
!!
!! Ring kernels (kernel reference §C), ring of radius s with unit line density, field radius r,
!! k = 2 sqrt(rs)/(r+s), m1 = 1 - k^2 = ((r-s)/(r+s))^2 formed directly (precision trap §C.1):
!!   (C1) G_zz = 2(1-nu) s K(k) / (pi G (r+s))
!!   (C2) G_rz = -(1-2nu)/(2G) (s/r) H(r-s)          (u_r due to normal ring)
!!   (C3) G_zr = -(1-2nu)/(2G) H(s-r)                (w due to radial ring)
!!   (C4) G_rr = (1-nu)(r+s)/(2 pi G r) [ (1+m1) K(k) - 2 E(k) ]
!! Logarithmic split used by the quadrature (DLMF 19.12.1–2): with K' = K(k'), E' = E(k'),
!!   K = (K'/pi) ln(1/m1) + analytic,  E = ((K' - E')/pi) ln(1/m1) + analytic,
!!   ln(1/m1) = 2 ln(r+s) - 2 ln|r-s|,
!! so the coefficient of ln|r-s| is -2 C K'/pi in (C1) and -2 C (2E' - k^2 K')/pi in (C4)
!! (C the prefactor); the leading value at s = r is -(1-nu)/(pi G), the plane-strain c_L.
!! K and the bracket of (C4) come from one arithmetic-geometric mean started at
!! k' = |r-s|/(r+s) (no 1 - k^2 formed): (1+m1)K - 2E = K sum_{n>=1} 2^n c_n^2 with
!! c_1 = min(r,s)/(r+s) exact, a sum of positive terms, so (C4) keeps full precision at every
!! k, its k^4 behaviour as k -> 0 included (`agm_terms`); GSL's Carlson forms only where
!! m1 < 1e-20 (their asymptotic branch). The tensor rules of well separated element pairs
!! evaluate the kernels on a grid of radii, the AGM running on vectors of field radii
!! (`ring_grid_values`) and started at (r + s, |r - s|) (`ring_diagonal`: one division per
!! evaluation); they need only (C1) and (C4): for r < s, (C2) is 0 and (C3) a constant
!! (split_kernel_t%coupling).
!!
!! Operator: T_ab = int_0^a int_0^a g_a(r) G(r,s) g_b(s) ds 2 pi r dr, blocks
!! [T_xx T_xz; T_zx T_zz] (bx coefficients first); symmetric by reciprocity r G_ij(r,s) =
!! s G_ji(s,r), positive definite. All kernels are homogeneous of degree 0, G(r,s) = F(s/r):
!! the element at the axis is integrated in ratio coordinates (see singular_quadrature).
module halfspace_plate
    use iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, add_context, EXIT_INPUT
    use gsl_wrappers, only: elliptic_ke_m1
    use shape_functions, only: basis_t
    use singular_quadrature, only: split_kernel_t, assemble_split_kernel_reference, &
                                   displacement_split_kernel
    use galerkin_assembly, only: assemble_split_kernel
    implicit none
    private

    public :: assemble_plate_flexibility, plate_surface_displacement, ring_kernels
    public :: elliptic_ke_agm

    real(dp), parameter :: agm_limit = 1.0e-20_dp  !! m1 below which GSL's asymptotic branch is used
    integer, parameter :: chunk = 32               !! field radii per vectorised AGM sweep

    !> Ring kernels (C1)–(C4) of one soil.
    type, extends(split_kernel_t) :: ring_kernel_t
        real(dp) :: g_f = 1.0_dp      !! shear modulus [force/length^2]
        real(dp) :: nu_f = 0.0_dp     !! Poisson's ratio
    contains
        procedure :: values => ring_values
        procedure :: grid_values => ring_grid_values
        procedure :: log_length => ring_log_length
    end type ring_kernel_t

contains

    !> Galerkin flexibility T of the half-space on the disk r in [0, a] (module header).
    subroutine assemble_plate_flexibility(bx, bz, g_f, nu_f, t_mat, err, reference, n_kernel, &
                                          far_digits, pairwise)
        type(basis_t), intent(in) :: bx                 !! basis of sigma_x (radial shear)
        type(basis_t), intent(in) :: bz                 !! basis of sigma_z (pressure), same mesh
        real(dp), intent(in) :: g_f                     !! soil shear modulus [force/length^2]
        real(dp), intent(in) :: nu_f                    !! soil Poisson's ratio, [0, 0.5]
        real(dp), allocatable, intent(out) :: t_mat(:, :)  !! (nx+nz)^2 [length^3/force]
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        logical, intent(in), optional :: reference      !! slow pair-by-pair reference assembly
        integer(int64), intent(out), optional :: n_kernel  !! kernel evaluations (point pairs)
        real(dp), intent(in), optional :: far_digits    !! accuracy studies: digits of the far
                                                        !! rules (galerkin_assembly)
        logical, intent(in), optional :: pairwise       !! every far pair pair by pair, no
                                                        !! interpolated blocks (the assembly
                                                        !! of main fc09087; tests, benchmarks)
        type(ring_kernel_t) :: kernel
        logical :: use_reference
        call new_ring_kernel(kernel, g_f, nu_f, err)
        if (allocated(err)) return
        if (bx%ne >= 1 .and. allocated(bx%x)) then
            if (bx%x(0) /= 0.0_dp) then
                call new_error(err, EXIT_INPUT, &
                               'plate half-space operator: mesh must start at r = 0')
                return
            end if
        end if
        use_reference = .false.
        if (present(reference)) use_reference = reference
        if (use_reference) then
            call assemble_split_kernel_reference(kernel, bx, bz, t_mat, err, n_kernel)
        else
            call assemble_split_kernel(kernel, bx, bz, t_mat, err, n_kernel, far_digits, pairwise)
        end if
        if (allocated(err)) call add_context(err, 'plate half-space operator')
    end subroutine assemble_plate_flexibility

    !> Surface displacements u_r, w at the radii r_eval under sigma_x = sum rx_b g_b,
    !! sigma_z = sum rz_b g_b: u_i(r) = int_0^a G_ij(r, s) sigma_j(s) ds, (C1)–(C4).
    subroutine plate_surface_displacement(bx, bz, rx, rz, g_f, nu_f, r_eval, u_r, u_z, err)
        type(basis_t), intent(in) :: bx            !! basis of sigma_x
        type(basis_t), intent(in) :: bz            !! basis of sigma_z
        real(dp), intent(in) :: rx(:)              !! sigma_x coefficients [force/length^2]
        real(dp), intent(in) :: rz(:)              !! sigma_z coefficients [force/length^2]
        real(dp), intent(in) :: g_f                !! soil shear modulus
        real(dp), intent(in) :: nu_f               !! soil Poisson's ratio
        real(dp), intent(in) :: r_eval(:)          !! radii >= 0 [length]
        real(dp), intent(out) :: u_r(:)            !! radial displacement, outward [length]
        real(dp), intent(out) :: u_z(:)            !! settlement, down positive [length]
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(ring_kernel_t) :: kernel
        real(dp), allocatable :: r_use(:)
        real(dp) :: a
        call new_ring_kernel(kernel, g_f, nu_f, err)
        if (allocated(err)) return
        if (any(r_eval < 0.0_dp)) then
            call new_error(err, EXIT_INPUT, 'plate surface displacement: negative radius')
            return
        end if
        a = 0.0_dp
        if (allocated(bx%x)) a = bx%x(bx%ne)
        ! radii within 1e-15 a of the axis are the axis (G(r, s) -> G(0, s) with error O(r/s))
        r_use = merge(0.0_dp, r_eval, r_eval <= 1.0e-15_dp*a)
        call displacement_split_kernel(kernel, bx, bz, rx, rz, r_use, u_r, u_z, err)
        if (allocated(err)) call add_context(err, 'plate half-space operator')
    end subroutine plate_surface_displacement

    !> The ring kernels (C1)–(C4) at field radius r >= 0 due to a ring of radius s > 0.
    subroutine ring_kernels(r, s, g_f, nu_f, g_zz, g_rr, g_rz, g_zr, err)
        real(dp), intent(in) :: r           !! field radius [length]
        real(dp), intent(in) :: s           !! ring radius [length], s /= r
        real(dp), intent(in) :: g_f         !! shear modulus
        real(dp), intent(in) :: nu_f        !! Poisson's ratio
        real(dp), intent(out) :: g_zz       !! (C1) w due to normal ring
        real(dp), intent(out) :: g_rr       !! (C4) u_r due to radial ring
        real(dp), intent(out) :: g_rz       !! (C2) u_r due to normal ring
        real(dp), intent(out) :: g_zr       !! (C3) w due to radial ring
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(ring_kernel_t) :: kernel
        real(dp) :: f(2, 2), p(2, 2)
        call new_ring_kernel(kernel, g_f, nu_f, err)
        if (allocated(err)) return
        call ring_point(kernel, r, s, .false., f, p, err)
        if (allocated(err)) return
        g_rr = f(1, 1)
        g_rz = f(1, 2)
        g_zr = f(2, 1)
        g_zz = f(2, 2)
    end subroutine ring_kernels

    !> Validated kernel object.
    pure subroutine new_ring_kernel(kernel, g_f, nu_f, err)
        type(ring_kernel_t), intent(out) :: kernel
        real(dp), intent(in) :: g_f, nu_f
        type(error_t), allocatable, intent(out) :: err
        if (.not. g_f > 0.0_dp .or. .not. (nu_f >= 0.0_dp .and. nu_f <= 0.5_dp)) then
            call new_error(err, EXIT_INPUT, 'half-space needs G_f > 0 and nu_f in [0, 0.5]')
            return
        end if
        kernel%g_f = g_f
        kernel%nu_f = nu_f
        kernel%homogeneous = .true.
        kernel%measure = [0.0_dp, 2.0_dp*pi]     ! 2 pi r
        ! r < s: (C2) G_rz = 0 and (C3) G_zr = -(1-2nu)/(2G), constants
        kernel%constant_coupling = .true.
        kernel%coupling = [0.0_dp, -(1.0_dp - 2.0_dp*nu_f)/(2.0_dp*g_f)]
    end subroutine new_ring_kernel

    !> The split is analytic for |r - s| <= r/2 about a singular point r (K' singular at rs = 0).
    pure real(dp) function ring_log_length(self, x_sing)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x_sing
        ring_log_length = 0.5_dp*x_sing
    end function ring_log_length

    !> Kernel values at a batch of points (interface of split_kernel_t): chunks of regular
    !! points (regular_pair) on vectors (ring_chunk, ring_log_chunk), a chunk with another
    !! point (on the axis, or next to the limits of the AGM) point by point (ring_point).
    subroutine ring_values(self, x, xi, with_log, f, p, err)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), xi(:)
        logical, intent(in) :: with_log(:)
        real(dp), intent(out) :: f(:, :, :), p(:, :, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: inv_r(chunk), f_chunk(chunk, 2, 2), p_chunk(chunk, 2, 2)
        integer :: k0, k1, n, k
        chunks: do k0 = 1, size(x), chunk
            k1 = min(size(x), k0 + chunk - 1)
            n = k1 - k0 + 1
            if (.not. all(regular_pair(x(k0:k1), xi(k0:k1)))) then
                points: do k = k0, k1
                    call ring_point(self, x(k), xi(k), with_log(k), f(:, :, k), p(:, :, k), err)
                    if (allocated(err)) return
                end do points
                cycle chunks
            end if
            inv_r(1:n) = 1.0_dp/x(k0:k1)
            call ring_chunk(self, x(k0:k1), inv_r(1:n), xi(k0:k1), f_chunk(1:n, :, :))
            p_chunk(1:n, :, :) = 0.0_dp
            if (any(with_log(k0:k1))) call ring_log_chunk(self, x(k0:k1), xi(k0:k1), &
                                                          p_chunk(1:n, :, :))
            unpack: do k = 1, n
                f(:, :, k0 + k - 1) = f_chunk(k, :, :)
                p(:, :, k0 + k - 1) = 0.0_dp
                if (with_log(k0 + k - 1)) p(:, :, k0 + k - 1) = p_chunk(k, :, :)
            end do unpack
        end do chunks
    end subroutine ring_values

    !> Both radii positive and neither m1 = k'^2 nor m = k^2 below agm_limit: the AGM of
    !! ring_chunk and ring_log_chunk applies.
    elemental logical function regular_pair(r, s)
        real(dp), intent(in) :: r, s
        regular_pair = .false.
        if (.not. (r > 0.0_dp .and. s > 0.0_dp)) return
        regular_pair = ((r - s)/(r + s))**2 >= agm_limit .and. 4.0_dp*r*s/(r + s)**2 >= agm_limit
    end function regular_pair

    !> Kernel values on the grid of field radii x(k) and ring radii s(l) of a well separated
    !! element pair (no x(k) = s(l), all > 0): f(k, l, i, i) = G_ii(x(k), s(l)), the field
    !! radii in chunks so that the AGM runs on vectors (interface of split_kernel_t; the
    !! coupling kernels are the constants kernel%coupling there and are not filled).
    subroutine ring_grid_values(self, x, s, f, err)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), s(:)
        real(dp), intent(out) :: f(:, :, :, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: inv_x(chunk), ring(chunk)
        integer :: k0, k1, n, l
        chunks: do k0 = 1, size(x), chunk
            k1 = min(size(x), k0 + chunk - 1)
            n = k1 - k0 + 1
            inv_x(1:n) = 1.0_dp/x(k0:k1)
            sources: do l = 1, size(s)
                ring(1:n) = s(l)
                call ring_diagonal(self, x(k0:k1), inv_x(1:n), ring(1:n), f(k0:k1, l, 1, 1), &
                                   f(k0:k1, l, 2, 2))
            end do sources
        end do chunks
    end subroutine ring_grid_values

    !> (C1)–(C4) at the regular pairs (regular_pair) of field radius r(k) and ring radius s(k),
    !! at most `chunk` of them: f(k, i, j) = G_ij(r(k), s(k)).
    pure subroutine ring_chunk(kernel, r, inv_r, s, f)
        type(ring_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: r(:)
        real(dp), intent(in) :: inv_r(:)        !! 1/r(k)
        real(dp), intent(in) :: s(:)
        real(dp), intent(out) :: f(:, :, :)
        real(dp) :: c_step
        c_step = -(1.0_dp - 2.0_dp*kernel%nu_f)/(2.0_dp*kernel%g_f)
        call ring_diagonal(kernel, r, inv_r, s, f(:, 1, 1), f(:, 2, 2))
        f(:, 1, 2) = merge(c_step*(s*inv_r), 0.0_dp, r > s)                   ! (C2)
        f(:, 2, 1) = merge(c_step, 0.0_dp, s > r)                             ! (C3)
    end subroutine ring_chunk

    !> (C4) and (C1) at the regular pairs (regular_pair) of field radius r(k) and ring radius
    !! s(k), at most `chunk` of them, from the AGM started at (r + s, |r - s|) (agm_sums, the
    !! AGM of agm_terms times r + s: no division by r + s): M = (r + s) M(1, k'), so
    !! K = pi (r + s)/(2 M) and K sum_{n>=1} 2^n c_n^2 = pi S/(2 M (r + s)) with S the sum of
    !! the unscaled terms, C_1 = min(r, s) exact; then (C1) = c_zz s pi/(2 M) and
    !! (C4) = c_rr pi S/(2 M r).
    pure subroutine ring_diagonal(kernel, r, inv_r, s, g_rr, g_zz)
        type(ring_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: r(:)
        real(dp), intent(in) :: inv_r(:)        !! 1/r(k) (shared by the rings of a grid)
        real(dp), intent(in) :: s(:)
        real(dp), intent(out) :: g_rr(:)        !! (C4)
        real(dp), intent(out) :: g_zz(:)        !! (C1)
        ! fixed size: automatic arrays would be allocated on the heap at every call
        real(dp), dimension(chunk) :: a, b, c, inv_mean, rr_sum
        real(dp) :: c_zz, c_rr
        integer :: n
        c_zz = (1.0_dp - kernel%nu_f)/kernel%g_f                    ! 2(1-nu)/(pi G) pi/2
        c_rr = (1.0_dp - kernel%nu_f)/(4.0_dp*kernel%g_f)           ! (1-nu)/(2 pi G) pi/2
        n = size(r)
        a(1:n) = r + s
        b(1:n) = abs(r - s)
        c(1:n) = min(r, s)
        call agm_sums(n, a, b, c, inv_mean, rr_sum)
        g_zz = c_zz*s*inv_mean(1:n)
        g_rr = c_rr*rr_sum(1:n)*inv_mean(1:n)*inv_r
    end subroutine ring_diagonal

    !> Coefficients of ln|r - s| (module header) at regular pairs (regular_pair), at most
    !! `chunk`: K(k') and E(k') from agm_terms started at the modulus k = 2 sqrt(rs)/(r+s).
    pure subroutine ring_log_chunk(kernel, r, s, p)
        type(ring_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: r(:), s(:)
        real(dp), intent(out) :: p(:, :, :)
        real(dp), dimension(chunk) :: inv_total, k_mod, c1, m1, m, k_p, sum_p, e_p, c_zz, c_rr
        integer :: n
        n = size(r)
        inv_total(1:n) = 1.0_dp/(r + s)
        k_mod(1:n) = 2.0_dp*sqrt(r*s)*inv_total(1:n)
        c1(1:n) = 0.5_dp*(1.0_dp - k_mod(1:n))
        m1(1:n) = ((r - s)*inv_total(1:n))**2
        m(1:n) = min(1.0_dp, 4.0_dp*r*s*inv_total(1:n)**2)
        call agm_terms(k_mod(1:n), c1(1:n), k_p(1:n), sum_p(1:n))
        e_p(1:n) = k_p(1:n)*(1.0_dp - 0.5_dp*(m1(1:n) + sum_p(1:n)))
        c_zz(1:n) = 2.0_dp*(1.0_dp - kernel%nu_f)*s*inv_total(1:n)/(pi*kernel%g_f)
        c_rr(1:n) = (1.0_dp - kernel%nu_f)*(r + s)/(2.0_dp*pi*kernel%g_f*r)
        p(:, 1, 2) = 0.0_dp
        p(:, 2, 1) = 0.0_dp
        call log_terms(c_zz(1:n), c_rr(1:n), m(1:n), k_p(1:n), e_p(1:n), p(:, 2, 2), p(:, 1, 1))
    end subroutine ring_log_chunk

    !> The coefficients of ln|r - s| in (C1) and (C4) from K(k') and E(k') (module header).
    elemental subroutine log_terms(c_zz, c_rr, m, k_p, e_p, p_zz, p_rr)
        real(dp), intent(in) :: c_zz, c_rr    !! prefactors of (C1) and (C4)
        real(dp), intent(in) :: m             !! k^2
        real(dp), intent(in) :: k_p, e_p      !! K(k'), E(k')
        real(dp), intent(out) :: p_zz, p_rr
        p_zz = -2.0_dp*c_zz*k_p/pi
        p_rr = -2.0_dp*c_rr*(2.0_dp*e_p - m*k_p)/pi
    end subroutine log_terms

    !> f(i, j) = G_ij(r, s) (1 = radial, 2 = normal) and p = coefficients of ln|r - s| at one
    !! point, the axis limits and GSL's asymptotic forms (m1 or m below agm_limit) included.
    subroutine ring_point(kernel, r, s, with_log, f, p, err)
        type(ring_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: r, s
        logical, intent(in) :: with_log
        real(dp), intent(out) :: f(2, 2), p(2, 2)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: g, nu, c_step, total, m, m1, k_m, e_m, k_p, e_p, c_zz, c_rr
        real(dp) :: r_one(1), inv_r_one(1), s_one(1), f_one(1, 2, 2)
        g = kernel%g_f
        nu = kernel%nu_f
        c_step = -(1.0_dp - 2.0_dp*nu)/(2.0_dp*g)
        p = 0.0_dp
        f(1, 2) = 0.0_dp
        f(2, 1) = 0.0_dp
        if (r > s) f(1, 2) = c_step*(s/r)          ! (C2)
        if (s > r) f(2, 1) = c_step                ! (C3)
        total = r + s
        if (r <= 0.0_dp .or. s <= 0.0_dp) then
            ! limits: G_zz(0, s) = (1-nu)/G, G_zz(r, 0) = 0, G_rr -> 0 at either end
            f(2, 2) = 0.0_dp
            if (s > 0.0_dp) f(2, 2) = (1.0_dp - nu)/g
            f(1, 1) = 0.0_dp
            return
        end if
        m1 = ((r - s)/total)**2
        m = min(1.0_dp, 4.0_dp*r*s/total**2)     ! k^2, may round above 1 next to r = s
        c_zz = 2.0_dp*(1.0_dp - nu)*s/(pi*g*total)
        c_rr = (1.0_dp - nu)*total/(2.0_dp*pi*g*r)
        if (m1 >= agm_limit) then
            r_one(1) = r
            inv_r_one(1) = 1.0_dp/r
            s_one(1) = s
            call ring_chunk(kernel, r_one, inv_r_one, s_one, f_one)
            f = f_one(1, :, :)
        else
            call elliptic_ke_m1(m1, k_m, e_m, err)
            if (allocated(err)) return
            f(2, 2) = c_zz*k_m                                             ! (C1)
            f(1, 1) = c_rr*((1.0_dp + m1)*k_m - 2.0_dp*e_m)                ! (C4)
        end if
        if (.not. with_log) return
        ! K(k'), E(k'): complementary parameter m, complementary modulus k = 2 sqrt(rs)/(r+s)
        if (m >= agm_limit) then
            call elliptic_ke_agm(2.0_dp*sqrt(r*s)/total, m1, k_p, e_p)
        else
            call elliptic_ke_m1(m, k_p, e_p, err)
            if (allocated(err)) return
        end if
        call log_terms(c_zz, c_rr, m, k_p, e_p, p(2, 2), p(1, 1))
    end subroutine ring_point

    !> K(k) and E(k) from agm_terms, given the complementary modulus k' = sqrt(1 - k^2) (formed
    !! without cancellation by the caller) and k^2: E = K (1 - (k^2 + sum_{n>=1} 2^n c_n^2)/2)
    !! (DLMF 19.8.6). Relative error a few ulps in K, and in E except as k -> 1, where the
    !! bracket cancels to about K ulps (E enters the kernels there next to 2K, so the kernels
    !! keep full precision). Checked against GSL's Carlson forms by the plate tests.
    pure subroutine elliptic_ke_agm(k_comp, m, k_val, e_val)
        real(dp), intent(in) :: k_comp      !! k' in (0, 1]
        real(dp), intent(in) :: m           !! k^2 = 1 - k'^2
        real(dp), intent(out) :: k_val      !! K(k)
        real(dp), intent(out) :: e_val      !! E(k)
        real(dp) :: kc_one(1), c1_one(1), k_one(1), sum_one(1)
        kc_one(1) = k_comp
        c1_one(1) = 0.5_dp*(1.0_dp - k_comp)
        call agm_terms(kc_one, c1_one, k_one, sum_one)
        k_val = k_one(1)
        e_val = k_val*(1.0_dp - 0.5_dp*(m + sum_one(1)))
    end subroutine elliptic_ke_agm

    !> The arithmetic-geometric mean M(1, k') of each entry (DLMF 19.8.1: a_0 = 1, b_0 = k',
    !! a_(n+1) = (a_n + b_n)/2 = a_n - c_(n+1), b_(n+1) = sqrt(a_n b_n), c_(n+1) = (a_n - b_n)/2)
    !! and its terms: K(k) = pi/(2 M) and rr_sum = sum_{n>=1} 2^n c_n^2, so that
    !! (1 + k'^2) K - 2 E = K rr_sum and E = K (1 - (k^2 + rr_sum)/2) (DLMF 19.8.6, c_0 = k).
    !! c_1 is given (formed exactly by the caller where it can be); the later c_n may carry an
    !! absolute error of an ulp of a_n, which changes rr_sum by an ulp relative to its first
    !! term 2 c_1^2 only (c_2 <= c_1^2/(4 a_2)). Once c = c_(n+1) <= agm_tail a_n (0.02), the
    !! rest is closed (agm_sums): (a_(n+1), b_(n+1)) = a_(n+1) (1, sqrt(1 - x^2)) with
    !! x = c/a_(n+1) <= 0.0205, whose AGM is a_(n+1) pi/(2 K(x)) and whose terms (c_(n+1)
    !! = a_(n+1) x first) sum to a_(n+1)^2 2 (1 - E(x)/K(x)) (DLMF 19.8.6 again), both as
    !! series in t = x^2 <= 4.2e-4: 2 K(x)/pi = 1 + t/4 + 9t^2/64 + 25t^3/256 + 1225t^4/16384
    !! + O(0.061 t^5) and 2 (1 - E/K) = t (1 + t/8 + t^2/16 + 41t^3/1024 + 59t^4/2048 +
    !! O(0.023 t^5)), truncated below 1e-18: one or two square roots fewer than the steps to
    !! c <= 1e-17 a (2.2 steps instead of 3.2 on average over the far pairs of N_e = 100).
    !! All entries (at most `chunk`) step together, so the loop runs on vectors.
    pure subroutine agm_terms(k_comp, c1, k_val, rr_sum)
        real(dp), intent(in) :: k_comp(:)   !! k' in (0, 1]
        real(dp), intent(in) :: c1(:)       !! c_1 = (1 - k')/2
        real(dp), intent(out) :: k_val(:)   !! K(k)
        real(dp), intent(out) :: rr_sum(:)  !! sum_{n>=1} 2^n c_n^2
        real(dp), dimension(chunk) :: a, b, c, inv_mean, sums  ! fixed size: see ring_diagonal
        integer :: m
        m = size(k_comp)
        a(1:m) = 1.0_dp
        b(1:m) = k_comp
        c(1:m) = c1
        call agm_sums(m, a, b, c, inv_mean, sums)
        k_val = 0.5_dp*pi*inv_mean(1:m)
        rr_sum = sums(1:m)
    end subroutine agm_terms

    !> The AGM M(a_0, b_0) of the first m entries (a_0 >= b_0 > 0 in a, b and c_1 =
    !! (a_0 - b_0)/2 in c, formed exactly by the caller where it can be; overwritten) as 1/M,
    !! and sum_{n>=1} 2^n c_n^2, with the closed tail of agm_terms (scale-free: c_(n+1) <=
    !! agm_tail a_n). All entries step together: one vector loop per step, which also forms
    !! the next c. Fixed-size arrays of the caller: no copies, no heap temporaries.
    pure subroutine agm_sums(m, a, b, c, inv_mean, rr_sum)
        integer, intent(in) :: m
        real(dp), intent(inout) :: a(chunk), b(chunk), c(chunk)
        real(dp), intent(out) :: inv_mean(chunk)  !! 1/M(a_0, b_0)
        real(dp), intent(out) :: rr_sum(chunk)    !! sum_{n>=1} 2^n c_n^2
        real(dp), parameter :: agm_tail = 0.02_dp
        real(dp) :: weight, root, inv_a, t
        integer :: n, k
        rr_sum(1:m) = 0.0_dp
        weight = 2.0_dp
        agm: do n = 1, 64
            if (all(c(1:m) <= agm_tail*a(1:m))) exit agm
            lanes: do k = 1, m
                rr_sum(k) = rr_sum(k) + weight*c(k)*c(k)
                root = sqrt(a(k)*b(k))
                a(k) = a(k) - c(k)
                b(k) = root
                c(k) = 0.5_dp*(a(k) - b(k))
            end do lanes
            weight = 2.0_dp*weight
        end do agm
        ! the rest in closed form (agm_terms): x = c_(n+1)/a_(n+1) <= 0.0205, t = x^2
        tail: do k = 1, m
            inv_a = 1.0_dp/(a(k) - c(k))                        ! 1/a_(n+1)
            t = (c(k)*inv_a)**2
            inv_mean(k) = inv_a*(1.0_dp + t*(0.25_dp + t*(9.0_dp/64.0_dp + &
                          t*(25.0_dp/256.0_dp + t*(1225.0_dp/16384.0_dp)))))
            rr_sum(k) = rr_sum(k) + weight*c(k)*c(k)*(1.0_dp + t*(0.125_dp + t*(0.0625_dp + &
                        t*(41.0_dp/1024.0_dp + t*(59.0_dp/2048.0_dp)))))
        end do tail
    end subroutine agm_sums
end module halfspace_plate
