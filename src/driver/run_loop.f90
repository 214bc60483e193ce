!> One run as a value (report figure 6): the system, its stepper, the
!! state, the books of the accepted steps, the print schedule, the
!! located switches and the sinks, all components of a run_t, so that runs
!! can proceed side by side (C.8's studies) and a caller can step one:
!!
!!    call run%init(m, sinks=sinks)          ! C.2, t = 0: the first frame, begin
!!    do while (.not. run%is_done())
!!       call run%advance()                   ! one accepted step (C.3-C.7)
!!    end do
!!    call run%finish(summary, err)           ! the summary, the sinks' finish
!!
!! init builds the system from the model (or takes an assembled one) and
!! the stepper from the model's numerics (or takes the caller's); the
!! sinks (sink_list) are any number, none required. A numerical failure
!! ends the run with everything computed so far kept, summary%end_reason
!! = end_failure (or end_energy) and err set (exit_numerical) by finish;
!! an error a sink reports ends the run too, and outweighs a numerical
!! failure (docs/usage.md). Nothing is allocated by advance (but a frame
!! at a print time and an event's record).
module run_loop
   use kinds, only: wp
   use error_handling, only: error_t, error_set
   use model, only: model_t
   use equations_of_motion, only: crash_system_t, system_build, system_initial_y
   use ode_system, only: stepper_t
   use run_summary, only: run_summary_t
   use end_tests, only: end_none, end_time, end_failure, end_energy
   use stepper_factory, only: stepper_traits_t, stepper_from_model, stepper_traits
   use sink_list, only: sink_list_t
   use step_bookkeeping, only: step_books_t, record_failure
   use print_schedule, only: print_schedule_t
   use switch_location, only: switch_locator_t
   use fmvss_table, only: fmvss_rows
   implicit none
   private

   public :: run_t

   type :: run_t
      private
      type(crash_system_t) :: sys
      class(stepper_t), allocatable :: stepper
      real(wp) :: t = 0.0_wp                 !< the last accepted point
      real(wp), allocatable :: y(:)
      type(run_summary_t) :: summary         !< maxima, criteria, events, energy balance so far
      type(step_books_t) :: books            !< what each accepted step updates
      type(print_schedule_t) :: schedule     !< print times and frames
      type(switch_locator_t) :: switches     !< switches located inside a step (issue 15)
      type(sink_list_t) :: sinks
      type(error_t) :: err                   !< a numerical failure (the summary's failure at finish)
      integer :: reason = end_none           !< why the run ended (end_none: it goes on)
      logical :: finished = .false.
      !> switches predicted before the step that would cross them (issue 16:
      !! an adaptive stepper with a continuous extension, unless init says not)
      logical :: predicts = .false.
   contains
      procedure :: init => run_init
      procedure :: advance => run_advance
      procedure :: is_done => run_is_done
      procedure :: finish => run_finish
      procedure :: time => run_time
      procedure :: peek => run_peek
   end type run_t

contains

   !> The run of model m at t = 0: the system (m's, or `system`, copied:
   !! its occupants may come from several models; m gives the time
   !! controls, the numerics and the vehicle's outputs), the stepper (from
   !! m's NINT and settings, or `stepper`, copied with its settings), C.2's
   !! initial outputs, the first frame to the sinks (which begin), and the
   !! books of t = 0. A first evaluation that fails ends the run at once
   !! (is_done), the sinks given a frame marked invalid. predict: switches
   !! predicted before the step that would cross them (issue 16; the
   !! default), or false: only found after it (tests compare the two).
   subroutine run_init(this, m, system, stepper, sinks, predict, belt_channels)
      class(run_t), intent(out) :: this
      type(model_t), intent(in) :: m
      type(crash_system_t), intent(in), optional :: system
      class(stepper_t), intent(in), optional :: stepper
      type(sink_list_t), intent(in), optional :: sinks
      logical, intent(in), optional :: predict
      !> the sinks take the belts' tensions at 10 kHz (HDF5's /channels, ISO-MME)
      logical, intent(in), optional :: belt_channels
      type(stepper_traits_t) :: tr
      real(wp), allocatable :: total0(:)
      type(error_t) :: why
      if (present(system)) then
         this%sys = system
      else
         call system_build(m, this%sys)
      end if
      if (present(sinks)) this%sinks = sinks
      call system_initial_y(this%sys, this%y)
      if (present(stepper)) then
         allocate (this%stepper, source=stepper)
      else
         call stepper_from_model(m, this%stepper)
      end if
      tr = stepper_traits(this%stepper)
      this%t = 0.0_wp
      ! the FMVSS 208 table where the run's outputs go somewhere (a listing,
      ! HDF5, a collector); a study's runs, the refinement's, read none of it
      if (this%sinks%size() > 0) then
         call this%books%init(this%sys, this%t, this%y, m%numerics, m%vehicle, this%summary, &
                              head_excursion=m%options%head_excursion, fmvss=m%fmvss, duration=m%time%t_max, &
                              belt_channels=belt_channels)
      else
         call this%books%init(this%sys, this%t, this%y, m%numerics, m%vehicle, this%summary, &
                              head_excursion=m%options%head_excursion)
      end if
      total0 = this%summary%occ%e_total0    ! (the energy totals the balances are measured from)
      call this%schedule%init(m%time, tr, m%vehicle, this%sys, total0, m%options%locate_switches)
      call this%stepper%init(this%sys, this%t, this%y, why)
      if (why%failed()) then
         ! no derivative at t = 0: the outputs say so and hold no time history
         call record_failure(why, this%t, this%summary, this%err)
         call this%schedule%blank_frame()
         call this%sinks%begin(this%sys, this%schedule%reg, this%schedule%frame)
         this%reason = end_failure
         return
      end if
      call make_frame(this)
      call this%sinks%begin(this%sys, this%schedule%reg, this%schedule%frame)
      call this%sinks%record(this%schedule%frame)
      call this%books%accept(this%sys, this%stepper, this%t, this%y, .false., this%summary, this%sinks, this%reason, &
                             this%err)
      call this%switches%init(this%sys, tr%relocates .and. m%options%locate_switches, this%t, this%y, &
                             this%stepper%stats)
      this%predicts = this%switches%on .and. this%stepper%next_step() > 0.0_wp
      if (present(predict)) this%predicts = this%predicts .and. predict
      ! a trial step an adaptive stepper rejects is cut at a switch it
      ! crosses (run_advance), not shortened blindly
      this%stepper%offers_trials = this%switches%on
   end subroutine run_init

   !> One accepted step: a step of the integrator, or the state inside it
   !! just past a located switch (issue 15); then the books (memory,
   !! maxima, events, end tests, a restart), a frame at a print time or at
   !! the end. Nothing when the run is done.
   subroutine run_advance(this)
      class(run_t), intent(inout) :: this
      real(wp) :: t_limit, t_step_end, t_step_limit
      real(wp), allocatable :: f_here(:)
      logical :: located, at_end, print_now
      integer :: reason
      type(error_t) :: why
      if (this%is_done()) return
      call this%schedule%next_limit(this%t, t_limit)
      ! a multistep method steps onto a kink of the vehicle's motion inside
      ! its step from a start (its start steps may end anywhere)
      if (this%schedule%limit_is_kink .and. this%stepper%multistep) then
         f_here = this%stepper%f
         call this%stepper%resume(this%sys, this%t, this%y, f_here, why)
         if (why%failed()) then
            call record_failure(why, this%t, this%summary, this%err)
            this%reason = end_failure
            return
         end if
      end if
      if (this%switches%on) call this%switches%mark(this%t, this%y, this%stepper%f, this%stepper%stats)
      ! (the step cut just short of a switch predicted inside it, issue 16)
      t_step_limit = t_limit
      if (this%predicts) t_step_limit = this%switches%predict(this%t, this%stepper%next_step(), t_limit)
      call this%stepper%advance(this%sys, this%t, this%y, t_step_limit, why)
      located = .false.
      ! a trial the stepper rejected: when it crossed a switch, its error
      ! was the switch's, and it is cut there as an accepted step would be;
      ! otherwise the stepper goes on with a shorter step
      do while (this%stepper%trial_offered .and. .not. why%failed())
         call this%switches%locate(this%sys, this%stepper, this%t, this%y, located, why, trial=.true., &
                                      t_limit=t_limit)
         if (located .or. why%failed()) exit
         ! (a switch there that could not be located: the stepper's own
         ! shorter steps, as without trials offered)
         this%stepper%offers_trials = .not. this%switches%trial_given_up
         call this%stepper%advance(this%sys, this%t, this%y, t_step_limit, why)
         this%stepper%offers_trials = .true.
      end do
      t_step_end = this%t
      ! a switch inside the step: the state just past the first
      if (.not. located .and. .not. why%failed() .and. this%switches%on) &
         call this%switches%locate(this%sys, this%stepper, this%t, this%y, located, why, t_limit=t_limit)
      ! (switches taken together with a print time just after them: the
      ! state there is a print time's, as a step's that ends there)
      if (located .and. this%t >= t_limit) located = .false.
      if (why%failed()) then
         ! keep the last accepted state in the output, then stop
         if (this%t > this%schedule%t_frame) call output_frame(this)
         call record_failure(why, this%t, this%summary, this%err)
         this%reason = end_failure
         return
      end if
      if (located) then
         ! an accepted state inside the step, not a step of the grid nor a
         ! print time (unless the run ends there); the step goes on from it
         call this%books%accept(this%sys, this%stepper, this%t, this%y, .false., this%summary, this%sinks, &
                                reason, this%err)
         call this%schedule%resume_at(t_step_end)
         if (reason /= end_none) call output_frame(this)
      else
         ! whether TMAX is reached here is known before the step's memory
         ! updates, so that no restart is made for a step that ends the run
         ! (a step to a kink of the vehicle's motion inside the grid's step
         ! is none of the grid, nor one to a print time; step_taken)
         if (this%schedule%limit_is_kink .and. this%schedule%kink_reached(this%t)) &
            this%stepper%stats%kinks = this%stepper%stats%kinks + 1
         call this%schedule%step_taken(this%t, t_limit, at_end, print_now)
         call this%books%accept(this%sys, this%stepper, this%t, this%y, at_end, this%summary, this%sinks, &
                                reason, this%err, kink=this%schedule%kink_reached(this%t))
         if (at_end .and. reason == end_none) reason = end_time
         if (print_now .or. reason /= end_none) call output_frame(this)
      end if
      if (this%summary%end_reason == end_energy) reason = end_energy
      this%reason = reason
      ! the signs the next step is compared with, with the memory just updated
      if (reason == end_none) &
         call this%switches%accepted(this%sys, this%t, this%y, this%stepper%stats, this%books%memory_unchanged)
   end subroutine run_advance

   !> The run has ended: TMAX, an end test (C.7), a numerical failure, or
   !! an output error.
   pure logical function run_is_done(this)
      class(run_t), intent(in) :: this
      run_is_done = this%reason /= end_none .or. this%sinks%failed()
   end function run_is_done

   !> The time of the last accepted point.
   pure real(wp) function run_time(this)
      class(run_t), intent(in) :: this
      run_time = this%t
   end function run_time

   !> A copy of the run's system (its effects and their memories) and of
   !! its state at the last accepted point: for tests that compare runs
   !! step by step.
   subroutine run_peek(this, sys, y)
      class(run_t), intent(in) :: this
      type(crash_system_t), intent(out) :: sys
      real(wp), allocatable, intent(out) :: y(:)
      sys = this%sys
      y = this%y
   end subroutine run_peek

   !> The run's summary (the cost, each effect's evaluations and peaks
   !! added), given to the sinks' finish; err: a numerical failure, or the
   !! sinks' error, which outweighs it (the outputs that would show the run
   !! up to the failure are incomplete). Left unchanged when nothing failed.
   !! Finished before it is done, a run's summary is that of the run so
   !! far (end_reason end_none). A second finish only gives the summary.
   subroutine run_finish(this, summary, err)
      class(run_t), intent(inout) :: this
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      integer :: o, i, n_occ
      if (.not. this%finished) then
         this%finished = .true.
         associate (s => this%summary, sys => this%sys)
            if (this%reason /= end_none .and. s%end_reason == end_none) s%end_reason = this%reason
            ! the run's failure, as the listing's summary and the caller see it
            if (this%err%failed()) s%failure = this%err
            n_occ = size(sys%occupants)
            s%t_end = this%t
            s%stats = this%stepper%stats
            s%counts = sys%counts
            allocate (s%effect_names(size(sys%counts, 1), n_occ), s%effect_titles(size(sys%counts, 1), n_occ))
            s%effect_names = ' '
            s%effect_titles = ' '
            do o = 1, n_occ
               allocate (s%occ(o)%peaks(0), s%occ(o)%study_peaks(0))
               do i = 1, size(sys%occupants(o)%effects)
                  s%effect_names(i, o) = sys%occupants(o)%effects(i)%e%name
                  s%effect_titles(i, o) = sys%occupants(o)%effects(i)%e%title
                  s%occ(o)%peaks = [s%occ(o)%peaks, sys%occupants(o)%effects(i)%e%peaks()]
                  s%occ(o)%study_peaks = [s%occ(o)%study_peaks, sys%occupants(o)%effects(i)%e%study_peaks()]
               end do
               ! the FMVSS 208 table from the filtered channels (fmvss_table)
               associate (os => s%occ(o))
                  if (os%channels%kept) &
                     os%fmvss = fmvss_rows(os%channels, os%fmvss_limits, os%head_criteria, os%chest_criteria)
               end associate
            end do
            s%evaluations = sys%evaluations
            call this%sinks%finish(s)
         end associate
         if (this%err%failed()) call error_set(err, this%err%code, this%err%message)
         associate (out_err => this%sinks%err)
            if (out_err%failed()) then
               if (err%failed()) then
                  call error_set(err, out_err%code, out_err%message//new_line('a')//'(the run had failed too: ' &
                                 //err%message//')')
               else
                  call error_set(err, out_err%code, out_err%message)
               end if
            end if
         end associate
      end if
      summary = this%summary
   end subroutine run_finish

   !> The frame at the current accepted point, with the energy balances
   !! checked.
   subroutine make_frame(this)
      type(run_t), intent(inout) :: this
      call this%schedule%make_frame(this%sys, this%t, this%y, this%stepper%f)
      call this%books%check_energy(this%sys, this%schedule%balance, this%t, this%summary, this%err)
      this%summary%n_frames = this%summary%n_frames + 1
   end subroutine make_frame

   !> A print record (C.6), to the sinks.
   subroutine output_frame(this)
      type(run_t), intent(inout) :: this
      call make_frame(this)
      call this%sinks%record(this%schedule%frame)
   end subroutine output_frame
end module run_loop
