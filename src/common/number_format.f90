!> Numbers in fixed-width listing fields, never printed as asterisks:
!! fixed switches a value that does not fit the F editing of its field to
!! E editing of the same width (wider only when even that cannot hold it,
!! in a field narrower than 9 columns); right_int right-justifies an integer
!! in its field and widens the field for one that does not fit; es11_3 and
!! f10_5 write the time-history tables' fields, the same characters as the
!! edit descriptors ES11.3 and F10.5, fast (ES11.3 holds every double; F10.5
!! every time up to TMAX's limit, 1000 s, the library's F10.5 beyond).
!!
!! Why the fast forms: the listing's time histories are most of its
!! numbers, and the run-time library's formatted conversion costs some
!! 2,600 instructions a number (a printf of the exact decimal expansion):
!! a third of a whole default-deck run (docs/performance.md). The fast
!! forms scale the number to its four (five) kept digits by one correctly
!! rounded multiplication or division by an exact power of ten, so the
!! scaled value is within a relative 2**-53 of the exact one; rounding it
!! to an integer gives the exact decimal rounding unless the exact value
!! lies within that error of a half (a tie, or near one), and there, and for
!! values outside the exact powers' range (zero, tiny, huge, NaN, Inf), they
!! use the library's conversion itself. test_number_format compares them
!! with the library over millions of values.
module number_format
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_negative
   use kinds, only: wp, i8
   implicit none
   private

   public :: fixed, es11_3, f10_5, right_int

   !> An integer right-justified in a field of w columns, or wider when it
   !! needs more (never asterisks).
   interface right_int
      module procedure right_int_default, right_int_i8
   end interface right_int

   !> 10**k, k = 0..22: every one exactly a double.
   real(wp), parameter :: pow10(0:22) = [1.0e0_wp, 1.0e1_wp, 1.0e2_wp, 1.0e3_wp, 1.0e4_wp, 1.0e5_wp, &
                                         1.0e6_wp, 1.0e7_wp, 1.0e8_wp, 1.0e9_wp, 1.0e10_wp, 1.0e11_wp, 1.0e12_wp, &
                                         1.0e13_wp, 1.0e14_wp, 1.0e15_wp, 1.0e16_wp, 1.0e17_wp, 1.0e18_wp, &
                                         1.0e19_wp, 1.0e20_wp, 1.0e21_wp, 1.0e22_wp]
   !> How close to a half (in units of the last kept digit) the scaled value
   !! may come before the library decides: far above its error (at most
   !! 1e4 * 2**-53, about 1.1e-12, for the ES field; 1e8 * 2**-53 for F10.5).
   real(wp), parameter :: tie_window = 1.0e-6_wp
   character(len=10), parameter :: digit_char = '0123456789'

