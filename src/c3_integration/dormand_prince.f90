!> Adaptive embedded Runge-Kutta: Dormand-Prince 5(4) with local
!! extrapolation (the 5th-order solution is kept), first-same-as-last,
!! and a PI step-size controller (Hairer, Norsett & Wanner, Solving ODE I,
!! II.4 and IV.2). An integration option of C.3. restart forgets the
!! first-same-as-last stage and the controller's previous error after a
!! change of the right-hand side.
module dormand_prince
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_numerical
   use strings, only: num
   use ode_system, only: ode_system_t, stepper_t
   implicit none
   private

   public :: dopri_stepper_t, dopri_err_old_initial

   ! Butcher tableau of Dormand & Prince (1980)
   real(wp), parameter :: c2 = 1.0_wp/5, c3 = 3.0_wp/10, c4 = 4.0_wp/5, c5 = 8.0_wp/9
   real(wp), parameter :: a21 = 1.0_wp/5
   real(wp), parameter :: a31 = 3.0_wp/40, a32 = 9.0_wp/40
   real(wp), parameter :: a41 = 44.0_wp/45, a42 = -56.0_wp/15, a43 = 32.0_wp/9
   real(wp), parameter :: a51 = 19372.0_wp/6561, a52 = -25360.0_wp/2187, a53 = 64448.0_wp/6561, &
                          a54 = -212.0_wp/729
   real(wp), parameter :: a61 = 9017.0_wp/3168, a62 = -355.0_wp/33, a63 = 46732.0_wp/5247, &
                          a64 = 49.0_wp/176, a65 = -5103.0_wp/18656
   real(wp), parameter :: a71 = 35.0_wp/384, a73 = 500.0_wp/1113, a74 = 125.0_wp/192, &
                          a75 = -2187.0_wp/6784, a76 = 11.0_wp/84
   ! error weights: 5th-order minus embedded 4th-order weights
   real(wp), parameter :: e1 = 71.0_wp/57600, e3 = -71.0_wp/16695, e4 = 71.0_wp/1920, &
                          e5 = -17253.0_wp/339200, e6 = 22.0_wp/525, e7 = -1.0_wp/40
   ! continuous extension of order 4 (Hairer, Norsett & Wanner, II.6, the
   ! dense output of DOPRI5): y(t0 + theta*h) = c1 + theta*(c2 + (1 -
   ! theta)*(c3 + theta*(c4 + (1 - theta)*c5))), from the step's stages
   real(wp), parameter :: d1 = -12715105075.0_wp/11282082432.0_wp, d3 = 87487479700.0_wp/32700410799.0_wp, &
                          d4 = -10690763975.0_wp/1880347072.0_wp, d5 = 701980252875.0_wp/199316789632.0_wp, &
                          d6 = -1453857185.0_wp/822651844.0_wp, d7 = 69997945.0_wp/29380423.0_wp
   ! step-size control
   real(wp), parameter :: safety = 0.9_wp, fac_min = 0.2_wp, fac_max = 5.0_wp
   real(wp), parameter :: beta = 0.04_wp, alpha = 0.2_wp - 0.75_wp*beta
   integer, parameter :: max_rejections_in_row = 60
   !> The PI controller's "previous error" before any step, and its floor
   !! (Hairer's DOPRI5 uses 1e-4 for both).
   real(wp), parameter :: dopri_err_old_initial = 1.0e-4_wp

   type, extends(stepper_t) :: dopri_stepper_t
      real(wp) :: h = 0.0_wp           !< the next step to try
      real(wp) :: rtol = 1.0e-7_wp, atol = 1.0e-9_wp
      !> an accepted step after which the controller proposes less than this
      !! (s) ends the run as a numerical failure: the run would need more
      !! than about 1e10 steps (a fuzzed hand arc of 1500 in, deep in every
      !! surface, went on at 1e-13 s a step for ever). 0: no such floor.
      real(wp) :: h_least = 0.0_wp
      real(wp) :: err_old = dopri_err_old_initial  !< the PI controller's memory
      real(wp), allocatable :: k2(:), k3(:), k4(:), k5(:), k6(:), k7(:), yt(:), ynew(:), e(:)
      !> the entries of y in the error norm (the system's error_controlled)
      integer, allocatable :: controlled(:)
      !> switches are located on the continuous extension (issue 15); off,
      !! the locator takes the step again to them (tests compare the two)
      logical :: dense_output = .true.
      !> the continuous extension of the last step taken, from t_dense0 over
      !! h_dense (its five coefficient vectors, columns of dense_c)
      real(wp), allocatable :: dense_c(:, :)
      real(wp) :: t_dense0 = 0.0_wp, h_dense = 0.0_wp
      logical :: dense_ready = .false.
      !> trials rejected in a row so far (across advances that offered a
      !! rejected trial to the caller: offers_trials)
      integer :: rejections_in_row = 0
   contains
      procedure :: init => dopri_init
      procedure :: advance => dopri_advance
      procedure :: restart => dopri_restart
      procedure :: retake => dopri_retake
      procedure :: resume => dopri_resume
      procedure :: has_dense => dopri_has_dense
      procedure :: dense => dopri_dense
      procedure :: within_tolerance => dopri_within_tolerance
      procedure :: next_step => dopri_next_step
   end type dopri_stepper_t

contains

   subroutine dopri_init(this, sys, t0, y0, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t0
      real(wp), intent(in), contiguous :: y0(:)
      type(error_t), intent(inout) :: err
      integer :: n, i
      n = size(y0)
      if (allocated(this%f)) deallocate (this%f, this%k2, this%k3, this%k4, this%k5, this%k6, &
                                         this%k7, this%yt, this%ynew, this%e, this%y_failed, this%dense_c)
      allocate (this%f(n), this%k2(n), this%k3(n), this%k4(n), this%k5(n), this%k6(n), this%k7(n), &
                this%yt(n), this%ynew(n), this%e(n), this%y_failed(n), this%dense_c(n, 5))
      this%controlled = pack([(i, i=1, n)], sys%error_controlled(n))
      call dopri_begin(this, sys, t0, y0, err)
   end subroutine dopri_init

   !> See stepper_t: the first-same-as-last stage and the previous error
   !! belong to the old right-hand side. h, the next step to try, is kept:
   !! y is continuous at a restart, and a step too long is rejected.
   subroutine dopri_restart(this, sys, t, y, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      if (.not. this%restartable(y, err)) return
      this%stats%restarts = this%stats%restarts + 1
      call dopri_begin(this, sys, t, y, err)
   end subroutine dopri_restart

   !> See stepper_t: f at (t, y) is the caller's (no evaluation); the
   !! first-same-as-last stage is f, the controller has no past, h (the
   !! next step to try) is kept, as at a restart.
   subroutine dopri_resume(this, sys, t, y, f, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:), f(:)
      type(error_t), intent(inout) :: err
      associate (unused => sys, u2 => t)
      end associate
      if (.not. this%restartable(y, err)) return
      this%f = f
      this%err_old = dopri_err_old_initial
      this%dense_ready = .false.
      this%trial_offered = .false.
      this%rejections_in_row = 0
   end subroutine dopri_resume

   !> See stepper_t: the continuous extension of the last step, unless
   !! switched off (dense_output) or no step was taken since a restart.
   pure logical function dopri_has_dense(this)
      class(dopri_stepper_t), intent(in) :: this
      dopri_has_dense = this%dense_output .and. this%dense_ready
   end function dopri_has_dense

   !> See stepper_t: the controller's proposal for the next step (0 without
   !! the continuous extension, on which a switch predicted is reached).
   pure real(wp) function dopri_next_step(this) result(h)
      class(dopri_stepper_t), intent(in) :: this
      h = merge(this%h, 0.0_wp, this%dense_output)
   end function dopri_next_step

   !> See stepper_t: y at t on the last step's continuous extension (order
   !! 4, Hairer's DOPRI5 dense output; exact at the step's ends).
   pure subroutine dopri_dense(this, t, y)
      class(dopri_stepper_t), intent(in) :: this
      real(wp), intent(in) :: t
      real(wp), intent(out), contiguous :: y(:)
      real(wp) :: th, th1
      th = (t - this%t_dense0)/this%h_dense
      th1 = 1.0_wp - th
      associate (c => this%dense_c)
         y = c(:, 1) + th*(c(:, 2) + th1*(c(:, 3) + th*(c(:, 4) + th1*c(:, 5))))
      end associate
   end subroutine dopri_dense

   !> See stepper_t: the scaled RMS norm of the step's error control
   !! (try_step's, with y at both ends) at most 1.
   pure logical function dopri_within_tolerance(this, y, dy) result(ok)
      class(dopri_stepper_t), intent(in) :: this
      real(wp), intent(in), contiguous :: y(:), dy(:)
      real(wp) :: sc, norm
      integer :: i, j
      norm = 0.0_wp
      do j = 1, size(this%controlled)
         i = this%controlled(j)
         sc = this%atol + this%rtol*abs(y(i))
         if (.not. abs(dy(i)) <= sc) then
            ok = .false.
            return
         end if
         norm = norm + (dy(i)/sc)**2
      end do
      ok = norm <= real(max(size(this%controlled), 1), wp)
   end function dopri_within_tolerance

   !> See stepper_t: the step to t_to at once (its part of a step the
   !! controller accepted), not the controller's next step size.
   subroutine dopri_retake(this, sys, t, y, t_to, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_to
      type(error_t), intent(inout) :: err
      this%h = max(this%h, t_to - t)
      call this%advance(sys, t, y, t_to, err)
   end subroutine dopri_retake

   !> Start (or start again) from (t, y): the first stage f(t, y) and a
   !! controller with no past.
   subroutine dopri_begin(this, sys, t, y, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      type(error_t), intent(inout) :: err
      this%err_old = dopri_err_old_initial
      this%dense_ready = .false.
      this%trial_offered = .false.
      this%rejections_in_row = 0
      ! (evaluate_end: a restart at a located switch, the locator's, comes
      ! before that state's accept, which may take what is kept here)
      if (.not. this%evaluate_end(sys, t, y, this%f)) call this%give_up_rhs(sys, err)
   end subroutine dopri_begin

   !> Try steps until one is accepted (or the step collapses). A trial
   !! whose evaluation fails is an outcome answered here, by a shorter
   !! step. With offers_trials (and the continuous extension on), a trial
   !! rejected for its error is given to the caller instead (t and y
   !! unchanged, trial_offered, its extension ready): the next advance
   !! goes on with the shorter step. Only when the step falls below its floor (or too many trials in
   !! a row were rejected) does err say why: the last trial's evaluation
   !! failed (the system's reason), or its error stayed too large.
   subroutine dopri_advance(this, sys, t, y, t_limit, err)
      class(dopri_stepper_t), intent(inout) :: this
      class(ode_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t
      real(wp), intent(inout), contiguous :: y(:)
      real(wp), intent(in) :: t_limit
      type(error_t), intent(inout) :: err
      real(wp) :: h, err_norm, fac, h_floor
      logical :: clipped, stages_ok
      integer :: rejections

      rejections = this%rejections_in_row
      this%trial_offered = .false.
      h_floor = 16.0_wp*epsilon(1.0_wp)*max(abs(t), 1.0e-3_wp)
      do
         h = this%h
         clipped = t + h >= t_limit
         if (clipped) h = t_limit - t
         call try_step(h, stages_ok, err_norm)
         if (stages_ok .and. err_norm <= 1.0_wp) exit
         ! rejected: shrink, without growth until a step is accepted
         this%stats%rejected = this%stats%rejected + 1
         rejections = rejections + 1
         if (stages_ok) then
            fac = max(fac_min, safety*err_norm**(-0.2_wp))
         else
            fac = 0.25_wp    ! the trial state could not be evaluated: back off hard
         end if
         this%h = h*fac
         if (this%h < h_floor .or. rejections > max_rejections_in_row) then
            if (stages_ok) then
               call error_set(err, exit_numerical, 'the step size fell below its floor (the problem is too stiff ' &
                              //'or discontinuous for the tolerances)')
            else
               call this%give_up_rhs(sys, err)
            end if
            this%rejections_in_row = 0
            return
         end if
         if (this%offers_trials .and. this%dense_output .and. stages_ok &
             .and. err_norm < huge(1.0_wp)) then
            ! the caller sees whether the trial crossed a switch (issue 15)
            call set_dense(h)
            this%trial_offered = .true.
            this%t_trial = merge(t_limit, t + h, clipped)
            this%rejections_in_row = rejections
            return
         end if
      end do
      this%rejections_in_row = 0

      ! accepted: PI controller for the next step
      err_norm = max(err_norm, 1.0e-10_wp)
      fac = safety*err_norm**(-alpha)*this%err_old**beta
      fac = min(fac_max, max(fac_min, fac))
      if (rejections > 0) fac = min(fac, 1.0_wp)
      this%err_old = max(err_norm, dopri_err_old_initial)
      ! the step's continuous extension (before y and f become the step's end)
      call set_dense(h)
      if (clipped) then
         ! a step shortened to meet t_limit does not shrink the next one
         this%h = max(this%h, h*fac)
         t = t_limit
      else
         this%h = h*fac
         t = t + h
      end if
      y = this%ynew
      this%f = this%k7
      this%stats%steps = this%stats%steps + 1
      this%stats%h_min = min(this%stats%h_min, h)
      this%stats%h_max = max(this%stats%h_max, h)
      if (.not. clipped .and. this%h < this%h_least) &
         call error_set(err, exit_numerical, 'the step size fell below its floor of '//num(this%h_least) &
                        //' s (1e-10 of the run: the problem is too stiff for Dormand-Prince at these tolerances)')
   contains
      !> The continuous extension of the trial step of size h from (t, y).
      subroutine set_dense(h)
         real(wp), intent(in) :: h
         associate (c => this%dense_c)
            c(:, 1) = y
            c(:, 2) = this%ynew - y
            c(:, 3) = h*this%f - c(:, 2)
            c(:, 4) = c(:, 2) - h*this%k7 - c(:, 3)
            c(:, 5) = h*(d1*this%f + d3*this%k3 + d4*this%k4 + d5*this%k5 + d6*this%k6 + d7*this%k7)
         end associate
         this%t_dense0 = t
         this%h_dense = h
         this%dense_ready = .true.
      end subroutine set_dense

      !> The seven stages and the scaled error norm of one trial step.
      subroutine try_step(h, ok, err_norm)
         real(wp), intent(in) :: h
         logical, intent(out) :: ok
         real(wp), intent(out) :: err_norm
         real(wp) :: sc
         integer :: i, j
         err_norm = huge(1.0_wp)
         associate (k1 => this%f, k2 => this%k2, k3 => this%k3, k4 => this%k4, k5 => this%k5, &
                    k6 => this%k6, k7 => this%k7, yt => this%yt, ynew => this%ynew, e => this%e)
            ok = .false.
            yt = y + h*a21*k1
            if (.not. this%evaluate(sys, t + c2*h, yt, k2)) return
            yt = y + h*(a31*k1 + a32*k2)
            if (.not. this%evaluate(sys, t + c3*h, yt, k3)) return
            yt = y + h*(a41*k1 + a42*k2 + a43*k3)
            if (.not. this%evaluate(sys, t + c4*h, yt, k4)) return
            yt = y + h*(a51*k1 + a52*k2 + a53*k3 + a54*k4)
            if (.not. this%evaluate(sys, t + c5*h, yt, k5)) return
            yt = y + h*(a61*k1 + a62*k2 + a63*k3 + a64*k4 + a65*k5)
            if (.not. this%evaluate(sys, t + h, yt, k6)) return
            ynew = y + h*(a71*k1 + a73*k3 + a74*k4 + a75*k5 + a76*k6)
            ! a state that is not finite is a step far too long: rejected
            ! (err_norm stays huge), not a failure of the right-hand side
            ok = .true.
            if (.not. all(ieee_is_finite(ynew))) return
            ok = .false.
            ! (first-same-as-last: f at the step's end, where it is accepted
            ! if it is; evaluate_end, whose results the system may keep)
            if (.not. this%evaluate_end(sys, t + h, ynew, k7)) return
            ok = .true.
            e = h*(e1*k1 + e3*k3 + e4*k4 + e5*k5 + e6*k6 + e7*k7)
            ! the scaled RMS norm over the error-controlled entries, without
            ! overflow whatever the tolerances:
            ! a component beyond 1e150 of its scale rejects the step at once
            err_norm = 0.0_wp
            do j = 1, size(this%controlled)
               i = this%controlled(j)
               sc = this%atol + this%rtol*max(abs(y(i)), abs(ynew(i)))
               if (.not. abs(e(i)) <= 1.0e150_wp*sc) then
                  err_norm = huge(1.0_wp)
                  return
               end if
               err_norm = err_norm + (e(i)/sc)**2
            end do
            err_norm = sqrt(err_norm/real(max(size(this%controlled), 1), wp))
         end associate
      end subroutine try_step

   end subroutine dopri_advance
end module dormand_prince
