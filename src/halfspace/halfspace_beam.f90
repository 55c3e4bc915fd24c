!> Galerkin flexibility of an elastic half-space under a beam of width b (BEAM, SPEC §2–3).
!!
!! Conventions (SPEC §1, kernel reference §0): x along the beam, z down into the soil;
!! sigma_z = p > 0 compressive, sigma_x = q tangential traction on the half-space in +x, both
!! LINE loads [force/length] spread uniformly across the width b; displacements u_x (+x) and
!! w (down) on the centre line y = 0. Units: G_f [force/length^2], lengths [length].
!!
!! Centre-line strip kernels (kernel reference §B.3 (ii)), X = x - xi, h = b/2:
!!   (B9)  k_zz(X) = (1-nu)/(pi G b) asinh(h/|X|)
!!   (B10) k_xx(X) = (1-nu)/(pi G b) asinh(h/|X|) + nu h / (pi G b sqrt(X^2 + h^2))
!!   (B11) k_zx(X) = (1-2nu)/(2 pi G b) atan(h/X)    (w due to tangential load),  k_xz = -k_zx
!! Logarithmic split: asinh(h/|X|) = -ln|X| + ln(h + sqrt(X^2 + h^2)), i.e. the coefficient of
!! ln|X| is -(1-nu)/(pi G b) in (B9) and (B10); the remainder is analytic on the real axis
!! (branch points X = +-i h), so log pieces are kept no longer than h. (B11) jumps by
!! (1-2nu)/(2 G b) at X = 0 (plane-strain value of A4) and is otherwise analytic.
!!
!! Operator: T_ab = int int g_a(x) k(x - xi) g_b(xi) dxi dx over [-l/2, l/2]^2, blocks
!! [T_xx T_xz; T_zx T_zz] (bx coefficients first); symmetric (k_xz(X) = -k_zx(X) = k_zx(-X)),
!! positive definite.
module halfspace_beam
    use iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, add_context, EXIT_INPUT
    use shape_functions, only: basis_t
    use singular_quadrature, only: split_kernel_t, assemble_split_kernel_reference, &
                                   displacement_split_kernel
    use galerkin_assembly, only: assemble_split_kernel
    implicit none
    private

    public :: assemble_beam_flexibility, beam_surface_displacement, strip_kernels

    !> Centre-line strip kernels (B9)–(B11) of one soil and width.
    type, extends(split_kernel_t) :: strip_kernel_t
        real(dp) :: g_f = 1.0_dp       !! shear modulus [force/length^2]
        real(dp) :: nu_f = 0.0_dp      !! Poisson's ratio
        real(dp) :: width = 1.0_dp     !! beam width b [length]
    contains
        procedure :: values => strip_values
        procedure :: log_length => strip_log_length
    end type strip_kernel_t

