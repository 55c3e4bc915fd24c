!> The LOADCASE and COMBINE cards (README "Load cases and combinations"): named load cases,
!! each the LOAD cards that follow its LOADCASE card, and the combinations of them with a
!! factor per case. Every error is a deck error at line and columns, like any other card's.
!!
!!     *...+....1....+....2....+....3....+....4....+....5....+....6....+....7....+....8
!!     LOADCASE  G         25.0
!!     LOAD      PATCH     1200.0              -3.7      -3.3
!!     LOADCASE  Q
!!     LOAD      PATCH     400.0               -3.7      -3.3
!!     LOADCASE  W
!!     LOAD      POINT               60.0      0.0
!!     COMBINE   ULS1      G         1.35      Q         1.5       W         0.9
!!     COMBINE   SLS       G         1.0       Q         1.0
!!     COMBINE   SLS       W         0.6
!!
!! LOADCASE name gamma: f1 the case's name, f2 (optional) the unit weight of the structure
!! (force/length^3), whose weight gamma h b l (plate gamma h pi a^2) then acts with the case
!! as a uniform load over the whole base. COMBINE name case factor case factor case factor:
!! up to three pairs a card; a COMBINE card right after one of the same name continues it.
!! Without COMBINE cards each load case is solved alone (factor 1). Names are one word of
!! letters, digits, _ and -, starting with a letter (they become part of file names).
module deck_combinations
    use kinds, only: dp
    use load_combinations, only: load_set_t, load_case_t, combination_t, name_length
    use deck_fields, only: field_width, field_first_column, field_text, read_real_field, &
                           read_word_field, FIELD_BLANK, FIELD_OK, add_diagnostic, diagnostics_t, &
                           int_text, max_fields, name_width, number_problem
    implicit none
    private

    !> A COMBINE pair whose case name is looked up once every LOADCASE card is read.
    type :: case_reference_t
        integer :: combination = 0                  !! index in the set's combinations
        character(len=name_length) :: name = ''     !! the case named
        character(len=name_length) :: factor = ''   !! the factor as written
        real(dp) :: value = 0.0_dp                  !! the factor
        integer :: line = 0, field = 0              !! where the name is
        character(len=:), allocatable :: echo       !! the card
    end type case_reference_t

    !> What the reader gathers from these cards while it reads the deck.
    type, public :: combination_cards_t
        type(load_set_t) :: set                        !! the result
        integer :: open_case = 0                       !! the LOADCASE the next LOAD is in
        integer :: load_case = 0                       !! case of the LOAD card being read
        integer, allocatable :: cards_per_case(:)      !! LOAD cards seen per case
        character(len=80), allocatable :: case_echoes(:)         !! each LOADCASE card
        character(len=80), allocatable :: combination_echoes(:)  !! each first COMBINE card
        type(case_reference_t), allocatable :: references(:)
        logical :: pair_error = .false.                !! a COMBINE pair could not be read
        integer :: combine_line = 0                    !! first COMBINE card's line
        character(len=:), allocatable :: combine_echo  !! and its text
    end type combination_cards_t

    character(len=*), parameter :: letters = 'ABCDEFGHIJKLMNOPQRSTUVWXYZ'
    character(len=*), parameter :: reserved(4) = [character(len=8) :: 'SUMMARY', 'SWEEP', &
                                                  'RESPONSE', 'ENVELOPE']

    public :: read_loadcase_card, read_combine_card, note_load_card, accept_load_card
    public :: finish_load_set

