!> Report C.4.d, the seat as a pair of non-rigid beams (figures 13 and 14,
!! reconstructed in docs/seat.md). A uniform beam of length l built in at
!! both ends (NB-1) carries the hip at z from its front end; a cantilever of
!! length k l, built in k l behind the front edge, carries the leg at its
!! tip (the front edge). e_1, e_2 are 3 E I of each (NB-1).
!!
!!   F*   = e_1 l^3 delta_A / (a^3 z^3)   hip-point stiffness K_1 of the built-in beam, a = l - z
!!   F*_s = e_2 delta_z / (k l)^3         tip stiffness K_2 of the cantilever
!!   F-hat = F* b/(2 k^3 l^3) delta_z/delta_A, b = z^3 - 3k^2l^2 z + 2k^3l^3 = c^2(2kl + z), c = kl - z:
!!          rho = b/(2 k^3 l^3) is the cantilever's deflection under the hip per unit tip deflection
!!
!! Reconstruction (docs/seat.md): the hip load reaches the cantilever through
!! the built-in beam, a spring K_1 in series with the cantilever's hip point,
!! which moves rho times its tip. The elastic energy
!!   U = 1/2 K_1 (delta_A - rho w)^2 + 1/2 K_2 w^2,  w >= delta_z (the leg holds the tip down)
!! gives the hip force F_s = K_1 (delta_A - rho w) = F* - F-hat (w = delta_z) and
!! the front force F'_s = K_2 w - rho F_s = F*_s - rho F_s. Its stiffness is
!! symmetric (Maxwell-Betti). The printed F-hat_s = 2 e_2 k l delta_A/(b c),
!! unverifiable (A-NB) and unbounded as the hip nears the cantilever's root,
!! is replaced by the reciprocal coupling rho F_s (erratum NB-3).
!!
!! delta_A = r_1 + d with d = y''_sc - y_1 + (x_1 - x''_sc) tan gamma_o (NB-2);
!! delta_z: the undeflected cushion line minus the leg's underside (the common
!! tangent of the hip and knee arcs, angle alpha_L, or of the knee and ankle
!! arcs, alpha_l) at the front edge. K_1 and rho change as the hip slides, so
!! the forces are not a gradient: "energy calculations must be done
!! incrementally": the work the body does on the seat is integrated.
!!
!! Figure 14's cases (the hip over beam 1, 0 <= z < l, or off it; the leg on
!! the front edge or not) are memory, decided on accepted steps as figure 12
!! (docs/seat.md, D-19); a trial evaluation past a switch keeps the case of
!! the last accepted step, with the stiffnesses of the nearest point of beam
!! 1. A beam that comes into action starts from its present deflection (its
!! reference, D-25), so its force does not jump up.
!!
!! Switches (issue 15; docs/seat.md "Switches (issue 15)"): figure 14's
!! case (z = 0 and z = l), the hip's force coming on or off (delta_A beyond
!! its reference reaching rho w), the leg taking the cantilever's tip over
!! from the hip (delta_z = w_free), beam 1's stiffness reaching its cap
!! (z = 0.05 l and 0.95 l), the hip passing the cantilever's root (z = k
!! l, where rho is C1 but its curvature jumps: an unlocated crossing cost
!! RK4 an order, 8.9 for 16 a halving in test_seat_switches_located_run),
!! the leg's branch and its resting on the edge, and the hip's sliding at
!! +-xi, held on an edge of its dead band (D-19a, seat_geometry's hip_slide).
module seat_beams
   use kinds, only: wp, deg
   use strings, only: num
   use model, only: n_dof, seat_section_t, body_section_t
   use effect_base, only: effect_t, body_state_t, slide_t
   use effect_events, only: accept_result_t
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds
   use point_forces, only: point_force_list_t
   use output_series, only: output_series_t, series_new, column
   use seat_geometry, only: hip_slide, hip_slide_switches, hip_sliding_decided, hip_released, &
      add_seat_point_forces, contact_reference, &
      seat_frame_t, seat_frame, leg_line_t, leg_line, leg_branch, leg_rests, leg_rest_margin, leg_branch_margin, &
      hip_friction, &
      slip_of, vehicle_power, add_hip_force, seg_thigh, seat_memory_t, rest_state, case_off, case_a
   implicit none
   private

   public :: seat_beams_t, seat_beams_effect, beams_stiffness, beams_forces, beams_state_t, beams_state
   public :: end_fraction, beams_case

   !> The hip beam's stiffness grows without bound at its built-in ends; it
   !! is taken no larger than at this fraction of l from either end.
   real(wp), parameter :: end_fraction = 0.05_wp

   type, extends(effect_t) :: seat_beams_t
      type(seat_section_t) :: p
      real(wp) :: l7 = 0.0_wp, l8 = 0.0_wp
      real(wp) :: r1 = 0.0_wp, r7 = 0.0_wp
      real(wp) :: alpha_l7 = 0.0_wp, alpha_l8 = 0.0_wp   !< alpha_L, alpha_l (C.4.d)
      !> figure 14's memory, decided on accepted steps: the case (case_a: the
      !! hip over beam 1; case_off), the leg on the edge, the hip sliding, the
      !! references of the hip's and the leg's deflections (D-25)
      type(seat_memory_t) :: mem
   contains
      procedure :: add_forces => beams_add_forces
      procedure :: accept => beams_accept
      procedure :: switches => beams_switches
      procedure :: slides => beams_slides
      procedure :: release => beams_release
      procedure :: point_forces => beams_point_forces
      procedure :: energy => beams_energy
      procedure :: outputs => beams_outputs
      procedure :: output_values => beams_output_values
      procedure :: describe => beams_describe
   end type seat_beams_t

   type :: beams_state_t
      type(seat_frame_t) :: fr
      type(leg_line_t) :: ln
      logical :: on = .false., leg = .false.
      real(wp) :: z = 0.0_wp, delta_a = 0.0_wp, delta_z = 0.0_wp
      real(wp) :: k1 = 0.0_wp, rho = 0.0_wp, k2 = 0.0_wp, w = 0.0_wp
      real(wp) :: g_hip = 0.0_wp, g_tip = 0.0_wp   !< beams_forces' switching functions (in)
      real(wp) :: f_s = 0.0_wp, fp_s = 0.0_wp, f = 0.0_wp
      real(wp) :: work_rate = 0.0_wp, dissipation = 0.0_wp, supply = 0.0_wp
   end type beams_state_t

