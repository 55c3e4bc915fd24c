!> A sweep's response figure, output/STEM_response.gp and .png: each key result of the
!! summary CSV against the first swept parameter, one curve per combination of the other
!! swept values (scripts/gnuplot/fricon_response.gp reads the summary CSV itself, so the
!! script draws the merged summary of a sharded sweep too). And the swept values of a case,
!! read back from its label, for the summary's parameter columns and the figure.
module response_figure
    use kinds, only: dp
    use errors, only: error_t, EXIT_OK
    use case_files, only: case_result_t
    use report_writer, only: write_script_folder, shell_safe
    use atomic_files, only: open_temporary, commit_file
    use figure_templates, only: response_template
    use model, only: model_t
    use case_scales, only: pressure_unit
    implicit none
    private

    !> Summary CSV columns before the swept parameters (case, parameters) and between them
    !! and the key results (status, rho, outer_iterations, elements).
    integer, parameter, public :: columns_before_swept = 2, columns_before_keys = 4

    public :: swept_values, write_response_script, parameter_unit

contains

    !> output/STEM_response.gp for the summary STEM_summary.csv of the cases' results (all
    !! cases of the sweep, in case order); nothing when no case solved or no key result is
    !! defined in any.
    subroutine write_response_script(path, stem, m, results, written, err)
        character(len=*), intent(in) :: path, stem     !! the script; the deck's file stem
        type(model_t), intent(in) :: m                 !! a case's model (title, units)
        type(case_result_t), intent(in) :: results(:)  !! every case of the sweep
        logical, intent(out) :: written                !! a script was written
        type(error_t), allocatable, intent(out) :: err !! allocated on failure
        character(len=16), allocatable :: names(:), texts(:), first_texts(:)
        real(dp), allocatable :: values(:), x(:)
        integer, allocatable :: keys(:)
        character(len=400), allocatable :: template(:)
        integer :: u, i, n_groups, solved
        logical :: combined
        written = .false.
        solved = findloc(results%status, EXIT_OK, dim=1)
        if (solved == 0) return
        call swept_values(results(1)%label, names, first_texts, values)
        if (size(names) == 0) return
        allocate (x(size(results)))
        n_groups = 1
        ! load combinations (the fastest index) at each sweep point: a curve per combination
        combined = .false.
        if (size(results) > 1) combined = same_sweep_point(results(1)%label, results(2)%label)
        do i = 1, size(results)
            call swept_values(results(i)%label, names, texts, values)
            x(i) = values(1)
            if ((size(names) > 1 .or. combined) .and. n_groups == i - 1 .and. &
                texts(1) == first_texts(1)) n_groups = i
        end do
        keys = plotted_keys(results, x)
        if (size(keys) == 0) return
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# fricon response figure: gnuplot '//stem//'_response.gp draws '// &
            stem//'_response.png from '//stem//'_summary.csv (from any folder)'
        call write_script_folder(u)
        write (u, '(a)') "summary = gp_dir.'"//stem//"_summary.csv'"
        write (u, '(a)') "response_png = gp_dir.'"//stem//"_response.png'"
        write (u, '(a)') "title = 'fricon: "//trim(shell_safe(m%title))//" (response)'"
        write (u, '(a,i0)') 'x_col = ', columns_before_swept + 1
        write (u, '(a)') "x_label = '"//trim(shell_safe(axis_label(names(1), m)))//"'"
        write (u, '(a,i0)') 'x_log = ', merge(1, 0, minval(x) > 0.0_dp .and. &
                                                   maxval(x) >= 20.0_dp*minval(x))
        call write_keys(u, results(solved), keys, columns_before_swept + size(names) + &
                        columns_before_keys)
        call write_groups(u, results(1:n_groups))
        template = response_template()
        do i = 1, size(template)
            write (u, '(a)') trim(template(i))
        end do
        call commit_file(path, u, err)
        written = .not. allocated(err)
    end subroutine write_response_script

    !> The key results the figure shows: those that vary and are defined at two values of
    !! the first swept parameter or more, without the positions of extremes (keys ending in
    !! _x), the solver's count and the edge distance (no responses).
    pure function plotted_keys(results, x) result(keys)
        type(case_result_t), intent(in) :: results(:)   !! the cases
        real(dp), intent(in) :: x(:)                    !! their first swept value
        integer, allocatable :: keys(:)
        integer :: i, k, n, at
        real(dp) :: x_at, v_at
        logical :: varies, spread
        character(len=32) :: key
        allocate (keys(0))
        n = 0
        do i = 1, size(results)
            if (has_entry(results(i), 1)) n = max(n, size(results(i)%entries))
        end do
        entries: do k = 1, n
            at = 0
            varies = .false.
            spread = .false.
            do i = 1, size(results)
                if (.not. has_entry(results(i), k)) cycle
                key = results(i)%entries(k)%key
                if (at == 0) then
                    at = i
                    x_at = x(i)
                    v_at = results(i)%entries(k)%value
                end if
                varies = varies .or. results(i)%entries(k)%value /= v_at
                spread = spread .or. x(i) /= x_at
            end do
            if (.not. (varies .and. spread)) cycle entries
            if (len_trim(key) > 2) then
                if (key(len_trim(key) - 1:len_trim(key)) == '_x') cycle entries
            end if
            if (key == 'linear_solves' .or. key == 'edge_distance') cycle entries
            keys = [keys, k]
        end do entries
    end function plotted_keys

    !> Case r solved and has a defined key result k.
    pure logical function has_entry(r, k)
        type(case_result_t), intent(in) :: r   !! a case
        integer, intent(in) :: k               !! entry index
        has_entry = .false.
        if (r%status /= EXIT_OK .or. .not. allocated(r%entries)) return
        if (size(r%entries) < k) return
        has_entry = r%entries(k)%defined
    end function has_entry

    !> The panels: each key's summary column and its title with unit.
    subroutine write_keys(u, solved, keys, before)
        integer, intent(in) :: u                   !! the open script
        type(case_result_t), intent(in) :: solved  !! a solved case (labels and units)
        integer, intent(in) :: keys(:)             !! entries plotted
        integer, intent(in) :: before              !! summary columns before the first key
        integer :: k
        character(len=:), allocatable :: title
        write (u, '(a,i0)') 'n_keys = ', size(keys)
        write (u, '(a,i0,a)') 'array key_col[', size(keys), ']'
        write (u, '(a,i0,a)') 'array key_title[', size(keys), ']'
        do k = 1, size(keys)
            associate (e => solved%entries(keys(k)))
                title = trim(e%label)
                if (len_trim(e%unit) > 0) title = title//' ['//trim(e%unit)//']'
                write (u, '(a,i0,a,i0)') 'key_col[', k, '] = ', before + keys(k)
                write (u, '(a,i0,a)') 'key_title[', k, "] = '"//trim(shell_safe(title))//"'"
            end associate
        end do
    end subroutine write_keys

    !> The curves: the swept values after the first of each of the first n_groups cases,
    !! and its load combination's name.
    subroutine write_groups(u, first)
        integer, intent(in) :: u                   !! the open script
        type(case_result_t), intent(in) :: first(:) !! the cases 1..n_groups
        character(len=16), allocatable :: names(:), texts(:)
        real(dp), allocatable :: values(:)
        character(len=:), allocatable :: title
        integer :: g, j
        write (u, '(a,i0)') 'n_groups = ', size(first)
        write (u, '(a,i0,a)') 'array group_title[', size(first), ']'
        do g = 1, size(first)
            call swept_values(first(g)%label, names, texts, values)
            title = ''
            do j = 2, size(names)
                if (j > 2) title = title//' '
                title = title//trim(names(j))//'='//trim(texts(j))
            end do
            if (len(title) > 0 .and. len(combination_word(first(g)%label)) > 0) &
                title = title//' '
            title = title//combination_word(first(g)%label)
            write (u, '(a,i0,a)') 'group_title[', g, "] = '"//trim(shell_safe(title))//"'"
        end do
    end subroutine write_groups

    !> The load combination's name in a case label ('ULS' of 'case 2 of 8: E_F=1.5E4 ULS =
    !! 1.35 G + 1.5 Q'): the first word after the colon that is no NAME=value pair; '' if none.
    pure function combination_word(label) result(word)
        character(len=*), intent(in) :: label   !! the case label
        character(len=:), allocatable :: word
        character(len=:), allocatable :: rest
        integer :: blank
        word = ''
        if (index(label, ':') == 0) return
        rest = trim(adjustl(label(index(label, ':') + 1:)))
        do while (len(rest) > 0)
            blank = index(rest, ' ')
            if (blank == 0) blank = len(rest) + 1
            if (index(rest(1:blank - 1), '=') == 0) then
                word = rest(1:blank - 1)
                return
            end if
            rest = trim(adjustl(rest(min(blank, len(rest) + 1):)))
        end do
    end function combination_word

    !> Two case labels with the same swept values ('E_F=15.0E3 SLS = ...' and 'E_F=15.0E3
    !! ULS = ...': two load combinations at one sweep point).
    pure logical function same_sweep_point(a, b)
        character(len=*), intent(in) :: a, b   !! case labels
        character(len=16), allocatable :: names_a(:), texts_a(:), names_b(:), texts_b(:)
        real(dp), allocatable :: values(:)
        call swept_values(a, names_a, texts_a, values)
        call swept_values(b, names_b, texts_b, values)
        same_sweep_point = size(texts_a) == size(texts_b)
        if (same_sweep_point) same_sweep_point = all(texts_a == texts_b) .and. &
                                                 all(names_a == names_b)
    end function same_sweep_point
    !> 'NAME [unit]' of a swept parameter, or NAME for a pure number.
    pure function axis_label(name, m) result(text)
        character(len=*), intent(in) :: name   !! a SWEEP parameter name
        type(model_t), intent(in) :: m         !! a case's model (its units)
        character(len=:), allocatable :: text
        text = trim(name)
        if (len(parameter_unit(name, m)) > 0) text = text//' ['//parameter_unit(name, m)//']'
    end function axis_label

    !> The unit of a SWEEP parameter's values, the deck's: moduli (E, E_F, E1 to E3, E_BASE)
    !! in F/L² by its SI name (kPa for kN and m), lengths (H, L, A, B, H1 to H3, DEPTH) in L
    !! (NONDIM decks: l or a; their layer moduli are relative: none); '' for the
    !! nondimensional groups, ratios and counts.
    pure function parameter_unit(name, m) result(unit)
        character(len=*), intent(in) :: name   !! a SWEEP parameter name
        type(model_t), intent(in) :: m         !! a case's model (its units)
        character(len=:), allocatable :: unit
        select case (trim(name))
        case ('E', 'E_F', 'E1', 'E2', 'E3', 'E_BASE')
            unit = trim(pressure_unit(m%units%force, m%units%length))
            if (m%nondim) unit = ''
        case ('H', 'L', 'A', 'B', 'H1', 'H2', 'H3', 'DEPTH')
            unit = trim(m%units%length)
        case default
            unit = ''
        end select
    end function parameter_unit

    !> The swept parameters of a case from its label ('case 002 of 006: RHO=0.01 F=0.5',
    !! deck_reader::case_model: NAME=value pairs, one blank apart, each value a deck field):
    !! the names, the values as the deck wrote them and as numbers. None for 'case 1 of 1'.
    pure subroutine swept_values(label, names, texts, values)
        character(len=*), intent(in) :: label                     !! the case label
        character(len=16), allocatable, intent(out) :: names(:)   !! e.g. RHO, F
        character(len=16), allocatable, intent(out) :: texts(:)   !! e.g. 0.01, 0.5
        real(dp), allocatable, intent(out) :: values(:)           !! the same as numbers
        character(len=:), allocatable :: rest, pair
        integer :: blank, eq, ios
        real(dp) :: x
        allocate (names(0), texts(0), values(0))
        if (index(label, ':') == 0) return
        rest = trim(adjustl(label(index(label, ':') + 1:)))
        pairs: do while (len(rest) > 0)
            blank = index(rest, ' ')
            if (blank == 0) blank = len(rest) + 1
            pair = rest(1:blank - 1)
            rest = trim(adjustl(rest(min(blank, len(rest) + 1):)))
            eq = index(pair, '=')
            if (eq < 2) cycle pairs
            read (pair(eq + 1:), *, iostat=ios) x      ! a deck number: 0.5, 10.0E3, 1.0D-6
            if (ios /= 0) x = 0.0_dp
            names = [character(len=16) :: names, pair(1:eq - 1)]
            texts = [character(len=16) :: texts, pair(eq + 1:)]
            values = [values, x]
        end do pairs
    end subroutine swept_values

end module response_figure
