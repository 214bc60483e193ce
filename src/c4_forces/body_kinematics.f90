!> Positions, velocities and accelerations of the body's points from the
!! generalized coordinates (section B, the start of C.4, C.6). The body is a
!! tree rooted at the hip; chain(:, i) lists the links from the hip to the
!! proximal joint of segment i as (segment, length index) pairs:
!!   1 lower torso: -                    5 upper arm:  1 L1, 2 L2, 3 L4
!!   2 center torso: 1 L1                6 lower arm:  1 L1, 2 L2, 3 L4, 5 L5
!!   3 upper torso: 1 L1, 2 L2           7 upper leg:  -
!!   4 head: 1 L1, 2 L2, 3 L3            8 lower leg:  7 L7
!! (L3 and L4 are the neck and shoulder offsets along segment 3.) Joint k
!! is the proximal joint of segment k for k = 1..6; the knee, joint 7, is
!! that of segment 8.
module body_kinematics
   use kinds, only: wp
   use model, only: body_section_t, n_seg, n_dof, n_joint, hip_x, hip_y
   implicit none
   private

   public :: point_state_t, segment_cg_state, joint_state, to_interior, joint_segment
   public :: point_force_generalized, joint_position_velocity, joint_positions
   public :: link_cos_sin, body_points, cg_positions, to_interior_cs

   integer, parameter :: max_links = 4
   integer, parameter :: n_links(n_seg) = [0, 1, 2, 3, 3, 4, 0, 1]
   !> chain_seg(k, i): segment of the k-th link towards segment i
   integer, parameter :: chain_seg(max_links, n_seg) = reshape([ &
      0, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0, 1, 2, 3, 0, &
      1, 2, 3, 0, 1, 2, 3, 5, 0, 0, 0, 0, 7, 0, 0, 0], [max_links, n_seg])
   !> chain_len(k, i): which L_j is the length of that link
   integer, parameter :: chain_len(max_links, n_seg) = reshape([ &
      0, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0, 1, 2, 3, 0, &
      1, 2, 4, 0, 1, 2, 4, 5, 0, 0, 0, 0, 7, 0, 0, 0], [max_links, n_seg])
   !> the segment whose proximal joint is joint k
   integer, parameter :: joint_segment(n_joint) = [1, 2, 3, 4, 5, 6, 8]

   !> Position, velocity and acceleration of a point (inertial unless said).
   type :: point_state_t
      real(wp) :: x = 0.0_wp, y = 0.0_wp
      real(wp) :: vx = 0.0_wp, vy = 0.0_wp
      real(wp) :: ax = 0.0_wp, ay = 0.0_wp
   end type point_state_t

