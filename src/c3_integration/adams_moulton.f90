!> The report's integrator (C.3): "a four point Adams-Moulton method
!! started with a modified Euler method ... The Euler method is used to
!! obtain the first three points after the given initial point. Thereafter
!! four points are used in the Adams third difference prediction and
!! correction equations. At each computation of a new point, the iteration
!! continues until successive approximations are within a given tolerance
!! or the iteration has been tried a prescribed number of times."
!!
!! Read as (docs/errata.md, D-6): predictor = Adams-Bashforth with third
!! differences (am_predictor), corrector = Adams-Moulton with third
!! differences (am_corrector), iterated; the starter is modified Euler
!! (Euler predictor, trapezoidal corrector) iterated the same way. "Within
!! a tolerance": max_i |y_i^k - y_i^k-1| / max(1, |y_i^k|) <= CTOL. After
!! the last correction f is evaluated once more at the accepted point
!! (P(EC)^kE).
!!
!! The second-order starter leaves an O(h^3) error that the fourth-order
!! formulas carry to the end: the report's method converges with order 3.
!! Option start = am_start_rk4 takes the three start steps by classic RK4
!! instead, and the method converges with order 4 (docs/validation.md).
!! restart begins a new start phase after a change of the right-hand side.
!! A step of the start phase may be shorter than h (to a located switch,
!! or back to the grid after one): the start phase then begins again
!! there, on a grid from that point.
module adams_moulton
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_numerical
   use strings, only: num, itoa
   use ode_system, only: ode_system_t, stepper_t
   implicit none
   private

   public :: am_stepper_t, am_start_euler, am_start_rk4
   public :: am_predictor, am_corrector

   !> How the first three points after the initial (or restart) point are
   !! found.
   integer, parameter :: am_start_euler = 1 !< modified Euler, as C.3 says (order 3 overall)
   integer, parameter :: am_start_rk4 = 2   !< classic RK4 (order 4 overall)

   !> Number of back points the formulas need beyond the current one.
   integer, parameter :: start_steps = 3

   type, extends(stepper_t) :: am_stepper_t
      real(wp) :: h = 0.0_wp
      real(wp) :: t0 = 0.0_wp               !< start of the grid: t = t0 + n*h
      real(wp) :: tol = 1.0e-6_wp           !< corrector tolerance (CTOL)
      integer :: max_iter = 10              !< corrector passes at most (CITER)
      integer :: start = am_start_euler     !< am_start_euler or am_start_rk4
      integer :: n = 0                      !< steps since init or restart
      real(wp), allocatable :: f1(:), f2(:), f3(:)  !< f at the three previous points
      real(wp), allocatable :: ynew(:), yold(:), fnew(:), ytmp(:)
   contains
      procedure :: init => am_init
      procedure :: advance => am_advance
      procedure :: restart => am_restart
   end type am_stepper_t

