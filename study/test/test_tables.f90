!> Tests of the study's table files: a table gets its name only when every
!> byte written reached the disk; one that did not, or one left unfinished, is
!> removed.
module test_tables
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: status_normal
    use sphere_row_tables, only: open_table, close_table, discard_tables, file_exists
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text
    implicit none
    private
    public :: collect_tables

    character(len=*), parameter :: dir = "build/test_tables"

contains

    !> The tables' tests.
    function collect_tables() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("table_renamed_when_complete", test_complete), &
            new_unittest("table_short_on_disk_removed", test_short), &
            new_unittest("unfinished_tables_discarded", test_discard) &
            ]
    end function collect_tables

    !> A complete table has its name and no temporary file is left.
    subroutine test_complete(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: unit, stat
        character(len=300) :: msg
        call execute_command_line("rm -rf "//dir)
        call open_table(dir, "a.tsv", "x"//achar(9)//"y", unit, stat, msg)
        call check(error, stat == status_normal, "open_table: "//trim(msg))
        if (allocated(error)) return
        call check(error, file_exists(dir//"/a.tsv.tmp") .and. &
            .not. file_exists(dir//"/a.tsv"), "while written, the table is a.tsv.tmp only")
        write (unit, "(a)") "1"//achar(9)//"2"
        call close_table(unit, stat, msg)
        call check(error, stat == status_normal, "close_table: "//trim(msg))
        call check(error, read_text(dir//"/a.tsv") == "x"//achar(9)//"y"//new_line("a")//"1" &
            //achar(9)//"2"//new_line("a"), "a.tsv: "//read_text(dir//"/a.tsv"))
        call check(error, .not. file_exists(dir//"/a.tsv.tmp"), "a.tsv.tmp left behind")
    end subroutine test_complete

    !> Bytes that did not reach the disk (here: the table's temporary name is
    !> a link to /dev/full, which takes no byte, as a full disk; gfortran
    !> reports neither) make the table an error, and it is removed; the table
    !> of that name before stays as it was.
    subroutine test_short(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: unit, stat, i
        character(len=300) :: msg
        call execute_command_line("rm -rf "//dir//" && mkdir -p "//dir//" && echo old > " &
            //dir//"/b.tsv && ln -s /dev/full "//dir//"/b.tsv.tmp")
        call open_table(dir, "b.tsv", "n", unit, stat, msg)
        call check(error, stat == status_normal, "open_table: "//trim(msg))
        if (allocated(error)) return
        do i = 1, 5000
            write (unit, "(i0)") i
        end do
        call close_table(unit, stat, msg)
        call check(error, stat /= status_normal, "a table short on disk was accepted")
        call check(error, index(msg, "out = "//dir//"/b.tsv: cannot be written (only 0 of " &
            //"23895 bytes reached the disk)") == 1, "message: "//trim(msg))
        call check(error, .not. file_exists(dir//"/b.tsv.tmp"), "b.tsv.tmp left behind")
        call check(error, read_text(dir//"/b.tsv") == "old"//new_line("a"), &
            "the previous b.tsv changed")
    end subroutine test_short

    !> discard_tables, as a program that fails calls it, removes every table
    !> still being written.
    subroutine test_discard(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: unit_c, unit_d, stat
        character(len=300) :: msg
        call execute_command_line("rm -rf "//dir)
        call open_table(dir, "c.tsv", "c", unit_c, stat, msg)
        call open_table(dir, "d.tsv", "d", unit_d, stat, msg)
        call check(error, stat == status_normal, "open_table: "//trim(msg))
        if (allocated(error)) return
        call discard_tables()
        call check(error, .not. (file_exists(dir//"/c.tsv.tmp") .or. &
            file_exists(dir//"/d.tsv.tmp") .or. file_exists(dir//"/c.tsv") .or. &
            file_exists(dir//"/d.tsv")), "a table was left")
    end subroutine test_discard

end module test_tables