contains

   !> The point at distance d along segment i from its proximal joint
   !! (d = rho_i: the centre of gravity; d = 0: the joint itself).
   pure function point_on_segment(body, z, zdot, zdd, i, d) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      integer, intent(in) :: i
      real(wp), intent(in) :: d
      type(point_state_t) :: p
      integer :: k
      p%x = z(hip_x)
      p%y = z(hip_y)
      p%vx = zdot(hip_x)
      p%vy = zdot(hip_y)
      p%ax = zdd(hip_x)
      p%ay = zdd(hip_y)
      do k = 1, n_links(i)
         call add_link(p, z, zdot, zdd, chain_seg(k, i), body%length(chain_len(k, i)))
      end do
      call add_link(p, z, zdot, zdd, i, d)
   end function point_on_segment

   !> Move p along segment j by the distance len.
   pure subroutine add_link(p, z, zdot, zdd, j, len)
      type(point_state_t), intent(inout) :: p
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      integer, intent(in) :: j
      real(wp), intent(in) :: len
      call add_link_cs(p, zdot, zdd, j, len, cos(z(j)), sin(z(j)))
   end subroutine add_link

   !> add_link with the cosine c and sine s of z(j) at hand (link_cos_sin's):
   !! the same sums.
   pure subroutine add_link_cs(p, zdot, zdd, j, len, c, s)
      type(point_state_t), intent(inout) :: p
      real(wp), intent(in) :: zdot(n_dof), zdd(n_dof)
      integer, intent(in) :: j
      real(wp), intent(in) :: len, c, s
      p%x = p%x + len*c
      p%y = p%y + len*s
      p%vx = p%vx - len*zdot(j)*s
      p%vy = p%vy + len*zdot(j)*c
      ! C.6 head/chest accelerations: -L(alpha'' sin + alpha'^2 cos), +L(alpha'' cos - alpha'^2 sin)
      p%ax = p%ax - len*(zdd(j)*s + zdot(j)**2*c)
      p%ay = p%ay + len*(zdd(j)*c - zdot(j)**2*s)
   end subroutine add_link_cs

   !> The cosine and sine of each segment angle, c(j) = cos(z(j)) and
   !! s(j) = sin(z(j)), with add_link's bits (the scalar library's), once
   !! for every link that turns about segment j (a print time's frame). Not
   !! the effects' st%c, st%s (segment_trig: the vector library's, other last
   !! bits); so the loop is kept scalar, which vectorized would call the
   !! vector library.
   pure subroutine link_cos_sin(z, c, s)
      real(wp), intent(in) :: z(n_seg)
      real(wp), intent(out) :: c(n_seg), s(n_seg)
      integer :: j
      !GCC$ novector
      do j = 1, n_seg
         c(j) = cos(z(j))
         s(j) = sin(z(j))
      end do
   end subroutine link_cos_sin

   !> Every segment's proximal joint joint(i) (point_on_segment at d = 0,
   !! as joint_state) and centre of gravity cg(i) (segment_cg_state), from
   !! link_cos_sin's c and s: point_on_segment's sums in the same order, each
   !! chain's prefix walked once (as joint_positions: the chain to segment
   !! i's joint is the chain to the joint of its last link's segment j, then
   !! that link; in the order 1..8, j comes before i).
   pure subroutine body_points(body, z, zdot, zdd, c, s, joint, cg)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof), c(n_seg), s(n_seg)
      type(point_state_t), intent(out) :: joint(n_seg), cg(n_seg)
      type(point_state_t) :: chain_end(n_seg)
      integer :: i, k, j
      do i = 1, n_seg
         k = n_links(i)
         if (k == 0) then
            chain_end(i) = point_state_t(z(hip_x), z(hip_y), zdot(hip_x), zdot(hip_y), zdd(hip_x), zdd(hip_y))
         else
            j = chain_seg(k, i)
            chain_end(i) = chain_end(j)
            call add_link_cs(chain_end(i), zdot, zdd, j, body%length(chain_len(k, i)), c(j), s(j))
         end if
         joint(i) = chain_end(i)
         call add_link_cs(joint(i), zdot, zdd, i, 0.0_wp, c(i), s(i))
         cg(i) = chain_end(i)
         call add_link_cs(cg(i), zdot, zdd, i, body%rho(i), c(i), s(i))
      end do
   end subroutine body_points

   !> The centres of gravity's positions p(:, i) alone (segment_cg_state's
   !! x, y, which do not depend on the rates), from link_cos_sin's c and s:
   !! body_points' sums for x and y.
   pure function cg_positions(body, z, c, s) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), c(n_seg), s(n_seg)
      real(wp) :: p(2, n_seg)
      real(wp) :: chain_end(2, n_seg)
      integer :: i, k, j
      do i = 1, n_seg
         k = n_links(i)
         if (k == 0) then
            chain_end(:, i) = [z(hip_x), z(hip_y)]
         else
            j = chain_seg(k, i)
            chain_end(1, i) = chain_end(1, j) + body%length(chain_len(k, i))*c(j)
            chain_end(2, i) = chain_end(2, j) + body%length(chain_len(k, i))*s(j)
         end if
         p(1, i) = chain_end(1, i) + body%rho(i)*c(i)
         p(2, i) = chain_end(2, i) + body%rho(i)*s(i)
      end do
   end function cg_positions

   !> Centre of gravity of segment i (section B X_i, Y_i with errata E-B1,
   !! E-B2; C.6 with E-65).
   pure function segment_cg_state(body, z, zdot, zdd, i) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      integer, intent(in) :: i
      type(point_state_t) :: p
      p = point_on_segment(body, z, zdot, zdd, i, body%rho(i))
   end function segment_cg_state

   !> Joint k (1 hip .. 7 knee), inertial.
   pure function joint_state(body, z, zdot, zdd, k) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      integer, intent(in) :: k
      type(point_state_t) :: p
      p = point_on_segment(body, z, zdot, zdd, joint_segment(k), 0.0_wp)
   end function joint_state

   !> Position and velocity (inertial) of the proximal joint of segment i
   !! from the cosines c and sines s of the angles, already at hand (the
   !! effects' body state): point_on_segment at d = 0 without its trig.
   pure subroutine joint_position_velocity(body, z, zdot, c, s, i, p, v)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), c(n_seg), s(n_seg)
      integer, intent(in) :: i
      real(wp), intent(out) :: p(2), v(2)
      integer :: k, j
      real(wp) :: len
      p = [z(hip_x), z(hip_y)]
      v = [zdot(hip_x), zdot(hip_y)]
      do k = 1, n_links(i)
         j = chain_seg(k, i)
         len = body%length(chain_len(k, i))
         p = p + len*[c(j), s(j)]
         v = v + len*zdot(j)*[-s(j), c(j)]
      end do
   end subroutine joint_position_velocity

   !> The proximal joints (inertial) of all segments, p(:, i) for segment i,
   !! from the cosines c and sines s of the angles: joint_position_velocity's
   !! p for each i with the same arithmetic in the same order, each chain's prefix taken
   !! once (the chains of the module's header: the chain to segment i's
   !! joint is the chain to the joint of its last link's segment, then that
   !! link).
   pure function joint_positions(body, z, c, s) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), c(n_seg), s(n_seg)
      real(wp) :: p(2, n_seg)
      integer :: i, k, j
      ! (in the order 1..8 the last link's segment j of every chain comes
      ! before i, and its own joint is that chain's prefix)
      do i = 1, n_seg
         k = n_links(i)
         if (k == 0) then
            p(:, i) = [z(hip_x), z(hip_y)]
         else
            j = chain_seg(k, i)
            p(:, i) = p(:, j) + body%length(chain_len(k, i))*[c(j), s(j)]
         end if
      end do
   end function joint_positions

   !> The generalized force of a force f (inertial) at the inertial point p
   !! of segment i: its virtual work J^T f, J = dp/dz for the material point
   !! (the hip's translation, each link of the chain to segment i turning
   !! about its joint, and segment i about its own proximal joint). The
   !! joint is point_on_segment's at d = 0 with the same sums in the same
   !! order, from the link's sine and cosine taken once for both uses (they
   !! were taken twice, and point_on_segment carried rates of zero along).
   pure function point_force_generalized(body, z, i, p, f) result(b)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), p(2), f(2)
      integer, intent(in) :: i
      real(wp) :: b(n_dof)
      real(wp) :: len, c, s, jx, jy
      integer :: k, j
      b = 0.0_wp
      b(hip_x) = f(1)
      b(hip_y) = f(2)
      jx = z(hip_x)
      jy = z(hip_y)
      do k = 1, n_links(i)
         j = chain_seg(k, i)
         len = body%length(chain_len(k, i))
         c = cos(z(j))
         s = sin(z(j))
         b(j) = b(j) + len*(-f(1)*s + f(2)*c)
         jx = jx + len*c
         jy = jy + len*s
      end do
      b(i) = b(i) - f(1)*(p(2) - jy) + f(2)*(p(1) - jx)
   end function point_force_generalized

   !> The start of C.4: a point's position and velocity relative to the
   !! vehicle interior, x = R(Phi)(X - x_c), with the -y Phi', +x Phi'
   !! terms of the rotating frame. vpos/vvel: x_c, y_c, Phi and their rates.
   pure function to_interior(p, vpos, vvel) result(q)
      type(point_state_t), intent(in) :: p
      real(wp), intent(in) :: vpos(3), vvel(3)
      type(point_state_t) :: q
      q = to_interior_cs(p, vpos, vvel, cos(vpos(3)), sin(vpos(3)))
   end function to_interior

   !> to_interior with the cosine c and sine s of the pitch vpos(3) at
   !! hand (the scalar library's, as to_interior takes them): the same sums.
   pure function to_interior_cs(p, vpos, vvel, c, s) result(q)
      type(point_state_t), intent(in) :: p
      real(wp), intent(in) :: vpos(3), vvel(3), c, s
      type(point_state_t) :: q
      real(wp) :: dx, dy, dvx, dvy
      dx = p%x - vpos(1)
      dy = p%y - vpos(2)
      dvx = p%vx - vvel(1)
      dvy = p%vy - vvel(2)
      q%x = dx*c - dy*s
      q%y = dx*s + dy*c
      q%vx = dvx*c - dvy*s - q%y*vvel(3)
      q%vy = dvx*s + dvy*c + q%x*vvel(3)
   end function to_interior_cs
end module body_kinematics
