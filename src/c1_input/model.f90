!> The model tables filled from the deck (report C.1, Tables 1-6) and read
!! without change during a run. Internal units are the report's: inch,
!! pound force, second, radian; mass in lb*s^2/in (the deck reader converts
!! degrees and g to these).
module model
   use kinds, only: wp
   implicit none
   private

   public :: n_seg, n_joint, n_dof, n_arc, n_injury
   public :: joint_partner, segment_name, joint_name, arc_name
   public :: form_linear, form_cubic, form_table, form_name
   public :: nint_adams, nint_rk4, nint_dopri, integrator_name
   public :: nend_time, nend_contact, nend_injury, nend_rest, end_option_name
   public :: stop_curve_t, restraint_t, model_t, pulse_table_t

   integer, parameter :: n_seg = 8     !< body segments (Table 5)
   integer, parameter :: n_joint = 7   !< body joints (Table 5)
   integer, parameter :: n_dof = 10    !< alpha_1..alpha_8, x_h, y_h (section B)
   integer, parameter :: n_arc = 10    !< body contact arcs (Table 1, r)
   integer, parameter :: n_injury = 10 !< rows of the bone/joint injury table (Table 5)

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
      'Adams-Moulton PECE, modified-Euler start', 'classic Runge-Kutta 4, fixed step', &
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

   !> Everything a run needs, as read from the deck. Defaults live in the card
   !! table (deck_cards), not here: the zeros below are only initial values.
   type :: model_t
      character(len=72) :: title = ' '
      ! options (C.1)
      integer :: nbody = 0, nbelt = 0, nend = 0, nload = 0, nout = 0
      integer :: nint = 0
      ! time controls (C.3, C.6, C.7)
      real(wp) :: t_max = 0.0_wp, dt = 0.0_wp, dt_print = 0.0_wp
      real(wp) :: corrector_tol = 0.0_wp
      integer :: corrector_max_iter = 0
      real(wp) :: rtol = 0.0_wp, atol = 0.0_wp
      ! body, Table 1 (per segment)
      real(wp) :: mass(n_seg) = 0.0_wp, inertia(n_seg) = 0.0_wp
      real(wp) :: length(n_seg) = 0.0_wp, rho(n_seg) = 0.0_wp
      ! joints, Table 1 (per joint)
      real(wp) :: k_elastic(n_joint) = 0.0_wp   !< K (in*lb/rad)
      real(wp) :: c_friction(n_joint) = 0.0_wp  !< C' (in*lb)
      real(wp) :: xi(n_joint) = 0.0_wp          !< friction velocity limit (rad/s)
      type(restraint_t) :: restraint(n_joint)
      ! injury limits, Table 1 / Table 5 (0 = not checked)
      real(wp) :: f_shear(n_injury) = 0.0_wp, f_compression(n_injury) = 0.0_wp
      real(wp) :: f_tension(n_injury) = 0.0_wp
      ! contact arcs, Table 1 (10 arcs + ankle)
      real(wp) :: r_arc(n_arc + 1) = 0.0_wp, rho_arc(n_arc) = 0.0_wp
      real(wp) :: gamma_arc(n_arc) = 0.0_wp
      ! initial conditions (C.1): angles and rates relative to the interior
      real(wp) :: theta0(n_seg) = 0.0_wp, theta_dot0(n_seg) = 0.0_wp
      ! vehicle (C.1)
      real(wp) :: vehicle_mass = 0.0_wp, vehicle_inertia = 0.0_wp
      real(wp) :: xc_dot0 = 0.0_wp, yc_dot0 = 0.0_wp
      real(wp) :: phi0 = 0.0_wp, phi_dot0 = 0.0_wp
      type(pulse_table_t) :: pulse_acc, pulse_vel, pulse_pos
      character(len=:), allocatable :: pulse_source  !< 'cards' or the CSV path
      real(wp) :: gravity = 0.0_wp
      ! end-of-program test thresholds (C.7)
      real(wp) :: rest_speed = 0.0_wp, rest_rate = 0.0_wp, rest_hold = 0.0_wp
   end type model_t

contains

end module model
