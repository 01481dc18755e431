!> Outcome codes of a run and of input checks, shared by every precision.
!>
!> The library reports through these codes and a message; it never stops the
!> program. Only programs decide to stop.
module sphere_row_status
    implicit none
    private
    public :: status_normal, status_collapsed, status_max_collisions, status_invalid
    public :: status_negative_gap, status_budget, status_solver_failed, status_horizon
    public :: event_start, event_collision, event_collapse, event_sample
    public :: status_word, status_words
    public :: answer_exact, answer_certified, answer_tolerance, answer_bounded, &
        answer_unresolved, answer_word, answer_words

    !> The run ended by the definition's criterion: no gap is closing any more.
    integer, parameter :: status_normal = 0
    !> The run ended, and on the way at least one contiguous group of spheres
    !> underwent inelastic collapse (infinitely many collisions in finite time),
    !> whose limit was taken: the quasi-plastic case.
    integer, parameter :: status_collapsed = 1
    !> The safety net `max_collisions` was reached before the end: the state
    !> returned is the one after the last collision computed.
    integer, parameter :: status_max_collisions = 2
    !> The scene was refused; the message names the parameter at fault.
    integer, parameter :: status_invalid = 3
    !> A method other than the engine saw two spheres overlap by more than its
    !> own resolution (a negative gap) and stopped: its event times are no longer
    !> meaningful.
    integer, parameter :: status_negative_gap = 4
    !> A time or step budget ran out before the end (time stepping, ODE
    !> integration): the state returned is the one reached.
    integer, parameter :: status_budget = 5
    !> The ODE solver (GSL) returned an error; the message says which.
    integer, parameter :: status_solver_failed = 6

    !> The run reached its horizon t_max with collisions still to come: the
    !> state returned is the one at t_max (a ring or a box with e < 1 has no
    !> end; a row that separated before t_max ends normal).
    integer, parameter :: status_horizon = 7

    !> Event kinds of the optional event record.
    integer, parameter :: event_start = 0, event_collision = 1, event_collapse = 2
    !> An observer's sample time reached (observer_t%wake): not an event of
    !> the run, and never in its event log.
    integer, parameter :: event_sample = 3

    !> How good an answer is, from the best to the weakest; a run's answer is
    !> the weakest of its end and its collapse limits.
    !>
    !> An exact answer: a finite sequence that separated (every rate >= 0), or
    !> a limit in closed form (a plastic pool at e = 0), exact to the working
    !> precision.
    integer, parameter :: answer_exact = 1
    !> A certified answer: a limit taken on a numerical certificate (a cycle's
    !> eigenvalues, an invariant box of ratios), exact to the working
    !> precision where the certificate holds.
    integer, parameter :: answer_certified = 2
    !> An answer at tolerance: the run ended with closing rates all below
    !> tol v0 (the definition's criterion, "insignificant" relative
    !> velocities); the final velocities lie within the stated bound.
    integer, parameter :: answer_tolerance = 3
    !> A bounded answer: a group's limit taken where its velocities are known
    !> to lie within the stated bound of its mean.
    integer, parameter :: answer_bounded = 4
    !> An unresolved answer: the work budget was spent; the groups still
    !> active are named, with the bound reached on them.
    integer, parameter :: answer_unresolved = 5

    !> The words printed for the status codes (status_normal to
    !> status_horizon) and the answer codes (0: none yet, then answer_exact to
    !> answer_unresolved), padded with blanks. status_word and answer_word
    !> trim them; where threads make texts at once, trim(status_words(s)) is
    !> the word without a character function of deferred length, whose length
    !> gfortran 12 keeps in a static variable of the caller.
    character(len=*), parameter :: status_words(0:7) = [character(len=16) :: "normal", &
        "quasi_plastic", "max_collisions", "invalid", "negative_gap", "budget_exhausted", &
        "solver_failed", "horizon"]
    character(len=*), parameter :: answer_words(0:5) = [character(len=10) :: "none", &
        "exact", "certified", "tolerance", "bounded", "unresolved"]

contains

    !> The word printed for an answer code: its answer_words entry, or none
    !> for a code outside them.
    pure function answer_word(answer) result(word)
        integer, intent(in) :: answer
        character(len=:), allocatable :: word
        word = word_of(answer_words, answer, "none")
    end function answer_word

    !> The word printed for a status code: its status_words entry, or unknown
    !> for a code outside them.
    pure function status_word(status) result(word)
        integer, intent(in) :: status
        character(len=:), allocatable :: word
        word = word_of(status_words, status, "unknown")
    end function status_word

    !> words(code) without its padding, or `other` for a code outside them.
    pure function word_of(words, code, other) result(word)
        character(len=*), intent(in) :: words(0:), other
        integer, intent(in) :: code
        character(len=:), allocatable :: word
        word = other
        if (code >= 0 .and. code < size(words)) word = trim(words(code))
    end function word_of
end module sphere_row_status
