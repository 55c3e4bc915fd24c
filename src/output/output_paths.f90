!> Where a run writes, checked before anything is solved: the output folder must be writable,
!! and no output file may be the deck itself (decks and data files may share the extension
!! .dat). POSIX calls (realpath, isatty) through thin bind(c) interfaces; folders are made
!! and listed by file_system, without a shell.
module output_paths
    use iso_c_binding, only: c_char, c_int, c_ptr, c_null_char, c_associated
    use errors, only: error_t, new_error, EXIT_INPUT
    use deck_fields, only: int_text
    use file_system, only: make_folder, writable_folder, folder_entries, delete_file, &
                           size_and_last_byte
    use sha256, only: sha256_hex
    implicit none
    private

    integer, parameter :: path_max = 4096

    !> The endings fricon writes (a case: NAME.ext, NAME_springs.csv and NAME.html; a sweep also
    !! STEM_summary.csv, STEM_sweep.gp, .png and STEM_response.gp, .png).
    character(len=*), parameter :: output_extensions(8) = ['.txt        ', '.dat        ', &
        '.csv        ', '.json       ', '.gp         ', '.png        ', '_springs.csv', &
        '.html       ']

    interface
        ! char *realpath(const char *path, char *resolved_path);
        function c_realpath(path, resolved) bind(c, name='realpath') result(p)
            import :: c_char, c_ptr
            character(kind=c_char), intent(in) :: path(*)
            character(kind=c_char), intent(out) :: resolved(*)
            type(c_ptr) :: p
        end function c_realpath
        ! int isatty(int fd);
        function c_isatty(fd) bind(c, name='isatty') result(yes)
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: yes
        end function c_isatty
    end interface

    public :: prepare_output_dir, check_deck_not_overwritten, stderr_is_terminal
    public :: case_name, case_number, writes_file, output_files, base_name, check_decks_apart
    public :: remove_stale_outputs, remove_output, canonical_path, looks_like_output
    public :: remove_shard_summaries, remove_sweep_outputs, deck_identity

