!> The unit words fricon knows, with their size in SI units: the UNITS card's force and length
!! words, and the display units of settlements and pressures. A deck whose UNITS words are
!! all known can be checked for plausible magnitudes (plausibility) and shown in other
!! display units (case_scales); any other word is a label only.
!!
!! Exact factors: 1 kip = 1000 lbf = 4448.2216152605 N; 1 in = 0.0254 m; 1 ft = 0.3048 m
!! (international yard and pound, 1959); psf = lbf/ft^2, psi = lbf/in^2.
!!
!!     UNITS     kN        m         mm        kPa
!!     UNITS     kip       ft        in        ksf
module physical_units
    use kinds, only: dp
    implicit none
    private

    real(dp), parameter :: lbf = 4.4482216152605_dp   !! pound-force [N]
    real(dp), parameter :: inch = 0.0254_dp           !! [m]
    real(dp), parameter :: foot = 0.3048_dp           !! [m]

    !> Words of each kind, for messages.
    character(len=*), parameter, public :: force_words = 'N, kN, MN, kip'
    character(len=*), parameter, public :: length_words = 'mm, m, in, ft'
    character(len=*), parameter, public :: disp_words = 'mm, cm, m, in, ft'
    character(len=*), parameter, public :: pressure_words = &
        'Pa, kPa, MPa, GPa, psf, ksf, psi, ksi'

    public :: force_in_newtons, length_in_metres, disp_in_metres, pressure_in_pascals

contains

    !> Size of a force word in N; 0 for a word fricon does not know.
    pure real(dp) function force_in_newtons(word)
        character(len=*), intent(in) :: word   !! the UNITS force word (case kept)
        select case (trim(word))
        case ('N')
            force_in_newtons = 1.0_dp
        case ('kN')
            force_in_newtons = 1.0e3_dp
        case ('MN')
            force_in_newtons = 1.0e6_dp
        case ('kip')
            force_in_newtons = 1.0e3_dp*lbf
        case default
            force_in_newtons = 0.0_dp
        end select
    end function force_in_newtons

    !> Size of a deck length word in m; 0 for a word fricon does not know.
    pure real(dp) function length_in_metres(word)
        character(len=*), intent(in) :: word   !! the UNITS length word (case kept)
        select case (trim(word))
        case ('mm')
            length_in_metres = 1.0e-3_dp
        case ('m')
            length_in_metres = 1.0_dp
        case ('in')
            length_in_metres = inch
        case ('ft')
            length_in_metres = foot
        case default
            length_in_metres = 0.0_dp
        end select
    end function length_in_metres

    !> Size of a settlement display word in m (the deck lengths and cm); 0 if unknown.
    pure real(dp) function disp_in_metres(word)
        character(len=*), intent(in) :: word   !! the display word (case kept)
        if (trim(word) == 'cm') then
            disp_in_metres = 1.0e-2_dp
        else
            disp_in_metres = length_in_metres(word)
        end if
    end function disp_in_metres

    !> Size of a pressure display word in Pa; 0 for a word fricon does not know.
    pure real(dp) function pressure_in_pascals(word)
        character(len=*), intent(in) :: word   !! the display word (case kept)
        select case (trim(word))
        case ('Pa')
            pressure_in_pascals = 1.0_dp
        case ('kPa')
            pressure_in_pascals = 1.0e3_dp
        case ('MPa')
            pressure_in_pascals = 1.0e6_dp
        case ('GPa')
            pressure_in_pascals = 1.0e9_dp
        case ('psf')
            pressure_in_pascals = lbf/foot**2
        case ('ksf')
            pressure_in_pascals = 1.0e3_dp*lbf/foot**2
        case ('psi')
            pressure_in_pascals = lbf/inch**2
        case ('ksi')
            pressure_in_pascals = 1.0e3_dp*lbf/inch**2
        case default
            pressure_in_pascals = 0.0_dp
        end select
    end function pressure_in_pascals
end module physical_units
