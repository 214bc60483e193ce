!> Proximity guards (D-C29): a region of a body point or segment in the
!! interior frame where an effect is inert for certain, which the occupant
!! tests from st's frame data before it dispatches add_forces. Where the
!! guard holds, the effect is inert at st: b unchanged, every rate
!! (extra_rate, aux_rate) zero, whatever its memory; the occupant writes
!! those zeros itself and counts the evaluation, without the call
!! (docs/architecture.md, the effect layer; the contact pairs far from
!! contact).
module proximity_guard
   use kinds, only: wp
   use body_state, only: body_state_t
   implicit none
   private

   public :: proximity_guard_t, guard_none, guard_ball, guard_half_plane, guard_slab, guard_capsule, guard_always
   public :: guard_rel_margin, guard_big, guard_holds

   !> Kinds of proximity guard: none (always dispatched); the body point
   !! q farther than the reach from the centre (ball); farther than the
   !! reach in front of the line through the centre, along the unit
   !! normal (half-plane); farther than the reach from that line on either
   !! side (slab); the segment from the joint to q (along e, the axis in
   !! the interior frame) farther than the reach from the centre
   !! (capsule); inert at every state (always).
   integer, parameter :: guard_none = 0, guard_ball = 1, guard_half_plane = 2, guard_capsule = 3, &
      guard_always = 4, guard_slab = 5
   !> The guard's margin, guard_rel_margin (1 + size + st%joint_size(seg)),
   !! added to its reach; a guard holds only where st%rate_size and
   !! size + st%joint_size(seg) are at most guard_big (not so NaN).
   real(wp), parameter :: guard_rel_margin = 2.0e-9_wp, guard_big = 1.0e100_wp

   !> A proximity guard (see the module's header). The body point is
   !! q = st%frame_joint(:, seg) + along st%frame_axis(:, seg) (ball,
   !! half-plane, slab), the capsule's axis st%frame_joint(:, seg) to that q; the
   !! reach is radius + m, m = guard_rel_margin (1 + size +
   !! st%joint_size(seg)). An effect declares one only where its holding
   !! implies, whatever the roundings of the two computations, the effect's
   !! own proof that it is inert (for a contact pair, far_check's bound,
   !! whose margin is half the guard's; radius >= 0). Declaring one makes
   !! the occupant fill st's interior frame data (as needs_joints); the
   !! occupant decides that when the effect is placed, so an effect whose
   !! guard may turn from none to another kind later must set needs_joints
   !! at construction (the contact pairs do).
   type :: proximity_guard_t
      integer :: kind = guard_none
      integer :: seg = 1
      real(wp) :: along = 0.0_wp
      real(wp) :: centre(2) = 0.0_wp, normal(2) = 0.0_wp
      real(wp) :: radius = 0.0_wp
      !> the effect's own sizes, in the margin (a pair's lengths and radii, its surface's)
      real(wp) :: size = 0.0_wp
   end type proximity_guard_t

contains

   !> Whether the proximity guard g holds at st (st's interior frame data
   !! filled: occupant_frame): the effect is then inert at st. A guard of
   !! kind none never holds, one of kind always at every state.
   pure logical function guard_holds(g, st) result(holds)
      type(proximity_guard_t), intent(in) :: g
      type(body_state_t), intent(in) :: st
      real(wp) :: scale, reach, q(2), v(2), u2, lam
      holds = g%kind == guard_always
      if (g%kind == guard_none .or. holds) return
      scale = g%size + st%joint_size(g%seg)
      if (.not. (st%rate_size <= guard_big .and. scale <= guard_big)) return
      reach = g%radius + guard_rel_margin*(1.0_wp + scale)
      select case (g%kind)
      case (guard_ball)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = q(1)*q(1) + q(2)*q(2) > reach*reach
      case (guard_half_plane)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = q(1)*g%normal(1) + q(2)*g%normal(2) > reach
      case (guard_slab)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = abs(q(1)*g%normal(1) + q(2)*g%normal(2)) > reach
      case (guard_capsule)
         ! the centre's distance to the segment from the joint to q
         v = g%along*st%frame_axis(:, g%seg)
         q = g%centre - st%frame_joint(:, g%seg)
         u2 = v(1)*v(1) + v(2)*v(2)
         lam = 0.0_wp
         if (u2 > 0.0_wp) lam = min(1.0_wp, max(0.0_wp, (q(1)*v(1) + q(2)*v(2))/u2))
         q = q - lam*v
         holds = q(1)*q(1) + q(2)*q(2) > reach*reach
      end select
   end function guard_holds
end module proximity_guard
