!> (D-B8) A bracketed, safeguarded Newton search for the root of a
!! nondecreasing function, by reverse communication: the shared deflection
!! of the belts and contacts (series_split) runs its searches with it.
!! Taken out of belt_shared_deflection (issue 14, item 34): one job.
module root_search
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   implicit none
   private

   public :: root_search_t, root_begin, root_update, root_running, root_converged, root_failed, root_not_finite
   public :: bisections

   !> States of a root search.
   integer, parameter :: root_running = 0, root_converged = 1, root_failed = 2, root_not_finite = 3

   !> (D-B8) A bracketed, safeguarded Newton search for the root of a
   !! nondecreasing function g on [lo, hi] with g(lo) <= 0 <= g(hi), by
   !! reverse communication: the caller evaluates g and g' at x and calls
   !! root_update until state /= root_running. A Newton step is taken when
   !! it stays inside the bracket and at least halves the step before last
   !! (the rule of rtsafe), otherwise the bracket is bisected, so the search
   !! cannot diverge; it converges when |g| <= g_tol*scale, when the bracket
   !! or the step falls below x_tol. That rule halves the step, not the
   !! bracket: Newton steps that alternate about a kink or a jump of g can use
   !! up max_iter evaluations before the bracket is small (seen from stale
   !! starts in unloading chains). So after max_iter evaluations the search
   !! bisects, at most bisections more times: enough to take any bracket of
   !! doubles below x_tol or to two neighbouring doubles (which is
   !! convergence), so it fails only on values that are not finite. A Newton
   !! step below x_tol is followed by a probe just past the predicted root,
   !! which closes the bracket when the step was right.
   type :: root_search_t
      real(wp) :: lo = 0.0_wp, hi = 0.0_wp
      real(wp) :: x = 0.0_wp
      real(wp) :: step = 0.0_wp, step_old = 0.0_wp
      real(wp) :: x_tol = 0.0_wp, g_tol = 0.0_wp
      real(wp) :: g = 0.0_wp            !< the last value of g
      integer :: iterations = 0, max_iter = 0
      logical :: bisecting = .false.   !< past max_iter: bisections only
      integer :: state = root_running
   end type root_search_t

   !> Bisections after max_iter evaluations (2**-110 of any bracket is far
   !! below every tolerance here, 1e-14 of its scale).
   integer, parameter :: bisections = 110

contains

   !> Begin a search on [lo, hi] from x0 (moved into the bracket).
   pure subroutine root_begin(r, lo, hi, x0, x_tol, g_tol, max_iter)
      type(root_search_t), intent(out) :: r
      real(wp), intent(in) :: lo, hi, x0, x_tol, g_tol
      integer, intent(in) :: max_iter
      r%lo = lo
      r%hi = hi
      if (ieee_is_finite(x0)) then
         r%x = min(max(x0, lo), hi)
      else
         r%x = 0.5_wp*(lo + hi)      ! no start (NaN, infinite): the middle
      end if
      r%step_old = hi - lo
      r%step = hi - lo
      r%x_tol = x_tol
      r%g_tol = g_tol
      r%max_iter = max_iter
      r%iterations = 0
      r%state = root_running
   end subroutine root_begin

   !> The value g and slope dg (>= 0) at r%x; scale: the size of the terms
   !! whose difference g is (for the relative test).
   pure subroutine root_update(r, g, dg, scale)
      type(root_search_t), intent(inout) :: r
      real(wp), intent(in) :: g, dg, scale
      real(wp) :: xn, span
      r%iterations = r%iterations + 1
      r%g = g
      if (.not. (ieee_is_finite(g) .and. ieee_is_finite(dg) .and. ieee_is_finite(r%x))) then
         r%state = root_not_finite
         return
      end if
      if (abs(g) <= r%g_tol*scale) then
         r%state = root_converged
         return
      end if
      if (g < 0.0_wp) then
         r%lo = r%x
      else
         r%hi = r%x
      end if
      if (r%hi - r%lo <= r%x_tol) then
         r%state = root_converged
         return
      end if
      if (r%iterations >= r%max_iter) then
         if (r%bisecting) then
            r%state = root_failed
            return
         end if
         r%bisecting = .true.
         r%max_iter = r%max_iter + bisections
      end if
      xn = r%lo - 1.0_wp      ! (outside: bisect unless Newton gives better)
      if (dg > 0.0_wp .and. dg < huge(1.0_wp) .and. .not. r%bisecting) then   ! (huge: g jumps here)
         ! a step longer than the bracket, which is rejected below, is not computed:
         ! g/dg overflows where dg is subnormal (an unloading curve's toe)
         span = r%hi - r%lo
         if (abs(g) < min(dg, huge(1.0_wp)/max(span, 1.0_wp))*span) xn = r%x - g/dg
      end if
      if (.not. (xn > r%lo .and. xn < r%hi .and. abs(xn - r%x) <= 0.5_wp*abs(r%step_old))) then
         xn = 0.5_wp*(r%lo + r%hi)
      else if (abs(xn - r%x) < 0.5_wp*r%x_tol) then
         ! a Newton step below the tolerance: probe just past the predicted root,
         ! which closes the bracket if the step was right (where the force test
         ! cannot be met, g's rounding exceeding it) and not if the slope was
         ! too large, when the search goes on
         xn = r%x - sign(0.5_wp*r%x_tol, g)
         if (.not. (xn > r%lo .and. xn < r%hi)) xn = 0.5_wp*(r%lo + r%hi)
      end if
      if (.not. (xn > r%lo .and. xn < r%hi)) then
         r%state = root_converged      ! the bracket is two neighbouring doubles
         return
      end if
      r%step_old = r%step
      r%step = xn - r%x
      r%x = xn
   end subroutine root_update
end module root_search
