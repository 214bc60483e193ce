!> The print times of a run (C.6: every DTPRINT, and the end) and the
!! frames made there. A fixed-step integrator (Adams-Moulton, RK4) prints
!! every DTPRINT/h steps of its grid and ends after TMAX/h steps; an
!! adaptive one (Dormand-Prince) is asked for steps that end at the print
!! times. A frame holds every series' values at one accepted point, with
!! each occupant's energy balance (its check is the bookkeeping's).
!!
!! Issue 15: the vehicle's kinks (vehicle_motion's vehicle_kinks: the knots
!! of its tables where a slope changes) are stepped onto, as located
!! switches are: a step that would cross one ends there, an accepted state
!! that is no step of the grid (and no print time), and the next goes back
!! to the grid. A one-step method (RK4, Dormand-Prince) crosses nothing
!! then; Adams-Moulton restarts there (its back values would span the kink).
module print_schedule
   use kinds, only: wp, i8
   use model, only: time_section_t, vehicle_section_t
   use equations_of_motion, only: crash_system_t
   use output_registry, only: output_registry_t, output_frame_t
   use output_producers, only: registry_build, frame_fill, energy_balance_t
   use stepper_factory, only: stepper_traits_t
   use vehicle_motion, only: vehicle_kinks
   implicit none
   private

   public :: print_schedule_t

   type :: print_schedule_t
      logical :: fixed_step = .false.
      real(wp) :: t_max = 0.0_wp, dt_print = 0.0_wp
      integer(i8) :: n_steps = 0       !< of the fixed grid, to TMAX
      integer(i8) :: print_every = 1   !< of the fixed grid's steps
      integer(i8) :: next_print = 1    !< adaptive: the next print time is next_print*DTPRINT
      integer(i8) :: n = 0             !< accepted steps of the grid so far (not located states)
      !> fixed grid: after a located switch, the end of the step it was found
      !! in, where the next step returns to the grid (negative: none)
      real(wp) :: t_resume = -1.0_wp
      real(wp) :: h = 0.0_wp           !< fixed grid: its step
      !> the vehicle's kinks in (0, TMAX), increasing, and the first not yet
      !! passed (issue 15)
      real(wp), allocatable :: kinks(:)
      integer :: next_kink = 1
      !> the limit next_limit gave is a kink inside the step (the step that
      !! ends there is no step of the grid, nor one to a print time)
      logical :: limit_is_kink = .false.
      !> the step to the limit next_limit gave ends on a kink, inside or at
      !! its end (a grid point, a print time): the forcing kinks there
      logical :: kink_at_limit = .false.
      real(wp) :: t_kink = 0.0_wp, kink_close = 0.0_wp   !< that kink, and a rounding of the step
      !> the frames: the vehicle's data for the outputs, the series, the
      !! last frame, each occupant's energy total at t = 0 and balance
      type(vehicle_section_t) :: vehicle
      type(output_registry_t) :: reg
      type(output_frame_t) :: frame
      real(wp), allocatable :: total0(:)
      type(energy_balance_t), allocatable :: balance(:)
      real(wp) :: t_frame = 0.0_wp     !< the time of the last frame
   contains
      procedure :: init => schedule_init
      procedure :: next_limit => schedule_next_limit
      procedure :: resume_at => schedule_resume_at
      procedure :: step_taken => schedule_step_taken
      procedure :: kink_reached => schedule_kink_reached
      procedure :: make_frame => schedule_make_frame
      procedure :: blank_frame => schedule_blank_frame
   end type print_schedule_t

