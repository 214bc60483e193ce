!> One contact pair of C.4.f as an effect (docs/contacts.md 3.1, D-C15):
!! body point i against surface k. Its normal force P comes from the
!! surface's materials through recurrent loading (Table 4, figure 18), a
!! chain of the body's material, the padding and what backs it (figures
!! 23-25, docs/contacts.md 3.4); the friction P' = mu P r (f.3, f.4) with r = v_T/xi clipped to
!! [-1, 1], v_T the sliding velocity of the body's material point along t:
!! the Coulomb force once the sliding reaches xi, in proportion to it below
!! (D-C18a, D-C22). The force P n - P' t acts at the contact point C, a
!! material point of the segment carrying the arc, so its generalized
!! forces are the virtual work J_C^T F (D-C23: the printed f.8 and its
!! errata F8-1..F8-6 are not needed). Memory (the loading cycle) changes
!! only on accepted steps. Energies (as the belts, docs/loading.md 4): per
!! element its stored energy from its deformation and memory and its
!! dissipated energy (booked by its memory, and its rate terms' work), the
!! friction's work P' v_T, and the work supplied by the
!! moving vehicle, S' = P (delta' + (J_C^T n) . z') - P' ((J_C^T t) . z' -
!! v_T), the power of the force at the surface's material point.
module contact_forces
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp, g_std, deg
   use strings, only: itoa, num
   use text_io, only: string_t, append_string
   use model, only: body_section_t, n_dof, arc_name
   use contact_tables, only: surface_name
   use effect_base, only: effect_t, body_state_t, kept_inputs_t, kept_set, kept_matches
   use effect_events, only: accept_result_t, accept_add_event
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds
   use point_forces, only: point_force_list_t, point_force_add
   use proximity_guard, only: proximity_guard_t, guard_none, guard_ball, guard_half_plane, guard_slab, guard_capsule, &
      guard_always
   use effect_peaks, only: effect_peak_t
   use contact_events, only: contact_event, event_undesired, event_shatter, event_cut, event_ramp_widened
   use output_series, only: output_series_t, series_new, column
   use body_kinematics, only: point_force_generalized
   use contact_geometry, only: contact_feature_t, contact_surface_t, contact_state_t, body_feature, contact_check, &
      arc_segment, front_side, shin_side_now, surface_flat, surface_line, surface_circle, surface_point, &
      region_switch_count, region_switches
   use contact_chain_switches, only: chain_switch_count, chain_take_up, chain_switch_values
   use recurrent_loading, only: recurrent_law_t
   use series_chain, only: series_chain_t, chain_split_t, chain_split, split_ok, chain_split_text, chain_new, &
      chain_accept, chain_energies, chain_n_aux, chain_set_initial, chain_relaxing, chain_stateful_any, max_chain, &
      chain_slack_split
   use dead_band, only: ramp_of
   implicit none
   private

   public :: contact_pair_effect_t, contact_pair_effect, pair_set_initial, pair_far, free_point_mass, pair_guard


   !> Everything about the pair at one state (pair_eval sets every field;
   !! no default values, which every evaluation would store first). The
   !! generalized forces of unit forces along n and t, J_C^T n and J_C^T t,
   !! are add_forces' own: no other caller reads them.
   type :: pair_state_t
      type(contact_feature_t) :: f             !< the body point (f.1) in the interior frame
      type(contact_state_t) :: cs
      type(chain_split_t) :: split
      real(wp) :: c_in(2), n_in(2), t_in(2)    !< C, n, t, inertial
      real(wp) :: p_t                          !< P', the friction force
   end type pair_state_t

   type, extends(effect_t) :: contact_pair_effect_t
      integer :: i = 0, k = 0
      type(body_section_t) :: body
      type(contact_surface_t) :: surface
      !> the elements in series: the body's material in front where Table 11
      !! shares the deflection (figure 23), then the surface's (Table 10): one,
      !! or a padding (or mat) that bottoms out at its cap eta D'' and its
      !! backing (figure 25, D-C19)
      integer :: n_elem = 1
      logical :: has_body = .false.            !< element 1 is the body's material
      !> the elements' laws and memories in series (series_chain): a padding's
      !! cap; the steering column gated, not moving until its padding has
      !! bottomed out (C.4.f, D-C19; its gate the padding's force at the cap)
      type(series_chain_t) :: chain
      !> D-C16a: the point came at a flat surface from behind its line; D-C16b:
      !! the panel's edge came at the shin from behind the shank's axis (memory)
      logical :: behind = .false.
      !> D-C16b, issue 15: the face of a solid met from inside (a flat
      !! surface's, the shin's far half) that acts, held from the last
      !! accepted state (contact_check's face; 0: none, the least depth)
      integer :: face = 0
      !> aux: the chain's (its elements' rate-term work and states), then the
      !! friction's work and the supplied work
      integer :: aux_friction = 0, aux_supplied = 0
      !> the outer material's friction (D-C22): mu P, reached at the sliding
      !! velocity xi and in proportion to it below (D-C18a)
      real(wp) :: mu = 0.0_wp, xi = 0.0_wp
      !> D-C18b: under a fixed step dt_fixed (0: an adaptive one) the ramp is
      !! never steeper than ramp_steps m_free/dt_fixed, m_free the contact
      !! point's effective mass as a free segment (a lower bound of the jointed
      !! body's); widened says it has been (reported once, an event)
      real(wp) :: dt_fixed = 0.0_wp, m_free = huge(1.0_wp)
      logical :: widened = .false.
      !> Table 9: a contact the end test NEND = 2 watches; it counts when the
      !! pair comes into contact at an accepted step, not when it is loaded
      !! at the start (D-C28)
      logical :: undesired = .false.
      logical :: accepted_once = .false., was_loaded = .false.
      !> the windshield (D-C24, D-C25): glass shatters at an accepted state
      !! whose P reaches fsw, and from then on carries nothing (its stored
      !! energy, released, is dissipated); a head through the broken glass is
      !! cut, once per episode of contact
      real(wp) :: fsw = 0.0_wp                  !< 0: never shatters
      logical :: shattered = .false., cutting = .false.
      !> issue 15: how many of the pair's switching functions are its chain's
      !! (contact_chain_switches) and its geometry's (contact_geometry's region_switches)
      integer :: n_chain_switch = 0, n_region_switch = 0
      !> the largest P over the accepted steps, when, and where (T and delta
      !! then): the summary's contact peaks (peaks)
      real(wp) :: peak_p = 0.0_wp, peak_t = 0.0_wp, peak_pos = 0.0_wp, peak_delta = 0.0_wp
      integer :: max_iter = 60
      !> add_forces returns at once, and accept takes its short path, where
      !! pair_far proves the pair slack (.false.: always the full path, for
      !! the tests that compare the two; an occupant's dispatch skips the
      !! pair where its proximity guard holds, D-C29, unless the guard's
      !! kind is set to guard_none too)
      logical :: exit_far = .true.
      !> the surface's e(psi) (for contact_check and front_side too: the
      !! same library call on the same angle, taken once) and normal, and for
      !! pair_far the sizes that scale its rounding margin (the body's
      !! lengths and radii, the surface's)
      real(wp) :: tk(2) = 0.0_wp, nk(2) = 0.0_wp, size_sum = 0.0_wp
      !> pair_eval at the evaluation that ended the step (add_forces_kept's
      !! full path), for accept, and the inputs it was computed from (issue
      !! 16 section 4: a cache, forgotten at every accept)
      type(pair_state_t) :: kept_ps
      type(kept_inputs_t) :: kept
   contains
      procedure :: add_forces => pair_add_forces
      procedure :: add_forces_kept => pair_add_forces_kept
      procedure :: accept => pair_accept
      procedure :: energy => pair_energy
      procedure :: outputs => pair_outputs
      procedure :: output_values => pair_output_values
      procedure :: chest_deflection => pair_chest_deflection
      procedure :: frame_values => pair_frame_values
      procedure :: point_forces => pair_point_forces
      procedure :: describe => pair_describe
      procedure :: failure_text => pair_failure_text
      procedure :: peaks => pair_peaks
      procedure :: initial_notes => pair_initial_notes
      procedure :: switches => pair_switches
   end type contact_pair_effect_t

   !> far_check's side where the bound does not decide it
   integer, parameter :: side_unknown = 2
   !> issue 15: a sliding velocity's switch compared with the take-up (in)
   !! over this time (s) (its sign is what matters)
   real(wp), parameter :: friction_time = 1.0e-3_wp


contains

   !> The pair (i, k) with surface sf (interior frame), the law of its
   !! material and its friction mu, xi (0: none).
   function contact_pair_effect(body, i, k, sf, law, mu, xi, undesired, fsw, backing, cap, body_law, gated, dt_fixed) &
      result(e)
      type(body_section_t), intent(in) :: body
      integer, intent(in) :: i, k
      type(contact_surface_t), intent(in) :: sf
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in), optional :: mu, xi
      logical, intent(in), optional :: undesired
      real(wp), intent(in), optional :: fsw
      type(recurrent_law_t), intent(in), optional :: backing   !< behind a padding that bottoms out
      real(wp), intent(in), optional :: cap                    !< the padding's bottoming depth eta D''
      type(recurrent_law_t), intent(in), optional :: body_law  !< the body's material (Table 11)
      logical, intent(in), optional :: gated                   !< the backing moves only once the padding is solid
      real(wp), intent(in), optional :: dt_fixed               !< the integrator's fixed step (D-C18b; absent: adaptive)
      type(contact_pair_effect_t) :: e
      type(recurrent_law_t) :: laws(3)
      real(wp) :: caps(3)
      logical :: gates(3)
      integer :: q
      e%name = 'contact_'//itoa(i)//'_'//itoa(k)
      e%title = 'contact '//itoa(i)//' on '//itoa(k)//' (C.4.f)'
      e%acts_on = .false.
      e%acts_on(arc_segment(i)) = .true.     ! its force acts on the body point's segment
      e%i = i
      e%k = k
      e%body = body
      e%surface = sf
      q = 0
      caps = 0.0_wp
      gates = .false.
      if (present(body_law)) then
         q = q + 1
         laws(q) = body_law
         e%has_body = .true.
         e%deflects_chest = i == 3          ! the chest's material, 12 (Table 11)
      end if
      q = q + 1
      laws(q) = law
      if (present(backing)) then
         if (present(cap)) caps(q) = cap
         q = q + 1
         laws(q) = backing
         if (present(gated)) gates(q) = gated
      end if
      e%n_elem = q
      e%chain = chain_new(laws(1:q), caps(1:q), gates(1:q), e%max_iter)
      if (present(mu)) e%mu = mu
      if (present(xi)) e%xi = xi
      if (present(dt_fixed)) e%dt_fixed = dt_fixed
      e%m_free = free_point_mass(body, i)
      if (present(undesired)) e%undesired = undesired
      if (present(fsw)) e%fsw = fsw
      ! issue 15: the take-up, the chain's, the friction ramp's edges, the
      ! glass's break, the geometry's (pair_switches)
      e%n_chain_switch = chain_switch_count(e%chain)
      e%n_region_switch = region_switch_count(i, sf)
      e%n_switch = 1 + e%n_chain_switch + e%n_region_switch
      e%reports_unchanged = .true.        ! (accept's far path, pair_accept_paths)
      if (e%mu > 0.0_wp) e%n_switch = e%n_switch + 2
      if (e%mu > 0.0_wp .and. e%dt_fixed > 0.0_wp) e%n_switch = e%n_switch + 1
      if (e%fsw > 0.0_wp) e%n_switch = e%n_switch + 1
      e%needs_vehicle = .true.
      e%needs_joints = .true.                          ! pair_far's bound
      e%external = .true.
      e%has_energy = .true.
      ! memory: the peak force (peaks) in every pair, and where they apply the
      ! loading cycles, the side a flat surface's pair came from (D-C16a), the
      ! windshield, Table 9's contacts and D-C18b's note
      e%has_memory = .true.
      e%keeps = .true.      ! (its accept takes pair_eval from the step's last evaluation)
      e%tk = [cos(sf%psi), sin(sf%psi)]
      e%nk = [-e%tk(2), e%tk(1)]
      e%size_sum = sum(abs(body%length)) + sum(abs(body%rho_arc)) + sum(abs(body%r_arc)) + abs(sf%s(1)) + &
               abs(sf%s(2)) + abs(sf%d)
      e%aux_friction = chain_n_aux(e%chain) + 1
      e%aux_supplied = e%aux_friction + 1
      e%n_aux = e%aux_supplied
      e%guard = pair_guard(e)
   end function contact_pair_effect

   !> The pair's proximity guard (D-C29, proximity_guard): cases of
   !! far_check's bound, with the same body point, the same reach less
   !! far_check's margin, and twice that margin (so where the guard holds
   !! far_check's bound holds, whatever the roundings of the two
   !! computations: a few ulps of the coordinates' size, against a margin
   !! of 1e-9 of it) - the point's circle farther than its radius from a
   !! circle or a point, in front of a line or of a flat surface's line
   !! (far whatever its extent), or, once the point has come from behind a
   !! flat surface (the memory behind, D-C16a), off its line on either side
   !! (a slab: accept and pair_set_initial keep the guard with the side);
   !! the shin's capsule from the panel's edge. Where add_forces would take
   !! its early exit for the other reason (a flat surface beyond its extent,
   !! the point behind it but not come from behind) the pair is dispatched
   !! as before. Broken glass: always. none for a radius below zero, which
   !! would turn the bound's margin round.
   pure function pair_guard(e) result(g)
      type(contact_pair_effect_t), intent(in) :: e
      type(proximity_guard_t) :: g
      real(wp) :: ext
      g%seg = arc_segment(e%i)
      g%size = e%size_sum
      g%centre = e%surface%s
      ext = 0.0_wp
      select case (e%i)               ! the body point, as far_check places it
      case (2, 3)
         ext = abs(e%body%rho_arc(e%i))
      case (4)
         g%along = e%body%rho_arc(4)
      case (6, 7, 8, 10)
         g%along = e%body%length(g%seg)
      case (9)
         g%along = e%body%length(8)
      end select
      if (e%i == 9) then
         g%kind = guard_capsule
         g%radius = max(e%body%r_arc(7), e%body%r_arc(11))
      else
         g%radius = e%body%r_arc(e%i) + ext
         select case (e%surface%kind)
         case (surface_circle)
            g%kind = guard_ball
            g%radius = g%radius + 0.5_wp*e%surface%d
         case (surface_point)
            g%kind = guard_ball
         case (surface_line)
            g%kind = guard_half_plane
            g%normal = e%nk
         case default                 ! a flat surface's line: in front, or either side if come from behind
            g%kind = merge(guard_slab, guard_half_plane, e%behind)
            g%normal = e%nk
         end select
      end if
      if (e%shattered) g%kind = guard_always
      if (.not. g%radius >= 0.0_wp) g%kind = guard_none
      ! a rate-dependent element's state moves out of contact too, while it
      ! recovers (series_chain): the pair's rates are not all zero there
      if (chain_stateful_any(e%chain)) g%kind = guard_none
   end function pair_guard

   !> The contact's geometry (figure 22), force split and friction at st
   !! (a subroutine: the state is written in place, not copied out of a
   !! function's result; the virtual work is add_forces').
   pure subroutine pair_eval(this, st, aux, ps)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: aux(:)              !< the pair's (the chain's states)
      type(pair_state_t), intent(out) :: ps
      real(wp) :: c, s
      call pair_geometry(this, st, ps, c, s)
      ! delta <= 0 is slack: the split gives no force (a contact never pulls);
      ! broken glass carries nothing (D-C24)
      if (this%shattered) then
         call chain_split(this%chain, -1.0_wp, 0.0_wp, aux, ps%split)
      else
         call chain_split(this%chain, ps%cs%delta, ps%cs%delta_dot, aux, ps%split)
      end if
      ps%c_in = st%vehicle%pos(1:2) + [c*ps%cs%c(1) + s*ps%cs%c(2), -s*ps%cs%c(1) + c*ps%cs%c(2)]
      ps%n_in = [c*ps%cs%n(1) + s*ps%cs%n(2), -s*ps%cs%n(1) + c*ps%cs%n(2)]
      ps%t_in = [c*ps%cs%t(1) + s*ps%cs%t(2), -s*ps%cs%t(1) + c*ps%cs%t(2)]
      ps%p_t = 0.0_wp
      if (.not. ps%split%force > 0.0_wp) return
      ! friction (f.3, f.4, D-C18a): P' = mu P along the sliding velocity v_T
      ! once it reaches xi, in proportion to it below
      ps%p_t = this%mu*ps%split%force*ramp_of(ramp_width(this, ps%split%force), ps%cs%v_t)
   end subroutine pair_eval

   !> A pair's geometry (pair_eval's first part; alone on the slack pairs'
   !! switches' path): the body point (f.1) and figure 22's check at st into
   !! ps%f, ps%cs; c, s: the vehicle's pitch's cosine and sine.
   pure subroutine pair_geometry(this, st, ps, c, s)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      type(pair_state_t), intent(inout) :: ps
      real(wp), intent(out) :: c, s
      ! (a pitch of zero, the sled's, needs no library call: cos 0 = 1, sin 0 = 0)
      c = 1.0_wp
      s = st%vehicle%pos(3)
      if (abs(st%vehicle%pos(3)) > 0.0_wp) then
         c = cos(st%vehicle%pos(3))
         s = sin(st%vehicle%pos(3))
      end if
      ps%f = body_feature(this%body, st%z, st%zdot, st%vehicle%pos, st%vehicle%vel, this%i, st%c, st%s, c, s)
      ps%cs = contact_check(ps%f, this%surface, this%behind, this%tk, this%face)
   end subroutine pair_geometry

   !> D-C18b: a lower bound of the effective mass of body point i's contact
   !! point: that of the point on its segment as a free body, 1/(1/m +
   !! r**2/I), r the largest distance from the segment's centre of gravity to
   !! the point's arc (the shin: its capsule). The joints only constrain the
   !! segment, and a constraint never lowers a point's effective mass
   !! (Rayleigh's theorem), so the jointed body's is at least this.
   pure real(wp) function free_point_mass(body, i) result(m)
      type(body_section_t), intent(in) :: body
      integer, intent(in) :: i
      real(wp) :: d, r, g
      integer :: sg
      sg = arc_segment(i)
      g = body%rho(sg)                       ! the centre of gravity, along the axis from the joint
      r = body%r_arc(i)
      select case (i)
      case (2, 3)                            ! rho'_i at gamma_i from the torso line
         d = norm2(body%rho_arc(i)*[cos(body%gamma_arc(i)), sin(body%gamma_arc(i))] - [g, 0.0_wp])
      case (4)
         d = abs(body%rho_arc(4) - g)
      case (6, 7, 8, 10)                     ! the segment's far end
         d = abs(body%length(sg) - g)
      case (9)                               ! the shin: from the knee to the ankle
         d = max(g, abs(body%length(8) - g))
         r = max(body%r_arc(7), body%r_arc(11))
      case default                           ! hip, shoulder: the joint
         d = g
      end select
      m = huge(1.0_wp)
      if (body%mass(sg) > 0.0_wp .and. body%inertia(sg) > 0.0_wp) &
         m = 1.0_wp/(1.0_wp/body%mass(sg) + (d + abs(r))**2/body%inertia(sg))
   end function free_point_mass

   !> D-C18b: the ramp's width at normal force p. Below xi the ramp is a
   !! damper mu p/xi on the body part, whose rate mu p/(xi m) a fixed step
   !! must resolve (RK4 is stable to 2.8/dt): under a fixed step the width
   !! is at least mu p dt/(ramp_steps m_free), m_free <= the point's
   !! effective mass, so that the damper's rate times the step stays below
   !! ramp_steps for this pair (pairs loaded at once on one body part add
   !! their rates: docs/contacts.md D-C18b) (2: RK4's limit with a margin; Adams-Moulton held too, the
   !! bound's mass being low). Continuous in p; xi itself where it is wider
   !! (with xi = 0, the bare Coulomb sign, only under an adaptive step),
   !! and always under an adaptive step, whose error control limits the
   !! step instead. (With the deck's xi of 0.1 in/s RK4 gave the default
   !! deck a HIC15 of 897 against Dormand-Prince's 460; widened, 460.)
   pure real(wp) function ramp_width(this, p) result(w)
      class(contact_pair_effect_t), intent(in) :: this
      real(wp), intent(in) :: p
      w = this%xi
      if (this%dt_fixed > 0.0_wp) w = max(w, widened_width(this, p))
   end function ramp_width

   !> D-C18b: the width a fixed step needs at normal force p, mu p
   !! dt/(ramp_steps m_free) (ramp_width).
   pure real(wp) function widened_width(this, p) result(w)
      class(contact_pair_effect_t), intent(in) :: this
      real(wp), intent(in) :: p
      real(wp), parameter :: ramp_steps = 2.0_wp
      w = this%mu*p*this%dt_fixed/(ramp_steps*this%m_free)
   end function widened_width

   !> Whether the pair is slack at st for certain, by a bound that needs
   !! neither trigonometry nor velocities: the body point's circle (for the
   !! upper back and chest, whose centre is within rho'_i of the segment's
   !! joint, the circle of radius r_i + rho'_i about the joint; for the
   !! shin, the capsule within max(r_7, r_A) of the knee-ankle segment) is
   !! farther than its radius from the surface by more than a margin of
   !! 1e-9 of the coordinates' size, far above the rounding of either
   !! computation. Then contact_check's delta is negative whatever primitive
   !! acts (a corner of a flat surface or of its opening lies on the
   !! surface's line, so its distance is at least the line's; a flat surface
   !! acts with its face only over its extent and from in front, unless the
   !! point came from behind, D-C16a), so chain_split clears the chain and
   !! the full path gives no force and zero rates: the memory (the loading
   !! cycle, the side) plays no part there.
   !! Broken glass carries nothing at any state. Not taken (.false.) when
   !! the rates or coordinates are not finite or beyond 1e100, where the
   !! full path's delta' could be non-finite and fail the split. st carries
   !! the interior frame's data (occupant_frame: the pair needs_joints).
   pure logical function pair_far(this, st) result(far)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      integer :: side
      call far_check(this, st, far, side)
   end function pair_far

   !> pair_far's bound (far), and where it is far what front_side would
   !! answer at st (D-C16a, D-C16b; accept's short path needs it): 0 for a
   !! surface that is neither flat nor the shin's edge, +1 where the flat
   !! surface is far because the point is clearly in front of its line, -1
   !! where it is clearly behind it (and at least r beyond its extent, or it
   !! came from behind), side_unknown where the bound does not decide it
   !! (broken glass). The bound's margins decide the side: for a flat
   !! surface far with h > reach = r + rho' + m (rho' for the arcs 2, 3
   !! whose centre is within rho' of the joint, else 0) and h > rho' + m
   !! (which follows for r >= 0), the centre's own h is above r, so
   !! front_side's first test holds and gives +1; with h < -reach and h <
   !! -(rho' + m) the centre is behind the line (h < 0) and either beyond the
   !! extent by more than reach (T below -reach or above D + reach, so the
   !! centre's T at least r beyond it: front_side gives -1) or come from
   !! behind (front_side gives -1 or 0, and 0 keeps the side that is
   !! behind): the memory becomes, or stays, behind. For the shin, far means
   !! off the capsule, where front_side gives the side of the shank's axis
   !! the edge is on: decided where the edge is more than the margin from
   !! the axis. The margin m, 1e-9 of the coordinates' size, covers the
   !! roundings, as for far.
   pure subroutine far_check(this, st, far, side)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      logical, intent(out) :: far
      integer, intent(out) :: side
      real(wp), parameter :: big = 1.0e100_wp, rel_margin = 1.0e-9_wp
      real(wp) :: d(2), jt(2), et(2), p(2), v(2), ext, reach, scale, m, h, tt, u2, lam
      integer :: seg
      far = this%shattered
      side = side_unknown
      if (far) return
      if (.not. st%rate_size <= big) return
      seg = arc_segment(this%i)
      ! the segment's proximal joint and direction in the interior frame
      ! (occupant_frame, once per evaluation)
      jt = st%frame_joint(:, seg)
      et = st%frame_axis(:, seg)
      scale = this%size_sum + st%joint_size(seg)
      if (.not. scale <= big) return
      m = rel_margin*(1.0_wp + scale)
      ext = 0.0_wp
      select case (this%i)
      case (2, 3)                     ! within rho'_i of the joint
         p = jt
         ext = abs(this%body%rho_arc(this%i))
      case (4)
         p = jt + this%body%rho_arc(4)*et
      case (6, 7, 8, 10)
         p = jt + this%body%length(seg)*et
      case (9)                        ! the shin against the edge: distance to the knee-ankle segment
         v = this%body%length(8)*et
         u2 = dot_product(v, v)
         d = this%surface%s - jt
         lam = 0.0_wp
         if (u2 > 0.0_wp) lam = min(1.0_wp, max(0.0_wp, dot_product(d, v)/u2))
         d = d - lam*v
         reach = max(this%body%r_arc(7), this%body%r_arc(11)) + m
         far = dot_product(d, d) > reach*reach
         ! off the capsule: front_side's side of the shank's axis the edge is
         ! on (D-C16b), where the margin decides it
         if (far) then
            h = dot_product(this%surface%s - jt, [-et(2), et(1)])
            if (h > m) side = 1
            if (h < -m) side = -1
         end if
         return
      case default                    ! hip, shoulder: the joint itself
         p = jt
      end select
      reach = this%body%r_arc(this%i) + ext + m
      select case (this%surface%kind)
      case (surface_circle, surface_point)
         if (this%surface%kind == surface_circle) reach = reach + 0.5_wp*this%surface%d
         d = p - this%surface%s
         far = dot_product(d, d) > reach*reach
         side = 0
      case (surface_line)
         far = dot_product(p - this%surface%s, this%nk) > reach
         side = 0
      case default                    ! flat: the face from in front, corners on its line
         h = dot_product(p - this%surface%s, this%nk)
         far = h > reach
         if (far) then                ! clearly in front (D-C16a)
            if (h > ext + m) side = 1
            return
         end if
         if (.not. abs(h) > reach) return
         tt = dot_product(this%surface%s - p, this%tk)
         ! come from behind: the ends, on the line; else the solid met from
         ! inside (D-C16b), whose ends' walls reach r beyond them
         far = this%behind .or. tt < -reach .or. tt > this%surface%d + reach
         if (far .and. h < -(ext + m)) side = -1   ! clearly behind (D-C16a)
      end select
   end subroutine far_check

   pure subroutine pair_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate))
      end associate
      if (this%exit_far) then
         if (pair_far(this, st)) then
            ! what the full path gives a slack pair: no force, no work; a
            ! rate-dependent element recovering at its damper's rate
            aux_rate = 0.0_wp
            if (chain_relaxing(this%chain, aux)) call slack_rates(this, aux, aux_rate)
            return
         end if
      end if
      call pair_add_full(this, st, aux, b, aux_rate)
   end subroutine pair_add_forces

   !> The rates of a slack pair's auxiliary quantities (pair_eval's split
   !! with no contact): its rate-dependent elements' states recovering.
   pure subroutine slack_rates(this, aux, aux_rate)
      class(contact_pair_effect_t), intent(in) :: this
      real(wp), intent(in) :: aux(:)
      real(wp), intent(inout) :: aux_rate(:)
      type(chain_split_t) :: sp
      call chain_split(this%chain, -1.0_wp, 0.0_wp, aux, sp)
      if (sp%status /= split_ok) then
         aux_rate = ieee_value(0.0_wp, ieee_quiet_nan)
         return
      end if
      aux_rate(1:this%aux_friction - 1) = sp%aux_rate(1:this%aux_friction - 1)
   end subroutine slack_rates

   !> add_forces' full path (its own procedure: the pair's state is not
   !! set up on the early exit).
   pure subroutine pair_add_full(this, st, aux, b, aux_rate)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: aux_rate(:)
      type(pair_state_t) :: ps
      real(wp) :: b_n(n_dof), b_t(n_dof)
      call pair_eval(this, st, aux, ps)
      if (ps%split%status /= split_ok) then
         aux_rate = ieee_value(0.0_wp, ieee_quiet_nan)
         return
      end if
      aux_rate(1:this%aux_friction - 1) = ps%split%aux_rate(1:this%aux_friction - 1)
      aux_rate(this%aux_friction:this%aux_supplied) = 0.0_wp
      if (.not. ps%split%force > 0.0_wp) return
      ! J_C^T n and J_C^T t, the generalized forces of unit forces at C (D-C23)
      ! C.4.f: P along the surface's normal and the friction P_t along its
      ! tangent, as generalized forces J_C^T n, J_C^T t (errata D-C23); the
      ! work the friction dissipates and the moving surface supplies (C.6
      ! with E6-2, docs/contacts.md 4.7), as pair_add_forces
      b_n = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%n_in)
      b_t = 0.0_wp
      if (abs(ps%p_t) > 0.0_wp) b_t = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%t_in)
      b = b + ps%split%force*b_n - ps%p_t*b_t
      aux_rate(this%aux_friction) = ps%p_t*ps%cs%v_t
      ! the vehicle's work (C.6 with E6-2, docs/contacts.md 4.7: the surface moves with it):
      ! the force's power at the body's material point plus what the surface
      ! absorbs and dissipates
      aux_rate(this%aux_supplied) = ps%split%force*(ps%cs%delta_dot + dot_product(b_n, st%zdot)) &
                               - ps%p_t*(dot_product(b_t, st%zdot) - ps%cs%v_t)
   end subroutine pair_add_full

   !> pair_add_forces at the evaluation that ends a step (effect_t's
   !! add_forces_kept): the same bits, and on the full path pair_eval's
   !! state kept for accept, tagged by st and aux. (pair_add_full's lines
   !! written out again: with a second caller, the compiler no longer puts
   !! them in line in add_forces, at every evaluation; test_kept_accept
   !! compares the two.)
   subroutine pair_add_forces_kept(this, st, extra, aux, b, extra_rate, aux_rate)
      class(contact_pair_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(pair_state_t) :: ps
      real(wp) :: b_n(n_dof), b_t(n_dof)
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate))
      end associate
      if (this%exit_far) then
         if (pair_far(this, st)) then
            ! pair_add_forces' early exit (accept's short path needs nothing kept)
            aux_rate = 0.0_wp
            if (chain_relaxing(this%chain, aux)) call slack_rates(this, aux, aux_rate)
            return
         end if
      end if
      call pair_eval(this, st, aux, ps)
      this%kept_ps = ps
      call kept_set(this%kept, st, extra, aux)
      ! pair_add_full
      if (ps%split%status /= split_ok) then
         aux_rate = ieee_value(0.0_wp, ieee_quiet_nan)
         return
      end if
      aux_rate(1:this%aux_friction - 1) = ps%split%aux_rate(1:this%aux_friction - 1)
      aux_rate(this%aux_friction:this%aux_supplied) = 0.0_wp
      if (.not. ps%split%force > 0.0_wp) return
      b_n = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%n_in)
      b_t = 0.0_wp
      if (abs(ps%p_t) > 0.0_wp) b_t = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%t_in)
      b = b + ps%split%force*b_n - ps%p_t*b_t
      aux_rate(this%aux_friction) = ps%p_t*ps%cs%v_t
      aux_rate(this%aux_supplied) = ps%split%force*(ps%cs%delta_dot + dot_product(b_n, st%zdot)) &
                               - ps%p_t*(dot_product(b_t, st%zdot) - ps%cs%v_t)
   end subroutine pair_add_forces_kept

   !> D-C16a's memory of a flat surface's pair, and its proximity guard
   !! with it (D-C29: a slab once come from behind, else a half-plane).
   pure subroutine set_behind(this, behind)
      type(contact_pair_effect_t), intent(inout) :: this
      logical, intent(in) :: behind
      this%behind = behind
      if (this%guard%kind == guard_half_plane .or. this%guard%kind == guard_slab) &
         this%guard%kind = merge(guard_slab, guard_half_plane, behind .and. this%surface%kind == surface_flat)
   end subroutine set_behind

   !> Issue 15 (docs/contacts.md, "Switches (issue 15)"): the pair's
   !! switching functions at st, n_switch of them in g. 1: the take-up of
   !! its chain (in, contact_chain_switches: > 0 where it carries load; s = delta,
   !! or nothing for broken glass): the contact's onset and release. Then
   !! its chain's (chain_switch_values: the elements' table points and
   !! turning points, the padding's cap, the column's gate, a rate term's
   !! clip). Then, with friction, the ramp's edges v_T -/+ w (in/s, D-C18a:
   !! P' = mu P r, r = v_T/w clipped to [-1, 1], w the ramp's width, kinks
   !! at v_T = +/-w) where the pair is loaded, each max(v_T -/+ w, -take-up
   !! / friction_time) (positive where it is not, crossing zero there only
   !! with the take-up); under a fixed step, the ramp's widening (D-C18b:
   !! xi - mu P dt/(2 m_free), in/s, where the width stops being xi and the
   !! ramp's P' stops growing with P) on the ramp (gated by w - |v_T| too).
   !! Then the glass's break (D-C24): FSW - P (lb),
   !! where accept shatters it, -1 once broken. Then the geometry's
   !! (contact_geometry's region_switches: an edge rounded, a solid's faces,
   !! the shin's far half and its way out).
   pure subroutine pair_switches(this, st, extra, aux, g)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      type(pair_state_t) :: ps
      real(wp) :: s, s_dot, u, w
      integer :: j
      real(wp) :: c_pitch, s_pitch
      logical :: slack
      associate (u1 => size(extra))
      end associate
      ! issue 16 section 4: a pair pair_far proves slack (delta < 0 whatever
      ! the memory) with a chain without states needs no split: chain_split
      ! would give chain_slack_split's (the same bits); the geometry, which
      ! the switching functions' values read, is pair_eval's
      slack = .false.
      if (this%exit_far) then
         if (pair_far(this, st)) call chain_slack_split(this%chain, ps%split, slack)
      end if
      if (slack) then
         call pair_geometry(this, st, ps, c_pitch, s_pitch)
      else if (kept_matches(this%kept, st, extra, aux)) then
         ! (the evaluation that ended the step, or a step taken again, was
         ! at st and aux with the memory as it is: the same bits)
         ps = this%kept_ps
      else
         call pair_eval(this, st, aux, ps)
      end if
      s = ps%cs%delta
      s_dot = ps%cs%delta_dot
      if (this%shattered) then             ! (pair_eval's split: nothing carried)
         s = -1.0_wp
         s_dot = 0.0_wp
      end if
      u = chain_take_up(this%chain, s, aux)
      ! (never 0: at a take-up of 0 the chain carries nothing, the negative side)
      g(1) = u
      if (.not. abs(u) > 0.0_wp) g(1) = -tiny(1.0_wp)
      j = 1
      call chain_switch_values(this%chain, s_dot, ps%split, u, g(j + 1:j + this%n_chain_switch))
      j = j + this%n_chain_switch
      if (this%mu > 0.0_wp) then
         w = ramp_width(this, ps%split%force)
         g(j + 1) = max(ps%cs%v_t - w, -u/friction_time)
         g(j + 2) = max(ps%cs%v_t + w, -u/friction_time)
         j = j + 2
         if (this%dt_fixed > 0.0_wp) then
            ! D-C18b: the ramp widened for the step beyond xi, on the ramp
            j = j + 1
            g(j) = max(this%xi - widened_width(this, ps%split%force), -min(u/friction_time, w - abs(ps%cs%v_t)))
         end if
      end if
      if (this%fsw > 0.0_wp) then
         j = j + 1
         g(j) = -1.0_wp
         if (.not. this%shattered) g(j) = this%fsw - ps%split%force
         if (.not. abs(g(j)) > 0.0_wp) g(j) = -tiny(1.0_wp)     ! (P = FSW breaks it)
      end if
      call region_switches(ps%f, this%surface, this%behind, this%tk, u, g(j + 1:j + this%n_region_switch))
   end subroutine pair_switches

   !> D-C14 (7): a pair that starts deep in its surface - more than half its
   !! arc's radius, or loaded beyond the body's weight - is most likely a
   !! misplaced surface (a sign of PSI, a point given at the wrong end). So
   !! is one whose body point starts on a flat surface's far side, its
   !! centre behind the line within the surface's extent (issue 14: the seat
   !! back 2-8 in ahead of the hip, through the pelvis, started the hip
   !! "behind" it, D-C16a, with no force and no warning): every surface
   !! faces its occupant, and what lies behind its line over its extent is
   !! the interior's structure (seat, dashboard, floor, the glass and the
   !! outside), so nothing of the occupant starts there. Beyond the extent
   !! or in the rim's opening a point behind the line is legitimately
   !! behind (the passenger's hand in his lap, below the upper panel's line
   !! far behind its rear end), as is one that goes there during the run
   !! (docs/contacts.md D-C14 (7)).
   function pair_initial_notes(this, st, extra, aux) result(notes)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(string_t), allocatable :: notes(:)
      type(pair_state_t) :: ps
      real(wp) :: weight, h, tt
      associate (u1 => size(extra) + size(aux))
      end associate
      allocate (notes(0))
      call pair_eval(this, st, aux, ps)
      if (ps%split%status /= split_ok) return
      if (this%i /= 9 .and. this%surface%kind == surface_flat) then
         h = dot_product(ps%f%p - this%surface%s, this%nk)
         tt = dot_product(this%surface%s - ps%f%p, this%tk)
         if (h < 0.0_wp .and. tt >= 0.0_wp .and. tt <= this%surface%d .and. .not. (this%surface%t_open(2) > &
             this%surface%t_open(1) .and. tt > this%surface%t_open(1) .and. tt < this%surface%t_open(2))) then
            call append_string(notes, '*SURFACES surface '//itoa(this%k)//' ('//trim(surface_name(this%k))//')' &
               //placed_by(this%k)//': body point '//itoa(this%i)//' ('//trim(arc_name(this%i))//') starts on its ' &
               //'far side, its centre '//cents(-h)//' in behind the line (the surface faces the occupant, PSI = ' &
               //cents(this%surface%psi/deg)//' deg), within its extent (T = '//cents(tt)//' of D = ' &
               //cents(this%surface%d)//' in): the surface passes through the body; is it where it should be? ' &
               //'(docs/contacts.md D-C14)')
            return
         end if
      end if
      weight = g_std*sum(this%body%mass)
      ! (an arc of radius 0, a point, is judged by its force alone)
      if ((ps%f%r > 0.0_wp .and. ps%cs%delta > 0.5_wp*ps%f%r) .or. ps%split%force > weight) &
         call append_string(notes, '*SURFACES surface '//itoa(this%k)//' ('//trim(surface_name(this%k))//')' &
         //placed_by(this%k)//': body point '//itoa(this%i)//' ('//trim(arc_name(this%i))//') starts ' &
         //cents(ps%cs%delta)//' in into it, with a force of '//cents(ps%split%force)//' lb (half its arc''s ' &
         //'radius is '//cents(0.5_wp*ps%f%r)//' in, the body''s weight '//cents(weight)//' lb): is the ' &
         //'surface where it should be? (docs/contacts.md D-C14)')
   contains
      function cents(x) result(s)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: s
         s = num(anint(100.0_wp*x)/100.0_wp)
      end function cents

      !> The card whose fields place a surface that f.2's relations derive.
      function placed_by(k) result(s)
         integer, intent(in) :: k
         character(len=:), allocatable :: s
         select case (k)
         case (4, 11)
            s = ', placed by surface 2''s card'
         case (10, 30)
            s = ', placed by surfaces 10 and 8'
         case (12)
            s = ', placed by surface 6''s card'
         case (25)
            s = ', the edge of surface 5'
         case default
            s = ''
         end select
      end function placed_by
   end function pair_initial_notes

   !> The largest P over the accepted steps, with T and delta then (none
   !! when the pair never touched).
   function pair_peaks(this) result(p)
      class(contact_pair_effect_t), intent(in) :: this
      type(effect_peak_t), allocatable :: p(:)
      allocate (p(0))
      if (.not. this%peak_p > 0.0_wp) return
      p = [effect_peak_t(name=trim(this%name)//'_force', title=this%title, label='largest force P', unit='lb', &
                         value=this%peak_p, t=this%peak_t), &
           effect_peak_t(name=trim(this%name)//'_pos', title=this%title, label='  where: T', unit='in', &
                         value=this%peak_pos, t=this%peak_t), &
           effect_peak_t(name=trim(this%name)//'_delta', title=this%title, label='  penetration delta', unit='in', &
                         value=this%peak_delta, t=this%peak_t)]
   end function pair_peaks

   !> The loading cycle (figure 18) from the accepted deformation and rate;
   !! a changed law restarts the stepper. What was kept at the evaluation
   !! that ended the step is forgotten: the memory may change here.
   subroutine pair_accept(this, st, extra, aux, result)
      class(contact_pair_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      call pair_accept_paths(this, st, extra, aux, result)
      this%kept%valid = .false.
   end subroutine pair_accept

   !> pair_accept's short path, where the pair is far, or its full path.
   subroutine pair_accept_paths(this, st, extra, aux, result)
      class(contact_pair_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      logical :: far, behind_was, loaded_was, once_was
      integer :: side
      associate (u1 => size(extra))
      end associate
      if (this%exit_far) then
         ! slack for certain (pair_far) with its side decided: what the full
         ! path below does at no force, without the full geometry
         call far_check(this, st, far, side)
         ! (a rate-dependent element still loaded takes the full path: it
         ! recovers out of contact, its memory follows it, series_chain)
         if (far .and. side /= side_unknown .and. .not. chain_relaxing(this%chain, aux)) then
            behind_was = this%behind
            loaded_was = this%was_loaded
            once_was = this%accepted_once
            result%memory_unchanged = this%face == 0
            if (side /= 0) call set_behind(this, side < 0)   ! D-C16a, as front_side
            this%face = 0                                ! (no solid met from inside)
            if (this%undesired) then                     ! D-C28: not loaded
               this%was_loaded = .false.
               this%accepted_once = .true.
            end if
            ! (the side, the face and Table 9's flags are all the memory this
            ! path can change; the switching functions read the side)
            result%memory_unchanged = result%memory_unchanged .and. (this%behind .eqv. behind_was) &
                                      .and. (this%was_loaded .eqv. loaded_was) .and. (this%accepted_once .eqv. once_was)
            ! no force: the glass holds (D-C24; broken glass, whose cut needs
            ! delta, has side_unknown), and the loading cycle keeps its memory
            return
         end if
      end if
      call pair_accept_full(this, st, extra, aux, result)
   end subroutine pair_accept_paths

   !> accept's full path (its own procedure: the pair's state is not set
   !! up on the short path). The pair's state at st is the one kept at the
   !! evaluation that ended the step where that was at st and aux exactly
   !! (with the memory as it is: kept since the last accept), else
   !! pair_eval's: the same bits.
   subroutine pair_accept_full(this, st, extra, aux, result)
      class(contact_pair_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      type(pair_state_t) :: ps
      type(contact_state_t) :: cs
      logical :: changed
      integer :: side
      if (kept_matches(this%kept, st, extra, aux)) then
         ps = this%kept_ps
         this%accepts_reused = this%accepts_reused + 1
      else
         call pair_eval(this, st, aux, ps)
      end if
      ! D-C16a: the side of the surface's line the point is on, where it is decided
      side = front_side(ps%f, this%surface, this%tk)
      if (side /= 0) call set_behind(this, side < 0)
      ! D-C16b, issue 15: the face of a solid met from inside whose depth is
      ! least here acts from here on (a located switch, the step just past
      ! where two are as deep: the force's direction jumps, a restart)
      ! (from none or to none, the face whose depth is least acts either way)
      cs = contact_check(ps%f, this%surface, this%behind, this%tk)
      if (cs%face /= this%face .and. cs%face /= 0 .and. this%face /= 0) then
         this%face = cs%face
         result%restart = .true.
         call pair_eval(this, st, aux, ps)
      end if
      this%face = cs%face
      ! Table 9 (C.7): coming into contact (D-C28)
      if (this%undesired) then
         if (this%accepted_once .and. .not. this%was_loaded .and. ps%split%force > 0.0_wp) &
            call accept_add_event(result, contact_event(event_undesired, st%t, this%i, this%k, ps%split%force))
         this%was_loaded = ps%split%force > 0.0_wp
         this%accepted_once = .true.
      end if
      ! the windshield (D-C24, D-C25): shattered at an accepted state whose force
      ! reaches FSW (never by a trial state); then a head through it is cut
      if (this%fsw > 0.0_wp .and. .not. this%shattered .and. ps%split%force >= this%fsw) then
         this%shattered = .true.
         if (this%guard%kind /= guard_none) this%guard%kind = guard_always   ! broken glass carries nothing
         result%restart = .true.
         call accept_add_event(result, contact_event(event_shatter, st%t, this%i, this%k, ps%split%force, this%fsw))
      end if
      if (this%shattered) then
         if (ps%cs%delta > 0.0_wp .and. .not. this%cutting) &
            call accept_add_event(result, contact_event(event_cut, st%t, this%i, this%k, ps%cs%delta))
         this%cutting = ps%cs%delta > 0.0_wp
      end if
      ! D-C18b: the first accepted step at which the fixed step widened the ramp
      if (.not. this%widened .and. this%mu > 0.0_wp .and. ps%split%force > 0.0_wp) then
         if (ramp_width(this, ps%split%force) > this%xi) then
            this%widened = .true.
            call accept_add_event(result, contact_event(event_ramp_widened, st%t, this%i, this%k, &
                                                        ramp_width(this, ps%split%force), this%xi))
         end if
      end if
      if (ps%split%status == split_ok .and. ps%split%force > this%peak_p) then
         this%peak_p = ps%split%force
         this%peak_t = st%t
         this%peak_pos = ps%cs%pos
         this%peak_delta = ps%cs%delta
      end if
      ! out of contact the memory stays (as a slack belt's, belt_accept), but a
      ! rate-dependent element still recovering moves, and its memory with it
      if (ps%split%status /= split_ok) return
      if (.not. ps%cs%delta > 0.0_wp .and. .not. chain_relaxing(this%chain, aux)) return
      if (this%shattered) return
      call chain_accept(this%chain, ps%cs%delta, ps%cs%delta_dot, aux, changed, split=ps%split)
      result%restart = result%restart .or. changed
   end subroutine pair_accept_full

   pure subroutine pair_energy(this, st, extra, aux, e)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      type(pair_state_t) :: ps
      real(wp) :: ce(max_chain), de(max_chain)
      associate (u2 => size(extra))
      end associate
      call pair_eval(this, st, aux, ps)
      call chain_energies(this%chain, ps%split, aux, ce, de)
      e(energy_stored) = sum(ce(1:this%n_elem))
      e(energy_dissipated) = sum(de(1:this%n_elem)) + aux(this%aux_friction)
      e(energy_supplied) = aux(this%aux_supplied)
   end subroutine pair_energy

   !> At the initial state st (the occupant at z0 in the vehicle at rest at
   !! pitch phi0): D-C16a's side of a flat surface, the side of its line the
   !! point's centre starts on (a point that starts behind the line has not
   !! come through the face: it meets the ends only, as one that came from
   !! behind); D-C21's initial split, where the chain's rate-dependent
   !! elements start (their stored energy then the curves' energy at their
   !! deformations, D-C26).
   pure subroutine pair_set_initial(this, st)
      type(contact_pair_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      type(pair_state_t) :: ps
      real(wp) :: none(chain_n_aux(this%chain))
      none = 0.0_wp
      call chain_set_initial(this%chain, 0.0_wp)
      call pair_eval(this, st, none, ps)
      if (this%i == 9) then
         ! the shin: the side of the shank's axis the panel's edge starts on (D-C16b)
         call set_behind(this, shin_side_now(ps%f, this%surface%s) < 0)
      else if (this%surface%kind == surface_flat) then
         call set_behind(this, dot_product(ps%f%p - this%surface%s, this%nk) < 0.0_wp)
      end if
      ! (its penetration with that side: where the chain's states start)
      if (this%behind) call pair_eval(this, st, none, ps)
      if (ps%split%status /= split_ok .or. .not. ps%cs%delta > 0.0_wp) return
      call chain_set_initial(this%chain, ps%cs%delta)
   end subroutine pair_set_initial

   pure subroutine pair_point_forces(this, st, extra, aux, list)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      type(pair_state_t) :: ps
      associate (u1 => size(extra))
      end associate
      call pair_eval(this, st, aux, ps)
      if (.not. ps%split%force > 0.0_wp) return
      ! an arc centred on a joint (hip, shoulder, elbow, knee) passes its load on
      ! through the joint: no load across a bone (docs/contacts.md 4.3)
      call point_force_add(list, arc_segment(this%i), ps%c_in, ps%split%force*ps%n_in - ps%p_t*ps%t_in, &
                           across_bone=.not. any(this%i == [1, 5, 6, 7]), arc=this%i, surface=this%k, &
                           normal_force=ps%split%force)
   end subroutine pair_point_forces

   function pair_outputs(this) result(series)
      class(contact_pair_effect_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      allocate (series(3))
      series(1) = series_new('force', 'CONTACT '//itoa(this%i)//' ON SURFACE '//itoa(this%k)//' (C.4.F)', &
                             'normal force P, friction force P'' (along -t), penetration delta, its rate, the ' &
                             //'sliding velocity v_T and T, where along the surface it acts (docs/contacts.md)', 1)
      series(1)%col = [column('P', 'lb'), column('Pprime', 'lb'), column('delta', 'in'), column('delta_dot', 'in/s'), &
                       column('v_T', 'in/s'), column('T', 'in')]
      series(2) = series_new('energy', 'CONTACT '//itoa(this%i)//' ON SURFACE '//itoa(this%k)//': ENERGIES (C.6)', &
                             'stored CE and dissipated DE of the surface material (E6-2) and the friction, work ' &
                             //'supplied by the moving vehicle', 3)
      series(2)%col = [column('conserved', 'in*lb'), column('dissipated', 'in*lb'), column('supplied', 'in*lb')]
      series(3) = series_new('deflection', 'CONTACT '//itoa(this%i)//' ON SURFACE '//itoa(this%k) &
                             //': DEFLECTIONS (FIGURES 23-25)', 'the penetration delta shared (figure 23): the ' &
                             //'body''s deflection (Table 11 pairs), the surface''s outer element (padding, mat, ' &
                             //'glass, foam or the non-rigid surface) and what is behind a padding or mat (its ' &
                             //'backing, or the column''s stroke)', 3)
      series(3)%col = [column('body', 'in'), column('surface', 'in'), column('backing', 'in')]
   end function pair_outputs

   !> The chest's deflection on this surface (issue 18): the share of the
   !! shared deflection (figure 23, Table 11) the chest's material (12)
   !! takes at st (in), for the chest's body point (i = 3) only.
   pure real(wp) function pair_chest_deflection(this, st, extra, aux) result(d)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(pair_state_t) :: ps
      associate (u1 => size(extra))
      end associate
      d = 0.0_wp
      if (.not. this%deflects_chest) return
      call pair_eval(this, st, aux, ps)
      d = max(ps%split%x(1), 0.0_wp)
   end function pair_chest_deflection

   pure subroutine pair_output_values(this, item, st, extra, aux, values)
      class(contact_pair_effect_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      type(pair_state_t) :: ps
      real(wp) :: e(n_energy_kinds)
      integer :: first
      if (item == 1) then
         call pair_eval(this, st, aux, ps)
         values = [ps%split%force, ps%p_t, ps%cs%delta, ps%cs%delta_dot, ps%cs%v_t, ps%cs%pos]
      else if (item == 3) then
         ! the elements in series: [body,] surface [, backing] (figures 23-25)
         call pair_eval(this, st, aux, ps)
         values = 0.0_wp
         first = merge(2, 1, this%has_body)
         if (this%has_body) values(1) = ps%split%x(1)
         values(2) = ps%split%x(first)
         if (this%n_elem > first) values(3) = ps%split%x(first + 1)
      else
         call pair_energy(this, st, extra, aux, e)
         values = e
      end if
   end subroutine pair_output_values

   !> A print time's frame (effect_t's frame_values): the pair evaluated
   !! once for its energies, its three series, its generalized force and its
   !! point force, the same bits as pair_energy, pair_output_values,
   !! pair_add_forces and pair_point_forces each evaluating it. A pair
   !! pair_far proves slack, with a chain without states, takes
   !! chain_slack_split's split (pair_switches': the same bits in the fields
   !! read here, force, x, gate and status) on pair_eval's geometry: no
   !! force, no friction, and add_forces' early exit.
   pure subroutine pair_frame_values(this, st, extra, aux, e, values, at, width, gf, b, pf, list, sums, b_sum)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      real(wp), intent(inout) :: values(:)
      integer, intent(in) :: at(:), width(:)
      logical, intent(in) :: gf, pf, sums
      real(wp), intent(inout) :: b(n_dof), b_sum(n_dof)
      type(point_force_list_t), intent(inout) :: list
      type(pair_state_t) :: ps
      real(wp) :: ce(max_chain), de(max_chain), b_n(n_dof), b_t(n_dof), c_pitch, s_pitch
      logical :: far, slack
      integer :: first
      associate (u1 => size(extra))
      end associate
      far = .false.
      slack = .false.
      if (this%exit_far) far = pair_far(this, st)
      if (far) call chain_slack_split(this%chain, ps%split, slack)
      if (slack) then
         call pair_geometry(this, st, ps, c_pitch, s_pitch)
         ps%p_t = 0.0_wp
      else
         call pair_eval(this, st, aux, ps)
      end if
      ! pair_energy
      call chain_energies(this%chain, ps%split, aux, ce, de)
      e(energy_stored) = sum(ce(1:this%n_elem))
      e(energy_dissipated) = sum(de(1:this%n_elem)) + aux(this%aux_friction)
      e(energy_supplied) = aux(this%aux_supplied)
      ! pair_output_values
      if (wanted(1)) values(at(1) + 1:at(1) + width(1)) = [ps%split%force, ps%p_t, ps%cs%delta, ps%cs%delta_dot, &
                                                         ps%cs%v_t, ps%cs%pos]
      if (wanted(2)) values(at(2) + 1:at(2) + width(2)) = e
      if (wanted(3)) then
         associate (v => values(at(3) + 1:at(3) + width(3)))
            v = 0.0_wp
            first = merge(2, 1, this%has_body)
            if (this%has_body) v(1) = ps%split%x(1)
            v(2) = ps%split%x(first)
            if (this%n_elem > first) v(3) = ps%split%x(first + 1)
         end associate
      end if
      ! pair_add_forces (pair_add_full's b; a far pair adds nothing)
      if ((gf .or. sums) .and. .not. far .and. ps%split%status == split_ok .and. ps%split%force > 0.0_wp) then
         b_n = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%n_in)
         b_t = 0.0_wp
         if (abs(ps%p_t) > 0.0_wp) b_t = point_force_generalized(this%body, st%z, arc_segment(this%i), ps%c_in, ps%t_in)
         if (gf) b = b + ps%split%force*b_n - ps%p_t*b_t
         if (sums) b_sum = b_sum + ps%split%force*b_n - ps%p_t*b_t
      end if
      ! pair_point_forces
      if (pf .and. ps%split%force > 0.0_wp) &
         call point_force_add(list, arc_segment(this%i), ps%c_in, ps%split%force*ps%n_in - ps%p_t*ps%t_in, &
                              across_bone=.not. any(this%i == [1, 5, 6, 7]), arc=this%i, surface=this%k, &
                              normal_force=ps%split%force)
   contains
      pure logical function wanted(j)
         integer, intent(in) :: j
         wanted = .false.
         if (j <= size(at)) wanted = at(j) >= 0
      end function wanted
   end subroutine pair_frame_values

   function pair_describe(this) result(text)
      class(contact_pair_effect_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': surface at ('//num(this%surface%s(1), 7)//', '//num(this%surface%s(2), 7)//') in'
   end function pair_describe

   !> Why the last evaluation at this state failed ('' when it did not):
   !! the chain's split of the deflection (figure 23) found no force.
   pure function pair_failure_text(this, st, extra, aux) result(text)
      class(contact_pair_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      character(len=:), allocatable :: text
      type(pair_state_t) :: ps
      associate (u1 => size(extra))
      end associate
      text = ''
      call pair_eval(this, st, aux, ps)
      if (ps%split%status /= split_ok) text = trim(this%title)//': ' &
         //chain_split_text(ps%split, ps%cs%delta, ps%cs%delta_dot, this%max_iter)
   end function pair_failure_text
end module contact_forces
