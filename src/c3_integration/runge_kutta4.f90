!> Classic fourth-order Runge-Kutta with a fixed step (an integration
!! option of C.3: "different schemes could be chosen according to the
!! option"). The derivative at the new point is computed at the end of
!! each step and serves as the first stage of the next one, so a step costs
!! four evaluations and output needs none. restart re-evaluates that first
!! stage after a change of the right-hand side and begins a new grid.
module runge_kutta4
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use ode_system, only: ode_system_t, stepper_t, step_ok, step_rhs_failed, step_not_finite, &
      step_bad_setting
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

   subroutine rk4_init(this, sys, t0, y0, status)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t0
      real(wp), intent(in), contiguous :: y0(:)
      integer, intent(out) :: status
      integer :: n
      n = size(y0)
      if (allocated(this%f)) deallocate (this%f, this%k2, this%k3, this%k4, this%ytmp)
      allocate (this%f(n), this%k2(n), this%k3(n), this%k4(n), this%ytmp(n))
      call rk4_begin(this, sys, t0, y0, status)
   end subroutine rk4_init

   !> See stepper_t: the first stage kept from the last step assumed the old
   !! right-hand side, so it is evaluated again; the grid restarts at t.
   subroutine rk4_restart(this, sys, t, y, status)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(out) :: status
      status = step_bad_setting
      if (.not. allocated(this%f)) return
      if (size(y) /= size(this%f)) return
      this%stats%restarts = this%stats%restarts + 1
      call rk4_begin(this, sys, t, y, status)
   end subroutine rk4_restart

   !> Start (or start again) from (t, y): a new grid t0 = t and the first
   !! stage f(t, y).
   subroutine rk4_begin(this, sys, t, y, status)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(out) :: status
      this%t0 = t
      this%n = 0
      call sys%rhs(t, y, this%f, this%rhs_status)
      this%stats%evaluations = this%stats%evaluations + 1
      status = merge(step_ok, step_rhs_failed, this%rhs_status == 0)
   end subroutine rk4_begin

   !> One step of size h, or shorter if t_limit comes first (a single-step
   !! method can shorten a step without disturbing the next).
   subroutine rk4_advance(this, sys, t, y, t_limit, status)
      class(rk4_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_limit
      integer, intent(out) :: status
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
      status = step_rhs_failed
      associate (k1 => this%f, k2 => this%k2, k3 => this%k3, k4 => this%k4, yt => this%ytmp)
         yt = y + 0.5_wp*h*k1
         if (.not. evaluate(t + 0.5_wp*h, yt, k2)) return
         yt = y + 0.5_wp*h*k2
         if (.not. evaluate(t + 0.5_wp*h, yt, k3)) return
         yt = y + h*k3
         if (.not. evaluate(t_new, yt, k4)) return
         yt = y + (h/6.0_wp)*(k1 + 2.0_wp*(k2 + k3) + k4)
         if (.not. all(ieee_is_finite(yt))) then
            status = step_not_finite
            return
         end if
         ! derivative at the new point: the first stage of the next step
         if (.not. evaluate(t_new, yt, k2)) return
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
      status = step_ok
   contains
      logical function evaluate(te, ye, fe)
         real(wp), intent(in) :: te
         real(wp), intent(in), contiguous :: ye(:)
         real(wp), intent(out), contiguous :: fe(:)
         call sys%rhs(te, ye, fe, this%rhs_status)
         this%stats%evaluations = this%stats%evaluations + 1
         evaluate = this%rhs_status == 0
      end function evaluate
   end subroutine rk4_advance
end module runge_kutta4