contains

   !> The schedule of TMAX and DTPRINT for a stepper with these traits,
   !! the series of sys, the energy totals at t = 0 the balances are
   !! measured from; kinks: step onto the vehicle's kinks (the option that
   !! locates switches, model_t%options%locate_switches).
   subroutine schedule_init(this, time, tr, vehicle, sys, total0, kinks)
      class(print_schedule_t), intent(out) :: this
      type(time_section_t), intent(in) :: time
      type(stepper_traits_t), intent(in) :: tr
      type(vehicle_section_t), intent(in) :: vehicle
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: total0(:)
      logical, intent(in) :: kinks
      this%fixed_step = tr%fixed_step
      this%t_max = time%t_max
      this%dt_print = time%dt_print
      if (tr%fixed_step) then
         this%h = tr%h
         this%n_steps = nint(time%t_max/tr%h, i8)
         this%print_every = max(1_i8, nint(time%dt_print/tr%h, i8))
      end if
      ! (only where an effect reads the vehicle's motion: a body alone, in
      ! inertial coordinates, does not feel the pulse, and its steps stay
      ! on the grid)
      if (kinks .and. sys%needs_vehicle) then
         this%kinks = vehicle_kinks(sys%vm, time%t_max)
      else
         allocate (this%kinks(0))
      end if
      this%next_kink = 1
      this%vehicle = vehicle
      this%total0 = total0
      allocate (this%balance(size(total0)))
      call registry_build(sys, this%reg)
   end subroutine schedule_init

   !> The latest time the next step may end at: a fixed-step integrator's
   !! own step, or the end of the step a located switch was found in (once);
   !! an adaptive one's next print time, or TMAX; either way the vehicle's
   !! next kink when it comes first (limit_is_kink; kink_at_limit also
   !! where it is the step's own end, to a rounding of the step).
   subroutine schedule_next_limit(this, t, t_limit)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(out) :: t_limit
      real(wp) :: t_end, t_kink, close
      logical :: resume
      resume = .false.
      if (this%fixed_step) then
         ! the end of the grid's step (the grid from t = 0), or the end of
         ! the step a located switch or a kink was found in (once)
         t_end = real(this%n + 1, wp)*this%h
         resume = this%t_resume > t
         if (resume) t_end = this%t_resume
         this%t_resume = -1.0_wp
         close = 1.0e-9_wp*this%h
      else
         t_end = min(real(this%next_print, wp)*this%dt_print, this%t_max)
         close = 1.0e-9_wp*max(t_end - t, spacing(t_end))
      end if
      t_limit = t_end
      this%limit_is_kink = .false.
      this%kink_at_limit = .false.
      ! the kinks passed (accepted at or beyond) are behind
      do while (this%next_kink <= size(this%kinks))
         if (this%kinks(this%next_kink) > t + close) exit
         this%next_kink = this%next_kink + 1
      end do
      if (this%next_kink > size(this%kinks)) then
         if (this%fixed_step .and. .not. resume) t_limit = huge(1.0_wp)
         return
      end if
      t_kink = this%kinks(this%next_kink)
      this%t_kink = t_kink
      this%kink_close = close
      if (t_kink < t_end - close) then
         t_limit = t_kink
         this%limit_is_kink = .true.
         this%kink_at_limit = .true.
         ! a fixed step goes back to the grid's end after it
         if (this%fixed_step) this%t_resume = t_end
      else if (t_kink <= t_end + close) then
         this%kink_at_limit = .true.
         ! the end of a step a switch was located in, inside the grid's
         ! step, that is a kink: a step to a kink as above
         if (this%fixed_step .and. t_end < real(this%n + 1, wp)*this%h - close) then
            this%limit_is_kink = .true.
            this%t_resume = real(this%n + 1, wp)*this%h
         end if
      end if
      ! (a fixed-step integrator takes its own step to the grid's end)
      if (this%fixed_step .and. .not. (this%limit_is_kink .or. resume)) t_limit = huge(1.0_wp)
   end subroutine schedule_next_limit

   !> A switch was located inside the step that ended at t_end: a fixed-step
   !! integrator's next step goes back to its grid there.
   subroutine schedule_resume_at(this, t_end)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t_end
      if (this%fixed_step) this%t_resume = t_end
   end subroutine schedule_resume_at

   !> The step accepted at t ended on the vehicle's kink next_limit found
   !! (inside the step or at its end; not one cut short of it by a located
   !! switch, nor an adaptive step that fell short).
   pure logical function schedule_kink_reached(this, t) result(reached)
      class(print_schedule_t), intent(in) :: this
      real(wp), intent(in) :: t
      reached = this%kink_at_limit .and. t >= this%t_kink - this%kink_close
   end function schedule_kink_reached

   !> A step of the grid (or an adaptive step asked to end at t_limit) was
   !! accepted at t: whether TMAX is reached, whether t is a print time.
   subroutine schedule_step_taken(this, t, t_limit, at_end, print_now)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t, t_limit
      logical, intent(out) :: at_end, print_now
      if (this%limit_is_kink) then
         ! a step to a kink inside the step: no step of the grid, no print time
         at_end = .false.
         print_now = .false.
         return
      end if
      this%n = this%n + 1
      if (this%fixed_step) then
         at_end = this%n >= this%n_steps
         print_now = mod(this%n, this%print_every) == 0
      else
         at_end = t >= this%t_max
         print_now = t >= t_limit
         if (print_now) this%next_print = this%next_print + 1
      end if
   end subroutine schedule_step_taken

   !> The frame at the accepted point (t, y) where the derivative is f, and
   !! each occupant's energy balance (this%balance).
   subroutine schedule_make_frame(this, sys, t, y, f)
      class(print_schedule_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t, f(:)
      real(wp), intent(in), contiguous :: y(:)
      call frame_fill(sys, this%vehicle, this%reg, t, y, f, this%total0, this%frame, this%balance)
      this%t_frame = t
   end subroutine schedule_make_frame

   !> The frame of a run whose first evaluation failed: no value is known.
   subroutine schedule_blank_frame(this)
      class(print_schedule_t), intent(inout) :: this
      allocate (this%frame%v(this%reg%n_values))
      this%frame%v = 0.0_wp
      this%frame%valid = .false.
   end subroutine schedule_blank_frame
end module print_schedule
