!> The print times of a run (C.6: every DTPRINT, and the end) and the
!! frames made there. A fixed-step integrator (Adams-Moulton, RK4) prints
!! every DTPRINT/h steps of its grid and ends after TMAX/h steps; an
!! adaptive one (Dormand-Prince) is asked for steps that end at the print
!! times. A frame holds every series' values at one accepted point, with
!! each occupant's energy balance (its check is the bookkeeping's).
module print_schedule
   use kinds, only: wp, i8
   use model, only: time_section_t, vehicle_section_t
   use equations_of_motion, only: crash_system_t
   use output_registry, only: output_registry_t, output_frame_t
   use output_producers, only: registry_build, frame_fill, energy_balance_t
   use stepper_factory, only: stepper_traits_t
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
      procedure :: make_frame => schedule_make_frame
      procedure :: blank_frame => schedule_blank_frame
   end type print_schedule_t

contains

   !> The schedule of TMAX and DTPRINT for a stepper with these traits,
   !! the series of sys, the energy totals at t = 0 the balances are
   !! measured from.
   subroutine schedule_init(this, time, tr, vehicle, sys, total0)
      class(print_schedule_t), intent(out) :: this
      type(time_section_t), intent(in) :: time
      type(stepper_traits_t), intent(in) :: tr
      type(vehicle_section_t), intent(in) :: vehicle
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: total0(:)
      this%fixed_step = tr%fixed_step
      this%t_max = time%t_max
      this%dt_print = time%dt_print
      if (tr%fixed_step) then
         this%n_steps = nint(time%t_max/tr%h, i8)
         this%print_every = max(1_i8, nint(time%dt_print/tr%h, i8))
      end if
      this%vehicle = vehicle
      this%total0 = total0
      allocate (this%balance(size(total0)))
      call registry_build(sys, this%reg)
   end subroutine schedule_init

   !> The latest time the next step may end at: a fixed-step integrator's
   !! own step, or the end of the step a located switch was found in (once);
   !! an adaptive one's next print time, or TMAX.
   subroutine schedule_next_limit(this, t, t_limit)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(out) :: t_limit
      if (this%fixed_step) then
         t_limit = huge(1.0_wp)
         if (this%t_resume > t) t_limit = this%t_resume    ! back onto the grid after a located switch
         this%t_resume = -1.0_wp
      else
         t_limit = min(real(this%next_print, wp)*this%dt_print, this%t_max)
      end if
   end subroutine schedule_next_limit

   !> A switch was located inside the step that ended at t_end: a fixed-step
   !! integrator's next step goes back to its grid there.
   subroutine schedule_resume_at(this, t_end)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t_end
      if (this%fixed_step) this%t_resume = t_end
   end subroutine schedule_resume_at

   !> A step of the grid (or an adaptive step asked to end at t_limit) was
   !! accepted at t: whether TMAX is reached, whether t is a print time.
   subroutine schedule_step_taken(this, t, t_limit, at_end, print_now)
      class(print_schedule_t), intent(inout) :: this
      real(wp), intent(in) :: t, t_limit
      logical, intent(out) :: at_end, print_now
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
