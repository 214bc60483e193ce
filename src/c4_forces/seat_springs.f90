!> Report C.4.d, the present seat (figures 11 and 12, reconstructed in
!! docs/seat.md): a linear spring s at the front edge acting on the thigh
!! (adult) or the shank (child), a third-order spring beta_1..beta_3 and a
!! damper c_s at the hip, friction at the hip f = mu (F_s + F'_s) sgn x_1',
!! and within z-hat of the front edge a linear hip spring whose constant is
!! that of the hip at the switch (A-S4). Off the seat when z < 0.
!!
!! Forces (interior components, on the body):
!!   hip         (-f, F_s)                 F_s = beta(d) + c_s d' >= 0, d = -y_1 (A-S3)
!!   front edge  F'_s (-tan phi, 1)        F'_s = s (y_zo - y_1 - y_z) >= 0, normal
!!               at the leg line's crossing of x = z_o (A-S1), y_zo = z_o tan gamma_o (A-S2)
!! and S_7..S_10 are their virtual work: the printed S_7..S_10 of C.4.d.
!!
!! Each spring acts on its compression beyond a reference that figure 12's
!! switches choose (D-25: zero unless a switch needs it): the hip force and
!! its stored energy never jump up at a switch.
!!
!! Energy (docs/seat.md): stored = sum beta_m u^{m+1}/(m+1) (no 1/2, E6-1;
!! case B 1/2 k u^2; u = d - the reference) + 1/2 s (front compression)^2, a
!! potential whose gradient the clipped springs are; dissipated = the
!! integral of the damper's and the friction's power (auxiliary quantity 1) +
!! what the switches of figure 12 took from the springs (never negative,
!! D-25); supplied = the integral of the power of the seat forces at the
!! vehicle's material points (auxiliary quantity 2).
!!
!! Switches (issue 15; docs/seat.md "Switches (issue 15)"): figure 12's
!! case (z = 0: off the seat; z = z-hat: regions A and B), the hip's force
!! coming on or off (the compression beyond the reference, and the clip of
!! the spring and damper), the front edge's (its compression beyond its
!! reference), the leg's branch (a corner) and its resting on the edge.
!! The hip's sliding at +-xi: held on an edge of its dead band while the
!! friction the motion needs lies within the law's range (D-19a; Filippov,
!! as the joints' friction, D-4b).
module seat_springs
   use kinds, only: wp, deg
   use strings, only: num
   use model, only: n_dof, n_seg, hip_x, hip_y, seat_section_t, body_section_t
   use effect_base, only: effect_t, body_state_t, slide_t
   use effect_events, only: accept_result_t
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds
   use point_forces, only: point_force_list_t
   use effect_peaks, only: effect_peak_t
   use output_series, only: output_series_t, series_new, column
   use body_kinematics, only: point_state_t, segment_cg_state
   use seat_geometry, only: hip_slide, hip_slide_switches, hip_sliding_decided, hip_released, &
      add_seat_point_forces, contact_reference, &
      seat_frame_t, seat_frame, leg_line_t, leg_line, leg_branch, leg_rests, leg_rest_margin, leg_branch_margin, &
      seat_memory_t, seat_case, hip_friction, slip_of, vehicle_power, add_hip_force, rest_state, case_off, case_a, case_b, &
      poly_force, poly_energy
   implicit none
   private

   public :: seat_springs_t, seat_springs_effect, springs_state_t, springs_state, static_loads
   public :: hip_law_at_switch

   type, extends(effect_t) :: seat_springs_t
      type(seat_section_t) :: p
      real(wp) :: l7 = 0.0_wp, l8 = 0.0_wp
      real(wp) :: y_zo = 0.0_wp                 !< z_o tan gamma_o (A-S2)
      real(wp) :: w_pred = 0.0_wp, fps_pred = 0.0_wp  !< static loads of the initial posture
      type(seat_memory_t) :: mem
      !> the largest hip and front-edge forces F_s, F'_s over the accepted
      !! steps and when (memory, changed in accept; peaks)
      real(wp) :: peak_hip = 0.0_wp, t_hip = 0.0_wp, peak_edge = 0.0_wp, t_edge = 0.0_wp
   contains
      procedure :: add_forces => springs_add_forces
      procedure :: accept => springs_accept
      procedure :: switches => springs_switches
      procedure :: slides => springs_slides
      procedure :: release => springs_release
      procedure :: point_forces => springs_point_forces
      procedure :: energy => springs_energy
      procedure :: outputs => springs_outputs
      procedure :: output_values => springs_output_values
      procedure :: frame_values => springs_frame_values
      procedure :: describe => springs_describe
      procedure :: peaks => springs_peaks
   end type seat_springs_t

   !> The seat at one state: figure 12's quantities, forces and powers.
   type :: springs_state_t
      type(seat_frame_t) :: fr
      type(leg_line_t) :: ln
      integer :: case = case_a
      logical :: leg = .false.
      real(wp) :: z = 0.0_wp, d = 0.0_wp, d_dot = 0.0_wp, u = 0.0_wp   !< u = d - the hip's reference
      real(wp) :: f_el = 0.0_wp, f_s = 0.0_wp, delta_e = 0.0_wp, fp_s = 0.0_wp, f = 0.0_wp
      real(wp) :: e_hip = 0.0_wp, e_edge = 0.0_wp
      real(wp) :: dissipation = 0.0_wp, supply = 0.0_wp   !< rates
   end type springs_state_t

