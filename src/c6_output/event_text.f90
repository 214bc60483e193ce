!> Events for the listing and HDF5 (C.7, Table 5, Table 9): every event
!! carries its description, written by its producer (effect_events), so
!! that the listing's summary and HDF5's /events/text say the same thing;
!! and the catalogue of every kind of event, by code, for docs/usage.md
!! (`hsri2d --outputs`) and the test that the codes stay 1, 2, ... with no
!! gap or repeat. A producer of a new kind of event adds its kinds here.
module event_text
   use strings, only: itoa
   use number_format, only: fixed
   use effect_events, only: event_t, event_kind_t
   use joint_dislocation, only: dislocation_event_kinds
   use force_injuries, only: force_event_kinds
   use contact_events, only: contact_event_kinds
   implicit none
   private

   public :: event_description, event_kind_catalogue

   !> Every kind of event, in the order of its code (1, 2, ...).
   type(event_kind_t), parameter :: event_kind_catalogue(*) = [dislocation_event_kinds, force_event_kinds, &
                                                               contact_event_kinds]

contains

   !> The event without its time, e.g. "joint neck  dislocation (below
   !! limit): angle  -80.008 deg, limit  -80.000 deg", as its producer
   !! described it; an event without a description says its kind is
   !! unknown (a programming error: test_every_event_kind_described).
   function event_description(e) result(text)
      type(event_t), intent(in) :: e
      character(len=:), allocatable :: text
      if (len_trim(e%text) > 0) then
         text = trim(e%text)
      else
         text = 'unknown event kind '//itoa(e%kind)//' (no description): index '//itoa(e%index)//', value' &
                //fixed(e%value, 12, 4)//', limit'//fixed(e%limit, 12, 4)
      end if
   end function event_description
end module event_text
