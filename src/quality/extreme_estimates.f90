!> Three additions to the error estimate of a key result that is the largest or least value of
!! a station field (settlement_max, differential_settlement, moment_sagging, moment_hogging,
!! shear_force_max), made after error_estimate's estimate from the nested meshes:
!!
!!  * **Between the stations.** The key is the extreme over the stations (design table: every
!!    node, patch edge and load position), the true value the extreme of the field. Where the
!!    field's extreme lies between two stations, every mesh whose stations fall at the same
!!    places beside it shows the same shortfall, and the nested meshes cannot see it (a thick
!!    beam under a short patch with H: the largest settlement lies at x = 0.014 l, between
!!    the stations 0 and 0.025 l of N_e = 20 and 40, 2.1e-5 below the field's 5.103e-3 on
!!    both, an estimate of 1e-6). The shortfall of a smooth extreme is the excess of the
!!    parabola through the extreme station and its two neighbours over the station's value
!!    (exact for a quadratic field), and is added to the estimate. At a station where the
!!    field has a kink or a jump (a POINT, RING or MOMENT load, a station with left and right
!!    limits) or at an end of the table the extreme is at the station itself: nothing added;
!!    nor where the parabola's stations span a concentrated load (a kink: see the next rule).
!!    The shear force's slope q - p jumps at the ends of a PATCH too, so for the largest
!!    |Q| those are kinks as well (kink_positions). The largest shear force of a stiff beam
!!    under a uniform load with a large H, P2 on 200 EDGES elements, lies between stations
!!    and was 5.71919 e-2 on N_e and 2 N_e, converged 5.71934 e-2: estimated at 1.6e-7 for an
!!    error of 1.5e-6 before the parabola's excess was added, 1.5e-6 after it
!!    (output/bench/estimate_effectivity_other_meshes.md, the thirteenth revision).
!!  * **At a concentrated load inside an element.** Under a POINT or RING load that lies
!!    between two nodes the settlement has its kink at the load, where the element's field
!!    (linear in P1) cannot follow it: the station at the load reads the element's value,
!!    below the peak, and meshes that keep the load inside an element show the same kind of
!!    shortfall (a thick soft beam, P1 on EDGES meshes: 1e-5 below the peak of 3.9e-4, an
!!    estimate of 1e-7). The field at the load is taken from the node of the loaded element
!!    nearer to it, continued with the slope of the element beyond that node (first order in
!!    the distance, which is at most half the element); its excess over the table's largest
!!    settlement is added to the estimates of the largest and the differential settlement.
!!    The node farther away is not used: the field's curvature between it and the load
!!    (concave next to the load, convex farther out on a soft base) makes a long extension
!!    too high or too low.
!!  * **An extreme moment the meshes do not resolve.** Under a point load on a very soft thick
!!    beam the moment at the load is sagging on coarse meshes and hogging on fine ones (rho
!!    1e-4, zeta 0.3: M(0) = -8.3e-3 on N_e = 20, +9.5e-3 converged), so the hogging moment
!!    is near 0 on the coarse meshes and grows from 2e-6 to 3e-3 over N_e = 20 to 160; its
!!    estimate from the nested meshes was a tenth of its error. Where an extreme moment's
!!    estimate is at least its own size (the value is not established), it is the smaller of
!!    the two extremes, and the larger one's estimate is at least half that extreme (the
!!    mesh is not sure of the moment field where it is largest, nor so of its sign), its
!!    estimate is at least the largest magnitude the moment field may have there,
!!    |M_opposite| + E_opposite.
module extreme_estimates
    use kinds, only: dp
    use model, only: model_t, LOAD_POINT, LOAD_RING
    use applied_loads, only: load_positions
    use station_columns, only: Q_X, Q_W, Q_M, Q_Q
    use station_results, only: station_table_t
    use summary_table, only: entry_t, entry_index
    use case_scales, only: scales_t, case_scale_factors
    implicit none
    private

    public :: parabola_excess, tent_height, add_sampling_errors, widen_unresolved_moments

