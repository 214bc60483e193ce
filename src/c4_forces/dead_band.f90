!> The friction dead band of C.4.c, C.4.d and C.4.f: Coulomb friction acts
!! once the sliding velocity reaches xi, and not below it (nor at zero
!! velocity whatever xi, D-16). The joints decide it at every evaluation;
!! the seat (A-S4) and the contacts (D-C18) decide it on accepted steps, as
!! memory, with a restart when it changes.
module dead_band
   use kinds, only: wp
   implicit none
   private

   public :: slip_of

contains

   !> The direction of sliding: sgn v once |v| reaches xi, else 0.
   pure integer function slip_of(xi, v)
      real(wp), intent(in) :: xi, v
      slip_of = 0
      if (abs(v) >= xi .and. abs(v) > 0.0_wp) slip_of = int(sign(1.0_wp, v))
   end function slip_of
end module dead_band
