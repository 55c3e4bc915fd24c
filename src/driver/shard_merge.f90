!> `fricon --merge SHARD...`: the summaries of a sweep run in shards (fricon --shard I/N, the
!! tasks of a job array) joined into the summary and the response figure a single run
!! writes. The shards are STEM_summary.shard-I-of-N.csv, all N of them; the merged summary
!! is the first shard's stamp line and header, then every case's row in case order, so it
!! is byte for byte the single run's when the runs share their run time (SOURCE_DATE_EPOCH).
!! The deck comes from the cases' JSON summaries beside each shard ("deck_sha256" must agree,
!! "deck_text" gives the titles and units of the figure). For a deck with load combinations
!! the merge also writes the envelope a single run writes (shard_envelope). Every check runs
!! before anything is written: a refusal leaves the output folder as it was.
module shard_merge
    use kinds, only: dp
    use iso_fortran_env, only: error_unit, output_unit
    use errors, only: error_t, new_error, EXIT_OK, EXIT_INPUT
    use deck_fields, only: int_text
    use deck_reader, only: deck_t, parse_deck, case_model
    use model, only: model_t
    use summary_table, only: entry_t, summary_entries
    use design_summary, only: summary_t
    use case_files, only: case_result_t
    use sweep_files, only: write_response_plot
    use atomic_files, only: open_temporary, commit_file
    use output_paths, only: base_name, prepare_output_dir, remove_output
    use text_files, only: read_lines, text_lines
    use case_json_reader, only: json_field
    use shard_envelope, only: shard_envelope_t, read_shard_envelope, write_shard_envelope
    implicit none
    private

    public :: merge_shards, run_merge

    character(len=*), parameter :: marker = '_summary.shard-'

    !> One line of text.
    type :: text_t
        character(len=:), allocatable :: text
    end type text_t

    !> One shard summary as read (rows one by one: gfortran 12 mishandles arrays of
    !! deferred length inside an array of derived type).
    type :: shard_t
        character(len=:), allocatable :: path, folder, stamp, header
        type(text_t), allocatable :: rows(:)
        integer :: index = 0, count = 0
    end type shard_t

