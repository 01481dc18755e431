!> Umbrella module: the public API of the package, in the working precision.
!>
!> The engine in real128 is exported here. The same engine in other kinds,
!> for precision studies, is used from its own module (sphere_row_engine_sp,
!> _dp, _xdp), whose names are the same as these.
module sphere_row
    use sphere_row_kinds, only: sp, dp, xdp, qp
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, event_start, event_collision, event_collapse, status_word
    use sphere_row_format, only: real_str
    use sphere_row_engine_qp, only: scene_t, run_t, event_log_t, scene_init, scene_check, &
        simulate, gaps_at, kinetic_energy, momentum, str
    implicit none
    private
    public :: sp, dp, xdp, qp
    public :: status_normal, status_collapsed, status_max_collisions, status_invalid
    public :: event_start, event_collision, event_collapse, status_word, real_str
    public :: scene_t, run_t, event_log_t
    public :: scene_init, scene_check, simulate, gaps_at, kinetic_energy, momentum, str
end module sphere_row
