!> c12-minimal-loop: the yardstick of c2's speed. The same job as c12-c2's
!> sampling and runs (the same blocks of the stream, the same MT19937 seeds,
!> Box-Muller, redraw rule, the same v4 bit for bit) with the minimal
!> hand-written real(16) loop of sphere_row_minimal, one thread, no
!> statistics beyond the mean; prints the mean and the time.
program c12_minimal_loop
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, real_str, itoa
    use sphere_row_monte_carlo, only: normal_sampler_t, mc_block_size, mc_block_seed
    use sphere_row_minimal, only: minimal_v4
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, say
    implicit none
    !> The definition's law of e.
    real(dp), parameter :: mean = 0.5_dp, sd = 0.05_dp
    type(cli_t) :: cli
    type(normal_sampler_t) :: sampler
    real(dp), allocatable :: v4(:)
    real(dp) :: z, e, total
    integer :: n, seed, b, i
    integer(int64) :: c0, c1, rate

    call start_program(cli, "c12-minimal-loop", &
        "The minimal real(16) loop of task c2 (the yardstick of c12-c2's speed):"//nl// &
        "n runs of the definition's row on c2's stream; prints their mean v4.", tables=.false.)
    call cli%add_int("n", "1000000", "runs", lo=1, hi=100000000)
    call cli%add_int("seed", "12", "MT19937 seed of the stream (as c12-c2's)", lo=1)
    call read_keys(cli)
    n = cli%get_int("n")
    seed = cli%get_int("seed")
    allocate (v4(n))
    call system_clock(c0, rate)
    do b = 1, (n - 1)/mc_block_size + 1
        call sampler%seed_block(mc_block_seed(seed, b))
        do i = (b - 1)*mc_block_size + 1, min(b*mc_block_size, n)
            do
                call sampler%draw(z)
                e = mean + sd*z
                if (e >= 0.0_dp .and. e <= 1.0_dp) exit
            end do
            v4(i) = real(minimal_v4(real(e, qp)), dp)
        end do
    end do
    call sampler%release()
    total = sum(v4)
    call system_clock(c1)
    call say("c12-minimal-loop: "//itoa(n)//" runs, mean v4 " &
        //real_str(real(total/n, qp), 17)//", "//real_str(real(c1 - c0, qp)/rate, 4)//" s")
end program c12_minimal_loop
