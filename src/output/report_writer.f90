!> The tabulated report, the whitespace data file and the gnuplot script of one case (SPEC §9).
module report_writer
    use deck_fields, only: int_text
    use number_text, only: es_text, f_text, integer_text
    use kinds, only: dp, pi
    use errors, only: error_t
    use atomic_files, only: open_temporary, commit_file
    use output_paths, only: canonical_path, deck_identity, base_name
    use input_record, only: write_input_record
    use model, only: load_t, model_t, MODEL_BEAM, LOAD_POINT, FIELD_U, FIELD_SZ, &
        flexural_rigidity, &
                     relative_stiffness, soil_shear_modulus, friction_compliance, &
                     total_vertical_load, has_concentrated_load, base_area, traction_measure
    use shape_functions, only: interp_name
    use discretization, only: discretization_t
    use contact_solver, only: solution_t
    use solution_checks, only: check_limit
    use interface_law, only: STATE_LIFTOFF, STATE_STICK, STATE_SLIP
    use station_columns, only: column_t, nondim_columns, physical_columns, column_index, &
                               role_column, Q_STATE, ROLE_POSITION, ROLE_SETTLEMENT, ROLE_GAP, &
                               ROLE_PRESSURE, ROLE_SHEAR_TRACTION, ROLE_STATE, ROLE_SLIP, &
                               ROLE_MOMENT, ROLE_HOOP_MOMENT, ROLE_SHEAR_FORCE, &
                               ROLE_AXIAL_FORCE, ROLE_HOOP_FORCE
    use case_scales, only: units_t, case_units
    use station_results, only: station_table_t, contact_extent, FLAG_TENSION, FLAG_OVERLAP
    use design_summary, only: summary_t, interval_t
    use figure_templates, only: panel_template, sweep_template, ground_template, &
                                line_length
    use summary_table, only: entry_t
    use adaptive_solve, only: adaptation_t
    use method_notes, only: simplification_text, error_method_text, adaptation_lines, &
                            no_estimate_reason
    use ground_text, only: layered, ground_model_words, write_layer_table, ground_csv_line, &
                           ground_json, write_ground_figure_settings, gp_number
    use run_identity, only: program_name, program_version, run_time, run_stamp
    use json_text, only: json_string, json_number
    use design_checks, only: evaluate_design_checks
    use check_report, only: write_check_table, write_check_json
    use report_folding, only: fold_table, fold_report_lines, write_wrapped
    implicit none
    private

    public :: write_script_folder
    public :: write_data_file, write_physical_csv, write_summary_json, write_plot_script, &
              write_sweep_script, write_report, shell_safe, json_string, json_number

    character(len=*), parameter :: state_word(0:2) = ['lift-off', 'stick   ', 'slip    ']

