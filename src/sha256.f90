!> SHA-256 (FIPS 180-4, section 6.2) of a text's bytes, as 64 lowercase hexadecimal digits:
!! the fingerprint of a deck's text in the JSON summary and the identity of a deck's file
!! (deck_identity). The 32-bit words are held in 64-bit integers and reduced modulo 2**32
!! after each sum, so no signed 32-bit overflow ever happens.
module sha256
    use iso_fortran_env, only: int64
    implicit none
    private

    public :: sha256_hex

    integer(int64), parameter :: mask32 = 4294967295_int64   !! 2**32 - 1

    !> The round constants K (FIPS 180-4, 4.2.2): the first 32 bits of the fractional parts
    !! of the cube roots of the first 64 primes.
    integer(int64), parameter :: k_round(64) = [ &
        int(z'428a2f98', int64), int(z'71374491', int64), int(z'b5c0fbcf', int64), &
        int(z'e9b5dba5', int64), int(z'3956c25b', int64), int(z'59f111f1', int64), &
        int(z'923f82a4', int64), int(z'ab1c5ed5', int64), int(z'd807aa98', int64), &
        int(z'12835b01', int64), int(z'243185be', int64), int(z'550c7dc3', int64), &
        int(z'72be5d74', int64), int(z'80deb1fe', int64), int(z'9bdc06a7', int64), &
        int(z'c19bf174', int64), int(z'e49b69c1', int64), int(z'efbe4786', int64), &
        int(z'0fc19dc6', int64), int(z'240ca1cc', int64), int(z'2de92c6f', int64), &
        int(z'4a7484aa', int64), int(z'5cb0a9dc', int64), int(z'76f988da', int64), &
        int(z'983e5152', int64), int(z'a831c66d', int64), int(z'b00327c8', int64), &
        int(z'bf597fc7', int64), int(z'c6e00bf3', int64), int(z'd5a79147', int64), &
        int(z'06ca6351', int64), int(z'14292967', int64), int(z'27b70a85', int64), &
        int(z'2e1b2138', int64), int(z'4d2c6dfc', int64), int(z'53380d13', int64), &
        int(z'650a7354', int64), int(z'766a0abb', int64), int(z'81c2c92e', int64), &
        int(z'92722c85', int64), int(z'a2bfe8a1', int64), int(z'a81a664b', int64), &
        int(z'c24b8b70', int64), int(z'c76c51a3', int64), int(z'd192e819', int64), &
        int(z'd6990624', int64), int(z'f40e3585', int64), int(z'106aa070', int64), &
        int(z'19a4c116', int64), int(z'1e376c08', int64), int(z'2748774c', int64), &
        int(z'34b0bcb5', int64), int(z'391c0cb3', int64), int(z'4ed8aa4a', int64), &
        int(z'5b9cca4f', int64), int(z'682e6ff3', int64), int(z'748f82ee', int64), &
        int(z'78a5636f', int64), int(z'84c87814', int64), int(z'8cc70208', int64), &
        int(z'90befffa', int64), int(z'a4506ceb', int64), int(z'bef9a3f7', int64), &
        int(z'c67178f2', int64)]

    !> The initial hash value H(0) (FIPS 180-4, 5.3.3).
    integer(int64), parameter :: h_initial(8) = [ &
        int(z'6a09e667', int64), int(z'bb67ae85', int64), int(z'3c6ef372', int64), &
        int(z'a54ff53a', int64), int(z'510e527f', int64), int(z'9b05688c', int64), &
        int(z'1f83d9ab', int64), int(z'5be0cd19', int64)]

