!> What an event is, in words (C.7, Table 5, Table 9): one description for
!! the listing's summary and HDF5's /events/text, so that the two say the
!! same thing.
module event_text
   use kinds, only: deg
   use strings, only: itoa, num
   use model, only: joint_name, arc_name
   use number_format, only: fixed
   use effect_base, only: event_t, event_kind_name, event_tension, event_compression, event_shear, event_undesired, &
      event_shatter, event_cut, event_ramp_widened, event_dislocation_low, event_dislocation_high, n_event_kinds
   use contact_tables, only: surface_name
   use force_injuries, only: fc_name, fs_name
   implicit none
   private

   public :: event_description, event_is_note

contains

   !> Whether events of this kind are notes: worth knowing, but neither an
   !! injury nor a happening of C.7 (a contact's friction ramp widened for
   !! the fixed step, D-C18b). The listing lists them apart (NOTES); their
   !! description, in the listing and in HDF5's /events/text, begins "note:".
   pure logical function event_is_note(kind)
      integer, intent(in) :: kind
      event_is_note = kind == event_ramp_widened
   end function event_is_note

   !> The event without its time, e.g. "joint neck  dislocation (below
   !! limit): angle  -80.008 deg, limit  -80.000 deg". Every kind of
   !! effect_base has its case; any other code says it is unknown (a
   !! programming error: test_every_event_kind_described).
   function event_description(e) result(text)
      type(event_t), intent(in) :: e
      character(len=:), allocatable :: text
      select case (e%kind)
      case (event_dislocation_low, event_dislocation_high)
         text = 'joint '//joint_name(e%index)//'  '//trim(event_kind_name(e%kind))//': angle' &
                //fixed(e%value/deg, 9, 3)//' deg, limit'//fixed(e%limit/deg, 9, 3)//' deg'
      case (event_tension)
         text = 'joint '//joint_name(e%index)//'  '//trim(event_kind_name(e%kind))//': force' &
                //fixed(e%value, 10, 1)//' lb, limit'//fixed(e%limit, 10, 1)//' lb'
      case (event_compression, event_shear)
         text = 'bone '//merge(fc_name(e%index), fs_name(e%index), e%kind == event_compression) &
                //'  '//trim(event_kind_name(e%kind))//': force'//fixed(e%value, 10, 1)//' lb, limit' &
                //fixed(e%limit, 10, 1)//' lb'
      case (event_undesired)
         text = 'point '//arc_name(e%index)//' on surface '//itoa(e%surface)//' ('//surface_name(e%surface) &
                //'): undesired contact (Table 9), force'//fixed(e%value, 10, 1)//' lb'
      case (event_shatter)
         ! (FSW as the deck gives it, the force to 5 digits: a tiny FSW is not "0.0", issue 14)
         text = 'windshield shattered by point '//arc_name(e%index)//': force '//num(e%value, 5) &
                //' lb, FSW '//num(e%limit)//' lb'
      case (event_cut)
         text = 'point '//arc_name(e%index)//' cut on the broken windshield: penetration' &
                //fixed(e%value, 9, 3)//' in'
      case (event_ramp_widened)
         text = 'point '//trim(arc_name(e%index))//' on surface '//itoa(e%surface)//' ('//surface_name(e%surface) &
                //'): friction ramp widened for DT: xi '//num(e%value, 4)//' in/s (XI '//num(e%limit)//')'
      case default
         text = 'unknown event kind '//itoa(e%kind)//' (of 1 to '//itoa(n_event_kinds)//'): index ' &
                //itoa(e%index)//', value'//fixed(e%value, 12, 4)//', limit'//fixed(e%limit, 12, 4)
      end select
      if (event_is_note(e%kind)) text = 'note: '//text
   end function event_description

end module event_text
