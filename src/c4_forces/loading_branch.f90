!> One element of a series chain (docs/belts.md 3, docs/loading.md): its
!! rate-independent branch of figure 18 at a deformation with the slope
!! there, where it carries nothing, and its rate terms and their inverse.
!! The shared deflection of the belts and contacts (series_split,
!! series_chain) evaluates its elements only through this module. Taken out
!! of belt_shared_deflection (issue 14, item 34).
module loading_branch
   use kinds, only: wp
   use loading_curves, only: loading_curve_t, curve_table, curve_is_defined, curve_value_slope
   use recurrent_loading, only: recurrent_law_t, loading_memory_t
   implicit none
   private

   public :: branch_point_t, branch_at, branch_at_memo, branch_eval, held_plastic, zero_extent
   public :: rate_force, rate_slope, rate_inverse, min_slope, rigid_slope
   public :: branch_argument, turn_switch, zero_on_side, turn_margin
   public :: branch_kink_count, branch_kinks

   !> (issue 15) How far past 0 (in/s) an element's rate is when its turning
   !! point or new cycle is located (turn_switch).
   real(wp), parameter :: turn_margin = 1.0e-7_wp
   !> A branch flatter than this (lb/in) is flat: its compliance is infinite.
   real(wp), parameter :: min_slope = 1.0e-200_wp
   !> The slope of a rigid element (a plastic one held at delta_max): no compliance.
   real(wp), parameter :: rigid_slope = huge(1.0_wp)

   !> An element's rate-independent branch at one deformation (figure 18).
   type :: branch_point_t
      real(wp) :: force = 0.0_wp    !< F_b, as recurrent_eval's branch
      real(wp) :: slope = 0.0_wp    !< dF_b/dx (right derivative at kinks)
      logical :: loading = .false.  !< on a loading branch
   end type branch_point_t

