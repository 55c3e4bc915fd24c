!> CASE.html: the printable calculation record of one solved case, a self-contained HTML page
!! (doc/OUTPUT.md "The calculation record"): the program, its version and the run's date
!! and time; the deck's name (never a folder of the machine); the inputs card by card with
!! their units; the ground model; the key results in display units (case_scales, the same
!! table as the report's design summary) with their error estimates; the contact intervals
!! and the statics; design checks when there are any; the figure embedded as a base64 PNG
!! data URI (or why there is none); the warnings; and the deck as read. Print styles lay it
!! out on A4. Written through atomic_files, after the figure is drawn.
module html_record
    use kinds, only: dp
    use errors, only: error_t
    use deck_fields, only: int_text
    use atomic_files, only: open_temporary, commit_file
    use model, only: model_t, MODEL_BEAM, total_vertical_load
    use solved_case, only: case_t
    use summary_table, only: entry_t, choose
    use case_scales, only: units_t, case_units
    use design_summary, only: summary_t
    use design_checks, only: design_check_t, evaluate_design_checks
    use method_notes, only: error_method_text, no_estimate_reason
    use run_identity, only: program_name, program_version, run_time
    use base64_encoding, only: base64_encoded
    use html_text, only: escaped, html_number, html_unit, cell, head_cell, table_row, &
                         style_sheet, replaced
    use deck_reader, only: deck_t
    use output_paths, only: base_name
    use record_inputs, only: write_input_tables, write_ground_model
    implicit none
    private

    !> One design check as the record shows it: a value against its limit.
    public :: write_html_record, write_case_record

contains

    !> The record of a solved case written beside its other files, base.html: the figure
    !! base.png embedded when figure_note is '' (it has been drawn), else figure_note says
    !! why there is none. No folder of the machine appears in it: the deck by its file name,
    !! the notes with the output folder taken out.
    subroutine write_case_record(deck, c, base, label, e, figure_note, notes, err)
        type(deck_t), intent(in) :: deck               !! the deck (its name and lines)
        type(case_t), intent(in) :: c                  !! the solved case
        character(len=*), intent(in) :: base           !! output path without extension
        character(len=*), intent(in) :: label          !! 'case i of n: values', or ''
        type(entry_t), intent(in) :: e(:)              !! key results with their estimates
        character(len=*), intent(in) :: figure_note    !! why there is no figure ('': drawn)
        character(len=*), intent(in) :: notes(:)       !! the report's closing lines
        type(error_t), allocatable, intent(out) :: err !! allocated on failure
        character(len=:), allocatable :: folder, name, figure
        character(len=len(notes) + 80), allocatable :: plain(:)
        integer :: k
        folder = base(1:index(base, '/', back=.true.))
        name = 'built-in default deck (input/default.dat)'
        if (deck%from_file) name = base_name(deck%path)
        allocate (plain(size(notes)))
        do k = 1, size(notes)
            plain(k) = without_folders(trim(notes(k)), folder, deck%path, name)
        end do
        figure = ''
        if (len(figure_note) == 0) figure = base//'.png'
        call write_html_record(base//'.html', name, deck%lines, label, c, e, figure, &
            without_folders(figure_note, folder, deck%path, name), plain, err, &
            evaluate_design_checks(c%model, c%summary))
    end subroutine write_case_record

    !> text with the output folder and the deck's path replaced by nothing and its name.
    pure function without_folders(text, folder, deck_path, deck_name) result(out)
        character(len=*), intent(in) :: text, folder, deck_path, deck_name
        character(len=:), allocatable :: out
        out = text
        if (len(deck_path) > 0) out = replaced(out, deck_path, deck_name)
        if (len(folder) > 0) out = replaced(out, folder, '')
    end function without_folders

    !> Write the record of a solved case to path (through path.tmp). figure is the PNG to
    !! embed ('' for none: figure_note says why); notes are the warnings and notes of the
    !! report's end; checks, when given and not empty, get their own section.
    subroutine write_html_record(path, deck_name, deck_lines, label, c, e, figure, &
                                 figure_note, notes, err, checks)
        character(len=*), intent(in) :: path           !! the page, CASE.html
        character(len=*), intent(in) :: deck_name      !! the deck's file name, no folder
        character(len=*), intent(in) :: deck_lines(:)  !! the deck as read
        character(len=*), intent(in) :: label          !! 'case i of n: values', or ''
        type(case_t), intent(in) :: c                  !! the solved case
        type(entry_t), intent(in) :: e(:)              !! key results with their estimates
        character(len=*), intent(in) :: figure         !! the PNG to embed ('' for none;
                                                       !! one that cannot be read: none)
        character(len=*), intent(in) :: figure_note    !! why there is no figure
        character(len=*), intent(in) :: notes(:)       !! 'WARNING: ...', 'NOTE: ...' lines
        type(error_t), allocatable, intent(out) :: err !! allocated on failure
        type(design_check_t), intent(in), optional :: checks(:)  !! design checks
        character(len=:), allocatable :: png, no_figure
        logical :: read_ok
        integer :: u
        png = ''
        no_figure = figure_note
        if (len(figure) > 0) then
            call read_bytes(figure, png, read_ok)
            if (.not. read_ok) no_figure = 'the figure '//base_name(figure)//' could not be read'
        end if
        call open_temporary(path, u, err)
        if (allocated(err)) return
        call write_head(u, c%model)
        call write_identity(u, c%model, deck_name, label)
        call write_input_tables(u, c%model, c%d%msh%ne)
        call write_ground_model(u, c%model)
        call write_results(u, c%model, e, c%summary)
        call write_statics(u, c)
        if (present(checks)) then
            if (size(checks) > 0) call write_checks(u, checks)
        end if
        call write_figure(u, png, no_figure)
        call write_notes(u, notes)
        call write_deck(u, deck_lines)
        write (u, '(a)') '</body>'
        write (u, '(a)') '</html>'
        call commit_file(path, u, err)
    end subroutine write_html_record

    !> The document's head: title and style sheet; the body's heading.
    subroutine write_head(u, m)
        integer, intent(in) :: u         !! the open page
        type(model_t), intent(in) :: m   !! its title
        character(len=100), allocatable :: css(:)
        integer :: i
        css = style_sheet()
        write (u, '(a)') '<!DOCTYPE html>'
        write (u, '(a)') '<html lang="en">'
        write (u, '(a)') '<head>'
        write (u, '(a)') '<meta charset="utf-8" />'
        write (u, '(a)') '<meta name="generator" content="'//program_name//' '// &
            program_version//'" />'
        write (u, '(a)') '<title>'//escaped(page_title(m))//'</title>'
        write (u, '(a)') '<style>'
        do i = 1, size(css)
            write (u, '(a)') trim(css(i))
        end do
        write (u, '(a)') '</style>'
        write (u, '(a)') '</head>'
        write (u, '(a)') '<body>'
        write (u, '(a)') '<h1>'//escaped(page_title(m))//'</h1>'
    end subroutine write_head

    pure function page_title(m) result(text)
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: text
        text = trim(m%title)
        if (len(text) == 0) text = 'Calculation record'
    end function page_title

    !> Who computed what, when: program, version, run time, deck, case, model.
    subroutine write_identity(u, m, deck_name, label)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: deck_name, label
        write (u, '(a)') '<table class="meta">'
        write (u, '(a)') table_row(cell('<b>Calculation record</b>')//cell(escaped( &
            program_name//' '//program_version//': '//choose( &
            m%structure%kind == MODEL_BEAM, 'beam', 'circular raft (plate)')// &
            ' on an elastic half-space with lift-off and friction')))
        write (u, '(a)') table_row(cell('Program')//cell(escaped(program_name)// &
            ', version '//escaped(program_version)))
        write (u, '(a)') table_row(cell('Run')//cell(escaped(trim(run_time))))
        write (u, '(a)') table_row(cell('Deck')//cell(escaped(deck_name)))
        if (len_trim(label) > 0) write (u, '(a)') table_row(cell('Case')// &
            cell(escaped(trim(label))))
        write (u, '(a)') table_row(cell('Data')//cell(choose(m%nondim, &
            'nondimensional groups (NONDIM card): results are nondimensional', &
            'physical; results in the display units named in each table')))
        write (u, '(a)') '</table>'
    end subroutine write_identity

    !> The key results (summary_table) with their positions and error estimates, and the
    !! contact, lift-off and slip intervals.
    subroutine write_results(u, m, e, s)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(entry_t), intent(in) :: e(:)
        type(summary_t), intent(in) :: s
        integer :: i
        logical :: estimated
        estimated = any(e%has_error)
        write (u, '(a)') '<section class="results">'
        write (u, '(a)') '<h2>Results: design summary</h2>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('quantity')//head_cell('value')// &
            head_cell('unit')//head_cell('at')//head_cell('estimated error'))//'</thead>'
        write (u, '(a)') '<tbody>'
        i = 1
        do while (i <= size(e))
            if (i < size(e)) then
                if (trim(adjustl(e(i + 1)%label)) == 'at') then
                    write (u, '(a)') result_row(e(i), e(i + 1))
                    i = i + 2
                    cycle
                end if
            end if
            write (u, '(a)') result_row(e(i))
            i = i + 1
        end do
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
        call write_result_notes(u, e, estimated, m%mesh%adapt_tol > 0.0_dp)
        call write_intervals(u, m, s)
        write (u, '(a)') '</section>'
    end subroutine write_results

    !> One key result; `at` is its position entry (the summary's '  at' line).
    pure function result_row(v, at) result(tr)
        type(entry_t), intent(in) :: v
        type(entry_t), intent(in), optional :: at
        character(len=:), allocatable :: tr, where, value, error
        where = ''
        if (present(at)) then
            if (at%defined) where = html_number(at%value, 4)//' '//html_unit(at%unit)
        end if
        if (.not. v%defined) then
            value = 'n/a'
        else if (v%integer_valued) then
            value = int_text(nint(v%value))
        else
            value = html_number(v%value, 4)
        end if
        error = ''
        if (v%singular .and. v%defined) then
            error = 'singular: the mesh decides the value'
        else if (v%has_error .and. v%defined) then
            error = '&#177; '//html_number(v%error, 2)
        end if
        tr = table_row(cell(escaped(trim(v%label)))//cell(value, 'num')// &
                       cell(html_unit(v%unit), 'key')//cell(where, 'num')//cell(error))
    end function result_row

    subroutine write_result_notes(u, e, estimated, adapted)
        integer, intent(in) :: u
        type(entry_t), intent(in) :: e(:)
        logical, intent(in) :: estimated
        logical, intent(in) :: adapted   !! the mesh was adapted (ADAPT): its own estimate
        if (estimated) then
            write (u, '(a)') '<p class="small">'// &
                escaped(error_method_text(adapted))//'</p>'
        else
            write (u, '(a)') '<p class="small">No error estimate: '// &
                escaped(no_estimate_reason())//'.</p>'
        end if
        if (any(e%singular .and. e%defined)) write (u, '(a)') '<p class="small">Singular: '// &
            'unbounded in the model where it is taken (an edge in contact, a concentrated '// &
            'load); read the mean pressure and the pressure at d from the edge for design.</p>'
        write (u, '(a)') '<p class="small">Pressures are element means at the stations (the '// &
            'forces the equations carry); moments are about the mid-plane, positive with the '// &
            'top fibre in tension (hogging).</p>'
    end subroutine write_result_notes

    !> Contact, lift-off and slip intervals, in the case's length unit (NONDIM: t).
    subroutine write_intervals(u, m, s)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(summary_t), intent(in) :: s
        real(dp) :: scale
        type(units_t) :: un
        character(len=:), allocatable :: unit
        integer :: k
        scale = merge(1.0_dp/m%structure%length, 1.0_dp, m%nondim)
        un = case_units(m)
        unit = trim(un%length)
        if (m%nondim) unit = 't (x/l or r/a)'
        write (u, '(a)') '<h3>Contact, lift-off and slip</h3>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('state')//head_cell('from ['// &
            html_unit(unit)//']')//head_cell('to ['//html_unit(unit)//']'))//'</thead>'
        write (u, '(a)') '<tbody>'
        do k = 1, size(s%intervals)
            write (u, '(a)') interval_row(choose(s%intervals(k)%contact, 'contact', 'lift-off'), &
                                          s%intervals(k)%x1*scale, s%intervals(k)%x2*scale)
        end do
        do k = 1, size(s%slip_intervals)
            write (u, '(a)') interval_row('slip', s%slip_intervals(k)%x1*scale, &
                                          s%slip_intervals(k)%x2*scale)
        end do
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
        if (size(s%slip_intervals) == 0 .and. any(s%intervals%contact)) write (u, '(a)') &
            '<p class="small">No slip: the base sticks wherever it is in contact.</p>'
    end subroutine write_intervals

    pure function interval_row(state, x1, x2) result(tr)
        character(len=*), intent(in) :: state
        real(dp), intent(in) :: x1, x2
        character(len=:), allocatable :: tr
        tr = table_row(cell(state)//cell(html_number(x1, 4), 'num')// &
                       cell(html_number(x2, 4), 'num'))
    end function interval_row

    !> Vertical and horizontal equilibrium: the reactions of the soil against the loads.
    subroutine write_statics(u, c)
        integer, intent(in) :: u
        type(case_t), intent(in) :: c
        character(len=:), allocatable :: f
        real(dp) :: v
        f = html_unit(trim(c%model%units%force))
        v = max(abs(total_vertical_load(c%model%loads)), tiny(1.0_dp))
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h3>Statics</h3>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('resultant')//head_cell('loads')// &
            head_cell('soil reactions')//head_cell('unit')//head_cell('difference / V'))// &
            '</thead>'
        write (u, '(a)') '<tbody>'
        write (u, '(a)') table_row(cell('vertical')//cell(html_number(c%sol%applied(1), 6), &
            'num')//cell(html_number(c%sol%reaction(1), 6), 'num')//cell(f)// &
            cell(html_number(abs(c%sol%reaction(1) - c%sol%applied(1))/v, 2), 'num'))
        write (u, '(a)') table_row(cell('horizontal')//cell(html_number(c%sol%applied(2), 6), &
            'num')//cell(html_number(c%sol%reaction(2), 6), 'num')//cell(f)// &
            cell(html_number(abs(c%sol%reaction(2) - c%sol%applied(2))/v, 2), 'num'))
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
        write (u, '(a)') '</section>'
    end subroutine write_statics

    !> The design checks: value, limit, utilisation and whether each is met.
    subroutine write_checks(u, checks)
        integer, intent(in) :: u
        type(design_check_t), intent(in) :: checks(:)
        integer :: k
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h2>Design checks</h2>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('check')//head_cell('value')// &
            head_cell('limit')//head_cell('unit')//head_cell('utilisation')// &
            head_cell('result'))//'</thead>'
        write (u, '(a)') '<tbody>'
        do k = 1, size(checks)
            associate (ck => checks(k))
            write (u, '(a)') table_row(cell(escaped(trim(ck%label)))// &
                cell(choose(ck%defined, html_number(ck%value, 4), 'n/a'), 'num')// &
                cell(html_number(ck%limit, 4), 'num')// &
                cell(html_unit(ck%unit))//cell(html_number(ck%utilisation, 3), 'num')// &
                cell(choose(ck%pass, 'met', 'NOT MET'), choose(ck%pass, 'num', 'fail')))
            end associate
        end do
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
        write (u, '(a)') '</section>'
    end subroutine write_checks

    !> The figure as a PNG data URI, or why there is none.
    subroutine write_figure(u, png, note)
        integer, intent(in) :: u
        character(len=*), intent(in) :: png    !! the PNG's bytes ('' for none)
        character(len=*), intent(in) :: note   !! why there is no figure
        write (u, '(a)') '<section class="figure">'
        write (u, '(a)') '<h2>Figure</h2>'
        if (len(png) == 0) then
            write (u, '(a)') '<p class="note">No figure: '//escaped(note)//'</p>'
        else
            write (u, '(a)') '<figure>'
            write (u, '(a)') '<img alt="settlement, pressures and stress resultants along '// &
                'the base" src="data:image/png;base64,'//base64_encoded(png)//'" />'
            write (u, '(a)') '<figcaption>Settlement, contact tractions and stress '// &
                'resultants along the base (the case''s figure, CASE.png).</figcaption>'
            write (u, '(a)') '</figure>'
        end if
        write (u, '(a)') '</section>'
    end subroutine write_figure

    !> The warnings and notes of the report's end, if any.
    subroutine write_notes(u, notes)
        integer, intent(in) :: u
        character(len=*), intent(in) :: notes(:)
        integer :: k
        if (.not. any(len_trim(notes) > 0)) return
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h2>Warnings and notes</h2>'
        do k = 1, size(notes)
            if (len_trim(notes(k)) == 0) cycle
            write (u, '(a)') '<p class="'//choose(index(notes(k), 'WARNING') == 1, 'warn', &
                'note')//'">'//escaped(trim(notes(k)))//'</p>'
        end do
        write (u, '(a)') '</section>'
    end subroutine write_notes

    !> The deck as read, line by line.
    subroutine write_deck(u, lines)
        integer, intent(in) :: u
        character(len=*), intent(in) :: lines(:)
        integer :: k
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h2>Appendix: the deck as read</h2>'
        write (u, '(a)', advance='no') '<pre>'
        do k = 1, size(lines)
            write (u, '(a)') escaped(trim(lines(k)))
        end do
        write (u, '(a)') '</pre>'
        write (u, '(a)') '</section>'
    end subroutine write_deck

    !> The bytes of a file; ok is false (and bytes '') when it cannot be read or is empty.
    subroutine read_bytes(path, bytes, ok)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: bytes
        logical, intent(out) :: ok
        integer :: u, ios, n
        bytes = ''
        ok = .false.
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=n)
        if (n > 0) then
            deallocate (bytes)
            allocate (character(len=n) :: bytes)
            read (u, iostat=ios) bytes
            ok = ios == 0
        end if
        close (u)
        if (.not. ok) bytes = ''
    end subroutine read_bytes
end module html_record
