!> Report C.4.c, figure 10: the joint-injury criterion - dislocation by an
!! excessive relative angle. Evaluated on accepted steps only (it has
!! memory: a joint dislocates once).
module joint_injury
   use kinds, only: wp
   use model, only: model_t, n_joint, n_dof, joint_partner
   implicit none
   private

   public :: injury_event_t, dislocation_check
   public :: event_dislocation_low, event_dislocation_high, event_kind_name

   integer, parameter :: event_dislocation_low = 1, event_dislocation_high = 2
   character(len=28), parameter :: event_kind_name(2) = [character(len=28) :: &
      'dislocation (below limit)', 'dislocation (above limit)']

   !> An injury found during the run.
   type :: injury_event_t
      real(wp) :: t = 0.0_wp
      integer :: kind = 0
      integer :: index = 0          !< the joint (Table 5)
      real(wp) :: value = 0.0_wp    !< the relative angle found (rad)
      real(wp) :: limit = 0.0_wp    !< the limit it passed (rad)
   end type injury_event_t

contains

   !> Mark the joints whose relative angle alpha_i - alpha_m has passed a
   !! dislocation limit for the first time; return them as events.
   pure subroutine dislocation_check(m, t, z, dislocated, events, n_new)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: t, z(n_dof)
      logical, intent(inout) :: dislocated(n_joint)
      type(injury_event_t), intent(out) :: events(n_joint)
      integer, intent(out) :: n_new
      integer :: i
      real(wp) :: delta
      n_new = 0
      do i = 1, n_joint
         if (dislocated(i)) cycle
         delta = z(i) - z(joint_partner(i))
         if (delta < m%restraint(i)%dislocation_lower) then
            n_new = n_new + 1
            events(n_new) = injury_event_t(t, event_dislocation_low, i, delta, &
                                           m%restraint(i)%dislocation_lower)
            dislocated(i) = .true.
         else if (delta > m%restraint(i)%dislocation_upper) then
            n_new = n_new + 1
            events(n_new) = injury_event_t(t, event_dislocation_high, i, delta, &
                                           m%restraint(i)%dislocation_upper)
            dislocated(i) = .true.
         end if
      end do
   end subroutine dislocation_check
end module joint_injury
