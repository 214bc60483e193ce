!> Report C.4.d, the seat forces S_1..S_10: the effect of the representation
!! the deck chooses (*SEAT FORM; docs/seat.md). A deck without a seat builds
!! none, so no seat code runs.
module seat_forces
   use kinds, only: wp
   use model, only: model_t, n_dof, seat_springs, seat_rigid_beam, seat_beams
   use effect_base, only: effect_t
   use seat_springs, only: seat_springs_effect
   use seat_rigid_beam, only: seat_rigid_beam_effect
   use seat_beams, only: seat_beams_effect
   implicit none
   private

   public :: seat_effect

contains

   !> The seat of model m for an occupant starting at z0 (unallocated for FORM = NONE).
   function seat_effect(m, z0) result(e)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: z0(n_dof)
      class(effect_t), allocatable :: e
      select case (m%seat%form)
      case (seat_springs)
         allocate (e, source=seat_springs_effect(m%seat, m%body, m%environment%gravity, z0, m%vehicle%phi0))
      case (seat_rigid_beam)
         allocate (e, source=seat_rigid_beam_effect(m%seat, m%body, m%environment%gravity, z0, m%vehicle%phi0))
      case (seat_beams)
         allocate (e, source=seat_beams_effect(m%seat, m%body))
      end select
   end function seat_effect
end module seat_forces
