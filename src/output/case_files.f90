!> The files of one case and their safety: what a solved or failed case writes, how a
!! figure is rendered, and which files an earlier run of the same case must not leave behind.
module case_files
    use kinds, only: dp
    use errors, only: error_t, EXIT_OK
    use deck_reader, only: deck_t
    use solved_case, only: case_t
    use summary_table, only: entry_t
    use design_envelope, only: design_value_t
    use design_checks, only: design_check_t
    use adaptive_solve, only: adaptation_t
    use plausibility, only: warning_length
    use report_writer, only: write_data_file, write_physical_csv, write_summary_json, &
                             write_plot_script, write_report
    use output_paths, only: remove_output, canonical_path, deck_identity
    use spring_file, only: has_springs, write_springs_csv
    use html_record, only: write_case_record
    use temporary_cleanup, only: register_temporary, release_temporary
    use file_system, only: move_file, delete_file
    use figure_renderer, only: renderer_t, draw_figure, stop_renderer, FIGURE_DRAWN, &
                               FIGURE_NO_GNUPLOT
    implicit none
    private

    !> Key results of one case, for the console and the sweep summary.
    type, public :: case_result_t
        character(len=:), allocatable :: name     !! case name, e.g. sweep_003
        character(len=:), allocatable :: label    !! 'case i of n: swept values'
        character(len=:), allocatable :: message  !! the failure, or a note on the figure
        integer :: status = EXIT_OK                !! exit status of the case
        real(dp) :: rho = 0.0_dp                   !! relative stiffness (paper 5.2b)
        real(dp) :: mean_pressure = 0.0_dp         !! V / contact area [F/L^2] (figures)
        integer :: n_outer = 0                     !! outer iterations (or Newton stages)
        integer :: n_inner = 0                     !! inner iterations (or Newton steps)
        integer :: elements = 0                    !! N_e of the mesh solved (refined, adapted)
        type(entry_t), allocatable :: entries(:)   !! key results (summary_table); solved only
        type(design_value_t), allocatable :: values(:)  !! design values (design_envelope)
        type(design_check_t), allocatable :: checks(:)  !! the CHECK cards' design checks
        type(adaptation_t) :: adaptation           !! what ADAPT did (adapted false without it)
        character(len=warning_length), allocatable :: warnings(:)  !! plausibility (deck, result)
    end type case_result_t

    public :: write_case_files, render_png

