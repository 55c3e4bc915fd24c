!> The number of threads OpenBLAS uses inside one LAPACK call. The driver runs every case's
!! BLAS on one thread (analysis_driver::run_analysis): a sweep's cases in parallel do not
!! oversubscribe the cores, and every digit is the same however many cores run
!! (output/bench/blas_threads.md). OpenBLAS is the BLAS/LAPACK that fpm.toml links.
module blas_threads
    use iso_c_binding, only: c_int
    implicit none
    private

    interface
        ! void openblas_set_num_threads(int num_threads);
        subroutine openblas_set_num_threads(n) bind(c, name='openblas_set_num_threads')
            import :: c_int
            integer(c_int), value :: n
        end subroutine openblas_set_num_threads
        ! int openblas_get_num_threads(void);
        function openblas_get_num_threads() bind(c, name='openblas_get_num_threads') result(n)
            import :: c_int
            integer(c_int) :: n
        end function openblas_get_num_threads
    end interface

    public :: set_blas_threads, blas_thread_count

contains

    subroutine set_blas_threads(n)
        integer, intent(in) :: n   !! threads (at least 1)
        call openblas_set_num_threads(int(max(n, 1), c_int))
    end subroutine set_blas_threads

    integer function blas_thread_count()
        blas_thread_count = int(openblas_get_num_threads())
    end function blas_thread_count
end module blas_threads
