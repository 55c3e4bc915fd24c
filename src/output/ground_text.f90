!> The words and numbers that state a layered ground in the outputs: the report's layer
!! table, the CSV's comment line and the JSON's "ground" object. A homogeneous half-space
!! (SOIL) is stated by E_f and nu_f as it always was, and gets none of these.
module ground_text
    use kinds, only: dp
    use deck_fields, only: format_real, int_text
    use model, only: model_t, MODEL_BEAM, GROUND_LAYERED, GROUND_BASE_HALFSPACE, layer_count, &
                     layer_profile, ground_depth, base_name
    implicit none
    private
    public :: gp_number
    public :: layered, ground_model_words, write_layer_table, ground_csv_line, ground_json, &
              write_ground_figure_settings

contains

    !> The case's ground is layered.
    pure logical function layered(m)
        type(model_t), intent(in) :: m   !! the case
        layered = m%ground%kind == GROUND_LAYERED .and. layer_count(m%ground) > 0
    end function layered

    !> 'layered elastic ground: 2 layers, 10 m deep, over a ROUGH (rigid, bonded) base'.
    pure function ground_model_words(m) result(text)
        type(model_t), intent(in) :: m   !! a case on layered ground
        character(len=:), allocatable :: text
        text = 'layered elastic ground: '//int_text(layer_count(m%ground))//' layer'// &
            trim(merge('s', ' ', layer_count(m%ground) > 1))//', '// &
            format_real(ground_depth(m%ground))//' '//trim(m%units%length)//' deep, over a '// &
            base_name(m%ground)//' base '//base_words(m)
    end function ground_model_words

    pure function base_words(m) result(text)
        type(model_t), intent(in) :: m
        character(len=:), allocatable :: text
        select case (base_name(m%ground))
        case ('ROUGH')
            text = '(rigid, bonded)'
        case ('SMOOTH')
            text = '(rigid, frictionless)'
        case default
            text = '(an elastic half-space)'
        end select
    end function base_words

    !> The report's table of the layers and the base (physical units of the case).
    subroutine write_layer_table(u, m)
        integer, intent(in) :: u         !! the open report
        type(model_t), intent(in) :: m   !! a case on layered ground
        real(dp), allocatable :: h(:), e_top(:), e_bottom(:), nu(:)
        real(dp) :: e_base, z
        character(len=:), allocatable :: stress
        integer :: j
        call layer_profile(m%ground, h, e_top, e_bottom, nu, e_base)
        stress = trim(m%units%force)//'/'//trim(m%units%length)//'^2'
        write (u, '(3x,a5,5a16)') 'layer', heading('z_top ['//trim(m%units%length)//']'), &
            heading('h ['//trim(m%units%length)//']'), heading('E_top ['//stress//']'), &
            heading('E_bot ['//stress//']'), heading('nu')
        z = 0.0_dp
        do j = 1, size(h)
            write (u, '(3x,i5,4es16.6,f16.4)') j, z, h(j), e_top(j), e_bottom(j), nu(j)
            z = z + h(j)
        end do
        if (m%ground%base == GROUND_BASE_HALFSPACE) then
            write (u, '(3x,a5,es16.6,16x,2es16.6,f16.4)') 'base', z, e_base, e_base, &
                m%ground%nu_base
        else
            write (u, '(3x,a5,es16.6,2x,a)') 'base', z, base_name(m%ground)//' '//base_words(m)
        end if
        write (u, '(3x,a)') 'E_f, nu_f and G_f are the top layer''s (friction compliance, rho)'
    end subroutine write_layer_table

    !> '# ground: LAYER h=4 E=8000..8000 nu=0.45; ...; BASE ROUGH' (units of the case).
    pure function ground_csv_line(m) result(text)
        type(model_t), intent(in) :: m   !! a case on layered ground
        character(len=:), allocatable :: text
        real(dp), allocatable :: h(:), e_top(:), e_bottom(:), nu(:)
        real(dp) :: e_base
        integer :: j
        call layer_profile(m%ground, h, e_top, e_bottom, nu, e_base)
        text = '# ground [' //trim(m%units%length)//', '//trim(m%units%force)//'/'// &
               trim(m%units%length)//'^2]:'
        do j = 1, size(h)
            text = text//' LAYER h='//format_real(h(j))//' E_top='//format_real(e_top(j))// &
                   ' E_bottom='//format_real(e_bottom(j))//' nu='//format_real(nu(j))//';'
        end do
        text = text//' BASE '//base_name(m%ground)
        if (m%ground%base == GROUND_BASE_HALFSPACE) text = text//' E='//format_real(e_base)// &
            ' nu='//format_real(m%ground%nu_base)
    end function ground_csv_line

    !> The JSON member `"ground": {...},` (one line; units of the case).
    pure function ground_json(m) result(text)
        type(model_t), intent(in) :: m   !! a case on layered ground
        character(len=:), allocatable :: text
        real(dp), allocatable :: h(:), e_top(:), e_bottom(:), nu(:)
        real(dp) :: e_base
        call layer_profile(m%ground, h, e_top, e_bottom, nu, e_base)
        text = '  "ground": {"kind": "layered", "thickness": '//numbers(h)// &
            ', "E_top": '//numbers(e_top)//', "E_bottom": '//numbers(e_bottom)// &
            ', "nu": '//numbers(nu)//', "base": "'//base_name(m%ground)//'"'
        if (m%ground%base == GROUND_BASE_HALFSPACE) text = text//', "E_base": '// &
            format_real(e_base)//', "nu_base": '//format_real(m%ground%nu_base)
        text = text//'},'
    end function ground_json

    !> The settings of the ground profile panel (scripts/gnuplot/fricon_ground.gp): each
    !! layer's top and bottom depth, E at them and nu, the base, the structure's thickness,
    !! labels and units. Lengths in the plotted unit of x (xs per deck length); moduli in the
    !! deck's F/L^2 (named as the pressures are), or relative to E_f in a NONDIM deck.
    subroutine write_ground_figure_settings(u, m, xs, e_unit)
        integer, intent(in) :: u                   !! the open .gp file
        type(model_t), intent(in) :: m             !! a case on layered ground
        real(dp), intent(in) :: xs                 !! plotted length per deck length
        character(len=*), intent(in) :: e_unit     !! the pressure unit, e.g. kPa
        real(dp), allocatable :: h(:), e_top(:), e_bottom(:), nu(:), z(:)
        real(dp) :: e_base, es
        character(len=:), allocatable :: z_unit
        integer :: n, j
        call layer_profile(m%ground, h, e_top, e_bottom, nu, e_base)
        n = size(h)
        allocate (z(0:n))
        z(0) = 0.0_dp
        do j = 1, n
            z(j) = z(j - 1) + h(j)*xs
        end do
        es = merge(1.0_dp/m%ground%e_f, 1.0_dp, m%nondim)
        write (u, '(a)') '# ground profile from the surface down: depth of each layer''s top '// &
            'and bottom, E there, nu; the base'
        write (u, '(a)') 'n_layers = '//int_text(n)
        call put_array(u, 'layer_z1', z(0:n - 1))
        call put_array(u, 'layer_z2', z(1:n))
        call put_array(u, 'layer_e1', es*e_top)
        call put_array(u, 'layer_e2', es*e_bottom)
        call put_array(u, 'layer_nu', nu)
        write (u, '(a)') "base_kind = '"//base_name(m%ground)//"'"
        write (u, '(a)') 'base_e = '//gp_number(es*e_base)
        write (u, '(a)') 'base_nu = '//gp_number(m%ground%nu_base)
        if (m%nondim) then
            z_unit = trim(merge('l', 'a', m%structure%kind == MODEL_BEAM))
            write (u, '(a)') "lab_depth = 'depth z/"//z_unit//"'"
            write (u, '(a)') "z_unit = ' "//z_unit//"'"
            write (u, '(a)') "e_unit = ' E_f'"
        else
            write (u, '(a)') "lab_depth = 'depth z ["//trim(m%units%length)//"]'"
            write (u, '(a)') "z_unit = ' "//trim(m%units%length)//"'"
            write (u, '(a)') "e_unit = ' "//trim(e_unit)//"'"
        end if
        write (u, '(a)') 'struct_h = '//gp_number(m%structure%h*xs)
    end subroutine write_ground_figure_settings

    !> `array NAME[n] = [x1, ..., xn]` in a gnuplot settings block.
    subroutine put_array(u, name, x)
        integer, intent(in) :: u
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: x(:)
        integer :: j
        write (u, '(a)', advance='no') 'array '//name//'['//int_text(size(x))//'] = ['
        do j = 1, size(x) - 1
            write (u, '(a)', advance='no') gp_number(x(j))//', '
        end do
        write (u, '(a)') gp_number(x(size(x)))//']'
    end subroutine put_array

    !> A number for a gnuplot script (full precision; the figure settings of every case).
    pure function gp_number(x) result(text)
        real(dp), intent(in) :: x   !! the number
        character(len=:), allocatable :: text
        character(len=32) :: buf
        write (buf, '(es22.14e3)') x
        text = trim(adjustl(buf))
    end function gp_number

    !> A column heading, right-justified in 16 characters.
    pure function heading(text) result(col)
        character(len=*), intent(in) :: text
        character(len=16) :: col
        integer :: n
        n = min(len(text), 15)
        col = repeat(' ', 16 - n)//text(1:n)
    end function heading

    pure function numbers(x) result(text)
        real(dp), intent(in) :: x(:)
        character(len=:), allocatable :: text
        integer :: j
        text = '['
        do j = 1, size(x)
            if (j > 1) text = text//', '
            text = text//format_real(x(j))
        end do
        text = text//']'
    end function numbers
end module ground_text
