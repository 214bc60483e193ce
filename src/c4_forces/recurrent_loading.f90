!> Recurrent loading with residual (permanent) deformation: report C.4.e,
!! figure 18 (lost in the OCR; reconstructed in docs/loading.md 3), for the
!! belts and the contact surfaces and body regions of C.4.f, and the energy
!! split of C.6 as corrected by erratum E6-2 (docs/loading.md 4).
!!
!! A law is a loading curve F_e (loading_curves) with G, the ratio of
!! residual to maximum deformation, and R, the ratio of the energy conserved
!! to that absorbed (Tables 2 and 4). Cycle n has a residual deformation
!! eps_n (eps_1 = 0) and, with d = delta - eps_n:
!! - loading:   F_b = F_e(d);
!! - unloading, after the turning point (delta_max, F_max), d_max = delta_max
!!   - eps_n: F_b = F_e(xi d_max) xi**p, xi = (delta - delta_0)/(delta_max
!!   - delta_0), zero below delta_0 = eps_n + G d_max. It passes through
!!   (delta_max, F_max) and (delta_0, 0), never lies above the loading curve,
!!   and p >= 0 makes the energy it returns R times the loading work:
!!   (1 - G) M(d_max, p) = R E(d_max). That needs R <= 1 - G (recurrent_check);
!!   R = 1 - G gives p = 0 (the loading curve compressed into [delta_0,
!!   delta_max]); R = 1, G = 0 the loading curve itself (elastic); R = 0 a
!!   drop to zero force (plastic);
!! - a new cycle begins at the point x where d-dot goes from negative to
!!   positive (C.4.e). Case 1, the load was completely removed (delta_x <=
!!   delta_0): eps_{n+1} = delta_0. Case 2, it was not: eps_{n+1} = delta_x -
!!   F_e^-1(F_x), the loading curve shifted to pass through x. Either way the
!!   force is continuous at x.
!! The rate terms of the curve act while the branch carries load (F_b > 0);
!! the total max(0, F_b + F_v) never pulls.
!!
!! The memory (loading_memory_t) is read-only in recurrent_eval and
!! recurrent_rates, which the right-hand side calls at trial points; only
!! recurrent_accept changes it, from an accepted state, and it says when
!! the law changed so that the stepper restarts (docs/architecture.md,
!! rule 1).
!!
!! Energies (C.6; erratum E6-2 as revised in issue 14, docs/loading.md 4):
!! the stored energy of an element is a function of its deformation and its
!! memory (recurrent_stored): the area under the path its law returns
!! along from the present state down to zero force - the unloading curve
!! once the turning point is accepted, and until then the loading curve
!! itself, which a trial state past the peak retraces (the memory changes
!! only on accepted steps). The energy between the two curves is
!! dissipated where the law changes, at the accepted turning point, where
!! the stored energy drops: recurrent_accept adds the drop to the memory's
!! e_dissipated, and keeps the stored energy continuous where a new loading
!! branch begins. The work of the rate terms the effect integrates.
module recurrent_loading
   use kinds, only: wp
   use loading_parameters, only: recurrent_check, ratio_slack
   use loading_curves, only: loading_curve_t, curve_elastic_force, curve_value_slope, curve_rate_force, curve_energy, &
      curve_moment, curve_deflection_at, curve_flat_extent, curve_is_defined
   use model, only: materials_section_t, loading_section_t
   implicit none
   private

   public :: recurrent_law_t, loading_memory_t, loading_point_t
   public :: recurrent_law, recurrent_check, recurrent_is_elastic
   public :: recurrent_eval, recurrent_force, recurrent_accept, recurrent_stored, recurrent_rate_dissipation
   public :: unloading_exponent, material_law, belt_law
   public :: cycle_first, cycle_case_1, cycle_case_2

   !> How the present cycle began (figure 18).
   integer, parameter :: cycle_first = 0, cycle_case_1 = 1, cycle_case_2 = 2

   !> A recurrent-loading law: a curve, G and R (Tables 2, 4).
   type :: recurrent_law_t
      type(loading_curve_t) :: curve
      real(wp) :: g = 0.0_wp          !< residual / maximum deformation of a cycle
      real(wp) :: r = 1.0_wp          !< energy returned / energy absorbed
      logical :: elastic = .true.     !< R = 1 (and so G = 0): unloading retraces loading, no memory
      logical :: plastic = .false.    !< R = 0: unloading drops to zero force
      !> Of the curve, kept here because the belts' right-hand side needs them at
      !! every evaluation (recurrent_law sets them): the extent of its initial
      !! flat part (curve_flat_extent) and the highest rate term it has (0: none).
      real(wp) :: flat = 0.0_wp
      integer :: n_rate = 0
   end type recurrent_law_t

   !> The memory of one element (figure 18), changed only by recurrent_accept.
   type :: loading_memory_t
      integer :: cycle = 1                 !< n, the loading cycle
      integer :: began = cycle_first       !< how cycle n began: cycle_first, cycle_case_1 or _2
      logical :: unloading = .false.       !< past the turning point of cycle n
      real(wp) :: eps = 0.0_wp             !< eps_n, residual deformation: origin of the loading curve
      real(wp) :: delta_max = 0.0_wp       !< the turning point (maximum deformation of the cycle)
      real(wp) :: f_max = 0.0_wp           !< F_e(delta_max - eps_n), the force there
      !> the unloading curve's slope at delta_max: beyond it, until an accepted
      !! state reloads, the branch is the unloading curve's tangent there
      !! (unloading_tangent; issue 15)
      real(wp) :: s_max = 0.0_wp
      real(wp) :: delta_zero = 0.0_wp      !< eps_n + G (delta_max - eps_n): end of the unloading curve
      real(wp) :: p = 0.0_wp               !< exponent of the unloading curve
      real(wp) :: delta_x = 0.0_wp         !< where cycle n began (point x of figure 18)
      real(wp) :: f_x = 0.0_wp             !< the force there
      !> the part of the loading curve's area already counted as dissipated on
      !! the present loading branch: its stored energy is E(delta - eps_n) -
      !! e_spent (a cycle begun under load, case 2, or a loading taken up again
      !! beyond the turning point: what makes the stored energy continuous there)
      real(wp) :: e_spent = 0.0_wp
      !> the energy dissipated at the accepted changes of the law so far: the
      !! drops of the stored energy at turning points (docs/loading.md 4)
      real(wp) :: e_dissipated = 0.0_wp
      !> where the element last stopped: 0 at first, delta_max at a turning
      !! point, where a new cycle began. A gated element (the steering column,
      !! D-C19) is held there by its gate (series_split)
      real(wp) :: x_hold = 0.0_wp
   end type loading_memory_t

   !> The force at one (delta, delta-dot).
   type :: loading_point_t
      real(wp) :: force = 0.0_wp      !< total force, >= 0
      real(wp) :: branch = 0.0_wp     !< F_b, the rate-independent part (loading or unloading curve)
      logical :: loading = .false.    !< on a loading branch (counts towards E_abs while d-dot > 0)
   end type loading_point_t

