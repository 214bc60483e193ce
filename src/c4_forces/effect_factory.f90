!> The scene (report C.4): the effects an occupant's deck calls for, built
!! once per run, in the order of the terms of b = C - G + J + S + B + Q.
!! An effect the deck does not call for is not built, so it costs nothing
!! (docs/architecture.md, rule 2). Adding an effect is one line here, and
!! one more for its parameter table (scene_parameter_tables), which the
!! listing prints.
module effect_factory
   use kinds, only: wp
   use model, only: model_t, n_joint, n_dof, seat_none, nbelt_lap, nbelt_torso, coupling_all
   use preliminary, only: body_constants_t
   use effect_base, only: effect_t
   use effect_slots, only: effect_slot_t
   use centrifugal, only: centrifugal_effect
   use gravity, only: gravity_effect
   use joint_elasticity, only: joint_elasticity_effect
   use joint_friction, only: joint_friction_effect
   use joint_stops, only: joint_stops_effect
   use joint_dislocation, only: joint_dislocation_effect
   use joint_restraints, only: restraint_is_active
   use seat_forces, only: seat_effect
   use belt_forces, only: belt_effect, belt_part_lap, belt_part_torso, belt_part_all
   use contact_scene, only: scene_contact_effects
   use contact_forces, only: contact_pair_effect_t, pair_set_initial
   use seat_geometry, only: rest_state
   use deck_reader, only: deck_t
   use text_table, only: text_table_t, append_table
   use model_tables, only: options_table, body_table, joints_table, injury_table, materials_table, arcs_table, &
      initial_table, pulse_table
   use loading_table, only: loading_curves_table
   use seat_table, only: seat_parameter_table
   use belts_table, only: belts_parameter_table
   use interior_table, only: surfaces_table, contact_pairs_table
   implicit none
   private

   public :: build_effects, scene_parameter_tables

contains

   !> The effects of one occupant whose body constants are bc and whose
   !! initial coordinates are z0 (and rates zdot0; zero when absent).
   subroutine build_effects(m, bc, z0, effects, zdot0)
      type(model_t), intent(in) :: m
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: z0(n_dof)
      real(wp), intent(in), optional :: zdot0(n_dof)
      type(effect_slot_t), allocatable, intent(out) :: effects(:)
      type(contact_pair_effect_t), allocatable :: contacts(:)
      integer :: i

      allocate (effects(0))
      call add(centrifugal_effect(bc))                                                  ! C.4.a
      if (m%environment%gravity > 0.0_wp) call add(gravity_effect(bc, m%body, m%environment%gravity, z0)) ! C.4.b
      if (any(m%joints%k_elastic > 0.0_wp)) call add(joint_elasticity_effect(m%joints%k_elastic, z0)) ! C.4.c
      if (any(m%joints%c_friction > 0.0_wp)) &
         call add(joint_friction_effect(m%joints%c_friction, m%joints%xi, rates0()))    ! C.4.c, D-4a
      if (any([(restraint_is_active(m%joints%restraint(i)), i=1, n_joint)])) &
         call add(joint_stops_effect(m%joints%restraint))                               ! C.4.c, fig. 9
      call add(joint_dislocation_effect(m%joints%restraint))                            ! C.4.c, fig. 10
      if (m%seat%form /= seat_none) call add(seat_effect(m, z0))                        ! C.4.d
      if (m%options%nbelt > 0 .and. m%belts%coupling == coupling_all) call add(belt_effect(m, belt_part_all)) ! C.4.e
      if (nbelt_lap(m%options%nbelt) .and. m%belts%coupling /= coupling_all) call add(belt_effect(m, belt_part_lap))
      if (nbelt_torso(m%options%nbelt) .and. m%belts%coupling /= coupling_all) call add(belt_effect(m, belt_part_torso))
      contacts = scene_contact_effects(m)                                               ! C.4.f, one per pair
      do i = 1, size(contacts)
         call pair_set_initial(contacts(i), rest_state(z0, m%vehicle%phi0))             ! D-C26
         call add(contacts(i))
      end do
   contains
      function rates0() result(r)
         real(wp) :: r(n_dof)
         r = 0.0_wp
         if (present(zdot0)) r = zdot0
      end function rates0

      subroutine add(e)
         class(effect_t), intent(in) :: e
         type(effect_slot_t), allocatable :: longer(:)
         integer :: k
         allocate (longer(size(effects) + 1))
         do k = 1, size(effects)
            call move_alloc(effects(k)%e, longer(k)%e)
         end do
         allocate (longer(size(longer))%e, source=e)
         call move_alloc(longer, effects)
      end subroutine add
   end subroutine build_effects

   !> The parameter tables of the scene a deck (read into deck, built into
   !! m) describes, in the listing's order: the model's sections
   !! (model_tables) and each subsystem's, declared beside its code. A
   !! subsystem the deck leaves out gives a table without lines.
   function scene_parameter_tables(m, deck) result(tables)
      type(model_t), intent(in) :: m
      type(deck_t), intent(in) :: deck
      type(text_table_t), allocatable :: tables(:)
      allocate (tables(0))
      call append_table(tables, options_table(m))
      call append_table(tables, body_table(m))
      call append_table(tables, joints_table(m))                ! C.4.c
      call append_table(tables, injury_table(m))
      call append_table(tables, materials_table(m))
      call append_table(tables, loading_curves_table(m))        ! C.4.e, f
      call append_table(tables, seat_parameter_table(m, deck))  ! C.4.d
      call append_table(tables, belts_parameter_table(m))       ! C.4.e
      call append_table(tables, surfaces_table(m))              ! C.4.f
      call append_table(tables, contact_pairs_table(m))
      call append_table(tables, arcs_table(m))
      call append_table(tables, initial_table(m))
      call append_table(tables, pulse_table(m))
   end function scene_parameter_tables
end module effect_factory