contains

    !> The excess over y(2) of the vertex of the parabola through (x(k), y(k)), k = 1, 2, 3,
    !! where x(1) < x(2) < x(3) and y(2) is the largest of the three; 0 where the three lie
    !! on a line or y(2) is not the largest.
    pure real(dp) function parabola_excess(x, y) result(excess)
        real(dp), intent(in) :: x(3)   !! abscissae, increasing
        real(dp), intent(in) :: y(3)   !! values
        real(dp) :: d1, d2, a, b
        excess = 0.0_dp
        if (.not. (x(1) < x(2) .and. x(2) < x(3))) return
        if (y(2) < y(1) .or. y(2) < y(3)) return
        d1 = (y(2) - y(1))/(x(2) - x(1))   ! >= 0
        d2 = (y(3) - y(2))/(x(3) - x(2))   ! <= 0
        ! y = y(2) + b (x - x(2)) + a (x - x(2))^2 through the three points
        a = (d2 - d1)/(x(3) - x(1))
        if (.not. a < 0.0_dp) return
        b = d1 + a*(x(2) - x(1))
        excess = -b*b/(4.0_dp*a)
    end function parabola_excess

    !> The shortfall of the largest value of y over the stations of tab (module header): the
    !! parabola's excess at the station of the largest value, 0 at an end, at a station with
    !! left and right limits or at a kink of y.
    pure real(dp) function station_shortfall(tab, y, kinks) result(excess)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: y(:)
        real(dp), intent(in) :: kinks(:)   !! where y has a kink (kink_positions)
        real(dp) :: tol
        integer :: i, left, right
        excess = 0.0_dp
        if (tab%n < 3) return
        i = maxloc(y, dim=1)
        if (tab%side(i) /= 0) return
        tol = 1.0e-9_dp*(tab%val(Q_X, tab%n) - tab%val(Q_X, 1))
        if (any(abs(kinks - tab%val(Q_X, i)) <= tol)) return
        left = station_beyond(tab, i, -1, tol)
        right = station_beyond(tab, i, 1, tol)
        if (left < 1 .or. right > tab%n) return
        ! a side much shorter than the other reaches out to half the other's length: the
        ! parabola would otherwise extrapolate the slope of a short gap (an extra station
        ! at a patch edge beside a node) over the long one
        if (x_of(right) - x_of(i) < 0.5_dp*(x_of(i) - x_of(left))) &
            right = station_beyond(tab, i, 1, 0.5_dp*(x_of(i) - x_of(left)))
        if (x_of(i) - x_of(left) < 0.5_dp*(x_of(right) - x_of(i))) &
            left = station_beyond(tab, i, -1, 0.5_dp*(x_of(right) - x_of(i)))
        if (left < 1 .or. right > tab%n) return
        ! a kink between the stations is one the parabola cannot describe
        if (any(kinks > x_of(left) + tol .and. kinks < x_of(right) - tol)) return
        excess = parabola_excess(tab%val(Q_X, [left, i, right]), y([left, i, right]))
    contains
        pure real(dp) function x_of(j)
            integer, intent(in) :: j
            x_of = tab%val(Q_X, j)
        end function x_of
    end function station_shortfall

    !> Where the fields have a kink or a jump: the settlement and the moment at the POINT,
    !! RING and MOMENT loads; the shear force (shear true) there and at both ends of every
    !! PATCH too, where its slope q - p jumps by the load's intensity.
    pure function kink_positions(m, shear) result(x)
        type(model_t), intent(in) :: m
        logical, intent(in) :: shear
        real(dp), allocatable :: x(:)
        x = load_positions(m%loads, patches=shear)
    end function kink_positions

    !> The field at a load xp inside the element [x(2), x(3)] continued from the node nearer
    !! to it with the slope of the element beyond that node, [x(1), x(2)] or [x(3), x(4)]
    !! (the larger of the two continuations where xp is midway); x(1) < x(2) < xp < x(3) <
    !! x(4).
    pure real(dp) function tent_height(x, y, xp) result(top)
        real(dp), intent(in) :: x(4)   !! the nodes of the loaded element and of its neighbours
        real(dp), intent(in) :: y(4)   !! the field at them
        real(dp), intent(in) :: xp     !! the load, inside (x(2), x(3))
        real(dp) :: left, right
        left = y(2) + (y(2) - y(1))/(x(2) - x(1))*(xp - x(2))
        right = y(3) + (y(3) - y(4))/(x(4) - x(3))*(x(3) - xp)
        if (xp - x(2) < x(3) - xp) then
            top = left
        else if (xp - x(2) > x(3) - xp) then
            top = right
        else
            top = max(left, right)
        end if
    end function tent_height

    !> The excess over the largest value of y over the stations of tab of the field at the
    !! POINT and RING loads that lie inside an element of the mesh (nodes), as tent_height
    !! continues it; 0 where none rises above it (module header). A load in the first or last
    !! element, or with a node missing from the table, adds nothing.
    pure real(dp) function tent_shortfall(m, tab, nodes, y) result(excess)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: nodes(0:)          !! the mesh's nodes, increasing
        real(dp), intent(in) :: y(:)
        real(dp) :: tol, yn(4), y_max
        integer :: k, j, q, ne
        logical :: found
        excess = 0.0_dp
        ne = ubound(nodes, 1)
        if (tab%n < 1 .or. ne < 3) return
        tol = 1.0e-9_dp*(nodes(ne) - nodes(0))
        y_max = maxval(y)
        loads: do k = 1, size(m%loads)
            if (.not. (m%loads(k)%kind == LOAD_POINT .or. m%loads(k)%kind == LOAD_RING)) &
                cycle loads
            ! the loaded element [nodes(j), nodes(j + 1)], the load strictly inside
            j = count(nodes(1:ne - 1) < m%loads(k)%x1 - tol)
            if (j < 1 .or. j + 2 > ne) cycle loads
            if (.not. (m%loads(k)%x1 > nodes(j) + tol .and. &
                       m%loads(k)%x1 < nodes(j + 1) - tol)) cycle loads
            do q = 1, 4
                call value_at(tab, y, nodes(j - 2 + q), tol, yn(q), found)
                if (.not. found) cycle loads
            end do
            excess = max(excess, tent_height(nodes(j - 1:j + 2), yn, m%loads(k)%x1) - y_max)
        end do loads
    end function tent_shortfall

    !> y at the first station at x0 (within tol); found false where the table has none.
    pure subroutine value_at(tab, y, x0, tol, v, found)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: y(:), x0, tol
        real(dp), intent(out) :: v
        logical, intent(out) :: found
        integer :: i
        v = 0.0_dp
        do i = 1, tab%n
            found = abs(tab%val(Q_X, i) - x0) <= tol
            if (found) then
                v = y(i)
                return
            end if
        end do
        found = .false.
    end subroutine value_at

    !> The first station from i in direction step (-1 or +1) at least gap from station i
    !! (0 or tab%n + 1 if none).
    pure integer function station_beyond(tab, i, step, gap) result(j)
        type(station_table_t), intent(in) :: tab
        integer, intent(in) :: i, step
        real(dp), intent(in) :: gap
        j = i + step
        do while (j >= 1 .and. j <= tab%n)
            if (step*(tab%val(Q_X, j) - tab%val(Q_X, i)) >= gap) return
            j = j + step
        end do
    end function station_beyond

    !> Add to the estimates of e the shortfall of their station extremes (module header):
    !! settlement_max and moment_hogging the largest W and M over the design table tab,
    !! moment_sagging the least M, differential_settlement both ends of W, shear_force_max
    !! the largest |Q|; each only where
    !! the extreme lies at the same station on the other mesh of the estimate (ef): where it
    !! moved, that mesh sampled the field nearer its extreme and the estimate holds the
    !! difference.
    pure subroutine add_sampling_errors(m, tab, e, ef, nodes)
        type(model_t), intent(in) :: m             !! the model (its loads, its units)
        type(station_table_t), intent(in) :: tab   !! the case's design table
        type(entry_t), intent(inout) :: e(:)       !! key results with estimates, updated
        type(entry_t), intent(in) :: ef(:)         !! the same keys on the other mesh
        !> the case's mesh nodes (0:N_e): the tents over loads inside an element
        real(dp), intent(in), optional :: nodes(0:)
        type(scales_t) :: k
        real(dp) :: w_high, w_low
        real(dp), allocatable :: kinks(:)
        k = case_scale_factors(m)
        kinks = kink_positions(m, shear=.false.)
        w_high = 0.0_dp
        w_low = 0.0_dp
        if (same_place(e, ef, 'settlement_max_x')) w_high = k%disp*station_shortfall(tab, &
            tab%val(Q_W, :), kinks)
        if (present(nodes)) w_high = max(w_high, &
                                         k%disp*tent_shortfall(m, tab, nodes, tab%val(Q_W, :)))
        if (same_place(e, ef, 'settlement_min_x')) w_low = k%disp*station_shortfall(tab, &
            -tab%val(Q_W, :), kinks)
        call add_to(e, 'settlement_max', w_high)
        call add_to(e, 'differential_settlement', w_high + w_low)
        if (same_place(e, ef, 'moment_hogging_x')) call add_to(e, 'moment_hogging', &
            k%moment*station_shortfall(tab, tab%val(Q_M, :), kinks))
        if (same_place(e, ef, 'moment_sagging_x')) call add_to(e, 'moment_sagging', &
            k%moment*station_shortfall(tab, -tab%val(Q_M, :), kinks))
        if (same_place(e, ef, 'shear_force_max_x')) call add_to(e, 'shear_force_max', &
            k%shear*station_shortfall(tab, abs(tab%val(Q_Q, :)), kink_positions(m, shear=.true.)))
    end subroutine add_sampling_errors

    !> Whether the location entry key has the same value in e and ef (1e-9 of its scale).
    pure logical function same_place(e, ef, key)
        type(entry_t), intent(in) :: e(:), ef(:)
        character(len=*), intent(in) :: key
        integer :: i
        same_place = .false.
        i = entry_index(e, key)
        if (i == 0 .or. i > size(ef)) return
        if (.not. (e(i)%defined .and. ef(i)%defined)) return
        same_place = abs(e(i)%value - ef(i)%value) <= 1.0e-9_dp*max(abs(e(i)%value), &
                                                                   abs(ef(i)%value), 1.0_dp)
    end function same_place

    pure subroutine add_to(e, key, amount)
        type(entry_t), intent(inout) :: e(:)
        character(len=*), intent(in) :: key
        real(dp), intent(in) :: amount
        integer :: i
        i = entry_index(e, key)
        if (i == 0) return
        if (e(i)%has_error) e(i)%error = e(i)%error + amount
    end subroutine add_to

    !> Widen the estimate of an extreme moment the meshes do not resolve (module header).
    pure subroutine widen_unresolved_moments(e)
        type(entry_t), intent(inout) :: e(:)   !! key results with estimates, updated
        type(entry_t) :: sag_before, hog_before
        integer :: sag, hog
        sag = entry_index(e, 'moment_sagging')
        hog = entry_index(e, 'moment_hogging')
        if (sag == 0 .or. hog == 0) return
        if (.not. (e(sag)%has_error .and. e(hog)%has_error)) return
        sag_before = e(sag)
        hog_before = e(hog)
        call widen(e(hog), sag_before)
        call widen(e(sag), hog_before)
    end subroutine widen_unresolved_moments

    pure subroutine widen(x, opposite)
        type(entry_t), intent(inout) :: x
        type(entry_t), intent(in) :: opposite
        if (x%error < abs(x%value)) return
        if (.not. abs(x%value) < abs(opposite%value)) return
        if (opposite%error < 0.5_dp*abs(opposite%value)) return
        x%error = max(x%error, abs(opposite%value) + opposite%error)
    end subroutine widen

end module extreme_estimates
