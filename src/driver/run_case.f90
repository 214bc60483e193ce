!> One case, deck files to listing and HDF5 file, as a library call: the
!! pipeline the program runs, and what C.8's repeated runs, a sweep and the
!! tests call. The program (src/app/hsri2d.f90) only parses its command
!! line, calls run_case and turns the error into an exit status.
module run_case_mod
   use, intrinsic :: iso_fortran_env, only: output_unit
   use error_handling, only: error_t, error_set, exit_io
   use strings, only: itoa
   use text_io, only: string_t
   use deck_reader, only: deck_t, deck_init, deck_add_file, deck_add_lines, deck_finish
   use default_deck, only: default_deck_lines
   use model_builder, only: build_model
   use model, only: model_t
   use simulation, only: run_simulation
   use run_summary, only: run_summary_t
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_base, only: event_t
   use run_report, only: listing_sink_t, listing_sink_start
   use history_sink, only: history_sink_t, history_sink_open
   use version_info, only: hsri2d_version
   implicit none
   private

   public :: run_request_t, run_case, read_case_deck, builtin_deck_name

   !> The outputs of a case: the listing, and the HDF5 file when asked for.
   type, extends(output_sink_t) :: case_sink_t
      type(listing_sink_t) :: listing
      type(history_sink_t) :: h5
      logical :: with_h5 = .false.
   contains
      procedure :: begin => case_begin
      procedure :: record => case_record
      procedure :: event => case_event
      procedure :: finish => case_finish
   end type case_sink_t

   !> The name that stands for the built-in default deck.
   character(len=*), parameter :: builtin_deck_name = '@default'

   !> What to run and where the results go.
   type :: run_request_t
      type(string_t), allocatable :: decks(:)        !< in order; builtin_deck_name = the built-in deck
      character(len=:), allocatable :: listing_file  !< '' = the listing goes to listing_unit
      integer :: listing_unit = output_unit          !< used when listing_file is ''
      character(len=:), allocatable :: h5_file       !< '' = no HDF5 file
      logical :: check_only = .false.                !< read and check the decks, run nothing
   end type run_request_t

contains

   !> Read the decks of a request (C.1) into deck and model; every problem
   !! found is appended to err.
   subroutine read_case_deck(req, deck, m, err)
      type(run_request_t), intent(in) :: req
      type(deck_t), intent(out) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      integer :: i
      call deck_init(deck)
      if (size(req%decks) == 0) then
         call deck_add_lines(deck, builtin_deck_name, '', default_deck_lines(), err)
      end if
      do i = 1, size(req%decks)
         if (req%decks(i)%s == builtin_deck_name) then
            call deck_add_lines(deck, builtin_deck_name, '', default_deck_lines(), err)
         else
            call deck_add_file(deck, req%decks(i)%s, err)
         end if
      end do
      if (err%code /= exit_io) call deck_finish(deck, err)
      if (.not. err%failed()) call build_model(deck, m, err)
   end subroutine read_case_deck

   !> Run one case: read the decks, simulate (C.2-C.7), write the listing
   !! and the HDF5 file. err says what went wrong, its code being the exit
   !! status (docs/usage.md); a numerical failure still writes both outputs
   !! up to the failure. warnings: what the user should know that is not an
   !! error (the listing shows them too).
   subroutine run_case(req, err, summary, warnings)
      type(run_request_t), intent(in) :: req
      type(error_t), intent(inout) :: err
      type(run_summary_t), intent(out), optional :: summary
      type(string_t), allocatable, intent(out), optional :: warnings(:)
      type(deck_t) :: deck
      type(model_t) :: m
      type(run_summary_t) :: res
      type(error_t) :: run_err, io_err
      type(case_sink_t) :: sink
      integer :: unit, ios
      character(len=256) :: msg

      call read_case_deck(req, deck, m, err)
      if (present(warnings) .and. allocated(m%warnings)) warnings = m%warnings
      if (err%failed() .or. req%check_only) return

      unit = req%listing_unit
      if (len(req%listing_file) > 0) then
         open (newunit=unit, file=req%listing_file, status='replace', action='write', iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call error_set(err, exit_io, req%listing_file//': cannot write the listing: '//trim(msg))
            return
         end if
      end if
      sink%with_h5 = len(req%h5_file) > 0
      if (sink%with_h5) then
         call history_sink_open(sink%h5, req%h5_file, m%title, deck_text(deck), err)
         if (err%failed()) return
      end if
      call listing_sink_start(sink%listing, unit, deck, m, hsri2d_version)
      call run_simulation(m, res, run_err, sink)
      if (sink%with_h5) call sink%h5%close(io_err)
      if (sink%listing%lst%io_status /= 0) call error_set(io_err, exit_io, 'cannot write the listing (error ' &
                                                          //itoa(sink%listing%lst%io_status)//')')
      if (unit /= req%listing_unit) close (unit)
      if (run_err%failed()) then
         call error_set(err, run_err%code, run_err%message)
      else if (io_err%failed()) then
         call error_set(err, io_err%code, io_err%message)
      end if
      if (present(summary)) summary = res
   end subroutine run_case

   subroutine case_begin(this, sys, reg, first, err)
      class(case_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      call this%listing%begin(sys, reg, first, err)
      if (this%with_h5) call this%h5%begin(sys, reg, first, err)
   end subroutine case_begin

   subroutine case_record(this, frame, err)
      class(case_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      call this%listing%record(frame, err)
      if (this%with_h5) call this%h5%record(frame, err)
   end subroutine case_record

   subroutine case_event(this, e, err)
      class(case_sink_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      call this%listing%event(e, err)
      if (this%with_h5) call this%h5%event(e, err)
   end subroutine case_event

   !> The listing's summary is written even when the HDF5 file failed.
   subroutine case_finish(this, summary, err)
      class(case_sink_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      type(error_t) :: listing_err
      call this%listing%finish(summary, listing_err)
      if (this%with_h5) call this%h5%finish(summary, err)
      if (listing_err%failed() .and. .not. err%failed()) err = listing_err
   end subroutine case_finish

   !> The deck's card images, for the HDF5 file.
   function deck_text(d) result(lines)
      type(deck_t), intent(in) :: d
      character(len=80), allocatable :: lines(:)
      integer :: k
      allocate (lines(d%n_echo))
      do k = 1, d%n_echo
         lines(k) = d%echo(k)%text
      end do
   end function deck_text
end module run_case_mod
