!> One run of a study (report C.8: "change certain input parameters or
!! data, and then initiate a new run"): the base deck with the varied
!! fields set (deck_set_field: the deck as a user could have written it,
!! checked as every card is), its model built and checked as every deck's,
!! run to its end (run_loop's run_t, through run_simulation, or write_case
!! when the run's own listing or HDF5 file is kept), and judged: its status
!! and criteria, and whether every criterion with a limit is within it.
!! A study of Section D's analog (*ANALOG) builds no model: each run solves
!! the varied case in closed form (analog_run; docs/analog.md).
!! One run's failure is that run's row, never the study's end.
module study_runs
   use kinds, only: wp
   use error_handling, only: error_t
   use strings, only: num
   use text_io, only: string_t
   use deck_reader, only: deck_t, deck_set_field
   use model, only: model_t
   use model_builder, only: build_model
   use simulation, only: run_simulation, initial_warnings
   use run_case_mod, only: write_case, accuracy_notes, deck_text
   use analog_model, only: analog_case_t, analog_solution_t, analog_solve
   use analog_input, only: analog_cases
   use analog_case, only: run_analog
   use run_summary, only: run_summary_t
   use end_tests, only: end_time, end_injury, end_rest, end_contact
   use study_input, only: study_t
   use study_criteria, only: criterion_index, criterion_value, analog_criterion_index, analog_criterion_value
   use study_table, only: run_row_t, status_completed, status_ended, status_failed, status_invalid
   implicit none
   private

   public :: study_run, study_deck

contains

   !> The deck of a run: base with variable v's field set to x(v). err:
   !! a value its field refuses (located at the card, "(varied)").
   !! written: the values the cards hold (deck units: x rounded to what the
   !! fields' columns hold).
   subroutine study_deck(base, st, x, deck, err, written)
      type(deck_t), intent(in) :: base
      type(study_t), intent(in) :: st
      real(wp), intent(in) :: x(:)
      type(deck_t), intent(out) :: deck
      type(error_t), intent(inout) :: err
      real(wp), intent(out) :: written(:)
      integer :: v
      deck = base
      do v = 1, size(st%vars)
         call deck_set_field(deck, st%vars(v)%gid, st%vars(v)%ic, st%vars(v)%k, x(v), err, written(v))
      end do
   end subroutine study_deck

   !> Run number `run` of the study st of deck base at the values x (deck
   !! units); listing_file, h5_file: the run's own outputs ('' = none).
   subroutine study_run(base, st, run, x, listing_file, h5_file, row)
      type(deck_t), intent(in) :: base
      type(study_t), intent(in) :: st
      integer, intent(in) :: run
      real(wp), intent(in) :: x(:)
      character(len=*), intent(in) :: listing_file, h5_file
      type(run_row_t), intent(out) :: row
      type(deck_t), allocatable :: deck     ! (large: on the heap)
      type(model_t), allocatable :: m
      type(run_summary_t) :: res
      type(error_t) :: err
      type(string_t), allocatable :: notes(:)
      integer :: k, j
      allocate (deck)
      row%run = run
      row%x = x
      row%reason = ''
      ! the values as run: what the cards now hold
      call study_deck(base, st, x, deck, err, row%x)
      if (st%analog) then
         call analog_run(deck, st, listing_file, h5_file, row, err)
         return
      end if
      allocate (m)
      if (.not. err%failed()) call build_model(deck, m, err)
      if (err%failed()) then
         row%status = status_invalid
         row%reason = message_of(err, 'the variation is not a valid deck')
         return
      end if
      m%warnings = [m%warnings, initial_warnings(m)]
      ! the head's excursion is kept only where the study judges by it
      m%options%head_excursion = any(st%crits(:)%word == 'HEADX')
      if (len(listing_file) > 0 .or. len(h5_file) > 0) then
         call write_case(deck, m, listing_file, h5_file, err, res, notes)
      else
         call run_simulation(m, res, err)
      end if
      row%t_end = res%t_end
      select case (res%end_reason)
      case (end_time)
         row%status = status_completed
      case (end_injury, end_rest, end_contact)
         row%status = status_ended
         row%reason = 'ended by the '//end_words(res%end_reason)//' end test (C.7) at t = '//num(res%t_end)//' s'
      case default
         ! end_failure, end_energy: the integration failed (exit 3's message)
         row%status = status_failed
         row%reason = message_of(err, 'the run ended without a result')
         return
      end select
      if (err%failed()) then
         ! the run's own outputs could not be written: the run is not a result
         row%status = status_failed
         row%reason = message_of(err, 'the run''s outputs could not be written')
         return
      end if
      ! what the run says of its own accuracy (a step too large, ...): in
      ! the row, as the program warns of it after a run (nothing silently wrong)
      notes = accuracy_notes(m, res)
      do j = 1, size(notes)
         if (len(row%reason) > 0) row%reason = row%reason//'; '
         row%reason = row%reason//'warning: '//notes(j)%s
      end do
      allocate (row%crit(size(st%crits)))
      row%meets = .true.
      do k = 1, size(st%crits)
         row%crit(k) = criterion_value(res, criterion_index(st%crits(k)%word), st%crits(k)%occupant)
         if (st%crits(k)%has_limit) row%meets = row%meets .and. row%crit(k) <= st%crits(k)%limit
      end do
   end subroutine study_run

   !> A run of a study of Section D's analog (docs/analog.md): the varied
   !! deck's one case solved in closed form (d_analog; no occupant model is
   !! built), judged by the analog's criteria; its own listing and HDF5
   !! file, when kept, those of a plain run of that deck (analog_case).
   !! err: the variation's, from study_deck.
   subroutine analog_run(deck, st, listing_file, h5_file, row, err)
      type(deck_t), intent(in) :: deck
      type(study_t), intent(in) :: st
      character(len=*), intent(in) :: listing_file, h5_file
      type(run_row_t), intent(inout) :: row
      type(error_t), intent(inout) :: err
      type(analog_case_t), allocatable :: cases(:)
      type(analog_solution_t), allocatable :: sols(:)
      integer :: k
      if (err%failed()) then
         row%status = status_invalid
         row%reason = message_of(err, 'the variation is not a valid deck')
         return
      end if
      if (len(listing_file) > 0 .or. len(h5_file) > 0) then
         call run_analog(deck, deck_text(deck), listing_file, h5_file, err, sols)
         if (err%failed()) then
            row%status = status_failed
            row%reason = message_of(err, 'the run''s outputs could not be written')
            return
         end if
      else
         cases = analog_cases(deck)   ! (read_study: one case)
         sols = [analog_solve(cases(1))]
      end if
      row%status = status_completed
      row%t_end = sols(1)%c%t_max
      allocate (row%crit(size(st%crits)))
      row%meets = .true.
      do k = 1, size(st%crits)
         row%crit(k) = analog_criterion_value(sols(1), analog_criterion_index(st%crits(k)%word))
         if (st%crits(k)%has_limit) row%meets = row%meets .and. row%crit(k) <= st%crits(k)%limit
      end do
   end subroutine analog_run

   !> err's message, or `otherwise` where it has none.
   pure function message_of(err, otherwise) result(m)
      type(error_t), intent(in) :: err
      character(len=*), intent(in) :: otherwise
      character(len=:), allocatable :: m
      m = otherwise
      if (allocated(err%message)) then
         if (len(err%message) > 0) m = err%message
      end if
   end function message_of

   pure function end_words(reason) result(w)
      integer, intent(in) :: reason
      character(len=:), allocatable :: w
      select case (reason)
      case (end_injury)
         w = 'injury'
      case (end_rest)
         w = 'rest'
      case (end_contact)
         w = 'undesired-contact'
      case default
         w = 'end'
      end select
   end function end_words
end module study_runs
