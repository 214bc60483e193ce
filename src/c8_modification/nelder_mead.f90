!> A bounded Nelder-Mead minimiser in reverse communication, for C.8's
!! optimisation (report section C.8: the program evaluates its own results,
!! changes input data and initiates a new run): the caller asks for a point,
!! evaluates it (a whole simulation) and tells the objective, so that it may
!! run the evaluations as it likes and resume a search by replaying a log of
!! its tells.
!!
!!    call opt%init(x0, low, high, tol, max_evals, err)
!!    do
!!       call opt%ask(x, done)
!!       if (done) exit
!!       call opt%tell(objective(x))
!!    end do
!!    call opt%best(x, f)
!!
!! The method works in the unit box u = (x - low)/(high - low). The initial
!! simplex is x0 and, for each axis i, x0 moved by 0.1 along u(i) (by -0.1
!! where +0.1 would leave the box). Each iteration orders the vertices by f
!! (equal values keep their order, a new vertex after its equals: Lagarias,
!! Reeds, Wright and Wright, SIAM J. Optim. 9 (1998) 112-147) and tries,
!! about the centroid c of all but the worst vertex w, the standard moves of
!! Nelder and Mead (Computer Journal 7 (1965) 308-313): reflection
!! r = c + (c - w); if f(r) is below the best, expansion c + 2(c - w) (kept
!! if better than r); if f(r) is at or above the second worst, contraction,
!! outside c + 0.5(r - c) when f(r) is below the worst (kept if not above
!! f(r)), inside c + 0.5(w - c) otherwise (kept if below the worst); when a
!! contraction fails, the simplex shrinks halfway towards its best vertex.
!! Every trial point is projected onto the box (each coordinate clipped to
!! [0, 1]), so every asked point lies within [low, high] (low and high
!! exactly at the faces), and a minimum outside the box is approached on
!! its boundary.
!!
!! Convergence, tested when an iteration starts: the spread of f over the
!! simplex (worst - best) is within tol*(|f_best| + tol), AND the simplex's
!! diameter in the unit box (the largest max-norm distance between two
!! vertices) is below tol. A minimum so claimed is confirmed by a restart:
!! a new initial simplex about the best point (its value reused, not asked
!! again), searched to convergence again; the search has converged when a
!! restart's best value is within tol*(|f_best| + tol) of the value at the
!! claim before it (so at least one restart; a simplex that collapsed
!! against failed runs, or degenerated on a face, gets a fresh shape). The
!! search ends when it converges, or when max_evals values have been told
!! (then ask says done even mid-iteration).
!!
!! A failed or infeasible run may be told as huge(1.0_wp); NaN and +Inf are
!! taken as huge(1.0_wp), -Inf as -huge(1.0_wp). Only comparisons and
!! differences of values of one sign are made of f, so no value breaks the
!! method: a huge vertex is the worst and is moved away first. When every
!! value told is huge (a start whose whole initial simplex fails), the
!! simplex shrinks onto the start and the search ends there, not converged.
!!
!! Deterministic: the same tells give the same asks, bit for bit. Asking
!! again before telling gives the same point; a tell with no point asked,
!! or after the end, is ignored.
module nelder_mead
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use strings, only: itoa, num
   use kinds, only: wp
   use error_handling, only: error_t, error_append, error_set, exit_deck
   implicit none
   private

   public :: nm_t

   !> What the pending point is for.
   integer, parameter :: stage_initial = 1, stage_reflect = 2, stage_expand = 3, &
                         stage_outside = 4, stage_inside = 5, stage_shrink = 6, stage_done = 7
   !> The standard coefficients: reflection, expansion, contraction, shrink.
   real(wp), parameter :: rho = 1.0_wp, chi = 2.0_wp, gamma = 0.5_wp, sigma = 0.5_wp
   !> The initial simplex's step along each axis, a fraction of the range.
   real(wp), parameter :: initial_step = 0.1_wp
   !> Inputs beyond this magnitude are refused.
   real(wp), parameter :: value_limit = 1.0e300_wp

   type :: nm_t
      private
      integer :: n = 0
      real(wp), allocatable :: low(:), high(:)
      real(wp) :: tol = 0.0_wp
      integer :: max_evals = 0
      integer :: n_evals = 0
      real(wp), allocatable :: v(:, :)       !< the simplex's vertices (unit box), sorted by fv from each iteration's start
      real(wp), allocatable :: fv(:)
      real(wp), allocatable :: centroid(:)   !< of all vertices but the worst
      real(wp), allocatable :: xr(:)         !< the reflected point and its value, while expanding or contracting
      real(wp) :: fr = 0.0_wp
      real(wp), allocatable :: trial(:)      !< the pending point (unit box)
      integer :: stage = stage_done
      integer :: vertex = 0                  !< the vertex being evaluated (initial simplex, shrink)
      logical :: pending = .false.           !< a point has been asked and not told
      logical :: is_converged = .false.
      real(wp), allocatable :: best_u(:)
      real(wp) :: best_f = huge(1.0_wp)
      real(wp) :: f_claimed = huge(1.0_wp)   !< the best value at the last claimed convergence
   contains
      procedure :: init => nm_init
      procedure :: ask => nm_ask
      procedure :: tell => nm_tell
      procedure :: best => nm_best
      procedure :: converged => nm_converged
      procedure :: evaluations => nm_evaluations
   end type nm_t

