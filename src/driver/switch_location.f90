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
!! (counted in the stepper's statistics, as evaluations of forces are);
!! while a switch is searched for, only those of the effects with a
!! function that crossed over the step, or moved by more than its distance
!! from zero (issue 16 section 4: the far contact pairs cost nothing there).
!! The locator changes no effect's memory: nothing was accepted at the
!! states it passes over.
module switch_location
   use kinds, only: wp, i8
   use error_handling, only: error_t
   use equations_of_motion, only: crash_system_t, system_body_state
   use ode_system, only: stepper_t, step_stats_t
   use effect_base, only: body_state_t
   use occupant, only: occupant_slide_switches
   implicit none
   private

   public :: switch_locator_t

   !> The step taken again at most this many times per located switch:
   !! the bracket at least halves every third try, so 100 tries reach
   !! below 1e-10 of any step.
   integer, parameter :: max_tries = 100
   !> The bracket's width, relative to the step, at which a switch is
   !! located: far below the step's own error in time.
   real(wp), parameter :: relative_tol = 1.0e-8_wp
   !> A switching function within this fraction of its value at the step's
   !! end sat on its root at the step's start: a switch located there leaves
   !! it within about relative_tol of the step's change, and a sliding
   !! constraint released there leaves its rate on the edge it was held on
   !! (seat_drop's neck: 2.7e-12 rad/s against 4.9e-5 over the step). A
   !! crossing within `immediate` of the step's start is taken at its end
   !! anyway; so is this one, by the effect's accept, without being counted
   !! as chatter.
   real(wp), parameter :: at_root = 1.0e-6_wp
   !> A switch located within this fraction of the step from its start is
   !! taken at the step's end instead (chatter, issue 15): a law that
   !! reverses at once would otherwise be located ever closer.
   real(wp), parameter :: immediate = 1.0e-6_wp
   !> At most this many steps running each end on a located switch: past
   !! it, a switch is taken at the end of its step (counted as not located)
   !! until a step crosses none. A law that reverses at once but not within
   !! `immediate` (a stiff contact's friction ramp crossed in microseconds
   !! under a far too large force) would otherwise cost some 80 evaluations
   !! a switch for ever; no shipped deck comes near it (docs/accuracy.md).
   integer, parameter :: max_run = 64
   !> Dormand-Prince: switches less than this far apart (s), or from the
   !! step's start, or from the next print time, are taken together at
   !! one accepted state past all of them (locator_locate): no accepted
   !! step is shorter (issue 15, section 2). The error this costs is this
   !! time times the jump of y' at most (1e-9 s: 5 orders below the
   !! stiffest contact's period), far below any tolerance's.
   real(wp), parameter, public :: merge_window = 1.0e-9_wp
   !> Steps taken again to a root of the continuous extension (shifted to
   !! the last one's switching functions) before the regula falsi takes over
   integer, parameter :: max_dense_tries = 3
   !> A gap crossed on a step's extension (locate_on_dense): the bound of
   !! its departure from the tangent, times this, within the tolerance ...
   real(wp), parameter :: gap_safety = 1.0_wp
   !> ... and the gap at most this fraction of the step taken again
   real(wp), parameter :: gap_fraction = 0.1_wp
   !> A step is cut this fraction short of the switch predicted inside it
   !! (locator_predict), so that it ends short of it unless the prediction
   !! erred by more (then the step crosses and is searched as any other)
   real(wp), parameter :: predict_margin = 0.01_wp
   !> ... and only where that switch lies at least this fraction of the step ahead
   real(wp), parameter :: predict_least = 0.01_wp

   type :: switch_locator_t
      !> some effect of the scene has switching functions and the stepper
      !! can take a step again
      logical :: on = .false.
      integer :: n_g = 0                   !< switching functions of the scene
      integer :: n_run = 0                 !< steps running that ended on a located switch
      !> the last trial offered crossed a switch that could not be located
      !! (locator_locate): the stepper shortens its next step itself
      logical :: trial_given_up = .false.
      real(wp), allocatable :: g_prev(:)   !< at the last accepted state, with its memory
      real(wp), allocatable :: g_lo(:), g_hi(:), g_try(:)
      !> on the continuous extension: its bracket's ends and trial, and its
      !! shift to the step's own switching functions (locate_on_dense)
      real(wp), allocatable :: g_da(:), g_db(:), g_dt(:), g_shift(:)
      real(wp), allocatable :: g_end(:)     !< at the step's end (locate_on_dense)
      logical, allocatable :: live(:)       !< the functions that may cross in this step
      !> the group of each switching function (an effect's, or an occupant's
      !! sliding constraints'), and the groups searched in this step: those
      !! with a function that crossed over it (issue 16 section 4)
      integer, allocatable :: group_of(:)
      logical, allocatable :: searched(:)
      !> each group's occupant and effect (0: the occupant's sliding constraints)
      integer, allocatable :: group_occ(:), group_eff(:)
      !> g_hi holds every switching function at (t_full, y_full), the state
      !! a step ended on without crossing, with the memory before its accept
      logical :: full_at_end = .false.
      real(wp) :: t_full = 0.0_wp
      real(wp), allocatable :: y_full(:)
      !> at the last accept some effect with memory and switching functions
      !! said it changed none: the next step's end is kept for its accept
      logical :: keeps_end = .true.
      !> some effect with switching functions may say so (reports_unchanged:
      !! a scene without one, the body alone, pays nothing for it)
      logical :: may_keep = .false.
      !> the functions of the searched groups, idx(1:n_searched): the search
      !! reads and writes only these (the others keep their values at the
      !! step's end, in g_hi, on the side they started on)
      integer, allocatable :: idx(:)
      integer :: n_searched = 0
      real(wp) :: t_prev = 0.0_wp          !< the last accepted state before the step
      !> locator_predict's history: the switching functions at the two
      !! accepted states before the last (g_h1 at t_h1, g_h2 at t_h2), and
      !! the last one's time t_acc (its functions are g_prev); n_hist of
      !! them known since predicting began (predicts)
      logical :: predicts = .false.
      integer :: n_hist = 0
      real(wp), allocatable :: g_h1(:), g_h2(:)
      real(wp) :: t_h1 = 0.0_wp, t_h2 = 0.0_wp, t_acc = 0.0_wp
      !> the step was cut at t_aim, short of a predicted switch
      logical :: aimed = .false.
      real(wp) :: t_aim = 0.0_wp
      !> a step taken again with the stepper's continuous extension stops
      !! this much short of its end and crosses the rest on the slope there
      !! (locator_locate; 0: not)
      real(wp) :: hop = 0.0_wp
      real(wp), allocatable :: y_prev(:)
      type(step_stats_t) :: stats_prev     !< the stepper's statistics then
      real(wp), allocatable :: y_hi(:)     !< the earliest state found past a switch
      !> the latest state found short of every switch, and y' there (on the
      !! stepper's slope: locator_locate crosses from it when a step taken
      !! again past the switch was rejected)
      real(wp), allocatable :: y_lo(:), f_lo(:)
      real(wp), allocatable :: y_end(:)    !< the step as first taken
      real(wp), allocatable :: f_prev(:), f_end(:)   !< y' at the step's ends (Hermite's interpolant)
      real(wp), allocatable :: y_work(:)   !< a state of the interpolant
      !> the extension's departure from its tangent over a gap (locate_on_dense)
      real(wp), allocatable :: dy_gap(:)
      real(wp), allocatable :: rates(:)    !< workspace of the sliding switches (occupant_slide_switches)
      integer(i8), allocatable :: counts(:)
   contains
      procedure :: init => locator_init
      procedure :: accepted => locator_accepted
      procedure :: mark => locator_mark
      procedure :: locate => locator_locate
      procedure :: predict => locator_predict
   end type switch_locator_t

contains

   !> On when an effect of sys has switching functions and the stepper can
   !! take a step again; room for n state entries; the signs at the
   !! accepted initial state (t, y).
   subroutine locator_init(this, sys, relocates, t, y, stats)
      class(switch_locator_t), intent(out) :: this
      type(crash_system_t), intent(in) :: sys
      logical, intent(in) :: relocates
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(step_stats_t), intent(inout) :: stats
      integer :: n, k
      call switch_groups(sys, this%group_of, this%searched, this%group_occ, this%group_eff)
      this%may_keep = .false.
      do k = 1, size(this%group_eff)
         if (this%group_eff(k) == 0) cycle
         this%may_keep = this%may_keep .or. sys%occupants(this%group_occ(k))%effects(this%group_eff(k))%e%reports_unchanged
      end do
      this%keeps_end = this%may_keep
      n = size(this%group_of)
      this%n_g = n
      this%on = relocates .and. n > 0
      if (.not. this%on) return
      allocate (this%g_prev(n), this%g_lo(n), this%g_hi(n), this%g_try(n), this%live(n), this%idx(n))
      allocate (this%g_da(n), this%g_db(n), this%g_dt(n), this%g_shift(n), this%g_end(n))
      allocate (this%g_h1(n), this%g_h2(n))
      allocate (this%y_prev(size(y)), this%y_hi(size(y)), this%y_end(size(y)), this%y_lo(size(y)), this%f_lo(size(y)))
      allocate (this%f_prev(size(y)), this%f_end(size(y)), this%y_work(size(y)), this%rates(size(y)), &
                this%dy_gap(size(y)))
      allocate (this%counts(size(sys%counts, 1)), this%y_full(size(y)))
      call this%accepted(sys, t, y, stats)
   end subroutine locator_init

   !> (t, y) was accepted and every effect's memory updated there: the
   !! switching functions' signs that the next step is compared with.
   !! unchanged(k, o): effect k of occupant o changed no memory at this
   !! accept (step_bookkeeping): where the step ended on (t, y) without a
   !! switch, its functions are those the step's end gave, kept, not
   !! evaluated again (a sliding constraint's, only where no effect of its
   !! occupant changed).
   subroutine locator_accepted(this, sys, t, y, stats, unchanged)
      class(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(step_stats_t), intent(inout) :: stats
      logical, intent(in), optional :: unchanged(:, :)
      integer :: grp, o, n_eff, i
      logical :: reuse
      if (.not. this%on) return
      ! (predict's history: g_prev is about to become this state's)
      if (this%predicts) then
         this%g_h2 = this%g_h1
         this%t_h2 = this%t_h1
         this%g_h1 = this%g_prev
         this%t_h1 = this%t_acc
         this%n_hist = min(this%n_hist + 1, 3)
      end if
      this%t_acc = t
      reuse = .false.
      if (present(unchanged) .and. this%may_keep) then
         this%keeps_end = .false.
         do grp = 1, size(this%searched)
            if (this%group_eff(grp) == 0) cycle
            associate (e => sys%occupants(this%group_occ(grp))%effects(this%group_eff(grp))%e)
               if (e%reports_unchanged .and. unchanged(this%group_eff(grp), this%group_occ(grp))) this%keeps_end = .true.
            end associate
         end do
         if (this%full_at_end .and. this%keeps_end) then
            ! (the same state, bit for bit)
            reuse = same_bits(t, this%t_full)
            do i = 1, size(y)
               if (.not. reuse) exit
               reuse = same_bits(y(i), this%y_full(i))
            end do
         end if
      end if
      this%full_at_end = .false.
      if (.not. reuse) then
         call switch_values(sys, t, y, this%g_prev, stats, this%rates, this%counts)
         return
      end if
      do grp = 1, size(this%searched)
         o = this%group_occ(grp)
         if (this%group_eff(grp) > 0) then
            this%searched(grp) = .not. unchanged(this%group_eff(grp), o)
         else
            n_eff = size(sys%occupants(o)%effects)
            this%searched(grp) = .not. all(unchanged(1:n_eff, o))
         end if
      end do
      this%g_prev = this%g_hi
      call switch_values(sys, t, y, this%g_prev, stats, this%rates, this%counts, this%searched)
      stats%switch_groups_kept = stats%switch_groups_kept + count(.not. this%searched)
   contains
      pure logical function same_bits(a, b)
         real(wp), intent(in) :: a, b
         same_bits = transfer(a, 0_i8) == transfer(b, 0_i8)
      end function same_bits
   end subroutine locator_accepted

   !> The accepted state (t, y) a step is about to start from, y' = f there.
   subroutine locator_mark(this, t, y, f, stats)
      class(switch_locator_t), intent(inout) :: this
      real(wp), intent(in) :: t, y(:), f(:)
      type(step_stats_t), intent(in) :: stats
      this%y_prev = y
      this%f_prev = f
      this%t_prev = t
      this%stats_prev = stats
   end subroutine locator_mark

   !> After a step from the marked state to (t, y): when a switching
   !! function changed sign in it, (t, y) becomes the state just past the
   !! first change (located: true), within tol_t of it; otherwise nothing
   !! changes. A step taken again that fails gives the step as first taken
   !! back (the switch then at its end, as without location); only if that
   !! fails too does the run fail (err: the stepper's why).
   !!
   !! trial: the stepper offered a trial step it rejected (trial_offered,
   !! ending at t_trial; (t, y) is still the marked state): when a switch
   !! lies in it, the trial is cut there as an accepted step would be (its
   !! error was the switch's; the step to the switch is smooth); when none
   !! does, or the switch cannot be located (the step to it is rejected
   !! too, or a switch at once), nothing changes (located false, the
   !! stepper back at the marked state) and the stepper goes on with its
   !! shorter step.
   subroutine locator_locate(this, sys, stepper, t, y, located, err, trial, t_limit)
      class(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      logical, intent(out) :: located
      type(error_t), intent(inout) :: err
      logical, intent(in), optional :: trial
      !> the next print time (or TMAX): a located state within merge_window
      !! of it is placed on it
      real(wp), intent(in), optional :: t_limit
      type(error_t) :: retry
      real(wp) :: t_lo, t_hi, t_to, t_end, tol_t, w_lo, w_hi, width(2), t_lo_start, t_seed
      integer :: k, side, last_side, i, j
      integer(i8) :: rejected_before
      logical :: on_root, on_dense, current_is_hi, dense_done, is_trial, short, current, hi_bound
      located = .false.
      is_trial = .false.
      if (present(trial)) is_trial = trial
      this%trial_given_up = .false.
      if (is_trial) then
         call stepper%dense(stepper%t_trial, this%y_work)
         call switch_values(sys, stepper%t_trial, this%y_work, this%g_hi, stepper%stats, this%rates, this%counts)
      else
         call switch_values(sys, t, y, this%g_hi, stepper%stats, this%rates, this%counts)
      end if
      ! a function that sat on its root at the accepted state (a switch
      ! just located there, or a constraint just left) has no side to
      ! cross from: its memory there decided its side
      this%live = abs(this%g_prev) > at_root*abs(this%g_hi)
      this%full_at_end = .false.
      if (.not. any(this%live .and. crossed(this%g_prev, this%g_hi))) then
         if (.not. is_trial) then
            ! a step cut short of a predicted switch: the rest on its extension
            if (this%aimed .and. t >= this%t_aim) then
               this%aimed = .false.
               call cross_predicted(this, sys, stepper, t, y, located, err, t_limit)
               if (located) return
            end if
            this%n_run = 0
            ! (every function at the state the run accepts next)
            if (this%keeps_end) then
               this%full_at_end = .true.
               this%t_full = t
               this%y_full = y
            end if
         end if
         return
      end if
      ! the search evaluates only the groups with a function that crossed
      ! over the step, or that changed by more than its distance from zero
      ! at either end (it may have crossed and crossed back inside the
      ! step, which a try of the search can find); the others keep their
      ! values at the step's end, on the same side as at its start
      this%searched = .false.
      do k = 1, this%n_g
         if (this%live(k) .and. (crossed(this%g_prev(k), this%g_hi(k)) .or. &
             abs(this%g_hi(k) - this%g_prev(k)) >= min(abs(this%g_prev(k)), abs(this%g_hi(k))))) &
            this%searched(this%group_of(k)) = .true.
      end do
      call index_searched(this)
      if (is_trial) then
         if (this%n_run >= max_run) return
         ! the trial, cut at the switch, counted as a step taken again
         ! (as an accepted step that crosses one), not as rejected
         t = stepper%t_trial
         y = this%y_work
         stepper%stats%rejected = stepper%stats%rejected - 1
         stepper%stats%steps = stepper%stats%steps + 1
      end if
      if (this%n_run >= max_run) then
         ! (chatter the law does not resolve: the switch at the step's end)
         stepper%stats%switches_unlocated = stepper%stats%switches_unlocated + 1
         return
      end if
      t_end = t
      this%y_end = y
      t_lo = this%t_prev
      t_lo_start = t_lo
      t_hi = t
      this%g_lo = this%g_prev
      this%y_hi = y
      tol_t = max(relative_tol*(t_end - t_lo), 8.0_wp*spacing(t_end))
      this%f_end = stepper%f
      current_is_hi = .true.
      on_dense = stepper%has_dense()
      ! a step taken again ends a little short of the time asked and crosses
      ! the rest on its slope: its stages then do not reach past a jump of
      ! the right-hand side (whose stage at the step's end would count it
      ! in the step's value as a first-order error, and in its estimate)
      this%hop = merge(tol_t, 0.0_wp, on_dense)
      short = .false.
      if (on_dense) then
         ! Dormand-Prince: the switch on the step's continuous extension,
         ! then ONE step from the marked state to just past it (an
         ! integrator's state, not an interpolated one)
         call locate_on_dense(this, sys, stepper, t_end, tol_t, t_lo, t_hi, current_is_hi, t, y, dense_done, short)
         if (is_trial .and. short) then
            call give_up_trial()
            return
         end if
      else
         ! the first try: the switch on Hermite's cubic through the step's
         ! ends (no evaluation of forces; its error is the step's own order)
         t_seed = hermite_crossing(this, sys, stepper, t_lo, t_end, tol_t, stepper%stats)
         dense_done = .false.
      end if
      w_lo = 1.0_wp        ! Illinois' weights of the bracket's ends
      w_hi = 1.0_wp
      last_side = 0
      ! t_hi a bound without a state past the switch (a step taken again to
      ! it was rejected): the bracket is halved, the state crossed to at last
      hi_bound = .false.
      this%y_lo = this%y_prev
      this%f_lo = this%f_prev
      width = huge(1.0_wp)       ! the bracket's width two tries ago and one
      do k = 1, max_tries
         if (dense_done) exit
         ! located: the bracket is that narrow, or the first root the
         ! secants of the functions that cross in it give lies that close
         ! to its end (a function past its root by a rounding)
         if (t_hi - t_lo <= tol_t) exit
         ! the bracket's start on a root of a function that changed sign
         ! over the step (a try that landed on it, g exactly 0): the root is
         ! there, and the next try goes just past it
         on_root = .false.
         do i = 1, this%n_searched
            j = this%idx(i)
            on_root = on_root .or. (this%live(j) .and. crossed(this%g_prev(j), this%g_hi(j)) &
                                    .and. .not. abs(this%g_lo(j)) > 0.0_wp)
         end do
         if (.not. on_root .and. .not. hi_bound) then
            if (t_hi - first_crossing(this%g_lo, this%g_hi, this%live, this%idx(:this%n_searched), &
                                      1.0_wp, 1.0_wp, t_lo, t_hi) <= tol_t) exit
         end if
         t_to = first_crossing(this%g_lo, this%g_hi, this%live, this%idx(:this%n_searched), w_lo, w_hi, t_lo, t_hi)
         if (k == 1 .and. .not. on_dense) t_to = t_seed
         if (on_root) t_to = min(t_lo + 0.5_wp*tol_t, 0.5_wp*(t_lo + t_hi))
         ! the middle when two tries did not halve the bracket: it at least
         ! halves every third try, whatever the switching functions' shape
         if (.not. on_root .and. t_hi - t_lo > 0.5_wp*width(1)) t_to = 0.5_wp*(t_lo + t_hi)
         width = [width(2), t_hi - t_lo]
         if (hi_bound) t_to = 0.5_wp*(t_lo + t_hi)
         if (.not. (t_to > t_lo .and. t_to < t_hi)) t_to = 0.5_wp*(t_lo + t_hi)
         if (.not. (t_to > t_lo .and. t_to < t_hi)) exit     ! (below the time's resolution)
         rejected_before = stepper%stats%rejected
         call step_again(this, sys, stepper, t_to, t, y, retry, short, current)
         current_is_hi = .false.
         if (retry%failed()) exit           ! (the earliest state found past the switch is kept)
         if (is_trial .and. short) exit
         if (short .and. on_dense) then
            ! rejected: a jump of the right-hand side before t_to, the
            ! switch's (the state the stepper shortened to is no bracket's
            ! end; its trials are counted as taken again, not rejected)
            t_hi = t_to
            hi_bound = .true.
            short = .false.
            stepper%stats%retaken = stepper%stats%retaken + (stepper%stats%rejected - rejected_before)
            stepper%stats%rejected = rejected_before
            cycle
         end if
         call search_values(this, sys, t, y, this%g_try, stepper%stats)
         ! past a switch only where a function has the sign opposite to its
         ! sign at the accepted state: a try on a root (g exactly 0, which
         ! the regula falsi reaches) is short of it, so that the state
         ! accepted has |g| > 0 and the effect's accept decides there as on
         ! the far side (a dislocation landed on its limit was not taken)
         if (any_change(this%g_prev, this%g_try, this%live, this%idx(:this%n_searched), .true.)) then
            side = 1                       ! past a switch: the bracket's end
            t_hi = t
            call copy_on(this%g_hi, this%g_try, this%idx(:this%n_searched))
            this%y_hi = y
            hi_bound = .false.
            if (last_side == 1) w_lo = 0.5_wp*w_lo
            w_hi = 1.0_wp
            current_is_hi = current
         else
            side = -1                      ! short of every switch: the bracket's start
            t_lo = t
            call copy_on(this%g_lo, this%g_try, this%idx(:this%n_searched))
            this%y_lo = y
            this%f_lo = stepper%f
            if (last_side == -1) w_hi = 0.5_wp*w_hi
            w_lo = 1.0_wp
         end if
         last_side = side
      end do
      if (hi_bound) then
         ! the switch within the bracket, no state past it taken: crossed
         ! to from the state short of it on its slope (an error of the
         ! bracket's width times the jump of y')
         this%y_hi = this%y_lo + (t_hi - t_lo)*this%f_lo
         current_is_hi = .false.
      end if
      if (is_trial .and. (retry%failed() .or. short .or. t_hi >= t_end &
                          .or. t_hi - t_lo_start < immediate*(t_end - t_lo_start))) then
         ! (the trial's end is no state to accept)
         call give_up_trial()
         return
      end if
      if (t_hi - t_lo_start < immediate*(t_end - t_lo_start)) then
         ! a switch at once after the last (chatter the law leaves, or
         ! rounding on a root): not located, the step kept as first taken,
         ! the memory decided at its end (counted: the listing says so)
         stepper%stats%switches_unlocated = stepper%stats%switches_unlocated + 1
         current_is_hi = t_hi >= t_end
         t_hi = t_end
         this%y_hi = this%y_end
      end if
      if (on_dense .and. t_hi < t_end) call merge_near(t_hi)
      ! the earliest state past the switch: accepted there, the stepper
      ! restarted (no back value, no controller memory from across it)
      call keep(this, sys, stepper, t_hi, this%y_hi, current_is_hi, t, y, err)
      located = t_hi < t_end .or. (on_dense .and. t_hi > t_end)
      this%n_run = merge(this%n_run + 1, 0, located)
      if (located) stepper%stats%switches_located = stepper%stats%switches_located + 1
   contains
      !> Switches within merge_window after the one located at t_hi (or of
      !! the step's start, or before the print time t_limit) taken with
      !! it: t_hi and y_hi moved past the last of them (on y's slope, no
      !! evaluation of forces), or onto the print time.
      subroutine merge_near(t_hi)
         real(wp), intent(inout) :: t_hi
         real(wp) :: t_w, t_m, frac
         integer :: i, m, n_on
         logical :: later, inside, ahead
         ! the state no earlier than merge_window after the step's start
         t_w = max(t_hi, this%t_prev) + merge_window + 8.0_wp*spacing(t_end)
         this%y_work = this%y_hi + (t_w - t_hi)*stepper%f
         ! within the step only the searched functions can cross (the others
         ! kept their side over all of it); past its end, any
         inside = t_w <= t_end
         call values_at(t_w, this%g_try, inside)
         n_on = merge(this%n_searched, this%n_g, inside)
         ! the switches still ahead at t_hi that lie before t_w: past the last
         t_m = max(t_hi, this%t_prev + merge_window + 8.0_wp*spacing(t_end))
         later = .false.
         do m = 1, n_on
            i = merge(this%idx(m), m, inside)
            if (.not. (this%live(i) .and. .not. passed(this%g_prev(i), this%g_hi(i)) &
                       .and. passed(this%g_prev(i), this%g_try(i)))) cycle
            later = .true.
            frac = 1.0_wp
            if (abs(this%g_hi(i) - this%g_try(i)) > 0.0_wp) frac = this%g_hi(i)/(this%g_hi(i) - this%g_try(i))
            t_m = max(t_m, t_hi + max(0.0_wp, min(1.0_wp, frac))*(t_w - t_hi) + 0.5_wp*tol_t)
         end do
         t_m = min(t_m, t_w)
         if (later) then
            ! past all of them at t_m, or else at t_w
            this%y_work = this%y_hi + (t_m - t_hi)*stepper%f
            call values_at(t_m, this%g_dt, inside)
            ahead = .false.
            do m = 1, n_on
               i = merge(this%idx(m), m, inside)
               ahead = ahead .or. (this%live(i) .and. .not. passed(this%g_prev(i), this%g_dt(i)) &
                                   .and. passed(this%g_prev(i), this%g_try(i)))
            end do
            if (ahead) t_m = t_w
         end if
         if (present(t_limit)) then
            t_m = min(t_m, t_limit)
            if (t_limit > t_m .and. t_limit - t_m < merge_window) t_m = t_limit
         end if
         if (t_m > t_hi) then
            this%y_hi = this%y_hi + (t_m - t_hi)*stepper%f
            t_hi = t_m
            current_is_hi = .false.
         end if
      end subroutine merge_near

      !> The switching functions at (t_at, y_work) that merge_near reads:
      !! the searched ones inside the step, else all.
      subroutine values_at(t_at, g, searched_only)
         real(wp), intent(in) :: t_at
         real(wp), intent(inout) :: g(:)
         logical, intent(in) :: searched_only
         if (searched_only) then
            call search_values(this, sys, t_at, this%y_work, g, stepper%stats)
         else
            call switch_values(sys, t_at, this%y_work, g, stepper%stats, this%rates, this%counts)
         end if
      end subroutine values_at

      !> The trial stays rejected: the stepper back at the marked state
      !! (with y' there), to go on with its shorter step.
      subroutine give_up_trial()
         this%trial_given_up = .true.
         stepper%stats%rejected = stepper%stats%rejected + 1
         stepper%stats%steps = stepper%stats%steps - 1
         stepper%stats%h_min = this%stats_prev%h_min
         stepper%stats%h_max = this%stats_prev%h_max
         t = this%t_prev
         y = this%y_prev
         this%y_work = this%f_prev
         call stepper%resume(sys, t, y, this%y_work, err)
      end subroutine give_up_trial
   end subroutine locator_locate

   !> Issue 16: the end of the next step (of size h from the accepted state
   !! at t), cut predict_margin short of the first switch the switching
   !! functions of the last three accepted states predict inside it; t_limit
   !! when none is (or no history is known yet). A function predicts a
   !! switch where it approaches zero monotonically over those states (one
   !! sign, |g| falling) and the quadratic through them reaches zero within
   !! the step. Such a step ends just short of the switch, and locate
   !! crosses the rest on its extension (cross_predicted): the step that
   !! would have crossed the switch is not taken only to be taken again to
   !! it (twelve evaluations then, six now). A wrong prediction costs a
   !! shorter step, never accuracy: a step that crosses anyway is searched
   !! as any other. Evaluates nothing.
   function locator_predict(this, t, h, t_limit) result(t_step)
      class(switch_locator_t), intent(inout) :: this
      real(wp), intent(in) :: t, h, t_limit
      real(wp) :: t_step
      real(wp) :: s1, s2, d1, d0, c2, r, r_min
      integer :: k
      logical :: found
      t_step = t_limit
      this%aimed = .false.
      if (.not. (this%on .and. h > 0.0_wp)) return
      if (.not. this%predicts) then
         ! (the history starts at the accepted state g_prev holds)
         this%predicts = .true.
         this%n_hist = 1
         return
      end if
      if (this%n_hist < 3) return
      ! the two states before, in the time from t (s2 < s1 < 0)
      s1 = this%t_h1 - t
      s2 = this%t_h2 - t
      if (.not. (s2 < s1 .and. s1 < 0.0_wp .and. this%t_acc >= t)) return
      r_min = min(h, t_limit - t)
      found = .false.
      do k = 1, this%n_g
         associate (g0 => this%g_prev(k), g1 => this%g_h1(k), g2 => this%g_h2(k))
            if (.not. (abs(g0) < abs(g1) .and. abs(g1) < abs(g2))) cycle
            if (.not. ((g0 > 0.0_wp .and. g1 > 0.0_wp .and. g2 > 0.0_wp) .or. &
                       (g0 < 0.0_wp .and. g1 < 0.0_wp .and. g2 < 0.0_wp))) cycle
            ! the quadratic through (s2, g2), (s1, g1), (0, g0) in Newton's
            ! form g0 + d1 s + c2 s (s - s1): c2 s^2 + (d1 - c2 s1) s + g0
            d1 = (g0 - g1)/(-s1)
            d0 = (g1 - g2)/(s1 - s2)
            c2 = (d1 - d0)/(-s2)
            r = least_positive_root(c2, d1 - c2*s1, g0)
         end associate
         if (r < r_min) then
            r_min = r
            found = .true.
         end if
      end do
      ! (a switch predicted within a hundredth of the step: the step that
      ! crosses it is searched as any other, no step that short is taken)
      if (.not. found .or. r_min < predict_least*h) return
      t_step = t + (1.0_wp - predict_margin)*r_min
      this%aimed = t_step > t
      this%t_aim = t_step
      if (.not. this%aimed) t_step = t_limit
   end function locator_predict

   !> The least positive root of a s^2 + b s + c (c /= 0), huge when none
   !! (the stable quadratic formula: no cancellation in either root).
   pure real(wp) function least_positive_root(a, b, c) result(r)
      real(wp), intent(in) :: a, b, c
      real(wp) :: disc, q, r1, r2
      r = huge(1.0_wp)
      if (.not. abs(a) > 0.0_wp) then
         if (abs(b) > 0.0_wp) then
            r1 = -c/b
            if (r1 > 0.0_wp) r = r1
         end if
         return
      end if
      disc = b*b - 4.0_wp*a*c
      if (.not. disc >= 0.0_wp) return
      q = -0.5_wp*(b + sign(sqrt(disc), b))
      if (.not. abs(q) > 0.0_wp) return
      r1 = q/a
      r2 = c/q
      if (r1 > 0.0_wp) r = r1
      if (r2 > 0.0_wp .and. r2 < r) r = r2
   end function least_positive_root

   !> The step from the marked state ended at t, where locator_predict cut
   !! it short of a switch: when the functions it neared reach zero within
   !! gap_fraction of the step past its end, on the step's own extension
   !! carried on, within the step's tolerance (estimated below),
   !! and no other function changes sign on the way, (t, y) becomes the
   !! state just past that switch (located) and the stepper restarts there;
   !! otherwise nothing changes (the next step crosses it and is searched).
   subroutine cross_predicted(this, sys, stepper, t, y, located, err, t_limit)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      logical, intent(out) :: located
      type(error_t), intent(inout) :: err
      real(wp), intent(in), optional :: t_limit
      real(wp) :: span, t_b, t_to, tol_t, sig
      integer :: k
      located = .false.
      span = t - this%t_prev
      if (.not. (stepper%has_dense() .and. span > 0.0_wp) .or. this%n_run >= max_run) return
      ! (not past the print time, kink or TMAX: merge_after places a switch
      ! found that close on it)
      t_b = t + gap_fraction*span
      if (present(t_limit)) t_b = min(t_b, t_limit)
      if (.not. t_b > t) return
      ! the groups with a function that, carried on along the step's
      ! secant, reaches zero within twice the gap
      this%searched = .false.
      do k = 1, this%n_g
         if (.not. (this%live(k) .and. abs(this%g_hi(k)) < abs(this%g_prev(k)))) cycle
         if (abs(this%g_hi(k)) <= 2.0_wp*gap_fraction*abs(this%g_prev(k) - this%g_hi(k))) &
            this%searched(this%group_of(k)) = .true.
      end do
      call index_searched(this)
      if (this%n_searched == 0) return
      associate (ix => this%idx(:this%n_searched))
         call stepper%dense(t_b, this%y_work)
         call search_values(this, sys, t_b, this%y_work, this%g_try, stepper%stats)
         if (.not. any_change(this%g_hi, this%g_try, this%live, ix, .false.)) return
         ! the root on the extension carried on (the step's end's values kept)
         tol_t = max(relative_tol*span, 8.0_wp*spacing(t))
         this%g_end = this%g_hi
         call copy_on(this%g_lo, this%g_hi, ix)
         call copy_on(this%g_hi, this%g_try, ix)
         this%g_shift = 0.0_wp
         t_to = interpolant_crossing(this, sys, stepper, t, t_b, tol_t, stepper%stats, .true.) + 0.5_wp*tol_t
         this%g_hi = this%g_end
         if (.not. (t_to > t .and. t_to < t_b)) return
         ! the extension's error over the gap, estimated by its difference
         ! from the cubic through the step's ends' values and slopes carried
         ! on with it: both leave the end on y and y'; where the step is in
         ! its asymptotic range the cubic's error, about y''''(h gap)**2/24,
         ! is the larger, but where stability bounds the step (near a stiff
         ! contact) the two err alike and the difference can fall below the
         ! error. An estimate, not a bound: measured against a reference
         ! started at the step's end over 481 crossings of the interior decks
         ! it fell below the error 196 times, yet no crossing it let through
         ! erred by more than 0.62 of the tolerance, the gaps being short (the
         ! step ends 1 % short of the root). The bound cross_gap_on_dense uses
         ! (the departure from the tangent) refused so many on smooth motion
         ! that prediction cost more than it saved (docs/accuracy.md).
         call stepper%dense(t_to, this%y_work)
         sig = (t_to - this%t_prev)/span
         this%dy_gap = this%y_work - ((2.0_wp*sig**3 - 3.0_wp*sig**2 + 1.0_wp)*this%y_prev &
                                      + (sig**3 - 2.0_wp*sig**2 + sig)*span*this%f_prev &
                                      + (-2.0_wp*sig**3 + 3.0_wp*sig**2)*y + (sig**3 - sig**2)*span*stepper%f)
         if (.not. stepper%within_tolerance(y, gap_safety*this%dy_gap)) return
         ! every function there: past the switch, and no other one crossed
         ! on the way (that one would be the step's to search)
         call switch_values(sys, t_to, this%y_work, this%g_try, stepper%stats, this%rates, this%counts)
         if (.not. any_change(this%g_prev, this%g_try, this%live, ix, .true.)) return
      end associate
      do k = 1, this%n_g
         if (this%live(k) .and. .not. this%searched(this%group_of(k)) .and. crossed(this%g_prev(k), this%g_try(k))) return
      end do
      call merge_after(t_to)
      this%y_hi = this%y_work
      call keep(this, sys, stepper, t_to, this%y_hi, .false., t, y, err)
      located = .true.
      this%n_run = this%n_run + 1
      stepper%stats%switches_located = stepper%stats%switches_located + 1
      stepper%stats%switches_predicted = stepper%stats%switches_predicted + 1
   contains
      !> As merge_near: the switches within merge_window after the one
      !! crossed at t_at taken with it (t_at and y_work moved past them on
      !! the extension), or the print time t_limit when that close. Only
      !! the functions that their rate over the gap brings to zero within
      !! ten times that are evaluated again.
      subroutine merge_after(t_at)
         real(wp), intent(inout) :: t_at
         real(wp) :: t_w, rate
         integer :: j
         logical :: near, later
         ! (within the gap whose error was checked)
         t_w = min(t_at + merge_window + 8.0_wp*spacing(t_at), t_b)
         this%searched = .false.
         near = .false.
         do j = 1, this%n_g
            if (.not. this%live(j) .or. passed(this%g_prev(j), this%g_try(j))) cycle
            rate = abs(this%g_try(j) - this%g_hi(j))/(t_at - t)
            if (abs(this%g_try(j)) <= 10.0_wp*rate*(t_w - t_at)) then
               this%searched(this%group_of(j)) = .true.
               near = .true.
            end if
         end do
         call index_searched(this)
         if (near .and. t_w > t_at) then
            call stepper%dense(t_w, this%y_lo)
            call search_values(this, sys, t_w, this%y_lo, this%g_dt, stepper%stats)
            ! past a switch not passed at t_at, from the accepted state's side
            later = .false.
            do j = 1, this%n_searched
               associate (i => this%idx(j))
                  later = later .or. (this%live(i) .and. .not. passed(this%g_prev(i), this%g_try(i)) &
                                      .and. passed(this%g_prev(i), this%g_dt(i)))
               end associate
            end do
            if (later) then
               t_at = t_w
               this%y_work = this%y_lo
            end if
         end if
         ! (onto the print time, kink or TMAX when that close, never past it)
         if (present(t_limit)) then
            if (t_at >= t_limit .or. t_limit - t_at < merge_window) then
               t_at = t_limit
               call stepper%dense(t_at, this%y_work)
            end if
         end if
      end subroutine merge_after
   end subroutine cross_predicted

   !> The earliest time in (t_a, t_b) - the step from the marked state to
   !! its end, where y_end, f_end - at which a switching function that
   !! changed sign over it reaches zero on the cubic Hermite interpolant
   !! of the step (interpolant_crossing, unshifted).
   function hermite_crossing(this, sys, stepper, t_a, t_b, tol_t, stats) result(t_past)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      class(stepper_t), intent(in) :: stepper
      real(wp), intent(in) :: t_a, t_b, tol_t
      type(step_stats_t), intent(inout) :: stats
      real(wp) :: t_past
      this%g_shift = 0.0_wp
      this%g_lo = this%g_prev
      t_past = interpolant_crossing(this, sys, stepper, t_a, t_b, tol_t, stats, .false.)
   end function hermite_crossing

   !> Location on the stepper's continuous extension (Dormand-Prince,
   !! issue 15): the first root of the live switching functions on it,
   !! bracketed to tol_t/8 by switching functions alone (no evaluation of
   !! forces); then ONE step from the marked state to tol_t/2 past it. When
   !! the state that step gives is past a switch (a strict sign change),
   !! it is the state accepted (done; (t_hi, y_hi) set, current_is_hi).
   !! Otherwise the step's own trajectory crosses a little later than the
   !! extension: its state is the bracket's start (t_lo, g_lo), the
   !! extension is shifted by the difference of the switching functions
   !! there, and the root of the shifted extension is tried in the same
   !! way (where it lies within a small gap of that step's end, on that
   !! step's own extension, without another step: cross_gap_on_dense),
   !! at most max_dense_tries times in all; then the caller's
   !! regula falsi goes on from the bracket (done false). Each try is a
   !! step taken again (stats%retaken).
   subroutine locate_on_dense(this, sys, stepper, t_end, tol_t, t_lo, t_hi, current_is_hi, t, y, done, short)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t_end, tol_t
      real(wp), intent(inout) :: t_lo, t_hi
      logical, intent(inout) :: current_is_hi
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      logical, intent(out) :: done
      logical, intent(out) :: short     !< a step taken again ended short of the time asked
      type(error_t) :: retry
      real(wp) :: t_to, t_b
      integer :: j, i
      logical :: current, lo_on_dense
      done = .false.
      short = .false.
      this%g_shift = 0.0_wp
      this%g_end = this%g_hi
      t_b = t_end
      ! the stepper's extension is that of a step taken again that ended
      ! at t_lo, short of the switch (not the first step's, nor a trial's)
      lo_on_dense = .false.
      do j = 1, max_dense_tries
         t_to = interpolant_crossing(this, sys, stepper, t_lo, t_b, tol_t, stepper%stats, .true.)
         t_to = t_to + 0.5_wp*tol_t
         if (.not. (t_to > t_lo .and. t_to < t_b)) exit
         if (lo_on_dense) then
            if (cross_gap_on_dense()) return
         end if
         lo_on_dense = .false.
         call step_again(this, sys, stepper, t_to, t, y, retry, short, current, allow_trial=j < max_dense_tries)
         current_is_hi = .false.
         if (retry%failed()) exit
         if (stepper%trial_offered) then
            ! the step to the switch was rejected: the trajectory crosses
            ! earlier than the extension said (a jump inside the step).
            ! When this shorter trial crosses, its own extension (nearer
            ! the trajectory) is searched next; otherwise short
            call stepper%dense(stepper%t_trial, this%y_work)
            call search_values(this, sys, stepper%t_trial, this%y_work, this%g_dt, stepper%stats)
            short = .true.
            if (.not. any_change(this%g_lo, this%g_dt, this%live, this%idx(:this%n_searched), .false.)) exit
            ! (a try of the location, counted as taken again, not rejected)
            stepper%stats%rejected = stepper%stats%rejected - 1
            stepper%stats%retaken = stepper%stats%retaken + 1
            t_b = stepper%t_trial
            call copy_on(this%g_hi, this%g_dt, this%idx(:this%n_searched))
            this%g_shift = 0.0_wp
            short = .false.
            cycle
         end if
         if (short) exit
         call search_values(this, sys, t, y, this%g_try, stepper%stats)
         if (any_change(this%g_prev, this%g_try, this%live, this%idx(:this%n_searched), .true.)) then
            t_hi = t
            call copy_on(this%g_hi, this%g_try, this%idx(:this%n_searched))
            this%y_hi = y
            current_is_hi = current
            done = .true.
            return
         end if
         ! short of every switch: the bracket's start, and the extension
         ! shifted to the step's switching functions there
         t_lo = t
         call copy_on(this%g_lo, this%g_try, this%idx(:this%n_searched))
         call stepper%dense(t, this%y_work)
         call search_values(this, sys, t, this%y_work, this%g_shift, stepper%stats)
         do i = 1, this%n_searched
            this%g_shift(this%idx(i)) = this%g_try(this%idx(i)) - this%g_shift(this%idx(i))
         end do
         lo_on_dense = .true.
      end do
      ! (the caller's bracket ends at the step's end)
      this%g_hi = this%g_end
   contains
      !> Issue 16: the step taken again ended short of the switch by a gap
      !! (t_lo to t_to) so small that its own continuous extension, carried
      !! on past its end, reaches the switch within the step's tolerance:
      !! that extension leaves the step's end on y' there (exactly: DOPRI5's
      !! extension is C1 at its ends) and departs from that tangent by
      !! y''(gap)**2/2, which the step's mean change of y' bounds
      !! (dy_gap; checked against the tolerance, the gap at most a tenth
      !! of the step). Then the state past the switch is taken from it
      !! (done) instead of taking the step once more (six evaluations);
      !! otherwise (or where the extension's state is still short) false.
      logical function cross_gap_on_dense() result(crossed_gap)
         real(wp) :: gap, span
         crossed_gap = .false.
         gap = t_to - t_lo
         span = t_lo - this%t_prev
         if (.not. (gap <= gap_fraction*span)) return
         this%dy_gap = (gap_safety*0.5_wp*gap*gap/span)*(stepper%f - this%f_prev)
         if (.not. stepper%within_tolerance(y, this%dy_gap)) return
         call stepper%dense(t_to, this%y_work)
         call search_values(this, sys, t_to, this%y_work, this%g_try, stepper%stats)
         if (.not. any_change(this%g_prev, this%g_try, this%live, this%idx(:this%n_searched), .true.)) return
         t_hi = t_to
         call copy_on(this%g_hi, this%g_try, this%idx(:this%n_searched))
         this%y_hi = this%y_work
         current_is_hi = .false.
         stepper%stats%gaps_crossed = stepper%stats%gaps_crossed + 1
         done = .true.
         crossed_gap = .true.
      end function cross_gap_on_dense
   end subroutine locate_on_dense

   !> The earliest time in (t_a, t_b) (t_a: the marked state's time or a
   !! try short of the switch, where g_lo; t_b: the step's end, where g_hi)
   !! at which a live switching function, on an interpolant of the step
   !! shifted by g_shift, crosses from its side at t_a: Illinois' regula
   !! falsi to within tol_t/8, the end past the root returned (switching
   !! functions only; counted in stats). t_b when none crosses. The
   !! interpolant: the stepper's continuous extension (dense), or the cubic
   !! Hermite through the step's ends' values and slopes.
   function interpolant_crossing(this, sys, stepper, t_a, t_b, tol_t, stats, dense) result(t_past)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      class(stepper_t), intent(in) :: stepper
      real(wp), intent(in) :: t_a, t_b, tol_t
      type(step_stats_t), intent(inout) :: stats
      logical, intent(in) :: dense
      real(wp) :: t_past
      real(wp) :: lo, hi, tau, w_lo, w_hi, h, sig
      integer :: k, last_side, i, j
      lo = t_a
      hi = t_b
      h = t_b - t_a
      associate (ix => this%idx(:this%n_searched))
      do i = 1, this%n_searched
         j = ix(i)
         this%g_da(j) = this%g_lo(j)
         this%g_db(j) = this%g_hi(j) + this%g_shift(j)
      end do
      t_past = t_b
      if (.not. any_change(this%g_da, this%g_db, this%live, ix, .false.)) return
      w_lo = 1.0_wp
      w_hi = 1.0_wp
      last_side = 0
      do k = 1, max_tries
         if (hi - lo <= 0.125_wp*tol_t) exit
         tau = first_crossing(this%g_da, this%g_db, this%live, ix, w_lo, w_hi, lo, hi)
         if (mod(k, 4) == 0) tau = 0.5_wp*(lo + hi)
         if (.not. (tau > lo .and. tau < hi)) tau = 0.5_wp*(lo + hi)
         if (.not. (tau > lo .and. tau < hi)) exit
         if (dense) then
            call stepper%dense(tau, this%y_work)
         else
            ! y(tau) on the cubic with the ends' values and slopes
            sig = (tau - t_a)/h
            this%y_work = (2.0_wp*sig**3 - 3.0_wp*sig**2 + 1.0_wp)*this%y_prev &
                          + (sig**3 - 2.0_wp*sig**2 + sig)*h*this%f_prev &
                          + (-2.0_wp*sig**3 + 3.0_wp*sig**2)*this%y_end + (sig**3 - sig**2)*h*this%f_end
         end if
         call search_values(this, sys, tau, this%y_work, this%g_dt, stats)
         do i = 1, this%n_searched
            this%g_dt(ix(i)) = this%g_dt(ix(i)) + this%g_shift(ix(i))
         end do
         if (any_change(this%g_da, this%g_dt, this%live, ix, .false.)) then
            hi = tau
            call copy_on(this%g_db, this%g_dt, ix)
            if (last_side == 1) w_lo = 0.5_wp*w_lo
            w_hi = 1.0_wp
            last_side = 1
         else
            lo = tau
            call copy_on(this%g_da, this%g_dt, ix)
            if (last_side == -1) w_hi = 0.5_wp*w_hi
            w_lo = 1.0_wp
            last_side = -1
         end if
      end do
      t_past = hi
      end associate
   end function interpolant_crossing

   !> The step taken again from the marked state to t_to, into (t, y); the
   !! step taken before is not kept (counted as taken again, stats%retaken).
   !! With a hop, the step ends hop short of t_to and y goes on to t_to on
   !! its slope there (an error of hop times the jump of y' at most, far
   !! below the tolerance); current: the stepper's f is y' at (t, y) (no
   !! hop). short: the stepper rejected the step and ended before t_to.
   subroutine step_again(this, sys, stepper, t_to, t, y, err, short, current, allow_trial)
      type(switch_locator_t), intent(in) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t_to
      real(wp), intent(out) :: t
      real(wp), intent(out), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      logical, intent(out), optional :: short, current
      !> a trial of the step rejected is offered to the caller (the
      !! stepper back at the marked state, stepper%trial_offered; short);
      !! otherwise the stepper shortens the step itself
      logical, intent(in), optional :: allow_trial
      real(wp) :: hop, t_stop
      logical :: offers
      hop = min(this%hop, 0.5_wp*(t_to - this%t_prev))
      t_stop = t_to - hop
      if (present(short)) short = .false.
      if (present(current)) current = .true.
      y = this%y_prev
      t = this%t_prev
      stepper%stats%steps = stepper%stats%steps - 1
      stepper%stats%retaken = stepper%stats%retaken + 1
      stepper%stats%h_min = this%stats_prev%h_min
      stepper%stats%h_max = this%stats_prev%h_max
      ! (y' there is known: f_prev, with the memory unchanged since)
      call stepper%resume(sys, t, y, this%f_prev, err)
      offers = stepper%offers_trials
      stepper%offers_trials = offers .and. present(allow_trial)
      if (stepper%offers_trials) stepper%offers_trials = allow_trial
      if (.not. err%failed()) call stepper%retake(sys, t, y, t_stop, err)
      stepper%offers_trials = offers
      if (err%failed()) then
         stepper%stats%steps = stepper%stats%steps + 1
      else if (t < t_stop) then
         if (present(short)) short = .true.
      else if (hop > 0.0_wp) then
         y = y + (t_to - t)*stepper%f
         t = t_to
         if (present(current)) current = .false.
      end if
   end subroutine step_again

   !> Keep the step from the marked state to t_keep (state y_keep) as the
   !! accepted one: (t, y) set to it, its size among the accepted ones,
   !! the stepper restarted there (not counted as a restart after a jump);
   !! current: the stepper's last step ended there, so its f is y' there
   !! (resumed with it: Dormand-Prince evaluates nothing).
   subroutine keep(this, sys, stepper, t_keep, y_keep, current, t, y, err)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t_keep, y_keep(:)
      logical, intent(in) :: current
      real(wp), intent(out) :: t
      real(wp), intent(out), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      y = y_keep
      t = t_keep
      stepper%stats%h_min = min(this%stats_prev%h_min, t_keep - this%t_prev)
      stepper%stats%h_max = max(this%stats_prev%h_max, t_keep - this%t_prev)
      if (current) then
         ! (a copy: resume sets the stepper's f from it)
         this%y_work = stepper%f
         call stepper%resume(sys, t, y, this%y_work, err)
      else
         call stepper%restart(sys, t, y, err)
         stepper%stats%restarts = stepper%stats%restarts - 1
      end if
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
   pure real(wp) function first_crossing(g_lo, g_hi, live, idx, w_lo, w_hi, t_lo, t_hi) result(t_first)
      real(wp), intent(in) :: g_lo(:), g_hi(:), w_lo, w_hi, t_lo, t_hi
      logical, intent(in) :: live(:)
      integer, intent(in) :: idx(:)          !< the functions searched
      real(wp) :: a, b, frac
      integer :: i, m
      t_first = t_hi
      do m = 1, size(idx)
         i = idx(m)
         if (.not. (live(i) .and. crossed(g_lo(i), g_hi(i)))) cycle
         a = w_lo*g_lo(i)
         b = w_hi*g_hi(i)
         frac = 0.5_wp
         if (abs(a - b) > 0.0_wp) frac = a/(a - b)
         t_first = min(t_first, t_lo + max(0.0_wp, min(1.0_wp, frac))*(t_hi - t_lo))
      end do
   end function first_crossing

   !> Whether a live function among idx has in b the sign opposite to a's
   !! (strict: passed) or changed sign from a to b (crossed).
   pure logical function any_change(a, b, live, idx, strict) result(yes)
      real(wp), intent(in) :: a(:), b(:)
      logical, intent(in) :: live(:), strict
      integer, intent(in) :: idx(:)
      integer :: m, i
      yes = .false.
      do m = 1, size(idx)
         i = idx(m)
         if (.not. live(i)) cycle
         if (strict) then
            yes = passed(a(i), b(i))
         else
            yes = crossed(a(i), b(i))
         end if
         if (yes) return
      end do
   end function any_change

   !> dst = src on the functions idx.
   pure subroutine copy_on(dst, src, idx)
      real(wp), intent(inout) :: dst(:)
      real(wp), intent(in) :: src(:)
      integer, intent(in) :: idx(:)
      integer :: m
      do m = 1, size(idx)
         dst(idx(m)) = src(idx(m))
      end do
   end subroutine copy_on

   !> Every switching function of the scene at (t, y), in the order of the
   !! occupants and their effects (counted in stats). The body state is
   !! made only for an occupant with an effect that has one.
   subroutine switch_values(sys, t, y, g, stats, rates, counts, only)
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout) :: g(:)
      type(step_stats_t), intent(inout) :: stats
      real(wp), intent(inout), contiguous :: rates(:)      !< workspace (the sliding switches' forces)
      integer(i8), intent(inout) :: counts(:)
      !> only the groups (switch_groups) marked here are evaluated; the
      !! others' functions are left as they are
      logical, intent(in), optional :: only(:)
      integer :: o, k, xo, ao, i, grp
      type(body_state_t) :: st
      logical :: made
      i = 0
      grp = 0
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            made = .false.
            do k = 1, size(occ%effects)
               associate (e => occ%effects(k)%e)
                  if (e%n_switch == 0) cycle
                  grp = grp + 1
                  if (present(only)) then
                     if (.not. only(grp)) then
                        i = i + e%n_switch
                        cycle
                     end if
                  end if
                  if (.not. made) st = system_body_state(sys, o, t, y)
                  made = .true.
                  xo = occ%extra_offset(k)
                  ao = occ%aux_offset(k)
                  call e%switches(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), g(i + 1:i + e%n_switch))
                  i = i + e%n_switch
               end associate
            end do
            if (occ%n_slide > 0) then
               grp = grp + 1
               if (present(only)) then
                  if (.not. only(grp)) then
                     i = i + 2*occ%n_slide
                     cycle
                  end if
               end if
               ! the sliding constraints' multipliers leaving their ranges
               if (.not. made) st = system_body_state(sys, o, t, y)
               made = .true.
               call occupant_slide_switches(occ, st, y, g(i + 1:i + 2*occ%n_slide), rates, counts)
               i = i + 2*occ%n_slide
            end if
         end associate
      end do
      stats%switch_evaluations = stats%switch_evaluations + 1
   end subroutine switch_values

   !> The switching functions at (t, y) as the search for a switch in the
   !! step needs them: those of the searched groups (the others, which the
   !! search does not read, are left as they are).
   subroutine search_values(this, sys, t, y, g, stats)
      type(switch_locator_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout) :: g(:)
      type(step_stats_t), intent(inout) :: stats
      call switch_values(sys, t, y, g, stats, this%rates, this%counts, this%searched)
      stats%switch_groups_skipped = stats%switch_groups_skipped + count(.not. this%searched)
   end subroutine search_values

   !> idx(1:n_searched): the functions of the groups searched.
   pure subroutine index_searched(this)
      type(switch_locator_t), intent(inout) :: this
      integer :: k
      this%n_searched = 0
      do k = 1, this%n_g
         if (.not. this%searched(this%group_of(k))) cycle
         this%n_searched = this%n_searched + 1
         this%idx(this%n_searched) = k
      end do
   end subroutine index_searched

   !> The group of each switching function of the scene, in switch_values'
   !! order: each effect's functions one group, each occupant's sliding
   !! constraints' one more; searched: room for a flag per group.
   subroutine switch_groups(sys, group_of, searched, group_occ, group_eff)
      type(crash_system_t), intent(in) :: sys
      integer, allocatable, intent(out) :: group_of(:)
      logical, allocatable, intent(out) :: searched(:)
      integer, allocatable, intent(out) :: group_occ(:), group_eff(:)   !< each group's occupant and effect (0: slides)
      integer :: o, k, i, grp, n, n_grp
      n = 0
      n_grp = 0
      do o = 1, size(sys%occupants)
         do k = 1, size(sys%occupants(o)%effects)
            n = n + sys%occupants(o)%effects(k)%e%n_switch
            if (sys%occupants(o)%effects(k)%e%n_switch > 0) n_grp = n_grp + 1
         end do
         n = n + 2*sys%occupants(o)%n_slide     ! (each sliding constraint's range, occupant_slide_switches)
         if (sys%occupants(o)%n_slide > 0) n_grp = n_grp + 1
      end do
      allocate (group_of(n), group_occ(n_grp), group_eff(n_grp))
      i = 0
      grp = 0
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            do k = 1, size(occ%effects)
               if (occ%effects(k)%e%n_switch == 0) cycle
               grp = grp + 1
               group_occ(grp) = o
               group_eff(grp) = k
               group_of(i + 1:i + occ%effects(k)%e%n_switch) = grp
               i = i + occ%effects(k)%e%n_switch
            end do
            if (occ%n_slide > 0) then
               grp = grp + 1
               group_occ(grp) = o
               group_eff(grp) = 0
               group_of(i + 1:i + 2*occ%n_slide) = grp
               i = i + 2*occ%n_slide
            end if
         end associate
      end do
      allocate (searched(grp))
      searched = .false.
   end subroutine switch_groups
end module switch_location
