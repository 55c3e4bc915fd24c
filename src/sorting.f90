!> The one sort of the program: short real arrays (integration cuts, the kinks of a Newton ray,
!! the deck's errors by line and column), stable, optionally carrying a permutation along.
module sorting
    use kinds, only: dp
    implicit none
    private

    public :: sort_ascending

contains

    !> Stable insertion sort in place (the arrays are short, often nearly sorted); `order`, if
    !! given, is permuted with x (start it at 1, 2, ..., n to get the sorting permutation).
    pure subroutine sort_ascending(x, order)
        real(dp), intent(inout) :: x(:)                !! keys, ascending on return
        integer, intent(inout), optional :: order(:)   !! moved as x is
        real(dp) :: key
        integer :: i, j, item
        item = 0
        outer: do i = 2, size(x)
            key = x(i)
            if (present(order)) item = order(i)
            j = i - 1
            shift: do while (j >= 1)
                if (x(j) <= key) exit shift
                x(j + 1) = x(j)
                if (present(order)) order(j + 1) = order(j)
                j = j - 1
            end do shift
            x(j + 1) = key
            if (present(order)) order(j + 1) = item
        end do outer
    end subroutine sort_ascending
end module sorting
