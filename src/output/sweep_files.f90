!> A sweep's own files: the summary CSV (one row per case) and the overlay figure of the
!! solved cases; a shard of a job array writes its rows to a shard summary.
module sweep_files
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_OK, EXIT_INPUT
    use model, only: model_t
    use summary_table, only: entry_keys
    use report_writer, only: write_sweep_script
    use atomic_files, only: open_temporary, commit_file
    use output_paths, only: remove_output, remove_shard_summaries, remove_sweep_outputs
    use case_files, only: case_result_t, render_png
    use run_identity, only: run_stamp
    use response_figure, only: swept_values, write_response_script
    implicit none
    private

    public :: write_sweep_outputs, write_response_plot

contains

    !> A sweep's summary CSV and overlay figure; a shard writes STEM_summary.shard-I-of-N.csv
    !! with its own rows (fricon --merge joins the shards into STEM_summary.csv).
    subroutine write_sweep_outputs(out_dir, stem, cases, results, selected, figures, &
                                   shard_index, shard_count, err)
        character(len=*), intent(in) :: out_dir        !! output folder
        character(len=*), intent(in) :: stem           !! the deck's name without extension
        type(model_t), intent(in) :: cases(:)          !! the sweep's models
        type(case_result_t), intent(in) :: results(:)  !! their results (selected ones solved)
        logical, intent(in) :: selected(:)             !! the cases of this shard
        logical, intent(in) :: figures                 !! render the overlay figure
        integer, intent(in) :: shard_index, shard_count  !! this shard of how many (1 of 1)
        type(error_t), allocatable, intent(out) :: err  !! a file could not be written
        character(len=40) :: shard
        integer :: n_unwritten
        shard = ''
        if (shard_count > 1) write (shard, '(a,i0,a,i0)') '.shard-', shard_index, '-of-', &
            shard_count
        n_unwritten = count(selected .and. results%status == EXIT_INPUT)
        if (n_unwritten > 0) then
            ! a case could not write its files (a full disk): a summary would cover part of
            ! the sweep, and one of an earlier run would not match it
            call remove_sweep_outputs(out_dir, stem, trim(shard))
            write (shard, '(i0)') n_unwritten
            call new_error(err, EXIT_INPUT, 'no sweep summary written: '//trim(shard)// &
                           ' case(s) could not write their files')
            return
        end if
        if (shard_count > 1) then
            ! the summaries of an earlier split into another number of shards are stale
            call remove_shard_summaries(out_dir, stem, shard_count)
            call write_summary_csv(out_dir//'/'//stem//'_summary'//trim(shard)//'.csv', cases(1), &
                                   pack(results, selected), err)
        else
            call remove_shard_summaries(out_dir, stem, 0)
            call write_summary_csv(out_dir//'/'//stem//'_summary.csv', cases(1), results, err)
            if (.not. allocated(err)) call write_sweep_plot(out_dir, stem, cases, results, &
                                                            figures, err)
            if (.not. allocated(err)) call write_response_plot(out_dir, stem, cases(1), results, &
                                                               figures, err)
            if (allocated(err)) then
                ! no summary or figure of an earlier run beside this run's cases
                call remove_sweep_outputs(out_dir, stem, '')
            end if
        end if
    end subroutine write_sweep_outputs

    !> output/STEM_sweep.gp and .png: the solved cases overlaid (report_writer
    !! write_sweep_script: the first solved case's settings, the case files, the legend labels
    !! of the swept values and each case's mean contact pressure for the clip rule).
    subroutine write_sweep_plot(out_dir, stem, cases, results, figures, err)
        character(len=*), intent(in) :: out_dir, stem
        type(model_t), intent(in) :: cases(:)
        type(case_result_t), intent(in) :: results(:)
        logical, intent(in) :: figures
        type(error_t), allocatable, intent(out) :: err
        character(len=200), allocatable :: names(:), labels(:)
        real(dp), allocatable :: means(:)
        character(len=:), allocatable :: note
        integer :: i, first
        allocate (names(0), labels(0), means(0))
        first = 0
        do i = 1, size(results)
            if (results(i)%status /= EXIT_OK) cycle
            if (first == 0) first = i
            names = [character(len=200) :: names, results(i)%name]
            labels = [character(len=200) :: labels, one_word(results(i)%label)]
            means = [means, results(i)%mean_pressure]
        end do
        if (first == 0 .or. .not. figures) call remove_output(out_dir//'/'//stem//'_sweep.png')
        if (first == 0) then
            ! no solved case: an earlier overlay would show curves of files that are gone
            call remove_output(out_dir//'/'//stem//'_sweep.gp')
            return
        end if
        call write_sweep_script(out_dir//'/'//stem//'_sweep.gp', stem, cases(first), names, &
                                labels, means, err)
        if (allocated(err)) return
        if (figures) call render_png(out_dir//'/'//stem//'_sweep', note)
    end subroutine write_sweep_plot

    !> output/STEM_response.gp and .png (response_figure); an earlier run's are removed
    !! when this run has none (no solved case, or no figures for the PNG).
    subroutine write_response_plot(out_dir, stem, m, results, figures, err)
        character(len=*), intent(in) :: out_dir, stem   !! output folder; the deck's file stem
        type(model_t), intent(in) :: m                  !! a case's model (title, units)
        type(case_result_t), intent(in) :: results(:)   !! every case of the sweep
        logical, intent(in) :: figures                  !! render the PNG
        type(error_t), allocatable, intent(out) :: err  !! allocated on failure
        character(len=:), allocatable :: base, note
        logical :: written
        base = out_dir//'/'//stem//'_response'
        call write_response_script(base//'.gp', stem, m, results, written, err)
        if (allocated(err)) return
        if (.not. written) call remove_output(base//'.gp')
        if (written .and. figures) then
            call render_png(base, note)
        else
            call remove_output(base//'.png')
        end if
    end subroutine write_response_plot

    !> A sweep label as one quoted gnuplot word (for word() and the legend):
    !! 'case 002 of 006: RHO=0.01 F=0.5' -> 'RHO=0.01 F=0.5' in single quotes.
    pure function one_word(label) result(word)
        character(len=*), intent(in) :: label
        character(len=:), allocatable :: word
        integer :: i
        word = trim(adjustl(label(index(label, ':') + 1:)))
        do i = 1, len(word)
            if (index('"''`$\', word(i:i)) > 0) word(i:i) = ' '
        end do
        word = trim(adjustl(word))
        if (len(word) == 0) word = 'case'
        word = "'"//word//"'"
    end function one_word

    !> output/STEM_summary.csv: a `#` line (program, version, run time), the header, one row
    !! per case, with the key results of summary_table
    !! (display units, named in the header); a failed case has empty result fields.
    subroutine write_summary_csv(path, m, results, err)
        character(len=*), intent(in) :: path
        type(model_t), intent(in) :: m
        type(case_result_t), intent(in) :: results(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=32), allocatable :: keys(:)
        character(len=16), allocatable :: names(:), texts(:)
        real(dp), allocatable :: values(:)
        integer :: u, i, k
        keys = entry_keys(m)
        call swept_values(results(1)%label, names, texts, values)
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# '//run_stamp()
        write (u, '(a)', advance='no') 'case,parameters'
        do k = 1, size(names)
            write (u, '(a)', advance='no') ','//trim(names(k))
        end do
        write (u, '(a)', advance='no') ',status,rho,outer_iterations,elements'
        do k = 1, size(keys)
            write (u, '(a)', advance='no') ','//trim(keys(k))//unit_suffix(results, k)
        end do
        write (u, '(a)') ',message'
        do i = 1, size(results)
            associate (r => results(i))
                write (u, '(a,",",a)', advance='no') r%name, '"'//r%label//'"'
                call swept_values(r%label, names, texts, values)
                do k = 1, size(values)
                    write (u, '(",",es15.7)', advance='no') values(k)
                end do
                write (u, '(",",i0,",",es15.7,",",i0,",",i0)', advance='no') r%status, r%rho, &
                    r%n_outer, r%elements
                do k = 1, size(keys)
                    if (r%status /= EXIT_OK .or. .not. allocated(r%entries)) then
                        write (u, '(a)', advance='no') ','
                    else if (.not. r%entries(k)%defined) then
                        write (u, '(a)', advance='no') ','
                    else if (r%entries(k)%integer_valued) then
                        write (u, '(",",i0)', advance='no') nint(r%entries(k)%value)
                    else
                        write (u, '(",",es15.7)', advance='no') r%entries(k)%value
                    end if
                end do
                write (u, '(a)') ',"'//r%message//'"'
            end associate
        end do
        call commit_file(path, u, err)
    end subroutine write_summary_csv

    !> ' [unit]' of key k from the first solved case ('' if none or a pure number).
    pure function unit_suffix(results, k) result(text)
        type(case_result_t), intent(in) :: results(:)
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(results)
            if (.not. allocated(results(i)%entries)) cycle
            if (size(results(i)%entries) < k) cycle      ! a failed case has no results
            if (len_trim(results(i)%entries(k)%unit) > 0) &
                text = ' ['//trim(results(i)%entries(k)%unit)//']'
            return
        end do
    end function unit_suffix
end module sweep_files
