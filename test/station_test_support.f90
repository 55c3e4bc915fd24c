!> Test access to the station table by column name (through the column table, never by
!! number), in nondimensional units (SPEC §6).
module station_test_support
    use kinds, only: dp
    use model, only: model_t
    use station_results, only: station_table_t
    use station_columns, only: column_t, nondim_columns, column_index
    implicit none
    private
    public :: nd, nd_all

contains

    !> Nondimensional value of column `key` at station i; i = 0 returns the factor alone.
    real(dp) function nd(m, tab, key, i)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        character(len=*), intent(in) :: key
        integer, intent(in) :: i
        type(column_t), allocatable :: cols(:)
        integer :: c
        cols = nondim_columns(m)
        c = column_index(cols, key)
        if (c == 0) error stop 'station_test_support: no such column'
        if (i == 0) then
            nd = cols(c)%scale
        else
            nd = tab%val(cols(c)%quantity, i)*cols(c)%scale
        end if
    end function nd

    !> The whole nondimensional column `key`.
    function nd_all(m, tab, key) result(v)
        type(model_t), intent(in) :: m
        type(station_table_t), intent(in) :: tab
        character(len=*), intent(in) :: key
        real(dp), allocatable :: v(:)
        integer :: i
        v = [(nd(m, tab, key, i), i=1, tab%n)]
    end function nd_all
end module station_test_support
