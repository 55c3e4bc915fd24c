!> Two additions to the error estimate of a key result that is the largest or least value of
!! a station field (settlement_max, differential_settlement, moment_sagging, moment_hogging),
!! made after error_estimate's estimate from the nested meshes:
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
!!    limits) or at an end of the table the extreme is at the station itself: nothing added.
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
    use model, only: model_t, LOAD_POINT, LOAD_RING, LOAD_MOMENT
    use station_columns, only: Q_X, Q_W, Q_M
    use station_results, only: station_table_t
    use summary_table, only: entry_t, entry_index
    use case_scales, only: scales_t, case_scale_factors
    implicit none
    private

    public :: parabola_excess, add_sampling_errors, widen_unresolved_moments

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
    !! left and right limits or at a concentrated load.
    pure real(dp) function station_shortfall(m, tab, y) result(excess)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: y(:)
        real(dp) :: tol
        integer :: i, left, right
        excess = 0.0_dp
        if (tab%n < 3) return
        i = maxloc(y, dim=1)
        if (tab%side(i) /= 0) return
        tol = 1.0e-9_dp*(tab%val(Q_X, tab%n) - tab%val(Q_X, 1))
        if (any(abs(m%loads%x1 - tab%val(Q_X, i)) <= tol .and. (m%loads%kind == LOAD_POINT &
                .or. m%loads%kind == LOAD_RING .or. m%loads%kind == LOAD_MOMENT))) return
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
        excess = parabola_excess(tab%val(Q_X, [left, i, right]), y([left, i, right]))
    contains
        pure real(dp) function x_of(j)
            integer, intent(in) :: j
            x_of = tab%val(Q_X, j)
        end function x_of
    end function station_shortfall

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
    !! moment_sagging the least M, differential_settlement both ends of W; each only where
    !! the extreme lies at the same station on the other mesh of the estimate (ef): where it
    !! moved, that mesh sampled the field nearer its extreme and the estimate holds the
    !! difference.
    pure subroutine add_sampling_errors(m, tab, e, ef)
        type(model_t), intent(in) :: m             !! the model (its loads, its units)
        type(station_table_t), intent(in) :: tab   !! the case's design table
        type(entry_t), intent(inout) :: e(:)       !! key results with estimates, updated
        type(entry_t), intent(in) :: ef(:)         !! the same keys on the other mesh
        type(scales_t) :: k
        real(dp) :: w_high, w_low
        k = case_scale_factors(m)
        w_high = 0.0_dp
        w_low = 0.0_dp
        if (same_place(e, ef, 'settlement_max_x')) w_high = k%disp*station_shortfall(m, &
            tab, tab%val(Q_W, :))
        if (same_place(e, ef, 'settlement_min_x')) w_low = k%disp*station_shortfall(m, &
            tab, -tab%val(Q_W, :))
        call add_to(e, 'settlement_max', w_high)
        call add_to(e, 'differential_settlement', w_high + w_low)
        if (same_place(e, ef, 'moment_hogging_x')) call add_to(e, 'moment_hogging', &
            k%moment*station_shortfall(m, tab, tab%val(Q_M, :)))
        if (same_place(e, ef, 'moment_sagging_x')) call add_to(e, 'moment_sagging', &
            k%moment*station_shortfall(m, tab, -tab%val(Q_M, :)))
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
