!> Report C.4.c, joint elasticity: tau = -K_i [(alpha_i - alpha_m) -
!! (alpha_i0 - alpha_m0)], the spring at rest in the initial position.
module joint_elasticity
   use kinds, only: wp
   use model, only: n_dof, n_joint, joint_partner
   use effect_base, only: effect_t, body_state_t
   use effect_energies, only: energy_stored, n_energy_kinds
   use output_series, only: output_series_t
   use joint_coupling, only: relative_angle, per_joint_series, joint_list_text
   implicit none
   private

   public :: joint_elasticity_t, joint_elasticity_effect

   type, extends(effect_t) :: joint_elasticity_t
      integer, allocatable :: joints(:)          !< joints with K > 0
      real(wp) :: k(n_joint) = 0.0_wp
      real(wp) :: rel0(n_joint) = 0.0_wp         !< relative angles at t = 0
   contains
      procedure :: add_forces => elasticity_add_forces
      procedure :: energy => elasticity_energy
      procedure :: outputs => elasticity_outputs
      procedure :: output_values => elasticity_output_values
      procedure :: describe => elasticity_describe
   end type joint_elasticity_t

contains

   function joint_elasticity_effect(k_elastic, z0) result(e)
      real(wp), intent(in) :: k_elastic(n_joint), z0(n_dof)
      type(joint_elasticity_t) :: e
      integer :: i
      e%name = 'joint_elasticity'
      e%title = 'joint elasticity (C.4.c)'
      e%k = k_elastic
      allocate (e%joints(count(k_elastic > 0.0_wp)))
      e%joints(:) = pack([(i, i=1, n_joint)], k_elastic > 0.0_wp)
      e%rel0 = [(relative_angle(z0, i), i=1, n_joint)]
      e%has_energy(energy_stored) = .true.
   end function joint_elasticity_effect

   pure subroutine elasticity_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(joint_elasticity_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      integer :: n, i, m
      real(wp) :: tau
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate) + size(aux_rate))
      end associate
      ! written out (joint_coupling's rule, +tau on i and -tau on m) because
      ! it runs at every evaluation
      do n = 1, size(this%joints)
         i = this%joints(n)
         m = joint_partner(i)
         tau = -this%k(i)*((st%z(i) - st%z(m)) - this%rel0(i))
         b(i) = b(i) + tau
         b(m) = b(m) - tau
      end do
   end subroutine elasticity_add_forces

   !> Energy of each spring, with the 1/2 (erratum E-61).
   pure function spring_energy(this, z) result(e)
      class(joint_elasticity_t), intent(in) :: this
      real(wp), intent(in) :: z(n_dof)
      real(wp) :: e(n_joint)
      integer :: i
      do i = 1, n_joint
         e(i) = 0.5_wp*this%k(i)*(relative_angle(z, i) - this%rel0(i))**2
      end do
   end function spring_energy

   pure subroutine elasticity_energy(this, st, extra, aux, e)
      class(joint_elasticity_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (u1 => size(extra) + size(aux))
      end associate
      e = 0.0_wp
      e(energy_stored) = sum(spring_energy(this, st%z))
   end subroutine elasticity_energy

   function elasticity_outputs(this) result(series)
      class(joint_elasticity_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      series = per_joint_series('energy', 'JOINT ELASTIC ENERGY', 'elastic energy of each joint (C.6, erratum E-61)')
   end function elasticity_outputs

   pure subroutine elasticity_output_values(this, item, st, extra, aux, values)
      class(joint_elasticity_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      associate (u1 => item, u2 => size(extra) + size(aux))
      end associate
      values = spring_energy(this, st%z)
   end subroutine elasticity_output_values

   function elasticity_describe(this) result(text)
      class(joint_elasticity_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': '//joint_list_text(this%joints)
   end function elasticity_describe
end module joint_elasticity
