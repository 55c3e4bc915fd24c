!> A text file read whole into lines (the report folded after writing, the shard summaries
!! and JSON summaries a merge reads).
module text_files
    implicit none
    private

    public :: read_lines, text_lines

contains

    !> Every line of a text file, as long as the longest (ok false if it cannot be read); a
    !! last line without its line feed counts.
    subroutine read_lines(path, lines, ok)
        character(len=*), intent(in) :: path                      !! the file
        character(len=:), allocatable, intent(out) :: lines(:)    !! its lines, blank-padded
        logical, intent(out) :: ok                                !! the file was read
        character(len=:), allocatable :: text
        integer :: u, ios, size_bytes
        ok = .false.
        allocate (character(len=1) :: lines(0))
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=size_bytes)
        allocate (character(len=max(size_bytes, 0)) :: text)
        if (size_bytes > 0) read (u, iostat=ios) text
        close (u)
        if (ios /= 0) return
        if (len(text) > 0) then
            if (text(len(text):) /= achar(10)) text = text//achar(10)
        end if
        call text_lines(text, lines)
        ok = .true.
    end subroutine read_lines

    !> The lines of a text whose lines each end in a line feed.
    pure subroutine text_lines(text, lines)
        character(len=*), intent(in) :: text                      !! lines, each ended by LF
        character(len=:), allocatable, intent(out) :: lines(:)    !! the lines, blank-padded
        integer :: k, start, n, width
        n = 0
        width = 1
        start = 1
        do k = 1, len(text)
            if (text(k:k) /= achar(10)) cycle
            n = n + 1
            width = max(width, k - start)
            start = k + 1
        end do
        allocate (character(len=width) :: lines(n))
        n = 0
        start = 1
        do k = 1, len(text)
            if (text(k:k) /= achar(10)) cycle
            n = n + 1
            lines(n) = text(start:k - 1)
            start = k + 1
        end do
    end subroutine text_lines
end module text_files
