!> The processes of a sweep: which items (row lengths p, sample blocks) each
!> process computes, and the ordered gathering of their results on process 0.
!>
!> Built with `-DSPHERE_ROW_MPI` (and mpifort) the processes are the ranks of
!> MPI_COMM_WORLD; without it there is one process, every item is its own and
!> gathering leaves the results as they are. The items are split by a fixed
!> rule of (item, number of ranks) alone, every item is computed by exactly
!> one rank, and the results come back to rank 0 indexed by item: whatever
!> rank 0 then does with them (write rows, add partial sums in item order)
!> gives the same bits for any number of ranks.
!>
!> A sweep over n items:
!>
!>     call ranks_start(ranks, stat, msg)
!>     do i = 1, n
!>         if (owner_of(i, n, ranks%n_ranks, layout_cyclic) /= ranks%rank) cycle
!>         ... compute item i; records(i)%bytes = its result as bytes
!>     end do
!>     call gather_records(ranks, layout_cyclic, records, stat, msg)
!>     if (ranks%rank == 0) ... every records(i) is filled, in item order
!>     call ranks_finish(ranks, stat, msg)
module sphere_row_ranks
#ifdef SPHERE_ROW_MPI
    use mpi_f08, only: mpi_init_thread, mpi_initialized, mpi_finalize, mpi_finalized, &
        mpi_comm_rank, mpi_comm_size, mpi_gatherv, mpi_comm_world, mpi_integer, mpi_integer1, &
        mpi_thread_funneled, mpi_success
#endif
    use, intrinsic :: iso_fortran_env, only: int8, int64
    use sphere_row, only: status_normal, status_invalid, itoa
    implicit none
    private
    public :: ranks_t, record_t, with_mpi, layout_cyclic, layout_blocks
    public :: ranks_start, ranks_finish, owner_of, block_range, gather_records

    !> True if the program was built with MPI.
#ifdef SPHERE_ROW_MPI
    logical, parameter :: with_mpi = .true.
#else
    logical, parameter :: with_mpi = .false.
#endif

    !> Item i goes to rank mod(i - 1, n_ranks): neighbours on different ranks,
    !> so a cost that grows along the items is shared evenly.
    integer, parameter :: layout_cyclic = 1
    !> The items in n_ranks contiguous blocks, the first mod(n, n_ranks) one
    !> item longer: each rank's items are one range (block_range).
    integer, parameter :: layout_blocks = 2

    !> This process among all of the sweep.
    type :: ranks_t
        !> Its rank, 0 ... n_ranks - 1; rank 0 gathers and writes.
        integer :: rank = 0
        !> Number of processes.
        integer :: n_ranks = 1
        !> True if ranks_start initialised MPI (and ranks_finish ends it).
        logical :: started = .false.
    end type ranks_t

    !> The result of one item as bytes (`transfer` of its numbers), of any
    !> length; unallocated where the item is not this rank's.
    type :: record_t
        integer(int8), allocatable :: bytes(:)
    end type record_t

contains

    !> Join the processes of the sweep: MPI initialised (if not yet, with
    !> threads that leave MPI calls to the main one) and this rank found.
    !> Without MPI: rank 0 of 1.
    subroutine ranks_start(ranks, stat, msg)
        type(ranks_t), intent(out) :: ranks
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
#ifdef SPHERE_ROW_MPI
        logical :: ready
        integer :: provided, ierr
        stat = status_invalid
        call mpi_initialized(ready, ierr)
        if (.not. ready) then
            call mpi_init_thread(mpi_thread_funneled, provided, ierr)
            if (ierr /= mpi_success) then
                msg = "MPI_Init_thread failed with error "//itoa(ierr)
                return
            end if
            ranks%started = .true.
            if (provided < mpi_thread_funneled) then
                msg = "the MPI library offers no threads (level "//itoa(provided) &
                    //"), OpenMP threads need MPI_THREAD_FUNNELED"
                return
            end if
        end if
        call mpi_comm_rank(mpi_comm_world, ranks%rank, ierr)
        call mpi_comm_size(mpi_comm_world, ranks%n_ranks, ierr)
#endif
        stat = status_normal
        msg = ""
    end subroutine ranks_start

    !> Leave the sweep: MPI finalised if ranks_start initialised it.
    subroutine ranks_finish(ranks, stat, msg)
        type(ranks_t), intent(inout) :: ranks
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
#ifdef SPHERE_ROW_MPI
        logical :: done
        integer :: ierr
        stat = status_invalid
        call mpi_finalized(done, ierr)
        if (ranks%started .and. .not. done) then
            call mpi_finalize(ierr)
            if (ierr /= mpi_success) then
                msg = "MPI_Finalize failed with error "//itoa(ierr)
                return
            end if
        end if
