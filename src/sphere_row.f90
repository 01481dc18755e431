#include "sphere_row_kinds.h"
!> Umbrella module: the public API of the package.
!>
!> The engine in real128, the working precision, is exported under its plain
!> type names (scene_t, run_t, event_log_t); the same engine in the other kinds
!> under suffixed names (scene_dp_t, ...). The procedures are generic over all
!> four kinds (three where the compiler has no 80-bit extended kind: see
!> include/sphere_row_kinds.h).
module sphere_row
    use sphere_row_kinds, only: sp, dp, xdp, qp
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, status_horizon, event_start, event_collision, event_collapse, &
        event_sample, status_word, status_words, answer_exact, answer_certified, &
        answer_tolerance, answer_bounded, answer_unresolved, answer_word, answer_words
    use sphere_row_format, only: real_str, short_text, itoa, real_text, int_text, &
        number_text_length, earned_str, earned_text
    use sphere_row_engine_qp, only: scene_t, run_t, observer_t, state_now => state_now_wp, &
        event_log_t, scene_init_qp => scene_init_wp, &
        scene_check_qp => scene_check_wp, simulate_qp => simulate_wp, &
        gaps_at_qp => gaps_at_wp, kinetic_energy_qp => kinetic_energy_wp, &
        momentum_qp => momentum_wp, str_qp => str_wp, bounds_t, &
        simulate_certified_qp => simulate_certified_wp, budget_qp => budget_wp, &
        order_check_qp => order_check_wp, order_premise_qp => order_premise_wp, &
        collapse_proven_qp => collapse_proven_wp, struck_least => struck_least_wp, &
        gaps_at_time_qp => gaps_at_time_wp, velocities_now_qp => velocities_now_wp, &
        comparisons_qp => comparisons_wp
#ifdef SPHERE_ROW_XDP
    use sphere_row_engine_xdp, only: scene_xdp_t => scene_t, run_xdp_t => run_t, &
        event_log_xdp_t => event_log_t, scene_init_xdp => scene_init_wp, &
        scene_check_xdp => scene_check_wp, simulate_xdp => simulate_wp, &
        gaps_at_xdp => gaps_at_wp, kinetic_energy_xdp => kinetic_energy_wp, &
        momentum_xdp => momentum_wp, str_xdp => str_wp, bounds_xdp_t => bounds_t, &
        simulate_certified_xdp => simulate_certified_wp, budget_xdp => budget_wp, &
        order_check_xdp => order_check_wp, order_premise_xdp => order_premise_wp, &
        collapse_proven_xdp => collapse_proven_wp, gaps_at_time_xdp => gaps_at_time_wp, &
        velocities_now_xdp => velocities_now_wp, comparisons_xdp => comparisons_wp
#endif
    use sphere_row_engine_dp, only: scene_dp_t => scene_t, run_dp_t => run_t, &
        event_log_dp_t => event_log_t, scene_init_dp => scene_init_wp, &
        scene_check_dp => scene_check_wp, simulate_dp => simulate_wp, &
        gaps_at_dp => gaps_at_wp, kinetic_energy_dp => kinetic_energy_wp, &
        momentum_dp => momentum_wp, str_dp => str_wp, bounds_dp_t => bounds_t, &
        simulate_certified_dp => simulate_certified_wp, budget_dp => budget_wp, &
        order_check_dp => order_check_wp, order_premise_dp => order_premise_wp, &
        collapse_proven_dp => collapse_proven_wp, gaps_at_time_dp => gaps_at_time_wp, &
        velocities_now_dp => velocities_now_wp, comparisons_dp => comparisons_wp
    use sphere_row_engine_sp, only: scene_sp_t => scene_t, run_sp_t => run_t, &
        event_log_sp_t => event_log_t, scene_init_sp => scene_init_wp, &
        scene_check_sp => scene_check_wp, simulate_sp => simulate_wp, &
        gaps_at_sp => gaps_at_wp, kinetic_energy_sp => kinetic_energy_wp, &
        momentum_sp => momentum_wp, str_sp => str_wp, bounds_sp_t => bounds_t, &
        simulate_certified_sp => simulate_certified_wp, budget_sp => budget_wp, &
        order_check_sp => order_check_wp, order_premise_sp => order_premise_wp, &
        collapse_proven_sp => collapse_proven_wp, gaps_at_time_sp => gaps_at_time_wp, &
        velocities_now_sp => velocities_now_wp, comparisons_sp => comparisons_wp
    use sphere_row_auto, only: auto_t, simulate_auto, simulate_in_dp, order_premise_in_dp, &
        velocity_bound
    implicit none
    private
    public :: sp, dp, xdp, qp
    public :: status_normal, status_collapsed, status_max_collisions, status_invalid
    public :: event_start, event_collision, event_collapse, status_word, real_str, &
        short_text, itoa
    public :: status_words, real_text, int_text, number_text_length, earned_str, earned_text
    public :: answer_exact, answer_certified, answer_tolerance, answer_bounded, &
        answer_unresolved, answer_word, answer_words
    public :: scene_t, run_t, event_log_t, observer_t, state_now
#ifdef SPHERE_ROW_XDP
    public :: scene_xdp_t, run_xdp_t, event_log_xdp_t
