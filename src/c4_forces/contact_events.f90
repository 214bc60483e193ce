!> The contact pairs' events (C.4.f, C.7; docs/contacts.md): Table 9's
!! undesired contact, the windshield shattered (D-C24) and the head cut on
!! its broken glass (D-C25), and the note that the fixed step widened a
!! friction ramp (D-C18b); their kinds and their words.
module contact_events
   use kinds, only: wp
   use strings, only: itoa, num
   use model, only: arc_name
   use number_format, only: fixed
   use contact_tables, only: surface_name
   use effect_events, only: event_t, event_kind_t, event_of
   implicit none
   private

   public :: contact_event, contact_event_kinds
   public :: event_undesired, event_shatter, event_cut, event_ramp_widened

   !> The codes (/events/kind, docs/usage.md): Table 9's undesired contact of body point
   !! `index` with surface `surface` (C.7, NEND = 2); the windshield shattered (FSW reached)
   !! and the head cut on its broken glass (an injury); a friction ramp widened (a note).
   integer, parameter :: event_undesired = 6, event_shatter = 7, event_cut = 8, event_ramp_widened = 9
   type(event_kind_t), parameter :: contact_event_kinds(4) = [ &
      event_kind_t(event_undesired, 'undesired contact'), event_kind_t(event_shatter, 'windshield shattered'), &
      event_kind_t(event_cut, 'cut on broken glass'), event_kind_t(event_ramp_widened, 'friction ramp widened', .true.)]

contains

   !> The event of kind code (one of the codes above) of body point i on
   !! surface k at time t: the force (undesired, shatter: limit FSW), the
   !! penetration (cut) or the ramp's width xi (widened: limit XI).
   function contact_event(code, t, i, k, value, limit) result(e)
      integer, intent(in) :: code, i, k
      real(wp), intent(in) :: t, value
      real(wp), intent(in), optional :: limit
      type(event_t) :: e
      real(wp) :: lim
      lim = 0.0_wp
      if (present(limit)) lim = limit
      select case (code)
      case (event_undesired)
         e = event_of(contact_event_kinds(1), t, i, value, 'point '//arc_name(i)//' on surface '//itoa(k)//' (' &
                      //surface_name(k)//'): undesired contact (Table 9), force'//fixed(value, 10, 1)//' lb', surface=k)
         e%undesired = .true.
      case (event_shatter)
         ! (FSW as the deck gives it, the force to 5 digits: a tiny FSW is not "0.0", issue 14)
         e = event_of(contact_event_kinds(2), t, i, value, 'windshield shattered by point '//arc_name(i)//': force ' &
                      //num(value, 5)//' lb, FSW '//num(lim)//' lb', limit=lim, surface=k)
      case (event_cut)
         e = event_of(contact_event_kinds(3), t, i, value, 'point '//arc_name(i)//' cut on the broken windshield: ' &
                      //'penetration'//fixed(value, 9, 3)//' in', injury=.true., surface=k)
      case default
         e = event_of(contact_event_kinds(4), t, i, value, 'point '//trim(arc_name(i))//' on surface '//itoa(k)//' (' &
                      //surface_name(k)//'): friction ramp widened for DT: xi '//num(value, 4)//' in/s (XI ' &
                      //num(lim)//')', limit=lim, surface=k)
      end select
   end function contact_event
end module contact_events
