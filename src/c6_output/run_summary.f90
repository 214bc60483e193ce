!> What a run leaves besides its time histories: why and when it ended,
!! the maxima over all accepted steps and when they happened, the events,
!! the energy balance and what the integration cost. Its size does not grow
!! with the length of the run (except for events, which are few).
module run_summary
   use kinds, only: wp, i8
   use error_handling, only: error_t
   use model, only: n_joint, n_injury, injury_section_t, fmvss_limits_t
   use ode_system, only: step_stats_t
   use effect_events, only: event_t
   use effect_peaks, only: effect_peak_t
   use acceleration_criteria, only: acceleration_criteria_t
   use accuracy_estimate, only: accuracy_t
   use fmvss_table, only: fmvss_channels_t, fmvss_row_t
   implicit none
   private

   public :: extreme_t, occupant_summary_t, run_summary_t, raise, lower, summary_add_event

   !> A running extreme and when it happened.
   type :: extreme_t
      real(wp) :: value = 0.0_wp
      real(wp) :: t = 0.0_wp
   end type extreme_t

   !> One occupant's maxima (accepted steps) and energy balance (print times).
   type :: occupant_summary_t
      type(extreme_t) :: head_max, chest_max
      !> the head's largest forward excursion (in): the largest x
      !! displacement of its centre of gravity relative to the interior (x
      !! forward, where a frontal pulse throws the occupant) from its place
      !! at t = 0, head_x0, over the accepted steps; 0 when it never moved
      !! forward. Not in the listing nor HDF5 (study_criteria's HEADX)
      type(extreme_t) :: head_excursion
      real(wp) :: head_x0 = 0.0_wp
      !> HIC, GSI, 3 ms clip of the head and chest accelerations (g), accepted steps
      type(acceleration_criteria_t) :: head_criteria, chest_criteria
      !> issue 18: the channels sampled at 10 kHz for SAE J211's filters
      !! (fmvss_table), the limits of *FMVSS208, and the table of FMVSS 208
      !! the run's end computes from them
      type(fmvss_channels_t) :: channels
      type(fmvss_limits_t) :: fmvss_limits
      type(fmvss_row_t), allocatable :: fmvss(:)
      !> Table 5's force criteria when the deck gives limits (force_injuries):
      !! the largest tension, compression and shear, and which were reported
      logical :: force_checked = .false.
      type(extreme_t) :: ft_max(n_joint), fc_max(n_injury), fs_max(n_injury)
      logical :: force_reported(3, n_injury) = .false.
      !> the occupant's Table 5 limits they were checked against (its *INJURY)
      type(injury_section_t) :: force_limits
      type(extreme_t) :: joint_min(n_joint), joint_max(n_joint)
      real(wp) :: e_total0 = 0.0_wp             !< energy total at t = 0
      real(wp) :: e_error_final = 0.0_wp
      type(extreme_t) :: energy_error_max       !< largest |balance error| (signed value)
      real(wp) :: ke_max = 0.0_wp               !< largest body kinetic energy
      real(wp) :: supplied_max = 0.0_wp         !< largest |work the vehicle supplied| so far
      !> the energy balance's scale (D-17a): the larger of ke_max and supplied_max
      real(wp) :: energy_scale = 0.0_wp
      logical :: energy_flagged = .false.       !< the balance exceeded its tolerance
      real(wp) :: t_flagged = 0.0_wp
      !> the largest values its effects kept over the accepted steps (the
      !! contact pairs' forces), at the end of the run
      type(effect_peak_t), allocatable :: peaks(:)
      !> the largest values its effects kept for a study's criteria alone
      !! (effect_t%study_peaks: the belts' tensions), which the listing and
      !! HDF5 do not show, at the end of the run
      type(effect_peak_t), allocatable :: study_peaks(:)
      !> how accurate the run was: the fixed-step integrators' local error
      !! estimates accumulated (docs/accuracy.md)
      type(accuracy_t) :: accuracy
   end type occupant_summary_t

   type :: run_summary_t
      integer :: end_reason = 0
      !> the numerical failure that ended the run (end_failure, end_energy):
      !! the run's error, as its finish returns it
      type(error_t) :: failure
      real(wp) :: t_end = 0.0_wp
      type(occupant_summary_t), allocatable :: occ(:)
      type(event_t), allocatable :: events(:)
      integer :: n_events = 0
      type(step_stats_t) :: stats
      integer(i8), allocatable :: counts(:, :)   !< evaluations of each effect (effect, occupant)
      character(len=24), allocatable :: effect_names(:, :)   !< the effects' names (effect, occupant)
      character(len=40), allocatable :: effect_titles(:, :)  !< and their titles
      integer(i8) :: evaluations = 0
      integer :: n_frames = 0                    !< print records made
   end type run_summary_t

contains

   pure subroutine raise(e, value, t)
      type(extreme_t), intent(inout) :: e
      real(wp), intent(in) :: value, t
      if (value > e%value) e = extreme_t(value, t)
   end subroutine raise

   pure subroutine lower(e, value, t)
      type(extreme_t), intent(inout) :: e
      real(wp), intent(in) :: value, t
      if (value < e%value) e = extreme_t(value, t)
   end subroutine lower

   pure subroutine summary_add_event(s, e)
      type(run_summary_t), intent(inout) :: s
      type(event_t), intent(in) :: e
      type(event_t), allocatable :: longer(:)
      if (.not. allocated(s%events)) allocate (s%events(8))
      if (s%n_events == size(s%events)) then
         allocate (longer(2*size(s%events)))
         longer(1:s%n_events) = s%events(1:s%n_events)
         call move_alloc(longer, s%events)
      end if
      s%n_events = s%n_events + 1
      s%events(s%n_events) = e
   end subroutine summary_add_event
end module run_summary
