!> The report's integrator (C.3): "a four point Adams-Moulton method
!! started with a modified Euler method ... The Euler method is used to
!! obtain the first three points after the given initial point. Thereafter
!! four points are used in the Adams third difference prediction and
!! correction equations. At each computation of a new point, the iteration
!! continues until successive approximations are within a given tolerance
!! or the iteration has been tried a prescribed number of times."
!!
!! Read as (docs/errata.md, D-6): predictor = Adams-Bashforth with third
!! differences (4 steps), corrector = Adams-Moulton with third differences
!! (y_n+1 = y_n + h/24 (9 f_n+1 + 19 f_n - 5 f_n-1 + f_n-2)), iterated; the
!! starter is modified Euler (Euler predictor, trapezoidal corrector)
!! iterated the same way. "Within a tolerance": max_i |y_i^k - y_i^k-1| /
!! max(1, |y_i^k|) <= CTOL. After the last correction f is evaluated once
!! more at the accepted point (PE(CE)^k). The second-order starter limits
!! the observed order to three (docs/validation.md).
module adams_moulton
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use ode_system, only: ode_system_t, stepper_t, step_ok, step_rhs_failed, step_not_finite, &
      step_beyond_limit
   implicit none
   private

   public :: am_stepper_t

   type, extends(stepper_t) :: am_stepper_t
      real(wp) :: h = 0.0_wp
      real(wp) :: t0 = 0.0_wp
      real(wp) :: tol = 1.0e-6_wp
      integer :: max_iter = 10
      integer :: n = 0                      !< steps taken
      real(wp), allocatable :: f1(:), f2(:), f3(:)  !< f at the three previous points
      real(wp), allocatable :: known(:), ynew(:), yold(:), fnew(:)
   contains
      procedure :: init => am_init
      procedure :: advance => am_advance
   end type am_stepper_t

contains

   subroutine am_init(this, sys, t0, y0, status)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t0
      real(wp), intent(in) :: y0(:)
      integer, intent(out) :: status
      integer :: n
      n = size(y0)
      if (allocated(this%f)) deallocate (this%f, this%f1, this%f2, this%f3, this%known, &
                                         this%ynew, this%yold, this%fnew)
      allocate (this%f(n), this%f1(n), this%f2(n), this%f3(n), this%known(n), this%ynew(n), &
                this%yold(n), this%fnew(n))
      this%t0 = t0
      this%n = 0
      call sys%rhs(t0, y0, this%f, this%rhs_status)
      this%stats%evaluations = this%stats%evaluations + 1
      status = merge(step_ok, step_rhs_failed, this%rhs_status == 0)
   end subroutine am_init

   subroutine am_advance(this, sys, t, y, t_limit, status)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout) :: y(:)
      real(wp), intent(in) :: t_limit
      integer, intent(out) :: status
      real(wp) :: h, t_new, w_new
      integer :: iter
      logical :: converged

      h = this%h
      t_new = this%t0 + real(this%n + 1, wp)*h
      ! a multistep method cannot shorten a step; the deck check keeps TMAX
      ! and DTPRINT whole multiples of DT, so this only guards the driver
      if (t_new > t_limit + 0.5_wp*h) then
         status = step_beyond_limit
         return
      end if
      status = step_rhs_failed
      associate (f0 => this%f, f1 => this%f1, f2 => this%f2, f3 => this%f3, &
                 known => this%known, ynew => this%ynew, yold => this%yold, fnew => this%fnew)
         if (this%n < 3) then
            ! modified Euler: Euler predictor, trapezoidal corrector
            ynew = y + h*f0
            known = y + 0.5_wp*h*f0
            w_new = 0.5_wp*h
         else
            ! Adams-Bashforth (third differences) predictor
            ynew = y + (h/24.0_wp)*(55.0_wp*f0 - 59.0_wp*f1 + 37.0_wp*f2 - 9.0_wp*f3)
            known = y + (h/24.0_wp)*(19.0_wp*f0 - 5.0_wp*f1 + f2)
            w_new = 9.0_wp*h/24.0_wp
         end if
         converged = .false.
         do iter = 1, this%max_iter
            if (.not. evaluate(t_new, ynew, fnew)) return
            yold = ynew
            ynew = known + w_new*fnew
            this%stats%corrector_iterations = this%stats%corrector_iterations + 1
            if (.not. all(ieee_is_finite(ynew))) then
               status = step_not_finite
               return
            end if
            if (all(abs(ynew - yold) <= this%tol*max(1.0_wp, abs(ynew)))) then
               converged = .true.
               exit
            end if
         end do
         if (.not. converged) this%stats%corrector_at_limit = this%stats%corrector_at_limit + 1
         ! final evaluation at the accepted point
         if (.not. evaluate(t_new, ynew, fnew)) return
         f3 = f2
         f2 = f1
         f1 = f0
         f0 = fnew
         y = ynew
      end associate
      this%n = this%n + 1
      t = t_new
      this%stats%steps = this%stats%steps + 1
      this%stats%h_min = min(this%stats%h_min, h)
      this%stats%h_max = max(this%stats%h_max, h)
      status = step_ok
   contains
      logical function evaluate(te, ye, fe)
         real(wp), intent(in) :: te, ye(:)
         real(wp), intent(out) :: fe(:)
         call sys%rhs(te, ye, fe, this%rhs_status)
         this%stats%evaluations = this%stats%evaluations + 1
         evaluate = this%rhs_status == 0
      end function evaluate
   end subroutine am_advance
end module adams_moulton