contains

   !> C.3 predictor, Adams-Bashforth with third differences (exact when f is
   !! a cubic in t): y_n+1 = y_n + h/24 (55 f_n - 59 f_n-1 + 37 f_n-2 - 9 f_n-3).
   elemental real(wp) function am_predictor(h, y, f0, f1, f2, f3) result(y_new)
      real(wp), intent(in) :: h   !< step
      real(wp), intent(in) :: y   !< y_n
      real(wp), intent(in) :: f0, f1, f2, f3  !< f_n, f_n-1, f_n-2, f_n-3
      y_new = y + (h/24.0_wp)*(55.0_wp*f0 - 59.0_wp*f1 + 37.0_wp*f2 - 9.0_wp*f3)
   end function am_predictor

   !> C.3 corrector, Adams-Moulton with third differences (exact when f is
   !! a cubic in t): y_n+1 = y_n + h/24 (9 f_n+1 + 19 f_n - 5 f_n-1 + f_n-2).
   elemental real(wp) function am_corrector(h, y, f_new, f0, f1, f2) result(y_new)
      real(wp), intent(in) :: h   !< step
      real(wp), intent(in) :: y   !< y_n
      real(wp), intent(in) :: f_new        !< f_n+1 at the latest estimate of y_n+1
      real(wp), intent(in) :: f0, f1, f2   !< f_n, f_n-1, f_n-2
      y_new = y + (h/24.0_wp)*(9.0_wp*f_new + 19.0_wp*f0 - 5.0_wp*f1 + f2)
   end function am_corrector

   subroutine am_init(this, sys, t0, y0, err)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t0
      real(wp), intent(in), contiguous :: y0(:)
      type(error_t), intent(inout) :: err
      integer :: n
      n = size(y0)
      if (allocated(this%f)) deallocate (this%f, this%f1, this%f2, this%f3, this%ynew, &
                                         this%yold, this%fnew, this%ytmp, this%y_failed, this%local_error)
      allocate (this%f(n), this%f1(n), this%f2(n), this%f3(n), this%ynew(n), this%yold(n), &
                this%fnew(n), this%ytmp(n), this%y_failed(n), this%local_error(n))
      this%local_error = 0.0_wp
      this%multistep = .true.
      call am_begin(this, sys, t0, y0, err)
   end subroutine am_init

   !> See stepper_t: the back values f1..f3 and f at the accepted point were
   !! computed with the old right-hand side, so the method starts again
   !! from (t, y) with its starter, on a new grid t0 = t.
   subroutine am_restart(this, sys, t, y, err)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      if (.not. this%restartable(y, err)) return
      this%stats%restarts = this%stats%restarts + 1
      call am_begin(this, sys, t, y, err)
   end subroutine am_restart

   !> Start (or start again) from (t, y): n = 0 puts the next three steps
   !! in the start phase, which refills f1..f3 before they are read.
   subroutine am_begin(this, sys, t, y, err)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      this%t0 = t
      this%n = 0
      if (.not. (this%start == am_start_euler .or. this%start == am_start_rk4)) then
         call error_set(err, exit_numerical, 'an integrator setting is invalid: the Adams-Moulton start is ' &
                        //itoa(this%start)//', neither modified Euler ('//itoa(am_start_euler)//') nor RK4 (' &
                        //itoa(am_start_rk4)//')')
         return
      end if
      if (.not. this%evaluate(sys, t, y, this%f)) call this%give_up_rhs(sys, err)
   end subroutine am_begin

   subroutine am_advance(this, sys, t, y, t_limit, err)
      class(am_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_limit
      type(error_t), intent(inout) :: err
      real(wp) :: h, t_new
      logical :: starting, short, back_value
      integer :: i

      h = this%h
      t_new = this%t0 + real(this%n + 1, wp)*h
      starting = this%n < start_steps
      ! a start step is a one-step method's, which may end anywhere: a step
      ! to a located switch, or back to the grid after one (issue 15); a new
      ! grid starts there
      short = starting .and. t_limit < t_new - 1.0e-6_wp*h
      ! a start step whose estimate may use the back value f1, a step of h
      ! before (docs/accuracy.md)
      back_value = starting .and. this%n > 0 .and. .not. short
      if (short) then
         h = t_limit - t
         t_new = t_limit
      else if (t_new > t_limit + 0.5_wp*h) then
         ! a multistep step cannot be shortened; the deck check keeps TMAX
         ! and DTPRINT whole multiples of DT, so this only guards the driver
         call error_set(err, exit_numerical, 'a fixed step would pass the requested end time (the step to t = ' &
                        //num(t_new)//' s, the end at t = '//num(t_limit)//' s)')
         return
      end if
      associate (f0 => this%f, f1 => this%f1, f2 => this%f2, f3 => this%f3, &
                 ynew => this%ynew, yold => this%yold, fnew => this%fnew, yt => this%ytmp, le => this%local_error)
         if (starting .and. this%start == am_start_rk4) then
            ! start option (C.3: "different schemes could be chosen according
            ! to the option"): classic RK4, fourth order so the start no longer
            ! limits the method; accumulated stage by stage into ynew (k1 = f0,
            ! k2..k4 in turn in fnew, their arguments in yt): no extra arrays
            ynew = y + (h/6.0_wp)*f0
            yt = y + 0.5_wp*h*f0
            if (.not. evaluate(t + 0.5_wp*h, yt, fnew)) return
            ynew = ynew + (h/3.0_wp)*fnew
            yt = y + 0.5_wp*h*fnew
            if (.not. evaluate(t + 0.5_wp*h, yt, fnew)) return
            ynew = ynew + (h/3.0_wp)*fnew
            yt = y + h*fnew
            if (.not. evaluate(t_new, yt, fnew)) return
            ynew = ynew + (h/6.0_wp)*fnew
            ! the embedded third-order estimate, as RK4's own (runge_kutta4),
            ! completed with the final evaluation below
            le = (h/6.0_wp)*fnew
            if (.not. all(ieee_is_finite(ynew))) then
               call this%give_up_not_finite(err)
               return
            end if
         else
            if (starting) then
               ynew = y + h*f0                    ! C.3 modified Euler: Euler predictor
            else
               ynew = am_predictor(h, y, f0, f1, f2, f3)   ! C.3 predictor
               le = ynew
            end if
            if (.not. correct()) return
            ! local error estimates (docs/accuracy.md)
            if (.not. starting) then
               ! Milne's device: the predictor's and corrector's errors are
               ! 251/720 and -19/720 h^5 y(5), so the corrector's is
               ! -19/270 of their difference
               do i = 1, size(le)   ! (element by element: no temporary for le on both sides)
                  le(i) = (-19.0_wp/270.0_wp)*(ynew(i) - le(i))
               end do
            else if (back_value) then
               ! a start step with a back value at h: the trapezoidal
               ! corrector (-1/12 h^3 y''') against Adams-Bashforth's second
               ! order (5/12 h^3 y'''), Milne's device again
               le = (-1.0_wp/6.0_wp)*(ynew - (y + (0.5_wp*h)*(3.0_wp*f0 - f1)))
            else
               ! the first start step (or a shorter one) has no back value at
               ! its own step: the trapezoid's
               ! fixed point y_c against its first iterate y_1 (Heun's
               ! method): y_c - y_1 = h/2 J (y_c - y_Euler) = h^3/4 J y'',
               ! which is h^3/4 y''' where f is linear in y, so the
               ! trapezoid's -h^3/12 y''' is -1/3 of it
               do i = 1, size(le)
                  le(i) = (-1.0_wp/3.0_wp)*(ynew(i) - le(i))
               end do
            end if
         end if
         ! final evaluation at the accepted point (evaluate_end: what the
         ! system keeps there serves the accepted step's bookkeeping)
         if (.not. this%evaluate_end(sys, t_new, ynew, fnew)) then
            call this%give_up_rhs(sys, err)
            return
         end if
         if (starting .and. this%start == am_start_rk4) then
            do i = 1, size(le)
               le(i) = le(i) - (h/6.0_wp)*fnew(i)
            end do
         end if
         this%local_error_new = .true.
         f3 = f2
         f2 = f1
         f1 = f0
         f0 = fnew
         y = ynew
      end associate
      this%n = this%n + 1
      if (short) then
         this%t0 = t_new
         this%n = 0
      end if
      t = t_new
      this%stats%steps = this%stats%steps + 1
      this%stats%h_min = min(this%stats%h_min, h)
      this%stats%h_max = max(this%stats%h_max, h)
   contains
      !> C.3: iterate the corrector until successive approximations agree
      !! within tol or max_iter passes were made; sets err on failure.
      logical function correct() result(ok)
         integer :: iter
         logical :: converged
         ok = .false.
         converged = .false.
         associate (f0 => this%f, f1 => this%f1, f2 => this%f2, ynew => this%ynew, &
                    yold => this%yold, fnew => this%fnew)
            do iter = 1, this%max_iter
               if (.not. evaluate(t_new, ynew, fnew)) return
               yold = ynew
               if (starting) then
                  ynew = y + (0.5_wp*h)*(f0 + fnew)  ! C.3 modified Euler: trapezoidal corrector
               else
                  ynew = am_corrector(h, y, fnew, f0, f1, f2)   ! C.3 corrector
               end if
               this%stats%corrector_iterations = this%stats%corrector_iterations + 1
               ! a start step without a back value keeps its first iterate for
               ! its estimate
               if (iter == 1 .and. starting .and. .not. back_value) this%local_error = ynew
               if (.not. all(ieee_is_finite(ynew))) then
                  call this%give_up_not_finite(err)
                  return
               end if
               if (all(abs(ynew - yold) <= this%tol*max(1.0_wp, abs(ynew)))) then
                  converged = .true.
                  exit
               end if
            end do
         end associate
         this%stats%corrector_solves = this%stats%corrector_solves + 1
         if (.not. converged) this%stats%corrector_at_limit = this%stats%corrector_at_limit + 1
         ok = .true.
      end function correct

      !> f(te, ye); a failure ends the step (a multistep method cannot
      !! shorten it): err says why.
      logical function evaluate(te, ye, fe)
         real(wp), intent(in) :: te
         real(wp), intent(in), contiguous :: ye(:)
         real(wp), intent(out), contiguous :: fe(:)
         evaluate = this%evaluate(sys, te, ye, fe)
         if (.not. evaluate) call this%give_up_rhs(sys, err)
      end function evaluate
   end subroutine am_advance
end module adams_moulton
