!> The interface between the integrators (C.3) and what they integrate:
!! an ODE system y' = f(t, y) and the abstract stepper that advances it.
module ode_system
   use kinds, only: wp, i8
   implicit none
   private

   public :: ode_system_t, stepper_t, step_stats_t
   public :: step_ok, step_rhs_failed, step_too_small, step_not_finite, step_beyond_limit
   public :: step_bad_setting
   public :: step_status_text

   !> Status codes of an integration step.
   integer, parameter :: step_ok = 0
   integer, parameter :: step_rhs_failed = 1   !< the right-hand side could not be evaluated
   integer, parameter :: step_too_small = 2    !< the adaptive step fell below its floor
   integer, parameter :: step_not_finite = 3   !< the state became NaN or infinite
   integer, parameter :: step_beyond_limit = 4 !< a fixed step would pass the time limit
   integer, parameter :: step_bad_setting = 5  !< a stepper setting has no meaning (init, restart)

   !> A system y' = f(t, y). rhs may update diagnostics held in the system
   !! (evaluation counters) but no physical state: integrators call it for
   !! trial points that may be thrown away.
   type, abstract :: ode_system_t
   contains
      procedure(rhs_interface), deferred :: rhs
      procedure :: error_controlled => system_error_controlled
   end type ode_system_t

   abstract interface
      !> status: 0 when f could be evaluated, otherwise a code the system explains.
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
      integer(i8) :: corrector_at_limit = 0 !< steps whose corrector reached the iteration limit
      integer(i8) :: restarts = 0           !< calls of restart (init is not counted)
      real(wp) :: h_min = huge(1.0_wp), h_max = 0.0_wp   !< accepted step sizes
   end type step_stats_t

   !> An integrator. After init, restart and every advance, f holds y' at
   !! the current accepted point, so output needs no extra evaluation.
   type, abstract :: stepper_t
      real(wp), allocatable :: f(:)
      type(step_stats_t) :: stats
      integer :: rhs_status = 0             !< the system's code when step_rhs_failed
   contains
      procedure(init_interface), deferred :: init
      procedure(advance_interface), deferred :: advance
      procedure(restart_interface), deferred :: restart
   end type stepper_t

   abstract interface
      !> Prepare to integrate from (t0, y0); evaluates f there.
      subroutine init_interface(this, sys, t0, y0, status)
         import :: stepper_t, ode_system_t, wp
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(in) :: t0
         real(wp), intent(in), contiguous :: y0(:)
         integer, intent(out) :: status
      end subroutine init_interface

      !> Take one accepted step, ending no later than t_limit; t and y are
      !! updated only when status is step_ok.
      subroutine advance_interface(this, sys, t, y, t_limit, status)
         import :: stepper_t, ode_system_t, wp
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(inout) :: t
         real(wp), intent(inout), contiguous :: y(:)
         real(wp), intent(in) :: t_limit
         integer, intent(out) :: status
      end subroutine advance_interface

      !> The right-hand side has just changed at the accepted point (t, y)
      !! (an effect with memory changed after an accepted step). Forget
      !! everything that assumed the old right-hand side (back values,
      !! the derivative kept at the accepted point, step-size controller
      !! memory), evaluate f at (t, y) (counted in stats%evaluations) and
      !! continue from there as after init. Must follow init; the workspace
      !! is kept (no allocation). stats accumulate; stats%restarts counts
      !! the calls. status: step_ok, step_rhs_failed or step_bad_setting.
      subroutine restart_interface(this, sys, t, y, status)
         import :: stepper_t, ode_system_t, wp
         class(stepper_t), intent(inout) :: this
         class(ode_system_t), intent(inout) :: sys
         real(wp), intent(in) :: t
         real(wp), intent(in), contiguous :: y(:)
         integer, intent(out) :: status
      end subroutine restart_interface
   end interface

contains

   pure function step_status_text(status) result(text)
      integer, intent(in) :: status
      character(len=:), allocatable :: text
      select case (status)
      case (step_ok);         text = 'ok'
      case (step_rhs_failed); text = 'the right-hand side could not be evaluated'
      case (step_too_small);  text = 'the step size fell below its floor (the problem is too stiff ' &
                                     //'or discontinuous for the tolerances)'
      case (step_not_finite); text = 'the state became infinite or NaN'
      case (step_beyond_limit); text = 'a fixed step would pass the requested end time'
      case (step_bad_setting); text = 'an integrator setting is invalid, or restart was called ' &
                                      //'before init or with a state of another size'
      case default;           text = 'unknown integration status'
      end select
   end function step_status_text

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
