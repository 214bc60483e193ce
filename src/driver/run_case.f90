!> One case, deck files to listing and HDF5 file, as a library call: the
!! pipeline the program runs, and what C.8's repeated runs, a sweep and the
!! tests call. The program (src/app/hsri2d.f90) only parses its command
!! line, calls run_case and turns the error into an exit status.
module run_case_mod
   use error_handling, only: error_t, error_set, exit_io, exit_usage
   use strings, only: num, itoa
   use accuracy_estimate, only: accuracy_warnings, corrector_warning, widened_ramp_warning
   use text_io, only: string_t, append_string
   use deck_reader, only: deck_t, deck_init, deck_add_file, deck_add_lines, deck_finish
   use deck_cards, only: g_pulsefile, g_pulsemme, g_study
   use default_deck, only: default_deck_lines
   use model_builder, only: build_model
   use model, only: model_t, nint_adams, nint_dopri
   use simulation, only: run_to_end, initial_warnings
   use run_loop, only: run_t
   use sink_list, only: sink_list_t
   use run_summary, only: run_summary_t
   use end_tests, only: end_failure, end_energy
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use run_report, only: listing_sink_t, listing_sink_start
   use history_sink, only: history_sink_t, history_sink_open
   use mme_sink, only: mme_sink_t, mme_sink_open, mme_check_dir
   use output_files, only: output_file_t, check_output_paths, deliver_outputs
   use equations_of_motion, only: system_build
   use output_producers, only: registry_build
   use output_doc, only: output_table_lines
   use version_info, only: hsri2d_version
   use refine_check, only: refine_table
   use analog_input, only: deck_is_analog
   use analog_case, only: run_analog
   implicit none
   private

   public :: run_request_t, run_case, write_case, read_case_deck, builtin_deck_name, describe_outputs, refine_case
   public :: deck_text, pulse_file, accuracy_notes

   !> The outputs of a case: the listing, and the HDF5 file when asked for.
   type, extends(output_sink_t) :: case_sink_t
      type(listing_sink_t) :: listing
      type(history_sink_t) :: h5
      logical :: with_h5 = .false.
      type(mme_sink_t) :: mme
      logical :: with_mme = .false.
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
      character(len=:), allocatable :: listing_file  !< '' = the listing goes to standard output
      character(len=:), allocatable :: h5_file       !< '' = no HDF5 file
      character(len=:), allocatable :: mme_dir       !< '' = no ISO-MME data set (--mme DIR)
      logical :: check_only = .false.                !< read and check the decks, run nothing
      !> the switches located inside a step (issue 15); off only in the
      !! tests that show what location buys (model_t%options)
      logical :: locate_switches = .true.
   end type run_request_t

