!> Figures drawn by gnuplot without a shell: a renderer is one gnuplot process, started on
!! its first figure and kept for the next ones (gnuplot's start costs about a third of a
!! figure: output/bench/fixed_cost.md), fed each figure script with `call` after `reset
!! session`, so that every figure starts from gnuplot's defaults as in a fresh process. Each
!! thread of a sweep has its own renderer. The process is handled by the C shim
!! figure_renderer_shim.c (posix_spawnp, a socket pair for its input and output).
module figure_renderer
    use iso_c_binding, only: c_int, c_char, c_null_char
    implicit none
    private

    !> One gnuplot process (none until the first figure).
    type, public :: renderer_t
        integer(c_int) :: pid = 0         !! gnuplot's process id; 0: not running
        integer(c_int) :: channel = -1    !! our end of its standard input and output
    end type renderer_t

    !> Outcomes of draw_figure.
    integer, parameter, public :: FIGURE_DRAWN = 0         !! gnuplot reported no error
    integer, parameter, public :: FIGURE_FAILED = 1        !! gnuplot reported an error, or died
    integer, parameter, public :: FIGURE_NO_GNUPLOT = 2    !! no gnuplot on the PATH

    !> The line gnuplot prints after each figure, followed by its error number.
    character(len=*), parameter :: marker = 'fricon-figure-done'
    character(len=*), parameter :: nl = achar(10)
    integer(c_int), parameter :: enoent = 2_c_int   !! errno ENOENT (Linux, BSD, macOS)

    interface
        ! int fricon_gnuplot_start(int *channel);
        function c_gnuplot_start(channel) bind(c, name='fricon_gnuplot_start') result(pid)
            import :: c_int
            integer(c_int), intent(out) :: channel
            integer(c_int) :: pid
        end function c_gnuplot_start
        ! int fricon_gnuplot_draw(int channel, const char *commands, const char *marker);
        function c_gnuplot_draw(channel, commands, marker_text) &
            bind(c, name='fricon_gnuplot_draw') result(outcome)
            import :: c_int, c_char
            integer(c_int), value :: channel
            character(kind=c_char), intent(in) :: commands(*), marker_text(*)
            integer(c_int) :: outcome
        end function c_gnuplot_draw
        ! void fricon_gnuplot_stop(int pid, int channel);
        subroutine c_gnuplot_stop(pid, channel) bind(c, name='fricon_gnuplot_stop')
            import :: c_int
            integer(c_int), value :: pid, channel
        end subroutine c_gnuplot_stop
    end interface

    public :: draw_figure, stop_renderer

contains

    !> gnuplot runs the figure script `script` with its output set to `png` (the script
    !! reads png_override). The paths must not contain quotes or backquotes (gnuplot's string
    !! and command syntax). A gnuplot that died or reported an error is stopped; the next
    !! figure starts a new one.
    subroutine draw_figure(r, script, png, outcome)
        type(renderer_t), intent(inout) :: r         !! the thread's gnuplot (started if none)
        !> the figure script (CASE.gp) and the PNG it draws to (CASE.png.tmp)
        character(len=*), intent(in) :: script, png
        integer, intent(out) :: outcome              !! FIGURE_DRAWN, _FAILED or _NO_GNUPLOT
        character(len=:), allocatable :: commands
        if (r%pid <= 0) then
            r%pid = c_gnuplot_start(r%channel)
            if (r%pid <= 0) then
                outcome = FIGURE_FAILED
                if (r%pid == -enoent) outcome = FIGURE_NO_GNUPLOT
                r%pid = 0
                return
            end if
        end if
        ! (unset output closes the PNG; print '-' goes to the channel, flushed)
        commands = 'reset errors'//nl//'reset session'//nl//"png_override = '"//png//"'"// &
                   nl//"call '"//script//"'"//nl//'unset output'//nl//"set print '-'"//nl// &
                   "print '"//marker//"', GPVAL_ERRNO"//nl
        outcome = int(c_gnuplot_draw(r%channel, commands//c_null_char, marker//c_null_char))
        if (outcome /= FIGURE_DRAWN) then
            call stop_renderer(r)
            outcome = FIGURE_FAILED
        end if
    end subroutine draw_figure

    !> End the renderer's gnuplot (if running) and wait for it.
    subroutine stop_renderer(r)
        type(renderer_t), intent(inout) :: r         !! the renderer; stopped on return
        if (r%pid > 0) call c_gnuplot_stop(r%pid, r%channel)
        r%pid = 0
        r%channel = -1
    end subroutine stop_renderer
end module figure_renderer
