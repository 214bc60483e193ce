!> The effect layer of report C.4: every term of the generalized force
!! vector b = C - G + J + S + B + Q is an effect - one module each, built
!! from the model only when the deck calls for it (effect_factory).
!!
!! An effect
!! - adds its generalized forces to b (`add_forces`). The effect is
!!   intent(in) there: its memory (a dislocated joint, a loading cycle, a
!!   broken windshield) is read-only during trial evaluations, so the
!!   compiler enforces that predictor, corrector and Runge-Kutta stages
!!   change nothing (docs/architecture.md, rule 1);
!! - may integrate auxiliary quantities with the motion (work integrals:
!!   n_aux of them, the last n_aux_start of which only start a search and
!!   stay outside the adaptive step's error norm) and carry extra degrees of freedom of its own (n_extra
!!   coordinates q and their rates, uncoupled from the body matrix, as the
!!   rigid-beam seat of C.4.d will be);
!! - changes its memory only in `accept`, after a step is accepted, and then
!!   says whether the right-hand side jumped (the stepper restarts) and
!!   which events (injuries) happened;
!! - reports its stored (conserved), dissipated and supplied energies;
!! - declares its output series and fills them at print times.
!! Evaluations are counted by the system, not by the effect (which is
!! read-only while it is evaluated).
!!
!! An effect may declare a proximity guard (proximity_guard_t, its
!! component guard): a region of a body point or segment in the interior
!! frame which the occupant tests from st's frame data before it
!! dispatches add_forces. Where the guard holds, the effect is inert at st:
!! b unchanged, every rate (extra_rate, aux_rate) zero, whatever its
!! memory; the occupant writes those zeros itself and counts the
!! evaluation, without the call (docs/architecture.md, the effect layer;
!! the contact pairs far from contact, D-C29).
module effect_base
   use kinds, only: wp
   use model, only: n_dof, n_seg
   use vehicle_motion, only: vehicle_state_t
   use output_series, only: output_series_t
   use text_io, only: string_t
   implicit none
   private

   public :: effect_t, effect_slot_t, body_state_t, event_t, accept_result_t, effect_peak_t
   public :: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds, energy_kind_name
   public :: event_dislocation_low, event_dislocation_high, event_kind_name, max_events_per_step
   public :: event_tension, event_compression, event_shear, event_undesired, event_shatter, event_cut
   public :: event_ramp_widened, n_event_kinds
   public :: point_force_t, point_force_list_t, point_force_add, point_force_reserve
   public :: proximity_guard_t, guard_none, guard_ball, guard_half_plane, guard_slab, guard_capsule, guard_always
   public :: guard_rel_margin, guard_big, guard_holds

   !> Kinds of energy an effect reports (C.6): stored in a conservative
   !! force, dissipated by it, supplied to the body from outside.
   integer, parameter :: energy_stored = 1, energy_dissipated = 2, energy_supplied = 3
   integer, parameter :: n_energy_kinds = 3
   character(len=10), parameter :: energy_kind_name(n_energy_kinds) = [character(len=10) :: &
      'stored', 'dissipated', 'supplied']

   !> Event kinds (injuries and other happenings on accepted steps).
   integer, parameter :: event_dislocation_low = 1, event_dislocation_high = 2
   !> Table 5's force criteria (force_injuries): joint j, bone i
   integer, parameter :: event_tension = 3, event_compression = 4, event_shear = 5
   !> Table 9's undesired contact of body point `index` with surface `surface` (C.7, NEND = 2)
   integer, parameter :: event_undesired = 6
   !> The windshield shattered (FSW reached), and the head cut on its broken glass (an injury)
   integer, parameter :: event_shatter = 7, event_cut = 8
   !> A contact's friction ramp widened for the fixed step (D-C18b; a note, not an injury)
   integer, parameter :: event_ramp_widened = 9
   !> The number of event kinds: every kind from 1 to it has a name here and
   !! a description in c6_output/event_text (test_every_event_kind_described)
   integer, parameter :: n_event_kinds = 9
   character(len=28), parameter :: event_kind_name(n_event_kinds) = [character(len=28) :: &
      'dislocation (below limit)', 'dislocation (above limit)', 'tension dislocation', 'compression fracture', &
      'shear fracture', 'undesired contact', 'windshield shattered', 'cut on broken glass', 'friction ramp widened']
   !> Events one effect may report at one accepted step.
   integer, parameter :: max_events_per_step = 16

   !> What every effect sees at one evaluation: the time, the occupant's
   !! generalized coordinates and rates, the sines and cosines of the
   !! segment angles, and the vehicle's state (filled only when an effect of
   !! the occupant needs it); after the vehicle's state, when an effect needs
   !! them (needs_joints: the contact pairs' bound, pair_far, reads them 20
   !! times an evaluation), the segments' joints and axes in the interior
   !! frame and the sizes that bound them (occupant_frame). No default
   !! values: it is filled at every evaluation (occupant_state), and
   !! initializing it there would cost as much as a force.
   type :: body_state_t
      real(wp) :: t
      real(wp) :: z(n_dof), zdot(n_dof)
      real(wp) :: c(n_seg), s(n_seg)
      type(vehicle_state_t) :: vehicle
      !> segment i's proximal joint and its e(theta_i) in the interior frame
      !! (x = R(Phi)(X - x_c), the start of C.4)
      real(wp) :: frame_joint(2, n_seg), frame_axis(2, n_seg)
      !> |X| + |Y| of segment i's joint (inertial) + |x_c| + |y_c|: the
      !! coordinates' size; sum |z'| + sum |vehicle rates|: the rates' size
      real(wp) :: joint_size(n_seg), rate_size
   end type body_state_t

   !> Something that happened at an accepted step.
   type :: event_t
      real(wp) :: t = 0.0_wp
      integer :: kind = 0
      integer :: index = 0          !< the joint, segment or surface it concerns
      real(wp) :: value = 0.0_wp    !< the value found
      real(wp) :: limit = 0.0_wp    !< the limit it passed
      logical :: injury = .false.   !< counts for the injury end test (C.7)
      integer :: occupant = 1
      integer :: surface = 0        !< the surface k of a contact event
   end type event_t

   !> Kinds of proximity guard: none (always dispatched); the body point
   !! q farther than the reach from the centre (ball); farther than the
   !! reach in front of the line through the centre, along the unit
   !! normal (half-plane); farther than the reach from that line on either
   !! side (slab); the segment from the joint to q (along e, the axis in
   !! the interior frame) farther than the reach from the centre
   !! (capsule); inert at every state (always).
   integer, parameter :: guard_none = 0, guard_ball = 1, guard_half_plane = 2, guard_capsule = 3, &
      guard_always = 4, guard_slab = 5
   !> The guard's margin, guard_rel_margin (1 + size + st%joint_size(seg)),
   !! added to its reach; a guard holds only where st%rate_size and
   !! size + st%joint_size(seg) are at most guard_big (not so NaN).
   real(wp), parameter :: guard_rel_margin = 2.0e-9_wp, guard_big = 1.0e100_wp

   !> A proximity guard (see the module's header). The body point is
   !! q = st%frame_joint(:, seg) + along st%frame_axis(:, seg) (ball,
   !! half-plane, slab), the capsule's axis st%frame_joint(:, seg) to that q; the
   !! reach is radius + m, m = guard_rel_margin (1 + size +
   !! st%joint_size(seg)). An effect declares one only where its holding
   !! implies, whatever the roundings of the two computations, the effect's
   !! own proof that it is inert (for a contact pair, far_check's bound,
   !! whose margin is half the guard's; radius >= 0). Declaring one makes
   !! the occupant fill st's interior frame data (as needs_joints); the
   !! occupant decides that when the effect is placed, so an effect whose
   !! guard may turn from none to another kind later must set needs_joints
   !! at construction (the contact pairs do).
   type :: proximity_guard_t
      integer :: kind = guard_none
      integer :: seg = 1
      real(wp) :: along = 0.0_wp
      real(wp) :: centre(2) = 0.0_wp, normal(2) = 0.0_wp
      real(wp) :: radius = 0.0_wp
      !> the effect's own sizes, in the margin (a pair's lengths and radii, its surface's)
      real(wp) :: size = 0.0_wp
   end type proximity_guard_t

   !> A force from outside the body (gravity, seat, belt, contact) on one
   !! segment, at a point of it: inertial components (lb) and position (in).
   !! Effects that apply such forces report them (`point_forces`), so that
   !! the joint reactions can be taken segment by segment (Newton-Euler,
   !! A-INJ), and each effect's list reproduces its generalized forces.
   type :: point_force_t
      integer :: segment = 0
      real(wp) :: point(2) = 0.0_wp
      real(wp) :: force(2) = 0.0_wp
      !> a load across the segment's bone (Table 5's shear fracture); not so
      !! gravity, spread over the segment, nor a force at a joint (the seat's
      !! hip force), which the joint passes on
      logical :: across_bone = .true.
      !> a contact's body point i, surface k and normal force P (Table 5's
      !! skull, back, rib, lower leg and face loads); 0 for other forces
      integer :: arc = 0, surface = 0
      real(wp) :: normal_force = 0.0_wp
   end type point_force_t

   !> The point forces of an occupant's effects at one state (f(1:n); it
   !! grows as forces are added, doubling, and keeps its storage when it is
   !! emptied (n = 0) and filled again: a list reserved before the step loop
   !! allocates nothing in it, docs/architecture.md).
   type :: point_force_list_t
      integer :: n = 0
      type(point_force_t), allocatable :: f(:)
   end type point_force_list_t

   !> A largest value over the accepted steps that an effect keeps (in its
   !! memory, changed in accept) and reports at the end of the run: the
   !! summary lists it and /summary/maxima of the HDF5 file has a column
   !! for it.
   type :: effect_peak_t
      character(len=19) :: name = ' '    !< the column: <effect>_<quantity>, lower case
      character(len=40) :: title = ' '   !< the effect's (for the listing)
      character(len=24) :: label = ' '   !< the quantity, for the listing
      character(len=8) :: unit = ' '
      real(wp) :: value = 0.0_wp
      real(wp) :: t = 0.0_wp             !< when
   end type effect_peak_t

   !> What `accept` reports.
   type :: accept_result_t
      logical :: restart = .false.  !< the right-hand side jumped: the stepper must restart
      integer :: n_events = 0
      type(event_t) :: events(max_events_per_step)
   end type accept_result_t

   type, abstract :: effect_t
      character(len=24) :: name = ' '    !< HDF5 group /effects/<name>; lower case, no blanks
      character(len=40) :: title = ' '   !< for the listing, with the report section
      integer :: n_aux = 0               !< auxiliary integrated quantities
      !> the last n_aux_start of them are only starting values of searches,
      !! integrated for speed: outside the step-size control (D-B7)
      integer :: n_aux_start = 0
      integer :: n_extra = 0             !< extra degrees of freedom (coordinates; rates follow)
      logical :: needs_vehicle = .false. !< reads st%vehicle
      !> reads st%frame_joint, frame_axis, joint_size, rate_size (and so needs_vehicle too)
      logical :: needs_joints = .false.
      logical :: acts = .true.           !< adds generalized forces (a pure monitor does not)
      logical :: has_memory = .false.    !< its accept changes something (only such are called)
      !> a jump of its right-hand side can be located inside a step (locate;
      !! only such are asked)
      logical :: locates = .false.
      logical :: has_energy(n_energy_kinds) = .false.
      !> applies forces from outside the body, which `point_forces` reports
      logical :: external = .false.
      !> where the effect is inert for certain, tested before each dispatch (D-C29)
      type(proximity_guard_t) :: guard
   contains
      procedure(add_forces_interface), deferred :: add_forces
      procedure :: accept => effect_accept
      procedure :: energy => effect_energy
      procedure :: outputs => effect_outputs
      procedure :: output_values => effect_output_values
      procedure :: describe => effect_describe
      procedure :: initial_extra => effect_initial_extra
      procedure :: failure_text => effect_failure_text
      procedure :: point_forces => effect_point_forces
      procedure :: peaks => effect_peaks
      procedure :: locate => effect_locate
      procedure :: initial_notes => effect_initial_notes
   end type effect_t

   !> An effect in a list.
   type :: effect_slot_t
      class(effect_t), allocatable :: e
   end type effect_slot_t

   abstract interface
      !> Add this effect's generalized forces to b; write the rates of its
      !! auxiliary quantities and of its extra degrees of freedom. extra
      !! holds (q, q') of the extra degrees of freedom; aux the auxiliary
      !! quantities. Must not fail: bounded input gives bounded output.
      pure subroutine add_forces_interface(this, st, extra, aux, b, extra_rate, aux_rate)
         import :: effect_t, body_state_t, wp, n_dof
         class(effect_t), intent(in) :: this
         type(body_state_t), intent(in) :: st
         real(wp), intent(in) :: extra(:), aux(:)
         real(wp), intent(inout) :: b(n_dof)
         real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      end subroutine add_forces_interface
   end interface

contains

   !> Whether the proximity guard g holds at st (st's interior frame data
   !! filled: occupant_frame): the effect is then inert at st. A guard of
   !! kind none never holds, one of kind always at every state.
   pure logical function guard_holds(g, st) result(holds)
      type(proximity_guard_t), intent(in) :: g
      type(body_state_t), intent(in) :: st
      real(wp) :: scale, reach, q(2), v(2), u2, lam
      holds = g%kind == guard_always
      if (g%kind == guard_none .or. holds) return
      scale = g%size + st%joint_size(g%seg)
      if (.not. (st%rate_size <= guard_big .and. scale <= guard_big)) return
      reach = g%radius + guard_rel_margin*(1.0_wp + scale)
      select case (g%kind)
      case (guard_ball)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = q(1)*q(1) + q(2)*q(2) > reach*reach
      case (guard_half_plane)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = q(1)*g%normal(1) + q(2)*g%normal(2) > reach
      case (guard_slab)
         q = st%frame_joint(:, g%seg) + g%along*st%frame_axis(:, g%seg) - g%centre
         holds = abs(q(1)*g%normal(1) + q(2)*g%normal(2)) > reach
      case (guard_capsule)
         ! the centre's distance to the segment from the joint to q
         v = g%along*st%frame_axis(:, g%seg)
         q = g%centre - st%frame_joint(:, g%seg)
         u2 = v(1)*v(1) + v(2)*v(2)
         lam = 0.0_wp
         if (u2 > 0.0_wp) lam = min(1.0_wp, max(0.0_wp, (q(1)*v(1) + q(2)*v(2))/u2))
         q = q - lam*v
         holds = q(1)*q(1) + q(2)*q(2) > reach*reach
      end select
   end function guard_holds

   !> Room for at least n forces in the list (its forces kept).
   pure subroutine point_force_reserve(list, n)
      type(point_force_list_t), intent(inout) :: list
      integer, intent(in) :: n
      type(point_force_t), allocatable :: longer(:)
      if (allocated(list%f)) then
         if (size(list%f) >= n) return
      end if
      allocate (longer(max(n, 16)))
      if (list%n > 0) longer(1:list%n) = list%f(1:list%n)
      call move_alloc(longer, list%f)
   end subroutine point_force_reserve

   !> Append a force to a list.
   pure subroutine point_force_add(list, segment, point, force, across_bone, arc, surface, normal_force)
      type(point_force_list_t), intent(inout) :: list
      integer, intent(in) :: segment
      real(wp), intent(in) :: point(2), force(2)
      logical, intent(in), optional :: across_bone
      integer, intent(in), optional :: arc, surface
      real(wp), intent(in), optional :: normal_force
      if (.not. allocated(list%f)) then
         call point_force_reserve(list, 16)
      else if (list%n == size(list%f)) then
         call point_force_reserve(list, 2*size(list%f))
      end if
      list%n = list%n + 1
      list%f(list%n) = point_force_t(segment=segment, point=point, force=force)
      if (present(across_bone)) list%f(list%n)%across_bone = across_bone
      if (present(arc)) list%f(list%n)%arc = arc
      if (present(surface)) list%f(list%n)%surface = surface
      if (present(normal_force)) list%f(list%n)%normal_force = normal_force
   end subroutine point_force_add

   !> The forces from outside the body that the effect applies, appended
   !! to list: none for the default effect (internal torques, inertia).
   pure subroutine effect_point_forces(this, st, extra, aux, list)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux), u4 => list%n)
      end associate
   end subroutine effect_point_forces

   !> After an accepted step: update memory, report events and jumps. The
   !! default effect has no memory.
   subroutine effect_accept(this, st, extra, aux, result)
      class(effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux), u4 => result%n_events)
      end associate
   end subroutine effect_accept

   !> Where inside the step just taken the effect's right-hand side should
   !! have jumped, as a fraction theta of the step (0 < theta < 1) from the
   !! last accepted state to st, a state not yet accepted (memory
   !! read-only); 0 when it need not be located; 1 or more when st falls
   !! short of a jump the effect watches for (read while the driver
   !! searches for one). The driver then takes the
   !! step again to that fraction (simulation: the windshield's break,
   !! D-C24b). The default effect never asks.
   pure real(wp) function effect_locate(this, st, extra, aux) result(theta)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      theta = 0.0_wp
   end function effect_locate

   !> What the user should know of the effect at the initial state st (a
   !! warning each, for the listing and standard error): nothing by default.
   function effect_initial_notes(this, st, extra, aux) result(notes)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(string_t), allocatable :: notes(:)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      allocate (notes(0))
   end function effect_initial_notes

   !> The largest values the effect kept over the accepted steps (effect_peak_t).
   !! None by default.
   function effect_peaks(this) result(p)
      class(effect_t), intent(in) :: this
      type(effect_peak_t), allocatable :: p(:)
      associate (unused => this%name)
      end associate
      allocate (p(0))
   end function effect_peaks

   !> The effect's energies (in*lb): stored, dissipated, supplied. Zero by default.
   pure subroutine effect_energy(this, st, extra, aux, e)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      e = 0.0_wp
   end subroutine effect_energy

   !> The effect's own output series (beyond its generalized force, which
   !! the registry adds for every acting effect). None by default.
   function effect_outputs(this) result(series)
      class(effect_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      allocate (series(0))
   end function effect_outputs

   !> The values of the effect's output series number item at this state.
   pure subroutine effect_output_values(this, item, st, extra, aux, values)
      class(effect_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      associate (unused => this%name, u1 => item, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      values = 0.0_wp
   end subroutine effect_output_values

   !> The initial values of the extra degrees of freedom (q, then q'); zero
   !! by default (the rigid-beam seat will start from its static deflection).
   pure subroutine effect_initial_extra(this, extra)
      class(effect_t), intent(in) :: this
      real(wp), intent(out) :: extra(:)
      associate (unused => this%name)
      end associate
      extra = 0.0_wp
   end subroutine effect_initial_extra

   !> Why an evaluation at this state gave rates that are not finite, when
   !! the effect knows ('' by default): the system asks when an evaluation
   !! fails, for the failure message (an effect whose internal solve cannot
   !! converge says so here; add_forces itself cannot return an error).
   pure function effect_failure_text(this, st, extra, aux) result(text)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      character(len=:), allocatable :: text
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      text = ''
   end function effect_failure_text

   !> One line for the listing: what the effect acts on.
   function effect_describe(this) result(text)
      class(effect_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)
   end function effect_describe
end module effect_base
