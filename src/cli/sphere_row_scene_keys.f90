!> The scene keys shared by the `sphere-row` CLI and the study programs (p, e,
!> d, a, gaps, v0, masses, tol, max_collisions, calendar_from) on the key registry of
!> `sphere_row_cli`, and the scene they give, refused where its scales do not
!> fit in real(16), or, for a run asked in real(8), in real(8).
module sphere_row_scene_keys
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: dp, qp
    use sphere_row_format, only: itoa, short_text
    use sphere_row_status, only: status_normal
    use sphere_row_error, only: error_t, fatal_error
    use sphere_row, only: scene_t, scene_init
    use sphere_row_cli, only: cli_t, find_key, key_index, origin
    use sphere_row_read, only: printable
    use sphere_row_gas, only: gas_state
    use sphere_row_spheres_file, only: read_spheres
    implicit none
    private
    public :: add_scene_keys, add_state_keys, scene_from_cli, check_scene_in_dp, max_spheres

    !> Largest number of spheres: every per-sphere array of a run is allocated
    !> from p, so p is bounded to what fits in memory many times over.
    integer, parameter :: max_spheres = 1000000

    character(len=*), parameter :: nl = new_line("a")

contains

    !> Register the keys of a scene: p, e, d, a, gaps, v0, masses, tol,
    !> max_collisions, and scene files. Their defaults are the definition's
    !> scene (those of scene_t, and a = 1); `e_default` replaces its e. A
    !> program that sets e itself names what sets it in `e_set_by`: the key e
    !> is then not registered (so refused) and its `--help` says why.
    pure subroutine add_scene_keys(cli, e_default, e_set_by)
        type(cli_t), intent(inout) :: cli
        real(qp), intent(in), optional :: e_default
        character(len=*), intent(in), optional :: e_set_by
        type(scene_t) :: defaults
        real(qp) :: e
        e = defaults%e
        if (present(e_default)) e = e_default
        cli%files = .true.
        call cli%add_int("p", itoa(defaults%p), "number of spheres", lo=2, hi=max_spheres, &
            in_file=.true.)
        if (present(e_set_by)) then
            if (.not. allocated(cli%about)) cli%about = ""
            cli%about = cli%about//nl//"The scene key e is not taken: "//e_set_by//" sets e."
        else
            call cli%add_real("e", short_text(e), "restitution coefficient of every impact", &
                lo=0.0_qp, hi=1.0_qp, in_file=.true.)
        end if
        call cli%add_real("d", short_text(defaults%d), "sphere diameter", lo=0.0_qp, &
            in_file=.true.)
        call cli%add_real("a", "1", "every initial gap", lo=0.0_qp, &
            in_file=.true.)
        call cli%add_reals("gaps", "a1,a2,...", "the initial gaps, p-1 values (instead of a)", &
            lo=0.0_qp, &
            overrides="a", in_file=.true.)
        call cli%add_real("v0", short_text(defaults%v0), "speed of sphere 1 at t = 0", &
            lo=0.0_qp, lo_open=.true., in_file=.true.)
        call cli%add_reals("masses", "m1,m2,...", "the masses, p values (default: all 1)", &
            lo=0.0_qp, lo_open=.true., in_file=.true.)
        call cli%add_real("tol", short_text(defaults%tol), "rates below tol*v0 and gaps " &
            //"below tol*max(a) are insignificant (default: the epsilon of the " &
            //"precision; with precision=dp, 2.22e-16)", lo=0.0_qp, hi=1.0_qp, hi_open=.true., &
            shown=short_text(defaults%tol, 3), in_file=.true.)
        call cli%add_real("vtol", short_text(defaults%vtol), "a cascade at one instant that " &
            //"has run long is taken to its limit when every velocity it will end with is " &
            //"within vtol*v0 of its pool's (0: never)", lo=0.0_qp, hi=1.0_qp, hi_open=.true., &
            in_file=.true.)
        call cli%add_int("max_collisions", itoa(defaults%max_collisions), &
            "the work budget: a run that takes this many collisions ends unresolved " &
            //"(0: max(10^6, 100 p))", lo=0, in_file=.true.)
        call cli%add_int("calendar_from", itoa(defaults%calendar_from), "rows of at least " &
            //"this many spheres take the next impact from a calendar (a heap), shorter " &
            //"rows scan every gap", lo=2, in_file=.true.)
    end subroutine add_scene_keys

    !> Register the keys of any initial state, beyond the struck row (the
    !> `sphere-row` CLI and the gas study): every sphere's velocity, walls, a
    !> ring, the scene as a table, a random gas, and a horizon
    !> (docs/scenes.md).
    pure subroutine add_state_keys(cli)
        type(cli_t), intent(inout) :: cli
        call cli%add_reals("velocities", "v1,v2,...", "every sphere's initial velocity, p " &
            //"values (instead of v0, the definition's sphere 1 at v0 and the rest at rest)", &
            overrides="v0", in_file=.true.)
        call cli%add_real("wall_left", "", "a fixed wall at this gap left of sphere 1 (a " &
            //"sphere of infinite mass at rest)", lo=0.0_qp, shown="none", in_file=.true.)
        call cli%add_real("wall_right", "", "a fixed wall at this gap right of sphere p", &
            lo=0.0_qp, shown="none", in_file=.true.)
        call cli%add_real("e_wall", "", "the restitution of a collision with a wall", &
            lo=0.0_qp, hi=1.0_qp, shown="e", in_file=.true.)
        call cli%add_real("ring", "", "the row closed into a ring: sphere p meets sphere 1 " &
            //"across this gap (not with walls)", lo=0.0_qp, shown="none", in_file=.true.)
        call cli%add_word("spheres", "", "the scene as a table FILE.tsv: a header line " &
            //"x<TAB>v<TAB>m, then one sphere a line (its position, velocity and mass), " &
            //"positions increasing by at least d (instead of p, gaps, masses, velocities)")
        call cli%add_choice("gas", "no", [character(len=4) :: "no", "ring", "box"], &
            "a random gas of p spheres on a ring, or in a box (walls at both ends): placed " &
            //"uniformly at `density`, Gaussian velocities of `temperature`, zero momentum, " &
            //"from `seed` (the same on any number of threads or ranks)")
        call cli%add_real("density", "0.5", "the gas's spheres per unit length (density d < 1)", &
            lo=0.0_qp, lo_open=.true., in_file=.true.)
        call cli%add_real("temperature", "1", "the gas's temperature m <(v - V)^2> at t = 0", &
            lo=0.0_qp, lo_open=.true., in_file=.true.)
        call cli%add_int("seed", "1", "the gas's random seed", lo=0, in_file=.true.)
        call cli%add_real("t_max", "", "the horizon: the run stops at this time and gives the " &
            //"state then (a ring or a box with e < 1 has no end)", lo=0.0_qp, lo_open=.true., &
            shown="none", in_file=.true.)
    end subroutine add_state_keys

    !> The scene the scene keys of `cli` describe. Beyond each key's own range,
    !> the lists must have p and p-1 values, and the scene's scales must be
    !> finite in real(16) so that no time, position or velocity of the run
    !> overflows: the row's length (p-1) d + sum(gaps), the time scale
    !> sum(gaps)/v0, the velocity scale v0 sum(m)/min(m) (no sphere ever moves
    !> faster) and the final positions' scale, that length times (1 + 2
    !> sum(m)/min(m)).
    subroutine scene_from_cli(cli, scene, error)
        type(cli_t), intent(in) :: cli
        type(scene_t), intent(out) :: scene
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: masses(:), gaps(:), velocities(:), v0, x1, wall_left, &
            wall_right, e_wall, ring, t_max
        type(scene_t) :: defaults
        real(qp) :: e
        integer :: p, stat
        character(len=400) :: msg
        p = cli%get_int("p")
        e = defaults%e
        if (find_key(cli, "e") > 0) e = cli%get_real("e")
        v0 = cli%get_real("v0")
        ! (the masses before any initial state: a gas draws its velocities for
        ! them; a table gives its own, refused with the key)
        if (cli%given("masses") .and. .not. spheres_given(cli)) then
            masses = cli%get_reals("masses")
            if (size(masses) /= p) then
                call fatal_error(error, origin(cli%keys(key_index(cli, "masses")))//"masses = " &
                    //printable(cli%get_text("masses"))//": " &
                    //itoa(size(masses))//" values given; allowed exactly p = "//itoa(p) &
                    //" values, each > 0")
                return
            end if
        end if
        if (find_key(cli, "velocities") > 0) then
            call state_from_cli(cli, p, masses, gaps, velocities, x1, wall_left, wall_right, &
                e_wall, ring, t_max, error)
            if (allocated(error)) return
            if (allocated(velocities)) deallocate (v0)
        end if
        if (cli%given("gaps")) then
            gaps = cli%get_reals("gaps")
            if (size(gaps) /= p - 1) then
                call fatal_error(error, origin(cli%keys(key_index(cli, "gaps")))//"gaps = " &
                    //printable(cli%get_text("gaps"))//": " &
                    //itoa(size(gaps))//" values given; allowed exactly p-1 = "//itoa(p - 1) &
                    //" values, each >= 0")
                return
            end if
        end if
        if (allocated(velocities)) then
            call check_scales(cli, p, cli%get_real("d"), max(maxval(abs(velocities)), &
                tiny(1.0_qp)), masses, gaps, huge(1.0_qp), "real(16)", error, "velocities")
        else
            call check_scales(cli, p, cli%get_real("d"), cli%get_real("v0"), masses, gaps, &
                huge(1.0_qp), "real(16)", error)
        end if
        if (allocated(error)) return
        ! masses or gaps not given are absent here (not allocated): scene_init
        ! makes them equal in the scene's own arrays, with no copy of p reals;
        ! so are the keys of any initial state that are not given
        call scene_init(scene, stat, msg, p=p, e=e, d=cli%get_real("d"), &
            a=cli%get_real("a"), v0=v0, tol=cli%get_real("tol"), &
            max_collisions=cli%get_int("max_collisions"), masses=masses, gaps=gaps, &
            velocities=velocities, x1=x1, wall_left=wall_left, wall_right=wall_right, &
            e_wall=e_wall, ring=ring, t_max=t_max)
        if (stat /= status_normal) call fatal_error(error, trim(msg))
        scene%calendar_from = cli%get_int("calendar_from")
        scene%vtol = cli%get_real("vtol")
    end subroutine scene_from_cli

    !> Whether a table of spheres gives the scene (the key known and given).
    logical function spheres_given(cli)
        type(cli_t), intent(in) :: cli
        spheres_given = .false.
        if (find_key(cli, "spheres") > 0) spheres_given = cli%given("spheres")
    end function spheres_given

    !> The keys of any initial state (add_state_keys), read into the scene's
    !> parts: each left unallocated where its key is not given. A table
    !> (spheres) sets p, x1, the gaps, velocities and masses; a gas the gaps
    !> (its ring's or its box's walls among them) and the velocities. Keys that
    !> cannot go together are refused in one line naming both.
    subroutine state_from_cli(cli, p, masses, gaps, velocities, x1, wall_left, wall_right, &
        e_wall, ring, t_max, error)
        type(cli_t), intent(in) :: cli
        integer, intent(inout) :: p
        real(qp), allocatable, intent(inout) :: masses(:), gaps(:)
        real(qp), allocatable, intent(out) :: velocities(:), x1, wall_left, wall_right, &
            e_wall, ring, t_max
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: gas, path
        integer :: i
        character(len=*), parameter :: placed(*) = [character(len=10) :: "p", "gaps", "a", &
            "masses", "velocities", "v0"], gas_set(*) = [character(len=10) :: "gaps", "a", &
            "velocities", "v0", "ring", "wall_left", "wall_right", "spheres"], &
            gas_keys(*) = [character(len=11) :: "density", "temperature", "seed"]
        gas = cli%get_word("gas")
        path = cli%get_word("spheres")
        if (cli%given("spheres")) then
            do i = 1, size(placed)
                if (.not. cli%given(trim(placed(i)))) cycle
                call both("spheres", trim(placed(i)), "the table gives p, the gaps, the " &
                    //"masses and the velocities")
                return
            end do
        end if
        if (gas /= "no") then
            do i = 1, size(gas_set)
                if (.not. cli%given(trim(gas_set(i)))) cycle
                call both("gas", trim(gas_set(i)), "the gas gives the gaps, its ring's or " &
                    //"walls' among them, and the velocities")
                return
            end do
        else
            do i = 1, size(gas_keys)
                if (.not. cli%given(trim(gas_keys(i)))) cycle
                call fatal_error(error, trim(gas_keys(i))//" = "//printable(cli%get_text( &
                    trim(gas_keys(i))))//": a key of the random gas; allowed only with " &
                    //"gas = ring or gas = box")
                return
            end do
        end if
        if (cli%given("e_wall") .and. .not. (cli%given("wall_left") .or. &
                cli%given("wall_right") .or. gas == "box")) then
            call fatal_error(error, "e_wall = "//printable(cli%get_text("e_wall")) &
                //": no wall to take it; allowed with wall_left, wall_right or gas = box")
            return
        end if
        if (cli%given("ring")) then
            if (cli%given("wall_left")) call both("ring", "wall_left", "a ring has no ends")
            if (cli%given("wall_right")) call both("ring", "wall_right", "a ring has no ends")
            if (allocated(error)) return
        end if
        if (cli%given("velocities")) then
            velocities = cli%get_reals("velocities")
            if (size(velocities) /= p) then
                call fatal_error(error, origin(cli%keys(key_index(cli, "velocities"))) &
                    //"velocities = "//printable(cli%get_text("velocities"))//": " &
                    //itoa(size(velocities))//" values given; allowed exactly p = "//itoa(p) &
                    //" values")
                return
            end if
        end if
        if (cli%given("wall_left")) wall_left = cli%get_real("wall_left")
        if (cli%given("wall_right")) wall_right = cli%get_real("wall_right")
        if (cli%given("e_wall")) e_wall = cli%get_real("e_wall")
        if (cli%given("ring")) ring = cli%get_real("ring")
        if (cli%given("t_max")) t_max = cli%get_real("t_max")
        if (cli%given("spheres")) then
            allocate (x1)
            call read_spheres(path, cli%get_real("d"), x1, gaps, velocities, masses, error)
            if (allocated(error)) return
            p = size(velocities)
            if (p > max_spheres) then
                call fatal_error(error, "spheres = "//printable(path)//": "//itoa(p) &
                    //" spheres; allowed at most "//itoa(max_spheres))
                return
            end if
        end if
        if (gas /= "no") call gas_from_cli(cli, gas == "ring", p, masses, gaps, velocities, &
            wall_left, wall_right, ring, error)
    contains
        !> Keys a and b given together, refused.
        subroutine both(a, b, why)
            character(len=*), intent(in) :: a, b, why
            call fatal_error(error, a//" = "//printable(cli%get_text(a))//" with "//b//" = " &
                //printable(cli%get_text(b))//": allowed one of them ("//why//")")
        end subroutine both
    end subroutine state_from_cli

    !> The random gas of p spheres (gas_state): on a ring (its gaps, the seam's
    !> among them) or in a box (its walls' gaps), velocities drawn for the
    !> masses given (1 each if none).
    subroutine gas_from_cli(cli, on_ring, p, masses, gaps, velocities, wall_left, &
            wall_right, ring, error)
        type(cli_t), intent(in) :: cli
        logical, intent(in) :: on_ring
        integer, intent(in) :: p
        real(qp), allocatable, intent(inout) :: masses(:), gaps(:), velocities(:), &
            wall_left, wall_right, ring
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: free(:)
        logical :: ok
        if (.not. allocated(masses)) allocate (masses(p), source=1.0_qp)
        allocate (velocities(p), free(merge(p, p + 1, on_ring)))
        call gas_state(p, cli%get_real("d"), masses, cli%get_real("density"), &
            cli%get_real("temperature"), int(cli%get_int("seed"), int64), free, &
            velocities, ok)
        if (.not. ok) then
            call fatal_error(error, "density = "//printable(cli%get_text("density"))//" with d = " &
                //printable(cli%get_text("d"))//": no room between the spheres; allowed " &
                //"density d < 1")
            return
        end if
        if (on_ring) then
            gaps = free(:p - 1)
            ring = free(p)
        else
            wall_left = free(1)
            gaps = free(2:p)
            wall_right = free(p + 1)
        end if
    end subroutine gas_from_cli

    !> Refuse a scene that a run in real(8) (precision = dp) cannot carry:
    !> every value not 0 must be a normal real(8) (a subnormal one keeps
    !> fewer digits, a smaller one reads as 0 and a larger one as inf), and
    !> the scene's scales must be finite in real(8), as scene_from_cli asks
    !> of real(16). The tolerance is not checked: below real(8)'s range it
    !> becomes 0, which decides the same for every rate real(8) can hold.
    subroutine check_scene_in_dp(cli, scene, error)
        type(cli_t), intent(in) :: cli
        type(scene_t), intent(in) :: scene
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: gap_key
        gap_key = "a"
        if (cli%given("gaps")) gap_key = "gaps"
        if (find_key(cli, "e") > 0) call check_values("e", [scene%e])
        if (.not. allocated(error)) call check_values("d", [scene%d])
        if (.not. allocated(error)) call check_values(gap_key, scene%a)
        if (.not. allocated(error)) call check_values("v0", [scene%v0])
        if (.not. allocated(error)) call check_values("masses", scene%m)
        if (allocated(scene%v) .and. .not. allocated(error)) call check_values("velocities", &
            scene%v)
        ! (a wall's or the seam's gap and the horizon: 0 or below is no wall,
        ! ring or horizon, so each given one must be a normal real(8) too)
        if (key_given("wall_left")) call check_values("wall_left", [scene%wall_left])
        if (key_given("wall_right")) call check_values("wall_right", [scene%wall_right])
        if (key_given("ring")) call check_values("ring", [scene%ring])
        if (key_given("t_max")) call check_values("t_max", [scene%t_max])
        if (allocated(error)) return
        call check_scales(cli, scene%p, scene%d, scene%v0, scene%m, scene%a, &
            real(huge(1.0_dp), qp), "real(8) (precision = dp)", error)
    contains
        !> Key `name` is one of the registry's, given, and nothing refused yet.
        logical function key_given(name)
            character(len=*), intent(in) :: name
            key_given = .false.
            if (allocated(error) .or. find_key(cli, name) == 0) return
            key_given = cli%given(name)
        end function key_given

        !> Each value of key `name` is 0 or a normal real(8).
        subroutine check_values(name, xs)
            character(len=*), intent(in) :: name
            real(qp), intent(in) :: xs(:)
            real(qp), parameter :: top = real(huge(1.0_dp), qp), low = real(tiny(1.0_dp), qp)
            character(len=:), allocatable :: which, allowed
            integer :: i
            ! the two numbers as the messages name them, to 5 digits each: the
            ! checks are made on the numbers themselves (tiny and huge)
            allowed = "with precision = dp, 0 or a magnitude in the normal range of real(8), " &
                //short_text(low, 5)//" to "//short_text(top, 5)//" (precision = qp or auto " &
                //"takes it)"
            do i = 1, size(xs)
                if (xs(i) == 0.0_qp .or. (abs(xs(i)) >= low .and. abs(xs(i)) <= top)) cycle
                which = "precision = dp: "
                if (name == "masses" .or. name == "gaps" .or. name == "velocities") then
                    which = which//"value "//itoa(i)//" is "//short_text(xs(i))//": "
                end if
                if (abs(xs(i)) > top) then
                    which = which//"beyond the largest real(8) number "//short_text(top, 5)
                else
                    which = which//"below the smallest normal real(8) number " &
                        //short_text(low, 5)
                end if
                call refuse_scale(error, cli, name, which//"; allowed "//allowed)
                return
            end do
        end subroutine check_values
    end subroutine check_scene_in_dp

    !> Refuse a scene whose length, time, velocity or position scale is not
    !> finite in the kind whose largest number is `big` (named `kind_name`),
    !> naming the key that makes it so.
    !> `masses` and `gaps` are read only where their keys are given: a row of
    !> equal gaps (the key a) or of equal masses has its sums in one product
    !> each, with no pass over p reals of real(16).
    subroutine check_scales(cli, p, d, v0, masses, gaps, big, kind_name, error, v0_key)
        type(cli_t), intent(in) :: cli
        integer, intent(in) :: p
        real(qp), intent(in) :: d, v0, big
        real(qp), intent(in), optional :: masses(:), gaps(:)
        character(len=*), intent(in) :: kind_name
        type(error_t), allocatable, intent(out) :: error
        !> The key that sets the velocity scale (v0, or velocities).
        character(len=*), intent(in), optional :: v0_key
        character(len=*), parameter :: row_text = "(p-1) d + sum(gaps)", &
            spread_text = "(1 + 2 sum(m)/min(m)) ((p-1) d + sum(gaps))"
        real(qp) :: row, gap_sum, diameters, ratio
        character(len=:), allocatable :: gap_key, limit, culprit, vkey
        logical :: table
        limit = short_text(big, 3, "down")
        vkey = "v0"
        if (present(v0_key)) vkey = v0_key
        gap_key = "a"
        if (cli%given("gaps")) gap_key = "gaps"
        ! (a table or a gas gives the gaps and masses of any initial state)
        table = .false.
        if (find_key(cli, "spheres") > 0) then
            if (cli%given("spheres")) gap_key = "spheres"
            if (cli%get_word("gas") /= "no") gap_key = "density"
            table = gap_key == "spheres" .or. gap_key == "density"
        end if
        if (cli%given("gaps") .or. table) then
            gap_sum = sum(gaps)
        else
            gap_sum = real(p - 1, qp)*cli%get_real("a")
        end if
        if (cli%given("masses") .or. (table .and. present(masses))) then
            ratio = sum(masses)/minval(masses)
        else
            ratio = real(p, qp)
        end if
        diameters = real(p - 1, qp)*d
        row = diameters + gap_sum
        ! the larger of the two terms of the row's length is the one at fault
        culprit = gap_key
        if (.not. (diameters <= big) .or. diameters >= gap_sum) culprit = "d"
        if (.not. (row <= big)) then
            call refuse_scale(error, cli, culprit, "the row's length "//row_text &
                //" overflows "//kind_name//"; allowed "//row_text//" <= "//limit)
            return
        end if
        if (.not. (gap_sum/v0 <= big)) then
            call refuse_scale(error, cli, vkey, "the time scale sum(gaps)/v0 overflows " &
                //kind_name//" (sum(gaps) = "//short_text(gap_sum, 3)//"); allowed v0 >= " &
                //short_text(gap_sum/big, 3, "up"))
            return
        end if
        if (.not. (ratio <= big/2.0_qp)) then
            call refuse_scale(error, cli, "masses", "sum(masses)/min(masses) overflows " &
                //kind_name//"; allowed sum(masses)/min(masses) <= " &
                //short_text(big/2.0_qp, 3, "down"))
            return
        end if
        if (.not. (2.0_qp*ratio*v0 <= big)) then
            call refuse_scale(error, cli, vkey, "the velocity scale 2 v0 sum(m)/min(m) " &
                //"overflows "//kind_name//"; allowed v0 <= " &
                //short_text(big/(2.0_qp*ratio), 3, "down"))
            return
        end if
        if (.not. ((1.0_qp + 2.0_qp*ratio)*row <= big)) then
            if (ratio > real(p, qp)) culprit = "masses"
            call refuse_scale(error, cli, culprit, "the positions' scale "//spread_text &
                //" overflows "//kind_name//"; allowed "//spread_text//" <= "//limit)
        end if
    end subroutine check_scales

    !> The message of a scene refused for its scales, naming key `name` and its value.
    subroutine refuse_scale(error, cli, name, why)
        type(error_t), allocatable, intent(out) :: error
        type(cli_t), intent(in) :: cli
        character(len=*), intent(in) :: name, why
        call fatal_error(error, origin(cli%keys(key_index(cli, name)))//name//" = " &
            //printable(cli%get_text(name))//": "//why)
    end subroutine refuse_scale

end module sphere_row_scene_keys
