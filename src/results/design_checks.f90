!> The design checks of the CHECK cards (design_limits): each a value of the solved case, its
!! limit, the utilisation and pass or fail, computed from the design summary and the model
!! (both read-only). A failed check is a result, not a failure of the analysis.
!!
!! Values and limits are in display units (case_scales: settlements in mm for a deck in m,
!! pressures in kPa for kN and m); the CHECK card's limits are in the deck's units. The
!! utilisation is value / limit where the limit is a largest value, limit / value where it
!! is a least value (the sliding factor of safety, the contact ratio); a check passes when
!! its utilisation is at most 1. A value that does not exist (no two loaded points, the point
!! at d from every edge lifted off or off the base, no horizontal load) is n/a: it passes
!! with utilisation 0.
!!
!!   BEARING_MEAN       V / contact area (the summary's mean pressure)
!!   BEARING_EDGE       the larger pressure at d = h from an edge (the summary's)
!!   BEARING_EFFECTIVE  V / A' of the codes for an eccentric load: beam (Meyerhof 1953)
!!                      A' = b (l - 2e), e = |M_base| / V with M_base = sum F_z x + M +
!!                      F_x h about the base's centre; circle of radius a (EN 1997-1 Annex
!!                      D, DNV-OS-J101 7 F) A' = 2 (a^2 acos(e/a) - e sqrt(a^2 - e^2)), with
!!                      e = 0: an axisymmetric plate carries no moment, so A' = pi a^2
!!   SETTLEMENT         the largest settlement
!!   DIFF_SETTLEMENT    largest minus smallest settlement
!!   RELATIVE_ROTATION  the angular distortion between adjacent loaded points (summary)
!!   TILT               |tilt| (a plate's is 0)
!!   SLIDING_FS         f V / H (a least value; n/a without horizontal load)
!!   CONTACT_RATIO      contact area / base area (a least value: 1 is no lift-off)
module design_checks
    use kinds, only: dp
    use model, only: model_t, MODEL_BEAM, total_vertical_load, base_area
    use design_limits, only: design_limits_t, has_check, CHECK_BEARING, CHECK_SETTLE, &
                             CHECK_DIFFSETTLE, CHECK_ROTATION, CHECK_TILT, CHECK_SLIDING, &
                             CHECK_CONTACT
    use solution_checks, only: applied_moment
    use design_summary, only: summary_t
    use case_scales, only: scales_t, case_scale_factors
    use summary_table, only: entry_t
    implicit none
    private

    !> One design check.
    type, public :: design_check_t
        ! (no initialisers on the character components: see case_scales)
        character(len=24) :: name          !! BEARING_MEAN, SETTLEMENT, ...
        character(len=48) :: label         !! words for the report
        character(len=16) :: unit          !! display unit of value and limit ('' a number)
        real(dp) :: value = 0.0_dp         !! the case's value, display units
        real(dp) :: limit = 0.0_dp         !! the CHECK card's limit, display units
        real(dp) :: utilisation = 0.0_dp   !! value/limit, or limit/value for a least value
        logical :: defined = .true.        !! the value exists (n/a: passes, utilisation 0)
        logical :: minimum = .false.       !! the limit is a least value
        logical :: pass = .true.           !! utilisation <= 1
        real(dp) :: largest = huge(1.0_dp) !! the largest value the quantity can take (a
                                           !! contact ratio: 1)
    end type design_check_t

    public :: evaluate_design_checks, check_entries, governing_check
    public :: effective_pressure, circle_effective_area

contains

    !> The checks of the model's CHECK cards, in the order of the module header.
    pure function evaluate_design_checks(m, s) result(checks)
        type(model_t), intent(in) :: m       !! the model (its CHECK limits, loads, geometry)
        type(summary_t), intent(in) :: s     !! the design summary of the solved case
        type(design_check_t), allocatable :: checks(:)
        type(scales_t) :: k
        real(dp) :: q_eff
        logical :: eff_ok
        k = case_scale_factors(m)
        allocate (checks(0))
        associate (lim => m%limits)
            if (has_check(lim, CHECK_BEARING)) then
                call effective_pressure(m, q_eff, eff_ok)
                checks = [checks, &
                    new_check('BEARING_MEAN', 'mean contact pressure V / contact area', &
                        k%u_pressure, s%mean_pressure*k%pressure, lim%limit(1, CHECK_BEARING)* &
                        k%pressure, s%contact_area > 0.0_dp, .false.), &
                    new_check('BEARING_EDGE', 'pressure at d from an edge (the larger)', &
                        k%u_pressure, edge_value(s)*k%pressure, lim%limit(2, CHECK_BEARING)* &
                        k%pressure, any(s%edge_point_in_contact), .false.), &
                    new_check('BEARING_EFFECTIVE', 'effective-area pressure V / A''', &
                        k%u_pressure, q_eff*k%pressure, lim%limit(3, CHECK_BEARING)*k%pressure, &
                        eff_ok, .false.)]
            end if
            checks = [checks, movement_checks(lim, s, k)]
            if (has_check(lim, CHECK_SLIDING)) checks = [checks, sliding_check(m, &
                lim%limit(1, CHECK_SLIDING))]
            if (has_check(lim, CHECK_CONTACT)) checks = [checks, new_check('CONTACT_RATIO', &
                'contact area / base area', '', s%contact_area/base_area(m%structure), &
                lim%limit(1, CHECK_CONTACT), .true., .true., largest=1.0_dp)]
        end associate
    end function evaluate_design_checks

    !> Settlement, differential settlement, relative rotation and tilt.
    pure function movement_checks(lim, s, k) result(checks)
        type(design_limits_t), intent(in) :: lim
        type(summary_t), intent(in) :: s
        type(scales_t), intent(in) :: k
        type(design_check_t), allocatable :: checks(:)
        allocate (checks(0))
        if (has_check(lim, CHECK_SETTLE)) checks = [checks, new_check('SETTLEMENT', &
            'max settlement', k%u_disp, s%w_max%value*k%disp, lim%limit(1, CHECK_SETTLE)* &
            k%disp, .true., .false.)]
        if (has_check(lim, CHECK_DIFFSETTLE)) checks = [checks, new_check('DIFF_SETTLEMENT', &
            'differential settlement (max - min)', k%u_disp, s%w_differential*k%disp, &
            lim%limit(1, CHECK_DIFFSETTLE)*k%disp, .true., .false.)]
        if (has_check(lim, CHECK_ROTATION)) checks = [checks, new_check('RELATIVE_ROTATION', &
            'angular distortion between loaded points', k%u_rotation, &
            s%angular_distortion%value*k%rotation, lim%limit(1, CHECK_ROTATION)*k%rotation, &
            s%angular_distortion%defined, .false.)]
        if (has_check(lim, CHECK_TILT)) checks = [checks, new_check('TILT', '|tilt|', &
            k%u_rotation, abs(s%tilt)*k%rotation, lim%limit(1, CHECK_TILT)*k%rotation, &
            .true., .false.)]
    end function movement_checks

    !> f V / H against FS_min (n/a without horizontal load: no sliding to guard against).
    pure function sliding_check(m, fs_min) result(c)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: fs_min
        type(design_check_t) :: c
        real(dp) :: h, fs
        h = abs(sum(m%loads%fx))
        fs = 0.0_dp
        if (h > 0.0_dp) fs = m%interface%f*total_vertical_load(m%loads)/h
        c = new_check('SLIDING_FS', 'sliding factor of safety f V / H', '', fs, fs_min, &
                      h > 0.0_dp, .true.)
    end function sliding_check

    !> The larger of the summary's pressures at d from an edge that are defined (0: none).
    pure real(dp) function edge_value(s)
        type(summary_t), intent(in) :: s
        edge_value = maxval(s%edge_pressure, mask=s%edge_point_in_contact)
        if (.not. any(s%edge_point_in_contact)) edge_value = 0.0_dp
    end function edge_value

    !> The effective-area pressure V / A' of the codes for an eccentric load (module header):
    !! beam A' = b (l - 2e), e = |M_base| / V; plate A' of a circle with e = 0. `defined` is
    !! false when the resultant lies outside the base (A' <= 0).
    pure subroutine effective_pressure(m, q, defined)
        type(model_t), intent(in) :: m          !! the model (loads, geometry)
        real(dp), intent(out) :: q              !! V / A' [F/L^2]
        logical, intent(out) :: defined         !! A' > 0
        real(dp) :: v, area
        v = total_vertical_load(m%loads)
        if (m%structure%kind == MODEL_BEAM) then
            area = m%structure%b*(m%structure%length - 2.0_dp*abs(applied_moment(m))/v)
        else
            area = circle_effective_area(m%structure%length, 0.0_dp)
        end if
        defined = area > 0.0_dp
        q = 0.0_dp
        if (defined) q = v/area
    end subroutine effective_pressure

    !> The effective area of a circular footing of radius r under a load at eccentricity e
    !! (EN 1997-1 Annex D; DNV-OS-J101 (2014) 7 F): twice the circular segment beyond the
    !! chord at e from the centre, 2 (r^2 acos(e/r) - e sqrt(r^2 - e^2)); pi r^2 at e = 0,
    !! 0 for e >= r.
    pure real(dp) function circle_effective_area(r, e) result(area)
        real(dp), intent(in) :: r   !! radius [L]
        real(dp), intent(in) :: e   !! eccentricity of the load [L]
        real(dp) :: ea
        ea = abs(e)
        area = 0.0_dp
        if (ea < r) area = 2.0_dp*(r**2*acos(ea/r) - ea*sqrt(r**2 - ea**2))
    end function circle_effective_area

    !> One check: utilisation value / limit, or limit / value when the limit is a least
    !! value (`minimum`; a least value of 0, no contact or no friction, cannot pass); an
    !! undefined value passes with utilisation 0. largest: the largest value the quantity can
    !! take, where it has one (a contact ratio: 1).
    pure function new_check(name, label, unit, value, limit, defined, minimum, largest) result(c)
        character(len=*), intent(in) :: name, label, unit
        real(dp), intent(in) :: value, limit
        logical, intent(in) :: defined, minimum
        real(dp), intent(in), optional :: largest
        type(design_check_t) :: c
        c = design_check_t(name, label, unit, 0.0_dp, limit, 0.0_dp, defined, minimum, .true.)
        if (present(largest)) c%largest = largest
        if (defined) c%value = value
        if (defined .and. .not. minimum) c%utilisation = value/limit
        if (defined .and. minimum .and. value > 0.0_dp) c%utilisation = limit/value
        if (defined .and. minimum .and. value <= 0.0_dp) c%utilisation = huge(1.0_dp)
        c%pass = c%utilisation <= 1.0_dp
    end function new_check

    !> The defined check of largest utilisation (0: none defined). A met check without
    !! margin (without_margin) governs only when no other check is defined: CONTACT 1.0 on a
    !! base in full contact sits at utilisation 1 by construction and would otherwise hide
    !! the bearing or settlement utilisation that does tell the margin.
    pure integer function governing_check(checks) result(i)
        type(design_check_t), intent(in) :: checks(:)   !! the case's checks
        integer :: k
        i = 0
        do k = 1, size(checks)
            if (.not. checks(k)%defined) cycle
            if (i == 0) then
                i = k
            else if (ranks_above(checks(k), checks(i))) then
                i = k
            end if
        end do
    end function governing_check

    !> a governs before b: a met check without margin ranks below any other; otherwise the
    !! larger utilisation.
    pure logical function ranks_above(a, b)
        type(design_check_t), intent(in) :: a, b
        if (without_margin(a) .neqv. without_margin(b)) then
            ranks_above = without_margin(b)
        else
            ranks_above = a%utilisation > b%utilisation
        end if
    end function ranks_above

    !> A met least-value check whose limit is the largest value its quantity can take: a
    !! contact ratio is at most 1, so CONTACT 1.0 (no gapping) is met or not, and a met one
    !! has no margin to report.
    pure logical function without_margin(c)
        type(design_check_t), intent(in) :: c
        without_margin = c%pass .and. c%minimum .and. c%limit >= c%largest
    end function without_margin

    !> The checks as named design values (summary_table's entry_t), two per check: its value
    !! (key `<name>_value`, lower case) and its utilisation (`<name>_utilisation`); undefined
    !! values are not defined entries. For lists of design values over several solutions.
    pure function check_entries(checks) result(e)
        type(design_check_t), intent(in) :: checks(:)   !! the case's checks
        type(entry_t), allocatable :: e(:)
        type(entry_t) :: one
        integer :: k
        allocate (e(0))
        do k = 1, size(checks)
            one%key = trim(lower(checks(k)%name))//'_value'
            one%label = checks(k)%label
            one%unit = checks(k)%unit
            one%value = checks(k)%value
            one%defined = checks(k)%defined
            e = [e, one]
            one%key = trim(lower(checks(k)%name))//'_utilisation'
            one%label = 'utilisation of '//checks(k)%name
            one%unit = ''
            one%value = checks(k)%utilisation
            e = [e, one]
        end do
    end function check_entries

    !> Lower-case copy of an ASCII name, trailing blanks removed.
    !! (a result of the argument's length, not a deferred one: scripts/check_thread_safety.py)
    pure function lower(name) result(text)
        character(len=*), intent(in) :: name
        character(len=len(name)) :: text
        integer :: i
        text = name
        do i = 1, len(text)
            if (text(i:i) >= 'A' .and. text(i:i) <= 'Z') text(i:i) = achar(iachar(text(i:i)) + 32)
        end do
    end function lower
end module design_checks
