!> Working precision and mathematical constants used throughout fricon.
module kinds
    use iso_fortran_env, only: real64, real128
    implicit none
    private

    integer, parameter, public :: dp = real64          !! double precision kind
    !> extended precision (binary128; in software, so only for a few sums whose round-off
    !! in double is the very quantity measured: contact_system::equilibrium_residual)
    integer, parameter, public :: xp = real128
    real(dp), parameter, public :: pi = 3.14159265358979323846264338327950288_dp
end module kinds
