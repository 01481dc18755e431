!> Every constant of the collapse rules, in one place, each with where it comes
!> from: derived from the precision or from a bound, measured for speed, or
!> tuned (and then on what).
!>
!> The rules themselves are in src/collapse/; the engine's event loop reads
!> none of these. Reals are real(16), so that every kind converts them to the
!> value its own literal would have.
module sphere_row_policy
    use sphere_row_kinds, only: qp
    implicit none
    private
    public :: policy_t, policy

    !> The collapse rules' constants.
    type :: policy_t
        ! ---- the watch for a repeating pattern (certified cycle) ----
        !> Longest collision pattern looked for (measured for speed: the watch
        !> costs O(min(8(p-1), period_max)) a collision).
        integer :: period_max = 512
        !> Shortest pattern length looked for and its multiple of p-1: a
        !> period of the collapse of p spheres involves each contact a few
        !> times (chosen: 8(p-1), at least 32, certifies p = 5's period-19
        !> cycle and p = 4's period-8 one).
        integer :: period_least = 32, period_per_gap = 8
        !> Whole periods a pattern runs before it is tried (derived: two
        !> periods after the first show a repeat, not a coincidence).
        integer :: cycle_repeats = 2
        !> Periods to wait at least before trying again a cycle that only an
        !> impact outside its group stood in the way of (chosen).
        integer :: blocked_wait = 4
        !> Collisions per gap before patterns are looked for (measured: a
        !> finite run of a struck row rarely needs more, so finite runs pay
        !> nothing for the watch).
        integer :: watch_per_gap = 4
        !> Periods run ahead on a copy of the group to check a cycle (derived:
        !> three are needed to see a ratio of changes settle).
        integer :: cycle_probes = 3
        !> Power iteration for the period map's dominant eigenvalue: most
        !> steps, and the steps over which its settling rate is measured
        !> (chosen: 400 steps settle any ratio |lambda_2/lambda_1| < 0.96 to
        !> the square root of real(16)'s epsilon).
        integer :: eigen_iterations = 400, eigen_window = 8
        !> Largest relative difference between the observed contraction per
        !> period and the dominant eigenvalue (chosen).
        real(qp) :: cycle_match = 1.0e-3_qp
        !> Part of the smallest decision margin that the remaining drift of the
        !> direction may use up: stands for the unknown sensitivity of a margin
        !> to the direction (chosen).
        real(qp) :: drift_safety = 1.0e-2_qp
        !> The drift that rounding alone produces, in epsilons of the kind
        !> (derived: a period's operations, rounded).
        real(qp) :: drift_noise = 1.0e3_qp

        ! ---- the bounded answer of a long cascade at one instant ----
        !> Collisions at one instant after which a cascade's cone bound is
        !> first looked at, and then after twice, four times as many (chosen so
        !> that a finite cascade of a struck row is stepped to its end: see
        !> docs/collapse.md for the measurement).
        integer :: bounded_after = 4096
        !> The default velocity tolerance of a bounded answer, relative to v0
        !> (scene_t%vtol; chosen by measurement on the collapse survey: see
        !> docs/collapse.md).
        real(qp) :: vtol = 1.0e-10_qp
        !> A group that has settled within vtol in time is taken to its mean
        !> only once the run has spent 1/settle_share of its budget (chosen: a
        !> run that would end within the first quarter is the exact sequence;
        !> the rest is left for the groups that collapse in time without a
        !> pattern, which at p = 100, e = 0.8 take about 450,000 collisions
        !> with it).
        integer :: settle_share = 4
        ! ---- a group below tol followed on its own scale (follow_group) ----
        !> The most spheres of a group followed (chosen); and the collisions
        !> of the nested runs of a run whose ends are not taken, together
        !> (chosen: a fifth of the survey's budget of 10^5 a row; the survey's
        !> time did not change when it replaced a share of the run's own
        !> collisions; 100,000 certifies 31 more of its rows, but with such
        !> certificates as p = 6, e = 0.3's after 39,698 collisions, a cycle of
        !> real(16)'s own order, which keeps exact arithmetic's for about
        !> 1,400: docs/collapse.md, rule 3). A nested run goes as deep
        !> as its kind's range (its tol is sqrt(tiny)): where it stops is set
        !> by this work, not by a depth.
        integer :: follow_spheres = 64, follow_most = 20000

        ! ---- the touching block: its proof (box) and its tries ----
        !> Collisions next to a closed gap before a cascade through touching
        !> spheres is tried for its limit: at first, and at most after failed
        !> tries (measured for speed: a finite cascade pays little for the
        !> tries, doubling from touch_first to touch_most).
        integer :: touch_first = 8, touch_most = 1024
        !> Longest run of closed gaps tried (measured for speed: a try costs a
        !> few passes over the run).
        integer :: touch_run_most = 2048
        !> The longest reference block (contacts) on which the box for struck
        !> blocks of every length is grown (measured for speed: the search,
        !> made once per e, costs about 100 looks per contact of the longest
        !> block tried).
        integer :: struck_reference_most = 4096
        !> Times the box of every length is grown again and its bounds in
        !> between joined, before a reference block twice as long is tried
        !> (chosen: the joins settle within two or three where they settle).
        integer :: struck_joins = 8
        !> Binary orders of magnitude between neighbouring contacts' reduced
        !> masses up to which the box uses the engine's order (derived: their
        !> ratio well inside double's range).
        integer :: rho_bits = 480
        !> The box: looks at contacts allowed per contact (measured for speed:
        !> a try costs O(n)), its first relative margin and the factor by
        !> which the margins grow on the second attempt (chosen).
        integer :: box_looks_per_contact = 64
        real(qp) :: box_widen = 1.0e-3_qp, box_speed_up = 1.2_qp
        !> The rounding allowed of a box's images, in epsilons of double over
        !> the box's resolution (derived: an image near S' = delta is good to
        !> about eps/delta, and e and the weights are rounded to double).
        real(qp) :: box_slack = 8.0_qp
        !> Touching blocks whose tries in the engine's order are remembered,
        !> each waiting before it is tried again (tuned on the collapse survey
        !> of 1000 random rows).
        integer :: order_blocks = 4
        !> The work of the last try (its cascade collisions times the block's
        !> contacts, the unit of order_work) per engine collision waited before
        !> the same block is tried again: after a try that found no merge, and
        !> after one that proved it. In the unit of the try's cost (a cascade
        !> collision of a try scans the block's rates), so that the tries'
        !> share of a run's time does not grow with the block's length. Tuned
        !> on the collapse survey as a wait per cascade collision (16, and 64
        !> after a merge: a wait of 1/16 after a merge answered 773 of 1000
        !> rows, 1/64 793 in 1.2 times the time, 1/256 803 in 1.5 times, no
        !> wait 814 in 4.6 times), kept as they were for a block of 16
        !> contacts (the survey's answers the same).
        integer :: order_work_per_wait = 256, order_work_per_wait_merged = 1024
        !> Blocks struck at rest within themselves whose first try's verdict is
        !> remembered, and the longest run of closed gaps looked at on a
        !> strike (tuned on the collapse survey).
        integer :: struck_most = 64, struck_run_most = 16

        ! ---- a try: the cascade in the engine's order (sphere_row_cascade) ----
        !> Its collisions at least and its work (collisions times contacts) at
        !> most, doubled for each try before it that ran out of work (at most
        !> order_doublings times), and the sequence length at which a period
        !> is first looked for (measured for speed: a try's share of the run's
        !> time stays bounded as they grow).
        integer :: order_steps_least = 16384, order_work = 2**22, order_doublings = 4, &
            order_first_check = 1024
        !> A cascade that stops with every rate below tol v0 merges by the
        !> fallback's rule if no choice on the way was closer than this many
        !> roundings per unit of work (derived: a bound on the rounding of the
        !> choices, with a factor 2 to spare).
        real(qp) :: quiet_noise = 16.0_qp
        !> A try that passes the engine's end of its cascade goes on for at most
        !> this many times the work done up to there (tuned on the collapse
        !> survey: 256 leaves every row as without the bound, 16 does not).
        integer :: quiet_more = 256
        !> Jumps over a pattern that part of the block repeats: the widest
        !> window of contacts, the most distinct jumps a try records, and the
        !> whole periods a pattern runs before it is jumped (measured on the
        !> collapse survey: fewer costs more in searches than it saves); a
        !> jump's longest period and the most doublings of its repeat count
        !> (derived: 2^30 repeats is beyond any try's work).
        integer :: jump_window_most = 40, jump_kinds_most = 256, jump_need = 8
        integer :: jump_period_most = 16, jump_levels = 30
        !> The periods a pattern is run before its cone is looked for (chosen:
        !> a quick refusal of patterns that break or do not contract).
        integer :: order_probes = 6
        !> The cone of a pattern's certificate is sought for the map of 1, 2,
        !> 4, ... periods, at most 2^cone_doublings (derived: the part of the
        !> rates off the dominant direction must shrink to half of it within
        !> the periods; 64 periods cover a second eigenvalue up to 0.99 of the
        !> first).
        integer :: cone_doublings = 6
        !> The most numbers the forms of a cone's choices may take (measured
        !> for speed and memory: 2^24 reals, 128 MiB in double precision, a
        !> fraction of a second).
        real(qp) :: cone_work = 2.0_qp**24
    end type policy_t

    !> The policy the engine runs with.
    type(policy_t), parameter :: policy = policy_t()

end module sphere_row_policy
