!> Where the driver sends output as the run proceeds (records at the print
!! interval, injury events), so that a file can be written incrementally.
!! The HDF5 history file is one such sink; a run without one uses none.
module output_sink
   use output_calc, only: output_record_t
   use joint_injury, only: injury_event_t
   use error_handling, only: error_t
   implicit none
   private

   public :: output_sink_t

   type, abstract :: output_sink_t
   contains
      procedure(record_interface), deferred :: record
      procedure(event_interface), deferred :: event
   end type output_sink_t

   abstract interface
      subroutine record_interface(this, r, err)
         import :: output_sink_t, output_record_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(output_record_t), intent(in) :: r
         type(error_t), intent(inout) :: err
      end subroutine record_interface

      subroutine event_interface(this, e, err)
         import :: output_sink_t, injury_event_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(injury_event_t), intent(in) :: e
         type(error_t), intent(inout) :: err
      end subroutine event_interface
   end interface
end module output_sink
