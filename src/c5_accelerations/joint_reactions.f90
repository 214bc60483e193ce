!> The joint reaction forces from the solved dynamics (Newton-Euler on the
!! segments with the accelerations of C.5; errata-forces A-INJ, docs/errata.md F5-1), in
!! place of the quasi-static sums of f.5-f.6, which leave out inertia and
!! gravity and cut the body inconsistently. For joint j, with D(j) the
!! segments on its distal side,
!!
!!     R_j = sum over s in D(j) of (m_s a_s - F_s),
!!
!! a_s the inertial acceleration of the centre of gravity of s and F_s the
!! sum of the forces from outside the body on s (gravity, seat, belts,
!! contacts: the effects' point forces): the force the proximal side
!! exerts on the distal side through the joint. On the axis e of the
!! distal segment (pointing from the joint into it) the tension is
!! FT_j = -R_j . e (positive when the proximal side holds the distal part
!! back) and the shear FS_j = R_j . e_perp, e_perp = (-sin, cos).
!!
!! Distal sides (Table 6's pairs; the hip's distal side is the leg):
!! hip {7, 8}, lumbar {2..6}, thoracic {3..6}, neck {4}, shoulder {5, 6},
!! elbow {6}, knee {8}. The joint's axis is that of the first of them.
module joint_reactions
   use kinds, only: wp
   use model, only: body_section_t, n_seg, n_dof, n_joint
   use point_forces, only: point_force_list_t
   use body_kinematics, only: point_state_t, joint_state, link_cos_sin, body_points
   implicit none
   private

   public :: joint_reaction_forces, body_imbalance, bone_components, distal_segment
   public :: segment_cg_states, joint_reactions_at, bone_components_at, joint_moment_at, distal

   !> distal(s, j): segment s lies on the distal side of joint j.
   logical, parameter :: distal(n_seg, n_joint) = reshape([ &
      .false., .false., .false., .false., .false., .false., .true., .true., &    ! hip
      .false., .true., .true., .true., .true., .true., .false., .false., &       ! lumbar
      .false., .false., .true., .true., .true., .true., .false., .false., &      ! thoracic
      .false., .false., .false., .true., .false., .false., .false., .false., &   ! neck
      .false., .false., .false., .false., .true., .true., .false., .false., &    ! shoulder
      .false., .false., .false., .false., .false., .true., .false., .false., &   ! elbow
      .false., .false., .false., .false., .false., .false., .false., .true.], &  ! knee
      [n_seg, n_joint])
   !> The segment whose axis is joint j's bone axis.
   integer, parameter :: distal_segment(n_joint) = [7, 2, 3, 4, 5, 6, 8]

contains

   !> The centre of gravity of every segment (inertial; segment_cg_state).
   pure function segment_cg_states(body, z, zdot, zdd) result(p)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_state_t) :: p(n_seg)
      type(point_state_t) :: joint(n_seg)
      real(wp) :: c(n_seg), s(n_seg)
      ! (each angle's cosine and sine once, each chain's prefix walked once:
      ! body_points gives segment_cg_state's bits; the FMVSS table's loads
      ! ask for these at every accepted step)
      call link_cos_sin(z(1:n_seg), c, s)
      call body_points(body, z, zdot, zdd, c, s, joint, p)
   end function segment_cg_states

   !> m_s a_s - F_s for every segment (inertial, lb).
   pure function segment_imbalance(body, z, zdot, zdd, forces) result(q)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_force_list_t), intent(in) :: forces
      real(wp) :: q(2, n_seg)
      q = imbalance_at(body, segment_cg_states(body, z, zdot, zdd), forces)
   end function segment_imbalance

   !> segment_imbalance with the centres of gravity cg (segment_cg_states) at hand.
   pure function imbalance_at(body, cg, forces) result(q)
      type(body_section_t), intent(in) :: body
      type(point_state_t), intent(in) :: cg(n_seg)
      type(point_force_list_t), intent(in) :: forces
      real(wp) :: q(2, n_seg)
      integer :: s, k
      do s = 1, n_seg
         q(:, s) = body%mass(s)*[cg(s)%ax, cg(s)%ay]
      end do
      do k = 1, forces%n
         associate (f => forces%f(k))
            q(:, f%segment) = q(:, f%segment) - f%force
         end associate
      end do
   end function imbalance_at

   !> R_j of every joint (inertial components, lb).
   pure function joint_reaction_forces(body, z, zdot, zdd, forces) result(r)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_force_list_t), intent(in) :: forces
      real(wp) :: r(2, n_joint)
      r = joint_reactions_at(body, segment_cg_states(body, z, zdot, zdd), forces)
   end function joint_reaction_forces

   !> joint_reaction_forces with the centres of gravity cg (segment_cg_states)
   !! at hand (a print time's frame, whose kinetic energies take them too).
   pure function joint_reactions_at(body, cg, forces) result(r)
      type(body_section_t), intent(in) :: body
      type(point_state_t), intent(in) :: cg(n_seg)
      type(point_force_list_t), intent(in) :: forces
      real(wp) :: r(2, n_joint)
      real(wp) :: q(2, n_seg)
      integer :: j, s
      q = imbalance_at(body, cg, forces)
      r = 0.0_wp
      do j = 1, n_joint
         do s = 1, n_seg
            if (distal(s, j)) r(:, j) = r(:, j) + q(:, s)
         end do
      end do
   end function joint_reactions_at

   !> The moment (lb in, counter-clockwise positive) the proximal side
   !! exerts on the distal side D(j) through joint j (issue 18: the neck's
   !! flexion/extension moment), from the distal side's angular momentum
   !! about the joint's point P at this instant (A-INJ's Newton-Euler, for
   !! moments):
   !!
   !!     M_j = sum over s in D(j) of [I_s alpha_s'' + (r_s - P) x m_s a_s]
   !!           - sum over the point forces F on D(j) of (r_F - P) x F,
   !!
   !! the joint's elastic, friction and stop torques and the pin's force R_j
   !! (which acts at P) among what M_j and R_j carry; cg from
   !! segment_cg_states.
   pure real(wp) function joint_moment_at(body, z, zdot, zdd, cg, forces, j) result(m)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_state_t), intent(in) :: cg(n_seg)
      type(point_force_list_t), intent(in) :: forces
      integer, intent(in) :: j
      type(point_state_t) :: p
      integer :: s, k
      p = joint_state(body, z, zdot, zdd, j)
      m = 0.0_wp
      do s = 1, n_seg
         if (.not. distal(s, j)) cycle
         m = m + body%inertia(s)*zdd(s) + body%mass(s)*cross(cg(s)%x - p%x, cg(s)%y - p%y, cg(s)%ax, cg(s)%ay)
      end do
      do k = 1, forces%n
         associate (f => forces%f(k))
            if (.not. distal(f%segment, j)) cycle
            m = m - cross(f%point(1) - p%x, f%point(2) - p%y, f%force(1), f%force(2))
         end associate
      end do
   contains
      pure real(wp) function cross(rx, ry, fx, fy)
         real(wp), intent(in) :: rx, ry, fx, fy
         cross = rx*fy - ry*fx
      end function cross
   end function joint_moment_at

   !> sum over the whole body of m_s a_s - F_s: zero when every force from
   !! outside is among the point forces and the accelerations solve C.5.
   pure function body_imbalance(body, z, zdot, zdd, forces) result(total)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_force_list_t), intent(in) :: forces
      real(wp) :: total(2)
      real(wp) :: q(2, n_seg)
      q = segment_imbalance(body, z, zdot, zdd, forces)
      total = sum(q, dim=2)
   end function body_imbalance

   !> Tension FT_j = -R_j . e and shear FS_j = R_j . e_perp on each joint's
   !! bone axis e = (cos alpha_d, sin alpha_d), d = distal_segment(j).
   pure subroutine bone_components(r, z, tension, shear)
      real(wp), intent(in) :: r(2, n_joint), z(n_dof)
      real(wp), intent(out) :: tension(n_joint), shear(n_joint)
      real(wp) :: c, s
      integer :: j
      do j = 1, n_joint
         c = cos(z(distal_segment(j)))
         s = sin(z(distal_segment(j)))
         tension(j) = -(r(1, j)*c + r(2, j)*s)
         shear(j) = -r(1, j)*s + r(2, j)*c
      end do
   end subroutine bone_components

   !> bone_components with the cosines c and sines s of the segment angles
   !! at hand, with its bits (body_kinematics' link_cos_sin; a print time's
   !! frame): the same sums.
   pure subroutine bone_components_at(r, c, s, tension, shear)
      real(wp), intent(in) :: r(2, n_joint), c(n_seg), s(n_seg)
      real(wp), intent(out) :: tension(n_joint), shear(n_joint)
      integer :: j, d
      do j = 1, n_joint
         d = distal_segment(j)
         tension(j) = -(r(1, j)*c(d) + r(2, j)*s(d))
         shear(j) = -r(1, j)*s(d) + r(2, j)*c(d)
      end do
   end subroutine bone_components_at
end module joint_reactions