contains

    !> output/CASE.dat: `#` header naming every column, then one row per station, all
    !! nondimensional (SPEC §6, §9).
    subroutine write_data_file(path, m, tab, err)
        character(len=*), intent(in) :: path             !! the file written
        type(model_t), intent(in) :: m                   !! the model
        type(station_table_t), intent(in) :: tab         !! the station table
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        call write_station_file(path, trim(m%title), nondim_columns(m), tab, ' ', err)
    end subroutine write_data_file

    !> output/CASE.csv (physical decks): a header line `key [unit]`, one row per station.
    subroutine write_physical_csv(path, m, tab, err)
        character(len=*), intent(in) :: path             !! the file written
        type(model_t), intent(in) :: m                   !! the model
        type(station_table_t), intent(in) :: tab         !! the station table
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        character(len=:), allocatable :: ground
        ground = ''
        if (layered(m)) ground = ground_csv_line(m)
        call write_station_file(path, trim(m%title), physical_columns(m), tab, ',', err, ground)
    end subroutine write_physical_csv

    !> A station file: whitespace with `#` header lines (sep ' '), or CSV with one header line
    !! (after the `#` line of the program, version and run time, and a `#` line stating a
    !! layered ground, when there is one).
    subroutine write_station_file(path, title, cols, tab, sep, err, ground)
        character(len=*), intent(in) :: path, title
        type(column_t), intent(in) :: cols(:)
        type(station_table_t), intent(in) :: tab
        character(len=1), intent(in) :: sep
        type(error_t), allocatable, intent(out) :: err
        character(len=*), intent(in), optional :: ground   !! the ground's line ('' none)
        integer :: u, c
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# '//run_stamp()
        if (present(ground)) then
            if (len(ground) > 0) write (u, '(a)') ground
        end if
        if (sep == ' ') then
            write (u, '(a)') '# fricon station data: '//title
            write (u, '(a)') '# all columns nondimensional (doc/SPEC.md section 6); a station '// &
                'at a concentrated load appears twice (left and right limit)'
            do c = 1, size(cols)
                write (u, '(a,i0,a)') '# ', c, &
                    ': '//trim(cols(c)%symbol)//'  '//trim(cols(c)%meaning)
            end do
            write (u, '(a)', advance='no') '#'
            do c = 1, size(cols)
                write (u, '(1x,a)', advance='no') trim(cols(c)%symbol)
            end do
        else
            do c = 1, size(cols)
                if (c > 1) write (u, '(a)', advance='no') sep
                write (u, '(a)', advance='no') trim(column_heading(cols(c)))
            end do
        end if
        write (u, '(a)') ''
        call write_rows(u, cols, tab, sep)
        call commit_file(path, u, err)
    end subroutine write_station_file

    !> One line per station: the columns' values separated by `sep` (the state as an integer),
    !! all in one write statement (a statement per row cost 3,000 to 4,000 instructions of
    !! gfortran's per-statement work).
    subroutine write_rows(u, cols, tab, sep)
        integer, intent(in) :: u
        type(column_t), intent(in) :: cols(:)
        type(station_table_t), intent(in) :: tab
        character(len=1), intent(in) :: sep
        integer :: i, c, k
        character(len=:), allocatable :: line
        if (tab%n < 1) return
        allocate (character(len=(17*size(cols) + 1)*tab%n) :: line)
        k = 0
        rows: do i = 1, tab%n
            if (i > 1) call put(new_line('a'))
            do c = 1, size(cols)
                if (c > 1 .and. sep /= ' ') call put(sep)
                if (cols(c)%integer_valued) then
                    call put(state_field(nint(tab%val(cols(c)%quantity, i))))
                else
                    call put(es_text(tab%val(cols(c)%quantity, i)*cols(c)%scale, 16, 7, 3))
                end if
            end do
        end do rows
        write (u, '(a)') line(1:k)
    contains
        subroutine put(text)
            character(len=*), intent(in) :: text
            line(k + 1:k + len(text)) = text
            k = k + len(text)
        end subroutine put
    end subroutine write_rows

    !> A state number as '(i3)' writes it (the states are 0 to 3).
    pure function state_field(state) result(text)
        integer, intent(in) :: state     !! the station's state
        character(len=3) :: text
        text = integer_text(state)
        text = adjustr(text)
    end function state_field

    !> `key [unit]`, or `key` for a pure number.
    pure function column_heading(c) result(text)
        type(column_t), intent(in) :: c
        character(len=32) :: text
        text = c%key
        if (len_trim(c%unit) > 0) text = trim(c%key)//' ['//trim(c%unit)//']'
    end function column_heading

    !> output/CASE.json: status, units, the key results (summary_table), contact intervals
    !! and the checks. A failed case gets its status and message, and no results.
    subroutine write_summary_json(path, name, deck_path, m, status, message, e, s, sol, tab, err, &
                                  adaptation, warnings, deck_id, deck_lines)
        !> the file; case name; the deck's path; the failure ('' if none)
        character(len=*), intent(in) :: path, name, deck_path, message
        type(model_t), intent(in) :: m                           !! the model
        integer, intent(in) :: status                            !! the case's exit status
        type(entry_t), intent(in) :: e(:)          !! key results with their error estimates
        type(summary_t), intent(in) :: s                         !! the design summary
        type(solution_t), intent(in) :: sol                      !! the solution
        type(station_table_t), intent(in) :: tab                 !! the station table
        type(error_t), allocatable, intent(out) :: err           !! allocated on failure
        type(adaptation_t), intent(in), optional :: adaptation   !! what ADAPT did
        character(len=*), intent(in), optional :: warnings(:)    !! as the report prints them
        character(len=*), intent(in), optional :: deck_id        !! the deck's identity ('' for
                                                                 !! no file; default: deck_path's)
        character(len=*), intent(in), optional :: deck_lines(:)  !! the deck's text: "inputs" 
        type(units_t) :: un
        integer :: u, i
        logical :: adapted
        adapted = .false.
        if (present(adaptation)) adapted = adaptation%adapted
        call open_temporary(path, u, err)
        if (allocated(err)) return
        un = case_units(m)
        write (u, '(a)') '{'
        write (u, '(a)') '  "program": '//json_string(program_name)//','
        write (u, '(a)') '  "version": '//json_string(program_version)//','
        write (u, '(a)') '  "run_time": '//json_string(trim(run_time))//','
        write (u, '(a)') '  "case": '//json_string(name)//','
        write (u, '(a)') '  "deck": '//json_string(base_name(deck_path))//','
        ! how a later run of the same deck, from any folder, knows these files for its own
        ! (output_paths::remove_stale_outputs)
        if (present(deck_id)) then
            write (u, '(a)') '  "deck_identity": '//json_string(deck_id)//','
        else
            write (u, '(a)') '  "deck_identity": '// &
                json_string(deck_identity(canonical_path(deck_path)))//','
        end if
        if (present(deck_lines)) call write_input_record(u, m, deck_lines)
        write (u, '(a)') '  "title": '//json_string(trim(m%title))//','
        write (u, '(a)') '  "model": '//json_string(trim(merge('BEAM ', 'PLATE', &
            m%structure%kind == MODEL_BEAM)))//','
        write (u, '(a)') '  "nondimensional": '//trim(merge('true ', 'false', m%nondim))//','
        if (layered(m)) write (u, '(a)') ground_json(m)
        write (u, '(a,i0,a)') '  "status": ', status, ','
        write (u, '(a)') '  "message": '//json_string(message)//','
        if (adapted) then
            write (u, '(a,i0,a)') '  "elements": ', adaptation%ne, ','
        else
            write (u, '(a,i0,a)') '  "elements": ', m%mesh%ne, ','
        end if
        write (u, '(a)', advance='no') '  "warnings": ['
        if (present(warnings)) then
            do i = 1, size(warnings)
                write (u, '(a)', advance='no') trim(merge(', ', '  ', i > 1))// &
                    json_string(trim(warnings(i)))
            end do
        end if
        write (u, '(a)') '],'
        if (status /= 0) then
            write (u, '(a)') '  "results": null'
            write (u, '(a)') '}'
            call commit_file(path, u, err)
            return
        end if
        write (u, '(a)') '  "units": {'
        do i = 1, size(e)
            write (u, '(a)') '    '//json_string(trim(e(i)%key))//': '// &
                json_string(trim(e(i)%unit))//','
        end do
        write (u, '(a)') '    "intervals": '//json_string(trim(merge('t               ', &
            un%length, m%nondim)))
        write (u, '(a)') '  },'
        write (u, '(a)') '  "results": {'
        do i = 1, size(e)
            if (e(i)%integer_valued) then
                write (u, '(a,i0,a)') '    '//json_string(trim(e(i)%key))//': ', &
                    nint(e(i)%value), ','
            else
                write (u, '(a)') '    '//json_string(trim(e(i)%key))//': '// &
                    json_number(e(i)%value, e(i)%defined)//','
            end if
        end do
        call write_json_intervals(u, m, s%intervals, s%slip_intervals)
        write (u, '(a)') '  },'
        call write_json_singular(u, e)
        write (u, '(a)') '  "pressures": "element means at the stations (the force the '// &
            'elements carry); the pointwise finite-element field is in the station files '// &
            '(Sigma_z^h; CSV sigma_z_fe)",'
        call write_json_errors(u, e, adapted)
        if (adapted) call write_json_adaptation(u, adaptation)
        call write_check_json(u, evaluate_design_checks(m, s))
        call write_json_checks(u, sol, tab, s)
        write (u, '(a)') '}'
        call commit_file(path, u, err)
    end subroutine write_summary_json

    !> "singular_results": the keys whose value is unbounded in the model where it is taken
    !! (summary_table::mark_singular): the mesh decides them.
    subroutine write_json_singular(u, e)
        integer, intent(in) :: u
        type(entry_t), intent(in) :: e(:)
        integer :: i
        logical :: first
        first = .true.
        write (u, '(a)', advance='no') '  "singular_results": ['
        do i = 1, size(e)
            if (.not. (e(i)%singular .and. e(i)%defined)) cycle
            if (.not. first) write (u, '(a)', advance='no') ', '
            write (u, '(a)', advance='no') json_string(trim(e(i)%key))
            first = .false.
        end do
        write (u, '(a)') '],'
    end subroutine write_json_singular

    !> "errors": the estimated absolute error of each estimated key (same unit as the
    !! result), "error_orders": the observed order (null where first order was assumed),
    !! "error_method": how the estimate was obtained (module error_estimate), or why there is
    !! none.
    subroutine write_json_errors(u, e, adapted)
        integer, intent(in) :: u
        type(entry_t), intent(in) :: e(:)
        logical, intent(in) :: adapted      !! the mesh was adapted (ADAPT)
        integer :: i, k
        character(len=*), parameter :: blocks(2) = ['errors      ', 'error_orders']
        do k = 1, 2
            write (u, '(a)', advance='no') '  "'//trim(blocks(k))//'": {'
            first: block
                logical :: first_item
                first_item = .true.
                do i = 1, size(e)
                    if (.not. e(i)%has_error) cycle
                    if (.not. first_item) write (u, '(a)', advance='no') ', '
                    if (k == 1) then
                        write (u, '(a)', advance='no') json_string(trim(e(i)%key))//': '// &
                            json_number(e(i)%error, .true.)
                    else
                        write (u, '(a)', advance='no') json_string(trim(e(i)%key))//': '// &
                            json_number(e(i)%order, e(i)%order > 0.0_dp)
                    end if
                    first_item = .false.
                end do
            end block first
            write (u, '(a)') '},'
        end do
        if (any(e%has_error)) then
            write (u, '(a)') '  "error_method": '//json_string(error_method_text(adapted))//','
        else
            write (u, '(a)') '  "error_method": '// &
                json_string('no error estimate: '//no_estimate_reason())//','
        end if
    end subroutine write_json_errors

    !> "adaptation": the ADAPT settings, the cycles, the final N_e and estimate, whether the
    !! tolerance was reached (and if not, why), and each cycle's N_e and estimate.
    subroutine write_json_adaptation(u, a)
        integer, intent(in) :: u
        type(adaptation_t), intent(in) :: a
        integer :: k
        write (u, '(a)') '  "adaptation": {'
        write (u, '(a)') '    "tolerance": '//json_number(a%tol, .true.)//','
        write (u, '(a,i0,a)') '    "max_elements": ', a%max_ne, ','
        write (u, '(a,i0,a)') '    "cycles": ', a%cycles, ','
        write (u, '(a,i0,a)') '    "elements": ', a%ne, ','
        write (u, '(a)') '    "estimate": '//json_number(a%estimate, a%estimate >= 0.0_dp)//','
        write (u, '(a)') '    "estimate_key": '//json_string(a%worst)//','
        write (u, '(a)') '    "tolerance_reached": '//trim(merge('true ', 'false', a%reached))//','
        write (u, '(a)') '    "note": '//json_string(a%note)//','
        write (u, '(a)', advance='no') '    "history": ['
        do k = 1, size(a%history_ne)
            if (k > 1) write (u, '(a)', advance='no') ', '
            write (u, '(a,i0,a)', advance='no') '[', a%history_ne(k), ', '// &
                json_number(a%history_estimate(k), a%history_estimate(k) >= 0.0_dp)//']'
        end do
        write (u, '(a)') ']'
        write (u, '(a)') '  },'
    end subroutine write_json_adaptation

    !> "contact_intervals", "liftoff_intervals" (iv) and "slip_intervals" (slip).
    subroutine write_json_intervals(u, m, iv, slip)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(interval_t), intent(in) :: iv(:), slip(:)
        real(dp) :: scale
        integer :: k
        logical :: first
        character(len=*), parameter :: kinds(3) = [character(len=17) :: 'contact_intervals', &
                                                   'liftoff_intervals', 'slip_intervals']
        integer :: j
        scale = merge(1.0_dp/m%structure%length, 1.0_dp, m%nondim)
        do j = 1, 3
            write (u, '(a)', advance='no') '    "'//trim(kinds(j))//'": ['
            first = .true.
            if (j < 3) then
                do k = 1, size(iv)
                    if (iv(k)%contact .neqv. (j == 1)) cycle
                    call pair(iv(k))
                end do
            else
                do k = 1, size(slip)
                    call pair(slip(k))
                end do
            end if
            write (u, '(a)') merge(']  ', '], ', j == 3)
        end do
    contains
        subroutine pair(one)
            type(interval_t), intent(in) :: one
            if (.not. first) write (u, '(a)', advance='no') ', '
            write (u, '(a)', advance='no') '['//json_number(one%x1*scale, .true.)//', '// &
                json_number(one%x2*scale, .true.)//']'
            first = .false.
        end subroutine pair
    end subroutine write_json_intervals

    subroutine write_json_checks(u, sol, tab, s)
        integer, intent(in) :: u
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(in) :: s
        write (u, '(a)') '  "checks": {'
        write (u, '(a)') '    "equilibrium": '//json_number(s%equilibrium, .true.)//','
        write (u, '(a)') '    "residual_structure": '//json_number(sol%residual(1), .true.)//','
        write (u, '(a)') '    "residual_interface": '//json_number(sol%residual(2), .true.)//','
        write (u, '(a)') '    "interface_law_traction_error": '// &
            json_number(sol%law_residual, .true.)//','
        write (u, '(a)') '    "check_limit": '//json_number(check_limit, .true.)//','
        write (u, '(a)') '    "complementarity": '//json_number(tab%complementarity, .true.)//','
        write (u, '(a)') '    "compatibility": '//json_number(tab%compatibility, .true.)//','
        write (u, '(a)') '    "friction_admissibility": '//json_number(s%admissibility, .true.)//','
        write (u, '(a)') '    "friction_admissibility_tol": '// &
            json_number(s%admissibility_tol, .true.)//','
        write (u, '(a)') '    "friction_admissible": '// &
            trim(merge('true ', 'false', s%admissibility <= s%admissibility_tol))//','
        write (u, '(a,i0,a)') '    "tension_flags": ', s%n_tension_flags, ','
        write (u, '(a,i0)') '    "overlap_flags": ', s%n_overlap_flags
        write (u, '(a)') '  }'
    end subroutine write_json_checks

    !> output/CASE.gp: the figure of one case, self-contained: the settings of the case
    !! (write_figure_settings) and the panel template (embedded in the program). The data file
    !! (CASE.csv for physical decks, CASE.dat for NONDIM decks) and the PNG are named relative
    !! to the script's own folder, so `gnuplot CASE.gp` draws from any working folder.
    subroutine write_plot_script(path, name, m, label, s, err)
        character(len=*), intent(in) :: path     !! the script, e.g. output/default.gp
        character(len=*), intent(in) :: name     !! the case, e.g. default or sweep_002
        type(model_t), intent(in) :: m           !! the model
        character(len=*), intent(in) :: label    !! 'case 002 of 006: RHO=0.001 F=0.5' or ''
        type(summary_t), intent(in) :: s         !! the design summary
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        character(len=:), allocatable :: title
        integer :: u
        title = 'fricon: '//trim(shell_safe(m%title))
        if (index(label, ':') > 0) title = title//"'.""\n"".'"//trim(shell_safe(label))
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# fricon figure of case '//name//': gnuplot '//name//'.gp draws '// &
            name//'.png (from any folder)'
        call write_script_folder(u)
        write (u, '(a)') "data = gp_dir.'"//name//trim(merge('.dat', '.csv', m%nondim))//"'"
        write (u, '(a)') "png = exists(""png_override"") ? png_override : gp_dir.'"//name//".png'"
        write (u, '(a)') "title = '"//title//"'"
        call write_figure_settings(u, m, s%mean_pressure)
        call write_panels(u, m)
        call commit_file(path, u, err)
    end subroutine write_plot_script

    !> STEM_sweep.gp: the solved cases of a sweep overlaid, self-contained: the settings of
    !! the first case (the cases of a sweep share columns, units and loads), the case files and
    !! their legend labels and mean pressures, and the sweep template.
    subroutine write_sweep_script(path, stem, m, names, labels, means, err)
        character(len=*), intent(in) :: path, stem  !! the script written; the deck's file stem
        type(model_t), intent(in) :: m              !! the first solved case
        character(len=*), intent(in) :: names(:)    !! case names (files NAME.csv or NAME.dat)
        character(len=*), intent(in) :: labels(:)   !! legend phrases in single quotes, e.g.
                                                    !! 'RHO=0.001 F=0.5' (one gnuplot word)
        real(dp), intent(in) :: means(:)            !! mean contact pressure of each case
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(column_t), allocatable :: cols(:)
        integer :: u, i
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# fricon sweep figure: gnuplot '//stem//'_sweep.gp draws '//stem// &
            '_sweep.png (from any folder)'
        call write_script_folder(u)
        call write_figure_settings(u, m, means(1))
        write (u, '(a)') "files = ''"
        write (u, '(a)') "labels = ''"
        write (u, '(a)') "p_means = ''"
        if (m%nondim) then
            cols = nondim_columns(m)
        else
            cols = physical_columns(m)
        end if
        do i = 1, size(names)
            write (u, '(a)') "files = files.' '.gp_dir.'"//trim(names(i))// &
                trim(merge('.dat', '.csv', m%nondim))//"'"
            write (u, '(a)') 'labels = labels." '//trim(labels(i))//'"'
            write (u, '(a)') "p_means = p_means.' "// &
                gp_number(means(i)*pressure_scale(m, cols))//"'"
        end do
        write (u, '(a)') "sweep_png = gp_dir.'"//stem//"_sweep.png'"
        write (u, '(a)') "title = 'fricon: "//trim(shell_safe(m%title))//" (sweep)'"
        call write_lines(u, sweep_template())
        call commit_file(path, u, err)
    end subroutine write_sweep_script

    !> gp_dir: the folder of the running script (gnuplot sets ARG0 to its path), '' for the
    !! current one; data and figure are named relative to it.
    subroutine write_script_folder(u)
        integer, intent(in) :: u   !! the open .gp file
        write (u, '(a)') "gp_dir = ''"
        write (u, '(a)') "do for [i_ = strlen(ARG0):1:-1] { if (gp_dir eq '' && ARG0[i_:i_] "// &
            "eq '/') { gp_dir = ARG0[1:i_] } }"
    end subroutine write_script_folder

    !> The lines, trimmed, in one write statement (a template of 200 lines written line by line
    !! cost 0.4 M instructions of gfortran's per-statement work).
    subroutine write_lines(u, lines)
        integer, intent(in) :: u
        character(len=*), intent(in) :: lines(:)
        character(len=:), allocatable :: text
        integer :: i, k, n(size(lines))
        if (size(lines) == 0) return
        n = len_trim(lines)   ! once: the template lines are mostly blanks to scan
        allocate (character(len=sum(n) + size(lines) - 1) :: text)
        k = 0
        do i = 1, size(lines)
            text(k + 1:k + n(i)) = lines(i)(1:n(i))
            k = k + n(i)
            if (i < size(lines)) then
                text(k + 1:k + 1) = new_line('a')
                k = k + 1
            end if
        end do
        write (u, '(a)') text
    end subroutine write_lines

    !> Factor from a pressure (force/length^2) to the plotted pressure column: that column's
    !! scale applied to the traction the model stores (a beam's line load is b times the
    !! pressure).
    pure real(dp) function pressure_scale(m, cols) result(f)
        type(model_t), intent(in) :: m
        type(column_t), intent(in) :: cols(:)
        character(len=7) :: key
        if (m%nondim) then
            key = 'Sigma_z'
        else
            key = merge('p_z    ', 'sigma_z', m%structure%kind == MODEL_BEAM)
        end if
        f = cols(column_index(cols, trim(key)))%scale*merge(m%structure%b, 1.0_dp, &
            m%structure%kind == MODEL_BEAM)
    end function pressure_scale

    !> The settings a panel or sweep template reads: model, data format, column numbers,
    !! axis labels and legend names with units (all from the station column table, by the
    !! columns' roles), the clip rule, the friction coefficient and the load positions.
    subroutine write_figure_settings(u, m, mean_pressure)
        integer, intent(in) :: u                   !! the open .gp file
        type(model_t), intent(in) :: m             !! the case
        real(dp), intent(in) :: mean_pressure      !! V / contact area [F/L^2]; 0: V / base
        type(column_t), allocatable :: cols(:)
        logical :: beam, phys
        real(dp) :: p_mean, xs
        beam = m%structure%kind == MODEL_BEAM
        phys = .not. m%nondim
        if (phys) then
            cols = physical_columns(m)
        else
            cols = nondim_columns(m)
        end if
        xs = cols(role_column(cols, ROLE_POSITION))%scale
        if (mean_pressure > 0.0_dp) then
            p_mean = mean_pressure*pressure_scale(m, cols)
        else      ! no contact area known: the load over the base
            p_mean = total_vertical_load(m%loads)/base_area(m%structure)*pressure_scale(m, cols)
        end if
        write (u, '(a)') "model = '"//trim(merge('BEAM ', 'PLATE', beam))//"'"
        write (u, '(a)') 'csv = '//int_text(merge(1, 0, phys))
        call write_figure_columns(u, cols)
        call write_figure_labels(u, cols, m%nondim, beam)
        if (beam .and. phys) then
            write (u, '(a)') '# beam width b: the right axis of the pressure panel is the '// &
                'line load b p_z'
            ! line load [F/L] = b [L] times the pressure in F/L^2 (display / its factor)
            call put_num(u, 'line_width', m%structure%b/pressure_scale(m, cols))
            call put_text(u, 'lab_line', 'line load b p_z ['//trim(case_line_load(m))//']')
        else
            call put_num(u, 'line_width', 0.0_dp)
            call put_text(u, 'lab_line', '')
        end if
        write (u, '(a)') '# clip rule: p_clip = max(clip_factor p_mean, clip_inner x the '// &
            'largest pressure'
        write (u, '(a)') '# at least edge_d from a free edge); p_mean = V / contact area, '// &
            'edge_d = h'
        call put_num(u, 'p_mean', p_mean)
        call put_num(u, 'clip_factor', 1.5_dp)
        call put_num(u, 'clip_inner', 1.25_dp)
        call put_num(u, 'edge_d', m%structure%h*xs)
        call put_num(u, 'friction', m%interface%f)
        call write_figure_loads(u, m%loads, xs)
        if (layered(m)) call write_ground_figure_settings(u, m, xs, &
                                                          trim(case_units_pressure(m)))
    end subroutine write_figure_settings

    !> The pressure unit of the case (kPa for kN and m).
    function case_units_pressure(m) result(unit)
        type(model_t), intent(in) :: m    !! the case
        character(len=:), allocatable :: unit
        type(units_t) :: un
        un = case_units(m)
        unit = trim(un%pressure)
    end function case_units_pressure

    !> The panel template; for a case on layered ground with the ground template's two parts
    !! (scripts/gnuplot/fricon_ground.gp): its layout in place of the panels' `set multiplot
    !! layout` line, its profile panel before their `unset multiplot`.
    subroutine write_panels(u, m)
        integer, intent(in) :: u                   !! the open .gp file
        type(model_t), intent(in) :: m             !! the case
        character(len=line_length), allocatable :: panels(:), ground(:)
        integer :: i, mark
        panels = panel_template()
        if (.not. layered(m)) then
            call write_lines(u, panels)
            return
        end if
        ground = ground_template()
        mark = size(ground) + 1
        do i = size(ground), 1, -1
            if (index(ground(i), '# ---- the profile panel') == 1) mark = i
        end do
        do i = 1, size(panels)
            if (index(panels(i), 'set multiplot layout') == 1) then
                call write_lines(u, ground(1:mark - 1))
                cycle
            end if
            if (trim(panels(i)) == 'unset multiplot') call write_lines(u, ground(mark:))
            write (u, '(a)') trim(panels(i))
        end do
    end subroutine write_panels

    !> The line-load unit of a physical deck (force/length).
    function case_line_load(m) result(unit)
        type(model_t), intent(in) :: m    !! the case
        character(len=:), allocatable :: unit
        type(units_t) :: un
        un = case_units(m)
        unit = trim(un%line_load)
    end function case_line_load

    !> The data file's column number of each plotted quantity (0: the model has none).
    subroutine write_figure_columns(u, cols)
        integer, intent(in) :: u                   !! the open .gp file
        type(column_t), intent(in) :: cols(:)      !! the case's station columns
        character(len=8), parameter :: names(12) = [character(len=8) :: 'c_x', 'c_w', &
            'c_gap', 'c_p', 'c_s', 'c_state', 'c_slip', 'c_m', 'c_mt', 'c_q', 'c_n', 'c_nt']
        integer, parameter :: roles(12) = [ROLE_POSITION, ROLE_SETTLEMENT, ROLE_GAP, &
            ROLE_PRESSURE, ROLE_SHEAR_TRACTION, ROLE_STATE, ROLE_SLIP, ROLE_MOMENT, &
            ROLE_HOOP_MOMENT, ROLE_SHEAR_FORCE, ROLE_AXIAL_FORCE, ROLE_HOOP_FORCE]
        integer :: k
        write (u, '(a)') '# columns of the data file (station column table)'
        do k = 1, size(names)
            write (u, '(a)') trim(names(k))//' = '//int_text(role_column(cols, roles(k)))
        end do
    end subroutine write_figure_columns

    !> Axis labels ('settlement w [mm]': words, symbol, unit) and legend names; a plate's
    !! moment and membrane panels show the radial and hoop quantities together.
    subroutine write_figure_labels(u, cols, nondim, beam)
        integer, intent(in) :: u                   !! the open .gp file
        type(column_t), intent(in) :: cols(:)      !! the case's station columns
        logical, intent(in) :: nondim              !! t = x/l or r/a on the x axis
        logical, intent(in) :: beam                !! a beam (else a plate)
        write (u, '(a)') '# axis labels and legend names'
        if (nondim) then
            call put_text(u, 'lab_x', heading(ROLE_POSITION, '', &
                                              trim(merge('t = x/l', 't = r/a', beam))))
        else
            call put_text(u, 'lab_x', heading(ROLE_POSITION, ''))
        end if
        call put_text(u, 'lab_w', heading(ROLE_SETTLEMENT))
        call put_text(u, 'lab_p', heading(ROLE_PRESSURE))
        call put_text(u, 'lab_s', heading(ROLE_SHEAR_TRACTION))
        call put_text(u, 'lab_slip', heading(ROLE_SLIP, symbols=''))
        if (beam) then
            call put_text(u, 'lab_m', heading(ROLE_MOMENT))
            call put_text(u, 'lab_q', heading(ROLE_SHEAR_FORCE))
            call put_text(u, 'lab_n', heading(ROLE_AXIAL_FORCE))
            call put_text(u, 'lab_mr', heading(ROLE_MOMENT))
            call put_text(u, 'lab_mt', '')
        else
            call put_text(u, 'lab_m', heading(ROLE_MOMENT, 'moments', &
                                              legend(ROLE_MOMENT)//', '//legend(ROLE_HOOP_MOMENT)))
            call put_text(u, 'lab_q', heading(ROLE_SHEAR_FORCE))
            call put_text(u, 'lab_n', heading(ROLE_AXIAL_FORCE, 'membrane forces', &
                                              legend(ROLE_AXIAL_FORCE)//', '// &
                                              legend(ROLE_HOOP_FORCE)))
            call put_text(u, 'lab_mr', heading(ROLE_MOMENT))
            call put_text(u, 'lab_mt', heading(ROLE_HOOP_MOMENT, symbols=legend(ROLE_HOOP_MOMENT)))
        end if
        call put_text(u, 'key_w', legend(ROLE_SETTLEMENT))
        call put_text(u, 'key_p', legend(ROLE_PRESSURE))
        call put_text(u, 'key_s', legend(ROLE_SHEAR_TRACTION))
        call put_text(u, 'key_slip', 'slip')
        call put_text(u, 'key_m', legend(ROLE_MOMENT))
        call put_text(u, 'key_mt', legend(ROLE_HOOP_MOMENT))
        call put_text(u, 'key_q', legend(ROLE_SHEAR_FORCE))
        call put_text(u, 'key_n', legend(ROLE_AXIAL_FORCE))
        call put_text(u, 'key_nt', legend(ROLE_HOOP_FORCE))
        call put_text(u, 'p_unit', trim(cols(role_column(cols, ROLE_PRESSURE))%unit))

    contains

        !> 'settlement w [mm]': the column's words (or `words`), its symbol (or `symbols`) and
        !! its unit (none for a pure number).
        function heading(role, words, symbols) result(text)
            integer, intent(in) :: role
            character(len=*), intent(in), optional :: words, symbols
            character(len=:), allocatable :: text, sym
            integer :: i
            i = role_column(cols, role)
            sym = trim(cols(i)%symbol)
            if (present(symbols)) sym = trim(symbols)
            text = trim(cols(i)%words)
            if (present(words)) text = trim(words)
            if (len(sym) > 0 .and. len(text) > 0) text = text//' '
            text = text//sym
            if (len_trim(cols(i)%unit) > 0) text = text//' ['//trim(cols(i)%unit)//']'
        end function heading

        !> The legend symbol of the column with this role ('' if none).
        function legend(role) result(text)
            integer, intent(in) :: role
            character(len=:), allocatable :: text
            text = ''
            if (role_column(cols, role) > 0) text = trim(cols(role_column(cols, role))%legend)
        end function legend
    end subroutine write_figure_labels

    !> name = 'text' (quoted, shell-safe) in a gnuplot settings block.
    subroutine put_text(u, name, text)
        integer, intent(in) :: u                   !! the open .gp file
        character(len=*), intent(in) :: name, text !! variable and its value
        write (u, '(a)') name//" = '"//trim(shell_safe(text))//"'"
    end subroutine put_text

    !> name = x in a gnuplot settings block.
    subroutine put_num(u, name, x)
        integer, intent(in) :: u                   !! the open .gp file
        character(len=*), intent(in) :: name       !! variable
        real(dp), intent(in) :: x                  !! its value
        write (u, '(a)') name//' = '//gp_number(x)
    end subroutine put_num

    !> The loads of the figure settings as gnuplot arrays: kind letter (P point, M moment,
    !! R ring, D patch) and the interval [x1, x2] (a point for all but the patch), in the
    !! plotted unit of x (xs per deck length).
    subroutine write_figure_loads(u, loads, xs)
        use model, only: LOAD_PATCH, LOAD_MOMENT, LOAD_RING
        integer, intent(in) :: u
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        real(dp), intent(in) :: xs
        character(len=1) :: kind_letter
        integer :: k, n
        write (u, '(a)') '# loads: P point, M moment, R ring, D patch [load_x1, load_x2] '// &
            '(plotted unit)'
        n = size(loads)
        write (u, '(a)') 'n_loads = '//int_text(n)
        if (n == 0) return
        write (u, '(a)', advance='no') 'array load_kind['//int_text(n)//'] = ['
        do k = 1, n
            select case (loads(k)%kind)
            case (LOAD_PATCH)
                kind_letter = 'D'
            case (LOAD_MOMENT)
                kind_letter = 'M'
            case (LOAD_RING)
                kind_letter = 'R'
            case default
                kind_letter = 'P'
            end select
            write (u, '(a)', advance='no') "'"//kind_letter//"'"//after(k)
        end do
        write (u, '(a)') ''
        write (u, '(a)', advance='no') 'array load_x1['//int_text(n)//'] = ['
        do k = 1, n
            write (u, '(a)', advance='no') gp_number(loads(k)%x1*xs)//after(k)
        end do
        write (u, '(a)') ''
        write (u, '(a)', advance='no') 'array load_x2['//int_text(n)//'] = ['
        do k = 1, n
            write (u, '(a)', advance='no') gp_number(merge(loads(k)%x2, loads(k)%x1, &
                loads(k)%kind == LOAD_PATCH)*xs)//after(k)
        end do
        write (u, '(a)') ''
    contains
        !> ', ' between the items of a gnuplot array, ']' after the last.
        function after(k) result(text)
            integer, intent(in) :: k
            character(len=:), allocatable :: text
            text = ']'
            if (k < n) text = ', '
        end function after
    end subroutine write_figure_loads

    !> Text safe inside single quotes of a shell or gnuplot command: quotes, backquote, $ and
    !! backslash become blanks.
    pure function shell_safe(text) result(safe)
        character(len=*), intent(in) :: text   !! any text
        character(len=len(text)) :: safe
        integer :: i
        safe = text
        do i = 1, len(safe)
            if (index("'""`$\", safe(i:i)) > 0) safe(i:i) = ' '
        end do
    end function shell_safe

    !> The text report. `failure` non-empty: ANALYSIS FAILED banner, log only.
    subroutine write_report(path, deck_path, lines, label, m, d, sol, tab, e, s, failure, notes, &
                            err, adaptation)
        !> the report; the deck; the case's label; the failure ('' if none)
        character(len=*), intent(in) :: path, deck_path, label, failure
        type(entry_t), intent(in) :: e(:)          !! key results with their error estimates
        character(len=*), intent(in) :: notes(:)   !! 'WARNING: ...' and 'NOTE: ...' lines
        character(len=*), intent(in) :: lines(:)   !! the deck's lines (echoed)
        type(model_t), intent(in) :: m             !! the model
        type(discretization_t), intent(in) :: d    !! the discretisation
        type(solution_t), intent(in) :: sol        !! the solution
        type(station_table_t), intent(in) :: tab   !! the station table
        type(summary_t), intent(in) :: s           !! the design summary
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(adaptation_t), intent(in), optional :: adaptation   !! what ADAPT did
        character(len=400), allocatable :: adapt_text(:)
        integer :: u, i
        allocate (adapt_text(0))
        if (present(adaptation)) adapt_text = adaptation_lines(adaptation)
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') repeat('=', 100)
        write (u, '(a)') ' fricon - beam / circular raft on an elastic half-space with '// &
            'lift-off and friction'
        write (u, '(a)') ' deck: '//base_name(deck_path)//'    case: '//label
        write (u, '(a)') ' title: '//trim(m%title)
        write (u, '(a)') ' '//run_stamp()
        write (u, '(a)') repeat('=', 100)
        if (len_trim(failure) > 0) then
            write (u, '(/,a)') ' *** ANALYSIS FAILED ***'
            call write_wrapped(u, ' '//trim(failure))
            write (u, '(a)') ''
        end if
        call write_echo(u, lines)
        call write_groups(u, m, d, sol)
        do i = 1, size(adapt_text)
            call write_wrapped(u, '   '//trim(adapt_text(i)))
        end do
        call write_conventions(u, m)
        call write_log(u, sol)
        if (len_trim(failure) == 0) then
            call write_table(u, ' 5. STATIONS (nondimensional, doc/SPEC.md section 6)', &
                nondim_columns(m), &
                             tab, .true.)
            if (.not. m%nondim) call write_table(u, ' 6. STATIONS (physical units)', &
                                                 physical_columns(m), tab, .false.)
            call write_station_notes(u, m, tab)
            call write_summary(u, m, e, s, size(adapt_text) > 0)
            call write_checks(u, m, sol, tab, s)
            call write_check_table(u, evaluate_design_checks(m, s))
        end if
        if (any(len_trim(notes) > 0)) write (u, '(a)') ''
        do i = 1, size(notes)
            if (len_trim(notes(i)) > 0) call write_wrapped(u, ' '//trim(notes(i)))
        end do
        call commit_file(path, u, err)
        if (.not. allocated(err)) call fold_report_lines(path, err)
    end subroutine write_report

    subroutine write_echo(u, lines)
        integer, intent(in) :: u
        character(len=*), intent(in) :: lines(:)
        integer :: i
        write (u, '(/,a)') ' 1. INPUT ECHO'
        write (u, '(a)') '  line '// &
            '|....+....1....+....2....+....3....+....4....+....5....+....6....+....7....+....8'
        do i = 1, size(lines)
            write (u, '(i6,a,a)') i, ' |', trim(lines(i))
        end do
    end subroutine write_echo

    subroutine write_groups(u, m, d, sol)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        character(len=*), parameter :: fmt = '(3x,a,t46,es14.6,2x,a)'
        integer :: field
        write (u, '(/,a)') ' 2. MODEL, NONDIMENSIONAL GROUPS AND PHYSICAL DATA'
        if (m%structure%kind == MODEL_BEAM .and. layered(m)) then
            call write_wrapped(u, '   model: BEAM (Timoshenko) on '//ground_model_words(m)// &
                ', tractions uniform across the width, compatibility on the centre line')
            write (u, fmt) 'rho = 32 EI (1-nu_f^2)/(pi E_f l^4)', relative_stiffness(m%structure, &
                m%ground)
            write (u, fmt) 'beta = b/l', m%structure%b/m%structure%length
        else if (layered(m)) then
            write (u, '(3x,a)') 'model: PLATE (axisymmetric Mindlin) on '//ground_model_words(m)
            write (u, fmt) 'rho = 2 D (1-nu_f^2)/(E_f a^3)', relative_stiffness(m%structure, &
                m%ground)
        else if (m%structure%kind == MODEL_BEAM) then
            write (u, '(3x,a)') 'model: BEAM (Timoshenko) on a 3-D elastic half-space, '// &
                'tractions uniform across the width, compatibility on the centre line'
            write (u, fmt) 'rho = 32 EI (1-nu_f^2)/(pi E_f l^4)', relative_stiffness(m%structure, &
                m%ground)
            write (u, fmt) 'beta = b/l', m%structure%b/m%structure%length
        else
            write (u, '(3x,a)') 'model: PLATE (axisymmetric Mindlin) on a 3-D elastic half-space'
            write (u, fmt) 'rho = 2 D (1-nu_f^2)/(E_f a^3)', relative_stiffness(m%structure, &
                m%ground)
        end if
        write (u, fmt) 'zeta = h/l (beam) or h/a (plate)', m%structure%h/m%structure%length
        write (u, fmt) 'nu (structure)', m%structure%nu
        write (u, fmt) 'nu_f (soil)', m%ground%nu_f
        write (u, fmt) 'f (friction coefficient)', m%interface%f
        write (u, fmt) 'eps_bar (friction regularisation)', m%interface%eps_bar
        write (u, fmt) 'eta_bar (penalty of the tension zone)', m%interface%eta_bar
        if (m%nondim) then
            write (u, '(3x,a)') 'physical set chosen to reproduce the groups: l (a) = 1, E = '// &
                '1, F = 1'
        end if
        write (u, fmt) 'l (beam length) or a (plate radius)', m%structure%length, &
            trim(m%units%length)
        write (u, fmt) 'h (thickness)', m%structure%h, trim(m%units%length)
        if (m%structure%kind == MODEL_BEAM) write (u, fmt) 'b (width)', m%structure%b, &
            trim(m%units%length)
        write (u, fmt) 'E (structure)', m%structure%e, &
            trim(m%units%force)//'/'//trim(m%units%length)//'^2'
        write (u, fmt) 'k (shear correction)', m%structure%k_shear
        write (u, fmt) 'E_f (soil)', m%ground%e_f, &
            trim(m%units%force)//'/'//trim(m%units%length)//'^2'
        write (u, fmt) 'G_f (soil)', soil_shear_modulus(m%ground), &
            trim(m%units%force)//'/'//trim(m%units%length)//'^2'
        if (layered(m)) call write_layer_table(u, m)
        if (m%structure%kind == MODEL_BEAM) then
            write (u, fmt) 'EI (bending stiffness)', flexural_rigidity(m%structure), &
                trim(m%units%force)//' '//trim(m%units%length)//'^2'
            write (u, fmt) 'c = 1/(4 pi G_f) (friction compliance)', &
                friction_compliance(m%structure, m%ground), &
                trim(m%units%length)//'^2/'//trim(m%units%force)
        else
            write (u, fmt) 'D (bending stiffness per unit width)', flexural_rigidity(m%structure), &
                trim(m%units%force)//' '//trim(m%units%length)
            write (u, fmt) 'c = a/(4 pi G_f) (friction compliance)', &
                friction_compliance(m%structure, m%ground), &
                trim(m%units%length)//'^3/'//trim(m%units%force)
        end if
        write (u, fmt) 'F (total vertical load)', total_vertical_load(m%loads), trim(m%units%force)
        write (u, fmt) 'H (total horizontal load)', sum(m%loads%fx), trim(m%units%force)
        write (u, '(3x,a,i0,a,a,a)', advance='no') 'mesh: N_e = ', d%msh%ne, ', ', &
            trim(m%mesh%grading), ', interpolation u w psi sigma_x sigma_z:'
        do field = FIELD_U, FIELD_SZ
            write (u, '(1x,a)', advance='no') interp_name(m%mesh%interp(field))
        end do
        write (u, '(a,i0,a,i0)') ', unknowns: displacements ', d%nv, ', tractions ', d%nr
        call write_wrapped(u, '   '//simplification_text(m, d, sol%decoupled))
        write (u, '(3x,a,es9.2,a,es9.2,a,i0,a,i0)') 'solver: tol outer ', m%solver%tol_outer, &
            ', tol inner ', m%solver%tol_inner, ', max outer ', m%solver%max_outer, &
                ', max inner ', m%solver%max_inner
    end subroutine write_groups

    !> The moment balance of a beam about x = 0, on the mid-plane (the check) and on the
    !! bottom face (base statics): the base moment is the mid-plane one plus (h/2) times the
    !! horizontal force, of the loads (on the top face) and of the reactions alike.
    subroutine write_moment_checks(u, m, sol, v)
        integer, intent(in) :: u                !! the open report
        type(model_t), intent(in) :: m          !! the case
        type(solution_t), intent(in) :: sol     !! reactions and loads
        real(dp), intent(in) :: v               !! total vertical load [F]
        real(dp) :: half_h
        half_h = 0.5_dp*m%structure%h
        write (u, '(3x,a,2es16.8,a,es9.2,a)') 'moment:     reaction, load ', sol%reaction(3), &
            sol%applied(3), '  rel.diff ', rel_diff(sol%reaction(3), sol%applied(3), &
            v*m%structure%length), '  (about x = 0 on the mid-plane z = 0)'
        write (u, '(3x,a,2es16.8,a)') '            the same about x = 0 on the base z = h/2 ', &
            sol%reaction(3) + half_h*sol%reaction(2), sol%applied(3) + half_h*sol%applied(2), &
            '  (mid-plane + (h/2) H: base statics)'
    end subroutine write_moment_checks

    subroutine write_conventions(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        write (u, '(/,a)') ' 3. SIGN CONVENTIONS AND UNITS'
        write (u, '(a)') '   z points down into the soil; w > 0 is settlement; x from the beam '// &
            'centre (plate: radius r).'
        write (u, '(a)') '   u_s: mid-plane horizontal displacement (+x / outward); psi: '// &
            'section rotation, psi = dw/dx in the thin limit.'
        write (u, '(a)') '   sigma_z > 0: compressive contact pressure on the soil; sigma_x: '// &
            'shear traction ON THE SOIL, +x (plate: outward);'
        write (u, '(a)') '   the structure receives -sigma. gap = w_f - w_b >= 0; slip = u_b - '// &
            'u_f, u_b = u_s - (h/2) psi.'
        if (m%structure%kind == MODEL_BEAM) then
            call write_wrapped(u, '   BEAM: sigma are line loads (force/length) over the width '// &
                'b; N = EA u_s'', M = EI psi'' (> 0: top fibre in tension, hogging), Q = kGbh '// &
                '(w''-psi).')
            write (u, '(a)') '   M is the moment about the mid-plane. A MOMENT load M0 > 0 '// &
                'turns the beam clockwise as the figure draws it'
            write (u, '(a)') '   (x to the right, w down: the +x side settles more); M drops '// &
                'by M0 across it. A horizontal load F_x'
            write (u, '(a)') '   on the top face acts h/2 above the mid-plane: M drops by '// &
                'F_x h/2 across it (at once at a POINT load).'
            write (u, '(a)') '   Nondimensional: t = x/l, U,W = EI u/(F l^3), Psi = EI psi/(F '// &
                'l^2), Sigma = l sigma/F, N/F, M/(F l), Q/F.'
        else
            call write_wrapped(u, '   PLATE: sigma are stresses; resultants per unit length: '// &
                'N_r, N_theta, M_r = D(psi''+nu psi/r), M_theta = D(psi/r+nu psi'') '// &
                '(> 0: top in tension), Q_r = kGh(w''-psi).')
            write (u, '(a)') '   Nondimensional: t = r/a, U,W = D u/(F a^2), Psi = D psi/(F '// &
                'a), Sigma = pi a^2 sigma/F, N a/F, M/F, Q a/F.'
        end if
        write (u, '(a)') '   Physical units: force '//trim(m%units%force)//', length '// &
            trim(m%units%length)//trim(merge(' (labels of the NONDIM set)', &
                                             '                           ', m%nondim))
    end subroutine write_conventions

    subroutine write_log(u, sol)
        integer, intent(in) :: u
        type(solution_t), intent(in) :: sol
        integer :: i
        character(len=200) :: line    ! a row, written without its trailing blanks
        write (u, '(/,a)') ' 4. SOLVER LOG (outer: friction threshold tau0 <- f sigma_z; '// &
            'inner: slip / tension sets)'
        if (.not. allocated(sol%history)) then
            write (u, '(a)') '   (no iteration: the case was refused before solving)'
            return
        end if
        write (u, '(a)') '   outer inner  slip-pts  lift-pts  changed   rel.increment   '// &
            'rel.residual  note'
        do i = 1, size(sol%history)
            associate (h => sol%history(i))
                if (h%residual >= 0.0_dp) then
                    write (line, '(3x,i5,i6,3i10,2es16.4,2x,a)') h%outer, h%inner, h%n_slip, &
                        h%n_tension, h%n_changed, h%increment, h%residual, trim(h%note)
                else
                    write (line, '(3x,i5,i6,3i10,es16.4,16x,2x,a)') h%outer, h%inner, h%n_slip, &
                        h%n_tension, h%n_changed, h%increment, trim(h%note)
                end if
                write (u, '(a)') trim(line)
            end associate
        end do
        write (u, '(3x,a,i0,a,i0,a)') 'iterations: ', sol%n_outer, ' outer, ', sol%n_inner, ' inner'
        write (u, '(3x,a,i0)') 'linear solves: ', sol%n_solves
        if (sol%n_nested_solves > 0) write (u, '(3x,a,i0,a)') 'start: ', sol%n_nested_solves, &
            ' linear solves on the nested coarser meshes (every other node)'
    end subroutine write_log

    !> A station table from a list of columns; flagged rows end with ` !T` (tension beyond
    !! O(eta)) or ` !O` (lifted off with a negative pointwise gap); folded into column
    !! groups when wider than the report (report_folding).
    subroutine write_table(u, heading, cols, tab, nondim)
        integer, intent(in) :: u
        character(len=*), intent(in) :: heading
        type(column_t), intent(in) :: cols(:)
        type(station_table_t), intent(in) :: tab
        logical, intent(in) :: nondim
        integer :: i, c, n_header
        real(dp) :: extent
        logical :: fixed
        character(len=13) :: cell
        character(len=13*size(cols) + 6), allocatable :: lines(:)
        extent = maxval(abs(tab%val(cols(1)%quantity, :)*cols(1)%scale), mask=tab%n > 0)
        fixed = fixed_positions(extent, 13)
        write (u, '(/,a)') heading
        n_header = merge(1, 2, nondim)
        allocate (lines(n_header + tab%n))
        lines = ''
        do c = 1, size(cols)
            if (.not. cols(c)%in_report) cycle
            write (cell, '(a13)') trim(cols(c)%symbol)
            lines(1)(13*count(cols(1:c - 1)%in_report) + 1:) = cell
            write (cell, '(a13)') '['//trim(cols(c)%unit)//']'
            if (.not. nondim) lines(2)(13*count(cols(1:c - 1)%in_report) + 1:) = cell
        end do
        rows: do i = 1, tab%n
            do c = 1, size(cols)
                if (.not. cols(c)%in_report) cycle
                if (cols(c)%integer_valued) then
                    cell = state_word(nint(tab%val(Q_STATE, i)))
                    cell = adjustr(cell)
                else if (c == 1) then
                    cell = position_text(tab%val(cols(c)%quantity, i)*cols(c)%scale, fixed, 13)
                else
                    cell = es_text(tab%val(cols(c)%quantity, i)*cols(c)%scale, 13, 4, 0)
                end if
                lines(n_header + i)(13*count(cols(1:c - 1)%in_report) + 1:) = cell
            end do
            if (iand(tab%flag(i), FLAG_TENSION) /= 0) lines(n_header + i) = &
                trim(lines(n_header + i))//' !T'
            if (iand(tab%flag(i), FLAG_OVERLAP) /= 0) lines(n_header + i) = &
                trim(lines(n_header + i))//' !O'
        end do rows
        lines = fold_table(lines, n_header, 13, 13, count(cols%in_report))
        write (u, '(a)') (trim(lines(i)), i=1, size(lines))
    end subroutine write_table

    subroutine write_station_notes(u, m, tab)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        write (u, '(/,a)') '   Station values: tractions are the mean over the elements '// &
            'meeting at the station (the forces the equations carry);'
        write (u, '(a)') '   the pointwise finite-element field is in the data files '// &
            '(Sigma_x^h, Sigma_z^h in the .dat; sigma_x_fe, sigma_z_fe in the CSV);'
        write (u, '(a)') '   states follow the solver''s interface law; gap is 0 where in '// &
            'contact (weak compatibility, see CHECKS);'
        write (u, '(a)') '   N, M, Q are from the statics of the part left of (inside) the '// &
            'section; a station at a concentrated load'
        write (u, '(a)') '   appears twice (left and right limit).'
        if (m%structure%kind /= MODEL_BEAM .and. any(m%loads%kind == LOAD_POINT)) call &
            write_wrapped(u, '   A POINT load on the axis makes Q_r unbounded there (Q_r = '// &
            '-P/(2 pi r)); the r = 0 station shows the symmetry value 0, and max |Q_r| depends '// &
            'on the mesh.')
        if (any(tab%flag /= 0)) write (u, '(a)') '   FLAGGED rows: !T tension beyond the '// &
            'penalty''s O(eta); !O lifted off with a negative pointwise gap (discretisation).'
    end subroutine write_station_notes

    !> The design summary: the entries of summary_table, then the contact intervals.
    subroutine write_summary(u, m, e, s, adapted)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(entry_t), intent(in) :: e(:)
        type(summary_t), intent(in) :: s
        logical, intent(in) :: adapted      !! the mesh was adapted (ADAPT)
        integer :: i
        character(len=60) :: label
        character(len=200) :: line    ! a row, written without its trailing blanks
        write (u, '(/,a)') ' 7. DESIGN SUMMARY ('//trim(merge('nondimensional (SPEC.md 6)', &
            'physical units            ', m%nondim))//')'//repeat(' ', 16)//'estimated error (*)'
        do i = 1, size(e)
            label = e(i)%label
            if (e(i)%singular .and. e(i)%defined) label = trim(label)//' [s]'
            if (.not. e(i)%defined) then
                write (line, '(3x,a,t52,a)') trim(label), 'n/a'
            else if (e(i)%integer_valued) then
                write (line, '(3x,a,t52,i14)') label, nint(e(i)%value)
            else if (e(i)%has_error) then
                write (line, '(3x,a,t52,es14.5,2x,a,t82,a,es9.2,a)') label, e(i)%value, &
                    trim(e(i)%unit), '+-', e(i)%error, trim(order_text(e(i)%order))
            else
                write (line, '(3x,a,t52,es14.5,2x,a)') label, e(i)%value, trim(e(i)%unit)
            end if
            write (u, '(a)') trim(line)
        end do
        if (any(e%singular .and. e%defined)) write (u, '(3x,a)') '[s] singular in the model '// &
            'where it is taken (notes below): the mesh decides the value; no error estimate'
        if (any(e%has_error)) then
            call write_wrapped(u, '   (*) '//error_method_text(adapted))
        else
            call write_wrapped(u, '   (*) no error estimate: '//no_estimate_reason())
        end if
        call write_intervals(u, m, s%intervals, s%slip_intervals)
        call write_pressure_note(u)
        if (s%edge_in_contact) then
            write (u, '(3x,a)') 'The pressure at an edge in contact is singular in theory: the '// &
                'station maximum there depends on the mesh;'
            write (u, '(3x,a)') 'use the mean pressure and the pressure at d from the edge '// &
                'for design.'
        end if
        if (has_concentrated_load(m%loads)) write (u, '(3x,a)') &
            'Under a POINT or RING load the pressure is singular too (logarithmic): its '// &
            'station maximum depends on the mesh.'
        if (s%point_on_plate) then
            write (u, '(3x,a)') 'Under a POINT load a Mindlin plate''s settlement and moments '// &
                'grow like ln r and its shear force like 1/r: their values at r = 0'
            write (u, '(3x,a)') 'depend on the mesh. For design, give the load its footprint '// &
                '(a PATCH over the column or plate it acts through).'
        end if
    end subroutine write_summary

    !> Which pressure the summary reports, and why.
    subroutine write_pressure_note(u)
        integer, intent(in) :: u
        write (u, '(3x,a)') 'Pressures are element means at the stations: the mean pressure '// &
            'over the elements meeting there'
        write (u, '(3x,a)') '(the forces the equations carry; they do not alternate from node '// &
            'to node as the nodal field does near an edge or a'
        write (u, '(3x,a)') 'lift-off boundary). Where the pressure is bounded both converge '// &
            'to the same value; the pointwise finite-element'
        write (u, '(3x,a)') 'field (data files) peaks higher under a concentrated load and at '// &
            'an edge in contact, where neither converges.'
    end subroutine write_pressure_note

    pure function order_text(p) result(text)
        real(dp), intent(in) :: p
        character(len=:), allocatable :: text
        character(len=16) :: buf
        if (p > 0.0_dp) then
            write (buf, '(a,f4.1)') '  p ', p
        else
            buf = '  p* 1'
        end if
        text = trim(buf)
    end function order_text

    !> Edit descriptor of positions up to extent in magnitude: 5 decimals where they show the
    !! value (extent >= 1E-3) and it fits, else scientific with 5 digits (-1.2345E+29 and
    !! -1.2345-100 take 11 columns). Width 12 (after text): below 1E4, -9999.99999 leaves a
    !! blank; width 13 (a table's first column): below 1E6, -999999.99999 fills it.
    pure function position_format(extent, width) result(fmt)
        real(dp), intent(in) :: extent    !! largest |position| [the column's unit]
        integer, intent(in) :: width      !! field width, 12 or 13
        character(len=:), allocatable :: fmt
        if (fixed_positions(extent, width)) then
            fmt = '(f'//int_text(width)//'.5)'
        else
            fmt = '(es'//int_text(width)//'.4)'
        end if
    end function position_format

    !> position_format's choice: 5 decimals (true) or scientific.
    pure logical function fixed_positions(extent, width) result(fixed)
        real(dp), intent(in) :: extent    !! largest |position| [the column's unit]
        integer, intent(in) :: width      !! field width, 12 or 13
        real(dp) :: widest
        widest = merge(1.0e4_dp, 1.0e6_dp, width <= 12)
        fixed = extent == 0.0_dp .or. (extent >= 1.0e-3_dp .and. extent < widest)
    end function fixed_positions

    !> A position x as position_format writes it; fixed: fixed_positions of the column.
    pure function position_text(x, fixed, width) result(text)
        real(dp), intent(in) :: x         !! the position [the column's unit]
        logical, intent(in) :: fixed      !! 5 decimals (fixed_positions), else scientific
        integer, intent(in) :: width      !! field width, 12 or 13
        character(len=width) :: text
        if (fixed) then
            text = f_text(x, width, 5)
        else
            text = es_text(x, width, 4, 0)
        end if
    end function position_text

    subroutine write_intervals(u, m, iv, slip)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(interval_t), intent(in) :: iv(:)
        type(interval_t), intent(in) :: slip(:)     !! where the base slips
        type(units_t) :: un
        real(dp) :: scale
        character(len=:), allocatable :: fmt
        integer :: k
        un = case_units(m)
        scale = merge(1.0_dp/m%structure%length, 1.0_dp, m%nondim)
        write (u, '(3x,a)') 'intervals ('//trim(merge('t               ', un%length, m%nondim))// &
            '; boundaries midway between stations of different state):'
        fmt = position_format(m%structure%length*scale, 12)
        fmt = '(6x,a,'//fmt(2:len(fmt) - 1)//',a,'//fmt(2:len(fmt) - 1)//',a)'
        do k = 1, size(iv)
            write (u, fmt) merge('contact  from', 'lift-off from', iv(k)%contact), &
                iv(k)%x1*scale, ' to', iv(k)%x2*scale, ''
        end do
        do k = 1, size(slip)
            write (u, fmt) 'slip     from', slip(k)%x1*scale, ' to', &
                slip(k)%x2*scale, trim(merge(' (f = 0: all contact slips)', &
                                              '                           ', &
                                                  m%interface%f == 0.0_dp))
        end do
        if (size(slip) == 0 .and. any(iv%contact)) write (u, '(6x,a)') &
            'no slip: the base sticks wherever it is in contact'
    end subroutine write_intervals

    subroutine write_checks(u, m, sol, tab, s)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(in) :: s
        real(dp) :: v
        v = total_vertical_load(m%loads)
        write (u, '(/,a)') ' 8. CHECKS'
        write (u, '(3x,a,es10.2,a,es8.1,a)') 'residual of 4.2a (equilibrium of the structure) ', &
            sol%residual(1), '  (limit ', check_limit, ')'
        write (u, '(3x,a,es10.2,a,es8.1,a)') 'interface law 4.2b as a traction error          ', &
            sol%law_residual, '  (of max |r|; limit ', check_limit, ')'
        write (u, '(3x,a,es10.2,a)') 'plain residual of 4.2b                          ', &
            sol%residual(2), '  (carries 1/eps_bar and 1/eta_bar: not a measure of accuracy)'
        write (u, '(3x,a,2es16.8,a,es9.2)') 'vertical:   reaction, load ', sol%reaction(1), &
            sol%applied(1), '  rel.diff ', rel_diff(sol%reaction(1), sol%applied(1), v)
        write (u, '(3x,a,2es16.8,a,es9.2)') 'horizontal: reaction, load ', sol%reaction(2), &
            sol%applied(2), '  rel.diff ', rel_diff(sol%reaction(2), sol%applied(2), v)
        if (m%structure%kind == MODEL_BEAM) call write_moment_checks(u, m, sol, v)
        write (u, '(3x,a,es10.2,a)') 'complementarity max |Sigma_z gap|/max W at lift-off '// &
            'stations ', tab%complementarity, '  (penalty: O(eta_bar))'
        call write_wrapped(u, '   compatibility max |pointwise gap|/max w at contact '// &
            'stations '//es_text(tab%compatibility, 10, 2, 0)//'  (discretisation error of '// &
            'the weak contact condition: falls as the mesh is refined; no pass/fail)')
        write (u, '(3x,a,es10.2,a,i0,a)') 'minimum station Sigma_z (< 0: tension) ', &
            nondim_sigma(m, tab%most_tensile), ' (', s%n_tension_flags, &
            ' stations beyond O(eta) flagged !T)'
        write (u, '(3x,a,es10.2)') 'most tensile Gauss-point Sigma_z (solver) ', &
            nondim_sigma(m, sol%min_sigma_z)
        write (u, '(3x,a,es10.2,a,es9.2,a)') 'friction admissibility max(|Sigma_x| - f Sigma_z) ', &
            s%admissibility, '  (tolerance ', s%admissibility_tol, &
            trim(merge(': ok)      ', ': EXCEEDED)', s%admissibility <= s%admissibility_tol))
        write (u, '(3x,a,i0,a)') 'state counts at the stations: ', &
            count(tab%state == STATE_STICK), &
            ' stick, '//int_text(count(tab%state == STATE_SLIP))//' slip, '// &
            int_text(count(tab%state == STATE_LIFTOFF))//' lift-off'
    end subroutine write_checks

    !> Sigma = l sigma / F (beam) or pi a^2 sigma / F (plate).
    pure real(dp) function nondim_sigma(m, sigma)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: sigma
        nondim_sigma = sigma*traction_measure(m%structure)/total_vertical_load(m%loads)
    end function nondim_sigma

    pure real(dp) function rel_diff(a, b, scale)
        real(dp), intent(in) :: a, b, scale
        rel_diff = abs(a - b)/max(abs(scale), tiny(1.0_dp))
    end function rel_diff

end module report_writer
