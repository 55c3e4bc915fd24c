!> The one sort of the program: short real arrays (integration cuts, the kinks of a Newton ray).
module sorting
    use kinds, only: dp
    implicit none
    private

    public :: sort_ascending

contains

    !> Insertion sort in place (the arrays are short, often nearly sorted).
    pure subroutine sort_ascending(x)
        real(dp), intent(inout) :: x(:)
        real(dp) :: key
        integer :: i, j
        outer: do i = 2, size(x)
            key = x(i)
            j = i - 1
            shift: do while (j >= 1)
                if (x(j) <= key) exit shift
                x(j + 1) = x(j)
                j = j - 1
            end do shift
            x(j + 1) = key
        end do outer
    end subroutine sort_ascending
end module sorting
