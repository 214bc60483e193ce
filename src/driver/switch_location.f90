!> Issue 15: the switches of the model located and stepped onto. Every
!! effect whose force, or the force's slope, changes discontinuously at a
!! threshold of the state declares switching functions (effect_t%switches,
!! n_switch): continuous in the state, changing sign exactly there. A
!! step that crosses such a point has lost an order of accuracy on it (a
!! jump: one, a kink: two), and the whole run with it. So after every
!! step the locator compares the signs of all switching functions with
!! those at the last accepted state; when one changed, it takes the step
!! again from that state to the first change (Illinois' regula falsi on
!! the switching function that changes first, in the time of the step),
!! until the change is bracketed to tol_t, and gives the state just past
!! it: there the run accepts (memory changes there, on the switch's far
!! side, as the effect's own accept decides from the state) and the
!! stepper restarts. Switches within tol_t of each other are taken
!! together (they all lie behind the state given).
!!
!! Only the switching functions of the scene's effects are evaluated
!! (counted in the stepper's statistics, as evaluations of forces are).
!! The locator changes no effect's memory: nothing was accepted at the
!! states it passes over.
module switch_location
   use kinds, only: wp
   use error_handling, only: error_t
   use equations_of_motion, only: crash_system_t, system_body_state
   use ode_system, only: stepper_t, step_stats_t
   use effect_base, only: body_state_t
   implicit none
   private

   public :: switch_locator_t

   !> The step taken again at most this many times per located switch:
   !! the bracket at least halves every third try, so 100 tries reach
   !! below 1e-10 of any step.
   integer, parameter :: max_tries = 100
   !> The bracket's width, relative to the step, at which a switch is
   !! located: far below the step's own error in time.
   real(wp), parameter :: relative_tol = 1.0e-10_wp

   type :: switch_locator_t
      !> some effect of the scene has switching functions and the stepper
      !! can take a step again
      logical :: on = .false.
      integer :: n_g = 0                   !< switching functions of the scene
      real(wp), allocatable :: g_prev(:)   !< at the last accepted state, with its memory
      real(wp), allocatable :: g_lo(:), g_hi(:), g_try(:)
      real(wp) :: t_prev = 0.0_wp          !< the last accepted state before the step
      real(wp), allocatable :: y_prev(:)
      type(step_stats_t) :: stats_prev     !< the stepper's statistics then
      real(wp), allocatable :: y_hi(:)     !< the earliest state found past a switch
   contains
      procedure :: init => locator_init
      procedure :: accepted => locator_accepted
      procedure :: mark => locator_mark
      procedure :: locate => locator_locate
   end type switch_locator_t

contains

   !> On when an effect of sys has switching functions and the stepper can
   !! take a step again; room for n state entries; the signs at the
   !! accepted initial state (t, y).
   subroutine locator_init(this, sys, relocates, t, y, stats)
      class(switch_locator_t), intent(out) :: this
      type(crash_system_t), intent(in) :: sys
      logical, intent(in) :: relocates
      real(wp), intent(in) :: t, y(:)
      type(step_stats_t), intent(inout) :: stats
      integer :: o, k, n
      n = 0
      do o = 1, size(sys%occupants)
         do k = 1, size(sys%occupants(o)%effects)
            n = n + sys%occupants(o)%effects(k)%e%n_switch
         end do
      end do
      this%n_g = n
      this%on = relocates .and. n > 0
      if (.not. this%on) return
      allocate (this%g_prev(n), this%g_lo(n), this%g_hi(n), this%g_try(n))
      allocate (this%y_prev(size(y)), this%y_hi(size(y)))
      call this%accepted(sys, t, y, stats)
   end subroutine locator_init

   !> (t, y) was accepted and every effect's memory updated there: the
   !! switching functions' signs that the next step is compared with.
   subroutine locator_accepted(this, sys, t, y, stats)
      class(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t, y(:)
      type(step_stats_t), intent(inout) :: stats
      if (.not. this%on) return
      call switch_values(sys, t, y, this%g_prev, stats)
   end subroutine locator_accepted

   !> The accepted state (t, y) a step is about to start from.
   subroutine locator_mark(this, t, y, stats)
      class(switch_locator_t), intent(inout) :: this
      real(wp), intent(in) :: t, y(:)
      type(step_stats_t), intent(in) :: stats
      this%y_prev = y
      this%t_prev = t
      this%stats_prev = stats
   end subroutine locator_mark

   !> After a step from the marked state to (t, y): when a switching
   !! function changed sign in it, (t, y) becomes the state just past the
   !! first change (located: true), within tol_t of it; otherwise nothing
   !! changes. A step taken again that fails gives the step as first taken
   !! back (the switch then at its end, as without location); only if that
   !! fails too does the run fail (err: the stepper's why).
   subroutine locator_locate(this, sys, stepper, t, y, located, err)
      class(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      logical, intent(out) :: located
      type(error_t), intent(inout) :: err
      type(error_t) :: retry
      real(wp) :: t_lo, t_hi, t_to, t_end, tol_t, w_lo, w_hi, width(2)
      integer :: k, side, last_side
      logical :: nudged, nudged_last
      located = .false.
      call switch_values(sys, t, y, this%g_hi, stepper%stats)
      if (.not. any(crossed(this%g_prev, this%g_hi))) return
      t_end = t
      t_lo = this%t_prev
      t_hi = t
      this%g_lo = this%g_prev
      this%y_hi = y
      tol_t = max(relative_tol*(t_end - t_lo), 8.0_wp*spacing(t_end))
      w_lo = 1.0_wp        ! Illinois' weights of the bracket's ends
      w_hi = 1.0_wp
      last_side = 0
      width = huge(1.0_wp)       ! the bracket's width two tries ago and one
      nudged_last = .false.
      do k = 1, max_tries
         if (t_hi - t_lo <= tol_t) exit
         t_to = first_crossing(this%g_lo, this%g_hi, w_lo, w_hi, t_lo, t_hi)
         ! (the bracket's start on a root of a function that changed sign over
         ! the step: the root is there)
         if (any(crossed(this%g_prev, this%g_hi) .and. .not. abs(this%g_lo) > 0.0_wp)) t_to = t_lo
         ! a try within tol_t/2 of an end (or on it: the end on a root, g
         ! exactly 0) goes tol_t/2 inside it, as in Brent's method: the regula
         ! falsi closes in on the root from one side, and the bracket then
         ! closes at the next try instead of halving from the far end some
         ! thirty times; not twice running, so that the middle below still
         ! comes every few tries
         nudged = .false.
         if (.not. nudged_last) then
            if (t_to >= t_hi - 0.5_wp*tol_t) then
               t_to = t_hi - 0.5_wp*tol_t
               nudged = .true.
            else if (t_to <= t_lo + 0.5_wp*tol_t) then
               t_to = t_lo + 0.5_wp*tol_t
               nudged = .true.
            end if
         end if
         nudged_last = nudged
         ! the middle when two tries did not halve the bracket: it at least
         ! halves every third try, whatever the switching functions' shape
         if (.not. nudged .and. t_hi - t_lo > 0.5_wp*width(1)) t_to = 0.5_wp*(t_lo + t_hi)
         width = [width(2), t_hi - t_lo]
         if (.not. (t_to > t_lo .and. t_to < t_hi)) t_to = 0.5_wp*(t_lo + t_hi)
         if (.not. (t_to > t_lo .and. t_to < t_hi)) exit     ! (below the time's resolution)
         call step_again(this, sys, stepper, t_to, t, y, retry)
         if (retry%failed()) exit           ! (the earliest state found past the switch is kept)
         call switch_values(sys, t, y, this%g_try, stepper%stats)
         ! past a switch only where a function has the sign opposite to its
         ! sign at the accepted state: a try on a root (g exactly 0, which
         ! the regula falsi reaches often) is short of it, so the state
         ! accepted has |g| > 0 and the effect's accept decides there as on
         ! the far side (a dislocation landed on its limit was not taken)
         if (any(passed(this%g_prev, this%g_try))) then
            side = 1                       ! past a switch: the bracket's end
            t_hi = t
            this%g_hi = this%g_try
            this%y_hi = y
            if (last_side == 1) w_lo = 0.5_wp*w_lo
            w_hi = 1.0_wp
         else
            side = -1                      ! short of every switch: the bracket's start
            t_lo = t
            this%g_lo = this%g_try
            if (last_side == -1) w_hi = 0.5_wp*w_hi
            w_lo = 1.0_wp
         end if
         last_side = side
      end do
      ! the earliest state past the switch: accepted there, the stepper
      ! restarted (no back value, no controller memory from across it)
      call keep(this, sys, stepper, t_hi, this%y_hi, t, y, err)
      located = t_hi < t_end
      if (located) stepper%stats%switches_located = stepper%stats%switches_located + 1
   end subroutine locator_locate

   !> The step taken again from the marked state to t_to, into (t, y); the
   !! step taken before is not kept (a rejected step in the statistics).
   subroutine step_again(this, sys, stepper, t_to, t, y, err)
      type(switch_locator_t), intent(in) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t_to
      real(wp), intent(out) :: t
      real(wp), intent(out), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      y = this%y_prev
      t = this%t_prev
      stepper%stats%steps = stepper%stats%steps - 1
      stepper%stats%rejected = stepper%stats%rejected + 1
      stepper%stats%h_min = this%stats_prev%h_min
      stepper%stats%h_max = this%stats_prev%h_max
      call stepper%restart(sys, t, y, err)
      stepper%stats%restarts = stepper%stats%restarts - 1
      if (.not. err%failed()) call stepper%advance(sys, t, y, t_to, err)
      if (err%failed()) stepper%stats%steps = stepper%stats%steps + 1
   end subroutine step_again

   !> Keep the step from the marked state to t_keep (state y_keep) as the
   !! accepted one: (t, y) set to it, its size among the accepted ones,
   !! the stepper restarted there (not counted as a restart after a jump).
   subroutine keep(this, sys, stepper, t_keep, y_keep, t, y, err)
      type(switch_locator_t), intent(in) :: this
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
   end subroutine keep

   !> Which switching functions changed sign from a to b: a strict change,
   !! or a value that reached zero from either side (a function that starts
   !! at zero has not crossed: the effect's memory there decided its side).
   pure elemental logical function crossed(a, b)
      real(wp), intent(in) :: a, b
      crossed = (a > 0.0_wp .and. .not. b > 0.0_wp) .or. (a < 0.0_wp .and. .not. b < 0.0_wp)
   end function crossed

   !> Which switching functions have the sign opposite to a's in b (a
   !! strict change: a zero is on neither side).
   pure elemental logical function passed(a, b)
      real(wp), intent(in) :: a, b
      passed = (a > 0.0_wp .and. b < 0.0_wp) .or. (a < 0.0_wp .and. b > 0.0_wp)
   end function passed

   !> The earliest time in (t_lo, t_hi) at which a switching function that
   !! changed sign over the bracket reaches zero, by the regula falsi of
   !! each (its ends weighted by Illinois' factors w_lo, w_hi).
   pure real(wp) function first_crossing(g_lo, g_hi, w_lo, w_hi, t_lo, t_hi) result(t_first)
      real(wp), intent(in) :: g_lo(:), g_hi(:), w_lo, w_hi, t_lo, t_hi
      real(wp) :: a, b, frac
      integer :: i
      t_first = t_hi
      do i = 1, size(g_lo)
         if (.not. crossed(g_lo(i), g_hi(i))) cycle
         a = w_lo*g_lo(i)
         b = w_hi*g_hi(i)
         frac = 0.5_wp
         if (abs(a - b) > 0.0_wp) frac = a/(a - b)
         t_first = min(t_first, t_lo + max(0.0_wp, min(1.0_wp, frac))*(t_hi - t_lo))
      end do
   end function first_crossing

   !> Every switching function of the scene at (t, y), in the order of the
   !! occupants and their effects (counted in stats). The body state is
   !! made only for an occupant with an effect that has one.
   subroutine switch_values(sys, t, y, g, stats)
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: g(:)
      type(step_stats_t), intent(inout) :: stats
      integer :: o, k, xo, ao, i
      type(body_state_t) :: st
      logical :: made
      i = 0
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            made = .false.
            do k = 1, size(occ%effects)
               associate (e => occ%effects(k)%e)
                  if (e%n_switch == 0) cycle
                  if (.not. made) st = system_body_state(sys, o, t, y)
                  made = .true.
                  xo = occ%extra_offset(k)
                  ao = occ%aux_offset(k)
                  call e%switches(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), g(i + 1:i + e%n_switch))
                  i = i + e%n_switch
               end associate
            end do
         end associate
      end do
      stats%switch_evaluations = stats%switch_evaluations + 1
   end subroutine switch_values
end module switch_location
