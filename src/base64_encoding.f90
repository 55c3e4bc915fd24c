!> Base64 (RFC 4648 §4, the standard alphabet A-Z a-z 0-9 + /, padded with '='): bytes as
!! text, for a figure embedded in a page as a data URI. Each character of a byte string is
!! one byte (0 to 255); every 3 bytes become 4 characters, a last group of 1 or 2 bytes
!! becomes 2 or 3 characters and '==' or '='.
module base64_encoding
    implicit none
    private

    character(len=64), parameter :: alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZ'// &
        'abcdefghijklmnopqrstuvwxyz0123456789+/'

    public :: base64_encoded, base64_decoded, base64_length

contains

    !> Length of the base64 text of n bytes: 4 ceiling(n/3).
    pure integer function base64_length(n)
        integer, intent(in) :: n   !! bytes
        base64_length = 4*((n + 2)/3)
    end function base64_length

    !> The base64 text of the bytes.
    pure function base64_encoded(bytes) result(text)
        character(len=*), intent(in) :: bytes   !! one byte per character
        character(len=base64_length(len(bytes))) :: text
        integer :: i, k, n, group, b(3)
        n = len(bytes)
        k = 0
        groups: do i = 1, n, 3
            b = 0
            b(1) = byte_at(bytes, i)
            if (i + 1 <= n) b(2) = byte_at(bytes, i + 1)
            if (i + 2 <= n) b(3) = byte_at(bytes, i + 2)
            group = ishft(b(1), 16) + ishft(b(2), 8) + b(3)
            text(k + 1:k + 1) = sextet(group, 18)
            text(k + 2:k + 2) = sextet(group, 12)
            text(k + 3:k + 3) = sextet(group, 6)
            text(k + 4:k + 4) = sextet(group, 0)
            if (i + 1 > n) text(k + 3:k + 3) = '='
            if (i + 2 > n) text(k + 4:k + 4) = '='
            k = k + 4
        end do groups
    end function base64_encoded

    !> The bytes of base64 text; ok is false when the text is not canonical base64 (a length
    !! not a multiple of 4, a character outside the alphabet, '=' other than at the end, or
    !! nonzero bits in the last character's padding).
    pure subroutine base64_decoded(text, bytes, ok)
        character(len=*), intent(in) :: text                  !! base64 text
        character(len=:), allocatable, intent(out) :: bytes   !! the decoded bytes
        logical, intent(out) :: ok                            !! the text was valid
        integer :: i, j, k, pad, group, v(4)
        ok = .false.
        if (mod(len(text), 4) /= 0) then
            bytes = ''
            return
        end if
        pad = 0
        if (len(text) >= 4) pad = count([text(len(text):len(text)) == '=', &
                                         text(len(text) - 1:len(text) - 1) == '='])
        if (pad == 1 .and. len(text) >= 2) then
            if (text(len(text) - 1:len(text) - 1) == '=') pad = 3
        end if
        if (pad == 3 .or. (len(text) >= 3 .and. pad == 2 .and. &
                           text(len(text) - 2:len(text) - 2) == '=')) then
            bytes = ''
            return
        end if
        allocate (character(len=3*(len(text)/4) - pad) :: bytes)
        k = 0
        groups: do i = 1, len(text), 4
            do j = 1, 4
                v(j) = index(alphabet, text(i + j - 1:i + j - 1)) - 1
                if (v(j) < 0 .and. .not. (i + 3 == len(text) .and. j > 4 - pad)) return
                v(j) = max(v(j), 0)
            end do
            group = ishft(v(1), 18) + ishft(v(2), 12) + ishft(v(3), 6) + v(4)
            if (i + 3 == len(text) .and. pad > 0) then
                if (iand(group, 2**(8*pad) - 1) /= 0) return
            end if
            do j = 1, 3
                if (k + j > len(bytes)) exit
                bytes(k + j:k + j) = achar(iand(ishft(group, -8*(3 - j)), 255))
            end do
            k = k + 3
        end do groups
        ok = .true.
    end subroutine base64_decoded

    !> The byte at position i, 0 to 255.
    pure integer function byte_at(bytes, i)
        character(len=*), intent(in) :: bytes
        integer, intent(in) :: i
        byte_at = iand(ichar(bytes(i:i)), 255)
    end function byte_at

    !> The character of the six bits of group starting at bit shift.
    pure character function sextet(group, shift)
        integer, intent(in) :: group, shift
        integer :: v
        v = iand(ishft(group, -shift), 63)
        sextet = alphabet(v + 1:v + 1)
    end function sextet
end module base64_encoding
