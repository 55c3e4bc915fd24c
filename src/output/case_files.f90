!> The files of one case and their safety: what a solved or failed case writes, how a
!! figure is rendered, and which files an earlier run of the same case must not leave behind.
module case_files
    use kinds, only: dp
    use errors, only: error_t, EXIT_OK
    use deck_reader, only: deck_t
    use solved_case, only: case_t
    use summary_table, only: entry_t
    use adaptive_solve, only: adaptation_t
    use plausibility, only: warning_length
    use report_writer, only: write_data_file, write_physical_csv, write_summary_json, &
                             write_plot_script, write_report
    use output_paths, only: remove_output, canonical_path
    use temporary_cleanup, only: register_temporary, release_temporary
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
        type(adaptation_t) :: adaptation           !! what ADAPT did (adapted false without it)
        character(len=warning_length), allocatable :: warnings(:)  !! plausibility (deck, result)
    end type case_result_t

    public :: write_case_files, render_png

contains

    !> The files of one solved or failed case: report, data, CSV, JSON summary, gnuplot script
    !! and PNG. A failed case writes its report (ANALYSIS FAILED) and its JSON only, and
    !! removes the data files and figure of an earlier run of the same case; a write that
    !! fails leaves no file of the case.
    subroutine write_case_files(deck, c, base, figures, result)
        type(deck_t), intent(in) :: deck             !! the deck (echoed in the report)
        type(case_t), intent(in) :: c                !! the case, solved or failed
        character(len=*), intent(in) :: base         !! output path without extension
        logical, intent(in) :: figures               !! run gnuplot on the written .gp
        type(case_result_t), intent(inout) :: result !! status and message on return
        type(error_t), allocatable :: err, err_report
        character(len=:), allocatable :: note
        associate (m => c%model, d => c%d, sol => c%sol, tab => c%stations, s => c%summary)
        call remove_temporaries(base)
        if (result%status /= EXIT_OK) then
            call remove_stale(base)
            call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                              result%entries, s, result%message, &
                              report_notes(result%warnings, ''), err_report, result%adaptation)
            if (.not. allocated(err_report)) call write_summary_json(base//'.json', result%name, &
                deck%path, m, result%status, result%message, result%entries, s, sol, tab, &
                err_report, result%adaptation, result%warnings, deck_file_of(deck))
            if (allocated(err_report)) then
                ! the failure's own report cannot be written: that is what the user must hear
                call remove_case_files(base)
                result%status = err_report%code
                result%message = trim(result%message)//'; and its report: '//err_report%message
            end if
            return
        end if
        call write_data_file(base//'.dat', m, tab, err)
        if (.not. allocated(err) .and. .not. m%nondim) call write_physical_csv(base//'.csv', m, &
                                                                               tab, err)
        if (.not. allocated(err)) call write_summary_json(base//'.json', result%name, deck%path, &
                                                          m, EXIT_OK, '', result%entries, s, &
                                                          sol, tab, err, result%adaptation, &
                                                          result%warnings, deck_file_of(deck))
        ! no figure or CSV of an earlier run beside results that have none
        if (.not. allocated(err) .and. .not. figures) call remove_output(base//'.png')
        if (.not. allocated(err) .and. m%nondim) call remove_output(base//'.csv')
        if (.not. allocated(err)) call write_plot_script(base//'.gp', result%name, m, &
                                                         result%label, s, err)
        if (allocated(err)) then
            ! no partial set of a case's files is left (README: exit 1 writes no output)
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
            return
        end if
        note = ''
        if (figures) call render_png(base, note)
        result%message = note
        call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                          result%entries, s, '', report_notes(result%warnings, note), err, &
                          result%adaptation)
        if (allocated(err)) then
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
        end if
        end associate
    end subroutine write_case_files

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
        character(len=*), parameter :: ext(5) = ['.dat', '.csv', '.gp ', '.png', '.txt']
        call remove_files(base, ext)
    end subroutine remove_stale

    !> The deck's canonical path for the JSON summaries ('' for the built-in default, which is
    !! no file: outputs of a deck that happens to lie at input/default.dat are not its own).
    function deck_file_of(deck) result(path)
        type(deck_t), intent(in) :: deck
        character(len=:), allocatable :: path
        path = ''
        if (deck%from_file) path = canonical_path(deck%path)
    end function deck_file_of

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
        character(len=*), parameter :: ext(6) = ['.dat.tmp ', '.csv.tmp ', '.gp.tmp  ', &
                                                 '.png.tmp ', '.txt.tmp ', '.json.tmp']
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
    !! into place on success; `note` says why a figure was not drawn.
    subroutine render_png(base, note)
        !> path of the script without .gp (and of the PNG without .png)
        character(len=*), intent(in) :: base
        !> why no figure was drawn ('' when it was)
        character(len=:), allocatable, intent(out) :: note
        integer :: exit_status, cmd_status
        note = ''
        if (index(base, "'") > 0 .or. index(base, '"') > 0) then
            note = 'figure not rendered: the output path contains a quote'
            call remove_output(base//'.png')
            return
        end if
        call execute_command_line('command -v gnuplot > /dev/null 2>&1', exitstat=exit_status, &
                                  cmdstat=cmd_status)
        if (cmd_status /= 0 .or. exit_status /= 0) then
            note = 'figure '//base//'.png not drawn: gnuplot is not installed (the script '// &
                   base//'.gp is written; scripts/setup.sh installs gnuplot)'
            call remove_output(base//'.png')      ! not an earlier run's figure beside it
            return
        end if
        call register_temporary(base//'.png.tmp')
        call execute_command_line("gnuplot -e ""png_override='"//base//".png.tmp'"" '"//base// &
            ".gp' && tail -c 12 '"//base//".png.tmp' | grep -qa IEND && mv -fT '"//base// &
            ".png.tmp' '"//base//".png'", exitstat=exit_status, cmdstat=cmd_status)
        if (cmd_status /= 0 .or. exit_status /= 0) then
            ! (a PNG ends with its IEND chunk: gnuplot exits 0 on a full disk with the file
            ! cut; mv -T: a folder named like the figure is not a place to move it into)
            note = 'figure '//base//'.png not drawn: gnuplot failed on '//base//'.gp, the '// &
                   'figure came out incomplete (disk full?), or '//base//'.png cannot be replaced'
            call remove_output(base//'.png')
            call execute_command_line("rm -f '"//base//".png.tmp'")
        end if
        call release_temporary(base//'.png.tmp')
    end subroutine render_png
end module case_files
