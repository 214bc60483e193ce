!> The friction velocity limit xi of C.4.c, C.4.d and C.4.f. For the
!! joints (D-4a) and the seat (A-S4): a dead band - Coulomb friction acts
!! once the sliding velocity reaches xi, and not below it (nor at zero
!! velocity whatever xi, D-16) - its direction decided on accepted steps,
!! as memory, with a restart when it changes. For the contacts (D-C18a): a
!! ramp - the whole Coulomb force from xi on, in proportion to the sliding
!! velocity below it - evaluated at every evaluation, continuous, with no
!! memory.
module dead_band
   use kinds, only: wp
   implicit none
   private

   public :: slip_of, ramp_of

contains

   !> The direction of sliding: sgn v once |v| reaches xi, else 0.
   pure integer function slip_of(xi, v)
      real(wp), intent(in) :: xi, v
      slip_of = 0
      if (abs(v) >= xi .and. abs(v) > 0.0_wp) slip_of = int(sign(1.0_wp, v))
   end function slip_of

   !> The fraction of the Coulomb force at sliding velocity v (D-C18a):
   !! v/xi clipped to [-1, 1]; with xi = 0 the bare sign (0 at v = 0).
   pure real(wp) function ramp_of(xi, v) result(f)
      real(wp), intent(in) :: xi, v
      if (xi > 0.0_wp) then
         f = max(-1.0_wp, min(1.0_wp, v/xi))
      else
         f = real(slip_of(0.0_wp, v), wp)
      end if
   end function ramp_of
end module dead_band
