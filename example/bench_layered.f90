!> Benchmark of the layered ground's flexibility (SPEC §3a): for PLATE and BEAM meshes (P1,
!! EDGES) and grounds of 1, 3 and 10 layers, the processor time of the homogeneous T (the top
!! layer's half-space, halfspace_plate / halfspace_beam), of the layered T (that T plus the
!! correction of layered_influence) and of one LU factorisation (dgetrf) of T; the number of
!! wavenumber nodes; for N_e <= 200 the quadrature check max |T_corr - T_corr(2x finer)| /
!! max |T|. Least of repeated runs below N_e = 500.
!! Usage (from the project folder; one thread, as a case of a sweep runs):
!!     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile release --example bench_layered
!! Writes output/bench/layered.md (table), layered.dat (columns) and layered.gp; then
!! `gnuplot output/bench/layered.gp` draws output/bench/layered.png.
program bench_layered
    use iso_fortran_env, only: output_unit
    use kinds, only: dp
    use errors, only: error_t
    use gsl_wrappers, only: gsl_start
    use blas_threads, only: set_blas_threads
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, INTERP_P1
    use lapack_interfaces, only: dgetrf
    use halfspace_plate, only: assemble_plate_flexibility
    use halfspace_beam, only: assemble_beam_flexibility
    use layered_compliance, only: layered_ground_t, new_layered_ground, BASE_ROUGH, &
                                  BASE_HALFSPACE
    use layered_influence, only: assemble_layered_flexibility, layered_correction
    implicit none
    integer, parameter :: n_ne = 6
    integer, parameter :: ne_list(n_ne) = [20, 50, 100, 200, 500, 1000]
    integer, parameter :: layer_list(3) = [1, 3, 10]
    real(dp), parameter :: width = 0.3_dp        !! beam width (beam length 2)
    type(layered_ground_t) :: grounds(3)
    integer :: md, dat, structure, ig, i
    character(len=5), parameter :: names(2) = ['PLATE', 'BEAM ']

    call gsl_start()
    call set_blas_threads(1)
    call make_grounds(grounds)
    open (newunit=md, file='output/bench/layered.md', status='replace', action='write')
    open (newunit=dat, file='output/bench/layered.dat', status='replace', action='write')
    call write_header(md)
    structures: do structure = 1, 2
        write (md, '(/,a,a,/)') '### ', trim(names(structure))
        write (md, '(a)') '| layers | N_e | unknowns of T | wavenumbers | homogeneous T s | '// &
            'layered T s | ratio | one LU of T s | quadrature check |'
        write (md, '(a)') '|---:|---:|---:|---:|---:|---:|---:|---:|---:|'
        ground_loop: do ig = 1, 3
            write (dat, '(a,a,i0,a)') '# ', trim(names(structure)), layer_list(ig), &
                ' layers: N_e, homogeneous T s, layered T s, LU s, wavenumbers'
            meshes: do i = 1, n_ne
                call run_case(structure == 2, ne_list(i), grounds(ig), layer_list(ig), md, dat)
            end do meshes
            write (dat, '(/)')
        end do ground_loop
    end do structures
    close (md)
    close (dat)
    call write_script()
    write (output_unit, '(a)') 'wrote output/bench/layered.md, layered.dat, layered.gp'

