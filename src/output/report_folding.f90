!> The plain-text report fits a printed listing: no line wider than report_width (132)
!! columns. A table too wide is folded into column groups, each repeating the first
!! column (x, t or r) like a printed listing; a line of text too long is wrapped at blanks,
!! its continuation indented under its start. The data files (.dat, .csv) stay one row per
!! station: they are for machines.
module report_folding
    use errors, only: error_t
    use atomic_files, only: open_temporary, commit_file
    use text_files, only: read_lines
    implicit none
    private

    integer, parameter, public :: report_width = 132   !! widest line of the report

    public :: fold_table, fold_report_lines, write_wrapped

contains

    !> A table of n_columns columns, the first `first` characters wide and the others `width`
    !! each, folded into groups of columns that fit report_width with the first column
    !! repeated in each. lines(1:n_header) are the header lines; anything after the last
    !! column of a row (a flag such as ' !T') is repeated at the end of each group's row.
    !! Groups after the first start with a blank line and '(continued, part k of n)'.
    pure function fold_table(lines, n_header, first, width, n_columns) result(folded)
        character(len=*), intent(in) :: lines(:)   !! header lines, then the rows
        integer, intent(in) :: n_header            !! header lines among them
        integer, intent(in) :: first, width        !! characters of column 1; of the others
        integer, intent(in) :: n_columns           !! columns, the first included
        character(len=:), allocatable :: folded(:)
        integer :: flags, per_group, groups, g, i, c1, c2, at, tail_width
        tail_width = 0
        do i = n_header + 1, size(lines)
            tail_width = max(tail_width, len_trim(lines(i)) - first - (n_columns - 1)*width)
        end do
        flags = max(tail_width, 0)
        per_group = max((report_width - first - flags)/width, 1)
        groups = (n_columns - 1 + per_group - 1)/per_group
        if (groups <= 1) then
            folded = lines
            return
        end if
        per_group = (n_columns - 1 + groups - 1)/groups      ! balanced groups
        allocate (character(len=report_width) :: folded(groups*size(lines) + 2*(groups - 1)))
        at = 0
        do g = 1, groups
            if (g > 1) then
                folded(at + 1) = ''
                write (folded(at + 2), '(a,i0,a,i0,a)') '   (continued, part ', g, ' of ', &
                    groups, ')'
                at = at + 2
            end if
            c1 = first + (g - 1)*per_group*width + 1
            c2 = min(first + g*per_group*width, first + (n_columns - 1)*width)
            do i = 1, size(lines)
                folded(at + i) = lines(i)(1:first)//lines(i)(c1:c2)
                if (i > n_header .and. g == 1) folded(at + i) = trim(folded(at + i))// &
                    lines(i)(first + (n_columns - 1)*width + 1:)
            end do
            at = at + size(lines)
        end do
    end function fold_table

    !> Rewrite the report at path with every line longer than report_width wrapped (nothing
    !! is written when none is): at the last blank that fits, the rest on lines indented by
    !! the line's own indent plus four.
    subroutine fold_report_lines(path, err)
        character(len=*), intent(in) :: path              !! the report, written and closed
        type(error_t), allocatable, intent(out) :: err    !! allocated when it cannot be rewritten
        character(len=:), allocatable :: lines(:)
        logical :: ok
        integer :: u, k
        call read_lines(path, lines, ok)
        if (.not. ok) return
        if (all(len_trim(lines) <= report_width)) return
        call open_temporary(path, u, err)
        if (allocated(err)) return
        do k = 1, size(lines)
            call write_wrapped(u, trim(lines(k)))
        end do
        call commit_file(path, u, err)
    end subroutine fold_report_lines

    !> One line, wrapped to report_width at blanks (cut where a word is longer than a line):
    !! the report's writers call it for every line whose length the text decides.
    subroutine write_wrapped(u, line)
        integer, intent(in) :: u                 !! the open report
        character(len=*), intent(in) :: line     !! the line, any length
        character(len=:), allocatable :: rest, indent
        integer :: cut
        if (len(line) <= report_width) then
            write (u, '(a)') line
            return
        end if
        indent = repeat(' ', min(verify(line, ' ') - 1, report_width/2) + 4)
        rest = line
        do while (len(rest) > report_width)
            cut = index(rest(1:report_width + 1), ' ', back=.true.) - 1
            if (cut <= len(indent)) cut = report_width
            write (u, '(a)') trim(rest(1:cut))
            rest = indent//trim(adjustl(rest(cut + 1:)))
        end do
        write (u, '(a)') rest
    end subroutine write_wrapped
end module report_folding
