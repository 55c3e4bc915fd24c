!> The inputs of a case in its JSON summary, so that the summary alone says what was solved:
!! the deck's text and its SHA-256, and every value of the case's model after defaults (the
!! swept values of the case in place), part by part, each part with the units of its values
!! (the deck's units F and L; NONDIM decks: F and l or a).
!!
!!     "deck_sha256": "ba7816bf...",
!!     "deck_text": "* a deck\nMODEL     BEAM\n...",
!!     "inputs": {"units": {...}, "structure": {...}, "ground": {...}, "interface": {...},
!!                "loads": [...], "mesh": {...}, "solver": {...}, "output": {...}},
module input_record
    use kinds, only: dp
    use sha256, only: sha256_hex
    use json_text, only: json_string, json_number
    use deck_fields, only: int_text
    use shape_functions, only: interp_name
    use case_scales, only: units_t, case_units, pressure_unit
    use model, only: model_t, MODEL_BEAM, GROUND_LAYERED, GROUND_BASE_HALFSPACE, load_kind_words, &
                     LOAD_PATCH, LOAD_MOMENT, METHOD_NEWTON, &
                     base_name, layer_profile
    implicit none
    private

    public :: write_input_record, deck_text

    character(len=*), parameter :: field_names(5) = [character(len=7) :: 'u_s', 'w', 'psi', &
                                                     'sigma_x', 'sigma_z']

contains

    !> The deck's lines as one text: each line without its trailing blanks and ended by a
    !! line feed (for a deck file without trailing blanks or carriage returns, the file's
    !! bytes: its SHA-256 is then what `sha256sum DECK` prints).
    pure function deck_text(lines) result(text)
        character(len=*), intent(in) :: lines(:)   !! the deck's lines
        character(len=:), allocatable :: text
        integer :: k, n, at
        n = sum(len_trim(lines)) + size(lines)
        allocate (character(len=n) :: text)
        at = 0
        do k = 1, size(lines)
            text(at + 1:at + len_trim(lines(k)) + 1) = trim(lines(k))//achar(10)
            at = at + len_trim(lines(k)) + 1
        end do
    end function deck_text

    !> "deck_sha256", "deck_text" and "inputs" (module header), each line ending in a comma.
    subroutine write_input_record(u, m, lines)
        integer, intent(in) :: u                   !! the JSON file, open for writing
        type(model_t), intent(in) :: m             !! the case's model
        character(len=*), intent(in) :: lines(:)   !! the deck's lines
        character(len=:), allocatable :: text
        text = deck_text(lines)
        write (u, '(a)') '  "deck_sha256": "'//sha256_hex(text)//'",'
        write (u, '(a)') '  "deck_text": '//escaped_text(lines)//','
        write (u, '(a)') '  "inputs": {'
        call write_units(u, m)
        call write_structure(u, m)
        call write_ground(u, m)
        write (u, '(a)') '    "interface": {"friction": '//num(m%interface%f)// &
            ', "eps_bar": '//num(m%interface%eps_bar)//', "eta_bar": '// &
            num(m%interface%eta_bar)//'},'
        call write_loads(u, m)
        call write_mesh(u, m)
        call write_solver(u, m)
        write (u, '(a)') '    "output": {"stations": '//int_text(m%output%stations)// &
            ', "note": "0: every node of the mesh"}'
        write (u, '(a)') '  },'
    end subroutine write_input_record

    !> The deck's text as one JSON string, a \n after each line.
    pure function escaped_text(lines) result(js)
        character(len=*), intent(in) :: lines(:)
        character(len=:), allocatable :: js, one
        integer :: k
        js = '"'
        do k = 1, size(lines)
            one = json_string(trim(lines(k)))
            js = js//one(2:len(one) - 1)//'\n'
        end do
        js = js//'"'
    end function escaped_text

    !> "units": the deck's unit words and display choices.
    subroutine write_units(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        type(units_t) :: un
        un = case_units(m)
        write (u, '(a)') '    "units": {"force": '//json_string(trim(m%units%force))// &
            ', "length": '//json_string(trim(m%units%length))//', "settlement_shown_in": '// &
            json_string(trim(un%disp))//', "pressure_shown_in": '// &
            json_string(trim(un%pressure))//', "units_card": '//logical_text(m%units%stated)// &
            ', "nondimensional": '//logical_text(m%nondim)//'},'
        if (.not. m%nondim) return
        write (u, '(a)') '    "nondim": {"rho": '//num(m%groups%rho)//', "zeta": '// &
            num(m%groups%zeta)//', "beta": '//num(m%groups%beta)//'},'
    end subroutine write_units

    !> "structure": the GEOMETRY and STRUCTURE cards (NONDIM: the physical set chosen).
    subroutine write_structure(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: f, l
        f = trim(m%units%force)
        l = trim(m%units%length)
        associate (s => m%structure)
        write (u, '(a)') '    "structure": {"model": '//json_string(trim(merge('BEAM ', &
            'PLATE', s%kind == MODEL_BEAM)))//', "length_or_radius": '//num(s%length)// &
            ', "thickness": '//num(s%h)//', "width": '//num(s%b)//', "modulus": '// &
            num(s%e)//', "poisson": '//num(s%nu)//', "shear_factor": '//num(s%k_shear)//','
        write (u, '(a)') '      "units": {"length_or_radius": '//json_string(l)// &
            ', "thickness": '//json_string(l)//', "width": '//json_string(l)// &
            ', "modulus": '//json_string(trim(pressure_unit(f, l)))//'}},'
        end associate
    end subroutine write_structure

    !> "ground": SOIL, or the layers (layer_profile: in the deck's units, E at the bottom
    !! equal to E at the top for a constant layer, layer 1 from E_f and nu_f) and the BASE.
    subroutine write_ground(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: modulus_unit
        real(dp), allocatable :: thickness(:), e_top(:), e_bottom(:), poisson(:)
        real(dp) :: e_base
        integer :: k
        modulus_unit = trim(pressure_unit(m%units%force, m%units%length))
        associate (g => m%ground)
        write (u, '(a)') '    "ground": {"kind": '//json_string(trim(merge('layered    ', &
            'homogeneous', g%kind == GROUND_LAYERED)))//', "modulus": '//num(g%e_f)// &
            ', "poisson": '//num(g%nu_f)//','
        if (g%kind == GROUND_LAYERED) then
            call layer_profile(g, thickness, e_top, e_bottom, poisson, e_base)
            write (u, '(a)', advance='no') '      "layers": ['
            do k = 1, size(thickness)
                write (u, '(a)', advance='no') separator(k)//'{"thickness": '// &
                    num(thickness(k))//', "modulus_top": '//num(e_top(k))// &
                    ', "modulus_bottom": '//num(e_bottom(k))//', "poisson": '// &
                    num(poisson(k))//'}'
            end do
            write (u, '(a)') '],'
            write (u, '(a)') '      "base": '//json_string(base_name(g))//', "base_modulus": '// &
                json_number(e_base, g%base == GROUND_BASE_HALFSPACE)//', "base_poisson": '// &
                json_number(g%nu_base, g%base == GROUND_BASE_HALFSPACE)//','
            write (u, '(a)') '      "units": {"modulus": '//json_string(modulus_unit)// &
                ', "thickness": '//json_string(trim(m%units%length))//'}},'
        else
            write (u, '(a)') '      "units": {"modulus": '//json_string(modulus_unit)//'}},'
        end if
        end associate
    end subroutine write_ground

    !> "loads": one object per LOAD card (PRESSURE as the PATCH it becomes), with units.
    subroutine write_loads(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: f, l, fz_unit
        integer :: k
        f = trim(m%units%force)
        l = trim(m%units%length)
        write (u, '(a)') '    "loads": ['
        do k = 1, size(m%loads)
            associate (ld => m%loads(k))
            fz_unit = f
            if (ld%kind == LOAD_MOMENT) fz_unit = f//'.'//l
            write (u, '(a)', advance='no') '      {"kind": '// &
                json_string(trim(load_kind_words(ld%kind)))// &
                ', "deck_line": '//int_text(ld%line)//', "f_z": '//num(ld%fz)// &
                ', "f_x": '//num(ld%fx)//', "x1": '//num(ld%x1)//', "x2": '// &
                json_number(ld%x2, ld%kind == LOAD_PATCH)//', "units": {"f_z": '// &
                json_string(fz_unit)//', "f_x": '//json_string(f)//', "x1": '// &
                json_string(l)//', "x2": '//json_string(l)//'}}'
            if (k < size(m%loads)) write (u, '(a)', advance='no') ','
            write (u, '(a)') ''
            end associate
        end do
        write (u, '(a)') '    ],'
    end subroutine write_loads

    !> "mesh": the MESH and ADAPT cards.
    subroutine write_mesh(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        integer :: k
        write (u, '(a)', advance='no') '    "mesh": {"elements": '//int_text(m%mesh%ne)// &
            ', "grading": '//json_string(trim(m%mesh%grading))//', "interpolation": {'
        do k = 1, size(field_names)
            write (u, '(a)', advance='no') separator(k)// &
                json_string(trim(field_names(k)))//': '//json_string(trim(interp_name( &
                m%mesh%interp(k))))
        end do
        if (m%mesh%adapt_tol > 0.0_dp) then
            write (u, '(a)') '}, "adapt_tolerance": '//num(m%mesh%adapt_tol)// &
                ', "adapt_max_elements": '//int_text(m%mesh%adapt_max_ne)//'},'
        else
            write (u, '(a)') '}, "adapt_tolerance": null, "adapt_max_elements": null},'
        end if
    end subroutine write_mesh

    !> "solver": the SOLVER card.
    subroutine write_solver(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        associate (c => m%solver)
        write (u, '(a)') '    "solver": {"method": '//json_string(trim(merge('NEWTON ', &
            'TWOLOOP', c%method == METHOD_NEWTON)))//', "tol_outer": '//num(c%tol_outer)// &
            ', "tol_inner": '//num(c%tol_inner)//', "max_outer": '//int_text(c%max_outer)// &
            ', "max_inner": '//int_text(c%max_inner)//', "tau0_start": '// &
            json_number(c%tau0_start, c%tau0_start >= 0.0_dp)//', "simplify": '// &
            logical_text(c%simplify)//'},'
        end associate
    end subroutine write_solver

    !> '' before the first item of a list, ', ' before the others.
    pure function separator(k) result(text)
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        text = ''
        if (k > 1) text = ', '
    end function separator

    pure function num(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        text = json_number(x, .true.)
    end function num

    pure function logical_text(yes) result(text)
        logical, intent(in) :: yes
        character(len=:), allocatable :: text
        text = trim(merge('true ', 'false', yes))
    end function logical_text
end module input_record
