!> Raw bind(C) interfaces to the GSL functions fricon uses. Nothing else lives here; the
!! physics calls `gsl_wrappers`, never these.
module gsl_bindings
    use iso_c_binding, only: c_int, c_double, c_ptr, c_funptr, c_char, c_size_t
    implicit none
    private

    integer(c_int), parameter, public :: GSL_SUCCESS = 0
    integer(c_int), parameter, public :: GSL_PREC_DOUBLE = 0   !! gsl_mode_t for full precision

    !> struct gsl_sf_result { double val; double err; }
    type, bind(c), public :: gsl_sf_result
        real(c_double) :: val
        real(c_double) :: err
    end type gsl_sf_result

    !> struct gsl_function { double (* function) (double x, void * params); void * params; }
    type, bind(c), public :: gsl_function
        type(c_funptr) :: function
        type(c_ptr) :: params
    end type gsl_function

    public :: gsl_set_error_handler_off, gsl_strerror
    public :: gsl_sf_ellint_rf_e, gsl_sf_ellint_rd_e
    public :: gsl_integration_workspace_alloc, gsl_integration_workspace_free
    public :: gsl_integration_qags

    interface
        ! gsl_error_handler_t * gsl_set_error_handler_off (void);
        function gsl_set_error_handler_off() bind(c, name='gsl_set_error_handler_off')
            import :: c_funptr
            type(c_funptr) :: gsl_set_error_handler_off
        end function gsl_set_error_handler_off

        ! const char * gsl_strerror (const int gsl_errno);
        function gsl_strerror(gsl_errno) bind(c, name='gsl_strerror')
            import :: c_int, c_ptr
            integer(c_int), value :: gsl_errno
            type(c_ptr) :: gsl_strerror
        end function gsl_strerror

        ! int gsl_sf_ellint_RF_e (double x, double y, double z, gsl_mode_t mode,
        !                         gsl_sf_result * result);
        function gsl_sf_ellint_rf_e(x, y, z, mode, result) bind(c, name='gsl_sf_ellint_RF_e')
            import :: c_int, c_double, gsl_sf_result
            real(c_double), value :: x, y, z
            integer(c_int), value :: mode
            type(gsl_sf_result), intent(out) :: result
            integer(c_int) :: gsl_sf_ellint_rf_e
        end function gsl_sf_ellint_rf_e

        ! int gsl_sf_ellint_RD_e (double x, double y, double z, gsl_mode_t mode,
        !                         gsl_sf_result * result);
        function gsl_sf_ellint_rd_e(x, y, z, mode, result) bind(c, name='gsl_sf_ellint_RD_e')
            import :: c_int, c_double, gsl_sf_result
            real(c_double), value :: x, y, z
            integer(c_int), value :: mode
            type(gsl_sf_result), intent(out) :: result
            integer(c_int) :: gsl_sf_ellint_rd_e
        end function gsl_sf_ellint_rd_e

        ! gsl_integration_workspace * gsl_integration_workspace_alloc (size_t n);
        function gsl_integration_workspace_alloc(n) &
            bind(c, name='gsl_integration_workspace_alloc')
            import :: c_size_t, c_ptr
            integer(c_size_t), value :: n
            type(c_ptr) :: gsl_integration_workspace_alloc
        end function gsl_integration_workspace_alloc

        ! void gsl_integration_workspace_free (gsl_integration_workspace * w);
        subroutine gsl_integration_workspace_free(w) bind(c, name='gsl_integration_workspace_free')
            import :: c_ptr
            type(c_ptr), value :: w
        end subroutine gsl_integration_workspace_free

        ! int gsl_integration_qags (const gsl_function * f, double a, double b, double epsabs,
        !     double epsrel, size_t limit, gsl_integration_workspace * workspace,
        !     double * result, double * abserr);
        function gsl_integration_qags(f, a, b, epsabs, epsrel, limit, workspace, result, &
                                      abserr) bind(c, name='gsl_integration_qags')
            import :: gsl_function, c_double, c_size_t, c_ptr, c_int
            type(gsl_function), intent(in) :: f
            real(c_double), value :: a, b, epsabs, epsrel
            integer(c_size_t), value :: limit
            type(c_ptr), value :: workspace
            real(c_double), intent(out) :: result, abserr
            integer(c_int) :: gsl_integration_qags
        end function gsl_integration_qags
    end interface

    ! keep c_char referenced for the wrappers that copy C strings
    character(kind=c_char), parameter, public :: c_nul = char(0, kind=c_char)
end module gsl_bindings
