!> Test driver of the study: runs every suite and ends with `N passed, N failed`.
program check
    use testsuite, only: run_tests, read_test_options
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
    integer :: passed, failed
    passed = 0
    failed = 0
    call read_test_options(failed)
    call run_tests("study", collect_study(), passed, failed)
    call run_tests("monte_carlo", collect_monte_carlo(), passed, failed)
    call run_tests("mc_blocks", collect_mc_blocks(), passed, failed)
    call run_tests("methods", collect_methods(), passed, failed)
    call run_tests("ecrit", collect_ecrit(), passed, failed)
    call run_tests("lean", collect_lean(), passed, failed)
    call run_tests("auto", collect_auto(), passed, failed)
    call run_tests("ranks", collect_ranks(), passed, failed)
    call run_tests("tables", collect_tables(), passed, failed)
    call run_tests("spacetime", collect_spacetime(), passed, failed)
    print "(i0, ' passed, ', i0, ' failed')", passed, failed
    if (failed > 0) stop 1, quiet=.true.
end program check
