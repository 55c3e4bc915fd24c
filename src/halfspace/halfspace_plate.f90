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
!! For k^2 < 0.3, (1+m1)K - 2E = k^4 S(k^2) is summed as a series (no cancellation).
!! K and E come from one arithmetic-geometric mean started at k' = |r-s|/(r+s) (no 1 - k^2
!! formed); GSL's Carlson forms only where m1 < 1e-20 (their asymptotic branch).
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

    real(dp), parameter :: series_limit = 0.3_dp   !! k^2 below which (C4) is summed as a series
    integer, parameter :: n_series = 40            !! terms of S(m): 0.3^40 c_42 < 1e-22
    real(dp), parameter :: agm_limit = 1.0e-20_dp  !! m1 below which GSL's asymptotic branch is used

    !> Ring kernels (C1)–(C4) of one soil.
    type, extends(split_kernel_t) :: ring_kernel_t
        real(dp) :: g_f = 1.0_dp      !! shear modulus [force/length^2]
        real(dp) :: nu_f = 0.0_dp     !! Poisson's ratio
        real(dp) :: series(0:n_series) = 0.0_dp  !! c_(n+2) of rr_series
    contains
        procedure :: values => ring_values
        procedure :: field_weight => ring_field_weight
        procedure :: log_length => ring_log_length
    end type ring_kernel_t

