!> The one sort of the program: short real arrays (integration cuts, the kinks of a Newton ray)
!! in place, and the stable sorting permutation of a list of keys (the deck's errors by line
!! and column).
module sorting
    use kinds, only: dp
    implicit none
    private

    public :: sort_ascending, ascending_order

contains

    !> Insertion sort in place (the arrays are short, often nearly sorted; it runs inside the
    !! assembly of T, so it carries nothing else along).
    pure subroutine sort_ascending(x)
        real(dp), intent(inout) :: x(:)   !! ascending on return
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

    !> The stable permutation that orders keys ascending: keys(order) is sorted, and equal
    !! keys keep their order (minloc gives the first of equal values).
    pure function ascending_order(keys) result(order)
        real(dp), intent(in) :: keys(:)   !! the keys
        integer :: order(size(keys))
        logical :: taken(size(keys))
        integer :: k
        taken = .false.
        do k = 1, size(keys)
            order(k) = minloc(keys, dim=1, mask=.not. taken)
            taken(order(k)) = .true.
        end do
    end function ascending_order
end module sorting