contains

   function seat_beams_effect(p, body) result(e)
      type(seat_section_t), intent(in) :: p
      type(body_section_t), intent(in) :: body
      type(seat_beams_t) :: e
      type(seat_frame_t) :: fr
      e%name = 'seat'
      e%title = 'non-rigid beam seat (C.4.d)'
      e%p = p
      e%l7 = body%length(7)
      e%l8 = body%length(8)
      e%r1 = body%r_arc(1)
      e%r7 = body%r_arc(7)
      ! C.4.d: alpha_L = asin((r_1 - r_7)/L_7), alpha_l = asin((r_7 - r_A)/L_8)
      e%alpha_l7 = asin((body%r_arc(1) - body%r_arc(7))/body%length(7))
      e%alpha_l8 = asin((body%r_arc(7) - body%r_arc(11))/body%length(8))
      ! figure 14's memory from the initial posture: the hip at the interior
      ! origin, the segments at their interior angles Theta_i0 (the builder
      ! puts the hip on beam 1)
      fr = seat_frame(rest_state([body%theta0, 0.0_wp, 0.0_wp], 0.0_wp), e%l7)
      e%mem%case = beams_case(p%z0 - fr%x1, p%ell)
      e%mem%leg_on = e%mem%case /= case_off .and. leg_rests(fr, p%z0, e%l7, e%l8)
      e%mem%slip = 0
      e%n_aux = 3
      e%needs_vehicle = .true.
      e%external = .true.
      e%has_memory = .true.
      e%has_energy = .true.
      e%n_switch = 9
      if (p%mu > 0.0_wp) then
         ! the hip's sliding (issue 15, D-19a): its two switches, its constraint
         e%n_switch = e%n_switch + 2
         e%n_slide = 1
      end if
   end function seat_beams_effect

   !> Figure 14's case for the hip at z behind the front edge: over beam 1
   !! (case_a) for 0 <= z < l, else off the seat (case_off).
   pure integer function beams_case(z, ell)
      real(wp), intent(in) :: z, ell
      beams_case = case_off
      if (z >= 0.0_wp .and. z < ell) beams_case = case_a
   end function beams_case

   !> K_1 (hip-point stiffness of the built-in beam), rho (cantilever
   !! deflection under the hip per unit tip deflection) and K_2 (tip
   !! stiffness) with the hip at z behind the front edge (C.4.d with NB-1).
   !! Whether the hip is on beam 1 at all is figure 14's case (beams_case, on
   !! accepted steps); a hip just past an end within a step (z < 0 or z >= l)
   !! gets the stiffnesses of the end, so that they are continuous in z.
   pure subroutine beams_stiffness(ell, k, e1, e2, z, k1, rho, k2)
      real(wp), intent(in) :: ell, k, e1, e2, z
      real(wp), intent(out) :: k1, rho, k2
      real(wp) :: a, zz, zc, c, b
      zc = min(max(z, 0.0_wp), ell)
      zz = max(zc, end_fraction*ell)
      a = max(ell - zc, end_fraction*ell)
      k1 = e1*ell**3/(a**3*zz**3)              ! F*/delta_A
      c = k*ell - zc
      if (c > 0.0_wp) then
         b = zc**3 - 3.0_wp*k**2*ell**2*zc + 2.0_wp*k**3*ell**3   ! = c^2 (2 k l + z)
         rho = b/(2.0_wp*k**3*ell**3)
      else
         rho = 0.0_wp                          ! the hip is not over the cantilever
      end if
      k2 = e2/(k*ell)**3                       ! F*_s/delta_z
   end subroutine beams_stiffness

   !> The forces of the reconstruction: the tip deflection w minimizes U with
   !! w >= delta_z; F_s = K_1 (delta_A - rho w) >= 0, F'_s = K_2 w - rho F_s >= 0.
   !! Issue 15: the forces' kinks are where g_hip = delta_A - rho w (in)
   !! reaches 0 (F_s comes on; w_free's own kink at delta_A = 0 lies where
   !! F_s is 0 on both sides) and where g_tip = delta_z - w_free (in) does
   !! (the leg takes the tip over); F'_s's clip only guards rounding (K_2 w -
   !! rho F_s >= 0 for w >= w_free).
   pure subroutine beams_forces(k1, rho, k2, delta_a, delta_z, f_s, fp_s, w, g_hip, g_tip)
      real(wp), intent(in) :: k1, rho, k2, delta_a, delta_z
      real(wp), intent(out) :: f_s, fp_s, w
      real(wp), intent(out), optional :: g_hip, g_tip
      real(wp) :: w_free
      w_free = 0.0_wp
      if (delta_a > 0.0_wp) w_free = rho*k1*delta_a/(k2 + rho**2*k1)
      w = max(delta_z, w_free)
      f_s = k1*max(delta_a - rho*w, 0.0_wp)
      fp_s = max(k2*w - rho*f_s, 0.0_wp)
      if (present(g_hip)) g_hip = delta_a - rho*w
      if (present(g_tip)) g_tip = delta_z - w_free
   end subroutine beams_forces

   !> Figure 14 (reconstructed) at state st with memory mem: the case and
   !! the leg are mem's, whatever the geometry says within the step.
   pure function beams_state(this, st, mem) result(s)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      type(seat_memory_t), intent(in) :: mem
      type(beams_state_t) :: s
      real(wp) :: tg0, h_c, fh(2), fe(2)
      integer :: seg
      s%fr = seat_frame(st, this%l7)
      s%z = this%p%z0 - s%fr%x1
      s%on = mem%case /= case_off
      if (.not. s%on) return
      tg0 = tan(this%p%gamma0)
      ! NB-2: d, the cushion line's height at the hip minus y_1; delta_A = r_1 + d
      s%delta_a = this%r1 + this%p%y_sc - s%fr%y1 + (s%fr%x1 - this%p%x_sc)*tg0
      s%leg = mem%leg_on
      if (s%leg) then
         seg = leg_branch(s%fr, this%p%z0)
         if (seg == seg_thigh) then
            s%ln = leg_line(s%fr, seg, this%p%z0, this%r1, this%alpha_l7, this%l7)
         else
            s%ln = leg_line(s%fr, seg, this%p%z0, this%r7, this%alpha_l8, this%l7)
         end if
         h_c = this%p%y_sc + (this%p%z0 - this%p%x_sc)*tg0
         s%delta_z = h_c - s%ln%h
      else
         s%delta_z = -huge(1.0_wp)        ! nothing on the cantilever's tip
      end if
      call beams_stiffness(this%p%ell, this%p%k_ratio, this%p%e1, this%p%e2, s%z, s%k1, s%rho, s%k2)
      ! the deflections beyond their references (D-25)
      call beams_forces(s%k1, s%rho, s%k2, s%delta_a - mem%hip_ref, s%delta_z - mem%edge_ref, s%f_s, s%fp_s, s%w, &
                        s%g_hip, s%g_tip)
      if (.not. s%leg) s%fp_s = 0.0_wp
      s%f = hip_friction(this%p%mu, s%f_s + s%fp_s, mem%slip)
      ! the work the body does on the beams: F_s delta_A' + F'_s delta_z'
      s%work_rate = s%f_s*(-s%fr%y1dot + s%fr%x1dot*tg0)
      if (s%leg) s%work_rate = s%work_rate - s%fp_s*s%ln%h_dot
      s%dissipation = s%f*s%fr%x1dot
      fh = [-s%f_s*tg0 - s%f, s%f_s]
      fe = s%fp_s*[-s%ln%tan_phi, 1.0_wp]
      s%supply = vehicle_power(s%fr, fh, [s%fr%x1, s%fr%y1]) + vehicle_power(s%fr, fe, [this%p%z0, s%ln%h])
   end function beams_state

   pure subroutine beams_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(beams_state_t) :: s
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate))
      end associate
      s = beams_state(this, st, this%mem)
      aux_rate = 0.0_wp
      if (.not. s%on) return
      ! external generalized forces: the hip force normal to the cushion line,
      ! -F_s d delta_A/dz, the friction, and F'_s normal to the leg's underside
      call add_hip_force(s%fr, [-s%f_s*tan(this%p%gamma0) - s%f, s%f_s], b)
      b = b + s%fp_s*s%ln%dh
      aux_rate = [s%work_rate, s%dissipation, s%supply]
   end subroutine beams_add_forces

   !> The hip force and F'_s normal to the leg, as point forces.
   pure subroutine beams_point_forces(this, st, extra, aux, list)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      type(beams_state_t) :: s
      associate (u1 => size(extra) + size(aux))
      end associate
      s = beams_state(this, st, this%mem)
      if (.not. s%on) return
      call add_seat_point_forces(s%fr, st%vehicle%pos, [-s%f_s*tan(this%p%gamma0) - s%f, s%f_s], &
                                 s%fp_s*[-s%ln%tan_phi, 1.0_wp], [this%p%z0, s%ln%h], s%ln%seg, list)
   end subroutine beams_point_forces

   !> Figure 14's decisions on an accepted step (as figure 12's, D-19): the
   !! hip on beam 1 or off it (beams_case), the leg on the front edge, the
   !! hip sliding; a change restarts the stepper. D-25: a beam that comes
   !! into action starts from its present deflection (the hip back on beam 1:
   !! delta_A; the leg onto the edge: delta_z beyond the tip's deflection
   !! under the hip alone), so no force jumps up; a reference is given up
   !! once the body is clear of the undeflected cushion. The energy is the
   !! integrated work, so no switch changes it.
   subroutine beams_accept(this, st, extra, aux, result)
      class(seat_beams_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      type(seat_memory_t) :: new, probe_mem
      type(beams_state_t) :: before, probe
      real(wp) :: w_free
      logical :: released
      associate (u1 => size(extra) + size(aux))
      end associate
      before = beams_state(this, st, this%mem)
      new = this%mem
      new%case = beams_case(before%z, this%p%ell)
      new%leg_on = new%case /= case_off .and. leg_rests(before%fr, this%p%z0, this%l7, this%l8)
      ! the deflections and stiffnesses at this state, whatever the memory
      probe_mem = seat_memory_t(case=case_a, leg_on=.true., slip=0)
      probe = beams_state(this, st, probe_mem)
      released = .false.
      call contact_reference(new%case /= case_off, before%on, probe%delta_a, probe%delta_a, new%hip_ref, released)
      ! the edge starts from the tip's deflection beyond what the hip alone makes (beams_forces' w_free)
      w_free = 0.0_wp
      if (probe%delta_a > new%hip_ref) w_free = probe%rho*probe%k1*(probe%delta_a - new%hip_ref) &
                                                /(probe%k2 + probe%rho**2*probe%k1)
      call contact_reference(new%leg_on, before%leg, probe%delta_z - w_free, probe%delta_z, new%edge_ref, released)
      call hip_sliding_decided(this%mem, new%case /= case_off, this%p%xi, before%fr%x1dot, new)
      if (new%case == this%mem%case .and. (new%leg_on .eqv. this%mem%leg_on) .and. new%slip == this%mem%slip &
          .and. new%edge == this%mem%edge .and. .not. released) return
      this%mem = new
      result%restart = .true.
   end subroutine beams_accept

   !> Issue 15: the non-rigid beams' switching functions at st with their
   !! memory (docs/seat.md, "Switches (issue 15)"):
   !!   1  z (in): off beam 1 below 0;  2  l - z (in): off it at l
   !!   3  delta_A - rho w beyond the references (in), while on: F_s's onset
   !!   4  delta_z - w_free beyond the references (in), while the leg rests
   !!      on the edge: the leg takes the tip over (a kink of both forces)
   !!   5  z - 0.05 l and 6  0.95 l - z (in), while on: K_1 reaches its cap
   !!   7  leg_rest_margin (in): figure 12's leg on the edge
   !!   8  x_knee - z_o (in), while the leg rests on the edge: the branch
   !!      (the leg's underside changes from thigh to shank: a corner)
   !!   9  k l - z (in), while on: the cantilever's root, where rho's
   !!      curvature jumps (rho and its slope are continuous)
   !! A function that does not apply in the memory held is +1.
   pure subroutine beams_switches(this, st, extra, aux, g)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      type(beams_state_t) :: s
      associate (u1 => size(extra) + size(aux))
      end associate
      s = beams_state(this, st, this%mem)
      g = 1.0_wp
      g(1) = s%z
      g(2) = this%p%ell - s%z
      if (s%on) then
         g(3) = s%g_hip
         g(5) = s%z - end_fraction*this%p%ell
         g(6) = (1.0_wp - end_fraction)*this%p%ell - s%z
         g(9) = this%p%k_ratio*this%p%ell - s%z
      end if
      if (s%leg) then
         g(4) = s%g_tip
         g(8) = leg_branch_margin(s%fr, this%p%z0)
      end if
      g(7) = leg_rest_margin(s%fr, this%p%z0, this%l7, this%l8)
      if (this%p%mu > 0.0_wp) call hip_slide_switches(s%fr, this%p%xi, this%mem%case /= case_off, this%mem%edge, &
                                                     g(this%n_switch - 1:this%n_switch))
   end subroutine beams_switches

   !> The hip held on an edge of its dead band (issue 15, D-19a): its
   !! sliding constraint, the friction's range mu times the normal load.
   pure subroutine beams_slides(this, st, extra, aux, s)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(slide_t), intent(out) :: s(:)
      type(beams_state_t) :: ss
      associate (u1 => size(extra) + size(aux))
      end associate
      if (this%mem%edge == 0 .or. this%mem%case == case_off) return
      ss = beams_state(this, st, this%mem)
      s(1) = hip_slide(ss%fr, st%vehicle%acc, this%p%mu, ss%f_s + ss%fp_s, this%p%xi, this%mem%edge, &
                       2, 3)
   end subroutine beams_slides

   !> The hip leaves its edge (D-19a).
   subroutine beams_release(this, k, at_upper)
      class(seat_beams_t), intent(inout) :: this
      integer, intent(in) :: k
      logical, intent(in) :: at_upper
      associate (u1 => k)
      end associate
      call hip_released(this%mem, this%p%xi, at_upper)
   end subroutine beams_release

   pure subroutine beams_energy(this, st, extra, aux, e)
      class(seat_beams_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (u1 => this%name, u2 => st%t, u3 => size(extra))
      end associate
      e(energy_stored) = aux(1)
      e(energy_dissipated) = aux(2)
      e(energy_supplied) = aux(3)
   end subroutine beams_energy

   function beams_outputs(this) result(series)
      class(seat_beams_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      allocate (series(2))
      series(1) = series_new('loads', 'NON-RIGID BEAM SEAT LOADS (C.4.d)', 'vertical components of the hip force ' &
                             //'F_s (normal to the cushion line) and the front-edge force F''_s (normal to the leg''s ' &
                             //'underside), the friction magnitude f, the penetrations delta_A and delta_z, the ' &
                             //'cantilever''s tip deflection w, z = z_o - x_1', 2)
      series(1)%col = [column('F_s', 'lb'), column('Fp_s', 'lb'), column('f', 'lb'), column('delta_A', 'in'), &
                       column('delta_z', 'in'), column('w', 'in'), column('z', 'in')]
      series(2) = series_new('energy', 'NON-RIGID BEAM SEAT ENERGIES (C.6)', 'the work the body did on the ' &
                             //'beams (integrated, not a potential), dissipated by the friction, supplied by the ' &
                             //'vehicle', 3)
      series(2)%col = [column('work', 'in*lb'), column('friction', 'in*lb'), column('supplied', 'in*lb')]
   end function beams_outputs

   pure subroutine beams_output_values(this, item, st, extra, aux, values)
      class(seat_beams_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      type(beams_state_t) :: s
      associate (u1 => size(extra))
      end associate
      s = beams_state(this, st, this%mem)
      if (item == 1) then
         values = [s%f_s, s%fp_s, s%f, s%delta_a, merge(s%delta_z, 0.0_wp, s%leg), s%w, s%z]
      else
         values = aux(1:3)
      end if
   end subroutine beams_output_values

   function beams_describe(this) result(text)
      class(seat_beams_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': l '//num(this%p%ell)//' in, k '//num(this%p%k_ratio)//', e_1 '//num(this%p%e1) &
             //', e_2 '//num(this%p%e2)//' lb*in^2, z_o '//num(this%p%z0)//' in, gamma_o ' &
             //num(anint(10.0_wp*this%p%gamma0/deg)/10.0_wp)//' deg'
      text = text(1:min(len(text), 128))
   end function beams_describe
end module seat_beams
