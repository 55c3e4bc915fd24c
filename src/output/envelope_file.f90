!> The envelope of a deck's load combinations (design_envelope) in three files beside the
!! combinations' own: STEM_envelope.txt (the report's table), STEM_envelope.json and
!! STEM_envelope.csv (doc/OUTPUT.md). Written only when every combination solved: an
!! envelope without one of them would not be the envelope; otherwise, and when a file
!! cannot be written, none of the three is left (an earlier run's included). The envelope is
!! of the design values as the cases' JSON summaries hold them (json_number's 16 significant
!! digits), so that fricon --merge, which reads them there (case_json_reader), writes the
!! same bytes as a single run.
module envelope_file
    use errors, only: error_t, new_error, EXIT_OK, EXIT_INPUT, EXIT_INTERNAL
    use design_envelope, only: design_value_t, envelope_t, envelope_of
    use case_files, only: case_result_t
    use atomic_files, only: open_temporary, commit_file
    use output_paths, only: remove_output, base_name
    use case_json_reader, only: read_json_number
    use json_text, only: json_string, json_number
    use run_identity, only: program_name, program_version, run_time
    use deck_fields, only: int_text
    implicit none
    private

    character(len=*), parameter :: kinds(3) = ['.txt ', '.json', '.csv ']

    public :: write_envelope_files, remove_envelope_files

