!> Injury criteria of an acceleration history that users of today expect
!! beside the report's (issue 7; the report predates them): the Head
!! Injury Criterion over windows up to 15 and 36 ms, the Gadd Severity
!! Index, and the cumulative 3 ms clip of FMVSS 208 S6.3. Samples come one
!! accepted step at a time, a jump being two samples at one time, in one
!! of two forms (docs/injury.md):
!!
!! - add_motion(t, a, v): the point's acceleration VECTOR a (g) and its
!!   velocity v (g s) at t. Between two samples the velocity is the cubic
!!   Hermite interpolant of v and a at both ends, and the acceleration its
!!   derivative, a quadratic: the criteria integrate its magnitude |a(t)|
!!   by 3-point Gauss-Legendre, and the peak is the largest |a(t)| on it.
!!   The interpolant's error in v is O(h^4) and its acceleration integrates
!!   to v exactly over each step, so V and HIC converge at fourth order in
!!   the step h and the peak at third (issue 15, section 3; with linear
!!   pieces of |a| both converged at second order).
!! - add(t, a): the resultant a (g) alone, linear between samples
!!   (trapezoids): for a history known only by its samples.
!!
!! Memory and cost do not grow with the number of steps beyond what the
!! criteria need.
!!
!! - GSI = integral of a^2.5 dt (Gadd 1966).
!! - HIC = max over t1 < t2, t2 - t1 <= W, of (t2 - t1) [V(t2) - V(t1)]^2.5
!!   / (t2 - t1)^2.5, V the integral of a. V is exact at every point (the
!!   integral of the linear pieces); the window ends are the points of a
!!   grid of spacing h (10 kHz unless the caller says, the sampling of
!!   SAE J211 data), every pair of them within W: every window, not only
!!   the longest from each start. HIC^2 = dV^5/dt^3 is compared, which
!!   needs no power; the window lengths go in blocks, each skipped when
!!   its bound (its longest window's dV over its shortest window's dt)
!!   cannot beat the best, and the windows shorter than m_cut are not
!!   looked at: with D the largest grid increment of V so far, a window
!!   of m steps has dV <= m D, so HIC^2 <= D^5 (m h)^2 / h^5, which cannot
!!   beat the best below m_cut (search_cut).
!! - The 3 ms clip: the level L that a(t) >= L for a cumulative 3 ms
!!   ("except for intervals whose cumulative duration is not more than
!!   3 milliseconds"); 0 when the history is shorter than 3 ms. It is
!!   measured on the linear pieces between samples in both forms (second
!!   order); the pieces above the level found so far are kept, since the
!!   level only rises as the history grows.
!! - The peak: the largest |a(t)| and its time.
module acceleration_criteria
   use kinds, only: wp
   use channel_record, only: hermite_acceleration
   implicit none
   private

   public :: acceleration_criteria_t, hic_result_t, criteria_new, hic_grid_default

   !> The window ends' grid spacing (s): 10 kHz.
   real(wp), parameter :: hic_grid_default = 1.0e-4_wp
   !> The cumulative duration of the clip (s).
   real(wp), parameter :: clip_duration = 3.0e-3_wp
   !> 3-point Gauss-Legendre on [0, 1]: nodes and weights.
   real(wp), parameter :: gl_node(3) = [0.5_wp - 0.5_wp*sqrt(0.6_wp), 0.5_wp, 0.5_wp + 0.5_wp*sqrt(0.6_wp)]
   real(wp), parameter :: gl_weight(3) = [5.0_wp/18.0_wp, 8.0_wp/18.0_wp, 5.0_wp/18.0_wp]
   !> The subintervals on which the peak of a step's |a(t)| is bracketed.
   integer, parameter :: peak_cells = 8

   !> A HIC and its window.
   type :: hic_result_t
      real(wp) :: value = 0.0_wp
      real(wp) :: t1 = 0.0_wp, t2 = 0.0_wp
   end type hic_result_t

   !> HIC over windows up to n_window grid steps.
   type :: hic_search_t
      integer :: n_window = 0
      real(wp) :: best2 = 0.0_wp                 !< the largest HIC^2 found
      integer :: k1 = 0, k2 = 0                  !< its window's grid points
   end type hic_search_t

   type :: acceleration_criteria_t
      logical :: started = .false.
      real(wp) :: h = hic_grid_default           !< the grid's spacing
      real(wp) :: t = 0.0_wp, a = 0.0_wp         !< the last sample
      !> the last sample's acceleration vector and velocity (add_motion)
      logical :: motion = .false.
      real(wp) :: a_vec(2) = 0.0_wp, v_vec(2) = 0.0_wp
      real(wp) :: peak = 0.0_wp, t_peak = 0.0_wp !< the largest |a| and its time
      real(wp) :: v = 0.0_wp                     !< V at the last sample
      real(wp) :: t0 = 0.0_wp                    !< the first sample's time (grid point 0)
      real(wp) :: gsi = 0.0_wp
      ! the grid: point k at t0 + k h, V there
      integer :: k = -1                          !< the last grid point reached
      !> the last n_buf grid points' V, oldest first in v_buf(p + 1 : p +
      !! n_buf): each written at p and p + n_buf, so that every window is one
      !! contiguous slice
      integer :: n_buf = 0, p = 0
      real(wp), allocatable :: v_buf(:)
      real(wp), allocatable :: inv_dt3(:)        !< 1/(m h)^3, m = 1 .. n_buf - 1
      real(wp) :: inv_h3 = 0.0_wp                !< 1/h^3
      real(wp) :: d_max = 0.0_wp                 !< the largest increment of V between grid points
      !> the windows search_cut proves short of the best are not looked at
      !! (.false.: all of them are, for the tests that compare the two)
      logical :: cut = .true.
      logical :: with_hic = .true.               !< the HIC searches (the head's)
      type(hic_search_t) :: hic(2)               !< 15 ms and 36 ms
      ! the clip: the linear pieces that reach above clip_floor
      real(wp) :: clip_floor = 0.0_wp
      real(wp) :: duration = 0.0_wp              !< of the whole history
      integer :: n_pieces = 0
      real(wp), allocatable :: piece(:, :)       !< (a at its start, a at its end, duration)
   contains
      procedure :: add => criteria_add
      procedure :: add_motion => criteria_add_motion
      procedure :: hic15 => criteria_hic15
      procedure :: hic36 => criteria_hic36
      procedure :: clip3ms => criteria_clip
   end type acceleration_criteria_t

contains

   !> Criteria with window ends on a grid of spacing h (s; default 10 kHz);
   !! with_hic false leaves out the HIC searches (GSI and clip only).
   pure function criteria_new(h, with_hic) result(c)
      real(wp), intent(in), optional :: h
      logical, intent(in), optional :: with_hic
      type(acceleration_criteria_t) :: c
      if (present(h)) c%h = h
      if (present(with_hic)) c%with_hic = with_hic
      call setup(c)
   end function criteria_new

   !> The buffers for the grid spacing c%h.
   pure subroutine setup(c)
      class(acceleration_criteria_t), intent(inout) :: c
      integer :: m
      c%hic(1)%n_window = nint(15.0e-3_wp/c%h)
      c%hic(2)%n_window = nint(36.0e-3_wp/c%h)
      c%n_buf = maxval(c%hic%n_window) + 1
      allocate (c%v_buf(0:2*c%n_buf - 1), c%piece(3, 256))
      c%v_buf = 0.0_wp
      c%p = c%n_buf - 1
      c%inv_dt3 = [(1.0_wp/(real(m, wp)*c%h)**3, m=1, c%n_buf - 1)]
      c%inv_h3 = 1.0_wp/c%h**3
   end subroutine setup

   !> One more sample: a (g, >= 0) at t (s, not before the last sample).
   pure subroutine criteria_add(this, t, a_in)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: t, a_in
      real(wp) :: dt, a
      logical :: first
      a = max(a_in, 0.0_wp)       ! (a resultant; V must not decrease)
      if (.not. allocated(this%v_buf)) call setup(this)
      this%motion = .false.
      call start(this, t, a, first)
      if (first) return
      dt = t - this%t
      if (.not. dt >= 0.0_wp) return                 ! (time does not go back)
      call raise_peak(this, a, t)
      call linear_piece(this, t, a, dt)
   end subroutine criteria_add

   !> The step from the last sample to (t, a), dt = t - this%t >= 0, with a
   !! linear between them (trapezoids).
   pure subroutine linear_piece(this, t, a, dt)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: t, a, dt
      real(wp) :: tk, ak
      this%gsi = this%gsi + 0.5_wp*dt*(gadd(this%a) + gadd(a))
      call add_piece(this, this%a, a, dt)
      ! the grid points this piece passes: V there from the linear piece
      do
         tk = this%t0 + real(this%k + 1, wp)*this%h
         if (tk > t) exit
         ak = this%a
         if (dt > 0.0_wp) ak = this%a + (a - this%a)*(tk - this%t)/dt
         call next_grid_point(this, this%v + 0.5_wp*(tk - this%t)*(this%a + ak))
      end do
      this%v = this%v + 0.5_wp*dt*(this%a + a)
      this%t = t
      this%a = a
   end subroutine linear_piece

   !> first: this is the first sample (taken here).
   pure subroutine start(this, t, a, first)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: t, a
      logical, intent(out) :: first
      first = .not. this%started
      if (.not. first) return
      this%started = .true.
      this%t0 = t
      this%t = t
      this%a = a
      this%k = -1
      call raise_peak(this, a, t)
      call next_grid_point(this, 0.0_wp)
   end subroutine start

   pure subroutine raise_peak(this, a, t)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: a, t
      if (a > this%peak) then
         this%peak = a
         this%t_peak = t
      end if
   end subroutine raise_peak

   !> One more sample of a point's motion: its acceleration vector a (g)
   !! and velocity v (g s, so that dv/dt = a) at t (s, not before the last
   !! sample). After a sample of add, or at the first, the step before is
   !! taken as linear in |a|.
   pure subroutine criteria_add_motion(this, t, a_vec, v_vec)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: t, a_vec(2), v_vec(2)
      real(wp) :: dt, c(2, 0:2), a, tk, s_peak, a_peak, m_step(3)
      integer :: i
      logical :: smooth, first
      a = hypot(a_vec(1), a_vec(2))
      smooth = this%motion
      if (.not. allocated(this%v_buf)) call setup(this)
      this%motion = .true.
      call start(this, t, a, first)
      if (.not. first) then
         dt = t - this%t
         if (.not. dt >= 0.0_wp) return              ! (time does not go back)
         call raise_peak(this, a, t)
         if (.not. (smooth .and. dt > 0.0_wp)) then
            ! a jump (two samples at one time), or no vector before
            call linear_piece(this, t, a, dt)
         else
            ! a(s) = c0 + c1 s + c2 s^2, s = (t' - t_last)/dt: the derivative
            ! of v's cubic Hermite interpolant on the step
            c = hermite_acceleration(this%a_vec, this%v_vec, a_vec, v_vec, dt)
            ! |a| at the step's Gauss nodes, for the GSI and for V at the step's end
            ! (quadrature's with x = 1, where x*node and r*x are exact: the
            ! magnitudes taken once for both)
            do i = 1, 3
               m_step(i) = magnitude(c, gl_node(i))
            end do
            this%gsi = this%gsi + dt*nodes_sum(m_step, .true.)
            call add_piece(this, this%a, a, dt)
            do
               tk = this%t0 + real(this%k + 1, wp)*this%h
               if (tk > t) exit
               call next_grid_point(this, this%v + dt*quadrature(c, (tk - this%t)/dt, .false.))
            end do
            this%v = this%v + dt*nodes_sum(m_step, .false.)
            call step_peak(c, s_peak, a_peak)
            ! (an interior peak only where it stands above the ends: not a
            ! rounding of a constant magnitude)
            if (a_peak > (1.0_wp + 1.0e-12_wp)*max(this%a, a)) call raise_peak(this, a_peak, this%t + s_peak*dt)
            this%t = t
            this%a = a
         end if
      end if
      this%a_vec = a_vec
      this%v_vec = v_vec
   end subroutine criteria_add_motion

   !> The integral over s in [0, x] of |c0 + c1 s + c2 s^2| (or of its
   !! 2.5th power when gsi; 3-point Gauss-Legendre).
   pure real(wp) function quadrature(c, x, gsi) result(r)
      real(wp), intent(in) :: c(2, 0:2), x
      logical, intent(in) :: gsi
      integer :: i
      real(wp) :: m(3)
      do i = 1, 3
         m(i) = magnitude(c, x*gl_node(i))
      end do
      r = nodes_sum(m, gsi)*x
   end function quadrature

   !> quadrature's weighted sum of the magnitudes m at its nodes (of their
   !! 2.5th powers when gsi), without its factor x.
   pure real(wp) function nodes_sum(m, gsi) result(r)
      real(wp), intent(in) :: m(3)
      logical, intent(in) :: gsi
      integer :: i
      r = 0.0_wp
      do i = 1, 3
         if (gsi) then
            r = r + gl_weight(i)*gadd(m(i))
         else
            r = r + gl_weight(i)*m(i)
         end if
      end do
   end function nodes_sum

   pure real(wp) function magnitude(c, s)
      real(wp), intent(in) :: c(2, 0:2), s
      real(wp) :: q(2)
      q = c(:, 0) + s*(c(:, 1) + s*c(:, 2))
      magnitude = hypot(q(1), q(2))
   end function magnitude

   !> The largest |a(s)| on the step's open interior, 0 < s < 1, and its s:
   !! |a|^2 is a quartic, so its slope 2 a.a' a cubic; a change of sign of
   !! the slope from + to - on one of peak_cells cells brackets a maximum,
   !! found by bisection (a_peak = 0 when there is none).
   pure subroutine step_peak(c, s_peak, a_peak)
      real(wp), intent(in) :: c(2, 0:2)
      real(wp), intent(out) :: s_peak, a_peak
      real(wp) :: lo, hi, mid, m, edge_slope(0:peak_cells)
      integer :: i, it
      s_peak = 0.0_wp
      a_peak = 0.0_wp
      ! (the slope at each cell's edge once: a cell's end is the next one's start)
      do i = 0, peak_cells
         edge_slope(i) = slope(real(i, wp)/peak_cells)
      end do
      do i = 1, peak_cells
         lo = real(i - 1, wp)/peak_cells
         hi = real(i, wp)/peak_cells
         if (.not. (edge_slope(i - 1) > 0.0_wp .and. edge_slope(i) <= 0.0_wp)) cycle
         do it = 1, 60
            mid = 0.5_wp*(lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            if (slope(mid) > 0.0_wp) then
               lo = mid
            else
               hi = mid
            end if
         end do
         m = magnitude(c, lo)
         if (m > a_peak) then
            a_peak = m
            s_peak = lo
         end if
      end do
   contains
      pure real(wp) function slope(s)
         real(wp), intent(in) :: s
         slope = dot_product(c(:, 0) + s*(c(:, 1) + s*c(:, 2)), c(:, 1) + 2.0_wp*s*c(:, 2))
      end function slope
   end subroutine step_peak

   !> a^2.5 (a >= 0).
   pure real(wp) function gadd(a)
      real(wp), intent(in) :: a
      gadd = a*a*sqrt(max(a, 0.0_wp))
   end function gadd

   !> Grid point k + 1 with V = v_k: the windows that end there.
   pure subroutine next_grid_point(this, v_k)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: v_k
      integer :: q, n, top, w, m_cut
      n = this%n_buf
      this%k = this%k + 1
      this%p = this%p + 1
      if (this%p == n) this%p = 0
      top = this%p + n
      this%v_buf(this%p) = v_k
      this%v_buf(top) = v_k
      if (.not. this%with_hic) return
      if (this%k > 0) this%d_max = max(this%d_max, v_k - this%v_buf(top - 1))
      do q = 1, size(this%hic)
         w = min(this%hic(q)%n_window, this%k)
         if (w < 1) cycle
         m_cut = 0
         if (this%cut) m_cut = search_cut(this%hic(q)%best2, this%d_max, this%inv_h3, w)
         call search_windows(this%hic(q), this%v_buf(top - w:top), this%inv_dt3, this%k, m_cut)
      end do
   end subroutine next_grid_point

   !> The windows of m <= m_cut steps cannot beat best2: V's stored grid
   !! values telescope, so dV <= m D exactly for a window of m steps (D the
   !! largest increment of them, computed; every rounding on the way is
   !! below 1e-14 of it), and HIC^2 = dV^5/(m h)^3 <= D^5 m^2/h^3. The
   !! margin of 1e-9 covers the roundings of the search's products and of
   !! this bound; a D^5/h^3 too small for relative roundings (below 1e-200),
   !! or not finite, cuts nothing. m_cut = w: no window can beat it.
   pure integer function search_cut(best2, d, inv_h3, w) result(m_cut)
      real(wp), intent(in) :: best2, d, inv_h3
      integer, intent(in) :: w
      real(wp) :: dd, q
      m_cut = 0
      if (.not. (d > 0.0_wp .and. best2 > 0.0_wp)) return
      if (.not. d < 1.0e50_wp) return          ! d**5 would overflow (and trap in the Debug build)
      dd = (d*d)*(d*d)*d*inv_h3
      if (.not. (dd > 1.0e-200_wp .and. dd <= huge(dd))) return
      q = best2/dd/(1.0_wp + 1.0e-9_wp)
      if (q >= real(w, wp)**2) then
         m_cut = w
      else
         m_cut = int(sqrt(q))
      end if
   end function search_cut

   !> The windows (k - m, k], m = m_cut + 1 .. w, against the best so far:
   !! v holds V at grid points k - w .. k (the shorter windows cannot beat
   !! it, search_cut: leaving them out changes no update, so the window
   !! found is that of m = 1 .. w). The windows go in blocks of hic_block
   !! lengths, each skipped when its bound (its longest window's dV over its
   !! shortest window's dt) cannot beat the best: in a plateau only the
   !! blocks near the best length are evaluated.
   pure subroutine search_windows(s, v, inv_dt3, k, m_cut)
      type(hic_search_t), intent(inout) :: s
      real(wp), intent(in) :: v(0:), inv_dt3(:)
      integer, intent(in) :: k
      integer, intent(in) :: m_cut          !< the windows up to m_cut steps cannot beat the best
      integer, parameter :: hic_block = 8
      real(wp) :: vk, x, r, r_best
      integer :: w, m, m_lo, m_hi, m_best
      w = size(v) - 1
      vk = v(w)
      r_best = s%best2
      m_best = 0
      do m_hi = w, m_cut + 1, -hic_block
         m_lo = max(m_cut + 1, m_hi - hic_block + 1)
         x = vk - v(w - m_hi)
         if (.not. (x*x)*(x*x)*x*inv_dt3(m_lo) > r_best) cycle
         do m = m_lo, m_hi
            x = vk - v(w - m)
            r = (x*x)*(x*x)*x*inv_dt3(m)
            if (r > r_best) then
               r_best = r
               m_best = m
            end if
         end do
      end do
      if (m_best == 0) return
      s%best2 = r_best
      s%k1 = k - m_best
      s%k2 = k
   end subroutine search_windows

   pure function criteria_hic15(this) result(r)
      class(acceleration_criteria_t), intent(in) :: this
      type(hic_result_t) :: r
      r = hic_of(this, 1)
   end function criteria_hic15

   pure function criteria_hic36(this) result(r)
      class(acceleration_criteria_t), intent(in) :: this
      type(hic_result_t) :: r
      r = hic_of(this, 2)
   end function criteria_hic36

   pure function hic_of(this, q) result(r)
      class(acceleration_criteria_t), intent(in) :: this
      integer, intent(in) :: q
      type(hic_result_t) :: r
      if (this%hic(q)%k2 == 0) return
      r%value = sqrt(this%hic(q)%best2)
      r%t1 = this%t0 + real(this%hic(q)%k1, wp)*this%h
      r%t2 = this%t0 + real(this%hic(q)%k2, wp)*this%h
   end function hic_of

   ! --- the 3 ms clip -----------------------------------------------------

   !> Keep the piece (a0 to a1 over dt) when it reaches above the floor;
   !! when the store is full, raise the floor to the clip of what is kept
   !! (the final clip cannot be lower) and drop what lies below it.
   pure subroutine add_piece(this, a0, a1, dt)
      class(acceleration_criteria_t), intent(inout) :: this
      real(wp), intent(in) :: a0, a1, dt
      real(wp), allocatable :: longer(:, :)
      integer :: i, n
      this%duration = this%duration + dt
      if (.not. (dt > 0.0_wp .and. max(a0, a1) > this%clip_floor)) return
      if (this%n_pieces == size(this%piece, 2)) then
         this%clip_floor = clip_level(this%piece(:, 1:this%n_pieces))
         n = 0
         do i = 1, this%n_pieces
            if (max(this%piece(1, i), this%piece(2, i)) > this%clip_floor) then
               n = n + 1
               this%piece(:, n) = this%piece(:, i)
            end if
         end do
         this%n_pieces = n
         if (n > size(this%piece, 2)/2) then
            allocate (longer(3, 2*size(this%piece, 2)))
            longer(:, 1:n) = this%piece(:, 1:n)
            call move_alloc(longer, this%piece)
         end if
         if (.not. max(a0, a1) > this%clip_floor) return
      end if
      this%n_pieces = this%n_pieces + 1
      this%piece(:, this%n_pieces) = [a0, a1, dt]
   end subroutine add_piece

   !> The 3 ms clip of the history so far (g).
   pure real(wp) function criteria_clip(this) result(level)
      class(acceleration_criteria_t), intent(in) :: this
      level = 0.0_wp
      if (.not. allocated(this%piece)) return
      if (this%duration < clip_duration) return
      level = max(this%clip_floor, clip_level(this%piece(:, 1:this%n_pieces)))
   end function criteria_clip

   !> The level L at which the pieces spend clip_duration at or above L
   !! (bisection: that time falls as L rises); 0 when they never do.
   pure real(wp) function clip_level(pieces) result(level)
      real(wp), intent(in) :: pieces(:, :)
      real(wp) :: lo, hi, mid
      integer :: it
      level = 0.0_wp
      if (size(pieces, 2) == 0) return
      if (time_above(pieces, 0.0_wp) < clip_duration) return
      lo = 0.0_wp
      hi = maxval(pieces(1:2, :))
      do it = 1, 200
         mid = 0.5_wp*(lo + hi)
         if (.not. (mid > lo .and. mid < hi)) exit
         if (time_above(pieces, mid) >= clip_duration) then
            lo = mid
         else
            hi = mid
         end if
      end do
      level = lo
   end function clip_level

   !> The time the linear pieces spend at or above level.
   pure real(wp) function time_above(pieces, level) result(t)
      real(wp), intent(in) :: pieces(:, :), level
      real(wp) :: a0, a1, lo, hi
      integer :: i
      t = 0.0_wp
      do i = 1, size(pieces, 2)
         a0 = pieces(1, i)
         a1 = pieces(2, i)
         lo = min(a0, a1)
         hi = max(a0, a1)
         if (lo >= level) then
            t = t + pieces(3, i)
         else if (hi > level) then
            t = t + pieces(3, i)*(hi - level)/(hi - lo)
         end if
      end do
   end function time_above
end module acceleration_criteria
