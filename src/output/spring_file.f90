!> output/CASE_springs.csv: the springs equivalent to the solved ground, for structural
!! software (doc/OUTPUT.md "Springs"). One row per mesh node: its position, settlement w and
!! bottom-face displacement u_b, the nodal contact forces F_z, F_x and springs k_v = F_z/w,
!! k_h = F_x/u_b (foundation_springs: a beam's whole width b, a plate's ring 2 pi r), the
!! contact pressure p_z there (the station value: element means at the node) and the modulus
!! of subgrade reaction k_s = p_z/w. A first `#` line names the program, version and run
!! time, a second says what the springs are; then the header `key [unit]`.
!!
!! Written for solved physical decks with P1 displacements (the nodal springs need nodal
!! values); a NONDIM deck has no physical springs, and neither gets the file.
module spring_file
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_INTERNAL
    use model, only: model_t, MODEL_BEAM, FIELD_U, FIELD_W, FIELD_PSI
    use shape_functions, only: INTERP_P1
    use discretization, only: discretization_t
    use contact_solver, only: solution_t
    use atomic_files, only: open_temporary, commit_file
    use case_scales, only: units_t, case_units
    use station_columns, only: Q_X, Q_W, Q_SZ
    use station_results, only: station_table_t
    use interface_law, only: STATE_LIFTOFF
    use foundation_springs, only: spring_table_t, nodal_springs
    use run_identity, only: run_stamp
    implicit none
    private

    public :: has_springs, write_springs_csv, subgrade_modulus

contains

    !> Whether the case gets a springs file: a physical deck with P1 displacements.
    pure logical function has_springs(m, d)
        type(model_t), intent(in) :: m            !! the model (its NONDIM flag)
        type(discretization_t), intent(in) :: d   !! its bases
        has_springs = .not. m%nondim .and. &
                      all(d%basis([FIELD_U, FIELD_W, FIELD_PSI])%family == INTERP_P1)
    end function has_springs

    !> Write path (CASE_springs.csv) for a case with has_springs; design is a station table
    !! holding every node (the design table).
    subroutine write_springs_csv(path, m, d, sol, design, err)
        character(len=*), intent(in) :: path             !! the file written
        type(model_t), intent(in) :: m                   !! the model solved
        type(discretization_t), intent(in) :: d          !! its discretisation
        type(solution_t), intent(in) :: sol              !! its solution
        type(station_table_t), intent(in) :: design      !! stations at every node
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(spring_table_t) :: s
        real(dp), allocatable :: p(:), k_s(:)
        integer :: u, i
        call nodal_springs(m, d, sol, s, err)
        if (allocated(err)) return
        call pressure_at_nodes(m, s, design, p, k_s, err)
        if (allocated(err)) return
        call open_temporary(path, u, err)
        if (allocated(err)) return
        call write_heading(u, m)
        associate (un => case_units(m))
        rows: do i = 1, s%n
            write (u, '(es16.7e3,8(",",es16.7e3))') s%x(i), s%w(i)*un%disp_factor, &
                s%u_b(i)*un%disp_factor, s%f_z(i), s%f_x(i), s%k_v(i), s%k_h(i), &
                p(i)*un%pressure_factor, k_s(i)
        end do rows
        end associate
        call commit_file(path, u, err)
    end subroutine write_springs_csv

    !> The two `#` lines and the header `key [unit]`.
    subroutine write_heading(u, m)
        integer, intent(in) :: u                 !! the open file
        type(model_t), intent(in) :: m           !! its units and structure
        type(units_t) :: un
        character(len=:), allocatable :: f_l, x, p
        logical :: beam
        un = case_units(m)
        beam = m%structure%kind == MODEL_BEAM
        f_l = trim(un%force)//'/'//trim(un%length)
        x = merge('x', 'r', beam)
        p = merge('p_z    ', 'sigma_z', beam)
        write (u, '(a)') '# '//run_stamp()
        write (u, '(a)') '# secant springs of this load case only (doc/OUTPUT.md): per node '// &
            'k_v = F_z/w and k_h = F_x/u_b ('// &
            trim(merge('the whole width b', 'the ring 2 pi r  ', beam))//'), k_s = '//trim(p)// &
            '/w; 0 where lifted off or not moving'
        write (u, '(a)') x//' ['//trim(un%length)//'],w ['//trim(un%disp)//'],u_b ['// &
            trim(un%disp)//'],F_z ['//trim(un%force)//'],F_x ['//trim(un%force)// &
            '],k_v ['//f_l//'],k_h ['//f_l//'],'//trim(p)//' ['//trim(un%pressure)// &
            '],k_s ['//f_l//'^3]'
    end subroutine write_heading

    !> At each node of s: the contact pressure p [F/L^2, deck units] of the design station at
    !! the node, and k_s = p/w (subgrade_modulus).
    subroutine pressure_at_nodes(m, s, design, p, k_s, err)
        type(model_t), intent(in) :: m
        type(spring_table_t), intent(in) :: s
        type(station_table_t), intent(in) :: design
        real(dp), allocatable, intent(out) :: p(:), k_s(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: tol, width
        integer :: i, j
        logical, allocatable :: lifted(:)
        allocate (p(s%n), lifted(s%n))
        width = merge(m%structure%b, 1.0_dp, m%structure%kind == MODEL_BEAM)
        tol = 1.0e-9_dp*max(maxval(abs(s%x)), tiny(1.0_dp))
        j = 1
        nodes: do i = 1, s%n
            do while (j <= design%n)
                if (abs(design%val(Q_X, j) - s%x(i)) <= tol) exit
                j = j + 1
            end do
            if (j > design%n) then
                call new_error(err, EXIT_INTERNAL, 'springs: a node has no design station')
                return
            end if
            p(i) = design%val(Q_SZ, j)/width
            lifted(i) = design%state(j) == STATE_LIFTOFF
        end do nodes
        k_s = subgrade_modulus(p, s%w, lifted)
    end subroutine pressure_at_nodes

    !> k_s = p/w [F/L^3], 0 where lifted off or where |w| is below 1e-12 of the largest.
    pure function subgrade_modulus(p, w, lifted) result(k_s)
        real(dp), intent(in) :: p(:)          !! contact pressure [F/L^2]
        real(dp), intent(in) :: w(:)          !! settlement [L]
        logical, intent(in) :: lifted(:)      !! lifted off
        real(dp) :: k_s(size(p))
        real(dp) :: small
        small = 1.0e-12_dp*max(maxval(abs(w)), tiny(1.0_dp))
        k_s = 0.0_dp
        where (abs(w) > small .and. .not. lifted) k_s = p/w
    end function subgrade_modulus
end module spring_file