contains

    !> STEM_envelope.txt, .json and .csv of the run's cases (results, in case order; their
    !! names STEM_TAG, the governing case named by TAG). No file when a case failed (err
    !! says which) or when a file cannot be written. The files name the deck by its file
    !! name, as the cases' files do.
    subroutine write_envelope_files(out_dir, stem, title, deck_path, deck_id, results, err, &
                                    time)
        character(len=*), intent(in) :: out_dir, stem     !! output folder; the deck's stem
        character(len=*), intent(in) :: title             !! the deck's TITLE
        character(len=*), intent(in) :: deck_path         !! the deck as given
        character(len=*), intent(in) :: deck_id           !! its identity ('' if no file)
        type(case_result_t), intent(in) :: results(:)     !! every case of the run
        type(error_t), allocatable, intent(out) :: err    !! a case failed, or a write
        !> the run time stamped on the files (default: this run's, run_identity)
        character(len=*), intent(in), optional :: time
        type(envelope_t) :: env
        character(len=:), allocatable :: base, tags(:), stamp_time
        base = out_dir//'/'//stem//'_envelope'
        stamp_time = trim(run_time)
        if (present(time)) stamp_time = trim(time)
        call envelope_of_results(results, env, err)
        if (allocated(err)) then
            call remove_envelope_files(out_dir, stem)
            return
        end if
        tags = case_tags(stem, results)
        call write_envelope_csv(base//'.csv', stamp_time, env, tags, err)
        if (.not. allocated(err)) call write_envelope_json(base//'.json', stamp_time, stem, &
                                                           base_name(deck_path), deck_id, &
                                                           title, results, env, tags, err)
        if (.not. allocated(err)) call write_envelope_report(base//'.txt', stamp_time, &
                                                             base_name(deck_path), title, &
                                                             results, env, tags, err)
        if (allocated(err)) call remove_envelope_files(out_dir, stem)
    end subroutine write_envelope_files

    !> The envelope's files and their temporaries.
    subroutine remove_envelope_files(out_dir, stem)
        character(len=*), intent(in) :: out_dir, stem   !! output folder; the deck's stem
        integer :: k
        do k = 1, size(kinds)
            call remove_output(out_dir//'/'//stem//'_envelope'//trim(kinds(k))//'.tmp')
            call remove_output(out_dir//'/'//stem//'_envelope'//trim(kinds(k)))
        end do
    end subroutine remove_envelope_files

    !> The envelope of the cases' design values as their JSON summaries hold them; an error
    !! if a case did not solve.
    subroutine envelope_of_results(results, env, err)
        type(case_result_t), intent(in) :: results(:)
        type(envelope_t), intent(out) :: env
        type(error_t), allocatable, intent(out) :: err
        type(design_value_t), allocatable :: values(:, :)
        integer :: k, n
        do k = 1, size(results)
            if (results(k)%status == EXIT_OK .and. allocated(results(k)%values)) cycle
            call new_error(err, EXIT_INPUT, 'no envelope written: '//results(k)%name// &
                           ' did not solve, and an envelope without it would not be one')
            return
        end do
        n = size(results(1)%values)
        allocate (values(n, size(results)))
        do k = 1, size(results)
            if (size(results(k)%values) /= n) then
                call new_error(err, EXIT_INTERNAL, 'envelope: the cases have different '// &
                               'lists of design values')
                return
            end if
            values(:, k) = as_written(results(k)%values)
        end do
        env = envelope_of(values)
    end subroutine envelope_of_results

    !> A design value as the case's JSON summary holds it (read back from json_number's
    !! text: null, a value not finite, is not defined).
    elemental function as_written(v) result(w)
        type(design_value_t), intent(in) :: v
        type(design_value_t) :: w
        w = v
        if (v%defined) call read_json_number(json_number(v%value, .true.), w%value, w%defined)
    end function as_written

    !> The stamp line's text: 'fricon 0.2.0, run TIME'.
    pure function stamp_of(time) result(text)
        character(len=*), intent(in) :: time
        character(len=:), allocatable :: text
        text = program_name//' '//program_version//', run '//time
    end function stamp_of

    !> The part of each case's name after STEM_: the combination ('ULS1'), after the sweep
    !! point's number in a sweep ('002_ULS1').
    pure function case_tags(stem, results) result(tags)
        character(len=*), intent(in) :: stem
        type(case_result_t), intent(in) :: results(:)
        character(len=:), allocatable :: tags(:)
        integer :: k, width
        width = 1
        do k = 1, size(results)
            width = max(width, len(results(k)%name) - len(stem) - 1)
        end do
        allocate (character(len=width) :: tags(size(results)))
        do k = 1, size(results)
            tags(k) = results(k)%name(min(len(stem) + 2, len(results(k)%name) + 1):)
        end do
    end function case_tags

    !> STEM_envelope.csv: a `#` line, then a column per design value ('key [unit]') and
    !! four rows: max, max_case, min, min_case (blank where not defined in any case).
    subroutine write_envelope_csv(path, time, env, tags, err)
        character(len=*), intent(in) :: path, time
        type(envelope_t), intent(in) :: env
        character(len=*), intent(in) :: tags(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: u, r
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '# '//stamp_of(time)//'; envelope of '//int_text(env%cases)//' cases'
        write (u, '(a)', advance='no') 'envelope'
        do r = 1, size(env%rows)
            write (u, '(a)', advance='no') ','//trim(env%rows(r)%name)//unit_text(env%rows(r)%unit)
        end do
        write (u, '(a)') ''
        call write_csv_values(u, 'max', env, .true.)
        call write_csv_cases(u, 'max_case', env, tags, .true.)
        call write_csv_values(u, 'min', env, .false.)
        call write_csv_cases(u, 'min_case', env, tags, .false.)
        call commit_file(path, u, err)
    end subroutine write_envelope_csv

    subroutine write_csv_values(u, head, env, largest)
        integer, intent(in) :: u
        character(len=*), intent(in) :: head
        type(envelope_t), intent(in) :: env
        logical, intent(in) :: largest
        integer :: r
        write (u, '(a)', advance='no') head
        do r = 1, size(env%rows)
            if (.not. env%rows(r)%defined) then
                write (u, '(a)', advance='no') ','
            else
                write (u, '(",",es15.7)', advance='no') merge(env%rows(r)%max, &
                                                              env%rows(r)%min, largest)
            end if
        end do
        write (u, '(a)') ''
    end subroutine write_csv_values

    subroutine write_csv_cases(u, head, env, tags, largest)
        integer, intent(in) :: u
        character(len=*), intent(in) :: head
        type(envelope_t), intent(in) :: env
        character(len=*), intent(in) :: tags(:)
        logical, intent(in) :: largest
        integer :: r
        write (u, '(a)', advance='no') head
        do r = 1, size(env%rows)
            write (u, '(a)', advance='no') ','//governing(env, r, tags, largest)
        end do
        write (u, '(a)') ''
    end subroutine write_csv_cases

    !> The tag of the case giving the row's max (min); '' when the value is not defined.
    pure function governing(env, r, tags, largest) result(tag)
        type(envelope_t), intent(in) :: env
        integer, intent(in) :: r
        character(len=*), intent(in) :: tags(:)
        logical, intent(in) :: largest
        character(len=:), allocatable :: tag
        tag = ''
        if (.not. env%rows(r)%defined) return
        tag = trim(tags(merge(env%rows(r)%max_case, env%rows(r)%min_case, largest)))
    end function governing

    !> STEM_envelope.json (doc/OUTPUT.md).
    subroutine write_envelope_json(path, time, stem, deck_name, deck_id, title, results, &
                                   env, tags, err)
        character(len=*), intent(in) :: path, time, stem, deck_name, deck_id, title
        type(case_result_t), intent(in) :: results(:)
        type(envelope_t), intent(in) :: env
        character(len=*), intent(in) :: tags(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: u, k, r
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') '{'
        write (u, '(a)') '  "program": '//json_string(program_name)//','
        write (u, '(a)') '  "version": '//json_string(program_version)//','
        write (u, '(a)') '  "run_time": '//json_string(time)//','
        write (u, '(a)') '  "envelope_of": '//json_string(stem)//','
        write (u, '(a)') '  "deck": '//json_string(deck_name)//','
        ! (how a later run of the deck knows this file for its own: output_paths)
        write (u, '(a)') '  "deck_identity": '//json_string(deck_id)//','
        write (u, '(a)') '  "title": '//json_string(trim(title))//','
        write (u, '(a)') '  "cases": ['
        do k = 1, size(results)
            write (u, '(a)') '    {"case": '//json_string(trim(tags(k)))//', "files": '// &
                json_string(results(k)%name)//', "label": '// &
                json_string(after_colon(results(k)%label))//'}'//trim(merge(', ', '  ', &
                k < size(results)))
        end do
        write (u, '(a)') '  ],'
        write (u, '(a)') '  "envelope": {'
        do r = 1, size(env%rows)
            associate (row => env%rows(r))
                write (u, '(a)') '    '//json_string(trim(row%name))//': {"unit": '// &
                    json_string(trim(row%unit))//', "max": '//json_number(row%max, row%defined)// &
                    ', "max_case": '//json_tag(governing(env, r, tags, .true.))// &
                    ', "min": '//json_number(row%min, row%defined)//', "min_case": '// &
                    json_tag(governing(env, r, tags, .false.))//'}'// &
                    trim(merge(', ', '  ', r < size(env%rows)))
            end associate
        end do
        write (u, '(a)') '  }'
        write (u, '(a)') '}'
        call commit_file(path, u, err)
    end subroutine write_envelope_json

    pure function json_tag(tag) result(text)
        character(len=*), intent(in) :: tag
        character(len=:), allocatable :: text
        if (len(tag) == 0) then
            text = 'null'
        else
            text = json_string(tag)
        end if
    end function json_tag

    !> STEM_envelope.txt: the cases and the envelope table.
    subroutine write_envelope_report(path, time, deck_name, title, results, env, tags, err)
        character(len=*), intent(in) :: path, time, deck_name, title
        type(case_result_t), intent(in) :: results(:)
        type(envelope_t), intent(in) :: env
        character(len=*), intent(in) :: tags(:)
        type(error_t), allocatable, intent(out) :: err
        integer :: u, k, r
        character(len=*), parameter :: row_fmt = '(3x,a34,a10,es14.5,a14,es14.5,2x,a)'
        character(len=34) :: name
        character(len=10) :: unit
        character(len=14) :: case_max
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)') repeat('=', 100)
        write (u, '(a)') ' fricon - envelope of the load combinations'
        write (u, '(a)') ' deck: '//deck_name
        write (u, '(a)') ' title: '//trim(title)
        write (u, '(a)') ' '//stamp_of(time)
        write (u, '(a)') repeat('=', 100)
        write (u, '(/,a)') ' 1. CASES (each solved as its own nonlinear problem; files '// &
            'NAME.txt, .csv, .json, ...)'
        do k = 1, size(results)
            write (u, '(3x,a,t20,a)') trim(tags(k)), after_colon(results(k)%label)// &
                '   -> '//results(k)%name//'.txt'
        end do
        write (u, '(/,a)') ' 2. ENVELOPE (largest and smallest value of each design value '// &
            'over the cases, and the case'
        write (u, '(a)') '    that gives it; values are signed: a sagging moment is '// &
            'negative, so its governing value is the min)'
        name = 'design value'
        unit = 'unit'
        case_max = '  case'
        write (u, '(3x,a34,a10,a14,a14,a14,2x,a)') name, unit, '           max', case_max, &
            '           min', 'case'
        do r = 1, size(env%rows)
            associate (row => env%rows(r))
                name = row%name
                unit = row%unit
                if (.not. row%defined) then
                    write (u, '(3x,a34,a10,a)') name, unit, '             -  (not defined '// &
                        'in any case)'
                    cycle
                end if
                case_max = '  '//governing(env, r, tags, .true.)
                write (u, row_fmt) name, unit, row%max, case_max, row%min, &
                    governing(env, r, tags, .false.)
            end associate
        end do
        write (u, '(/,a)') ' Keys, units and definitions: README "Design summary"; the '// &
            'envelope files: doc/OUTPUT.md.'
        call commit_file(path, u, err)
    end subroutine write_envelope_report

    !> 'ULS1 = 1.35 G + 1.5 Q' from 'case 2 of 4: ULS1 = 1.35 G + 1.5 Q'.
    pure function after_colon(label) result(text)
        character(len=*), intent(in) :: label
        character(len=:), allocatable :: text
        text = trim(adjustl(label(index(label, ':') + 1:)))
    end function after_colon

    pure function unit_text(unit) result(text)
        character(len=*), intent(in) :: unit
        character(len=:), allocatable :: text
        text = ''
        if (len_trim(unit) > 0) text = ' ['//trim(unit)//']'
    end function unit_text
end module envelope_file
