!> The output sinks of a run, any number of them (none required): the
!! listing, the HDF5 file, a frame collector, a results row. The run does
!! not own them: the list points at the caller's sinks, which must outlive
!! the run (declare them `target`). One error is shared by all: the first
!! sink that fails ends the run, no record or event is sent after it, and
!! every sink still begins and finishes, seeing that error (a sink decides
!! what it can still write: the listing its summary, docs/usage.md).
module sink_list
   use error_handling, only: error_t
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use effect_events, only: event_t
   use run_summary, only: run_summary_t
   use equations_of_motion, only: crash_system_t
   implicit none
   private

   public :: sink_list_t

   type :: sink_ref_t
      class(output_sink_t), pointer :: s => null()
   end type sink_ref_t

   type :: sink_list_t
      private
      type(sink_ref_t), allocatable :: items(:)
      integer :: n = 0
      !> what the sinks reported: an output error ends the run
      type(error_t), public :: err
   contains
      procedure :: add => list_add
      procedure :: size => list_size
      procedure :: failed => list_failed
      procedure :: begin => list_begin
      procedure :: record => list_record
      procedure :: event => list_event
      procedure :: finish => list_finish
   end type sink_list_t

contains

   !> One more sink, after those already in the list (they are called in
   !! that order).
   subroutine list_add(this, sink)
      class(sink_list_t), intent(inout) :: this
      class(output_sink_t), intent(in), target :: sink
      type(sink_ref_t), allocatable :: longer(:)
      if (.not. allocated(this%items)) allocate (this%items(2))
      if (this%n == size(this%items)) then
         allocate (longer(2*this%n))
         longer(1:this%n) = this%items(1:this%n)
         call move_alloc(longer, this%items)
      end if
      this%n = this%n + 1
      this%items(this%n)%s => sink
   end subroutine list_add

   pure integer function list_size(this)
      class(sink_list_t), intent(in) :: this
      list_size = this%n
   end function list_size

   pure logical function list_failed(this)
      class(sink_list_t), intent(in) :: this
      list_failed = this%err%failed()
   end function list_failed

   subroutine list_begin(this, sys, reg, first)
      class(sink_list_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      integer :: k
      do k = 1, this%n
         call this%items(k)%s%begin(sys, reg, first, this%err)
      end do
   end subroutine list_begin

   subroutine list_record(this, frame)
      class(sink_list_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      integer :: k
      do k = 1, this%n
         if (this%err%failed()) return
         call this%items(k)%s%record(frame, this%err)
      end do
   end subroutine list_record

   subroutine list_event(this, e)
      class(sink_list_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      integer :: k
      do k = 1, this%n
         if (this%err%failed()) return
         call this%items(k)%s%event(e, this%err)
      end do
   end subroutine list_event

   subroutine list_finish(this, summary)
      class(sink_list_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      integer :: k
      do k = 1, this%n
         call this%items(k)%s%finish(summary, this%err)
      end do
   end subroutine list_finish
end module sink_list
