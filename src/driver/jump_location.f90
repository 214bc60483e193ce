!> D-C24b: a jump of the right-hand side that an effect can locate inside
!! a step (effect_t%locate: the windshield's break) is stepped to, so that
!! it falls on an accepted state instead of up to a step late. The locator
!! keeps the last accepted state before the step (the step is taken again
!! from it) and the bracket of the search; it changes no effect's memory
!! (nothing was accepted at the states it passes over).
module jump_location
   use kinds, only: wp
   use error_handling, only: error_t
   use equations_of_motion, only: crash_system_t, system_body_state
   use ode_system, only: stepper_t, step_stats_t
   use effect_base, only: body_state_t
   implicit none
   private

   public :: jump_locator_t

   !> The step taken again at most this many times per step.
   integer, parameter :: max_locate = 8

   type :: jump_locator_t
      !> some effect of the system can locate a jump and the stepper can
      !! take a step again (RK4, Dormand-Prince)
      logical :: on = .false.
      real(wp) :: t_prev = 0.0_wp          !< the last accepted state before the step
      real(wp), allocatable :: y_prev(:)
      type(step_stats_t) :: stats_prev     !< the stepper's statistics then
      real(wp) :: t_step_end = 0.0_wp      !< the end of the step as first taken
      real(wp), allocatable :: y_end(:)
      real(wp), allocatable :: y_hi(:)     !< the earliest state found past the jump
   contains
      procedure :: init => locator_init
      procedure :: mark => locator_mark
      procedure :: locate => locator_locate
   end type jump_locator_t

contains

   !> On when an effect of sys can locate a jump (effect_t%locates) and
   !! the stepper can take a step again; its room for n state entries.
   subroutine locator_init(this, sys, relocates, n)
      class(jump_locator_t), intent(out) :: this
      type(crash_system_t), intent(in) :: sys
      logical, intent(in) :: relocates
      integer, intent(in) :: n
      integer :: o, k
      this%on = .false.
      if (relocates) then
         do o = 1, size(sys%occupants)
            do k = 1, size(sys%occupants(o)%effects)
               this%on = this%on .or. sys%occupants(o)%effects(k)%e%locates
            end do
         end do
      end if
      if (this%on) allocate (this%y_prev(n), this%y_end(n), this%y_hi(n))
   end subroutine locator_init

   !> The accepted state (t, y) a step is about to start from.
   subroutine locator_mark(this, t, y, stats)
      class(jump_locator_t), intent(inout) :: this
      real(wp), intent(in) :: t, y(:)
      type(step_stats_t), intent(in) :: stats
      this%y_prev = y
      this%t_prev = t
      this%stats_prev = stats
   end subroutine locator_mark

   !> After a step from the marked state to (t, y), ask the effects that
   !! can (effect_t%locate) whether their right-hand side should have
   !! jumped inside it; while one says so, take the step again from t_prev
   !! to the fraction it asks (a secant from the accepted state), keeping
   !! the jump bracketed between the latest state found short of it (an
   !! answer of 1 or more; at first t_prev) and the earliest found past it
   !! (at first t). A fraction outside the bracket, or the try after a
   !! state found short, takes the bracket's middle instead, so the bracket
   !! at least halves every second try: a tiny FSW, whose secant lands
   !! before the head even touches, was stepped to 5e-14 s at a time, for
   !! ever (issue 14). It ends at a state where none asks (the jump there,
   !! within its tolerance) or, after max_locate tries, at the earliest
   !! state past the jump (the jump there, late by less than the bracket):
   !! at most max_locate steps taken again, whatever the threshold. done:
   !! (t, y) is now inside the step, t_step_end its end. A step taken again
   !! that fails gives the step as first taken back (the jump then at its
   !! end, as without location), and only if that fails too does the run
   !! fail (err: the stepper's why).
   subroutine locator_locate(this, sys, stepper, t, y, done, err)
      class(jump_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      logical, intent(out) :: done
      type(error_t), intent(inout) :: err
      type(error_t) :: retry
      real(wp) :: theta, t_to, t_lo, t_hi
      logical :: short
      integer :: k
      done = .false.
      this%t_step_end = t
      this%y_end = y
      call fraction_asked(sys, t, y, theta, short)
      if (.not. theta < 1.0_wp) return
      t_lo = this%t_prev
      t_hi = t
      this%y_hi = y
      do k = 1, max_locate
         ! the step again: to the secant's fraction inside the bracket, else its middle
         t_to = this%t_prev + theta*(t - this%t_prev)
         if (.not. (t_to > t_lo .and. t_to < t_hi)) t_to = 0.5_wp*(t_lo + t_hi)
         if (.not. (t_to > t_lo .and. t_to < t_hi)) exit     ! (the bracket below the time's resolution)
         y = this%y_prev
         t = this%t_prev
         ! the step taken is not kept: a rejected step in the statistics (its
         ! size not among the accepted ones, its start again no restart after
         ! a jump)
         stepper%stats%steps = stepper%stats%steps - 1
         stepper%stats%rejected = stepper%stats%rejected + 1
         stepper%stats%h_min = this%stats_prev%h_min
         stepper%stats%h_max = this%stats_prev%h_max
         call stepper%restart(sys, t, y, retry)
         stepper%stats%restarts = stepper%stats%restarts - 1
         if (.not. retry%failed()) call stepper%advance(sys, t, y, t_to, retry)
         if (retry%failed()) then
            ! back to the step as first taken (memory untouched since: the
            ! same derivative), kept with the jump at its end
            stepper%stats%steps = stepper%stats%steps + 1
            call keep_try(this, sys, stepper, this%t_step_end, this%y_end, t, y, err)
            done = .false.
            return
         end if
         done = .true.
         call fraction_asked(sys, t, y, theta, short)
         if (theta < 1.0_wp) then          ! past the jump again: the bracket's end
            t_hi = t
            this%y_hi = y
         else if (short) then              ! short of it: the bracket's start, then its middle
            t_lo = t
            theta = 1.0_wp
         else                              ! here, within the jump's tolerance
            return
         end if
      end do
      ! the tries spent: the earliest state past the jump, where it happens
      if (.not. t_hi < this%t_step_end) then
         call keep_try(this, sys, stepper, this%t_step_end, this%y_end, t, y, err)      ! (none before the step's end)
         done = .false.
      else if (t < t_hi) then
         call keep_try(this, sys, stepper, t_hi, this%y_hi, t, y, err)
      end if
   end subroutine locator_locate

   !> Keep the step from t_prev to t_keep taken earlier (y_keep) rather
   !! than the last one taken: (t, y) set to it, its size among the
   !! accepted ones, the stepper restarted there (not counted as a restart
   !! after a jump); err when that restart fails.
   subroutine keep_try(this, sys, stepper, t_keep, y_keep, t, y, err)
      type(jump_locator_t), intent(in) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t_keep, y_keep(:)
      real(wp), intent(out) :: t
      real(wp), intent(out), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      y = y_keep
      t = t_keep
      stepper%stats%h_min = min(this%stats_prev%h_min, t_keep - this%t_prev)
      stepper%stats%h_max = max(this%stats_prev%h_max, t_keep - this%t_prev)
      call stepper%restart(sys, t, y, err)
      stepper%stats%restarts = stepper%stats%restarts - 1
   end subroutine keep_try

   !> The smallest fraction of the last step at which an effect asks for
   !! its jump (effect_t%locate), 1 when none asks; short: an effect
   !! answered that the state falls short of its jump (1 or more). The
   !! body state is made only for an occupant with an effect that may ask.
   subroutine fraction_asked(sys, t, y, theta, short)
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: theta
      logical, intent(out) :: short
      real(wp) :: theta_k
      integer :: o, k, xo, ao
      type(body_state_t) :: st
      logical :: made
      theta = 1.0_wp
      short = .false.
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            made = .false.
            do k = 1, size(occ%effects)
               associate (e => occ%effects(k)%e)
                  if (.not. e%locates) cycle
                  if (.not. made) st = system_body_state(sys, o, t, y)
                  made = .true.
                  xo = occ%extra_offset(k)
                  ao = occ%aux_offset(k)
                  theta_k = e%locate(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux))
                  if (theta_k > 0.0_wp) theta = min(theta, theta_k)
                  short = short .or. .not. theta_k < 1.0_wp
               end associate
            end do
         end associate
      end do
   end subroutine fraction_asked
end module jump_location
