!> Nested discretisations: a coarse mesh whose nodes are nodes of the fine mesh
!! (mesh_refinement::coarsened) has every coarse basis function of a field in that field's
!! fine space, g^c_b = sum_i P_ib g^f_i (P1 and P2: piecewise polynomials of the same degree
!! on a subdivision; S2: knot insertion). The Galerkin matrix of any operator on the coarse
!! space is then P^T A_f P, exactly. The nested start of the Newton method restricts the fine
!! half-space flexibility T this way instead of assembling the coarse one (O(n_f n_c) work
!! against the kernel integrals of every element pair).
!!
!! P is found one coarse function at a time, by the L2 projection onto the fine functions
!! that are nonzero on its support, integrated over that support only: the coarse function
!! lies in their span, and they are linearly independent there (local linear independence
!! of Lagrange and B-spline bases), so the projection reproduces it; the coefficients of the
!! fine functions that reach beyond the support come out 0 to round-off. (Nestedness of
!! spline spaces under knot insertion and local linear independence of B-splines: de Boor,
!! A Practical Guide to Splines, 2001, ch. IX and XI.)
module nested_spaces
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use model, only: FIELD_SX, FIELD_SZ
    use discretization, only: discretization_t
    use shape_functions, only: basis_t, eval_basis, max_local
    use quadrature, only: gauss_legendre
    use lapack_interfaces, only: dgesv
    implicit none
    private

    !> P of one field (or of the traction pair), by columns: coarse function j is
    !! sum over k = first(j) .. first(j+1)-1 of val(k) g^f_row(k).
    type :: prolongation_t
        integer, allocatable :: first(:)   !! column j holds entries first(j) .. first(j+1)-1
        integer, allocatable :: row(:)     !! fine coefficient of an entry
        real(dp), allocatable :: val(:)    !! its value P_ij
    end type prolongation_t

    public :: restricted_tractions

