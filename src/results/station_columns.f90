!> The one table of station columns: for every quantity at a station, its name, its
!! nondimensional symbol (SPEC §6), its physical unit and the factors that turn the stored
!! value (physical, in the deck's units) into either. The text report, the nondimensional data
!! file (.dat), the physical CSV, the figures and the tests all take their columns from here,
!! so no module reads a station column by its number.
!!
!! Display units for physical decks: settlements in mm when the deck's length unit is `m`
!! (else in the deck's length unit); pressures as force/length^2 with the usual SI name (kPa
!! for kN and m); beam tractions both as line loads (force/length, the unknowns of the model)
!! and as pressures over the width b; plate resultants per unit length.
module station_columns
    use kinds, only: dp, pi
    use model, only: model_t, MODEL_BEAM, flexural_rigidity, total_vertical_load
    implicit none
    private

    !> Stored station quantities (rows of station_table_t%val), physical deck units.
    integer, parameter, public :: Q_X = 1, Q_U = 2, Q_W = 3, Q_PSI = 4, Q_SX = 5, Q_SZ = 6, &
                                  Q_GAP = 7, Q_SLIP = 8, Q_STATE = 9, Q_N = 10, Q_NT = 11, &
                                  Q_M = 12, Q_MT = 13, Q_Q = 14, Q_SX_FE = 15, Q_SZ_FE = 16
    integer, parameter, public :: n_quantities = 16

    !> Display units of a case, with the factor from the deck's units to each.
    type, public :: units_t
        character(len=16) :: length = 'm'       !! coordinates x, r, h
        character(len=16) :: disp = 'mm'        !! settlement, gap, slip
        real(dp) :: disp_factor = 1.0e3_dp      !! deck length -> disp unit
        character(len=16) :: force = 'kN'
        character(len=16) :: pressure = 'kPa'   !! force/length^2
        character(len=16) :: line_load = 'kN/m' !! force/length
        character(len=16) :: moment = 'kN.m'    !! force*length
    end type units_t

    !> One column of a station table.
    type, public :: column_t
        character(len=12) :: key = ''       !! CSV / JSON name, e.g. 'w'
        character(len=12) :: symbol = ''    !! nondimensional symbol, e.g. 'W'
        character(len=16) :: unit = ''      !! display unit ('' for a pure number)
        character(len=60) :: meaning = ''   !! one line for README and file headers
        integer :: quantity = Q_X           !! which stored quantity (Q_*)
        real(dp) :: scale = 1.0_dp          !! printed value = stored * scale (nondimensional
                                            !! for nondim_columns, display units for physical)
        logical :: integer_valued = .false. !! the state code
        logical :: in_report = .true.       !! also a column of the report's table
    end type column_t

    public :: case_units, nondim_columns, physical_columns, column_index, pressure_unit

contains

    !> Display units from the deck's UNITS labels (NONDIM decks: F and l or a, unscaled).
    pure function case_units(m) result(un)
        type(model_t), intent(in) :: m
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
    end function case_units

    !> The SI name of force/length^2 where there is one (kN/m^2 = kPa), else 'F/L^2'.
    pure function pressure_unit(force, length) result(unit)
        character(len=*), intent(in) :: force, length
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

    !> Columns of the nondimensional data file and report table (SPEC §9 fixes the first nine).
    pure function nondim_columns(m) result(cols)
        type(model_t), intent(in) :: m
        type(column_t), allocatable :: cols(:)
        real(dp) :: f, l, rig, s_disp, s_psi, s_sig
        f = total_vertical_load(m%loads)
        l = m%structure%length
        rig = flexural_rigidity(m%structure)
        if (m%structure%kind == MODEL_BEAM) then
            s_disp = rig/(f*l**3)
            s_psi = rig/(f*l**2)
            s_sig = l/f
        else
            s_disp = rig/(f*l**2)
            s_psi = rig/(f*l)
            s_sig = pi*l**2/f
        end if
        cols = [col('t', 't', '', 'x/l (beam) or r/a (plate)', Q_X, 1.0_dp/l), &
                col('U', 'U', '', 'mid-plane horizontal displacement', Q_U, s_disp), &
                col('W', 'W', '', 'settlement', Q_W, s_disp), &
                col('Psi', 'Psi', '', 'section rotation', Q_PSI, s_psi), &
                col('Sigma_x', 'Sigma_x', '', 'shear traction on the soil', Q_SX, s_sig), &
                col('Sigma_z', 'Sigma_z', '', 'contact pressure (compression > 0)', Q_SZ, s_sig), &
                col('gap', 'gap', '', 'gap w_f - w_b (0 where in contact)', Q_GAP, s_disp), &
                col('slip', 'slip', '', 'slip u_b - u_f', Q_SLIP, s_disp), &
                col('state', 'state', '', '0 lift-off, 1 stick, 2 slip', Q_STATE, 1.0_dp)]
        cols(size(cols))%integer_valued = .true.
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('N/F', 'N/F', '', 'axial force', Q_N, 1.0_dp/f), &
                    col('M/(Fl)', 'M/(Fl)', '', 'bending moment (> 0 hogging)', Q_M, &
                        1.0_dp/(f*l)), &
                    col('Q/F', 'Q/F', '', 'shear force', Q_Q, 1.0_dp/f)]
        else
            cols = [cols, col('N_r*a/F', 'N_r*a/F', '', 'radial membrane force', Q_N, l/f), &
                    col('N_t*a/F', 'N_t*a/F', '', 'hoop membrane force', Q_NT, l/f), &
                    col('M_r/F', 'M_r/F', '', 'radial moment (> 0 hogging)', Q_M, 1.0_dp/f), &
                    col('M_t/F', 'M_t/F', '', 'hoop moment (> 0 hogging)', Q_MT, 1.0_dp/f), &
                    col('Q_r*a/F', 'Q_r*a/F', '', 'radial shear force', Q_Q, l/f)]
        end if
        ! the finite-element traction itself (the paper's nodal values; see station_results)
        cols = [cols, col('Sigma_x^h', 'Sigma_x^h', '', 'finite-element Sigma_x at the station', &
                          Q_SX_FE, s_sig), &
                col('Sigma_z^h', 'Sigma_z^h', '', 'finite-element Sigma_z at the station', &
                    Q_SZ_FE, s_sig)]
        cols(size(cols) - 1:)%in_report = .false.
    end function nondim_columns

    !> Columns of the physical CSV and report table, in display units.
    pure function physical_columns(m) result(cols)
        type(model_t), intent(in) :: m
        type(column_t), allocatable :: cols(:)
        type(units_t) :: un
        character(len=16) :: traction
        un = case_units(m)
        traction = merge(un%line_load, un%pressure, m%structure%kind == MODEL_BEAM)
        cols = [col(merge('x', 'r', m%structure%kind == MODEL_BEAM), merge('x', 'r', &
            m%structure%kind == MODEL_BEAM), &
                    un%length, 'position', Q_X, 1.0_dp), &
                col('u_s', 'u_s', un%disp, 'mid-plane horizontal displacement', Q_U, &
                    un%disp_factor), &
                col('w', 'w', un%disp, 'settlement', Q_W, un%disp_factor), &
                col('psi', 'psi', 'rad', 'section rotation', Q_PSI, 1.0_dp), &
                col('sigma_x', 'sigma_x', traction, 'shear traction on the soil', Q_SX, 1.0_dp), &
                col('sigma_z', 'sigma_z', traction, 'contact pressure (compression > 0)', &
                    Q_SZ, 1.0_dp)]
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('p_x', 'p_x', un%pressure, 'shear stress sigma_x/b', Q_SX, &
                              1.0_dp/m%structure%b), &
                    col('p_z', 'p_z', un%pressure, 'contact pressure sigma_z/b', Q_SZ, &
                        1.0_dp/m%structure%b)]
        end if
        cols = [cols, col('gap', 'gap', un%disp, 'gap w_f - w_b (0 where in contact)', Q_GAP, &
                          un%disp_factor), &
                col('slip', 'slip', un%disp, 'slip u_b - u_f', Q_SLIP, un%disp_factor), &
                col('state', 'state', '', '0 lift-off, 1 stick, 2 slip', Q_STATE, 1.0_dp)]
        cols(size(cols))%integer_valued = .true.
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('N', 'N', un%force, 'axial force', Q_N, 1.0_dp), &
                    col('M', 'M', un%moment, 'bending moment (> 0 hogging)', Q_M, 1.0_dp), &
                    col('Q', 'Q', un%force, 'shear force', Q_Q, 1.0_dp)]
        else
            cols = [cols, col('N_r', 'N_r', un%line_load, 'radial membrane force', Q_N, 1.0_dp), &
                    col('N_t', 'N_t', un%line_load, 'hoop membrane force', Q_NT, 1.0_dp), &
                    col('M_r', 'M_r', trim(un%moment)//'/'//trim(un%length), &
                        'radial moment (> 0 hogging)', Q_M, 1.0_dp), &
                    col('M_t', 'M_t', trim(un%moment)//'/'//trim(un%length), &
                        'hoop moment (> 0 hogging)', Q_MT, 1.0_dp), &
                    col('Q_r', 'Q_r', un%line_load, 'radial shear force', Q_Q, 1.0_dp)]
        end if
    end function physical_columns

    pure function col(key, symbol, unit, meaning, quantity, factor) result(c)
        character(len=*), intent(in) :: key, symbol, unit, meaning
        integer, intent(in) :: quantity
        real(dp), intent(in) :: factor
        type(column_t) :: c
        c%key = key
        c%symbol = symbol
        c%unit = unit
        c%meaning = meaning
        c%quantity = quantity
        c%scale = factor
    end function col

    !> Position of the column named `key` in `cols`; 0 if absent.
    pure integer function column_index(cols, key) result(i)
        type(column_t), intent(in) :: cols(:)
        character(len=*), intent(in) :: key
        do i = 1, size(cols)
            if (trim(cols(i)%key) == key) return
        end do
        i = 0
    end function column_index
end module station_columns