contains

   !> The law of a curve with G and R that passed recurrent_check.
   pure function recurrent_law(curve, g, r) result(law)
      type(loading_curve_t), intent(in) :: curve
      real(wp), intent(in) :: g, r
      type(recurrent_law_t) :: law
      law%curve = curve
      law%g = g
      law%r = r
      law%elastic = r >= 1.0_wp - ratio_slack .and. g <= ratio_slack
      law%plastic = r <= 0.0_wp
      law%flat = curve_flat_extent(curve)
      law%n_rate = 0
      if (any(abs(curve%sigma_rate) > 0.0_wp)) law%n_rate = findloc(abs(curve%sigma_rate) > 0.0_wp, .true., 1, back=.true.)
   end function recurrent_law

   !> True when the law needs no memory (R = 1, G = 0).
   pure logical function recurrent_is_elastic(law)
      type(recurrent_law_t), intent(in) :: law
      recurrent_is_elastic = law%elastic
   end function recurrent_is_elastic

   !> The force at a trial state (delta, delta_dot) with the memory as it
   !! stands (docs/loading.md 3). Pure; the memory is not changed.
   pure function recurrent_eval(law, mem, delta, delta_dot) result(pt)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta, delta_dot
      type(loading_point_t) :: pt
      real(wp) :: xi
      if (law%elastic .or. .not. mem%unloading .or. (law%plastic .and. delta >= mem%delta_max)) then
         ! the loading curve of cycle n (a plastic law's beyond its turning point)
         pt%loading = .true.
         pt%branch = curve_elastic_force(law%curve, delta - mem%eps)
      else if (delta >= mem%delta_max) then
         pt%branch = unloading_tangent(mem, delta)
      else if (law%plastic .or. .not. delta > mem%delta_zero) then
         pt%branch = 0.0_wp
      else
         ! the unloading curve through (delta_zero, 0) and (delta_max, f_max)
         xi = (delta - mem%delta_zero)/(mem%delta_max - mem%delta_zero)
         pt%branch = curve_elastic_force(law%curve, xi*(mem%delta_max - mem%eps))
         if (mem%p > 0.0_wp) pt%branch = pt%branch*xi**mem%p
      end if
      ! the rate terms while the branch carries load; the sum never pulls
      pt%force = 0.0_wp
      if (pt%branch > 0.0_wp) pt%force = max(0.0_wp, pt%branch + curve_rate_force(law%curve, delta_dot))
   end function recurrent_eval

   !> The total force at a trial state (recurrent_eval's force).
   pure real(wp) function recurrent_force(law, mem, delta, delta_dot) result(f)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta, delta_dot
      type(loading_point_t) :: pt
      pt = recurrent_eval(law, mem, delta, delta_dot)
      f = pt%force
   end function recurrent_force

   !> The power the rate terms of a single element dissipate at (delta,
   !! delta_dot): (F - F_b) delta_dot >= 0 (the clip keeps F - F_b of the sign
   !! of delta_dot). A chain of several elements has its own (series_chain).
   pure real(wp) function recurrent_rate_dissipation(law, mem, delta, delta_dot) result(p)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta, delta_dot
      type(loading_point_t) :: pt
      pt = recurrent_eval(law, mem, delta, delta_dot)
      p = (pt%force - pt%branch)*delta_dot
   end function recurrent_rate_dissipation

   !> The energy the element stores at deformation delta with its memory
   !! (docs/loading.md 4): the area under the path its law returns along
   !! from delta down to zero force. On a loading branch that is the
   !! loading curve, E(delta - eps_n) - e_spent (the law changes only at an
   !! accepted turning point, so until then a state past the peak retraces
   !! the loading curve); on the unloading curve its area from delta_0 to
   !! delta, (span/d_max) xi**p M(xi d_max, p) with span = delta_max -
   !! delta_0 - (1 - G) M(d_max, p) = R E(d_max) at the turning point, 0 at
   !! delta_0 and below; beyond delta_max while unloading, that plus the
   !! loading curve's area from delta_max. 0 for a law without a curve.
   pure real(wp) function recurrent_stored(law, mem, delta) result(e)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta
      e = 0.0_wp
      if (.not. curve_is_defined(law%curve)) return
      if (law%elastic .or. .not. mem%unloading) then
         e = curve_energy(law%curve, delta - mem%eps) - mem%e_spent
      else if (delta >= mem%delta_max .and. law%plastic) then
         e = unloading_area(law, mem, mem%delta_max) + curve_energy(law%curve, delta - mem%eps) &
             - curve_energy(law%curve, mem%delta_max - mem%eps)
      else if (delta >= mem%delta_max) then
         ! the area under the tangent beyond delta_max (unloading_tangent)
         e = unloading_area(law, mem, mem%delta_max) + (delta - mem%delta_max)*(mem%f_max &
             + 0.5_wp*mem%s_max*(delta - mem%delta_max))
      else
         e = unloading_area(law, mem, delta)
      end if
   end function recurrent_stored

   !> Issue 15: the branch of an unloading element (not plastic) beyond its
   !! turning point, until an accepted state there returns it to its loading
   !! curve (recurrent_accept): the unloading curve's tangent at delta_max,
   !! f_max + s_max (delta - delta_max). Only a trial state gets there - a
   !! Runge-Kutta stage just after a located turn, a Newton iterate - since
   !! the driver locates the return at delta_max (loading_branch's
   !! branch_kinks); read as the loading curve, such a stage would cross the
   !! kink at delta_max (30 times the slope where a stiff structure unloads)
   !! inside the step. Linear, not the unloading curve itself, whose xi**p
   !! overflows far beyond xi = 1 for a large p.
   pure real(wp) function unloading_tangent(mem, delta) result(f)
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta
      f = mem%f_max + mem%s_max*(delta - mem%delta_max)
   end function unloading_tangent

   !> The area under the unloading curve from delta_0 to delta (delta <=
   !! delta_max): with v = t d_max, the integral of F_e(t d_max) t**p over
   !! t from 0 to xi, times span, is (span/d_max) xi**p M(xi d_max, p).
   pure real(wp) function unloading_area(law, mem, delta) result(e)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta
      real(wp) :: span, dm, xi
      e = 0.0_wp
      if (law%plastic .or. .not. delta > mem%delta_zero) return
      span = mem%delta_max - mem%delta_zero
      dm = mem%delta_max - mem%eps
      if (.not. (span > 0.0_wp .and. dm > 0.0_wp)) return
      xi = min((delta - mem%delta_zero)/span, 1.0_wp)
      e = span/dm*curve_moment(law%curve, xi*dm, mem%p)
      if (mem%p > 0.0_wp) e = e*xi**mem%p
   end function unloading_area

   !> After an ACCEPTED step: update the memory from the accepted state
   !! (figure 18; docs/loading.md 3). changed: the law is a different
   !! function from here on (a turning point, a new cycle), so the stepper
   !! must restart. The force is continuous at every change except the
   !! turning point of a plastic law (R = 0), where it drops to zero.
   !! Energy (docs/loading.md 4): the stored energy recurrent_stored is kept
   !! continuous where a new loading branch begins (e_spent); its drop at a
   !! turning point - the energy between the loading and the unloading curve
   !! - is added to e_dissipated.
   pure subroutine recurrent_accept(law, mem, delta, delta_dot, changed)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(inout) :: mem
      real(wp), intent(in) :: delta, delta_dot
      logical, intent(out) :: changed
      real(wp) :: fx, e_before
      changed = .false.
      if (law%elastic) return
      ! (the stored energy before a change: only where one may happen, it
      ! integrates the curve)
      if (.not. mem%unloading) then
         ! loading: the turning point, where d-dot becomes negative under load
         if (delta_dot < 0.0_wp) call turn(law, mem, delta, recurrent_stored(law, mem, delta), changed)
      else if (delta >= mem%delta_max) then
         ! back beyond the turning point within one step: on the loading curve again
         if (delta_dot < 0.0_wp) then
            call turn(law, mem, delta, recurrent_stored(law, mem, delta), changed)
         else if (delta_dot > 0.0_wp) then
            e_before = recurrent_stored(law, mem, delta)
            ! (its stored energy as before: the unloading curve's area to
            ! delta_max and the loading curve's beyond)
            mem%e_spent = curve_energy(law%curve, delta - mem%eps) - e_before
            mem%unloading = .false.
            changed = .true.
         end if
      else if (delta_dot > 0.0_wp) then
         ! point x: d-dot from negative to positive, a new cycle (C.4.e)
         e_before = recurrent_stored(law, mem, delta)
         if (delta <= mem%delta_zero) then
            ! case 1: the load was completely removed; the new cycle starts at
            ! the end of the unloading curve
            mem%began = cycle_case_1
            mem%f_x = 0.0_wp
            mem%eps = mem%delta_zero
         else
            ! case 2: under load; the loading curve shifted to pass through x
            fx = unloading_force(law, mem, delta)
            mem%began = cycle_case_2
            mem%f_x = fx
            mem%eps = delta - curve_deflection_at(law%curve, fx)
         end if
         mem%cycle = mem%cycle + 1
         mem%unloading = .false.
         mem%delta_x = delta
         mem%x_hold = max(delta, mem%eps)
         ! the stored energy as it was on the unloading curve (0 in case 1)
         mem%e_spent = curve_energy(law%curve, delta - mem%eps) - e_before
         changed = .true.
      end if
   end subroutine recurrent_accept

   !> The turning point of the cycle at delta, if the element is loaded
   !! there; e_before, its stored energy before: the drop is dissipated.
   pure subroutine turn(law, mem, delta, e_before, changed)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(inout) :: mem
      real(wp), intent(in) :: delta, e_before
      logical, intent(inout) :: changed
      real(wp) :: d, fm, fe, se
      integer :: seg
      d = delta - mem%eps
      fm = curve_elastic_force(law%curve, d)
      if (.not. fm > 0.0_wp) return
      mem%unloading = .true.
      mem%delta_max = delta
      mem%f_max = fm
      mem%delta_zero = mem%eps + law%g*d
      mem%p = unloading_exponent(law, d)
      ! the unloading curve's slope at xi = 1: (F_e'(d) d + F_e(d) p)/span
      mem%s_max = 0.0_wp
      if (.not. law%plastic .and. delta - mem%delta_zero > 0.0_wp) then
         seg = 0
         call curve_value_slope(law%curve, d, fe, se, seg)
         mem%s_max = (se*d + fm*mem%p)/(delta - mem%delta_zero)
      end if
      mem%x_hold = delta
      mem%e_spent = 0.0_wp
      mem%e_dissipated = mem%e_dissipated + (e_before - recurrent_stored(law, mem, delta))
      changed = .true.
   end subroutine turn

   !> The exponent p >= 0 of the unloading curve from a maximum deformation
   !! d of the cycle: (1 - G) M(d, p) = R E(d) (docs/loading.md 3). M falls
   !! from E(d) at p = 0 towards 0; bisection to rounding. huge for R = 0.
   pure real(wp) function unloading_exponent(law, d) result(p)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: d
      real(wp) :: target, lo, hi, mid
      integer :: it
      p = 0.0_wp
      if (law%plastic) then
         p = huge(1.0_wp)
         return
      end if
      if (law%elastic .or. law%r >= (1.0_wp - law%g)) return
      target = law%r/(1.0_wp - law%g)*curve_energy(law%curve, d)
      if (.not. target > 0.0_wp) return
      lo = 0.0_wp
      hi = 1.0_wp
      do it = 1, 2000
         if (curve_moment(law%curve, d, hi) <= target .or. hi > huge(1.0_wp)/4.0_wp) exit
         lo = hi
         hi = 2.0_wp*hi
      end do
      do it = 1, 2000
         mid = 0.5_wp*(lo + hi)
         if (.not. (mid > lo .and. mid < hi)) exit
         if (curve_moment(law%curve, d, mid) > target) then
            lo = mid
         else
            hi = mid
         end if
      end do
      p = 0.5_wp*(lo + hi)
   end function unloading_exponent

   !> The elastic force on the unloading curve at delta (delta_zero < delta < delta_max).
   pure real(wp) function unloading_force(law, mem, delta) result(f)
      type(recurrent_law_t), intent(in) :: law
      type(loading_memory_t), intent(in) :: mem
      real(wp), intent(in) :: delta
      type(loading_point_t) :: pt
      pt = recurrent_eval(law, mem, delta, 0.0_wp)
      f = pt%branch
   end function unloading_force

   !> The law of material l (Table 4): its curve (*MATERIALS CURVE), G and R.
   !! A material without a curve gives a law whose curve is not defined
   !! (loading_curves' curve_is_defined is false): it carries no force.
   pure function material_law(materials, loading, l) result(law)
      type(materials_section_t), intent(in) :: materials
      type(loading_section_t), intent(in) :: loading
      integer, intent(in) :: l
      type(recurrent_law_t) :: law
      type(loading_curve_t) :: none
      if (loading%material_curve(l) > 0) then
         law = recurrent_law(loading%curve(loading%material_curve(l)), materials%g(l), materials%r(l))
      else
         law = recurrent_law(none, materials%g(l), materials%r(l))
      end if
   end function material_law

   !> The law of belt section j (Table 2; *BELTLOADING): its curve, G and R.
   pure function belt_law(loading, j) result(law)
      type(loading_section_t), intent(in) :: loading
      integer, intent(in) :: j
      type(recurrent_law_t) :: law
      type(loading_curve_t) :: none
      if (loading%belt_curve(j) > 0) then
         law = recurrent_law(loading%curve(loading%belt_curve(j)), loading%belt_g(j), loading%belt_r(j))
      else
         law = recurrent_law(none, loading%belt_g(j), loading%belt_r(j))
      end if
   end function belt_law
end module recurrent_loading
