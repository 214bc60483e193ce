!> Where the driver sends output as the run proceeds, so that every output
!! is written as the run goes and nothing grows with its length: `begin`
!! once the scene is built (the registry, the occupants and the first
!! frame known), `record` at every print time, `event` when one happens,
!! `finish` with the summary. The listing and the HDF5 file are sinks; a
!! run without output uses none; tests collect frames with one.
module output_sink
   use error_handling, only: error_t
   use output_registry, only: output_registry_t, output_frame_t
   use effect_events, only: event_t
   use run_summary, only: run_summary_t
   use equations_of_motion, only: crash_system_t
   implicit none
   private

   public :: output_sink_t

   type, abstract :: output_sink_t
   contains
      procedure(begin_interface), deferred :: begin
      procedure(record_interface), deferred :: record
      procedure(event_interface), deferred :: event
      procedure(finish_interface), deferred :: finish
   end type output_sink_t

   abstract interface
      !> The run is about to start: sys is the assembled system, reg the
      !! series, first the frame at t = 0 (also passed to record).
      subroutine begin_interface(this, sys, reg, first, err)
         import :: output_sink_t, crash_system_t, output_registry_t, output_frame_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(crash_system_t), intent(in) :: sys
         type(output_registry_t), intent(in) :: reg
         type(output_frame_t), intent(in) :: first
         type(error_t), intent(inout) :: err
      end subroutine begin_interface

      subroutine record_interface(this, frame, err)
         import :: output_sink_t, output_frame_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(output_frame_t), intent(in) :: frame
         type(error_t), intent(inout) :: err
      end subroutine record_interface

      subroutine event_interface(this, e, err)
         import :: output_sink_t, event_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(event_t), intent(in) :: e
         type(error_t), intent(inout) :: err
      end subroutine event_interface

      !> The run has ended (or failed): its summary.
      subroutine finish_interface(this, summary, err)
         import :: output_sink_t, run_summary_t, error_t
         class(output_sink_t), intent(inout) :: this
         type(run_summary_t), intent(in) :: summary
         type(error_t), intent(inout) :: err
      end subroutine finish_interface
   end interface
end module output_sink
