!> The one table of station columns: for every quantity at a station, its name, its
!! nondimensional symbol (SPEC §6), its physical unit and the factors that turn the stored
!! value (physical, in the deck's units) into either. The text report, the nondimensional data
!! file (.dat), the physical CSV, the figures and the tests all take their columns from here,
!! so no module reads a station column by its number.
!!
!! Units and factors come from the case's one table of scales (case_scales).
!!
!! Two columns of each traction: the element mean at the station (Sigma_x, Sigma_z; sigma_x,
!! sigma_z, p_x, p_z: the force the elements carry, what the report and the design summary
!! use) and the pointwise finite-element field (Sigma_x^h, Sigma_z^h; sigma_x_fe, sigma_z_fe,
!! p_x_fe, p_z_fe), which peaks higher under a concentrated load and at an edge in contact
!! (station_results says how each is evaluated).
module station_columns
    use kinds, only: dp
    use model, only: model_t, MODEL_BEAM
    use case_scales, only: units_t, scales_t, case_units, nondim_scale_factors
    implicit none
    private

    !> Stored station quantities (rows of station_table_t%val), physical deck units.
    integer, parameter, public :: Q_X = 1, Q_U = 2, Q_W = 3, Q_PSI = 4, Q_SX = 5, Q_SZ = 6, &
                                  Q_GAP = 7, Q_SLIP = 8, Q_STATE = 9, Q_N = 10, Q_NT = 11, &
                                  Q_M = 12, Q_MT = 13, Q_Q = 14, Q_SX_FE = 15, Q_SZ_FE = 16
    integer, parameter, public :: n_quantities = 16

    !> What a column means to a figure (its role): the panels ask the table for the column
    !! with a role, never for a name. ROLE_PRESSURE and ROLE_SHEAR_TRACTION are the plotted
    !! tractions (a beam's p_z, p_x per area; a plate's sigma_z, sigma_x; Sigma_z, Sigma_x);
    !! ROLE_MOMENT, ROLE_SHEAR_FORCE, ROLE_AXIAL_FORCE the beam's M, Q, N or the plate's
    !! radial M_r, Q_r, N_r; the plate's hoop M_theta, N_theta have roles of their own.
    integer, parameter, public :: ROLE_NONE = 0, ROLE_POSITION = 1, ROLE_SETTLEMENT = 2, &
                                  ROLE_GAP = 3, ROLE_PRESSURE = 4, ROLE_SHEAR_TRACTION = 5, &
                                  ROLE_STATE = 6, ROLE_SLIP = 7, ROLE_MOMENT = 8, &
                                  ROLE_HOOP_MOMENT = 9, ROLE_SHEAR_FORCE = 10, &
                                  ROLE_AXIAL_FORCE = 11, ROLE_HOOP_FORCE = 12

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
        integer :: role = ROLE_NONE         !! what it means to a figure (ROLE_*)
        character(len=24) :: words = ''     !! the quantity in words, for axis labels
        character(len=12) :: legend = ''    !! its symbol in a legend (M_theta for M_t)
    end type column_t

    public :: nondim_columns, physical_columns, column_index, role_column

contains

    !> Columns of the nondimensional data file and report table (SPEC §9 fixes the first nine).
    pure function nondim_columns(m) result(cols)
        type(model_t), intent(in) :: m   !! the model
        type(column_t), allocatable :: cols(:)
        type(scales_t) :: k
        real(dp) :: s_disp, s_psi, s_sig
        logical :: beam
        beam = m%structure%kind == MODEL_BEAM
        k = nondim_scale_factors(m)
        s_disp = k%disp
        s_psi = k%rotation
        s_sig = k%traction
        cols = [col('t', 't', '', 'x/l (beam) or r/a (plate)', Q_X, k%length), &
                col('U', 'U', '', 'mid-plane horizontal displacement', Q_U, s_disp), &
                col('W', 'W', '', 'settlement', Q_W, s_disp), &
                col('Psi', 'Psi', '', 'section rotation', Q_PSI, s_psi), &
                col('Sigma_x', 'Sigma_x', '', 'shear traction on the soil, element mean', Q_SX, &
                    s_sig), &
                col('Sigma_z', 'Sigma_z', '', 'contact pressure (compression > 0), element mean', &
                    Q_SZ, s_sig), &
                col('gap', 'gap', '', 'gap w_f - w_b (0 where in contact)', Q_GAP, s_disp), &
                col('slip', 'slip', '', 'slip u_b - u_f', Q_SLIP, s_disp), &
                col('state', 'state', '', '0 lift-off, 1 stick, 2 slip', Q_STATE, 1.0_dp)]
        cols(size(cols))%integer_valued = .true.
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('N/F', 'N/F', '', 'axial force', Q_N, k%force), &
                    col('M/(Fl)', 'M/(Fl)', '', 'bending moment (> 0 hogging)', Q_M, &
                        k%moment), &
                    col('Q/F', 'Q/F', '', 'shear force', Q_Q, k%shear)]
        else
            cols = [cols, col('N_r*a/F', 'N_r*a/F', '', 'radial membrane force', Q_N, &
                              k%line_force), &
                    col('N_t*a/F', 'N_t*a/F', '', 'hoop membrane force', Q_NT, k%line_force), &
                    col('M_r/F', 'M_r/F', '', 'radial moment (> 0 hogging)', Q_M, k%moment), &
                    col('M_t/F', 'M_t/F', '', 'hoop moment (> 0 hogging)', Q_MT, k%moment), &
                    col('Q_r*a/F', 'Q_r*a/F', '', 'radial shear force', Q_Q, k%shear)]
        end if
        ! the pointwise finite-element traction (the paper's nodal values; see station_results)
        cols = [cols, col('Sigma_x^h', 'Sigma_x^h', '', 'shear traction, finite-element field '// &
                          'at the station', Q_SX_FE, s_sig), &
                col('Sigma_z^h', 'Sigma_z^h', '', 'contact pressure, finite-element field at '// &
                    'the station', Q_SZ_FE, s_sig)]
        cols(size(cols) - 1:)%in_report = .false.
        call set_roles(cols, [character(len=12) :: 't', 'W', 'gap', 'Sigma_z', 'Sigma_x', &
                              'state', 'slip', merge('M/(Fl)', 'M_r/F ', beam), &
                              merge('     ', 'M_t/F', beam), merge('Q/F    ', 'Q_r*a/F', beam), &
                              merge('N/F    ', 'N_r*a/F', beam), merge('       ', 'N_t*a/F', &
                                  beam)], &
                       [character(len=12) :: 'M_theta/F', 'N_theta*a/F'])
    end function nondim_columns

    !> Columns of the physical CSV and report table, in display units.
    pure function physical_columns(m) result(cols)
        type(model_t), intent(in) :: m   !! the model
        type(column_t), allocatable :: cols(:)
        type(units_t) :: un
        character(len=16) :: traction
        real(dp) :: s_trac
        integer :: n_before
        un = case_units(m)
        traction = merge(un%line_load, un%pressure, m%structure%kind == MODEL_BEAM)
        ! the beam's tractions are line loads in the deck's units, the plate's pressures
        s_trac = merge(1.0_dp, un%pressure_factor, m%structure%kind == MODEL_BEAM)
        cols = [col(merge('x', 'r', m%structure%kind == MODEL_BEAM), merge('x', 'r', &
            m%structure%kind == MODEL_BEAM), &
                    un%length, 'position', Q_X, 1.0_dp), &
                col('u_s', 'u_s', un%disp, 'mid-plane horizontal displacement', Q_U, &
                    un%disp_factor), &
                col('w', 'w', un%disp, 'settlement', Q_W, un%disp_factor), &
                col('psi', 'psi', 'rad', 'section rotation', Q_PSI, 1.0_dp), &
                col('sigma_x', 'sigma_x', traction, 'shear traction on the soil, element mean', &
                    Q_SX, s_trac), &
                col('sigma_z', 'sigma_z', traction, 'contact pressure (compression > 0), '// &
                    'element mean', Q_SZ, s_trac)]
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('p_x', 'p_x', un%pressure, 'shear stress sigma_x/b', Q_SX, &
                              un%pressure_factor/m%structure%b), &
                    col('p_z', 'p_z', un%pressure, 'contact pressure sigma_z/b', Q_SZ, &
                        un%pressure_factor/m%structure%b)]
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
        ! the pointwise finite-element traction (see nondim_columns), last, out of the report
        n_before = size(cols)
        cols = [cols, col('sigma_x_fe', 'sigma_x_fe', traction, 'shear traction, '// &
                          'finite-element field at the station', Q_SX_FE, s_trac), &
                col('sigma_z_fe', 'sigma_z_fe', traction, 'contact pressure, finite-element '// &
                    'field at the station', Q_SZ_FE, s_trac)]
        if (m%structure%kind == MODEL_BEAM) then
            cols = [cols, col('p_x_fe', 'p_x_fe', un%pressure, 'shear stress sigma_x_fe/b', &
                              Q_SX_FE, un%pressure_factor/m%structure%b), &
                    col('p_z_fe', 'p_z_fe', un%pressure, 'contact pressure sigma_z_fe/b', &
                        Q_SZ_FE, un%pressure_factor/m%structure%b)]
        end if
        cols(n_before + 1:)%in_report = .false.
        if (m%structure%kind == MODEL_BEAM) then
            call set_roles(cols, [character(len=12) :: 'x', 'w', 'gap', 'p_z', 'p_x', 'state', &
                                  'slip', 'M', '', 'Q', 'N', ''], [character(len=12) :: '', ''])
        else
            call set_roles(cols, [character(len=12) :: 'r', 'w', 'gap', 'sigma_z', 'sigma_x', &
                                  'state', 'slip', 'M_r', 'M_t', 'Q_r', 'N_r', 'N_t'], &
                           [character(len=12) :: 'M_theta', 'N_theta'])
        end if
    end function physical_columns

    !> The roles of the columns named keys(ROLE_POSITION:ROLE_HOOP_FORCE) ('' where the model
    !! has none), their words, and the legends of the hoop moment and force.
    pure subroutine set_roles(cols, keys, hoop_legends)
        type(column_t), intent(inout) :: cols(:)          !! the table
        character(len=*), intent(in) :: keys(:)           !! per role, the column's key
        character(len=*), intent(in) :: hoop_legends(2)   !! M_theta, N_theta (or '')
        character(len=24), parameter :: beam_words(12) = [character(len=24) :: '', &
            'settlement', '', 'contact pressure', 'shear traction', '', 'slip u_b - u_f', &
            'bending moment', '', 'shear force', 'axial force', '']
        character(len=24), parameter :: plate_words(12) = [character(len=24) :: '', &
            'settlement', '', 'contact pressure', 'shear traction', '', 'slip u_b - u_f', &
            'radial moment', 'hoop moment', 'radial shear force', 'radial membrane force', &
            'hoop membrane force']
        integer :: r, i
        do r = 1, size(keys)
            if (len_trim(keys(r)) == 0) cycle
            i = column_index(cols, trim(keys(r)))
            cols(i)%role = r
            cols(i)%legend = cols(i)%symbol
            cols(i)%words = merge(plate_words(r), beam_words(r), &
                len_trim(keys(ROLE_HOOP_MOMENT)) > 0)
        end do
        if (len_trim(keys(ROLE_HOOP_MOMENT)) == 0) return
        cols(column_index(cols, trim(keys(ROLE_HOOP_MOMENT))))%legend = hoop_legends(1)
        cols(column_index(cols, trim(keys(ROLE_HOOP_FORCE))))%legend = hoop_legends(2)
    end subroutine set_roles

    !> Position of the column with this role in `cols`; 0 if the model has none.
    pure integer function role_column(cols, role) result(i)
        type(column_t), intent(in) :: cols(:)   !! the table
        integer, intent(in) :: role             !! ROLE_*
        do i = 1, size(cols)
            if (cols(i)%role == role) return
        end do
        i = 0
    end function role_column

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
        type(column_t), intent(in) :: cols(:)   !! the columns
        character(len=*), intent(in) :: key     !! a column name
        do i = 1, size(cols)
            if (trim(cols(i)%key) == key) return
        end do
        i = 0
    end function column_index
end module station_columns