contains

    !> LOADCASE name [gamma]: opens a load case.
    subroutine read_loadcase_card(cc, line, text, diag)
        type(combination_cards_t), intent(inout) :: cc   !! the cards so far
        integer, intent(in) :: line                      !! deck line
        character(len=*), intent(in) :: text             !! the card
        type(diagnostics_t), intent(inout) :: diag       !! input errors
        type(load_case_t) :: lc
        integer :: s, c
        if (.not. allocated(cc%set%cases)) allocate (cc%set%cases(0), cc%cards_per_case(0), &
                                                     cc%case_echoes(0))
        lc%line = line
        call take_name(line, text, 1, 'LOADCASE name (of the load case)', lc%name, diag)
        do c = 1, size(cc%set%cases)
            if (lc%name == cc%set%cases(c)%name .and. len_trim(lc%name) > 0) &
                call error_at(diag, line, text, 1, 'duplicate load case name '''// &
                    trim(lc%name)//''' (first given at line '//int_text(cc%set%cases(c)%line)//')')
        end do
        call read_real_field(field_text(text, 2), lc%unit_weight, s)
        if (s == FIELD_BLANK) then
            lc%unit_weight = 0.0_dp
        else if (s /= FIELD_OK) then
            call error_at(diag, line, text, 2, 'LOADCASE gamma (unit weight of the '// &
                'structure, force/length^3), positive or blank: '// &
                number_problem(s, trim(adjustl(field_text(text, 2)))))
            lc%unit_weight = 0.0_dp
        else if (lc%unit_weight <= 0.0_dp) then
            call error_at(diag, line, text, 2, 'LOADCASE gamma (unit weight of the '// &
                'structure, force/length^3) must be a positive number or blank, got '''// &
                trim(adjustl(field_text(text, 2)))//'''')
            lc%unit_weight = 0.0_dp
        end if
        call check_blank_after(diag, line, text, 2, 'LOADCASE')
        cc%set%cases = [cc%set%cases, lc]
        cc%cards_per_case = [cc%cards_per_case, 0]
        cc%case_echoes = [character(len=80) :: cc%case_echoes, text]
        cc%open_case = size(cc%set%cases)
    end subroutine read_loadcase_card

    !> COMBINE name case factor ...: a new combination, or more of the one on the card
    !! before (continued: the previous card is a COMBINE).
    subroutine read_combine_card(cc, line, text, continued, diag)
        type(combination_cards_t), intent(inout) :: cc   !! the cards so far
        integer, intent(in) :: line                      !! deck line
        character(len=*), intent(in) :: text             !! the card
        logical, intent(in) :: continued                 !! the previous card is a COMBINE
        type(diagnostics_t), intent(inout) :: diag       !! input errors
        character(len=name_length) :: name
        integer :: k, j
        if (.not. allocated(cc%set%combinations)) allocate (cc%set%combinations(0), &
                                                            cc%references(0), &
                                                            cc%combination_echoes(0))
        if (cc%combine_line == 0) then
            cc%combine_line = line
            cc%combine_echo = trim(text)
        end if
        call take_name(line, text, 1, 'COMBINE name (of the combination)', name, diag)
        k = size(cc%set%combinations)
        if (.not. (continued .and. k > 0 .and. len_trim(name) > 0)) then
            k = 0
        else if (cc%set%combinations(k)%name /= name) then
            k = 0
        end if
        if (k == 0) then
            call check_new_combination(cc, name, line, text, diag)
            cc%set%combinations = [cc%set%combinations, combination_t(name=name, line=line)]
            cc%combination_echoes = [character(len=80) :: cc%combination_echoes, text]
            k = size(cc%set%combinations)
        end if
        do j = 2, max_fields - 1, 2
            call read_pair(cc, k, line, text, j, diag)
        end do
    end subroutine read_combine_card

    !> A new combination's name is not one given before.
    subroutine check_new_combination(cc, name, line, text, diag)
        type(combination_cards_t), intent(in) :: cc
        character(len=*), intent(in) :: name, text
        integer, intent(in) :: line
        type(diagnostics_t), intent(inout) :: diag
        integer :: k
        if (len_trim(name) == 0) return
        do k = 1, size(cc%set%combinations)
            if (cc%set%combinations(k)%name == name) call error_at(diag, line, text, 1, &
                'duplicate combination name '''//trim(name)//''' (first given at line '// &
                int_text(cc%set%combinations(k)%line)//'; a combination continues only on '// &
                'the COMBINE card right after it)')
        end do
    end subroutine check_new_combination

    !> The pair of fields j (case name) and j+1 (factor) of a COMBINE card.
    subroutine read_pair(cc, k, line, text, j, diag)
        type(combination_cards_t), intent(inout) :: cc
        integer, intent(in) :: k, line, j
        character(len=*), intent(in) :: text
        type(diagnostics_t), intent(inout) :: diag
        type(case_reference_t) :: ref
        character(len=field_width) :: word
        integer :: s_name, s_factor
        call read_word_field(field_text(text, j), word, s_name)
        call read_real_field(field_text(text, j + 1), ref%value, s_factor)
        if (s_name == FIELD_BLANK .and. s_factor == FIELD_BLANK) return
        cc%pair_error = cc%pair_error .or. s_name /= FIELD_OK .or. s_factor /= FIELD_OK
        if (s_name /= FIELD_OK) then
            call error_at(diag, line, text, j, 'COMBINE load case name f'//int_text(j)// &
                ' must be one word (the factor in f'//int_text(j + 1)//' needs its case), '// &
                'got '''// &
                trim(adjustl(field_text(text, j)))//'''')
            return
        end if
        if (s_factor == FIELD_BLANK) then
            call error_at(diag, line, text, j + 1, 'COMBINE factor f'//int_text(j + 1)// &
                ' of load case '//trim(word)//' must be a number, got a blank field')
            return
        else if (s_factor /= FIELD_OK) then
            call error_at(diag, line, text, j + 1, 'COMBINE factor f'//int_text(j + 1)// &
                ' of load case '//trim(word)//': '// &
                number_problem(s_factor, trim(adjustl(field_text(text, j + 1)))))
            return
        end if
        ref%combination = k
        ref%name = word
        ref%factor = adjustl(field_text(text, j + 1))
        ref%line = line
        ref%field = j
        ref%echo = trim(text)
        cc%references = [cc%references, ref]
    end subroutine read_pair

    !> A LOAD card is about to be read: the case it belongs to (an error when load cases are
    !! given and it comes before the first LOADCASE).
    subroutine note_load_card(cc, cases_given, line, text, diag)
        type(combination_cards_t), intent(inout) :: cc   !! the cards so far
        logical, intent(in) :: cases_given               !! the deck has LOADCASE cards
        integer, intent(in) :: line                      !! deck line of the LOAD card
        character(len=*), intent(in) :: text             !! the card
        type(diagnostics_t), intent(inout) :: diag       !! input errors
        cc%load_case = cc%open_case
        if (cc%open_case > 0) then
            cc%cards_per_case(cc%open_case) = cc%cards_per_case(cc%open_case) + 1
        else if (cases_given) then
            call add_diagnostic(diag, line, 1, name_width, 'LOAD outside any load case: '// &
                'in a deck with LOADCASE cards every LOAD follows the LOADCASE card of its '// &
                'case', trim(text))
        end if
    end subroutine note_load_card

    !> The LOAD card just read is in the model: record its case.
    subroutine accept_load_card(cc)
        type(combination_cards_t), intent(inout) :: cc   !! the cards so far
        if (.not. allocated(cc%set%load_case)) allocate (cc%set%load_case(0))
        cc%set%load_case = [cc%set%load_case, cc%load_case]
    end subroutine accept_load_card

    !> After every card: COMBINE needs LOADCASE; no load case is empty or left out of every
    !! combination; every case named exists, once per combination; a NONDIM deck has none
    !! (its forces are in units of the one total load). Without COMBINE every case is solved
    !! alone. Without LOADCASE and COMBINE the set stays empty.
    subroutine finish_load_set(cc, nondim, diag)
        type(combination_cards_t), intent(inout) :: cc   !! the cards read
        logical, intent(in) :: nondim                    !! a NONDIM deck
        type(diagnostics_t), intent(inout) :: diag       !! input errors
        integer :: c, n_cases
        n_cases = 0
        if (allocated(cc%set%cases)) n_cases = size(cc%set%cases)
        if (n_cases == 0 .and. cc%combine_line > 0) call add_diagnostic(diag, cc%combine_line, &
            1, name_width, 'COMBINE without LOADCASE cards: a combination factors named load '// &
            'cases (LOADCASE name, followed by the LOAD cards of the case)', cc%combine_echo)
        if (n_cases == 0) return
        if (nondim) call add_diagnostic(diag, cc%set%cases(1)%line, 1, name_width, 'load '// &
            'cases need a physical deck: in a NONDIM deck forces are in units of the one '// &
            'total vertical load F', trim(cc%case_echoes(1)))
        do c = 1, n_cases
            if (cc%cards_per_case(c) == 0 .and. cc%set%cases(c)%unit_weight <= 0.0_dp) &
                call add_diagnostic(diag, cc%set%cases(c)%line, 1, name_width, 'load case '''// &
                    trim(cc%set%cases(c)%name)//''' is empty: no LOAD card follows its '// &
                    'LOADCASE card and it has no unit weight (f2)', trim(cc%case_echoes(c)))
        end do
        if (cc%combine_line == 0) then
            call cases_alone(cc%set)
        else
            call resolve_references(cc, diag)
        end if
    end subroutine finish_load_set

    !> No COMBINE card: each load case a combination of its own, factor 1.
    pure subroutine cases_alone(set)
        type(load_set_t), intent(inout) :: set
        integer :: c, n
        n = size(set%cases)
        allocate (set%combinations(n))
        do c = 1, n
            set%combinations(c)%name = set%cases(c)%name
            allocate (set%combinations(c)%factors(n), set%combinations(c)%factor_texts(n))
            set%combinations(c)%factors = 0.0_dp
            set%combinations(c)%factors(c) = 1.0_dp
            set%combinations(c)%factor_texts = ''
            set%combinations(c)%factor_texts(c) = '1'
        end do
    end subroutine cases_alone

    !> The factors of every combination from its case references.
    subroutine resolve_references(cc, diag)
        type(combination_cards_t), intent(inout) :: cc
        type(diagnostics_t), intent(inout) :: diag
        integer :: r, c, k, n
        logical, allocatable :: used(:)
        n = size(cc%set%cases)
        allocate (used(n))
        used = .false.
        do k = 1, size(cc%set%combinations)
            allocate (cc%set%combinations(k)%factors(n), cc%set%combinations(k)%factor_texts(n))
            cc%set%combinations(k)%factors = 0.0_dp
            cc%set%combinations(k)%factor_texts = ''
        end do
        do r = 1, size(cc%references)
            associate (ref => cc%references(r))
                c = case_index(cc%set, ref%name)
                if (c == 0) then
                    call error_at(diag, ref%line, ref%echo, ref%field, 'COMBINE names '// &
                        'the unknown load case '''//trim(ref%name)//''' (load cases: '// &
                        case_list(cc%set)//')')
                    cycle
                end if
                associate (comb => cc%set%combinations(ref%combination))
                    if (len_trim(comb%factor_texts(c)) > 0) call error_at(diag, ref%line, &
                        ref%echo, ref%field, 'load case '''//trim(ref%name)//''' is given '// &
                        'twice in combination '''//trim(comb%name)//'''')
                    comb%factors(c) = ref%value
                    comb%factor_texts(c) = ref%factor
                end associate
                used(c) = .true.
            end associate
        end do
        call check_coverage(cc, used, diag)
    end subroutine resolve_references

    !> Every combination names a case and has a factor other than 0; every case is in a
    !! combination.
    subroutine check_coverage(cc, used, diag)
        type(combination_cards_t), intent(in) :: cc
        logical, intent(in) :: used(:)
        type(diagnostics_t), intent(inout) :: diag
        integer :: c, k
        do k = 1, size(cc%set%combinations)
            if (.not. any(cc%references%combination == k) .and. .not. cc%pair_error) &
                call add_diagnostic(diag, &
                cc%set%combinations(k)%line, field_first_column(2), field_first_column(3) + &
                field_width - 1, 'combination '''//trim(cc%set%combinations(k)%name)// &
                ''' names no load case: give pairs of a case name and its factor in f2 '// &
                'and f3, f4 and f5, f6 and f7', trim(cc%combination_echoes(k)))
            if (any(cc%references%combination == k) .and. .not. cc%pair_error) then
                if (all(cc%set%combinations(k)%factors == 0.0_dp)) call add_diagnostic(diag, &
                    cc%set%combinations(k)%line, field_first_column(1), &
                    field_first_column(1) + field_width - 1, 'combination '''// &
                    trim(cc%set%combinations(k)%name)//''' has every factor 0: it carries '// &
                    'no load (give at least one case a factor other than 0)', &
                    trim(cc%combination_echoes(k)))
            end if
        end do
        ! (a pair that could not be read has its error: the case it names is not reported)
        if (cc%pair_error) return
        do c = 1, size(used)
            if (.not. used(c)) call add_diagnostic(diag, cc%set%cases(c)%line, &
                field_first_column(1), field_first_column(1) + field_width - 1, 'load case '''// &
                trim(cc%set%cases(c)%name)//''' is in no COMBINE card (every case is '// &
                'combined; without COMBINE cards each case is solved alone)', &
                trim(cc%case_echoes(c)))
        end do
    end subroutine check_coverage

    !> The index of the load case named name (0: none).
    pure integer function case_index(set, name) result(c)
        type(load_set_t), intent(in) :: set
        character(len=*), intent(in) :: name
        do c = 1, size(set%cases)
            if (set%cases(c)%name == name) return
        end do
        c = 0
    end function case_index

    !> 'G, Q, W'
    pure function case_list(set) result(text)
        type(load_set_t), intent(in) :: set
        character(len=:), allocatable :: text
        integer :: c
        text = ''
        do c = 1, size(set%cases)
            if (c > 1) text = text//', '
            text = text//trim(set%cases(c)%name)
        end do
    end function case_list

    !> A name field: one word of letters, digits, _ and -, starting with a letter, not a word
    !! of fricon's own file names.
    subroutine take_name(line, text, j, what, name, diag)
        integer, intent(in) :: line, j
        character(len=*), intent(in) :: text, what
        character(len=name_length), intent(out) :: name
        type(diagnostics_t), intent(inout) :: diag
        character(len=field_width) :: word
        integer :: s
        call read_word_field(field_text(text, j), word, s)
        name = ''
        if (s == FIELD_BLANK) then
            call error_at(diag, line, text, j, what//' is required but the field is blank')
        else if (s /= FIELD_OK .or. verify(trim(word), letters//'0123456789_-') > 0 .or. &
                 index(letters, word(1:1)) == 0) then
            call error_at(diag, line, text, j, what//' must be one word of letters, '// &
                'digits, _ and -, starting with a letter (it names files), got '''// &
                trim(adjustl(field_text(text, j)))//'''')
        else if (any(reserved == word)) then
            call error_at(diag, line, text, j, what//' cannot be '//trim(word)//': '// &
                'SUMMARY, SWEEP, RESPONSE and ENVELOPE name fricon''s own files')
        else
            name = word
        end if
    end subroutine take_name

    !> Fields after the last one a card uses are blank.
    subroutine check_blank_after(diag, line, text, n_used, card)
        type(diagnostics_t), intent(inout) :: diag
        integer, intent(in) :: line, n_used
        character(len=*), intent(in) :: text, card
        integer :: j
        do j = n_used + 1, max_fields
            if (len_trim(field_text(text, j)) == 0) cycle
            call error_at(diag, line, text, j, card//' uses '//int_text(n_used)// &
                ' fields; f'//int_text(j)//' must be blank, got '''// &
                trim(adjustl(field_text(text, j)))//'''')
            return
        end do
    end subroutine check_blank_after

    subroutine error_at(diag, line, text, j, message)
        type(diagnostics_t), intent(inout) :: diag
        integer, intent(in) :: line, j
        character(len=*), intent(in) :: text, message
        integer :: c1
        c1 = field_first_column(j)
        call add_diagnostic(diag, line, c1, c1 + field_width - 1, message, trim(text))
    end subroutine error_at
end module deck_combinations