contains

    !> The three grounds (lengths in units of the plate radius / beam half-length).
    subroutine make_grounds(grounds)
        type(layered_ground_t), intent(out) :: grounds(3)
        type(error_t), allocatable :: err
        real(dp) :: h(10), e(10), nu(10)
        integer :: j
        call new_layered_ground(grounds(1), [1.0_dp], [1.0_dp], [1.0_dp], [0.45_dp], &
                                BASE_ROUGH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) error stop 'bench_layered: ground 1'
        call new_layered_ground(grounds(2), [0.5_dp, 1.0_dp, 2.0_dp], [1.0_dp, 3.0_dp, 10.0_dp], &
                                [1.0_dp, 3.0_dp, 10.0_dp], [0.45_dp, 0.35_dp, 0.3_dp], &
                                BASE_ROUGH, 0.0_dp, 0.0_dp, err)
        if (allocated(err)) error stop 'bench_layered: ground 2'
        do j = 1, 10
            h(j) = 0.3_dp + 0.05_dp*real(j, dp)
            e(j) = merge(1.0_dp, 4.0_dp, mod(j, 2) == 1)*real(j, dp)
            nu(j) = merge(0.45_dp, 0.3_dp, mod(j, 2) == 1)
        end do
        call new_layered_ground(grounds(3), h, e, e, nu, BASE_HALFSPACE, 50.0_dp, 0.25_dp, err)
        if (allocated(err)) error stop 'bench_layered: ground 3'
    end subroutine make_grounds

    !> Time the three steps of one case and write its row.
    subroutine run_case(beam, ne, ground, layers, md, dat)
        logical, intent(in) :: beam
        integer, intent(in) :: ne, layers, md, dat
        type(layered_ground_t), intent(in) :: ground
        type(mesh_t) :: msh
        type(basis_t) :: bx, bz
        type(error_t), allocatable :: err
        real(dp), allocatable :: t_hs(:, :), t_lay(:, :), c1(:, :), c2(:, :), lu(:, :)
        integer, allocatable :: ipiv(:)
        real(dp) :: t0, t1, time_hs, time_lay, time_lu, check
        character(len=16) :: check_text
        integer :: rep, n_rep, info, n_nodes
        if (beam) then
            call new_mesh(msh, -1.0_dp, 1.0_dp, ne, 'EDGES', err)
        else
            call new_mesh(msh, 0.0_dp, 1.0_dp, ne, 'EDGES', err)
        end if
        if (allocated(err)) error stop 'bench_layered: mesh'
        call new_basis(bx, msh, INTERP_P1)
        call new_basis(bz, msh, INTERP_P1)
        n_rep = merge(3, 1, ne < 500)
        time_hs = huge(1.0_dp)
        time_lay = huge(1.0_dp)
        time_lu = huge(1.0_dp)
        repeats: do rep = 1, n_rep
            call cpu_time(t0)
            if (beam) then
                call assemble_beam_flexibility(bx, bz, ground%shear_modulus(1), &
                                               ground%poisson(1), width, t_hs, err)
            else
                call assemble_plate_flexibility(bx, bz, ground%shear_modulus(1), &
                                                ground%poisson(1), t_hs, err)
            end if
            call cpu_time(t1)
            if (allocated(err)) error stop 'bench_layered: homogeneous T'
            time_hs = min(time_hs, t1 - t0)
            call cpu_time(t0)
            call assemble_layered_flexibility(bx, bz, beam, width, ground, t_lay, err)
            call cpu_time(t1)
            if (allocated(err)) error stop 'bench_layered: layered T'
            time_lay = min(time_lay, t1 - t0)
            lu = t_lay
            allocate (ipiv(size(lu, 1)))
            call cpu_time(t0)
            call dgetrf(size(lu, 1), size(lu, 1), lu, size(lu, 1), ipiv, info)
            call cpu_time(t1)
            deallocate (ipiv)
            if (info /= 0) error stop 'bench_layered: dgetrf'
            time_lu = min(time_lu, t1 - t0)
        end do repeats
        call layered_correction(bx, bz, beam, width, ground, c1, err, n_nodes=n_nodes)
        if (allocated(err)) error stop 'bench_layered: correction'
        check_text = 'n/a'
        if (ne <= 200) then
            call layered_correction(bx, bz, beam, width, ground, c2, err, refine=2.0_dp)
            if (allocated(err)) error stop 'bench_layered: refined correction'
            check = maxval(abs(c1 - c2))/maxval(abs(t_lay))
            write (check_text, '(es9.2)') check
        end if
        write (md, '("| ",i0," | ",i0," | ",i0," | ",i0," | ",f9.4," | ",f9.4," | ",f6.2, &
              &" | ",f9.4," | ",a," |")') layers, ne, size(t_lay, 1), n_nodes, time_hs, &
            time_lay, time_lay/max(time_hs, 1.0e-6_dp), time_lu, trim(adjustl(check_text))
        write (dat, '(i6,3es12.4,i8)') ne, time_hs, time_lay, time_lu, n_nodes
        flush (md)
    end subroutine run_case

    subroutine write_header(md)
        integer, intent(in) :: md
        write (md, '(a)') '# Layered ground: time to build T (bench_layered)'
        write (md, '(a)') ''
        write (md, '(a)') '    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile '// &
            'release --example bench_layered'
        write (md, '(a)') ''
        write (md, '(a)') 'Processor seconds, least of 3 runs below N_e = 500, one thread. '// &
            'P1 tractions on EDGES meshes; plate radius 1, beam length 2 and width 0.3. '// &
            'Grounds: 1 layer (h 1, E 1, nu 0.45) on a ROUGH base; 3 layers (h 0.5, 1, 2; '// &
            'E 1, 3, 10; nu 0.45, 0.35, 0.3) on a ROUGH base; 10 layers (h 0.35 to 0.8, E '// &
            'alternating soft/stiff from 1 to 40) over a HALFSPACE (E 50, nu 0.25). '// &
            '"homogeneous T": the top layer''s half-space; "layered T": that T plus the '// &
            'correction; "quadrature check": max |T_corr - T_corr(panels and element '// &
            'rules twice as fine)| / max |T|.'
    end subroutine write_header

    subroutine write_script()
        integer :: gp
        open (newunit=gp, file='output/bench/layered.gp', status='replace', action='write')
        write (gp, '(a)') '# bench_layered: run from the project folder: '// &
            'gnuplot output/bench/layered.gp'
        write (gp, '(a)') "set terminal pngcairo size 1400,600 font 'Sans,11' noenhanced"
        write (gp, '(a)') "set output 'output/bench/layered.png'"
        write (gp, '(a)') "set multiplot layout 1,2 title 'fricon: time to build T on layered "// &
            "ground (P1, EDGES, 1 thread)' font 'Sans,14'"
        write (gp, '(a)') 'set logscale xy; set grid; set format y "%.0e"'
        write (gp, '(a)') 'set xtics (20, 50, 100, 200, 500, 1000); set xrange [15:1300]'
        write (gp, '(a)') "set xlabel 'N_e'; set ylabel 'processor time [s]'"
        write (gp, '(a)') 'set key left top box opaque'
        call plot_line(gp, 'PLATE', 0)
        call plot_line(gp, 'BEAM', 3)
        write (gp, '(a)') 'unset multiplot'
        close (gp)
    end subroutine write_script

    subroutine plot_line(gp, title, first)
        integer, intent(in) :: gp, first
        character(len=*), intent(in) :: title
        character(len=*), parameter :: f = "'output/bench/layered.dat'"
        write (gp, '(a)') "set title '"//title//"'"
        write (gp, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'plot '//f//' index ', first, &
            " using 1:2 with linespoints lw 2 pt 4 lc rgb 'black' title 'homogeneous T', "// &
            f//' index ', first, " using 1:3 with linespoints lw 2 pt 5 lc rgb '#1f77b4' "// &
            "title 'layered T, 1 layer', "//f//' index ', first + 1, &
            " using 1:3 with linespoints lw 2 pt 7 lc rgb '#ff7f0e' title 'layered T, 3 "// &
            "layers', "//f//' index ', first + 2, " using 1:3 with linespoints lw 2 pt 9 "// &
            "lc rgb '#2ca02c' title 'layered T, 10 layers', "//f//' index ', first, &
            " using 1:4 with linespoints lw 2 dt 2 pt 6 lc rgb 'gray40' title 'one LU of T'"
    end subroutine plot_line
end program bench_layered
