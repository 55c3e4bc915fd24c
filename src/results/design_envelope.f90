!> The envelope of the design values over the cases of a run (the load combinations of a
!! deck, at every sweep point): for each named design value its largest and smallest value
!! and the case that gives each. The design values of a case are one list of named values
!! (name, label, unit, value), built in one place, design_values, from the case's key
!! results (summary_table, themselves read from the design summary); a new kind of design
!! value (a design check's value and utilisation, say) is added there and is enveloped,
!! reported and written with the others.
module design_envelope
    use kinds, only: dp
    use solved_case, only: case_t
    use summary_table, only: entry_t
    use design_checks, only: evaluate_design_checks, check_entries
    implicit none
    private

    !> One named design value of a case.
    type, public :: design_value_t
        character(len=32) :: name = ''      !! key (JSON / CSV name)
        character(len=56) :: label = ''     !! words for the report
        character(len=16) :: unit = ''      !! display unit ('' for a pure number)
        real(dp) :: value = 0.0_dp          !! in that unit
        logical :: defined = .true.         !! false: not applicable in this case
    end type design_value_t

    !> The envelope of one design value.
    type, public :: envelope_row_t
        character(len=32) :: name = ''      !! key
        character(len=56) :: label = ''     !! words
        character(len=16) :: unit = ''      !! display unit
        logical :: defined = .false.        !! defined in some case enveloped
        real(dp) :: max = 0.0_dp, min = 0.0_dp   !! largest and smallest value
        integer :: max_case = 0, min_case = 0    !! the cases that give them (first if tied)
    end type envelope_row_t

    !> The envelope over a run's cases.
    type, public :: envelope_t
        type(envelope_row_t), allocatable :: rows(:)   !! one per design value, in list order
        integer :: cases = 0                           !! cases enveloped
    end type envelope_t

    public :: design_values, values_of_entries, envelope_of

contains

    !> The design values of a solved case: its key results without the positions of
    !! extremes (keys ending in _x), the solver's count and the edge distance (no responses),
    !! then the value and the utilisation of each design check of its CHECK cards
    !! (design_checks::check_entries: `<check>_value`, `<check>_utilisation`).
    pure function design_values(c) result(v)
        type(case_t), intent(in) :: c   !! a solved case
        type(design_value_t), allocatable :: v(:)
        v = values_of_entries([c%entries, check_entries(evaluate_design_checks(c%model, &
                                                                               c%summary))])
    end function design_values

    !> design_values' selection from a case's key results (and its checks' entries).
    pure function values_of_entries(e) result(v)
        type(entry_t), intent(in) :: e(:)   !! key results (summary_table), check entries
        type(design_value_t), allocatable :: v(:)
        integer :: i, n
        allocate (v(0))
        do i = 1, size(e)
            n = len_trim(e(i)%key)
            if (n > 2) then
                if (e(i)%key(n - 1:n) == '_x') cycle
            end if
            if (e(i)%key == 'linear_solves' .or. e(i)%key == 'edge_distance') cycle
            v = [v, design_value_t(name=e(i)%key, label=e(i)%label, unit=e(i)%unit, &
                                   value=e(i)%value, defined=e(i)%defined)]
        end do
    end function values_of_entries

    !> The envelope of the cases' design values: values(:, k) are case k's (every case has
    !! the same list, design_values of one model kind). A value not defined in a case is
    !! left out of that case's comparison.
    pure function envelope_of(values) result(env)
        type(design_value_t), intent(in) :: values(:, :)   !! (design value, case)
        type(envelope_t) :: env
        integer :: r, k
        env%cases = size(values, 2)
        allocate (env%rows(size(values, 1)))
        do r = 1, size(values, 1)
            env%rows(r)%name = values(r, 1)%name
            env%rows(r)%label = values(r, 1)%label
            env%rows(r)%unit = values(r, 1)%unit
            do k = 1, size(values, 2)
                if (values(r, k)%defined) call include(env%rows(r), values(r, k)%value, k)
            end do
        end do
    end function envelope_of

    !> Case k's value into a row.
    pure subroutine include(row, x, k)
        type(envelope_row_t), intent(inout) :: row
        real(dp), intent(in) :: x
        integer, intent(in) :: k
        if (.not. row%defined) then
            row%defined = .true.
            row%max = x
            row%min = x
            row%max_case = k
            row%min_case = k
            return
        end if
        if (x > row%max) then
            row%max = x
            row%max_case = k
        end if
        if (x < row%min) then
            row%min = x
            row%min_case = k
        end if
    end subroutine include
end module design_envelope
