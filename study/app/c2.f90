!> c12-c2: task c2 of ARGESIM Comparison 12. The restitution coefficient e is
!> normally distributed (mean 0.5, standard deviation 0.05); the distribution
!> of the final velocity v4 of the last sphere, its mean, standard deviation,
!> the 95 % confidence interval of the mean and the 95 % interval of v4 itself,
!> from a Monte Carlo of the row in real(16): with precision=auto (the
!> default) each run is made in real(64) where a rounding certificate shows
!> that it takes real(16)'s decisions, and again in real(16) where not.
!>
!> One stream of nmax samples is drawn; the main answers are the statistics of
!> its first n samples and the convergence table takes the prefixes
!> N = 10^2, 10^3, ... of the same stream, so its row N = n is the main
!> answer. The stream is made of blocks of 10^4 samples, each from its own
!> generator (see monte_carlo_v4), run in parallel with OpenMP where built
!> with it and, built with MPI, shared out over the ranks in contiguous
!> ranges of blocks; rank 0 gathers every block's samples and counts, adds
!> the counts in block order and alone writes the tables: the output is the
!> same for any number of threads and ranks.
!>
!> For the definition's row every answer is checked against the exact
!> law of v4 = v0 ((1+e)/2)^3, valid where sphere 4 is struck once; the bound
!> of that region is found with the engine and the samples below it counted.
program c12_c2
    use, intrinsic :: iso_fortran_env, only: error_unit, int64, int8
    use sphere_row, only: dp, qp, scene_t, itoa
    use sphere_row_monte_carlo, only: mc_counts_t, monte_carlo_v4, normal_mass_outside_unit, &
        min_acceptance, mc_block_size
    use sphere_row_ranks, only: ranks_t, record_t, ranks_start, ranks_finish, block_range, &
        gather_records, layout_blocks
    use sphere_row_c2_tables, only: c2_sample_t, c2_statistics, c2_write_tables
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        say, stop_unless_normal, add_row_keys, precision_is_auto
    use sphere_row_system, only: stderr_is_terminal
    use sphere_row_error, only: error_t
    implicit none

    character(len=*), parameter :: name = "c12-c2"
    !> Sample sizes: at least 100 for the normal-quantile interval (see
    !> mean_ci_half_width); at most 10^8, about 3 GB of work arrays.
    integer, parameter :: n_least = 100, n_most = 100000000
    integer, parameter :: bins_most = 100000
    !> Progress on a terminal: from this many seconds on, at most once per
    !> report_every seconds.
    real(dp), parameter :: report_after = 2.0_dp, report_every = 1.0_dp

    type(cli_t) :: cli
    type(ranks_t) :: ranks
    character(len=:), allocatable :: rank_msg
    !> Blocks of the stream, this rank's first ... last, and each block's
    !> counts in the main sample and after it (one straddling n has both).
    integer :: n_blocks, b_own_first, b_own_last
    type(mc_counts_t), allocatable :: main_counts(:), rest_counts(:)
    character(len=:), allocatable :: out
    character(len=300) :: msg
    type(scene_t) :: scene
    type(c2_sample_t) :: c
    type(error_t), allocatable :: error
    integer :: stat
    integer(int64) :: clock0, clock_rate, clock_shown
    real(dp) :: seconds
    logical :: terminal, shown

    call ranks_start(ranks, stat, rank_msg)
    call stop_unless_normal(stat, rank_msg)
    call define_keys()
    call read_keys(cli, scene)
    out = cli%get_word("out")
    c%n = cli%get_int("n")
    c%nmax = c%n
    if (cli%given("nmax")) c%nmax = cli%get_int("nmax")
    c%seed = cli%get_int("seed")
    c%mean = cli%get_real("mean")
    c%sd = cli%get_real("sd")
    c%bins = cli%get_int("bins")
    c%precision = trim(merge("auto", "qp  ", precision_is_auto(cli)))
    c%v0 = scene%v0
    call check_settings()

    call run_stream()
    call gather_stream()
    if (ranks%rank == 0) call write_results()
    call ranks_finish(ranks, stat, rank_msg)
    call stop_unless_normal(stat, rank_msg)

