!> What a run does after each accepted step (docs/architecture.md, rule 1):
!! the effects' accept (memory, events, jumps), the maxima and the
!! acceleration criteria, Table 5's force criteria, the end tests (C.7),
!! and a restart of the stepper when an effect's memory made the
!! right-hand side jump; and at print times the energy balance against its
!! tolerance. Each occupant's limits, end test and criteria are its own
!! (its NEND, rest limits, Table 5 limits). Nothing is allocated here at a
!! step: the room it needs is reserved by books_init.
module step_bookkeeping
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp, i8, g_std, inch_m, inch_mm, pound_force_n
   use acceleration_criteria, only: criteria_new
   use error_handling, only: error_t, error_set, error_prefix, exit_numerical
   use strings, only: num
   use model, only: n_dof, n_seg, n_joint, n_injury, joint_partner, nend_rest, numerics_section_t, vehicle_section_t, &
      fmvss_limits_t
   use equations_of_motion, only: crash_system_t, system_body_state, system_settle
   use occupant, only: occupant_t, occupant_state, occupant_point_forces, occupant_vehicle, occupant_chest_deflection
   use ode_system, only: stepper_t, evaluate_outside_step
   use effect_base, only: body_state_t
   use effect_events, only: accept_result_t, event_t
   use point_forces, only: point_force_list_t, point_force_reserve
   use joint_reactions, only: segment_cg_states, joint_reactions_at, joint_moment_at, bone_components_at, distal
   use body_kinematics, only: point_state_t
   use force_injuries, only: bone_loads_t, bone_loads, fc_defined, fs_defined, force_injury_event, event_tension, &
      event_compression, event_shear
   use joint_coupling, only: relative_angle
   use output_calc, only: head_chest_acceleration, head_chest_motion, head_interior_x
   use output_producers, only: frame_energy, energy_balance_t
   use run_summary, only: run_summary_t, occupant_summary_t, extreme_t, raise, summary_add_event
   use fmvss_table, only: fmvss_belts_reserve, fmvss_belts_sample
   use channel_record, only: channel_grid_head
   use accuracy_estimate, only: accuracy_t
   use end_tests, only: end_state_t, end_none, end_failure, end_energy, end_injury, end_contact, end_rest, &
      end_test_update, body_at_rest
   use sink_list, only: sink_list_t
   implicit none
   private

   public :: step_books_t, record_failure

   !> A balance error below this fraction of its scale is rounding.
   real(wp), parameter :: rounding = 1.0e-9_wp
   !> The distal sides of the neck (the head) and the hip (thigh, shank):
   !! the segments whose forces the FMVSS 208 table's loads need (sample_loads)
   logical, parameter :: loads_segments(n_seg) = distal(:, 4) .or. distal(:, 1)

   type :: step_books_t
      type(end_state_t), allocatable :: end_state(:)   !< each occupant's rest timer (C.7)
      logical, allocatable :: injured(:)               !< each occupant injured so far (C.7, NEND = 3)
      !> the point forces for Table 5's criteria, reused from step to step
      type(point_force_list_t) :: forces
      !> the derivative at the accepted point, kept for the frame of a restart that fails
      !> workspace of the sliding constraints' settling (system_settle)
      real(wp), allocatable :: rates(:)
      integer(i8), allocatable :: counts(:)
      real(wp), allocatable :: f_accepted(:)
      !> an occupant's state at the accepted point (kept from step to step;
      !! its vehicle state only when something reads it)
      type(body_state_t) :: st
      !> *NUMERICS EBTOL and EBFAIL; whether the vehicle's rates or
      !! positions are tabulated (the balance's message then says more)
      type(numerics_section_t) :: numerics
      logical :: pulse_tabulated = .false.
      !> the accuracy estimate's books (docs/accuracy.md): the last
      !! accepted point (where the next step starts), the stepper's
      !! rejected and retaken steps then (a fixed-step stepper has those only
      !! where it takes a step again to a located jump or switch), room for a state moved by its
      !! estimated error and its derivative
      real(wp) :: t_accepted = 0.0_wp
      integer(i8) :: rejected_seen = 0
      real(wp), allocatable :: y_moved(:), f_moved(:)
      !> at the last accept, effect k of occupant o (k, o) changed none of
      !! its memory (an effect without memory, or one whose accept said so;
      !! none where a sliding constraint left its surface): the switch
      !! locator keeps its switching functions (issue 16 section 4)
      logical, allocatable :: memory_unchanged(:, :)
      !> some effect may say so (effect_t%reports_unchanged): else the flags
      !! stay false and cost nothing
      logical :: tracks_unchanged = .false.
      !> the head's excursion is kept (model_t%options%head_excursion)
      logical :: head_excursion = .false.
   contains
      procedure :: init => books_init
      procedure :: accept => books_accept
      procedure :: check_energy => books_check_energy
   end type step_books_t

contains

   !> The books of a run of sys from (t, y): C.2's initial outputs in the
   !! summary (the energy totals the balance is measured from, the initial
   !! joint angles the ranges start from, the criteria), and the room the
   !! accepted steps need.
   subroutine books_init(this, sys, t, y, numerics, vehicle, summary, head_excursion, fmvss, duration, belt_channels)
      class(step_books_t), intent(out) :: this
      type(crash_system_t), intent(in) :: sys
      real(wp), intent(in) :: t, y(:)
      type(numerics_section_t), intent(in) :: numerics
      type(vehicle_section_t), intent(in) :: vehicle
      type(run_summary_t), intent(inout) :: summary
      logical, intent(in), optional :: head_excursion   !< keep the head's excursion (C.8's HEADX)
      !> the FMVSS 208 table's limits (*FMVSS208): its channels are kept (absent: no table)
      type(fmvss_limits_t), intent(in), optional :: fmvss
      real(wp), intent(in), optional :: duration            !< the run's length (s): the channels' room
      !> with fmvss: keep the belt sections' tensions too (an HDF5 file's or an
      !! ISO-MME data set's channels; fmvss_belts_reserve)
      logical, intent(in), optional :: belt_channels
      real(wp) :: room
      integer :: o, i, n_occ
      n_occ = size(sys%occupants)
      this%numerics = numerics
      this%t_accepted = t
      if (present(head_excursion)) this%head_excursion = head_excursion
      allocate (this%y_moved(size(y)), this%f_moved(size(y)))
      this%pulse_tabulated = allocated(vehicle%pulse_vel%t) .or. allocated(vehicle%pulse_pos%t)
      allocate (summary%occ(n_occ), this%end_state(n_occ), this%injured(n_occ), this%f_accepted(size(y)))
      this%injured = .false.
      do o = 1, n_occ
         this%st = system_body_state(sys, o, t, y)
         associate (eb => frame_energy(sys%occupants(o), this%st, y, 0.0_wp))
            summary%occ(o)%e_total0 = eb%total
         end associate
         summary%occ(o)%head_criteria = criteria_new()
         summary%occ(o)%chest_criteria = criteria_new(with_hic=.false.)   ! GSI and the 3 ms clip
         ! the channels of the FMVSS 208 table (fmvss_table), with room for the run
         ! (a run without it, whose outputs go nowhere, a study's: none)
         room = 0.0_wp
         if (present(duration)) room = duration
         if (present(fmvss)) then
            summary%occ(o)%fmvss_limits = fmvss
            summary%occ(o)%channels%kept = .true.
            ! (the head's at 20 kHz, CFC 1000's corridor: channel_record)
            call summary%occ(o)%channels%head%reserve(2, room, h=channel_grid_head)
            call summary%occ(o)%channels%chest%reserve(2, room)
            ! the neck's and femur's loads from the joint reactions
            summary%occ(o)%channels%neck_kept = .true.
            summary%occ(o)%channels%femur_kept = .true.
            call summary%occ(o)%channels%neck%reserve(2, room)
            call summary%occ(o)%channels%femur%reserve(1, room)
            ! the chest's deflection where an effect deflects its material
            summary%occ(o)%channels%deflection_kept = &
               any([(sys%occupants(o)%effects(i)%e%deflects_chest, i=1, size(sys%occupants(o)%effects))])
            if (summary%occ(o)%channels%deflection_kept) call summary%occ(o)%channels%deflection%reserve(1, room)
            if (present(belt_channels)) then
               if (belt_channels) call fmvss_belts_reserve(summary%occ(o)%channels, sys%occupants(o), room)
            end if
         end if
         ! Table 5's force criteria only when the occupant's deck gives a limit
         ! (they cost the point forces and the joint reactions at every
         ! accepted step)
         associate (lim => sys%occupants(o)%injury)
            summary%occ(o)%force_checked = any(lim%f_tension > 0.0_wp) .or. any(lim%f_compression > 0.0_wp) &
                                           .or. any(lim%f_shear > 0.0_wp)
            summary%occ(o)%force_limits = lim
         end associate
         ! where the head's excursion is measured from
         summary%occ(o)%head_x0 = head_interior_x(sys%occupants(o)%body, this%st%z, this%st%c, this%st%s, &
                                                  this%st%vehicle%pos)
         summary%occ(o)%head_excursion = extreme_t(0.0_wp, t)
         ! not kept: not a number, never a silent 0 (C.8's HEADX asks for it)
         if (.not. this%head_excursion) summary%occ(o)%head_excursion%value = ieee_value(0.0_wp, ieee_quiet_nan)
         do i = 1, n_joint
            summary%occ(o)%joint_min(i) = extreme_t(relative_angle(this%st%z, i), 0.0_wp)
            summary%occ(o)%joint_max(i) = summary%occ(o)%joint_min(i)
         end do
      end do
      ! Nothing allocated in the step loop (docs/architecture.md): room for
      ! the point forces, one per segment of each effect from outside (the
      ! most any reports: gravity's)
      if (any([(summary%occ(o)%force_checked .or. summary%occ(o)%channels%neck_kept, o=1, n_occ)])) &
         call point_force_reserve(this%forces, n_seg*maxval([(count([(sys%occupants(o)%effects(i)%e%external, &
                                                                  i=1, size(sys%occupants(o)%effects))]), o=1, n_occ)]))
   end subroutine books_init

   !> Memory updates after the step accepted at (t, y) (docs/architecture.md,
   !! rule 1): the effects' accept, maxima, the end tests; a restart of the
   !! stepper when an effect's memory made the right-hand side jump. last:
   !! the run ends at this step (TMAX), so no restart. The run ends
   !! (reason) at the first injury or undesired contact of an occupant
   !! whose NEND asks for it, or when every occupant whose NEND asks for
   !! rest has rested for its THOLD; end_failure when the restart fails
   !! (err: why). Events go to the summary and the sinks.
   subroutine books_accept(this, sys, stepper, t, y, last, summary, sinks, reason, err, kink)
      class(step_books_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      logical, intent(in) :: last
      type(run_summary_t), intent(inout) :: summary
      type(sink_list_t), intent(inout) :: sinks
      integer, intent(out) :: reason
      type(error_t), intent(inout) :: err
      !> the vehicle's motion kinks at t (print_schedule): a multistep
      !! method restarts, its back values spanning the kink
      logical, intent(in), optional :: kink
      type(accept_result_t) :: ar
      type(error_t) :: why
      real(wp) :: a_head, a_chest, delta, h, dzdd(n_dof)
      integer :: k, q, j, o, xo, ao, reason_o
      logical :: restart, undesired, at_rest, any_rest, all_rested, settled, estimated, located

      restart = .false.
      any_rest = .false.
      all_rested = .true.
      reason = end_none
      if (.not. allocated(this%memory_unchanged)) then
         k = 0
         do o = 1, size(sys%occupants)
            k = max(k, size(sys%occupants(o)%effects))
         end do
         allocate (this%memory_unchanged(k, size(sys%occupants)))
         this%memory_unchanged = .false.
         do o = 1, size(sys%occupants)
            do k = 1, size(sys%occupants(o)%effects)
               if (sys%occupants(o)%effects(k)%e%reports_unchanged) this%tracks_unchanged = .true.
            end do
         end do
      end if
      if (this%tracks_unchanged) this%memory_unchanged = .true.
      ! the step's local error estimate (a fixed-step stepper's), read once;
      ! the step was taken again to a located switch when the stepper
      ! rejected one (the windshield's jump) or took one again (a switch)
      h = t - this%t_accepted
      this%t_accepted = t
      estimated = stepper%local_error_new .and. allocated(stepper%local_error)
      stepper%local_error_new = .false.
      located = stepper%stats%rejected + stepper%stats%retaken /= this%rejected_seen
      this%rejected_seen = stepper%stats%rejected + stepper%stats%retaken
      do o = 1, size(sys%occupants)
         undesired = .false.
         associate (occ => sys%occupants(o), os => summary%occ(o), st => this%st)
            ! the vehicle's state only when something reads it
            call occupant_state(occ, t, y, st)
            if (sys%needs_vehicle .or. occ%nend == nend_rest .or. this%head_excursion) &
               call occupant_vehicle(occ, sys%vm, t, st)
            ! the head's forward excursion relative to the interior (C.8's
            ! HEADX), only where a study asks for it
            if (this%head_excursion) call raise(os%head_excursion, &
               head_interior_x(occ%body, st%z, st%c, st%s, st%vehicle%pos) - os%head_x0, t)
            ! Table 5's force criteria and the FMVSS table's neck and femur
            ! loads, with the memory the step was taken with (the point
            ! forces once for both)
            if (os%force_checked) then
               call occupant_point_forces(occ, st, y, this%forces)
            else if (os%channels%neck_kept) then
               call occupant_point_forces(occ, st, y, this%forces, loads_segments)
            end if
            if (os%force_checked) &
               call force_criteria(this, occ, o, t, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), summary, sinks)
            if (os%channels%neck_kept) &
               call sample_loads(occ, st, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), this%forces, t, os)
            ! the chest's deflection (mm) under the torso belt and its contacts
            if (os%channels%deflection_kept) &
               call os%channels%deflection%add(t, [inch_mm*occupant_chest_deflection(occ, st, y)])
            if (os%channels%belts_kept) call fmvss_belts_sample(os%channels, occ, st, y, t)
            if (estimated) then
               call os%accuracy%add_step(t, stepper%local_error(occ%z_offset + 1:occ%z_offset + n_dof), &
                                         stepper%local_error(occ%zdot_offset + 1:occ%zdot_offset + n_dof))
               ! the head's peak so far: its sensitivity to the estimated
               ! state error, with the memory the step was taken with
               call head_chest_acceleration(occ%body, st%c, st%s, st%zdot, &
                                            stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), a_head, a_chest)
               if (a_head > os%head_max%value .and. os%accuracy%head_due(a_head)) &
                  call head_sensitivity(this, sys, stepper, o, t, y, a_head, os%accuracy)
            end if
            do q = 1, size(occ%remembering)
               k = occ%remembering(q)
               ar%restart = .false.
               ar%n_events = 0
               ar%memory_unchanged = .false.
               xo = occ%extra_offset(k)
               ao = occ%aux_offset(k)
               associate (e => occ%effects(k)%e)
                  call e%accept(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), ar)
               end associate
               if (this%tracks_unchanged) this%memory_unchanged(k, o) = ar%memory_unchanged
               restart = restart .or. ar%restart
               do j = 1, ar%n_events
                  ar%events(j)%occupant = o
                  this%injured(o) = this%injured(o) .or. ar%events(j)%injury
                  undesired = undesired .or. ar%events(j)%undesired
                  call summary_add_event(summary, ar%events(j))
                  call sinks%event(ar%events(j))
               end do
            end do
            call sample_criteria(occ, st, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), t, os)
            do k = 1, n_joint
               delta = st%z(k) - st%z(joint_partner(k))
               if (delta < os%joint_min(k)%value) os%joint_min(k) = extreme_t(delta, t)
               if (delta > os%joint_max(k)%value) os%joint_max(k) = extreme_t(delta, t)
            end do
            ! C.7 with the occupant's own NEND and limits
            at_rest = .false.
            if (occ%nend == nend_rest) at_rest = body_at_rest(occ%body, occ%end_tests, st%z, st%zdot, st%vehicle)
            call end_test_update(occ%nend, occ%end_tests, this%end_state(o), t, this%injured(o), at_rest, &
                                 reason_o, undesired)
            if (occ%nend == nend_rest) then
               any_rest = .true.
               all_rested = all_rested .and. reason_o == end_rest
            else if (reason_o == end_injury .or. reason_o == end_contact) then
               if (reason == end_none) reason = reason_o
            end if
         end associate
      end do
      if (reason == end_none .and. any_rest .and. all_rested) reason = end_rest
      ! sliding constraints that cannot hold leave their surfaces here,
      ! after the effects' own memory changed (issue 15)
      if (.not. allocated(this%rates)) allocate (this%rates(size(y)), this%counts(size(sys%counts, 1)))
      call system_settle(sys, t, y, settled, this%rates, this%counts)
      restart = restart .or. settled
      if (settled .and. this%tracks_unchanged) this%memory_unchanged = .false.
      if (present(kink)) restart = restart .or. (kink .and. stepper%multistep)
      if (restart) then
         ! the derivative at the accepted point is kept, for the frame of a
         ! restart that fails
         this%f_accepted = stepper%f
         if (reason == end_none .and. .not. last) then
            call stepper%restart(sys, t, y, why)
         else
            ! the run ends here: no restart, but the last record holds one
            ! state's values, so its z'' is the new memory's (issue 14, 6)
            call evaluate_outside_step(sys, t, y, stepper%f, why)
         end if
         if (why%failed()) then
            stepper%f = this%f_accepted
            call record_failure(why, t, summary, err)
            reason = end_failure
         else
            call sample_after_jump(this, sys, stepper, t, y, summary)
         end if
         if (.not. why%failed() .and. estimated .and. .not. located) then
            ! the memory took a switch that happened inside the step at its
            ! end: the jump of z'' there, for the accuracy estimate
            do o = 1, size(sys%occupants)
               associate (vo => sys%occupants(o)%zdot_offset)
                  ! (a local of fixed size: no temporary allocated)
                  dzdd = stepper%f(vo + 1:vo + n_dof) - this%f_accepted(vo + 1:vo + n_dof)
                  call summary%occ(o)%accuracy%add_switch(t, h, dzdd)
               end associate
            end do
         end if
      end if

   end subroutine books_accept

   !> After the memory changed at an accepted point (t, y), z'' is the new
   !! memory's (stepper%f): the head's and chest's accelerations there are
   !! a second sample at the same time, so that the criteria's linear
   !! pieces keep the jump (acceleration_criteria: "a jump is two samples
   !! at one time") and the maxima see the far side. With one sample the
   !! jump was spread over the next step: HIC15 converged at first order
   !! (issue 15, section 3).
   subroutine sample_after_jump(this, sys, stepper, t, y, summary)
      class(step_books_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      class(stepper_t), intent(in) :: stepper
      real(wp), intent(in) :: t, y(:)
      type(run_summary_t), intent(inout) :: summary
      integer :: o
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o), os => summary%occ(o), st => this%st)
            call occupant_state(occ, t, y, st)
            call sample_criteria(occ, st, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), t, os)
            ! the loads' second sample, with the new memory's forces
            if (os%channels%neck_kept) then
               call occupant_point_forces(occ, st, y, this%forces, loads_segments)
               call sample_loads(occ, st, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), this%forces, t, os)
            end if
            if (os%channels%deflection_kept) &
               call os%channels%deflection%add(t, [inch_mm*occupant_chest_deflection(occ, st, y)])
            if (os%channels%belts_kept) call fmvss_belts_sample(os%channels, occ, st, y, t)
         end associate
      end do
   end subroutine sample_after_jump

   !> The head's and chest's accelerations at the accepted point t, z''
   !! = zdd, to the criteria, whose interpolant between accepted steps
   !! gives the peaks (acceleration_criteria, in g).
   pure subroutine sample_criteria(occ, st, zdd, t, os)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: zdd(n_dof), t
      type(occupant_summary_t), intent(inout) :: os
      real(wp) :: a_head(2), a_chest(2), v_head(2), v_chest(2)
      call head_chest_motion(occ%body, st%c, st%s, st%zdot, zdd, a_head, a_chest, v_head, v_chest)
      call os%head_criteria%add_motion(t, a_head/g_std, v_head/g_std)
      call os%chest_criteria%add_motion(t, a_chest/g_std, v_chest/g_std)
      if (os%channels%kept) then
         call os%channels%head%add_motion(t, a_head/g_std, v_head/g_std)
         call os%channels%chest%add_motion(t, a_chest/g_std, v_chest/g_std)
      end if
      call raise(os%head_max, g_std*os%head_criteria%peak, os%head_criteria%t_peak)
      call raise(os%chest_max, g_std*os%chest_criteria%peak, os%chest_criteria%t_peak)
   end subroutine sample_criteria

   !> The head acceleration of occupant o at the accepted point (t, y),
   !! a_head, against its value at the state moved by its estimated error
   !! (z and z', with the signs of the errors' sums; one evaluation of the
   !! right-hand side, counted as the stepper's, with the memory the step
   !! was taken with): the estimate of the head's peak so far
   !! (docs/accuracy.md). A state where the right-hand side cannot be
   !! evaluated leaves the estimate as it was.
   subroutine head_sensitivity(this, sys, stepper, o, t, y, a_head, acc)
      class(step_books_t), intent(inout) :: this
      type(crash_system_t), intent(inout) :: sys
      class(stepper_t), intent(inout) :: stepper
      integer, intent(in) :: o
      real(wp), intent(in) :: t, y(:), a_head
      type(accuracy_t), intent(inout) :: acc
      real(wp) :: ez(n_dof), ev(n_dof), a_moved, a_chest
      type(error_t) :: why
      associate (occ => sys%occupants(o), zo => sys%occupants(o)%z_offset, vo => sys%occupants(o)%zdot_offset)
         call acc%state_error(t, ez, ev)
         this%y_moved = y
         this%y_moved(zo + 1:zo + n_dof) = y(zo + 1:zo + n_dof) + ez
         this%y_moved(vo + 1:vo + n_dof) = y(vo + 1:vo + n_dof) + ev
         call evaluate_outside_step(sys, t, this%y_moved, this%f_moved, why)
         stepper%stats%evaluations = stepper%stats%evaluations + 1
         acc%head_evaluations = acc%head_evaluations + 1
         acc%head_error_at = a_head
         if (why%failed()) return
         call head_chest_acceleration(occ%body, cos(this%y_moved(zo + 1:zo + n_seg)), sin(this%y_moved(zo + 1:zo + n_seg)), &
                                      this%y_moved(vo + 1:vo + n_dof), this%f_moved(vo + 1:vo + n_dof), a_moved, a_chest)
         acc%head_error = abs(a_moved - a_head)
      end associate
   end subroutine head_sensitivity

   !> Table 5's criteria of occupant o at the step accepted at (t, y),
   !! where its z'' is zdd: the bone loads against its limits, an event the
   !! first time each is passed, the maxima kept.
   subroutine force_criteria(this, occ, o, t, zdd, summary, sinks)
      class(step_books_t), intent(inout) :: this
      type(occupant_t), intent(in) :: occ
      integer, intent(in) :: o
      real(wp), intent(in) :: t, zdd(n_dof)
      type(run_summary_t), intent(inout) :: summary
      type(sink_list_t), intent(inout) :: sinks
      type(bone_loads_t) :: bl
      integer :: i
      bl = bone_loads(occ%body, this%st%z, this%st%zdot, zdd, this%forces)
      do i = 1, n_joint
         call raise(summary%occ(o)%ft_max(i), bl%ft(i), t)
         call force_passed(this, o, t, 1, event_tension, i, bl%ft(i), occ%injury%f_tension(i), summary, sinks)
      end do
      do i = 1, n_injury
         if (fc_defined(i)) then
            call raise(summary%occ(o)%fc_max(i), bl%fc(i), t)
            call force_passed(this, o, t, 2, event_compression, i, bl%fc(i), occ%injury%f_compression(i), summary, sinks)
         end if
         if (fs_defined(i)) then
            call raise(summary%occ(o)%fs_max(i), bl%fs(i), t)
            call force_passed(this, o, t, 3, event_shear, i, bl%fs(i), occ%injury%f_shear(i), summary, sinks)
         end if
      end do
   end subroutine force_criteria

   !> The neck's and femur's loads at the accepted point t for the FMVSS 208
   !! table (fmvss_table), in SI: from the joint reactions (A-INJ) with the
   !! point forces at hand, the neck's axial force (FT_4 on the head's axis,
   !! + tension) and its flexion/extension moment (the moment the torso
   !! exerts on the head about the neck joint, counter-clockwise: flexion
   !! lowers the neck's relative angle, docs/anthropometry.md, so the torso
   !! holding a head that pitches forward is + flexion), and one femur's
   !! axial compression (the hip's reaction on the thigh's axis, Table 5's
   !! FC_7, halved: segment 7 is both thighs). docs/injury.md.
   pure subroutine sample_loads(occ, st, zdd, forces, t, os)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: zdd(n_dof), t
      type(point_force_list_t), intent(in) :: forces
      type(occupant_summary_t), intent(inout) :: os
      real(wp), parameter :: newton = pound_force_n             ! N per lbf
      real(wp), parameter :: newton_metre = newton*inch_m        ! N m per lbf in
      real(wp), parameter :: thighs = 2.0_wp                  ! femurs in segment 7
      integer, parameter :: hip = 1, neck = 4
      type(point_state_t) :: cg(n_seg)
      real(wp) :: r(2, n_joint), tension(n_joint), shear(n_joint), moment
      cg = segment_cg_states(occ%body, st%z, st%zdot, zdd)
      r = joint_reactions_at(occ%body, cg, forces)
      ! Table 5's FT_j on the distal bones' axes (the neck's: the head's)
      call bone_components_at(r, st%c, st%s, tension, shear)
      moment = joint_moment_at(occ%body, st%z, st%zdot, zdd, cg, forces, neck)
      call os%channels%neck%add(t, [newton*tension(neck), newton_metre*moment])
      call os%channels%femur%add(t, [-newton*tension(hip)/thighs])
   end subroutine sample_loads

   !> Criterion c (1 tension, 2 compression, 3 shear) of occupant o's joint
   !! or bone index at time t: an event the first time value passes a
   !! limit that is given (an injury: C.7's NEND = 3).
   subroutine force_passed(this, o, t, c, kind, index, value, limit, summary, sinks)
      class(step_books_t), intent(inout) :: this
      integer, intent(in) :: o, c, kind, index
      real(wp), intent(in) :: t, value, limit
      type(run_summary_t), intent(inout) :: summary
      type(sink_list_t), intent(inout) :: sinks
      type(event_t) :: e
      if (.not. limit > 0.0_wp .or. summary%occ(o)%force_reported(c, index)) return
      if (.not. value > limit) return
      summary%occ(o)%force_reported(c, index) = .true.
      e = force_injury_event(kind, t, index, value, limit)
      e%occupant = o
      this%injured(o) = .true.
      call summary_add_event(summary, e)
      call sinks%event(e)
   end subroutine force_passed

   !> The energy balance of C.6 at a print time t (each occupant's, from
   !! its frame) against its tolerance (*NUMERICS EBTOL) times its scale
   !! (D-17a): the larger of the largest body kinetic energy and the largest
   !! work the moving vehicle has supplied, both so far, so that energy
   !! that entered the body after a start at rest (a rear impact) counts
   !! as much as energy it started with. A run whose balance fails is
   !! flagged and, unless the deck says to continue, ends as a numerical
   !! failure (summary%end_reason = end_energy, err: why).
   subroutine books_check_energy(this, sys, balance, t, summary, err)
      class(step_books_t), intent(in) :: this
      type(crash_system_t), intent(in) :: sys
      type(energy_balance_t), intent(in) :: balance(:)
      real(wp), intent(in) :: t
      type(run_summary_t), intent(inout) :: summary
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: who, why
      integer :: o
      do o = 1, size(balance)
         associate (os => summary%occ(o), eb => balance(o))
            os%ke_max = max(os%ke_max, eb%ke_body)
            os%supplied_max = max(os%supplied_max, abs(eb%supplied))
            os%energy_scale = max(os%ke_max, os%supplied_max)
            os%e_error_final = eb%error
            if (abs(eb%error) > abs(os%energy_error_max%value)) os%energy_error_max = extreme_t(eb%error, t)
            if (os%energy_flagged) cycle
            if (abs(eb%error) > this%numerics%energy_tol*os%energy_scale .and. &
                abs(eb%error) > rounding*max(1.0_wp, os%energy_scale)) then
               os%energy_flagged = .true.
               os%t_flagged = t
               if (.not. this%numerics%energy_continue .and. summary%end_reason == end_none) then
                  ! "occupant k: " when there are several
                  who = ''
                  if (size(balance) > 1) who = trim(sys%occupants(o)%label)//': '
                  summary%end_reason = end_energy
                  why = who//'the energy balance error '//num(eb%error, 6)//' in*lb at t = '//num(t) &
                     //' s exceeds EBTOL = '//num(this%numerics%energy_tol)//' of its scale, the larger of the ' &
                     //'largest body kinetic energy ('//num(os%ke_max, 6)//' in*lb) and the largest work the ' &
                     //'vehicle supplied ('//num(os%supplied_max, 6)//' in*lb): the results are not trustworthy. ' &
                     //'A smaller DT (or NINT = 3 with tighter RTOL) should help; *NUMERICS EBFAIL = CONTINUE ' &
                     //'runs on regardless'
                  if (this%pulse_tabulated) &
                     why = why//'. Tabulated vehicle rates or positions that are not ' &
                           //'the integrals of its accelerations (C.3) make such an error whatever DT: ' &
                           //'see the deck''s warnings'
                  call error_set(err, exit_numerical, why)
               end if
            end if
         end associate
      end do
   end subroutine books_check_energy

   !> The run failed numerically after the accepted point t: why (the
   !! stepper's error: what failed, when and why) with that context in err,
   !! the summary's end reason end_failure.
   subroutine record_failure(why, t, summary, err)
      type(error_t), intent(in) :: why
      real(wp), intent(in) :: t
      type(run_summary_t), intent(inout) :: summary
      type(error_t), intent(inout) :: err
      call error_set(err, why%code, why%message)
      call error_prefix(err, 'integration stopped after t = '//num(t)//' s: ')
      summary%end_reason = end_failure
   end subroutine record_failure
end module step_bookkeeping
