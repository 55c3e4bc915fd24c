!> The design values of a solved case, computed from the station table and the solution (both
!! read-only), in the deck's physical units. The report, the JSON summary and the sweep CSV
!! print these values; README "Design summary" defines every key.
!!
!! Conventions: pressures are force/length^2 (a beam's line load divided by its width b), read
!! from the element means of the station table (the forces the equations carry, free of the
!! nodal field's alternation), not from the pointwise finite-element field (station_results);
!! M > 0 is hogging (top fibre in tension), so the largest sagging moment is the most negative
!! M. Contact intervals come from the station states; a boundary between a station in contact
!! and one lifted off is placed midway between them (the resolution of the stations). The
!! contact pressure at the edge of a footing in contact is singular in theory, so beside the
!! largest station value the summary gives the pressure at the distance h (the thickness) from
!! each edge, where the plate/beam model itself starts to hold; it is defined where that point
!! lies on the base and in contact (an edge that lifts off moves the contact edge inwards,
!! and the point at h may still carry pressure). A largest sagging (hogging) moment is defined
!! only where some station sags (hogs): "max hogging" of a raft that sags everywhere is not
!! the least negative sagging moment. The values are read from the design table
!! (station_results::tabulate_design: every node, patch edge and load position, and the
!! OUTPUT card's stations).
module design_summary
    use kinds, only: dp, pi
    use model, only: load_t, structure_t, model_t, MODEL_BEAM, LOAD_PATCH, LOAD_POINT, LOAD_RING, &
                     total_vertical_load, friction_compliance, base_area, traction_measure
    use contact_solver, only: solution_t
    use interface_law, only: STATE_LIFTOFF, STATE_SLIP, admissible_excess
    use station_columns, only: Q_X, Q_W, Q_SZ, Q_M, Q_MT, Q_Q, Q_SLIP
    use station_results, only: station_table_t, FLAG_TENSION, FLAG_OVERLAP
    use loaded_points, only: loaded_positions
    implicit none
    private

    !> One maximal run of stations in contact (or lifted off), [x1, x2].
    type, public :: interval_t
        real(dp) :: x1 = 0.0_dp, x2 = 0.0_dp
        logical :: contact = .true.
    end type interval_t

    !> A value and where it occurs.
    type, public :: located_t
        real(dp) :: value = 0.0_dp
        real(dp) :: x = 0.0_dp
        logical :: defined = .true.   !! false: no station has a value of the kind sought
    end type located_t

    !> Everything the design summary reports.
    type, public :: summary_t
        type(located_t) :: w_max, w_min               !! settlement [L]
        real(dp) :: w_differential = 0.0_dp           !! w_max - w_min [L]
        real(dp) :: w_mean = 0.0_dp                   !! mean over the base (plate: by area) [L]
        real(dp) :: subgrade_modulus = 0.0_dp         !! (V / base area) / w_mean [F/L^3]
        real(dp) :: tilt = 0.0_dp                     !! beam (w(l/2) - w(-l/2))/l; plate 0 [rad]
        type(located_t) :: slope_max                  !! largest |dw/dx| between stations [rad]
        type(located_t) :: slope_relative_max         !! largest |dw/dx - tilt| between
                                                      !! neighbouring stations [rad]
        !> the codes' angular distortion: the largest |slope - tilt| of the line joining
        !! adjacent loaded points (loaded_points), x midway between them; undefined with
        !! fewer than two loaded points [rad]
        type(located_t) :: angular_distortion
        type(interval_t), allocatable :: intervals(:) !! contact and lift-off, in order of x
        type(interval_t), allocatable :: slip_intervals(:) !! where the base slips (contact
                                                           !! true), in order of x
        real(dp) :: contact_length = 0.0_dp           !! beam: length in contact; plate: 0 [L]
        real(dp) :: contact_ends(2) = 0.0_dp          !! t = x/l of the leftmost and the
                                                      !! rightmost station in contact [-]
        real(dp) :: liftoff(2) = 0.0_dp               !! beam: lifted off at the left / right
                                                      !! end (contact_ends) [L]
        logical :: contact_ends_defined = .false.     !! some station is in contact
        real(dp) :: contact_area = 0.0_dp             !! [L^2]
        real(dp) :: mean_pressure = 0.0_dp            !! V / contact area [F/L^2]
        type(located_t) :: pressure_max               !! largest station pressure [F/L^2]
        logical :: pressure_max_singular = .false.    !! it is at an edge in contact or under
                                                      !! a POINT or RING load (singular there)
        logical :: point_on_plate = .false.           !! a POINT load on the plate's axis: w,
                                                      !! M_r, M_theta, Q_r unbounded there
        real(dp) :: edge_distance = 0.0_dp            !! h [L]
        real(dp) :: edge_pressure(2) = 0.0_dp         !! at h from the left end / the rim [F/L^2]
        logical :: edge_point_in_contact(2) = .false. !! that point is on the base, in contact
        logical :: edge_in_contact = .false.          !! an edge of the base is in contact
                                                      !! (the beam's ends, the plate's rim)
        real(dp) :: centre_pressure = 0.0_dp          !! at x = 0 (plate: the axis) [F/L^2]
        logical :: centre_defined = .false.           !! x = 0 on the base, no concentrated load
        type(located_t) :: m_sag, m_hog               !! beam M, plate M_r [F L or F L / L]
        type(located_t) :: mt_sag, mt_hog             !! plate M_theta
        type(located_t) :: q_abs_max                  !! largest |Q| (signed value) [F or F/L]
        real(dp) :: utilisation = -1.0_dp             !! H/(f V); -1 if f = 0
        integer :: linear_solves = 0
        integer :: n_tension_flags = 0, n_overlap_flags = 0
        integer :: n_tension_lifted = 0               !! tension flags at lifted-off stations
        real(dp) :: equilibrium = 0.0_dp              !! max relative reaction error
        real(dp) :: admissibility = 0.0_dp            !! max(|Sigma_x| - f Sigma_z), nondim
        real(dp) :: admissibility_tol = 0.0_dp
    end type summary_t

    public :: summarise

contains

    !> All design values of a solved case.
    pure function summarise(m, sol, tab) result(s)
        type(model_t), intent(in) :: m             !! the model
        type(solution_t), intent(in) :: sol        !! the solution
        type(station_table_t), intent(in) :: tab   !! the station table
        type(summary_t) :: s
        call settlement_values(m, tab, s)
        call contact_values(m, tab, s)
        call resultant_values(m%structure, tab, s)
        call check_values(m, sol, tab, s)
    end function summarise

    pure subroutine settlement_values(m, tab, s)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        real(dp) :: slope
        integer :: i
        s%w_max = located_max(tab, tab%val(Q_W, :))
        s%w_min = located_max(tab, -tab%val(Q_W, :))
        s%w_min%value = -s%w_min%value
        s%w_differential = s%w_max%value - s%w_min%value
        call mean_settlement(m, tab, s)
        s%tilt = 0.0_dp
        if (m%structure%kind == MODEL_BEAM) s%tilt = (tab%val(Q_W, tab%n) - tab%val(Q_W, &
            1))/m%structure%length
        pairs: do i = 1, tab%n - 1
            if (tab%val(Q_X, i + 1) <= tab%val(Q_X, i)) cycle pairs
            slope = (tab%val(Q_W, i + 1) - tab%val(Q_W, i))/(tab%val(Q_X, i + 1) - tab%val(Q_X, i))
            if (abs(slope) > abs(s%slope_max%value)) &
                s%slope_max = located_t(slope, 0.5_dp*(tab%val(Q_X, i) + tab%val(Q_X, i + 1)))
            if (abs(slope - s%tilt) > s%slope_relative_max%value) s%slope_relative_max = &
                located_t(abs(slope - s%tilt), 0.5_dp*(tab%val(Q_X, i) + tab%val(Q_X, i + 1)))
        end do pairs
        s%angular_distortion = relative_rotation(loaded_positions(m%structure, m%loads), &
                                                 tab, s%tilt)
    end subroutine settlement_values

    !> The largest relative rotation |(w(x_k+1) - w(x_k))/(x_k+1 - x_k) - tilt| between
    !! adjacent points x (Burland & Wroth's angular distortion; EN 1997-1 Annex H), the
    !! settlements interpolated from the stations, placed midway between the two points;
    !! undefined with fewer than two points.
    pure function relative_rotation(x, tab, tilt) result(beta)
        real(dp), intent(in) :: x(:)                !! the points, ascending [L]
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: tilt                !! the foundation's tilt [rad]
        type(located_t) :: beta
        real(dp) :: w(size(x)), rotation
        integer :: k
        beta = located_t(0.0_dp, 0.0_dp, size(x) >= 2)
        do k = 1, size(x)
            w(k) = interpolate(tab, tab%val(Q_W, :), x(k))
        end do
        do k = 1, size(x) - 1
            rotation = abs((w(k + 1) - w(k))/(x(k + 1) - x(k)) - tilt)
            if (k > 1 .and. rotation <= beta%value) cycle
            beta = located_t(rotation, 0.5_dp*(x(k) + x(k + 1)))
        end do
    end function relative_rotation

    !> Mean settlement over the base (station_results: the finite-element w integrated, plate
    !! weight 2 pi r, the same whatever the stations) and the secant modulus of subgrade
    !! reaction (V / base area) / w_mean.
    pure subroutine mean_settlement(m, tab, s)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        s%w_mean = tab%w_mean
        s%subgrade_modulus = 0.0_dp
        if (s%w_mean > 0.0_dp) s%subgrade_modulus = total_vertical_load(m%loads)/ &
                                                    base_area(m%structure)/s%w_mean
    end subroutine mean_settlement

    !> Intervals, contact length and area, mean, largest and near-edge pressures.
    pure subroutine contact_values(m, tab, s)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        real(dp) :: width, x0, x1
        integer :: k
        width = merge(m%structure%b, 1.0_dp, &
            m%structure%kind == MODEL_BEAM)   ! line load -> pressure
        s%intervals = contact_intervals(tab)
        s%slip_intervals = slip_runs(tab)
        call contact_ends(m%structure, tab, s)
        s%contact_length = 0.0_dp
        s%contact_area = 0.0_dp
        do k = 1, size(s%intervals)
            if (.not. s%intervals(k)%contact) cycle
            associate (a => s%intervals(k)%x1, b => s%intervals(k)%x2)
                if (m%structure%kind == MODEL_BEAM) then
                    s%contact_length = s%contact_length + (b - a)
                    s%contact_area = s%contact_area + (b - a)*m%structure%b
                else
                    s%contact_area = s%contact_area + pi*(b**2 - a**2)
                end if
            end associate
        end do
        s%mean_pressure = 0.0_dp
        if (s%contact_area > 0.0_dp) s%mean_pressure = total_vertical_load(m%loads)/s%contact_area
        s%pressure_max = located_max(tab, tab%val(Q_SZ, :)/width)
        s%pressure_max_singular = at_singular_point(m, tab, s%pressure_max%x)
        ! (a RING of radius 0 is a POINT load)
        s%point_on_plate = m%structure%kind &
            /= MODEL_BEAM .and. any(m%loads%kind == LOAD_POINT .or. &
            (m%loads%kind == LOAD_RING .and. m%loads%x1 <= 1.0e-9_dp*m%structure%length))
        s%edge_distance = m%structure%h
        x0 = tab%val(Q_X, 1)
        x1 = tab%val(Q_X, tab%n)
        s%edge_in_contact = tab%state(tab%n) /= STATE_LIFTOFF
        if (m%structure%kind == MODEL_BEAM) s%edge_in_contact = s%edge_in_contact .or. &
                                                      tab%state(1) /= STATE_LIFTOFF
        if (m%structure%h < x1 - x0) then
            s%edge_pressure(2) = interpolate(tab, tab%val(Q_SZ, :), x1 - m%structure%h)/width
            s%edge_point_in_contact(2) = in_contact_at(tab, x1 - m%structure%h)
            if (m%structure%kind == MODEL_BEAM) then
                s%edge_pressure(1) = interpolate(tab, tab%val(Q_SZ, :), x0 + m%structure%h)/width
                s%edge_point_in_contact(1) = in_contact_at(tab, x0 + m%structure%h)
            end if
        end if
        call centre_value(m%loads, tab, width, s)
    end subroutine contact_values

    !> Both ends of the contact: t = x/l of the leftmost and the rightmost station in
    !! contact (stick or slip), and the lengths lifted off at the beam's left and right ends,
    !! the end runs of lifted-off stations of the contact intervals (the boundary midway
    !! between a station in contact and one lifted off): a beam and its mirror image swap
    !! the lengths and swap the t with their signs changed. Undefined when no station is in
    !! contact.
    pure subroutine contact_ends(structure, tab, s)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        logical :: touching(tab%n)
        integer :: n
        touching = tab%state /= STATE_LIFTOFF
        s%contact_ends_defined = any(touching)
        s%contact_ends = 0.0_dp
        s%liftoff = 0.0_dp
        if (.not. s%contact_ends_defined) return
        s%contact_ends = [minval(tab%val(Q_X, :), mask=touching), &
                          maxval(tab%val(Q_X, :), mask=touching)]/structure%length
        n = size(s%intervals)
        if (.not. s%intervals(1)%contact) s%liftoff(1) = s%intervals(1)%x2 - s%intervals(1)%x1
        if (.not. s%intervals(n)%contact) s%liftoff(2) = s%intervals(n)%x2 - s%intervals(n)%x1
    end subroutine contact_ends

    !> The pressure at the centre x = 0 (the plate's axis, the middle of a beam), under the
    !! load of most footings. Not defined when x = 0 is off the base or lifted off (the
    !! station nearest to it), or when a concentrated load (beam POINT or MOMENT, plate RING
    !! at r = 0) acts there: the Mindlin plate's or beam's pressure is singular under it
    !! (1/r, log), and no mesh converges to a value.
    pure subroutine centre_value(loads, tab, width, s)
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: width              !! line load -> pressure
        type(summary_t), intent(inout) :: s
        real(dp) :: x0, x1, tol
        integer :: k
        x0 = tab%val(Q_X, 1)
        x1 = tab%val(Q_X, tab%n)
        tol = 1.0e-9_dp*(x1 - x0)
        s%centre_defined = x0 <= tol .and. x1 >= -tol
        if (s%centre_defined) s%centre_defined = in_contact_at(tab, 0.0_dp)
        do k = 1, size(loads)
            if (loads(k)%kind /= LOAD_PATCH .and. abs(loads(k)%x1) <= tol) &
                s%centre_defined = .false.
        end do
        s%centre_pressure = 0.0_dp
        if (s%centre_defined) s%centre_pressure = interpolate(tab, tab%val(Q_SZ, :), 0.0_dp)/width
    end subroutine centre_value

    !> Maximal runs of equal contact status; boundaries midway between differing stations.
    pure function contact_intervals(tab) result(iv)
        type(station_table_t), intent(in) :: tab
        type(interval_t), allocatable :: iv(:)
        iv = alternating_runs(tab, tab%state /= STATE_LIFTOFF)
    end function contact_intervals

    !> The runs of slipping stations (interval_t%contact true), in order of x.
    pure function slip_runs(tab) result(iv)
        type(station_table_t), intent(in) :: tab
        type(interval_t), allocatable :: iv(:)
        type(interval_t), allocatable :: runs(:)
        integer :: k
        runs = alternating_runs(tab, tab%state == STATE_SLIP)
        allocate (iv(0))
        do k = 1, size(runs)
            if (runs(k)%contact) iv = [iv, runs(k)]
        end do
    end function slip_runs

    !> Maximal runs of stations of equal flag(i), in order of x (interval_t%contact: the
    !! flag of the run); boundaries midway between differing stations, the base's ends at
    !! the ends.
    pure function alternating_runs(tab, flag) result(iv)
        type(station_table_t), intent(in) :: tab
        logical, intent(in) :: flag(:)
        type(interval_t), allocatable :: iv(:)
        real(dp) :: mid
        integer :: i
        iv = [interval_t(tab%val(Q_X, 1), tab%val(Q_X, tab%n), flag(1))]
        do i = 2, tab%n
            if (flag(i) .eqv. flag(i - 1)) cycle
            mid = 0.5_dp*(tab%val(Q_X, i - 1) + tab%val(Q_X, i))
            iv(size(iv))%x2 = mid
            iv = [iv, interval_t(mid, tab%val(Q_X, tab%n), flag(i))]
        end do
    end function alternating_runs

    pure subroutine resultant_values(structure, tab, s)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        integer :: i
        call moment_extremes(tab, tab%val(Q_M, :), s%m_sag, s%m_hog)
        if (structure%kind /= MODEL_BEAM) call moment_extremes(tab, tab%val(Q_MT, :), s%mt_sag, &
            s%mt_hog)
        i = maxloc(abs(tab%val(Q_Q, :)), dim=1)
        s%q_abs_max = located_t(tab%val(Q_Q, i), tab%val(Q_X, i))
    end subroutine resultant_values

    !> The largest sagging (most negative) and hogging (most positive) moment, each defined
    !! only where some station has a moment of that sign.
    pure subroutine moment_extremes(tab, moment, sag, hog)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: moment(:)
        type(located_t), intent(out) :: sag, hog
        real(dp) :: noise
        ! a moment within round-off of zero (a free end's 4e-12 of 3000 kN m) has no sign
        noise = 1.0e-9_dp*maxval(abs(moment))
        hog = located_max(tab, moment)
        hog%defined = hog%value > noise
        sag = located_max(tab, -moment)
        sag%value = -sag%value
        sag%defined = sag%value < -noise
    end subroutine moment_extremes

    pure subroutine check_values(m, sol, tab, s)
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(inout) :: s
        real(dp) :: v, scale(3), sigma_scale
        v = total_vertical_load(m%loads)
        s%utilisation = -1.0_dp
        if (m%interface%f > 0.0_dp) s%utilisation = abs(sum(m%loads%fx))/(m%interface%f*v)
        s%linear_solves = sol%n_solves
        s%n_tension_flags = count(iand(tab%flag, FLAG_TENSION) /= 0)
        s%n_tension_lifted = count(iand(tab%flag, FLAG_TENSION) /= 0 .and. &
                                   tab%state == STATE_LIFTOFF)
        s%n_overlap_flags = count(iand(tab%flag, FLAG_OVERLAP) /= 0)
        scale = v*[1.0_dp, 1.0_dp, m%structure%length]
        s%equilibrium = maxval(abs(sol%reaction - sol%applied)/scale)
        sigma_scale = traction_measure(m%structure)/v
        s%admissibility = sol%admissibility*sigma_scale
        ! the excess the regularised law allows at the largest slip (interface_law), doubled for
        ! the slip read at stations rather than at the Gauss points, plus the precision of the
        ! tractions: 1e-8 of the largest pressure (the precision the solver holds the law to;
        ! with eps_bar = 1e-12 the law's own allowance lies below it)
        s%admissibility_tol = 2.0_dp*admissible_excess(m%interface%eps_bar, &
            maxval(abs(tab%val(Q_SLIP, :))), &
                                                       friction_compliance(m%structure, &
                                                           m%ground))*sigma_scale + &
                              max(10.0_dp*m%interface%eps_bar, 1.0e-8_dp)* &
                              max(1.0_dp, maxval(tab%val(Q_SZ, :))*sigma_scale)
    end subroutine check_values

    !> Largest value of `y` over the stations and its position.
    pure function located_max(tab, y) result(loc)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: y(:)
        type(located_t) :: loc
        integer :: i
        i = maxloc(y, dim=1)
        loc = located_t(y(i), tab%val(Q_X, i))
    end function located_max

    !> Whether the contact pressure is singular at x: an end of the base in contact (the
    !! half-space's edge singularity; the plate's axis is no edge) or a POINT or RING load
    !! (a kink of the settlement: logarithmic).
    pure logical function at_singular_point(m, tab, x)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: x
        real(dp) :: tol
        integer :: k
        tol = 1.0e-9_dp*(tab%val(Q_X, tab%n) - tab%val(Q_X, 1))
        at_singular_point = abs(x - tab%val(Q_X, tab%n)) <= tol .and. &
                            tab%state(tab%n) /= STATE_LIFTOFF
        if (m%structure%kind == MODEL_BEAM) at_singular_point = at_singular_point .or. &
            (abs(x - tab%val(Q_X, 1)) <= tol .and. tab%state(1) /= STATE_LIFTOFF)
        do k = 1, size(m%loads)
            if (m%loads(k)%kind /= LOAD_POINT .and. m%loads(k)%kind /= LOAD_RING) cycle
            at_singular_point = at_singular_point .or. abs(x - m%loads(k)%x1) <= tol
        end do
    end function at_singular_point

    !> Whether x is in contact: the state of the station nearest to x (the contact intervals'
    !! boundaries lie midway between stations, contact_intervals).
    pure logical function in_contact_at(tab, x)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: x
        integer :: i
        i = minloc(abs(tab%val(Q_X, :) - x), dim=1)
        in_contact_at = tab%state(i) /= STATE_LIFTOFF
    end function in_contact_at

    !> Station values `y` linearly interpolated at x (the first bracket that holds x).
    pure real(dp) function interpolate(tab, y, x) result(v)
        type(station_table_t), intent(in) :: tab
        real(dp), intent(in) :: y(:), x
        integer :: i
        real(dp) :: s
        v = y(tab%n)
        do i = 1, tab%n - 1
            if (x > tab%val(Q_X, i + 1)) cycle
            if (tab%val(Q_X, i + 1) <= tab%val(Q_X, i)) cycle
            s = (x - tab%val(Q_X, i))/(tab%val(Q_X, i + 1) - tab%val(Q_X, i))
            v = (1.0_dp - s)*y(i) + s*y(i + 1)
            return
        end do
    end function interpolate
end module design_summary
