!> The layers of src/ (doc/ARCHITECTURE.md): scripts/check_layers.py finds no module that uses
!! a module of a later layer, and it does find one in a small tree made to have one (so the
!! check can fail); likewise the thread check and the line length (scripts/check_line_length.py).
module test_architecture
    use harness, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_architecture

contains

    subroutine collect_architecture(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('no_back_edges', test_no_back_edges), &
                 new_unittest('back_edge_found', test_back_edge_found), &
                 new_unittest('threads_call_no_deferred_length_text', test_thread_safety), &
                 new_unittest('deferred_length_call_on_threads_found', test_thread_unsafe_found), &
                 new_unittest('inquire_by_name_in_output_found', test_inquire_found), &
                 new_unittest('lines_at_most_100_characters', test_line_length), &
                 new_unittest('long_line_found', test_long_line_found)]
    end subroutine collect_architecture

    !> The exit status of `python3 scripts/SCRIPT.py`, its output in build/SCRIPT.txt.
    integer function script_status(script) result(status)
        character(len=*), intent(in) :: script   !! e.g. 'check_layers'
        call execute_command_line('python3 scripts/'//script//'.py > build/'//script//'.txt', &
                                  exitstat=status)
    end function script_status

    !> Every .f90 and .c line under src/, app/, test/ and example/ has at most 100 characters
    !! (STYLE.md's limit): exit status 0.
    subroutine test_line_length(err)
        type(error_t), allocatable, intent(out) :: err
        call check(err, script_status('check_line_length') == 0, &
                   'a source line is over 100 characters: see build/check_line_length.txt')
    end subroutine test_line_length

    !> A tree with one line of 101 characters in src/ (and one of 100 with a two-byte '²' in
    !! test/, 101 bytes but 100 characters, which passes): exit status 1, that line named.
    subroutine test_long_line_found(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_line_length'
        integer :: status
        call execute_command_line('rm -rf '//dir)
        call tree_file(dir, 'src/long.f90', &
                       [character(len=101) :: 'module long', '! '//repeat('x', 99), &
                        'end module long'])
        call tree_file(dir, 'test/wide.f90', ['! '//repeat('x', 96)//'m²'])
        status = script_on_tree('check_line_length', dir)
        call check(err, status == 1 .and. count_lines(dir//'.txt') == 2, 'a 101-character '// &
                   'line was not reported, or a 100-character one with a two-byte character was')
        call execute_command_line('rm -rf '//dir//' '//dir//'.txt')
    end subroutine test_long_line_found

    !> Write the lines to dir/rel (its folders made): a file of a tree made to fail a check.
    subroutine tree_file(dir, rel, lines)
        character(len=*), intent(in) :: dir, rel, lines(:)
        integer :: u, k
        k = index(rel, '/', back=.true.)
        call execute_command_line('mkdir -p '//dir//'/'//rel(1:max(k - 1, 0)))
        open (newunit=u, file=dir//'/'//rel, status='replace', action='write')
        write (u, '(a)') (trim(lines(k)), k = 1, size(lines))
        close (u)
    end subroutine tree_file

    !> The exit status of `python3 scripts/SCRIPT.py DIR`, its output in DIR.txt.
    integer function script_on_tree(script, dir) result(status)
        character(len=*), intent(in) :: script, dir
        call execute_command_line('python3 scripts/'//script//'.py '//dir//' > '//dir// &
                                  '.txt', exitstat=status)
    end function script_on_tree

    !> The number of lines of a text file (0 if it cannot be read).
    integer function count_lines(path) result(n)
        character(len=*), intent(in) :: path
        character(len=256) :: line
        integer :: u, ios
        n = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            n = n + 1
        end do
        close (u)
    end function count_lines

    !> The project's own src/: exit status 0 (no back-edge).
    subroutine test_no_back_edges(err)
        type(error_t), allocatable, intent(out) :: err
        call check(err, script_status('check_layers') == 0, &
                   'a module uses a later layer: see build/check_layers.txt')
    end subroutine test_no_back_edges

    !> A tree where a results module uses an output module: exit status 1.
    subroutine test_back_edge_found(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_layers'
        call execute_command_line('rm -rf '//dir)
        call tree_file(dir, 'output/writer.f90', [character(len=20) :: 'module writer', &
                                                  'end module writer'])
        call tree_file(dir, 'results/table.f90', [character(len=20) :: 'module table', &
                                                  '    use writer', 'end module table'])
        call check(err, script_on_tree('check_layers', dir) == 1, &
                   'results using output was not reported as a back-edge')
        call execute_command_line('rm -rf '//dir//' '//dir//'.txt')
    end subroutine test_back_edge_found

    !> The project's own src/: no function with a deferred-length character result is called
    !! from the code that runs on a sweep's threads (gfortran keeps such a result's length in a
    !! static variable: two threads at one call site got an empty JSON key).
    subroutine test_thread_safety(err)
        type(error_t), allocatable, intent(out) :: err
        call check(err, script_status('check_thread_safety') == 0, 'code on threads calls '// &
                   'a deferred-length character function: see build/check_thread_safety.txt')
    end subroutine test_thread_safety

    !> A tree where a results module calls such a function: exit status 1.
    subroutine test_thread_unsafe_found(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_threads'
        call execute_command_line('rm -rf '//dir)
        call tree_file(dir, 'results/table.f90', [character(len=48) :: 'module table', &
            'contains', '    function word() result(t)', &
            '        character(len=:), allocatable :: t', '        t = ''x''', &
            '    end function word', '    subroutine key(k)', &
            '        character(len=8), intent(out) :: k', '        k = word()', &
            '    end subroutine key', 'end module table'])
        call check(err, script_on_tree('check_thread_safety', dir) == 1, &
                   'a call of word() in results/ was not reported')
        call execute_command_line('rm -rf '//dir//' '//dir//'.txt')
    end subroutine test_thread_unsafe_found

    !> A tree whose output/ room asks INQUIRE (FILE=...): exit status 1 (gfortran's INQUIRE by
    !! name waits for every open unit's lock: a sweep's writer waited for another thread's
    !! gnuplot, scripts/check_thread_safety.py).
    subroutine test_inquire_found(err)
        type(error_t), allocatable, intent(out) :: err
        character(len=*), parameter :: dir = 'build/test_inquire'
        call execute_command_line('rm -rf '//dir)
        call tree_file(dir, 'output/files.f90', [character(len=48) :: 'module files', &
            'contains', '    logical function there(p)', &
            '        character(len=*), intent(in) :: p', '        inquire (file=p, exist=there)', &
            '    end function there', 'end module files'])
        call check(err, script_on_tree('check_thread_safety', dir) == 1, &
                   'an INQUIRE by name in output/ was not reported')
        call execute_command_line('rm -rf '//dir//' '//dir//'.txt')
    end subroutine test_inquire_found
end module test_architecture
