!> What the deck asks of the discretisation: the MESH card (number of elements, grading, the
!! interpolation of each field) and the ADAPT card. The mesh itself is built from it by
!! `discretization`; a refined or adapted mesh is a new request, never a change of this one.
module mesh_request
    use kinds, only: dp
    implicit none
    private

    !> The five fields of the mixed formulation, in the order of the global vector
    !! z = [u_s, w, psi, sigma_x, sigma_z] (SPEC §2).
    integer, parameter, public :: FIELD_U = 1, FIELD_W = 2, FIELD_PSI = 3, &
                                  FIELD_SX = 4, FIELD_SZ = 5

    !> MESH and ADAPT cards.
    type, public :: mesh_request_t
        integer :: ne = 20                      !! number of elements N_e
        character(len=10) :: grading = 'UNIFORM' !! UNIFORM, EDGES or LOADS
        integer :: interp(5) = 1                !! per field (FIELD_*): INTERP_P1/P2/S2
        logical :: interp_given = .false.       !! the MESH card gives an interpolation
        real(dp) :: adapt_tol = 0.0_dp          !! ADAPT tol; 0: the MESH card's mesh as it is
        integer :: adapt_max_ne = 0             !! largest number of elements of an adapted mesh
    end type mesh_request_t
end module mesh_request
