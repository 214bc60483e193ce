!> Small text helpers shared by the readers and the formatters.
module strings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use kinds, only: wp, i8
   implicit none
   private

   public :: itoa, num, escaped, upper, read_real, read_int

contains

   !> Read a Fortran-style real literal: [sign] digits [. digits] [E|D [sign] digits].
   !! Anything else (NaN, Inf, embedded blanks, two points) is rejected, and
   !! so is a magnitude beyond 1e300 either way, before any conversion that
   !! could overflow.
   subroutine read_real(s, x, ok)
      character(len=*), intent(in) :: s
      real(wp), intent(out) :: x
      logical, intent(out) :: ok
      integer :: i, n, ndig, nexp, ios, exponent, lead, sig_before_point, first_sig
      logical :: point, expo, exp_negative, seen_nonzero
      character(len=len(s)) :: t

      x = 0.0_wp
      ok = .false.
      n = len(s)
      if (n == 0 .or. n > 40) return
      t = s
      i = 1
      if (t(i:i) == '+' .or. t(i:i) == '-') i = i + 1
      ndig = 0
      nexp = 0
      exponent = 0
      exp_negative = .false.
      point = .false.
      expo = .false.
      seen_nonzero = .false.
      lead = 0              ! zeros after the point before the first significant digit
      sig_before_point = 0  ! significant digits before the point
      first_sig = 0
      do while (i <= n)
         select case (t(i:i))
         case ('0':'9')
            if (expo) then
               nexp = nexp + 1
               if (nexp <= 4) exponent = 10*exponent + (iachar(t(i:i)) - iachar('0'))
            else
               ndig = ndig + 1
               if (t(i:i) /= '0') seen_nonzero = .true.
               if (seen_nonzero .and. .not. point) sig_before_point = sig_before_point + 1
               if (.not. seen_nonzero .and. point) lead = lead + 1
            end if
         case ('.')
            if (point .or. expo) return
            point = .true.
         case ('E', 'e', 'D', 'd')
            if (expo .or. ndig == 0) return
            expo = .true.
            t(i:i) = 'E'
            if (i < n) then
               if (t(i + 1:i + 1) == '+' .or. t(i + 1:i + 1) == '-') then
                  exp_negative = t(i + 1:i + 1) == '-'
                  i = i + 1
               end if
            end if
         case default
            return
         end select
         i = i + 1
      end do
      if (ndig == 0 .or. (expo .and. nexp == 0) .or. nexp > 4) return
      if (exp_negative) exponent = -exponent
      if (seen_nonzero) then
         ! decimal order of magnitude of the value
         if (sig_before_point > 0) then
            first_sig = exponent + sig_before_point - 1
         else
            first_sig = exponent - lead - 1
         end if
         if (abs(first_sig) > 300) return
      end if
      read (t, *, iostat=ios) x
      if (ios /= 0) return
      if (.not. ieee_is_finite(x)) return
      ok = .true.
   end subroutine read_real

   !> Read [sign] digits, at most 9 digits.
   pure subroutine read_int(s, n, ok)
      character(len=*), intent(in) :: s
      integer, intent(out) :: n
      logical, intent(out) :: ok
      integer :: i, first, sgn
      n = 0
      ok = .false.
      if (len(s) == 0) return
      first = 1
      sgn = 1
      if (s(1:1) == '+' .or. s(1:1) == '-') then
         if (s(1:1) == '-') sgn = -1
         first = 2
      end if
      if (len(s) < first .or. len(s) - first + 1 > 9) return
      do i = first, len(s)
         if (s(i:i) < '0' .or. s(i:i) > '9') return
         n = 10*n + (iachar(s(i:i)) - iachar('0'))
      end do
      n = sgn*n
      ok = .true.
   end subroutine read_int

   pure function upper(s) result(u)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: u
      integer :: i
      u = s
      do i = 1, len(s)
         if (u(i:i) >= 'a' .and. u(i:i) <= 'z') u(i:i) = achar(iachar(u(i:i)) - 32)
      end do
   end function upper

   pure function itoa(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=16) :: buf
      integer(i8) :: m
      integer :: p
      ! (the digits by hand: an internal write costs some 4,500 instructions,
      ! and a listing makes thousands; the magnitude in 64 bits, so that
      ! -huge(i) - 1 has one)
      m = abs(int(i, i8))
      p = len(buf) + 1
      do
         p = p - 1
         buf(p:p) = achar(iachar('0') + int(mod(m, 10_i8)))
         m = m/10_i8
         if (m == 0_i8) exit
      end do
      if (i < 0) then
         p = p - 1
         buf(p:p) = '-'
      end if
      s = buf(p:)
   end function itoa

   !> A number for messages, warnings and generated docs: the shortest
   !! decimal of at most 15 significant digits (or of `digits`, when given)
   !! that reads back as x, else x to 15 (`digits`) significant digits:
   !! 386, 0.2, 0.9999999, 1.5E-04, 1.0E-14. Every value a deck can give is
   !! printed as written (a value is never rounded to the round number a
   !! check compares it with: "G = 0.9999999", not "G = 1."); only the last
   !! bits of a computed or converted value (75.00000000000001 from radians)
   !! are left out, below every tolerance the program checks. Magnitudes
   !! from 1e-3 to below 1e7 print in fixed point (whole numbers without a
   !! point), others as d.dE+nn.
   pure function num(x, digits) result(s)
      real(wp), intent(in) :: x
      integer, intent(in), optional :: digits
      character(len=:), allocatable :: s
      integer, parameter :: max_digits = 15
      character(len=40) :: buf
      character(len=:), allocatable :: mantissa, sign
      integer :: p, p_max, e, n, ios
      real(wp) :: back

      if (ieee_is_nan(x)) then
         s = 'NaN'
         return
      else if (.not. ieee_is_finite(x)) then
         s = merge('-Infinity', 'Infinity ', x < 0.0_wp)
         s = trim(s)
         return
      else if (.not. abs(x) > 0.0_wp) then
         s = '0'
         return
      end if
      p_max = max_digits
      if (present(digits)) p_max = max(1, min(digits, max_digits))
      ! the fewest significant digits that read back as x
      do p = 1, p_max
         call scientific(abs(x), p, mantissa, e)
         buf = buf_of(mantissa, e)
         read (buf, *, iostat=ios) back
         if (ios == 0 .and. .not. abs(back - abs(x)) > 0.0_wp) exit
      end do
      if (p > p_max) call scientific(abs(x), p_max, mantissa, e)
      ! trailing zeros carry nothing
      n = len(mantissa)
      do while (n > 1 .and. mantissa(n:n) == '0')
         n = n - 1
      end do
      mantissa = mantissa(1:n)
      sign = ''
      if (x < 0.0_wp) sign = '-'
      if (e >= -3 .and. e <= 6) then
         if (e >= 0) then
            if (n <= e + 1) then
               s = sign//mantissa//repeat('0', e + 1 - n)
            else
               s = sign//mantissa(1:e + 1)//'.'//mantissa(e + 2:)
            end if
         else
            s = sign//'0.'//repeat('0', -e - 1)//mantissa
         end if
      else
         if (n == 1) then
            s = sign//mantissa//'.0'
         else
            s = sign//mantissa(1:1)//'.'//mantissa(2:)
         end if
         write (buf, '(i2.2)') abs(e)
         if (abs(e) > 99) write (buf, '(i0)') abs(e)
         s = s//'E'//merge('-', '+', e < 0)//trim(buf)
      end if
   contains
      !> The significant digits of y > 0 rounded to p, and its decimal exponent.
      pure subroutine scientific(y, p, digits_out, exponent)
         real(wp), intent(in) :: y
         integer, intent(in) :: p
         character(len=:), allocatable, intent(out) :: digits_out
         integer, intent(out) :: exponent
         character(len=40) :: b
         character(len=16) :: fmt
         integer :: k, epos
         write (fmt, '(a,i0,a,i0,a)') '(es', p + 10, '.', p - 1, 'e4)'
         write (b, fmt) y
         b = adjustl(b)
         epos = index(b, 'E')
         read (b(epos + 1:), *) exponent
         digits_out = ''
         do k = 1, epos - 1
            if (b(k:k) >= '0' .and. b(k:k) <= '9') digits_out = digits_out//b(k:k)
         end do
      end subroutine scientific
      !> The text "d.dddE+eeee" of significant digits m and exponent ex.
      pure function buf_of(m, ex) result(t)
         character(len=*), intent(in) :: m
         integer, intent(in) :: ex
         character(len=:), allocatable :: t
         character(len=12) :: eb
         write (eb, '(i0)') ex
         t = m(1:1)//'.'//m(2:)//'0E'//trim(eb)
      end function buf_of
   end function num

   !> A name (a file's) for messages and the listing, one line whatever it
   !! holds: a backslash and the control characters are escaped as in C
   !! (\\, \n, \t, \r, \xNN), so that a name never splits a message or
   !! an echo line and the escaped form cannot be mistaken for another name.
   pure function escaped(name) result(s)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: s
      character(len=*), parameter :: hex = '0123456789ABCDEF'
      integer :: i, c
      s = ''
      do i = 1, len(name)
         c = iachar(name(i:i))
         select case (c)
         case (92)
            s = s//'\\'
         case (10)
            s = s//'\n'
         case (9)
            s = s//'\t'
         case (13)
            s = s//'\r'
         case (0:8, 11:12, 14:31, 127)
            s = s//'\x'//hex(c/16 + 1:c/16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
         case default
            s = s//name(i:i)
         end select
      end do
   end function escaped

end module strings
