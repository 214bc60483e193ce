!> Report C.4.c, figure 9: the angular restraints (stops) of the joints,
!! linear, cubic or tabulated (joint_restraints), acting beyond omega and
!! Omega. The dead band |rate| < xi of C.4.c is applied to the friction
!! only (docs/errata.md D-4): a joint resting on its stop still feels it.
!!
!! Switches (issue 15): the torque's slope jumps where a relative angle
!! reaches its stop (omega or Omega; every form starts from zero torque
!! there, D-3) and, for a tabulated stop, at each inner point of its curve
!! (the last point is no switch: the curve goes on along its last
!! interval). Each is a threshold angle theta of the relative angle delta:
!! g = delta - theta below (omega - DEPTH_k), theta - delta above (Omega +
!! DEPTH_k), in rad, positive on the free side. The stops have no memory.
module joint_stops
   use kinds, only: wp
   use model, only: n_dof, n_joint, restraint_t, stop_curve_t, form_table, joint_partner
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
      !> each switching function's joint, side (+1 lower, -1 upper) and
      !! threshold angle (rad): g = side (delta - threshold)
      integer, allocatable :: switch_joint(:), switch_side(:)
      real(wp), allocatable :: switch_angle(:)
   contains
      procedure :: add_forces => stops_add_forces
      procedure :: switches => stops_switches
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
      call stop_thresholds(e)
      e%n_switch = size(e%switch_angle)
   end function joint_stops_effect

   !> Issue 15: the relative angles at which the torque of a joint's stop
   !! changes its slope (see the module's note), for the joints whose
   !! restraint can act.
   subroutine stop_thresholds(e)
      type(joint_stops_t), intent(inout) :: e
      integer :: n, i
      allocate (e%switch_joint(0), e%switch_side(0), e%switch_angle(0))
      do n = 1, size(e%joints)
         i = e%joints(n)
         associate (r => e%restraint(i))
            ! figure 9: the torque acts beyond omega and Omega (D-3)
            call add_side(i, 1, r%lower, r%curve_lower, r%form == form_table)
            call add_side(i, -1, r%upper, r%curve_upper, r%form == form_table)
         end associate
      end do
   contains
      subroutine add_side(i, side, stop_angle, curve, tabulated)
         integer, intent(in) :: i, side
         real(wp), intent(in) :: stop_angle
         type(stop_curve_t), intent(in) :: curve
         logical, intent(in) :: tabulated
         integer :: k, n_inner
         n_inner = 0
         ! the curve's inner points (D-3: linear between points, the last
         ! interval extrapolated, so its last point is no kink)
         if (tabulated) n_inner = max(0, size(curve%depth) - 2)
         e%switch_joint = [e%switch_joint, spread(i, 1, 1 + n_inner)]
         e%switch_side = [e%switch_side, spread(side, 1, 1 + n_inner)]
         e%switch_angle = [e%switch_angle, stop_angle]
         do k = 2, n_inner + 1
            e%switch_angle = [e%switch_angle, stop_angle - side*curve%depth(k)]
         end do
      end subroutine add_side
   end subroutine stop_thresholds

   !> Issue 15: g = side (delta - threshold) for every stop and curve point
   !! (rad), negative beyond it.
   pure subroutine stops_switches(this, st, extra, aux, g)
      class(joint_stops_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      integer :: q, i
      associate (u1 => size(extra) + size(aux))
      end associate
      do q = 1, this%n_switch
         i = this%switch_joint(q)
         g(q) = real(this%switch_side(q), wp)*((st%z(i) - st%z(joint_partner(i))) - this%switch_angle(q))
      end do
   end subroutine stops_switches

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
