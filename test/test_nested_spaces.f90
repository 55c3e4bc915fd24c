!> Nested spaces (src/fe/nested_spaces.f90): the Galerkin restriction P^T T_f P of the fine
!! half-space flexibility equals the flexibility assembled directly on the nested coarse mesh.
!! The reference is that direct assembly (galerkin_assembly, itself checked entry by entry
!! against independent nested quadrature and the closed forms in test_halfspace_plate and
!! test_halfspace_beam). Every coarse traction function is a combination of fine ones, so the
!! restriction is exact in exact arithmetic; both routes are accurate to about 1e-15 of the
!! largest entry, and they agree to that.
module test_nested_spaces
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check
    use model, only: model_t, load_t, MODEL_PLATE, MODEL_BEAM, LOAD_POINT, LOAD_RING, FIELD_SX, &
                     FIELD_SZ
    use contact_test_support, only: nondim_plate, nondim_beam
    use discretization, only: discretization_t, new_discretization, discretise_mesh
    use applied_loads, only: load_positions
    use mesh, only: mesh_t
    use mesh_refinement, only: coarsened, pinned_nodes
    use halfspace_operator, only: assemble_flexibility
    use nested_spaces, only: restricted_tractions
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2, interp_name
    implicit none
    private
    public :: collect_nested_spaces

contains

    subroutine collect_nested_spaces(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('restricted_t_equals_assembled_plate', test_plate), &
                 new_unittest('restricted_t_equals_assembled_beam', test_beam)]
    end subroutine collect_nested_spaces

    !> Plate: P1, P2, S2 tractions on uniform, edge-graded and load-graded meshes of 41
    !! elements (odd: the coarsening keeps one element whole at the end); LOADS grading with two
    !! off-centre loads pins their nodes, so coarse elements of one fine element also sit
    !! inside the mesh.
    subroutine test_plate(err)
        type(error_t), allocatable, intent(out) :: err
        call each_basis(MODEL_PLATE, err)
    end subroutine test_plate

    !> Beam (b/l = 0.05): the same bases and meshes.
    subroutine test_beam(err)
        type(error_t), allocatable, intent(out) :: err
        call each_basis(MODEL_BEAM, err)
    end subroutine test_beam

    subroutine each_basis(kind, err)
        integer, intent(in) :: kind
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: families(3) = [INTERP_P1, INTERP_P2, INTERP_S2]
        character(len=*), parameter :: gradings(3) = [character(len=8) :: 'UNIFORM', 'EDGES', &
                                                      'LOADS']
        integer :: i, g
        do g = 1, size(gradings)
            do i = 1, size(families)
                call compare(case_model(kind, families(i), gradings(g)), err)
                if (allocated(err)) return
            end do
        end do
    end subroutine each_basis

    function case_model(kind, family, grading) result(m)
        integer, intent(in) :: kind, family
        character(len=*), intent(in) :: grading
        type(model_t) :: m
        if (kind == MODEL_PLATE) then
            m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.0_dp, 41)
            if (grading == 'LOADS') m%loads = [load_t(kind=LOAD_RING, fz=1.0_dp, x1=0.37_dp), &
                                               load_t(kind=LOAD_RING, fz=0.5_dp, x1=0.71_dp)]
        else
            m = nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.0_dp, ne=41, &
                            loads=[load_t(kind=LOAD_POINT, fz=1.0_dp, x1=0.137_dp)])
            if (grading == 'LOADS') m%loads = [load_t(kind=LOAD_POINT, fz=1.0_dp, x1=-0.23_dp), &
                                               load_t(kind=LOAD_POINT, fz=0.5_dp, x1=0.31_dp)]
        end if
        m%mesh%grading = grading
        m%mesh%interp(FIELD_SX) = family
        m%mesh%interp(FIELD_SZ) = family
    end function case_model

    subroutine compare(m, err)
        type(model_t), intent(in) :: m
        type(error_t), allocatable, intent(out) :: err
        type(discretization_t) :: d, dc
        type(mesh_t) :: coarse
        logical, allocatable :: pinned_c(:)
        real(dp), allocatable :: t_f(:, :), t_direct(:, :), t_c(:, :)
        type(error_t), allocatable :: run_err
        real(dp) :: diff
        character(len=160) :: text
        call new_discretization(m, d, run_err)
        if (.not. allocated(run_err)) call assemble_flexibility(m, d, t_f, run_err)
        if (.not. allocated(run_err)) then
            call coarsened(d%msh, pinned_nodes(d%msh, load_positions(m%loads)), coarse, pinned_c)
            call discretise_mesh(m, coarse, dc)
            call assemble_flexibility(m, dc, t_direct, run_err)
        end if
        if (.not. allocated(run_err)) call restricted_tractions(t_f, d, dc, t_c, run_err)
        call check(err, .not. allocated(run_err), 'assembly or restriction failed')
        if (allocated(err)) return
        diff = maxval(abs(t_c - t_direct))/maxval(abs(t_direct))
        write (text, '(a,a,i0,a,i0,a,es9.2)') trim(merge('PLATE', 'BEAM ', &
            m%structure%kind == MODEL_PLATE)) &
            //' '//trim(interp_name(m%mesh%interp(FIELD_SZ)))//' '//trim(m%mesh%grading), &
                ', N_e ', &
            d%msh%ne, ' -> ', dc%msh%ne, ': max |P^T T P - T_c| / max |T_c| = ', diff
        write (*, '(4x,a)') trim(text)
        call check(err, size(t_c, 1) == dc%nr .and. diff <= 1.0e-13_dp, trim(text))
    end subroutine compare
end module test_nested_spaces
