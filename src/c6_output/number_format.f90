!> Numbers in fixed-width listing fields that never print as asterisks: a
!! value that does not fit the F editing of its field switches to E
!! editing of the same width (as many digits as fit).
module number_format
   use kinds, only: wp
   implicit none
   private

   public :: fixed

contains

   !> x in w columns with d decimals (Fw.d), or in E notation when that
   !! would overflow the field; w >= 9.
   function fixed(x, w, d) result(s)
      real(wp), intent(in) :: x
      integer, intent(in) :: w, d
      character(len=w) :: s
      character(len=16) :: fmt
      integer :: digits
      write (fmt, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
      write (s, fmt) x
      if (index(s, '*') == 0) return
      ! a blank, the sign, a digit, the point, E, the exponent's sign and digits
      if (abs(x) >= 1.0e100_wp) then
         digits = max(1, w - 9)
         write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', digits, 'e3)'
      else
         digits = max(1, w - 8)
         write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', digits, ')'
      end if
      write (s, fmt) x
   end function fixed
end module number_format
