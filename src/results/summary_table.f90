!> The key results of a case as one table of entries (key, label, unit, value): the report's
!! design summary, the JSON summary file and the sweep CSV all print this table, so a key
!! has one name, one unit and one definition everywhere (README "Design summary").
!!
!! Values are in display units for physical decks (settlements in mm when lengths are in m,
!! pressures in kPa for kN and m) and nondimensional (SPEC §6) for NONDIM decks.
module summary_table
    use kinds, only: dp
    use model, only: structure_t, model_t, MODEL_BEAM
    use case_scales, only: scales_t, case_scale_factors
    use design_summary, only: summary_t
    implicit none
    private

    !> One key result.
    type, public :: entry_t
        character(len=32) :: key = ''       !! JSON / CSV name
        character(len=56) :: label = ''     !! words for the report
        character(len=16) :: unit = ''      !! display unit ('' for a pure number)
        real(dp) :: value = 0.0_dp
        logical :: defined = .true.         !! false: not applicable (printed as null / blank)
        logical :: integer_valued = .false. !! a count
        logical :: has_error = .false.      !! an error estimate is attached (error_estimate)
        real(dp) :: error = 0.0_dp          !! estimated absolute error, same unit as value
        real(dp) :: order = -1.0_dp         !! observed order of convergence (-1: assumed 1)
        logical :: singular = .false.       !! unbounded in the model where it is taken (an
                                            !! edge in contact, a concentrated load): the
                                            !! mesh decides the value; no error estimate
    end type entry_t

    public :: summary_entries, entry_keys, entry_index, choose

