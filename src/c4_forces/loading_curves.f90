!> Loading curves of the belts (report C.4.e) and of the padded and
!! non-rigid interior surfaces (C.4.f): the force F(d, v) >= 0 that an
!! element carries at a deformation d and a rate of deformation v = d-dot
!! (docs/loading.md, sections 1-2).
!!
!! - NLOAD = 1, polynomial (Tables 2 and 4: N, sigma_n and sigma_{n+N}):
!!   elastic part  F_e(d) = sigma_1 d + sigma_2 d**2 + ... + sigma_N d**N;
!!   rate part     F_v(v) = sum_k sigma_{N+k} |v|**(k-1) v   (k = 1..N).
!! - NLOAD = 2, tabulated: F_e(d) linear between points (d_i, F_i) that
!!   start at (0, 0), d increasing and F not decreasing; beyond the last
!!   point along the last interval. The rate part is as above.
!! - total: F = max(0, F_e(d) + F_v(v)) while the elastic part carries load
!!   (F_e > 0), else 0. A curve never pulls.
!!
!! The rate terms are the report's polynomial in the rate ("fifth-order
!! polynomials in both the deflection and the rate of deflection", C.4.f)
!! extended oddly to v < 0, so that every term with sigma_{N+k} >= 0 opposes
!! the motion: F_v v = sum sigma_{N+k} |v|**(k+1) >= 0. Taken literally,
!! sigma v**2 would push harder while the element unloads (an energy source).
!! The clip at 0 removes at most part of a term that opposes v, so the rate
!! part F - F_e keeps the sign of v: it only ever dissipates (loading.md 2).
!!
!! The checks a deck must pass (curve_check): F_e not decreasing for d >= 0
!! (which with F_e(0) = 0 means it never pulls; polynomials are checked
!! exactly, through the real roots of F_e'), not identically zero, rate
!! coefficients >= 0, table abscissae increasing.
module loading_curves
   use kinds, only: wp
   use table_search, only: bracket_index
   use loading_parameters, only: loading_curve_t, curve_none, curve_polynomial, curve_table, max_order, &
      x_far, curve_is_defined, curve_check, polynomial_minimum
   implicit none
   private

   public :: loading_curve_t, curve_none, curve_polynomial, curve_table, max_order
   public :: curve_is_defined, curve_elastic_force, curve_rate_force, curve_force
   public :: curve_energy, curve_moment, curve_deflection_at, curve_check, curve_flat_extent
   public :: polynomial_minimum, table_interval, curve_max_slope, curve_kinks_about, curve_value_slope

contains

   !> The extent of the curve's initial flat part: the largest table
   !! deformation up to which every point carries no force (0 for a
   !! polynomial, or a table rising from its first point).
   pure real(wp) function curve_flat_extent(c) result(z)
      type(loading_curve_t), intent(in) :: c
      integer :: k
      z = 0.0_wp
      if (c%form /= curve_table) return
      do k = 1, size(c%force)
         if (c%force(k) > 0.0_wp) exit
         z = c%defl(k)
      end do
   end function curve_flat_extent

   !> The curve's stiffest slope (lb/in): a table's steepest interval, a
   !! polynomial's F_e' at 1 in (it has no largest). The shared deflection
   !! gives a padding crushed solid this slope in a chain with a
   !! rate-dependent element (series_chain). 0 for a curve not defined.
   pure real(wp) function curve_max_slope(c) result(k)
      type(loading_curve_t), intent(in) :: c
      integer :: i
      k = 0.0_wp
      select case (c%form)
      case (curve_polynomial)
         do i = 1, c%order
            k = k + real(i, wp)*c%sigma(i)
         end do
      case (curve_table)
         do i = 1, size(c%defl) - 1
            k = max(k, slope(c, i))
         end do
      end select
      k = max(k, 0.0_wp)
   end function curve_max_slope

   !> The elastic (rate-independent) part F_e(d); 0 for d <= 0.
   pure real(wp) function curve_elastic_force(c, d) result(f)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d
      integer :: k
      f = 0.0_wp
      if (.not. d > 0.0_wp) return
      select case (c%form)
      case (curve_polynomial)
         ! Tables 2, 4: sum sigma_n d**n (Horner)
         do k = c%order, 1, -1
            f = (f + c%sigma(k))*d
         end do
      case (curve_table)
         k = table_interval(c%defl, d)
         f = c%force(k) + slope(c, k)*(d - c%defl(k))
      end select
      f = max(f, 0.0_wp)   ! a curve that passed curve_check is >= 0 already
   end function curve_elastic_force

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
      integer :: n, k
      n = size(defl)
      lo = hint
      if (lo < 1 .or. lo >= n) then
         if (n > walk_points) then
            lo = table_interval(defl, d)
            return
         end if
         lo = 1
      end if
      ! (counted loops, not unrolled: a walk is mostly of no step or one, and
      ! -funroll-loops' dispatch into an unrolled walk cost more than the walk,
      ! some 30 % of an evaluation of the curve; issue 16 section 4)
      !GCC$ unroll 1
      do k = lo, n - 2
         if (.not. defl(k + 1) <= d) exit
         lo = k + 1
      end do
      !GCC$ unroll 1
      do k = lo, 2, -1
         if (defl(k) <= d) exit
         lo = k - 1
      end do
   end function table_interval_from

   !> The rate part F_v(v) = sum_k sigma_{N+k} |v|**(k-1) v (loading.md 2):
   !! the sign of v, so that it always dissipates.
   pure real(wp) function curve_rate_force(c, v) result(f)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: v
      integer :: k
      real(wp) :: a
      f = 0.0_wp
      a = abs(v)
      do k = max_order, 1, -1
         f = (f + c%sigma_rate(k))*a
      end do
      f = sign(f, v)
      if (.not. abs(v) > 0.0_wp) f = 0.0_wp
   end function curve_rate_force

   !> The force of the curve without memory (an elastic element, docs/
   !! loading.md 2): max(0, F_e(d) + F_v(v)) while F_e(d) > 0, else 0.
   pure real(wp) function curve_force(c, d, v) result(f)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d, v
      real(wp) :: fe
      fe = curve_elastic_force(c, d)
      f = 0.0_wp
      if (fe > 0.0_wp) f = max(0.0_wp, fe + curve_rate_force(c, v))
   end function curve_force

   !> The energy of the elastic part, E(d) = integral of F_e from 0 to d
   !! (exact: sum sigma_n d**(n+1)/(n+1), or the trapezoids of the table).
   pure real(wp) function curve_energy(c, d) result(e)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d
      e = curve_moment(c, d, 0.0_wp)
   end function curve_energy

   !> M(d, p) = integral from 0 to d of F_e(u) (u/d)**p du, p >= 0, exact
   !! for both forms (M(d, 0) = E(d)). The unloading curves of recurrent
   !! loading are sized with it (docs/loading.md 3).
   pure real(wp) function curve_moment(c, d, p) result(m)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d, p
      integer :: k, last
      real(wp) :: s0, s1, u0, u1, b, f0
      m = 0.0_wp
      if (.not. d > 0.0_wp) return
      select case (c%form)
      case (curve_polynomial)
         ! integral of sigma_n u**n (u/d)**p = sigma_n d**(n+1)/(n+1+p)
         do k = c%order, 1, -1
            m = (m + c%sigma(k)/(real(k + 1, wp) + p))*d
         end do
         m = m*d
      case (curve_table)
         ! F_e = f0 + b (u - u0) on each interval, u = s d: the integral of
         ! (f0 - b u0 + b d s) s**p d ds in closed form
         last = table_interval(c%defl, d)
         do k = 1, last
            u0 = c%defl(k)
            u1 = d
            if (k < last) u1 = c%defl(k + 1)
            b = slope(c, k)
            f0 = c%force(k)
            s0 = u0/d
            s1 = u1/d
            m = m + d*((f0 - b*u0)*(pw(s1, p + 1.0_wp) - pw(s0, p + 1.0_wp))/(p + 1.0_wp) &
                       + b*d*(pw(s1, p + 2.0_wp) - pw(s0, p + 2.0_wp))/(p + 2.0_wp))
         end do
      end select
   end function curve_moment

   !> The smallest d >= 0 at which F_e(d) >= f: the inverse of the curve
   !! (recurrent loading, case 2 of figure 18; docs/loading.md 3). 0 for
   !! f <= 0. For an f the curve never reaches (a table ending flat), the
   !! last point.
   pure real(wp) function curve_deflection_at(c, f) result(d)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: f
      real(wp) :: lo, hi, mid, b
      integer :: k, n, it
      d = 0.0_wp
      if (.not. f > 0.0_wp) return
      select case (c%form)
      case (curve_polynomial)
         ! F_e is continuous and not decreasing: bisection for its first crossing of f
         hi = 1.0_wp
         do it = 1, 2000
            if (curve_elastic_force(c, hi) >= f .or. hi > x_far) exit
            hi = 2.0_wp*hi
         end do
         lo = 0.0_wp
         do it = 1, 2000
            mid = 0.5_wp*(lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            if (curve_elastic_force(c, mid) >= f) then
               hi = mid
            else
               lo = mid
            end if
         end do
         d = hi
      case (curve_table)
         n = size(c%defl)
         do k = 1, n - 1
            if (c%force(k + 1) >= f) then
               ! first interval that reaches f; its slope is > 0 since force(k) < f
               d = c%defl(k) + (f - c%force(k))*(c%defl(k + 1) - c%defl(k))/(c%force(k + 1) - c%force(k))
               return
            end if
         end do
         b = slope(c, n - 1)
         d = c%defl(n)
         if (b > 0.0_wp) d = c%defl(n) + (f - c%force(n))/b
      end select
   end function curve_deflection_at

   !> Issue 15: the kinks of F_e nearest to d - the deformations where its
   !! slope changes - at or below d (d_lo) and above it (d_hi); -huge and
   !! huge where there is none. A polynomial has one, at 0 (F_e is 0 below);
   !! a table one at each point where the slopes of its two sides differ
   !! (0 before its first point; the last interval goes on beyond its last,
   !! so that is none), among them the end of its flat start (curve_flat_
   !! extent: where it takes load). Points whose sides' slopes agree to
   !! 1e-12 of the larger are not kinks (collinear points, rounding).
   !! An effect that locates where its force kinks keeps d_lo, d_hi of its
   !! last accepted state and switches where d leaves [d_lo, d_hi).
   pure subroutine curve_kinks_about(c, d, d_lo, d_hi)
      type(loading_curve_t), intent(in) :: c
      real(wp), intent(in) :: d
      real(wp), intent(out) :: d_lo, d_hi
      integer :: k, n
      d_lo = -huge(1.0_wp)
      d_hi = huge(1.0_wp)
      select case (c%form)
      case (curve_polynomial)
         if (d >= 0.0_wp) then
            d_lo = 0.0_wp
         else
            d_hi = 0.0_wp
         end if
      case (curve_table)
         n = size(c%defl)
         ! the points at or below d, from the highest down, then those above
         k = 0
         if (d >= c%defl(1)) k = table_interval(c%defl, d)
         if (k == n - 1 .and. d >= c%defl(n)) k = n
         do while (k >= 1)
            if (is_kink(k)) then
               d_lo = c%defl(k)
               exit
            end if
            k = k - 1
         end do
         k = 1
         if (d >= c%defl(1)) k = table_interval(c%defl, d) + 1
         do while (k <= n - 1)
            if (c%defl(k) > d .and. is_kink(k)) then
               d_hi = c%defl(k)
               exit
            end if
            k = k + 1
         end do
      end select
   contains
      !> Whether the slopes on the two sides of point k (< n) differ.
      pure logical function is_kink(k)
         integer, intent(in) :: k
         real(wp) :: before, after
         is_kink = .false.
         if (k >= n) return
         before = 0.0_wp
         if (k > 1) before = slope(c, k - 1)
         after = slope(c, k)
         is_kink = abs(after - before) > 1.0e-12_wp*max(abs(after), abs(before))
      end function is_kink
   end subroutine curve_kinks_about

   !> The table interval k (1 <= k < n) that holds d > 0; the last one beyond
   !! the table (extrapolation along it).
   pure integer function table_interval(defl, d) result(k)
      real(wp), intent(in) :: defl(:), d
      k = bracket_index(defl, d)
   end function table_interval

   pure real(wp) function slope(c, k)
      type(loading_curve_t), intent(in) :: c
      integer, intent(in) :: k
      slope = (c%force(k + 1) - c%force(k))/(c%defl(k + 1) - c%defl(k))
   end function slope

   !> s**p for 0 <= s, p > 0 (0 at s = 0 without a logarithm of zero).
   pure real(wp) function pw(s, p)
      real(wp), intent(in) :: s, p
      pw = 0.0_wp
      if (s > 0.0_wp) pw = s**p
   end function pw
end module loading_curves
