!> The geometry of the contacts of C.4.f (docs/contacts.md 1-3): the body's
!! contact features (equations f.1 with errata F1-1, F1-2; the segment that
!! carries each arc, D-C1; the shin capsule, D-C2), the surfaces' features
!! (a flat piece, an infinite line, the head rest's circle, the lower
!! panel's edge) and the check of figure 22 (D-C16): which primitive acts
!! and its penetration delta, normal n (from the surface to the body),
!! tangent t (n turned by -90 deg), contact point C, position T, and the
!! rates delta' = -V_C.n and v_T = V_C.t of the material point C (f.2 with
!! F2-1, f.3 with F3-1, F3-2, F24-1). All in the interior frame of C.4.
!! Pure functions, no memory: the contact effects are built on them.
module contact_geometry
   use kinds, only: wp, pi
   use model, only: body_section_t, n_seg, n_dof
   use body_kinematics, only: point_state_t, joint_state, to_interior, joint_position_velocity
   implicit none
   private

   public :: contact_feature_t, contact_surface_t, contact_state_t
   public :: body_feature, shin_alpha0, contact_check, arc_segment, front_side, shin_side_now, e
   public :: region_switch_count, region_switches
   public :: surface_flat, surface_line, surface_circle, surface_point
   public :: region_none, region_face, region_corner, region_circle, region_shin_line, region_shin_knee, &
      region_shin_ankle, region_end_wall, region_shin_far

   !> The segment that carries each arc i = 1..10 (D-C1, A-C2, F3-1).
   integer, parameter :: arc_segment(10) = [1, 3, 3, 4, 5, 5, 7, 8, 8, 6]
   !> The joint at the proximal end of each segment (the hip for 1 and 7).
   integer, parameter :: proximal_joint(n_seg) = [1, 2, 3, 4, 5, 6, 1, 7]

   integer, parameter :: surface_flat = 1, surface_line = 2, surface_circle = 3, surface_point = 4
   integer, parameter :: region_none = 0, region_face = 1, region_corner = 2, region_circle = 3, &
      region_shin_line = 4, region_shin_knee = 5, region_shin_ankle = 6
   !> D-C16b: the end of a flat surface's solid met from inside it (a point
   !! come through the face, its centre behind the line); the shin met by
   !! an edge that crossed its axis (the far half, its faces: the near
   !! tangent, the planes across the axis through the knee's top and the
   !! ankle's bottom)
   integer, parameter :: region_end_wall = 7, region_shin_far = 8

   !> A body feature (interior frame): an arc of radius r centred at the
   !! material point p of segment seg, or (i = 9) the shin capsule.
   type :: contact_feature_t
      integer :: arc = 0, seg = 0
      real(wp) :: p(2) = 0.0_wp, r = 0.0_wp
      !> the segment's proximal joint and its velocity, its angle and rate
      real(wp) :: joint(2) = 0.0_wp, joint_vel(2) = 0.0_wp, theta = 0.0_wp, theta_dot = 0.0_wp
      !> the shin: the ankle's centre, its radius, the knee's radius, alpha_0
      real(wp) :: ankle(2) = 0.0_wp, r_ankle = 0.0_wp, alpha0 = 0.0_wp
   end type contact_feature_t

   !> A surface feature (interior frame): a flat piece from s back along
   !! -e(psi) by d (with an opening between t_open(1) and t_open(2) when
   !! t_open(2) > t_open(1)), an infinite line through s at psi, a circle
   !! of diameter d centred at s, or the point s (the lower panel's edge).
   type :: contact_surface_t
      integer :: kind = surface_flat
      real(wp) :: s(2) = 0.0_wp, psi = 0.0_wp, d = 0.0_wp
      real(wp) :: t_open(2) = 0.0_wp
   end type contact_surface_t

   type :: contact_state_t
      integer :: region = region_none
      real(wp) :: delta = 0.0_wp, delta_dot = 0.0_wp
      real(wp) :: n(2) = 0.0_wp, t(2) = 0.0_wp, c(2) = 0.0_wp
      real(wp) :: pos = 0.0_wp           !< T, where along the surface (or the shin) it acts
      real(wp) :: v_t = 0.0_wp           !< sliding velocity of the body's material point along t
      !> which face of a solid met from inside acts (D-C16b; issue 15): a
      !! flat surface's face (1) or the walls past its ends at T = a (2) and
      !! b (3) of the piece [a, b], 3 more for the rim's second piece; the
      !! shin's far half's near tangent (1), knee top (2) or ankle bottom
      !! (3). 0 elsewhere.
      integer :: face = 0
   end type contact_state_t

contains

   !> alpha_0 of C.2: the angle of the shin (the common tangent of the knee
   !! circle r_7 and the ankle circle r_A) to the lower leg's centre line.
   pure real(wp) function shin_alpha0(body) result(a)
      type(body_section_t), intent(in) :: body
      a = asin((body%r_arc(7) - body%r_arc(11))/body%length(8))
   end function shin_alpha0

   !> Body feature i (f.1 with F1-1, F1-2) at the inertial state (z, z')
   !! and the vehicle's position and rates vpos, vvel, in the interior frame.
   !! (c, s: the cosines and sines of the segment angles when at hand, as in
   !! the effects' body state; cp, sp those of the pitch: no trig repeated)
   pure function body_feature(body, z, zdot, vpos, vvel, i, c, s, cp, sp) result(f)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), vpos(3), vvel(3)
      integer, intent(in) :: i
      real(wp), intent(in), optional :: c(n_seg), s(n_seg), cp, sp
      type(contact_feature_t) :: f
      type(point_state_t) :: j
      real(wp) :: zero(n_dof), p(2), v(2), d(2), dv(2), cph, sph, et(2)
      f%arc = i
      f%seg = arc_segment(i)
      if (present(c) .and. present(s) .and. present(cp) .and. present(sp)) then
         ! to_interior with the trig at hand: x = R(Phi)(X - x_c) and its rate
         call joint_position_velocity(body, z, zdot, c, s, f%seg, p, v)
         cph = cp
         sph = sp
         d = p - vpos(1:2)
         dv = v - vvel(1:2)
         f%joint = [d(1)*cph - d(2)*sph, d(1)*sph + d(2)*cph]
         f%joint_vel = [dv(1)*cph - dv(2)*sph - f%joint(2)*vvel(3), dv(1)*sph + dv(2)*cph + f%joint(1)*vvel(3)]
      else
         zero = 0.0_wp
         j = to_interior(joint_state(body, z, zdot, zero, proximal_joint(f%seg)), vpos, vvel)
         f%joint = [j%x, j%y]
         f%joint_vel = [j%vx, j%vy]
      end if
      f%theta = z(f%seg) + vpos(3)
      f%theta_dot = zdot(f%seg) + vvel(3)
      f%r = body%r_arc(i)
      ! e(theta) of the carrying segment, from the trig at hand when given
      if (present(c) .and. present(s) .and. present(cp) .and. present(sp)) then
         et = [c(f%seg)*cp - s(f%seg)*sp, s(f%seg)*cp + c(f%seg)*sp]
      else
         et = e(f%theta)
      end if
      select case (i)
      case (1, 5)                 ! hip, shoulder: the joint itself (F1-2)
         f%p = f%joint
      case (2, 3)                 ! upper back, chest: rho'_i at gamma_i from the torso line
         f%p = f%joint + body%rho_arc(i)*e(f%theta + body%gamma_arc(i))
      case (4)                    ! head: rho'_4 along its centre line (F1-1)
         f%p = f%joint + body%rho_arc(4)*et
      case (6, 7, 8, 10)          ! elbow, knee, foot (the ankle), hand: the segment's far end
         f%p = f%joint + body%length(f%seg)*et
      case (9)                    ! the shin: the knee circle and the ankle circle (D-C2)
         f%p = f%joint
         f%r = body%r_arc(7)
         f%ankle = f%joint + body%length(8)*et
         f%r_ankle = body%r_arc(11)
         f%alpha0 = shin_alpha0(body)
      end select
   end function body_feature

   !> Whether T = tt lies inside the surface's opening (the rim's, D-C11).
   pure logical function in_opening(sf, tt)
      type(contact_surface_t), intent(in) :: sf
      real(wp), intent(in) :: tt
      in_opening = sf%t_open(2) > sf%t_open(1) .and. tt > sf%t_open(1) .and. tt < sf%t_open(2)
   end function in_opening

   !> The unit vector at angle a: (cos a, sin a).
   pure function e(a) result(v)
      real(wp), intent(in) :: a
      real(wp) :: v(2)
      v = [cos(a), sin(a)]
   end function e

   !> Figure 22 reconstructed (docs/contacts.md 3.2): the primitive that
   !! acts between body feature f and surface sf, and its state. The region
   !! is chosen so that delta and its gradient are continuous everywhere.
   !! behind (the pair's memory): the point came at the surface from behind
   !! its line, where a flat surface meets it with its ends only (D-C16a);
   !! for the shin, the panel's edge came at it from behind the shank's
   !! axis (D-C16b). Absent: the side the point (the edge) is on now.
   !! e_psi: e(sf%psi) when at hand (a pair's, taken once: the same bits).
   !! face (the pair's memory, issue 15; 0 or absent: none): the face of a
   !! solid met from inside that acts (cs%face), held from the last
   !! accepted state: where two faces are as deep the force's direction
   !! jumps, a switch the driver locates and steps onto, so within a step
   !! the face held acts (its depth continued past the tie) and the pair's
   !! accept takes the one whose depth is least.
   pure function contact_check(f, sf, behind, e_psi, face) result(cs)
      type(contact_feature_t), intent(in) :: f
      type(contact_surface_t), intent(in) :: sf
      logical, intent(in), optional :: behind
      real(wp), intent(in), optional :: e_psi(2)
      integer, intent(in), optional :: face
      type(contact_state_t) :: cs
      real(wp) :: tk(2), nk(2), tt, te, h
      logical :: from_behind
      integer :: held
      from_behind = .false.
      if (present(behind)) from_behind = behind
      held = 0
      if (present(face)) held = face
      if (f%arc == 9) then
         if (present(behind)) then
            cs = shin_check(f, sf%s, merge(-1, 1, from_behind), held)
         else
            cs = shin_check(f, sf%s, 0)
         end if
         return
      end if
      select case (sf%kind)
      case (surface_circle)        ! the head rest (F24-1, F4-1)
         call round(f%p - sf%s, 0.5_wp*sf%d, region_circle, cs)
         cs%pos = head_rest_position(sf, cs%n)
      case (surface_point)
         call round(f%p - sf%s, 0.0_wp, region_corner, cs)
         cs%pos = 0.0_wp
      case default
         if (present(e_psi)) then
            tk = e_psi
         else
            tk = e(sf%psi)
         end if
         nk = [-tk(2), tk(1)]
         tt = dot_product(sf%s - f%p, tk)                ! f.2's T
         h = dot_product(f%p - sf%s, nk)
         te = -1.0_wp
         if (sf%kind == surface_flat .and. h < 0.0_wp .and. .not. from_behind) then
            ! D-C16b: come from the front, its centre behind the line: the
            ! surface is the face of a solid (its extent, or each piece of the
            ! rim beside the opening), met from inside
            call solid_from_inside(cs)
         else
            if (sf%kind == surface_flat) then
               if (tt < 0.0_wp) then
                  te = 0.0_wp
               else if (tt > sf%d) then
                  te = sf%d
               else if (in_opening(sf, tt)) then
                  te = merge(sf%t_open(1), sf%t_open(2), tt - sf%t_open(1) <= sf%t_open(2) - tt)
               end if
               if (te < 0.0_wp .and. from_behind) te = nearest_end(sf, tt)   ! from behind: the nearest free end
            end if
            if (te >= 0.0_wp) then   ! a corner at the end (or the opening's edge) nearest (D-C16)
               call round(f%p - (sf%s - te*tk), 0.0_wp, region_corner, cs)
               cs%pos = te
            else                      ! the face: delta = r - (P - S).n_k (f.2)
               cs%region = region_face
               cs%n = nk
               cs%delta = f%r - h
               cs%pos = tt
            end if
         end if
      end select
      cs%t = [cs%n(2), -cs%n(1)]
      cs%c = f%p - f%r*cs%n
      call rates(f, cs)
   contains
      !> the body's circle against a circle of radius rad (0: a point) at
      !! distance d = |v| from its centre, v from that centre to the body
      pure subroutine round(v, rad, region, st)
         real(wp), intent(in) :: v(2), rad
         integer, intent(in) :: region
         type(contact_state_t), intent(out) :: st
         real(wp) :: d
         d = norm2(v)
         st%region = region
         st%delta = rad + f%r - d
         if (d > 0.0_wp) then
            st%n = v/d
         else
            st%n = [0.0_wp, 1.0_wp]          ! (coincident centres: any direction)
         end if
      end subroutine round

      !> D-C16b: the circle's penetration of the solid behind a flat piece
      !! [a, b] of the surface, its centre inside or beyond the piece's ends
      !! and behind its line (h < 0): the least of the depths to leave it
      !! through the face (r - h, along n_k) or past either end (r - (a - T),
      !! along +t_k; r - (T - b), along -t_k), the larger of the rim's two
      !! pieces. r - the signed distance of the centre to the solid: equal to
      !! the face's and the corners' at h = 0, so continuous there, and never
      !! along -n_k (the surface never pulls the point in).
      !! (held: the face the pair holds, issue 15.)
      pure subroutine solid_from_inside(st)
         type(contact_state_t), intent(out) :: st
         type(contact_state_t) :: other
         if (sf%t_open(2) > sf%t_open(1)) then
            if (held > 3) then
               call piece(sf%t_open(2), sf%d, held - 3, st)
               st%face = st%face + 3
            else if (held > 0) then
               call piece(0.0_wp, sf%t_open(1), held, st)
            else
               call piece(0.0_wp, sf%t_open(1), 0, st)
               call piece(sf%t_open(2), sf%d, 0, other)
               other%face = other%face + 3
               if (other%delta > st%delta) st = other
            end if
         else
            call piece(0.0_wp, sf%d, held, st)
         end if
      end subroutine solid_from_inside

      !> The piece [a, b]: the least depth below its face and walls, or
      !! the depth below the one held (which: 1 to 3, 0 none).
      pure subroutine piece(a, b, which, st)
         real(wp), intent(in) :: a, b
         integer, intent(in) :: which
         type(contact_state_t), intent(out) :: st
         st%region = region_face
         st%n = nk
         st%delta = f%r - h
         st%pos = tt
         st%face = 1
         if ((which == 0 .and. f%r - (a - tt) < st%delta) .or. which == 2) then
            st%region = region_end_wall
            st%n = tk
            st%delta = f%r - (a - tt)
            st%pos = a
            st%face = 2
         end if
         if ((which == 0 .and. f%r - (tt - b) < st%delta) .or. which == 3) then
            st%region = region_end_wall
            st%n = -tk
            st%delta = f%r - (tt - b)
            st%pos = b
            st%face = 3
         end if
      end subroutine piece
   end function contact_check

   !> D-C3: where on the head rest (k = 1) the head acts, T = 1/2 D_1 times
   !! the angle from the direction the rest faces, e(psi_1 + 90 deg), to the
   !! contact's normal n, counter-clockwise positive: a signed arc length
   !! along the rest's face, increasing the way a flat surface's T does
   !! (towards -e(psi_1) from the facing point).
   pure real(wp) function head_rest_position(sf, n) result(pos)
      type(contact_surface_t), intent(in) :: sf
      real(wp), intent(in) :: n(2)
      real(wp) :: facing(2)
      facing = e(sf%psi + 0.5_wp*pi)
      pos = 0.5_wp*sf%d*atan2(facing(1)*n(2) - facing(2)*n(1), dot_product(facing, n))
   end function head_rest_position

   !> D-C16a, D-C16b: which side of a flat surface's line a body point is
   !! on, for the pair's memory, or 0 where it is not decided: decided only
   !! where the two sides' rules give the same (so the switch is continuous
   !! and needs no restart) - at least r in front of the line, where nothing
   !! touches either way; beyond the surface's ends (or in the rim's
   !! opening) in front of the line, where both meet the end's corner; and
   !! there behind the line only once at least r beyond the end, where the
   !! solid met from inside (D-C16b) no longer touches. Elsewhere the point
   !! keeps the side it came from. The shin (D-C16b): the side of the
   !! shank's axis the panel's edge is on, decided where the edge is off the
   !! capsule (no contact either way).
   !! e_psi: e(sf%psi) when at hand, as for contact_check.
   pure integer function front_side(f, sf, e_psi) result(side)
      type(contact_feature_t), intent(in) :: f
      type(contact_surface_t), intent(in) :: sf
      real(wp), intent(in), optional :: e_psi(2)
      type(contact_state_t) :: cs
      real(wp) :: tk(2), nk(2), tt, h, beyond
      side = 0
      if (f%arc == 9) then
         cs = shin_check(f, sf%s, 0)
         if (.not. cs%delta > 0.0_wp) side = shin_side_now(f, sf%s)
         return
      end if
      if (sf%kind /= surface_flat) return
      if (present(e_psi)) then
         tk = e_psi
      else
         tk = e(sf%psi)
      end if
      nk = [-tk(2), tk(1)]
      tt = dot_product(sf%s - f%p, tk)
      h = dot_product(f%p - sf%s, nk)
      if (h >= f%r) then
         side = 1
      else if (tt < 0.0_wp .or. tt > sf%d .or. in_opening(sf, tt)) then
         ! how far beyond the nearest end (or edge of the opening)
         if (tt < 0.0_wp) then
            beyond = -tt
         else if (tt > sf%d) then
            beyond = tt - sf%d
         else
            beyond = min(tt - sf%t_open(1), sf%t_open(2) - tt)
         end if
         if (h >= 0.0_wp) then
            side = 1
         else if (beyond >= f%r) then
            side = -1
         end if
      end if
   end function front_side

   !> The free end of a flat surface nearest to position tt along it: its
   !! two ends and, for the rim, the edges of its opening.
   pure real(wp) function nearest_end(sf, tt) result(te)
      type(contact_surface_t), intent(in) :: sf
      real(wp), intent(in) :: tt
      te = merge(0.0_wp, sf%d, tt <= 0.5_wp*sf%d)
      if (sf%t_open(2) > sf%t_open(1)) then
         if (abs(tt - sf%t_open(1)) < abs(tt - te)) te = sf%t_open(1)
         if (abs(tt - sf%t_open(2)) < abs(tt - te)) te = sf%t_open(2)
      end if
   end function nearest_end

   !> The side of the shank's axis the panel's edge ed is on: +1 in front
   !! (the side of e(theta_8 + 90 deg), on the axis too), -1 behind.
   pure integer function shin_side_now(f, ed) result(side)
      type(contact_feature_t), intent(in) :: f
      real(wp), intent(in) :: ed(2)
      real(wp) :: axis_n(2)
      axis_n = [-sin(f%theta), cos(f%theta)]
      side = merge(1, -1, dot_product(ed - f%joint, axis_n) >= 0.0_wp)
   end function shin_side_now

   !> The shin capsule against the lower panel's edge ed (D-C2). side: the
   !! side of the shank's axis the edge came from (the pair's memory,
   !! D-C16b; 0: the side it is on now). On that side, and wherever the
   !! edge is off the capsule, the capsule (shin_capsule). An edge that came
   !! from one side and has crossed the axis, still inside the capsule,
   !! meets the far half as a solid met from inside (shin_far): it keeps
   !! pushing the shin the way the edge came, where the capsule's other
   !! tangent would pull it onto the edge (issue 14: 2,400 lb reversed in
   !! one step). Out through the other side, the edge has gone through the
   !! shin and lets go.
   !! held (issue 15): the far half's plane the pair holds (cs%face; 0:
   !! the least depth).
   pure function shin_check(f, ed, side, held) result(cs)
      type(contact_feature_t), intent(in) :: f
      real(wp), intent(in) :: ed(2)
      integer, intent(in) :: side
      integer, intent(in), optional :: held
      type(contact_state_t) :: cs
      integer :: side_now, plane
      side_now = shin_side_now(f, ed)
      cs = shin_capsule(f, ed, side_now)
      if (side == 0 .or. side == side_now .or. .not. cs%delta > 0.0_wp) return
      plane = 0
      if (present(held)) plane = held
      cs = shin_far(f, ed, side, plane)
   end function shin_check

   !> The capsule (D-C2) against the edge ed on its side side_now of the
   !! shank's axis: the line part (F2-2, F2-3) between the tangent points,
   !! the knee or the ankle circle beyond them. The normal is the edge's
   !! push on the body. The front tangent (F2-2, F2-3) or, for an edge
   !! behind the axis, the back one (its mirror), so the shin is the convex
   !! hull of its two circles on both sides (review of issue 7). They agree
   !! on the axis.
   pure function shin_capsule(f, ed, side_now) result(cs)
      type(contact_feature_t), intent(in) :: f
      real(wp), intent(in) :: ed(2)
      integer, intent(in) :: side_now
      type(contact_state_t) :: cs
      real(wp) :: u(2), m(2), tt, t_end, v(2), d
      call shin_frame(f, side_now, u, m)
      tt = dot_product(ed - f%joint, u)                  ! T_9 (F2-3)
      t_end = norm2(f%ankle - f%joint)*cos(f%alpha0)
      if (tt >= 0.0_wp .and. tt <= t_end) then
         cs%region = region_shin_line
         cs%delta = f%r - dot_product(ed - f%joint, m)   ! F2-2
         cs%n = -m
         cs%c = f%joint + f%r*m + tt*u
      else
         if (tt < 0.0_wp) then
            cs%region = region_shin_knee
            v = f%joint - ed
            cs%delta = f%r - norm2(v)
            d = norm2(v)
            cs%c = f%joint
         else
            cs%region = region_shin_ankle
            v = f%ankle - ed
            cs%delta = f%r_ankle - norm2(v)
            d = norm2(v)
            cs%c = f%ankle
         end if
         cs%n = [0.0_wp, 1.0_wp]
         if (d > 0.0_wp) cs%n = v/d
         cs%c = cs%c - merge(f%r, f%r_ankle, cs%region == region_shin_knee)*cs%n
      end if
      cs%pos = tt
      cs%t = [cs%n(2), -cs%n(1)]
      call rates(f, cs)
   end function shin_capsule

   !> The tangent of the shin on side side of the shank's axis (+1: the
   !! front, F2-2's; -1: the back, its mirror about the axis): its direction
   !! u from the knee towards the ankle and its outward normal m.
   pure subroutine shin_frame(f, side, u, m)
      type(contact_feature_t), intent(in) :: f
      integer, intent(in) :: side
      real(wp), intent(out) :: u(2), m(2)
      if (side >= 0) then
         u = e(f%theta - f%alpha0)
         m = [-u(2), u(1)]
      else
         u = e(f%theta + f%alpha0)
         m = [u(2), -u(1)]
      end if
   end subroutine shin_frame

   !> D-C16b: the edge ed, come from side side of the shank's axis, has
   !! crossed it inside the capsule. The shin's far half is then met as a
   !! solid from inside, bounded by the near tangent, extended, and the
   !! planes across the axis through the knee circle's top and the ankle
   !! circle's bottom: delta is the least depth to leave it through one of
   !! them (r_7 - (E - K).m along -m; r_7 + (E - K).a along a = e(theta_8);
   !! r_A - (E - A).a along -a), each a plane of the shank, so C = E - delta
   !! n is a material point of it with delta' = -V_C.n. On the axis these
   !! equal the capsule's (its line part, knee and ankle circles), so the
   !! force is continuous as the edge crosses it; none has a component
   !! towards the side the edge came from.
   !! plane: the plane held (cs%face, issue 15), 0 the least depth.
   pure function shin_far(f, ed, side, plane) result(cs)
      type(contact_feature_t), intent(in) :: f
      real(wp), intent(in) :: ed(2)
      integer, intent(in) :: side, plane
      type(contact_state_t) :: cs
      real(wp) :: u(2), m(2), a(2), d(2), depth
      call shin_frame(f, side, u, m)
      a = e(f%theta)
      d = ed - f%joint
      cs%region = region_shin_far
      cs%delta = f%r - dot_product(d, m)                 ! through the near tangent
      cs%n = -m
      cs%face = 1
      depth = f%r + dot_product(d, a)                    ! over the knee's top
      if ((plane == 0 .and. depth < cs%delta) .or. plane == 2) then
         cs%delta = depth
         cs%n = a
         cs%face = 2
      end if
      depth = f%r_ankle - dot_product(ed - f%ankle, a)   ! under the ankle's bottom
      if ((plane == 0 .and. depth < cs%delta) .or. plane == 3) then
         cs%delta = depth
         cs%n = -a
         cs%face = 3
      end if
      cs%c = ed - cs%delta*cs%n
      cs%pos = dot_product(d, u)
      cs%t = [cs%n(2), -cs%n(1)]
      call rates(f, cs)
   end function shin_far

   !> Issue 15: how many switching functions region_switches gives for body
   !! point arc against a surface sf: the shin's six against the panel's
   !! edge; a flat surface's six (twelve with the rim's opening); none for a
   !! line, a circle or a point, whose one primitive acts everywhere.
   pure integer function region_switch_count(arc, sf) result(n)
      integer, intent(in) :: arc
      type(contact_surface_t), intent(in) :: sf
      n = 0
      if (arc == 9) then
         n = 6
      else if (sf%kind == surface_flat) then
         n = 6
         if (sf%t_open(2) > sf%t_open(1)) n = 12
      end if
   end function region_switch_count

   !> Issue 15: where figure 22's check (contact_check, with the pair's
   !! memory behind) changes the primitive that acts between f and sf while
   !! the pair is loaded, as switching functions in g (in): the force's
   !! slope jumps where the contact point rounds an edge (a face meets a
   !! corner's circle, the shin's line part its knee or ankle circle, a
   !! capsule the far half's planes: delta and its gradient continue, the
   !! normal's rate does not - P/r of geometric stiffness), and the force's
   !! direction jumps where a point inside a solid (D-C16b) is as deep
   !! below two of its faces. take_up (in): the pair's chain taken up beyond
   !! its zero extent, > 0 where it carries load. A boundary b matters only
   !! where the pair is loaded (and the mode it bounds acts, q > 0): each g
   !! is max(b, -q) with q = min(take_up, the mode's own margin), so it has
   !! b's sign there and is positive elsewhere - continuous, and crossing
   !! zero outside b's own root only where q does (with take_up, at the
   !! contact's onset or release, which the pair's own switch locates).
   !! Flat surface (T = (S - P).t_k, h = (P - S).n_k): T and D - T (a face's
   !! ends), T - T_o1 and T_o2 - T (the rim opening's edges), h (the line:
   !! a corner met from in front or an end wall from inside, D-C16b), and,
   !! inside the solid (h < 0, the point came from the front), for each
   !! piece [a, b] the ties of its face with its end walls (depths r - h,
   !! r - (a - T), r - (T - b)), and of its two walls, where both are less
   !! deep than the face (a piece shorter than the point's depth: the rim's
   !! 1 in pieces under a head), and with the opening, the tie of its two
   !! pieces. Not
   !! located: the nearest of a surface's free ends for a point come from
   !! behind, and the middle of the rim's opening (a rim pair's arc wider
   !! than the opening is refused, *INTERIOR DI). The shin (i = 9; E the
   !! panel's edge, h_a its side of the shank's axis, s the side it came
   !! from): on its own side the capsule's T_9 and T_end - T_9 (its line
   !! part meets the knee and ankle circles), h_a (the capsule meets the far
   !! half, D-C16b), beyond the axis the far half's ties of its near tangent
   !! with the knee's top and the ankle's bottom, and the capsule's delta on
   !! the edge's present side while beyond the axis inside the far half: the
   !! edge leaving through the far side lets the shin go (a jump), and
   !! decides its side.
   pure subroutine region_switches(f, sf, behind, e_psi, take_up, g)
      type(contact_feature_t), intent(in) :: f
      type(contact_surface_t), intent(in) :: sf
      logical, intent(in) :: behind
      real(wp), intent(in) :: e_psi(2), take_up
      real(wp), intent(out) :: g(:)
      real(wp) :: nk(2), tt, h, q_in, d1, d2, u(2), m(2), a(2), d(2), t_end, side, q_own, q_far
      real(wp) :: d_near, d_knee, d_ankle
      type(contact_state_t) :: cs
      ! (the last argument of gated: the side contact_check takes where b
      ! is 0, so that an accepted state there is past the switch or short of
      ! it as the check itself is, never on it)
      if (f%arc == 9) then
         ! the shin against the edge E = sf%s
         side = merge(-1.0_wp, 1.0_wp, behind)
         h = dot_product(sf%s - f%joint, [-sin(f%theta), cos(f%theta)])
         q_own = min(take_up, side*h)
         q_far = min(take_up, -side*h)
         call shin_frame(f, merge(1, -1, h >= 0.0_wp), u, m)
         tt = dot_product(sf%s - f%joint, u)
         t_end = norm2(f%ankle - f%joint)*cos(f%alpha0)
         g(1) = gated(tt, q_own, 1.0_wp)
         g(2) = gated(t_end - tt, q_own, 1.0_wp)
         g(3) = gated(h, take_up, 1.0_wp)
         call shin_frame(f, nint(side), u, m)
         a = e(f%theta)
         d = sf%s - f%joint
         d_near = f%r - dot_product(d, m)
         d_knee = f%r + dot_product(d, a)
         d_ankle = f%r_ankle - dot_product(sf%s - f%ankle, a)
         g(4) = gated(d_knee - d_near, q_far, 1.0_wp)
         g(5) = gated(d_ankle - d_near, q_far, 1.0_wp)
         ! (in the far half, min(d_near, d_knee, d_ankle) > 0; where the edge
         ! crosses the axis off the capsule, beyond the knee or the ankle, it
         ! is not, and nothing switches)
         cs = shin_capsule(f, sf%s, merge(1, -1, h >= 0.0_wp))
         g(6) = gated(cs%delta, min(-side*h, min(d_near, d_knee, d_ankle)), -1.0_wp)
         return
      end if
      if (sf%kind /= surface_flat) return
      nk = [-e_psi(2), e_psi(1)]
      tt = dot_product(sf%s - f%p, e_psi)
      h = dot_product(f%p - sf%s, nk)
      ! inside the solid: loaded, behind the line, come from the front
      q_in = min(take_up, -h)
      if (behind) q_in = -1.0_wp
      g(1) = gated(tt, take_up, 1.0_wp)
      g(2) = gated(sf%d - tt, take_up, 1.0_wp)
      g(3) = gated(h, take_up, 1.0_wp)
      if (sf%t_open(2) > sf%t_open(1)) then
         g(4) = gated(tt - sf%t_open(1), take_up, -1.0_wp)
         g(5) = gated(sf%t_open(2) - tt, take_up, -1.0_wp)
         call piece_ties(0.0_wp, sf%t_open(1), g(6:8))
         call piece_ties(sf%t_open(2), sf%d, g(9:11))
         ! the pieces' depths below their faces and walls (solid_from_inside)
         d1 = piece_depth(0.0_wp, sf%t_open(1))
         d2 = piece_depth(sf%t_open(2), sf%d)
         g(12) = gated(d1 - d2, q_in, 1.0_wp)
      else
         call piece_ties(0.0_wp, sf%d, g(4:6))
      end if
   contains
      !> The ties of piece [a, b]'s face and walls met from inside, each the
      !! difference of two of the depths contact_check compares, in its own
      !! arithmetic (a tie it decides one way is that sign here, to the bit).
      pure subroutine piece_ties(a, b, gp)
         real(wp), intent(in) :: a, b
         real(wp), intent(out) :: gp(3)
         gp(1) = gated((f%r - (a - tt)) - (f%r - h), q_in, 1.0_wp)
         gp(2) = gated((f%r - (tt - b)) - (f%r - h), q_in, 1.0_wp)
         ! (the walls' tie where both are less deep than the face)
         gp(3) = gated((f%r - (tt - b)) - (f%r - (a - tt)), min(q_in, -h - 0.5_wp*(b - a)), 1.0_wp)
      end subroutine piece_ties

      !> The depth of piece [a, b] as solid_from_inside's piece takes it.
      pure real(wp) function piece_depth(a, b) result(dp)
         real(wp), intent(in) :: a, b
         dp = f%r - h
         if (f%r - (a - tt) < dp) dp = f%r - (a - tt)
         if (f%r - (tt - b) < dp) dp = f%r - (tt - b)
      end function piece_depth
   end subroutine region_switches

   !> A boundary b (changing sign where the check changes the primitive)
   !! that matters only where q > 0: max(b, -q), of b's sign there and
   !! positive elsewhere. Where b is 0, the sign of zero_side (the side the
   !! check takes there); never 0 (a switching function 0 at an accepted
   !! state would count as not crossed, and leaving it would be missed).
   pure real(wp) function gated(b, q, zero_side) result(g)
      real(wp), intent(in) :: b, q, zero_side
      g = b
      if (.not. abs(g) > 0.0_wp) g = sign(tiny(1.0_wp), zero_side)
      g = max(g, -q)
      if (.not. abs(g) > 0.0_wp) g = tiny(1.0_wp)
   end function gated

   !> delta' = -V_C.n and v_T = V_C.t, V_C the interior velocity of the
   !! body's material point at C (the surface is fixed in the interior).
   pure subroutine rates(f, cs)
      type(contact_feature_t), intent(in) :: f
      type(contact_state_t), intent(inout) :: cs
      real(wp) :: vc(2), rel(2)
      rel = cs%c - f%joint
      vc = f%joint_vel + f%theta_dot*[-rel(2), rel(1)]
      cs%delta_dot = -dot_product(vc, cs%n)
      cs%v_t = dot_product(vc, cs%t)
   end subroutine rates
end module contact_geometry
