!> Tests of the sharing of a sweep's items over processes: every item has one
!> owner under both layouts, the blocks are the owners' ranges, a rank with
!> a missing result is refused, and an e_c row survives its trip as bytes.
module test_ranks
    use, intrinsic :: iso_fortran_env, only: int8
    use sphere_row, only: qp, itoa, status_normal, status_invalid
    use sphere_row_ranks, only: ranks_t, record_t, owner_of, block_range, gather_records, &
        layout_cyclic, layout_blocks
    use sphere_row_ecrit, only: ecrit_settings_t, ecrit_row_t, ecrit_row, row_bytes, &
        row_from_bytes
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_ranks

contains

    !> The ranks tests (one process: gathering over MPI ranks is what
    !> `make test-mpi` compares).
    function collect_ranks() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("blocks_are_owners_ranges", test_blocks), &
            new_unittest("cyclic_owners", test_cyclic), &
            new_unittest("gather_refuses_missing", test_missing), &
            new_unittest("row_bytes_round_trip", test_round_trip) &
            ]
    end function collect_ranks

    !> For n items on r ranks (fewer, as many and more items than ranks) the
    !> blocks follow each other from item 1 to n, differ in length by at most
    !> one, and owner_of names the block's rank for each of its items.
    subroutine test_blocks(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: n, r, rank, first, last, next, i, shortest, longest
        do n = 0, 13
            do r = 1, 5
                next = 1
                shortest = huge(1)
                longest = 0
                do rank = 0, r - 1
                    call block_range(n, r, rank, first, last)
                    call check(error, first == next, "n = "//itoa(n)//", ranks = "//itoa(r) &
                        //": block of rank "//itoa(rank)//" starts at "//itoa(first))
                    if (allocated(error)) return
                    do i = first, last
                        call check(error, owner_of(i, n, r, layout_blocks) == rank, "n = " &
                            //itoa(n)//", ranks = "//itoa(r)//": item "//itoa(i) &
                            //" owned by "//itoa(owner_of(i, n, r, layout_blocks)))
                        if (allocated(error)) return
                    end do
                    shortest = min(shortest, last - first + 1)
                    longest = max(longest, last - first + 1)
                    next = last + 1
                end do
                call check(error, next == n + 1 .and. longest - shortest <= 1, "n = "//itoa(n) &
                    //", ranks = "//itoa(r)//": blocks end at "//itoa(next - 1)//", lengths " &
                    //itoa(shortest)//" ... "//itoa(longest))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_blocks

    !> Cyclic: neighbours on consecutive ranks, each rank with n/r or n/r + 1.
    subroutine test_cyclic(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: n = 11, r = 4
        integer :: owners(n), i, rank
        owners = owner_of([(i, i=1, n)], n, r, layout_cyclic)
        call check(error, all(owners == [0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2]), "owners "// &
            itoa(owners(1))//" "//itoa(owners(2))//" ... "//itoa(owners(n)))
        if (allocated(error)) return
        do rank = 0, r - 1
            call check(error, count(owners == rank) >= n/r .and. count(owners == rank) <= n/r + 1, &
                "rank "//itoa(rank)//" owns "//itoa(count(owners == rank))//" items")
            if (allocated(error)) return
        end do
    end subroutine test_cyclic

    !> A rank whose own item has no record is refused; with all of them the
    !> records come back as they were.
    subroutine test_missing(error)
        type(error_t), allocatable, intent(out) :: error
        type(ranks_t) :: ranks
        type(record_t) :: records(3)
        character(len=:), allocatable :: msg
        integer :: stat
        records(1)%bytes = [1_int8, 2_int8]
        records(3)%bytes = [3_int8]
        call gather_records(ranks, layout_cyclic, records, stat, msg)
        call check(error, stat == status_invalid .and. index(msg, "item 2") > 0, &
            "a missing record of item 2 gave status "//itoa(stat)//" ("//msg//")")
        if (allocated(error)) return
        records(2)%bytes = [integer(int8) ::]
        call gather_records(ranks, layout_blocks, records, stat, msg)
        call check(error, stat == status_normal .and. size(records(2)%bytes) == 0 .and. &
            all(records(1)%bytes == [1_int8, 2_int8]) .and. all(records(3)%bytes == [3_int8]), &
            "one process: the records changed, status "//itoa(stat)//" ("//msg//")")
    end subroutine test_missing

    !> The row of p = 3 (cycle, rate map, closed form, the scans in real(16),
    !> real64 and at the deep tol: every field set) read back from its bytes
    !> writes the same bytes, and its fields are equal; a cut record is
    !> refused.
    subroutine test_round_trip(error)
        type(error_t), allocatable, intent(out) :: error
        type(ecrit_settings_t) :: s
        type(ecrit_row_t) :: row, back
        integer(int8), allocatable :: bytes(:)
        integer :: stat
        s%n_grid = 10
        s%n_scan = 12
        s%robust_p_max = 3
        call ecrit_row(3, s, row)
        call check(error, row%has_map .and. row%form%found .and. size(row%cycle) > 0 .and. &
            size(row%outcomes_dp) == 12 .and. size(row%outcomes_deep) == 12 .and. &
            any(row%decades /= 0), "p = 3: the row does not set every field")
        if (allocated(error)) return
        bytes = row_bytes(row)
        call row_from_bytes(bytes, back, stat)
        call check(error, stat == status_normal, "p = 3: its own bytes refused")
        if (allocated(error)) return
        call check(error, all(row_bytes(back) == bytes) .and. back%e_map == row%e_map .and. &
            back%form%text == row%form%text .and. all(back%cycle == row%cycle) .and. &
            back%b%e_low == row%b%e_low .and. (back%has_map .eqv. row%has_map) .and. &
            all(back%outcomes == row%outcomes) .and. all(back%decades == row%decades) .and. &
            all(back%outcomes_deep == row%outcomes_deep) .and. back%e_to == row%e_to, &
            "p = 3: the row read back differs")
        if (allocated(error)) return
        call row_from_bytes(bytes(:size(bytes) - 1), back, stat)
        call check(error, stat == status_invalid, "a record one byte short was read")
        if (allocated(error)) return
        call row_from_bytes(bytes(:size(bytes) - 4), back, stat)
        call check(error, stat == status_invalid, "a record one integer short was read")
    end subroutine test_round_trip

end module test_ranks
