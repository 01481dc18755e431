!> The common record of a run of any method, and its comparison with a
!> reference run.
!>
!> Every method of the comparison (the engine in any kind, absolute variables, ODE
!> integration, time stepping) reports into one `outcome_t` in real128, so that
!> a study compares them with one piece of code. Converting a method's own kind
!> to real128 is exact, so nothing is lost on the way.
module sphere_row_outcome
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp
    use sphere_row_status, only: status_normal, status_collapsed, status_negative_gap, &
        status_invalid
    implicit none
    private
    public :: outcome_t, outcome_start, outcome_add
    public :: comparison_t, compare_outcomes
    public :: category_right, category_wrong_count, category_wrong_state
    public :: category_negative_gap, category_no_end, n_categories
    public :: classify, category_word

    !> Outcome of one run of one method.
    type :: outcome_t
        !> One of the status_* codes of sphere_row_status.
        integer :: status = status_invalid
        !> Why a run was refused or failed (blank otherwise).
        character(len=200) :: message = ""
        !> Number of binary collisions.
        integer :: n = 0
        !> Integrator steps (ODE) or time steps (stepping); 0 for event methods.
        integer(int64) :: steps = 0
        !> Time of the last collision [L/V].
        real(qp) :: t_end = 0.0_qp
        !> Most negative gap seen during the run [L]; 0 if no gap went negative.
        real(qp) :: min_gap = 0.0_qp
        !> Final absolute velocities [V], size p.
        real(qp), allocatable :: v(:)
        !> Final gaps [L], size p-1.
        real(qp), allocatable :: y(:)
        !> Whether the collisions below are recorded.
        logical :: recording = .false.
        !> Collision times [L/V] (recorded runs only; entries 1..n are valid).
        real(qp), allocatable :: t(:)
        !> Left sphere i of each colliding pair (i, i+1) (recorded runs only).
        integer, allocatable :: pair(:)
    end type outcome_t

    !> How a run compares with a reference run of the same scene.
    type :: comparison_t
        !> Same number of collisions.
        logical :: same_count = .false.
        !> Same number and the same pair at every collision (needs both runs
        !> recorded; false otherwise).
        logical :: same_sequence = .false.
        !> Leading collisions whose pairs agree.
        integer :: n_matched = 0
        !> Largest |v_i - v_i,ref| of the final velocities [V].
        real(qp) :: v_error = 0.0_qp
        !> Largest |t_j - t_j,ref| over the matched collisions [L/V].
        real(qp) :: t_error = 0.0_qp
    end type comparison_t

    !> Outcome categories of a run against its reference (stability map).
    !> Right: the run ended with the reference's collision sequence (or, where
    !> the reference collapsed, its quasi-plastic state) and final velocities
    !> within the tolerance given to `classify`.
    integer, parameter :: category_right = 0
    !> The run ended, but its count or sequence of collisions differs.
    integer, parameter :: category_wrong_count = 1
    !> The run ended with the right sequence, but wrong final velocities.
    integer, parameter :: category_wrong_state = 2
    !> The run stopped on a negative gap (status_negative_gap).
    integer, parameter :: category_negative_gap = 3
    !> The run did not end: a budget ran out or the solver failed.
    integer, parameter :: category_no_end = 4
    !> Number of categories.
    integer, parameter :: n_categories = 5

contains

    !> Prepare `out` for a run of p spheres, keeping its arrays when p is the
    !> same as before, so that timing loops do not allocate; `record` (absent:
    !> false, as in every method's own optional argument) asks for every
    !> collision.
    pure subroutine outcome_start(out, p, record)
        type(outcome_t), intent(inout) :: out
        integer, intent(in) :: p
        logical, intent(in), optional :: record
        integer, parameter :: first_capacity = 64
        logical :: keep
        if (allocated(out%v)) then
            if (size(out%v) /= p) deallocate (out%v, out%y)
        end if
        if (.not. allocated(out%v)) allocate (out%v(p), out%y(p - 1))
        out%status = status_invalid
        out%message = ""
        out%n = 0
        out%steps = 0
        out%t_end = 0.0_qp
        out%min_gap = 0.0_qp
        out%v = 0.0_qp
        out%y = 0.0_qp
        keep = .false.
        if (present(record)) keep = record
        out%recording = keep
        if (keep .and. .not. allocated(out%t)) then
            allocate (out%t(first_capacity), out%pair(first_capacity))
        end if
    end subroutine outcome_start

    !> Count one collision of pair (k, k+1) at time t, and record it if asked.
    pure subroutine outcome_add(out, t, k)
        type(outcome_t), intent(inout) :: out
        real(qp), intent(in) :: t
        integer, intent(in) :: k
        real(qp), allocatable :: t_new(:)
        integer, allocatable :: k_new(:)
        out%n = out%n + 1
        out%t_end = t
        if (.not. out%recording) return
        if (out%n > size(out%t)) then
            allocate (t_new(2*size(out%t)), k_new(2*size(out%t)))
            t_new(:size(out%t)) = out%t
            k_new(:size(out%t)) = out%pair
            call move_alloc(t_new, out%t)
            call move_alloc(k_new, out%pair)
        end if
        out%t(out%n) = t
        out%pair(out%n) = k
    end subroutine outcome_add

    !> Compare a run with a reference run of the same scene.
    pure function compare_outcomes(ref, out) result(cmp)
        type(outcome_t), intent(in) :: ref, out
        type(comparison_t) :: cmp
        integer :: j
        cmp%same_count = ref%n == out%n
        if (allocated(ref%v) .and. allocated(out%v)) then
            if (size(ref%v) == size(out%v)) cmp%v_error = maxval(abs(out%v - ref%v))
        end if
        if (.not. (ref%recording .and. out%recording)) return
        do j = 1, min(ref%n, out%n)
            if (ref%pair(j) /= out%pair(j)) exit
            cmp%n_matched = j
            cmp%t_error = max(cmp%t_error, abs(out%t(j) - ref%t(j)))
        end do
        cmp%same_sequence = cmp%same_count .and. cmp%n_matched == ref%n
    end function compare_outcomes

    !> Category of a run against its reference; `v_tol` [V] is the largest
    !> final-velocity error that still counts as right. Where the reference
    !> ended quasi-plastic (infinitely many collisions, their limit taken), no
    !> finite count is right and only the final state is judged.
    pure integer function classify(ref, out, v_tol) result(category)
        type(outcome_t), intent(in) :: ref, out
        real(qp), intent(in) :: v_tol
        type(comparison_t) :: cmp
        if (out%status == status_negative_gap) then
            category = category_negative_gap
            return
        else if (out%status /= status_normal .and. out%status /= status_collapsed) then
            category = category_no_end
            return
        end if
        cmp = compare_outcomes(ref, out)
        if (ref%status /= status_collapsed) then
            if (.not. cmp%same_count .or. &
                ((ref%recording .and. out%recording) .and. .not. cmp%same_sequence)) then
                category = category_wrong_count
                return
            end if
        end if
        if (cmp%v_error <= v_tol) then
            category = category_right
        else
            category = category_wrong_state
        end if
    end function classify

    !> The word printed for a category.
    pure function category_word(category) result(word)
        integer, intent(in) :: category
        character(len=:), allocatable :: word
        select case (category)
        case (category_right)
            word = "right"
        case (category_wrong_count)
            word = "wrong_count"
        case (category_wrong_state)
            word = "wrong_state"
        case (category_negative_gap)
            word = "negative_gap"
        case (category_no_end)
            word = "no_end"
        case default
            word = "unknown"
        end select
    end function category_word

end module sphere_row_outcome