contains

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
      if (law%elastic .or. .not. mem%unloading .or. (law%plastic .and. x >= mem%delta_max)) then
         ! the loading curve of cycle n: F_e(x - eps_n)
         bp%loading = .true.
         d = x - mem%eps
      else if (x >= mem%delta_max) then
         ! beyond the turning point, until an accepted state reloads: the
         ! unloading curve's tangent (recurrent_loading's unloading_tangent)
         bp%loading = .false.
         bp%force = mem%f_max + mem%s_max*(x - mem%delta_max)
         bp%slope = mem%s_max
         return
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

   !> Issue 15: the deformation at which the element's branch reads its
   !! loading curve at x, with the memory as it stands: on a loading branch
   !! x - eps_n, on the unloading curve xi d_max (figure 18; branch_eval),
   !! continued linearly below delta_0 (where the branch carries nothing)
   !! so that it is continuous and increasing in x - also at delta_max,
   !! where the two agree. The branch's force kinks where this argument
   !! passes a kink of the curve (loading_curves' curve_kinks_about). A
   !! plastic element that has turned is rigid at delta_max and reloads
   !! along its loading curve: x - eps_n.
   pure real(wp) function branch_argument(law, mem, x) result(d)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x
      if (law%elastic .or. law%plastic .or. .not. mem%unloading .or. x >= mem%delta_max) then
         d = x - mem%eps
      else
         d = (x - mem%delta_zero)/(mem%delta_max - mem%delta_zero)*(mem%delta_max - mem%eps)
      end if
   end function branch_argument

   !> Issue 15: the switching function of an element's turning point and
   !! new cycle (figure 18; recurrent_accept), in in/s: on a loading branch it
   !! turns where its rate x_dot falls below 0, on an unloading one a new
   !! cycle begins where it rises above 0: x_dot + turn_margin, x_dot -
   !! turn_margin, so that where the driver accepts, just past the root, the
   !! rate has the sign the law asks for and the function that follows (the
   !! other one, with the memory changed) starts turn_margin*2 from its own
   !! root, not at the rate's rounding noise (some 1e-11 in/s where a chest
   !! carries 1000 lb: a root found there by the next step's first try was
   !! one of noise, and switches followed each other 1e-16 s apart). The
   !! switch so falls where the rate is 1e-7 in/s past 0: a memory changed
   !! 1e-7/|x''| s late, which moves the force by (slope change) 1e-14/|x''|.
   !! Where the element carries no load (loaded false) a constant of the
   !! sign it has before such a change (+1 loading, -1 unloading), so that
   !! nothing switches there: the force stays 0; it changes sign only where
   !! the element takes load (with x_dot > 0 on a loading branch, a new cycle
   !! on an unloading one: located with the onset). An elastic law has none.
   pure real(wp) function turn_switch(mem, loaded, x_dot) result(g)
      type(loading_memory_t), intent(in) :: mem
      logical, intent(in) :: loaded
      real(wp), intent(in) :: x_dot
      if (loaded) then
         g = merge(x_dot - turn_margin, x_dot + turn_margin, mem%unloading)
      else
         g = merge(-1.0_wp, 1.0_wp, mem%unloading)
      end if
   end function turn_switch

   !> Issue 15: a switching function's value g, or where it is exactly 0 a
   !! value of the sign of the side the law puts that point on (positive
   !! when above), too small to matter (1e-100): the driver takes a state
   !! where g reaches 0 as past the switch, and accepts there; where the
   !! law (accept, a region's test) counts the point itself as short of it
   !! (a rate of 0 turns nothing; a slack of 0 carries nothing), g must not
   !! be 0 there, or the accepted state would change nothing and, g being 0
   !! at it, the switch's later crossing would go unseen.
   elemental real(wp) function zero_on_side(g, above) result(v)
      real(wp), intent(in) :: g
      logical, intent(in) :: above
      real(wp), parameter :: nudge = 1.0e-100_wp
      v = g
      if (.not. abs(g) > 0.0_wp) v = merge(nudge, -nudge, above)
   end function zero_on_side
   !> Issue 15: how many switching functions branch_kinks gives for an
   !! element of this law: one per interior point of a tabulated curve that
   !! carries force (F_e's slope jumps there; the points of a flat start end
   !! at the element's zero extent, where its chain takes up or goes slack,
   !! the chain's own switch; the last point has none, the table going on
   !! along its last interval), and one for the turning point where an
   !! unloading curve meets the loading curve (a law with memory). Fixed
   !! by the law: the same whatever the memory.
   pure integer function branch_kink_count(law) result(n)
      type(recurrent_law_t), intent(in) :: law
      integer :: np
      n = 0
      if (law%curve%form == curve_table) then
         np = size(law%curve%force)
         if (np > 2) n = count(law%curve%force(2:np - 1) > 0.0_wp)
      end if
      if (.not. law%elastic .and. curve_is_defined(law%curve)) n = n + 1
   end function branch_kink_count

   !> Issue 15: the switching functions of an element's branch (figure 18,
   !! with its memory) at deformation x, branch_kink_count of them in g: x -
   !! X (in) for each kink X of the branch, so that each changes sign where
   !! the branch's slope jumps. A table point d_k (loading.md 2) lies at
   !! eps_n + d_k on the loading curve and, while unloading, at delta_0 +
   !! (delta_max - delta_0) d_k/d_max on the unloading curve F_e(xi d_max)
   !! xi**p (where xi d_max = d_k), or beyond delta_max on the loading curve
   !! again (d_k >= d_max); the unloading curve meets the loading curve at
   !! delta_max, the last one. A kink the branch does not have (the junction
   !! while loading; a plastic law's unloading, which carries nothing below
   !! delta_max) gives -1: a constant, never crossed.
   pure subroutine branch_kinks(law, mem, x, g)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: x
      real(wp), intent(out) :: g(:)
      real(wp) :: dm, span
      integer :: k, j, np
      logical :: unloading
      unloading = .not. law%elastic .and. mem%unloading
      dm = mem%delta_max - mem%eps
      span = mem%delta_max - mem%delta_zero
      j = 0
      if (law%curve%form == curve_table) then
         np = size(law%curve%force)
         do k = 2, np - 1
            if (.not. law%curve%force(k) > 0.0_wp) cycle
            j = j + 1
            if (.not. unloading .or. law%curve%defl(k) >= dm) then
               g(j) = x - (mem%eps + law%curve%defl(k))
            else if (law%plastic .or. .not. (span > 0.0_wp .and. dm > 0.0_wp)) then
               g(j) = -1.0_wp
            else
               g(j) = x - (mem%delta_zero + span*law%curve%defl(k)/dm)
            end if
         end do
      end if
      if (.not. law%elastic .and. curve_is_defined(law%curve)) then
         j = j + 1
         g(j) = -1.0_wp
         if (unloading) g(j) = x - mem%delta_max
      end if
   end subroutine branch_kinks

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

   !> dF_v/dv at v (>= 0; the rate terms of rate_force).
   pure real(wp) function rate_slope(law, v) result(c)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: v
      integer :: k
      real(wp) :: a
      c = 0.0_wp
      a = abs(v)
      do k = law%n_rate, 1, -1
         c = c*a + real(k, wp)*law%curve%sigma_rate(k)
      end do
   end function rate_slope

   !> The rate v at which the rate terms carry the force f: F_v(v) = f
   !! (F_v odd and increasing, rate_force). Exact for a linear rate term;
   !! otherwise Newton's method on |v| from above, which F_v's convexity
   !! for v > 0 (every coefficient >= 0) makes monotone, then a bisection
   !! polish. 0 for a law without rate terms.
   pure real(wp) function rate_inverse(law, f) result(v)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: f
      real(wp) :: a, lo, hi, g, c
      integer :: it
      v = 0.0_wp
      if (law%n_rate < 1 .or. .not. abs(f) > 0.0_wp) return
      a = abs(f)
      if (law%n_rate == 1) then
         v = sign(a/law%curve%sigma_rate(1), f)
         return
      end if
      ! a bracket [lo, hi] of |v|: F_v(hi) >= a
      lo = 0.0_wp
      hi = 1.0_wp
      do it = 1, 400
         if (rate_force(law, hi) >= a) exit
         lo = hi
         hi = 2.0_wp*hi
      end do
      ! Newton from hi: F_v convex on v > 0, so the iterates stay above the root
      v = hi
      do it = 1, 100
         g = rate_force(law, v) - a
         c = rate_slope(law, v)
         if (.not. (g > 0.0_wp .and. c > 0.0_wp)) exit
         if (.not. v - g/c < v) exit
         v = max(v - g/c, lo)
      end do
      v = sign(v, f)
   end function rate_inverse
end module loading_branch
