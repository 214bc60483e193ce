!> The interval of an ascending table that holds a value, by bisection:
!! shared by the vehicle's tables (C.1), the loading curves (C.4.e, f) and
!! the joints' tabulated stops (C.4.c).
module table_search
   use kinds, only: wp
   implicit none
   private

   public :: bracket_index

contains

   !> k in 1 .. n-1 with x(k) <= v < x(k+1) for x(1) <= v < x(n); n-1 for
   !! v >= x(n) and 1 for v < x(1), the end intervals that extrapolate.
   pure integer function bracket_index(x, v) result(k)
      real(wp), intent(in) :: x(:), v
      integer :: lo, hi, mid
      lo = 1
      hi = size(x)
      if (v >= x(hi)) then
         k = hi - 1
         return
      end if
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (x(mid) <= v) then
            lo = mid
         else
            hi = mid
         end if
      end do
      k = lo
   end function bracket_index

end module table_search
