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
!! - declares its output series and fills them at print times (one
!!   series at a time, `output_values`, or everything a print time's frame
!!   takes from it at once, `frame_values`, which an effect whose series
!!   each repeat one evaluation overrides).
!! Evaluations are counted by the system, not by the effect (which is
!! read-only while it is evaluated).
!!
!! The evaluation that ends a step (the integrator marks it: ode_system's
!! rhs_end) is at the state the step is accepted at, with the memory accept
!! then starts from. An effect that `keeps` takes it through
!! `add_forces_kept` instead of add_forces, which may keep what its accept
!! needs (a cache, not memory: the forces are add_forces' bits), tagged by
!! the inputs it was computed from (kept_inputs_t); accept takes it where
!! the tags match bit for bit and computes it again where they do not, and
!! forgets it (its memory may change). Issue 16 section 4.
!!
!! An effect whose force or slope changes discontinuously at a threshold
!! of the state declares switching functions (n_switch, `switches`), which
!! the driver locates inside steps (issue 15).
!!
!! An effect may declare a proximity guard (proximity_guard): a region
!! where it is inert for certain, tested before each dispatch (D-C29).
!!
!! What the interface's procedures take and give has a module each:
!! body_state (what an effect sees; also public here), effect_events
!! (what accept reports), effect_energies, point_forces, effect_peaks,
!! proximity_guard, output_series; effect_slots holds effects in a list.
module effect_base
   use kinds, only: wp, i8
   use model, only: n_dof, n_seg
   use body_state, only: body_state_t
   use effect_energies, only: n_energy_kinds
   use effect_events, only: accept_result_t
   use point_forces, only: point_force_list_t
   use effect_peaks, only: effect_peak_t
   use proximity_guard, only: proximity_guard_t
   use output_series, only: output_series_t
   use text_io, only: string_t
   use sliding_surface, only: slide_t
   implicit none
   private

   !> (body_state_t: the interface's state argument, public here too)
   public :: effect_t, body_state_t, slide_t
   public :: kept_inputs_t, kept_set, kept_matches

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
      !> its accept may say it changed none of its memory (accept_result_t's
      !! memory_unchanged; the switch locator then keeps its switching
      !! functions, issue 16 section 4)
      logical :: reports_unchanged = .false.
      !> switching functions (`switches`): where the force or its slope
      !! changes discontinuously (issue 15); none by default
      integer :: n_switch = 0
      !> sliding constraints it may hold (`slides`, `release`): Filippov's
      !! sliding on a surface where its force is discontinuous (issue 15)
      integer :: n_slide = 0
      logical :: has_energy(n_energy_kinds) = .false.
      !> applies forces from outside the body, which `point_forces` reports
      logical :: external = .false.
      !> deflects the chest's body material (material 12), which
      !! `chest_deflection` reports (issue 18: the FMVSS 208 table)
      logical :: deflects_chest = .false.
      !> the segments its point forces may act on (all unless it says):
      !! the FMVSS 208 table's neck and femur loads ask only the effects
      !! that can load the head or the legs (occupant_point_forces)
      logical :: acts_on(n_seg) = .true.
      !> where the effect is inert for certain, tested before each dispatch (D-C29)
      type(proximity_guard_t) :: guard
      !> the evaluation that ends a step goes through add_forces_kept, which
      !! keeps what accept needs (issue 16 section 4); .false.: add_forces.
      !! Not with sliding constraints (n_slide > 0): a release changes the
      !! memory outside accept, which would leave the kept results stale
      !! (occupant_add_effect then ignores it)
      logical :: keeps = .false.
      !> accepts that took the kept results instead of computing them again
      !! (counted, for the tests and measurements)
      integer(i8) :: accepts_reused = 0
   contains
      procedure(add_forces_interface), deferred :: add_forces
      procedure :: add_forces_kept => effect_add_forces_kept
      procedure :: accept => effect_accept
      procedure :: energy => effect_energy
      procedure :: outputs => effect_outputs
      procedure :: output_values => effect_output_values
      procedure :: frame_values => effect_frame_values
      procedure :: describe => effect_describe
      procedure :: initial_extra => effect_initial_extra
      procedure :: failure_text => effect_failure_text
      procedure :: point_forces => effect_point_forces
      procedure :: chest_deflection => effect_chest_deflection
      procedure :: peaks => effect_peaks
      procedure :: study_peaks => effect_study_peaks
      procedure :: switches => effect_switches
      procedure :: slides => effect_slides
      procedure :: release => effect_release
      procedure :: initial_notes => effect_initial_notes
   end type effect_t

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

   !> The inputs an effect's kept results were computed from: the time, the
   !! occupant's coordinates and rates, the effect's auxiliary quantities.
   !! What else an evaluation reads is a function of these (the segments'
   !! cosines and sines, the vehicle's state at t, the interior frame's
   !! data) or the effect's memory, which accept forgets the kept results
   !! with. valid: set by kept_set.
   type :: kept_inputs_t
      logical :: valid = .false.
      real(wp) :: t = 0.0_wp
      real(wp) :: z(n_dof) = 0.0_wp, zdot(n_dof) = 0.0_wp
      real(wp), allocatable :: aux(:)
      real(wp), allocatable :: extra(:)   !< the effect's own coordinates and rates, if any
   end type kept_inputs_t

contains

   !> add_forces at the evaluation that ends a step (rhs_end): the default
   !! keeps nothing.
   subroutine effect_add_forces_kept(this, st, extra, aux, b, extra_rate, aux_rate)
      class(effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      call this%add_forces(st, extra, aux, b, extra_rate, aux_rate)
   end subroutine effect_add_forces_kept

   !> Tag kept results with the inputs (st, extra, aux) they were computed
   !! from (the rooms allocated at the first, then reused: their sizes are
   !! fixed).
   pure subroutine kept_set(k, st, extra, aux)
      type(kept_inputs_t), intent(inout) :: k
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      integer :: i
      call fit(k%aux, size(aux))
      call fit(k%extra, size(extra))
      k%t = st%t
      k%z = st%z
      k%zdot = st%zdot
      do i = 1, size(aux)
         k%aux(i) = aux(i)
      end do
      do i = 1, size(extra)
         k%extra(i) = extra(i)
      end do
      k%valid = .true.
   contains
      pure subroutine fit(a, n)
         real(wp), allocatable, intent(inout) :: a(:)
         integer, intent(in) :: n
         if (allocated(a)) then
            if (size(a) == n) return
            deallocate (a)
         end if
         allocate (a(n))
      end subroutine fit
   end subroutine kept_set

   !> The kept results were computed from exactly these inputs: every one
   !! the same bits (a signed zero or a NaN is not taken for another).
   pure logical function kept_matches(k, st, extra, aux) result(same)
      type(kept_inputs_t), intent(in) :: k
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      integer :: i
      same = .false.
      if (.not. k%valid) return
      if (size(k%aux) /= size(aux) .or. size(k%extra) /= size(extra)) return
      do i = 1, size(extra)
         if (.not. same_bits(k%extra(i), extra(i))) return
      end do
      if (.not. same_bits(k%t, st%t)) return
      do i = 1, n_dof
         if (.not. (same_bits(k%z(i), st%z(i)) .and. same_bits(k%zdot(i), st%zdot(i)))) return
      end do
      do i = 1, size(aux)
         if (.not. same_bits(k%aux(i), aux(i))) return
      end do
      same = .true.
   contains
      pure logical function same_bits(a, b)
         real(wp), intent(in) :: a, b
         same_bits = transfer(a, 0_i8) == transfer(b, 0_i8)
      end function same_bits
   end function kept_matches

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

   !> The largest deflection (in) of the chest's body material (material 12)
   !! that the effect's chains share at st (issue 18): 0 for the default
   !! effect, which deflects no chest (deflects_chest).
   pure real(wp) function effect_chest_deflection(this, st, extra, aux) result(d)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      d = 0.0_wp
   end function effect_chest_deflection

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

   !> The effect's switching functions at state st (n_switch of them, in
   !! g): each continuous in the state for the memory the effect holds, and
   !! changing sign exactly where the effect's force, or the force's slope,
   !! changes discontinuously - a threshold of the state (a contact's
   !! onset), or where its memory should change (a friction direction, a
   !! loading branch). Read-only, as add_forces. After every step the driver
   !! compares their signs with those at the last accepted state and, when
   !! one changed, takes the step again to the first change, and accepts
   !! just past it (switch_location, docs/architecture.md "Switches"): the
   !! memory changes there, and the next step starts on the other side.
   !! The default effect has none.
   pure subroutine effect_switches(this, st, extra, aux, g)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux))
      end associate
      g = 1.0_wp
   end subroutine effect_switches

   !> The effect's sliding constraints at st (n_slide of them; issue 15,
   !! sliding_surface): where a friction force that is discontinuous across
   !! a surface of the state (its sliding velocity at an edge of the dead
   !! band) points into the surface from both sides, the motion slides on it
   !! (Filippov). The effect holds whether each is active (memory: entered
   !! in its accept, left by `release`) and adds no force of its own for an
   !! active one; the occupant's solve finds the multiplier (c5,
   !! sliding_constraints). None by default.
   pure subroutine effect_slides(this, st, extra, aux, s)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(slide_t), intent(out) :: s(:)
      associate (unused => this%name, u2 => st%t, u3 => size(extra) + size(aux), u4 => size(s))
      end associate
   end subroutine effect_slides

   !> Sliding constraint k leaves the surface: its multiplier reached hi
   !! (at_upper) or lo, and the law's force on that side takes over
   !! (memory: called on an accepted state, issue 15). Nothing by default.
   subroutine effect_release(this, k, at_upper)
      class(effect_t), intent(inout) :: this
      integer, intent(in) :: k
      logical, intent(in) :: at_upper
      associate (unused => this%name, u2 => k, u3 => at_upper)
      end associate
   end subroutine effect_release

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

   !> The largest values the effect kept over the accepted steps for a
   !! study's criteria alone (C.8; c8_modification/study_criteria): like
   !! peaks, but neither the listing nor HDF5 shows them (their output
   !! stays as it was). None by default; the belts' tensions.
   function effect_study_peaks(this) result(p)
      class(effect_t), intent(in) :: this
      type(effect_peak_t), allocatable :: p(:)
      associate (unused => this%name)
      end associate
      allocate (p(0))
   end function effect_study_peaks

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

   !> Everything a print time's frame takes from the effect at st, at once
   !! (issue 16 section 4): its energies e (as `energy`); the values of its
   !! own series j = 1, 2, ... (as `output_values`) into values(at(j) + 1 :
   !! at(j) + width(j)), for each j <= size(at) with at(j) >= 0 (a series not
   !! wanted has at(j) < 0); when gf, its generalized force added to b (as
   !! `add_forces`); when pf, its point forces appended to list (as
   !! `point_forces`); when sums, its generalized force added to b_sum, the
   !! running sum of the occupant's effects' forces, as `add_forces` adds it
   !! (for the sliding constraints' solve). Rates are not kept. The same
   !! bits as those procedures called one by one, which this default does;
   !! an effect whose procedures each repeat one evaluation (a contact pair,
   !! a belt) evaluates once here instead.
   pure subroutine effect_frame_values(this, st, extra, aux, e, values, at, width, gf, b, pf, list, sums, b_sum)
      class(effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      real(wp), intent(inout) :: values(:)
      integer, intent(in) :: at(:), width(:)
      logical, intent(in) :: gf, pf, sums
      real(wp), intent(inout) :: b(n_dof), b_sum(n_dof)
      type(point_force_list_t), intent(inout) :: list
      integer :: j
      call this%energy(st, extra, aux, e)
      do j = 1, size(at)
         if (at(j) < 0) cycle
         call this%output_values(j, st, extra, aux, values(at(j) + 1:at(j) + width(j)))
      end do
      if (gf) call forces(b)
      if (pf) call this%point_forces(st, extra, aux, list)
      if (sums) call forces(b_sum)
   contains
      !> add_forces into bb (its rates discarded: on the stack where they
      !! are few, as they are but for a test's effect)
      pure subroutine forces(bb)
         real(wp), intent(inout) :: bb(n_dof)
         integer, parameter :: few = 16
         real(wp) :: extra_rate(few), aux_rate(few)
         if (size(extra) <= few .and. size(aux) <= few) then
            call this%add_forces(st, extra, aux, bb, extra_rate(1:size(extra)), aux_rate(1:size(aux)))
         else
            block
               real(wp), allocatable :: extra_rates(:), aux_rates(:)
               allocate (extra_rates(size(extra)), aux_rates(size(aux)))
               call this%add_forces(st, extra, aux, bb, extra_rates, aux_rates)
            end block
         end if
      end subroutine forces
   end subroutine effect_frame_values

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
