!> sphere-row: run one scene of a row of spheres and print the complete answer.
program sphere_row_main
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, simulate, status_word, &
        status_invalid, status_normal, event_collision, event_collapse, itoa, auto_t, &
        simulate_auto, simulate_in_dp, answer_word, answer_certified, answer_unresolved, &
        answer_exact, real_str, collapse_proven, budget, sphere_row_version, order_premise, &
        order_premise_in_dp, velocity_bound
    use sphere_row_cli, only: cli_t, read_command_line, fail
    use sphere_row_scene_keys, only: add_scene_keys, add_state_keys, scene_from_cli, &
        check_scene_in_dp
    use sphere_row_error, only: error_t, fatal_error
    use sphere_row_format, only: short_text, real_text, int_text, number_text_length, &
        earned_text, finite
    use sphere_row_read, only: printable, read_real
    use sphere_row_system, only: text_out_t, stderr_is_terminal, system_error_text, path_kind, &
        path_missing, path_regular
    use sphere_row_watch, only: watch_t, event_header, sample_header, progress_on_terminal, &
        progress_elsewhere
    use sphere_row_lines, only: output_help, line_names
    implicit none
    type(cli_t) :: cli
    type(scene_t), target :: scene
    type(run_t) :: run
    type(watch_t) :: watch
    type(error_t), allocatable :: error
    type(auto_t) :: auto
    !> The answer (standard output) and, with events=FILE, the event table's
    !> file; with events=yes the table goes to `out` before the answer.
    type(text_out_t), target :: out, table, samples_table
    !> The event table is written (events=yes or a file), and to a file; the
    !> samples' table is written (samples=FILE).
    logical :: events, events_to_file, samples
    character(len=:), allocatable :: precision_word, events_word, samples_word
    !> The answer's lines asked for (print): ",all," or ",name,name,...,".
    character(len=:), allocatable :: print_list
    !> Significant digits of the kind that answered: real(16)'s (str's), or
    !> real(8)'s where it answered (precision=dp, or auto in real(8)); no
    !> number is written with more digits than its kind holds.
    integer :: precision_digits = precision(1.0_qp) + 1
    !> The order check's budget, p^2 times the collisions it would follow to
    !> the answer's premise (order_premise), in real(16) and in real(8). Tuned
    !> on this project's machine (release build, p = 10...190): the check
    !> costs about 1e-6 s (real(16)) and 2e-8 s (real(8)) per p^2 a
    !> collision, so each budget is about 4 s at most; the collapse survey's
    !> certified rows the check proves need at most 6e5. Beyond it the answer
    !> says that its order is computed, not checked.
    real(qp), parameter :: order_work_qp = 4.0e6_qp, order_work_dp = 2.0e8_qp
    !> The number of the last output line, i, and its digits, the last
    !> place_length characters of place_text (count_to).
    integer :: place_value = -1, place_length = 0
    character(len=number_text_length) :: place_text = ""

    call define_keys()
    call read_command_line(cli)
    call scene_from_cli(cli, scene, error)
    if (allocated(error)) call fail(cli%name, error)
    events_word = cli%get_word("events")
    events = events_word /= "no"
    events_to_file = events .and. events_word /= "yes"
    samples_word = cli%get_word("samples")
    samples = samples_word /= "no"
    print_list = ","//cli%get_word("print")//","
    call choose_precision(error)
    if (allocated(error)) call fail(cli%name, error)
    call start_watch(error)
    if (allocated(error)) call fail(cli%name, error)
    if (wanted("order") .or. wanted("order_stopped_by")) scene%keep_order = order_kept()
    call run_scene(scene, run, watch)
    call check_run(error)
    if (allocated(error)) call stop_on(error)
    call write_run()
    ! the tables' files complete before the answer is let out, and given
    ! their names only once all are written: a failure anywhere leaves no file
    if (events_to_file) call table%finish(error)
    if (allocated(error)) call stop_on(error)
    if (samples) call samples_table%finish(error)
    if (allocated(error)) call stop_on(error)
    call out%finish(error)
    if (allocated(error)) call stop_on(error)
    if (events_to_file) call table%commit(error)
    if (allocated(error)) call stop_on(error)
    if (samples) call samples_table%commit(error)
    if (allocated(error)) call fail(cli%name, error)

