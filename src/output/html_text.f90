!> The pieces of text an HTML page is built from: escaped text, numbers to a given number of
!! significant digits, units with their exponents and dots typeset, table cells and rows, and
!! the page's style sheet (screen and A4 print). Pure functions; nothing here writes a file.
module html_text
    use kinds, only: dp
    use deck_fields, only: int_text, format_real
    use number_text, only: es_text, f_text
    implicit none
    private

    public :: escaped, html_number, html_exact, html_unit, cell, head_cell, table_row, style_sheet
    public :: replaced

contains

    !> text with &, <, > and " written as character references.
    pure function escaped(text) result(html)
        character(len=*), intent(in) :: text   !! plain text
        character(len=:), allocatable :: html
        integer :: i
        if (scan(text, '&<>"') == 0) then
            html = text
            return
        end if
        html = ''
        do i = 1, len(text)
            select case (text(i:i))
            case ('&')
                html = html//'&amp;'
            case ('<')
                html = html//'&lt;'
            case ('>')
                html = html//'&gt;'
            case ('"')
                html = html//'&quot;'
            case default
                html = html//text(i:i)
            end select
        end do
    end function escaped

    !> text with every occurrence of old replaced by new (old not empty).
    pure function replaced(text, old, new) result(out)
        character(len=*), intent(in) :: text   !! the text
        character(len=*), intent(in) :: old    !! what to replace
        character(len=*), intent(in) :: new    !! its replacement
        character(len=:), allocatable :: out
        integer :: i, k
        out = ''
        if (len(old) == 0) then
            out = text
            return
        end if
        i = 1
        do
            k = index(text(i:), old)
            if (k == 0) exit
            out = out//text(i:i + k - 2)//new
            i = i + k - 1 + len(old)
        end do
        out = out//text(i:)
    end function replaced

    !> x to `digits` significant digits: plain decimals for 1E-3 <= |x| < 1E6 (24.76,
    !! 0.004521, 125400), else a mantissa times a power of ten (1.250&#215;10<sup>7</sup>).
    pure function html_number(x, digits) result(html)
        real(dp), intent(in) :: x        !! the number
        integer, intent(in) :: digits    !! significant digits, 1 to 12
        character(len=:), allocatable :: html
        character(len=40) :: buf
        integer :: e, decimals
        if (x == 0.0_dp) then
            html = '0'
            return
        end if
        buf = es_text(x, 30, digits - 1, 3)
        ! the exponent's three digits (es_text's text always ends in E+ddd or E-ddd)
        e = 100*digit(28) + 10*digit(29) + digit(30)
        if (buf(27:27) == '-') e = -e
        if (e >= -3 .and. e <= 5) then
            decimals = max(0, digits - 1 - e)
            buf = f_text(x, 30, decimals)
            html = trim(adjustl(buf))
            if (html(len(html):len(html)) == '.') html = html(1:len(html) - 1)
            if (html(1:1) == '.') html = '0'//html
            if (len(html) > 1) then
                if (html(1:2) == '-.') html = '-0'//html(2:)
            end if
        else
            buf = adjustl(buf)
            html = buf(1:index(buf, 'E') - 1)//'&#215;10<sup>'//int_text(e)//'</sup>'
        end if
        if (html(1:1) == '-') html = '&#8722;'//html(2:)
    contains
        pure integer function digit(k)
            integer, intent(in) :: k
            digit = iachar(buf(k:k)) - iachar('0')
        end function digit
    end function html_number

    !> x as the deck would give it, up to 10 significant digits and no trailing zeros (0.8,
    !! 1200, 3.0&#215;10<sup>7</sup>): deck_fields::format_real typeset.
    pure function html_exact(x) result(html)
        real(dp), intent(in) :: x   !! the number
        character(len=:), allocatable :: html
        integer :: k
        html = format_real(x)
        k = index(html, 'E')
        if (k > 0) html = html(1:k - 1)//'&#215;10<sup>'//html(k + 1:)//'</sup>'
        if (html(1:1) == '-') html = '&#8722;'//html(2:)
    end function html_exact

    !> A unit label typeset: kN.m/m as kN&#183;m/m, m^2 as m<sup>2</sup> ('' stays '').
    pure function html_unit(unit) result(html)
        character(len=*), intent(in) :: unit   !! e.g. kN.m/m, kN/m^3, kPa
        character(len=:), allocatable :: html
        integer :: i
        if (scan(unit, '^.&<>"') == 0) then
            html = trim(unit)
            return
        end if
        html = ''
        i = 1
        do while (i <= len_trim(unit))
            if (unit(i:i) == '^' .and. i < len_trim(unit)) then
                html = html//'<sup>'//unit(i + 1:i + 1)//'</sup>'
                i = i + 2
                cycle
            end if
            if (unit(i:i) == '.') then
                html = html//'&#183;'
            else
                html = html//escaped(unit(i:i))
            end if
            i = i + 1
        end do
    end function html_unit

    !> <td>html</td>, with a class when given (e.g. 'num' for numbers, right-aligned).
    pure function cell(html, class) result(td)
        character(len=*), intent(in) :: html              !! the cell's content (HTML)
        character(len=*), intent(in), optional :: class   !! a CSS class
        character(len=:), allocatable :: td
        if (present(class)) then
            td = '<td class="'//class//'">'//html//'</td>'
        else
            td = '<td>'//html//'</td>'
        end if
    end function cell

    !> <th>html</th>.
    pure function head_cell(html) result(th)
        character(len=*), intent(in) :: html   !! the heading (HTML)
        character(len=:), allocatable :: th
        th = '<th>'//html//'</th>'
    end function head_cell

    !> <tr>cells</tr>.
    pure function table_row(cells) result(tr)
        character(len=*), intent(in) :: cells   !! <td> and <th> elements
        character(len=:), allocatable :: tr
        tr = '<tr>'//cells//'</tr>'
    end function table_row

    !> The page's CSS, one rule a line: sans-serif text, ruled tables that wrap their cells
    !! and never exceed the page, and for print an A4 page with 15 mm margins, no section
    !! heading left at the foot of a page, no table row split across pages.
    pure function style_sheet() result(lines)
        character(len=100), allocatable :: lines(:)
        lines = [character(len=100) :: &
            'body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 10pt;', &
            '       color: #111; max-width: 180mm; margin: 8mm auto; line-height: 1.35; }', &
            'h1 { font-size: 16pt; margin: 0 0 2mm 0; }', &
            'h2 { font-size: 12pt; margin: 6mm 0 2mm 0; border-bottom: 1px solid #444; }', &
            'h3 { font-size: 10.5pt; margin: 4mm 0 1mm 0; }', &
            'table { border-collapse: collapse; width: 100%; table-layout: auto;', &
            '        margin: 1mm 0 2mm 0; }', &
            'th, td { border: 1px solid #999; padding: 1px 4px; vertical-align: top;', &
            '         overflow-wrap: break-word; }', &
            'td.key { white-space: nowrap; }', &
            'th { background: #e8e8e8; text-align: left; font-weight: bold; }', &
            'td.num { text-align: right; white-space: nowrap; }', &
            'table.meta td { border: none; padding: 0 6px 0 0; }', &
            'p.note { margin: 1mm 0; }', &
            'p.warn { margin: 1mm 0; color: #8a1c00; }', &
            'td.fail { color: #8a1c00; font-weight: bold; }', &
            'pre { font-size: 7.5pt; border: 1px solid #bbb; padding: 2mm; margin: 1mm 0;', &
            '      white-space: pre; overflow: hidden; }', &
            'figure { margin: 2mm 0; text-align: center; }', &
            'figure img { max-width: 100%; height: auto; }', &
            'figcaption { font-size: 9pt; color: #333; }', &
            '.small { font-size: 8.5pt; color: #333; }', &
            '@page { size: A4; margin: 15mm 15mm 15mm 15mm; }', &
            '@media print {', &
            '  body { max-width: none; margin: 0; font-size: 9.5pt; }', &
            '  h2, h3 { break-after: avoid; page-break-after: avoid; }', &
            '  tr, figure, pre { break-inside: avoid; page-break-inside: avoid; }', &
            '  thead { display: table-header-group; }', &
            '  section.results { break-before: page; page-break-before: always; }', &
            '}']
    end function style_sheet
end module html_text
