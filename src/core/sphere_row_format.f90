!> Text form of numbers: reals with every significant digit of their kind
!> (tables), reals in the fewest digits that read back (messages, `--help`,
!> prose), integers of either kind with as many places as they need.
module sphere_row_format
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_negative
    use sphere_row_kinds, only: dp, qp
    implicit none
    private
    public :: real_str, short_text, itoa, real_text, int_text, number_text_length, put_exponent, &
        finite, earned_str, earned_text

    !> Length of the buffers of real_text (enough for up to 52 digits) and
    !> int_text.
    integer, parameter :: number_text_length = 64
    !> Limbs of nine decimal digits for the longest integer that the exact
    !> decimal digits of a real128 need: m 5^16607, m of 113 bits (the
    !> smallest subnormal), has some 11,650 digits.
    integer, parameter :: limbs_most = 1320
    integer(int64), parameter :: limb_base = 1000000000_int64
    !> The two digits of each k = 0..99 at 2 k + 1 and 2 k + 2.
    character(len=200), parameter :: digit_pairs = &
        "00010203040506070809101112131415161718192021222324" &
        //"25262728293031323334353637383940414243444546474849" &
        //"50515253545556575859606162636465666768697071727374" &
        //"75767778798081828384858687888990919293949596979899"
    !> The mantissa of zero at any number of digits.
    character(len=number_text_length), parameter :: zeros = repeat("0", number_text_length)
    !> 10^j, j = 0..18: the places of an int64.
    integer(int64), parameter :: tens(0:18) = [1_int64, 10_int64, 10_int64**2, &
        10_int64**3, 10_int64**4, 10_int64**5, 10_int64**6, 10_int64**7, 10_int64**8, &
        10_int64**9, 10_int64**10, 10_int64**11, 10_int64**12, 10_int64**13, 10_int64**14, &
        10_int64**15, 10_int64**16, 10_int64**17, 10_int64**18]

    !> Text of an integer of either kind.
    interface itoa
        module procedure itoa_default, itoa_int64
    end interface itoa

