!> Test driver of the study: runs every suite and ends with `N passed, N failed`.
program check
    use testsuite, only: new_suite, run_suites
    use test_study, only: collect_study
    use test_monte_carlo, only: collect_monte_carlo
    use test_mc_blocks, only: collect_mc_blocks
    use test_methods, only: collect_methods
    use test_ecrit, only: collect_ecrit
    use test_lean, only: collect_lean
    use test_auto, only: collect_auto
    use test_ranks, only: collect_ranks
    use test_tables, only: collect_tables
    use test_spacetime, only: collect_spacetime
    implicit none
    call run_suites([ &
        new_suite("study", collect_study()), &
        new_suite("monte_carlo", collect_monte_carlo()), &
        new_suite("mc_blocks", collect_mc_blocks()), &
        new_suite("methods", collect_methods()), &
        new_suite("ecrit", collect_ecrit()), &
        new_suite("lean", collect_lean()), &
        new_suite("auto", collect_auto()), &
        new_suite("ranks", collect_ranks()), &
        new_suite("tables", collect_tables()), &
        new_suite("spacetime", collect_spacetime())])
end program check
