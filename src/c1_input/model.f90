!> The model tables filled from the deck (report C.1, Tables 1-6) and read
!! without change during a run. Internal units are the report's: inch,
!! pound force, second, radian; mass in lb*s^2/in (the deck reader converts
!! degrees and g to these).
module model
   use kinds, only: wp
   use text_io, only: string_t
   use loading_parameters, only: loading_curve_t
   implicit none
   private

   public :: n_seg, n_joint, n_dof, n_arc, n_injury, hip_x, hip_y, n_material, material_name
   public :: joint_partner, segment_name, joint_name, arc_name
   public :: form_linear, form_cubic, form_table, form_name
   public :: nint_adams, nint_rk4, nint_dopri, integrator_name
   public :: nend_time, nend_contact, nend_injury, nend_rest, end_option_name
   public :: stop_curve_t, restraint_t, model_t, pulse_table_t
   public :: options_section_t, time_section_t, numerics_section_t, body_section_t, joints_section_t
   public :: fmvss_limits_t
   public :: injury_section_t, vehicle_section_t, environment_section_t, end_tests_section_t
   public :: interior_section_t, printer_plot_section_t, max_plot_times
   public :: materials_section_t, loading_section_t, max_curves, n_belt_section
   public :: seat_section_t, n_beam_quantities, beam_quantity_name
   public :: bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   public :: seat_none, seat_springs, seat_rigid_beam, seat_beams, seat_form_name
   public :: belts_section_t, n_belt_card, belt_card_lap2, coupling_independent, coupling_torso, coupling_all
   public :: coupling_name, nbelt_lap, nbelt_torso
   public :: solver_structured, solver_dense, solver_name, astart_euler, astart_rk4, astart_name

   integer, parameter :: n_seg = 8     !< body segments (Table 5)
   integer, parameter :: n_joint = 7   !< body joints (Table 5)
   integer, parameter :: n_dof = 10    !< alpha_1..alpha_8, x_h, y_h (section B)
   !> The hip's generalized coordinates among the n_dof (section B).
   integer, parameter :: hip_x = 9, hip_y = 10
   integer, parameter :: n_arc = 10    !< body contact arcs (Table 1, r)
   integer, parameter :: n_injury = 10 !< rows of the bone/joint injury table (Table 5)
   integer, parameter :: n_material = 14 !< materials of Table 4
   character(len=10), parameter :: material_name(n_material) = [character(len=10) :: &
      'seat', 'glass', 'padding', 'floormat', 'floor', 'metal', 'rim', 'headrest', 'visor', 'column', &
      'abdomen', 'chest', 'face', 'shoulder']

   !> Table 6: joint i couples segment i with segment m(i); its relative
   !! angle is alpha_i - alpha_m (errata.md, "Joint springs").
   integer, parameter :: joint_partner(n_joint) = [7, 1, 2, 3, 3, 5, 8]

   character(len=12), parameter :: segment_name(n_seg) = [character(len=12) :: &
      'lower torso', 'center torso', 'upper torso', 'head', &
      'upper arm', 'lower arm', 'upper leg', 'lower leg']
   character(len=12), parameter :: joint_name(n_joint) = [character(len=12) :: &
      'hip', 'lower spine', 'upper spine', 'neck', 'shoulder', 'elbow', 'knee']
   character(len=12), parameter :: arc_name(n_arc + 1) = [character(len=12) :: &
      'hip', 'upper back', 'chest', 'head', 'shoulder', 'elbow', 'knee', &
      'foot', 'shin', 'hand', 'ankle']

   !> Forms of a joint's angular restraint (C.4.c, figure 9).
   integer, parameter :: form_linear = 1, form_cubic = 2, form_table = 3
   character(len=6), parameter :: form_name(3) = [character(len=6) :: 'LINEAR', 'CUBIC', 'TABLE']

   !> Integration option (C.3).
   integer, parameter :: nint_adams = 1, nint_rk4 = 2, nint_dopri = 3
   character(len=40), parameter :: integrator_name(3) = [character(len=40) :: &
      'Adams-Moulton predictor-corrector', 'classic Runge-Kutta 4, fixed step', &
      'Dormand-Prince 5(4), adaptive']

   !> End-of-program option NEND (C.7).
   integer, parameter :: nend_time = 1, nend_contact = 2, nend_injury = 3, nend_rest = 4
   character(len=32), parameter :: end_option_name(4) = [character(len=32) :: &
      'time', 'time + undesired contact', 'time + injury', 'time + cessation of motion']

   !> A tabulated restraint torque against penetration beyond a stop:
   !! torque(k) (in*lb, >= 0) at penetration depth(k) (rad, increasing from 0).
   type :: stop_curve_t
      real(wp), allocatable :: depth(:)
      real(wp), allocatable :: torque(:)
   end type stop_curve_t

   !> The angular restraint of one joint (C.4.c, figure 9). The torque acts
   !! against the penetration d of the relative angle beyond omega (lower)
   !! or big_omega (upper): magnitude c1*d + c2*d**2 + c3*d**3, or the curve.
   type :: restraint_t
      integer :: form = form_linear
      real(wp) :: lower = 0.0_wp          !< omega, lower stop angle (rad)
      real(wp) :: upper = 0.0_wp          !< Omega, upper stop angle (rad)
      real(wp) :: coef_lower(3) = 0.0_wp  !< T' and the cubic's c2, c3
      real(wp) :: coef_upper(3) = 0.0_wp  !< T-hat' and the cubic's c2, c3
      real(wp) :: dislocation_lower = 0.0_wp !< figure 10 limits (rad)
      real(wp) :: dislocation_upper = 0.0_wp
      type(stop_curve_t) :: curve_lower, curve_upper
   end type restraint_t

   !> A vehicle time table: value columns at times t (C.1); a column that is
   !! not available has given(c) false.
   type :: pulse_table_t
      real(wp), allocatable :: t(:)
      real(wp), allocatable :: v(:, :)   !< (size(t), 3): x, y, pitch
      logical :: given(3) = .false.
   end type pulse_table_t

   !> Linear solver of A z'' = b (C.5).
   integer, parameter :: solver_structured = 1, solver_dense = 2
   character(len=48), parameter :: solver_name(2) = [character(len=48) :: &
      'L D L^T for the body''s structure', 'LAPACK dense Cholesky (dpotf2, dtrsv)']

   !> Start of the Adams-Moulton method (C.3; docs/errata.md D-6).
   integer, parameter :: astart_euler = 1, astart_rk4 = 2
   character(len=40), parameter :: astart_name(2) = [character(len=40) :: &
      'modified Euler (the report''s, order 3)', 'RK4 (order 4)']

   !> Program options (C.1, *OPTIONS).
   type :: options_section_t
      integer :: nbody = 0, nbelt = 0, nend = 0, nload = 0, nout = 0, nint = 0
      !> the switches of the effects located inside a step (issue 15); no
      !! card sets it: off only in the tests that show what location buys
      !! (tests/test_hard_*.pf, issue 15 section 4)
      logical :: locate_switches = .true.
      !> the head's forward excursion kept on accepted steps (C.8's HEADX);
      !! no card sets it: a study asks for it when it judges by HEADX, so a
      !! run that does not pays nothing for it
      logical :: head_excursion = .false.
   end type options_section_t

   !> Time controls (C.3, C.6, C.7, *TIME).
   type :: time_section_t
      real(wp) :: t_max = 0.0_wp, dt = 0.0_wp, dt_print = 0.0_wp
      real(wp) :: corrector_tol = 0.0_wp
      integer :: corrector_max_iter = 0
      real(wp) :: rtol = 0.0_wp, atol = 0.0_wp
   end type time_section_t

   !> Numerical controls beyond the report (*NUMERICS).
   type :: numerics_section_t
      integer :: am_start = astart_euler
      integer :: solver = solver_structured
      real(wp) :: energy_tol = 0.0_wp       !< allowed energy-balance error / largest body kinetic energy
      logical :: energy_continue = .false.  !< go on when the balance fails
   end type numerics_section_t

   !> *FMVSS208: the limits of the summary's FMVSS 208 table, in SI as
   !! FMVSS 208 S6 states them (defaults: its 50th-percentile male's).
   type :: fmvss_limits_t
      real(wp) :: hic15 = 700.0_wp
      real(wp) :: clip3ms = 60.0_wp              !< g
      real(wp) :: chest_deflection = 63.0_wp     !< mm
      real(wp) :: nij = 1.0_wp
      real(wp) :: neck_tension = 4170.0_wp       !< N
      real(wp) :: neck_compression = 4000.0_wp   !< N
      real(wp) :: femur = 10008.0_wp             !< N, compression
   end type fmvss_limits_t

   !> The occupant's body (Table 1 segments and contact arcs) and its initial
   !! position (C.1): angles and rates relative to the interior.
   type :: body_section_t
      real(wp) :: mass(n_seg) = 0.0_wp, inertia(n_seg) = 0.0_wp
      real(wp) :: length(n_seg) = 0.0_wp, rho(n_seg) = 0.0_wp
      real(wp) :: r_arc(n_arc + 1) = 0.0_wp, rho_arc(n_arc) = 0.0_wp
      real(wp) :: gamma_arc(n_arc) = 0.0_wp
      real(wp) :: theta0(n_seg) = 0.0_wp, theta_dot0(n_seg) = 0.0_wp
   end type body_section_t

   !> The body's joints (Table 1, Table 6, figure 9).
   type :: joints_section_t
      real(wp) :: k_elastic(n_joint) = 0.0_wp   !< K (in*lb/rad)
      real(wp) :: c_friction(n_joint) = 0.0_wp  !< C' (in*lb)
      real(wp) :: xi(n_joint) = 0.0_wp          !< friction velocity limit (rad/s)
      type(restraint_t) :: restraint(n_joint)
   end type joints_section_t

   !> Force injury criteria, Table 1 / Table 5 (0 = not checked).
   type :: injury_section_t
      real(wp) :: f_shear(n_injury) = 0.0_wp, f_compression(n_injury) = 0.0_wp
      real(wp) :: f_tension(n_injury) = 0.0_wp
   end type injury_section_t

   !> Materials of Table 4 (l as in material_name): friction and the
   !! recurrent-loading ratios; each material's loading curve is named in
   !! loading_section_t.
   type :: materials_section_t
      real(wp) :: mu(n_material) = 0.0_wp    !< friction coefficient
      real(wp) :: xi(n_material) = 0.0_wp    !< friction velocity limit (in/s)
      real(wp) :: g(n_material) = 0.0_wp     !< residual / maximum deformation
      real(wp) :: r(n_material) = 1.0_wp     !< conserved / absorbed energy
      logical :: given(n_material) = .false. !< the deck has a card for it
      real(wp) :: eta(n_material) = 1.0_wp   !< padding, floormat: bottoming depth / depth (figure 25)
      real(wp) :: fsw = 0.0_wp               !< glass: the force that shatters it (0: never)
   end type materials_section_t

   !> The interior's contact surfaces as the deck gives them (Table 3;
   !! docs/contacts.md 2.4): surface k in 1..32 (20 + k for k*). The
   !! relations of f.2 and the scene are resolved by contact_scene.
   type :: interior_section_t
      logical :: given(32) = .false.
      real(wp) :: x(32) = 0.0_wp, y(32) = 0.0_wp, psi(32) = 0.0_wp, d(32) = 0.0_wp, dpp(32) = 0.0_wp
      real(wp) :: dfr = 0.0_wp, di = 0.0_wp
      real(wp) :: ds = 0.0_wp                   !< 0: not given
      integer, allocatable :: off(:, :)         !< (i, k) of the pairs left out
   end type interior_section_t

   integer, parameter :: max_curves = 20     !< loading curves k of a deck (*LOADPOLY, *LOADTABLE)
   integer, parameter :: n_belt_section = 3  !< belt sections j of Table 2: lap, torso on 2, torso on 3

   !> Loading curves (C.4.e, C.4.f; docs/loading.md): the curves of the form
   !! NLOAD selects, by number k (form curve_none: not given), the curve of
   !! each material (0: none) and of each belt section with its G and R
   !! (Table 2; those of the materials are in materials_section_t).
   type :: loading_section_t
      type(loading_curve_t) :: curve(max_curves)
      integer :: material_curve(n_material) = 0
      integer :: belt_curve(n_belt_section) = 0
      real(wp) :: belt_g(n_belt_section) = 0.0_wp   !< residual / maximum deformation
      real(wp) :: belt_r(n_belt_section) = 1.0_wp   !< conserved / absorbed energy
   end type loading_section_t
   !> Seat representations (C.4.d; docs/seat.md): none, the report's present
   !! springs (figures 11, 12), the rigid beam (15, 16), the non-rigid beams (13, 14).
   integer, parameter :: seat_none = 0, seat_springs = 1, seat_rigid_beam = 2, seat_beams = 3
   character(len=9), parameter :: seat_form_name(0:3) = [character(len=9) :: &
      'NONE', 'SPRINGS', 'RIGIDBEAM', 'BEAMS']

   !> The rigid beam's ten quantities at t = 0 of which the deck gives any
   !! four (C.4.d, A-RB; seat_beam_statics solves for the other six).
   integer, parameter :: n_beam_quantities = 10
   !> The ten quantities, in the report's order (C.4.d, with the F'_so the OCR lost).
   integer, parameter :: bq_a = 1, bq_ap = 2, bq_w0 = 3, bq_fhps0 = 4, bq_fs0 = 5, bq_fps0 = 6, &
      bq_ds0 = 7, bq_dz0 = 8, bq_yg0 = 9, bq_gamma0 = 10
   !> Their deck names (*SEATBEAMINIT, and W0, FPS0, GAMMA0 of *SEAT).
   character(len=6), parameter :: beam_quantity_name(n_beam_quantities) = [character(len=6) :: &
      'A', 'AP', 'W0', 'FHPS0', 'FS0', 'FPS0', 'DS0', 'DZ0', 'YG0', 'GAMMA0']

   !> The seat (C.1's seat parameters and C.4.d; *SEAT, *SEATSPRINGS,
   !! *SEATBEAM, *SEATBEAMINIT, *SEATBEAMS). Lengths in inches, measured in
   !! the interior frame from the initial hip; the friction mu, xi is that
   !! of material 1 (Table 4).
   type :: seat_section_t
      integer :: form = seat_none
      real(wp) :: z0 = 0.0_wp        !< hip to front edge at t = 0, z_o
      real(wp) :: z_hat = 0.0_wp     !< width of the front region, z-hat
      real(wp) :: gamma0 = 0.0_wp    !< cushion angle gamma_o (rigid beam: its initial angle)
      real(wp) :: w0 = 0.0_wp        !< static load at the hip W_o
      real(wp) :: fps0 = 0.0_wp      !< static load on the front edge F'_so
      real(wp) :: c_s = 0.0_wp, s = 0.0_wp, beta(3) = 0.0_wp   !< damper, front spring, hip polynomial
      real(wp) :: mu = 0.0_wp, xi = 0.0_wp                     !< friction (material 1)
      ! the rigid beam (figure 15): mass, inertia, unloaded CG height and angle,
      ! the body's contact stiffnesses, and the ten quantities of the initial relations
      real(wp) :: m_s = 0.0_wp, i_s = 0.0_wp, y_gu = 0.0_wp, gamma_u = 0.0_wp
      real(wp) :: k_hip = 0.0_wp, k_edge = 0.0_wp
      real(wp) :: a = 0.0_wp, a_prime = 0.0_wp, fhps0 = 0.0_wp, fs0 = 0.0_wp
      real(wp) :: ds0 = 0.0_wp, dz0 = 0.0_wp, yg0 = 0.0_wp
      logical :: beam_given(n_beam_quantities) = .false.   !< which of the ten the deck gives
      ! the non-rigid beams (figure 13): lengths l and k*l, e = 3 E I (NB-1),
      ! the undeflected cushion line through (x''_sc, y''_sc)
      real(wp) :: ell = 0.0_wp, k_ratio = 0.0_wp, e1 = 0.0_wp, e2 = 0.0_wp
      real(wp) :: x_sc = 0.0_wp, y_sc = 0.0_wp
   end type seat_section_t

   !> *BELTS cards: the sections of Table 2 (j = 1 lap, 2 torso on the centre
   !! torso, 3 torso on the upper torso) and card 4, the lap belt's second
   !! side when *BELTOPTIONS LAPSIDES = 2 (docs/belts.md).
   integer, parameter :: n_belt_card = 4, belt_card_lap2 = 4
   !> How the sections share their tension (*BELTOPTIONS COUPLING; section A
   !! of the report): each its own (the report's phase two), the two torso
   !! sections one, all three one.
   integer, parameter :: coupling_independent = 1, coupling_torso = 2, coupling_all = 3
   character(len=12), parameter :: coupling_name(3) = [character(len=12) :: 'SEPARATE', 'TORSO', 'ALL']

   !> The belts' geometry (Table 2, C.2) and options. Lengths in, angles rad.
   type :: belts_section_t
      logical :: given(n_belt_card) = .false.        !< the deck has the card
      real(wp) :: h(n_belt_card) = 0.0_wp            !< h_j: wrap radius (lap), distance along the centre line (torso)
      real(wp) :: length0(n_belt_card) = 0.0_wp      !< l_j0, torso sections (the lap belt's is computed, C2-2)
      real(wp) :: phi0(n_belt_card) = 0.0_wp         !< phi_j0, torso sections, anchor -> belt point
      real(wp) :: length_anchor(n_belt_card) = 0.0_wp  !< l'_0, lap belt: anchor to initial hip
      real(wp) :: phi_anchor(n_belt_card) = 0.0_wp   !< phi'_0, lap belt: direction anchor -> initial hip
      real(wp) :: slack(n_belt_card) = 0.0_wp        !< Delta_j
      integer :: coupling = coupling_independent
      integer :: lap_sides = 1
      integer :: max_iter = 60                       !< iteration limit of the shared-deflection searches
   end type belts_section_t

   !> The vehicle (C.1, C.3): constants, initial motion, time tables.
   type :: vehicle_section_t
      real(wp) :: mass = 0.0_wp, inertia = 0.0_wp
      real(wp) :: xc_dot0 = 0.0_wp, yc_dot0 = 0.0_wp
      real(wp) :: phi0 = 0.0_wp, phi_dot0 = 0.0_wp
      type(pulse_table_t) :: pulse_acc, pulse_vel, pulse_pos
      character(len=:), allocatable :: pulse_source  !< 'cards', 'none ...' or the CSV path
      logical :: pulse_from_file = .false.
      type(string_t), allocatable :: pulse_inputs(:)   !< the files the pulse was read from (*PULSEFILE, *PULSEMME)
   end type vehicle_section_t

   !> Gravity (*GRAVITY).
   type :: environment_section_t
      real(wp) :: gravity = 0.0_wp
   end type environment_section_t

   !> End-of-program test thresholds (C.7, *ENDTESTS).
   type :: end_tests_section_t
      real(wp) :: rest_speed = 0.0_wp, rest_rate = 0.0_wp, rest_hold = 0.0_wp
   end type end_tests_section_t

   !> The listing's printer plots (C.6, *PRINTERPLOT; issue 18): asked for or
   !! not, and the times of the occupant's pictures, field k of the card
   !! (s, increasing; none given: the acceleration plots only).
   integer, parameter :: max_plot_times = 7
   type :: printer_plot_section_t
      logical :: wanted = .false.
      logical :: given(max_plot_times) = .false.
      real(wp) :: times(max_plot_times) = 0.0_wp
   end type printer_plot_section_t

   !> Everything a run needs, as read from the deck: one section per kind of
   !! card group, each filled by its own builder (model_builder). Defaults
   !! live in the card table (deck_cards), not here: the zeros above are
   !! only initial values.
   type :: model_t
      character(len=72) :: title = ' '
      type(options_section_t) :: options
      type(time_section_t) :: time
      type(numerics_section_t) :: numerics
      type(body_section_t) :: body
      type(joints_section_t) :: joints
      type(injury_section_t) :: injury
      type(materials_section_t) :: materials
      type(loading_section_t) :: loading
      type(belts_section_t) :: belts
      type(vehicle_section_t) :: vehicle
      type(environment_section_t) :: environment
      type(end_tests_section_t) :: end_tests
      type(seat_section_t) :: seat
      type(interior_section_t) :: interior
      type(fmvss_limits_t) :: fmvss
      type(printer_plot_section_t) :: printer_plot
      !> Things worth a user's attention that are not errors (listing and stderr).
      type(string_t), allocatable :: warnings(:)
   end type model_t

contains

   !> NBELT (C.1) calls for the lap belt: 1 or 3.
   pure logical function nbelt_lap(nbelt)
      integer, intent(in) :: nbelt
      nbelt_lap = nbelt == 1 .or. nbelt == 3
   end function nbelt_lap

   !> NBELT (C.1) calls for the torso belt: 2 or 3.
   pure logical function nbelt_torso(nbelt)
      integer, intent(in) :: nbelt
      nbelt_torso = nbelt == 2 .or. nbelt == 3
   end function nbelt_torso
end module model
