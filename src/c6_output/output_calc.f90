!> Report C.6, output calculations: head and chest accelerations, energies
!! of the vehicle, the segments and the joints, gravitational energy,
!! angles relative to the interior and joint positions (C.4), for one
!! accepted state.
module output_calc
   use kinds, only: wp
   use model, only: model_t, n_dof, n_seg, n_joint, joint_partner
   use generalized_forces, only: scene_t
   use body_kinematics, only: point_state_t, segment_cg_state, joint_state, to_interior
   use joint_restraints, only: restraint_energy
   use vehicle_motion, only: vehicle_state_t
   implicit none
   private

   public :: output_record_t, output_compute, head_chest_acceleration, body_energy

   !> Segments whose centre-of-gravity accelerations C.6 prints.
   integer, parameter :: chest = 3, head = 4

   !> All output variables at one time (internal units; the listing converts).
   type :: output_record_t
      real(wp) :: t = 0.0_wp
      real(wp) :: head_acc = 0.0_wp, chest_acc = 0.0_wp   !< resultant, in/s^2
      real(wp) :: veh_pos(3) = 0.0_wp, veh_vel(3) = 0.0_wp, veh_acc(3) = 0.0_wp
      real(wp) :: z(n_dof) = 0.0_wp, zdot(n_dof) = 0.0_wp, zdd(n_dof) = 0.0_wp
      real(wp) :: theta(n_seg) = 0.0_wp        !< segment angles relative to the interior
      real(wp) :: joint_angle(n_joint) = 0.0_wp !< alpha_i - alpha_m
      real(wp) :: joint_x(n_joint) = 0.0_wp, joint_y(n_joint) = 0.0_wp !< relative to the interior
      real(wp) :: ke_vehicle = 0.0_wp
      real(wp) :: ke_seg(n_seg) = 0.0_wp
      real(wp) :: pe_gravity(n_seg) = 0.0_wp
      real(wp) :: e_spring(n_joint) = 0.0_wp, e_stop(n_joint) = 0.0_wp, w_friction(n_joint) = 0.0_wp
      real(wp) :: e_total = 0.0_wp              !< body kinetic + conserved + dissipated
      real(wp) :: e_error = 0.0_wp              !< e_total minus its initial value
   end type output_record_t

contains

   !> Resultant accelerations of the head and chest centres of gravity
   !! (C.6; the kinematic acceleration, as the report defines it). Written
   !! out for the two chains (hip - L1 - L2 - upper torso - L3 - head) as it
   !! runs on every accepted step.
   pure subroutine head_chest_acceleration(m, z, zdot, zdd, a_head, a_chest)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      real(wp), intent(out) :: a_head, a_chest
      real(wp) :: c(head), s(head), spine(2), chest_cg(2), head_cg(2)
      c = cos(z(1:head))
      s = sin(z(1:head))
      spine = zdd(9:10) + link(1, m%length(1)) + link(2, m%length(2))
      chest_cg = spine + link(chest, m%rho(chest))
      head_cg = spine + link(chest, m%length(3)) + link(head, m%rho(head))
      a_head = hypot(head_cg(1), head_cg(2))
      a_chest = hypot(chest_cg(1), chest_cg(2))
   contains
      !> acceleration of a point len along segment j relative to its joint
      pure function link(j, len) result(a)
         integer, intent(in) :: j
         real(wp), intent(in) :: len
         real(wp) :: a(2)
         a(1) = -len*(zdd(j)*s(j) + zdot(j)**2*c(j))
         a(2) = len*(zdd(j)*c(j) - zdot(j)**2*s(j))
      end function link
   end subroutine head_chest_acceleration

   !> Fill an output record. y is the integrator's state (z, z', friction
   !! work), zdd the accelerations there, vs the vehicle state, y_cg0 the
   !! initial CG heights (gravitational energy is measured from them).
   pure subroutine output_compute(m, sc, t, y, zdd, vs, y_cg0, e_total0, r)
      type(model_t), intent(in) :: m
      type(scene_t), intent(in) :: sc
      real(wp), intent(in) :: t, y(:), zdd(n_dof)
      type(vehicle_state_t), intent(in) :: vs
      real(wp), intent(in) :: y_cg0(n_seg), e_total0
      type(output_record_t), intent(out) :: r
      type(point_state_t) :: p
      integer :: i, k

      r%t = t
      r%z = y(1:n_dof)
      r%zdot = y(n_dof + 1:2*n_dof)
      r%zdd = zdd
      r%veh_pos = vs%pos
      r%veh_vel = vs%vel
      r%veh_acc = vs%acc
      call head_chest_acceleration(m, r%z, r%zdot, r%zdd, r%head_acc, r%chest_acc)
      ! Theta_i = alpha_i + Phi (section B)
      r%theta = r%z(1:n_seg) + vs%pos(3)
      do i = 1, n_joint
         r%joint_angle(i) = r%z(i) - r%z(joint_partner(i))
         p = to_interior(joint_state(m, r%z, r%zdot, r%zdd, i), vs%pos, vs%vel)
         r%joint_x(i) = p%x
         r%joint_y(i) = p%y
      end do
      ! C.6 kinetic energies: vehicle, and segments with erratum E-65
      r%ke_vehicle = 0.5_wp*m%vehicle_mass*(vs%vel(1)**2 + vs%vel(2)**2) &
                     + 0.5_wp*m%vehicle_inertia*vs%vel(3)**2
      do i = 1, n_seg
         p = segment_cg_state(m, r%z, r%zdot, r%zdd, i)
         r%ke_seg(i) = 0.5_wp*m%mass(i)*(p%vx**2 + p%vy**2) + 0.5_wp*m%inertia(i)*r%zdot(i)**2
         ! gravitational energy from the inertial CG height (erratum E-63)
         r%pe_gravity(i) = m%gravity*m%mass(i)*(p%y - y_cg0(i))
      end do
      ! joints: elastic energy with the 1/2 (erratum E-61), stop energy,
      ! friction work integrated with the motion (erratum E-64)
      do i = 1, n_joint
         r%e_spring(i) = 0.5_wp*m%k_elastic(i)*(r%joint_angle(i) - sc%rel0(i))**2
         r%e_stop(i) = restraint_energy(m%restraint(i), r%joint_angle(i))
      end do
      do k = 1, size(sc%friction_joints)
         r%w_friction(sc%friction_joints(k)) = y(2*n_dof + k)
      end do
      r%e_total = body_energy(r)
      r%e_error = r%e_total - e_total0
   end subroutine output_compute

   !> Body energy that is constant while no external force acts: kinetic +
   !! gravitational + elastic + stop energy + work dissipated by friction.
   pure real(wp) function body_energy(r)
      type(output_record_t), intent(in) :: r
      body_energy = sum(r%ke_seg) + sum(r%pe_gravity) + sum(r%e_spring) + sum(r%e_stop) &
                    + sum(r%w_friction)
   end function body_energy
end module output_calc
