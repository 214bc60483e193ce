!> Report C.4.d, what the three seat representations share (docs/seat.md):
!! the hip in the vehicle interior (the start of C.4), the leg line that
!! rests on the front edge of the seat (figure 11: the thigh for an adult,
!! the shank for a child whose legs stick out), the friction at the hip,
!! the power of a seat force against the vehicle, and the logic of figure
!! 12 that decides, on accepted steps only, whether the occupant is on the
!! seat, in the front region z <= z-hat, and whether his leg rests on the
!! front edge.
!!
!! Conventions (errata-forces.md): interior coordinates x forward, y up,
!! from the initial hip; Theta_i = alpha_i + Phi; z = z_o - x_1 is the
!! horizontal hip to front-edge distance. Forces are given in interior
!! components; the generalized force of a force F at a body point P is
!! F . dP/dz_k with the vehicle held fixed (virtual work).
module seat_geometry
   use kinds, only: wp, deg
   use segment_trig, only: segment_cos_sin
   use model, only: n_dof, n_seg, hip_x, hip_y
   use body_state, only: body_state_t
   use point_forces, only: point_force_list_t, point_force_add
   use dead_band, only: slip_of, edge_at, edge_range, slip_released   ! (the hip slides once |x_1'| reaches xi, A-S4)
   use sliding_surface, only: slide_t
   use seat_beam_statics, only: poly_force   ! (the statics at t = 0 use it too: C.2 below C.4)
   implicit none
   private

   public :: seat_frame_t, seat_frame, leg_line_t, leg_line, leg_branch, leg_rests, leg_rest_margin, leg_branch_margin
   public :: seat_memory_t, seat_case, hip_friction, slip_of, vehicle_power, add_hip_force, rest_state
   public :: case_off, case_a, case_b, seg_thigh, seg_shank, max_leg_slope
   public :: add_seat_point_forces, contact_reference, poly_force, poly_energy
   public :: hip_slide, hip_slide_switches, hip_sliding_decided, hip_released

   integer, parameter :: seg_thigh = 7, seg_shank = 8
   !> Figure 11's cases: off the seat (z < 0), case A (z > z-hat: hip
   !! spring-damper and front-edge spring), case B (0 <= z <= z-hat: the
   !! hip spring linear).
   integer, parameter :: case_off = 0, case_a = 1, case_b = 2
   !> A leg segment steeper than this does not rest on the front edge: the
   !! front-edge force normal to it (erratum A-S1) would grow without bound
   !! (tan Theta_8 of the shank case; docs/seat.md).
   real(wp), parameter :: max_leg_slope = 75.0_wp*deg

   !> The interior frame at one evaluation: the pitch, the hip's interior
   !! position and rate (x_1, y_1 and their rates, with the -y Phi', +x Phi'
   !! terms of C.4), the thigh and shank angles Theta_7, Theta_8 and rates, and
   !! the velocity of the interior origin in interior components (R c').
   type :: seat_frame_t
      real(wp) :: c_phi = 1.0_wp, s_phi = 0.0_wp, phi_dot = 0.0_wp
      real(wp) :: x1 = 0.0_wp, y1 = 0.0_wp, x1dot = 0.0_wp, y1dot = 0.0_wp
      real(wp) :: c7 = 1.0_wp, s7 = 0.0_wp, c8 = 1.0_wp, s8 = 0.0_wp
      real(wp) :: th7dot = 0.0_wp, th8dot = 0.0_wp
      real(wp) :: vc(2) = 0.0_wp
      real(wp) :: knee(2) = 0.0_wp, knee_dot(2) = 0.0_wp   !< knee, interior
   end type seat_frame_t

   !> Where a leg line crosses the vertical x = x_e (the front edge): its
   !! height h there, the rate of h (interior), its slope tan phi, and the
   !! gradient dh/dz. The material point of the leg at the crossing carries a
   !! force normal to the line (A-S1).
   type :: leg_line_t
      integer :: seg = seg_thigh
      real(wp) :: h = 0.0_wp, h_dot = 0.0_wp, tan_phi = 0.0_wp
      real(wp) :: dh(n_dof) = 0.0_wp
   end type leg_line_t

   !> What the seat remembers between accepted steps (figure 12 as
   !! reconstructed in docs/seat.md): the case, whether the leg rests on the
   !! front edge, the direction the hip slides in (+1, -1; 0 within the dead
   !! band xi), the spring constant of case B (chosen at the switch, A-S4),
   !! the references of the hip's and the front edge's springs (or contacts:
   !! each acts on its compression beyond its reference, chosen at a switch
   !! so that no force jumps up and no energy is made: docs/seat.md, D-25),
   !! and the energy the switches moved out of the stored energy.
   type :: seat_memory_t
      integer :: case = case_a
      logical :: leg_on = .true.
      integer :: slip = 0
      !> the hip held on an edge of the dead band (issue 15, D-19a): +1 at
      !! x_1' = +xi, -1 at -xi (both at 0 when xi = 0), 0 not
      integer :: edge = 0
      real(wp) :: k_hat = 0.0_wp
      real(wp) :: hip_ref = 0.0_wp, edge_ref = 0.0_wp
      real(wp) :: e_switch = 0.0_wp
   end type seat_memory_t

contains

   !> The body at rest at z0 in a vehicle at rest at pitch phi0 (the initial
   !! posture, from which figure 12's memory starts).
   pure function rest_state(z0, phi0) result(st)
      real(wp), intent(in) :: z0(n_dof), phi0
      type(body_state_t) :: st
      st%t = 0.0_wp
      st%z = z0
      st%zdot = 0.0_wp
      call segment_cos_sin(z0(1:n_seg), st%c, st%s)     ! (segment_trig: the same bits in every build)
      st%vehicle%pos = [0.0_wp, 0.0_wp, phi0]
      st%vehicle%vel = 0.0_wp
      st%vehicle%acc = 0.0_wp
   end function rest_state

   !> The interior frame at st (the start of C.4; vehicle state in st%vehicle).
   pure function seat_frame(st, l7) result(fr)
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: l7
      type(seat_frame_t) :: fr
      real(wp) :: dx, dy, dvx, dvy
      associate (v => st%vehicle)
         fr%c_phi = cos(v%pos(3))
         fr%s_phi = sin(v%pos(3))
         fr%phi_dot = v%vel(3)
         dx = st%z(hip_x) - v%pos(1)
         dy = st%z(hip_y) - v%pos(2)
         dvx = st%zdot(hip_x) - v%vel(1)
         dvy = st%zdot(hip_y) - v%vel(2)
         ! C.4: x_1 = R(Phi)(X_h - x_c), and its rate in the rotating frame
         fr%x1 = dx*fr%c_phi - dy*fr%s_phi
         fr%y1 = dx*fr%s_phi + dy*fr%c_phi
         fr%x1dot = dvx*fr%c_phi - dvy*fr%s_phi - fr%y1*fr%phi_dot
         fr%y1dot = dvx*fr%s_phi + dvy*fr%c_phi + fr%x1*fr%phi_dot
         fr%vc = [v%vel(1)*fr%c_phi - v%vel(2)*fr%s_phi, v%vel(1)*fr%s_phi + v%vel(2)*fr%c_phi]
      end associate
      ! Theta_i = alpha_i + Phi (section B)
      fr%c7 = st%c(7)*fr%c_phi - st%s(7)*fr%s_phi
      fr%s7 = st%s(7)*fr%c_phi + st%c(7)*fr%s_phi
      fr%c8 = st%c(8)*fr%c_phi - st%s(8)*fr%s_phi
      fr%s8 = st%s(8)*fr%c_phi + st%c(8)*fr%s_phi
      fr%th7dot = st%zdot(7) + fr%phi_dot
      fr%th8dot = st%zdot(8) + fr%phi_dot
      fr%knee = [fr%x1 + l7*fr%c7, fr%y1 + l7*fr%s7]
      fr%knee_dot = [fr%x1dot - l7*fr%th7dot*fr%s7, fr%y1dot + l7*fr%th7dot*fr%c7]
   end function seat_frame

   !> Figure 11: the front edge (at x = x_e) lies under the thigh when z <=
   !! L_7 cos Theta_7 (an adult), else under the shank (a child).
   pure integer function leg_branch(fr, x_e)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: x_e
      if (leg_branch_margin(fr, x_e) >= 0.0_wp) then
         leg_branch = seg_thigh
      else
         leg_branch = seg_shank
      end if
   end function leg_branch

   !> The leg rests on the front edge: the segment over it is no steeper
   !! than max_leg_slope and, for the thigh, the hip is behind the edge; for
   !! the shank, the foot reaches past it (leg_rest_margin >= 0).
   pure logical function leg_rests(fr, x_e, l7, l8)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: x_e, l7, l8
      leg_rests = leg_rest_margin(fr, x_e, l7, l8) >= 0.0_wp
   end function leg_rests

   !> By how much the leg rests on the front edge (in): the least of the
   !! margins of leg_rests' conditions, each a length - the segment's
   !! slope as L (cos Theta - cos 75 deg), the hip behind the edge x_e -
   !! x_1 (thigh), the foot past it L_8 cos Theta_8 - (x_e - x_knee)
   !! (shank). Its sign is leg_rests' answer, bit for bit (the sign of a
   !! difference is exact); within a branch it is continuous in the state,
   !! so it is the switching function of the leg's coming onto or off the
   !! edge (issue 15). It may jump where the branch changes, which is a
   !! switch of its own (leg_branch_margin).
   pure real(wp) function leg_rest_margin(fr, x_e, l7, l8) result(margin)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: x_e, l7, l8
      ! (a segment of no length scales its slope's margin by 1 in; the
      ! product of a positive length and a difference of cosines keeps its sign)
      if (leg_branch(fr, x_e) == seg_thigh) then
         margin = min(merge(l7, 1.0_wp, l7 > 0.0_wp)*(fr%c7 - cos(max_leg_slope)), x_e - fr%x1)
      else
         margin = min(merge(l8, 1.0_wp, l8 > 0.0_wp)*(fr%c8 - cos(max_leg_slope)), l8*fr%c8 - (x_e - fr%knee(1)))
      end if
   end function leg_rest_margin

   !> Where the edge passes the knee (in): >= 0 when the thigh lies over
   !! the edge (leg_branch), the shank's otherwise; the front-edge force
   !! has a corner there (issue 15).
   pure real(wp) function leg_branch_margin(fr, x_e)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: x_e
      leg_branch_margin = fr%knee(1) - x_e
   end function leg_branch_margin

   !> The leg line of segment seg (7 thigh from the hip, 8 shank from the
   !! knee) at angle phi = Theta_seg + omega, offset by r from the joint to
   !! the side of its underside (r = omega = 0: the centre line of C.4.d;
   !! r, omega: the common tangent of two arcs, A-NB), where it crosses x = x_e.
   !! With r = omega = 0 its height is y_1 + y_z and dh/dz is d y_1/dz + the
   !! printed partials of y_z: for the thigh z sec^2 Theta_7, 0, -cos Phi tan
   !! Theta_7, sin Phi tan Theta_7; for the shank L_7(cos Theta_7 + sin Theta_7
   !! tan Theta_8), (z - L_7 cos Theta_7) sec^2 Theta_8, -cos Phi tan Theta_8,
   !! sin Phi tan Theta_8 (C.4.d, verified in errata-forces.md).
   pure function leg_line(fr, seg, x_e, r, omega, l7) result(ln)
      type(seat_frame_t), intent(in) :: fr
      integer, intent(in) :: seg
      real(wp), intent(in) :: x_e, r, omega, l7
      type(leg_line_t) :: ln
      real(wp) :: cp, sp, j(2), jdot(2), b(2), sec2, phidot
      ln%seg = seg
      if (seg == seg_thigh) then
         cp = fr%c7*cos(omega) - fr%s7*sin(omega)
         sp = fr%s7*cos(omega) + fr%c7*sin(omega)
         j = [fr%x1, fr%y1]
         jdot = [fr%x1dot, fr%y1dot]
         phidot = fr%th7dot
      else
         cp = fr%c8*cos(omega) - fr%s8*sin(omega)
         sp = fr%s8*cos(omega) + fr%c8*sin(omega)
         j = fr%knee
         jdot = fr%knee_dot
         phidot = fr%th8dot
      end if
      ! a numerical guard only: figure 12's logic (leg_rests, on accepted
      ! steps) lifts the leg off the edge long before the line is this steep.
      ! The floor keeps the segment's direction: a segment that points back
      ! (cos < 0, the shank behind a knee the edge has just passed inside a
      ! step) keeps its own line, not a near-vertical one through the edge
      if (abs(cp) < 1.0e-3_wp) cp = sign(1.0e-3_wp, cp)
      ln%tan_phi = sp/cp
      sec2 = 1.0_wp + ln%tan_phi**2
      b = j + r*[sp, -cp]
      ln%h = b(2) + (x_e - b(1))*ln%tan_phi
      ! rate in the interior frame; the offset r turns with the segment and
      ! drops out (d/dphi of b_y - b_x tan phi is 0)
      ln%h_dot = jdot(2) - jdot(1)*ln%tan_phi + (x_e - b(1))*sec2*phidot
      ln%dh = 0.0_wp
      ln%dh(seg) = (x_e - b(1))*sec2
      if (seg == seg_shank) ln%dh(seg_thigh) = l7*(fr%c7 + fr%s7*ln%tan_phi)
      ! d(x_1, y_1)/dx_h = (cos Phi, sin Phi), d/dy_h = (-sin Phi, cos Phi)
      ln%dh(hip_x) = fr%s_phi - ln%tan_phi*fr%c_phi
      ln%dh(hip_y) = fr%c_phi + ln%tan_phi*fr%s_phi
   end function leg_line

   !> Add the generalized forces of a force f (interior components) applied
   !! at the hip: S_9, S_10 (C.4.d; the hip does not move with the alpha_i).
   pure subroutine add_hip_force(fr, f, b)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: f(2)
      real(wp), intent(inout) :: b(n_dof)
      b(hip_x) = b(hip_x) + f(1)*fr%c_phi + f(2)*fr%s_phi
      b(hip_y) = b(hip_y) - f(1)*fr%s_phi + f(2)*fr%c_phi
   end subroutine add_hip_force

   !> C.4.d friction at the hip: f = mu (F_s + F'_s) sgn x_1' while the hip
   !! slides (slip = sgn x_1', decided on accepted steps), zero within the
   !! dead band (A-S4); the force on the body is -f along the interior x (A-f).
   pure real(wp) function hip_friction(mu, n, slip) result(f)
      real(wp), intent(in) :: mu, n
      integer, intent(in) :: slip
      f = mu*max(n, 0.0_wp)*real(slip, wp)
   end function hip_friction

   !> The hip held on an edge of its dead band (issue 15, D-19a; as the
   !! joints, D-4b): its sliding velocity x_1' stays there while the friction
   !! the motion needs (on the body, along the interior x) lies within the
   !! law's range on the two sides, mu n beyond the edge (edge_range). With
   !! x_1' = (X_h' - x_c') . (cos Phi, -sin Phi) - y_1 Phi' (seat_frame):
   !!   d      = (cos Phi, -sin Phi) in (x_h, y_h), the generalized force of a
   !!            unit interior-x force at the hip (add_hip_force);
   !!   offset = -(R c')_x - y_1 Phi', the vehicle's part;
   !!   bias   = -(R c'')_x - 2 y_1' Phi' + x_1 Phi'^2 - y_1 Phi'', its rate's
   !!            part that z'' does not give (y_1' the rotating frame's rate).
   !! acc: the vehicle's accelerations (x_c'', y_c'', Phi''). The friction's
   !! power goes to the seat's dissipated work (its auxiliary quantity
   !! aux_dissipated), the vehicle's to the supplied (aux_supplied), as the
   !! seat integrates its own.
   pure function hip_slide(fr, acc, mu, n, xi, edge, aux_dissipated, aux_supplied) result(sl)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: acc(3), mu, n, xi
      integer, intent(in) :: edge, aux_dissipated, aux_supplied
      type(slide_t) :: sl
      sl%active = edge /= 0
      if (.not. sl%active) return
      sl%d(hip_x) = fr%c_phi
      sl%d(hip_y) = -fr%s_phi
      sl%offset = -(fr%vc(1) + fr%phi_dot*fr%y1)
      sl%bias = -(acc(1)*fr%c_phi - acc(2)*fr%s_phi) - 2.0_wp*fr%y1dot*fr%phi_dot + fr%x1*fr%phi_dot**2 &
                - fr%y1*acc(3)
      call edge_range(xi, edge, mu*max(n, 0.0_wp), sl%lo, sl%hi)
      sl%aux_dissipated = aux_dissipated
      sl%aux_supplied = aux_supplied
   end function hip_slide

   !> The hip's sliding switches (issue 15, D-19a): x_1' - xi and x_1' + xi
   !! (in/s) where the sliding direction changes (slip_of), while on the
   !! seat and not held on an edge (held, it leaves by its friction's
   !! range: the occupant's sliding switches); +1 otherwise.
   pure subroutine hip_slide_switches(fr, xi, on, edge, g)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: xi
      logical, intent(in) :: on
      integer, intent(in) :: edge
      real(wp), intent(out) :: g(2)
      g = 1.0_wp
      if (.not. on .or. edge /= 0) return
      g = [fr%x1dot - xi, fr%x1dot + xi]
   end subroutine hip_slide_switches

   !> Figure 12's hip sliding decided on an accepted state (D-19, D-19a):
   !! off the seat nothing; held on an edge it stays (left by hip_released);
   !! else the direction at x_1' = v, and where it changed with v on an edge
   !! of the dead band (a located switch), held there.
   pure subroutine hip_sliding_decided(old, on, xi, v, new)
      type(seat_memory_t), intent(in) :: old
      logical, intent(in) :: on
      real(wp), intent(in) :: xi, v
      type(seat_memory_t), intent(inout) :: new
      new%slip = 0
      new%edge = 0
      if (.not. on) return
      if (old%edge /= 0) then
         new%edge = old%edge
         return
      end if
      new%slip = slip_of(xi, v)
      if (new%slip /= old%slip) then
         new%edge = edge_at(xi, v)
         if (new%edge /= 0) new%slip = 0
      end if
   end subroutine hip_sliding_decided

   !> The hip leaves its edge (D-19a): its friction reached the upper end
   !! of its range (at_upper) or the lower (slip_released).
   pure subroutine hip_released(mem, xi, at_upper)
      type(seat_memory_t), intent(inout) :: mem
      real(wp), intent(in) :: xi
      logical, intent(in) :: at_upper
      mem%slip = slip_released(xi, mem%edge, at_upper)
      mem%edge = 0
   end subroutine hip_released

   !> The power that the vehicle delivers through a seat force f (on the
   !! body, interior components) acting at the interior point p: f . R u,
   !! u the velocity of the vehicle's material point at p, R u = R c' +
   !! Phi' (p_y, -p_x) (docs/seat.md, "Energy").
   pure real(wp) function vehicle_power(fr, f, p)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: f(2), p(2)
      vehicle_power = f(1)*(fr%vc(1) + fr%phi_dot*p(2)) + f(2)*(fr%vc(2) - fr%phi_dot*p(1))
   end function vehicle_power

   !> A seat's forces on the body as point forces (for the joint reactions):
   !! f_hip (interior) at the hip, on the lower torso, and f_edge (interior,
   !! normal to the leg's underside) at the leg's material point over the
   !! front edge, edge = (x_e, h), on segment seg; each turned into the
   !! inertial frame, X = x_c + R(Φ)ᵀ x. Their virtual work is the seat's S.
   pure subroutine add_seat_point_forces(fr, vpos, f_hip, f_edge, edge, seg, list)
      type(seat_frame_t), intent(in) :: fr
      real(wp), intent(in) :: vpos(3), f_hip(2), f_edge(2), edge(2)
      integer, intent(in) :: seg
      type(point_force_list_t), intent(inout) :: list
      if (any(abs(f_hip) > 0.0_wp)) call point_force_add(list, 1, inertial(fr, [fr%x1, fr%y1]) + vpos(1:2), &
                                                     inertial(fr, f_hip), across_bone=.false.)   ! at the hip joint
      if (any(abs(f_edge) > 0.0_wp)) call point_force_add(list, seg, inertial(fr, edge) + vpos(1:2), inertial(fr, f_edge))
   contains
      pure function inertial(frame, v) result(w)
         type(seat_frame_t), intent(in) :: frame
         real(wp), intent(in) :: v(2)
         real(wp) :: w(2)
         w = [frame%c_phi*v(1) + frame%s_phi*v(2), -frame%s_phi*v(1) + frame%c_phi*v(2)]
      end function inertial
   end subroutine add_seat_point_forces

   !> D-25: a seat contact's reference (the compression it acts beyond) at
   !! an accepted step: none while it does not act; when it comes into
   !! action, start (its present compression), so that no force jumps up; given
   !! up (released: the stepper restarts) once the body is clear of the
   !! undeflected cushion (penetration <= 0), where it carries nothing.
   pure subroutine contact_reference(acting, was_acting, start, penetration, ref, released)
      logical, intent(in) :: acting, was_acting
      real(wp), intent(in) :: start, penetration
      real(wp), intent(inout) :: ref
      logical, intent(inout) :: released
      if (.not. acting) then
         ref = 0.0_wp
      else if (.not. was_acting) then
         ref = max(0.0_wp, start)
      else if (ref > 0.0_wp .and. penetration <= 0.0_wp) then
         ref = 0.0_wp
         released = .true.
      end if
   end subroutine contact_reference

   !> Figure 12 (reconstructed): off the seat when the hip has passed the
   !! front edge (z < 0), case B within z-hat of it, case A behind.
   pure integer function seat_case(z, z_hat)
      real(wp), intent(in) :: z, z_hat
      if (z < 0.0_wp) then
         seat_case = case_off
      else if (z <= z_hat) then
         seat_case = case_b
      else
         seat_case = case_a
      end if
   end function seat_case

   !> C.6 (E6-1): its energy sum beta_m u^{m+1}/(m+1).
   pure real(wp) function poly_energy(beta, u)
      real(wp), intent(in) :: beta(3), u
      poly_energy = u**2*(beta(1)/2.0_wp + u*(beta(2)/3.0_wp + u*beta(3)/4.0_wp))
   end function poly_energy
end module seat_geometry