contains

    !> fricon --merge: merge and say what was written (standard output) or why not (standard
    !! error, status 1).
    subroutine run_merge(paths, out_dir, figures, quiet, status)
        character(len=*), intent(in) :: paths(:)   !! the shard summaries
        character(len=*), intent(in) :: out_dir    !! -o DIR, or ''
        logical, intent(in) :: figures             !! draw the response figure
        logical, intent(in) :: quiet               !! no line on standard output
        integer, intent(out) :: status             !! 0 merged, 1 refused
        type(error_t), allocatable :: err
        character(len=:), allocatable :: merged, envelope
        call merge_shards(paths, out_dir, figures, merged, err, envelope)
        if (allocated(err)) then
            write (error_unit, '(a)') 'ERROR: fricon --merge: '//err%message// &
                ' (nothing written)'
            status = err%code
            return
        end if
        status = EXIT_OK
        if (len(envelope) > 0) merged = merged//' and '//envelope
        if (.not. quiet) write (output_unit, '(a)') 'fricon --merge: '// &
            int_text(size(paths))//' shards -> '//merged
    end subroutine run_merge

    !> Merge the shard summaries `paths` into out_dir (''; the first shard's folder):
    !! STEM_summary.csv, STEM_response.gp and (figures) STEM_response.png, and for a deck with
    !! load combinations STEM_envelope.txt, .json and .csv. `merged` names the summary
    !! written.
    subroutine merge_shards(paths, out_dir, figures, merged, err, envelope)
        character(len=*), intent(in) :: paths(:)     !! the shard summaries, any order
        character(len=*), intent(in) :: out_dir      !! -o DIR, or '' (the first shard's folder)
        logical, intent(in) :: figures               !! draw the response figure
        character(len=:), allocatable, intent(out) :: merged   !! the summary written
        type(error_t), allocatable, intent(out) :: err   !! a refusal (nothing written)
        !> the envelope's report written ('' for a deck without load combinations)
        character(len=:), allocatable, intent(out), optional :: envelope
        type(shard_t), allocatable :: shards(:)
        character(len=:), allocatable :: stem, folder, rows(:), deck_lines(:), jsons(:)
        type(case_result_t), allocatable :: results(:)
        type(deck_t) :: deck
        type(model_t) :: m
        type(shard_envelope_t) :: env
        if (present(envelope)) envelope = ''
        call read_shards(paths, shards, stem, err)
        if (allocated(err)) return
        call ordered_rows(shards, rows, err)
        if (allocated(err)) return
        call case_jsons(shards, rows, jsons)
        call shard_deck(jsons, deck_lines, err)
        if (allocated(err)) return
        call rebuilt_results(stem, deck_lines, shards(1)%header, rows, deck, m, results, err)
        if (allocated(err)) return
        call read_shard_envelope(deck, m, jsons, shards(1)%stamp, results, env, err)
        if (allocated(err)) return
        folder = out_dir
        if (len(folder) == 0) folder = shards(1)%folder
        call prepare_output_dir(folder, err)
        if (allocated(err)) return
        merged = folder//'/'//stem//'_summary.csv'
        call write_merged(merged, shards(1), rows, err)
        if (allocated(err)) return
        call write_response_plot(folder, stem, m, results, figures, err)
        if (.not. allocated(err)) call write_shard_envelope(folder, stem, env, results, err)
        if (allocated(err)) then
            call remove_output(merged)
            call remove_output(folder//'/'//stem//'_response.gp')
            call remove_output(folder//'/'//stem//'_response.png')
            return
        end if
        if (present(envelope) .and. env%wanted) envelope = folder//'/'//stem//'_envelope.txt'
    end subroutine merge_shards

    !> Read every shard, after checking their names: one stem, one N, each I from 1 to N
    !! exactly once.
    subroutine read_shards(paths, shards, stem, err)
        character(len=*), intent(in) :: paths(:)
        type(shard_t), allocatable, intent(out) :: shards(:)
        character(len=:), allocatable, intent(out) :: stem
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: this_stem, missing
        integer :: k, i, n
        logical :: seen(64)
        stem = ''
        if (size(paths) == 0) then
            call new_error(err, EXIT_INPUT, '--merge needs the shard summaries '// &
                           'STEM_summary.shard-I-of-N.csv')
            return
        end if
        allocate (shards(size(paths)))
        seen = .false.
        do k = 1, size(paths)
            call shard_name(trim(paths(k)), this_stem, i, n, err)
            if (allocated(err)) return
            if (k == 1) stem = this_stem
            if (this_stem /= stem .or. n /= shards(1)%count .and. k > 1) then
                call new_error(err, EXIT_INPUT, trim(paths(k))//' is not a shard of '// &
                    stem//marker//'I-of-'//int_text(shards(1)%count)//'.csv')
                return
            end if
            if (seen(i)) then
                call new_error(err, EXIT_INPUT, 'shard '//int_text(i)//' of '//int_text(n)// &
                               ' given twice ('//trim(paths(k))//')')
                return
            end if
            seen(i) = .true.
            shards(k)%index = i
            shards(k)%count = n
            call read_shard(trim(paths(k)), shards(k), err)
            if (allocated(err)) return
        end do
        missing = ''
        do i = 1, shards(1)%count
            if (.not. seen(i)) missing = missing//' '//stem//marker//int_text(i)//'-of-'// &
                                         int_text(shards(1)%count)//'.csv'
        end do
        if (len(missing) > 0) call new_error(err, EXIT_INPUT, 'shard summaries missing:'// &
            missing//' (every shard of the job array must have finished)')
    end subroutine read_shards

    !> STEM, I and N of a path .../STEM_summary.shard-I-of-N.csv (2 <= N <= 64).
    subroutine shard_name(path, stem, i, n, err)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: stem
        integer, intent(out) :: i, n
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: name, split
        integer :: at, of, ios_i, ios_n
        name = base_name(path)
        at = index(name, marker, back=.true.)
        i = 0
        n = 0
        ios_i = 1
        ios_n = 1
        stem = ''
        if (at > 1 .and. len(name) > at + len(marker) + 4) then
            stem = name(1:at - 1)
            split = name(at + len(marker):)
            of = index(split, '-of-')
            if (of > 1 .and. index(split, '.csv', back=.true.) == len(split) - 3) then
                read (split(1:of - 1), *, iostat=ios_i) i
                read (split(of + 4:len(split) - 4), *, iostat=ios_n) n
            end if
        end if
        if (ios_i /= 0 .or. ios_n /= 0 .or. n < 2 .or. n > 64 .or. i < 1 .or. i > n) &
            call new_error(err, EXIT_INPUT, path//' is not a shard summary '// &
                           '(STEM_summary.shard-I-of-N.csv, written by fricon --shard I/N)')
    end subroutine shard_name

    !> A shard's lines: its stamp ('# fricon ...'), its header ('case,parameters,...'), rows.
    subroutine read_shard(path, shard, err)
        character(len=*), intent(in) :: path
        type(shard_t), intent(inout) :: shard
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: lines(:)
        logical :: ok
        integer :: r
        shard%path = path
        shard%folder = path(1:max(index(path, '/', back=.true.) - 1, 0))
        if (len(shard%folder) == 0) shard%folder = '.'
        if (path(1:1) == '/' .and. index(path, '/', back=.true.) == 1) shard%folder = '/'
        call read_lines(path, lines, ok)
        if (.not. ok) then
            call new_error(err, EXIT_INPUT, 'cannot read the shard summary '//path)
            return
        end if
        if (size(lines) < 2) then
            call new_error(err, EXIT_INPUT, path//' is cut short: no header (a shard that '// &
                           'did not finish?)')
            return
        end if
        if (index(lines(1), '# fricon ') /= 1 .or. index(lines(2), 'case,parameters,') /= 1) then
            call new_error(err, EXIT_INPUT, path//' is not a summary fricon wrote (no '// &
                           '"# fricon" line and "case,parameters" header)')
            return
        end if
        shard%stamp = trim(lines(1))
        shard%header = trim(lines(2))
        allocate (shard%rows(size(lines) - 2))
        do r = 1, size(shard%rows)
            shard%rows(r)%text = trim(lines(r + 2))
        end do
    end subroutine read_shard

    !> Every row of every shard in case order, after checking that the shards agree on the
    !! header, that each case of the sweep (1 to n, from the rows' 'case i of n') is in
    !! exactly one shard, and in the one --shard I/N gives it (I = mod(i - 1, N) + 1).
    subroutine ordered_rows(shards, rows, err)
        type(shard_t), intent(in) :: shards(:)
        character(len=:), allocatable, intent(out) :: rows(:)
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: owner(:)
        integer :: k, r, i, n, total, width
        total = -1
        width = 1
        do k = 1, size(shards)
            do r = 1, size(shards(k)%rows)
                width = max(width, len(shards(k)%rows(r)%text))
            end do
        end do
        do k = 1, size(shards)
            if (shards(k)%header /= shards(1)%header) then
                call new_error(err, EXIT_INPUT, shards(k)%path//' has other columns than '// &
                               shards(1)%path//': a shard of another deck')
                return
            end if
            if (program_of(shards(k)%stamp) /= program_of(shards(1)%stamp)) then
                call new_error(err, EXIT_INPUT, shards(k)%path//' and '//shards(1)%path// &
                    ' were written by different versions: '//program_of(shards(k)%stamp)// &
                    ', '//program_of(shards(1)%stamp))
                return
            end if
            do r = 1, size(shards(k)%rows)
                call case_of_row(shards(k)%rows(r)%text, i, n)
                if (total < 0 .and. n > 0) then
                    total = n
                    allocate (owner(total))
                    owner = 0
                    allocate (character(len=width) :: rows(total))
                end if
                if (i < 1 .or. n /= total .or. i > max(total, 0)) then
                    call new_error(err, EXIT_INPUT, shards(k)%path//', row '//int_text(r)// &
                        ': not a case of a sweep of '//int_text(max(total, 0))//' cases')
                    return
                end if
                if (owner(i) /= 0) then
                    call new_error(err, EXIT_INPUT, 'case '//int_text(i)//' is in both '// &
                        shards(owner(i))%path//' and '//shards(k)%path//': overlapping shards')
                    return
                end if
                if (mod(i - 1, shards(k)%count) + 1 /= shards(k)%index) then
                    call new_error(err, EXIT_INPUT, 'case '//int_text(i)//' in '// &
                        shards(k)%path//' belongs to shard '//int_text(mod(i - 1, &
                        shards(k)%count) + 1)//': shards of another split')
                    return
                end if
                owner(i) = k
                rows(i) = shards(k)%rows(r)%text
            end do
        end do
        if (total < 1) then
            call new_error(err, EXIT_INPUT, 'the shards hold no case')
        else if (any(owner == 0)) then
            call new_error(err, EXIT_INPUT, 'case '//int_text(findloc(owner, 0, dim=1))// &
                ' of '//int_text(total)//' is in no shard (a shard cut short?)')
        end if
    end subroutine ordered_rows

    !> 'fricon 0.2.0' of a stamp line '# fricon 0.2.0, run 2026-...'.
    pure function program_of(stamp) result(text)
        character(len=*), intent(in) :: stamp
        character(len=:), allocatable :: text
        text = stamp(3:)
        if (index(text, ', run ') > 0) text = text(1:index(text, ', run ') - 1)
    end function program_of

    !> i and n of a row's label '"case i of n: ..."' (0 when it has none).
    pure subroutine case_of_row(row, i, n)
        character(len=*), intent(in) :: row
        integer, intent(out) :: i, n
        integer :: at, of, colon, ios
        i = 0
        n = 0
        at = index(row, ',"case ')
        if (at == 0) return
        of = index(row(at:), ' of ') + at - 1
        colon = index(row(at:), ':') + at - 1
        if (of <= at + 7 .or. colon <= of + 4) return
        read (row(at + 7:of - 1), *, iostat=ios) i
        if (ios /= 0) i = 0
        read (row(of + 4:colon - 1), *, iostat=ios) n
        if (ios /= 0) n = 0
    end subroutine case_of_row

    !> Each case's JSON summary: CASE.json beside the shard summary holding its row.
    subroutine case_jsons(shards, rows, jsons)
        type(shard_t), intent(in) :: shards(:)
        character(len=*), intent(in) :: rows(:)
        character(len=:), allocatable, intent(out) :: jsons(:)
        integer :: k, r, i, n
        allocate (character(len=maxval([(len(shards(k)%folder), k=1, size(shards))]) + &
                  len(rows) + 6) :: jsons(size(rows)))
        do k = 1, size(shards)
            do r = 1, size(shards(k)%rows)
                call case_of_row(shards(k)%rows(r)%text, i, n)
                jsons(i) = shards(k)%folder//'/'//rows(i)(1:index(rows(i), ',') - 1)//'.json'
            end do
        end do
    end subroutine case_jsons

    !> The deck of the shards: every case's JSON summary must carry the same "deck_sha256";
    !! its "deck_text" as lines.
    subroutine shard_deck(jsons, lines, err)
        character(len=*), intent(in) :: jsons(:)
        character(len=:), allocatable, intent(out) :: lines(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: hash, first_hash, text
        integer :: i
        logical :: there
        do i = 1, size(jsons)
            call json_field(trim(jsons(i)), 'deck_sha256', hash)
            if (len(hash) == 0) then
                inquire (file=trim(jsons(i)), exist=there)
                if (.not. there) then
                    call new_error(err, EXIT_INPUT, 'the case''s JSON summary '// &
                        trim(jsons(i))//' is missing (it lies beside its shard summary)')
                else
                    call new_error(err, EXIT_INPUT, 'no deck_sha256 in '//trim(jsons(i))// &
                        ': the deck of the shard cannot be told')
                end if
                return
            end if
            if (i == 1) first_hash = hash
            if (hash /= first_hash) then
                call new_error(err, EXIT_INPUT, trim(jsons(i))//' and '//trim(jsons(1))// &
                    ' are cases of different decks (deck_sha256): shards of different decks')
                return
            end if
        end do
        call json_field(trim(jsons(1)), 'deck_text', text)
        call text_lines(text, lines)
    end subroutine shard_deck

    !> The cases as the response figure needs them (name, label, status, key results) from
    !! the merged rows, with the key results' labels and units of the deck: the summary's
    !! key columns must be the deck's.
    subroutine rebuilt_results(stem, deck_lines, header, rows, deck, m, results, err)
        character(len=*), intent(in) :: stem, header
        character(len=*), intent(in) :: deck_lines(:), rows(:)
        type(deck_t), intent(out) :: deck
        type(model_t), intent(out) :: m
        type(case_result_t), allocatable, intent(out) :: results(:)
        type(error_t), allocatable, intent(out) :: err
        type(summary_t) :: empty
        type(entry_t), allocatable :: template(:)
        character(len=:), allocatable :: label, fields(:), names(:)
        integer :: i, k, first_key, status_col
        call parse_deck(stem//'.dat', deck_lines, deck, err)
        if (.not. allocated(err)) call case_model(deck, 1, m, label, err)
        if (allocated(err)) then
            err%message = 'the deck in the cases'' JSON summaries: '//err%message
            return
        end if
        template = summary_entries(m, empty, 0.0_dp)
        call split_csv(header, names)
        status_col = 0
        do k = size(names), 1, -1
            if (names(k) == 'status') status_col = k
        end do
        first_key = status_col + 4
        if (status_col == 0 .or. size(names) /= first_key + size(template)) then
            call new_error(err, EXIT_INPUT, 'the shards'' columns are not those of their '// &
                           'deck (a summary of another fricon version?)')
            return
        end if
        allocate (results(size(rows)))
        do i = 1, size(rows)
            call split_csv(rows(i), fields)
            results(i)%name = trim(fields(1))
            results(i)%label = trim(fields(2))
            read (fields(status_col), *, iostat=k) results(i)%status
            results(i)%entries = template
            do k = 1, size(template)
                results(i)%entries(k)%defined = len_trim(fields(first_key + k - 1)) > 0
                if (results(i)%entries(k)%defined) read (fields(first_key + k - 1), *) &
                    results(i)%entries(k)%value
            end do
        end do
    end subroutine rebuilt_results

    !> The comma-separated fields of a CSV line; a field in double quotes (no quotes inside)
    !! may hold commas and loses its quotes.
    pure subroutine split_csv(line, fields)
        character(len=*), intent(in) :: line
        character(len=:), allocatable, intent(out) :: fields(:)
        integer :: k, start, n, pass
        logical :: quoted
        do pass = 1, 2
            n = 0
            start = 1
            quoted = .false.
            do k = 1, len_trim(line) + 1
                if (k <= len_trim(line)) then
                    if (line(k:k) == '"') quoted = .not. quoted
                    if (line(k:k) /= ',' .or. quoted) cycle
                end if
                n = n + 1
                if (pass == 2) fields(n) = unquoted(line(start:k - 1))
                start = k + 1
            end do
            if (pass == 1) allocate (character(len=max(len(line), 1)) :: fields(n))
        end do
    end subroutine split_csv

    !> A CSV field without its double quotes.
    pure function unquoted(field) result(text)
        character(len=*), intent(in) :: field
        character(len=:), allocatable :: text
        text = field
        if (len(text) >= 2) then
            if (text(1:1) == '"' .and. text(len(text):) == '"') text = text(2:len(text) - 1)
        end if
    end function unquoted

    !> The merged summary: the first shard's stamp and header, the rows in case order.
    subroutine write_merged(path, first, rows, err)
        character(len=*), intent(in) :: path
        type(shard_t), intent(in) :: first
        character(len=*), intent(in) :: rows(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: u, i
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') first%stamp
        write (u, '(a)') first%header
        do i = 1, size(rows)
            write (u, '(a)') trim(rows(i))
        end do
        call commit_file(path, u, err)
    end subroutine write_merged
end module shard_merge
