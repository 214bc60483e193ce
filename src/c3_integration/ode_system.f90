!> The interface between the integrators (C.3) and what they integrate:
!! an ODE system y' = f(t, y) and the abstract stepper that advances it.
!!
!! Errors (docs/architecture.md, "Errors"): an evaluation of the right-hand
!! side that cannot be completed is an outcome, not an error: rhs answers
!! with the system's own code (0: evaluated), allocates nothing and builds
!! no message, and a stepper may answer it by itself (Dormand-Prince shrinks
!! the step). When a stepper gives up - init, advance or restart cannot go
!! on - it returns an error_t (exit_numerical) that says what failed, when,
!! and why: for an evaluation, the system's failure_text at the evaluation
!! that failed, asked then and only then (the cold path). No code above the
!! steppers sees a status code.
module ode_system
   use kinds, only: wp, i8
   use error_handling, only: error_t, error_set, exit_numerical
   use strings, only: num, itoa
   implicit none
   private

   public :: ode_system_t, stepper_t, step_stats_t
   public :: evaluate_outside_step

   !> A system y' = f(t, y). rhs may update diagnostics held in the system
   !! (evaluation counters) but no physical state: integrators call it for
   !! trial points that may be thrown away.
   type, abstract :: ode_system_t
   contains
      procedure(rhs_interface), deferred :: rhs
      procedure :: rhs_end => system_rhs_end
      procedure :: error_controlled => system_error_controlled
      procedure :: failure_text => system_failure_text
   end type ode_system_t

   abstract interface
      !> status: 0 when f could be evaluated, otherwise a code of the
      !! system's own, which only its failure_text explains (an outcome:
      !! an adaptive stepper answers it by shrinking the step).
      !! y and dydt are contiguous (as every integrator's arrays are; the
      !! steppers' y too): the system passes its effects' slices of them
      !! with a stride of one (docs/performance.md, fourth round).
      subroutine rhs_interface(this, t, y, dydt, status)
         import :: ode_system_t, wp
         class(ode_system_t), intent(inout) :: this
         real(wp), intent(in) :: t
         real(wp), intent(in), contiguous :: y(:)
         real(wp), intent(out), contiguous :: dydt(:)
         integer, intent(out) :: status
      end subroutine rhs_interface
   end interface

   !> What an integration cost.
   type :: step_stats_t
      integer(i8) :: steps = 0              !< accepted steps
      integer(i8) :: rejected = 0           !< rejected trial steps (adaptive)
      integer(i8) :: evaluations = 0        !< right-hand-side evaluations
      integer(i8) :: corrector_iterations = 0 !< corrector passes (Adams-Moulton, modified Euler)
      !> corrector solves (one per step taken, also a step taken again to
      !! locate a switch; Adams-Moulton, modified Euler)
      integer(i8) :: corrector_solves = 0
      integer(i8) :: corrector_at_limit = 0 !< solves that reached the iteration limit
      integer(i8) :: restarts = 0           !< calls of restart (init is not counted)
      integer(i8) :: switches_located = 0   !< accepted states placed just past a switch (issue 15)
      integer(i8) :: retaken = 0            !< steps taken again to locate a switch (not rejected ones)
      !> switches reached on the continuous extension of a step taken again
      !! that ended just short of them, not by taking it once more (issue 16)
      integer(i8) :: gaps_crossed = 0
      !> switches predicted before the step that would have crossed them,
      !! which was cut just short of them and crossed the rest on its own
      !! extension (issue 16; switch_location's predict)
      integer(i8) :: switches_predicted = 0
      !> accepted states on a kink of the vehicle's motion inside a step (issue 15; print_schedule)
      integer(i8) :: kinks = 0
      !> switches found at once after the last, taken at the step's end (chatter)
      integer(i8) :: switches_unlocated = 0
      integer(i8) :: switch_evaluations = 0 !< evaluations of the effects' switching functions
      !> effects' (or sliding constraints') switching functions not evaluated
      !! in a search for a switch, where none of them could cross (issue 16)
      integer(i8) :: switch_groups_skipped = 0
      !> effects' (or sliding constraints') switching functions kept after an
      !! accept that changed none of their memory (issue 16)
      integer(i8) :: switch_groups_kept = 0
      real(wp) :: h_min = huge(1.0_wp), h_max = 0.0_wp   !< accepted step sizes
   end type step_stats_t

   !> An integrator. After init, restart and every advance, f holds y' at
   !! the current accepted point, so output needs no extra evaluation.
   type, abstract :: stepper_t
      real(wp), allocatable :: f(:)
      type(step_stats_t) :: stats
      !> the last evaluation that failed: its time, the system's code and
      !! its state, kept (a copy, no allocation after the first) for the
      !! message should the stepper give up
      real(wp) :: t_failed = 0.0_wp
      integer :: code_failed = 0
      real(wp), allocatable :: y_failed(:)
      !> the local error estimate of the last step advance took, in y's
      !! layout (y_exact - y_step, signed): given by the fixed-step
      !! integrators (docs/accuracy.md); not allocated when a stepper gives
      !! none. local_error_new: set by advance, cleared by the reader, so
      !! that a step is counted once
      real(wp), allocatable :: local_error(:)
      logical :: local_error_new = .false.
      !> an adaptive stepper with a continuous extension may return a trial
      !! step it rejected to the caller (trial_offered, ending at t_trial;
      !! its extension given by dense) instead of trying a shorter one at
      !! once: the caller cuts it at a switch it crosses (issue 15: the
      !! error of a step across a switch is the switch's, not the step
      !! size's), or calls advance again, which goes on with the shorter
      !! step. Set by the caller that locates switches.
      logical :: offers_trials = .false.
      logical :: trial_offered = .false.
      !> a multistep method (Adams-Moulton): its steps lean on back values,
      !! so it restarts to step onto a kink of the forcing and again after
      !! it (issue 15; print_schedule)
      logical :: multistep = .false.
      real(wp) :: t_trial = 0.0_wp
   contains
      procedure(init_interface), deferred :: init
      procedure(advance_interface), deferred :: advance
      procedure(restart_interface), deferred :: restart
      procedure :: retake => stepper_retake
      procedure :: resume => stepper_resume
      procedure :: has_dense => stepper_has_dense
      procedure :: dense => stepper_dense
      procedure :: within_tolerance => stepper_within_tolerance
      procedure :: next_step => stepper_next_step
      procedure, non_overridable :: evaluate => stepper_evaluate
      procedure, non_overridable :: evaluate_end => stepper_evaluate_end
      procedure, non_overridable :: restartable => stepper_restartable
      procedure, non_overridable :: give_up_rhs => stepper_give_up_rhs
      procedure, non_overridable :: give_up_not_finite => stepper_give_up_not_finite
   end type stepper_t

   abstract interface
      !> Prepare to integrate from (t0, y0); evaluates f there. err: the
      !! evaluation failed, or a setting is invalid.
      subroutine init_interface(this, sys, t0, y0, err)
         import :: stepper_t, ode_system_t, wp, error_t
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(in) :: t0
         real(wp), intent(in), contiguous :: y0(:)
         type(error_t), intent(inout) :: err
      end subroutine init_interface

      !> Take one accepted step, ending no later than t_limit; t and y are
      !! updated only when it succeeds. err: no step could be taken (an
      !! evaluation failed, the step fell below its floor, the state became
      !! infinite, a fixed step would pass t_limit), and why.
      subroutine advance_interface(this, sys, t, y, t_limit, err)
         import :: stepper_t, ode_system_t, wp, error_t
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(inout) :: t
         real(wp), intent(inout), contiguous :: y(:)
         real(wp), intent(in) :: t_limit
         type(error_t), intent(inout) :: err
      end subroutine advance_interface

      !> The right-hand side has just changed at the accepted point (t, y)
      !! (an effect with memory changed after an accepted step). Forget
      !! everything that assumed the old right-hand side (back values,
      !! the derivative kept at the accepted point, step-size controller
      !! memory), evaluate f at (t, y) (counted in stats%evaluations) and
      !! continue from there as after init. Must follow init; the workspace
      !! is kept (no allocation). stats accumulate; stats%restarts counts
      !! the calls. err: the evaluation failed, restart came before init or
      !! with a state of another size, or a setting is invalid.
      subroutine restart_interface(this, sys, t, y, err)
         import :: stepper_t, ode_system_t, wp, error_t
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(in) :: t
         real(wp), intent(in), contiguous :: y(:)
         type(error_t), intent(inout) :: err
      end subroutine restart_interface
   end interface

contains

   !> One step from the accepted point (t, y) (after init or restart) that
   !! ends at t_to exactly, inside a step already taken and accepted (to
   !! locate a switch in it, issue 15). By default advance with t_to as
   !! its limit: a fixed step at least as long ends there.
   subroutine stepper_retake(this, sys, t, y, t_to, err)
      class(stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_to
      type(error_t), intent(inout) :: err
      call this%advance(sys, t, y, t_to, err)
   end subroutine stepper_retake

   !> Continue from the accepted point (t, y) whose derivative f, with the
   !! right-hand side as it is now, the caller already holds (the state a
   !! step started from, to take it again; the end of a step just taken):
   !! as restart, but a stepper that needs no more than f there may take
   !! it instead of evaluating it again (Dormand-Prince). Not counted as a
   !! restart. By default restart (f evaluated again, the count undone).
   subroutine stepper_resume(this, sys, t, y, f, err)
      class(stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:), f(:)
      type(error_t), intent(inout) :: err
      associate (unused => size(f))
      end associate
      call this%restart(sys, t, y, err)
      if (.not. err%failed()) this%stats%restarts = this%stats%restarts - 1
   end subroutine stepper_resume

   !> The size of the step the next advance will try (an adaptive
   !! stepper's proposal; 0: none known, a fixed-step method's steps are
   !! the grid's).
   pure real(wp) function stepper_next_step(this) result(h)
      class(stepper_t), intent(in) :: this
      associate (unused => this%stats%steps)
      end associate
      h = 0.0_wp
   end function stepper_next_step

   !> Whether dense can give the state anywhere in the step the last
   !! advance (or retake) took: its continuous extension (issue 15, the
   !! switches located on it without taking the step again). None by
   !! default: a caller interpolates itself (switch_location: Hermite's
   !! cubic through the step's ends).
   pure logical function stepper_has_dense(this)
      class(stepper_t), intent(in) :: this
      associate (unused => this%stats%steps)
      end associate
      stepper_has_dense = .false.
   end function stepper_has_dense

   !> y at time t inside the step the last advance took, on the stepper's
   !! continuous extension (only when has_dense; no evaluation). The
   !! default, never called, gives y = 0.
   pure subroutine stepper_dense(this, t, y)
      class(stepper_t), intent(in) :: this
      real(wp), intent(in) :: t
      real(wp), intent(out), contiguous :: y(:)
      associate (unused => this%stats%steps, u2 => t)
      end associate
      y = 0.0_wp
   end subroutine stepper_dense

   !> A change dy of the state y within the stepper's error tolerance for
   !! one step (its scaled norm at most 1): where a state may be taken from
   !! the continuous extension a little past the step's end (the switch
   !! locator, issue 16). The default, a stepper without an error
   !! tolerance: never.
   pure logical function stepper_within_tolerance(this, y, dy)
      class(stepper_t), intent(in) :: this
      real(wp), intent(in), contiguous :: y(:), dy(:)
      associate (unused => this%stats%steps, u2 => size(y) + size(dy))
      end associate
      stepper_within_tolerance = .false.
   end function stepper_within_tolerance

   !> f(t, y) for a step of this stepper, counted in its statistics: true
   !! when the system could evaluate it. A failure is an outcome here (the
   !! caller may answer it with a shorter step); only its time, code and
   !! state are kept, for give_up_rhs.
   logical function stepper_evaluate(this, sys, t, y, f) result(ok)
      class(stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: f(:)
      integer :: code
      call sys%rhs(t, y, f, code)
      this%stats%evaluations = this%stats%evaluations + 1
      ok = code == 0
      if (.not. ok) then
         this%t_failed = t
         this%code_failed = code
         this%y_failed = y
      end if
   end function stepper_evaluate

   !> As evaluate, for the evaluation that ends a step: at the point the
   !! step is accepted at, if it is, so that the system may keep what is
   !! computed there for what follows an accepted step (rhs_end; issue 16
   !! section 4). The same f.
   logical function stepper_evaluate_end(this, sys, t, y, f) result(ok)
      class(stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: f(:)
      integer :: code
      call sys%rhs_end(t, y, f, code)
      this%stats%evaluations = this%stats%evaluations + 1
      ok = code == 0
      if (.not. ok) then
         this%t_failed = t
         this%code_failed = code
         this%y_failed = y
      end if
   end function stepper_evaluate_end

   !> The stepper gives up because its last evaluation failed: err says
   !! when and, through the system's failure_text at that evaluation, why.
   subroutine stepper_give_up_rhs(this, sys, err)
      class(stepper_t), intent(in) :: this
      class(ode_system_t), intent(in) :: sys
      type(error_t), intent(inout) :: err
      call rhs_failed(sys, this%t_failed, this%y_failed, this%code_failed, err)
   end subroutine stepper_give_up_rhs

   !> The stepper gives up because the state of its step is not finite
   !! (the right-hand side was, but the step's combination of it overflowed).
   subroutine stepper_give_up_not_finite(this, err)
      class(stepper_t), intent(in) :: this
      type(error_t), intent(inout) :: err
      associate (unused => this)
      end associate
      call error_set(err, exit_numerical, 'the state became infinite or NaN')
   end subroutine stepper_give_up_not_finite

   !> restart may follow: init has been called, with a state of y's size;
   !! if not, err says which.
   logical function stepper_restartable(this, y, err) result(ok)
      class(stepper_t), intent(in) :: this
      real(wp), intent(in) :: y(:)
      type(error_t), intent(inout) :: err
      ok = .false.
      if (.not. allocated(this%f)) then
         call error_set(err, exit_numerical, 'restart was called before init')
      else if (size(y) /= size(this%f)) then
         call error_set(err, exit_numerical, 'restart was called with a state of '//itoa(size(y)) &
                        //' entries, init with '//itoa(size(this%f)))
      else
         ok = .true.
      end if
   end function stepper_restartable

   !> f(t, y) outside any step (the derivative at an accepted point after
   !! the right-hand side jumped, when no step follows): not a stepper's
   !! evaluation (not in its statistics); err when it fails, as a
   !! stepper's.
   subroutine evaluate_outside_step(sys, t, y, f, err)
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: f(:)
      type(error_t), intent(inout) :: err
      integer :: code
      call sys%rhs(t, y, f, code)
      if (code /= 0) call rhs_failed(sys, t, y, code, err)
   end subroutine evaluate_outside_step

   !> The evaluation at (t, y) failed with the system's code: err says
   !! when, and why when the system says (its failure_text).
   subroutine rhs_failed(sys, t, y, code, err)
      class(ode_system_t), intent(in) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(in) :: code
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: why
      why = sys%failure_text(t, y, code)
      if (len(why) > 0) why = ': '//why
      call error_set(err, exit_numerical, 'the right-hand side could not be evaluated at t = '//num(t)//' s'//why)
   end subroutine rhs_failed

   !> rhs at the evaluation that ends a step (stepper_evaluate_end): the
   !! same f and status as rhs; a system may keep there what its accepted
   !! step's bookkeeping would compute again at (t, y) (crash_system_t:
   !! its effects' results for their accept). By default rhs.
   subroutine system_rhs_end(this, t, y, dydt, status)
      class(ode_system_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: dydt(:)
      integer, intent(out) :: status
      call this%rhs(t, y, dydt, status)
   end subroutine system_rhs_end

   !> Why the evaluation at (t, y) failed with the system's code (rhs's
   !! status): asked only when a stepper gives up, never at a trial, so it
   !! may take its time (evaluate again, build a message). The default
   !! system does not say ('').
   function system_failure_text(this, t, y, code) result(text)
      class(ode_system_t), intent(in) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      associate (unused => this, u2 => t, u3 => size(y), u4 => code)
      end associate
      text = ''
   end function system_failure_text

   !> For each of the n entries of y, whether an adaptive stepper's error
   !! norm includes it: all of them unless the system says otherwise.
   pure function system_error_controlled(this, n) result(mask)
      class(ode_system_t), intent(in) :: this
      integer, intent(in) :: n
      logical :: mask(n)
      associate (unused => this)
      end associate
      mask = .true.
   end function system_error_controlled
end module ode_system