contains

    !> Text of a default integer.
    pure function itoa_default(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        s = itoa_int64(int(i, int64))
    end function itoa_default

    !> Text of a 64-bit integer (counts, fingerprints).
    pure function itoa_int64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=number_text_length) :: buf
        integer :: length
        call int_text(i, buf, length)
        s = buf(:length)
    end function itoa_int64

    !> itoa into `text`, its first `length` characters: a subroutine, as
    !> real_text and for the same reason, so that threads may call it at once.
    pure subroutine int_text(i, text, length)
        integer(int64), intent(in) :: i
        character(len=number_text_length), intent(out) :: text
        integer, intent(out) :: length
        integer(int64) :: rest
        integer :: at, places, pair
        ! digits from the right, two at a time, without formatted I/O (it is
        ! called per line of long outputs); the most negative value has no
        ! positive twin
        if (i == -huge(i) - 1) then
            text = "-9223372036854775808"
            length = 20
            return
        end if
        rest = abs(i)
        places = 1
        do while (places < 19)
            if (rest < tens(places)) exit
            places = places + 1
        end do
        length = places
        if (i < 0) length = length + 1
        text(length + 1:) = ""
        at = length
        do while (rest >= 10)
            pair = int(mod(rest, 100_int64))
            text(at - 1:at) = digit_pairs(2*pair + 1:2*pair + 2)
            rest = rest/100
            at = at - 2
        end do
        if (at > length - places) then
            text(at:at) = achar(iachar("0") + int(rest))
        end if
        if (i < 0) text(1:1) = "-"
    end subroutine int_text

    !> `x` (converted exactly to real128) written with `digits` significant
    !> digits in scientific notation; the exponent gets as many places as it needs.
    !> Non-finite values are written as `nan`, `inf` or `-inf`.
    pure function real_str(x, digits) result(str)
        real(qp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: str
        character(len=number_text_length) :: buf
        integer :: length
        call real_text(x, digits, buf, length)
        str = buf(:length)
    end function real_str

    !> real_str into `text`, its first `length` characters: the text that
    !> Fortran's ES(digits+ew+8).(digits-1)E(ew) edit descriptor writes (ew = 2
    !> exponent digits unless |log10 |x|| >= 99, then 4), without its leading
    !> blanks. Made without formatted I/O: gfortran's internal write holds one
    !> lock of its run-time library for the whole statement, so that threads
    !> formatting numbers at once wait for each other (measured: the b2 grid
    !> on two threads spent most of its waits there). No character result of
    !> deferred length either: gfortran 12 keeps the length of such a result
    !> in a static variable of the caller, so two threads that call one at
    !> once may get each other's length; threads may call this subroutine at
    !> once.
    pure subroutine real_text(x, digits, text, length)
        real(qp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=number_text_length), intent(out) :: text
        integer, intent(out) :: length
        character(len=number_text_length) :: mantissa
        integer :: power, ew, at
        if (.not. finite(x)) then
            if (x /= x) then
                text = "nan"
                length = 3
            else
                text = merge("inf ", "-inf", x > 0)
                length = len_trim(text)
            end if
        else
            ew = 2
            if (beyond_two_places(x)) ew = 4
            call decimal_digits(abs(x), digits, mantissa, power)
            ! sign, d.ddd, E, sign, the exponent's places: put in place (the
            ! text of every number of a long row's answer)
            at = 0
            if (negative(x)) then
                text(1:1) = "-"
                at = 1
            end if
            text(at + 1:at + 1) = mantissa(1:1)
            text(at + 2:at + 2) = "."
            text(at + 3:at + digits + 1) = mantissa(2:digits)
            at = at + digits + 1
            call put_exponent(power, ew, text, at)
            text(at + 1:) = ""
            length = at
        end if
    end subroutine real_text

    !> x written down to the decade of its bound and no further, as sphere-row
    !> writes a velocity: with `most` significant digits (default every digit
    !> of real(16); no fewer than 2) where the bound is 0 (x exact), or NaN or
    !> infinite (no bound to go by), and as real_str where x is not finite
    !> (nan, inf, -inf); else with the digits from x's decade down to the
    !> bound's, at most `most`. Where fewer than two digits are earned, x
    !> rounded at the bound's decade as q 10^place: 0E-33 for 0 within
    !> 1e-33, 1E+00 for 0.96 within 0.1, 0E-01 for 0.003 within 0.1, 0E+4932
    !> within huge (the engine's bound where it has none).
    pure function earned_str(x, bound, most) result(str)
        real(qp), intent(in) :: x, bound
        integer, intent(in), optional :: most
        character(len=:), allocatable :: str
        character(len=number_text_length) :: buf
        integer :: length
        call earned_text(x, bound, buf, length, most)
        str = buf(:length)
    end function earned_str

    !> earned_str into `text`, its first `length` characters (as real_text
    !> is real_str's: made without I/O, callable from threads at once).
    pure subroutine earned_text(x, bound, text, length, most)
        real(qp), intent(in) :: x, bound
        character(len=number_text_length), intent(out) :: text
        integer, intent(out) :: length
        integer, intent(in), optional :: most
        integer :: digits, earned, place, q
        digits = precision(x) + 1
        if (present(most)) digits = max(2, most)
        if (.not. (finite(x) .and. bound > 0 .and. bound <= huge(bound))) then
            call real_text(x, digits, text, length)
            return
        end if
        place = decade(bound)
        earned = 0
        if (x /= 0) earned = decade(abs(x)) - place + 1
        if (earned >= 2) then
            call real_text(x, min(digits, earned), text, length)
            return
        end if
        ! (|x| < 10^(place + 1) here, so |q| <= 10; 10^-place in two factors,
        ! each within range at every scale)
        q = 0
        if (x /= 0) q = nint(x*10.0_qp**(-place/2)*10.0_qp**(place/2 - place))
        if (abs(q) == 10) then
            q = q/10
            place = place + 1
        end if
        call int_text(int(q, int64), text, length)
        call put_exponent(place, merge(2, 4, abs(place) < 100), text, length)
    end subroutine earned_text

    !> floor(log10(x)) of x > 0: from real(8)'s log10 where x is in its range
    !> and the logarithm is not within 1e-9 of an integer (its rounding, about
    !> 1e-16, cannot then move the floor), else from real(16)'s, twenty times
    !> slower (two of them per sphere of a long row's answer). Within about
    !> 1e-33 of a power of ten, relatively, real(16)'s log10 rounds to the
    !> integer: x just below 10^k has decade k (a bound's then ends one digit
    !> sooner; a value's text rounds to 10^k).
    pure integer function decade(x)
        real(qp), intent(in) :: x
        real(dp) :: l
        ! (the range told in real(8), where a comparison is no call: x rounded
        ! into tiny or huge of real(8) has their decade)
        l = real(x, dp)
        if (l >= tiny(1.0_dp) .and. l <= huge(1.0_dp)) then
            l = log10(l)
            if (abs(l - anint(l)) > 1.0e-9_dp) then
                decade = floor(l)
                return
            end if
        end if
        decade = floor(log10(x))
    end function decade

    !> `E`, the sign and |power| in at least `places` places (2 or 4), put
    !> into `text` after its first `length` characters; `length` moves past
    !> them: 1.5E-02's and real_str's exponent.
    pure subroutine put_exponent(power, places, text, length)
        integer, intent(in) :: power, places
        character(len=number_text_length), intent(inout) :: text
        integer, intent(inout) :: length
        character(len=number_text_length) :: e
        integer :: ne
        if (abs(power) < 100) then
            ! (two places, the exponent of every ordinary number)
            e(1:2) = digit_pairs(2*abs(power) + 1:2*abs(power) + 2)
            ne = 2
        else
            call int_text(int(abs(power), int64), e, ne)
        end if
        text(length + 1:length + 2) = merge("E+", "E-", power >= 0)
        length = length + 2
        if (ne < places) then
            text(length + 1:length + places - ne) = "000"
            length = length + places - ne
        end if
        text(length + 1:length + ne) = e(:ne)
        length = length + ne
    end subroutine put_exponent

    !> x is neither infinite nor a NaN: for binary128, its exponent field is
    !> not all ones, told from its bits (real(16) comparisons are calls: three
    !> a sphere of a long row's answer).
    elemental logical function finite(x)
        real(qp), intent(in) :: x
        integer, parameter :: i16 = selected_int_kind(38)
        if (digits(x) == 113 .and. maxexponent(x) == 16384) then
            finite = iand(shiftr(transfer(x, 1_i16), 112), 32767_i16) /= 32767_i16
        else
            finite = x == x .and. abs(x) <= huge(x)
        end if
    end function finite

    !> x carries a minus sign (-0 too), from its sign bit for binary128.
    pure logical function negative(x)
        real(qp), intent(in) :: x
        integer, parameter :: i16 = selected_int_kind(38)
        if (digits(x) == 113 .and. maxexponent(x) == 16384) then
            negative = btest(transfer(x, 1_i16), 127)
        else
            negative = ieee_is_negative(x)
        end if
    end function negative

    !> x is +0 or -0, from its bits for binary128.
    pure logical function is_zero(x)
        real(qp), intent(in) :: x
        integer, parameter :: i16 = selected_int_kind(38)
        if (digits(x) == 113 .and. maxexponent(x) == 16384) then
            is_zero = iand(transfer(x, 1_i16), huge(1_i16)) == 0
        else
            is_zero = x == 0.0_qp
        end if
    end function is_zero

    !> The exponent of finite x /= 0 needs more than two places: |x| >= 1e99
    !> or |x| <= 1e-99. A binary128 number of binary exponent within +-320
    !> (2^-320 > 1e-99, 2^321 < 1e99) needs two: told from its bits, without
    !> the two comparisons of real(16), which are calls.
    pure logical function beyond_two_places(x)
        real(qp), intent(in) :: x
        integer, parameter :: i16 = selected_int_kind(38)
        integer :: biased
        if (digits(x) == 113 .and. maxexponent(x) == 16384) then
            biased = int(iand(shiftr(transfer(x, 1_i16), 112), 32767_i16))
            if (abs(biased - 16383) <= 320) then
                beyond_two_places = .false.
                return
            end if
        end if
        beyond_two_places = x /= 0.0_qp .and. (abs(x) >= 1.0e99_qp .or. abs(x) <= 1.0e-99_qp)
    end function beyond_two_places

    !> The first n significant digits of y >= 0 (finite), rounded to nearest
    !> with ties to even, as in y = 0.d1 d2 ... dn * 10^(power + 1): exactly,
    !> from y = m 2^k (m an integer of at most 113 bits) as the integer m 2^k
    !> (k >= 0) or m 5^(-k) times 10^k (k < 0), in limbs of nine decimal digits.
    !> The work grows with the square of |k|: about a microsecond for ordinary
    !> numbers, under 10 us up to 1e+-300, about 1.5 ms for the smallest
    !> subnormal (11,641 digits).
    pure subroutine decimal_digits(y, n, mantissa, power)
        real(qp), intent(in) :: y
        integer, intent(in) :: n
        character(len=number_text_length), intent(out) :: mantissa
        integer, intent(out) :: power
        logical :: done
        ! (a constant of zeros: repeat with n would make a temporary each call)
        mantissa = zeros
        power = 0
        if (is_zero(y)) return
        call fast_digits(y, n, mantissa, power, done)
        if (done) return
        call exact_digits(y, n, mantissa, power)
    end subroutine decimal_digits

    !> decimal_digits by the long road, exactly, in limbs: any finite y > 0 (its
    !> work arrays, some 20 kB, only where it is taken).
    pure subroutine exact_digits(y, n, mantissa, power)
        real(qp), intent(in) :: y
        integer, intent(in) :: n
        character(len=number_text_length), intent(inout) :: mantissa
        integer, intent(out) :: power
        integer(int64) :: limb(limbs_most)
        character(len=9*limbs_most) :: all
        real(qp) :: m, high
        integer(int64) :: low
        integer :: nl, k, shift, step, length, i
        logical :: up
        m = scale(fraction(y), digits(y))
        k = exponent(y) - digits(y)
        ! m = high 2^56 + low into limbs, exactly (high and low are integers
        ! of at most 57 bits, which int64 holds)
        high = aint(scale(m, -56))
        low = int(m - scale(high, 56), int64)
        nl = 0
        call limbs_times_plus(limb, nl, 1_int64, int(high, int64))
        call limbs_times_plus(limb, nl, 2_int64**28, 0_int64)
        call limbs_times_plus(limb, nl, 2_int64**28, low)
        shift = min(k, 0)
        do while (k > 0)
            step = min(k, 29)
            call limbs_times_plus(limb, nl, 2_int64**step, 0_int64)
            k = k - step
        end do
        do while (k < 0)
            step = min(-k, 13)
            call limbs_times_plus(limb, nl, 5_int64**step, 0_int64)
            k = k + step
        end do
        ! the digits of the integer, from its most significant limb
        length = 0
        do i = nl, 1, -1
            call limb_digits(limb(i), i == nl, all, length)
        end do
        power = length - 1 + shift
        if (length <= n) then
            mantissa(1:length) = all(1:length)
            return
        end if
        mantissa(1:n) = all(1:n)
        up = all(n + 1:n + 1) > "5"
        if (all(n + 1:n + 1) == "5") up = verify(all(n + 2:length), "0") > 0 .or. &
            mod(iachar(all(n:n)) - iachar("0"), 2) == 1
        if (.not. up) return
        do i = n, 1, -1
            if (mantissa(i:i) /= "9") then
                mantissa(i:i) = achar(iachar(mantissa(i:i)) + 1)
                return
            end if
            mantissa(i:i) = "0"
        end do
        ! 9...9 rounded up
        mantissa(1:1) = "1"
        power = power + 1
    end subroutine exact_digits

    !> decimal_digits by a shorter road where it is open (done), not done where
    !> not (the caller then takes the long one): y a normal binary128 number, y = m 2^k
    !> (m of 113 bits), and q = y 10^s, s = n - 1 - (decimal exponent of y)
    !> in 0 ... 54, so that m 5^s, of a 113-bit and an at most 126-bit
    !> integer, is held exactly in two int128 parts (its partial products of
    !> pieces of at most 60 and 66 bits, and their sums, stay below 2^127), and
    !> q, its integer part after the shift by 2^(s + k), below 10^n <= 10^34.
    !> The rounding to nearest, ties to even, reads the bits shifted out: the
    !> same digits as the long road, three to four times sooner (0.16 - 0.29
    !> us against 0.5 - 1 us a number of 1e-10 ... 1e6 at 34 digits; every
    !> ordinary number of a run's output takes this road).
    pure subroutine fast_digits(y, n, mantissa, power, done)
        real(qp), intent(in) :: y
        integer, intent(in) :: n
        character(len=number_text_length), intent(inout) :: mantissa
        integer, intent(inout) :: power
        logical, intent(out) :: done
        integer, parameter :: i16 = selected_int_kind(38)
        integer(i16), parameter :: one = 1_i16, mask60 = shiftl(one, 60) - 1, &
            mask120 = shiftl(one, 120) - 1
        integer :: j
        integer(i16), parameter :: five(0:54) = [(5_i16**j, j=0, 54)], &
            ten(0:34) = [(10_i16**j, j=0, 34)]
        integer(i16) :: bits, m, f, mh, ml, fh, fl, mid, low, high, q, rest, half, top
        integer :: k, p10, s, d, try
        done = .false.
        if (digits(y) /= 113 .or. maxexponent(y) /= 16384 .or. n > 34) return
        bits = transfer(y, one)
        if (shiftr(bits, 112) == 0) return
        m = ior(iand(bits, shiftl(one, 112) - 1), shiftl(one, 112))
        k = int(shiftr(bits, 112)) - 16383 - 112
        ! 10^p10 <= y < 10^(p10 + 1), p10 estimated from the binary exponent
        ! (low by at most one: then q reaches 10^n and s steps down)
        p10 = floor(real(k + 112, kind(1.0d0))*0.30102999566398120d0)
        s = n - 1 - p10
        top = ten(n)
        do try = 1, 2
            if (s < 0 .or. s > 54) return
            f = five(s)
            mh = shiftr(m, 60)
            ml = iand(m, mask60)
            fh = shiftr(f, 60)
            fl = iand(f, mask60)
            ! m f = high 2^120 + low, exactly
            mid = mh*fl + ml*fh
            low = ml*fl + shiftl(iand(mid, mask60), 60)
            high = mh*fh + shiftr(mid, 60) + shiftr(low, 120)
            low = iand(low, mask120)
            ! q = floor(m f 2^-d), d = -(s + k); rest and half compare the bits
            ! shifted out with half of the last place
            d = -(s + k)
            if (d <= 0) then
                if (high /= 0 .or. -d > 6) return
                q = shiftl(low, -d)
                rest = 0
                half = 1
            else if (d < 120) then
                if (high >= shiftl(one, d)) return
                q = shiftl(high, 120 - d) + shiftr(low, d)
                rest = iand(low, shiftl(one, d) - 1)
                half = shiftl(one, d - 1)
            else
                return
            end if
            if (q < top) exit
            s = s - 1
            if (try == 2) return
        end do
        if (q < ten(n - 1)) return
        if (rest > half .or. (rest == half .and. iand(q, one) == 1)) q = q + 1
        power = n - 1 - s
        if (q == top) then
            q = top/10
            power = power + 1
        end if
        call digits_of(q, n, mantissa)
        done = .true.
    contains
        !> The n decimal digits of 0 <= q < 10^n into mantissa(1:n): two
        !> int64 parts of 17 digits, each written from the right two digits at
        !> a time.
        pure subroutine digits_of(q, n, mantissa)
            integer(i16), intent(in) :: q
            integer, intent(in) :: n
            character(len=number_text_length), intent(inout) :: mantissa
            integer(int64) :: part(2), rest
            integer :: i, j, last, pair
            part(1) = int(q/ten(17), int64)
            part(2) = int(q - part(1)*ten(17), int64)
            do j = 2, 1, -1
                rest = part(j)
                i = n - 17*(2 - j)
                last = max(n - 17*(3 - j) + 1, 1)
                do while (i > last)
                    pair = int(mod(rest, 100_int64))
                    mantissa(i - 1:i) = digit_pairs(2*pair + 1:2*pair + 2)
                    rest = rest/100
                    i = i - 2
                end do
                if (i == last) mantissa(i:i) = achar(iachar("0") + int(mod(rest, 10_int64)))
            end do
        end subroutine digits_of
    end subroutine fast_digits

    !> Limbs 1..nl of an integer in base 10^9 times f, plus a (f < 2^31 and
    !> 0 <= a < 2^62, so that no product and carry leaves int64); with nl = 0
    !> the integer a.
    pure subroutine limbs_times_plus(limb, nl, f, a)
        integer(int64), intent(inout) :: limb(:)
        integer, intent(inout) :: nl
        integer(int64), intent(in) :: f, a
        integer(int64) :: carry, t
        integer :: j
        carry = a
        do j = 1, nl
            t = limb(j)*f + carry
            limb(j) = mod(t, limb_base)
            carry = t/limb_base
        end do
        do while (carry > 0)
            nl = nl + 1
            limb(nl) = mod(carry, limb_base)
            carry = carry/limb_base
        end do
    end subroutine limbs_times_plus

    !> The nine digits of a limb appended to text(:length) (a leading limb
    !> without its leading zeros).
    pure subroutine limb_digits(value, leading, text, length)
        integer(int64), intent(in) :: value
        logical, intent(in) :: leading
        character(len=9*limbs_most), intent(inout) :: text
        integer, intent(inout) :: length
        character(len=9) :: nine
        integer(int64) :: rest
        integer :: j, first
        rest = value
        do j = 9, 1, -1
            nine(j:j) = achar(iachar("0") + int(mod(rest, 10_int64)))
            rest = rest/10
        end do
        first = 1
        if (leading) first = max(1, verify(nine, "0"))
        text(length + 1:length + 10 - first) = nine(first:)
        length = length + 10 - first
    end subroutine limb_digits

    !> The shortest text (at most `digits` significant digits, default as many
    !> as needed) that reads back as `x`: 0.2, 1, 1000000, 1.93e-34. A bound
    !> cut to a few digits is rounded `toward` "down" or "up" if asked, so that
    !> the text is still on the allowed side.
    pure function short_text(x, digits, toward) result(text)
        real(qp), intent(in) :: x
        integer, intent(in), optional :: digits
        character(len=*), intent(in), optional :: toward
        character(len=:), allocatable :: text
        character(len=80) :: buffer, form
        character(len=3) :: mode
        real(qp) :: y
        integer :: d, most, ios
        logical :: plain
        most = 37
        if (present(digits)) most = digits
        mode = ""
        if (present(toward)) then
            if (toward == "down") mode = "rd,"
            if (toward == "up") mode = "ru,"
        end if
        plain = x == 0.0_qp .or. (abs(x) >= 1.0e-3_qp .and. abs(x) < 1.0e7_qp)
        do d = 1, most
            if (plain) then
                write (form, "('(', a, 'f0.', i0, ')')") trim(mode), d
            else
                write (form, "('(', a, 'es60.', i0, 'e5)')") trim(mode), d - 1
            end if
            write (buffer, form) x
            read (buffer, *, iostat=ios) y
            if (ios == 0 .and. y == x) exit
        end do
        text = tidy_number(trim(adjustl(buffer)))
    end function short_text

    !> Tidy a number written by short_text: no trailing zeros or '.' in the
    !> mantissa, a leading 0 before '.', a lower-case exponent without '+'
    !> and leading zeros: "1.00" -> "1", ".5" -> "0.5", "1.9E-0034" -> "1.9e-34".
    pure function tidy_number(text) result(tidy)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: tidy
        character(len=:), allocatable :: m, exponent, sign
        integer :: e
        e = scan(text, "eEdD")
        if (e == 0) then
            m = text
            exponent = ""
        else
            m = text(:e - 1)
            exponent = text(e + 1:)
        end if
        if (index(m, ".") > 0) then
            do while (len(m) > 1)
                if (m(len(m):len(m)) /= "0") exit
                m = m(:len(m) - 1)
            end do
            if (m(len(m):len(m)) == ".") m = m(:len(m) - 1)
        end if
        if (len(m) == 0) m = "0"
        if (m(1:1) == ".") m = "0"//m
        if (len(m) > 1) then
            if (m(1:2) == "-.") m = "-0"//m(2:)
        end if
        if (len(exponent) > 0) then
            sign = ""
            if (exponent(1:1) == "-") sign = "-"
            exponent = exponent(verify(exponent, "+-0"):)
            tidy = m//"e"//sign//exponent
        else
            tidy = m
        end if
    end function tidy_number

end module sphere_row_format
