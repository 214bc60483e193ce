!> Report C.4.c, figure 10: the joint-injury criterion - dislocation by an
!! excessive relative angle. An effect without forces: its memory (which
!! joints have dislocated) changes only when a step is accepted, and each
!! first passage of a limit is an injury event.
!!
!! Switches (issue 15): its memory changes where a relative angle passes a
!! limit for the first time; g = delta - lower and upper - delta (rad) per
!! joint, so the event (and an end on injury, NEND = 3) falls on the time
!! the limit is reached, not at the end of the step. A dislocated joint's
!! two are +1: nothing more changes there.
module joint_dislocation
   use kinds, only: wp, deg
   use model, only: n_joint, n_dof, restraint_t, joint_name
   use number_format, only: fixed
   use effect_base, only: effect_t, body_state_t
   use effect_events, only: accept_result_t, event_t, event_kind_t, event_of, accept_add_event
   use joint_coupling, only: relative_angle
   implicit none
   private

   public :: joint_dislocation_t, joint_dislocation_effect, dislocation_event, dislocation_event_kinds
   public :: event_dislocation_low, event_dislocation_high

   !> Its events' codes (/events/kind, docs/usage.md) and kinds: joint `index` dislocated
   !! below its lower or above its upper limit (an injury).
   integer, parameter :: event_dislocation_low = 1, event_dislocation_high = 2
   type(event_kind_t), parameter :: dislocation_event_kinds(2) = [ &
      event_kind_t(event_dislocation_low, 'dislocation (below limit)'), &
      event_kind_t(event_dislocation_high, 'dislocation (above limit)')]

   type, extends(effect_t) :: joint_dislocation_t
      real(wp) :: lower(n_joint) = 0.0_wp, upper(n_joint) = 0.0_wp  !< limits (rad)
      logical :: dislocated(n_joint) = .false.                      !< memory
   contains
      procedure :: add_forces => dislocation_add_forces
      procedure :: accept => dislocation_accept
      procedure :: switches => dislocation_switches
   end type joint_dislocation_t

contains

   function joint_dislocation_effect(restraint) result(e)
      type(restraint_t), intent(in) :: restraint(n_joint)
      type(joint_dislocation_t) :: e
      e%name = 'joint_dislocation'
      e%title = 'joint dislocation (C.4.c, figure 10)'
      e%acts = .false.
      e%has_memory = .true.
      e%lower = restraint%dislocation_lower
      e%upper = restraint%dislocation_upper
      e%n_switch = 2*n_joint
   end function joint_dislocation_effect

   !> Issue 15: per joint, delta - lower and upper - delta (rad), negative
   !! past the limit (dislocation_accept's test); +1 once dislocated.
   pure subroutine dislocation_switches(this, st, extra, aux, g)
      class(joint_dislocation_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      integer :: i
      real(wp) :: delta
      associate (u1 => size(extra) + size(aux))
      end associate
      do i = 1, n_joint
         if (this%dislocated(i)) then
            g(2*i - 1:2*i) = 1.0_wp
         else
            delta = relative_angle(st%z, i)
            g(2*i - 1) = delta - this%lower(i)
            g(2*i) = this%upper(i) - delta
         end if
      end do
   end subroutine dislocation_switches

   !> No generalized force: the report's dislocation is an injury criterion.
   pure subroutine dislocation_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(joint_dislocation_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      associate (u1 => this%name, u2 => st%t, u3 => size(extra) + size(aux), u4 => size(b), &
                 u5 => size(extra_rate) + size(aux_rate))
      end associate
   end subroutine dislocation_add_forces

   !> A joint whose relative angle has passed a limit for the first time
   !! dislocates: an injury event.
   subroutine dislocation_accept(this, st, extra, aux, result)
      class(joint_dislocation_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      integer :: i, kind
      real(wp) :: delta, limit
      associate (u1 => size(extra) + size(aux))
      end associate
      do i = 1, n_joint
         if (this%dislocated(i)) cycle
         delta = relative_angle(st%z, i)
         if (delta < this%lower(i)) then
            kind = event_dislocation_low
            limit = this%lower(i)
         else if (delta > this%upper(i)) then
            kind = event_dislocation_high
            limit = this%upper(i)
         else
            cycle
         end if
         this%dislocated(i) = .true.
         call accept_add_event(result, dislocation_event(kind, st%t, i, delta, limit))
      end do
   end subroutine dislocation_accept

   !> The injury event of kind code (event_dislocation_low or _high) at time
   !! t: joint i's relative angle passed its limit (rad).
   function dislocation_event(code, t, i, angle, limit) result(e)
      integer, intent(in) :: code, i
      real(wp), intent(in) :: t, angle, limit
      type(event_t) :: e
      type(event_kind_t) :: k
      k = dislocation_event_kinds(code)
      e = event_of(k, t, i, angle, 'joint '//joint_name(i)//'  '//trim(k%name)//': angle'//fixed(angle/deg, 9, 3) &
                   //' deg, limit'//fixed(limit/deg, 9, 3)//' deg', limit=limit, injury=.true.)
   end function dislocation_event
end module joint_dislocation
