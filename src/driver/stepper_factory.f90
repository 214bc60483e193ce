!> The integrator of a run (C.3): built from the model's numerics (NINT,
!! DT, the corrector's and the tolerances' settings), or given by the
!! caller; and what the run loop must know of it (its grid, whether it can
!! take a step again to a located switch).
module stepper_factory
   use kinds, only: wp
   use model, only: model_t, nint_adams, nint_dopri, astart_rk4
   use ode_system, only: stepper_t
   use runge_kutta4, only: rk4_stepper_t
   use adams_moulton, only: am_stepper_t, am_start_euler, am_start_rk4
   use dormand_prince, only: dopri_stepper_t
   implicit none
   private

   public :: stepper_traits_t, stepper_from_model, stepper_traits

   !> How the run loop drives a stepper.
   type :: stepper_traits_t
      !> steps of one size h on a grid from t = 0 (Adams-Moulton, RK4): the
      !! run counts its steps and prints every DTPRINT/h of them; otherwise
      !! (adaptive) the run asks for steps that end at the print times
      logical :: fixed_step = .false.
      real(wp) :: h = 0.0_wp
      !> it can take a step again to a fraction of it (RK4, Dormand-Prince;
      !! Adams-Moulton by its starter, after a restart): a switch of an
      !! effect inside a step is stepped to (issue 15)
      logical :: relocates = .false.
   end type stepper_traits_t

contains

   !> The integrator of option NINT (C.3) with its settings.
   subroutine stepper_from_model(m, stepper)
      type(model_t), intent(in) :: m
      class(stepper_t), allocatable, intent(out) :: stepper
      select case (m%options%nint)
      case (nint_adams)
         allocate (am_stepper_t :: stepper)
      case (nint_dopri)
         allocate (dopri_stepper_t :: stepper)
      case default
         allocate (rk4_stepper_t :: stepper)
      end select
      select type (s => stepper)
      type is (am_stepper_t)
         s%h = m%time%dt
         s%tol = m%time%corrector_tol
         s%max_iter = m%time%corrector_max_iter
         s%start = merge(am_start_rk4, am_start_euler, m%numerics%am_start == astart_rk4)
      type is (rk4_stepper_t)
         s%h = m%time%dt
      type is (dopri_stepper_t)
         s%h = m%time%dt
         s%rtol = m%time%rtol
         s%atol = m%time%atol
         s%h_least = 1.0e-10_wp*m%time%t_max     ! (more than 1e10 steps: a failure, not a run)
      end select
   end subroutine stepper_from_model

   !> What the run loop must know of a stepper. A stepper of a type this
   !! module does not know is driven as an adaptive one that cannot take
   !! a step again (steps that end at the print times, no located switches).
   function stepper_traits(stepper) result(tr)
      class(stepper_t), intent(in) :: stepper
      type(stepper_traits_t) :: tr
      select type (s => stepper)
      type is (am_stepper_t)
         tr = stepper_traits_t(fixed_step=.true., h=s%h, relocates=.true.)
      type is (rk4_stepper_t)
         tr = stepper_traits_t(fixed_step=.true., h=s%h, relocates=.true.)
      type is (dopri_stepper_t)
         tr = stepper_traits_t(fixed_step=.false., h=s%h, relocates=.true.)
      class default
         tr = stepper_traits_t()
      end select
   end function stepper_traits
end module stepper_factory
