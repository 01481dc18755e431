!> c12-tight-loop: the tight event loop of the study (sphere_row_tight.inc)
!> as a whole process, the yardstick of `sphere-row` as one (c12-bench): a
!> row of p equal spheres, gaps 1, struck at one end by v0 = 1, run to its
!> end (or max_collisions) in real(16) or real(8) at that kind's epsilon as
!> tol; prints the collisions, t_end and the row's momentum (v0 times one
!> mass: 1, to rounding).
program c12_tight_loop
    use sphere_row, only: qp, dp, real_str, itoa
    use sphere_row_tight_qp, only: tight_qp => tight_run
    use sphere_row_tight_dp, only: tight_dp => tight_run
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, say
    implicit none
    type(cli_t) :: cli
    integer :: p, budget, n
    real(qp) :: e, t_end, momentum
    real(dp) :: t_end_dp, momentum_dp
    logical :: two

    call start_program(cli, "c12-tight-loop", &
        "The study's tight event loop on a struck row of p equal spheres (no collapse"//nl// &
        "rules, no output but a line): the yardstick of sphere-row's price.", tables=.false.)
    call cli%add_int("p", "1000000", "spheres", lo=2, hi=100000000)
    call cli%add_real("e", "1", "coefficient of restitution", lo=0.0_qp, hi=1.0_qp)
    call cli%add_int("max_collisions", "0", "collisions at most (0: no limit)", lo=0)
    call cli%add_choice("kind", "qp", [character(len=2) :: "qp", "dp"], &
        "qp: real(16); dp: real(8)")
    call cli%add_choice("clock", "one", [character(len=3) :: "one", "two"], &
        "the clock in one real, or in two as the engine's calendar carries it")
    call read_keys(cli)
    p = cli%get_int("p")
    e = cli%get_real("e")
    budget = cli%get_int("max_collisions")
    if (budget == 0) budget = huge(1)
    two = cli%get_word("clock") == "two"
    if (cli%get_word("kind") == "dp") then
        call tight_dp(p, real(e, dp), 1.0_dp, epsilon(1.0_dp), budget, two, n, t_end_dp, &
            momentum_dp)
        t_end = real(t_end_dp, qp)
        momentum = real(momentum_dp, qp)
    else
        call tight_qp(p, e, 1.0_qp, epsilon(1.0_qp), budget, two, n, t_end, momentum)
    end if
    call say("c12-tight-loop: "//itoa(n)//" collisions, t_end "//real_str(t_end, 34)// &
        ", momentum "//real_str(momentum, 17))
end program c12_tight_loop
