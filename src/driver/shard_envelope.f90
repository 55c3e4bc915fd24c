!> The envelope of a deck's load combinations from its shards (fricon --merge): the same
!! STEM_envelope.txt, .json and .csv as a single run of the deck writes (envelope_file), built
!! from the design values in the cases' JSON summaries beside the shards (case_json_reader;
!! nothing is solved again), stamped with the shards' run time as the merged summary is. The
!! cases are read and checked before the merge writes anything: a case that did not solve, a
!! summary that cannot be read, or shards of another fricon version refuse the merge, as a
!! single run writes no envelope when a case fails.
module shard_envelope
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_OK, EXIT_INPUT
    use deck_reader, only: deck_t, combination_names
    use model, only: model_t
    use design_summary, only: summary_t
    use summary_table, only: entry_t, summary_entries
    use case_files, only: case_result_t
    use case_json_reader, only: json_field, read_case_values
    use envelope_file, only: write_envelope_files
    use run_identity, only: program_name, program_version
    use deck_fields, only: int_text
    implicit none
    private

    !> What the merged envelope needs besides the cases.
    type, public :: shard_envelope_t
        logical :: wanted = .false.                      !! the deck has load combinations
        character(len=:), allocatable :: title           !! the deck's TITLE
        character(len=:), allocatable :: deck_name       !! its file name (the cases' "deck")
        character(len=:), allocatable :: deck_id         !! its identity (the cases' JSON)
        character(len=:), allocatable :: time            !! the run time of the stamp
    end type shard_envelope_t

    public :: read_shard_envelope, write_shard_envelope

contains

    !> For a deck with load combinations: every case's design values into results(:)%values
    !! from its JSON summary jsons(i), and what the envelope's files name; nothing for a deck
    !! without. err (a refusal): a case did not solve or its summary cannot be read, or the
    !! shards were written by another fricon version than this one.
    subroutine read_shard_envelope(deck, m, jsons, stamp, results, env, err)
        type(deck_t), intent(in) :: deck                   !! the shards' deck
        type(model_t), intent(in) :: m                     !! its first case's model
        character(len=*), intent(in) :: jsons(:)           !! each case's JSON summary
        character(len=*), intent(in) :: stamp              !! the summary's '# fricon ...' line
        type(case_result_t), intent(inout) :: results(:)   !! the cases (name, label, status)
        type(shard_envelope_t), intent(out) :: env         !! for write_shard_envelope
        type(error_t), allocatable, intent(out) :: err     !! a refusal
        type(summary_t) :: empty
        type(entry_t), allocatable :: keys(:)
        integer :: i
        env%wanted = size(combination_names(deck)) > 0
        if (.not. env%wanted) return
        call check_version(stamp, env%time, err)
        if (allocated(err)) return
        keys = summary_entries(m, empty, 0.0_dp)
        do i = 1, size(results)
            call read_case(trim(jsons(i)), keys, results(i), err)
            if (allocated(err)) return
            if (size(results(i)%values) /= size(results(1)%values)) then
                call new_error(err, EXIT_INPUT, trim(jsons(i))//' and '//trim(jsons(1))// &
                               ' hold different design values: not cases of one deck')
                return
            end if
            if (any(results(i)%values%name /= results(1)%values%name)) then
                call new_error(err, EXIT_INPUT, trim(jsons(i))//' and '//trim(jsons(1))// &
                               ' hold different design values: not cases of one deck')
                return
            end if
        end do
        env%title = trim(deck%base%title)
        call json_field(trim(jsons(1)), 'deck', env%deck_name)
        call json_field(trim(jsons(1)), 'deck_identity', env%deck_id)
    end subroutine read_shard_envelope

    !> One case's design values; a refusal when it did not solve.
    subroutine read_case(json, keys, result, err)
        character(len=*), intent(in) :: json
        type(entry_t), intent(in) :: keys(:)
        type(case_result_t), intent(inout) :: result
        type(error_t), allocatable, intent(out) :: err
        integer :: status
        call read_case_values(json, keys, status, result%values, err)
        if (allocated(err)) return
        if (status /= result%status) then
            call new_error(err, EXIT_INPUT, json//' gives exit status '//int_text(status)// &
                ' where its shard summary gives '//int_text(result%status)//': files of '// &
                'different runs')
        else if (status /= EXIT_OK) then
            call new_error(err, EXIT_INPUT, 'no envelope of the load combinations: '// &
                result%name//' ('//result%label//') did not solve (exit status '// &
                int_text(status)//'; its report '//result%name//'.txt says why), and an '// &
                'envelope without it would not be one, as in a single run of the deck')
        end if
    end subroutine read_case

    !> The run time of the stamp '# fricon 0.2.0, run TIME', which must be this fricon's:
    !! the envelope's design values are those this version writes and reads.
    subroutine check_version(stamp, time, err)
        character(len=*), intent(in) :: stamp
        character(len=:), allocatable, intent(out) :: time
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: mark = ', run '
        character(len=:), allocatable :: writer
        integer :: at
        at = index(stamp, mark)
        writer = stamp(min(3, len(stamp) + 1):max(at - 1, 0))
        time = stamp(at + len(mark):)
        if (at == 0 .or. writer /= program_name//' '//program_version) then
            call new_error(err, EXIT_INPUT, 'the shards were written by '//writer//', this '// &
                'is '//program_name//' '//program_version//': merge a deck with load '// &
                'combinations with the version that solved it (its envelope is built from '// &
                'the cases'' JSON summaries)')
            time = ''
        end if
    end subroutine check_version

    !> STEM_envelope.txt, .json and .csv in folder (nothing for a deck without combinations).
    subroutine write_shard_envelope(folder, stem, env, results, err)
        character(len=*), intent(in) :: folder, stem       !! the merge's folder; the stem
        type(shard_envelope_t), intent(in) :: env          !! from read_shard_envelope
        type(case_result_t), intent(in) :: results(:)      !! the cases, with their values
        type(error_t), allocatable, intent(out) :: err     !! a file cannot be written
        if (.not. env%wanted) return
        call write_envelope_files(folder, stem, env%title, env%deck_name, env%deck_id, &
                                  results, err, env%time)
    end subroutine write_shard_envelope
end module shard_envelope