contains

    !> Galerkin flexibility T of the half-space under the beam (module header).
    subroutine assemble_beam_flexibility(bx, bz, g_f, nu_f, width, t_mat, err, reference, &
                                         n_kernel, far_digits)
        type(basis_t), intent(in) :: bx                 !! basis of sigma_x
        type(basis_t), intent(in) :: bz                 !! basis of sigma_z, same mesh
        real(dp), intent(in) :: g_f                     !! soil shear modulus [force/length^2]
        real(dp), intent(in) :: nu_f                    !! soil Poisson's ratio, [0, 0.5]
        real(dp), intent(in) :: width                   !! beam width b [length]
        real(dp), allocatable, intent(out) :: t_mat(:, :)  !! (nx+nz)^2 [length/force]
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        logical, intent(in), optional :: reference      !! slow pair-by-pair reference assembly
        integer(int64), intent(out), optional :: n_kernel  !! kernel evaluations (point pairs)
        real(dp), intent(in), optional :: far_digits    !! accuracy studies: digits of the far
                                                        !! rules (galerkin_assembly)
        type(strip_kernel_t) :: kernel
        logical :: use_reference
        call new_strip_kernel(kernel, g_f, nu_f, width, err)
        if (allocated(err)) return
        use_reference = .false.
        if (present(reference)) use_reference = reference
        if (use_reference) then
            call assemble_split_kernel_reference(kernel, bx, bz, t_mat, err, n_kernel)
        else
            call assemble_split_kernel(kernel, bx, bz, t_mat, err, n_kernel, far_digits)
        end if
        if (allocated(err)) call add_context(err, 'beam half-space operator')
    end subroutine assemble_beam_flexibility

    !> Centre-line displacements u_x, w at x_eval under the line loads sigma_x = sum rx_b g_b,
    !! sigma_z = sum rz_b g_b: u_i(x) = int k_ij(x - xi) sigma_j(xi) dxi, (B9)–(B11).
    subroutine beam_surface_displacement(bx, bz, rx, rz, g_f, nu_f, width, x_eval, u_x, u_z, err)
        type(basis_t), intent(in) :: bx            !! basis of sigma_x
        type(basis_t), intent(in) :: bz            !! basis of sigma_z
        real(dp), intent(in) :: rx(:)              !! sigma_x coefficients [force/length]
        real(dp), intent(in) :: rz(:)              !! sigma_z coefficients [force/length]
        real(dp), intent(in) :: g_f                !! soil shear modulus
        real(dp), intent(in) :: nu_f               !! soil Poisson's ratio
        real(dp), intent(in) :: width              !! beam width b
        real(dp), intent(in) :: x_eval(:)          !! evaluation points [length]
        real(dp), intent(out) :: u_x(:)            !! horizontal displacement, +x [length]
        real(dp), intent(out) :: u_z(:)            !! settlement, down positive [length]
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(strip_kernel_t) :: kernel
        call new_strip_kernel(kernel, g_f, nu_f, width, err)
        if (allocated(err)) return
        call displacement_split_kernel(kernel, bx, bz, rx, rz, x_eval, u_x, u_z, err)
        if (allocated(err)) call add_context(err, 'beam half-space operator')
    end subroutine beam_surface_displacement

    !> The centre-line kernels (B9)–(B11) at X = x - xi /= 0 (line load of unit force per length).
    pure subroutine strip_kernels(x_dist, g_f, nu_f, width, k_zz, k_xx, k_zx)
        real(dp), intent(in) :: x_dist      !! X = x - xi [length]
        real(dp), intent(in) :: g_f         !! shear modulus
        real(dp), intent(in) :: nu_f        !! Poisson's ratio
        real(dp), intent(in) :: width       !! b
        real(dp), intent(out) :: k_zz       !! (B9) w due to normal load
        real(dp), intent(out) :: k_xx       !! (B10) u_x due to tangential load
        real(dp), intent(out) :: k_zx       !! (B11) w due to tangential load (k_xz = -k_zx)
        type(strip_kernel_t) :: kernel
        real(dp) :: f(2, 2), p(2, 2)
        kernel%g_f = g_f
        kernel%nu_f = nu_f
        kernel%width = width
        call strip_point(kernel, x_dist, .false., f, p)
        k_xx = f(1, 1)
        k_zx = f(2, 1)
        k_zz = f(2, 2)
    end subroutine strip_kernels

    !> Validated kernel object.
    pure subroutine new_strip_kernel(kernel, g_f, nu_f, width, err)
        type(strip_kernel_t), intent(out) :: kernel
        real(dp), intent(in) :: g_f, nu_f, width
        type(error_t), allocatable, intent(out) :: err
        if (.not. g_f > 0.0_dp .or. .not. (nu_f >= 0.0_dp .and. nu_f <= 0.5_dp) .or. &
            .not. width > 0.0_dp) then
            call new_error(err, EXIT_INPUT, 'half-space needs G_f > 0, nu_f in [0, 0.5], b > 0')
            return
        end if
        kernel%g_f = g_f
        kernel%nu_f = nu_f
        kernel%width = width
        kernel%translation_invariant = .true.
        kernel%measure = [1.0_dp, 0.0_dp]       ! line loads
    end subroutine new_strip_kernel

    !> The remainder of the split is analytic within |X| < h = b/2 (branch points +-i h).
    pure real(dp) function strip_log_length(self, x_sing)
        class(strip_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x_sing
        strip_log_length = 0.5_dp*self%width
    end function strip_log_length

    !> Kernel values at a batch of points (interface of split_kernel_t).
    subroutine strip_values(self, x, xi, with_log, f, p, err)
        class(strip_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:), xi(:)
        logical, intent(in) :: with_log(:)
        real(dp), intent(out) :: f(:, :, :), p(:, :, :)
        type(error_t), allocatable, intent(out) :: err
        integer :: k
        points: do k = 1, size(x)
            call strip_point(self, x(k) - xi(k), with_log(k), f(:, :, k), p(:, :, k))
        end do points
    end subroutine strip_values

    !> f(i, j) = k_ij(X) (1 = tangential, 2 = normal) and p = coefficients of ln|X|.
    pure subroutine strip_point(kernel, x_dist, with_log, f, p)
        type(strip_kernel_t), intent(in) :: kernel
        real(dp), intent(in) :: x_dist
        logical, intent(in) :: with_log
        real(dp), intent(out) :: f(2, 2), p(2, 2)
        real(dp) :: g, nu, b, h, c_log, ax
        g = kernel%g_f
        nu = kernel%nu_f
        b = kernel%width
        h = 0.5_dp*b
        ax = abs(x_dist)
        c_log = (1.0_dp - nu)/(pi*g*b)
        f(2, 2) = c_log*asinh(h/ax)                                            ! (B9)
        f(1, 1) = f(2, 2) + nu*h/(pi*g*b*sqrt(x_dist**2 + h**2))                ! (B10)
        f(2, 1) = (1.0_dp - 2.0_dp*nu)/(2.0_dp*pi*g*b)*atan(h/x_dist)          ! (B11)
        f(1, 2) = -f(2, 1)
        p = 0.0_dp
        if (with_log) then
            p(1, 1) = -c_log
            p(2, 2) = -c_log
        end if
    end subroutine strip_point
end module halfspace_beam