contains

    !> The files of one solved or failed case: report, data, CSV, JSON summary, gnuplot script
    !! and PNG. A failed case writes its report (ANALYSIS FAILED) and its JSON only, and
    !! removes the data files and figure of an earlier run of the same case; a write that
    !! fails leaves no file of the case. Cases of a sweep call this in parallel: every Fortran
    !! I/O statement runs one case at a time (critical section fricon_output: in gfortran 12 an
    !! internal write that runs while another thread opens or closes a file can come out
    !! garbled, doc/CHOICES.md), and only gnuplot's drawing, a child process fed through C,
    !! runs in parallel.
    subroutine write_case_files(deck, c, base, figures, result, renderer, record)
        type(deck_t), intent(in) :: deck             !! the deck (echoed in the report)
        type(case_t), intent(in) :: c                !! the case, solved or failed
        character(len=*), intent(in) :: base         !! output path without extension
        logical, intent(in) :: figures               !! run gnuplot on the written .gp
        type(case_result_t), intent(inout) :: result !! status and message on return
        type(renderer_t), intent(inout), optional :: renderer  !! the thread's gnuplot
        logical, intent(in), optional :: record      !! write the HTML record (default yes)
        character(len=:), allocatable :: note
        logical :: written, drawn_next, html
        html = .true.
        if (present(record)) html = record
        !$omp critical (fricon_output)
        call remove_temporaries(base)
        if (.not. html) call remove_output(base//'.html')
        if (result%status /= EXIT_OK) then
            call write_failed_case(deck, c, base, result)
            written = .false.
        else
            call write_case_data(deck, c, base, figures, result, written)
        end if
        ! without a figure the report follows at once (one pass through the section)
        drawn_next = written .and. figures
        if (written .and. .not. figures) call write_case_report(deck, c, base, '', result)
        if (written .and. .not. figures .and. html) call write_record(deck, c, base, &
            'the run was asked for no figures (--no-figures)', '', result)
        !$omp end critical (fricon_output)
        if (.not. drawn_next) return
        call render_png(base, note, renderer)
        result%message = note
        !$omp critical (fricon_output)
        call write_case_report(deck, c, base, note, result)
        if (html) call write_record(deck, c, base, note, note, result)
        !$omp end critical (fricon_output)
    end subroutine write_case_files

    !> A solved case's calculation record (html_record), written after its report and
    !! figure; if it cannot be written, no file of the case is left.
    subroutine write_record(deck, c, base, figure_note, note, result)
        type(deck_t), intent(in) :: deck             !! the deck (its name and lines)
        type(case_t), intent(in) :: c                !! the solved case
        character(len=*), intent(in) :: base         !! output path without extension
        character(len=*), intent(in) :: figure_note  !! why there is no figure ('': drawn)
        character(len=*), intent(in) :: note         !! the report's note on the figure, or ''
        type(case_result_t), intent(inout) :: result !! status and message on failure
        type(error_t), allocatable :: err
        if (result%status /= EXIT_OK) return
        call write_case_record(deck, c, base, result%label, result%entries, figure_note, &
                               report_notes(result%warnings, note), err)
        if (allocated(err)) then
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
        end if
    end subroutine write_record

    !> A failed case: its report (ANALYSIS FAILED) and JSON; no data file or figure of an
    !! earlier run of the case is left beside them.
    subroutine write_failed_case(deck, c, base, result)
        type(deck_t), intent(in) :: deck             !! the deck (echoed in the report)
        type(case_t), intent(in) :: c                !! the failed case
        character(len=*), intent(in) :: base         !! output path without extension
        type(case_result_t), intent(inout) :: result !! status and message on return
        type(error_t), allocatable :: err_report
        associate (m => c%model, d => c%d, sol => c%sol, tab => c%stations, s => c%summary)
        call remove_stale(base)
        call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                          result%entries, s, result%message, &
                          report_notes(result%warnings, ''), err_report, result%adaptation)
        if (.not. allocated(err_report)) call write_summary_json(base//'.json', result%name, &
            deck%path, m, result%status, result%message, result%entries, s, sol, tab, &
            err_report, result%adaptation, result%warnings, deck_id_of(deck), deck%lines)
        if (allocated(err_report)) then
            ! the failure's own report cannot be written: that is what the user must hear
            call remove_case_files(base)
            result%status = err_report%code
            result%message = trim(result%message)//'; and its report: '//err_report%message
        end if
        end associate
    end subroutine write_failed_case

    !> A solved case's data file, CSV and springs CSV (physical decks; the springs with P1
    !! displacements: spring_file), JSON summary and figure script;
    !! `written` is false when one of them could not be written (then none is left).
    subroutine write_case_data(deck, c, base, figures, result, written)
        type(deck_t), intent(in) :: deck             !! the deck (its path in the JSON)
        type(case_t), intent(in) :: c                !! the solved case
        character(len=*), intent(in) :: base         !! output path without extension
        logical, intent(in) :: figures               !! a figure will be drawn
        type(case_result_t), intent(inout) :: result !! status and message on failure
        logical, intent(out) :: written
        type(error_t), allocatable :: err
        associate (m => c%model, sol => c%sol, tab => c%stations, s => c%summary)
        call write_data_file(base//'.dat', m, tab, err)
        if (.not. allocated(err) .and. .not. m%nondim) call write_physical_csv(base//'.csv', m, &
                                                                               tab, err)
        if (.not. allocated(err)) call write_summary_json(base//'.json', result%name, deck%path, &
                                                          m, EXIT_OK, '', result%entries, s, &
                                                          sol, tab, err, result%adaptation, &
                                                          result%warnings, deck_id_of(deck), &
                                                          deck%lines)
        ! no figure or CSV of an earlier run beside results that have none
        if (.not. allocated(err) .and. .not. figures) call remove_output(base//'.png')
        if (.not. allocated(err) .and. m%nondim) call remove_output(base//'.csv')
        if (.not. allocated(err) .and. has_springs(m, c%d)) call write_springs_csv( &
            base//'_springs.csv', m, c%d, sol, c%design, err)
        if (.not. allocated(err) .and. .not. has_springs(m, c%d)) &
            call remove_output(base//'_springs.csv')
        if (.not. allocated(err)) call write_plot_script(base//'.gp', result%name, m, &
                                                         result%label, s, err)
        written = .not. allocated(err)
        if (allocated(err)) then
            ! no partial set of a case's files is left (README: exit 1 writes no output)
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
        end if
        end associate
    end subroutine write_case_data

    !> A solved case's report, its closing lines the warnings and the figure's note; if it
    !! cannot be written, no file of the case is left.
    subroutine write_case_report(deck, c, base, note, result)
        type(deck_t), intent(in) :: deck             !! the deck (echoed in the report)
        type(case_t), intent(in) :: c                !! the solved case
        character(len=*), intent(in) :: base         !! output path without extension
        character(len=*), intent(in) :: note         !! why the figure was not drawn, or ''
        type(case_result_t), intent(inout) :: result !! status and message on failure
        type(error_t), allocatable :: err
        associate (m => c%model, d => c%d, sol => c%sol, tab => c%stations, s => c%summary)
        call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                          result%entries, s, '', report_notes(result%warnings, note), err, &
                          result%adaptation)
        if (allocated(err)) then
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
        end if
        end associate
    end subroutine write_case_report

    !> The report's closing lines: each warning, then the note (if any).
    pure function report_notes(warnings, note) result(lines)
        character(len=*), intent(in) :: warnings(:), note
        character(len=warning_length + 10), allocatable :: lines(:)
        integer :: k
        allocate (lines(size(warnings) + merge(1, 0, len_trim(note) > 0)))
        do k = 1, size(warnings)
            lines(k) = 'WARNING: '//warnings(k)
        end do
        if (len_trim(note) > 0) lines(size(lines)) = 'NOTE: '//note
    end function report_notes

    !> Results of an earlier run of the same case that a failed run must not leave beside its
    !! ANALYSIS FAILED report.
    subroutine remove_stale(base)
        character(len=*), intent(in) :: base
        character(len=*), parameter :: ext(7) = ['.dat        ', '.csv        ', &
            '.gp         ', '.png        ', '.txt        ', '_springs.csv', '.html       ']
        call remove_files(base, ext)
    end subroutine remove_stale

    !> The deck's identity for the JSON summaries ('' for the built-in default, which is no
    !! file: outputs of a deck that happens to lie at input/default.dat are not its own).
    function deck_id_of(deck) result(identity)
        type(deck_t), intent(in) :: deck
        character(len=:), allocatable :: identity
        identity = ''
        if (deck%from_file) identity = deck_identity(canonical_path(deck%path))
    end function deck_id_of

    !> Every file of a case (a write that failed leaves none of the others).
    subroutine remove_case_files(base)
        character(len=*), intent(in) :: base
        call remove_stale(base)
        call remove_files(base, ['.json'])
        call remove_temporaries(base)
    end subroutine remove_case_files

    !> The temporary files of this case's outputs that a killed earlier run may have left
    !! (NAME.ext.tmp): removed before the case writes, so none is ever taken for a result.
    subroutine remove_temporaries(base)
        character(len=*), intent(in) :: base
        character(len=*), parameter :: ext(8) = ['.dat.tmp        ', '.csv.tmp        ', &
            '.gp.tmp         ', '.png.tmp        ', '.txt.tmp        ', '.json.tmp       ', &
            '_springs.csv.tmp', '.html.tmp       ']
        call remove_files(base, ext)
    end subroutine remove_temporaries

    !> base.ext for each ext, where it looks like fricon's output (never a deck given such a
    !! name: output_paths::remove_output).
    subroutine remove_files(base, ext)
        character(len=*), intent(in) :: base
        character(len=*), intent(in) :: ext(:)
        integer :: k
        do k = 1, size(ext)
            call remove_output(base//trim(ext(k)))
        end do
    end subroutine remove_files

    !> gnuplot runs the figure script base.gp and renders the PNG to a temporary name, moved
    !! into place when complete; `note` says why a figure was not drawn. With a renderer, its
    !! gnuplot draws the figure (and stays for the next); without, a gnuplot of its own. The
    !! drawing runs in parallel with other threads; the checks of the files are Fortran I/O
    !! and run in the critical section fricon_output (so never call this inside it).
    subroutine render_png(base, note, renderer)
        character(len=*), intent(in) :: base                   !! output path without extension
        character(len=:), allocatable, intent(out) :: note     !! '' when drawn
        type(renderer_t), intent(inout), optional :: renderer  !! the thread's gnuplot
        type(renderer_t) :: own
        integer :: outcome
        logical :: moved
        note = ''
        if (scan(base, '''"`'//achar(10)) > 0) then
            note = 'figure not rendered: the output path contains a quote'
            !$omp critical (fricon_output)
            call remove_output(base//'.png')
            !$omp end critical (fricon_output)
            return
        end if
        ! a SIGTERM or SIGINT while gnuplot draws removes the temporary figure
        call register_temporary(base//'.png.tmp')
        if (present(renderer)) then
            call draw_figure(renderer, base//'.gp', base//'.png.tmp', outcome)
        else
            call draw_figure(own, base//'.gp', base//'.png.tmp', outcome)
            call stop_renderer(own)
        end if
        if (outcome == FIGURE_NO_GNUPLOT) then
            note = 'figure '//base//'.png not drawn: gnuplot is not installed (the script '// &
                   base//'.gp is written; scripts/setup.sh installs gnuplot)'
            !$omp critical (fricon_output)
            call remove_output(base//'.png')      ! not an earlier run's figure beside it
            !$omp end critical (fricon_output)
            call release_temporary(base//'.png.tmp')
            return
        end if
        moved = .false.
        !$omp critical (fricon_output)
        ! (a PNG ends with its IEND chunk: gnuplot reports no error on a full disk with the
        ! file cut; rename(2): a folder named like the figure is not a place to move it into)
        if (outcome == FIGURE_DRAWN) then
            if (png_complete(base//'.png.tmp')) call move_file(base//'.png.tmp', base//'.png', &
                                                               moved)
        end if
        if (.not. moved) then
            note = 'figure '//base//'.png not drawn: gnuplot failed on '//base//'.gp, the '// &
                   'figure came out incomplete (disk full?), or '//base//'.png cannot be replaced'
            call remove_output(base//'.png')
            call delete_file(base//'.png.tmp')
        end if
        !$omp end critical (fricon_output)
        call release_temporary(base//'.png.tmp')
    end subroutine render_png

    !> The file ends with a PNG's IEND chunk within its last 12 bytes.
    logical function png_complete(path)
        character(len=*), intent(in) :: path   !! the figure's file
        character(len=12) :: tail
        integer :: u, ios, size_bytes
        png_complete = .false.
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=size_bytes)
        if (size_bytes >= len(tail)) then
            read (u, pos=size_bytes - len(tail) + 1, iostat=ios) tail
            png_complete = ios == 0 .and. index(tail, 'IEND') > 0
        end if
        close (u)
    end function png_complete
end module case_files
