!> The run-level part of a deck with load combinations: after every case (each combination
!! at each sweep point) is solved and written, the envelope over all of them and its console
!! line. A sharded run (--shard I/N) solves part of the cases and writes no envelope, and
!! says so: fricon --merge of the shards writes it (shard_envelope).
module combination_runs
    use errors, only: error_t, EXIT_OK, EXIT_INPUT
    use deck_reader, only: deck_t
    use case_files, only: case_result_t
    use envelope_file, only: write_envelope_files, remove_envelope_files
    use output_paths, only: canonical_path, deck_identity
    use deck_fields, only: int_text
    implicit none
    private

    public :: write_run_envelope

contains

    !> STEM_envelope.txt, .json, .csv over every case of the run, and one console line; when
    !! a case failed, none (and a line on the error unit saying why). status: raised when a
    !! file cannot be written (a failed case has raised it already).
    subroutine write_run_envelope(deck, out_dir, results, shard_count, log_unit, err_unit, &
                                  status)
        type(deck_t), intent(in) :: deck                !! the deck run
        character(len=*), intent(in) :: out_dir         !! output folder
        type(case_result_t), intent(in) :: results(:)   !! every case, in case order
        integer, intent(in) :: shard_count              !! shards of the run (1: whole run)
        integer, intent(in) :: log_unit, err_unit       !! console: outcome; errors
        integer, intent(inout) :: status                !! the run's worst exit status
        type(error_t), allocatable :: err
        character(len=:), allocatable :: deck_id
        if (shard_count > 1) then
            call remove_envelope_files(out_dir, deck%stem)
            write (log_unit, '(a)') deck%stem//'_envelope: none from a shard; fricon '// &
                '--merge '//out_dir//'/'//deck%stem//'_summary.shard-*-of-'// &
                int_text(shard_count)//'.csv writes it when every shard has finished'
            return
        end if
        deck_id = ''
        if (deck%from_file) deck_id = deck_identity(canonical_path(deck%path))
        call write_envelope_files(out_dir, deck%stem, deck%base%title, deck%path, deck_id, &
                                  results, err)
        if (allocated(err)) then
            if (all(results%status == EXIT_OK)) then
                write (err_unit, '(a)') 'ERROR: '//deck%stem//'_envelope ('//deck%path// &
                    '): '//err%message
                status = max(status, max(err%code, EXIT_INPUT))
            else
                write (err_unit, '(a)') 'WARNING: '//deck%stem//'_envelope ('//deck%path// &
                    '): '//err%message
            end if
            return
        end if
        write (log_unit, '(a)') deck%stem//'_envelope: envelope of '// &
            int_text(size(results))//' cases (max and min of every design value, with the '// &
            'case that gives it)  -> '//out_dir//'/'//deck%stem//'_envelope.txt'
    end subroutine write_run_envelope
end module combination_runs
