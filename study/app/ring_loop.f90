!> c12-ring-loop: the tight event loop of a ring of equal spheres
!> (sphere_row_ring.inc) as a whole process, the yardstick of `sphere-row
!> gas=ring` as one (c12-bench): the same random gas (the library's
!> gas_state: the same seed gives the same state), run to t_max in real(8) or
!> real(16), collisions below `cutoff` elastic if asked; prints the
!> collisions and the temperature at t_max.
program c12_ring_loop
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, dp, real_str, itoa
    use sphere_row_gas, only: gas_state
    use sphere_row_ring_dp, only: ring_dp => ring_run
    use sphere_row_ring_qp, only: ring_qp => ring_run
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, say
    implicit none
    type(cli_t) :: cli
    integer :: p, budget, n
    real(qp), allocatable :: gaps(:), v(:), m(:)
    real(qp) :: t_end, temperature(1), per_sphere(1)
    real(dp) :: t_end_dp, temperature_dp(1), per_sphere_dp(1)
    logical :: ok

    call start_program(cli, "c12-ring-loop", &
        "The study's tight event loop on the random ring gas of sphere-row gas=ring (no"//nl// &
        "collapse rules, no output but a line): the yardstick of sphere-row's price on it.", &
        tables=.false.)
    call cli%add_int("p", "100000", "spheres", lo=3, hi=100000000)
    call cli%add_real("e", "0.99", "coefficient of restitution", lo=0.0_qp, hi=1.0_qp)
    call cli%add_real("density", "0.5", "spheres per unit length (diameter 1)", lo=0.0_qp, &
        hi=1.0_qp, lo_open=.true., hi_open=.true.)
    call cli%add_real("temperature", "1", "the temperature at t = 0", lo=0.0_qp, lo_open=.true.)
    call cli%add_int("seed", "1", "the gas's random seed", lo=0)
    call cli%add_real("t_max", "1", "the horizon", lo=0.0_qp, lo_open=.true.)
    call cli%add_real("cutoff", "0", "collisions slower than this are elastic", lo=0.0_qp)
    call cli%add_int("max_collisions", "0", "collisions at most (0: no limit)", lo=0)
    call cli%add_choice("kind", "dp", [character(len=2) :: "qp", "dp"], &
        "qp: real(16); dp: real(8)")
    call read_keys(cli)
    p = cli%get_int("p")
    budget = cli%get_int("max_collisions")
    if (budget == 0) budget = huge(1)
    allocate (gaps(p), v(p), m(p))
    m = 1
    call gas_state(p, 1.0_qp, m, cli%get_real("density"), cli%get_real("temperature"), &
        int(cli%get_int("seed"), int64), gaps, v, ok)
    if (cli%get_word("kind") == "dp") then
        call ring_dp(p, real(cli%get_real("e"), dp), real(cli%get_real("cutoff"), dp), &
            real(gaps, dp), real(v, dp), [real(cli%get_real("t_max"), dp)], budget, n, &
            t_end_dp, temperature_dp, per_sphere_dp)
        t_end = real(t_end_dp, qp)
        temperature = real(temperature_dp, qp)
    else
        call ring_qp(p, cli%get_real("e"), cli%get_real("cutoff"), gaps, v, &
            [cli%get_real("t_max")], budget, n, t_end, temperature, per_sphere)
    end if
    call say("c12-ring-loop: "//itoa(n)//" collisions, last at "//real_str(t_end, 17)// &
        ", temperature at t_max "//real_str(temperature(1), 17))
end program c12_ring_loop
