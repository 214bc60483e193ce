!> The deformation split of a chain of rate-independent elements in series
!! (figure 19 for the belts, figures 23-25 for the contacts; docs/belts.md
!! 3): given the chain's total deformation s, the deformations x_i >= 0 of
!! its elements, sum x_i = s, at which every element's branch of figure 18
!! carries one force F. Some elements may be held where the caller says
!! (fixed: a rate-dependent element whose deformation is a state of the
!! chain, series_chain), a padding bottoms out at its cap, the steering
!! column is held by its gate (D-C19), a plastic element that has turned
!! is held at its maximum (D-B10): their graphs have vertical pieces, where
!! they are rigid.
!!
!! Solvers: one free element needs none; two plain ones a bracketed search
!! on x_1; otherwise Newton's method on (x, F) at once (D-B11) and, where it
!! gives up, the bracketed search by force (D-B8). Everything is pure: the
!! memories are read, never written. Taken out of belt_shared_deflection
!! (issue 14, item 34: one job per module).
module series_split
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use recurrent_loading, only: recurrent_law_t, loading_memory_t
   use loading_branch, only: branch_point_t, branch_eval, held_plastic, zero_extent, min_slope, rigid_slope
   use root_search, only: root_search_t, root_begin, root_update, root_running, root_not_finite, root_failed
   implicit none
   private

   public :: max_chain, deformation_split_t, split_deformation
   public :: split_ok, split_no_convergence, split_not_finite
   public :: path_none, path_pair, path_newton, path_search, max_sweeps
   public :: region_slack, region_unloaded, region_loaded
   public :: force_tol, defl_tol, element_eval

   !> Elements of one chain at most: three webbing sections and three body surfaces.
   integer, parameter :: max_chain = 6

   !> Outcome of a split.
   integer, parameter :: split_ok = 0, split_no_convergence = 1, split_not_finite = 2
   !> Which solver gave a split: none (slack, unloaded, one free element),
   !! the pair's search on x_1, Newton's method on (x, F) (D-B11), or the
   !! search by force (where Newton's gave up).
   integer, parameter :: path_none = 0, path_pair = 1, path_newton = 2, path_search = 3
   !> (D-B11) Sweeps of Newton's method on (x, F) before the search by force
   !! takes over: where it converges it mostly ends in 2-3 (quadratically, or
   !! at once on linear pieces), at times in up to 8 (from a start on a
   !! convex unloading toe), and sweeps that go on are mostly a kink crossed
   !! back and forth, which the search's bracket settles.
   integer, parameter :: max_sweeps = 12
   !> Where the chain is: slack (s <= 0), taken up but carrying no force
   !! (within the elements' residual deformations), loaded.
   integer, parameter :: region_slack = 0, region_unloaded = 1, region_loaded = 2

   !> The relative tolerances of the splits: a force balance to 1e-12 of the
   !! force, a deformation to 1e-14 of the chain's (a few ulps).
   real(wp), parameter :: force_tol = 1.0e-12_wp, defl_tol = 1.0e-14_wp

   !> A split at one deformation. The arrays are defined for the chain's n
   !! elements only (no default initialization: it would cost as much as a
   !! split at every evaluation).
   type :: deformation_split_t
      integer :: status = split_ok
      integer :: region = region_slack
      integer :: iterations = 0              !< evaluations of the elements' branches
      integer :: path = path_none            !< the solver that gave it
      integer :: sweeps = 0                  !< sweeps of Newton's method on (x, F) (0: not tried)
      real(wp) :: force = 0.0_wp             !< F, the force every free element carries
      real(wp) :: guess = 0.0_wp             !< the unknown of the search: x of the first free element (a pair) or F
      real(wp) :: x(max_chain)               !< element deformations
      real(wp) :: slope(max_chain)           !< dF/dx of each at its x (rigid_slope: held; 0: flat)
      logical :: loading(max_chain)          !< on a loading branch
   end type deformation_split_t

contains

   !> The split of n elements (laws and memories) at total deformation s.
   !! max_iter bounds the evaluations of each search; a search that does not
   !! converge gives status split_no_convergence, one that meets a value that
   !! is not finite split_not_finite. guess: a start for the unknown (sp%guess
   !! of a nearby state); the result does not depend on it beyond the
   !! tolerance, only the number of iterations does. cap (> 0): an element
   !! that bottoms out there (figure 25). gate (> 0): the steering column's
   !! gate (D-C19): held at its memory's x_hold while its force lies from its
   !! branch's force there F_h to F_h + gate, carrying gate plus its branch
   !! beyond, its branch alone below (where it springs back, the gate free);
   !! a gate <= 0 is none. cap_slope (> 0, with a cap): the cap is not rigid
   !! but the element, crushed solid, stiffens to that slope beyond it
   !! (element_eval; series_chain's chains with a rate-dependent element).
   !! fixed, x_fixed: elements held at x_fixed whatever the force (x_fixed
   !! read only there). search: the search by force alone, without Newton's
   !! method first (the tests' reference).
   !! (Issue 16 section 4: every array is explicit-shape, the chain's own
   !! arrays passed as they lie - no descriptor built, nothing copied at a
   !! call, which the optional assumed-shape arrays before cost some 150
   !! instructions a split; only the scalars are optional.)
   pure subroutine split_deformation(n, law, mem, s, max_iter, cap, gate, cap_slope, fixed, x_fixed, sp, guess, &
                                     search)
      integer, intent(in) :: n
      type(recurrent_law_t), intent(in) :: law(n)
      type(loading_memory_t), intent(in) :: mem(n)
      real(wp), intent(in) :: s
      integer, intent(in) :: max_iter
      real(wp), intent(in) :: cap(n), gate(n), cap_slope(n), x_fixed(n)
      logical, intent(in) :: fixed(n)
      type(deformation_split_t), intent(out) :: sp
      real(wp), intent(in), optional :: guess
      logical, intent(in), optional :: search
      real(wp) :: z(max_chain), zfree, sfree, held_sum
      logical :: plain, by_force
      integer :: i, nfree, i1, i2
      type(branch_point_t) :: bp
      integer :: seg

      sp%iterations = 0
      sp%sweeps = 0
      sp%path = path_none
      sp%status = split_ok
      sp%force = 0.0_wp
      sp%x = 0.0_wp
      sp%slope = 0.0_wp
      sp%loading = .false.
      if (.not. ieee_is_finite(s)) then
         sp%status = split_not_finite
         return
      end if
      ! the part of s the free elements share; the first and last free ones
      held_sum = 0.0_wp
      nfree = 0
      i1 = 0
      i2 = 0
      do i = 1, n
         if (fixed(i)) then
            sp%x(i) = x_fixed(i)
            sp%slope(i) = rigid_slope
            held_sum = held_sum + x_fixed(i)
         else
            nfree = nfree + 1
            if (i1 == 0) i1 = i
            i2 = i
         end if
      end do
      sfree = s - held_sum
      sp%region = region_slack
      if (.not. sfree > 0.0_wp .or. nfree < 1) then
         sp%guess = 0.0_wp
         return
      end if
      ! (the residual deformations only past the slack, which most splits are)
      zfree = 0.0_wp
      plain = .true.
      do i = 1, n
         if (fixed(i)) then
            z(i) = x_fixed(i)
         else
            z(i) = zero_extent(law(i), mem(i))
            zfree = zfree + z(i)
            plain = plain .and. .not. (cap(i) > 0.0_wp .or. gate(i) > 0.0_wp)
         end if
      end do
      if (sfree <= zfree) then
         ! taken up within the residual deformations: no force; the free
         ! deformation is shared in proportion to them (continuous with the
         ! loaded split)
         sp%region = region_unloaded
         do i = 1, n
            if (.not. fixed(i)) sp%x(i) = sfree*z(i)/zfree
         end do
         sp%guess = sp%x(i1)
         return
      end if

      sp%region = region_loaded
      by_force = .false.
      if (present(search)) by_force = search
      if (nfree == 1) then
         ! one free element: its deformation is what the others leave
         i = i1
         sp%x(i) = sfree
         seg = 0
         if (cap(i) > 0.0_wp .and. .not. cap_slope(i) > 0.0_wp) sp%x(i) = min(sfree, cap(i))
         call element_eval(law(i), mem(i), sp%x(i), cap(i), cap_slope(i), seg, bp)
         sp%force = bp%force
         sp%slope(i) = bp%slope
         sp%loading(i) = bp%loading
         if (gate(i) > 0.0_wp .and. sp%x(i) > max(mem(i)%x_hold, z(i))) sp%force = sp%force + gate(i)
         if (cap(i) > 0.0_wp .and. .not. cap_slope(i) > 0.0_wp .and. sfree >= cap(i)) sp%slope(i) = rigid_slope
         sp%iterations = 1
         sp%guess = sp%x(i)
      else if (nfree == 2 .and. plain .and. .not. by_force) then
         call pair_split(n, law, mem, i1, i2, sfree, z, max_iter, sp, guess)
      else
         call split_by_force(n, law, mem, s, z, cap, gate, cap_slope, fixed, max_iter, by_force, sp, guess)
      end if
      if (sp%status /= split_ok) then
         do i = 1, n
            sp%x(i) = 0.0_wp
            if (fixed(i)) sp%x(i) = x_fixed(i)
         end do
         sp%force = 0.0_wp
      end if
   end subroutine split_deformation

   !> Two free elements i1, i2 sharing s: x_i1 = e in [z_i1, s - z_i2] where
   !! g(e) = F_i1(e) - F_i2(s - e) = 0, g' = k_1 + k_2 >= 0 (g(z_1) < 0 <
   !! g(s - z_2)). First point: the secant through the bracket's ends (exact
   !! for linear branches), or the guess.
   pure subroutine pair_split(n, law, mem, i1, i2, s, z, max_iter, sp, guess)
      integer, intent(in) :: n
      type(recurrent_law_t), intent(in) :: law(n)
      type(loading_memory_t), intent(in) :: mem(n)
      integer, intent(in) :: i1, i2
      real(wp), intent(in) :: s, z(n)
      integer, intent(in) :: max_iter
      type(deformation_split_t), intent(inout) :: sp
      real(wp), intent(in), optional :: guess
      type(root_search_t) :: r
      type(branch_point_t) :: b1, b2, bj
      real(wp) :: lo, hi, f2_lo, f1_hi, x0, xi1, xi2, xp1, xp2
      integer :: seg1, seg2, seg, i, j, q
      integer :: ix(2)
      ix = [i1, i2]
      seg1 = 0
      seg2 = 0
      sp%iterations = 0
      sp%path = path_pair
      ! (D-B10) a plastic element held at delta_max while the other carries no
      ! more than its f_max: the other takes the whole change
      do q = 1, 2
         i = ix(q)
         j = ix(3 - q)
         if (.not. held_plastic(law(i), mem(i))) cycle
         seg = 0
         call branch_eval(law(j), mem(j), s - mem(i)%delta_max, seg, bj)
         sp%iterations = sp%iterations + 1
         if (bj%force <= mem(i)%f_max) then
            sp%x(i) = mem(i)%delta_max
            sp%x(j) = s - mem(i)%delta_max
            sp%force = bj%force
            sp%slope(i) = rigid_slope
            sp%loading(i) = .false.
            sp%slope(j) = bj%slope
            sp%loading(j) = bj%loading
            sp%guess = sp%x(i1)
            return
         end if
      end do
      ! else the bracket: g(z_1) < 0 < g(s - z_2), an element held above reloading
      lo = z(i1)
      hi = s - z(i2)
      if (present(guess)) then
         ! a start from a nearby state: the bracket's signs are known, no need
         ! to evaluate its ends
         x0 = guess
      else
         call branch_eval(law(i2), mem(i2), s - lo, seg2, b2)
         call branch_eval(law(i1), mem(i1), hi, seg1, b1)
         f2_lo = b2%force
         f1_hi = b1%force
         x0 = 0.5_wp*(lo + hi)
         if (f2_lo + f1_hi > 0.0_wp) x0 = lo + (hi - lo)*f2_lo/(f2_lo + f1_hi)
         sp%iterations = 2
      end if
      call root_begin(r, lo, hi, x0, defl_tol*s, force_tol, max_iter)
      ! the memo of xi**p (branch_eval) where a start is given, the belts' chains,
      ! whose evaluations after the first are a Newton step from it
      xi1 = merge(0.0_wp, -1.0_wp, present(guess))
      xi2 = xi1
      xp1 = 0.0_wp
      xp2 = 0.0_wp
      do
         if (xi1 >= 0.0_wp) then
            call branch_eval(law(i1), mem(i1), r%x, seg1, b1, xi1, xp1)
            call branch_eval(law(i2), mem(i2), s - r%x, seg2, b2, xi2, xp2)
         else
            call branch_eval(law(i1), mem(i1), r%x, seg1, b1)
            call branch_eval(law(i2), mem(i2), s - r%x, seg2, b2)
         end if
         call root_update(r, b1%force - b2%force, b1%slope + b2%slope, max(b1%force, b2%force))
         if (r%state /= root_running) exit
      end do
      sp%iterations = sp%iterations + r%iterations
      if (r%state == root_not_finite) then
         sp%status = split_not_finite
         return
      end if
      if (r%state == root_failed) sp%status = split_no_convergence
      sp%x(i1) = r%x
      sp%x(i2) = s - r%x
      ! (the branches are continuous - the one jump, a plastic law's drop, is
      ! handled above - so the bracket closes on a root of g)
      sp%force = 0.5_wp*(b1%force + b2%force)
      sp%slope(i1) = b1%slope
      sp%slope(i2) = b2%slope
      sp%loading(i1) = b1%loading
      sp%loading(i2) = b2%loading
      sp%guess = sp%x(i1)
   end subroutine pair_split

   !> Three or more free elements, or any with a cap or a gate: first
   !! Newton's method on (x, F) at once (newton_split, D-B11), and where it
   !! gives up the search by force: the common force F in (0, F_hi] with h(F)
   !! = sum x_i(F) - s = 0, x_i(F) the element's deformation at force F (an
   !! inner search on its range, started on the tangent at the element's last
   !! point), h' = sum 1/k_i, from where Newton's method ended. Where the
   !! bracket closes on a flat branch or a jump, the deformations are
   !! interpolated between its ends so that they add up. search: the search
   !! alone (the tests' reference).
   pure subroutine split_by_force(n, law, mem, s, z, cap, gate, cap_slope, fixed, max_iter, search, sp, guess)
      integer, intent(in) :: n
      type(recurrent_law_t), intent(in) :: law(n)
      type(loading_memory_t), intent(in) :: mem(n)
      real(wp), intent(in) :: s, z(n), cap(n), gate(n), cap_slope(n)
      logical, intent(in) :: fixed(n)
      integer, intent(in) :: max_iter
      logical, intent(in) :: search      !< the search by force alone, no Newton's method first
      type(deformation_split_t), intent(inout) :: sp
      real(wp), intent(in), optional :: guess
      type(root_search_t) :: r
      real(wp) :: x_max(max_chain), secant(max_chain), f_max(max_chain), f_hi, f0, h, dh, x(max_chain)
      real(wp) :: x_lo(max_chain), x_hi(max_chain), h_lo, h_hi, theta
      real(wp) :: f_cap(max_chain)           ! a capped element's force at its cap (huge: no cap)
      real(wp) :: x_h(max_chain), f_h(max_chain)   ! a gated element's hold and its branch's force there
      integer :: i, status, seg(max_chain)
      type(branch_point_t) :: bp
      logical :: done, newton_free(max_chain), have_lo, have_hi
      logical :: plastic_held(max_chain)     ! held_plastic of each element (its memory is read-only here)
      real(wp) :: f_newton, zsum
      ! each element's last point (x_at, f_at) on its branch and its slope k_at
      ! there (f_at < 0: none yet): where its next search at another force starts
      real(wp) :: x_at(max_chain), f_at(max_chain), k_at(max_chain)

      ! (whole arrays of max_chain: stores in line, not a call of memset each;
      ! the elements beyond n are never read)
      seg = 0
      f_cap = huge(1.0_wp)
      x_h = 0.0_wp
      f_h = 0.0_wp
      x = 0.0_wp
      zsum = sum(z(1:n))
      do i = 1, n
         plastic_held(i) = held_plastic(law(i), mem(i))
         x_max(i) = s - zsum + z(i)
         if (fixed(i)) then
            x_max(i) = z(i)
            f_max(i) = 0.0_wp
            secant(i) = huge(1.0_wp)
            cycle
         end if
         if (cap(i) > 0.0_wp .and. cap(i) < x_max(i) .and. .not. cap_slope(i) > 0.0_wp) then
            x_max(i) = cap(i)               ! it cannot deform beyond its cap (figure 25)
            call branch_eval(law(i), mem(i), cap(i), seg(i), bp)
            f_cap(i) = bp%force
         end if
         if (gate(i) > 0.0_wp) then
            x_h(i) = min(max(mem(i)%x_hold, z(i)), x_max(i))
            call branch_eval(law(i), mem(i), x_h(i), seg(i), bp)
            f_h(i) = bp%force
         end if
         call element_eval(law(i), mem(i), x_max(i), cap(i), cap_slope(i), seg(i), bp)
         f_max(i) = bp%force + gate_above(i, x_max(i))
         if (x_max(i) > z(i)) then
            secant(i) = f_max(i)/(x_max(i) - z(i))
         else
            secant(i) = huge(1.0_wp)           ! a cap at or below its residual deformation: rigid
         end if
      end do
      sp%iterations = sp%iterations + n
      f_hi = maxval(f_max(1:n), mask=.not. fixed(1:n))
      ! first point: the secants in series
      f0 = (s - zsum)/sum(1.0_wp/max(secant(1:n), min_slope))
      if (present(guess)) f0 = guess
      ! (D-B11) first Newton's method on the deformations and the force at once;
      ! where it does not converge in a few sweeps, or meets what it cannot
      ! handle, the search by force below decides, from where it ended
      f_at = -1.0_wp
      x_at = 0.0_wp
      k_at = 0.0_wp
      if (.not. search) then
         call newton_split(f0, x, seg, f_newton, sp%slope, newton_free, sp%loading, sp%iterations, sp%sweeps, &
                           x_at, f_at, k_at, done)
         if (done) then
            sp%force = f_newton
            sp%path = path_newton
            sp%x = x
            do i = 1, n
               if (newton_free(i)) cycle
               sp%slope(i) = rigid_slope        ! fixed, held (D-B10), at its cap, or behind its gate
               sp%loading(i) = .false.
            end do
            sp%guess = sp%force
            return
         end if
         ! the search starts where Newton's method ended, and each element where it was evaluated last
         if (f_newton > 0.0_wp .and. f_newton <= f_hi) f0 = f_newton
      end if
      sp%path = path_search
      call root_begin(r, 0.0_wp, f_hi, f0, defl_tol*f_hi, defl_tol, max_iter)
      have_lo = .false.
      have_hi = .false.
      do
         call deformations_at(r%x, x, h, dh, status, sp%iterations, seg, x_at, f_at, k_at)
         if (status /= split_ok) then
            sp%status = status
            return
         end if
         ! the deformations at the bracket's ends as the search found them (root_update's
         ! rule: h < 0 moves lo): on a flat piece, within the force tolerance of its
         ! force, an element's x_i(F) is wherever its inner search began, so the ends
         ! are kept rather than evaluated again
         if (h < 0.0_wp) then
            x_lo(1:n) = x(1:n)
            h_lo = h
            have_lo = .true.
         else
            x_hi(1:n) = x(1:n)
            h_hi = h
            have_hi = .true.
         end if
         call root_update(r, h, dh, s)
         if (r%state /= root_running) exit
      end do
      if (r%state == root_not_finite) then
         sp%status = split_not_finite
         return
      end if
      if (r%state == root_failed) sp%status = split_no_convergence
      sp%force = r%x
      if (abs(h) > defl_tol*s .and. sp%status == split_ok) then
         ! a flat branch or a jump: interpolate between the bracket's ends (an end
         ! the search never evaluated, 0 or F_hi, evaluated now)
         status = split_ok
         if (.not. have_lo) call deformations_at(r%lo, x_lo, h_lo, dh, status, sp%iterations, seg, x_at, f_at, k_at)
         if (.not. have_hi .and. status == split_ok) &
            call deformations_at(r%hi, x_hi, h_hi, dh, status, sp%iterations, seg, x_at, f_at, k_at)
         if (status /= split_ok) then
            sp%status = status
            return
         end if
         theta = 0.0_wp
         if (h_hi - h_lo > 0.0_wp) theta = min(1.0_wp, max(0.0_wp, -h_lo/(h_hi - h_lo)))
         x(1:n) = x_lo(1:n) + theta*(x_hi(1:n) - x_lo(1:n))
         sp%force = r%lo + theta*(r%hi - r%lo)
      end if
      sp%x = x
      do i = 1, n
         if (held(i, sp%force)) then
            sp%slope(i) = rigid_slope        ! fixed, held (D-B10), bottomed out, or held by its gate
            sp%loading(i) = .false.
         else
            call element_eval(law(i), mem(i), x(i), cap(i), cap_slope(i), seg(i), bp)
            sp%slope(i) = bp%slope
            sp%loading(i) = bp%loading
         end if
      end do
      sp%guess = sp%force
   contains
      !> The gate element i adds to its branch at deformation xi: all of it
      !! beyond its hold x_h, none below (D-C19, the column springing back).
      pure real(wp) function gate_above(i, xi) result(add)
         integer, intent(in) :: i
         real(wp), intent(in) :: xi
         add = 0.0_wp
         if (gate(i) > 0.0_wp .and. xi >= x_h(i)) add = gate(i)
      end function gate_above

      !> Whether element i is rigid at the chain's force f (held_at).
      pure logical function held(i, f)
         integer, intent(in) :: i
         real(wp), intent(in) :: f
         real(wp) :: x_held
         logical :: free_i
         call held_at(i, f, free_i, x_held)
         held = .not. free_i
      end function held

      !> (D-B11) Newton's method on (x_1 .. x_n, F) at once. The elements
      !! that are rigid at the force F are held (fixed; a plastic element
      !! below f_max, D-B10; a padding at its cap, figure 25; a column within
      !! its gate, D-C19); each free element's tangent at x_i, F_i + k_i dx_i
      !! = F_new, and sum x_i = s give F_new = (s - sum held x - sum (x_i -
      !! F_i/k_i)) / sum (1/k_i) and the new x_i: one evaluation of each free
      !! element per sweep, exact on linear pieces of tabulated curves,
      !! quadratic on smooth branches. An element on a flat piece of its curve
      !! (slope 0, force > 0: the column crushing at its plateau) sets F_new to
      !! its force and takes the deformation the others leave. It converges
      !! when every free element carries F to the force tolerance and the
      !! deformations add up to s to the deformation tolerance. It gives up
      !! (done = .false.) on what the search's bracket settles better: a jump
      !! (a huge slope), two flat elements, an element at the origin of its
      !! curve or pushed out of its range, a force <= 0, a value that is not
      !! finite, or no convergence within max_sweeps sweeps.
      pure subroutine newton_split(f_start, xs, hint, f, kb, free, on_loading, evaluations, sweeps, x_at, f_at, k_at, &
                                   done)
         real(wp), intent(in) :: f_start
         real(wp), intent(inout) :: xs(:)         !< the deformations (set for the n elements)
         integer, intent(inout) :: hint(:)        !< each element's table interval
         real(wp), intent(out) :: f               !< the force
         real(wp), intent(inout) :: kb(:)         !< the free elements' slopes
         logical, intent(out) :: free(:)          !< not held at f
         logical, intent(inout) :: on_loading(:)  !< the free elements' branches
         integer, intent(inout) :: evaluations    !< of the elements' branches
         integer, intent(out) :: sweeps
         !> each element's last evaluated point and slope (for the search, should it follow)
         real(wp), intent(inout) :: x_at(:), f_at(:), k_at(:)
         logical, intent(out) :: done
         type(branch_point_t) :: b
         real(wp) :: f_new, fb(max_chain), compliance, rest, xsum, x_held, x_new
         logical :: balanced, was_free, pinned_out
         integer :: k, k_flat, k_pinned
         done = .false.
         sweeps = 0
         ! the start: the force given (a nearby state's), else the secants in series
         f = f_start
         if (.not. (f > 0.0_wp .and. f <= f_hi)) f = (s - zsum)/sum(1.0_wp/max(secant(1:n), min_slope))
         if (.not. (f > 0.0_wp .and. f <= f_hi)) return
         do k = 1, n
            call held_at(k, f, free(k), xs(k))
            if (free(k)) xs(k) = on_secant(k, f)
         end do
         k_pinned = 0
         do sweeps = 1, max_sweeps
            compliance = 0.0_wp
            rest = s
            xsum = 0.0_wp
            balanced = .true.
            pinned_out = .false.
            k_flat = 0
            do k = 1, n
               xsum = xsum + xs(k)
               if (.not. free(k)) then
                  rest = rest - xs(k)
                  cycle
               end if
               if (k == k_pinned .and. .not. (xs(k) >= z(k) .and. xs(k) <= x_max(k))) then
                  ! a flat element the others' steps pushed out of its range: it
                  ! keeps the force it set until they settle
                  if (k_flat /= 0) return           ! (a second flat element)
                  fb(k) = f
                  kb(k) = 0.0_wp
                  pinned_out = .true.
                  k_flat = k
                  cycle
               end if
               if (.not. (xs(k) >= z(k) .and. xs(k) <= x_max(k))) return    ! out of its range
               call element_eval(law(k), mem(k), xs(k), cap(k), cap_slope(k), hint(k), b)
               evaluations = evaluations + 1
               fb(k) = b%force + gate_above(k, xs(k))
               kb(k) = b%slope
               on_loading(k) = b%loading
               x_at(k) = xs(k)
               f_at(k) = fb(k)
               k_at(k) = kb(k)
               ! (to the inner searches' tolerance, or to the outer one's on the force,
               ! 1e-14 of F_hi: near an unloading toe forces of 1e-20 lb cannot be
               ! resolved to 1e-12 of themselves)
               balanced = balanced .and. abs(fb(k) - f) <= max(force_tol*f, defl_tol*f_hi)
               if (kb(k) > min_slope .and. kb(k) < rigid_slope) then
                  compliance = compliance + 1.0_wp/kb(k)
                  rest = rest - (xs(k) - fb(k)/kb(k))
               else if (.not. kb(k) > min_slope .and. b%force > 0.0_wp .and. k_flat == 0) then
                  k_flat = k           ! on a flat piece
               else
                  return               ! a jump, a second flat element, or at its curve's origin
               end if
            end do
            if (pinned_out) then
               ! the others carry its force, and it is still out of its range: not on its flat piece
               if (balanced) return
            else if (balanced .and. abs(xsum - s) <= defl_tol*s) then
               done = .true.
               return
            end if
            k_pinned = k_flat
            if (k_flat > 0) then
               f_new = fb(k_flat)      ! the flat element sets the force ...
            else
               if (.not. (compliance > 0.0_wp)) return             ! every element held
               f_new = rest/compliance
            end if
            if (.not. (f_new > 0.0_wp .and. f_new < huge(1.0_wp))) return
            do k = 1, n
               if (.not. free(k) .or. k == k_flat) cycle
               ! (a step past the top of its range is cut back to the top, one below
               ! its zero-force extent to halfway there; the next step comes back)
               x_new = xs(k) + (f_new - fb(k))/kb(k)
               if (x_new <= z(k)) x_new = 0.5_wp*(xs(k) + z(k))
               xs(k) = min(x_new, x_max(k))
            end do
            if (k_flat > 0) xs(k_flat) = s - (sum(xs(1:n)) - xs(k_flat))   ! ... and takes what the others leave
            f = f_new
            ! the elements held at the new force; one taken up starts on its secant
            do k = 1, n
               was_free = free(k)
               call held_at(k, f, free(k), x_held)
               if (.not. free(k)) then
                  xs(k) = x_held
               else if (.not. was_free) then
                  xs(k) = on_secant(k, f)
               end if
            end do
         end do
         sweeps = max_sweeps
      end subroutine newton_split

      !> Element k's deformation at force f on a secant of its range: from (z_k,
      !! 0) to (x_max_k, f_max_k); a gated element's, on the side of its hold
      !! the force puts it (Newton's start: a curve's origin has no slope to go
      !! by, the secant has).
      pure real(wp) function on_secant(k, f) result(x_k)
         integer, intent(in) :: k
         real(wp), intent(in) :: f
         real(wp) :: x0, f0, x1, f1
         x0 = z(k)
         f0 = 0.0_wp
         x1 = x_max(k)
         f1 = f_max(k)
         if (gate(k) > 0.0_wp) then
            if (f > f_h(k)) then
               x0 = x_h(k)
               f0 = f_h(k) + gate(k)
            else
               x1 = x_h(k)
               f1 = f_h(k)
            end if
         end if
         x_k = x0
         if (f1 > f0) x_k = min(x0 + (x1 - x0)*max(f - f0, 0.0_wp)/(f1 - f0), x1)
      end function on_secant

      !> Whether element k is free at the chain's force f, and if not where it
      !! is held: fixed where the caller says; a plastic element that has
      !! turned at delta_max up to f_max (D-B10); a capped one at its cap from
      !! its force there (figure 25); a gated one at its hold x_h while f lies
      !! from its branch's force there to that plus the gate (D-C19).
      pure subroutine held_at(k, f, free_k, x_held)
         integer, intent(in) :: k
         real(wp), intent(in) :: f
         logical, intent(out) :: free_k
         real(wp), intent(out) :: x_held
         free_k = .false.
         x_held = 0.0_wp
         if (fixed(k)) then
            x_held = z(k)
         else if (plastic_held(k) .and. f <= mem(k)%f_max) then
            x_held = mem(k)%delta_max
         else if (f >= f_cap(k)) then
            x_held = x_max(k)
         else if (gate(k) > 0.0_wp .and. f >= f_h(k) .and. f <= f_h(k) + gate(k)) then
            x_held = x_h(k)
         else
            free_k = .true.
         end if
      end subroutine held_at

      !> x_i(F) for every element, h(F) = sum x_i - s and h'(F).
      pure subroutine deformations_at(f, xs, hf, dhf, st, iterations, hint, x_last, f_last, k_last)
         real(wp), intent(in) :: f
         real(wp), intent(inout) :: xs(:)      ! (set for the n elements)
         real(wp), intent(out) :: hf, dhf
         integer, intent(out) :: st
         integer, intent(inout) :: iterations
         integer, intent(inout) :: hint(:)     ! each element's table interval
         !> each element's last point on its branch and the slope there (f_last < 0: none)
         real(wp), intent(inout) :: x_last(:), f_last(:), k_last(:)
         type(root_search_t) :: q
         type(branch_point_t) :: b
         real(wp) :: x0, lo, hi, add
         logical :: free_k
         integer :: k
         st = split_ok
         dhf = 0.0_wp
         do k = 1, n
            call held_at(k, f, free_k, xs(k))
            if (.not. free_k) cycle          ! rigid: no compliance
            if (f >= f_max(k) .and. f > 0.0_wp) then
               ! beyond the force it reaches at the top of its range: it stays
               ! there, and adds no compliance (its branch's slope there would make
               ! h' large, and a Newton step falsely small)
               xs(k) = x_max(k)
               cycle
            end if
            ! the range and the gate's part on the side of its hold the force puts it
            lo = z(k)
            hi = x_max(k)
            add = 0.0_wp
            if (gate(k) > 0.0_wp) then
               if (f > f_h(k)) then
                  lo = x_h(k)
                  add = gate(k)
               else
                  hi = x_h(k)
               end if
            end if
            if (.not. f > 0.0_wp) then
               xs(k) = z(k)
               call element_eval(law(k), mem(k), z(k), cap(k), cap_slope(k), hint(k), b)
            else
               ! the start: on the tangent at the element's last point (an outer step
               ! or Newton's method before), else on its secant
               if (f_last(k) >= 0.0_wp .and. k_last(k) > min_slope .and. k_last(k) < rigid_slope) then
                  x0 = x_last(k) + (f - f_last(k))/k_last(k)
               else
                  x0 = on_secant(k, f)
               end if
               call root_begin(q, lo, hi, x0, defl_tol*s, force_tol, max_iter)
               do
                  call element_eval(law(k), mem(k), q%x, cap(k), cap_slope(k), hint(k), b)
                  call root_update(q, b%force + add - f, b%slope, f)
                  if (q%state /= root_running) exit
               end do
               iterations = iterations + q%iterations
               x_last(k) = q%x               ! (where b was evaluated: the search ends there)
               f_last(k) = b%force + add
               k_last(k) = b%slope
               if (q%state == root_not_finite) then
                  st = split_not_finite
               else if (q%state == root_failed) then
                  st = split_no_convergence
               end if
               xs(k) = q%x
            end if
            if (b%slope > min_slope .and. dhf < huge(1.0_wp)) then
               dhf = dhf + 1.0_wp/b%slope
            else
               dhf = huge(1.0_wp)       ! a flat branch: h jumps at f
            end if
         end do
         hf = sum(xs(1:n)) - s
      end subroutine deformations_at
   end subroutine split_by_force

   !> An element's branch at x (branch_eval), and beyond a soft cap - cap > 0
   !! with a slope k_cap > 0 - the force there rising at k_cap: the element
   !! crushed solid (its own deformation the cap's, the rest elastic).
   pure subroutine element_eval(law, mem, x, cap, k_cap, seg, bp)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x, cap, k_cap
      integer, intent(inout) :: seg
      type(branch_point_t), intent(out) :: bp
      if (k_cap > 0.0_wp .and. cap > 0.0_wp .and. x > cap) then
         call branch_eval(law, mem, cap, seg, bp)
         bp%force = bp%force + k_cap*(x - cap)
         bp%slope = k_cap
         bp%loading = .false.
      else
         call branch_eval(law, mem, x, seg, bp)
      end if
   end subroutine element_eval
end module series_split
