!> Report C.8: the criteria by which a study judges each of its runs -
!! "the undesired contact end-of-program test, the injury criteria for the
!! torso and neck, and/or large forces in the belts themselves", and those
!! users now expect beside them (HIC, the chest's 3 ms clip, the head's
!! excursion) - as named numbers taken from a finished run's summary.
!!
!! A fixed list: each criterion has a deck word (at most 8 characters,
!! upper case: criterion_words, for a card field), a CSV column (lower
!! case), a unit, a one-line meaning and the report section it comes from.
!! Its value for one occupant is criterion_value (real, in its unit; the
!! same number the listing prints where the listing prints it). A code
!! never changes its meaning; a new criterion takes the next index
!! (docs/modification.md).
!!
!! Neck and torso (C.4.f, figure 26, Table 5): the loads are computed only
!! when the occupant's *INJURY gives some limit (docs/injury.md); without
!! one NECKF, NECKINJ and TORSOINJ are 0. The torso's criteria are those of
!! Table 5 rows 1-3 (the spine: the lower, centre and upper spine's
!! compression and shear, the spine joints' tension - the lower and upper
!! spine joints, 2 and 3; not the hip, which joins the leg) and rows 5 and
!! 6 (the back's and the ribs' shear, from the upper back's and the
!! chest's contacts); the neck's is joint 4's tension (Table 5 has no
!! compression or shear of the neck itself; the skull's shear is a head
!! contact's). A ratio is the load over its limit: 1 or more is an injury.
module study_criteria
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp, g_std
   use strings, only: upper
   use run_summary, only: run_summary_t, occupant_summary_t
   use end_tests, only: end_injury, end_contact, end_rest
   use joint_dislocation, only: event_dislocation_low, event_dislocation_high
   use force_injuries, only: event_tension, fc_defined, fs_defined
   use analog_model, only: analog_solution_t, critical_damping
   implicit none
   private

   public :: n_criteria, criterion_words, criterion_word, criterion_column, criterion_unit, criterion_meaning
   public :: criterion_section, criterion_index, criterion_value
   public :: crit_hic15, crit_hic36, crit_headg, crit_headgsi, crit_chestg, crit_chestgsi, crit_clip3ms, crit_headx, &
             crit_beltf, crit_lapf, crit_torsof, crit_neckf, crit_neckinj, crit_torsoinj, crit_unwanted, crit_injury, &
             crit_disloc, crit_ended
   public :: n_analog_criteria, analog_criterion_words, analog_criterion_index, analog_criterion_value
   public :: analog_criterion_word, analog_criterion_column, analog_criterion_unit, analog_criterion_meaning
   public :: acrit_meet, acrit_tmeet, acrit_sepmin, acrit_overlap, acrit_cdamp
   public :: word_column, word_unit

   !> The criteria's indices (their order in every table).
   integer, parameter :: crit_hic15 = 1, crit_hic36 = 2, crit_headg = 3, crit_headgsi = 4, crit_chestg = 5, &
                         crit_chestgsi = 6, crit_clip3ms = 7, crit_headx = 8, crit_beltf = 9, crit_lapf = 10, &
                         crit_torsof = 11, crit_neckf = 12, crit_neckinj = 13, crit_torsoinj = 14, &
                         crit_unwanted = 15, crit_injury = 16, crit_disloc = 17, crit_ended = 18
   integer, parameter :: n_criteria = 18

   !> Section D's analog (docs/analog.md): the criteria of a run that is an
   !! analog case, a list of their own (an analog run has no occupant model:
   !! none of the 18 above applies to it). MEET: 1 when the occupants meet
   !! before TMAX, else 0; TMEET: s, when they first meet (NaN when they
   !! never do); SEPMIN: in, their least separation over the run (0 or less
   !! once they meet: the scan's overlap); OVERLAP: in, how deep they pass
   !! into each other, max(0, -SEPMIN) (a limit is "at most": OVERLAP LIMIT
   !! 0 keeps them apart, a limit that grows with the overlap, as OPTIMIZE's
   !! penalty needs, where MEET's steps from 0 to 1); CDAMP: lb*s/in, the
   !! harness's damper c of the run (ZETA times critical, SD-2: an input, a
   !! criterion so that OPTIMIZE can minimise it: the least damping that
   !! keeps the occupants apart).
   integer, parameter :: acrit_meet = 1, acrit_tmeet = 2, acrit_sepmin = 3, acrit_overlap = 4, acrit_cdamp = 5
   integer, parameter :: n_analog_criteria = 5
   character(len=*), parameter :: analog_criterion_words = 'MEET|TMEET|SEPMIN|OVERLAP|CDAMP'
   character(len=8), parameter :: analog_words(n_analog_criteria) = [character(len=8) :: 'MEET', 'TMEET', 'SEPMIN', &
      'OVERLAP', 'CDAMP']
   character(len=9), parameter :: analog_columns(n_analog_criteria) = [character(len=9) :: 'meet', 't_meet', &
      'sep_min', 'overlap', 'c_damp']
   character(len=7), parameter :: analog_units(n_analog_criteria) = [character(len=7) :: '0/1', 's', 'in', 'in', &
      'lb*s/in']
   character(len=100), parameter :: analog_meanings(n_analog_criteria) = [character(len=100) :: &
      '1 when the occupants meet before TMAX, else 0', &
      'when the occupants first meet (NaN: never)', &
      'least separation of the occupants (0 or less: they meet)', &
      'how deep the occupants pass into each other, max(0, -SEPMIN)', &
      'the harness''s damper c of the run (ZETA times critical)']

   !> The deck words in the list's order, '|' between them (for a card
   !! field's word list; test_study_criteria checks it against criterion_word).
   character(len=*), parameter :: criterion_words = 'HIC15|HIC36|HEADG|HEADGSI|CHESTG|CHESTGSI|CLIP3MS|HEADX|' &
                                                    //'BELTF|LAPF|TORSOF|NECKF|NECKINJ|TORSOINJ|UNWANTED|INJURY|' &
                                                    //'DISLOC|ENDED'

   character(len=8), parameter :: words(n_criteria) = [character(len=8) :: 'HIC15', 'HIC36', 'HEADG', 'HEADGSI', &
      'CHESTG', 'CHESTGSI', 'CLIP3MS', 'HEADX', 'BELTF', 'LAPF', 'TORSOF', 'NECKF', 'NECKINJ', 'TORSOINJ', &
      'UNWANTED', 'INJURY', 'DISLOC', 'ENDED']
   character(len=9), parameter :: columns(n_criteria) = [character(len=9) :: 'hic15', 'hic36', 'head_g', &
      'head_gsi', 'chest_g', 'chest_gsi', 'clip3ms', 'head_x', 'belt_f', 'lap_f', 'torso_f', 'neck_f', &
      'neck_inj', 'torso_inj', 'undesired', 'injuries', 'disloc', 'ended']
   character(len=5), parameter :: units(n_criteria) = [character(len=5) :: '-', '-', 'g', '-', 'g', '-', 'g', 'in', &
      'lb', 'lb', 'lb', 'lb', '-', '-', 'count', 'count', 'count', '0/1']
   character(len=*), parameter :: sec_acc = 'C.6 (head and chest accelerations); docs/injury.md'
   character(len=60), parameter :: sections(n_criteria) = [character(len=60) :: sec_acc, sec_acc, &
      'C.6 (head acceleration)', sec_acc, 'C.6 (chest acceleration)', sec_acc, sec_acc, &
      'C.6 (positions relative to the interior), C.8', 'C.4.e, C.8 (large forces in the belts)', &
      'C.4.e, C.8', 'C.4.e, C.8', 'C.4.f (f.5, figure 26), Table 5, C.8', &
      'C.4.f (figure 26), Table 5, C.8', 'C.4.f (figure 26), Table 5, C.8', &
      'C.4.f (Table 9, figure 20), C.7 (NEND = 2), C.8', 'C.4.c (figure 10), C.4.f (figures 20, 26), C.7', &
      'C.4.c (figure 10), C.4.f (Table 5 FTD)', 'C.7']
   character(len=120), parameter :: meanings(n_criteria) = [character(len=120) :: &
      'head injury criterion over windows up to 15 ms (0 where none was computed)', &
      'head injury criterion over windows up to 36 ms (0 where none was computed)', &
      'largest resultant acceleration of the head centre of gravity', &
      'Gadd severity index of the head acceleration', &
      'largest resultant acceleration of the chest centre of gravity', &
      'Gadd severity index of the chest acceleration', &
      'chest 3 ms clip: the level exceeded for a cumulative 3 ms (FMVSS 208)', &
      'largest forward x displacement of the head centre of gravity relative to the interior from t = 0', &
      'largest tension of any belt section (0 without belts)', &
      'largest tension of the lap belt (either side; 0 without one)', &
      'largest tension of the torso belt (either section; 0 without one)', &
      'largest tension FT_4 at the neck joint (0 when *INJURY gives no limit)', &
      'largest neck tension over its limit FTD_4 (0 without that limit; 1 or more: an injury)', &
      'largest torso load of Table 5 over its limit (spine, back, ribs; 0 without a limit; 1 or more: an injury)', &
      'number of undesired contacts (Table 9)', &
      'number of injury events (dislocations, Table 5 force criteria, cut on broken glass)', &
      'number of joint dislocations (relative angle, figure 10; tension, Table 5 FTD)', &
      '1 when an end test (injury, undesired contact, rest) ended the run before TMAX, else 0']

   !> Table 5: the neck joint; the torso's spine joints and bones, back and rib.
   integer, parameter :: neck_joint = 4
   integer, parameter :: torso_joints(2) = [2, 3]
   integer, parameter :: torso_fc(3) = [1, 2, 3]
   integer, parameter :: torso_fs(5) = [1, 2, 3, 5, 6]

contains

   !> Criterion i's deck word (upper case, at most 8 characters).
   pure function criterion_word(i) result(w)
      integer, intent(in) :: i
      character(len=:), allocatable :: w
      w = trim(words(i))
   end function criterion_word

   !> Criterion i's column in a results table (lower case).
   pure function criterion_column(i) result(c)
      integer, intent(in) :: i
      character(len=:), allocatable :: c
      c = trim(columns(i))
   end function criterion_column

   !> Criterion i's unit ('-' for a number without one).
   pure function criterion_unit(i) result(u)
      integer, intent(in) :: i
      character(len=:), allocatable :: u
      u = trim(units(i))
   end function criterion_unit

   !> What criterion i means, in one line.
   pure function criterion_meaning(i) result(m)
      integer, intent(in) :: i
      character(len=:), allocatable :: m
      m = trim(meanings(i))
   end function criterion_meaning

   !> The report's sections criterion i comes from.
   pure function criterion_section(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      s = trim(sections(i))
   end function criterion_section

   !> The index of the criterion whose deck word is word (any case, blanks
   !! around it ignored); 0 when there is none.
   pure integer function criterion_index(word) result(i)
      character(len=*), intent(in) :: word
      character(len=len(word)) :: w
      w = upper(adjustl(word))
      do i = 1, n_criteria
         if (trim(w) == trim(words(i))) return
      end do
      i = 0
   end function criterion_index

   !> Criterion i of occupant `occupant` of the finished run `summary`, in
   !! its unit (criterion_unit). Not a number when i is not a criterion or
   !! the summary has no such occupant (a caller's mistake).
   pure function criterion_value(summary, i, occupant) result(v)
      type(run_summary_t), intent(in) :: summary
      integer, intent(in) :: i, occupant
      real(wp) :: v
      v = ieee_value(v, ieee_quiet_nan)
      if (i < 1 .or. i > n_criteria .or. .not. allocated(summary%occ)) return
      if (occupant < 1 .or. occupant > size(summary%occ)) return
      associate (os => summary%occ(occupant))
         select case (i)
         case (crit_hic15)
            v = hic_value(os, 15)
         case (crit_hic36)
            v = hic_value(os, 36)
         case (crit_headg)
            v = os%head_max%value/g_std      ! as the listing's maxima
         case (crit_headgsi)
            v = os%head_criteria%gsi
         case (crit_chestg)
            v = os%chest_max%value/g_std
         case (crit_chestgsi)
            v = os%chest_criteria%gsi
         case (crit_clip3ms)
            v = os%chest_criteria%clip3ms()
         case (crit_headx)
            v = os%head_excursion%value
         case (crit_beltf)
            v = largest_tension(os, '')
         case (crit_lapf)
            v = largest_tension(os, 'lap')
         case (crit_torsof)
            v = largest_tension(os, 'torso')
         case (crit_neckf)
            v = 0.0_wp
            if (os%force_checked) v = os%ft_max(neck_joint)%value
         case (crit_neckinj)
            v = 0.0_wp
            if (os%force_checked) v = ratio(os%ft_max(neck_joint)%value, os%force_limits%f_tension(neck_joint))
         case (crit_torsoinj)
            v = torso_ratio(os)
         case (crit_unwanted)
            v = real(count_events(summary, occupant, i), wp)
         case (crit_injury)
            v = real(count_events(summary, occupant, i), wp)
         case (crit_disloc)
            v = real(count_events(summary, occupant, i), wp)
         case (crit_ended)
            v = merge(1.0_wp, 0.0_wp, any(summary%end_reason == [end_injury, end_contact, end_rest]))
         end select
      end associate
   end function criterion_value

   !> HIC over windows up to 15 or 36 ms (0 where none was computed).
   pure real(wp) function hic_value(os, window) result(v)
      type(occupant_summary_t), intent(in) :: os
      integer, intent(in) :: window
      v = 0.0_wp
      if (.not. os%head_criteria%with_hic) return
      if (window == 15) then
         associate (r => os%head_criteria%hic15())
            v = r%value
         end associate
      else
         associate (r => os%head_criteria%hic36())
            v = r%value
         end associate
      end if
   end function hic_value

   !> The largest tension of the belt sections whose names begin with
   !! prefix (belt_forces' study peaks, <label>_tension: 'lap...',
   !! 'torso...'; '' any); 0 when there is none.
   pure real(wp) function largest_tension(os, prefix) result(v)
      type(occupant_summary_t), intent(in) :: os
      character(len=*), intent(in) :: prefix
      integer :: k, n
      v = 0.0_wp
      if (.not. allocated(os%study_peaks)) return
      do k = 1, size(os%study_peaks)
         associate (p => os%study_peaks(k))
            n = len_trim(p%name)
            if (n < 8) cycle
            if (p%name(n - 7:n) /= '_tension' .or. index(p%name, prefix) /= 1) cycle
            v = max(v, p%value)
         end associate
      end do
   end function largest_tension

   !> A load over its limit; 0 where no limit is given; the largest number
   !! where the quotient would overflow (a limit the deck gives absurdly
   !! small: never an overflow, which the tests' build traps).
   pure real(wp) function ratio(load, limit)
      real(wp), intent(in) :: load, limit
      ratio = 0.0_wp
      if (.not. limit > 0.0_wp) return
      ratio = sign(huge(1.0_wp), load)
      ! (Fortran's .or. need not stop at its first operand: nested)
      if (limit >= 1.0_wp) then
         ratio = load/limit
      else if (abs(load) < limit*huge(1.0_wp)) then
         ratio = load/limit
      end if
   end function ratio

   !> The largest of the torso's Table 5 loads over their limits (the
   !! module's header); 0 when the deck gives none of those limits.
   pure real(wp) function torso_ratio(os) result(v)
      type(occupant_summary_t), intent(in) :: os
      integer :: k
      v = 0.0_wp
      if (.not. os%force_checked) return
      associate (lim => os%force_limits)
         do k = 1, size(torso_joints)
            v = max(v, ratio(os%ft_max(torso_joints(k))%value, lim%f_tension(torso_joints(k))))
         end do
         do k = 1, size(torso_fc)
            if (fc_defined(torso_fc(k))) v = max(v, ratio(os%fc_max(torso_fc(k))%value, lim%f_compression(torso_fc(k))))
         end do
         do k = 1, size(torso_fs)
            if (fs_defined(torso_fs(k))) v = max(v, ratio(os%fs_max(torso_fs(k))%value, lim%f_shear(torso_fs(k))))
         end do
      end associate
   end function torso_ratio

   !> The number of occupant o's events that criterion i counts.
   pure integer function count_events(summary, o, i) result(n)
      type(run_summary_t), intent(in) :: summary
      integer, intent(in) :: o, i
      integer :: k
      n = 0
      if (.not. allocated(summary%events)) return
      do k = 1, summary%n_events
         associate (e => summary%events(k))
            if (e%occupant /= o) cycle
            select case (i)
            case (crit_unwanted)
               if (e%undesired) n = n + 1
            case (crit_injury)
               if (e%injury) n = n + 1
            case (crit_disloc)
               if (any(e%kind == [event_dislocation_low, event_dislocation_high, event_tension])) n = n + 1
            end select
         end associate
      end do
   end function count_events

   !> The analog criterion's index of a deck word (any case, blanks around
   !! it ignored; 0: not one).
   pure integer function analog_criterion_index(word) result(code)
      character(len=*), intent(in) :: word
      integer :: k
      code = 0
      do k = 1, n_analog_criteria
         if (trim(analog_words(k)) == upper(trim(adjustl(word)))) code = k
      end do
   end function analog_criterion_index

   !> Analog criterion i's deck word.
   pure function analog_criterion_word(i) result(w)
      integer, intent(in) :: i
      character(len=:), allocatable :: w
      w = trim(analog_words(i))
   end function analog_criterion_word

   !> Analog criterion i's column in a results table.
   pure function analog_criterion_column(i) result(c)
      integer, intent(in) :: i
      character(len=:), allocatable :: c
      c = trim(analog_columns(i))
   end function analog_criterion_column

   !> Analog criterion i's unit.
   pure function analog_criterion_unit(i) result(u)
      integer, intent(in) :: i
      character(len=:), allocatable :: u
      u = trim(analog_units(i))
   end function analog_criterion_unit

   !> What analog criterion i means, in one line.
   pure function analog_criterion_meaning(i) result(m)
      integer, intent(in) :: i
      character(len=:), allocatable :: m
      m = trim(analog_meanings(i))
   end function analog_criterion_meaning

   !> The table's column of a criterion's deck word, of either list ('' for
   !! a word of neither).
   pure function word_column(word) result(c)
      character(len=*), intent(in) :: word
      character(len=:), allocatable :: c
      c = ''
      if (criterion_index(word) > 0) then
         c = criterion_column(criterion_index(word))
      else if (analog_criterion_index(word) > 0) then
         c = analog_criterion_column(analog_criterion_index(word))
      end if
   end function word_column

   !> The unit of a criterion's deck word, of either list ('' for a word of
   !! neither).
   pure function word_unit(word) result(u)
      character(len=*), intent(in) :: word
      character(len=:), allocatable :: u
      u = ''
      if (criterion_index(word) > 0) then
         u = criterion_unit(criterion_index(word))
      else if (analog_criterion_index(word) > 0) then
         u = analog_criterion_unit(analog_criterion_index(word))
      end if
   end function word_unit

   !> The value of analog criterion `code` of a solved analog case (Section
   !! D: find_contacts' first contact and least separation; the damper c as
   !! the case's parameter table gives it, SD-2).
   real(wp) function analog_criterion_value(sol, code) result(v)
      type(analog_solution_t), intent(in) :: sol
      integer, intent(in) :: code
      select case (code)
      case (acrit_meet)
         v = merge(1.0_wp, 0.0_wp, sol%n_contact > 0)
      case (acrit_tmeet)
         if (sol%n_contact > 0) then
            v = sol%contact(1)%t_begin
         else
            v = ieee_value(v, ieee_quiet_nan)
         end if
      case (acrit_sepmin)
         v = sol%min_gap
      case (acrit_overlap)
         v = max(0.0_wp, -sol%min_gap)
      case (acrit_cdamp)
         v = sol%c%zeta*critical_damping(sol%c)
      case default
         v = ieee_value(v, ieee_quiet_nan)
      end select
   end function analog_criterion_value
end module study_criteria
