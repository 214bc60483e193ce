!> Report C.4.c: joint torques from elasticity, Coulomb friction and the
!! angular restraints. Joint i couples segment i and its partner m (Table 6)
!! through the relative angle alpha_i - alpha_m; a joint torque tau acts
!! +tau on segment i and -tau on segment m, which reproduces every J_i of
!! C.4.c (errata.md, "Joint springs"). Each routine walks only the joints
!! the scene lists for it.
module joint_torques
   use kinds, only: wp
   use model, only: n_joint, n_dof, joint_partner, restraint_t
   use joint_restraints, only: restraint_torque
   implicit none
   private

   public :: joint_elastic_torques, joint_friction_torques, joint_stop_torques

contains

   !> Elasticity: tau = -K_i [(alpha_i - alpha_m) - (alpha_i0 - alpha_m0)].
   pure subroutine joint_elastic_torques(joints, k_elastic, rel0, z, b)
      integer, intent(in) :: joints(:)
      real(wp), intent(in) :: k_elastic(n_joint), rel0(n_joint), z(n_dof)
      real(wp), intent(inout) :: b(n_dof)
      integer :: n, i, m
      real(wp) :: tau
      do n = 1, size(joints)
         i = joints(n)
         m = joint_partner(i)
         tau = -k_elastic(i)*((z(i) - z(m)) - rel0(i))
         b(i) = b(i) + tau
         b(m) = b(m) - tau
      end do
   end subroutine joint_elastic_torques

   !> Coulomb friction, J-hat of C.4.c: C'_i sgn(alpha-dot_m - alpha-dot_i)
   !! when the relative rate reaches xi_i, zero below it. Also returns the
   !! power each joint dissipates (C'_i |relative rate|), for the energy
   !! accounting of C.6.
   pure subroutine joint_friction_torques(joints, c_friction, xi, zdot, b, power)
      integer, intent(in) :: joints(:)
      real(wp), intent(in) :: c_friction(n_joint), xi(n_joint), zdot(n_dof)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: power(:)
      integer :: n, i, m
      real(wp) :: w, tau
      do n = 1, size(joints)
         i = joints(n)
         m = joint_partner(i)
         w = zdot(i) - zdot(m)
         if (abs(w) >= xi(i)) then
            tau = -sign(c_friction(i), w)
            power(n) = c_friction(i)*abs(w)
         else
            tau = 0.0_wp
            power(n) = 0.0_wp
         end if
         b(i) = b(i) + tau
         b(m) = b(m) - tau
      end do
   end subroutine joint_friction_torques

   !> Angular restraints T_i (figure 9). The dead band |rate| < xi of C.4.c is
   !! applied to the friction only (docs/errata.md, D-4): a joint resting on
   !! its stop still feels the stop.
   pure subroutine joint_stop_torques(joints, restraint, z, b)
      integer, intent(in) :: joints(:)
      type(restraint_t), intent(in) :: restraint(n_joint)
      real(wp), intent(in) :: z(n_dof)
      real(wp), intent(inout) :: b(n_dof)
      integer :: n, i, m
      real(wp) :: tau
      do n = 1, size(joints)
         i = joints(n)
         m = joint_partner(i)
         tau = restraint_torque(restraint(i), z(i) - z(m))
         b(i) = b(i) + tau
         b(m) = b(m) - tau
      end do
   end subroutine joint_stop_torques
end module joint_torques
