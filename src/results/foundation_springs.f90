!> Springs equivalent to the solved ground, for structural software: at each node of the
!! mesh the vertical spring k_v = F_z / w and the horizontal spring k_h = F_x / u_b, where
!! F_z, F_x are the nodal forces the contact tractions put on the structure (M^T r of the
!! discrete equilibrium K v + M^T r = q, mindlin_structure) and w, u_b = u_s - (h/2) psi the
!! node's settlement and bottom-face displacement. A structure on these independent springs
!! (the vertical one on w, the horizontal one on u_b) under the same loads is in equilibrium
!! at fricon's displacements: K v + S v = K v + M^T r = q. The springs are secant values of
!! this one load case: another load needs other springs (the contact and the ground's
!! coupling between points are what they stand for). Where the node is lifted off (F = 0)
!! or does not move (|w| or |u_b| below 1e-12 of the largest) the spring is 0.
!!
!! Nodal values need P1 displacement bases (the coefficients are the nodal values); the
!! forces are total forces on the beam (a beam of width b) or on the plate's ring (2 pi r).
module foundation_springs
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INPUT
    use model, only: model_t, FIELD_U, FIELD_W, FIELD_PSI
    use shape_functions, only: INTERP_P1
    use discretization, only: discretization_t
    use contact_solver, only: solution_t
    use mindlin_structure, only: coupling_entries
    use sparse_matrix, only: columns_t, compressed, transposed, columns_times
    implicit none
    private

    !> The nodal springs of a solved case (physical units of the deck).
    type, public :: spring_table_t
        integer :: n = 0                        !! nodes
        real(dp), allocatable :: x(:)           !! node position [L]
        real(dp), allocatable :: w(:)           !! settlement [L]
        real(dp), allocatable :: u_b(:)         !! bottom-face horizontal displacement [L]
        real(dp), allocatable :: f_z(:)         !! nodal contact force, vertical [F]
        real(dp), allocatable :: f_x(:)         !! nodal contact force, horizontal [F]
        real(dp), allocatable :: k_v(:)         !! vertical spring F_z / w [F/L]
        real(dp), allocatable :: k_h(:)         !! horizontal spring F_x / u_b [F/L]
    end type spring_table_t

    public :: nodal_springs

contains

    !> The nodal springs of the solution sol on the discretisation d.
    subroutine nodal_springs(m, d, sol, springs, err)
        type(model_t), intent(in) :: m                  !! the model solved
        type(discretization_t), intent(in) :: d         !! its discretisation
        type(solution_t), intent(in) :: sol             !! its solution (z = [v; r])
        type(spring_table_t), intent(out) :: springs    !! the springs at the nodes
        type(error_t), allocatable, intent(out) :: err  !! the bases are not P1
        type(columns_t) :: mt
        real(dp), allocatable :: f(:)
        integer :: n
        if (any(d%basis([FIELD_U, FIELD_W, FIELD_PSI])%family /= INTERP_P1)) then
            call new_error(err, EXIT_INPUT, 'nodal springs need P1 displacements (MESH '// &
                           'u_s, w, psi blank or P1)')
            return
        end if
        mt = transposed(compressed(coupling_entries(m%structure, d)))
        f = columns_times(mt, sol%z(d%nv + 1:d%n))
        n = d%msh%ne + 1
        springs%n = n
        springs%x = d%msh%x(0:d%msh%ne)
        springs%w = sol%z(d%offset(FIELD_W) + 1:d%offset(FIELD_W) + n)
        springs%u_b = sol%z(d%offset(FIELD_U) + 1:d%offset(FIELD_U) + n) - &
                      0.5_dp*m%structure%h*sol%z(d%offset(FIELD_PSI) + 1:d%offset(FIELD_PSI) + n)
        springs%f_z = f(d%offset(FIELD_W) + 1:d%offset(FIELD_W) + n)
        springs%f_x = f(d%offset(FIELD_U) + 1:d%offset(FIELD_U) + n)
        springs%k_v = secant(springs%f_z, springs%w)
        springs%k_h = secant(springs%f_x, springs%u_b)
    end subroutine nodal_springs

    !> force / displacement, 0 where the displacement is below 1e-12 of the largest.
    pure function secant(force, disp) result(k)
        real(dp), intent(in) :: force(:), disp(:)
        real(dp) :: k(size(force))
        real(dp) :: small
        small = 1.0e-12_dp*max(maxval(abs(disp)), tiny(1.0_dp))
        k = 0.0_dp
        where (abs(disp) > small) k = force/disp
    end function secant
end module foundation_springs
