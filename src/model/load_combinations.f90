!> Named load cases and their combinations (LOADCASE and COMBINE cards): which LOAD card
!! belongs to which case, the self-weight of a case, and the factored loads of a combination.
!! A combination is solved as its own nonlinear problem with the loads
!!
!!     F_j(combination k) = factor(case of load j, k) * F_j      (every LOAD card j)
!!     self-weight of case c: factor(c, k) * gamma_c * h * b * l   (beam, a PATCH over the
!!                            whole base) or gamma_c * h * pi a^2  (plate, a PATCH r <= a)
!!
!! never as a superposition of solved cases (contact and friction are nonlinear). Every load
!! of every case is in every combination, with factor 0 where the combination leaves its
!! case out, so that all combinations of a deck share the load positions (LOADS grading and
!! the design table's stations) and so one mesh. Units: the deck's (gamma in F/L^3).
module load_combinations
    use kinds, only: dp, pi
    use foundation_structure, only: structure_t, MODEL_BEAM
    use applied_loads, only: load_t, LOAD_PATCH
    implicit none
    private

    integer, parameter, public :: name_length = 10   !! a card field

    !> One LOADCASE card.
    type, public :: load_case_t
        character(len=name_length) :: name = ''   !! upper case
        real(dp) :: unit_weight = 0.0_dp          !! gamma of the structure [F/L^3]; 0: none
        integer :: line = 0                       !! deck line of the card
    end type load_case_t

    !> One combination (a COMBINE card and its continuations), or a load case alone.
    type, public :: combination_t
        character(len=name_length) :: name = ''   !! upper case, part of the file names
        real(dp), allocatable :: factors(:)       !! per load case; 0: case not combined
        character(len=name_length), allocatable :: factor_texts(:)  !! as written ('' if none)
        integer :: line = 0                       !! deck line of the first card (0: implied)
    end type combination_t

    !> The load cases and combinations of a deck (no LOADCASE card: all empty).
    type, public :: load_set_t
        type(load_case_t), allocatable :: cases(:)            !! in deck order
        integer, allocatable :: load_case(:)                  !! per model load: its case
        type(combination_t), allocatable :: combinations(:)   !! in deck order
    end type load_set_t

    public :: combination_count, combination_loads, self_weight_load, combination_text

contains

    !> Number of combinations solved: 0 for a deck without load cases.
    pure integer function combination_count(set)
        type(load_set_t), intent(in) :: set   !! the deck's load set
        combination_count = 0
        if (allocated(set%combinations)) combination_count = size(set%combinations)
    end function combination_count

    !> The factored loads of combination k: every LOAD card scaled by its case's factor, then
    !! the self-weight of each case with a unit weight (module header).
    pure function combination_loads(set, loads, s, k) result(factored)
        type(load_set_t), intent(in) :: set     !! the deck's load set
        type(load_t), intent(in) :: loads(:)    !! every LOAD card (load_case aligned)
        type(structure_t), intent(in) :: s      !! the structure of the case (its geometry)
        integer, intent(in) :: k                !! combination 1..combination_count
        type(load_t), allocatable :: factored(:)
        real(dp) :: f
        integer :: j, c
        factored = loads
        do j = 1, size(loads)
            f = set%combinations(k)%factors(set%load_case(j))
            factored(j)%fz = f*loads(j)%fz
            factored(j)%fx = f*loads(j)%fx
        end do
        do c = 1, size(set%cases)
            if (set%cases(c)%unit_weight <= 0.0_dp) cycle
            factored = [factored, self_weight_load(s, set%combinations(k)%factors(c)* &
                                                   set%cases(c)%unit_weight, set%cases(c)%line)]
        end do
    end function combination_loads

    !> The weight of the structure of unit weight gamma as a uniform PATCH over the whole
    !! base: gamma h b l on the beam (x from -l/2 to l/2), gamma h pi a^2 on the plate
    !! (r from 0 to a).
    pure function self_weight_load(s, gamma, line) result(ld)
        type(structure_t), intent(in) :: s   !! the structure
        real(dp), intent(in) :: gamma        !! unit weight, factored [F/L^3]
        integer, intent(in) :: line          !! the LOADCASE card's line
        type(load_t) :: ld
        ld%kind = LOAD_PATCH
        ld%line = line
        if (s%kind == MODEL_BEAM) then
            ld%fz = gamma*s%h*s%b*s%length
            ld%x1 = -0.5_dp*s%length
            ld%x2 = 0.5_dp*s%length
        else
            ld%fz = gamma*s%h*pi*s%length**2
            ld%x1 = 0.0_dp
            ld%x2 = s%length
        end if
    end function self_weight_load

    !> 'ULS1 = 1.35 G + 1.5 Q' (the factors as written on the COMBINE cards); a load case
    !! solved alone: its name.
    pure function combination_text(set, k) result(text)
        type(load_set_t), intent(in) :: set   !! the deck's load set
        integer, intent(in) :: k              !! combination 1..combination_count
        character(len=:), allocatable :: text
        character(len=:), allocatable :: terms
        integer :: c
        text = trim(set%combinations(k)%name)
        if (set%combinations(k)%line == 0) return
        terms = ''
        do c = 1, size(set%cases)
            if (len_trim(set%combinations(k)%factor_texts(c)) == 0) cycle
            if (len(terms) > 0) terms = terms//' + '
            terms = terms//trim(adjustl(set%combinations(k)%factor_texts(c)))//' '// &
                    trim(set%cases(c)%name)
        end do
        text = text//' = '//terms
    end function combination_text
end module load_combinations