contains

    !> P^T T_f P for the traction unknowns [sigma_x; sigma_z] (T_f as the half-space
    !! assembly orders it: all sigma_x coefficients first), dc nested in df.
    subroutine restricted_tractions(t_f, df, dc, t_c, err)
        real(dp), intent(in) :: t_f(:, :)              !! fine operator, df%nr x df%nr
        type(discretization_t), intent(in) :: df       !! the fine discretisation
        type(discretization_t), intent(in) :: dc       !! the coarse one, nested in df
        real(dp), allocatable, intent(out) :: t_c(:, :)  !! coarse operator, dc%nr x dc%nr
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(prolongation_t) :: px, pz, p
        call prolongation(df%basis(FIELD_SX), dc%basis(FIELD_SX), px, err)
        if (allocated(err)) return
        call prolongation(df%basis(FIELD_SZ), dc%basis(FIELD_SZ), pz, err)
        if (allocated(err)) return
        ! the pair: sigma_z rows after the fine sigma_x coefficients
        p%first = [px%first(1:size(px%first) - 1), pz%first + size(px%row)]
        p%row = [px%row, pz%row + df%basis(FIELD_SX)%n_dof]
        p%val = [px%val, pz%val]
        call galerkin_product(t_f, p, t_c)
    end subroutine restricted_tractions

    !> t_c = P^T t_f P with P sparse by columns (W = t_f P first: O(n_f n_c nnz)).
    pure subroutine galerkin_product(t_f, p, t_c)
        real(dp), intent(in) :: t_f(:, :)                !! fine operator (symmetric)
        type(prolongation_t), intent(in) :: p            !! P, fine rows x coarse columns
        real(dp), allocatable, intent(out) :: t_c(:, :)  !! P^T t_f P
        real(dp), allocatable :: w(:, :)
        integer :: nc, i, j, k
        nc = size(p%first) - 1
        allocate (w(size(t_f, 1), nc), t_c(nc, nc))
        columns_of_w: do j = 1, nc
            w(:, j) = 0.0_dp
            do k = p%first(j), p%first(j + 1) - 1
                w(:, j) = w(:, j) + p%val(k)*t_f(:, p%row(k))
            end do
        end do columns_of_w
        ! T is symmetric, and so is P^T T P: the lower triangle, mirrored
        columns: do j = 1, nc
            rows: do i = j, nc
                t_c(i, j) = 0.0_dp
                do k = p%first(i), p%first(i + 1) - 1
                    t_c(i, j) = t_c(i, j) + p%val(k)*w(p%row(k), j)
                end do
                t_c(j, i) = t_c(i, j)
            end do rows
        end do columns
    end subroutine galerkin_product

    !> P of one field: bf on the fine mesh, bc (same family) on a coarse mesh whose nodes are
    !! fine nodes.
    subroutine prolongation(bf, bc, p, err)
        type(basis_t), intent(in) :: bf              !! fine basis
        type(basis_t), intent(in) :: bc              !! coarse basis, same family
        type(prolongation_t), intent(out) :: p
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: node(:), e_lo(:), e_hi(:), f_lo(:), f_hi(:)
        integer :: j, k
        call fine_nodes(bf, bc, node, err)
        if (allocated(err)) return
        call supports(bc, e_lo, e_hi)
        allocate (f_lo(bc%n_dof), f_hi(bc%n_dof), p%first(bc%n_dof + 1))
        p%first(1) = 1
        sizes: do j = 1, bc%n_dof
            call fine_range(bf, node(e_lo(j) - 1), node(e_hi(j)), f_lo(j), f_hi(j))
            p%first(j + 1) = p%first(j) + f_hi(j) - f_lo(j) + 1
        end do sizes
        allocate (p%row(p%first(bc%n_dof + 1) - 1), p%val(p%first(bc%n_dof + 1) - 1))
        columns: do j = 1, bc%n_dof
            associate (k0 => p%first(j), k1 => p%first(j + 1) - 1)
                p%row(k0:k1) = [(k, k=f_lo(j), f_hi(j))]
                call project_one(bf, bc, j, e_lo(j), node(e_lo(j) - 1), node(e_hi(j)), f_lo(j), &
                                 p%val(k0:k1), err)
            end associate
            if (allocated(err)) return
        end do columns
    end subroutine prolongation

    !> The fine functions f_lo .. f_hi nonzero on the fine elements n_lo+1 .. n_hi.
    pure subroutine fine_range(bf, n_lo, n_hi, f_lo, f_hi)
        type(basis_t), intent(in) :: bf
        integer, intent(in) :: n_lo, n_hi
        integer, intent(out) :: f_lo, f_hi
        integer :: idx(max_local), e
        real(dp) :: val(max_local), der(max_local), x
        f_lo = huge(1)
        f_hi = 0
        fine_elements: do e = n_lo + 1, n_hi
            call eval_basis(bf, e, 0.0_dp, idx, val, der, x)
            f_lo = min(f_lo, minval(idx(1:bf%n_local)))
            f_hi = max(f_hi, maxval(idx(1:bf%n_local)))
        end do fine_elements
    end subroutine fine_range

    !> node(k): the fine node at coarse node k (coarse nodes are fine nodes, bit for bit).
    subroutine fine_nodes(bf, bc, node, err)
        type(basis_t), intent(in) :: bf, bc
        integer, allocatable, intent(out) :: node(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: k, i
        allocate (node(0:bc%ne))
        i = 0
        coarse_nodes: do k = 0, bc%ne
            do while (i < bf%ne .and. bf%x(i) < bc%x(k))
                i = i + 1
            end do
            if (bf%x(i) /= bc%x(k) .or. bf%family /= bc%family) then
                call new_error(err, EXIT_INTERNAL, 'nested spaces: the coarse mesh is not '// &
                               'nested in the fine one')
                return
            end if
            node(k) = i
        end do coarse_nodes
    end subroutine fine_nodes

    !> The coarse elements e_lo(j) .. e_hi(j) on which coarse function j is nonzero.
    pure subroutine supports(bc, e_lo, e_hi)
        type(basis_t), intent(in) :: bc
        integer, allocatable, intent(out) :: e_lo(:), e_hi(:)
        integer :: idx(max_local), e, l
        real(dp) :: val(max_local), der(max_local), x
        allocate (e_lo(bc%n_dof), e_hi(bc%n_dof))
        e_lo = huge(1)
        e_hi = 0
        coarse_elements: do e = 1, bc%ne
            call eval_basis(bc, e, 0.0_dp, idx, val, der, x)
            do l = 1, bc%n_local
                e_lo(idx(l)) = min(e_lo(idx(l)), e)
                e_hi(idx(l)) = max(e_hi(idx(l)), e)
            end do
        end do coarse_elements
    end subroutine supports

    !> The fine coefficients coef (of f_lo, f_lo + 1, ...) of coarse function j, whose
    !! support starts in coarse element ec_lo and spans the fine elements n_lo+1 .. n_hi: the
    !! L2 projection there (module header).
    subroutine project_one(bf, bc, j, ec_lo, n_lo, n_hi, f_lo, coef, err)
        type(basis_t), intent(in) :: bf, bc
        integer, intent(in) :: j, ec_lo, n_lo, n_hi, f_lo
        real(dp), intent(out) :: coef(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: gram(size(coef), size(coef))
        integer :: ipiv(size(coef)), info
        character(len=80) :: text
        call local_moments(bf, bc, j, ec_lo, n_lo, n_hi, f_lo, gram, coef)
        call dgesv(size(coef), 1, gram, size(coef), ipiv, coef, size(coef), info)
        if (info /= 0) then
            write (text, '(a,i0,a,i0,a)') 'nested spaces: local Gram matrix of coarse function ', &
                j, ' singular (dgesv info ', info, ')'
            call new_error(err, EXIT_INTERNAL, trim(text))
        end if
    end subroutine project_one

    !> gram(a, b) = int g^f_a g^f_b and rhs(a) = int g^f_a g^c_j over the fine elements
    !! n_lo+1 .. n_hi (Gauss–Legendre with degree + 1 points: exact for the products).
    pure subroutine local_moments(bf, bc, j, ec_lo, n_lo, n_hi, f_lo, gram, rhs)
        type(basis_t), intent(in) :: bf, bc
        integer, intent(in) :: j, ec_lo, n_lo, n_hi, f_lo
        real(dp), intent(out) :: gram(:, :), rhs(:)
        real(dp) :: xi(max_local + 1), w(max_local + 1), val(max_local), der(max_local)
        real(dp) :: cval(max_local), x, xc, wx, gc, x_c
        integer :: idx(max_local), cidx(max_local), e, q, a, b, ec, ng
        ng = bf%degree + 1
        call gauss_legendre(ng, xi(1:ng), w(1:ng))
        gram = 0.0_dp
        rhs = 0.0_dp
        ec = ec_lo
        elements: do e = n_lo + 1, n_hi
            points: do q = 1, ng
                call eval_basis(bf, e, xi(q), idx, val, der, x)
                wx = 0.5_dp*w(q)*(bf%x(e) - bf%x(e - 1))
                ! the coarse element holding the fine one: found from its midpoint
                do while (ec < bc%ne .and. bc%x(ec) <= 0.5_dp*(bf%x(e - 1) + bf%x(e)))
                    ec = ec + 1
                end do
                xc = 2.0_dp*(x - bc%x(ec - 1))/(bc%x(ec) - bc%x(ec - 1)) - 1.0_dp
                call eval_basis(bc, ec, xc, cidx, cval, der, x_c)
                gc = sum(cval(1:bc%n_local), mask=cidx(1:bc%n_local) == j)
                rows: do a = 1, bf%n_local
                    rhs(idx(a) - f_lo + 1) = rhs(idx(a) - f_lo + 1) + wx*val(a)*gc
                    columns: do b = 1, bf%n_local
                        gram(idx(a) - f_lo + 1, idx(b) - f_lo + 1) = &
                            gram(idx(a) - f_lo + 1, idx(b) - f_lo + 1) + wx*val(a)*val(b)
                    end do columns
                end do rows
            end do points
        end do elements
    end subroutine local_moments
end module nested_spaces
