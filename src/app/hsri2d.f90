!> hsri2d: read card decks, run the simulation, write the listing (and
!! the HDF5 time histories). The only place that prints errors and chooses
!! the exit status (docs/usage.md).
program hsri2d
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use error_handling, only: error_t, exit_ok, exit_io, exit_deck, exit_numerical, error_category_name
   use text_io, only: string_t, append_string
   use command_line, only: options_t, parse_command_line, usage_text, builtin_deck_name
   use deck_reader, only: deck_t, deck_init, deck_add_file, deck_add_lines, deck_finish
   use deck_doc, only: write_deck_format
   use default_deck, only: default_deck_lines
   use model_builder, only: build_model
   use model, only: model_t
   use simulation, only: run_result_t, run_simulation
   use listing, only: listing_t
   use run_report, only: write_listing
   use history_sink, only: history_sink_t, history_sink_open
   use version_info, only: hsri2d_version
   implicit none

   interface
      !> C's exit(): ends with a status and no message (Fortran STOP prints one).
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   type(options_t) :: opts
   type(error_t) :: err, run_err, io_err
   type(deck_t) :: deck
   type(model_t) :: m
   type(run_result_t) :: res
   type(listing_t) :: lst
   type(history_sink_t) :: h5
   type(string_t), allocatable :: builtin(:)
   integer :: i, unit, ios
   character(len=256) :: msg

   call parse_command_line(opts, err)
   if (err%failed()) call quit(err)
   if (opts%help) then
      write (output_unit, '(a)') usage_text()
      call finish(exit_ok)
   end if
   if (opts%version) then
      write (output_unit, '(a)') 'hsri2d '//hsri2d_version
      call finish(exit_ok)
   end if
   if (opts%deck_format) then
      call write_deck_format(output_unit)
      call finish(exit_ok)
   end if
   builtin = default_deck_lines()
   if (opts%print_default_deck) then
      do i = 1, size(builtin)
         write (output_unit, '(a)') builtin(i)%s
      end do
      call finish(exit_ok)
   end if

   ! C.1: read every deck, then check the whole
   call deck_init(deck)
   if (size(opts%decks) == 0) call append_string(opts%decks, builtin_deck_name)
   do i = 1, size(opts%decks)
      if (opts%decks(i)%s == builtin_deck_name) then
         call deck_add_lines(deck, builtin_deck_name, '', builtin, err)
      else
         call deck_add_file(deck, opts%decks(i)%s, err)
      end if
   end do
   if (err%code /= exit_io) call deck_finish(deck, err)
   if (.not. err%failed()) call build_model(deck, m, err)
   if (err%failed()) call quit(err)
   if (opts%check_only) then
      write (output_unit, '(a)') 'hsri2d: the deck is valid'
      call finish(exit_ok)
   end if

   ! outputs
   unit = output_unit
   if (len(opts%listing_file) > 0) then
      open (newunit=unit, file=opts%listing_file, status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         err%code = exit_io
         err%message = opts%listing_file//': cannot write the listing: '//trim(msg)
         call quit(err)
      end if
   end if
   if (len(opts%h5_file) > 0) then
      call history_sink_open(h5, opts%h5_file, m%title, deck_text(deck), err)
      if (err%failed()) call quit(err)
   end if

   ! C.2-C.7
   if (len(opts%h5_file) > 0) then
      call run_simulation(m, res, run_err, h5)
   else
      call run_simulation(m, res, run_err)
   end if
   call lst%start(unit, 'HSRI-2D '//hsri2d_version, m%title)
   call write_listing(lst, deck, m, res, hsri2d_version)
   if (len(opts%h5_file) > 0) call h5%close(io_err)
   if (lst%io_status /= 0) then
      io_err%code = exit_io
      io_err%message = 'cannot write the listing (error '//trim(itoa_local(lst%io_status))//')'
   end if
   if (unit /= output_unit) close (unit)
   if (run_err%failed()) call quit(run_err)
   if (io_err%failed()) call quit(io_err)
   call finish(exit_ok)

contains

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

   function itoa_local(n) result(s)
      integer, intent(in) :: n
      character(len=16) :: s
      write (s, '(i0)') n
   end function itoa_local

   !> Print an error report on standard error and exit with its status.
   subroutine quit(e)
      type(error_t), intent(in) :: e
      integer :: code
      code = e%code
      write (error_unit, '(a)') 'hsri2d: '//error_category_name(code)//':'
      write (error_unit, '(a)') e%message
      if (code == exit_deck) write (error_unit, '(a)') 'hsri2d: see docs/deck-format.md or hsri2d --deck-format'
      if (code == exit_numerical) write (error_unit, '(a)') 'hsri2d: the listing holds the run up to the failure'
      call finish(code)
   end subroutine quit

   subroutine finish(code)
      integer, intent(in) :: code
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine finish
end program hsri2d
