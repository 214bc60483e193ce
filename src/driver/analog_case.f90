!> A deck with *ANALOG: report Section D's two-occupant analog instead of
!! the occupant simulation (docs/analog.md). Every case of the deck solved
!! (d_analog), its listing written in the program's line-printer style (the
!! run's banner, the deck echoed, per case its parameters, events and time
!! history, then a summary of the cases), and the time histories in an
!! HDF5 file when asked for.
module analog_case
   use kinds, only: wp
   use strings, only: itoa
   use error_handling, only: error_t, error_set
   use text_io, only: string_t
   use text_table, only: text_table_t
   use deck_reader, only: deck_t
   use analog_model, only: analog_case_t, analog_solution_t, analog_solve, front_state, rear_state, separation
   use analog_input, only: analog_cases, analog_title
   use analog_report, only: analog_parameter_table, analog_event_table, analog_history_tables, &
      analog_summary_table, analog_history_times
   use listing, only: listing_t
   use output_files, only: output_file_t, deliver_outputs
   use history_h5, only: history_file_t
   use run_report, only: write_deck_echo
   use version_info, only: hsri2d_version
   implicit none
   private

   public :: run_analog

contains

   !> Solve every case of the analog deck and write the listing
   !! (listing_file, '' = standard output) and the HDF5 file (h5_file, '' =
   !! none), whose paths the caller has checked. deck_lines: its card
   !! images, for the HDF5 file. solutions: the cases solved (a study's run
   !! that keeps its outputs judges them without solving again).
   subroutine run_analog(deck, deck_lines, listing_file, h5_file, err, solutions)
      type(deck_t), intent(in) :: deck
      character(len=80), intent(in) :: deck_lines(:)
      character(len=*), intent(in) :: listing_file, h5_file
      type(error_t), intent(inout) :: err
      type(analog_solution_t), allocatable, intent(out), optional :: solutions(:)
      type(analog_case_t), allocatable :: cases(:)
      type(analog_solution_t), allocatable :: sols(:)
      type(listing_t) :: lst
      type(output_file_t) :: h5_out
      type(history_file_t) :: h5
      type(error_t) :: io_err
      integer :: k

      ! (allocated first: gfortran's -Wuninitialized reads the descriptor of the assignment)
      allocate (cases(0))
      cases = analog_cases(deck)
      allocate (sols(size(cases)))
      do k = 1, size(cases)
         sols(k) = analog_solve(cases(k))
      end do
      if (present(solutions)) solutions = sols

      call lst%create_text(listing_file, 'listing', err)
      if (err%failed()) return
      if (len(h5_file) > 0) then
         call h5_out%reserve(h5_file, 'HDF5 file', io_err)
         if (.not. io_err%failed()) &
            call h5%open(h5_out%writing_path(), analog_title(deck), deck_lines, io_err)
         if (.not. io_err%failed()) call write_h5(h5, sols, io_err)
         if (.not. io_err%failed()) call h5%close(io_err)
         if (io_err%failed()) then
            call deliver_outputs(io_err, lst, h5_out)
            call error_set(err, io_err%code, io_err%message)
            return
         end if
      end if
      call write_listing(lst, deck, sols)
      call lst%flush(io_err)
      if (len(h5_file) > 0) then
         call deliver_outputs(io_err, lst, h5_out)
      else
         call deliver_outputs(io_err, lst)
      end if
      if (io_err%failed()) call error_set(err, io_err%code, io_err%message)
   end subroutine run_analog

   !> The listing: the banner, the deck, each case, the summary.
   subroutine write_listing(lst, deck, sols)
      type(listing_t), intent(inout) :: lst
      type(deck_t), intent(in) :: deck
      type(analog_solution_t), intent(in) :: sols(:)
      type(text_table_t), allocatable :: history(:)
      integer :: k, i
      allocate (history(0))
      call lst%start('HSRI-2D '//hsri2d_version, analog_title(deck))
      call lst%new_page('RUN')
      call lst%put(' HSRI-2D '//hsri2d_version//'  the two-occupant analog of Section D')
      call lst%put(' after J. M. Becker and D. H. Robbins, Mathematical Simulation of Collision, I,')
      call lst%put(' Highway Safety Research Institute, The University of Michigan (section D, "A simple analog')
      call lst%put(' to collision between auto occupants")')
      call lst%blank()
      call lst%put(' TITLE   '//analog_title(deck), indent=9)
      do i = 1, size(deck%source_name)
         call lst%put(' DECK    '//deck%source_name(i)%s, indent=9)
      end do
      call lst%put(' CASES   '//itoa(size(sols)))
      call lst%put(' UNITS   inch, pound force, second; angles in degrees in the listing')
      call lst%put(' MODEL   closed form, phase by phase (docs/analog.md); the report''s errata SD-1 to SD-8 ' &
                   //'(docs/errata.md)', indent=9)
      call write_deck_echo(lst, deck)
      do k = 1, size(sols)
         call lst%new_page('ANALOG OF SECTION D: CASE '//itoa(k))
         call lst%table(analog_parameter_table(sols(k), k))
         call lst%table(analog_event_table(sols(k), k))
         history = analog_history_tables(sols(k), k)
         call lst%new_page('ANALOG OF SECTION D: CASE '//itoa(k)//', TIME HISTORY')
         do i = 1, size(history)
            call lst%table(history(i))
         end do
      end do
      call lst%new_page('ANALOG OF SECTION D: SUMMARY')
      call lst%table(analog_summary_table(sols))
   end subroutine write_listing

   !> Each case's time history at the listing's times, /analog/case_N:
   !! t, theta1, theta1', theta2, theta2' (rad, rad/s), the separation (in).
   subroutine write_h5(h5, sols, err)
      type(history_file_t), intent(inout) :: h5
      type(analog_solution_t), intent(in) :: sols(:)
      type(error_t), intent(inout) :: err
      real(wp), allocatable :: times(:)
      real(wp) :: th1, r1, th2, r2
      integer :: k, i, id
      allocate (times(0))
      do k = 1, size(sols)
         call h5%add_series('analog/case_'//itoa(k), [character(len=10) :: 't', 'theta1', 'theta1dot', 'theta2', &
                            'theta2dot', 'separation'], [character(len=5) :: 's', 'rad', 'rad/s', 'rad', 'rad/s', &
                            'in'], 'Section D analog, case '//itoa(k)//' (docs/analog.md)', id, err)
         if (err%failed()) return
         times = analog_history_times(sols(k)%c%t_max)
         do i = 1, size(times)
            call front_state(sols(k), times(i), th1, r1)
            call rear_state(sols(k)%c, sols(k)%omega0, times(i), th2, r2)
            call h5%append(id, [times(i), th1, r1, th2, r2, separation(sols(k), times(i))], err)
            if (err%failed()) return
         end do
      end do
   end subroutine write_h5
end module analog_case