contains

    !> The table for a solved case.
    pure function summary_entries(m, s, extent) result(e)
        type(model_t), intent(in) :: m      !! the model
        type(summary_t), intent(in) :: s    !! the design summary
        real(dp), intent(in) :: extent      !! contact extent t (SPEC §9)
        type(entry_t), allocatable :: e(:)
        type(scales_t) :: k
        logical :: beam
        beam = m%structure%kind == MODEL_BEAM
        k = case_scale_factors(m)
        e = [ent('settlement_max', 'max settlement', k%u_disp, s%w_max%value*k%disp), &
             ent('settlement_max_x', '  at', k%u_length, s%w_max%x*k%length), &
             ent('settlement_min', 'min settlement', k%u_disp, s%w_min%value*k%disp), &
             ent('settlement_min_x', '  at', k%u_length, s%w_min%x*k%length), &
             ent('differential_settlement', 'differential settlement (max - min)', k%u_disp, &
                 s%w_differential*k%disp), &
             ent('settlement_mean', 'mean settlement over the base', k%u_disp, s%w_mean*k%disp), &
             ent('subgrade_modulus', 'secant subgrade modulus (V/A)/w_mean', k%u_subgrade, &
                 s%subgrade_modulus, .not. m%nondim .and. s%w_mean > 0.0_dp), &
             ent('tilt', 'tilt (w(l/2) - w(-l/2))/l (plate: 0)', k%u_rotation, s%tilt*k%rotation), &
             ent('angular_distortion', 'angular distortion between loaded points', &
                 k%u_rotation, s%angular_distortion%value*k%rotation, &
                 s%angular_distortion%defined), &
             ent('angular_distortion_x', '  midway between the two points, at', k%u_length, &
                 s%angular_distortion%x*k%length, s%angular_distortion%defined), &
             ent('slope_relative_max', 'max |dw/dx - tilt| between stations', k%u_rotation, &
                 s%slope_relative_max%value*k%rotation), &
             ent('slope_relative_max_x', '  at', k%u_length, s%slope_relative_max%x*k%length), &
             ent('contact_extent_t', 'contact extent t (largest t >= 0 in contact)', '', extent)]
        if (beam) e = [e, end_entries(s, k)]
        e = [e, ent(either(beam, 'contact_length', 'contact_area'), &
                 either(beam, 'contact length', 'contact area'), &
                 either(beam, k%u_length, area_unit(k)), &
                 merge(s%contact_length*k%length, s%contact_area*k%length**2, beam)), &
             ent('pressure_mean', 'mean contact pressure V / contact area', k%u_pressure, &
                 s%mean_pressure*k%pressure), &
             ent('pressure_max', 'max pressure (element mean at a station)', k%u_pressure, &
                 s%pressure_max%value*k%pressure), &
             ent('pressure_max_x', '  at', k%u_length, s%pressure_max%x*k%length), &
             ent('edge_distance', 'distance d from the edge (= h)', k%u_length, &
                 s%edge_distance*k%length)]
        if (beam) e = [e, ent('pressure_near_left_end', 'pressure at d from the left end', &
                              k%u_pressure, s%edge_pressure(1)*k%pressure, &
                                  s%edge_point_in_contact(1))]
        e = [e, ent(either(beam, 'pressure_near_right_end', 'pressure_near_rim'), &
                    either(beam, 'pressure at d from the right end', &
                        'pressure at d from the rim'), &
                    k%u_pressure, s%edge_pressure(2)*k%pressure, &
                    s%edge_point_in_contact(2))]
        e = [e, ent('pressure_centre', either(beam, 'pressure at the centre x = 0', &
                    'pressure at the centre r = 0'), k%u_pressure, s%centre_pressure*k%pressure, &
                    s%centre_defined)]
        e = [e, moment_entries(m%structure, s, k), &
             ent('shear_force_max', either(beam, 'max |Q| (signed)', 'max |Q_r| (signed)'), &
                 k%u_shear, s%q_abs_max%value*k%shear), &
             ent('shear_force_max_x', '  at', k%u_length, s%q_abs_max%x*k%length), &
             ent('sliding_utilisation', 'sliding utilisation H/(f V)', '', s%utilisation, &
                 s%utilisation >= 0.0_dp .and. beam), &
             ent('linear_solves', 'linear solves', '', real(s%linear_solves, dp))]
        e(size(e))%integer_valued = .true.
        call mark_singular(s, e)
    end function summary_entries

    !> The entries whose value is unbounded in the model where it is taken: the largest
    !! pressure at an edge in contact or under a POINT or RING load; under a POINT load on
    !! the plate's axis (or a RING of radius 0) also the settlement (Mindlin: the shear
    !! deflection ~ ln r, its slope ~ 1/r), the moments (~ ln r) and the shear force (~ 1/r)
    !! there, hence the largest settlement, its difference, the angular distortion (the axis
    !! is a loaded point) and the largest slope relative to the tilt, the largest sagging
    !! moments and |Q_r|.
    pure subroutine mark_singular(s, e)
        type(summary_t), intent(in) :: s
        type(entry_t), intent(inout) :: e(:)
        character(len=*), parameter :: point_keys(7) = [character(len=24) :: 'settlement_max', &
            'differential_settlement', 'moment_sagging', 'hoop_moment_sagging', &
            'shear_force_max', 'angular_distortion', 'slope_relative_max']
        integer :: i
        do i = 1, size(e)
            if (trim(e(i)%key) == 'pressure_max') e(i)%singular = s%pressure_max_singular
            if (s%point_on_plate .and. any(point_keys == e(i)%key)) e(i)%singular = .true.
        end do
    end subroutine mark_singular

    !> The index of the entry with the key in e (0 if none).
    pure integer function entry_index(e, key) result(i)
        type(entry_t), intent(in) :: e(:)      !! key results
        character(len=*), intent(in) :: key    !! a key of summary_entries
        do i = 1, size(e)
            if (trim(e(i)%key) == key) return
        end do
        i = 0
    end function entry_index

    !> The keys of summary_entries for a model (the sweep CSV header).
    pure function entry_keys(m) result(keys)
        type(model_t), intent(in) :: m   !! the model
        character(len=32), allocatable :: keys(:)
        type(summary_t) :: empty
        type(entry_t), allocatable :: e(:)
        integer :: i
        e = summary_entries(m, empty, 0.0_dp)
        keys = [(e(i)%key, i=1, size(e))]
    end function entry_keys

    !> A beam's two ends of contact: the t of the leftmost and the rightmost station in
    !! contact and the lengths lifted off from the left and the right end to them.
    pure function end_entries(s, k) result(e)
        type(summary_t), intent(in) :: s
        type(scales_t), intent(in) :: k
        type(entry_t), allocatable :: e(:)
        logical :: on
        on = s%contact_ends_defined
        e = [ent('contact_extent_left_t', 'contact from t (leftmost station in contact)', '', &
                 s%contact_ends(1), on), &
             ent('contact_extent_right_t', 'contact to t (rightmost station in contact)', '', &
                 s%contact_ends(2), on), &
             ent('liftoff_left', 'lift-off length at the left end', k%u_length, &
                 s%liftoff(1)*k%length, on), &
             ent('liftoff_right', 'lift-off length at the right end', k%u_length, &
                 s%liftoff(2)*k%length, on)]
    end function end_entries

    pure function moment_entries(structure, s, k) result(e)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(summary_t), intent(in) :: s
        type(scales_t), intent(in) :: k
        type(entry_t), allocatable :: e(:)
        character(len=4) :: sym
        sym = merge('M   ', 'M_r ', structure%kind == MODEL_BEAM)
        e = [ent('moment_sagging', 'max sagging '//trim(sym)//' (bottom in tension)', k%u_moment, &
                 s%m_sag%value*k%moment, s%m_sag%defined), &
             ent('moment_sagging_x', '  at', k%u_length, s%m_sag%x*k%length, s%m_sag%defined), &
             ent('moment_hogging', 'max hogging '//trim(sym)//' (top in tension)', k%u_moment, &
                 s%m_hog%value*k%moment, s%m_hog%defined), &
             ent('moment_hogging_x', '  at', k%u_length, s%m_hog%x*k%length, s%m_hog%defined)]
        if (structure%kind == MODEL_BEAM) return
        e = [e, ent('hoop_moment_sagging', 'max sagging M_theta', k%u_moment, &
                    s%mt_sag%value*k%moment, s%mt_sag%defined), &
             ent('hoop_moment_sagging_x', '  at', k%u_length, s%mt_sag%x*k%length, &
                 s%mt_sag%defined), &
             ent('hoop_moment_hogging', 'max hogging M_theta', k%u_moment, &
                 s%mt_hog%value*k%moment, s%mt_hog%defined), &
             ent('hoop_moment_hogging_x', '  at', k%u_length, s%mt_hog%x*k%length, &
                 s%mt_hog%defined)]
    end function moment_entries

    pure function area_unit(k) result(unit)
        type(scales_t), intent(in) :: k
        character(len=16) :: unit
        unit = ''
        if (len_trim(k%u_length) > 0) unit = trim(k%u_length)//'^2'
    end function area_unit

    !> a if cond, else b (MERGE needs equal lengths).
    pure function choose(cond, a, b) result(text)
        logical, intent(in) :: cond              !! which one
        character(len=*), intent(in) :: a, b     !! the two texts
        character(len=:), allocatable :: text
        if (cond) then
            text = a
        else
            text = b
        end if
    end function choose

    !> choose for the arguments of ent: a blank-padded result (the length of the longer text),
    !! not a deferred-length one, since summary_entries runs on the sweep's threads and
    !! gfortran keeps a deferred result's length in a static variable of the caller
    !! (scripts/check_thread_safety.py); ent stores the texts in fixed-length fields, where the
    !! padding is what they hold anyway.
    pure function either(cond, a, b) result(text)
        logical, intent(in) :: cond              !! which one
        character(len=*), intent(in) :: a, b     !! the two texts
        character(len=max(len(a), len(b))) :: text
        if (cond) then
            text = a
        else
            text = b
        end if
    end function either

    pure function ent(key, label, unit, value, defined) result(e)
        character(len=*), intent(in) :: key, label, unit
        real(dp), intent(in) :: value
        logical, intent(in), optional :: defined
        type(entry_t) :: e
        e%key = key
        e%label = label
        e%unit = unit
        e%value = value
        if (present(defined)) e%defined = defined
    end function ent
end module summary_table
