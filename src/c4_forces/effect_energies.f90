!> The kinds of energy an effect reports (C.6; effect_t's energy): for the
!! energy balance, the registry's energy series and the listing.
module effect_energies
   implicit none
   private

   public :: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds, energy_kind_name

   !> Kinds of energy an effect reports (C.6): stored in a conservative
   !! force, dissipated by it, supplied to the body from outside.
   integer, parameter :: energy_stored = 1, energy_dissipated = 2, energy_supplied = 3
   integer, parameter :: n_energy_kinds = 3
   character(len=10), parameter :: energy_kind_name(n_energy_kinds) = [character(len=10) :: &
      'stored', 'dissipated', 'supplied']
end module effect_energies
