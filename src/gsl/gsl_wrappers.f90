!> Fortran face of GSL: real(dp) in, error_t out, status always checked.
!!
!! Complete elliptic integrals are taken in Carlson's symmetric form (DLMF 19.25.1) with the
!! COMPLEMENTARY parameter m1 = 1 - k^2 as argument, so that K and E stay accurate as k -> 1
!! (ring loads at r -> s; see reference/halfspace_kernels.md §C.1):
!!   K(k) = R_F(0, m1, 1),   E(k) = R_F(0, m1, 1) - (k^2/3) R_D(0, m1, 1).
module gsl_wrappers
    use iso_c_binding, only: c_int, c_double, c_funptr, c_ptr, c_char, c_f_pointer, &
                             c_associated
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use gsl_bindings, only: gsl_sf_result, gsl_set_error_handler_off, gsl_strerror, &
                            gsl_sf_ellint_rf_e, gsl_sf_ellint_rd_e, GSL_SUCCESS, GSL_PREC_DOUBLE
    implicit none
    private

    public :: gsl_start, elliptic_ke_m1, gsl_status_text

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
        type(error_t), allocatable, intent(out) :: err
        type(gsl_sf_result) :: rf, rd
        integer(c_int) :: status
        status = gsl_sf_ellint_rf_e(0.0_c_double, real(m1, c_double), 1.0_c_double, &
                                    GSL_PREC_DOUBLE, rf)
        if (status == GSL_SUCCESS) status = gsl_sf_ellint_rd_e(0.0_c_double, &
                                            real(m1, c_double), 1.0_c_double, GSL_PREC_DOUBLE, rd)
        if (status /= GSL_SUCCESS) then
            call new_error(err, EXIT_INTERNAL, 'GSL Carlson elliptic integral failed: '// &
                           gsl_status_text(status))
            return
        end if
        k_val = rf%val
        e_val = rf%val - (1.0_dp - m1)/3.0_dp*rd%val
    end subroutine elliptic_ke_m1

    !> gsl_strerror copied into a Fortran string.
    function gsl_status_text(status) result(text)
        integer(c_int), intent(in) :: status
        character(len=:), allocatable :: text
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
