!> The inputs of a case as the calculation record (html_record) shows them: one row per value
!! of each card (card, quantity, symbol, value, unit, in the deck's units: fricon never
!! converts them), the loads as a table, and the ground model (SOIL's half-space, or the
!! LAYER table and its BASE). The values are the case's: a swept value appears as solved.
module record_inputs
    use kinds, only: dp
    use deck_fields, only: int_text
    use model, only: model_t, MODEL_BEAM, LOAD_PATCH, &
                     load_kind_words, &
                     METHOD_NEWTON, FIELD_U, FIELD_SZ, total_vertical_load, relative_stiffness, &
                     soil_shear_modulus, layer_profile, base_name, GROUND_BASE_HALFSPACE
    use shape_functions, only: interp_name
    use case_scales, only: pressure_unit
    use summary_table, only: choose
    use ground_text, only: layered, ground_model_words
    use html_text, only: escaped, html_exact, html_number, html_unit, cell, head_cell, &
                         table_row
    implicit none
    private

    public :: write_input_tables, write_ground_model

contains

    !> Section 1: the cards' values (structure, interface, mesh, solver, output) and the
    !! loads; ne_solved is the mesh the results are from (refined or adapted meshes differ
    !! from the MESH card's).
    subroutine write_input_tables(u, m, ne_solved)
        integer, intent(in) :: u           !! the open page
        type(model_t), intent(in) :: m     !! the case
        integer, intent(in) :: ne_solved   !! elements of the mesh solved
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h2>Inputs</h2>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('card')//head_cell('quantity')// &
            head_cell('symbol')//head_cell('value')//head_cell('unit'))//'</thead>'
        write (u, '(a)') '<tbody>'
        call write_structure_rows(u, m)
        call write_interface_rows(u, m)
        call write_mesh_rows(u, m, ne_solved)
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
        call write_loads(u, m)
        write (u, '(a)') '</section>'
    end subroutine write_input_tables

    !> MODEL, UNITS, GEOMETRY and STRUCTURE (or NONDIM).
    subroutine write_structure_rows(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: f, l, stress
        logical :: beam
        beam = m%structure%kind == MODEL_BEAM
        f = trim(m%units%force)
        l = trim(m%units%length)
        stress = trim(pressure_unit(f, l))
        write (u, '(a)') word_row('MODEL', 'structure', choose(beam, &
            'BEAM (Timoshenko beam)', 'PLATE (axisymmetric Mindlin plate)'))
        if (m%nondim) then
            call write_nondim_rows(u, m)
            return
        end if
        write (u, '(a)') word_row('UNITS', 'force, length', f//', '//l// &
            choose(m%units%stated, '', ' (no UNITS card: labels N and m)'))
        write (u, '(a)') value_row('GEOMETRY', choose(beam, 'length', 'radius'), &
            choose(beam, 'l', 'a'), m%structure%length, l)
        write (u, '(a)') value_row('', 'thickness', 'h', m%structure%h, l)
        if (beam) write (u, '(a)') value_row('', 'width', 'b', m%structure%b, l)
        write (u, '(a)') value_row('STRUCTURE', 'Young''s modulus', 'E', m%structure%e, stress)
        write (u, '(a)') value_row('', 'Poisson''s ratio', '&#957;', m%structure%nu, '')
        write (u, '(a)') value_row('', 'shear correction factor', 'k', m%structure%k_shear, '')
        if (.not. layered(m)) then
            write (u, '(a)') value_row('SOIL', 'Young''s modulus', 'E<sub>f</sub>', &
                                       m%ground%e_f, stress)
            write (u, '(a)') value_row('', 'Poisson''s ratio', '&#957;<sub>f</sub>', &
                                       m%ground%nu_f, '')
        end if
    end subroutine write_structure_rows

    !> The NONDIM card's groups and the physical set fricon chose for them.
    subroutine write_nondim_rows(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        write (u, '(a)') value_row('NONDIM', 'relative stiffness', '&#961;', &
                                   relative_stiffness(m%structure, m%ground), '')
        write (u, '(a)') value_row('', 'thickness ratio h/l (h/a)', '&#950;', m%groups%zeta, '')
        write (u, '(a)') value_row('', 'Poisson''s ratio of the structure', '&#957;', &
                                   m%structure%nu, '')
        write (u, '(a)') value_row('', 'Poisson''s ratio of the soil', '&#957;<sub>f</sub>', &
                                   m%ground%nu_f, '')
        if (m%structure%kind == MODEL_BEAM) write (u, '(a)') value_row('', 'width ratio b/l', &
            '&#946;', m%groups%beta, '')
        write (u, '(a)') word_row('', 'physical set', 'l (a) = 1, E = 1, F = 1: lengths in '// &
            'units of l (a), forces in units of the total vertical load F')
    end subroutine write_nondim_rows

    !> FRICTION and the penalty of the tension zone.
    subroutine write_interface_rows(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        write (u, '(a)') value_row('FRICTION', 'Coulomb friction coefficient', 'f', &
                                   m%interface%f, '')
        write (u, '(a)') value_row('', 'regularisation of the friction law', &
                                   '&#949;&#772;', m%interface%eps_bar, '')
    end subroutine write_interface_rows

    !> MESH, ADAPT, SOLVER and OUTPUT.
    subroutine write_mesh_rows(u, m, ne_solved)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        integer, intent(in) :: ne_solved
        character(len=:), allocatable :: interp
        integer :: field
        interp = ''
        do field = FIELD_U, FIELD_SZ
            interp = interp//' '//interp_name(m%mesh%interp(field))
        end do
        if (ne_solved /= m%mesh%ne) then
            write (u, '(a)') word_row('MESH', 'elements N<sub>e</sub>', int_text(m%mesh%ne)// &
                ' (the results: '//int_text(ne_solved)//', adapted)')
        else
            write (u, '(a)') word_row('MESH', 'elements N<sub>e</sub>', int_text(m%mesh%ne))
        end if
        write (u, '(a)') word_row('', 'grading', trim(m%mesh%grading))
        write (u, '(a)') word_row('', 'interpolation u<sub>s</sub> w &#968; '// &
            '&#963;<sub>x</sub> &#963;<sub>z</sub>', interp(2:))
        if (m%mesh%adapt_tol > 0.0_dp) then
            write (u, '(a)') value_row('ADAPT', 'tolerance', 'tol', m%mesh%adapt_tol, '')
            write (u, '(a)') word_row('', 'largest mesh', int_text(m%mesh%adapt_max_ne))
        end if
        write (u, '(a)') word_row('SOLVER', 'method', choose( &
            m%solver%method == METHOD_NEWTON, 'NEWTON (semismooth Newton)', &
            'TWOLOOP (the paper''s two loops)'))
        write (u, '(a)') value_row('', 'tolerance outer, inner', '', m%solver%tol_outer, '', &
                                   m%solver%tol_inner)
        write (u, '(a)') word_row('', 'largest number of iterations outer, inner', &
            int_text(m%solver%max_outer)//', '//int_text(m%solver%max_inner))
        write (u, '(a)') value_row('', 'penalty of the tension zone', '&#951;&#772;', &
                                   m%interface%eta_bar, '')
        if (m%output%stations > 0) then
            write (u, '(a)') word_row('OUTPUT', 'stations', int_text(m%output%stations))
        else
            write (u, '(a)') word_row('OUTPUT', 'stations', 'every node of the mesh')
        end if
    end subroutine write_mesh_rows

    !> The LOAD cards, with their totals.
    subroutine write_loads(u, m)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: f, l
        logical :: beam
        integer :: k
        beam = m%structure%kind == MODEL_BEAM
        f = html_unit(trim(m%units%force))
        l = html_unit(trim(m%units%length))
        write (u, '(a)') '<h3>Loads (LOAD cards; F<sub>z</sub> downward, F<sub>x</sub> '// &
            choose(beam, 'along +x', 'radial')//' on the top face; a PRESSURE is given as its '// &
            'PATCH total)</h3>'
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('#')//head_cell('kind')// &
            head_cell('F<sub>z</sub> ['//f//']'//choose(beam, ' (MOMENT: ['//f//'&#183;'//l// &
            '])', ''))// &
            head_cell('F<sub>x</sub> ['//f//']')//head_cell('x<sub>1</sub> ['//l//']')// &
            head_cell('x<sub>2</sub> ['//l//']'))//'</thead>'
        write (u, '(a)') '<tbody>'
        do k = 1, size(m%loads)
            associate (ld => m%loads(k))
            write (u, '(a)') table_row(cell(int_text(k))//cell(trim(load_kind_words(ld%kind)))// &
                cell(html_exact(ld%fz), 'num')//cell(html_exact(ld%fx), 'num')// &
                cell(html_exact(ld%x1), 'num')//cell(second_position(ld%kind, ld%x2), 'num'))
            end associate
        end do
        write (u, '(a)') table_row(cell('')//cell('<b>total</b>')// &
            cell('<b>'//html_exact(total_vertical_load(m%loads))//'</b>', 'num')// &
            cell('<b>'//html_exact(sum(m%loads%fx))//'</b>', 'num')//cell('')//cell(''))
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
    end subroutine write_loads

    pure function second_position(kind, x2) result(html)
        integer, intent(in) :: kind
        real(dp), intent(in) :: x2
        character(len=:), allocatable :: html
        html = ''
        if (kind == LOAD_PATCH) html = html_exact(x2)
    end function second_position

    !> Section 2: the ground model. A homogeneous half-space (SOIL) by its E_f, nu_f, G_f; a
    !! layered ground by its layers from the surface down and its base.
    subroutine write_ground_model(u, m)
        integer, intent(in) :: u          !! the open page
        type(model_t), intent(in) :: m    !! the case
        character(len=:), allocatable :: stress
        stress = trim(pressure_unit(trim(m%units%force), trim(m%units%length)))
        write (u, '(a)') '<section>'
        write (u, '(a)') '<h2>Ground model</h2>'
        if (layered(m)) then
            write (u, '(a)') '<p class="note">'//escaped(ground_model_words(m))//'.</p>'
            call write_layer_table(u, m, stress)
        else
            write (u, '(a)') '<p class="note">Homogeneous elastic half-space (SOIL): E<sub>f'// &
                '</sub> = '//html_exact(m%ground%e_f)//' '//html_unit(stress)// &
                ', &#957;<sub>f</sub> = '//html_exact(m%ground%nu_f)//', G<sub>f</sub> = '// &
                html_number(soil_shear_modulus(m%ground), 5)//' '//html_unit(stress)//'.</p>'
        end if
        write (u, '(a)') '<p class="small">Friction compliance and &#961; use the top '// &
            'layer''s E<sub>f</sub>, &#957;<sub>f</sub>; &#961; = '// &
            html_number(relative_stiffness(m%structure, m%ground), 4)//'.</p>'
        write (u, '(a)') '</section>'
    end subroutine write_ground_model

    !> The layers (top depth, thickness, E at top and bottom, nu) and the base.
    subroutine write_layer_table(u, m, stress)
        integer, intent(in) :: u
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: stress
        real(dp), allocatable :: h(:), e_top(:), e_bottom(:), nu(:)
        real(dp) :: e_base, z
        character(len=:), allocatable :: l, s
        integer :: j
        call layer_profile(m%ground, h, e_top, e_bottom, nu, e_base)
        l = html_unit(trim(m%units%length))
        s = html_unit(stress)
        write (u, '(a)') '<table>'
        write (u, '(a)') '<thead>'//table_row(head_cell('layer')//head_cell('top at z ['//l// &
            ']')//head_cell('thickness h ['//l//']')//head_cell('E at top ['//s//']')// &
            head_cell('E at bottom ['//s//']')//head_cell('&#957;'))//'</thead>'
        write (u, '(a)') '<tbody>'
        z = 0.0_dp
        do j = 1, size(h)
            write (u, '(a)') table_row(cell(int_text(j))//cell(html_exact(z), 'num')// &
                cell(html_exact(h(j)), 'num')//cell(html_exact(e_top(j)), 'num')// &
                cell(html_exact(e_bottom(j)), 'num')//cell(html_exact(nu(j)), 'num'))
            z = z + h(j)
        end do
        if (m%ground%base == GROUND_BASE_HALFSPACE) then
            write (u, '(a)') table_row(cell('base: HALFSPACE')//cell(html_exact(z), 'num')// &
                cell('&#8734;', 'num')//cell(html_exact(e_base), 'num')// &
                cell(html_exact(e_base), 'num')//cell(html_exact(m%ground%nu_base), 'num'))
        else
            write (u, '(a)') table_row(cell('base: '//base_name(m%ground))// &
                cell(html_exact(z), 'num')//cell('rigid')//cell('')//cell('')//cell(''))
        end if
        write (u, '(a)') '</tbody>'
        write (u, '(a)') '</table>'
    end subroutine write_layer_table

    !> A row of one number (and optionally a second, 'a, b').
    pure function value_row(card, quantity, symbol, x, unit, x2) result(tr)
        character(len=*), intent(in) :: card, quantity, symbol, unit
        real(dp), intent(in) :: x
        real(dp), intent(in), optional :: x2
        character(len=:), allocatable :: tr, value
        value = html_exact(x)
        if (present(x2)) value = value//', '//html_exact(x2)
        tr = table_row(cell('<b>'//card//'</b>', 'key')//cell(escaped(quantity))// &
                       cell(symbol, 'key')//cell(value, 'key')//cell(html_unit(unit), 'key'))
    end function value_row

    !> A row whose value is a word or a list (HTML allowed in quantity).
    pure function word_row(card, quantity, value) result(tr)
        character(len=*), intent(in) :: card, quantity, value
        character(len=:), allocatable :: tr
        tr = table_row(cell('<b>'//card//'</b>', 'key')//cell(quantity)//cell('')// &
                       cell(escaped(value))//cell(''))
    end function word_row
end module record_inputs