#endif
        ranks%started = .false.
        stat = status_normal
        msg = ""
    end subroutine ranks_finish

    !> The items first ... last of `rank` when n items are cut into n_ranks
    !> contiguous blocks (layout_blocks); last < first if it has none.
    pure subroutine block_range(n, n_ranks, rank, first, last)
        integer, intent(in) :: n, n_ranks, rank
        integer, intent(out) :: first, last
        integer :: base, extra
        base = n/n_ranks
        extra = mod(n, n_ranks)
        first = rank*base + min(rank, extra) + 1
        last = first + base - 1
        if (rank < extra) last = last + 1
    end subroutine block_range

    !> The rank that computes item i of n under `layout`.
    elemental integer function owner_of(i, n, n_ranks, layout) result(owner)
        integer, intent(in) :: i, n, n_ranks, layout
        integer :: base, extra
        if (layout == layout_cyclic) then
            owner = mod(i - 1, n_ranks)
        else
            ! ranks below `extra` hold base + 1 items, the others base
            base = n/n_ranks
            extra = mod(n, n_ranks)
            if (i <= extra*(base + 1)) then
                owner = (i - 1)/(base + 1)
            else
                owner = extra + (i - 1 - extra*(base + 1))/base
            end if
        end if
    end function owner_of

    !> Bring every item's record to rank 0: on entry each rank holds the
    !> records of its own items (owner_of under `layout`), on return rank 0
    !> holds all of them, each at its item's index; the other ranks' records
    !> are left as they were. Collective: every rank calls it with the same
    !> number of items. Without MPI nothing moves. `stat` is status_invalid
    !> (and `msg` says why) if an own record is missing or the bytes of a
    !> rank do not fit a default integer count.
    subroutine gather_records(ranks, layout, records, stat, msg)
        type(ranks_t), intent(in) :: ranks
        integer, intent(in) :: layout
        type(record_t), intent(inout) :: records(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
        integer :: i
        stat = status_invalid
        do i = 1, size(records)
            if (owner_of(i, size(records), ranks%n_ranks, layout) /= ranks%rank) cycle
            if (.not. allocated(records(i)%bytes)) then
                msg = "item "//itoa(i)//": no result on rank "//itoa(ranks%rank)
                return
            end if
        end do
#ifdef SPHERE_ROW_MPI
        if (ranks%n_ranks > 1) then
            call gather_mpi(ranks, layout, records, stat, msg)
            return
        end if
#endif
        stat = status_normal
        msg = ""
    end subroutine gather_records

#ifdef SPHERE_ROW_MPI
    !> gather_records over MPI: the lengths of the records first, then their
    !> bytes, each rank's own in item order, both by MPI_Gatherv to rank 0.
    subroutine gather_mpi(ranks, layout, records, stat, msg)
        type(ranks_t), intent(in) :: ranks
        integer, intent(in) :: layout
        type(record_t), intent(inout) :: records(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
        integer :: n, r, i, k, ierr, owner(size(records)), lengths(size(records))
        integer, dimension(0:ranks%n_ranks - 1) :: items, item_offsets, byte_counts, byte_offsets
        integer, allocatable :: own_lengths(:), order(:)
        integer(int8), allocatable :: own_bytes(:), bytes(:)
        integer(int64) :: total
        stat = status_invalid
        n = size(records)
        owner = owner_of([(i, i=1, n)], n, ranks%n_ranks, layout)
        do r = 0, ranks%n_ranks - 1
            items(r) = count(owner == r)
        end do
        item_offsets = offsets(items)
        ! the items as rank 0 receives them: rank by rank, each in item order
        order = [(pack([(i, i=1, n)], owner == r), r=0, ranks%n_ranks - 1)]
        own_lengths = pack([(size(records(i)%bytes), i=1, n)], owner == ranks%rank)
        total = sum(int(own_lengths, int64))
        if (total > huge(1)) then
            msg = "rank "//itoa(ranks%rank)//": results of more than "//itoa(huge(1)) &
                //" bytes, more than one MPI message can hold"
            return
        end if
        allocate (own_bytes(total))
        k = 0
        do i = 1, n
            if (owner(i) /= ranks%rank) cycle
            own_bytes(k + 1:k + size(records(i)%bytes)) = records(i)%bytes
            k = k + size(records(i)%bytes)
        end do
        call mpi_gatherv(own_lengths, size(own_lengths), mpi_integer, lengths, items, &
            item_offsets, mpi_integer, 0, mpi_comm_world, ierr)
        if (ierr /= mpi_success) then
            msg = "MPI_Gatherv of the record lengths failed with error "//itoa(ierr)
            return
        end if
        byte_counts = 0
        if (ranks%rank == 0) then
            total = sum(int(lengths, int64))
            if (total > huge(1)) then
                msg = "results of more than "//itoa(huge(1))//" bytes in all, more than " &
                    //"rank 0 can receive in one MPI message"
                return
            end if
            do r = 0, ranks%n_ranks - 1
                byte_counts(r) = sum(lengths(item_offsets(r) + 1:item_offsets(r) + items(r)))
            end do
        end if
        byte_offsets = offsets(byte_counts)
        allocate (bytes(max(1, sum(byte_counts))))
        call mpi_gatherv(own_bytes, size(own_bytes), mpi_integer1, bytes, byte_counts, &
            byte_offsets, mpi_integer1, 0, mpi_comm_world, ierr)
        if (ierr /= mpi_success) then
            msg = "MPI_Gatherv of the records failed with error "//itoa(ierr)
            return
        end if
        if (ranks%rank == 0) then
            k = 0
            do i = 1, n
                records(order(i))%bytes = bytes(k + 1:k + lengths(i))
                k = k + lengths(i)
            end do
        end if
        stat = status_normal
        msg = ""

    contains

        !> Where each part starts in the concatenation of parts of `sizes`.
        pure function offsets(sizes) result(starts)
            integer, intent(in) :: sizes(0:)
            integer :: starts(0:ubound(sizes, 1)), j
            starts(0) = 0
            do j = 1, ubound(sizes, 1)
                starts(j) = starts(j - 1) + sizes(j - 1)
            end do
        end function offsets

    end subroutine gather_mpi
#endif

end module sphere_row_ranks
