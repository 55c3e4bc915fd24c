!> Fortran face of GSL: real(dp) in, error_t out, status always checked.
!!
!! Complete elliptic integrals are taken in Carlson's symmetric form (DLMF 19.25.1) with the
!! COMPLEMENTARY parameter m1 = 1 - k^2 as argument, so that K and E stay accurate as k -> 1
!! (ring loads at r -> s; see doc/halfspace_kernels.md §C.1):
!!   K(k) = R_F(0, m1, 1),   E(k) = R_F(0, m1, 1) - (k^2/3) R_D(0, m1, 1)   (m1 >= 1/2),
!!   E(k) = (m1/3) (R_D(0, m1, 1) + R_D(0, 1, m1))                           (m1 < 1/2),
!! the second form free of the cancellation of the first as k -> 1.
!!
!! Adaptive quadrature: QAGS (QUADPACK, Piessens et al. 1983: 21-point Gauss–Kronrod with
!! epsilon-algorithm extrapolation, for integrable end-point singularities). The integrand is an
!! extension of `integrand_t`; it reaches the C callback through c_loc of a local box.
module gsl_wrappers
    use iso_c_binding, only: c_int, c_double, c_funptr, c_ptr, c_char, c_f_pointer, &
                             c_associated, c_size_t, c_loc, c_funloc, c_null_ptr
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use gsl_bindings, only: gsl_sf_result, gsl_set_error_handler_off, gsl_strerror, &
                            gsl_sf_ellint_rf_e, gsl_sf_ellint_rd_e, GSL_SUCCESS, GSL_PREC_DOUBLE, &
                            gsl_function, gsl_integration_workspace_alloc, &
                            gsl_integration_workspace_free, gsl_integration_qags
    implicit none
    private

    public :: gsl_start, elliptic_ke_m1, gsl_status_text
    public :: integrand_t, integrate_qags

    !> A real function of one variable for `integrate_qags`; extend it with the data it needs.
    type, abstract :: integrand_t
    contains
        procedure(integrand_value_i), deferred :: value
    end type integrand_t

    abstract interface
        !> f(x); may record a failure in its own components (it cannot stop the integration).
        function integrand_value_i(self, x) result(f)
            import :: integrand_t, dp
            class(integrand_t), intent(inout) :: self
            real(dp), intent(in) :: x
            real(dp) :: f
        end function integrand_value_i
    end interface

    !> Context handed to the C callback.
    type :: integrand_box_t
        class(integrand_t), pointer :: f => null()
    end type integrand_box_t

    integer(c_size_t), parameter :: qags_limit = 1000_c_size_t  !! subintervals of QAGS

