!> Report C.4.e and C.2: the geometry of the belts — for each section its
!! direction φ_j, nominal deformation δ_j, its rate δ̇_j and the gradient
!! ∂δ_j/∂z, from which the generalized forces are B = −F_j ∂δ_j/∂z
!! (docs/errata.md, BE-1: the printed B_2, B_3 are not this). Everything is
!! in the vehicle-interior frame of the start of C.4 (x forward, y up,
!! angles θ = α + Φ), with the conventions of errata-forces.md:
!! (u_j, v_j) = belt point on the body − anchor, φ_j its direction (anchor →
!! body) by atan2 (BE-2), the belt pulls the body towards the anchor.
!!
!! Lap belt (j = 1, figure 17, lost; reconstruction A-B1): it runs straight
!! from its anchor A to its tangent point on the circle of radius h_1 about
!! the hip, then wraps clockwise to E = hip + h_1 e(θ_1), h_1 up the lower
!! torso's centre line. Its length is √(d² − h_1²) + h_1 (φ_1 − θ_1 + π/2),
!! d = |hip − A|, φ_1 = asin(h_1/d) + atan2(v_1, u_1). Where the wrap would
!! be negative the belt runs straight from A to E.
!!
!! Torso sections (j = 2, 3): straight from the anchor to the point h_j
!! along the centre line of segment j from its proximal joint (joint 2 for
!! the centre torso, joint 3 for the upper torso).
!!
!! The anchors and free lengths are fixed at t = 0 from the initial angles
!! and lengths of the belts (C.2 with errata C2-1, C2-2, C2-3), so that
!! every δ_j(0) = 0.
module belt_geometry
   use kinds, only: wp, pi
   use model, only: n_dof, n_seg, hip_x, hip_y
   implicit none
   private

   public :: belt_section_geometry_t, belt_kinematics_t, belt_body_t
   public :: belt_lap, belt_torso, lap_belt_geometry, torso_belt_geometry, belt_kinematics
   public :: belt_body_from, belt_body_of_state, belt_body_fill, belt_section_add, lap_wrap

   !> Kinds of belt section.
   integer, parameter :: belt_lap = 1, belt_torso = 2

   !> One section's fixed geometry (C.2).
   type :: belt_section_geometry_t
      integer :: kind = belt_torso
      integer :: segment = 2          !< the segment carrying the belt point (1 for the lap belt)
      real(wp) :: h = 0.0_wp          !< h_j: wrap radius (lap) or distance along the centre line (torso)
      real(wp) :: anchor(2) = 0.0_wp  !< the anchorage, interior frame (in)
      real(wp) :: length0 = 0.0_wp    !< ℓ_j0: the belt length at t = 0 (for the lap belt, with its wrap)
   end type belt_section_geometry_t

   !> What the belts need of the body at one instant, in the interior frame:
   !! the positions and velocities of joints 1-3 (hip, lower spine, upper
   !! spine), the angles and rates of segments 1-3, and the lengths and the
   !! pitch for the gradients.
   type :: belt_body_t
      real(wp) :: joint(2, 3), joint_rate(2, 3)
      real(wp) :: theta(3), theta_rate(3)
      real(wp) :: length(2)        !< L_1, L_2
      real(wp) :: phi              !< the vehicle's pitch Φ
      real(wp) :: ct(3), st(3)     !< cos θ_i, sin θ_i
      real(wp) :: cphi, sphi       !< cos Φ, sin Φ
   end type belt_body_t

   !> A section's state: direction, deformation, rate, gradient.
   type :: belt_kinematics_t
      real(wp) :: phi = 0.0_wp          !< φ_j, direction anchor → belt (or tangent) point
      real(wp) :: delta = 0.0_wp        !< δ_j, nominal deformation (length − ℓ_j0)
      real(wp) :: delta_rate = 0.0_wp   !< δ̇_j
      real(wp) :: gradient(n_dof) = 0.0_wp  !< ∂δ_j/∂z
      logical :: wrapped = .true.       !< lap belt: wraps the hip (false: straight to E)
      !> where the belt acts on the body (interior): the tension F pulls the
      !! material point `point` of the section's segment by -F `direction`
      !! (e(φ_j); for the wrapped lap belt at the tangent point, scaled by
      !! h/d inside the circle), so that its virtual work is -F ∂δ_j/∂z
      real(wp) :: point(2) = 0.0_wp, direction(2) = 0.0_wp
   end type belt_kinematics_t

