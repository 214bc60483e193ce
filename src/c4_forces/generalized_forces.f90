!> Report C.4: the generalized force vector b = C - G + J + S + B + Q.
!! The scene - the list of effects a deck calls for - is assembled once;
!! each right-hand-side evaluation walks that list and nothing else, so an
!! effect absent from the deck costs nothing (design.md, rule 2). Seat
!! (C.4.d), belts (C.4.e) and contacts (C.4.f) will join the list as
!! further effect kinds.
module generalized_forces
   use kinds, only: wp, i8
   use model, only: model_t, n_joint, n_dof, n_seg, joint_partner
   use preliminary, only: body_constants_t
   use centrifugal, only: centrifugal_forces
   use gravity, only: gravity_forces
   use joint_torques, only: joint_elastic_torques, joint_friction_torques, joint_stop_torques
   use joint_restraints, only: restraint_is_active
   implicit none
   private

   public :: scene_t, force_counts_t, scene_assemble, generalized_force_vector
   public :: effect_centrifugal, effect_gravity, effect_joint_elastic, effect_joint_friction
   public :: effect_joint_stops, n_effect_kinds, effect_name

   integer, parameter :: effect_centrifugal = 1   !< C.4.a
   integer, parameter :: effect_gravity = 2       !< C.4.b
   integer, parameter :: effect_joint_elastic = 3 !< C.4.c, elasticity
   integer, parameter :: effect_joint_friction = 4 !< C.4.c, Coulomb friction
   integer, parameter :: effect_joint_stops = 5   !< C.4.c, angular restraints
   integer, parameter :: n_effect_kinds = 5
   character(len=20), parameter :: effect_name(n_effect_kinds) = [character(len=20) :: &
      'centrifugal (C.4.a)', 'gravity (C.4.b)', 'joint elasticity', 'joint friction', 'joint stops']

   !> The effects a scene calls for, built once per run (read-only after).
   type :: scene_t
      integer :: n_effects = 0
      integer :: effect(n_effect_kinds) = 0
      integer, allocatable :: elastic_joints(:), friction_joints(:), stop_joints(:)
      real(wp) :: rel0(n_joint) = 0.0_wp   !< initial relative joint angles (spring rest)
      real(wp) :: gravity = 0.0_wp
      !> auxiliary integrated quantities: the work of each friction joint
      integer :: n_aux = 0
   end type scene_t

   !> How many times each effect was evaluated (diagnostics, not physics).
   type :: force_counts_t
      integer(i8) :: evaluations(n_effect_kinds) = 0
   end type force_counts_t

contains

   !> Build the scene from the model: which effects act, on which joints.
   pure subroutine scene_assemble(m, z0, sc)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: z0(n_dof)
      type(scene_t), intent(out) :: sc
      integer :: i
      logical :: elastic(n_joint), friction(n_joint), stops(n_joint), on(n_effect_kinds)

      do i = 1, n_joint
         sc%rel0(i) = z0(i) - z0(joint_partner(i))
         elastic(i) = m%k_elastic(i) > 0.0_wp
         friction(i) = m%c_friction(i) > 0.0_wp
         stops(i) = restraint_is_active(m%restraint(i))
      end do
      allocate (sc%elastic_joints(count(elastic)), sc%friction_joints(count(friction)), &
                sc%stop_joints(count(stops)))
      sc%elastic_joints(:) = pack([(i, i=1, n_joint)], elastic)
      sc%friction_joints(:) = pack([(i, i=1, n_joint)], friction)
      sc%stop_joints(:) = pack([(i, i=1, n_joint)], stops)
      sc%gravity = m%gravity
      sc%n_aux = size(sc%friction_joints)

      ! the order of the list is the order of the terms of b in C.4
      on = .false.
      on(effect_centrifugal) = .true.
      on(effect_gravity) = sc%gravity > 0.0_wp
      on(effect_joint_elastic) = size(sc%elastic_joints) > 0
      on(effect_joint_friction) = size(sc%friction_joints) > 0
      on(effect_joint_stops) = size(sc%stop_joints) > 0
      sc%n_effects = count(on)
      sc%effect(1:sc%n_effects) = pack([(i, i=1, n_effect_kinds)], on)
   end subroutine scene_assemble

   !> b for the state (z, z-dot), and the power dissipated by each friction
   !! joint (size scene%n_aux). Reads the model, writes only b, power and
   !! the counters: trial evaluations change nothing (design.md, rule 1).
   pure subroutine generalized_force_vector(sc, m, bc, c, s, z, zdot, b, power, counts)
      type(scene_t), intent(in) :: sc
      type(model_t), intent(in) :: m
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg), z(n_dof), zdot(n_dof)
      real(wp), intent(out) :: b(n_dof)
      real(wp), intent(out) :: power(:)
      type(force_counts_t), intent(inout) :: counts
      integer :: e, kind

      b = 0.0_wp
      do e = 1, sc%n_effects
         kind = sc%effect(e)
         select case (kind)
         case (effect_centrifugal)
            call centrifugal_forces(bc, c, s, zdot, b)
         case (effect_gravity)
            call gravity_forces(bc, sc%gravity, c, b)
         case (effect_joint_elastic)
            call joint_elastic_torques(sc%elastic_joints, m%k_elastic, sc%rel0, z, b)
         case (effect_joint_friction)
            call joint_friction_torques(sc%friction_joints, m%c_friction, m%xi, zdot, b, power)
         case (effect_joint_stops)
            call joint_stop_torques(sc%stop_joints, m%restraint, z, b)
         end select
         counts%evaluations(kind) = counts%evaluations(kind) + 1
      end do
   end subroutine generalized_force_vector
end module generalized_forces