contains

    !> Turn GSL's abort-on-error handler off; call once at program start.
    subroutine gsl_start()
        type(c_funptr) :: previous
        previous = gsl_set_error_handler_off()
    end subroutine gsl_start

    !> K(k) and E(k) from the complementary parameter m1 = 1 - k^2 in (0, 1].
    subroutine elliptic_ke_m1(m1, k_val, e_val, err)
        real(dp), intent(in) :: m1          !! 1 - k^2, 0 < m1 <= 1
        real(dp), intent(out) :: k_val      !! K(k)
        real(dp), intent(out) :: e_val      !! E(k)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(gsl_sf_result) :: rf, rd, rd_swap
        integer(c_int) :: status
        real(dp) :: big_l
        if (.not. (m1 > 0.0_dp .and. m1 <= 1.0_dp)) then
            call new_error(err, EXIT_INTERNAL, 'elliptic integral: m1 = 1 - k^2 outside (0, 1]')
            return
        end if
        if (m1 < 1.0e-20_dp) then
            ! DLMF 19.12.1-2 to first order, L = ln(4/k'); omitted terms O(m1^2 L) < 1e-38.
            ! (GSL's R_D rejects arguments below ~1e-205.)
            big_l = log(4.0_dp) - 0.5_dp*log(m1)
            k_val = big_l + 0.25_dp*m1*(big_l - 1.0_dp)
            e_val = 1.0_dp + 0.5_dp*m1*(big_l - 0.5_dp)
            return
        end if
        status = gsl_sf_ellint_rf_e(0.0_c_double, real(m1, c_double), 1.0_c_double, &
                                    GSL_PREC_DOUBLE, rf)
        if (status == GSL_SUCCESS) status = gsl_sf_ellint_rd_e(0.0_c_double, &
                                            real(m1, c_double), 1.0_c_double, GSL_PREC_DOUBLE, rd)
        if (status == GSL_SUCCESS .and. m1 < 0.5_dp) status = gsl_sf_ellint_rd_e(0.0_c_double, &
            1.0_c_double, real(m1, c_double), GSL_PREC_DOUBLE, rd_swap)
        if (status /= GSL_SUCCESS) then
            call new_error(err, EXIT_INTERNAL, 'GSL Carlson elliptic integral failed: '// &
                           trim(gsl_status_text(status)))
            return
        end if
        k_val = rf%val
        if (m1 < 0.5_dp) then
            ! E = (m1/3)(R_D(0,m1,1) + R_D(0,1,m1)) (DLMF 19.25.1): no cancellation as k -> 1
            e_val = m1/3.0_dp*(rd%val + rd_swap%val)
        else
            e_val = rf%val - (1.0_dp - m1)/3.0_dp*rd%val
        end if
    end subroutine elliptic_ke_m1

    !> int_a^b f(x) dx by GSL QAGS to max(epsabs, epsrel |result|). Recursive: an integrand
    !! may itself call integrate_qags (iterated integrals); GSL keeps no global state here.
    recursive subroutine integrate_qags(f, a, b, epsabs, epsrel, result, abserr, err)
        class(integrand_t), intent(inout), target :: f  !! integrand
        real(dp), intent(in) :: a, b                    !! limits
        real(dp), intent(in) :: epsabs, epsrel          !! requested accuracy
        real(dp), intent(out) :: result                 !! integral
        real(dp), intent(out) :: abserr                 !! QAGS error estimate
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        type(integrand_box_t), target :: box
        type(gsl_function) :: gf
        type(c_ptr) :: workspace
        real(c_double) :: res, abs_err
        integer(c_int) :: status
        result = 0.0_dp
        abserr = 0.0_dp
        box%f => f
        gf%function = c_funloc(qags_callback)
        gf%params = c_loc(box)
        workspace = gsl_integration_workspace_alloc(qags_limit)
        if (.not. c_associated(workspace)) then
            call new_error(err, EXIT_INTERNAL, 'GSL could not allocate a QAGS workspace')
            return
        end if
        status = gsl_integration_qags(gf, real(a, c_double), real(b, c_double), &
                                      real(epsabs, c_double), real(epsrel, c_double), &
                                      qags_limit, workspace, res, abs_err)
        call gsl_integration_workspace_free(workspace)
        gf%params = c_null_ptr
        result = res
        abserr = abs_err
        if (status /= GSL_SUCCESS) call new_error(err, EXIT_INTERNAL, 'GSL QAGS failed: '// &
                                                  trim(gsl_status_text(status)))
    end subroutine integrate_qags

    !> double (* function) (double x, void * params) for QAGS.
    recursive function qags_callback(x, params) bind(c) result(fx)
        real(c_double), value :: x
        type(c_ptr), value :: params
        real(c_double) :: fx
        type(integrand_box_t), pointer :: box
        call c_f_pointer(params, box)
        fx = box%f%value(real(x, dp))
    end function qags_callback

    !> gsl_strerror copied into a Fortran string.
    function gsl_status_text(status) result(text)
        integer(c_int), intent(in) :: status   !! a GSL status code
        ! blank-padded, not deferred-length: it runs on the sweep's threads
        ! (scripts/check_thread_safety.py)
        character(len=200) :: text
        character(kind=c_char), pointer :: chars(:)
        type(c_ptr) :: p
        integer :: n
        p = gsl_strerror(status)
        text = 'unknown GSL status'
        if (.not. c_associated(p)) return
        call c_f_pointer(p, chars, [200])
        n = 0
        do while (n < 200)
            if (chars(n + 1) == char(0)) exit
            n = n + 1
        end do
        text = transfer(chars(1:n), repeat(' ', n))
    end function gsl_status_text
end module gsl_wrappers