contains

   !> Start a search from x0 within [low, high] (low < high on every axis),
   !! converging to tol (0 < tol < 1) or stopping after max_evals (>= 1)
   !! values. On bad input err says why (exit_deck) and the search is done
   !! at once.
   subroutine nm_init(this, x0, low, high, tol, max_evals, err)
      class(nm_t), intent(inout) :: this
      real(wp), intent(in) :: x0(:), low(:), high(:)
      real(wp), intent(in) :: tol
      integer, intent(in) :: max_evals
      type(error_t), intent(inout) :: err
      type(error_t) :: problems
      integer :: n, i

      n = size(x0)
      this%n = n
      this%n_evals = 0
      this%stage = stage_done
      this%pending = .false.
      this%is_converged = .false.
      this%best_f = huge(1.0_wp)
      this%fr = 0.0_wp
      this%vertex = 0
      this%tol = tol
      this%max_evals = max_evals
      if (n < 1) call error_append(problems, exit_deck, 'the optimisation needs at least one variable')
      if (size(low) /= n .or. size(high) /= n) then
         call error_append(problems, exit_deck, 'the optimisation''s start and bounds differ in size')
      else if (.not. (all(usable(x0)) .and. all(usable(low)) .and. all(usable(high)))) then
         call error_append(problems, exit_deck, 'the optimisation''s start and bounds must be numbers within +-1e300')
      else
         do i = 1, n
            if (.not. low(i) < high(i)) then
               call error_append(problems, exit_deck, 'optimisation variable '//itoa(i) &
                                 //': its low bound is not below its high')
            else if (x0(i) < low(i) .or. x0(i) > high(i)) then
               call error_append(problems, exit_deck, 'optimisation variable '//itoa(i) &
                                 //': its start is outside its bounds')
            end if
         end do
      end if
      if (.not. (tol > 0.0_wp .and. tol < 1.0_wp)) &
         call error_append(problems, exit_deck, 'the optimisation''s tolerance must lie between 0 and 1')
      if (max_evals < 1) call error_append(problems, exit_deck, 'the optimisation needs a budget of at least 1 run')
      if (problems%failed()) then
         call error_set(err, problems%code, problems%message)
         this%n = 0
         return
      end if

      this%low = low
      this%high = high
      if (allocated(this%v)) deallocate (this%v, this%fv, this%centroid, this%xr, this%trial)
      allocate (this%v(n, n + 1), this%fv(n + 1), this%centroid(n), this%xr(n), this%trial(n))
      this%centroid = 0.0_wp
      this%xr = 0.0_wp
      this%best_u = project((x0 - low)/(high - low))
      this%f_claimed = huge(1.0_wp)
      call start_simplex(this, this%best_u)
   end subroutine nm_init

   !> The initial simplex about u0 (unit box), to be evaluated from u0.
   subroutine start_simplex(this, u0)
      type(nm_t), intent(inout) :: this
      real(wp), intent(in) :: u0(:)
      integer :: i
      this%v(:, 1) = u0
      do i = 1, this%n
         this%v(:, i + 1) = u0
         if (u0(i) + initial_step <= 1.0_wp) then
            this%v(i, i + 1) = u0(i) + initial_step
         else
            this%v(i, i + 1) = u0(i) - initial_step
         end if
      end do
      this%fv = huge(1.0_wp)
      this%stage = stage_initial
      this%vertex = 1
      this%trial = this%v(:, 1)
   end subroutine start_simplex

   !> The next point to evaluate, or done (converged, budget spent or never
   !! started); when done, x is the best point told.
   subroutine nm_ask(this, x, done)
      class(nm_t), intent(inout) :: this
      real(wp), intent(out) :: x(:)
      logical, intent(out) :: done
      done = this%stage == stage_done .or. this%n_evals >= this%max_evals
      if (done) then
         this%stage = stage_done
         this%pending = .false.
         if (this%n > 0) then
            x = to_box(this, this%best_u)
         else
            x = 0.0_wp
         end if
         return
      end if
      x = to_box(this, this%trial)
      this%pending = .true.
   end subroutine nm_ask

   !> The objective at the point last asked; the search moves on.
   subroutine nm_tell(this, f)
      class(nm_t), intent(inout) :: this
      real(wp), intent(in) :: f
      real(wp) :: value
      integer :: n

      if (.not. this%pending .or. this%stage == stage_done) return
      this%pending = .false.
      n = this%n
      value = f
      if (ieee_is_nan(value)) then
         value = huge(1.0_wp)
      else
         value = min(max(value, -huge(1.0_wp)), huge(1.0_wp))
      end if
      this%n_evals = this%n_evals + 1
      if (value < this%best_f) then
         this%best_f = value
         this%best_u = this%trial
      end if

      select case (this%stage)
      case (stage_initial, stage_shrink)
         this%fv(this%vertex) = value
         this%vertex = this%vertex + 1
         if (this%vertex <= n + 1) then
            this%trial = this%v(:, this%vertex)
         else
            call start_iteration(this)
         end if
      case (stage_reflect)
         this%xr = this%trial
         this%fr = value
         if (value < this%fv(1)) then
            this%trial = project(this%centroid + chi*(this%centroid - this%v(:, n + 1)))
            this%stage = stage_expand
         else if (value < this%fv(n)) then
            call replace_worst(this, .false., value)
         else if (value < this%fv(n + 1)) then
            this%trial = project(this%centroid + gamma*(this%xr - this%centroid))
            this%stage = stage_outside
         else
            this%trial = project(this%centroid + gamma*(this%v(:, n + 1) - this%centroid))
            this%stage = stage_inside
         end if
      case (stage_expand)
         if (value < this%fr) then
            call replace_worst(this, .true., value)
         else
            call replace_worst(this, .false., this%fr)
         end if
      case (stage_outside)
         if (value <= this%fr) then
            call replace_worst(this, .true., value)
         else
            call start_shrink(this)
         end if
      case (stage_inside)
         if (value < this%fv(n + 1)) then
            call replace_worst(this, .true., value)
         else
            call start_shrink(this)
         end if
      end select
      if (this%n_evals >= this%max_evals) this%stage = stage_done
   end subroutine nm_tell

   !> The best point told and its value (x0 and huge before any tell).
   subroutine nm_best(this, x, f)
      class(nm_t), intent(in) :: this
      real(wp), intent(out) :: x(:)
      real(wp), intent(out) :: f
      if (this%n > 0) then
         x = to_box(this, this%best_u)
      else
         x = 0.0_wp
      end if
      f = this%best_f
   end subroutine nm_best

   pure logical function nm_converged(this)
      class(nm_t), intent(in) :: this
      nm_converged = this%is_converged
   end function nm_converged

   !> The number of values told.
   pure integer function nm_evaluations(this)
      class(nm_t), intent(in) :: this
      nm_evaluations = this%n_evals
   end function nm_evaluations

   !> The worst vertex replaced by an accepted point, the trial or the
   !! reflection (named, not passed: a component of this as an argument
   !! beside this would alias what start_iteration changes); the next
   !! iteration.
   subroutine replace_worst(this, trial, f)
      type(nm_t), intent(inout) :: this
      logical, intent(in) :: trial
      real(wp), intent(in) :: f
      if (trial) then
         this%v(:, this%n + 1) = this%trial
      else
         this%v(:, this%n + 1) = this%xr
      end if
      this%fv(this%n + 1) = f
      call start_iteration(this)
   end subroutine replace_worst

   !> Every vertex but the best moved halfway towards it, then evaluated.
   subroutine start_shrink(this)
      type(nm_t), intent(inout) :: this
      integer :: i
      do i = 2, this%n + 1
         this%v(:, i) = this%v(:, 1) + sigma*(this%v(:, i) - this%v(:, 1))
      end do
      this%stage = stage_shrink
      this%vertex = 2
      this%trial = this%v(:, 2)
   end subroutine start_shrink

   !> Order the simplex, test convergence, and ask for the reflection.
   subroutine start_iteration(this)
      type(nm_t), intent(inout) :: this
      real(wp) :: key, u(this%n)
      integer :: i, k, n

      n = this%n
      do i = 2, n + 1   ! stable insertion sort: a vertex stays after its equals
         key = this%fv(i)
         u = this%v(:, i)
         k = i - 1
         do while (k >= 1)
            if (.not. this%fv(k) > key) exit
            this%fv(k + 1) = this%fv(k)
            this%v(:, k + 1) = this%v(:, k)
            k = k - 1
         end do
         this%fv(k + 1) = key
         this%v(:, k + 1) = u
      end do
      if (small_spread(this%fv(1), this%fv(n + 1), this%tol) .and. diameter(this%v) < this%tol) then
         ! a claimed minimum is confirmed by a restart that gains no more
         ! than the tolerance (a simplex may collapse against failed runs)
         if (.not. this%best_f < huge(1.0_wp)) then
            this%stage = stage_done   ! every run failed: nothing to go on
         else if (small_spread(this%best_f, this%f_claimed, this%tol)) then
            this%is_converged = .true.
            this%stage = stage_done
         else
            this%f_claimed = this%best_f
            call start_simplex(this, this%best_u)
            this%fv(1) = this%best_f
            this%vertex = 2
            this%trial = this%v(:, 2)
         end if
         return
      end if
      this%centroid = sum(this%v(:, 1:n), dim=2)/real(n, wp)
      this%trial = project(this%centroid + rho*(this%centroid - this%v(:, n + 1)))
      this%stage = stage_reflect
   end subroutine start_iteration

   !> worst - best <= tol*(|best| + tol), without overflow: best <= worst,
   !! both within +-huge, tol in (0, 1).
   pure logical function small_spread(best, worst, tol)
      real(wp), intent(in) :: best, worst, tol
      real(wp) :: allowed
      allowed = tol*(abs(best) + tol)
      if (best < 0.0_wp .and. worst > 0.0_wp) then
         small_spread = worst <= allowed + best   ! worst - best could overflow
      else
         small_spread = worst - best <= allowed
      end if
   end function small_spread

   !> The largest max-norm distance between two vertices.
   pure real(wp) function diameter(v)
      real(wp), intent(in) :: v(:, :)
      integer :: i, k
      diameter = 0.0_wp
      do i = 1, size(v, 2) - 1
         do k = i + 1, size(v, 2)
            diameter = max(diameter, maxval(abs(v(:, k) - v(:, i))))
         end do
      end do
   end function diameter

   !> A point of the unit box's space projected onto the box.
   pure function project(u) result(p)
      real(wp), intent(in) :: u(:)
      real(wp) :: p(size(u))
      p = min(max(u, 0.0_wp), 1.0_wp)
   end function project

   !> A unit-box point in the caller's units: the faces exactly at low and
   !! high, every value within them.
   pure function to_box(this, u) result(x)
      type(nm_t), intent(in) :: this
      real(wp), intent(in) :: u(:)
      real(wp) :: x(size(u))
      integer :: i
      do i = 1, size(u)
         if (u(i) <= 0.0_wp) then
            x(i) = this%low(i)
         else if (u(i) >= 1.0_wp) then
            x(i) = this%high(i)
         else
            x(i) = min(max(this%low(i) + u(i)*(this%high(i) - this%low(i)), this%low(i)), this%high(i))
         end if
      end do
   end function to_box

   elemental logical function usable(x)
      real(wp), intent(in) :: x
      usable = .false.
      if (.not. ieee_is_nan(x)) usable = abs(x) <= value_limit
   end function usable

end module nelder_mead
