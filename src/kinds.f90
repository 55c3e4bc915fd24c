!> Working precision and mathematical constants used throughout fricon.
module kinds
    use iso_fortran_env, only: real64
    implicit none
    private

    integer, parameter, public :: dp = real64          !! double precision kind
    real(dp), parameter, public :: pi = 3.14159265358979323846264338327950288_dp
end module kinds
