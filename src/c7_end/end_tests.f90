!> Report C.7, the end-of-program tests: time (always), time + injury,
!! time + undesired contact (Table 9, the contacts' events), and time +
!! cessation of body motion relative to the vehicle. A run also ends when it
!! fails numerically or when its energy balance fails (*NUMERICS EBFAIL).
module end_tests
   use kinds, only: wp
   use model, only: body_section_t, end_tests_section_t, n_dof, n_seg, n_joint, nend_injury, nend_rest, nend_contact
   use body_kinematics, only: point_state_t, joint_state, to_interior
   use vehicle_motion, only: vehicle_state_t
   implicit none
   private

   public :: end_state_t, end_none, end_time, end_injury, end_rest, end_failure, end_energy, end_contact
   public :: end_reason_text, end_test_update, body_at_rest

   integer, parameter :: end_none = 0, end_time = 1, end_injury = 2, end_rest = 3, end_failure = 4, &
      end_energy = 5, end_contact = 6

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
      case (end_injury);  text = 'injury (NEND = 3)'
      case (end_contact); text = 'undesired contact (NEND = 2, Table 9)'
      case (end_rest);    text = 'rest: body motion relative to the vehicle ceased (NEND = 4)'
      case (end_failure); text = 'numerical failure'
      case (end_energy);  text = 'numerical failure: the energy balance exceeded its tolerance (*NUMERICS EBTOL)'
      case default;       text = 'still running'
      end select
   end function end_reason_text

   !> Every joint's speed relative to the interior below rest_speed and
   !! every segment's angular rate relative to the interior below rest_rate.
   pure logical function body_at_rest(body, et, z, zdot, vs)
      type(body_section_t), intent(in) :: body
      type(end_tests_section_t), intent(in) :: et
      real(wp), intent(in) :: z(n_dof), zdot(n_dof)
      type(vehicle_state_t), intent(in) :: vs
      type(point_state_t) :: p
      real(wp) :: zero(n_dof)
      integer :: k
      body_at_rest = all(abs(zdot(1:n_seg) + vs%vel(3)) < et%rest_rate)
      if (.not. body_at_rest) return
      zero = 0.0_wp
      do k = 1, n_joint
         p = to_interior(joint_state(body, z, zdot, zero, k), vs%pos, vs%vel)
         if (hypot(p%vx, p%vy) >= et%rest_speed) then
            body_at_rest = .false.
            return
         end if
      end do
   end function body_at_rest

   !> After an accepted step: the end reason, or end_none to go on.
   !! t_max is checked by the driver (it knows the step count).
   pure subroutine end_test_update(nend, et, state, t, injured, at_rest, reason, undesired)
      integer, intent(in) :: nend
      type(end_tests_section_t), intent(in) :: et
      type(end_state_t), intent(inout) :: state
      real(wp), intent(in) :: t
      logical, intent(in) :: injured, at_rest
      integer, intent(out) :: reason
      logical, intent(in) :: undesired   !< a Table 9 contact began at this step
      reason = end_none
      select case (nend)
      case (nend_contact)
         if (undesired) reason = end_contact
      case (nend_injury)
         if (injured) reason = end_injury
      case (nend_rest)
         if (at_rest) then
            if (state%rest_since < 0.0_wp) state%rest_since = t
            if (t - state%rest_since >= et%rest_hold) reason = end_rest
         else
            state%rest_since = -1.0_wp
         end if
      end select
   end subroutine end_test_update
end module end_tests
