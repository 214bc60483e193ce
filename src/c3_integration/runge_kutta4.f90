!> Classic fourth-order Runge-Kutta with a fixed step (an integration
!! option of C.3: "different schemes could be chosen according to the
!! option"). The derivative at the new point is computed at the end of
!! each step and serves as the first stage of the next one, so a step costs
!! four evaluations and output needs none. restart re-evaluates that first
!! stage after a change of the right-hand side and begins a new grid.
module runge_kutta4
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use error_handling, only: error_t
   use ode_system, only: ode_system_t, stepper_t
   implicit none
   private

   public :: rk4_stepper_t

   type, extends(stepper_t) :: rk4_stepper_t
      real(wp) :: h = 0.0_wp
      real(wp) :: t0 = 0.0_wp
      integer :: n = 0                    !< steps taken: t = t0 + n*h exactly
      real(wp), allocatable :: k2(:), k3(:), k4(:), ytmp(:)
   contains
      procedure :: init => rk4_init
      procedure :: advance => rk4_advance
      procedure :: restart => rk4_restart
   end type rk4_stepper_t

contains

   subroutine rk4_init(this, sys, t0, y0, err)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t0
      real(wp), intent(in), contiguous :: y0(:)
      type(error_t), intent(inout) :: err
      integer :: n
      n = size(y0)
      if (allocated(this%f)) deallocate (this%f, this%k2, this%k3, this%k4, this%ytmp, this%y_failed, this%local_error)
      allocate (this%f(n), this%k2(n), this%k3(n), this%k4(n), this%ytmp(n), this%y_failed(n), this%local_error(n))
      this%local_error = 0.0_wp
      call rk4_begin(this, sys, t0, y0, err)
   end subroutine rk4_init

   !> See stepper_t: the first stage kept from the last step assumed the old
   !! right-hand side, so it is evaluated again; the grid restarts at t.
   subroutine rk4_restart(this, sys, t, y, err)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      if (.not. this%restartable(y, err)) return
      this%stats%restarts = this%stats%restarts + 1
      call rk4_begin(this, sys, t, y, err)
   end subroutine rk4_restart

   !> Start (or start again) from (t, y): a new grid t0 = t and the first
   !! stage f(t, y).
   subroutine rk4_begin(this, sys, t, y, err)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      this%t0 = t
      this%n = 0
      if (.not. this%evaluate(sys, t, y, this%f)) call this%give_up_rhs(sys, err)
   end subroutine rk4_begin

   !> One step of size h, or shorter if t_limit comes first (a single-step
   !! method can shorten a step without disturbing the next).
   subroutine rk4_advance(this, sys, t, y, t_limit, err)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_limit
      type(error_t), intent(inout) :: err
      real(wp) :: h, t_new
      logical :: full
      full = t_limit - t >= this%h*(1.0_wp - 1.0e-9_wp)
      if (full) then
         h = this%h
         t_new = this%t0 + real(this%n + 1, wp)*h
      else
         h = t_limit - t
         t_new = t_limit
      end if
      associate (k1 => this%f, k2 => this%k2, k3 => this%k3, k4 => this%k4, yt => this%ytmp)
         yt = y + 0.5_wp*h*k1
         if (.not. evaluate(t + 0.5_wp*h, yt, k2)) return
         yt = y + 0.5_wp*h*k2
         if (.not. evaluate(t + 0.5_wp*h, yt, k3)) return
         yt = y + h*k3
         if (.not. evaluate(t_new, yt, k4)) return
         yt = y + (h/6.0_wp)*(k1 + 2.0_wp*(k2 + k3) + k4)
         if (.not. all(ieee_is_finite(yt))) then
            call this%give_up_not_finite(err)
            return
         end if
         ! derivative at the new point: the first stage of the next step, and
         ! the evaluation that ends it (evaluate_end: what the system keeps
         ! there serves the accepted step's bookkeeping)
         if (.not. this%evaluate_end(sys, t_new, yt, k2)) then
            call this%give_up_rhs(sys, err)
            return
         end if
         ! local error estimate (docs/accuracy.md): the embedded third-order
         ! solution y + h/6 (k1 + 2 k2 + 2 k3 + f(t+h, y_new)) from the
         ! stages already taken (the last is the next step's first): no
         ! extra evaluation
         this%local_error = (h/6.0_wp)*(k4 - k2)
         this%local_error_new = .true.
         y = yt
         k1 = k2
      end associate
      if (full) then
         this%n = this%n + 1
      else
         this%t0 = t_new
         this%n = 0
      end if
      t = t_new
      this%stats%steps = this%stats%steps + 1
      this%stats%h_min = min(this%stats%h_min, h)
      this%stats%h_max = max(this%stats%h_max, h)
   contains
      !> f(te, ye); a failure ends the step (a fixed step is not shortened
      !! on its account): err says why.
      logical function evaluate(te, ye, fe)
         real(wp), intent(in) :: te
         real(wp), intent(in), contiguous :: ye(:)
         real(wp), intent(out), contiguous :: fe(:)
         evaluate = this%evaluate(sys, te, ye, fe)
         if (.not. evaluate) call this%give_up_rhs(sys, err)
      end function evaluate
   end subroutine rk4_advance
end module runge_kutta4