contains

    !> The keys of sphere-row: the scene keys, `events` and `precision`; and
    !> what it writes, after the keys in `--help`.
    subroutine define_keys()
        character(len=*), parameter :: nl = new_line("a")
        cli%name = "sphere-row"
        cli%version = sphere_row_version
        cli%synopsis = "[FILE] [key=value ...] | --help | --version"
        cli%about = &
            "Runs one row of spheres struck by sphere 1 (ARGESIM Comparison 12) in"//nl// &
            "real(16) and prints the number of collisions, the end time, the status, how"//nl// &
            "good the answer is, the final velocities v1..vp, positions x1..xp and gaps"//nl// &
            "y1..y(p-1) (each line is described below). FILE - reads the scene from stdin."//nl// &
            "Any initial state too: every velocity, walls, a ring, a table of spheres, a"//nl// &
            "random gas, and a horizon t_max (docs/scenes.md)."
        call add_scene_keys(cli)
        call add_state_keys(cli)
        call cli%add_table("events", "no", "yes: the event table on stdout before the " &
            //"answer; FILE.tsv: the table alone into that file, the answer on stdout " &
            //"(its columns are described below)")
        call cli%add_table("samples", "no", "FILE.tsv: a time series of the run up to t_max " &
            //"into that file, streamed as it goes: t, temperature (sum m (v - V)^2/p), " &
            //"energy, collisions_per_sphere and clusters (runs of touching spheres), at t = 0 " &
            //"and log-spaced times, 10 a decade from t_max/10^4 (precision = qp)")
        call cli%add_real("sample_every", "", "the samples every this much time instead of " &
            //"log-spaced", lo=0.0_qp, shown="log")
        call cli%add_choice("precision", "qp", [character(len=4) :: "qp", "dp", "auto"], &
            "qp: real(16); dp: real(8), for a scene within real(8)'s normal range; auto:" &
            //" real(8) where a rounding certificate holds, else real(16)")
        call cli%add_choices("print", "all", line_names(), "the lines of the answer to " &
            //"print, by their names below (v, x, y: every v<i>, x<i>, y<i>), each where it " &
            //"applies and in the order below (print=v: the velocities alone); all: every " &
            //"line; the event table is events'")
        cli%epilogue = output_help()
    end subroutine define_keys

    !> A refusal or failure after the event table's file was created: the
    !> file goes, then the message and the exit status.
    subroutine stop_on(error)
        type(error_t), intent(in) :: error
        if (events_to_file) call table%discard()
        if (samples) call samples_table%discard()
        call fail(cli%name, error)
    end subroutine stop_on

    !> The precision asked for (qp, dp or auto; the registry checked the
    !> word); the event table only with qp; with dp, a scene real(8) carries,
    !> and real(8)'s epsilon as tol unless tol is given.
    subroutine choose_precision(error)
        type(error_t), allocatable, intent(out) :: error
        precision_word = cli%get_word("precision")
        if (events .and. precision_word /= "qp") then
            call fatal_error(error, "events = "//printable(events_word)//" with precision = " &
                //precision_word//": allowed only with precision = qp")
            return
        end if
        if (samples .and. precision_word /= "qp") then
            call fatal_error(error, "samples = "//printable(samples_word)//" with precision = " &
                //precision_word//": allowed only with precision = qp")
            return
        end if
        if (samples .and. .not. cli%given("t_max")) then
            call fatal_error(error, "samples = "//printable(samples_word)//": no t_max given; " &
                //"allowed with a horizon t_max, up to which the samples go")
            return
        end if
        if (samples_word == "yes") then
            call fatal_error(error, "samples = yes: allowed no or the name of a file ending " &
                //"in .tsv")
            return
        end if
        if (samples .and. events_to_file .and. samples_word == events_word) then
            call fatal_error(error, "samples = "//printable(samples_word)//": the file events " &
                //"writes too; allowed another file")
            return
        end if
        if (cli%given("sample_every") .and. .not. samples) then
            call fatal_error(error, "sample_every = "//printable(cli%get_text("sample_every")) &
                //": allowed only with samples = FILE.tsv")
            return
        end if
        if (precision_word /= "dp") return
        call check_scene_in_dp(cli, scene, error)
        ! real(8) resolves rates and gaps to its own epsilon, as real(16) to its
        ! own; and at that tol the calendar of a long row stays on
        if (.not. cli%given("tol")) scene%tol = real(epsilon(1.0_dp), qp)
    end subroutine choose_precision

    !> The watch of the run: the event table written row by row as the run
    !> goes, its header first, onto stdout or into its file (created here:
    !> a file that cannot be made is refused before the run); for a long row
    !> a note on stderr that says what it costs (every row holds 2p + 6
    !> numbers); progress lines on stderr, fewer when it is not a terminal.
    subroutine start_watch(error)
        type(error_t), allocatable, intent(out) :: error
        real :: megabytes
        character(len=16) :: text
        integer :: errno, kind
        watch%events = events
        watch%progress = .true.
        watch%progress_every = merge(progress_on_terminal, progress_elsewhere, &
            stderr_is_terminal())
        call progress_from_environment(error)
        if (allocated(error)) return
        watch%budget = budget(scene)
        watch%v0 = scene%v0
        watch%out => out
        if (samples) then
            call open_table(samples_table, "samples", samples_word, error)
            if (allocated(error)) return
            watch%samples = .true.
            watch%sample_out => samples_table
            watch%scene => scene
            if (cli%given("sample_every")) watch%sample_every = cli%get_real("sample_every")
            watch%wake = 0
            call samples_table%put(sample_header)
        end if
        if (.not. events) return
        if (events_to_file) then
            call open_table(table, "events", events_word, error)
            if (allocated(error)) return
            watch%out => table
        end if
        call watch%out%put(event_header(scene%p, scene%wall_right >= 0 .or. scene%ring >= 0))
        megabytes = real(2*scene%p + 6)*41.0/1.0e6
        if (megabytes < 1.0) return
        write (text, "(f0.1)") megabytes
        write (error_unit, "(a)") "sphere-row: note (the run goes on): events = " &
            //printable(events_word)//" writes "//itoa(2*scene%p + 6)//" numbers, about " &
            //trim(text)//" MB, per event, and a row of "//itoa(scene%p)//" spheres has at " &
            //"least "//itoa(scene%p - 1)//" collisions"
    end subroutine start_watch

    !> Create the file of a table key's value (events or samples): a
    !> directory or a device of that name would be found only when the table
    !> is renamed, after the run, so it is refused now.
    subroutine open_table(file, key, path, error)
        type(text_out_t), intent(inout) :: file
        character(len=*), intent(in) :: key, path
        type(error_t), allocatable, intent(out) :: error
        integer :: errno, kind
        kind = path_kind(path, errno)
        if (kind /= path_missing .and. kind /= path_regular) then
            call fatal_error(error, key//" = "//printable(path)//": not a regular " &
                //"file (a directory, a device, a FIFO or a socket); allowed yes, no or " &
                //"a file name ending in .tsv")
            return
        end if
        call file%create(path, errno)
        if (errno /= 0) then
            call fatal_error(error, key//" = "//printable(path)//": cannot be " &
                //"written ("//system_error_text(errno)//"); allowed yes, no or a file " &
                //"name ending in .tsv in a directory that exists and may be written")
        end if
    end subroutine open_table

    !> SPHERE_ROW_PROGRESS=SECONDS in the environment sets the seconds
    !> between progress lines (0: at every look at the clock; off: none).
    subroutine progress_from_environment(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: text
        character(len=*), parameter :: name = "SPHERE_ROW_PROGRESS"
        real(qp) :: seconds
        integer :: length, stat
        call get_environment_variable(name, length=length, status=stat)
        if (stat /= 0) return
        allocate (character(len=length) :: text)
        if (length > 0) call get_environment_variable(name, text)
        if (text == "off" .and. length == 3) then
            watch%progress = .false.
            return
        end if
        call read_real(name, text, seconds, error, "seconds >= 0 or off")
        if (allocated(error)) return
        if (seconds < 0 .or. seconds > 1.0e6_qp) then
            call fatal_error(error, name//" = "//printable(text)//": allowed 0 <= seconds " &
                //"<= 1e6 or off")
            return
        end if
        watch%progress_every = real(seconds)
    end subroutine progress_from_environment

    !> Run `sc` in the precision asked for.
    subroutine run_scene(sc, r, w)
        type(scene_t), intent(in) :: sc
        type(run_t), intent(inout) :: r
        type(watch_t), intent(inout), optional :: w
        select case (precision_word)
        case ("auto")
            call simulate_auto(sc, r, auto)
        case ("dp")
            call simulate_in_dp(sc, r)
        case default
            if (present(w)) then
                call simulate(sc, r, observer=w)
            else
                call simulate(sc, r)
            end if
        end select
    end subroutine run_scene

    !> Refuse a run the engine did not accept, or one whose output would hold
    !> a number that is not finite (the scene checks are meant to make that
    !> impossible; this keeps inf and nan out of the output whatever happens).
    !> A run whose times overflow is refused naming v0: times scale as 1/v0,
    !> so the same scene run with v0 = 1 gives the smallest v0 allowed.
    subroutine check_run(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: kind_name, length_key
        kind_name = "real(16)"
        if (precision_word == "dp") kind_name = "real(8)"
        length_key = "d"
        if (maxval(scene%a) > scene%d) length_key = merge("gaps", "a   ", cli%given("gaps"))
        if (run%status == status_invalid .or. .not. (finite(run%t_end) .and. &
            finite(run%limits%t))) then
            call refuse_time(kind_name, error)
            if (.not. allocated(error) .and. run%status == status_invalid) then
                call fatal_error(error, trim(run%message))
            end if
            return
        end if
        if (.not. all_finite(run%v)) then
            call fatal_error(error, "v0 = "//printable(cli%get_text("v0"))//": the run's " &
                //"velocities overflow "//kind_name//"; allowed a smaller v0")
            return
        end if
        if (.not. (all_finite(run%x) .and. all_finite(run%y))) then
            call fatal_error(error, trim(length_key)//" = "//printable(cli%get_text( &
                trim(length_key)))//": the run's positions overflow "//kind_name &
                //"; allowed a shorter row")
            return
        end if
        if (watch%overflow > 0) call fatal_error(error, "events = "//printable(events_word) &
            //": event "//itoa(watch%overflow)//" of this scene overflows "//kind_name &
            //"; allowed events = no")
    end subroutine check_run

    !> A run whose times overflow, refused naming v0 with the smallest v0
    !> whose run stays finite; no error if the same scene at v0 = 1 fails too.
    subroutine refuse_time(kind_name, error)
        character(len=*), intent(in) :: kind_name
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: unit_speed
        type(run_t) :: check
        real(qp) :: t1, big
        unit_speed = scene
        unit_speed%v0 = 1.0_qp
        call run_scene(unit_speed, check)
        if (check%status == status_invalid) return
        t1 = max(check%t_end, check%limits%t)
        if (.not. finite(t1)) return
        big = huge(1.0_qp)
        if (precision_word == "dp") big = real(huge(1.0_dp), qp)
        call fatal_error(error, "v0 = "//printable(cli%get_text("v0"))//": the run's " &
            //"times (t_end = "//short_text(t1, 3)//"/v0) overflow "//kind_name &
            //"; allowed v0 >= "//short_text(t1/big, 3, "up"))
    end subroutine refuse_time

    !> Every element of xs is finite, looked at in place (a long row's
    !> answer holds millions: no array made of them).
    pure logical function all_finite(xs)
        real(qp), intent(in) :: xs(:)
        integer :: i
        all_finite = .false.
        do i = 1, size(xs)
            if (.not. finite(xs(i))) return
        end do
        all_finite = .true.
    end function all_finite

    !> The answer, one quantity per line, collected by `out` (whose every
    !> write is checked at its finish): how it ended, what holds in exact
    !> arithmetic (`answer`, and `v_bound`, the largest bound on a final
    !> velocity, the run's own rounding included), the collapse limits by kind
    !> and whether the collapse is proven, the groups still active if the
    !> budget ran out, and the velocities (each with the digits its bound
    !> leaves), positions and gaps; of these, the lines print= asks for.
    subroutine write_run()
        real(qp) :: bound, separation
        integer :: j
        character(len=:), allocatable :: groups
        if (wanted("collisions")) call out%put("collisions "//itoa(run%n))
        if (precision_word == "dp") precision_digits = precision(1.0_dp) + 1
        if (precision_word == "auto") then
            if (auto%answered == "dp") precision_digits = precision(1.0_dp) + 1
        end if
        if (wanted("t_end")) call out%put("t_end "//real_str(run%t_end, precision_digits))
        ! (with a horizon, the time of the state below: t_max, or the last
        ! event's where the budget ran out first)
        if (cli%given("t_max") .and. wanted("t")) call out%put("t "//real_str(run%clock%t, &
            precision_digits))
        if (wanted("status")) call out%put("status "//status_word(run%status))
        if (precision_word == "auto") then
            if (wanted("precision")) call out%put("precision "//auto%answered)
            if (wanted("certified")) call out%put("certified "//trim(merge("yes", "no ", &
                auto%certified)))
            if (auto%answered /= "dp" .and. wanted("not_dp")) call out%put("not_dp " &
                //auto%why_not_dp)
        else
            if (wanted("precision")) call out%put("precision "//precision_word)
        end if
        ! (the run's v_bound is its spheres' largest; auto's certificate may
        ! lower some of them)
        bound = run%v_bound
        if (precision_word == "auto") then
            bound = 0
            do j = 1, size(run%v)
                bound = max(bound, velocity_bound(run, auto, j))
            end do
        end if
        if (wanted("answer")) call out%put("answer "//answer_word(run%answer))
        if (wanted("v_bound")) call out%put("v_bound "//real_str(bound, 2))
        if (run%answer /= answer_unresolved) call write_premises()
        if (run%limits%n > 0) then
            if (wanted("collapses")) call out%put("collapses "//itoa(run%limits%n))
            if (wanted("closed_form_limits")) call out%put("closed_form_limits " &
                //itoa(run%limits%closed_form))
            if (wanted("limits_exact")) call out%put("limits_exact "//itoa(run%limits%exact))
            if (wanted("limits_certified")) call out%put("limits_certified " &
                //itoa(run%limits%certified))
            if (wanted("limits_tolerance")) call out%put("limits_tolerance " &
                //itoa(run%limits%tolerance))
            if (wanted("limits_bounded")) call out%put("limits_bounded " &
                //itoa(run%limits%bounded))
            ! a collapse is proven where every limit is, in exact arithmetic;
            ! else a merged group's exact final rates are only known to lie
            ! within twice the velocities' bound
            if (collapse_proven(run)) then
                if (wanted("collapse")) call out%put("collapse proven")
            else
                if (wanted("collapse")) call out%put("collapse unproven")
                if (wanted("separation_not_excluded_below")) call out%put( &
                    "separation_not_excluded_below "//real_str(2*bound/scene%v0, 2))
            end if
            if (wanted("collapse_spheres")) call out%put("collapse_spheres " &
                //itoa(run%limits%first)//"-"//itoa(run%limits%last))
            if (wanted("collapse_t")) call out%put("collapse_t "//real_str(run%limits%t, &
                precision_digits))
        end if
        if (run%answer == answer_exact .and. run%status == status_normal .and. &
            wanted("separation_scale")) then
            separation = maxval(abs(run%dy))/scene%v0
            if (separation < sqrt(epsilon(1.0_qp))) call out%put("separation_scale " &
                //real_str(separation, 2))
        end if
        if (run%answer == answer_unresolved .and. wanted("active")) then
            groups = ""
            do j = 1, size(run%active, 2)
                groups = groups//" "//itoa(run%active(1, j))//"-"//itoa(run%active(2, j))
            end do
            if (len(groups) == 0) groups = " none"
            call out%put("active"//groups)
        end if
        if (wanted("v")) call write_velocities()
        if (wanted("x")) call write_numbered("x", run%x)
        if (wanted("y")) call write_numbered("y", run%y)
    end subroutine write_run

    !> What the answer rests on beyond the counts of its limits: whether the
    !> order of collisions it rests on is proven (write_order, run only for
    !> its lines), and an answer at tolerance or bounded names each premise
    !> that makes it so (run%rests_on, judged with the answer).
    subroutine write_premises()
        if (wanted("order") .or. wanted("order_stopped_by")) call write_order()
        if (len_trim(run%rests_on) > 0 .and. wanted("rests_on")) then
            call out%put("rests_on"//trim(run%rests_on))
        end if
    end subroutine write_premises

    !> The collisions whose gaps the run keeps for write_order: as many as
    !> the order check's budget lets it follow (real(8)'s where the run may
    !> answer in real(8)).
    integer function order_kept() result(n)
        real(qp) :: work
        work = order_work_qp
        if (precision_word /= "qp") work = order_work_dp
        n = int(min(work/real(scene%p, qp)**2 + 1, real(huge(n), qp)))
    end function order_kept

    !> Whether exact arithmetic's order of the collisions the answer rests on
    !> is proven: by precision=auto's certificate, where it holds (it checks
    !> every decision of its run), else by order_premise in the kind that
    !> answered.
    subroutine write_order()
        logical :: proven
        character(len=80) :: why
        if (precision_word == "auto" .and. auto%certified) then
            proven = .true.
        else if (precision_word == "dp" .or. (precision_word == "auto" .and. &
                auto%answered == "dp")) then
            call order_premise_in_dp(scene, run, order_work_dp, proven, why)
        else
            call order_premise(scene, run, order_work_qp, proven, why)
        end if
        if (wanted("order")) call out%put("order "//trim(merge("proven  ", "computed", proven)))
        if (.not. proven .and. wanted("order_stopped_by")) call out%put("order_stopped_by " &
            //trim(why))
    end subroutine write_order

    !> True if the answer's line `name` (v, x, y: every v<i>, x<i>, y<i>) is
    !> asked for: print=all, or the name in print's list.
    logical function wanted(name)
        character(len=*), intent(in) :: name
        wanted = print_list == ",all," .or. index(print_list, ","//name//",") > 0
    end function wanted

    !> Lines `v<i> <v_i>`, each with the digits its bound leaves (earned_text:
    !> every digit of the kind that answered where the bound is 0 or not
    !> finite, else down to the bound's decade, and below it rounded there as
    !> q times its power of ten; velocity_bound gives each sphere's bound). Each
    !> line is assembled in place, as put_numbered's: a long row's answer has
    !> a million.
    subroutine write_velocities()
        integer :: i, n_text
        character(len=number_text_length) :: text
        do i = 1, size(run%v)
            call earned_text(run%v(i), velocity_bound(run, auto, i), text, n_text, &
                precision_digits)
            call put_line("v", i, text(:n_text))
        end do
    end subroutine write_velocities

    !> Lines `<name><i> <values(i)>`.
    subroutine write_numbered(name, values)
        character(len=*), intent(in) :: name
        real(qp), intent(in) :: values(:)
        integer :: i
        do i = 1, size(values)
            call put_numbered(name, i, values(i))
        end do
    end subroutine write_numbered

    !> The line `<name><i> <x>`, x with every digit of the kind that answered.
    subroutine put_numbered(name, i, x)
        character(len=*), intent(in) :: name
        integer, intent(in) :: i
        real(qp), intent(in) :: x
        character(len=number_text_length) :: number
        integer :: n_number
        call real_text(x, precision_digits, number, n_number)
        call put_line(name, i, number(:n_number))
    end subroutine put_numbered

    !> The line `<name><i> <text>`, assembled in place: a million of them are
    !> a long row's answer. The lines come numbered 1, 2, 3, ...: i's digits
    !> are the last line's counted up by one (place_text), not made anew.
    subroutine put_line(name, i, text)
        character(len=*), intent(in) :: name, text
        integer, intent(in) :: i
        character(len=2*number_text_length + 2) :: line
        integer :: n_place, at
        call count_to(i)
        n_place = place_length
        at = len(name)
        line(:at) = name
        line(at + 1:at + n_place) = place_text(len(place_text) - n_place + 1:)
        at = at + n_place + 1
        line(at:at) = " "
        line(at + 1:at + len(text)) = text
        at = at + len(text) + 1
        line(at:at) = new_line("a")
        call out%put_text(line(:at))
    end subroutine put_line

    !> place_text ends in the digits of i (place_length of them): counted up
    !> by one from the last i where i follows it, else written anew.
    subroutine count_to(i)
        integer, intent(in) :: i
        character(len=number_text_length) :: digits_text
        integer :: at
        if (i == place_value + 1 .and. place_value >= 0) then
            at = len(place_text)
            do
                if (place_text(at:at) /= "9") then
                    place_text(at:at) = achar(iachar(place_text(at:at)) + 1)
                    exit
                end if
                place_text(at:at) = "0"
                at = at - 1
                if (at == len(place_text) - place_length) then
                    place_text(at:at) = "1"
                    place_length = place_length + 1
                    exit
                end if
            end do
        else
            call int_text(int(i, int64), digits_text, place_length)
            place_text(len(place_text) - place_length + 1:) = digits_text(:place_length)
        end if
        place_value = i
    end subroutine count_to



end program sphere_row_main
