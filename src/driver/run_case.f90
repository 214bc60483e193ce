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
   use simulation, only: run_result_t, run_simulation
   use listing, only: listing_t
   use run_report, only: write_listing
   use history_sink, only: history_sink_t, history_sink_open
   use version_info, only: hsri2d_version
   implicit none
   private

   public :: run_request_t, run_case, read_case_deck, builtin_deck_name

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
   !! up to the failure.
   subroutine run_case(req, err, result)
      type(run_request_t), intent(in) :: req
      type(error_t), intent(inout) :: err
      type(run_result_t), intent(out), optional :: result
      type(deck_t) :: deck
      type(model_t) :: m
      type(run_result_t) :: res
      type(error_t) :: run_err, io_err
      type(listing_t) :: lst
      type(history_sink_t) :: h5
      integer :: unit, ios
      character(len=256) :: msg
      logical :: with_h5

      call read_case_deck(req, deck, m, err)
      if (err%failed() .or. req%check_only) return

      unit = req%listing_unit
      if (len(req%listing_file) > 0) then
         open (newunit=unit, file=req%listing_file, status='replace', action='write', iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call error_set(err, exit_io, req%listing_file//': cannot write the listing: '//trim(msg))
            return
         end if
      end if
      with_h5 = len(req%h5_file) > 0
      if (with_h5) then
         call history_sink_open(h5, req%h5_file, m%title, deck_text(deck), err)
         if (err%failed()) return
         call run_simulation(m, res, run_err, h5)
      else
         call run_simulation(m, res, run_err)
      end if
      call lst%start(unit, 'HSRI-2D '//hsri2d_version, m%title)
      call write_listing(lst, deck, m, res, hsri2d_version)
      if (with_h5) call h5%close(io_err)
      if (lst%io_status /= 0) call error_set(io_err, exit_io, 'cannot write the listing (error ' &
                                             //itoa(lst%io_status)//')')
      if (unit /= req%listing_unit) close (unit)
      if (run_err%failed()) then
         call error_set(err, run_err%code, run_err%message)
      else if (io_err%failed()) then
         call error_set(err, io_err%code, io_err%message)
      end if
      if (present(result)) result = res
   end subroutine run_case

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