contains

    !> Galerkin flexibility T of the half-space on the disk r in [0, a] (module header).
    subroutine assemble_plate_flexibility(bx, bz, g_f, nu_f, t_mat, err, reference, n_kernel)
        type(basis_t), intent(in) :: bx                 !! basis of sigma_x (radial shear)
        type(basis_t), intent(in) :: bz                 !! basis of sigma_z (pressure), same mesh
        real(dp), intent(in) :: g_f                     !! soil shear modulus [force/length^2]
        real(dp), intent(in) :: nu_f                    !! soil Poisson's ratio, [0, 0.5]
        real(dp), allocatable, intent(out) :: t_mat(:, :)  !! (nx+nz)^2 [length^3/force]
        type(error_t), allocatable, intent(out) :: err
        logical, intent(in), optional :: reference      !! slow pair-by-pair reference assembly
        integer(int64), intent(out), optional :: n_kernel  !! kernel evaluations (point pairs)
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
            call assemble_split_kernel(kernel, bx, bz, t_mat, err, n_kernel)
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
        type(error_t), allocatable, intent(out) :: err
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
        type(error_t), allocatable, intent(out) :: err
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
        call series_coefficients(kernel%series)
    end subroutine new_ring_kernel

    !> Field measure 2 pi r.
    pure real(dp) function ring_field_weight(self, x)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x
        ring_field_weight = 2.0_dp*pi*x
    end function ring_field_weight

    !> The split is analytic for |r - s| <= r/2 about a singular point r (K' singular at rs = 0).
    pure real(dp) function ring_log_length(self, x_sing)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x_sing
        ring_log_length = 0.5_dp*x_sing
    end function ring_log_length

    !> Kernel values at a batch of points (interface of split_kernel_t).
    subroutine ring_values(self, x, xi, with_log, f, p, err)
        class(ring_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), xi(:)
        logical, intent(in) :: with_log(:)
        real(dp), intent(out) :: f(:, :, :), p(:, :, :)
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        points: do k = 1, size(x)
            call ring_point(self, x(k), xi(k), with_log(k), f(:, :, k), p(:, :, k), err)
            if (allocated(err)) return
        end do points
    end subroutine ring_values

    !> f(i, j) = G_ij(r, s) (1 = radial, 2 = normal) and p = coefficients of ln|r - s|.
    subroutine ring_point(kernel, r, s, with_log, f, p, err)
        type(ring_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: r, s
        logical, intent(in) :: with_log
        real(dp), intent(out) :: f(2, 2), p(2, 2)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: g, nu, c_step, total, m, m1, k_m, e_m, k_p, e_p, c_zz, c_rr
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
        if (m1 >= agm_limit) then
            call elliptic_ke_agm(abs(r - s)/total, m, k_m, e_m)
        else
            call elliptic_ke_m1(m1, k_m, e_m, err)
            if (allocated(err)) return
        end if
        c_zz = 2.0_dp*(1.0_dp - nu)*s/(pi*g*total)
        c_rr = (1.0_dp - nu)*total/(2.0_dp*pi*g*r)
        f(2, 2) = c_zz*k_m                                                 ! (C1)
        if (m < series_limit) then
            ! (C4) as (1-nu)/(2 pi G) 16 r s^2/(r+s)^3 S(m), exact rewriting of c_rr m^2 S(m)
            f(1, 1) = (1.0_dp - nu)/(2.0_dp*pi*g)*16.0_dp*r*(s/total)**2/total* &
                      rr_series(kernel%series, m)
        else
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
        p(2, 2) = -2.0_dp*c_zz*k_p/pi
        p(1, 1) = -2.0_dp*c_rr*(2.0_dp*e_p - m*k_p)/pi
    end subroutine ring_point

    !> K(k) and E(k) by the arithmetic-geometric mean (DLMF 19.8.1, 19.8.6), given the
    !! complementary modulus k' = sqrt(1 - k^2) (formed without cancellation by the caller) and
    !! k^2: K = pi / (2 M(1, k')), E = K (1 - sum_{n>=0} 2^(n-1) c_n^2), c_0^2 = k^2,
    !! c_(n+1) = (a_n - b_n)/2. One pass gives both; quadratic convergence (at most 7 steps for
    !! k' >= 1e-10). Relative error a few ulps in K, and in E except as k -> 1, where 1 - sum
    !! cancels to about K ulps (E enters the kernels there next to 2K, so the kernels keep full
    !! precision). Checked against GSL's Carlson forms by the plate tests.
    pure subroutine elliptic_ke_agm(k_comp, m, k_val, e_val)
        real(dp), intent(in) :: k_comp      !! k' in (0, 1]
        real(dp), intent(in) :: m           !! k^2 = 1 - k'^2
        real(dp), intent(out) :: k_val      !! K(k)
        real(dp), intent(out) :: e_val      !! E(k)
        real(dp) :: a, b, a_next, c, weight, total
        integer :: n
        a = 1.0_dp
        b = k_comp
        weight = 0.5_dp
        total = 0.5_dp*m
        agm: do n = 1, 64
            c = 0.5_dp*(a - b)
            weight = 2.0_dp*weight
            total = total + weight*c*c
            a_next = a - c
            if (c <= 2.0e-9_dp*a) then
                ! the next c is below c^2/(4a) <= 1e-18 a: a_next is M(1, k') to rounding
                a = a_next
                exit agm
            end if
            b = sqrt(a*b)
            a = a_next
        end do agm
        k_val = 0.5_dp*pi/a
        e_val = k_val*(1.0_dp - total)
    end subroutine elliptic_ke_agm

    !> S(m) = ((2-m)K - 2E)/m^2 = sum_{n>=2} c_n m^(n-2) by Horner's rule (m < series_limit).
    pure real(dp) function rr_series(c, m) result(total)
        real(dp), intent(in) :: c(0:n_series)    !! c_(n+2), series_coefficients
        real(dp), intent(in) :: m
        integer :: n
        total = c(n_series)
        horner: do n = n_series - 1, 0, -1
            total = total*m + c(n)
        end do horner
    end function rr_series

    !> c_n = (pi/2)(a_n 4n/(2n-1) - a_{n-1}), a_n = ((1/2)_n/n!)^2, n = 2..n_series+2, from the
    !! hypergeometric series of K and E (DLMF 19.5.1–2); stored as c(n - 2).
    pure subroutine series_coefficients(c)
        real(dp), intent(out) :: c(0:n_series)
        real(dp) :: a_prev, a_n
        integer :: n
        a_prev = 0.25_dp                  ! a_1
        terms: do n = 2, n_series + 2
            a_n = a_prev*(real(2*n - 1, dp)/real(2*n, dp))**2
            c(n - 2) = 0.5_dp*pi*(a_n*real(4*n, dp)/real(2*n - 1, dp) - a_prev)
            a_prev = a_n
        end do terms
    end subroutine series_coefficients
end module halfspace_plate
