!> Timoshenko beam and axisymmetric Mindlin plate: stiffness K, top-face loads q and the
!! interface coupling M of the discrete system (paper 4.2, SPEC §2).
!!
!! Kinematics (paper 2.1): u_x = u_s - z psi, u_z = w, gamma = w' - psi; z down, bottom face
!! z = +h/2 (u_b = u_s - (h/2) psi), top face z = -h/2 (u_t = u_s + (h/2) psi).
!! Energies (integrated over the beam, or over the whole plate with weight 2 pi r dr, so that
!! every load and reaction below is a total force):
!!   beam   EA u'^2 + EI psi'^2 + kGbh (w' - psi)^2
!!   plate  C (u'^2 + 2 nu u' u/r + u^2/r^2) + D (psi'^2 + 2 nu psi' psi/r + psi^2/r^2)
!!          + kGh (w' - psi)^2
!! Locking: the shear term is integrated with max(deg w, deg psi) Gauss points (one point for
!! P1), the rest exactly; with h/l -> 0 the element then tends to Euler–Bernoulli/Kirchhoff.
!! Coupling (paper 2.2b): the structure receives -sigma at its bottom face, so
!!   M(x_a, u_b) = int g_a f_b,  M(x_a, psi_b) = -(h/2) int g_a f_b,  M(z_a, w_b) = int g_a f_b.
module mindlin_structure
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, EXIT_INPUT
    use quadrature, only: gauss_legendre
    use shape_functions, only: basis_t, eval_basis, max_local
    use discretization, only: discretization_t, locate_element
    use sparse_matrix, only: triplets_t, new_triplets, add_entry, compressed, dense_of
    use foundation_structure, only: section_t, section_of
    use model, only: structure_t, model_t, load_t, MODEL_BEAM, LOAD_POINT, LOAD_PATCH, &
        LOAD_MOMENT, &
                     LOAD_RING, FIELD_U, FIELD_W, FIELD_PSI, FIELD_SX, FIELD_SZ
    implicit none
    private

    !> Field values at a point: value and x-derivative of u_s, w, psi.
    type, public :: field_point_t
        real(dp) :: x = 0.0_dp
        real(dp) :: val(3) = 0.0_dp   !! u_s, w, psi
        real(dp) :: der(3) = 0.0_dp   !! u_s', w', psi'
    end type field_point_t

    public :: section_t, section_of, assemble_stiffness, assemble_loads, assemble_coupling
    public :: stiffness_entries, coupling_entries
    public :: displacement_at, traction_at, resultants

contains

    !> Structural stiffness K (nv x nv) in the numbering of d, dense (tests, benchmarks).
    pure subroutine assemble_stiffness(sec, d, k)
        type(section_t), intent(in) :: sec   !! the section stiffnesses
        type(discretization_t), intent(in) :: d   !! the discretisation
        real(dp), intent(out) :: k(:, :)     !! nv x nv
        k = dense_of(compressed(stiffness_entries(sec, d)))
    end subroutine assemble_stiffness

    !> The element contributions to K as triplets (they add where they meet).
    pure function stiffness_entries(sec, d) result(k)
        type(section_t), intent(in) :: sec        !! the section stiffnesses
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(triplets_t) :: k
        integer :: e, n_full, n_shear
        real(dp), allocatable :: xi_full(:), w_full(:), xi_shear(:), w_shear(:)
        k = new_triplets(d%nv, d%nv, 4*d%msh%ne*(2*max_local)**2)
        n_full = maxval(d%basis(FIELD_U:FIELD_PSI)%degree) + merge(2, 1, sec%plate)
        n_shear = max(d%basis(FIELD_W)%degree, d%basis(FIELD_PSI)%degree)
        ! the rules once, not once per element (once per element they cost 4 % of a small case's
        ! time)
        allocate (xi_full(n_full), w_full(n_full), xi_shear(n_shear), w_shear(n_shear))
        call gauss_legendre(n_full, xi_full, w_full)
        call gauss_legendre(n_shear, xi_shear, w_shear)
        elements: do e = 1, d%msh%ne
            call add_membrane_bending(sec, d, e, xi_full, w_full, k)
            call add_shear(sec, d, e, xi_shear, w_shear, k)
        end do elements
    end function stiffness_entries

    !> Membrane and bending terms of element e (the exact Gauss rule xi, w on [-1, 1]).
    pure subroutine add_membrane_bending(sec, d, e, xi, w, k)
        type(section_t), intent(in) :: sec
        type(discretization_t), intent(in) :: d
        integer, intent(in) :: e
        real(dp), intent(in) :: xi(:), w(:)
        type(triplets_t), intent(inout) :: k
        integer :: q
        gauss_points: do q = 1, size(xi)
            call add_strain_energy(sec, d%basis(FIELD_U), d%offset(FIELD_U), e, xi(q), w(q), &
                                   sec%axial, k)
            call add_strain_energy(sec, d%basis(FIELD_PSI), d%offset(FIELD_PSI), e, xi(q), &
                                   w(q), sec%bending, k)
        end do gauss_points
    end subroutine add_membrane_bending

    !> One Gauss point of  stiff * (a'b' + nu (a'b + ab')/r + ab/r^2)  (plate) or  stiff a'b'.
    pure subroutine add_strain_energy(sec, basis, offset, e, xi, w_gauss, stiff, k)
        type(section_t), intent(in) :: sec
        type(basis_t), intent(in) :: basis
        integer, intent(in) :: offset, e
        real(dp), intent(in) :: xi, w_gauss, stiff
        type(triplets_t), intent(inout) :: k
        integer :: idx(max_local), i, j, n
        real(dp) :: val(max_local), der(max_local), x, wt, r_inv
        call eval_basis(basis, e, xi, idx, val, der, x)
        n = basis%n_local
        wt = w_gauss*0.5_dp*(basis%x(e) - basis%x(e - 1))*stiff
        if (sec%plate) then
            wt = wt*2.0_dp*pi*x
            r_inv = 1.0_dp/x
        end if
        do j = 1, n
            do i = 1, n
                if (sec%plate) then
                    call add_entry(k, offset + idx(i), offset + idx(j), &
                                   wt*(der(i)*der(j) + sec%nu*(der(i)*val(j) + val(i)*der(j)) &
                                       *r_inv + val(i)*val(j)*r_inv**2))
                else
                    call add_entry(k, offset + idx(i), offset + idx(j), wt*der(i)*der(j))
                end if
            end do
        end do
    end subroutine add_strain_energy

    !> Shear term  shear * (w' - psi)(dw' - dpsi)  with the reduced Gauss rule xi, w.
    pure subroutine add_shear(sec, d, e, xi, w, k)
        type(section_t), intent(in) :: sec
        type(discretization_t), intent(in) :: d
        integer, intent(in) :: e
        real(dp), intent(in) :: xi(:), w(:)
        type(triplets_t), intent(inout) :: k
        real(dp) :: b_vec(2*max_local), x, wt
        real(dp) :: val(max_local), der(max_local)
        integer :: idx_w(max_local), idx_p(max_local), dofs(2*max_local), q, i, j, nw, np
        gauss_points: do q = 1, size(xi)
            call eval_basis(d%basis(FIELD_W), e, xi(q), idx_w, val, der, x)
            nw = d%basis(FIELD_W)%n_local
            b_vec(1:nw) = der(1:nw)
            dofs(1:nw) = d%offset(FIELD_W) + idx_w(1:nw)
            call eval_basis(d%basis(FIELD_PSI), e, xi(q), idx_p, val, der, x)
            np = d%basis(FIELD_PSI)%n_local
            b_vec(nw + 1:nw + np) = -val(1:np)
            dofs(nw + 1:nw + np) = d%offset(FIELD_PSI) + idx_p(1:np)
            wt = w(q)*0.5_dp*(d%msh%x(e) - d%msh%x(e - 1))*sec%shear
            if (sec%plate) wt = wt*2.0_dp*pi*x
            do j = 1, nw + np
                do i = 1, nw + np
                    call add_entry(k, dofs(i), dofs(j), wt*b_vec(i)*b_vec(j))
                end do
            end do
        end do gauss_points
    end subroutine add_shear

    !> Coupling M (nr x nv) between tractions and bottom-face displacements (paper 2.2b),
    !! dense (tests, benchmarks).
    pure subroutine assemble_coupling(m, d, mm)
        type(model_t), intent(in) :: m       !! the model
        type(discretization_t), intent(in) :: d   !! the discretisation
        real(dp), intent(out) :: mm(:, :)    !! nr x nv
        mm = dense_of(compressed(coupling_entries(m%structure, d)))
    end subroutine assemble_coupling

    !> The element contributions to M as triplets.
    pure function coupling_entries(structure, d) result(mm)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d      !! the discretisation
        type(triplets_t) :: mm
        integer, parameter :: n = 4    ! exact for degree 2 x degree 2 x r
        real(dp) :: xi(n), w(n)
        integer :: e
        mm = new_triplets(d%nr, d%nv, 12*d%msh%ne*max_local**2)
        call gauss_legendre(n, xi, w)
        elements: do e = 1, d%msh%ne
            call add_mass_block(structure, d, e, FIELD_SX, FIELD_U, 1.0_dp, xi, w, mm)
            call add_mass_block(structure, d, e, FIELD_SX, FIELD_PSI, -0.5_dp*structure%h, xi, w, &
                mm)
            call add_mass_block(structure, d, e, FIELD_SZ, FIELD_W, 1.0_dp, xi, w, mm)
        end do elements
    end function coupling_entries

    !> factor * int g_a f_b (weight 1 or 2 pi r) on element e into the (row_field, col_field) block.
    pure subroutine add_mass_block(structure, d, e, row_field, col_field, factor, xi, w, mm)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        integer, intent(in) :: e, row_field, col_field
        real(dp), intent(in) :: factor
        real(dp), intent(in) :: xi(:), w(:)     !! Gauss rule on [-1, 1] (coupling_entries)
        type(triplets_t), intent(inout) :: mm
        real(dp) :: vr(max_local), vc(max_local), dr(max_local), x, wt
        integer :: ir(max_local), ic(max_local), q, i, j, row0
        row0 = d%offset(row_field) - d%nv
        do q = 1, size(xi)
            call eval_basis(d%basis(row_field), e, xi(q), ir, vr, dr, x)
            call eval_basis(d%basis(col_field), e, xi(q), ic, vc, dr, x)
            wt = factor*w(q)*0.5_dp*(d%msh%x(e) - d%msh%x(e - 1))
            if (structure%kind /= MODEL_BEAM) wt = wt*2.0_dp*pi*x
            do j = 1, d%basis(col_field)%n_local
                do i = 1, d%basis(row_field)%n_local
                    call add_entry(mm, row0 + ir(i), d%offset(col_field) + ic(j), &
                                   wt*vr(i)*vc(j))
                end do
            end do
        end do
    end subroutine add_mass_block

    !> Generalised top-face loads q (paper 2.2a): F_z on w, F_x on u_s + (h/2) psi.
    subroutine assemble_loads(m, d, q, err)
        type(model_t), intent(in) :: m       !! the model
        type(discretization_t), intent(in) :: d          !! the discretisation
        real(dp), intent(out) :: q(:)        !! nv
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer :: i
        q = 0.0_dp
        loads: do i = 1, size(m%loads)
            associate (ld => m%loads(i))
                select case (ld%kind)
                case (LOAD_POINT, LOAD_RING)
                    call add_point_force(d, FIELD_W, ld%x1, ld%fz, q)
                    call add_point_force(d, FIELD_U, ld%x1, ld%fx, q)
                    call add_point_force(d, FIELD_PSI, ld%x1, 0.5_dp*m%structure%h*ld%fx, q)
                case (LOAD_MOMENT)
                    call add_point_force(d, FIELD_PSI, ld%x1, ld%fz, q)
                case (LOAD_PATCH)
                    call add_patch(m%structure, d, ld, q)
                case default
                    call new_error(err, EXIT_INPUT, 'unknown load kind')
                    return
                end select
            end associate
        end do loads
    end subroutine assemble_loads

    !> A concentrated generalised force on one field at x.
    pure subroutine add_point_force(d, field, x, force, q)
        type(discretization_t), intent(in) :: d
        integer, intent(in) :: field
        real(dp), intent(in) :: x, force
        real(dp), intent(inout) :: q(:)
        integer :: e, idx(max_local), n
        real(dp) :: xi, val(max_local), der(max_local), xp
        if (force == 0.0_dp) return
        call locate_element(d%msh, x, e, xi)
        call eval_basis(d%basis(field), e, xi, idx, val, der, xp)
        n = d%basis(field)%n_local
        q(d%offset(field) + idx(1:n)) = q(d%offset(field) + idx(1:n)) + force*val(1:n)
    end subroutine add_point_force

    !> Uniform patch of total F_z, F_x over [x1, x2] (beam) or the annulus x1 <= r <= x2 (plate).
    pure subroutine add_patch(structure, d, ld, q)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(load_t), intent(in) :: ld
        real(dp), intent(inout) :: q(:)
        integer, parameter :: n = 4
        real(dp) :: xg(n), wg(n), area, lo, hi, x, wt
        integer :: e, g
        call gauss_legendre(n, xg, wg)
        if (structure%kind == MODEL_BEAM) then
            area = ld%x2 - ld%x1
        else
            area = pi*(ld%x2**2 - ld%x1**2)
        end if
        elements: do e = 1, d%msh%ne
            lo = max(ld%x1, d%msh%x(e - 1))
            hi = min(ld%x2, d%msh%x(e))
            if (hi <= lo) cycle elements
            do g = 1, n
                x = lo + 0.5_dp*(xg(g) + 1.0_dp)*(hi - lo)
                wt = 0.5_dp*wg(g)*(hi - lo)/area
                if (structure%kind /= MODEL_BEAM) wt = wt*2.0_dp*pi*x
                call add_point_force(d, FIELD_W, x, wt*ld%fz, q)
                call add_point_force(d, FIELD_U, x, wt*ld%fx, q)
                call add_point_force(d, FIELD_PSI, x, wt*0.5_dp*structure%h*ld%fx, q)
            end do
        end do elements
    end subroutine add_patch

    !> u_s, w, psi and their derivatives at local xi of element e.
    pure function displacement_at(d, v, e, xi) result(p)
        type(discretization_t), intent(in) :: d   !! the discretisation
        real(dp), intent(in) :: v(:)       !! displacement coefficients (nv)
        integer, intent(in) :: e           !! the element
        real(dp), intent(in) :: xi         !! local coordinate in [-1, 1]
        type(field_point_t) :: p
        integer :: field, idx(max_local), n, k
        real(dp) :: val(max_local), der(max_local), coef(max_local)
        do field = FIELD_U, FIELD_PSI
            call eval_basis(d%basis(field), e, xi, idx, val, der, p%x)
            n = d%basis(field)%n_local
            ! (gathered element by element into a fixed-size local: a vector subscript, in the
            ! call or in this assignment, makes a heap temporary at every point)
            do k = 1, n
                coef(k) = v(d%offset(field) + idx(k))
            end do
            p%val(field) = dot_product(val(1:n), coef(1:n))
            p%der(field) = dot_product(der(1:n), coef(1:n))
        end do
    end function displacement_at

    !> sigma_x, sigma_z at local xi of element e from the traction coefficients r (nr).
    pure function traction_at(d, r, e, xi) result(s)
        type(discretization_t), intent(in) :: d   !! the discretisation
        real(dp), intent(in) :: r(:)              !! the traction coefficients (nr)
        integer, intent(in) :: e                  !! the element
        real(dp), intent(in) :: xi                !! local coordinate in [-1, 1]
        real(dp) :: s(2)
        integer :: field, idx(max_local), n, k
        real(dp) :: val(max_local), der(max_local), x, coef(max_local)
        do field = FIELD_SX, FIELD_SZ
            call eval_basis(d%basis(field), e, xi, idx, val, der, x)
            n = d%basis(field)%n_local
            do k = 1, n   ! (see displacement_at)
                coef(k) = r(d%offset(field) - d%nv + idx(k))
            end do
            s(field - FIELD_SX + 1) = dot_product(val(1:n), coef(1:n))
        end do
    end function traction_at

    !> Stress resultants at a point. Beam: N, M, Q. Plate: N_r, N_theta, M_r, M_theta, Q_r
    !! (per unit length of circumference / radius). At r = 0, u/r and psi/r take their limits
    !! u' and psi' (both vanish at the axis).
    pure function resultants(sec, p) result(res)
        type(section_t), intent(in) :: sec     !! the section stiffnesses
        type(field_point_t), intent(in) :: p   !! u_s, w, psi and their derivatives at the point
        real(dp) :: res(5)
        real(dp) :: u_r, psi_r
        res = 0.0_dp
        if (.not. sec%plate) then
            res(1) = sec%axial*p%der(1)
            res(2) = sec%bending*p%der(3)
            res(3) = sec%shear*(p%der(2) - p%val(3))
            return
        end if
        if (p%x > 0.0_dp) then
            u_r = p%val(1)/p%x
            psi_r = p%val(3)/p%x
        else
            u_r = p%der(1)
            psi_r = p%der(3)
        end if
        res(1) = sec%axial*(p%der(1) + sec%nu*u_r)
        res(2) = sec%axial*(u_r + sec%nu*p%der(1))
        res(3) = sec%bending*(p%der(3) + sec%nu*psi_r)
        res(4) = sec%bending*(psi_r + sec%nu*p%der(3))
        res(5) = sec%shear*(p%der(2) - p%val(3))
    end function resultants
end module mindlin_structure
