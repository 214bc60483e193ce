!> An output sink that keeps every frame in memory, with the registry to
!! read them by series name: for the tests and for callers of the library
!! (C.8's repeated runs) that want the time histories as arrays. Its memory
!! grows with the number of print times, so the program itself never uses
!! it.
module frame_collector
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_io
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use run_summary, only: run_summary_t
   implicit none
   private

   public :: frame_collector_t

   type, extends(output_sink_t) :: frame_collector_t
      type(output_registry_t) :: reg
      type(output_frame_t), allocatable :: frames(:)
      integer :: n = 0
   contains
      procedure :: begin => collector_begin
      procedure :: record => collector_record
      procedure :: event => collector_event
      procedure :: finish => collector_finish
      procedure :: values => collector_values
      procedure :: column => collector_column
   end type frame_collector_t

contains

   subroutine collector_begin(this, sys, reg, first, err)
      class(frame_collector_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      associate (u1 => size(sys%occupants), u2 => first%t, u3 => err%code)
      end associate
      this%reg = reg
      this%n = 0
      if (allocated(this%frames)) deallocate (this%frames)
      allocate (this%frames(64))
   end subroutine collector_begin

   subroutine collector_record(this, frame, err)
      class(frame_collector_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      type(output_frame_t), allocatable :: longer(:)
      integer :: k
      if (.not. allocated(this%frames)) then
         call error_set(err, exit_io, 'the frame collector received a record before the run began')
         return
      end if
      if (this%n == size(this%frames)) then
         allocate (longer(2*size(this%frames)))
         do k = 1, this%n
            call move_alloc(this%frames(k)%v, longer(k)%v)
            longer(k)%t = this%frames(k)%t
         end do
         call move_alloc(longer, this%frames)
      end if
      this%n = this%n + 1
      this%frames(this%n) = frame
   end subroutine collector_record

   subroutine collector_event(this, e, err)
      class(frame_collector_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      associate (u1 => this%n, u2 => e%t, u3 => err%code)
      end associate
   end subroutine collector_event

   subroutine collector_finish(this, summary, err)
      class(frame_collector_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      associate (u1 => this%n, u2 => summary%t_end, u3 => err%code)
      end associate
   end subroutine collector_finish

   !> The values of series `name` in frame k (an empty array when there is
   !! no such series).
   function collector_values(this, name, k) result(v)
      class(frame_collector_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: k
      real(wp), allocatable :: v(:)
      integer :: s
      s = this%reg%find(name)
      if (s == 0) then
         allocate (v(0))
         return
      end if
      associate (ser => this%reg%series(s))
         v = this%frames(k)%v(ser%offset + 1:ser%offset + size(ser%col))
      end associate
   end function collector_values

   !> Column c of series `name` over all frames.
   function collector_column(this, name, c) result(v)
      class(frame_collector_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: c
      real(wp), allocatable :: v(:)
      integer :: s, k
      s = this%reg%find(name)
      allocate (v(this%n))
      v = 0.0_wp
      if (s == 0) return
      do k = 1, this%n
         v(k) = this%frames(k)%v(this%reg%series(s)%offset + c)
      end do
   end function collector_column
end module frame_collector
