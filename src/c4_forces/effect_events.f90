!> Events: what happened at an accepted step (injuries, C.7's happenings,
!! notes), as an effect's accept (or the driver's Table 5 check) reports it.
!!
!! An event carries everything its consumers need, so that none of them
!! holds a list of kinds: its kind's code (HDF5 /events/kind), whether it
!! counts for the injury end test, whether it is an undesired contact
!! (NEND = 2) or a note, and its description in words, which its producer
!! writes (the listing's summary and HDF5's /events/text print it as it is).
!! Each producer declares its kinds (event_kind_t: a code, a name, note or
!! not) next to the code that reports them; the codes are stable and
!! documented (docs/usage.md, from c6_output/event_text's catalogue, whose
!! test checks that they run 1, 2, ... without a gap or a repeat).
module effect_events
   use kinds, only: wp
   implicit none
   private

   public :: event_t, event_kind_t, accept_result_t, max_events_per_step, event_text_len
   public :: event_of, accept_add_event

   !> Events one effect may report at one accepted step.
   integer, parameter :: max_events_per_step = 16
   !> The longest description (the listing wraps it; HDF5 keeps its first 120 characters).
   integer, parameter :: event_text_len = 200

   !> A kind of event: its code (/events/kind; never reused), its name (docs/usage.md) and
   !! whether it is a note: worth knowing, but neither an injury nor a happening of C.7
   !! (the listing lists notes apart; their description begins "note:").
   type :: event_kind_t
      integer :: code = 0
      character(len=28) :: name = ' '
      logical :: note = .false.
   end type event_kind_t

   !> Something that happened at an accepted step.
   type :: event_t
      real(wp) :: t = 0.0_wp
      integer :: kind = 0           !< its kind's code
      integer :: index = 0          !< the joint, segment or body point it concerns
      real(wp) :: value = 0.0_wp    !< the value found
      real(wp) :: limit = 0.0_wp    !< the limit it passed
      logical :: injury = .false.   !< counts for the injury end test (C.7)
      integer :: occupant = 1
      integer :: surface = 0        !< the surface k of a contact event
      logical :: note = .false.     !< a note (its kind's)
      logical :: undesired = .false. !< Table 9's undesired contact: ends the run when NEND = 2 (C.7)
      !> what happened, in words, without the time (its producer's); "note: " before a note's
      character(len=event_text_len) :: text = ' '
   end type event_t

   !> What `accept` reports.
   type :: accept_result_t
      logical :: restart = .false.  !< the right-hand side jumped: the stepper must restart
      !> the accept changed none of the effect's memory: its switching
      !! functions at the state are those before it (issue 16 section 4;
      !! the default says nothing of the kind)
      logical :: memory_unchanged = .false.
      integer :: n_events = 0
      type(event_t) :: events(max_events_per_step)
   end type accept_result_t

contains

   !> An event of kind k at time t, described by text (a note's gets "note: " before it).
   pure function event_of(k, t, index, value, text, limit, injury, surface) result(e)
      type(event_kind_t), intent(in) :: k
      real(wp), intent(in) :: t, value
      integer, intent(in) :: index
      character(len=*), intent(in) :: text
      real(wp), intent(in), optional :: limit
      logical, intent(in), optional :: injury
      integer, intent(in), optional :: surface
      type(event_t) :: e
      e = event_t(t=t, kind=k%code, index=index, value=value, note=k%note)
      if (present(limit)) e%limit = limit
      if (present(injury)) e%injury = injury
      if (present(surface)) e%surface = surface
      if (k%note) then
         e%text = 'note: '//text
      else
         e%text = text
      end if
   end function event_of

   !> Append e to what accept reports (up to max_events_per_step events a step).
   pure subroutine accept_add_event(result, e)
      type(accept_result_t), intent(inout) :: result
      type(event_t), intent(in) :: e
      if (result%n_events >= max_events_per_step) return
      result%n_events = result%n_events + 1
      result%events(result%n_events) = e
   end subroutine accept_add_event
end module effect_events
