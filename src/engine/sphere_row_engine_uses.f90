!> What every per-kind engine module (sphere_row_engine_sp, _dp, _xdp, _qp)
!> takes from the kind-free modules, named once: the instance
!> (sphere_row_instance.inc) is the same text in every kind, so what it uses
!> is too. The `use` statements cannot stand in the include itself: fpm finds
!> a module's dependencies in its .f90 file only, not in the files it includes.
module sphere_row_engine_uses
    use sphere_row_format, only: real_str, itoa, int_text, number_text_length
    use sphere_row_policy, only: policy
    use sphere_row_cascade, only: ordered_cascade_merges, cascade_kind
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, status_horizon, event_start, event_collision, event_collapse, &
        event_sample, answer_exact, &
        answer_certified, answer_tolerance, answer_bounded, answer_unresolved
    implicit none
    private
    !> The formatting, policy, cascade and status names the instance uses (each
    !> documented in its own module).
    public :: real_str, itoa, int_text, number_text_length
    public :: policy
    public :: ordered_cascade_merges, cascade_kind
    public :: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, status_horizon, event_start, event_collision, event_collapse, &
        event_sample, answer_exact, &
        answer_certified, answer_tolerance, answer_bounded, answer_unresolved
end module sphere_row_engine_uses
