!> A list of effects of different types: an occupant's scene (effect_factory).
module effect_slots
   use effect_base, only: effect_t
   implicit none
   private

   public :: effect_slot_t

   !> An effect in a list.
   type :: effect_slot_t
      class(effect_t), allocatable :: e
   end type effect_slot_t
end module effect_slots