#endif
    public :: scene_dp_t, run_dp_t, event_log_dp_t
    public :: scene_sp_t, run_sp_t, event_log_sp_t
    public :: scene_init, scene_check, simulate, gaps_at, kinetic_energy, momentum, str, budget
    public :: bounds_t, bounds_dp_t, bounds_sp_t, simulate_certified, auto_t, simulate_auto, &
        velocity_bound
    public :: simulate_in_dp, order_premise_in_dp, collapse_proven, struck_least, order_check, &
        order_premise, gaps_at_time, velocities_now, status_horizon, event_sample, comparisons
    public :: sphere_row_version

    !> The package's version, as fpm.toml states it (a test compares them).
    character(len=*), parameter :: sphere_row_version = "0.1.0"
#ifdef SPHERE_ROW_XDP
    public :: bounds_xdp_t
#endif

    !> Run a scene and certify its decisions against bounds on the rounding
    !> error (see simulate_certified_wp in sphere_row_engine.inc).
    interface simulate_certified
        module procedure simulate_certified_qp, simulate_certified_dp, simulate_certified_sp
#ifdef SPHERE_ROW_XDP
        module procedure simulate_certified_xdp
#endif
    end interface simulate_certified

    !> How many of a row's first collisions exact arithmetic takes in the
    !> working precision's order (see order_check_wp in sphere_row_order.inc).
    interface order_check
        module procedure order_check_qp, order_check_dp, order_check_sp
#ifdef SPHERE_ROW_XDP
        module procedure order_check_xdp
#endif
    end interface order_check

    !> Whether order_check proves the order of collisions a run's answer
    !> rests on (see order_premise_wp in sphere_row_order.inc).
    interface order_premise
        module procedure order_premise_qp, order_premise_dp, order_premise_sp
#ifdef SPHERE_ROW_XDP
        module procedure order_premise_xdp
#endif
    end interface order_premise

    !> Build and check a scene (see scene_init_wp in sphere_row_engine.inc).
    interface scene_init
        module procedure scene_init_qp, scene_init_dp, scene_init_sp
#ifdef SPHERE_ROW_XDP
        module procedure scene_init_xdp
#endif
    end interface scene_init

    !> Check every parameter of a scene.
    interface scene_check
        module procedure scene_check_qp, scene_check_dp, scene_check_sp
#ifdef SPHERE_ROW_XDP
        module procedure scene_check_xdp
#endif
    end interface scene_check

    !> The engine's comparisons of two reals against the operators (see
    !> comparisons_wp in sphere_row_calendar.inc).
    interface comparisons
        module procedure comparisons_qp, comparisons_dp, comparisons_sp
#ifdef SPHERE_ROW_XDP
        module procedure comparisons_xdp
#endif
    end interface comparisons

    !> Run a scene to its end.
    interface simulate
        module procedure simulate_qp, simulate_dp, simulate_sp
#ifdef SPHERE_ROW_XDP
        module procedure simulate_xdp
#endif
    end interface simulate

    !> Gaps at a given time from an event log.
    interface gaps_at
        module procedure gaps_at_qp, gaps_at_dp, gaps_at_sp
#ifdef SPHERE_ROW_XDP
        module procedure gaps_at_xdp
#endif
    end interface gaps_at

    !> The gaps of a run at a time at or after its current one (an
    !> observer's sample between events).
    interface gaps_at_time
        module procedure gaps_at_time_qp, gaps_at_time_dp, gaps_at_time_sp
#ifdef SPHERE_ROW_XDP
        module procedure gaps_at_time_xdp
#endif
    end interface gaps_at_time

    !> The velocities of a run as it stands, and a bound on their distance
    !> from exact arithmetic's in the kinetic-energy norm.
    interface velocities_now
        module procedure velocities_now_qp, velocities_now_dp, velocities_now_sp
#ifdef SPHERE_ROW_XDP
        module procedure velocities_now_xdp
#endif
    end interface velocities_now

    !> Total kinetic energy of velocities v.
    interface kinetic_energy
        module procedure kinetic_energy_qp, kinetic_energy_dp, kinetic_energy_sp
#ifdef SPHERE_ROW_XDP
        module procedure kinetic_energy_xdp
#endif
    end interface kinetic_energy

    !> Total momentum of velocities v.
    interface momentum
        module procedure momentum_qp, momentum_dp, momentum_sp
#ifdef SPHERE_ROW_XDP
        module procedure momentum_xdp
#endif
    end interface momentum

    !> The work budget of a scene in collisions: its max_collisions, or for 0
    !> max(10^6, 100 p).
    interface budget
        module procedure budget_qp, budget_dp, budget_sp
#ifdef SPHERE_ROW_XDP
        module procedure budget_xdp
#endif
    end interface budget

    !> Whether a finished run's collapse is proven in exact arithmetic: limits
    !> taken, each exact or certified, and no collision passed over below tol.
    interface collapse_proven
        module procedure collapse_proven_qp, collapse_proven_dp, collapse_proven_sp
#ifdef SPHERE_ROW_XDP
        module procedure collapse_proven_xdp
#endif
    end interface collapse_proven

    !> Text form of a real with every significant digit of its kind.
    interface str
        module procedure str_qp, str_dp, str_sp
#ifdef SPHERE_ROW_XDP
        module procedure str_xdp
#endif
    end interface str

end module sphere_row
