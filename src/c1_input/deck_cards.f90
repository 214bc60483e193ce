!> The one table of card layouts (report C.1: "parameters grouped according
!! to type ... any one section can be changed by simply substituting new data
!! cards"). Parsing, validation of single fields, the deck echo in the listing
!! and docs/deck-format.md are all driven by this table, so they cannot
!! disagree.
!!
!! Card conventions (docs/deck-format.md): 80-column card images; a card with
!! '*' in column 1 opens a card group; '$' in column 1 is a comment; blank
!! cards are ignored. Data cards have up to seven fields of ten columns in
!! columns 3-72 (field k in columns 10k-7 .. 10k+2); columns 1-2 hold the row
!! index of indexed groups and are blank otherwise; columns 73-80 are free
!! for card identification and are ignored.
module deck_cards
   use kinds, only: wp, deg, g_std
   use loading_parameters, only: max_order
   use model, only: max_curves, n_belt_section, n_belt_card, max_plot_times
   implicit none
   private

   public :: field_spec_t, group_spec_t, card_table, find_group
   public :: max_fields, index_first_col, index_last_col, data_last_col, card_width
   public :: kind_real, kind_int, kind_word, kind_text
   public :: blank_default, blank_required, blank_absent
   public :: layout_single, layout_indexed, layout_list, layout_multi
   public :: field_first_col, field_last_col
   public :: g_title, g_options, g_time, g_segments, g_joints, g_restraints, g_stopcurve
   public :: g_injury, g_arcs, g_initial, g_vehicle, g_gravity, g_pulse, g_pulserates
   public :: g_pulsepos, g_pulsefile, g_endtests, g_numerics, g_materials, n_groups
   public :: g_surfaces, g_interior, g_contactoff
   public :: g_loadpoly, g_loadrate, g_loadtable, g_beltloading
   public :: g_seat, g_seatsprings, g_seatbeam, g_seatbeaminit, g_seatbeams
   public :: g_belts, g_beltoptions
   public :: g_study, g_vary, g_values, g_criteria, study_methods, max_study_variables, criterion_word_list
   public :: g_fmvss, g_pulsemme, g_analog, g_printerplot

   integer, parameter :: max_fields = 7
   integer, parameter :: card_width = 80
   integer, parameter :: index_first_col = 1, index_last_col = 2
   integer, parameter :: data_last_col = 72

   !> Field kinds.
   integer, parameter :: kind_real = 1, kind_int = 2, kind_word = 3, kind_text = 4
   !> What a blank field means.
   integer, parameter :: blank_default = 1   !< takes the documented default
   integer, parameter :: blank_required = 2  !< an error: the field must be given
   integer, parameter :: blank_absent = 3    !< "not available" (the model decides)
   !> Group layouts.
   integer, parameter :: layout_single = 1   !< exactly one card
   integer, parameter :: layout_indexed = 2  !< one card per index 1..max_index
   integer, parameter :: layout_list = 3     !< a list of cards, no index (tables)
   integer, parameter :: layout_multi = 4    !< a list of cards, each with an index

   !> Group identifiers (positions in the table).
   integer, parameter :: g_title = 1, g_options = 2, g_time = 3, g_segments = 4, &
      g_joints = 5, g_restraints = 6, g_stopcurve = 7, g_injury = 8, g_arcs = 9, &
      g_initial = 10, g_vehicle = 11, g_gravity = 12, g_pulse = 13, g_pulserates = 14, &
      g_pulsepos = 15, g_pulsefile = 16, g_endtests = 17, g_numerics = 18, g_materials = 19
   !> Loading curves (C.4.e, C.4.f; docs/loading.md).
   integer, parameter :: g_loadpoly = 20, g_loadrate = 21, g_loadtable = 22, g_beltloading = 23
   !> The seat, C.4.d (docs/seat.md).
   integer, parameter :: g_seat = 24, g_seatsprings = 25, g_seatbeam = 26, g_seatbeaminit = 27, g_seatbeams = 28
   !> Belts (C.4.e, Table 2; docs/belts.md).
   integer, parameter :: g_belts = 29, g_beltoptions = 30
   !> The interior's contact surfaces (C.4.f; docs/contacts.md).
   integer, parameter :: g_surfaces = 31, g_interior = 32, g_contactoff = 33
   !> A study: the program varies its own inputs (C.8; docs/modification.md).
   integer, parameter :: g_study = 34, g_vary = 35, g_values = 36, g_criteria = 37
   !> FMVSS 208's limits for the summary's table (issue 18; docs/injury.md).
   integer, parameter :: g_fmvss = 38
   !> The pulse from an ISO-MME data set (ISO/TS 13499; docs/pulse.md).
   integer, parameter :: g_pulsemme = 39
   !> Section D's two-occupant analog, a deck of its own (docs/analog.md).
   integer, parameter :: g_analog = 40
   !> The listing's printer plots (C.6; issue 18).
   integer, parameter :: g_printerplot = 41
   integer, parameter :: n_groups = 41

   !> C.8's methods, in the order of *STUDY's METHOD words.
   character(len=*), parameter :: study_methods = 'OAT|GRID|RANDOM|LHS|ENSEMBLE|OPTIMIZE'
   !> The evaluation criteria a study may judge a run by: the occupant
   !! simulation's, then Section D analog's (c8_modification's study_criteria
   !! holds each one's meaning; test_study_criteria checks the two agree).
   character(len=*), parameter :: criterion_word_list = &
      'HIC15|HIC36|HEADG|HEADGSI|CHESTG|CHESTGSI|CLIP3MS|HEADX|BELTF|LAPF|TORSOF|NECKF|NECKINJ|TORSOINJ|' &
      //'UNWANTED|INJURY|DISLOC|ENDED|MEET|TMEET|SEPMIN|OVERLAP|CDAMP'
   integer, parameter :: max_study_variables = 20

   !> One field of a card.
   type :: field_spec_t
      character(len=8) :: name = ' '
      integer :: kind = kind_real
      integer :: first_col = 0, last_col = 0
      character(len=12) :: unit = ' '       !< unit as written in the deck
      real(wp) :: scale = 1.0_wp            !< deck unit -> internal unit
      integer :: blank = blank_default
      real(wp) :: default = 0.0_wp          !< in deck units
      real(wp) :: low = -huge(1.0_wp), high = huge(1.0_wp) !< valid range, deck units
      logical :: low_open = .false.         !< the range excludes low
      character(len=400) :: words = ' '     !< allowed words, separated by '|' (*VARY GROUP: every group's name)
      character(len=72) :: meaning = ' '
   end type field_spec_t

   !> One card group.
   type :: group_spec_t
      character(len=16) :: name = ' '
      character(len=16) :: kind = ' '   !< a later group of the same kind replaces an earlier one
      integer :: layout = layout_single
      integer :: max_index = 0          !< indexed/multi: valid indices 1..max_index
      logical :: all_rows = .false.     !< indexed: every index must be given
      logical :: required = .false.     !< the deck must hold this group
      integer :: min_cards = 1
      integer :: max_cards = 1
      character(len=12) :: index_name = ' '
      integer :: n_fields = 0
      type(field_spec_t) :: field(max_fields)
      character(len=72) :: title = ' '
      character(len=1200) :: note = ' '
   end type group_spec_t

contains

   !> First column of data field k.
   pure integer function field_first_col(k)
      integer, intent(in) :: k
      field_first_col = 10*k - 7
   end function field_first_col

   !> Last column of data field k.
   pure integer function field_last_col(k)
      integer, intent(in) :: k
      field_last_col = 10*k + 2
   end function field_last_col

   !> The index of the group called name (blanks and case ignored), or 0.
   pure integer function find_group(table, name)
      type(group_spec_t), intent(in) :: table(:)
      character(len=*), intent(in) :: name
      integer :: i
      find_group = 0
      do i = 1, size(table)
         if (table(i)%name == ' ') cycle   ! (a number not yet given to a group)
         if (table(i)%name == name) then
            find_group = i
            return
         end if
      end do
   end function find_group

   ! --- field constructors -------------------------------------------------

   pure function real_field(name, unit, scale, blank, default, low, high, meaning, low_open) result(f)
      character(len=*), intent(in) :: name, unit, meaning
      real(wp), intent(in) :: scale, default, low, high
      integer, intent(in) :: blank
      logical, intent(in), optional :: low_open
      type(field_spec_t) :: f
      f%name = name
      f%kind = kind_real
      f%unit = unit
      f%scale = scale
      f%blank = blank
      f%default = default
      f%low = low
      f%high = high
      f%meaning = meaning
      if (present(low_open)) f%low_open = low_open
   end function real_field

   pure function int_field(name, blank, default, low, high, meaning) result(f)
      character(len=*), intent(in) :: name, meaning
      integer, intent(in) :: blank, default, low, high
      type(field_spec_t) :: f
      f%name = name
      f%kind = kind_int
      f%unit = '-'
      f%blank = blank
      f%default = real(default, wp)
      f%low = real(low, wp)
      f%high = real(high, wp)
      f%meaning = meaning
   end function int_field

   pure function word_field(name, words, blank, meaning) result(f)
      character(len=*), intent(in) :: name, words, meaning
      integer, intent(in) :: blank
      type(field_spec_t) :: f
      f%name = name
      f%kind = kind_word
      f%unit = '-'
      f%blank = blank
      f%words = words
      f%meaning = meaning
   end function word_field

   pure function text_field(name, blank, meaning) result(f)
      character(len=*), intent(in) :: name, meaning
      integer, intent(in) :: blank
      type(field_spec_t) :: f
      f%name = name
      f%kind = kind_text
      f%unit = '-'
      f%blank = blank
      f%meaning = meaning
      f%first_col = 1
      f%last_col = data_last_col
   end function text_field

   !> Place the data fields of a group at their columns (text fields keep theirs).
   pure subroutine set_fields(g, fields)
      type(group_spec_t), intent(inout) :: g
      type(field_spec_t), intent(in) :: fields(:)
      integer :: k
      g%n_fields = size(fields)
      do k = 1, size(fields)
         g%field(k) = fields(k)
         if (fields(k)%kind /= kind_text) then
            g%field(k)%first_col = field_first_col(k)
            g%field(k)%last_col = field_last_col(k)
         end if
      end do
   end subroutine set_fields

   !> The card table. Report references: C.1 and Tables 1-6 for the body,
   !! C.3 for the time controls and vehicle tables, C.7 for the end tests.
   pure function card_table() result(t)
      type(group_spec_t) :: t(n_groups)
      ! an upper bound on magnitudes that keeps every product of the model far
      ! from overflow (the divergence guard of equations_of_motion relies on it)
      real(wp), parameter :: big = 1.0e12_wp, one = 1.0_wp, zero = 0.0_wp
      ! masses and inertias below this (a few thousandths of an ounce) would let
      ! the accelerations of the model overflow before any guard sees them
      real(wp), parameter :: small_mass = 1.0e-6_wp

      t(g_title)%name = 'TITLE'
      t(g_title)%title = 'Run title, printed at the head of every page'
      t(g_title)%note = 'A header with no data card, or a blank one, gives an empty title.'
      call set_fields(t(g_title), [text_field('TITLE', blank_default, 'title text (columns 1-72)')])

      t(g_options)%name = 'OPTIONS'
      t(g_options)%title = 'Program options (C.1)'
      t(g_options)%note = 'NBELT selects the belts (C.4.e): their geometry is *BELTS, their loading ' &
         //'*BELTLOADING, their options *BELTOPTIONS. NLOAD selects the loading curves the deck gives: *LOADPOLY (1) or ' &
         //'*LOADTABLE (2). NBODY selects the contacts of Tables 7 and 8 among the surfaces *SURFACES describes. ' &
         //'NEND: 1 time, 2 time or an undesired contact of Table 9 (one must be among the assembled pairs), ' &
         //'3 time or an injury (a dislocation, or a force of Table 5 past its *INJURY limit), 4 time or rest.'
      call set_fields(t(g_options), [ &
         int_field('NBODY', blank_default, 1, 1, 3, 'occupant: 1 driver, 2 front-seat passenger, 3 rear-seat passenger'), &
         int_field('NBELT', blank_default, 0, 0, 3, 'belts: 0 none, 1 lap, 2 torso, 3 lap and torso (C.4.e)'), &
         int_field('NEND', blank_default, 1, 1, 4, 'end test: 1 time, 2 +undesired contact, 3 +injury, 4 +rest'), &
         int_field('NLOAD', blank_default, 1, 1, 2, 'loading curves: 1 polynomial, 2 tabulated'), &
         int_field('NOUT', blank_default, 2, 0, 3, 'output: 0 summary, 1 +accelerations/energies, 2 +body, 3 all'), &
         int_field('NINT', blank_default, 2, 1, 3, 'integrator: 1 Adams-Moulton (report), 2 RK4, 3 Dormand-Prince')])

      t(g_time)%name = 'TIME'
      t(g_time)%title = 'Time controls (C.3, C.6, C.7)'
      t(g_time)%note = 'For the fixed-step integrators (NINT 1, 2) TMAX and DTPRINT must be whole multiples ' &
         //'of DT. For NINT 3, DT is the first trial step and the step never exceeds DTPRINT. RTOL is at ' &
         //'least 1e-14 (RTOL = 0 is refused): some 50 times the rounding of a double, below which the error ' &
         //'estimate of a step is itself rounding and a tighter tolerance would only shrink the step.' &
         //' A fixed-step run estimates its error and warns when DT is too large for the deck, and when the ' &
         //'corrector reached CITER (docs/accuracy.md).'
      call set_fields(t(g_time), [ &
         real_field('TMAX', 's', one, blank_default, 0.2_wp, zero, 1.0e3_wp, 'duration of the run', .true.), &
         real_field('DT', 's', one, blank_default, 1.0e-4_wp, zero, 1.0_wp, 'integration step', .true.), &
         real_field('DTPRINT', 's', one, blank_default, 5.0e-3_wp, zero, 1.0e3_wp, 'print interval', .true.), &
         real_field('CTOL', '-', one, blank_default, 1.0e-6_wp, zero, 1.0_wp, &
            'corrector tolerance (relative to max(1,|y|))', .true.), &
         int_field('CITER', blank_default, 10, 1, 1000, 'corrector iteration limit'), &
         real_field('RTOL', '-', one, blank_default, 1.0e-7_wp, 1.0e-14_wp, 1.0_wp, &
            'adaptive relative tolerance (1e-14 at least)'), &
         real_field('ATOL', '-', one, blank_default, 1.0e-9_wp, zero, 1.0_wp, 'adaptive absolute tolerance', .true.)])

      t(g_segments)%name = 'SEGMENTS'
      t(g_segments)%title = 'Body segments, Table 1 (i as in Table 5)'
      t(g_segments)%layout = layout_indexed
      t(g_segments)%max_index = 8
      t(g_segments)%all_rows = .true.
      t(g_segments)%required = .true.
      t(g_segments)%index_name = 'segment i'
      t(g_segments)%note = 'L3 and L4 are the neck and shoulder offsets along segment 3 from the upper-spine ' &
         //'joint; L6 and L8 are used by contacts only. RHO is measured from the segment''s proximal joint ' &
         //'(the hip for segments 1 and 7, the knee for 8).'
      call set_fields(t(g_segments), [ &
         real_field('M', 'lb*s^2/in', one, blank_required, zero, small_mass, big, 'mass m_i'), &
         real_field('I', 'lb*in*s^2', one, blank_required, zero, small_mass, big, 'moment of inertia I_i about the CG'), &
         real_field('L', 'in', one, blank_default, zero, zero, big, 'link length L_i'), &
         real_field('RHO', 'in', one, blank_required, zero, zero, big, 'distance rho_i from the joint to the CG')])

      t(g_joints)%name = 'JOINTS'
      t(g_joints)%title = 'Body joints, Table 1 (i as in Table 5; partner m(i) as in Table 6)'
      t(g_joints)%layout = layout_indexed
      t(g_joints)%max_index = 7
      t(g_joints)%all_rows = .true.
      t(g_joints)%required = .true.
      t(g_joints)%index_name = 'joint i'
      t(g_joints)%note = 'Joint i couples segments i and m(i) = 7,1,2,3,3,5,8; its relative angle is ' &
         //'alpha_i - alpha_m. The stops act beyond OMEGA and BOMEGA with restoring torque of slope ' &
         //'TLOW and THIGH (magnitudes); see *RESTRAINTS for cubic and tabulated forms.'
      call set_fields(t(g_joints), [ &
         real_field('K', 'in*lb/rad', one, blank_default, zero, zero, big, 'elasticity K_i'), &
         real_field('CF', 'in*lb', one, blank_default, zero, zero, big, 'Coulomb friction torque C''_i'), &
         real_field('XI', 'deg/s', deg, blank_default, 0.01_wp/deg, zero, big, 'friction velocity limit xi_i'), &
         real_field('OMEGA', 'deg', deg, blank_required, zero, -360.0_wp, 360.0_wp, 'lower stop angle omega_i'), &
         real_field('BOMEGA', 'deg', deg, blank_required, zero, -360.0_wp, 360.0_wp, 'upper stop angle Omega_i'), &
         real_field('TLOW', 'in*lb/rad', one, blank_default, zero, zero, big, 'lower stop stiffness T''_i'), &
         real_field('THIGH', 'in*lb/rad', one, blank_default, zero, zero, big, 'upper stop stiffness T-hat''_i')])

      t(g_restraints)%name = 'RESTRAINTS'
      t(g_restraints)%title = 'Form of the joint angular restraints (C.4.c, figure 9)'
      t(g_restraints)%layout = layout_indexed
      t(g_restraints)%max_index = 7
      t(g_restraints)%index_name = 'joint i'
      t(g_restraints)%note = 'A joint without a card here has the LINEAR form. CUBIC adds c2*d**2 + c3*d**3 ' &
         //'to the linear term, d being the penetration beyond the stop; TABLE takes the torque from ' &
         //'the *STOPCURVE cards of the joint. DISLOW and DISHIGH are the dislocation angles of figure 10 ' &
         //'(blank: the stop angles, as Table 1 defines omega and Omega).'
      call set_fields(t(g_restraints), [ &
         word_field('FORM', 'LINEAR|CUBIC|TABLE', blank_default, 'restraint form'), &
         real_field('C2LOW', 'in*lb/rad^2', one, blank_default, zero, zero, big, 'lower stop, quadratic coefficient'), &
         real_field('C3LOW', 'in*lb/rad^3', one, blank_default, zero, zero, big, 'lower stop, cubic coefficient'), &
         real_field('C2HIGH', 'in*lb/rad^2', one, blank_default, zero, zero, big, 'upper stop, quadratic coefficient'), &
         real_field('C3HIGH', 'in*lb/rad^3', one, blank_default, zero, zero, big, 'upper stop, cubic coefficient'), &
         real_field('DISLOW', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'lower dislocation angle'), &
         real_field('DISHIGH', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'upper dislocation angle')])
      t(g_restraints)%field(1)%default = real(1, wp)   ! word 1: LINEAR

      t(g_stopcurve)%name = 'STOPCURVE'
      t(g_stopcurve)%title = 'Tabulated restraint torques (C.4.c, figure 9)'
      t(g_stopcurve)%layout = layout_multi
      t(g_stopcurve)%max_index = 7
      t(g_stopcurve)%min_cards = 2
      t(g_stopcurve)%max_cards = 100000
      t(g_stopcurve)%index_name = 'joint i'
      t(g_stopcurve)%note = 'Points (depth, torque) of one side of a joint''s stop, depth increasing from 0; ' &
         //'between points the torque is interpolated linearly and beyond the last point extrapolated ' &
         //'along the last segment.'
      call set_fields(t(g_stopcurve), [ &
         word_field('SIDE', 'LOWER|UPPER', blank_required, 'which stop'), &
         real_field('DEPTH', 'deg', deg, blank_required, zero, zero, 360.0_wp, 'penetration beyond the stop'), &
         real_field('TORQUE', 'in*lb', one, blank_required, zero, zero, big, 'restoring torque magnitude')])

      t(g_injury)%name = 'INJURY'
      t(g_injury)%title = 'Force injury criteria, Table 1 (i as in Table 5)'
      t(g_injury)%layout = layout_indexed
      t(g_injury)%max_index = 10
      t(g_injury)%index_name = 'row i'
      t(g_injury)%note = 'Zero or blank means the criterion is not checked. Checked at every accepted step ' &
         //'against the forces from the solved dynamics (docs/injury.md): FTD against the tension of joint i ' &
         //'(1-7), FCF the compression of bone i (1-8 but 4), FSF the load across bone i from outside (1-9: ' &
         //'belts and seat across the spine and leg bones, the contacts of skull, back, ribs, lower leg and ' &
         //'face). The first passing of each is an injury event ' &
         //'(NEND 3 ends the run there).'
      call set_fields(t(g_injury), [ &
         real_field('FSF', 'lb', one, blank_default, zero, zero, big, 'shear fracture force'), &
         real_field('FCF', 'lb', one, blank_default, zero, zero, big, 'compression fracture force'), &
         real_field('FTD', 'lb', one, blank_default, zero, zero, big, 'tension dislocation force')])

      t(g_arcs)%name = 'ARCS'
      t(g_arcs)%title = 'Body contact arcs, Table 1 (i as in Table 5; 11 = ankle radius r_A)'
      t(g_arcs)%layout = layout_indexed
      t(g_arcs)%max_index = 11
      t(g_arcs)%index_name = 'arc i'
      t(g_arcs)%note = 'RHOP is used for arcs 2-4 and GAMMA for arcs 2-3 (Table 1). Their centres are the body ' &
                       //'points of the contacts (C.4.f).'
      call set_fields(t(g_arcs), [ &
         real_field('R', 'in', one, blank_default, zero, zero, big, 'contact arc radius r_i'), &
         real_field('RHOP', 'in', one, blank_default, zero, zero, big, 'distance rho''_i to the arc centre'), &
         real_field('GAMMA', 'deg', deg, blank_default, zero, -180.0_wp, 180.0_wp, 'angle gamma_i of the arc centre')])

      t(g_initial)%name = 'INITIAL'
      t(g_initial)%title = 'Initial body position (C.1), relative to the vehicle interior'
      t(g_initial)%layout = layout_indexed
      t(g_initial)%max_index = 8
      t(g_initial)%all_rows = .true.
      t(g_initial)%required = .true.
      t(g_initial)%index_name = 'segment i'
      t(g_initial)%note = 'Angles are measured counter-clockwise from the interior horizontal (x forward, y up). ' &
         //'The hip starts at the origin of the interior frame with the vehicle''s velocity.'
      call set_fields(t(g_initial), [ &
         real_field('THETA', 'deg', deg, blank_required, zero, -360.0_wp, 360.0_wp, 'angle Theta_i0'), &
         real_field('THETADOT', 'deg/s', deg, blank_default, zero, -1.0e6_wp, 1.0e6_wp, 'angular rate')])

      t(g_vehicle)%name = 'VEHICLE'
      t(g_vehicle)%title = 'Vehicle (C.1)'
      t(g_vehicle)%note = 'x is forward and y up; the pitch Phi is positive front end down. Initial ' &
         //'positions are zero; PHI0 is the initial pitch.'
      call set_fields(t(g_vehicle), [ &
         real_field('MASS', 'lb*s^2/in', one, blank_default, zero, zero, big, 'vehicle mass m_c'), &
         real_field('INERTIA', 'lb*in*s^2', one, blank_default, zero, zero, big, 'pitch moment of inertia I_c'), &
         real_field('XDOT0', 'in/s', one, blank_default, zero, -1.0e5_wp, 1.0e5_wp, 'initial forward velocity'), &
         real_field('YDOT0', 'in/s', one, blank_default, zero, -1.0e5_wp, 1.0e5_wp, 'initial vertical velocity'), &
         real_field('PHI0', 'deg', deg, blank_default, zero, -90.0_wp, 90.0_wp, 'initial pitch'), &
         real_field('PHIDOT0', 'deg/s', deg, blank_default, zero, -1.0e5_wp, 1.0e5_wp, 'initial pitch rate')])

      t(g_gravity)%name = 'GRAVITY'
      t(g_gravity)%title = 'Gravity'
      call set_fields(t(g_gravity), [ &
         real_field('G', 'in/s^2', one, blank_default, g_std, zero, 1.0e4_wp, 'acceleration of gravity')])

      t(g_pulse)%name = 'PULSE'
      t(g_pulse)%kind = 'PULSE'
      t(g_pulse)%title = 'Vehicle accelerations at times t_m (C.1, C.3)'
      t(g_pulse)%layout = layout_list
      t(g_pulse)%min_cards = 1
      t(g_pulse)%max_cards = 1000000
      t(g_pulse)%note = 'Times increase from 0. Between the t_m the accelerations are linear in time and ' &
         //'velocities and positions are their exact integrals; after the last t_m the last values hold. ' &
         //'*PULSEFILE gives the same table from a CSV file and replaces this group.'
      call set_fields(t(g_pulse), [ &
         real_field('T', 's', one, blank_required, zero, zero, 1.0e3_wp, 'time t_m'), &
         real_field('XDDOT', 'g', g_std, blank_default, zero, -1.0e4_wp, 1.0e4_wp, 'horizontal acceleration'), &
         real_field('YDDOT', 'g', g_std, blank_default, zero, -1.0e4_wp, 1.0e4_wp, 'vertical acceleration'), &
         real_field('PHIDDOT', 'deg/s^2', deg, blank_default, zero, -1.0e8_wp, 1.0e8_wp, 'pitch acceleration')])

      t(g_pulserates)%name = 'PULSERATES'
      t(g_pulserates)%title = 'Vehicle velocities at times t_m, where available (C.1, C.3)'
      t(g_pulserates)%layout = layout_list
      t(g_pulserates)%min_cards = 1
      t(g_pulserates)%max_cards = 1000000
      t(g_pulserates)%note = 'A column left blank on every card is not available and is integrated from the ' &
         //'accelerations; a column given replaces that integration (linear between the t_m). The inertial ' &
         //'forces still come from the accelerations, so a column should be their integral; at its knots it is ' &
         //'compared with the integral of the tables below it, against the largest speed of the tables and ' &
         //'integrals (for PHIDOT the largest pitch rate): a difference beyond 1 % is warned about with the ' &
         //'figures, one beyond 10 % (a unit, a column or a digit wrong) is a deck error. The energy balance ' &
         //'need not show such a difference.'
      call set_fields(t(g_pulserates), [ &
         real_field('T', 's', one, blank_required, zero, zero, 1.0e3_wp, 'time t_m'), &
         real_field('XDOT', 'in/s', one, blank_absent, zero, -1.0e5_wp, 1.0e5_wp, 'horizontal velocity'), &
         real_field('YDOT', 'in/s', one, blank_absent, zero, -1.0e5_wp, 1.0e5_wp, 'vertical velocity'), &
         real_field('PHIDOT', 'deg/s', deg, blank_absent, zero, -1.0e6_wp, 1.0e6_wp, 'pitch rate')])

      t(g_pulsepos)%name = 'PULSEPOSITIONS'
      t(g_pulsepos)%title = 'Vehicle positions at times t_m, where available (C.1, C.3)'
      t(g_pulsepos)%layout = layout_list
      t(g_pulsepos)%min_cards = 1
      t(g_pulsepos)%max_cards = 1000000
      t(g_pulsepos)%note = 'As *PULSERATES, for the displacements of the vehicle from its initial position.'
      call set_fields(t(g_pulsepos), [ &
         real_field('T', 's', one, blank_required, zero, zero, 1.0e3_wp, 'time t_m'), &
         real_field('X', 'in', one, blank_absent, zero, -1.0e6_wp, 1.0e6_wp, 'horizontal displacement'), &
         real_field('Y', 'in', one, blank_absent, zero, -1.0e6_wp, 1.0e6_wp, 'vertical displacement'), &
         real_field('PHI', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'pitch angle')])

      t(g_pulsefile)%name = 'PULSEFILE'
      t(g_pulsefile)%kind = 'PULSE'
      t(g_pulsefile)%title = 'Vehicle accelerations from a CSV file'
      t(g_pulsefile)%note = 'The file (an absolute path, or one relative to the directory of a deck that is a ' &
         //'regular file, or to the current directory for a deck read from standard input, a pipe, a FIFO or a ' &
         //'process substitution such as /dev/fd/63) holds lines ' &
         //'"t, xddot, yddot, phiddot" in s, g, g, deg/s^2; missing trailing columns are 0; lines ' &
         //'starting with # and a first line of column names are skipped. Replaces *PULSE.'
      call set_fields(t(g_pulsefile), [text_field('FILE', blank_required, 'CSV file name (columns 1-72)')])

      t(g_pulsemme)%name = 'PULSEMME'
      t(g_pulsemme)%kind = 'PULSE'
      t(g_pulsemme)%title = 'Vehicle accelerations from an ISO-MME data set (ISO/TS 13499)'
      t(g_pulsemme)%layout = layout_list
      t(g_pulsemme)%min_cards = 2
      t(g_pulsemme)%max_cards = 2
      t(g_pulsemme)%note = 'Two cards. Card 1: the data set''s .mme file (a path as *PULSEFILE''s); its channel ' &
         //'index and channel files are in the folder CHANNEL beside it. Card 2: in columns 1-20 the code of an ' &
         //'acceleration channel (dimension AC; direction X: XDDOT, positive forward; Z: YDDOT, the sign ' &
         //'reversed, ISO''s z pointing down), in columns 21-30 CFC, the channel class of the SAE J211 filter ' &
         //'applied (blank or 0: none; 60, 180, 600, 1000), in columns 31-40 T0 (s), the data set''s time taken ' &
         //'as the run''s t = 0 (blank: 0); samples before it are dropped, after filtering. Units g, m/s**2, ' &
         //'ft/s**2, in/s**2; NOVALUE samples inside the record are bridged linearly (an error beyond 1 ms). ' &
         //'Replaces *PULSE. docs/pulse.md.'
      call set_fields(t(g_pulsemme), [text_field('TEXT', blank_required, &
         'card 1: the .mme file; card 2: channel, CFC, T0')])

      t(g_endtests)%name = 'ENDTESTS'
      t(g_endtests)%title = 'End-of-program test thresholds (C.7)'
      t(g_endtests)%note = 'With NEND = 4 the run ends once every joint speed relative to the interior is ' &
         //'below VREST, every segment angular rate relative to the interior below WREST, for THOLD seconds.'
      call set_fields(t(g_endtests), [ &
         real_field('VREST', 'in/s', one, blank_default, 0.1_wp, zero, big, 'speed counted as rest', .true.), &
         real_field('WREST', 'deg/s', deg, blank_default, 0.5_wp, zero, big, 'angular rate counted as rest', .true.), &
         real_field('THOLD', 's', one, blank_default, 0.01_wp, zero, big, 'time at rest before the run ends')])

      t(g_numerics)%name = 'NUMERICS'
      t(g_numerics)%title = 'Numerical controls beyond the report (C.3, C.5, C.6)'
      t(g_numerics)%note = 'ASTART: how Adams-Moulton (NINT 1) starts, by the report''s modified Euler ' &
         //'(order 3) or by RK4 (order 4). SOLVER: A z'''' = b by an L D L^T written for the body''s ' &
         //'structure or by LAPACK (equal to rounding). An energy-balance error beyond EBTOL times its ' &
         //'scale, the larger of the largest body kinetic energy and the largest work the vehicle has supplied ' &
         //'so far (D-17a), flags the run; with EBFAIL = STOP it ends as a numerical failure (exit 3).'
      call set_fields(t(g_numerics), [ &
         word_field('ASTART', 'EULER|RK4', blank_default, 'Adams-Moulton start'), &
         word_field('SOLVER', 'STRUCTURED|DENSE', blank_default, 'linear solver of C.5'), &
         real_field('EBTOL', '-', one, blank_default, 0.01_wp, zero, 1.0e6_wp, &
            'allowed energy-balance error (fraction)', .true.), &
         word_field('EBFAIL', 'STOP|CONTINUE', blank_default, 'when the balance fails')])
      t(g_numerics)%field(1)%default = real(1, wp)
      t(g_numerics)%field(2)%default = real(1, wp)
      t(g_numerics)%field(4)%default = real(1, wp)

      t(g_fmvss)%name = 'FMVSS208'
      t(g_fmvss)%title = 'FMVSS 208 limits of the summary''s table (50th male; beyond the report)'
      t(g_fmvss)%note = 'The limits the table "FMVSS 208 (50th male)" of the summary judges the run by, in SI as ' &
         //'FMVSS 208 (49 CFR 571.208, S6) states them; the defaults are its 50th-percentile male''s. The values ' &
         //'come from the filtered channels (SAE J211-1: head CFC 1000, chest CFC 180, neck and femur CFC 600): ' &
         //'HIC15, the chest''s 3 ms clip, its deflection, Nij, the neck''s tension and compression, the femur''s ' &
         //'compression (docs/injury.md).'
      call set_fields(t(g_fmvss), [ &
         real_field('HIC15', '-', one, blank_default, 700.0_wp, zero, big, 'HIC15 limit', .true.), &
         real_field('CLIP3MS', 'g', one, blank_default, 60.0_wp, zero, big, 'chest 3 ms clip limit', .true.), &
         real_field('CHESTD', 'mm', one, blank_default, 63.0_wp, zero, big, 'chest deflection limit', .true.), &
         real_field('NIJ', '-', one, blank_default, 1.0_wp, zero, big, 'Nij limit', .true.), &
         real_field('NECKT', 'N', one, blank_default, 4170.0_wp, zero, big, 'neck tension limit', .true.), &
         real_field('NECKC', 'N', one, blank_default, 4000.0_wp, zero, big, 'neck compression limit', .true.), &
         real_field('FEMUR', 'N', one, blank_default, 10008.0_wp, zero, big, 'femur compression limit', .true.)])

      t(g_materials)%name = 'MATERIALS'
      t(g_materials)%title = 'Materials, Table 4'
      t(g_materials)%layout = layout_indexed
      t(g_materials)%max_index = 14
      t(g_materials)%index_name = 'material l'
      t(g_materials)%note = 'l: 1 seat, 2 glass, 3 padding, 4 floormat, 5 floor, 6 metal, 7 rim, 8 headrest, ' &
         //'9 visor, 10 column, 11 abdomen, 12 chest, 13 face, 14 shoulder. MU and XI: Coulomb friction ' &
         //'against the material: for the seat (material 1) all of it once the sliding velocity reaches XI, ' &
         //'none below; for the contacts all of it from XI on and in proportion to the sliding velocity ' &
         //'below (docs/contacts.md D-C18a); XI should exceed mu P DT / m, the change of sliding velocity ' &
         //'one step of the friction makes on the body part: under a fixed step (NINT 1, 2) a narrower ' &
         //'ramp is widened to what the step can integrate, and the listing says so (D-C18b). G: ratio ' &
         //'of residual to maximum deformation; R: ratio of the energy ' &
         //'conserved to that absorbed (recurrent loading, C.4.e figure 18); R must not exceed 1 - G ' &
         //'(docs/loading.md). CURVE: the number k of its loading curve (*LOADPOLY or *LOADTABLE, as ' &
         //'NLOAD selects), 0 for none. A material without a card ' &
         //'has no friction, G = 0 and R = 1 (elastic) and no curve. ETA (padding 3, floormat 4 only): the ' &
         //'fraction of the layer''s depth D'''' at which it bottoms out (figure 25). FSW (glass 2 only): the ' &
         //'force at which the windshield shatters; blank, never (docs/contacts.md).'
      call set_fields(t(g_materials), [ &
         real_field('MU', '-', one, blank_default, zero, zero, 10.0_wp, 'friction coefficient mu_l'), &
         real_field('XI', 'in/s', one, blank_default, 0.1_wp, zero, 1.0e4_wp, 'friction velocity limit xi_l'), &
         real_field('G', '-', one, blank_default, zero, zero, 1.0_wp, 'residual / maximum deformation G_l'), &
         real_field('R', '-', one, blank_default, one, zero, 1.0_wp, 'conserved / absorbed energy R_l'), &
         int_field('CURVE', blank_default, 0, 0, max_curves, 'loading curve k (0: none)'), &
         real_field('ETA', '-', one, blank_default, one, zero, 1.0_wp, 'eta = D''/D'''' of padding or mat (3, 4)', &
                    .true.), &
         real_field('FSW', 'lb', one, blank_absent, zero, zero, 1.0e6_wp, 'glass (2): force that shatters it', &
                    .true.)])

      call loading_groups(t)
      call contact_groups(t)
      call belt_groups(t)

      call seat_groups(t)
      call output_groups(t)
      ! (the analog before the study: *VARY's GROUP words are the groups named before it)
      call analog_groups(t)
      call study_groups(t)

      block
         integer :: i
         do i = 1, n_groups
            if (t(i)%kind == ' ') t(i)%kind = t(i)%name
            ! a repeated index is reported as such, not as "too many cards"
            if (t(i)%layout == layout_indexed) t(i)%max_cards = 10*t(i)%max_index
         end do
      end block
   end function card_table

   !> The loading-curve groups (C.4.e, C.4.f, Tables 2 and 4; docs/loading.md).
   pure subroutine loading_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: big = 1.0e12_wp, one = 1.0_wp, zero = 0.0_wp
      character(len=8), parameter :: s_unit(max_order) = [character(len=8) :: &
         'lb/in', 'lb/in^2', 'lb/in^3', 'lb/in^4', 'lb/in^5']
      character(len=12), parameter :: r_unit(max_order) = [character(len=12) :: &
         'lb*s/in', 'lb*s^2/in^2', 'lb*s^3/in^3', 'lb*s^4/in^4', 'lb*s^5/in^5']
      character(len=1), parameter :: digit(max_order) = ['1', '2', '3', '4', '5']
      type(field_spec_t) :: f(max_order + 1)
      integer :: n

      t(g_loadpoly)%name = 'LOADPOLY'
      t(g_loadpoly)%title = 'Polynomial loading curves, NLOAD = 1 (Tables 2 and 4: N, sigma_n)'
      t(g_loadpoly)%layout = layout_indexed
      t(g_loadpoly)%max_index = max_curves
      t(g_loadpoly)%index_name = 'curve k'
      t(g_loadpoly)%note = 'Force F = SIGMA1 d + SIGMA2 d**2 + ... + SIGMAN d**N (lb) at a deformation d >= 0 ' &
         //'(in), plus the rate terms of *LOADRATE. The force must not decrease as d grows, so that it ' &
         //'never pulls; SIGMAn beyond N must be blank. Materials (*MATERIALS CURVE) and belt sections ' &
         //'(*BELTLOADING) name their curve by k. Used when NLOAD = 1; see docs/loading.md.'
      f(1) = int_field('N', blank_required, 0, 1, max_order, 'order N of the polynomial')
      do n = 1, max_order
         f(n + 1) = real_field('SIGMA'//digit(n), trim(s_unit(n)), one, blank_default, zero, -big, big, &
                               'coefficient sigma_'//digit(n)//' of d**'//digit(n))
      end do
      call set_fields(t(g_loadpoly), f)

      t(g_loadrate)%name = 'LOADRATE'
      t(g_loadrate)%title = 'Rate terms of the loading curves (Tables 2 and 4: sigma_n+N)'
      t(g_loadrate)%layout = layout_indexed
      t(g_loadrate)%max_index = max_curves
      t(g_loadrate)%index_name = 'curve k'
      t(g_loadrate)%note = 'Adds RATE1 v + RATE2 v abs(v) + ... + RATEn v abs(v)**(n-1) (lb) to curve k, v being the rate ' &
         //'of deformation (in/s): sigma_N+1 .. sigma_2N of the report, odd in v so that each term ' &
         //'opposes the motion. They act while the curve carries load, and the total force never ' &
         //'pulls. A polynomial curve of order N takes RATE1..RATEN only. Curve k must be given.'
      do n = 1, max_order
         f(n) = real_field('RATE'//digit(n), trim(r_unit(n)), one, blank_default, zero, zero, big, &
                           'sigma_N+'//digit(n)//': coefficient of abs(v)**'//digit(n)//', sign of v')
      end do
      call set_fields(t(g_loadrate), f(1:max_order))

      t(g_loadtable)%name = 'LOADTABLE'
      t(g_loadtable)%title = 'Tabulated loading curves, NLOAD = 2'
      t(g_loadtable)%layout = layout_multi
      t(g_loadtable)%max_index = max_curves
      t(g_loadtable)%min_cards = 2
      t(g_loadtable)%max_cards = 100000
      t(g_loadtable)%index_name = 'curve k'
      t(g_loadtable)%note = 'Points (d, F) of curve k in order: the first (0, 0), d increasing, F not ' &
         //'decreasing. Between points the force is linear in d; beyond the last point it continues ' &
         //'along the last interval. *LOADRATE may add rate terms. Used when NLOAD = 2.'
      call set_fields(t(g_loadtable), [ &
         real_field('DEFL', 'in', one, blank_required, zero, zero, big, 'deformation d'), &
         real_field('FORCE', 'lb', one, blank_required, zero, zero, big, 'force F at d')])

      t(g_beltloading)%name = 'BELTLOADING'
      t(g_beltloading)%title = 'Loading of the belt sections, Table 2 (C.4.e, figure 18)'
      t(g_beltloading)%layout = layout_indexed
      t(g_beltloading)%max_index = n_belt_section
      t(g_beltloading)%index_name = 'section j'
      t(g_beltloading)%note = 'j: 1 lap belt, 2 torso belt at the centre torso, 3 torso belt at the upper ' &
         //'torso. CURVE: the number k of the section''s loading curve (*LOADPOLY or *LOADTABLE, as ' &
         //'NLOAD selects). G and R as for *MATERIALS; R must not exceed 1 - G.'
      call set_fields(t(g_beltloading), [ &
         int_field('CURVE', blank_required, 0, 1, max_curves, 'loading curve k'), &
         real_field('G', '-', one, blank_default, zero, zero, one, 'residual / maximum deformation G_j'), &
         real_field('R', '-', one, blank_default, one, zero, one, 'conserved / absorbed energy R_j')])
   end subroutine loading_groups
   !> The seat card groups (C.1's seat parameters, C.4.d; docs/seat.md).
   pure subroutine seat_groups(t)
      type(group_spec_t), intent(inout) :: t(n_groups)
      real(wp), parameter :: big = 1.0e12_wp, zero = 0.0_wp, one = 1.0_wp, small_mass = 1.0e-6_wp, stiff = 1.0e8_wp

      t(g_seat)%name = 'SEAT'
      t(g_seat)%title = 'Seat (C.1, C.4.d): representation and geometry'
      t(g_seat)%note = 'FORM: NONE (no seat code runs), SPRINGS (the report''s present seat: hip spring-damper, ' &
         //'front-edge spring, hip friction of material 1; figures 11-12), RIGID (the rigid-beam seat, ' &
         //'figures 15-16) or BEAMS (the pair of non-rigid beams, figures 13-14); docs/seat.md. Z0: the ' &
         //'horizontal distance from the initial hip to the front edge; ZHAT: the front region where the ' &
         //'hip spring becomes linear (SPRINGS only, < Z0); GAMMA0: the undeflected cushion angle (RIGID: ' &
         //'the initial beam angle). W0, FPS0: static loads at the hip and on the front edge; SPRINGS: ' &
         //'checks, listed beside those the occupant''s statics predict; RIGID: two of the ten ' &
         //'quantities of *SEATBEAMINIT.'
      call set_fields(t(g_seat), [ &
         word_field('FORM', 'NONE|SPRINGS|RIGID|BEAMS', blank_default, 'seat representation'), &
         real_field('Z0', 'in', one, blank_default, 14.0_wp, zero, 100.0_wp, 'hip to front edge z_o', .true.), &
         real_field('ZHAT', 'in', one, blank_default, zero, zero, 100.0_wp, 'front region z-hat'), &
         real_field('GAMMA0', 'deg', deg, blank_default, zero, -45.0_wp, 45.0_wp, 'cushion angle gamma_o'), &
         real_field('W0', 'lb', one, blank_absent, zero, zero, 1.0e5_wp, 'static load at the hip W_o'), &
         real_field('FPS0', 'lb', one, blank_absent, zero, zero, 1.0e5_wp, 'static front-edge load F''_so')])
      t(g_seat)%field(1)%default = real(1, wp)   ! word 1: NONE

      t(g_seatsprings)%name = 'SEATSPRINGS'
      t(g_seatsprings)%title = 'Seat cushion springs and damper (C.4.d)'
      t(g_seatsprings)%note = 'The hip force is F_s = BETA1 d + BETA2 d**2 + BETA3 d**3 + CS d'' for a ' &
         //'compression d > 0 (a compression polynomial, erratum A-S3), the front-edge force F''_s = S times ' &
         //'the front compression; neither pulls. BETA2 may be negative down to -2 sqrt(BETA1 BETA3), so ' &
         //'that the spring pushes at every compression. RIGID: the rear (BETA, CS) and front (S) supports.'
      call set_fields(t(g_seatsprings), [ &
         real_field('CS', 'lb*s/in', one, blank_default, 3.0_wp, zero, 1.0e6_wp, 'hip damper c_s'), &
         real_field('S', 'lb/in', one, blank_default, 30.0_wp, zero, stiff, 'front-edge spring s'), &
         real_field('BETA1', 'lb/in', one, blank_default, 50.0_wp, zero, stiff, 'hip spring beta_1'), &
         real_field('BETA2', 'lb/in^2', one, blank_default, zero, -stiff, stiff, 'hip spring beta_2'), &
         real_field('BETA3', 'lb/in^3', one, blank_default, 15.0_wp, zero, stiff, 'hip spring beta_3')])

      t(g_seatbeam)%name = 'SEATBEAM'
      t(g_seatbeam)%title = 'Rigid-beam seat (C.4.d, figure 15)'
      t(g_seatbeam)%note = 'The beam''s mass and inertia, its unloaded CG height (from the initial hip) and ' &
         //'angle, and the stiffnesses of the body''s contacts with it: the hip and the leg at the front ' &
         //'edge press into the moving beam (erratum A-RB; docs/seat.md).'
      call set_fields(t(g_seatbeam), [ &
         real_field('MS', 'lb*s^2/in', one, blank_default, 0.05_wp, small_mass, big, 'beam mass m_s'), &
         real_field('IS', 'lb*in*s^2', one, blank_default, one, small_mass, big, 'beam inertia I_s'), &
         real_field('YGU', 'in', one, blank_default, zero, -100.0_wp, 100.0_wp, 'unloaded CG height y_gu'), &
         real_field('GAMMAU', 'deg', deg, blank_default, zero, -45.0_wp, 45.0_wp, 'unloaded angle gamma_u'), &
         real_field('KHIP', 'lb/in', one, blank_default, 2000.0_wp, zero, stiff, 'hip contact stiffness', .true.), &
         real_field('KEDGE', 'lb/in', one, blank_default, 500.0_wp, zero, stiff, 'leg contact stiffness', .true.)])

      t(g_seatbeaminit)%name = 'SEATBEAMINIT'
      t(g_seatbeaminit)%title = 'Rigid-beam seat at t = 0 (C.4.d): four of the ten quantities'
      t(g_seatbeaminit)%note = 'The ten quantities a, a'', W_o, F-hat''_so, F_so, F''_so, Delta_so, Delta_zo, ' &
         //'y_go, gamma_o (A, AP, *SEAT W0, FHPS0, FS0, *SEAT FPS0, DS0, DZ0, YG0, *SEAT GAMMA0) obey six ' &
         //'relations (equilibrium of forces and moments, the two support laws, the two deflections): give ' &
         //'exactly four and the program solves for the other six. Four that leave the rest undetermined ' &
         //'(FS0 with DS0, FPS0 with DZ0, ...) are refused (erratum A-RB).'
      call set_fields(t(g_seatbeaminit), [ &
         real_field('A', 'in', one, blank_absent, zero, zero, 100.0_wp, 'front edge to rear support a', .true.), &
         real_field('AP', 'in', one, blank_absent, zero, zero, 100.0_wp, 'front edge to beam CG a''', .true.), &
         real_field('FHPS0', 'lb', one, blank_absent, zero, zero, 1.0e5_wp, 'leg load on the edge F-hat''_so'), &
         real_field('FS0', 'lb', one, blank_absent, zero, zero, 1.0e5_wp, 'rear support force F_so'), &
         real_field('DS0', 'in', one, blank_absent, zero, zero, 100.0_wp, 'rear support deflection'), &
         real_field('DZ0', 'in', one, blank_absent, zero, zero, 100.0_wp, 'front support deflection'), &
         real_field('YG0', 'in', one, blank_absent, zero, -100.0_wp, 100.0_wp, 'CG height y_go')])

      t(g_seatbeams)%name = 'SEATBEAMS'
      t(g_seatbeams)%title = 'Non-rigid beam seat (C.4.d, figure 13)'
      t(g_seatbeams)%note = 'A beam of length L built in at both ends carries the hip; a cantilever of length ' &
         //'K*L, built in K*L behind the front edge, carries the legs at its tip (docs/seat.md). E1, E2 are ' &
         //'3 E I of each (erratum NB-1). The undeflected cushion line passes through (XSC, YSC) at GAMMA0; ' &
         //'YSC blank: through the point r_1 (hip arc, *ARCS) below the initial hip.'
      call set_fields(t(g_seatbeams), [ &
         real_field('L', 'in', one, blank_default, 20.0_wp, zero, 100.0_wp, 'hip beam length l', .true.), &
         real_field('K', '-', one, blank_default, 0.5_wp, zero, one, 'cantilever length / l', .true.), &
         real_field('E1', 'lb*in^2', one, blank_default, 12500.0_wp, zero, big, 'hip beam 3EI, e_1', .true.), &
         real_field('E2', 'lb*in^2', one, blank_default, 30000.0_wp, zero, big, 'cantilever 3EI, e_2', .true.), &
         real_field('XSC', 'in', one, blank_default, zero, -100.0_wp, 100.0_wp, 'cushion line point x''''_sc'), &
         real_field('YSC', 'in', one, blank_absent, zero, -100.0_wp, 100.0_wp, 'cushion line point y''''_sc')])
   end subroutine seat_groups

   !> The belt groups (C.4.e, Table 2, C.2; docs/belts.md).
   pure subroutine belt_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: big = 1.0e12_wp, zero = 0.0_wp, one_ = 1.0_wp

      t(g_belts)%name = 'BELTS'
      t(g_belts)%title = 'Belt geometry, Table 2 (C.4.e, C.2)'
      t(g_belts)%layout = layout_indexed
      t(g_belts)%max_index = n_belt_card
      t(g_belts)%index_name = 'section j'
      t(g_belts)%note = 'j: 1 lap belt, 2 torso belt at H along the centre torso from the lower-spine joint, ' &
         //'3 torso belt at H along the upper torso from the upper-spine joint, 4 the lap belt''s second ' &
         //'side (*BELTOPTIONS LAPSIDES = 2). The lap belt wraps the hip at radius H; its anchor lies ' &
         //'LPRIME from the initial hip, PHIPRIME the direction from anchor to hip; its free length and ' &
         //'angle follow (C.2, errata C2-2, C2-3). A torso section runs straight from its anchor to its ' &
         //'belt point: LENGTH is their initial distance, PHI the direction from anchor to point (C2-1). ' &
         //'Angles from the interior horizontal, counter-clockwise. A section carries load once its ' &
         //'deformation exceeds SLACK. NBELT says which sections are used; *BELTLOADING their loading.'
      call set_fields(t(g_belts), [ &
         real_field('H', 'in', one_, blank_required, zero, zero, big, 'h_j: lap wrap radius, torso point distance'), &
         real_field('LENGTH', 'in', one_, blank_absent, zero, zero, big, 'l_j0: torso anchor to belt point', .true.), &
         real_field('PHI', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'phi_j0: torso, anchor -> belt point'), &
         real_field('LPRIME', 'in', one_, blank_absent, zero, zero, big, 'l''_0: lap anchor to initial hip', .true.), &
         real_field('PHIPRIME', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'phi''_0: lap, anchor -> hip'), &
         real_field('SLACK', 'in', one_, blank_default, zero, zero, big, 'Delta_j: slack')])

      t(g_beltoptions)%name = 'BELTOPTIONS'
      t(g_beltoptions)%title = 'Belt options (C.4.e, section A)'
      t(g_beltoptions)%note = 'COUPLING: SEPARATE, every section its own tension (the report''s phase two); ' &
         //'TORSO, the two torso sections one tension (the webbing slides over the chest); ALL, the three ' &
         //'sections one tension (one webbing sliding through buckle and D-ring: the deformations add). ' &
         //'LAPSIDES = 2 gives the lap belt''s two sides their own anchorages (*BELTS 1 and 4), each ' &
         //'carrying half of the lap belt''s law. ITER: Newton evaluations of the shared-deflection ' &
         //'search (belt and abdomen or chest in series) before it bisects its bracket (docs/belts.md).'
      call set_fields(t(g_beltoptions), [ &
         word_field('COUPLING', 'SEPARATE|TORSO|ALL', blank_default, 'sections sharing one tension'), &
         int_field('LAPSIDES', blank_default, 1, 1, 2, 'lap belt sides modelled: 1 lumped, 2 each its own'), &
         int_field('ITER', blank_default, 60, 1, 1000, 'Newton evaluations of a search, then bisection')])
      t(g_beltoptions)%field(1)%default = real(1, wp)
   end subroutine belt_groups

   !> The interior (C.4.f, Tables 3, 7, 8; docs/contacts.md 2.4).
   pure subroutine contact_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: zero = 0.0_wp, one_ = 1.0_wp

      t(g_surfaces)%name = 'SURFACES'
      t(g_surfaces)%title = 'Contact surfaces, Table 3 (C.4.f, f.2)'
      t(g_surfaces)%layout = layout_indexed
      t(g_surfaces)%max_index = 32
      t(g_surfaces)%index_name = 'surface k'
      t(g_surfaces)%note = 'k: 1 head rest (a circle: X, Y its centre, D its diameter, PSI the way it faces), ' &
         //'2 windshield, 3 sun visor, 4 upper panel, 5 lower panel, 6 toeboard, 7 back of the front seat, ' &
         //'8 steering column, 9 seat back, 10 steering-wheel rim, 11 roof, 12 floor; 21 the back of the front ' &
         //'head rest (1*), 26 the sloping rear floor (6*), 29 the rear seat back (9*), 32 the rear-seat floor ' &
         //'(12*). In the occupant''s interior frame (origin at the initial hip, x forward, y up): a flat ' &
         //'surface ends at (X, Y) and runs back from it along -e(PSI) for D; the body lies on the side of ' &
         //'e(PSI + 90 deg). Derived by f.2''s relations and left blank: X, Y of 4 (the windshield''s lower ' &
         //'end), PSI of 10 (the column''s), X, PSI, D of 11 (Y, the windshield''s upper end) and of 12 (Y, ' &
         //'the toeboard''s lower end), and X, PSI, D of 32 (a level line at Y). DPP: the padding''s or mat''s ' &
         //'depth D''''. A contact pair of the occupant''s position (Tables 7, 8; NBODY) is built only when its ' &
         //'surface is described here; no deck without *SURFACES has contacts.'
      call set_fields(t(g_surfaces), [ &
         real_field('X', 'in', one_, blank_absent, zero, -500.0_wp, 500.0_wp, 'x''''_k: the end at T = 0'), &
         real_field('Y', 'in', one_, blank_absent, zero, -500.0_wp, 500.0_wp, 'y''''_k'), &
         real_field('PSI', 'deg', deg, blank_absent, zero, -360.0_wp, 360.0_wp, 'psi_k, direction to (X, Y)'), &
         real_field('D', 'in', one_, blank_absent, zero, zero, 500.0_wp, 'D_k, length (k = 1: diameter)', .true.), &
         real_field('DPP', 'in', one_, blank_default, zero, zero, 50.0_wp, 'D''''_k, padding depth')])

      t(g_interior)%name = 'INTERIOR'
      t(g_interior)%title = 'Interior options, Table 3 "other" (C.4.f)'
      t(g_interior)%note = 'DFR: the distance between the front and rear seats (listed only; no force uses it, ' &
         //'D-C10). DI: the steering wheel''s inside diameter: a body point passes the rim''s opening to the ' &
         //'column (D-C11). DS: the side rim''s equivalent length in the section through the arms (10*, D-C12); ' &
         //'needed for the driver''s shoulder and hand pairs with the side rim.'
      call set_fields(t(g_interior), [ &
         real_field('DFR', 'in', one_, blank_default, zero, zero, 500.0_wp, 'D_fr, front to rear seat'), &
         real_field('DI', 'in', one_, blank_default, zero, zero, 100.0_wp, 'D_i, wheel inside diameter'), &
         real_field('DS', 'in', one_, blank_absent, zero, zero, 100.0_wp, 'D_s, side rim length', .true.)])

      t(g_contactoff)%name = 'CONTACTOFF'
      t(g_contactoff)%title = 'Contact pairs left out (Tables 7, 8)'
      t(g_contactoff)%layout = layout_list
      t(g_contactoff)%max_cards = 40
      t(g_contactoff)%note = 'One card per pair of the occupant''s position to leave out: body point I (1 hip, ' &
         //'2 back, 3 chest, 4 head, 5 shoulder, 6 elbow, 7 knee, 8 foot, 9 shin, 10 hand) and surface K (as ' &
         //'*SURFACES; 25 the lower panel''s edge, 30 the side rim). A pair the position does not have is an error.'
      call set_fields(t(g_contactoff), [ &
         int_field('I', blank_required, 0, 1, 10, 'body point i'), &
         int_field('K', blank_required, 0, 1, 32, 'surface k')])
   end subroutine contact_groups

   !> The listing's printer plots (C.6; issue 18; docs/usage.md, "The listing").
   pure subroutine output_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: zero = 0.0_wp, one = 1.0_wp, most = 1000.0_wp
      integer :: k
      t(g_printerplot)%name = 'PRINTERPLOT'
      t(g_printerplot)%title = 'Printer plots in the listing (C.6)'
      t(g_printerplot)%note = 'With this group the listing ends its time histories with printer plots, as ' &
         //'programs of the report''s era drew them on the 132-column page: the occupant over the interior ' &
         //'(surfaces, seat, belts, the body''s segments and head) at each time T1..T7 given, drawn at the first ' &
         //'print time at or after it, and the head''s and chest''s resultant accelerations against time (in ' &
         //'each of the plot''s 100 columns of time, the largest at a print time within it). Times in ' &
         //'increasing order, at most TMAX; blank: no picture of the occupant, the acceleration plots only.'
      call set_fields(t(g_printerplot), [(real_field('T'//achar(48 + k), 's', one, blank_absent, zero, zero, most, &
                                                     'time of a picture of the occupant'), k=1, max_plot_times)])
   end subroutine output_groups

   !> C.8: a study of the deck (docs/modification.md).
   pure subroutine study_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: zero = 0.0_wp, one = 1.0_wp
      character(len=:), allocatable :: names
      integer :: i
      t(g_study)%name = 'STUDY'
      t(g_study)%title = 'A study: runs of the deck with fields varied (C.8)'
      t(g_study)%note = 'With this group the program varies the fields *VARY names and runs the deck once for ' &
         //'each variation, judging each run by *CRITERIA. METHOD: OAT one field at a time about the deck, ' &
         //'GRID every combination, RANDOM and LHS (Latin hypercube) RUNS draws (SEED required), ENSEMBLE RUNS ' &
         //'small perturbations (SPREAD) about the deck (SEED required), OPTIMIZE minimises criterion OBJECT ' &
         //'of occupant OCC within the limits of *CRITERIA (Nelder-Mead within LOW-HIGH, at most RUNS runs, ' &
         //'to TOL). KEEP: also each run''s own listing and HDF5 file. A deck with *ANALOG (one case) may ' &
         //'hold a study too: each run solves the analog (docs/analog.md). docs/modification.md.'
      call set_fields(t(g_study), [ &
         word_field('METHOD', study_methods, blank_required, 'how the fields vary'), &
         int_field('RUNS', blank_absent, 0, 1, 1000000, 'runs (RANDOM, LHS, ENSEMBLE; OPTIMIZE: budget)'), &
         int_field('SEED', blank_absent, 0, 1, huge(1), 'seed of the random methods'), &
         real_field('TOL', '-', one, blank_default, 1.0e-3_wp, zero, one, 'OPTIMIZE: convergence tolerance', &
                    .true.), &
         word_field('OBJECT', criterion_word_list, blank_absent, 'OPTIMIZE: the criterion minimised'), &
         int_field('OCC', blank_default, 1, 1, 2, 'the occupant OBJECT is read from'), &
         word_field('KEEP', 'NONE|LISTING|H5|BOTH', blank_default, 'each run''s own outputs')])
      t(g_study)%field(7)%default = real(1, wp)

      names = ''
      do i = 1, size(t)
         if (t(i)%name == ' ') cycle
         if (len(names) > 0) names = names//'|'
         names = names//trim(t(i)%name)
      end do
      t(g_vary)%name = 'VARY'
      t(g_vary)%title = 'The fields a study varies (C.8)'
      t(g_vary)%layout = layout_multi
      t(g_vary)%max_index = max_study_variables
      t(g_vary)%max_cards = max_study_variables
      t(g_vary)%index_name = 'variable v'
      t(g_vary)%note = 'One card per varied field: the field FIELD of card CARD of group GROUP (CARD: the row ' &
         //'index in a group of one card per index, such as *BELTS, else the card''s number in its group, ' &
         //'comment cards not counted). Its values: those of ' &
         //'*VALUES for v if given, else COUNT values from LOW to HIGH (OAT, GRID) or draws within LOW-HIGH ' &
         //'(RANDOM, LHS; OPTIMIZE searches there); ENSEMBLE adds SPREAD times a standard normal draw to the ' &
         //'deck''s value, kept within LOW-HIGH. LOW, HIGH, SPREAD in the field''s own deck units.'
      call set_fields(t(g_vary), [ &
         word_field('GROUP', 'TITLE', blank_required, 'card group of the field'), &
         int_field('CARD', blank_default, 1, 1, 99999, 'its card (row index or number)'), &
         text_field('FIELD', blank_required, 'field name'), &
         real_field('LOW', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'lowest value'), &
         real_field('HIGH', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'highest value'), &
         int_field('COUNT', blank_absent, 0, 1, 10000, 'values from LOW to HIGH (OAT, GRID)'), &
         real_field('SPREAD', '(field)', one, blank_absent, zero, zero, huge(one), 'ENSEMBLE: standard deviation')])
      t(g_vary)%field(1)%words = names
      ! the group's name may be as long as 14 letters (PULSEPOSITIONS)
      t(g_vary)%field(1)%first_col = 3
      t(g_vary)%field(1)%last_col = 17
      t(g_vary)%field(2)%first_col = 18
      t(g_vary)%field(2)%last_col = 22
      t(g_vary)%field(3)%first_col = 23
      t(g_vary)%field(3)%last_col = 32

      t(g_values)%name = 'VALUES'
      t(g_values)%title = 'The values of a varied field (C.8)'
      t(g_values)%layout = layout_multi
      t(g_values)%max_index = max_study_variables
      t(g_values)%max_cards = 10000
      t(g_values)%index_name = 'variable v'
      t(g_values)%note = 'The list of values of *VARY''s variable v, in its field''s deck units, in order over ' &
         //'as many cards as needed (blank fields skipped).'
      call set_fields(t(g_values), [ &
         real_field('V1', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V2', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V3', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V4', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V5', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V6', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value'), &
         real_field('V7', '(field)', one, blank_absent, zero, -huge(one), huge(one), 'a value')])

      t(g_criteria)%name = 'CRITERIA'
      t(g_criteria)%title = 'How a study judges each run (C.8)'
      t(g_criteria)%layout = layout_list
      t(g_criteria)%max_cards = 40
      t(g_criteria)%note = 'One card per criterion reported for each run (docs/modification.md lists them); a ' &
         //'run meets the study''s limits when every criterion with a LIMIT is at most its LIMIT (a count ' &
         //'such as UNWANTED with LIMIT 0: no such event). A deck with *ANALOG is judged by MEET, TMEET, ' &
         //'SEPMIN, OVERLAP and CDAMP only, of both occupants together (OCC blank); any other deck by the rest.'
      call set_fields(t(g_criteria), [ &
         word_field('CRIT', criterion_word_list, blank_required, 'the criterion'), &
         int_field('OCC', blank_default, 1, 1, 2, 'of occupant'), &
         real_field('LIMIT', '(crit.)', one, blank_absent, zero, -huge(one), huge(one), 'largest value allowed')])
   end subroutine study_groups

   !> Report Section D: the two-occupant analog (docs/analog.md).
   pure subroutine analog_groups(t)
      type(group_spec_t), intent(inout) :: t(:)
      real(wp), parameter :: zero = 0.0_wp, one = 1.0_wp
      ! 1 mph = 5280*12/3600 in/s
      real(wp), parameter :: mph = 17.6_wp
      t(g_analog)%name = 'ANALOG'
      t(g_analog)%title = 'The two-occupant analog of Section D: one card per case'
      t(g_analog)%layout = layout_list
      t(g_analog)%max_cards = 100
      t(g_analog)%note = 'A deck with this group runs Section D''s analog instead of the occupant simulation, ' &
         //'and holds no other group but *TITLE (and a study of it: *STUDY, *VARY, *VALUES, *CRITERIA, with one ' &
         //'case). Each card is one case: a front occupant held by a shoulder ' &
         //'harness (spring K1 at L1 from the hip, damping ratio ZETA: 0 undamped, 1 critical) and a hip ' &
         //'torque T; a rear occupant pivoting freely until the front seat back stops him at 60 deg; both the ' &
         //'95th-percentile upper body of the report (110 lb, 38 in, CG 17 in from the hip, I0 = 117 ' &
         //'lb*in*s^2), upright at the start with m V rho = I0 omega; hips L apart. The harness turns the ' &
         //'body with L1**2 K1 (erratum D-2): the report''s motion is K1 = 1470.59 lb/in at L1 = 17 in. ' &
         //'Listed every 1 ms to TMAX (docs/analog.md).'
      call set_fields(t(g_analog), [ &
         real_field('V', 'mph', mph, blank_default, 20.0_wp, zero, 200.0_wp, 'collision speed v', .true.), &
         real_field('K1', 'lb/in', one, blank_default, 1470.59_wp, zero, 1.0e7_wp, 'harness spring k_1', .true.), &
         real_field('L1', 'in', one, blank_default, 17.0_wp, zero, 100.0_wp, 'hip to harness l_1', .true.), &
         real_field('ZETA', '-', one, blank_default, zero, zero, 100.0_wp, 'harness damping ratio (1 critical)'), &
         real_field('T', 'in*lb', one, blank_default, 3300.0_wp, zero, 1.0e7_wp, 'front hip torque T'), &
         real_field('L', 'in', one, blank_default, 34.0_wp, zero, 200.0_wp, 'seat spacing: hip to hip', .true.), &
         real_field('TMAX', 's', one, blank_default, 0.125_wp, zero, 2.0_wp, 'duration', .true.)])
   end subroutine analog_groups

end module deck_cards
