!> Collapse in general rows: a seeded survey of random rows of spheres (see
!> sphere_row_survey), each run to its end with the collapse cycle limits and
!> once more with the fallback rule alone, with the invariants checked.
program c12_collapse
    use, intrinsic :: iso_fortran_env, only: error_unit
    use sphere_row, only: qp, scene_t, run_t, simulate, status_max_collisions
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene, &
        check_invariants
    use sphere_row_args, only: get_args, int_key, unused_arg, wants_help
    use sphere_row_status, only: status_normal
    implicit none
    type(survey_t) :: survey
    type(scene_t) :: scene
    type(run_t) :: run
    character(len=:), allocatable :: args(:)
    logical, allocatable :: used(:)
    character(len=300) :: msg
    character(len=40) :: why
    integer :: n, seed, i, stat, n_max, n_bad, worst_n, cap, show
    real :: t0, t1, worst_t
    call get_args(args)
    allocate (used(size(args)))
    used = .false.
    n = 10000
    seed = 12
    call int_key(args, used, "n", n, 1, huge(1), stat, msg)
    call int_key(args, used, "seed", seed, 0, huge(1), stat, msg)
    show = 0
    call int_key(args, used, "show", show, 0, huge(1), stat, msg)
    cap = 100000
    call int_key(args, used, "cap", cap, 1, huge(1), stat, msg)
    call survey_open(survey, seed, 2, 20, 1.0e3_qp)
    n_max = 0
    n_bad = 0
    worst_t = 0
    worst_n = 0
    do i = 1, n
        call survey_scene(survey, scene)
        scene%max_collisions = cap
        if (show > 0) then
            if (i /= show) cycle
            print "(a, i0, a, g0, a)", "p=", scene%p, " e=", scene%e, " masses=\"
            print "(*(g0, :, ','))", scene%m
            print "(a)", "gaps=\"
            print "(*(g0, :, ','))", scene%a
            exit
        end if
        call cpu_time(t0)
        call simulate(scene, run)
        call cpu_time(t1)
        if (t1 - t0 > worst_t) then
            worst_t = t1 - t0
            worst_n = i
        end if
        if (run%status == status_max_collisions) then
            n_max = n_max + 1
            if (n_max < 40) print "(i6, i4, f8.4, 2es10.2, l3, i8, i5, i5)", i, scene%p, &
                real(scene%e), real(maxval(scene%m)/minval(scene%m)), real(t1 - t0), &
                any(scene%a == 0), run%n, run%collapses, run%closed_limits
        end if
        call check_invariants(scene, run, 1.0e4_qp, why)
        if (why /= "") then
            n_bad = n_bad + 1
            if (n_bad < 20) print *, i, scene%p, real(scene%e), trim(why), run%n, run%collapses, &
                run%closed_limits
        end if
    end do
    print *, "scenes", n, "max_collisions", n_max, "invariant failures", n_bad, &
        "slowest", worst_t, worst_n
    call survey_close(survey)
end program c12_collapse
