!> A largest value an effect keeps over the accepted steps (effect_t's
!! peaks): the listing's summary lists it, /summary/maxima has a column.
module effect_peaks
   use kinds, only: wp
   implicit none
   private

   public :: effect_peak_t

   !> A largest value over the accepted steps that an effect keeps (in its
   !! memory, changed in accept) and reports at the end of the run: the
   !! summary lists it and /summary/maxima of the HDF5 file has a column
   !! for it.
   type :: effect_peak_t
      character(len=19) :: name = ' '    !< the column: <effect>_<quantity>, lower case
      character(len=40) :: title = ' '   !< the effect's (for the listing)
      character(len=24) :: label = ' '   !< the quantity, for the listing
      character(len=8) :: unit = ' '
      real(wp) :: value = 0.0_wp
      real(wp) :: t = 0.0_wp             !< when
   end type effect_peak_t
end module effect_peaks