contains

    !> The SHA-256 digest of the bytes of text, 64 lowercase hexadecimal digits.
    pure function sha256_hex(text) result(hex)
        character(len=*), intent(in) :: text   !! the message (any length, any bytes)
        character(len=64) :: hex
        integer(int64) :: h(8)
        integer(int64), allocatable :: bytes(:)
        integer :: block, k
        character(len=*), parameter :: digits = '0123456789abcdef'
        bytes = padded_message(text)
        h = h_initial
        blocks: do block = 0, size(bytes)/64 - 1
            call compress(h, bytes(64*block + 1:64*block + 64))
        end do blocks
        do k = 0, 31
            associate (byte => iand(ishft(h(k/4 + 1), -8*(3 - mod(k, 4))), 255_int64))
                hex(2*k + 1:2*k + 1) = digits(byte/16 + 1:byte/16 + 1)
                hex(2*k + 2:2*k + 2) = digits(mod(byte, 16_int64) + 1:mod(byte, 16_int64) + 1)
            end associate
        end do
    end function sha256_hex

    !> The message's bytes, then 0x80, zeros, and its length in bits as a 64-bit big-endian
    !! number, to a whole number of 64-byte blocks (FIPS 180-4, 5.1.1).
    pure function padded_message(text) result(bytes)
        character(len=*), intent(in) :: text
        integer(int64), allocatable :: bytes(:)
        integer :: n, total, k
        integer(int64) :: bits
        n = len(text)
        total = ((n + 8)/64 + 1)*64
        allocate (bytes(total))
        bytes = 0_int64
        do k = 1, n
            bytes(k) = int(ichar(text(k:k)), int64)
        end do
        bytes(n + 1) = 128_int64
        bits = 8_int64*int(n, int64)
        do k = 0, 7
            bytes(total - k) = iand(ishft(bits, -8*k), 255_int64)
        end do
    end function padded_message

    !> One block of 64 bytes into the hash value h (FIPS 180-4, 6.2.2 steps 1 to 4).
    pure subroutine compress(h, block)
        integer(int64), intent(inout) :: h(8)     !! the hash value, words < 2**32
        integer(int64), intent(in) :: block(64)   !! the block's bytes
        integer(int64) :: w(64), a(8), t1, t2, s0, s1
        integer :: t
        do t = 1, 16
            w(t) = ior(ior(ishft(block(4*t - 3), 24), ishft(block(4*t - 2), 16)), &
                       ior(ishft(block(4*t - 1), 8), block(4*t)))
        end do
        schedule: do t = 17, 64
            s0 = ieor(ieor(rotr(w(t - 15), 7), rotr(w(t - 15), 18)), ishft(w(t - 15), -3))
            s1 = ieor(ieor(rotr(w(t - 2), 17), rotr(w(t - 2), 19)), ishft(w(t - 2), -10))
            w(t) = iand(w(t - 16) + s0 + w(t - 7) + s1, mask32)
        end do schedule
        a = h
        rounds: do t = 1, 64
            s1 = ieor(ieor(rotr(a(5), 6), rotr(a(5), 11)), rotr(a(5), 25))
            t1 = a(8) + s1 + ieor(iand(a(5), a(6)), iand(iand(not(a(5)), mask32), a(7))) &
                 + k_round(t) + w(t)
            s0 = ieor(ieor(rotr(a(1), 2), rotr(a(1), 13)), rotr(a(1), 22))
            t2 = s0 + ieor(ieor(iand(a(1), a(2)), iand(a(1), a(3))), iand(a(2), a(3)))
            a(2:8) = a(1:7)
            a(5) = iand(a(5) + t1, mask32)
            a(1) = iand(t1 + t2, mask32)
        end do rounds
        h = iand(h + a, mask32)
    end subroutine compress

    !> A 32-bit word rotated right by n bits.
    elemental integer(int64) function rotr(x, n)
        integer(int64), intent(in) :: x   !! a word < 2**32
        integer, intent(in) :: n          !! 0 < n < 32
        ! (two shifts: gfortran's ishftc with a size argument is a library loop, 20 times slower)
        rotr = ior(ishft(x, -n), iand(ishft(x, 32 - n), mask32))
    end function rotr
end module sha256
