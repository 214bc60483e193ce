!> Report C.4.e, the shared deflection: "the nominal deformation is the sum
!! of the actual belt elongation and the body deflection ... Thus the total
!! deformation must be partitioned between the belt elongation and the body
!! deflection, and likewise for the rate." (figure 19, lost; docs/belts.md 3).
!!
!! A belt section and the body surface under it are elements in series
!! carrying one force: the webbing (its *BELTLOADING law) and the abdomen
!! (material 11) or the chest (material 12), each a recurrent-loading law
!! with its own memory (recurrent_loading). A *chain* is such a series: one
!! section and its body surface (the report's independent sections), or,
!! when several sections share one tension (*BELTOPTIONS COUPLING), every
!! webbing section and body surface of the shared sections. Given the
!! chain's total deformation s (the nominal deformations less the slack)
!! and its rate, chain_split finds
!!
!! - the deformations x_i >= 0 of the elements, sum x_i = s, at which every
!!   element's rate-independent branch carries the same force F_b (the
!!   deformation split; a bracketed, safeguarded Newton iteration that ends
!!   with a status, never silently; for three or more elements Newton's
!!   method on (x, F) at once first, D-B11, the bracketed search where it
!!   gives up);
!! - their rates, the derivative of that split along the motion: x_i' =
!!   w_i s', w_i = (1/k_i) / sum (1/k_j), k_i the slope of element i's
!!   branch at x_i (the rate split: the elements' forces stay equal as s
!!   changes, dF_b/dt = k_i x_i' for every i);
!! - the chain's force F = F_b + F_v, F_v = sum w_i F_v,i(x_i'), the weighted
!!   mean of the elements' rate terms: for linear rate terms it is the
!!   series combination c = sum w_i**2 c_i, which is the low-frequency limit
!!   of elements in series, and it dissipates exactly what each element's
!!   own rate terms dissipate at its own rate (F_v s' = sum F_v,i x_i').
!!   The total never pulls: F = max(0, F_b + F_v) while F_b > 0;
!! - each element's auxiliary work rates (E6-2: W, E_abs, D_v; docs/
!!   loading.md 4) at the common force, so that sum W_i' = F s' exactly:
!!   the energy balance of C.6 does not depend on the solver's tolerance.
!!
!! Everything here is pure: the memories are read, never written
!! (recurrent_accept changes them, after accepted steps, with the x_i and
!! x_i' of the accepted state).
module belt_shared_deflection
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use strings, only: num, itoa
   use loading_curves, only: loading_curve_t, curve_polynomial, curve_table, curve_is_defined, &
      curve_elastic_force, curve_rate_force, table_interval
   use recurrent_loading, only: recurrent_law_t, loading_memory_t, n_loading_aux, aux_work, aux_absorbed, &
      aux_rate_work
   implicit none
   private

   public :: max_chain, branch_point_t, branch_at, branch_at_memo, zero_extent, scaled_law
   public :: chain_split_t, chain_split, chain_split_text
   public :: split_ok, split_no_convergence, split_not_finite
   public :: path_none, path_pair, path_newton, path_search, max_sweeps
   public :: region_slack, region_unloaded, region_loaded
   public :: root_search_t, root_begin, root_update, root_running, root_converged, root_failed, root_not_finite

   !> Elements of one chain at most: three webbing sections and three body surfaces.
   integer, parameter :: max_chain = 6

   !> Outcome of a split.
   integer, parameter :: split_ok = 0, split_no_convergence = 1, split_not_finite = 2
   !> Which solver gave a split: none (slack, unloaded, one element, an
   !! element held, capped or gated in a pair), the pair's search on x_1,
   !! Newton's method on (x, F) of three or more (D-B11), or their search by
   !! force (where Newton's gave up).
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

   !> States of a root search.
   integer, parameter :: root_running = 0, root_converged = 1, root_failed = 2, root_not_finite = 3

   !> The relative tolerances of the splits: a force balance to 1e-12 of the
   !! force, a deformation to 1e-14 of the chain's (a few ulps).
   real(wp), parameter :: force_tol = 1.0e-12_wp, defl_tol = 1.0e-14_wp
   !> A branch flatter than this (lb/in) is flat: its compliance is infinite.
   real(wp), parameter :: min_slope = 1.0e-200_wp
   !> The slope of a rigid element (a plastic one held at delta_max): no compliance.
   real(wp), parameter :: rigid_slope = huge(1.0_wp)

   !> An element's rate-independent branch at one deformation (figure 18).
   type :: branch_point_t
      real(wp) :: force = 0.0_wp    !< F_b, as recurrent_eval's branch
      real(wp) :: slope = 0.0_wp    !< dF_b/dx (right derivative at kinks)
      logical :: loading = .false.  !< on a loading branch (E_abs counts while x' > 0)
   end type branch_point_t

   !> A chain's split at one state. The arrays are defined for the chain's
   !! n elements only (chain_split sets them; no default initialization,
   !! which would cost as much as a split at every evaluation).
   type :: chain_split_t
      integer :: status = split_ok
      integer :: region = region_slack
      integer :: iterations = 0              !< force evaluations of the search
      integer :: path = path_none            !< the solver that gave it
      integer :: sweeps = 0                  !< sweeps of Newton's method on (x, F), D-B11 (0: not tried)
      real(wp) :: force = 0.0_wp             !< F, the chain's force (every element carries it)
      real(wp) :: branch = 0.0_wp            !< F_b, its rate-independent part
      real(wp) :: guess = 0.0_wp             !< the unknown of the search: x_1 (two elements) or F_b
      real(wp) :: guess_rate = 0.0_wp        !< its rate, for a start value integrated with the motion
      real(wp) :: x(max_chain)               !< element deformations
      real(wp) :: rate(max_chain)            !< their rates
      real(wp) :: aux_rate(n_loading_aux, max_chain)  !< W', E_abs', D_v' per element
   end type chain_split_t

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

   ! --- the root search ----------------------------------------------------

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

   ! --- one element --------------------------------------------------------

   !> F_e(d) and dF_e/dd of a curve at once (the value as loading_curves'
   !! curve_elastic_force computes it, the right derivative; 0 and 0 for
   !! d <= 0): one search of a table for both. seg: the table interval to
   !! try first (0: none), and on return the one used - a search's later
   !! evaluations mostly fall in the interval of the one before, and the
   !! interval holding d is unique, so the hint changes nothing but the cost.
   pure subroutine curve_value_slope(c, d, f, k, seg)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d
      real(wp), intent(out) :: f, k
      integer, intent(inout) :: seg
      integer :: n, lo
      f = 0.0_wp
      k = 0.0_wp
      if (.not. d > 0.0_wp) return
      select case (c%form)
      case (curve_polynomial)
         ! Tables 2, 4: F_e = sum sigma_n d**n and its derivative (Horner)
         do n = c%order, 1, -1
            k = k*d + f + c%sigma(n)
            f = (f + c%sigma(n))*d
         end do
      case (curve_table)
         lo = table_interval_from(c%defl, d, seg)
         seg = lo
         k = (c%force(lo + 1) - c%force(lo))/(c%defl(lo + 1) - c%defl(lo))
         f = c%force(lo) + k*(d - c%defl(lo))
      end select
      f = max(f, 0.0_wp)
      k = max(k, 0.0_wp)
   end subroutine curve_value_slope

   !> The table interval lo (1 <= lo < n) holding d > 0, loading_curves'
   !! table_interval (the largest lo < n with defl(lo) <= d, 1 if none), found
   !! by walking from the interval hint (when 1 <= hint < n; a search's next
   !! evaluation is mostly in the same interval or the next), or for a table
   !! of up to walk_points points from its first (cheaper than bisection's
   !! call; table_interval for a longer one without a hint). The interval is
   !! unique, so the way it is found changes nothing but the cost.
   pure integer function table_interval_from(defl, d, hint) result(lo)
      real(wp), intent(in) :: defl(:), d
      integer, intent(in) :: hint
      integer, parameter :: walk_points = 16
      integer :: n
      n = size(defl)
      lo = hint
      if (lo < 1 .or. lo >= n) then
         if (n > walk_points) then
            lo = table_interval(defl, d)
            return
         end if
         lo = 1
      end if
      do while (lo < n - 1)
         if (.not. defl(lo + 1) <= d) exit
         lo = lo + 1
      end do
      do while (lo > 1)
         if (defl(lo) <= d) exit
         lo = lo - 1
      end do
   end function table_interval_from

   !> The branch of figure 18 at deformation x with the memory as it stands:
   !! the same selection and force as recurrent_loading's recurrent_eval
   !! (test_branch_matches_recurrent_eval), with the slope.
   pure function branch_at(law, mem, x) result(bp)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x
      type(branch_point_t) :: bp
      integer :: seg
      seg = 0
      call branch_eval(law, mem, x, seg, bp)
   end function branch_at

   !> branch_at with the memo of xi**p of a search (xi0, xp0; branch_eval),
   !! for the tests.
   pure subroutine branch_at_memo(law, mem, x, xi0, xp0, bp)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x
      real(wp), intent(inout) :: xi0, xp0
      type(branch_point_t), intent(out) :: bp
      integer :: seg
      seg = 0
      call branch_eval(law, mem, x, seg, bp, xi0, xp0)
   end subroutine branch_at_memo

   !> branch_at with a table interval to try first (seg, see curve_value_slope).
   !! (One evaluation of the curve, whichever the branch: the compiler can
   !! then put it in line.) xi0, xp0: a search's memo of the unloading
   !! curve's xi**p, for its later evaluations close by (xi0 = 0: none yet;
   !! set where pow is called): the same value to a few ulps.
   pure subroutine branch_eval(law, mem, x, seg, bp, xi0, xp0)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x
      integer, intent(inout) :: seg
      type(branch_point_t), intent(out) :: bp
      real(wp), intent(inout), optional :: xi0, xp0
      real(wp) :: xi, span, dm, d, fe, se, xp, u, p
      if (law%elastic .or. .not. mem%unloading .or. x >= mem%delta_max) then
         ! the loading curve of cycle n: F_e(x - eps_n)
         bp%loading = .true.
         d = x - mem%eps
      else if (law%plastic .or. .not. x > mem%delta_zero) then
         bp%loading = .false.
         bp%force = 0.0_wp
         bp%slope = 0.0_wp
         return
      else
         ! the unloading curve F_e(xi d_max) xi**p, xi = (x - delta_0)/(delta_max - delta_0)
         bp%loading = .false.
         span = mem%delta_max - mem%delta_zero
         dm = mem%delta_max - mem%eps
         xi = (x - mem%delta_zero)/span
         d = xi*dm
      end if
      call curve_value_slope(law%curve, d, fe, se, seg)
      if (bp%loading) then
         bp%force = fe
         bp%slope = se
      else if (mem%p > 0.0_wp) then
         xp = -1.0_wp
         if (present(xi0)) then
            ! near xi0, where xp0 = xi0**p was computed: xi**p = xp0 (1 + u)**p, u =
            ! xi/xi0 - 1, by the binomial series to u**4 - its remainder, about
            ! (p u)**5/120, below 1e-17 of it while p |u| <= 1e-3 - in place of
            ! pow, whose latency the search's later evaluations (a Newton step
            ! away) waited for
            p = mem%p
            if (xi0 > 0.0_wp) then
               u = (xi - xi0)/xi0
               if (abs(u)*max(p, 1.0_wp) <= 1.0e-3_wp) &
                  xp = xp0*(1.0_wp + u*p*(1.0_wp + u*(p - 1.0_wp)*0.5_wp*(1.0_wp + u*(p - 2.0_wp)*(1.0_wp/3.0_wp) &
                       *(1.0_wp + u*(p - 3.0_wp)*0.25_wp))))
            end if
         end if
         if (xp < 0.0_wp) then
            xp = xi**mem%p
            if (present(xi0)) then
               xi0 = xi
               xp0 = xp
            end if
         end if
         bp%force = fe*xp
         bp%slope = (se*dm*xp + fe*mem%p*xp/xi)/span
      else
         bp%force = fe
         bp%slope = se*dm/span
      end if
   end subroutine branch_eval

   !> (D-B10) A plastic element (R = 0) that has turned: its graph is a
   !! vertical segment at delta_max, from 0 to f_max, where it is rigid -
   !! for a force up to f_max it keeps delta_max, beyond it it reloads.
   pure logical function held_plastic(law, mem)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      held_plastic = law%plastic .and. .not. law%elastic .and. mem%unloading
   end function held_plastic

   !> The largest deformation at which the element's branch carries no
   !! force (its residual deformation, and for a table that starts flat the
   !! flat part): below it the element is slack.
   pure real(wp) function zero_extent(law, mem) result(z)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      if (law%elastic .or. .not. mem%unloading) then
         z = mem%eps + law%flat
      else if (law%plastic) then
         z = mem%delta_max
      else
         z = mem%delta_zero + (mem%delta_max - mem%delta_zero)*law%flat/(mem%delta_max - mem%eps)
      end if
   end function zero_extent

   !> The law with its forces multiplied by factor (> 0): curve and rate
   !! terms; G and R, and so every deformation of figure 18, unchanged.
   !! One side of a lap belt whose two sides are given (D-B5) carries half
   !! the lap belt's law.
   pure function scaled_law(law, factor) result(s)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: factor
      type(recurrent_law_t) :: s
      s = law
      s%curve%sigma = factor*law%curve%sigma
      s%curve%sigma_rate = factor*law%curve%sigma_rate
      if (allocated(law%curve%force)) s%curve%force = factor*law%curve%force
   end function scaled_law

   ! --- a chain ------------------------------------------------------------

   !> The split of a chain of n elements (laws and memories) at total
   !! deformation s (slack taken out) and its rate s_dot. max_iter bounds the
   !! force evaluations of each search; a search that does not converge
   !! gives status split_no_convergence (and the forces of the last iterate),
   !! one that meets a value that is not finite split_not_finite. guess: a
   !! start for the search's unknown (split%guess of a nearby state, e.g.
   !! integrated with the motion from split%guess_rate); the result does not
   !! depend on it beyond the tolerance, only the number of iterations does.
   !! cap (> 0 where given): an element that bottoms out at deformation cap
   !! (a contact's padding, figure 25, D-C19): there its graph turns
   !! vertical and the other elements take the rest. gate (> 0 where given):
   !! an element that does not move until the chain's force exceeds gate,
   !! and then carries gate plus its own curve (the steering column behind
   !! its padding, C.4.f, D-C19). search: three or more elements by the
   !! search by force alone, without Newton's method on (x, F) first (D-B11;
   !! the tests' reference); split%path says which solver gave the split.
   pure subroutine chain_split(n, law, mem, s, s_dot, max_iter, split, guess, cap, gate, search)
      integer, intent(in) :: n
      type(recurrent_law_t), intent(in) :: law(:)
      type(loading_memory_t), intent(in) :: mem(:)
      real(wp), intent(in) :: s, s_dot
      integer, intent(in) :: max_iter
      type(chain_split_t), intent(out) :: split
      real(wp), intent(in), optional :: guess
      real(wp), intent(in), optional :: cap(:), gate(:)
      logical, intent(in), optional :: search
      real(wp) :: z(max_chain), zsum, slope(max_chain), w(max_chain), fv(max_chain), fv_chain, lambda
      logical :: loading(max_chain), by_force
      integer :: i

      ! (each path sets x, rate and aux_rate of the n elements: no clearing first)
      if (.not. (ieee_is_finite(s) .and. ieee_is_finite(s_dot))) then
         split%status = split_not_finite
         call clear(split, n)
         return
      end if
      ! slack, or no element: no force (a belt carries no compression; D-B1)
      if (.not. s > 0.0_wp .or. n < 1) then
         call clear(split, n)
         return
      end if

      zsum = 0.0_wp
      do i = 1, n
         z(i) = zero_extent(law(i), mem(i))
         zsum = zsum + z(i)
      end do
      if (s <= zsum) then
         ! taken up within the residual deformations: no force; the deformation
         ! is shared in proportion to them (continuous with the loaded split)
         split%region = region_unloaded
         do i = 1, n
            split%x(i) = s*z(i)/zsum
            split%rate(i) = s_dot*z(i)/zsum
            split%aux_rate(:, i) = 0.0_wp
         end do
         if (n < 3) then
            split%guess = split%x(1)
            split%guess_rate = split%rate(1)
         end if
         return
      end if

      split%region = region_loaded
      select case (n)
      case (1)
         split%x(1) = s
         associate (bp => branch_at(law(1), mem(1), s))
            split%branch = bp%force
            slope(1) = bp%slope
            loading(1) = bp%loading
         end associate
         split%iterations = 1
      case (2)
         if (present(gate)) then
            if (any(gate(1:2) > 0.0_wp) .and. present(cap)) then
               call gated_split(cap(1:2), gate(1:2), split, slope, loading)
            else if (any(gate(1:2) > 0.0_wp)) then
               call gated_split(gate2=gate(1:2), sp=split, slope2=slope, loading2=loading)
            else if (present(cap)) then
               call capped_split(cap(1:2), split, slope, loading)
            else
               split%iterations = -1
            end if
         else if (present(cap)) then
            call capped_split(cap(1:2), split, slope, loading)
         else
            split%status = split_ok
            split%iterations = -1
         end if
         if (split%iterations < 0) call pair_split(law, mem, s, z, max_iter, split, slope, loading, guess)
      case default
         by_force = .false.
         if (present(search)) by_force = search
         call chain_split_by_force(n, law, mem, s, z, max_iter, by_force, split, slope, loading, guess, cap, gate)
      end select
      if (split%status /= split_ok) then
         call clear(split, n)
         return
      end if

      ! the rate split: x_i' = w_i s', the compliances' shares (D-B2)
      call rate_weights(n, slope, w)
      do i = 1, n
         split%rate(i) = w(i)*s_dot
      end do
      if (n < 3) then
         split%guess = split%x(1)
         split%guess_rate = split%rate(1)
      else
         ! dF_b/dt = k_i x_i' (any element with a slope; 0 when all are flat)
         split%guess = split%branch
         split%guess_rate = 0.0_wp
         i = maxloc(slope(1:n), 1)
         if (slope(i) > min_slope) split%guess_rate = slope(i)*split%rate(i)
      end if
      ! the chain's rate term: the weighted mean of the elements' at their rates (D-B2)
      fv_chain = 0.0_wp
      do i = 1, n
         fv(i) = rate_force(law(i), split%rate(i))
         fv_chain = fv_chain + w(i)*fv(i)
      end do
      split%force = 0.0_wp
      if (split%branch > 0.0_wp) split%force = max(0.0_wp, split%branch + fv_chain)
      ! the clip scales every element's rate term alike (each keeps its sign)
      lambda = 1.0_wp
      if (abs(fv_chain) > 0.0_wp) lambda = (split%force - split%branch)/fv_chain
      if (.not. split%branch > 0.0_wp) lambda = 0.0_wp
      do i = 1, n
         ! E6-2 per element (docs/loading.md 4): W' = (F_b + F_v,i) x', E_abs'
         ! = F_b x' on a loading branch while x' > 0, D_v' = F_v,i x' >= 0
         split%aux_rate(aux_work, i) = (split%branch + lambda*fv(i))*split%rate(i)
         split%aux_rate(aux_absorbed, i) = 0.0_wp
         if (loading(i) .and. split%rate(i) > 0.0_wp) split%aux_rate(aux_absorbed, i) = split%branch*split%rate(i)
         split%aux_rate(aux_rate_work, i) = lambda*fv(i)*split%rate(i)
      end do
      ! a gated element (the column): the gate's share of its work is crush
      ! work, dissipated, not part of what its own law absorbs and returns
      ! (so its stored energy comes from its own curve only; review of issue 7)
      if (present(gate)) then
         do i = 1, n
            if (.not. gate(i) > 0.0_wp) cycle
            if (split%aux_rate(aux_absorbed, i) > 0.0_wp) split%aux_rate(aux_absorbed, i) = &
               (split%branch - gate(i))*split%rate(i)
            split%aux_rate(aux_rate_work, i) = split%aux_rate(aux_rate_work, i) + gate(i)*split%rate(i)
         end do
      end if
   contains
      !> A gated element (the column) and a capped one (its padding): the
      !! column stays at its zero-force extent while the padding takes the
      !! deformation up to its cap (where its force is the gate), then the
      !! padding is solid and the column carries gate + its own curve.
      pure subroutine gated_split(cap2, gate2, sp, slope2, loading2)
         real(wp), intent(in), optional :: cap2(2)
         real(wp), intent(in) :: gate2(2)
         type(chain_split_t), intent(inout) :: sp
         real(wp), intent(out) :: slope2(:)
         logical, intent(out) :: loading2(:)
         type(branch_point_t) :: bp
         real(wp) :: pad_cap
         integer :: ig, ip
         ig = merge(1, 2, gate2(1) > 0.0_wp)
         ip = 3 - ig
         pad_cap = huge(1.0_wp)
         if (present(cap2)) then
            if (cap2(ip) > 0.0_wp) pad_cap = cap2(ip)
         end if
         sp%iterations = 1
         if (s - z(ig) <= pad_cap) then      ! the column at rest, the padding compressing
            sp%x(ig) = z(ig)
            sp%x(ip) = s - z(ig)
            bp = branch_at(law(ip), mem(ip), sp%x(ip))
            sp%branch = bp%force
            slope2(ig) = rigid_slope
            loading2(ig) = .false.
            slope2(ip) = bp%slope
            loading2(ip) = bp%loading
         else                                ! the padding solid, the column moving
            sp%x(ip) = pad_cap
            sp%x(ig) = s - pad_cap
            bp = branch_at(law(ig), mem(ig), sp%x(ig))
            sp%branch = gate2(ig) + bp%force
            slope2(ip) = rigid_slope
            loading2(ip) = .false.
            slope2(ig) = bp%slope
            loading2(ig) = bp%loading
         end if
      end subroutine gated_split

      !> Figure 25: element i bottomed out at cap(i) when the other, at s -
      !! cap(i), carries at least the force i has there; iterations = -1
      !! when no cap acts (the ordinary search follows).
      pure subroutine capped_split(cap2, sp, slope2, loading2)
         real(wp), intent(in) :: cap2(2)
         type(chain_split_t), intent(inout) :: sp
         real(wp), intent(out) :: slope2(:)
         logical, intent(out) :: loading2(:)
         type(branch_point_t) :: bi, bj
         integer :: ic, jc
         sp%iterations = -1
         do ic = 1, 2
            if (.not. cap2(ic) > 0.0_wp) cycle
            jc = 3 - ic
            if (.not. s - cap2(ic) > z(jc)) cycle
            bi = branch_at(law(ic), mem(ic), cap2(ic))
            bj = branch_at(law(jc), mem(jc), s - cap2(ic))
            if (bj%force < bi%force) cycle
            sp%x(ic) = cap2(ic)
            sp%x(jc) = s - cap2(ic)
            sp%branch = bj%force
            slope2(ic) = rigid_slope
            loading2(ic) = .false.
            slope2(jc) = bj%slope
            loading2(jc) = bj%loading
            sp%iterations = 2
            return
         end do
         slope2 = 0.0_wp
         loading2 = .false.
      end subroutine capped_split
   end subroutine chain_split

   !> No deformation, rate or work in the chain's n elements. (Every entry
   !! is cleared, max_chain of them: stores of a known length, where a loop
   !! to n became two calls of memset per element.)
   pure subroutine clear(split, n)
      type(chain_split_t), intent(inout) :: split
      integer, intent(in) :: n
      if (n < 1) return
      split%x = 0.0_wp
      split%rate = 0.0_wp
      split%aux_rate = 0.0_wp
   end subroutine clear

   !> loading_curves' curve_rate_force of the law's curve, its Horner sum
   !! begun at the highest rate term the curve has (law%n_rate; the terms
   !! above it are zero, and so would add nothing): the same value.
   pure real(wp) function rate_force(law, v) result(f)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: v
      integer :: k
      real(wp) :: a
      f = 0.0_wp
      a = abs(v)
      do k = law%n_rate, 1, -1
         f = (f + law%curve%sigma_rate(k))*a
      end do
      f = sign(f, v)
      if (.not. abs(v) > 0.0_wp) f = 0.0_wp
   end function rate_force

   !> w_i = (1/k_i)/sum(1/k_j); elements of zero slope (a flat branch) share
   !! the whole rate equally, rigid ones (rigid_slope) take none. (A chain
   !! has at least one element that is not rigid: see held_plastic.)
   pure subroutine rate_weights(n, slope, w)
      integer, intent(in) :: n
      real(wp), intent(in) :: slope(:)
      real(wp), intent(out) :: w(:)
      integer :: n_flat, i
      real(wp) :: total
      n_flat = 0
      do i = 1, n
         if (.not. slope(i) > min_slope) n_flat = n_flat + 1
      end do
      if (n_flat > 0) then
         w(1:n) = merge(1.0_wp/real(n_flat, wp), 0.0_wp, .not. slope(1:n) > min_slope)
      else
         total = 0.0_wp
         do i = 1, n
            if (slope(i) < rigid_slope) then
               w(i) = 1.0_wp/slope(i)
            else
               w(i) = 0.0_wp                       ! a rigid element takes no share
            end if
            total = total + w(i)
         end do
         if (total > 0.0_wp) then
            w(1:n) = w(1:n)/total
         else
            w(1:n) = 0.0_wp                        ! every element rigid: the chain takes no rate
         end if
      end if
   end subroutine rate_weights

   !> Two elements: x_1 = e in [z_1, s - z_2] where g(e) = F_1(e) - F_2(s - e)
   !! = 0, g' = k_1 + k_2 >= 0 (g(z_1) < 0 < g(s - z_2)). First point: the
   !! secant through the bracket's ends (exact for linear branches).
   pure subroutine pair_split(law, mem, s, z, max_iter, split, slope, loading, guess)
      type(recurrent_law_t), intent(in) :: law(:)
      type(loading_memory_t), intent(in) :: mem(:)
      real(wp), intent(in) :: s, z(:)
      integer, intent(in) :: max_iter
      type(chain_split_t), intent(inout) :: split
      real(wp), intent(out) :: slope(:)
      logical, intent(out) :: loading(:)
      real(wp), intent(in), optional :: guess
      type(root_search_t) :: r
      type(branch_point_t) :: b1, b2, bj
      real(wp) :: lo, hi, f2_lo, f1_hi, x0, xi1, xi2, xp1, xp2
      integer :: seg1, seg2, seg, i, j
      seg1 = 0
      seg2 = 0
      split%iterations = 0
      split%path = path_pair
      ! (D-B10) a plastic element held at delta_max while the other carries no
      ! more than its f_max: the other takes the whole change
      do i = 1, 2
         if (.not. held_plastic(law(i), mem(i))) cycle
         j = 3 - i
         seg = 0
         call branch_eval(law(j), mem(j), s - mem(i)%delta_max, seg, bj)
         split%iterations = split%iterations + 1
         if (bj%force <= mem(i)%f_max) then
            split%x(i) = mem(i)%delta_max
            split%x(j) = s - mem(i)%delta_max
            split%branch = bj%force
            slope(i) = rigid_slope
            loading(i) = .false.
            slope(j) = bj%slope
            loading(j) = bj%loading
            return
         end if
      end do
      ! else the bracket: g(z_1) < 0 < g(s - z_2), an element held above reloading
      lo = z(1)
      hi = s - z(2)
      if (present(guess)) then
         ! a start from a nearby state: the bracket's signs are known
         ! (g(z_1) < 0 < g(s - z_2)), no need to evaluate its ends
         x0 = guess
      else
         call branch_eval(law(2), mem(2), s - lo, seg2, b2)
         call branch_eval(law(1), mem(1), hi, seg1, b1)
         f2_lo = b2%force
         f1_hi = b1%force
         x0 = 0.5_wp*(lo + hi)
         if (f2_lo + f1_hi > 0.0_wp) x0 = lo + (hi - lo)*f2_lo/(f2_lo + f1_hi)
         split%iterations = 2
      end if
      call root_begin(r, lo, hi, x0, defl_tol*s, force_tol, max_iter)
      ! the memo of xi**p (branch_eval) where a start is given, the belts' chains,
      ! whose evaluations after the first are a Newton step from it: the contacts'
      ! pairs, started from their bracket, gain little, and their values at a few
      ! ulps move the interior deck's Dormand-Prince steps (docs/performance.md)
      xi1 = merge(0.0_wp, -1.0_wp, present(guess))
      xi2 = xi1
      xp1 = 0.0_wp
      xp2 = 0.0_wp
      do
         if (xi1 >= 0.0_wp) then
            call branch_eval(law(1), mem(1), r%x, seg1, b1, xi1, xp1)
            call branch_eval(law(2), mem(2), s - r%x, seg2, b2, xi2, xp2)
         else
            call branch_eval(law(1), mem(1), r%x, seg1, b1)
            call branch_eval(law(2), mem(2), s - r%x, seg2, b2)
         end if
         call root_update(r, b1%force - b2%force, b1%slope + b2%slope, max(b1%force, b2%force))
         if (r%state /= root_running) exit
      end do
      split%iterations = split%iterations + r%iterations
      if (r%state == root_not_finite) then
         split%status = split_not_finite
         return
      end if
      if (r%state == root_failed) split%status = split_no_convergence
      split%x(1) = r%x
      split%x(2) = s - r%x
      ! (the branches are continuous - the one jump, a plastic law's drop, is
      ! handled above - so the bracket closes on a root of g)
      split%branch = 0.5_wp*(b1%force + b2%force)
      slope(1) = b1%slope
      slope(2) = b2%slope
      loading(1) = b1%loading
      loading(2) = b2%loading
   end subroutine pair_split

   !> Three or more elements (sections sharing one tension; a contact's body,
   !! padding and backing): first Newton's method on (x_1 .. x_n, F) at once
   !! (newton_split, D-B11), and where it gives up the search by force: the
   !! common force F_b in (0, F_hi] with h(F) = sum x_i(F) - s = 0, x_i(F)
   !! the element's deformation at force F (each an inner search on [z_i, s -
   !! sum z + z_i], started on the tangent at the element's last point), h' =
   !! sum 1/k_i, from where Newton's method ended. Where the bracket closes on
   !! a flat branch or a jump, the deformations are interpolated between its
   !! ends so that they add up. search: the search alone (the tests' reference).
   pure subroutine chain_split_by_force(n, law, mem, s, z, max_iter, search, split, slope, loading, guess, cap, gate)
      integer, intent(in) :: n
      type(recurrent_law_t), intent(in) :: law(:)
      type(loading_memory_t), intent(in) :: mem(:)
      real(wp), intent(in) :: s, z(:)
      integer, intent(in) :: max_iter
      logical, intent(in) :: search      !< the search by force alone, no Newton's method first
      type(chain_split_t), intent(inout) :: split
      real(wp), intent(out) :: slope(:)
      logical, intent(out) :: loading(:)
      real(wp), intent(in), optional :: guess
      real(wp), intent(in), optional :: cap(:), gate(:)
      type(root_search_t) :: r
      real(wp) :: x_max(max_chain), secant(max_chain), f_max(max_chain), f_hi, f0, h, dh, x(max_chain)
      real(wp) :: x_lo(max_chain), x_hi(max_chain), h_lo, h_hi, theta
      real(wp) :: f_cap(max_chain)           ! a capped element's force at its cap (huge: no cap)
      real(wp) :: f_gate(max_chain)          ! a gated element's force before it moves (0: no gate)
      integer :: i, status, seg(max_chain)
      type(branch_point_t) :: bp
      logical :: done, newton_free(max_chain), have_lo, have_hi
      real(wp) :: f_newton
      ! each element's last point (x_at, f_at) on its branch and its slope k_at
      ! there (f_at < 0: none yet): where its next search at another force starts
      real(wp) :: x_at(max_chain), f_at(max_chain), k_at(max_chain)

      seg(1:n) = 0
      f_cap(1:n) = huge(1.0_wp)
      f_gate(1:n) = 0.0_wp
      if (present(gate)) f_gate(1:n) = max(gate(1:n), 0.0_wp)
      do i = 1, n
         x_max(i) = s - sum(z(1:n)) + z(i)
         if (present(cap)) then
            if (cap(i) > 0.0_wp .and. cap(i) < x_max(i)) then
               x_max(i) = cap(i)               ! it cannot deform beyond its cap (figure 25)
               call branch_eval(law(i), mem(i), cap(i), seg(i), bp)
               f_cap(i) = bp%force
            end if
         end if
         call branch_eval(law(i), mem(i), x_max(i), seg(i), bp)
         f_max(i) = bp%force + f_gate(i)
         if (x_max(i) > z(i)) then
            secant(i) = f_max(i)/(x_max(i) - z(i))
         else
            secant(i) = huge(1.0_wp)           ! a cap at or below its residual deformation: rigid
         end if
      end do
      split%iterations = n
      f_hi = maxval(f_max(1:n))
      ! first point: the secants in series
      f0 = (s - sum(z(1:n)))/sum(1.0_wp/max(secant(1:n), min_slope))
      if (present(guess)) f0 = guess
      ! (D-B11) first Newton's method on the deformations and the force at once;
      ! where it does not converge in a few sweeps, or meets what it cannot
      ! handle, the search by force below decides, from where it ended
      f_at(1:n) = -1.0_wp
      x_at(1:n) = 0.0_wp
      k_at(1:n) = 0.0_wp
      if (.not. search) then
         call newton_split(f0, x, seg, f_newton, slope, newton_free, loading, split%iterations, split%sweeps, &
                           x_at, f_at, k_at, done)
         if (done) then
            split%branch = f_newton
            split%path = path_newton
            split%x(1:n) = x(1:n)
            do i = 1, n
               if (newton_free(i)) cycle
               slope(i) = rigid_slope        ! held (D-B10), at its cap, or behind its gate
               loading(i) = .false.
            end do
            return
         end if
         ! the search starts where Newton's method ended, and each element where it was evaluated last
         if (f_newton > 0.0_wp .and. f_newton <= f_hi) f0 = f_newton
      end if
      split%path = path_search
      call root_begin(r, 0.0_wp, f_hi, f0, defl_tol*f_hi, defl_tol, max_iter)
      have_lo = .false.
      have_hi = .false.
      do
         call deformations_at(r%x, x, h, dh, status, split%iterations, seg, x_at, f_at, k_at)
         if (status /= split_ok) then
            split%status = status
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
         split%status = split_not_finite
         return
      end if
      if (r%state == root_failed) split%status = split_no_convergence
      split%branch = r%x
      if (abs(h) > defl_tol*s .and. split%status == split_ok) then
         ! a flat branch or a jump: interpolate between the bracket's ends (an end
         ! the search never evaluated, 0 or F_hi, evaluated now)
         status = split_ok
         if (.not. have_lo) call deformations_at(r%lo, x_lo, h_lo, dh, status, split%iterations, seg, x_at, f_at, k_at)
         if (.not. have_hi .and. status == split_ok) &
            call deformations_at(r%hi, x_hi, h_hi, dh, status, split%iterations, seg, x_at, f_at, k_at)
         if (status /= split_ok) then
            split%status = status
            return
         end if
         theta = 0.0_wp
         if (h_hi - h_lo > 0.0_wp) theta = min(1.0_wp, max(0.0_wp, -h_lo/(h_hi - h_lo)))
         x(1:n) = x_lo(1:n) + theta*(x_hi(1:n) - x_lo(1:n))
         split%branch = r%lo + theta*(r%hi - r%lo)
      end if
      split%x(1:n) = x(1:n)
      do i = 1, n
         if ((held_plastic(law(i), mem(i)) .and. split%branch <= mem(i)%f_max) .or. split%branch >= f_cap(i) &
             .or. (f_gate(i) > 0.0_wp .and. split%branch <= f_gate(i))) then
            slope(i) = rigid_slope        ! held (D-B10), bottomed out at its cap, or held by its gate
            loading(i) = .false.
         else
            call branch_eval(law(i), mem(i), x(i), seg(i), bp)
            slope(i) = bp%slope
            loading(i) = bp%loading
         end if
      end do
   contains
      !> (D-B11) Newton's method on (x_1 .. x_n, F) at once. The elements
      !! that are rigid at the force F are held (a plastic element below
      !! f_max, D-B10; a padding at its cap, figure 25; a column below its
      !! gate, D-C19); each free element's tangent at x_i, F_i + k_i dx_i =
      !! F_new, and sum x_i = s give F_new = (s - sum held x - sum (x_i -
      !! F_i/k_i)) / sum (1/k_i) and the new x_i: one evaluation of each free
      !! element per sweep, exact on linear pieces of tabulated curves,
      !! quadratic on smooth branches, where the search by force runs an
      !! inner search per element for each of its evaluations of h(F). An
      !! element on a flat piece of its curve (slope 0, force > 0: the column
      !! crushing at its plateau) sets F_new to its force and takes the
      !! deformation the others leave. It converges when every free element
      !! carries F to the force tolerance (the inner searches' test) and the
      !! deformations add up to s to the deformation tolerance (the outer
      !! one's). It gives up (done = .false.) on what the search's bracket
      !! settles better: a jump (a huge slope), two flat elements, an element
      !! at the origin of its curve (no slope to go by) or pushed out of [z_i,
      !! x_max_i], a force <= 0, a value that is not finite, or no
      !! convergence within max_sweeps sweeps. The held set follows F at every
      !! sweep; an element taken up starts on its secant.
      pure subroutine newton_split(f_start, xs, hint, f, kb, free, on_loading, evaluations, sweeps, x_at, f_at, k_at, done)
         real(wp), intent(in) :: f_start
         real(wp), intent(out) :: xs(:)           !< the deformations
         integer, intent(inout) :: hint(:)        !< each element's table interval (curve_value_slope)
         real(wp), intent(out) :: f               !< the force
         real(wp), intent(out) :: kb(:)           !< the free elements' slopes
         logical, intent(out) :: free(:)          !< not held at f
         logical, intent(out) :: on_loading(:)    !< the free elements' branches
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
         if (.not. (f > 0.0_wp .and. f <= f_hi)) f = (s - sum(z(1:n)))/sum(1.0_wp/max(secant(1:n), min_slope))
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
               call branch_eval(law(k), mem(k), xs(k), hint(k), b)
               evaluations = evaluations + 1
               fb(k) = b%force + f_gate(k)
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
               ! its zero-force extent to halfway there - at z_k its curve's origin has
               ! no slope to go by; the next step comes back)
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

      !> Element k's deformation at force f on its secant from (z_k, its
      !! gate) towards (x_max_k, f_max_k): Newton's start (its curve's origin
      !! has no slope to go by, the secant has).
      pure real(wp) function on_secant(k, f) result(x_k)
         integer, intent(in) :: k
         real(wp), intent(in) :: f
         x_k = z(k)
         if (f_max(k) > f_gate(k)) x_k = min(z(k) + (x_max(k) - z(k))*max(f - f_gate(k), 0.0_wp)/(f_max(k) - f_gate(k)), &
                                             x_max(k))
      end function on_secant

      !> Whether element k is free at the chain's force f, and if not where
      !! it is held (deformations_at's rules): a plastic element that has
      !! turned at delta_max up to f_max (D-B10), a capped one at its cap from
      !! its force there (figure 25), a gated one at z_k up to its gate.
      pure subroutine held_at(k, f, free_k, x_held)
         integer, intent(in) :: k
         real(wp), intent(in) :: f
         logical, intent(out) :: free_k
         real(wp), intent(out) :: x_held
         free_k = .false.
         x_held = 0.0_wp
         if (held_plastic(law(k), mem(k)) .and. f <= mem(k)%f_max) then
            x_held = mem(k)%delta_max
         else if (f >= f_cap(k)) then
            x_held = x_max(k)
         else if (f_gate(k) > 0.0_wp .and. f <= f_gate(k)) then
            x_held = z(k)
         else
            free_k = .true.
         end if
      end subroutine held_at

      !> x_i(F) for every element, h(F) = sum x_i - s and h'(F).
      pure subroutine deformations_at(f, xs, hf, dhf, st, iterations, hint, x_last, f_last, k_last)
         real(wp), intent(in) :: f
         real(wp), intent(out) :: xs(:), hf, dhf
         integer, intent(out) :: st
         integer, intent(inout) :: iterations
         integer, intent(inout) :: hint(:)     ! each element's table interval (curve_value_slope)
         !> each element's last point on its branch and the slope there (f_last < 0: none)
         real(wp), intent(inout) :: x_last(:), f_last(:), k_last(:)
         type(root_search_t) :: q
         type(branch_point_t) :: b
         real(wp) :: x0
         integer :: k
         st = split_ok
         dhf = 0.0_wp
         do k = 1, n
            if (held_plastic(law(k), mem(k)) .and. f <= mem(k)%f_max) then
               xs(k) = mem(k)%delta_max    ! held, rigid: no compliance (D-B10)
               cycle
            end if
            if (f >= f_cap(k)) then
               xs(k) = x_max(k)            ! bottomed out at its cap: rigid beyond (figure 25)
               cycle
            end if
            if (f_gate(k) > 0.0_wp .and. f <= f_gate(k)) then
               xs(k) = z(k)                ! the gate holds it (the column before it moves)
               cycle
            end if
            if (f >= f_max(k) .and. f > 0.0_wp) then
               ! beyond the force it reaches at the top of its range, s - sum z + z_k:
               ! it stays there, and adds no compliance (its branch's slope there
               ! would make h' large, and a Newton step falsely small)
               xs(k) = x_max(k)
               cycle
            end if
            if (.not. f > 0.0_wp) then
               xs(k) = z(k)
               call branch_eval(law(k), mem(k), z(k), hint(k), b)
            else
               ! the start: on the tangent at the element's last point (an outer step
               ! or Newton's method before), else on its secant
               x0 = z(k) + (f - f_gate(k))/max(secant(k), min_slope)
               if (f_last(k) >= 0.0_wp .and. k_last(k) > min_slope .and. k_last(k) < rigid_slope) &
                  x0 = x_last(k) + (f - f_last(k))/k_last(k)
               call root_begin(q, z(k), x_max(k), x0, defl_tol*s, force_tol, max_iter)
               do
                  call branch_eval(law(k), mem(k), q%x, hint(k), b)
                  call root_update(q, b%force + f_gate(k) - f, b%slope, f)
                  if (q%state /= root_running) exit
               end do
               iterations = iterations + q%iterations
               x_last(k) = q%x               ! (where b was evaluated: the search ends there)
               f_last(k) = b%force + f_gate(k)
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
   end subroutine chain_split_by_force

   !> Why a split failed, for the failure message.
   pure function chain_split_text(split, s, s_dot, max_iter, setting) result(text)
      type(chain_split_t), intent(in) :: split
      real(wp), intent(in) :: s, s_dot
      integer, intent(in) :: max_iter
      character(len=*), intent(in), optional :: setting   !< where the deck sets max_iter, e.g. ' (*BELTOPTIONS ITER)'
      character(len=:), allocatable :: text
      select case (split%status)
      case (split_no_convergence)
         text = 'the shared deflection did not converge within '//itoa(max_iter)//' iterations'
         if (present(setting)) text = text//setting
         text = text//' and '//itoa(bisections)//' bisections at the deformation '//num(s, 6)//' in, rate '//num(s_dot, 6)//' in/s'
      case (split_not_finite)
         text = 'the shared deflection met a value that is not finite (deformation '//num(s, 6)//' in, rate ' &
                //num(s_dot, 6)//' in/s)'
      case default
         text = ''
      end select
   end function chain_split_text
end module belt_shared_deflection
