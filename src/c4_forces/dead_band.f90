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

   public :: slip_of, ramp_of, edge_at, edge_range, slip_released

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

   !> The edge of the dead band the sliding velocity v sits on, to within a
   !! located switch's tolerance (issue 15, D-4b): +1 at +xi, -1 at -xi, 0 at
   !! neither (a located switch leaves v within about 1e-10 of its edge).
   pure integer function edge_at(xi, v) result(edge)
      real(wp), intent(in) :: xi, v
      real(wp) :: tol
      tol = 1.0e-6_wp*max(xi, 1.0_wp)
      edge = 0
      if (abs(v - xi) <= tol) then
         edge = 1
      else if (abs(v + xi) <= tol) then
         edge = -1
      end if
   end function edge_at

   !> The range of the friction force (on the body, along the sliding
   !! direction) that holds the motion on an edge of the dead band, the
   !! law's magnitude c beyond it (D-4b): [-c, 0] at +xi, [0, c] at -xi,
   !! [-c, c] with xi = 0 (Coulomb's sticking).
   pure subroutine edge_range(xi, edge, c, lo, hi)
      real(wp), intent(in) :: xi, c
      integer, intent(in) :: edge
      real(wp), intent(out) :: lo, hi
      lo = -c
      hi = c
      if (xi > 0.0_wp) then
         if (edge > 0) hi = 0.0_wp
         if (edge < 0) lo = 0.0_wp
      end if
   end subroutine edge_range

   !> The direction of sliding after the motion leaves its edge, its force
   !! at the upper end of edge_range (at_upper) or the lower (D-4b): at +xi,
   !! -c slides on (+1) and 0 returns to the dead band; at -xi, +c slides on
   !! (-1) and 0 returns; with xi = 0, -c slides forward and +c backward.
   pure integer function slip_released(xi, edge, at_upper) result(slip)
      real(wp), intent(in) :: xi
      integer, intent(in) :: edge
      logical, intent(in) :: at_upper
      if (xi > 0.0_wp) then
         slip = 0
         if (edge > 0) slip = merge(0, 1, at_upper)
         if (edge < 0) slip = merge(-1, 0, at_upper)
      else
         slip = merge(-1, 1, at_upper)
      end if
   end function slip_released
end module dead_band
