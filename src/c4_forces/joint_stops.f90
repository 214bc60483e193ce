!> Report C.4.c, figure 9: the angular restraints (stops) of the joints,
!! linear, cubic or tabulated (joint_restraints), acting beyond omega and
!! Omega. The dead band |rate| < xi of C.4.c is applied to the friction
!! only (docs/errata.md D-4): a joint resting on its stop still feels it.
module joint_stops
   use kinds, only: wp
   use model, only: n_dof, n_joint, restraint_t, joint_partner
   use effect_base, only: effect_t, body_state_t
   use effect_energies, only: energy_stored, n_energy_kinds
   use output_series, only: output_series_t
   use joint_coupling, only: relative_angle, per_joint_series, joint_list_text
   use joint_restraints, only: restraint_torque, restraint_energy, restraint_is_active
   implicit none
   private

   public :: joint_stops_t, joint_stops_effect

   type, extends(effect_t) :: joint_stops_t
      integer, allocatable :: joints(:)          !< joints whose restraint can act
      type(restraint_t) :: restraint(n_joint)
   contains
      procedure :: add_forces => stops_add_forces
      procedure :: energy => stops_energy
      procedure :: outputs => stops_outputs
      procedure :: output_values => stops_output_values
      procedure :: describe => stops_describe
   end type joint_stops_t

contains

   function joint_stops_effect(restraint) result(e)
      type(restraint_t), intent(in) :: restraint(n_joint)
      type(joint_stops_t) :: e
      integer :: i
      e%name = 'joint_stops'
      e%title = 'joint stops (C.4.c, figure 9)'
      e%restraint = restraint
      allocate (e%joints(count([(restraint_is_active(restraint(i)), i=1, n_joint)])))
      e%joints(:) = pack([(i, i=1, n_joint)], [(restraint_is_active(restraint(i)), i=1, n_joint)])
      e%has_energy(energy_stored) = .true.
   end function joint_stops_effect

   pure subroutine stops_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(joint_stops_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      integer :: n, i, m
      real(wp) :: tau
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate) + size(aux_rate))
      end associate
      do n = 1, size(this%joints)
         i = this%joints(n)
         m = joint_partner(i)
         tau = restraint_torque(this%restraint(i), st%z(i) - st%z(m))
         b(i) = b(i) + tau
         b(m) = b(m) - tau
      end do
   end subroutine stops_add_forces

   pure function stop_energy(this, z) result(e)
      class(joint_stops_t), intent(in) :: this
      real(wp), intent(in) :: z(n_dof)
      real(wp) :: e(n_joint)
      integer :: i
      do i = 1, n_joint
         e(i) = restraint_energy(this%restraint(i), relative_angle(z, i))
      end do
   end function stop_energy

   pure subroutine stops_energy(this, st, extra, aux, e)
      class(joint_stops_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (u1 => size(extra) + size(aux))
      end associate
      e = 0.0_wp
      e(energy_stored) = sum(stop_energy(this, st%z))
   end subroutine stops_energy

   function stops_outputs(this) result(series)
      class(joint_stops_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      series = per_joint_series('energy', 'JOINT STOP ENERGY', 'energy stored in each joint''s stops (figure 9)')
   end function stops_outputs

   pure subroutine stops_output_values(this, item, st, extra, aux, values)
      class(joint_stops_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      associate (u1 => item, u2 => size(extra) + size(aux))
      end associate
      values = stop_energy(this, st%z)
   end subroutine stops_output_values

   function stops_describe(this) result(text)
      class(joint_stops_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': '//joint_list_text(this%joints)
   end function stops_describe
end module joint_stops