contains

   !> Read the decks of a request (C.1) into deck and model; every problem
   !! found is appended to err.
   subroutine read_case_deck(req, deck, m, err)
      type(run_request_t), intent(in) :: req
      type(deck_t), intent(out) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      call read_deck_files(req, deck, err)
      if (.not. err%failed() .and. deck_is_analog(deck)) &
         call error_set(err, exit_usage, 'an analog deck (*ANALOG, report Section D) is run as a plain run, '// &
                        'not by --refine or --outputs, which take a simulation''s deck (docs/analog.md)')
      call build_case_model(deck, m, err)
   end subroutine read_case_deck

   !> The decks of a request read (C.1) into deck; every problem found is
   !! appended to err.
   subroutine read_deck_files(req, deck, err)
      type(run_request_t), intent(in) :: req
      type(deck_t), intent(out) :: deck
      type(error_t), intent(inout) :: err
      integer :: i
      call deck_init(deck)
      if (size(req%decks) == 0) then
         call deck_add_lines(deck, builtin_deck_name, '', default_deck_lines(), err)
      end if
      do i = 1, size(req%decks)
         if (is_builtin(req%decks(i)%s)) then
            call deck_add_lines(deck, builtin_deck_name, '', default_deck_lines(), err)
         else
            call deck_add_file(deck, req%decks(i)%s, err)
         end if
      end do
      if (err%code /= exit_io) call deck_finish(deck, err)
   end subroutine read_deck_files

   !> The model of a simulation's deck (not a study's): built and checked.
   subroutine build_case_model(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      if (.not. err%failed() .and. deck%group(g_study)%present) &
         call error_set(err, exit_usage, 'a study deck (*STUDY, report C.8) is run from regular files, as a study: '// &
                        'not from standard input, a pipe or a FIFO, nor by --refine or --outputs, which take a single '// &
                        'run''s deck (docs/modification.md)')
      if (.not. err%failed()) call build_model(deck, m, err)
      if (.not. err%failed()) m%warnings = [m%warnings, initial_warnings(m)]
   end subroutine build_case_model

   !> `hsri2d --refine`: read the decks and run the case at its setting and
   !! at a refined one (refine_check), writing nothing; lines: the table.
   !! A run that fails numerically is err (exit 3), as a plain run's.
   subroutine refine_case(req, lines, err)
      type(run_request_t), intent(in) :: req
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      type(deck_t) :: deck
      type(model_t) :: m
      logical :: converged
      allocate (lines(0))
      call read_case_deck(req, deck, m, err)
      if (err%failed()) return
      m%options%locate_switches = req%locate_switches
      call refine_table(m, lines, converged, err)
   end subroutine refine_case

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
      type(string_t), allocatable :: notes(:)
      integer :: k

      call read_deck_files(req, deck, err)
      if (.not. err%failed() .and. deck_is_analog(deck)) then
         ! report Section D's analog instead of the simulation (docs/analog.md)
         if (present(warnings)) allocate (warnings(0))
         if (allocated(req%mme_dir)) then
            if (len(req%mme_dir) > 0) then
               call error_set(err, exit_usage, 'an analog deck (*ANALOG) has no channels to write as an ISO-MME ' &
                              //'data set; --mme would be ignored')
               return
            end if
         end if
         block
            type(string_t) :: no_pulse(0)   ! (an analog deck reads no pulse)
            call check_output_paths(deck_files(req), no_pulse, req%listing_file, req%h5_file, err)
         end block
         if (err%failed() .or. req%check_only) return
         call run_analog(deck, deck_text(deck), req%listing_file, req%h5_file, err)
         return
      end if
      call build_case_model(deck, m, err)
      m%options%locate_switches = req%locate_switches
      if (present(warnings)) then
         if (allocated(m%warnings)) then
            warnings = m%warnings
         else
            allocate (warnings(0))
         end if
      end if
      if (err%failed()) return

      ! outputs are written under temporary names and put in place of their
      ! targets at the end (output_files); nothing is created before the
      ! paths are known not to be inputs (--check checks them too)
      call check_output_paths(deck_files(req), pulse_file(deck, m), req%listing_file, req%h5_file, err)
      if (.not. err%failed() .and. allocated(req%mme_dir)) then
         if (len(req%mme_dir) > 0) call mme_check_dir(req%mme_dir, err)
      end if
      if (err%failed() .or. req%check_only) return
      if (allocated(req%mme_dir)) then
         call write_case(deck, m, req%listing_file, req%h5_file, err, res, notes, req%mme_dir)
      else
         call write_case(deck, m, req%listing_file, req%h5_file, err, res, notes)
      end if
      if (present(warnings)) then
         do k = 1, size(notes)
            call append_string(warnings, notes(k)%s)
         end do
      end if
      if (present(summary)) summary = res
   end subroutine run_case

   !> Simulate model m of deck (C.2-C.7) and write its listing (listing_file,
   !! '' = standard output) and HDF5 file (h5_file, '' = none), whose paths
   !! the caller has checked; res: the run's summary; notes: the warnings
   !! of the run's accuracy (the listing shows them too); mme_dir: the
   !! folder of the run's ISO-MME data set (absent or '': none). err as
   !! run_case's.
   subroutine write_case(deck, m, listing_file, h5_file, err, res, notes, mme_dir)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(in) :: m
      character(len=*), intent(in) :: listing_file, h5_file
      character(len=*), intent(in), optional :: mme_dir
      type(error_t), intent(inout) :: err
      type(run_summary_t), intent(out) :: res
      type(string_t), allocatable, intent(out) :: notes(:)
      type(error_t) :: run_err, io_err
      ! on the heap: it holds the model, which outgrows the stack's static limit
      type(case_sink_t), allocatable, target :: sink
      type(sink_list_t) :: sinks
      type(run_t) :: run
      type(output_file_t) :: h5_file_out

      allocate (notes(0), sink)
      ! the ISO-MME data set's folder first: it holds no earlier output to
      ! keep (no file of it is ever overwritten), so nothing is to be undone
      if (present(mme_dir)) sink%with_mme = len(mme_dir) > 0
      if (sink%with_mme) call mme_sink_open(sink%mme, mme_dir, m%title, err)
      if (err%failed()) return
      call sink%listing%lst%create_text(listing_file, 'listing', err)
      if (err%failed()) return
      sink%with_h5 = len(h5_file) > 0
      if (sink%with_h5) then
         call h5_file_out%reserve(h5_file, 'HDF5 file', io_err)
         if (.not. io_err%failed()) &
            call history_sink_open(sink%h5, h5_file_out%writing_path(), m%title, deck_text(deck), io_err)
         if (io_err%failed()) then
            call deliver_outputs(io_err, sink%listing%lst, h5_file_out)
            call error_set(err, io_err%code, io_err%message)
            return
         end if
      end if
      call listing_sink_start(sink%listing, deck, m, hsri2d_version)
      call sinks%add(sink)
      call run%init(m, sinks=sinks, belt_channels=sink%with_h5 .or. sink%with_mme)
      call run_to_end(run, res, run_err)
      if (sink%with_h5) call sink%h5%close(io_err)
      call sink%listing%lst%flush(io_err)
      ! An input/output error outweighs a numerical failure: the outputs
      ! that would show the run up to the failure are incomplete.
      if (run_err%code == exit_io .and. io_err%failed()) then
         ! the run ended on an output's failure, which closing that output
         ! may report again: said once
         if (index(run_err%message, io_err%message) == 0) then
            io_err%message = run_err%message//new_line('a')//io_err%message
         else
            io_err = run_err
         end if
      else if (run_err%code == exit_io) then
         io_err = run_err
      else if (run_err%failed() .and. io_err%failed()) then
         io_err%message = io_err%message//new_line('a')//'(the run had failed too: '//run_err%message//')'
      else if (run_err%failed()) then
         io_err = run_err
      end if
      if (sink%with_h5) then
         call deliver_outputs(io_err, sink%listing%lst, h5_file_out)
      else
         call deliver_outputs(io_err, sink%listing%lst)
      end if
      if (io_err%failed()) call error_set(err, io_err%code, io_err%message)
      ! a fixed step too large for the deck, a corrector that did not
      ! converge (docs/accuracy.md): said in the listing's summary too
      notes = accuracy_notes(m, res)
   end subroutine write_case

   !> What a finished run of model m says of its own accuracy (docs/accuracy.md):
   !! a fixed step too large, a widened friction ramp, a corrector that did
   !! not converge, an energy balance that failed while the deck said to go
   !! on. The program's warnings, and a study's rows (C.8).
   function accuracy_notes(m, res) result(notes)
      type(model_t), intent(in) :: m
      type(run_summary_t), intent(in) :: res
      type(string_t), allocatable :: notes(:)
      type(string_t), allocatable :: accuracy(:)
      character(len=:), allocatable :: who
      integer :: o, k
      allocate (notes(0))
      do o = 1, size(res%occ)
         who = ''
         if (size(res%occ) > 1) who = 'occupant '//itoa(o)//': '
         accuracy = accuracy_warnings(res%occ(o)%accuracy, who, res%occ(o)%head_max%value, res%t_end, m%time%dt, &
                                      failed=res%end_reason == end_failure .or. res%end_reason == end_energy)
         do k = 1, size(accuracy)
            call append_string(notes, accuracy(k)%s)
         end do
      end do
      if (m%options%nint /= nint_dopri .and. allocated(res%events)) then
         who = widened_ramp_warning(res%events, res%n_events)
         if (len(who) > 0) call append_string(notes, who)
      end if
      if (m%options%nint == nint_adams) then
         who = corrector_warning(res%stats, m%time%corrector_tol, m%time%corrector_max_iter)
         if (len(who) > 0) call append_string(notes, who)
      end if
      ! a balance that failed while the deck said to go on is worth a warning
      do o = 1, size(res%occ)
         if (res%occ(o)%energy_flagged .and. m%numerics%energy_continue) call append_string(notes, &
            'the energy balance failed its tolerance at t = '//num(res%occ(o)%t_flagged)//' s (*NUMERICS ' &
            //'EBTOL; EBFAIL = CONTINUE ran on): the results are not trustworthy')
      end do
   end function accuracy_notes

   subroutine case_begin(this, sys, reg, first, err)
      class(case_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      ! the HDF5 file's structure first (it is flushed at once), then the
      ! listing's first pages, what is known before the run, on the disk
      ! before the run starts: a run killed early leaves both (docs/usage.md)
      if (this%with_mme) call this%mme%begin(sys, reg, first, err)
      if (this%with_h5) call this%h5%begin(sys, reg, first, err)
      call this%listing%begin(sys, reg, first, err)
      call this%listing%lst%flush(err)
   end subroutine case_begin

   subroutine case_record(this, frame, err)
      class(case_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      call this%listing%record(frame, err)
      ! each page of tables on the disk as soon as it is complete (every
      ! 50 records; nothing to write otherwise), and a listing nobody can
      ! read any more (a closed pipe) ends the run at once
      call this%listing%lst%flush(err)
      if (this%with_h5) call this%h5%record(frame, err)
      if (this%with_mme) call this%mme%record(frame, err)
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
      if (this%with_mme) call this%mme%finish(summary, err)
      if (listing_err%failed() .and. .not. err%failed()) err = listing_err
   end subroutine case_finish

   !> The series a run of the request's decks writes (docs/usage.md), as
   !! Markdown lines; nothing is run.
   subroutine describe_outputs(req, lines, err)
      type(run_request_t), intent(in) :: req
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      type(deck_t) :: deck
      type(model_t) :: m
      type(crash_system_t) :: sys
      type(output_registry_t) :: reg
      allocate (lines(0))
      call read_case_deck(req, deck, m, err)
      if (err%failed()) return
      ! the table goes where the listing would (-o or standard output)
      call check_output_paths(deck_files(req), pulse_file(deck, m), req%listing_file, '', err)
      if (err%failed()) return
      call system_build(m, sys)
      call registry_build(sys, reg)
      lines = output_table_lines(reg)
   end subroutine describe_outputs

   !> The name of the built-in deck exactly ("@default " is a file name:
   !! Fortran's == would ignore the trailing blank).
   pure logical function is_builtin(name)
      character(len=*), intent(in) :: name
      is_builtin = len(name) == len(builtin_deck_name)
      if (is_builtin) is_builtin = name == builtin_deck_name
   end function is_builtin

   !> The deck files named in the request (not the built-in deck).
   function deck_files(req) result(files)
      type(run_request_t), intent(in) :: req
      type(string_t), allocatable :: files(:)
      integer :: k
      allocate (files(0))
      do k = 1, size(req%decks)
         if (.not. is_builtin(req%decks(k)%s)) call append_string(files, req%decks(k)%s)
      end do
   end function deck_files

   !> The files the pulse was read from: the CSV file of a *PULSEFILE card,
   !! the .mme file, channel index and channel file of *PULSEMME (none when
   !! the pulse is on cards).
   function pulse_file(d, m) result(paths)
      type(deck_t), intent(in) :: d
      type(model_t), intent(in) :: m
      type(string_t), allocatable :: paths(:)
      allocate (paths(0))
      if (.not. (d%group(g_pulsefile)%present .or. d%group(g_pulsemme)%present)) return
      if (allocated(m%vehicle%pulse_inputs)) paths = m%vehicle%pulse_inputs
   end function pulse_file

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
