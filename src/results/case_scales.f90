!> The one table of scales and units of a case: the display units of a physical deck and the
!! factors that turn a stored value (physical, in the deck's units) into what is printed,
!! either in display units or, for a NONDIM deck, as the nondimensional group of SPEC §6.
!! The station columns (station_columns), the key results (summary_table), the report, the
!! data files and the figures all take their units and factors from here.
!!
!! Display units for physical decks: settlements in mm when the deck's length unit is `m`
!! (else in the deck's length unit); pressures as force/length^2 with the usual SI name (kPa
!! for kN and m); beam tractions as line loads (force/length, the unknowns of the model) and
!! as pressures over the width b; plate resultants per unit length. The UNITS card's f3 and
!! f4 choose the settlement and pressure units instead (physical_units: the deck's words are
!! then known units, and the factors their ratios).
!!
!! Nondimensional groups (SPEC §6; F the total vertical load, l or a the length, D or EI the
!! flexural rigidity): beam W = EI w/(F l^3), Psi = EI psi/(F l^2), Sigma = l sigma/F,
!! M/(F l), Q/F; plate W = D w/(F a^2), Psi = D psi/(F a), Sigma = pi a^2 sigma/F, M/F, Q a/F.
module case_scales
    use kinds, only: dp
    use model, only: model_t, MODEL_BEAM, flexural_rigidity, total_vertical_load, &
                     traction_measure
    use physical_units, only: force_in_newtons, length_in_metres, disp_in_metres, &
                              pressure_in_pascals
    implicit none
    private

    !> Display units of a physical deck, with the factor from the deck's length to disp.
    type, public :: units_t
        character(len=16) :: length = 'm'       !! coordinates x, r, h
        character(len=16) :: disp = 'mm'        !! settlement, gap, slip
        real(dp) :: disp_factor = 1.0e3_dp      !! deck length -> disp unit
        character(len=16) :: force = 'kN'
        character(len=16) :: pressure = 'kPa'   !! force/length^2
        real(dp) :: pressure_factor = 1.0_dp    !! deck force/length^2 -> pressure unit
        character(len=16) :: line_load = 'kN/m' !! force/length
        character(len=16) :: moment = 'kN.m'    !! force*length
    end type units_t

    !> The scales of a case: printed value = stored value * factor, with its unit ('' for a
    !! nondimensional group).
    type, public :: scales_t
        type(units_t) :: units                  !! the physical display units
        real(dp) :: length = 1.0_dp             !! positions (1/l for t = x/l)
        real(dp) :: disp = 1.0_dp               !! settlements, gaps, slips
        real(dp) :: rotation = 1.0_dp           !! section rotation psi
        real(dp) :: traction = 1.0_dp           !! the model's tractions sigma (beam: per length)
        real(dp) :: pressure = 1.0_dp           !! pressures p (force per area)
        real(dp) :: moment = 1.0_dp             !! bending moments (plate: per length)
        real(dp) :: shear = 1.0_dp              !! shear forces (plate: per length)
        real(dp) :: force = 1.0_dp              !! beam axial force N
        real(dp) :: line_force = 1.0_dp         !! plate membrane forces, radial shear
        ! (no initialisers: gfortran 12 writes blank character constants of a type that
        ! travels through several modules into .mod files it cannot read back)
        character(len=16) :: u_disp, u_length, u_pressure, u_moment, u_shear, u_rotation, &
                             u_subgrade
    end type scales_t

    public :: case_units, case_scale_factors, nondim_scale_factors, pressure_unit

contains

    !> Display units from the deck's UNITS labels (NONDIM decks: F and l or a, unscaled).
    pure function case_units(m) result(un)
        type(model_t), intent(in) :: m   !! its unit labels and NONDIM flag
        type(units_t) :: un
        un%length = m%units%length
        un%force = m%units%force
        un%disp = m%units%length
        un%disp_factor = 1.0_dp
        if (trim(m%units%length) == 'm' .and. .not. m%nondim) then
            un%disp = 'mm'
            un%disp_factor = 1.0e3_dp
        end if
        un%pressure = pressure_unit(m%units%force, m%units%length)
        un%line_load = trim(m%units%force)//'/'//trim(m%units%length)
        un%moment = trim(m%units%force)//'.'//trim(m%units%length)
        if (m%nondim) return
        if (len_trim(m%units%disp) > 0) then
            un%disp = m%units%disp
            un%disp_factor = length_in_metres(m%units%length)/disp_in_metres(m%units%disp)
        end if
        if (len_trim(m%units%pressure) > 0) then
            un%pressure = m%units%pressure
            un%pressure_factor = force_in_newtons(m%units%force)/ &
                (length_in_metres(m%units%length)**2*pressure_in_pascals(m%units%pressure))
        end if
    end function case_units

    !> The SI name of force/length^2 where there is one (kN/m^2 = kPa), else 'F/L^2'.
    pure function pressure_unit(force, length) result(unit)
        character(len=*), intent(in) :: force    !! force unit label
        character(len=*), intent(in) :: length   !! length unit label
        character(len=16) :: unit
        select case (trim(force)//' '//trim(length))
        case ('N m')
            unit = 'Pa'
        case ('kN m', 'N mm')
            unit = merge('kPa', 'MPa', trim(force) == 'kN')
        case ('MN m')
            unit = 'MPa'
        case ('kN mm')
            unit = 'GPa'
        case default
            unit = trim(force)//'/'//trim(length)//'^2'
        end select
    end function pressure_unit

    !> Display units and factors (physical deck), or the nondimensional groups of SPEC §6.
    pure function case_scale_factors(m) result(k)
        type(model_t), intent(in) :: m   !! structure, loads, units, NONDIM flag
        type(scales_t) :: k
        if (m%nondim) then
            k = nondim_scale_factors(m)
            return
        end if
        k = unit_scales(m)
        k%disp = k%units%disp_factor
        k%pressure = k%units%pressure_factor
        k%u_disp = k%units%disp
        k%u_length = k%units%length
        k%u_pressure = k%units%pressure
        k%u_moment = k%units%moment
        k%u_shear = k%units%force
        k%u_rotation = 'rad'
        k%u_subgrade = trim(k%units%force)//'/'//trim(k%units%length)//'^3'
        if (m%structure%kind /= MODEL_BEAM) then
            k%u_moment = trim(k%units%moment)//'/'//trim(k%units%length)
            k%u_shear = k%units%line_load
        end if
    end function case_scale_factors

    !> Factors 1 and no unit labels: the start of either set of scales.
    pure function unit_scales(m) result(k)
        type(model_t), intent(in) :: m   !! its unit labels
        type(scales_t) :: k
        k%units = case_units(m)
        k%u_disp = ''
        k%u_length = ''
        k%u_pressure = ''
        k%u_moment = ''
        k%u_shear = ''
        k%u_rotation = ''
        k%u_subgrade = ''
    end function unit_scales

    !> The groups of SPEC §6 (module header), for any deck: the nondimensional data file of a
    !! physical deck prints them too.
    pure function nondim_scale_factors(m) result(k)
        type(model_t), intent(in) :: m          !! structure and loads
        type(scales_t) :: k
        real(dp) :: f, l, rig
        k = unit_scales(m)
        f = total_vertical_load(m%loads)
        l = m%structure%length
        rig = flexural_rigidity(m%structure)
        k%length = 1.0_dp/l
        k%traction = traction_measure(m%structure)/f
        if (m%structure%kind == MODEL_BEAM) then
            k%disp = rig/(f*l**3)
            k%rotation = rig/(f*l**2)
            k%pressure = l*m%structure%b/f       ! Sigma = l sigma / F, sigma = b p
            k%moment = 1.0_dp/(f*l)
            k%shear = 1.0_dp/f
            k%force = 1.0_dp/f
        else
            k%disp = rig/(f*l**2)
            k%rotation = rig/(f*l)
            k%pressure = k%traction
            k%moment = 1.0_dp/f
            k%shear = l/f
            k%line_force = l/f
        end if
    end function nondim_scale_factors
end module case_scales