contains

    !> On rank 0, with every block gathered: the counts, the statistics, the
    !> tables and the line that says how long the stream took.
    subroutine write_results()
        call add_counts()
        call c2_statistics(c, scene, error)
        if (allocated(error)) call fail(error)
        call c2_write_tables(c, out, error)
        if (allocated(error)) call fail(error)
        call say(name//": "//itoa(c%nmax)//" runs in "//fixed(seconds) &
            //" s ("//fixed(1.0e6_dp*seconds/c%nmax)//" us per run); tables in "//out)
    end subroutine write_results

    !> This rank's blocks of the stream (all of them on one process), timed:
    !> the part in the main sample first, then the part after it.
    subroutine run_stream()
        integer(int64) :: clock1
        integer :: lo, hi
        n_blocks = (c%nmax - 1)/mc_block_size + 1
        call block_range(n_blocks, ranks%n_ranks, ranks%rank, b_own_first, b_own_last)
        allocate (c%v4(c%nmax), c%e(c%nmax), main_counts(n_blocks), rest_counts(n_blocks))
        terminal = ranks%rank == 0 .and. stderr_is_terminal()
        shown = .false.
        call system_clock(clock0, clock_rate)
        clock_shown = clock0
        if (b_own_last >= b_own_first) then
            lo = (b_own_first - 1)*mc_block_size + 1
            hi = min(b_own_last*mc_block_size, c%nmax)
            if (lo <= c%n) call run_part(lo, min(hi, c%n), main_counts)
            if (hi > c%n) call run_part(max(lo, c%n + 1), hi, rest_counts)
        end if
        call system_clock(clock1)
        if (shown) write (error_unit, "(a)") ""
        seconds = real(clock1 - clock0, dp)/real(clock_rate, dp)
    end subroutine run_stream

    !> Samples first ... last of the stream, with the counts of each block
    !> they touch into block_counts at the block's index.
    subroutine run_part(first, last, block_counts)
        integer, intent(in) :: first, last
        type(mc_counts_t), intent(inout) :: block_counts(:)
        type(mc_counts_t) :: counts
        integer :: b_first, b_last
        b_first = (first - 1)/mc_block_size + 1
        b_last = (last - 1)/mc_block_size + 1
        call monte_carlo_v4(scene, c%mean, c%sd, c%seed, first, c%v4(first:last), &
            c%e(first:last), counts, stat, msg, progress=show_progress, &
            auto=c%precision == "auto", per_block=block_counts(b_first:b_last))
        call stop_unless_normal(stat, msg)
    end subroutine run_part

    !> Every block's samples and counts to rank 0 (nothing to do on one
    !> process): a block's record is its v4, its e, then its main and rest counts.
    subroutine gather_stream()
        type(record_t), allocatable :: records(:)
        integer(int8), allocatable :: bytes(:)
        integer :: b, lo, hi, k, n_v, n_c
        if (ranks%n_ranks == 1) return
        allocate (records(n_blocks))
        do b = b_own_first, b_own_last
            lo = (b - 1)*mc_block_size + 1
            hi = min(b*mc_block_size, c%nmax)
            records(b)%bytes = [transfer(c%v4(lo:hi), [0_int8]), transfer(c%e(lo:hi), [0_int8]), &
                transfer(main_counts(b), [0_int8]), transfer(rest_counts(b), [0_int8])]
        end do
        call gather_records(ranks, layout_blocks, records, stat, rank_msg)
        call stop_unless_normal(stat, rank_msg)
        if (ranks%rank /= 0) return
        n_c = size(transfer(main_counts(1), [0_int8]))
        do b = 1, n_blocks
            lo = (b - 1)*mc_block_size + 1
            hi = min(b*mc_block_size, c%nmax)
            n_v = size(transfer(c%v4(lo:hi), [0_int8]))
            if (size(records(b)%bytes) /= 2*n_v + 2*n_c) call fail("block " &
                //itoa(b)//" of the stream: its record gathered on rank 0 is damaged")
            bytes = records(b)%bytes
            k = 0
            c%v4(lo:hi) = transfer(bytes(k + 1:k + n_v), c%v4(lo:hi))
            k = k + n_v
            c%e(lo:hi) = transfer(bytes(k + 1:k + n_v), c%e(lo:hi))
            k = k + n_v
            main_counts(b) = transfer(bytes(k + 1:k + n_c), main_counts(b))
            rest_counts(b) = transfer(bytes(k + n_c + 1:k + 2*n_c), rest_counts(b))
            deallocate (records(b)%bytes)
        end do
    end subroutine gather_stream

    !> The counts of the main sample and the runs escalated in the whole
    !> stream, the blocks' counts added in block order (integers and a
    !> maximum: the same for any split of the blocks).
    subroutine add_counts()
        integer :: b
        c%counts = mc_counts_t()
        c%escalated_nmax = 0
        do b = 1, n_blocks
            associate (m => main_counts(b), t => c%counts)
                t%runs = t%runs + m%runs
                t%redraws = t%redraws + m%redraws
                t%collisions = t%collisions + m%collisions
                t%collapsed = t%collapsed + m%collapsed
                t%incomplete = t%incomplete + m%incomplete
                t%escalated = t%escalated + m%escalated
                t%bound_max = max(t%bound_max, m%bound_max)
            end associate
            c%escalated_nmax = c%escalated_nmax + main_counts(b)%escalated &
                + rest_counts(b)%escalated
        end do
    end subroutine add_counts

    !> On a terminal, after report_after seconds: the share of the runs done,
    !> on one line of stderr rewritten in place.
    subroutine show_progress(done, total)
        integer(int64), intent(in) :: done, total
        integer(int64) :: now
        if (.not. terminal) return
        call system_clock(now)
        if (real(now - clock0, dp) < report_after*clock_rate) return
        if (real(now - clock_shown, dp) < report_every*clock_rate .and. done < total) return
        clock_shown = now
        shown = .true.
        write (error_unit, "(a, i0, a, i0, a)", advance="no") achar(13)//name//": ", &
            (100*done)/total, " % of ", total, " runs"
        flush (error_unit)
    end subroutine show_progress

    !> Refuse settings outside their ranges before any work is done.
    !> The keys of c2: the sample, the law of e, the histogram, and the scene
    !> keys but e, which is sampled.
    subroutine define_keys()
        call start_program(cli, name, &
            "Task c2 of ARGESIM Comparison 12: e ~ N(mean, sd^2), drawn by Box-Muller"//nl// &
            "from GSL's MT19937 and truncated to 0 <= e <= 1 (draws outside are drawn"//nl// &
            "again and counted); each row is run in real(16), or with precision=auto in"//nl// &
            "real(64) where a rounding certificate holds. Writes c2_answers.tsv,"//nl// &
            "c2_ecdf.tsv, c2_histogram.tsv and c2_convergence.tsv into the directory out.")
        call cli%add_int("n", "1000000", "main sample size", lo=n_least, hi=n_most)
        call cli%add_int("nmax", "", "largest N of the convergence table (rows 10^2, 10^3," &
            //" ..., n, nmax; one stream), at least n", lo=n_least, hi=n_most, shown="n")
        call cli%add_int("seed", "12", "MT19937 seed", lo=1)
        call cli%add_real("mean", "0.5", "mean of e; at least 10 % of the law in [0, 1]")
        call cli%add_real("sd", "0.05", "standard deviation of e", lo=0.0_qp, lo_open=.true.)
        call cli%add_int("bins", "100", "histogram bins", lo=1, hi=bins_most)
        call add_row_keys(cli, e_set_by="the normal law of e")
    end subroutine define_keys

    !> What the keys' own ranges cannot say: nmax >= n and enough of the law
    !> of e inside [0, 1] for the truncation to draw again rarely.
    subroutine check_settings()
        if (c%nmax < c%n) call fail("nmax = "//cli%get_text("nmax")//": allowed an integer " &
            //"n <= nmax <= "//itoa(n_most)//" (n = "//itoa(c%n)//")")
        if (.not. (1.0_dp - normal_mass_outside_unit(c%mean, c%sd) >= min_acceptance)) then
            call fail("mean = "//cli%get_text("mean")//", sd = "//cli%get_text("sd") &
                //": under 10 % of the normal law lies in 0 <= e <= 1; allowed at least 10 %")
        end if
    end subroutine check_settings

    !> Three decimals with the leading zero that f0.3 leaves out.
    pure function fixed(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write (buf, "(f32.3)") x
        s = trim(adjustl(buf))
    end function fixed

end program c12_c2