contains

   !> The effect for seat p, body, gravity g and the initial state (alpha_0
   !! in z0, pitch phi0): figure 12's memory starts from the initial posture.
   function seat_springs_effect(p, body, g, z0, phi0) result(e)
      type(seat_section_t), intent(in) :: p
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: g, z0(n_dof), phi0
      type(seat_springs_t) :: e
      type(body_state_t) :: st
      type(seat_frame_t) :: fr
      e%name = 'seat'
      e%title = 'seat springs (C.4.d)'
      e%p = p
      e%l7 = body%length(7)
      e%l8 = body%length(8)
      e%y_zo = p%z0*tan(p%gamma0)
      e%n_aux = 2
      e%needs_vehicle = .true.
      e%external = .true.
      e%has_memory = .true.
      e%has_energy = .true.
      e%n_switch = 6
      if (p%mu > 0.0_wp) then
         ! the hip's sliding (issue 15, D-19a): its two switches, its constraint
         e%n_switch = e%n_switch + 2
         e%n_slide = 1
      end if
      st = rest_state(z0, phi0)
      fr = seat_frame(st, e%l7)
      e%mem%case = seat_case(p%z0, p%z_hat)
      e%mem%leg_on = e%mem%case /= case_off .and. leg_rests(fr, p%z0, e%l7, e%l8)
      e%mem%k_hat = p%beta(1)
      e%mem%slip = 0
      call static_loads(body, g, z0, phi0, p%z0, e%w_pred, e%fps_pred)
   end function seat_springs_effect

   !> The static loads on the hip and the front edge that hold the body, as
   !! one rigid piece in the posture z0, in equilibrium under gravity
   !! (vertical forces and moments about the hip; the horizontal component of
   !! the front-edge force is left to the friction). What W_o and F'_so
   !! should be for this occupant (A-S2); zero F'_so when the leg does not
   !! rest on the edge.
   subroutine static_loads(body, g, z0, phi0, x_e, w, fps)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: g, z0(n_dof), phi0, x_e
      real(wp), intent(out) :: w, fps
      type(body_state_t) :: st
      type(seat_frame_t) :: fr
      type(leg_line_t) :: ln
      type(point_state_t) :: cg
      real(wp) :: moment, zero10(n_dof), dx, dy
      integer :: i
      st = rest_state(z0, phi0)
      fr = seat_frame(st, body%length(7))
      zero10 = 0.0_wp
      moment = 0.0_wp
      do i = 1, n_seg
         cg = segment_cg_state(body, z0, zero10, zero10, i)
         dx = cg%x - z0(hip_x)
         dy = cg%y - z0(hip_y)
         ! gravity g (sin Phi, -cos Phi) in the interior frame; its moment about the hip
         moment = moment - g*body%mass(i)*((dx*fr%c_phi - dy*fr%s_phi)*fr%c_phi + (dx*fr%s_phi + dy*fr%c_phi)*fr%s_phi)
      end do
      fps = 0.0_wp
      if (leg_rests(fr, x_e, body%length(7), body%length(8))) then
         ln = leg_line(fr, leg_branch(fr, x_e), x_e, 0.0_wp, 0.0_wp, body%length(7))
         ! the moment about the hip of F'_s (-tan phi, 1) at the crossing is F'_s
         ! times the sum of dh/d alpha over the leg (a rotation of the whole body)
         ! (a leg line through the hip turns with it: no lever, no F'_s predicted)
         if (abs(sum(ln%dh(1:n_seg))) > epsilon(1.0_wp)*body%length(7)) &
            fps = max(0.0_wp, -moment/sum(ln%dh(1:n_seg)))
      end if
      w = sum(body%mass)*g*fr%c_phi - fps
   end subroutine static_loads

   !> Figure 12 (reconstructed) at state st with memory mem.
   pure function springs_state(this, st, mem) result(s)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      type(seat_memory_t), intent(in) :: mem
      type(springs_state_t) :: s
      real(wp) :: fe(2)
      s%fr = seat_frame(st, this%l7)
      s%case = mem%case
      s%z = this%p%z0 - s%fr%x1                     ! C.4.d, z = z_o - x_1
      s%d = -s%fr%y1                                ! hip compression (A-S3)
      s%d_dot = -s%fr%y1dot
      s%leg = mem%leg_on .and. mem%case /= case_off
      if (mem%case == case_off) return
      ! the hip spring acts on the compression beyond its reference (D-25)
      s%u = s%d - mem%hip_ref
      associate (beta => this%p%beta, u => s%u)
         ! in the cushion, or on its surface and pressing in: there the damper
         ! acts at once (the force's limit along the motion), so that a hip at
         ! rest on the undeflected cushion (decks/seat_drop.deck,
         ! seat_child.deck at t = 0), where RK4's second stage sits on u = 0
         ! with the rate of the first, is not taken off the cushion: that cost
         ! RK4 two orders in the whole run (issue 15; docs/seat.md)
         if (u > 0.0_wp .or. (.not. u < 0.0_wp .and. s%d_dot > 0.0_wp)) then
            if (mem%case == case_a) then
               ! C.4.d, sum beta_m d^m (A-S3) and its energy sum beta_m d^{m+1}/(m+1) (E6-1)
               s%f_el = poly_force(beta, u)
               s%e_hip = poly_energy(beta, u)
            else
               ! case B: the linear spring of the front region (A-S4)
               s%f_el = mem%k_hat*u
               s%e_hip = 0.5_wp*mem%k_hat*u**2
            end if
            ! with the damper c_s; a cushion never pulls
            s%f_s = max(0.0_wp, s%f_el + this%p%c_s*s%d_dot)
         end if
      end associate
      if (s%leg) then
         ! the front-edge spring on the leg line at x = z_o (A-S1, A-S2)
         s%ln = leg_line(s%fr, leg_branch(s%fr, this%p%z0), this%p%z0, 0.0_wp, 0.0_wp, this%l7)
         s%delta_e = this%y_zo - s%ln%h
         ! beyond the edge's reference (D-25)
         s%fp_s = this%p%s*max(s%delta_e - mem%edge_ref, 0.0_wp)
         s%e_edge = 0.5_wp*this%p%s*max(s%delta_e - mem%edge_ref, 0.0_wp)**2
      end if
      ! C.4.d friction at the hip, A-S4, A-f
      s%f = hip_friction(this%p%mu, s%f_s + s%fp_s, mem%slip)
      ! dissipated: damper and the clip of the hip force, (F_s - beta(d)) d' >= 0; friction f x_1' >= 0
      s%dissipation = (s%f_s - s%f_el)*s%d_dot + s%f*s%fr%x1dot
      ! supplied by the vehicle: the seat forces at the vehicle's material points
      fe = s%fp_s*[-s%ln%tan_phi, 1.0_wp]
      s%supply = vehicle_power(s%fr, [-s%f, s%f_s], [s%fr%x1, s%fr%y1]) + &
                 vehicle_power(s%fr, fe, [this%p%z0, s%ln%h])
   end function springs_state

   pure subroutine springs_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(springs_state_t) :: s
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate))
      end associate
      s = springs_state(this, st, this%mem)
      ! C.4.d: S_1..S_6 = 0; S_7, S_8 = F'_s dy_z/d alpha; S_9, S_10: the hip
      ! forces (F_s, -f) rotated by Phi plus F'_s d(y_1 + y_z)/dx_h, /dy_h
      ! (springs_forces' sums, written out: the right-hand side's call
      ! would not be inlined)
      call add_hip_force(s%fr, [-s%f, s%f_s], b)
      b = b + s%fp_s*s%ln%dh
      aux_rate(1) = s%dissipation
      aux_rate(2) = s%supply
   end subroutine springs_add_forces

   !> The hip force (-f, F_s) and F'_s normal to the leg, as point forces.
   pure subroutine springs_point_forces(this, st, extra, aux, list)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      associate (u1 => size(extra) + size(aux))
      end associate
      call springs_point_forces_of(this, springs_state(this, st, this%mem), st%vehicle%pos, list)
   end subroutine springs_point_forces

   !> springs_point_forces from the seat's state s, the vehicle at vpos.
   pure subroutine springs_point_forces_of(this, s, vpos, list)
      class(seat_springs_t), intent(in) :: this
      type(springs_state_t), intent(in) :: s
      real(wp), intent(in) :: vpos(3)
      type(point_force_list_t), intent(inout) :: list
      call add_seat_point_forces(s%fr, vpos, [-s%f, s%f_s], s%fp_s*[-s%ln%tan_phi, 1.0_wp], [this%p%z0, s%ln%h], &
                                 s%ln%seg, list)
   end subroutine springs_point_forces_of

   !> Figure 12's decisions on an accepted step: the case (off, A, B), the
   !! leg on the front edge, the hip's law in the new case, the hip sliding
   !! or not; the stored energy a switch changes goes to the switching
   !! account, and the stepper restarts (the right-hand side jumps only here,
   !! so no step straddles a jump: docs/seat.md).
   !!
   !! D-25: a switch never makes energy. The new case's hip law (case B's k
   !! and the references) is chosen from the conditions at this accepted
   !! step (A-S4) so that the hip's elastic force does not jump up and its
   !! stored energy does not grow; a spring that comes into action (the hip
   !! back on the seat, the leg onto the front edge) starts from its present
   !! compression; a reference is given up once the body is clear of the
   !! undeflected cushion, where neither law carries anything.
   subroutine springs_accept(this, st, extra, aux, result)
      class(seat_springs_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      type(seat_memory_t) :: new
      type(springs_state_t) :: before, after
      type(leg_line_t) :: ln
      logical :: released
      real(wp) :: start
      associate (u1 => size(extra) + size(aux))
      end associate
      before = springs_state(this, st, this%mem)
      if (before%f_s > this%peak_hip) then
         this%peak_hip = before%f_s
         this%t_hip = st%t
      end if
      if (before%fp_s > this%peak_edge) then
         this%peak_edge = before%fp_s
         this%t_edge = st%t
      end if
      new = this%mem
      new%case = seat_case(before%z, this%p%z_hat)
      new%leg_on = new%case /= case_off .and. leg_rests(before%fr, this%p%z0, this%l7, this%l8)
      released = .false.
      if (new%case == case_off) then
         new%hip_ref = 0.0_wp
      else if (new%case /= this%mem%case) then
         call hip_law_at_switch(this%p%beta, new%case, before%f_el, before%e_hip, before%d, this%mem%hip_ref, &
                                new%k_hat, new%hip_ref)
      else if (new%hip_ref > 0.0_wp .and. before%d <= 0.0_wp) then
         new%hip_ref = 0.0_wp                 ! the cushion has recovered under a lifted hip
         released = .true.
      end if
      ! the leg onto the edge starts from its present compression
      start = 0.0_wp
      if (new%leg_on .and. .not. before%leg) then
         ln = leg_line(before%fr, leg_branch(before%fr, this%p%z0), this%p%z0, 0.0_wp, 0.0_wp, this%l7)
         start = this%y_zo - ln%h
      end if
      call contact_reference(new%leg_on, before%leg, start, before%delta_e, new%edge_ref, released)
      call hip_sliding_decided(this%mem, new%case /= case_off, this%p%xi, before%fr%x1dot, new)
      if (new%case == this%mem%case .and. (new%leg_on .eqv. this%mem%leg_on) .and. new%slip == this%mem%slip &
          .and. new%edge == this%mem%edge .and. .not. released) return
      after = springs_state(this, st, new)
      ! D-25: the switch only takes energy from the springs
      new%e_switch = this%mem%e_switch + (before%e_hip + before%e_edge) - (after%e_hip + after%e_edge)
      this%mem = new
      result%restart = .true.
   end subroutine springs_accept

   !> Issue 15: the seat's switching functions at st with its memory,
   !! each positive on one side of figure 12's decision or of a kink of the
   !! forces, zero where it switches (docs/seat.md, "Switches (issue 15)"):
   !!   1  z (in): off the seat below 0 (seat_case)
   !!   2  z - z-hat (in): region B at or below 0, A above
   !!   3  min(k u, F_el + c_s d') (lb), k = beta_1 (1 lb/in if 0): the
   !!      hip force F_s is positive exactly where both are (u > 0 and the
   !!      clip max(0, F_el + c_s d') open); its onset jumps by c_s d'
   !!   4  the front compression beyond its reference (in), while the leg
   !!      rests on the edge: F'_s's kink
   !!   5  x_knee - z_o (in), while the leg rests on the edge: the branch
   !!      thigh/shank, a corner of F'_s
   !!   6  leg_rest_margin (in): figure 12's leg on the edge
   !! A function that does not apply in the memory held is +1.
   pure subroutine springs_switches(this, st, extra, aux, g)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      type(springs_state_t) :: s
      associate (u1 => size(extra) + size(aux))
      end associate
      s = springs_state(this, st, this%mem)
      g = 1.0_wp
      g(1) = s%z
      g(2) = s%z - this%p%z_hat
      if (s%case /= case_off) g(3) = min(merge(this%p%beta(1), 1.0_wp, this%p%beta(1) > 0.0_wp)*s%u, &
                                         s%f_el + this%p%c_s*s%d_dot)
      if (s%leg) then
         g(4) = s%delta_e - this%mem%edge_ref
         g(5) = leg_branch_margin(s%fr, this%p%z0)
      end if
      g(6) = leg_rest_margin(s%fr, this%p%z0, this%l7, this%l8)
      if (this%p%mu > 0.0_wp) call hip_slide_switches(s%fr, this%p%xi, this%mem%case /= case_off, this%mem%edge, &
                                                     g(this%n_switch - 1:this%n_switch))
   end subroutine springs_switches

   !> The hip held on an edge of its dead band (issue 15, D-19a): its
   !! sliding constraint, the friction's range mu times the normal load.
   pure subroutine springs_slides(this, st, extra, aux, s)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(slide_t), intent(out) :: s(:)
      type(springs_state_t) :: ss
      associate (u1 => size(extra) + size(aux))
      end associate
      if (this%mem%edge == 0 .or. this%mem%case == case_off) return
      ss = springs_state(this, st, this%mem)
      s(1) = hip_slide(ss%fr, st%vehicle%acc, this%p%mu, ss%f_s + ss%fp_s, this%p%xi, this%mem%edge, &
                       1, 2)
   end subroutine springs_slides

   !> The hip leaves its edge (D-19a).
   subroutine springs_release(this, k, at_upper)
      class(seat_springs_t), intent(inout) :: this
      integer, intent(in) :: k
      logical, intent(in) :: at_upper
      associate (u1 => k)
      end associate
      call hip_released(this%mem, this%p%xi, at_upper)
   end subroutine springs_release

   !> The largest hip and front-edge forces over the accepted steps (none
   !! that never acted).
   function springs_peaks(this) result(p)
      class(seat_springs_t), intent(in) :: this
      type(effect_peak_t), allocatable :: p(:)
      allocate (p(0))
      if (this%peak_hip > 0.0_wp) p = [p, effect_peak_t(name=trim(this%name)//'_hip_force', title=this%title, &
                                                       label='largest hip force F_s', unit='lb', value=this%peak_hip, &
                                                       t=this%t_hip)]
      if (this%peak_edge > 0.0_wp) p = [p, effect_peak_t(name=trim(this%name)//'_edge_force', title=this%title, &
                                                         label='largest edge force F''_s', unit='lb', &
                                                         value=this%peak_edge, t=this%t_edge)]
   end function springs_peaks

   !> The hip's law on a switch into case (A or B) at compression d, where
   !! the law in force gives the elastic force f0 and the stored energy v0
   !! (its reference ref0); returns case B's k and the new reference ref
   !! (D-25, from A-S4: "a linear spring whose spring constant is dependent
   !! on the conditions at the previous time instant"). With u = d - ref:
   !!   f0 = 0 (the hip not in the cushion, or back on the seat): ref =
   !!     max(ref0, d), nothing carried; case B's k = beta_1;
   !!   case B: k u = f0 and 1/2 k u^2 = min(v0, 1/2 f0 d), ref >= 0: the force is
   !!     continuous, the energy too where the polynomial hardens (else the
   !!     secant, ref = 0, and the difference is dissipated);
   !!   case A: beta(u) = f0 at the least u whose energy does not exceed v0,
   !!     else the u whose energy is v0 (the force drops), u <= d.
   pure subroutine hip_law_at_switch(beta, case, f0, v0, d, ref0, k, ref)
      real(wp), intent(in) :: beta(3), f0, v0, d, ref0
      integer, intent(in) :: case
      real(wp), intent(inout) :: k
      real(wp), intent(out) :: ref
      real(wp) :: u, lo, hi, mid, ue, step
      integer :: it, j
      integer, parameter :: n_scan = 64
      ! (no load, or an energy too small to give a positive compression:
      ! u = 2 v0/f0 would be 0 and k = f0/u infinite)
      if (.not. f0 > 0.0_wp .or. .not. d > 0.0_wp .or. .not. v0 > 0.0_wp) then
         ref = max(ref0, d, 0.0_wp)
         if (case == case_b) k = beta(1)
         return
      end if
      if (case == case_b) then
         u = min(d, 2.0_wp*v0/f0)
         k = f0/u
         ref = d - u
         return
      end if
      ! case A: ue, the compression whose energy is min(v0, P(d)) (P increases)
      lo = 0.0_wp
      hi = d
      if (poly_energy(beta, d) > v0) then
         do it = 1, 200
            mid = 0.5_wp*(lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            if (poly_energy(beta, mid) > v0) then
               hi = mid
            else
               lo = mid
            end if
         end do
         ue = lo
      else
         ue = d
      end if
      ! the least u <= ue with beta(u) >= f0 (beta need not increase: scan, then bisect)
      u = ue
      step = ue/n_scan
      do j = 1, n_scan
         if (poly_force(beta, j*step) >= f0) then
            lo = (j - 1)*step
            hi = j*step
            do it = 1, 200
               mid = 0.5_wp*(lo + hi)
               if (.not. (mid > lo .and. mid < hi)) exit
               if (poly_force(beta, mid) >= f0) then
                  hi = mid
               else
                  lo = mid
               end if
            end do
            u = lo
            exit
         end if
      end do
      ref = d - u
   end subroutine hip_law_at_switch

   pure subroutine springs_energy(this, st, extra, aux, e)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      type(springs_state_t) :: s
      associate (u1 => size(extra))
      end associate
      s = springs_state(this, st, this%mem)
      e(energy_stored) = s%e_hip + s%e_edge
      e(energy_dissipated) = aux(1) + this%mem%e_switch
      e(energy_supplied) = aux(2)
   end subroutine springs_energy

   function springs_outputs(this) result(series)
      class(seat_springs_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      allocate (series(3))
      series(1) = series_new('loads', 'SEAT LOADS (C.4.d)', 'seat forces on the body: F_s up at the hip, F''_s the ' &
                             //'vertical and Fp_x the horizontal component of the front-edge force normal to the ' &
                             //'leg (A-S1), f the friction magnitude (the force is -f along the interior x)', 2)
      series(1)%col = [column('F_s', 'lb'), column('Fp_s', 'lb'), column('Fp_x', 'lb'), column('f', 'lb')]
      series(2) = series_new('geometry', 'SEAT GEOMETRY (C.4.d, FIGURES 11-12)', 'case (0 off the seat, 1 A, 2 B: ' &
                             //'within z-hat of the front edge), leg on the front edge (0 none, 7 thigh, 8 shank), ' &
                             //'z = z_o - x_1, hip compression d = -y_1, front-edge compression y_zo - y_1 - y_z, ' &
                             //'y_z, the spring constant of case B', 3)
      series(2)%col = [column('case', '-'), column('leg', '-'), column('z', 'in'), column('d_hip', 'in'), &
                       column('d_edge', 'in'), column('y_z', 'in'), column('k_hat', 'lb/in')]
      series(3) = series_new('energy', 'SEAT ENERGIES (C.6)', 'stored in the hip and front-edge springs, ' &
                             //'dissipated by the damper and friction, moved out of the springs by the switches ' &
                             //'of figure 12, supplied by the vehicle through the seat', 3)
      series(3)%col = [column('hip_spring', 'in*lb'), column('edge_spring', 'in*lb'), column('damp_frict', 'in*lb'), &
                       column('switching', 'in*lb'), column('supplied', 'in*lb')]
   end function springs_outputs

   pure subroutine springs_output_values(this, item, st, extra, aux, values)
      class(seat_springs_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      associate (u1 => size(extra))
      end associate
      call springs_series(this, item, springs_state(this, st, this%mem), aux, values)
   end subroutine springs_output_values

   !> The values of series item from the seat's state s (springs_state).
   pure subroutine springs_series(this, item, s, aux, values)
      class(seat_springs_t), intent(in) :: this
      integer, intent(in) :: item
      type(springs_state_t), intent(in) :: s
      real(wp), intent(in) :: aux(:)
      real(wp), intent(out) :: values(:)
      integer :: leg
      leg = 0
      if (s%leg) leg = s%ln%seg
      select case (item)
      case (1)
         values = [s%f_s, s%fp_s, -s%fp_s*s%ln%tan_phi, s%f]
      case (2)
         values = [real(s%case, wp), real(leg, wp), s%z, s%d, s%delta_e, s%ln%h - s%fr%y1, this%mem%k_hat]
      case default
         values = [s%e_hip, s%e_edge, aux(1), this%mem%e_switch, aux(2)]
      end select
   end subroutine springs_series

   !> A print time's frame (effect_t's frame_values): figure 12's state
   !! taken once for the energies, the three series, the generalized force
   !! and the point forces, the same bits as springs_energy,
   !! springs_output_values, springs_add_forces and springs_point_forces
   !! each taking it.
   pure subroutine springs_frame_values(this, st, extra, aux, e, values, at, width, gf, b, pf, list, sums, b_sum)
      class(seat_springs_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      real(wp), intent(inout) :: values(:)
      integer, intent(in) :: at(:), width(:)
      logical, intent(in) :: gf, pf, sums
      real(wp), intent(inout) :: b(n_dof), b_sum(n_dof)
      type(point_force_list_t), intent(inout) :: list
      type(springs_state_t) :: s
      integer :: j
      associate (u1 => size(extra))
      end associate
      s = springs_state(this, st, this%mem)
      ! springs_energy
      e(energy_stored) = s%e_hip + s%e_edge
      e(energy_dissipated) = aux(1) + this%mem%e_switch
      e(energy_supplied) = aux(2)
      do j = 1, size(at)
         if (at(j) >= 0) call springs_series(this, j, s, aux, values(at(j) + 1:at(j) + width(j)))
      end do
      if (gf) call springs_forces(s, b)
      if (pf) call springs_point_forces_of(this, s, st%vehicle%pos, list)
      if (sums) call springs_forces(s, b_sum)
   end subroutine springs_frame_values

   !> The seat's generalized forces from its state s added to b, with
   !! springs_add_forces' sums (C.4.d S_7..S_10, as there).
   pure subroutine springs_forces(s, b)
      type(springs_state_t), intent(in) :: s
      real(wp), intent(inout) :: b(n_dof)
      call add_hip_force(s%fr, [-s%f, s%f_s], b)
      b = b + s%fp_s*s%ln%dh
   end subroutine springs_forces

   function springs_describe(this) result(text)
      class(seat_springs_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': z_o '//r1(this%p%z0)//', z-hat '//r1(this%p%z_hat)//' in, gamma_o ' &
             //r1(this%p%gamma0/deg)//' deg, mu '//r1(this%p%mu)//'; static loads W_o ' &
             //r1(this%w_pred)//', F''_so '//r1(this%fps_pred)//' lb'
      if (this%p%w0 > 0.0_wp .or. this%p%fps0 > 0.0_wp) text = text//' (deck '//r1(this%p%w0)//', '//r1(this%p%fps0)//')'
      text = text(1:min(len(text), 128))
   contains
      function r1(x) result(t)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: t
         t = num(anint(10.0_wp*x)/10.0_wp)
      end function r1
   end function springs_describe
end module seat_springs
