!> Test driver of the engine and the CLI: runs every suite and ends with
!> `N passed, N failed`.
program check
    use testsuite, only: run_tests, read_test_options
    use test_engine, only: collect_engine
    use test_collapse, only: collect_collapse
    use test_calendar, only: collect_calendar
    use test_auto, only: collect_auto
    use test_cli, only: collect_cli
    use test_front, only: collect_front
    use test_limits, only: collect_limits
    use test_replays, only: collect_replays
    use test_labels, only: collect_labels
    use test_scenes, only: collect_scenes
    use test_proofs, only: collect_proofs
    implicit none
    integer :: passed, failed
    passed = 0
    failed = 0
    call read_test_options(failed)
    call run_tests("engine", collect_engine(), passed, failed)
    call run_tests("collapse", collect_collapse(), passed, failed)
    call run_tests("calendar", collect_calendar(), passed, failed)
    call run_tests("limits", collect_limits(), passed, failed)
    call run_tests("replays", collect_replays(), passed, failed)
    call run_tests("labels", collect_labels(), passed, failed)
    call run_tests("scenes", collect_scenes(), passed, failed)
    call run_tests("proofs", collect_proofs(), passed, failed)
    call run_tests("auto", collect_auto(), passed, failed)
    call run_tests("front", collect_front(), passed, failed)
    call run_tests("cli", collect_cli(), passed, failed)
    print "(i0, ' passed, ', i0, ' failed')", passed, failed
    if (failed > 0) stop 1, quiet=.true.
end program check