contains

   !> The body data the belts use, from the interior positions and
   !! velocities of joints 1-3 and the generalized state (section B, C.4).
   pure function belt_body_from(joint, joint_rate, z, zdot, length, phi, phi_rate) result(bb)
      real(wp), intent(in) :: joint(2, 3), joint_rate(2, 3), z(n_dof), zdot(n_dof), length(n_seg)
      real(wp), intent(in) :: phi, phi_rate
      type(belt_body_t) :: bb
      bb%joint = joint
      bb%joint_rate = joint_rate
      bb%theta = z(1:3) + phi            ! θ_i = α_i + Φ (section B)
      bb%theta_rate = zdot(1:3) + phi_rate
      bb%length = length(1:2)
      bb%phi = phi
      bb%ct = cos(bb%theta)
      bb%st = sin(bb%theta)
      bb%cphi = cos(phi)
      bb%sphi = sin(phi)
   end function belt_body_from

   !> The belt data of the body at (z, z') in a vehicle at vpos = (x_c, y_c,
   !! Phi) moving at vvel (the start of C.4): joints 1-3 from the hip along
   !! L_1 and L_2 (section B), rotated into the interior frame, their rates
   !! with the -y Phi', +x Phi' terms of the rotating frame. c, s: cos and
   !! sin of alpha_1..alpha_8. The same as body_kinematics' joint_state and
   !! to_interior (test_belts: test_body_data_matches_kinematics), without
   !! their sines and cosines.
   pure function belt_body_of_state(length, z, zdot, c, s, vpos, vvel) result(bb)
      real(wp), intent(in) :: length(n_seg), z(n_dof), zdot(n_dof), c(n_seg), s(n_seg), vpos(3), vvel(3)
      type(belt_body_t) :: bb
      call belt_body_fill(length, z, zdot, c, s, vpos, vvel, 3, bb)
   end function belt_body_of_state

   !> belt_body_of_state into bb, for joints and segments 1..last only (the
   !! rest of bb is left as it was): an effect whose sections lie on
   !! segments <= last reads no more (belt_kinematics reads joint s, and
   !! segments 1..s, of a section on segment s).
   pure subroutine belt_body_fill(length, z, zdot, c, s, vpos, vvel, last, bb)
      real(wp), intent(in) :: length(n_seg), z(n_dof), zdot(n_dof), c(n_seg), s(n_seg), vpos(3), vvel(3)
      integer, intent(in) :: last
      type(belt_body_t), intent(inout) :: bb
      real(wp) :: p(2, 3), v(2, 3), cp, sp, dx, dy, dvx, dvy
      integer :: k
      p(:, 1) = [z(hip_x), z(hip_y)]
      v(:, 1) = [zdot(hip_x), zdot(hip_y)]
      do k = 1, last - 1
         p(:, k + 1) = p(:, k) + length(k)*[c(k), s(k)]
         v(:, k + 1) = v(:, k) + length(k)*zdot(k)*[-s(k), c(k)]
      end do
      ! R(Phi) of the start of C.4. A vehicle that does not pitch (Phi = 0, a
      ! sled pulse): cos 0 = 1 and sin 0 = 0 (of 0's sign, as sin gives it)
      ! exactly, without the library's sine and cosine at every evaluation
      if (abs(vpos(3)) > 0.0_wp) then
         cp = cos(vpos(3))
         sp = sin(vpos(3))
      else
         cp = 1.0_wp
         sp = vpos(3)
      end if
      do k = 1, last
         dx = p(1, k) - vpos(1)
         dy = p(2, k) - vpos(2)
         dvx = v(1, k) - vvel(1)
         dvy = v(2, k) - vvel(2)
         bb%joint(1, k) = dx*cp - dy*sp
         bb%joint(2, k) = dx*sp + dy*cp
         bb%joint_rate(1, k) = dvx*cp - dvy*sp - bb%joint(2, k)*vvel(3)
         bb%joint_rate(2, k) = dvx*sp + dvy*cp + bb%joint(1, k)*vvel(3)
         bb%theta(k) = z(k) + vpos(3)          ! theta_i = alpha_i + Phi (section B)
         bb%theta_rate(k) = zdot(k) + vvel(3)
         bb%ct(k) = c(k)*cp - s(k)*sp          ! cos(alpha_i + Phi)
         bb%st(k) = s(k)*cp + c(k)*sp
      end do
      bb%length = length(1:2)
      bb%phi = vpos(3)
      bb%cphi = cp
      bb%sphi = sp
   end subroutine belt_body_fill

   !> C.2 for the lap belt (j = 1): the anchor at ℓ'_0 from the initial hip
   !! in the direction −e(φ'_0) (φ'_0 points from the anchor to the hip:
   !! λ_1 = ℓ'_0 cos φ'_0, λ_2 = ℓ'_0 sin φ'_0), and the free length
   !! ℓ_10 = √(ℓ'_0² − h_1²) + h_1 [φ_10 − Θ_10 + π/2], φ_10 = φ'_0 + asin(h_1/ℓ'_0)
   !! (errata C2-2, C2-3). hip0 is the hip's initial interior position.
   pure function lap_belt_geometry(h, length_anchor, phi_anchor, hip0, theta10) result(g)
      real(wp), intent(in) :: h, length_anchor, phi_anchor, hip0(2), theta10
      type(belt_section_geometry_t) :: g
      g%kind = belt_lap
      g%segment = 1
      g%h = h
      g%anchor = hip0 - length_anchor*[cos(phi_anchor), sin(phi_anchor)]
      g%length0 = lap_length(g, hip0, theta10)
   end function lap_belt_geometry

   !> C.2 for a torso section (j = 2, 3): the anchor at ℓ_j0 from the
   !! initial belt point P_j0 = joint_j0 + h_j e(Θ_j0) in the direction
   !! −e(φ_j0) (errata C2-1: the horizontal sums belong to u_j, the vertical
   !! ones to v_j).
   pure function torso_belt_geometry(segment, h, length0, phi0, joint0, theta0) result(g)
      integer, intent(in) :: segment
      real(wp), intent(in) :: h, length0, phi0, joint0(2), theta0
      type(belt_section_geometry_t) :: g
      g%kind = belt_torso
      g%segment = segment
      g%h = h
      g%length0 = length0
      g%anchor = joint0 + h*[cos(theta0), sin(theta0)] - length0*[cos(phi0), sin(phi0)]
   end function torso_belt_geometry

   !> The lap belt's length from its anchor to E (with its wrap when the
   !! wrap is positive).
   pure real(wp) function lap_length(g, hip, theta1) result(length)
      type(belt_section_geometry_t), intent(in) :: g
      real(wp), intent(in) :: hip(2), theta1
      real(wp) :: u, v, d, phi1, wrap, e(2)
      u = hip(1) - g%anchor(1)
      v = hip(2) - g%anchor(2)
      d = hypot(u, v)
      phi1 = tangent_turn(g%h, d) + atan2(v, u)
      wrap = phi1 - theta1 + 0.5_wp*pi
      if (wrap >= 0.0_wp) then
         length = sqrt(max(d**2 - g%h**2, 0.0_wp)) + g%h*wrap
         return
      end if
      e = hip + g%h*[cos(theta1), sin(theta1)] - g%anchor
      length = hypot(e(1), e(2))
   end function lap_length

   !> Issue 15: the lap belt's wrap about the hip, phi_1 - theta_1 + pi/2
   !! (rad; section_state's), continued below 0 where the belt runs straight
   !! from its anchor to E (D-24). Where it passes 0 the belt leaves the hip:
   !! its length and gradient are continuous there (the straight line is the
   !! tangent), and so is the gradient's slope, but not the slope's slope - a
   !! kink of the force's slope along the motion, like a turning point's: a
   !! switch (test_lap_wrap_switch).
   pure real(wp) function lap_wrap(g, bb) result(wrap)
      type(belt_section_geometry_t), intent(in) :: g
      type(belt_body_t), intent(in) :: bb
      real(wp) :: u, v
      u = bb%joint(1, 1) - g%anchor(1)
      v = bb%joint(2, 1) - g%anchor(2)
      wrap = tangent_turn(g%h, sqrt(u**2 + v**2)) + atan2(v, u) - bb%theta(1) + 0.5_wp*pi
   end function lap_wrap

   !> asin(h/d), the angle between the line from the anchor to the hip and
   !! the tangent from the anchor to the hip's circle of radius h; π/2 when
   !! the anchor lies on or inside the circle, where the anchor is its own
   !! tangent point and the belt's length, sqrt(d² − h²) + h·wrap, stays
   !! continuous (the anchor inside the pelvis is not a physical state,
   !! but a run may pass through it: no jump then).
   pure real(wp) function tangent_turn(h, d) result(a)
      real(wp), intent(in) :: h, d
      a = 0.5_wp*pi
      if (d > h) a = asin(h/d)
   end function tangent_turn

   !> φ_j, δ_j, δ̇_j and ∂δ_j/∂z of one section (C.4.e). angle = .false.
   !! skips φ_j of a straight section (its direction is used without it;
   !! the effect asks for φ_j only for its outputs).
   pure function belt_kinematics(g, bb, angle) result(k)
      type(belt_section_geometry_t), intent(in) :: g
      type(belt_body_t), intent(in) :: bb
      logical, intent(in), optional :: angle
      type(belt_kinematics_t) :: k
      logical :: with_angle
      with_angle = .true.
      if (present(angle)) with_angle = angle
      k%gradient = 0.0_wp
      call section_state(g, bb, with_angle, k%phi, k%delta, k%delta_rate, k%gradient, k%wrapped, &
                         k%point, k%direction)
   end function belt_kinematics

   !> δ_j and δ̇_j of one section, added to a chain's s and s', and ∂δ_j/∂z
   !! added to its gradient g: belt_kinematics without φ_j of a straight
   !! section and without a result to copy (the effect's right-hand side).
   pure subroutine belt_section_add(geom, bb, s, s_dot, g)
      type(belt_section_geometry_t), intent(in) :: geom
      type(belt_body_t), intent(in) :: bb
      real(wp), intent(inout) :: s, s_dot, g(n_dof)
      real(wp) :: phi, delta, delta_rate
      logical :: wrapped
      call section_state(geom, bb, .false., phi, delta, delta_rate, g, wrapped)
      s = s + delta
      s_dot = s_dot + delta_rate
   end subroutine belt_section_add

   !> The section's φ_j (when with_angle, or for a lap belt that wraps the
   !! hip, whose length needs it; else 0), δ_j, δ̇_j, whether a lap belt
   !! wraps the hip, and ∂δ_j/∂z added to grad, entry by entry.
   pure subroutine section_state(g, bb, with_angle, phi, delta, delta_rate, grad, wrapped, point, direction)
      type(belt_section_geometry_t), intent(in) :: g
      type(belt_body_t), intent(in) :: bb
      logical, intent(in) :: with_angle
      real(wp), intent(out) :: phi, delta, delta_rate
      real(wp), intent(inout) :: grad(n_dof)
      logical, intent(out) :: wrapped
      real(wp), intent(out), optional :: point(2), direction(2)   ! (belt_kinematics_t)
      real(wp) :: p(2), p_rate(2), e(2), u, v, d, wrap, length, r, cr, ts(2)
      integer :: s

      s = g%segment
      wrapped = .true.
      if (g%kind == belt_lap) then
         u = bb%joint(1, 1) - g%anchor(1)
         v = bb%joint(2, 1) - g%anchor(2)
         d = sqrt(u**2 + v**2)   ! (lengths are bounded: equations_of_motion's range guard)
         phi = tangent_turn(g%h, d) + atan2(v, u)     ! C.4.e φ_1, with atan2 (BE-2)
         wrap = phi - bb%theta(1) + 0.5_wp*pi
         wrapped = wrap >= 0.0_wp .and. d > 0.0_wp   ! A-B1: no negative wrap
         if (wrapped) then
            ! δ_1 = √(u²+v²−h_1²) − ℓ_10 + h_1 [φ_1 − θ_1 + π/2]; its derivative
            ! is the tangent direction against the hip's motion minus h_1 dθ_1;
            ! e(φ_1) is (u, v)/d turned by asin(h_1/d). Inside the circle
            ! (d <= h_1) the length is h_1 wrap alone, whose derivative
            ! h_1 ∇atan2 = (h_1/d) (−v, u)/d is the same formula with the
            ! turn held at π/2 and the factor h_1/d: continuous at d = h_1.
            length = sqrt(max(d**2 - g%h**2, 0.0_wp)) + g%h*wrap
            r = min(g%h/d, 1.0_wp)
            cr = sqrt(1.0_wp - r**2)
            e = [u*cr - v*r, v*cr + u*r]/d
            if (d < g%h) e = (g%h/d)*e
            delta = length - g%length0
            delta_rate = dot_product(e, bb%joint_rate(:, 1)) - g%h*bb%theta_rate(1)   ! C.4.e δ̇_1
            call add_joint_gradient(bb, s, e, grad)
            grad(s) = grad(s) - g%h    ! − h_1 ∂θ_1/∂α_1
            ! the tangent point hip + h_1 e⊥/|e|² (e⊥ = e turned by +90°):
            ! -F e there does the virtual work -F (e·∂hip/∂z − h_1 ∂θ_1/∂z)
            if (present(point)) point = bb%joint(:, 1) + g%h*[-e(2), e(1)]/dot_product(e, e)
            if (present(direction)) direction = e
            return
         end if
         ! straight from the anchor to E = hip + h_1 e(θ_1)
         ts = [-bb%st(1), bb%ct(1)]
         p = bb%joint(:, 1) + g%h*[bb%ct(1), bb%st(1)]
         p_rate = bb%joint_rate(:, 1) + g%h*bb%theta_rate(1)*ts
      else
         ! C.4.e: u_j = x_j + h_j cos θ_j − (anchor x), v_j likewise
         ts = [-bb%st(s), bb%ct(s)]
         p = bb%joint(:, s) + g%h*[bb%ct(s), bb%st(s)]
         p_rate = bb%joint_rate(:, s) + g%h*bb%theta_rate(s)*ts
      end if
      u = p(1) - g%anchor(1)
      v = p(2) - g%anchor(2)
      d = sqrt(u**2 + v**2)
      phi = 0.0_wp
      if (with_angle) phi = atan2(v, u)   ! C.4.e φ_j, atan2 (BE-2); for the outputs only
      e = [u, v]/d                                 ! e(φ_j)
      delta = d - g%length0                        ! δ_j = √(u_j² + v_j²) − ℓ_j0
      delta_rate = dot_product(e, p_rate)          ! = ẋ_j cos φ_j + ẏ_j sin φ_j + h_j θ̇_j sin(φ_j − θ_j)
      call add_joint_gradient(bb, s, e, grad)
      grad(s) = grad(s) + g%h*dot_product(e, ts)
      if (present(point)) point = p
      if (present(direction)) direction = e
   end subroutine section_state

   !> Adds e . ∂(interior position of the proximal joint of segment s)/∂z
   !! to grad, s = 1..3: the hip moves with x_h, y_h (rotated into the
   !! interior frame), joint 2 also with α_1 (L_1), joint 3 with α_1 and α_2
   !! (section B). Written out: the Jacobian has 2 + 2(s - 1) entries that
   !! are not zero.
   pure subroutine add_joint_gradient(bb, s, e, grad)
      type(belt_body_t), intent(in) :: bb
      integer, intent(in) :: s
      real(wp), intent(in) :: e(2)
      real(wp), intent(inout) :: grad(n_dof)
      integer :: k
      grad(hip_x) = grad(hip_x) + (e(1)*bb%cphi + e(2)*bb%sphi)       ! e . R(Φ) e_x
      grad(hip_y) = grad(hip_y) + (e(1)*(-bb%sphi) + e(2)*bb%cphi)    ! e . R(Φ) e_y
      do k = 1, s - 1
         grad(k) = grad(k) + (e(1)*(bb%length(k)*(-bb%st(k))) + e(2)*(bb%length(k)*bb%ct(k)))
      end do
   end subroutine add_joint_gradient
end module belt_geometry
