!> Test driver of the engine and the CLI: runs every suite and ends with
!> `N passed, N failed`.
program check
    use testsuite, only: new_suite, run_suites
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
    call run_suites([ &
        new_suite("engine", collect_engine()), &
        new_suite("collapse", collect_collapse()), &
        new_suite("calendar", collect_calendar()), &
        new_suite("limits", collect_limits()), &
        new_suite("replays", collect_replays()), &
        new_suite("labels", collect_labels()), &
        new_suite("scenes", collect_scenes()), &
        new_suite("proofs", collect_proofs()), &
        new_suite("auto", collect_auto()), &
        new_suite("front", collect_front()), &
        new_suite("cli", collect_cli())])
end program check
