!> Small text helpers shared by the readers and the formatters.
module strings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   implicit none
   private

   public :: itoa, num, upper, read_real, read_int

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
      write (buf, '(i0)') i
      s = trim(buf)
   end function itoa

   !> A short readable form of a number for messages: 386, 0.2, 1.5E-04.
   pure function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      integer :: e, k
      if (abs(x) < 1.0e15_wp .and. abs(x - anint(x)) <= 1.0e-12_wp*max(1.0_wp, abs(x))) then
         write (buf, '(i0)') nint(x, kind=8)
         s = trim(buf)
      else if (abs(x) >= 1.0e-3_wp .and. abs(x) < 1.0e6_wp) then
         write (buf, '(f0.6)') x
         s = trim(buf)
         k = len(s)
         do while (s(k:k) == '0')
            k = k - 1
         end do
         s = s(1:k)
         if (s(1:1) == '.') s = '0'//s
         if (s(1:2) == '-.') s = '-0'//s(2:)
      else
         if (abs(x) >= 1.0e100_wp .or. (abs(x) < 1.0e-99_wp .and. abs(x) > 0.0_wp)) then
            write (buf, '(es13.5e3)') x
         else
            write (buf, '(es13.5)') x
         end if
         s = trim(adjustl(buf))
         e = index(s, 'E')
         k = e - 1
         do while (s(k:k) == '0')
            k = k - 1
         end do
         if (s(k:k) == '.') k = k + 1
         s = s(1:k)//s(e:)
      end if
   end function num

end module strings
