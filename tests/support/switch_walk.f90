!> Issue 15's check of an effect's switching functions: a walk along a
!! path of states s in [s0, s1] (a path_t the test extends: the effect's
!! forces f and switching functions g at s, and optionally its accept at s)
!! that finds where the forces jump or change their slope and where a g
!! changes sign, and whether the two coincide.
!!
!! The walk samples n + 1 points. In an interval where some g changes sign
!! it brackets the change by bisection to far below the interval and asks
!! whether the forces jump or kink there (one-sided slopes at +-eps, eps =
!! 1e-4 of the interval); in every other interval it asks whether they do
!! anywhere inside (the slopes at its two ends differ by more than
!! slope_tol + slope_rel times the larger of them, or the increment is not
!! the trapezoid of the end slopes to jump_tol + h times their difference):
!! a stray switch. So a kink or jump found only where a g
!! changes sign, and one found at every such place, is what the tests
!! assert (n_stray = 0, n_switched = n_roots). The tolerances must exceed
!! the smooth variation of the slope over an interval (|f''| h).
!!
!! With accepting, the walk accepts every sample as a run accepts its
!! steps (the memory changes there): g at a sample is compared, as the
!! driver compares it, with g at the sample before after its accept; a
!! memory change (accept's restart) in an interval where no g changed sign
!! counts as stray (n_stray_memory); one that makes the forces jump (by
!! more than jump_tol) is counted in n_memory_jumps.
module switch_walk
   use kinds, only: wp
   implicit none
   private

   public :: path_t, walk_t, walk_path

   !> A path of states through an effect's switches.
   type, abstract :: path_t
      integer :: nf = 0    !< forces (components) compared
      integer :: ng = 0    !< the effect's switching functions
   contains
      procedure(path_at), deferred :: at
      procedure :: accept_at => path_accept_at
   end type path_t

   abstract interface
      !> The forces f(1:nf) and switching functions g(1:ng) at the point s,
      !! with the memory the effect holds.
      subroutine path_at(this, s, f, g)
         import :: path_t, wp
         class(path_t), intent(inout) :: this
         real(wp), intent(in) :: s
         real(wp), intent(out) :: f(:), g(:)
      end subroutine path_at
   end interface

   type :: walk_t
      integer :: n_roots = 0          !< intervals in which a switching function changed sign
      integer :: n_switched = 0       !< of those, where the forces jump or kink at the change
      integer :: n_stray = 0          !< intervals without a change in which the forces jump or kink
      integer :: n_memory = 0         !< accepts that changed the memory (accepting)
      integer :: n_stray_memory = 0   !< of those, in an interval without a change of sign
      integer :: n_memory_jumps = 0   !< of those, where the forces jump
      real(wp), allocatable :: roots(:)          !< where the changes of sign are
      logical, allocatable :: switched(:)        !< whether the forces jump or kink at each
      real(wp) :: first_stray = huge(1.0_wp)     !< the first stray interval's start (in the walk's direction)
   end type walk_t

contains

   !> By default a path has no memory to accept.
   subroutine path_accept_at(this, s, changed)
      class(path_t), intent(inout) :: this
      real(wp), intent(in) :: s
      logical, intent(out) :: changed
      associate (u1 => this%nf, u2 => s)
      end associate
      changed = .false.
   end subroutine path_accept_at

   !> Walk path from s0 to s1 in n intervals (see the module's note).
   function walk_path(path, s0, s1, n, slope_tol, jump_tol, accepting, slope_rel) result(w)
      class(path_t), intent(inout) :: path
      real(wp), intent(in) :: s0, s1, slope_tol, jump_tol
      integer, intent(in) :: n
      logical, intent(in), optional :: accepting
      real(wp), intent(in), optional :: slope_rel
      type(walk_t) :: w
      real(wp) :: h, eps, s, a, b, mid, sr, rel
      real(wp), dimension(path%nf) :: f0, f1, fr0, fl1, fm2, fm1, fp1, fp2, sl, sr_slope, f_before
      real(wp), dimension(path%ng) :: g0, g1, gm, gdum
      logical :: acc, changed, root
      integer :: k, it
      acc = .false.
      if (present(accepting)) acc = accepting
      rel = 0.0_wp
      if (present(slope_rel)) rel = slope_rel
      allocate (w%roots(0), w%switched(0))
      h = (s1 - s0)/real(n, wp)
      eps = 1.0e-4_wp*h
      if (acc) call path%accept_at(s0, changed)
      call path%at(s0, f0, g0)
      call path%at(s0 + eps, fr0, gdum)
      do k = 1, n
         s = s0 + h*real(k, wp)
         ! g at the new point with the memory held since the last one
         call path%at(s, f1, g1)
         call path%at(s - eps, fl1, gdum)
         root = any((g0 > 0.0_wp) .neqv. (g1 > 0.0_wp))
         if (root) then
            w%n_roots = w%n_roots + 1
            a = s - h
            b = s
            do it = 1, 80
               mid = 0.5_wp*(a + b)
               if (.not. ((mid - a)*(b - mid) > 0.0_wp)) exit     ! (a walk may go down: s1 < s0)
               call path%at(mid, fm1, gm)
               if (any((g0 > 0.0_wp) .neqv. (gm > 0.0_wp))) then
                  b = mid
               else
                  a = mid
               end if
            end do
            sr = 0.5_wp*(a + b)
            w%roots = [w%roots, sr]
            call path%at(sr - 2.0_wp*eps, fm2, gdum)
            call path%at(sr - eps, fm1, gdum)
            call path%at(sr + eps, fp1, gdum)
            call path%at(sr + 2.0_wp*eps, fp2, gdum)
            sl = (fm1 - fm2)/eps
            sr_slope = (fp2 - fp1)/eps
            w%switched = [w%switched, any(abs(sr_slope - sl) > slope_tol + rel*max(abs(sl), abs(sr_slope))) .or. &
                                      any(abs(fp1 - fm1 - eps*(sl + sr_slope)) > jump_tol)]
            if (w%switched(size(w%switched))) w%n_switched = w%n_switched + 1
         else if (any(abs((f1 - fl1)/eps - (fr0 - f0)/eps) > slope_tol + rel*max(abs((f1 - fl1)/eps), &
                                                                                 abs((fr0 - f0)/eps))) .or. &
                  any(abs(f1 - f0 - 0.5_wp*h*((fr0 - f0)/eps + (f1 - fl1)/eps)) > &
                      jump_tol + abs(h)*abs((f1 - fl1)/eps - (fr0 - f0)/eps))) then
            ! (a smooth f misses the trapezoid of its end slopes by less than
            ! h times their difference)
            w%n_stray = w%n_stray + 1
            if (w%n_stray == 1) w%first_stray = s - h
         end if
         if (acc) then
            f_before = f1
            call path%accept_at(s, changed)
            call path%at(s, f1, g1)       ! (with the memory accepted here)
            if (changed) then
               w%n_memory = w%n_memory + 1
               if (.not. root) w%n_stray_memory = w%n_stray_memory + 1
               if (any(abs(f1 - f_before) > jump_tol)) w%n_memory_jumps = w%n_memory_jumps + 1
            end if
         end if
         f0 = f1
         g0 = g1
         call path%at(s + eps, fr0, gdum)
      end do
   end function walk_path
end module switch_walk
