!> Rigid-body coordinates of the structure: stiff structures (rho up to 1e6 with zeta down to
!! 0.001) solved with the equilibrium check at 1e-8 (doc/CHOICES.md, Stiff thin structures).
!!
!! K annihilates the structure's rigid-body modes (translations; for the beam also the
!! rotation psi = 1, w = x). For a structure much stiffer than the soil the displacement is a
!! large rigid motion plus a flexural part smaller by the stiffness ratio; stored as absolute
!! coefficients, the flexural part keeps only eps |v| of absolute precision, and K times it
!! leaves round-off of eps |K| |v|, which can exceed the forces the soil exerts (rho = 1e6,
!! zeta = 0.001: 4e-2 of the load). The solvers therefore work in rigid coordinates:
!!   v = R a + v',   a = the "pinned" unknowns (one per mode), v'(pinned) = 0,
!! where the columns of R are the rigid modes, each 1 at its own pinned unknown and 0 at the
!! others. The unknown vector keeps its layout: its pinned entries hold a, the other
!! displacement entries v'. With P the map z -> z_absolute, the equations become
!! P^T F(P z) = 0: K R = 0 and R^T K = 0 are set exactly (not computed), so the rows of the
!! pinned unknowns are the load compatibility R^T (M^T r - q) = 0 (the structure's rigid-body
!! equilibrium: statics) and the traction rows see M v = M v' + (M R) a. The matrix stays
!! symmetric; the flexural part is solved for directly, to the precision of its own size.
module rigid_body
    use kinds, only: dp
    use sparse_matrix, only: triplets_t, add_entry
    implicit none
    private

    !> The rigid-body modes of one discretised structure.
    type, public :: rigid_t
        integer :: np = 0                    !! number of modes (0: none, absolute coordinates)
        integer, allocatable :: pinned(:)    !! the displacement unknown fixing each mode
        real(dp), allocatable :: modes(:, :) !! R (nv x np): mode k is 1 at pinned(k), 0 at
                                             !! the other pinned unknowns
    end type rigid_t

    public :: new_rigid, to_rigid_coordinates, to_absolute

contains

    !> The modes from the unknown ranges of the translations (translation(:, k) = first, last
    !! unknown of the field) and, for the beam, the rotation (psi = 1 on psi_range with
    !! w = x: rotation_w, the coefficients of x in the w basis, on the first translation's
    !! range). Pinned: the first unknown of each translation; with the rotation also the last
    !! w, the two w modes then being the end values of a rigid w = alpha + beta x.
    pure function new_rigid(nv, translation, psi_range, rotation_w) result(rb)
        integer, intent(in) :: nv                         !! displacement unknowns
        !> first and last unknown of each translated field
        integer, intent(in) :: translation(:, :)
        integer, intent(in) :: psi_range(2)   !! first and last unknown of psi (beam rotation)
        real(dp), intent(in), optional :: rotation_w(:)   !! the coefficients of w = x (beam)
        type(rigid_t) :: rb
        integer :: k
        real(dp) :: span
        rb%np = size(translation, 2)
        if (present(rotation_w)) rb%np = rb%np + 1
        allocate (rb%pinned(rb%np), rb%modes(nv, rb%np))
        rb%modes = 0.0_dp
        do k = 1, size(translation, 2)
            rb%pinned(k) = translation(1, k)
            rb%modes(translation(1, k):translation(2, k), k) = 1.0_dp
        end do
        if (.not. present(rotation_w)) return
        associate (w1 => translation(1, 1), w2 => translation(2, 1), x => rotation_w)
            span = x(size(x)) - x(1)
            rb%pinned(rb%np) = w2
            ! w = (x_last - x)/span, psi = -1/span: 1 at the first w, 0 at the last
            rb%modes(w1:w2, 1) = (x(size(x)) - x)/span
            rb%modes(psi_range(1):psi_range(2), 1) = -1.0_dp/span
            ! w = (x - x_first)/span, psi = 1/span: 0 at the first w, 1 at the last
            rb%modes(w1:w2, rb%np) = (x - x(1))/span
            rb%modes(psi_range(1):psi_range(2), rb%np) = 1.0_dp/span
            rb%modes(w1, rb%np) = 0.0_dp
            rb%modes(w2, rb%np) = 1.0_dp
            rb%modes(w2, 1) = 0.0_dp
            rb%modes(w1, 1) = 1.0_dp
        end associate
    end function new_rigid

    !> [K M^T; M B] <- P^T [K M^T; M B] P and q <- P^T q, on the entries of K (nv x nv) and
    !! M (nr x nv); B is unchanged. K R = 0 and R^T K = 0 exactly: the entries of K in the
    !! pinned rows and columns are set to 0; the pinned columns of M become M R.
    pure subroutine to_rigid_coordinates(rb, k, mm, q)
        type(rigid_t), intent(in) :: rb   !! the rigid-body modes and pinned unknowns
        !> the entries of K and of M, transformed in place
        type(triplets_t), intent(inout) :: k, mm
        real(dp), intent(inout) :: q(:)   !! the structural loads, transformed in place
        real(dp), allocatable :: mr(:, :), rq(:)
        logical, allocatable :: pinned(:)
        integer :: i, e
        if (rb%np == 0) return
        allocate (pinned(k%ncol), mr(mm%nrow, rb%np))
        pinned = .false.
        pinned(rb%pinned) = .true.
        mr = 0.0_dp                                  ! M R: the modes seen by the tractions
        do e = 1, mm%n
            mr(mm%row(e), :) = mr(mm%row(e), :) + mm%val(e)*rb%modes(mm%col(e), :)
        end do
        rq = matmul(q, rb%modes)
        where (pinned(k%row(1:k%n)) .or. pinned(k%col(1:k%n))) k%val(1:k%n) = 0.0_dp
        where (pinned(mm%col(1:mm%n))) mm%val(1:mm%n) = 0.0_dp
        modes: do e = 1, rb%np
            do i = 1, mm%nrow
                if (mr(i, e) /= 0.0_dp) call add_entry(mm, i, rb%pinned(e), mr(i, e))
            end do
            q(rb%pinned(e)) = rq(e)
        end do modes
    end subroutine to_rigid_coordinates

    !> The absolute unknowns of z in rigid coordinates (the tractions are unchanged).
    pure function to_absolute(rb, z) result(z_abs)
        type(rigid_t), intent(in) :: rb   !! the rigid-body modes and pinned unknowns
        real(dp), intent(in) :: z(:)      !! the unknowns in rigid coordinates
        real(dp) :: z_abs(size(z))
        real(dp), allocatable :: amplitude(:)
        integer :: nv
        z_abs = z
        if (rb%np == 0) return
        nv = size(rb%modes, 1)
        amplitude = z(rb%pinned)
        z_abs(rb%pinned) = 0.0_dp
        z_abs(1:nv) = z_abs(1:nv) + matmul(rb%modes, amplitude)
    end function to_absolute
end module rigid_body