contains

   !> x in w columns with d decimals (Fw.d), or in E notation when that
   !! would overflow the field (w >= 9 holds every double so); in a narrower
   !! field, a value that fits neither gets the few columns more it needs.
   function fixed(x, w, d) result(s)
      real(wp), intent(in) :: x
      integer, intent(in) :: w, d
      character(len=:), allocatable :: s
      character(len=16) :: fmt
      character(len=40) :: wide
      integer :: digits, width
      allocate (character(len=w) :: s)
      write (fmt, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
      write (s, fmt) x
      if (index(s, '*') == 0) return
      ! a blank, the sign, a digit, the point, E, the exponent's sign and digits
      width = max(w, 9)
      if (abs(x) >= 1.0e100_wp) then
         digits = max(1, width - 9)
         write (fmt, '(a,i0,a,i0,a)') '(es', width, '.', digits, 'e3)'
      else
         digits = max(1, width - 8)
         write (fmt, '(a,i0,a,i0,a)') '(es', width, '.', digits, ')'
      end if
      write (wide, fmt) x
      if (width == w) then
         s = wide(1:w)
      else
         ! as few columns past w as it needs
         s = trim(adjustl(wide(1:width)))
         if (len(s) < w) s = repeat(' ', w - len(s))//s
      end if
   end function fixed

   function right_int_default(n, w) result(s)
      integer, intent(in) :: n, w
      character(len=:), allocatable :: s
      s = right_int_i8(int(n, i8), w)
   end function right_int_default

   function right_int_i8(n, w) result(s)
      integer(i8), intent(in) :: n
      integer, intent(in) :: w
      character(len=:), allocatable :: s
      character(len=24) :: digits
      write (digits, '(i0)') n
      s = trim(digits)
      if (len(s) < w) s = repeat(' ', w - len(s))//s
   end function right_int_i8

   !> write (s, '(es11.3)') x: "  d.dddE+xx", "-" before the digit when x < 0.
   pure function es11_3(x) result(s)
      real(wp), intent(in) :: x
      character(len=11) :: s
      real(wp) :: a, y
      integer :: e, n, k
      ! 10**(3-e) exact for e in -19..25, one off either way included (NaN
      ! goes to the library uncompared: an ordered comparison would signal)
      if (ieee_is_nan(x)) then
         a = 0.0_wp
      else
         a = abs(x)
         if (.not. a > 0.0_wp) then       ! zero, a listing's most frequent number (pairs out of contact)
            s = '  0.000E+00'
            if (ieee_is_negative(x)) s(2:2) = '-'
            return
         end if
      end if
      if (.not. (a >= 1.0e-18_wp .and. a < 1.0e24_wp)) then
         write (s, '(es11.3)') x
         return
      end if
      e = floor(log10(a))
      do k = 1, 2            ! log10's floor may be one off next to a power of ten
         y = scaled(a, 3 - e)
         ! (which exponent is itself decided by a tie, at 999.5 and 9999.5)
         if (abs(y - 999.5_wp) < tie_window .or. abs(y - 9999.5_wp) < tie_window) exit
         if (y < 999.5_wp) then
            e = e - 1
         else if (y >= 9999.5_wp) then
            e = e + 1
         else
            exit
         end if
      end do
      if (.not. (y >= 999.5_wp .and. y < 9999.5_wp) .or. abs(y - aint(y) - 0.5_wp) < tie_window) then
         write (s, '(es11.3)') x
         return
      end if
      n = nint(y)
      s = '  0.000E+00'
      if (x < 0.0_wp) s(2:2) = '-'
      s(3:3) = digit(n/1000)
      s(5:5) = digit(mod(n/100, 10))
      s(6:6) = digit(mod(n/10, 10))
      s(7:7) = digit(mod(n, 10))
      if (e < 0) s(9:9) = '-'
      s(10:10) = digit(abs(e)/10)
      s(11:11) = digit(mod(abs(e), 10))
   end function es11_3

   !> write (s, '(f10.5)') t for 0 <= t < 1000 as the fast form (the
   !! listing's times), the library's conversion otherwise.
   pure function f10_5(t) result(s)
      real(wp), intent(in) :: t
      character(len=10) :: s
      real(wp) :: y
      integer :: n, whole, frac, p, k
      y = 0.5_wp                 ! (NaN, -0, the negative, the large: the library)
      if (.not. ieee_is_nan(t)) then
         if (t >= 0.0_wp .and. t < 1000.0_wp .and. .not. ieee_is_negative(t)) y = t*pow10(5)
      end if
      if (abs(y - aint(y) - 0.5_wp) < tie_window) then
         write (s, '(f10.5)') t
         return
      end if
      n = nint(y)
      whole = n/100000
      frac = mod(n, 100000)
      s = ' '
      s(5:5) = '.'
      do k = 10, 6, -1
         s(k:k) = digit(mod(frac, 10))
         frac = frac/10
      end do
      p = 4
      do
         s(p:p) = digit(mod(whole, 10))
         whole = whole/10
         p = p - 1
         if (whole == 0) exit
      end do
   end function f10_5

   !> a 10**k by one correctly rounded operation with an exact power (|k| <= 22).
   pure real(wp) function scaled(a, k)
      real(wp), intent(in) :: a
      integer, intent(in) :: k
      if (k >= 0) then
         scaled = a*pow10(k)
      else
         scaled = a/pow10(-k)
      end if
   end function scaled

   pure character function digit(d)
      integer, intent(in) :: d
      digit = digit_char(d + 1:d + 1)
   end function digit
end module number_format