contains

    !> Create the folder (and its parents) and check that files can be created in it (stat
    !! and access(2): no probe file); an error (exit status 1) names the folder and the reason.
    subroutine prepare_output_dir(dir, err)
        character(len=*), intent(in) :: dir              !! the output folder
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        character(len=:), allocatable :: why
        logical :: made, writable
        ! (the figures' gnuplot command line quotes the folder: these characters would break it)
        if (scan(dir, '''"`$\') > 0) then
            call new_error(err, EXIT_INPUT, 'output folder '''//dir//''': quotes, backquotes, '// &
                           '$ and \ are not allowed in its name')
            return
        end if
        call make_folder(dir, made)        ! when it fails, the check below says why
        call writable_folder(dir, writable, why)
        if (.not. writable) then
            call new_error(err, EXIT_INPUT, 'cannot write to the output folder '//dir//': '// &
                           why//' (is it a file, or read-only?)')
            return
        end if
    end subroutine prepare_output_dir

    !> Refuse (exit status 1) when an output of the deck would be the deck itself: the deck
    !! lies in the output folder and is named like one of the files its n cases write
    !! (writes_file).
    subroutine check_deck_not_overwritten(deck_path, dir, stem, n, err, tags)
        !> the deck's path; the output folder; the deck's file stem
        character(len=*), intent(in) :: deck_path, dir, stem
        integer, intent(in) :: n                 !! cases of the deck
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        !> the deck's load combinations (writes_file)
        character(len=*), intent(in), optional :: tags(:)
        character(len=:), allocatable :: deck_real, dir_real
        deck_real = canonical_path(deck_path)
        dir_real = canonical_path(dir)
        if (len(deck_real) == 0 .or. len(dir_real) == 0) return
        if (deck_real(1:len(deck_real) - len(base_name(deck_real))) /= dir_real//'/') return
        if (.not. writes_file(stem, n, base_name(deck_real), tags)) return
        call new_error(err, EXIT_INPUT, 'the deck '//deck_path//' lies in the output folder '// &
            dir//' and would be overwritten by one of its own outputs: give another folder '// &
            '(-o DIR) or rename the deck (decks are not overwritten)')
    end subroutine check_deck_not_overwritten

    !> Refuse (exit status 1) a run of several decks in which one deck would write a file that
    !! another writes (two decks named alike, or a sweep's STEM_001 beside a deck of that
    !! name) or would overwrite another deck of the run. Deck k has the path paths(k), writes
    !! into dirs(k), has the file stem stems(k) and counts(k) cases (0: unreadable, writes
    !! nothing), and the load combinations tags(1:tag_counts(k), k) (none when absent).
    subroutine check_decks_apart(paths, dirs, stems, counts, err, tags, tag_counts)
        !> per deck: its path, output folder, file stem
        character(len=*), intent(in) :: paths(:), dirs(:), stems(:)
        integer, intent(in) :: counts(:)                 !! per deck: its cases (0: unreadable)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        !> (combination, deck): the names of each deck's load combinations
        character(len=*), intent(in), optional :: tags(:, :)
        integer, intent(in), optional :: tag_counts(:)   !! per deck: its combinations
        character(len=:), allocatable :: files(:), deck_real, dir_real, tags_i(:)
        integer :: i, j, k
        do i = 1, size(paths)
            if (counts(i) < 1) cycle
            tags_i = tags_of(i, tags, tag_counts)
            dir_real = canonical_path(trim(dirs(i)))
            do j = 1, size(paths)
                if (j == i) cycle
                ! deck j overwritten by an output of deck i
                deck_real = canonical_path(trim(paths(j)))
                if (len(deck_real) > 0 .and. len(dir_real) > 0) then
                    if (deck_real == dir_real//'/'//base_name(deck_real) .and. &
                        writes_file(trim(stems(i)), counts(i), base_name(deck_real), tags_i)) then
                        call new_error(err, EXIT_INPUT, 'the deck '//trim(paths(j))// &
                            ' would be overwritten by an output of '//trim(paths(i))// &
                            ': run them with different -o folders, or rename one '// &
                            '(decks are not overwritten)')
                        return
                    end if
                end if
                ! the same file written by both
                if (j < i .or. counts(j) < 1) cycle
                if (.not. same_folder(trim(dirs(i)), trim(dirs(j)))) cycle
                files = output_files(trim(stems(j)), counts(j), tags_of(j, tags, tag_counts))
                do k = 1, size(files)
                    if (.not. writes_file(trim(stems(i)), counts(i), trim(files(k)), tags_i)) cycle
                    call new_error(err, EXIT_INPUT, 'the decks '//trim(paths(i))//' and '// &
                        trim(paths(j))//' would both write '//trim(dirs(i))//'/'// &
                        trim(files(k))//': run them with different -o folders')
                    return
                end do
            end do
        end do
    end subroutine check_decks_apart

    !> Deck k's load combinations, tags(1:tag_counts(k), k) (none without tags).
    pure function tags_of(k, tags, tag_counts) result(t)
        integer, intent(in) :: k
        character(len=*), intent(in), optional :: tags(:, :)
        integer, intent(in), optional :: tag_counts(:)
        character(len=:), allocatable :: t(:)
        if (present(tags) .and. present(tag_counts)) then
            allocate (character(len=len(tags)) :: t(tag_counts(k)))
            t = tags(1:tag_counts(k), k)
        else
            allocate (character(len=1) :: t(0))
        end if
    end function tags_of

    !> Remove what an earlier run of the same deck left in dir that this run does not write
    !! (n cases; n = 0 for a deck with input errors, which writes nothing): the files of a
    !! case STEM.* or STEM_NNN.* (NNN: 3 to 9 digits, not all zero) whose JSON summary records
    !! this deck's identity (`"deck_identity"`, deck_identity: nothing another deck wrote is
    !! touched, whatever folder it was run from), and a sweep's STEM_summary*.csv and
    !! STEM_sweep.* when
    !! such a case of a sweep was removed and this run is no sweep. So are the files of any
    !! other STEM_NAME.json recording this deck that this run does not write (a load
    !! combination's, STEM_envelope.*: tags are this run's load combinations, writes_file).
    !! Only files that look like
    !! fricon's outputs are deleted (remove_output): never a deck. The cases are found in one
    !! listing of the folder (its STEM_*.json), so the cost does not grow with what else the
    !! folder holds.
    subroutine remove_stale_outputs(dir, stem, n, deck_path, tags)
        !> the output folder; the deck's file stem; the deck's path
        character(len=*), intent(in) :: dir, stem, deck_path
        integer, intent(in) :: n   !! cases this run writes (0: none)
        !> the deck's load combinations (writes_file)
        character(len=*), intent(in), optional :: tags(:)
        character(len=:), allocatable :: deck_real, group, summaries(:)
        logical :: swept, listed
        integer :: k
        deck_real = canonical_path(deck_path)
        if (len(deck_real) == 0) return          ! no deck file: nothing can be proven its own
        if (n /= 1 .or. tagged(tags)) call remove_group(dir//'/'//stem, deck_real)
        call folder_entries(dir, stem//'_', '.json', summaries, listed)
        if (.not. listed) return                 ! no folder, or one that cannot be listed
        swept = .false.
        cases: do k = 1, size(summaries)
            group = trim(summaries(k))
            group = group(1:len(group) - len('.json'))
            if (writes_file(stem, n, group//'.txt', tags)) cycle cases   ! this run's own case
            if (.not. names_deck(dir//'/'//group//'.json', deck_real)) cycle cases
            call remove_group(dir//'/'//group, deck_real)
            swept = .true.
        end do cases
        if (.not. swept .or. n > 1) return
        call remove_sweep_outputs(dir, stem, '')
        call remove_shard_summaries(dir, stem, 0)
    end subroutine remove_stale_outputs

    !> The shards' summaries STEM_summary.shard-I-of-N.csv (--shard I/N: 1 <= I <= N, N from
    !! 2 to 64) of every N but keep_n (0: all), an earlier split into another number of
    !! shards; found in one listing of the folder.
    subroutine remove_shard_summaries(dir, stem, keep_n)
        character(len=*), intent(in) :: dir, stem   !! the output folder; the deck's file stem
        integer, intent(in) :: keep_n               !! shards of this run (0: none)
        character(len=*), parameter :: prefix = '_summary.shard-'
        character(len=:), allocatable :: names(:), split
        logical :: listed
        integer :: k, i, count, ios_i, ios_n, at
        call folder_entries(dir, stem//prefix, '.csv', names, listed)
        shards: do k = 1, size(names)
            split = trim(names(k))                ! I-of-N, between the prefix and .csv
            split = split(len(stem) + len(prefix) + 1:len(split) - len('.csv'))
            at = index(split, '-of-')
            if (at < 2 .or. verify(split, '0123456789-of') /= 0) cycle shards
            read (split(1:at - 1), *, iostat=ios_i) i
            read (split(at + 4:), *, iostat=ios_n) count
            if (ios_i /= 0 .or. ios_n /= 0) cycle shards
            if (count < 2 .or. count > 64 .or. count == keep_n .or. i < 1 .or. i > count) &
                cycle shards
            ! the very name that --shard I/N writes (no leading zeros)
            if (split /= int_text(i)//'-of-'//int_text(count)) cycle shards
            call remove_output(dir//'/'//trim(names(k)))
        end do shards
    end subroutine remove_shard_summaries

    !> A sweep's summary STEM_summary<shard>.csv and, unsharded (shard ''), its overlay
    !! script and figure, with their .tmp.
    subroutine remove_sweep_outputs(dir, stem, shard)
        character(len=*), intent(in) :: dir, stem  !! the output folder; the deck's file stem
        character(len=*), intent(in) :: shard      !! '' or '.shard-I-of-N'
        integer :: k
        character(len=*), parameter :: tails(4) = ['_sweep.gp    ', '_sweep.png   ', &
                                                   '_response.gp ', '_response.png']
        call remove_output(dir//'/'//stem//'_summary'//shard//'.csv.tmp')
        call remove_output(dir//'/'//stem//'_summary'//shard//'.csv')
        if (len(shard) > 0) return
        do k = 1, size(tails)
            call remove_output(dir//'/'//stem//trim(tails(k))//'.tmp')
            call remove_output(dir//'/'//stem//trim(tails(k)))
        end do
    end subroutine remove_sweep_outputs

    !> The files of one case, base.ext for every output extension and their .tmp, if its JSON
    !! summary records the deck (deck_real: its canonical path).
    subroutine remove_group(base, deck_real)
        character(len=*), intent(in) :: base, deck_real
        integer :: k
        if (.not. names_deck(base//'.json', deck_real)) return
        do k = 1, size(output_extensions)
            call remove_output(base//trim(output_extensions(k))//'.tmp')
            if (trim(output_extensions(k)) == '.json') cycle
            call remove_output(base//trim(output_extensions(k)))
        end do
        call remove_output(base//'.json')   ! last: it is the proof of provenance
    end subroutine remove_group

    !> Delete path if it exists and looks like a file fricon writes, by its first bytes and
    !! its extension (a .tmp by the extension before it): a report starts with '=', a data
    !! file or figure script with '#', a JSON summary with '{', a station CSV has a 'key
    !! [unit]' header and a sweep summary starts with 'case,', a figure is a PNG, a record
    !! starts with '<!DOCTYPE html>'. A deck
    !! starts with none of these (a card name, or a comment '*', '$' or 'C '), so no deck
    !! given an output's name is ever deleted.
    subroutine remove_output(path)
        character(len=*), intent(in) :: path   !! a file
        integer :: size_bytes, last
        ! nothing there, or a folder (size -1): nothing to remove. (Not by a failing Fortran
        ! open: gfortran formats its message and loads the locale's files for each one)
        call size_and_last_byte(path, size_bytes, last)
        if (size_bytes < 0) return
        if (.not. looks_like_output(path)) return
        call delete_file(path)
    end subroutine remove_output

    !> See remove_output.
    logical function looks_like_output(path)
        character(len=*), intent(in) :: path   !! a file
        character(len=:), allocatable :: name
        character(len=200) :: head
        integer :: u, ios, n
        looks_like_output = .false.
        name = path
        if (len(name) > 4) then
            if (name(len(name) - 3:) == '.tmp') name = name(1:len(name) - 4)
        end if
        head = ''
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        read (u, iostat=ios) head
        close (u)
        ! (gfortran opens a folder; reading it fails: no output. The end of a shorter file is
        ! no failure)
        if (ios > 0) return
        n = index(head, achar(10)) - 1
        if (n < 0) n = len_trim(head)
        if (len_trim(head) == 0) then
            looks_like_output = .true.            ! an empty file (a cut-off write): nobody's deck
            return
        end if
        if (ends_with(name, '.txt')) then
            looks_like_output = head(1:1) == '='
        else if (ends_with(name, '.dat') .or. ends_with(name, '.gp')) then
            looks_like_output = head(1:1) == '#'
        else if (ends_with(name, '.json')) then
            looks_like_output = head(1:1) == '{'
        else if (ends_with(name, '.csv')) then
            looks_like_output = head(1:5) == 'case,' .or. index(head(1:max(n, 1)), ' [') > 0 &
                                .or. head(1:9) == '# fricon '
        else if (ends_with(name, '.png')) then
            looks_like_output = head(1:4) == achar(137)//'PNG'
        else if (ends_with(name, '.html')) then
            looks_like_output = head(1:15) == '<!DOCTYPE html>'
        end if
    end function looks_like_output

    pure logical function ends_with(text, tail)
        character(len=*), intent(in) :: text, tail
        ends_with = len(text) >= len(tail)
        if (ends_with) ends_with = text(len(text) - len(tail) + 1:) == tail
    end function ends_with

    !> Whether the JSON summary at path was written for the deck of canonical path deck_real:
    !! its "deck_identity" is deck_identity(deck_real), or (a summary of fricon 0.2.0 and
    !! earlier) its "deck_file" is deck_real (JSON escapes of quotes and backslashes undone).
    logical function names_deck(path, deck_real)
        character(len=*), intent(in) :: path, deck_real
        character(len=8192) :: line
        character(len=:), allocatable :: given
        integer :: u, ios, k, size_bytes, last
        names_deck = .false.
        if (len(deck_real) == 0) return
        call size_and_last_byte(path, size_bytes, last)   ! (see remove_output)
        if (size_bytes < 0) return
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            k = index(line, '"deck_identity": "')
            if (k > 0) then
                names_deck = line(k + 18:) == deck_identity(deck_real)//'",'
                exit
            end if
            k = index(line, '"deck_file": "')
            if (k == 0) cycle
            given = line(k + 14:)
            k = index(given, '"', back=.true.)
            if (k >= 1) names_deck = json_unescaped(given(1:k - 1)) == deck_real
            exit
        end do
        close (u)
    end function names_deck

    !> What a JSON summary records of the deck it was written for: 'sha256:' and the SHA-256
    !! of the deck's canonical path (no machine path in the outputs, yet two decks of one
    !! name in two folders are told apart); '' for no deck file.
    pure function deck_identity(deck_real) result(identity)
        character(len=*), intent(in) :: deck_real   !! the deck's canonical path, or ''
        character(len=:), allocatable :: identity
        identity = ''
        if (len(deck_real) > 0) identity = 'sha256:'//sha256_hex(deck_real)
    end function deck_identity

    !> A JSON string's text with \" and \\ (the escapes a path can need) undone.
    pure function json_unescaped(text) result(plain)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: plain
        integer :: i
        plain = ''
        i = 1
        do while (i <= len(text))
            if (text(i:i) == '\' .and. i < len(text)) i = i + 1
            plain = plain//text(i:i)
            i = i + 1
        end do
    end function json_unescaped

    !> i with leading zeros in width digits.
    pure function padded(i, width) result(text)
        integer, intent(in) :: i, width
        character(len=:), allocatable :: text
        character(len=12) :: fmt, buf
        write (fmt, '(a,i0,a,i0,a)') '(i', width, '.', width, ')'
        write (buf, fmt) i
        text = trim(buf)
    end function padded

    !> Two spellings of one folder: the same canonical path where both exist, else the same
    !! text once './' steps, doubled and trailing slashes are dropped.
    logical function same_folder(a, b)
        character(len=*), intent(in) :: a, b
        character(len=:), allocatable :: ra, rb
        ra = canonical_path(a)
        rb = canonical_path(b)
        if (len(ra) > 0 .and. len(rb) > 0) then
            same_folder = ra == rb
        else
            same_folder = tidy_folder(a) == tidy_folder(b)
        end if
    end function same_folder

    pure function tidy_folder(dir) result(t)
        character(len=*), intent(in) :: dir
        character(len=:), allocatable :: t
        integer :: k
        t = trim(dir)//'/'
        do
            k = index(t, '/./')
            if (k == 0) exit
            t = t(1:k)//t(k + 3:)
        end do
        do
            k = index(t, '//')
            if (k == 0) exit
            t = t(1:k)//t(k + 2:)
        end do
        if (len(t) > 2) then
            if (t(1:2) == './') t = t(3:)
        end if
        if (len(t) > 1) t = t(1:len(t) - 1)
    end function tidy_folder

    !> Whether `file` (a name without its folder) is one of the outputs of a deck of file
    !! stem `stem` with n cases: STEM.ext for one case; for a sweep STEM_NNN.ext (NNN a case
    !! number, case_number) and STEM_summary.csv, STEM_sweep.gp, STEM_sweep.png,
    !! STEM_response.gp, STEM_response.png; ext one of
    !! output_extensions, or that with .tmp (written first, then renamed).
    pure logical function writes_file(stem, n, file, tags)
        !> the deck's file stem; a file name without its folder
        character(len=*), intent(in) :: stem, file
        integer, intent(in) :: n   !! the deck's cases
        !> the deck's load combinations: the cases are named by them (case_name), and
        !! STEM_envelope.txt, .json and .csv are written too
        character(len=*), intent(in), optional :: tags(:)
        character(len=:), allocatable :: name, digits
        integer :: k, i, ios, n_ext
        writes_file = .false.
        name = file
        if (len(name) > 4) then
            if (name(len(name) - 3:) == '.tmp') name = name(1:len(name) - 4)
        end if
        if (n > 1) then
            writes_file = name == stem//'_summary.csv' .or. name == stem//'_sweep.gp' .or. &
                          name == stem//'_sweep.png' .or. name == stem//'_response.gp' .or. &
                          name == stem//'_response.png'
            ! a shard's summary, STEM_summary.shard-I-of-N.csv (--shard I/N)
            if (len(name) > len(stem) + 19) writes_file = writes_file .or. &
                (name(1:len(stem) + 15) == stem//'_summary.shard-' .and. ends_with(name, '.csv'))
            if (writes_file) return
        end if
        if (tagged(tags)) then
            writes_file = tagged_output(stem, n, name, tags)
            return
        end if
        do k = 1, size(output_extensions)
            n_ext = len_trim(output_extensions(k))
            if (len(name) <= n_ext) cycle
            if (name(len(name) - n_ext + 1:) /= output_extensions(k)(1:n_ext)) cycle
            if (n <= 1) then
                writes_file = name == stem//output_extensions(k)(1:n_ext)
            else if (len(name) > len(stem) + 1 + n_ext) then
                if (name(1:len(stem) + 1) /= stem//'_') cycle
                digits = name(len(stem) + 2:len(name) - n_ext)
                if (len(digits) /= len(case_number(n, n))) cycle
                if (verify(digits, '0123456789') /= 0) cycle
                read (digits, *, iostat=ios) i
                writes_file = ios == 0 .and. i >= 1 .and. i <= n
            end if
            if (writes_file) return
        end do
    end function writes_file

    !> The names of every file the n cases of a deck of file stem `stem` write (writes_file).
    pure function output_files(stem, n, tags) result(files)
        character(len=*), intent(in) :: stem   !! the deck's file stem
        integer, intent(in) :: n               !! the deck's cases
        !> the deck's load combinations (case_name; and the envelope's files)
        character(len=*), intent(in), optional :: tags(:)
        character(len=:), allocatable :: files(:)
        integer :: i, k, width, n_envelope
        width = len(stem) + 1 + len(case_number(n, n)) + maxval(len_trim(output_extensions))
        width = max(width, len(stem) + len('_response.png'))
        n_envelope = 0
        if (tagged(tags)) then
            width = width + 1 + len(tags)
            n_envelope = 3
        end if
        allocate (character(len=width) :: files(size(output_extensions)*n + merge(5, 0, n > 1) &
                                                + n_envelope))
        do i = 1, n
            do k = 1, size(output_extensions)
                files(size(output_extensions)*(i - 1) + k) = case_name(stem, i, n, tags)// &
                                                               trim(output_extensions(k))
            end do
        end do
        if (n > 1) files(size(output_extensions)*n + 1:size(output_extensions)*n + 5) = &
            [character(len=width) :: stem//'_summary.csv', stem//'_sweep.gp', &
             stem//'_sweep.png', stem//'_response.gp', stem//'_response.png']
        if (n_envelope > 0) files(size(files) - 2:) = [character(len=width) :: &
            stem//'_envelope.txt', stem//'_envelope.json', stem//'_envelope.csv']
    end function output_files

    !> STEM, or STEM_NNN for case i of a sweep of n (at least three digits); with load
    !! combinations (tags, the fastest-varying index of the cases) STEM_TAG, or STEM_NNN_TAG
    !! with NNN the sweep point.
    pure function case_name(stem, i, n, tags) result(name)
        character(len=*), intent(in) :: stem   !! the deck's file stem
        integer, intent(in) :: i, n            !! case number; cases of the sweep
        !> the names of the deck's load combinations (none: no LOADCASE cards)
        character(len=*), intent(in), optional :: tags(:)
        character(len=:), allocatable :: name
        integer :: n_tags, points
        name = stem
        if (tagged(tags)) then
            n_tags = size(tags)
            points = max(1, n/n_tags)
            if (points > 1) name = stem//'_'//case_number((i - 1)/n_tags + 1, points)
            name = name//'_'//trim(tags(mod(i - 1, n_tags) + 1))
        else if (n > 1) then
            name = stem//'_'//case_number(i, n)
        end if
    end function case_name

    !> Load combinations given (tags present and not empty).
    pure logical function tagged(tags)
        character(len=*), intent(in), optional :: tags(:)   !! combination names
        tagged = .false.
        if (present(tags)) tagged = size(tags) > 0
    end function tagged

    !> name (no folder, no .tmp) is a file of a deck with load combinations: a case's
    !! (case_name with an output extension) or STEM_envelope.txt, .json or .csv.
    pure logical function tagged_output(stem, n, name, tags)
        character(len=*), intent(in) :: stem, name
        integer, intent(in) :: n
        character(len=*), intent(in) :: tags(:)
        integer :: i, k
        tagged_output = name == stem//'_envelope.txt' .or. name == stem//'_envelope.json' .or. &
                        name == stem//'_envelope.csv'
        if (tagged_output) return
        do i = 1, n
            do k = 1, size(output_extensions)
                tagged_output = name == case_name(stem, i, n, tags)//trim(output_extensions(k))
                if (tagged_output) return
            end do
        end do
    end function tagged_output

    !> i with leading zeros, as wide as n and at least three digits (001, 0042 of 1000).
    pure function case_number(i, n) result(text)
        integer, intent(in) :: i, n   !! case number; cases of the sweep
        character(len=:), allocatable :: text
        integer :: width
        width = 3
        do while (10**width <= n .and. width < 9)
            width = width + 1
        end do
        text = padded(i, width)
    end function case_number

    !> The last component of a path.
    pure function base_name(path) result(name)
        character(len=*), intent(in) :: path   !! a path
        character(len=:), allocatable :: name
        name = trim(path(index(path, '/', back=.true.) + 1:))
    end function base_name

    !> The canonical absolute path of an existing file or folder; '' if it cannot be resolved
    !! (a JSON summary records its hash: deck_identity).
    function canonical_path(path) result(resolved)
        character(len=*), intent(in) :: path   !! a path
        character(len=:), allocatable :: resolved
        character(kind=c_char) :: buffer(path_max)
        integer :: n
        buffer = c_null_char
        resolved = ''
        if (.not. c_associated(c_realpath(path//c_null_char, buffer))) return
        n = 0
        do while (n < path_max)
            if (buffer(n + 1) == c_null_char) exit
            n = n + 1
        end do
        resolved = repeat(' ', n)
        do n = 1, len(resolved)
            resolved(n:n) = buffer(n)
        end do
    end function canonical_path

    !> Standard error (file descriptor 2) is a terminal: progress is shown by default.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(2_c_int) == 1
    end function stderr_is_terminal
end module output_paths
