!> Analysis of collision sequences in the working precision: the sequence of a
!> run, its repeating tail, the linear map a sequence applies to the rates, the
!> restitution at which a collapse cycle stops being self-similar, and the final
!> velocities of a fixed sequence as polynomials in e.
module sphere_row_analysis
    use sphere_row, only: qp, wp => qp, event_log_t, status_normal, status_invalid, &
        event_collision, event_collapse
    use sphere_row_bisection, only: bisect
    implicit none
    private
    public :: sequence_of, sequence_text, sequence_hash, tail_period, rate_map
    public :: cubic_discriminant, critical_restitution, sequence_polynomials, poly_eval

contains

    !> Pairs i (collision of spheres i, i+1) of the collisions in a log, in
    !> order, up to the first collapse limit if `before_collapse` is true.
    pure subroutine sequence_of(log, pairs, before_collapse)
        type(event_log_t), intent(in) :: log
        integer, allocatable, intent(out) :: pairs(:)
        logical, intent(in), optional :: before_collapse
        integer :: j, n, last
        last = log%n
        if (present(before_collapse)) then
            if (before_collapse) then
                do j = 1, log%n
                    if (log%kind(j) == event_collapse) then
                        last = j - 1
                        exit
                    end if
                end do
            end if
        end if
        n = count(log%kind(1:last) == event_collision)
        allocate (pairs(n))
        n = 0
        do j = 1, last
            if (log%kind(j) == event_collision) then
                n = n + 1
                pairs(n) = log%first(j)
            end if
        end do
    end subroutine sequence_of

    !> The sequence as text: digits for rows of up to 10 spheres, else a
    !> dot-separated list.
    pure function sequence_text(pairs) result(text)
        integer, intent(in) :: pairs(:)
        character(len=:), allocatable :: text
        character(len=12) :: buf
        integer :: j
        text = ""
        if (size(pairs) == 0) return
        if (maxval(pairs) <= 9) then
            text = repeat(" ", size(pairs))
            do j = 1, size(pairs)
                text(j:j) = achar(iachar("0") + pairs(j))
            end do
        else
            do j = 1, size(pairs)
                write (buf, "(i0)") pairs(j)
                text = text//merge(".", " ", j > 1)//trim(buf)
            end do
            text = text(2:)
        end if
    end function sequence_text

    !> A 64-bit fingerprint of a sequence (FNV-1a over its pairs), to tell
    !> sequences apart without storing them.
    pure function sequence_hash(pairs) result(hash)
        integer, intent(in) :: pairs(:)
        integer(8) :: hash
        integer(8), parameter :: prime = 1099511628211_8
        integer :: j
        hash = -3750763034362895579_8
        do j = 1, size(pairs)
            hash = ieor(hash, int(pairs(j), 8))
            hash = hash*prime
        end do
    end function sequence_hash

    !> Smallest period P <= max_period with which the last `window` pairs
    !> repeat; 0 if there is none (or the sequence is too short).
    pure integer function tail_period(pairs, window, max_period) result(period)
        integer, intent(in) :: pairs(:), window, max_period
        integer :: n, q, j
        logical :: repeats
        n = size(pairs)
        period = 0
        do q = 1, max_period
            if (n < window + q) return
            repeats = .true.
            do j = n - window + 1, n
                if (pairs(j) /= pairs(j - q)) then
                    repeats = .false.
                    exit
                end if
            end do
            if (repeats) then
                period = q
                return
            end if
        end do
    end function tail_period

    !> Matrix `a` of size (p-1, p-1) that maps the gap rates before the
    !> collisions `pairs` to the rates after them, by (6) with masses m.
    pure subroutine rate_map(m, e, pairs, a)
        real(qp), intent(in) :: m(:), e
        integer, intent(in) :: pairs(:)
        real(qp), intent(out) :: a(:, :)
        integer :: j, k, q
        real(qp) :: left, right, spare(size(a, 2)), spare_right(size(a, 2))
        q = size(m) - 1
        a = 0.0_qp
        do j = 1, q
            a(j, j) = 1.0_qp
        end do
        do j = 1, size(pairs)
            k = pairs(j)
            left = (1.0_qp + e)*m(k + 1)/(m(k) + m(k + 1))
            right = (1.0_qp + e)*m(k)/(m(k) + m(k + 1))
            ! the collision (6) on the rows: new dy(k-1) = dy(k-1) + left dy(k), ...
            spare = 0.0_qp
            if (k > 1 .and. k < q) then
                call collide_rates(a(k, :), a(k - 1, :), a(k + 1, :), left, right, e)
            else if (k > 1) then
                call collide_rates(a(k, :), a(k - 1, :), spare, left, right, e)
            else if (k < q) then
                call collide_rates(a(k, :), spare, a(k + 1, :), left, right, e)
            else
                spare_right = 0.0_qp
                call collide_rates(a(k, :), spare, spare_right, left, right, e)
            end if
        end do
    end subroutine rate_map

    !> Discriminant of the characteristic polynomial of a 3x3 matrix, scaled by
    !> its trace so that it is dimensionless: positive for three distinct real
    !> eigenvalues, negative for a complex pair.
    pure function cubic_discriminant(a) result(disc)
        real(qp), intent(in) :: a(3, 3)
        real(qp) :: disc
        real(qp) :: b(3, 3), c1, c2, c3, s
        s = a(1, 1) + a(2, 2) + a(3, 3)
        if (s == 0.0_qp) s = maxval(abs(a))
        b = a/s
        ! lambda^3 - c1 lambda^2 + c2 lambda - c3
        c1 = b(1, 1) + b(2, 2) + b(3, 3)
        c2 = b(1, 1)*b(2, 2) - b(1, 2)*b(2, 1) + b(1, 1)*b(3, 3) - b(1, 3)*b(3, 1) &
            + b(2, 2)*b(3, 3) - b(2, 3)*b(3, 2)
        c3 = b(1, 1)*(b(2, 2)*b(3, 3) - b(2, 3)*b(3, 2)) &
            - b(1, 2)*(b(2, 1)*b(3, 3) - b(2, 3)*b(3, 1)) &
            + b(1, 3)*(b(2, 1)*b(3, 2) - b(2, 2)*b(3, 1))
        ! discriminant of x^3 + B x^2 + C x + D with B = -c1, C = c2, D = -c3
        disc = 18*(-c1)*c2*(-c3) - 4*(-c1)**3*(-c3) + c1**2*c2**2 - 4*c2**3 - 27*c3**2
    end function cubic_discriminant

    !> The restitution in [e_lo, e_hi] at which the rate map of the collision
    !> cycle `cycle` (four spheres, masses m) gets a complex eigenvalue pair,
    !> found by bisecting the sign of its discriminant to the resolution of
    !> real128. A collapse along the cycle needs a real dominant eigenvector,
    !> so this is where that collapse stops. `stat` is status_invalid if the
    !> row is not of four spheres or the sign does not change in the bracket.
    subroutine critical_restitution(m, cycle, e_lo, e_hi, e_c, stat)
        real(qp), intent(in) :: m(:), e_lo, e_hi
        integer, intent(in) :: cycle(:)
        real(qp), intent(out) :: e_c
        integer, intent(out) :: stat
        real(qp) :: lo, hi, a(3, 3), d_lo
        !> Most halvings: more than real128 can resolve in [0, 1].
        integer, parameter :: max_steps = 200
        e_c = 0.0_qp
        stat = status_invalid
        if (size(m) /= 4 .or. size(cycle) == 0) return
        lo = e_lo
        hi = e_hi
        call rate_map(m, lo, cycle, a)
        d_lo = cubic_discriminant(a)
        call rate_map(m, hi, cycle, a)
        if (sign(1.0_qp, d_lo) == sign(1.0_qp, cubic_discriminant(a))) return
        call bisect(same_sign_as_lo, lo, hi, 0.0_qp, max_steps)
        e_c = 0.5_qp*(lo + hi)
        stat = status_normal

    contains

        !> Whether the discriminant at e has the sign it has at e_lo.
        logical function same_sign_as_lo(e) result(same)
            real(qp), intent(in) :: e
            real(qp) :: map(3, 3)
            call rate_map(m, e, cycle, map)
            same = sign(1.0_qp, cubic_discriminant(map)) == sign(1.0_qp, d_lo)
        end function same_sign_as_lo

    end subroutine critical_restitution

    !> Final velocities after the collisions `pairs` of a row struck at v0, as
    !> polynomials in e: v_i(e) = sum_j coef(j, i) e^j, degree <= size(pairs).
    !> Exact wherever the run has this sequence: each collision (2) is linear in
    !> the velocities with coefficients linear in e.
    pure subroutine sequence_polynomials(m, v0, pairs, coef)
        real(qp), intent(in) :: m(:), v0
        integer, intent(in) :: pairs(:)
        real(qp), allocatable, intent(out) :: coef(:, :)
        real(qp), allocatable :: w(:), kick(:)
        integer :: j, k, n
        n = size(pairs)
        allocate (coef(0:n, size(m)), w(0:n), kick(0:n))
        coef = 0.0_qp
        coef(0, 1) = v0
        do j = 1, n
            k = pairs(j)
            w = coef(:, k + 1) - coef(:, k)
            ! (1 + e) w
            kick = w
            kick(1:) = kick(1:) + w(:n - 1)
            coef(:, k) = coef(:, k) + m(k + 1)/(m(k) + m(k + 1))*kick
            coef(:, k + 1) = coef(:, k + 1) - m(k)/(m(k) + m(k + 1))*kick
        end do
    end subroutine sequence_polynomials

    !> Value of sum_j coef(j) e^j by Horner's rule.
    pure function poly_eval(coef, e) result(value)
        real(qp), intent(in) :: coef(0:), e
        real(qp) :: value
        integer :: j
        value = 0.0_qp
        do j = ubound(coef, 1), 0, -1
            value = value*e + coef(j)
        end do
    end function poly_eval

    include "../../src/engine/sphere_row_rule.inc"

end module sphere_row_analysis
