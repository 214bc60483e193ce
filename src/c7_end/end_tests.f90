!> Report C.7, the end-of-program tests: time (always), time + injury,
!! and time + cessation of body motion relative to the vehicle. (Time +
!! undesired contact needs the contacts of C.4.f.)
module end_tests
   use kinds, only: wp
   use model, only: model_t, n_dof, n_seg, n_joint, nend_injury, nend_rest
   use body_kinematics, only: point_state_t, joint_state, to_interior
   use vehicle_motion, only: vehicle_state_t
   implicit none
   private

   public :: end_state_t, end_none, end_time, end_injury, end_rest, end_failure
   public :: end_reason_text, end_test_update, body_at_rest

   integer, parameter :: end_none = 0, end_time = 1, end_injury = 2, end_rest = 3, end_failure = 4

   !> Memory of the rest test: when the body came to rest (negative: moving).
   type :: end_state_t
      real(wp) :: rest_since = -1.0_wp
   end type end_state_t

contains

   pure function end_reason_text(reason) result(text)
      integer, intent(in) :: reason
      character(len=:), allocatable :: text
      select case (reason)
      case (end_time);    text = 'time: TMAX reached'
      case (end_injury);  text = 'injury: a joint dislocated (NEND = 3)'
      case (end_rest);    text = 'rest: body motion relative to the vehicle ceased (NEND = 4)'
      case (end_failure); text = 'numerical failure'
      case default;       text = 'still running'
      end select
   end function end_reason_text

   !> Every joint's speed relative to the interior below rest_speed and
   !! every segment's angular rate relative to the interior below rest_rate.
   pure logical function body_at_rest(m, z, zdot, vs)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: z(n_dof), zdot(n_dof)
      type(vehicle_state_t), intent(in) :: vs
      type(point_state_t) :: p
      real(wp) :: zero(n_dof)
      integer :: k
      body_at_rest = all(abs(zdot(1:n_seg) + vs%vel(3)) < m%rest_rate)
      if (.not. body_at_rest) return
      zero = 0.0_wp
      do k = 1, n_joint
         p = to_interior(joint_state(m, z, zdot, zero, k), vs%pos, vs%vel)
         if (hypot(p%vx, p%vy) >= m%rest_speed) then
            body_at_rest = .false.
            return
         end if
      end do
   end function body_at_rest

   !> After an accepted step: the end reason, or end_none to go on.
   !! t_max is checked by the driver (it knows the step count).
   pure subroutine end_test_update(m, state, t, injured, at_rest, reason)
      type(model_t), intent(in) :: m
      type(end_state_t), intent(inout) :: state
      real(wp), intent(in) :: t
      logical, intent(in) :: injured, at_rest
      integer, intent(out) :: reason
      reason = end_none
      select case (m%nend)
      case (nend_injury)
         if (injured) reason = end_injury
      case (nend_rest)
         if (at_rest) then
            if (state%rest_since < 0.0_wp) state%rest_since = t
            if (t - state%rest_since >= m%rest_hold) reason = end_rest
         else
            state%rest_since = -1.0_wp
         end if
      end select
   end subroutine end_test_update
end module end_tests
