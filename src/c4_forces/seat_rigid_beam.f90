!> Report C.4.d, the rigid-beam seat (figures 15 and 16, reconstructed in
!! docs/seat.md): a beam of mass m_s and inertia I_s whose centre of gravity
!! stays a' behind the front edge, on a linear spring s at the front edge
!! and a spring beta_1..beta_3 with damper c_s a behind it. Its two degrees
!! of freedom (y_g, gamma) are the effect's extra coordinates, uncoupled from
!! the body matrix.
!!
!! Erratum A-RB: the body presses into the *moving* beam at the hip and,
!! through the leg line, at the front edge (contact springs KHIP, KEDGE,
!! preloaded so that they carry W_o and F-hat'_so at t = 0); each contact
!! force acts equally and oppositely on the body and on the beam. The
!! printed W_o, F-hat'_so and m_s y_1'' terms drop out. The beam's equations
!! are written in the vehicle interior: gravity -m_s g cos Phi and the
!! frame's pseudo-forces enter (A-RB), and the moments carry sec^2 gamma
!! (RB-2) about the CG (RB-1):
!!   m_s y_g'' = F_s + F'_s - F_hip - F_edge - m_s g cos Phi
!!               - m_s (x_c'' sin Phi + y_c'' cos Phi) + m_s (Phi'' x_g + Phi'^2 y_g)
!!   I_s gamma'' = sec^2 gamma [a'(F'_s - F_edge) - (a - a')F_s - (x_1 - x_g)F_hip] + I_s Phi''
!!
!! Switches (issue 15; docs/seat.md "Switches (issue 15)"): the hip
!! leaving the beam or coming back (z = 0), the rear support's force coming
!! on or off (its deflection, and the clip of spring and damper), the front
!! support's, the hip's and the edge's contacts (penetration beyond the
!! reference), the leg's branch (a corner) and its resting on the edge.
!! The hip's sliding at +-xi, held on an edge of its dead band (D-19a).
module seat_rigid_beam
   use kinds, only: wp, deg
   use strings, only: num
   use model, only: n_dof, n_seg, seat_section_t, body_section_t
   use effect_base, only: effect_t, body_state_t, slide_t
   use effect_events, only: accept_result_t
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds
   use point_forces, only: point_force_list_t
   use output_series, only: output_series_t, series_new, column
   use seat_geometry, only: hip_slide, hip_slide_switches, hip_sliding_decided, hip_released, &
      add_seat_point_forces, contact_reference, &
      seat_frame_t, seat_frame, leg_line_t, leg_line, leg_branch, leg_rests, leg_rest_margin, leg_branch_margin, &
      seat_memory_t, hip_friction, slip_of, vehicle_power, add_hip_force, rest_state, case_off, case_a, poly_force, poly_energy
   implicit none
   private

   public :: seat_rigid_beam_t, seat_rigid_beam_effect, beam_state_t, beam_state

   type, extends(effect_t) :: seat_rigid_beam_t
      type(seat_section_t) :: p
      real(wp) :: l7 = 0.0_wp, l8 = 0.0_wp, g = 0.0_wp
      real(wp) :: x_g = 0.0_wp                      !< the CG's interior x, z_o - a'
      real(wp) :: e_hip = 0.0_wp, e_edge = 0.0_wp   !< contact lines below the beam's top
      type(seat_memory_t) :: mem
   contains
      procedure :: add_forces => beam_add_forces
      procedure :: accept => beam_accept
      procedure :: switches => beam_switches
      procedure :: slides => beam_slides
      procedure :: release => beam_release
      procedure :: point_forces => beam_point_forces
      procedure :: energy => beam_energy
      procedure :: outputs => beam_outputs
      procedure :: output_values => beam_output_values
      procedure :: describe => beam_describe
      procedure :: initial_extra => beam_initial_extra
   end type seat_rigid_beam_t

   !> The beam and its contacts at one state.
   type :: beam_state_t
      type(seat_frame_t) :: fr
      type(leg_line_t) :: ln
      logical :: on = .true., leg = .false.
      real(wp) :: z = 0.0_wp, y_g = 0.0_wp, gam = 0.0_wp, yg_dot = 0.0_wp, gam_dot = 0.0_wp
      real(wp) :: tg = 0.0_wp, sec2 = 1.0_wp
      real(wp) :: ds = 0.0_wp, ds_dot = 0.0_wp, dz = 0.0_wp     !< support deflections Delta_s, Delta_z
      real(wp) :: fs_el = 0.0_wp, f_s = 0.0_wp, fp_s = 0.0_wp   !< support forces
      real(wp) :: p_hip = 0.0_wp, f_hip = 0.0_wp, p_edge = 0.0_wp, f_edge = 0.0_wp, f = 0.0_wp
      real(wp) :: acc(2) = 0.0_wp                                 !< y_g'', gamma''
      real(wp) :: e_kin = 0.0_wp, e_support = 0.0_wp, e_contact = 0.0_wp, e_grav = 0.0_wp
      real(wp) :: dissipation = 0.0_wp, supply = 0.0_wp
   end type beam_state_t

contains

   !> The effect for seat p (its ten initial quantities solved by the
   !! builder), body, gravity g and the initial state (z0, pitch phi0).
   function seat_rigid_beam_effect(p, body, g, z0, phi0) result(e)
      type(seat_section_t), intent(in) :: p
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: g, z0(n_dof), phi0
      type(seat_rigid_beam_t) :: e
      type(body_state_t) :: st
      type(seat_frame_t) :: fr
      type(leg_line_t) :: ln
      e%name = 'seat'
      e%title = 'rigid-beam seat (C.4.d)'
      e%p = p
      e%l7 = body%length(7)
      e%l8 = body%length(8)
      e%g = g
      e%x_g = p%z0 - p%a_prime
      e%n_extra = 2
      e%n_aux = 2
      e%needs_vehicle = .true.
      e%external = .true.
      e%has_memory = .true.
      e%has_energy = .true.
      e%n_switch = 7
      if (p%mu > 0.0_wp) then
         ! the hip's sliding (issue 15, D-19a): its two switches, its constraint
         e%n_switch = e%n_switch + 2
         e%n_slide = 1
      end if
      st = rest_state(z0, phi0)
      fr = seat_frame(st, e%l7)
      e%mem%case = case_a
      e%mem%leg_on = leg_rests(fr, p%z0, e%l7, e%l8)
      ! the contact lines carry W_o and F-hat'_so at t = 0 (the hip at the origin)
      e%e_hip = p%yg0 + (0.0_wp - e%x_g)*tan(p%gamma0) - p%w0/p%k_hip
      ln = leg_line(fr, leg_branch(fr, p%z0), p%z0, 0.0_wp, 0.0_wp, e%l7)
      e%e_edge = p%yg0 + p%a_prime*tan(p%gamma0) - ln%h - p%fhps0/p%k_edge
   end function seat_rigid_beam_effect

   !> (y_go, gamma_o) at rest: the solution of C.4.d's initial relations.
   pure subroutine beam_initial_extra(this, extra)
      class(seat_rigid_beam_t), intent(in) :: this
      real(wp), intent(out) :: extra(:)
      extra = [this%p%yg0, this%p%gamma0, 0.0_wp, 0.0_wp]
   end subroutine beam_initial_extra

   !> Everything at state st, beam state extra = (y_g, gamma, y_g', gamma'), memory mem.
   pure function beam_state(this, st, extra, mem) result(s)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(4)
      type(seat_memory_t), intent(in) :: mem
      type(beam_state_t) :: s
      real(wp) :: a, ap, tu, q_ps(2), phi_dd, ac_y, fe(2), fh(2)
      a = this%p%a
      ap = this%p%a_prime
      s%fr = seat_frame(st, this%l7)
      s%z = this%p%z0 - s%fr%x1
      s%y_g = extra(1)
      s%gam = extra(2)
      s%yg_dot = extra(3)
      s%gam_dot = extra(4)
      s%tg = tan(s%gam)
      s%sec2 = 1.0_wp + s%tg**2
      tu = tan(this%p%gamma_u)
      ! C.4.d: Delta_s, Delta_z, Delta_s' of the supports (tan-gamma kinematics)
      s%ds = this%p%y_gu - s%y_g + (a - ap)*(s%tg - tu)
      s%ds_dot = (a - ap)*s%gam_dot*s%sec2 - s%yg_dot
      s%dz = this%p%y_gu - s%y_g + ap*(tu - s%tg)
      ! C.4.d: F_s = sum beta_m Delta_s^m + c_s Delta_s', F'_s = s Delta_z; supports do not pull
      associate (beta => this%p%beta, d => s%ds)
         ! (on the support's surface and pressing in, the damper acts at once:
         ! as the spring seat's hip, seat_springs)
         if (d > 0.0_wp .or. (.not. d < 0.0_wp .and. s%ds_dot > 0.0_wp)) then
            s%fs_el = poly_force(beta, d)
            s%f_s = max(0.0_wp, s%fs_el + this%p%c_s*s%ds_dot)
            s%e_support = poly_energy(beta, d)
         end if
      end associate
      s%fp_s = this%p%s*max(s%dz, 0.0_wp)
      s%e_support = s%e_support + 0.5_wp*this%p%s*max(s%dz, 0.0_wp)**2
      ! A-RB: the body's penetration of the moving beam, at the hip and at the front edge
      ! (each contact acts on its penetration beyond its reference, D-25)
      s%on = mem%case /= case_off
      s%leg = s%on .and. mem%leg_on
      if (s%on) then
         s%p_hip = s%y_g + (s%fr%x1 - this%x_g)*s%tg - this%e_hip - s%fr%y1
         s%f_hip = this%p%k_hip*max(s%p_hip - mem%hip_ref, 0.0_wp)
         s%e_contact = 0.5_wp*this%p%k_hip*max(s%p_hip - mem%hip_ref, 0.0_wp)**2
      end if
      if (s%leg) then
         s%ln = leg_line(s%fr, leg_branch(s%fr, this%p%z0), this%p%z0, 0.0_wp, 0.0_wp, this%l7)
         s%p_edge = s%y_g + ap*s%tg - this%e_edge - s%ln%h
         s%f_edge = this%p%k_edge*max(s%p_edge - mem%edge_ref, 0.0_wp)
         s%e_contact = s%e_contact + 0.5_wp*this%p%k_edge*max(s%p_edge - mem%edge_ref, 0.0_wp)**2
      end if
      ! C.4.d friction at the hip, on the beam's load (A-S4, A-f)
      s%f = hip_friction(this%p%mu, s%f_hip + s%f_edge, mem%slip)
      ! the frame's pseudo-forces on the beam (A-RB): translation, and the pitch
      ! acceleration and rate at the CG; the angle feels Phi'' (gamma is measured
      ! from the turning interior)
      phi_dd = st%vehicle%acc(3)
      ac_y = st%vehicle%acc(1)*s%fr%s_phi + st%vehicle%acc(2)*s%fr%c_phi
      q_ps = [this%p%m_s*(-ac_y + phi_dd*this%x_g + s%fr%phi_dot**2*s%y_g), this%p%i_s*phi_dd]
      s%acc(1) = (s%f_s + s%fp_s - s%f_hip - s%f_edge - this%p%m_s*this%g*s%fr%c_phi + q_ps(1))/this%p%m_s
      ! RB-1 (moments about the CG) and RB-2 (sec^2 gamma)
      s%acc(2) = s%sec2*(ap*(s%fp_s - s%f_edge) - (a - ap)*s%f_s - (s%fr%x1 - this%x_g)*s%f_hip)/this%p%i_s &
                 + q_ps(2)/this%p%i_s
      s%e_kin = 0.5_wp*(this%p%m_s*s%yg_dot**2 + this%p%i_s*s%gam_dot**2)
      s%e_grav = this%p%m_s*this%g*s%fr%c_phi*(s%y_g - this%p%yg0)
      ! dissipated: the rear damper and the clip of its force, and the friction
      s%dissipation = (s%f_s - s%fs_el)*s%ds_dot + s%f*s%fr%x1dot
      ! supplied (docs/seat.md): the body's contact forces at the vehicle's
      ! material points, the pseudo-forces' power, and the turning of gravity
      fh = [-s%f_hip*s%tg - s%f, s%f_hip]
      fe = s%f_edge*[-s%ln%tan_phi, 1.0_wp]
      s%supply = vehicle_power(s%fr, fh, [s%fr%x1, s%fr%y1]) + vehicle_power(s%fr, fe, [this%p%z0, s%ln%h]) &
                 + q_ps(1)*s%yg_dot + q_ps(2)*s%gam_dot &
                 - this%p%m_s*this%g*s%fr%s_phi*s%fr%phi_dot*(s%y_g - this%p%yg0)
   end function beam_state

   pure subroutine beam_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(beam_state_t) :: s
      associate (u1 => size(aux))
      end associate
      s = beam_state(this, st, extra, this%mem)
      ! on the body: the hip contact, normal to the beam (-F tan gamma, F), the
      ! friction -f, and the leg contact normal to the leg line (A-S1)
      call add_hip_force(s%fr, [-s%f_hip*s%tg - s%f, s%f_hip], b)
      b = b + s%f_edge*s%ln%dh
      extra_rate = [extra(3), extra(4), s%acc(1), s%acc(2)]
      aux_rate(1) = s%dissipation
      aux_rate(2) = s%supply
   end subroutine beam_add_forces

   !> The hip contact, friction and leg contact on the body, as point forces.
   pure subroutine beam_point_forces(this, st, extra, aux, list)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      type(beam_state_t) :: s
      associate (u1 => size(aux))
      end associate
      s = beam_state(this, st, extra, this%mem)
      call add_seat_point_forces(s%fr, st%vehicle%pos, [-s%f_hip*s%tg - s%f, s%f_hip], &
                                 s%f_edge*[-s%ln%tan_phi, 1.0_wp], [this%p%z0, s%ln%h], s%ln%seg, list)
   end subroutine beam_point_forces

   !> On accepted steps (figure 12's logic, as for the present seat): the hip
   !! leaves the beam past its front edge (z < 0) or comes back, the leg
   !! leaves the edge or comes onto it, the hip slides or sticks. D-25: a
   !! contact that comes into action starts from its present penetration (its
   !! reference), so a switch never makes energy; a reference is given up once
   !! the body is clear of the beam, where neither law carries anything.
   subroutine beam_accept(this, st, extra, aux, result)
      class(seat_rigid_beam_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      type(seat_memory_t) :: new, probe_mem
      type(beam_state_t) :: before, after, probe
      logical :: released
      associate (u1 => size(aux))
      end associate
      before = beam_state(this, st, extra, this%mem)
      new = this%mem
      new%case = merge(case_off, case_a, before%z < 0.0_wp)
      new%leg_on = new%case /= case_off .and. leg_rests(before%fr, this%p%z0, this%l7, this%l8)
      ! the penetrations at this state, whatever the memory
      probe_mem = new
      probe_mem%case = case_a
      probe_mem%leg_on = .true.
      probe_mem%hip_ref = 0.0_wp
      probe_mem%edge_ref = 0.0_wp
      probe = beam_state(this, st, extra, probe_mem)
      released = .false.
      call contact_reference(new%case /= case_off, before%on, probe%p_hip, probe%p_hip, new%hip_ref, released)
      call contact_reference(new%leg_on, before%leg, probe%p_edge, probe%p_edge, new%edge_ref, released)
      call hip_sliding_decided(this%mem, new%case /= case_off, this%p%xi, before%fr%x1dot, new)
      if (new%case == this%mem%case .and. (new%leg_on .eqv. this%mem%leg_on) .and. new%slip == this%mem%slip &
          .and. new%edge == this%mem%edge .and. .not. released) return
      after = beam_state(this, st, extra, new)
      new%e_switch = this%mem%e_switch + before%e_contact - after%e_contact
      this%mem = new
      result%restart = .true.
   end subroutine beam_accept

   !> Issue 15: the rigid beam's switching functions at st, beam state
   !! extra, with its memory, each zero where a force comes on or off or
   !! figure 12's decision changes (docs/seat.md, "Switches (issue 15)"):
   !!   1  z (in): the hip off the beam below 0
   !!   2  min(k Delta_s, F_s,el + c_s Delta_s') (lb), k = beta_1 (1 lb/in if
   !!      0): the rear support's force is positive exactly where both are
   !!   3  Delta_z (in): the front support's spring
   !!   4  the hip's penetration beyond its reference (in), while on the beam
   !!   5  the edge's penetration beyond its reference (in), while the leg
   !!      rests on the edge
   !!   6  x_knee - z_o (in), while the leg rests on the edge: the branch
   !!   7  leg_rest_margin (in): figure 12's leg on the edge
   !! A function that does not apply in the memory held is +1.
   pure subroutine beam_switches(this, st, extra, aux, g)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      type(beam_state_t) :: s
      associate (u1 => size(aux))
      end associate
      s = beam_state(this, st, extra, this%mem)
      g = 1.0_wp
      g(1) = s%z
      g(2) = min(merge(this%p%beta(1), 1.0_wp, this%p%beta(1) > 0.0_wp)*s%ds, s%fs_el + this%p%c_s*s%ds_dot)
      g(3) = s%dz
      if (s%on) g(4) = s%p_hip - this%mem%hip_ref
      if (s%leg) then
         g(5) = s%p_edge - this%mem%edge_ref
         g(6) = leg_branch_margin(s%fr, this%p%z0)
      end if
      g(7) = leg_rest_margin(s%fr, this%p%z0, this%l7, this%l8)
      if (this%p%mu > 0.0_wp) call hip_slide_switches(s%fr, this%p%xi, this%mem%case /= case_off, this%mem%edge, &
                                                     g(this%n_switch - 1:this%n_switch))
   end subroutine beam_switches

   !> The hip held on an edge of its dead band (issue 15, D-19a): its
   !! sliding constraint, the friction's range mu times the normal load.
   pure subroutine beam_slides(this, st, extra, aux, s)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(slide_t), intent(out) :: s(:)
      type(beam_state_t) :: ss
      associate (u1 => size(aux))
      end associate
      if (this%mem%edge == 0 .or. this%mem%case == case_off) return
      ss = beam_state(this, st, extra, this%mem)
      s(1) = hip_slide(ss%fr, st%vehicle%acc, this%p%mu, ss%f_hip + ss%f_edge, this%p%xi, this%mem%edge, &
                       1, 2)
   end subroutine beam_slides

   !> The hip leaves its edge (D-19a).
   subroutine beam_release(this, k, at_upper)
      class(seat_rigid_beam_t), intent(inout) :: this
      integer, intent(in) :: k
      logical, intent(in) :: at_upper
      associate (u1 => k)
      end associate
      call hip_released(this%mem, this%p%xi, at_upper)
   end subroutine beam_release

   pure subroutine beam_energy(this, st, extra, aux, e)
      class(seat_rigid_beam_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      type(beam_state_t) :: s
      s = beam_state(this, st, extra, this%mem)
      e(energy_stored) = s%e_kin + s%e_support + s%e_contact + s%e_grav
      e(energy_dissipated) = aux(1) + this%mem%e_switch
      e(energy_supplied) = aux(2)
   end subroutine beam_energy

   function beam_outputs(this) result(series)
      class(seat_rigid_beam_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      allocate (series(3))
      series(1) = series_new('loads', 'RIGID-BEAM SEAT LOADS (C.4.d)', 'contact forces of the beam on the body: ' &
                             //'F_hip (vertical component; normal to the beam) and F_edge (vertical component; ' &
                             //'normal to the leg, horizontal part Fe_x), the friction magnitude f; the support ' &
                             //'forces F_s (rear, beta and c_s) and Fp_s (front, s) on the beam', 2)
      series(1)%col = [column('F_hip', 'lb'), column('F_edge', 'lb'), column('Fe_x', 'lb'), column('f', 'lb'), &
                       column('F_s', 'lb'), column('Fp_s', 'lb')]
      series(2) = series_new('beam', 'RIGID-BEAM SEAT MOTION (C.4.d, FIGURE 15)', 'the beam''s CG height y_g and ' &
                             //'angle gamma, the support deflections Delta_s, Delta_z, z = z_o - x_1, whether the ' &
                             //'hip is on the beam (1) and which leg segment rests on the front edge (7, 8; 0 none)', 3)
      series(2)%col = [column('y_g', 'in'), column('gamma', 'rad', 'deg', 1.0_wp/deg), column('Delta_s', 'in'), &
                       column('Delta_z', 'in'), column('z', 'in'), column('on', '-'), column('leg', '-')]
      series(3) = series_new('energy', 'RIGID-BEAM SEAT ENERGIES (C.6)', 'the beam''s kinetic energy (interior), ' &
                             //'its supports, the body''s contacts, its gravity; dissipated by the damper and ' &
                             //'friction, moved out of the contacts by figure 12''s switches; supplied by the vehicle', 3)
      series(3)%col = [column('kinetic', 'in*lb'), column('supports', 'in*lb'), column('contacts', 'in*lb'), &
                       column('gravity', 'in*lb'), column('damp_frict', 'in*lb'), column('switching', 'in*lb'), &
                       column('supplied', 'in*lb')]
   end function beam_outputs

   pure subroutine beam_output_values(this, item, st, extra, aux, values)
      class(seat_rigid_beam_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      type(beam_state_t) :: s
      integer :: leg
      s = beam_state(this, st, extra, this%mem)
      leg = 0
      if (s%leg) leg = s%ln%seg
      select case (item)
      case (1)
         values = [s%f_hip, s%f_edge, -s%f_edge*s%ln%tan_phi, s%f, s%f_s, s%fp_s]
      case (2)
         values = [s%y_g, s%gam, s%ds, s%dz, s%z, merge(1.0_wp, 0.0_wp, s%on), real(leg, wp)]
      case default
         values = [s%e_kin, s%e_support, s%e_contact, s%e_grav, aux(1), this%mem%e_switch, aux(2)]
      end select
   end subroutine beam_output_values

   function beam_describe(this) result(text)
      class(seat_rigid_beam_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': a '//r2(this%p%a)//', a'' '//r2(this%p%a_prime)//', y_go '//r2(this%p%yg0) &
             //' in, gamma_o '//r2(this%p%gamma0/deg)//' deg; W_o '//r2(this%p%w0)//', F^''_so '//r2(this%p%fhps0) &
             //', F_so '//r2(this%p%fs0)//', F''_so '//r2(this%p%fps0)//' lb'
      text = text(1:min(len(text), 128))
   contains
      function r2(x) result(t)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: t
         t = num(anint(100.0_wp*x)/100.0_wp)
      end function r2
   end function beam_describe
end module seat_rigid_beam
