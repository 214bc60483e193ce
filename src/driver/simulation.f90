!> The driver of one run (report figure 6): preliminary calculations (C.2)
!! and the scene, then the loop integrate (C.3) -> forces (C.4) -> solve
!! (C.5), with output (C.6) and the end tests (C.7) after each accepted
!! step. Everything with memory - the effects' memory, maxima, the rest
!! timer - changes here, on accepted steps only; when an effect's memory
!! makes the right-hand side jump, the stepper restarts.
module simulation
   use kinds, only: wp, i8, g_std
   use acceleration_criteria, only: criteria_new
   use error_handling, only: error_t, error_set, exit_numerical
   use strings, only: num
   use text_io, only: string_t
   use model, only: model_t, n_dof, n_seg, n_joint, n_injury, joint_partner, nint_adams, nint_rk4, nint_dopri, nend_rest, astart_rk4
   use equations_of_motion, only: crash_system_t, system_build, system_initial_y, system_body_state, &
      rhs_status_text, rhs_diverged, rhs_not_finite
   use occupant, only: occupant_t, occupant_state, occupant_point_forces, occupant_vehicle
   use ode_system, only: stepper_t, step_ok, step_rhs_failed, step_status_text, step_stats_t
   use runge_kutta4, only: rk4_stepper_t
   use adams_moulton, only: am_stepper_t, am_start_euler, am_start_rk4
   use dormand_prince, only: dopri_stepper_t
   use effect_base, only: body_state_t
   use effect_events, only: accept_result_t, event_t
   use point_forces, only: point_force_list_t, point_force_reserve
   use force_injuries, only: bone_loads_t, bone_loads, fc_defined, fs_defined, force_injury_event, event_tension, &
      event_compression, event_shear
   use joint_coupling, only: relative_angle
   use output_calc, only: head_chest_acceleration
   use output_registry, only: output_registry_t, output_frame_t
   use output_producers, only: registry_build, frame_fill, frame_energy, energy_balance_t
   use output_sink, only: output_sink_t
   use run_summary, only: run_summary_t, occupant_summary_t, extreme_t, raise, summary_add_event
   use end_tests, only: end_state_t, end_none, end_time, end_failure, end_energy, end_injury, end_contact, end_rest, &
      end_test_update, body_at_rest
   implicit none
   private

   public :: run_simulation, run_system, initial_warnings

   !> A balance error below this fraction of the largest kinetic energy is rounding.
   real(wp), parameter :: rounding = 1.0e-9_wp

contains

   !> Run the model. A numerical failure ends the run with everything
   !! computed so far kept, summary%end_reason = end_failure (or end_energy)
   !! and err set (exit_numerical). sink, when present, receives the frames
   !! and events as they are made; an error it reports stops the run.
   subroutine run_simulation(m, summary, err, sink)
      type(model_t), intent(in) :: m
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      class(output_sink_t), intent(inout), optional :: sink
      type(crash_system_t) :: sys
      call system_build(m, sys)
      if (present(sink)) then
         call run_system(m, sys, summary, err, sink)
      else
         call run_system(m, sys, summary, err)
      end if
   end subroutine run_simulation

   !> What the model's effects say of its initial state (effect_t%
   !! initial_notes: a contact pair starting deep in its surface): warnings,
   !! before the run.
   function initial_warnings(m) result(notes)
      type(model_t), intent(in) :: m
      type(string_t), allocatable :: notes(:)
      type(crash_system_t) :: sys
      type(body_state_t) :: st
      real(wp), allocatable :: y(:)
      integer :: o, k, xo, ao
      allocate (notes(0))
      call system_build(m, sys)
      call system_initial_y(sys, y)
      do o = 1, size(sys%occupants)
         st = system_body_state(sys, o, 0.0_wp, y)
         associate (occ => sys%occupants(o))
            do k = 1, size(occ%effects)
               xo = occ%extra_offset(k)
               ao = occ%aux_offset(k)
               associate (e => occ%effects(k)%e)
                  notes = [notes, e%initial_notes(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux))]
               end associate
            end do
         end associate
      end do
   end function initial_warnings

   !> Run an assembled system (its occupants may come from several models;
   !! m gives the time controls, the integrator, the numerics and the
   !! vehicle; each occupant carries its own NEND, rest limits and Table 5
   !! limits).
   subroutine run_system(m, sys, summary, err, sink)
      type(model_t), intent(in) :: m
      type(crash_system_t), intent(inout) :: sys
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      class(output_sink_t), intent(inout), optional :: sink
      type(error_t) :: out_err       ! what the sinks report: ends the run too
      class(stepper_t), allocatable :: stepper
      type(end_state_t), allocatable :: end_state(:)   !< each occupant's rest timer (C.7)
      logical, allocatable :: occ_injured(:)            !< each occupant injured so far (C.7, NEND = 3)
      type(output_registry_t) :: reg
      type(output_frame_t) :: frame
      real(wp), allocatable :: y(:), total0(:), f_accepted(:), y_prev(:), y_end(:), y_hi(:)
      real(wp) :: t, t_limit, t_frame, t_prev, t_resume, t_prev_end
      logical :: fixed_step, print_now, at_end, locating, located
      type(step_stats_t) :: stats_prev
      integer :: status, reason, o, i, n_occ
      integer(i8) :: n, n_steps, print_every, next_print
      type(body_state_t) :: st
      !> the point forces for Table 5's criteria, reused from step to step
      type(point_force_list_t) :: forces

      n_occ = size(sys%occupants)
      allocate (summary%occ(n_occ), total0(n_occ), end_state(n_occ), occ_injured(n_occ))
      occ_injured = .false.
      call system_initial_y(sys, y)
      call choose_stepper(m, stepper)
      fixed_step = m%options%nint == nint_adams .or. m%options%nint == nint_rk4

      t = 0.0_wp
      ! C.2's initial outputs: the energy totals the balance is measured from,
      ! the initial joint angles the ranges start from
      do o = 1, n_occ
         st = system_body_state(sys, o, t, y)
         associate (eb => frame_energy(sys%occupants(o), st, y, 0.0_wp))
            total0(o) = eb%total
         end associate
         summary%occ(o)%e_total0 = total0(o)
         summary%occ(o)%head_criteria = criteria_new()
         summary%occ(o)%chest_criteria = criteria_new(with_hic=.false.)   ! GSI and the 3 ms clip
         ! Table 5's force criteria only when the occupant's deck gives a limit
         ! (they cost the point forces and the joint reactions at every
         ! accepted step)
         associate (lim => sys%occupants(o)%injury)
            summary%occ(o)%force_checked = any(lim%f_tension > 0.0_wp) .or. any(lim%f_compression > 0.0_wp) &
                                           .or. any(lim%f_shear > 0.0_wp)
         end associate
         do i = 1, n_joint
            summary%occ(o)%joint_min(i) = extreme_t(relative_angle(st%z, i), 0.0_wp)
            summary%occ(o)%joint_max(i) = summary%occ(o)%joint_min(i)
         end do
      end do
      call registry_build(sys, reg)
      allocate (f_accepted(size(y)))
      ! Nothing allocated in the step loop (docs/architecture.md): room for
      ! the point forces, one per segment of each effect from outside (the
      ! most any reports: gravity's)
      if (any([(summary%occ(o)%force_checked, o=1, n_occ)])) &
         call point_force_reserve(forces, n_seg*maxval([(count([(sys%occupants(o)%effects(i)%e%external, &
                                                                  i=1, size(sys%occupants(o)%effects))]), o=1, n_occ)]))
      call stepper%init(sys, t, y, status)
      if (status /= step_ok) then
         ! no derivative at t = 0: the outputs say so and hold no time history
         call fail(status)
         allocate (frame%v(reg%n_values))
         frame%v = 0.0_wp
         frame%valid = .false.
         if (present(sink)) call sink%begin(sys, reg, frame, out_err)
         call finish()
         call merge_output_error()
         return
      end if
      call make_frame(t)
      if (present(sink)) call sink%begin(sys, reg, frame, out_err)
      if (present(sink) .and. .not. out_err%failed()) call sink%record(frame, out_err)
      reason = end_none
      n_steps = nint(m%time%t_max/m%time%dt, i8)
      call on_accepted(t, .false., reason)

      print_every = max(1_i8, nint(m%time%dt_print/m%time%dt, i8))
      next_print = 1
      n = 0
      t_frame = 0.0_wp
      ! D-C24b: a jump an effect can locate (the windshield's break) is stepped
      ! to, under RK4 and Dormand-Prince (Adams-Moulton keeps its fixed step)
      locating = m%options%nint /= nint_adams .and. any_locating()
      if (locating) allocate (y_prev(size(y)), y_end(size(y)), y_hi(size(y)))
      t_resume = -1.0_wp
      located = .false.
      do while (reason == end_none .and. .not. out_err%failed())
         if (fixed_step) then
            t_limit = huge(1.0_wp)
            if (t_resume > t) t_limit = t_resume    ! back onto the grid after a located jump
            t_resume = -1.0_wp
         else
            t_limit = min(real(next_print, wp)*m%time%dt_print, m%time%t_max)
         end if
         if (locating) then
            y_prev = y
            t_prev = t
            stats_prev = stepper%stats
         end if
         call stepper%advance(sys, t, y, t_limit, status)
         located = .false.
         if (status == step_ok .and. locating) call locate_jump(located, status)
         if (status /= step_ok) then
            ! keep the last accepted state in the output, then stop
            if (t > t_frame) call output_frame(t)
            call fail(status)
            exit
         end if
         if (locating .and. located) then
            ! an accepted state inside the step, not a step of the grid nor a
            ! print time (unless the run ends there); the step goes on from it
            call on_accepted(t, .false., reason)
            if (fixed_step) t_resume = t_prev_end
            if (reason /= end_none) call output_frame(t)
            if (summary%end_reason == end_energy) reason = end_energy
            cycle
         end if
         n = n + 1
         ! whether TMAX is reached here is known before the step's memory
         ! updates, so that no restart is made for a step that ends the run
         if (fixed_step) then
            at_end = n >= n_steps
         else
            at_end = t >= m%time%t_max
         end if
         call on_accepted(t, at_end, reason)
         if (fixed_step) then
            print_now = mod(n, print_every) == 0
         else
            print_now = t >= t_limit
            if (print_now) next_print = next_print + 1
         end if
         if (at_end .and. reason == end_none) reason = end_time
         if (print_now .or. reason /= end_none) call output_frame(t)
         if (summary%end_reason == end_energy) reason = end_energy
      end do
      if (reason /= end_none .and. summary%end_reason == end_none) summary%end_reason = reason
      call finish()
      call merge_output_error()

   contains

      !> Whether an effect of the system can locate a jump (effect_t%locates).
      logical function any_locating()
         integer :: oo, kk
         any_locating = .false.
         do oo = 1, n_occ
            do kk = 1, size(sys%occupants(oo)%effects)
               any_locating = any_locating .or. sys%occupants(oo)%effects(kk)%e%locates
            end do
         end do
      end function any_locating

      !> D-C24b: after a step from (t_prev, y_prev) to (t, y), ask the effects
      !! that can (effect_t%locate) whether their right-hand side should have
      !! jumped inside it; while one says so, take the step again from t_prev
      !! to the fraction it asks (a secant from the accepted state), keeping
      !! the jump bracketed between the latest state found short of it (an
      !! answer of 1 or more; at first t_prev) and the earliest found past it
      !! (at first t). A fraction outside the bracket, or the try after a
      !! state found short, takes the bracket's middle instead, so the bracket
      !! at least halves every second try: a tiny FSW, whose secant lands
      !! before the head even touches, was stepped to 5e-14 s at a time, for
      !! ever (issue 14). It ends at a state where none asks (the jump there,
      !! within its tolerance) or, after max_locate tries, at the earliest
      !! state past the jump (the jump there, late by less than the bracket):
      !! at most max_locate steps taken again, whatever the threshold. done:
      !! (t, y) is now inside the step, t_prev_end its end. A step taken again
      !! that fails gives the step as first taken back (the jump then at its
      !! end, as without location), and only if that fails too does the run
      !! fail (stat).
      subroutine locate_jump(done, stat)
         logical, intent(out) :: done
         integer, intent(out) :: stat
         integer, parameter :: max_locate = 8
         real(wp) :: theta, t_to, t_lo, t_hi
         logical :: short
         integer :: k
         done = .false.
         stat = step_ok
         t_prev_end = t
         y_end = y
         call fraction_asked(theta, short)
         if (.not. theta < 1.0_wp) return
         t_lo = t_prev
         t_hi = t
         y_hi = y
         do k = 1, max_locate
            ! the step again: to the secant's fraction inside the bracket, else its middle
            t_to = t_prev + theta*(t - t_prev)
            if (.not. (t_to > t_lo .and. t_to < t_hi)) t_to = 0.5_wp*(t_lo + t_hi)
            if (.not. (t_to > t_lo .and. t_to < t_hi)) exit     ! (the bracket below the time's resolution)
            y = y_prev
            t = t_prev
            ! the step taken is not kept: a rejected step in the statistics (its
            ! size not among the accepted ones, its start again no restart after
            ! a jump)
            stepper%stats%steps = stepper%stats%steps - 1
            stepper%stats%rejected = stepper%stats%rejected + 1
            stepper%stats%h_min = stats_prev%h_min
            stepper%stats%h_max = stats_prev%h_max
            call stepper%restart(sys, t, y, stat)
            stepper%stats%restarts = stepper%stats%restarts - 1
            if (stat == step_ok) call stepper%advance(sys, t, y, t_to, stat)
            if (stat /= step_ok) then
               ! back to the step as first taken (memory untouched since: the
               ! same derivative), kept with the jump at its end
               stepper%stats%steps = stepper%stats%steps + 1
               call keep_try(t_prev_end, y_end, stat)
               done = .false.
               return
            end if
            done = .true.
            call fraction_asked(theta, short)
            if (theta < 1.0_wp) then          ! past the jump again: the bracket's end
               t_hi = t
               y_hi = y
            else if (short) then              ! short of it: the bracket's start, then its middle
               t_lo = t
               theta = 1.0_wp
            else                              ! here, within the jump's tolerance
               return
            end if
         end do
         ! the tries spent: the earliest state past the jump, where it happens
         if (.not. t_hi < t_prev_end) then
            call keep_try(t_prev_end, y_end, stat)      ! (none before the step's end)
            done = .false.
         else if (t < t_hi) then
            call keep_try(t_hi, y_hi, stat)
         end if
      end subroutine locate_jump

      !> Keep the step from t_prev to t_keep taken earlier (y_keep) rather
      !! than the last one taken: its size among the accepted ones, the
      !! stepper restarted there (not counted as a restart after a jump).
      subroutine keep_try(t_keep, y_keep, stat)
         real(wp), intent(in) :: t_keep, y_keep(:)
         integer, intent(out) :: stat
         y = y_keep
         t = t_keep
         stepper%stats%h_min = min(stats_prev%h_min, t_keep - t_prev)
         stepper%stats%h_max = max(stats_prev%h_max, t_keep - t_prev)
         call stepper%restart(sys, t, y, stat)
         stepper%stats%restarts = stepper%stats%restarts - 1
      end subroutine keep_try

      !> The smallest fraction of the last step at which an effect asks for
      !! its jump (effect_t%locate), 1 when none asks; short: an effect
      !! answered that the state falls short of its jump (1 or more). The
      !! body state is made only for an occupant with an effect that may ask.
      subroutine fraction_asked(theta, short)
         real(wp), intent(out) :: theta
         logical, intent(out) :: short
         real(wp) :: theta_k
         integer :: oo, kk, xo2, ao2
         type(body_state_t) :: st2
         logical :: made
         theta = 1.0_wp
         short = .false.
         do oo = 1, n_occ
            associate (occ => sys%occupants(oo))
               made = .false.
               do kk = 1, size(occ%effects)
                  associate (e => occ%effects(kk)%e)
                     if (.not. e%locates) cycle
                     if (.not. made) st2 = system_body_state(sys, oo, t, y)
                     made = .true.
                     xo2 = occ%extra_offset(kk)
                     ao2 = occ%aux_offset(kk)
                     theta_k = e%locate(st2, y(xo2 + 1:xo2 + 2*e%n_extra), y(ao2 + 1:ao2 + e%n_aux))
                     if (theta_k > 0.0_wp) theta = min(theta, theta_k)
                     short = short .or. .not. theta_k < 1.0_wp
                  end associate
               end do
            end associate
         end do
      end subroutine fraction_asked

      !> An output error outweighs a numerical failure (docs/usage.md): the
      !! outputs that would show the run up to the failure are incomplete.
      subroutine merge_output_error()
         if (.not. out_err%failed()) return
         if (err%failed()) then
            call error_set(err, out_err%code, out_err%message//new_line('a')//'(the run had failed too: ' &
                           //err%message//')')
         else
            call error_set(err, out_err%code, out_err%message)
         end if
      end subroutine merge_output_error

      subroutine finish()
         summary%t_end = t
         summary%stats = stepper%stats
         summary%counts = sys%counts
         allocate (summary%effect_names(size(sys%counts, 1), n_occ), summary%effect_titles(size(sys%counts, 1), n_occ))
         summary%effect_names = ' '
         summary%effect_titles = ' '
         do o = 1, n_occ
            allocate (summary%occ(o)%peaks(0))
            do i = 1, size(sys%occupants(o)%effects)
               summary%effect_names(i, o) = sys%occupants(o)%effects(i)%e%name
               summary%effect_titles(i, o) = sys%occupants(o)%effects(i)%e%title
               summary%occ(o)%peaks = [summary%occ(o)%peaks, sys%occupants(o)%effects(i)%e%peaks()]
            end do
         end do
         summary%evaluations = sys%evaluations
         if (present(sink)) call sink%finish(summary, out_err)
      end subroutine finish

      !> The bone loads at the accepted point against Table 5's limits: an
      !! event the first time each criterion is passed; the maxima kept.
      subroutine check_force_injuries(occ, os, occ_i, t_now, injured)
         type(occupant_t), intent(in) :: occ
         type(occupant_summary_t), intent(inout) :: os
         integer, intent(in) :: occ_i
         real(wp), intent(in) :: t_now
         logical, intent(inout) :: injured
         type(bone_loads_t) :: bl
         integer :: i
         call occupant_point_forces(occ, st, y, forces)
         bl = bone_loads(occ%body, st%z, st%zdot, stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), forces)
         do i = 1, n_joint
            call raise(os%ft_max(i), bl%ft(i), t_now)
            call passed(os, occ_i, t_now, 1, event_tension, i, bl%ft(i), occ%injury%f_tension(i), injured)
         end do
         do i = 1, n_injury
            if (fc_defined(i)) then
               call raise(os%fc_max(i), bl%fc(i), t_now)
               call passed(os, occ_i, t_now, 2, event_compression, i, bl%fc(i), occ%injury%f_compression(i), injured)
            end if
            if (fs_defined(i)) then
               call raise(os%fs_max(i), bl%fs(i), t_now)
               call passed(os, occ_i, t_now, 3, event_shear, i, bl%fs(i), occ%injury%f_shear(i), injured)
            end if
         end do
      end subroutine check_force_injuries

      !> Criterion c (1 tension, 2 compression, 3 shear) of joint or bone
      !! index: an event the first time value passes a limit that is given.
      subroutine passed(os, occ_i, t_now, c, kind, index, value, limit, injured)
         type(occupant_summary_t), intent(inout) :: os
         integer, intent(in) :: occ_i, c, kind, index
         real(wp), intent(in) :: t_now, value, limit
         logical, intent(inout) :: injured
         type(event_t) :: e
         if (.not. limit > 0.0_wp .or. os%force_reported(c, index)) return
         if (.not. value > limit) return
         os%force_reported(c, index) = .true.
         e = force_injury_event(kind, t_now, index, value, limit)
         e%occupant = occ_i
         injured = .true.
         call summary_add_event(summary, e)
         if (present(sink) .and. .not. out_err%failed()) call sink%event(e, out_err)
      end subroutine passed

      !> Memory updates after an accepted step (docs/architecture.md, rule 1):
      !! the effects' accept, maxima, the end tests; a restart of the
      !! stepper when an effect's memory made the right-hand side jump.
      !! Each occupant's end test is its own (its NEND, rest limits, Table 5
      !! limits): the run ends at the first injury or undesired contact of an
      !! occupant whose NEND asks for it, or when every occupant whose NEND
      !! asks for rest has rested for its THOLD.
      subroutine on_accepted(t_now, last, reason_out)
         real(wp), intent(in) :: t_now
         logical, intent(in) :: last      !< the run ends at this step: no restart
         integer, intent(out) :: reason_out
         type(accept_result_t) :: ar
         real(wp) :: a_head, a_chest, delta
         integer :: k, q, j, occ_i, xo, ao, restart_status, rhs_code, reason_o
         logical :: restart, undesired, at_rest, any_rest, all_rested

         restart = .false.
         any_rest = .false.
         all_rested = .true.
         reason_out = end_none
         do occ_i = 1, n_occ
            undesired = .false.
            associate (occ => sys%occupants(occ_i), os => summary%occ(occ_i))
               ! the vehicle's state only when something reads it
               call occupant_state(occ, t_now, y, st)
               if (sys%needs_vehicle .or. occ%nend == nend_rest) call occupant_vehicle(occ, sys%vm, t_now, st)
               ! Table 5's force criteria, with the memory the step was taken with
               if (os%force_checked) call check_force_injuries(occ, os, occ_i, t_now, occ_injured(occ_i))
               do q = 1, size(occ%remembering)
                  k = occ%remembering(q)
                  ar%restart = .false.
                  ar%n_events = 0
                  xo = occ%extra_offset(k)
                  ao = occ%aux_offset(k)
                  associate (e => occ%effects(k)%e)
                     call e%accept(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), ar)
                  end associate
                  restart = restart .or. ar%restart
                  do j = 1, ar%n_events
                     ar%events(j)%occupant = occ_i
                     occ_injured(occ_i) = occ_injured(occ_i) .or. ar%events(j)%injury
                     undesired = undesired .or. ar%events(j)%undesired
                     call summary_add_event(summary, ar%events(j))
                     if (present(sink) .and. .not. out_err%failed()) call sink%event(ar%events(j), out_err)
                  end do
               end do
               call head_chest_acceleration(occ%body, st%c, st%s, st%zdot, &
                                            stepper%f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), a_head, a_chest)
               call raise(os%head_max, a_head, t_now)
               call raise(os%chest_max, a_chest, t_now)
               call os%head_criteria%add(t_now, a_head/g_std)
               call os%chest_criteria%add(t_now, a_chest/g_std)
               do k = 1, n_joint
                  delta = st%z(k) - st%z(joint_partner(k))
                  if (delta < os%joint_min(k)%value) os%joint_min(k) = extreme_t(delta, t_now)
                  if (delta > os%joint_max(k)%value) os%joint_max(k) = extreme_t(delta, t_now)
               end do
               ! C.7 with the occupant's own NEND and limits
               at_rest = .false.
               if (occ%nend == nend_rest) at_rest = body_at_rest(occ%body, occ%end_tests, st%z, st%zdot, st%vehicle)
               call end_test_update(occ%nend, occ%end_tests, end_state(occ_i), t_now, occ_injured(occ_i), at_rest, &
                                    reason_o, undesired)
               if (occ%nend == nend_rest) then
                  any_rest = .true.
                  all_rested = all_rested .and. reason_o == end_rest
               else if (reason_o == end_injury .or. reason_o == end_contact) then
                  if (reason_out == end_none) reason_out = reason_o
               end if
            end associate
         end do
         if (reason_out == end_none .and. any_rest .and. all_rested) reason_out = end_rest
         if (restart) then
            ! the derivative at the accepted point is kept, for the frame of a
            ! restart that fails
            f_accepted = stepper%f
            if (reason_out == end_none .and. .not. last) then
               call stepper%restart(sys, t_now, y, restart_status)
            else
               ! the run ends here: no restart, but the last record holds one
               ! state's values, so its z'' is the new memory's (issue 14, 6)
               call sys%rhs(t_now, y, stepper%f, rhs_code)
               restart_status = step_ok
               if (rhs_code /= 0) then
                  stepper%rhs_status = rhs_code
                  restart_status = step_rhs_failed
               end if
            end if
            if (restart_status /= step_ok) then
               stepper%f = f_accepted
               call fail(restart_status)
               reason_out = end_failure
            end if
         end if
      end subroutine on_accepted

      !> The frame at the current accepted point, with the energy balances.
      subroutine make_frame(t_now)
         real(wp), intent(in) :: t_now
         type(energy_balance_t) :: balance(n_occ)
         call frame_fill(sys, m%vehicle, reg, t_now, y, stepper%f, total0, frame, balance)
         do o = 1, n_occ
            call check_energy(summary%occ(o), balance(o), t_now)
         end do
         summary%n_frames = summary%n_frames + 1
         t_frame = t_now
      end subroutine make_frame

      !> A print record (C.6), to the sink.
      subroutine output_frame(t_now)
         real(wp), intent(in) :: t_now
         call make_frame(t_now)
         if (present(sink) .and. .not. out_err%failed()) call sink%record(frame, out_err)
      end subroutine output_frame

      !> The energy balance of C.6 against its tolerance (*NUMERICS EBTOL):
      !! a run whose balance fails is flagged and, unless the deck says to
      !! continue, ends as a numerical failure.
      subroutine check_energy(os, eb, t_now)
         type(occupant_summary_t), intent(inout) :: os
         type(energy_balance_t), intent(in) :: eb
         real(wp), intent(in) :: t_now
         os%ke_max = max(os%ke_max, eb%ke_body)
         os%e_error_final = eb%error
         if (abs(eb%error) > abs(os%energy_error_max%value)) os%energy_error_max = extreme_t(eb%error, t_now)
         if (os%energy_flagged) return
         if (abs(eb%error) > m%numerics%energy_tol*os%ke_max .and. abs(eb%error) > rounding*max(1.0_wp, os%ke_max)) then
            os%energy_flagged = .true.
            os%t_flagged = t_now
            if (.not. m%numerics%energy_continue .and. summary%end_reason == end_none) then
               summary%end_reason = end_energy
               summary%failure = occupant_prefix()//'the energy balance error '//num(eb%error, 6)//' in*lb at t = '//num(t_now) &
                  //' s exceeds EBTOL = '//num(m%numerics%energy_tol)//' of the largest body kinetic energy (' &
                  //num(os%ke_max, 6)//' in*lb): the results are not trustworthy. A smaller DT (or NINT = 3 ' &
                  //'with tighter RTOL) should help; *NUMERICS EBFAIL = CONTINUE runs on regardless'
               if (allocated(m%vehicle%pulse_vel%t) .or. allocated(m%vehicle%pulse_pos%t)) &
                  summary%failure = summary%failure//'. Tabulated vehicle rates or positions that are not ' &
                                    //'the integrals of its accelerations (C.3) make such an error whatever DT: ' &
                                    //'see the deck''s warnings'
               call error_set(err, exit_numerical, summary%failure)
            end if
         end if
      end subroutine check_energy

      !> "occupant k: " when there are several.
      function occupant_prefix() result(s)
         character(len=:), allocatable :: s
         s = ''
         if (n_occ > 1) s = trim(sys%occupants(o)%label)//': '
      end function occupant_prefix

      subroutine fail(code)
         integer, intent(in) :: code
         character(len=:), allocatable :: why
         why = step_status_text(code)
         if (code == step_rhs_failed) then
            why = why//' at t = '//num(sys%last_t)//' s: '//rhs_status_text(stepper%rhs_status)
            if ((stepper%rhs_status == rhs_diverged .or. stepper%rhs_status == rhs_not_finite) &
                .and. allocated(sys%failure_detail)) &
               why = why//' ('//sys%failure_detail//')'
         end if
         summary%failure = 'integration stopped after t = '//num(t)//' s: '//why
         summary%end_reason = end_failure
         call error_set(err, exit_numerical, summary%failure)
      end subroutine fail
   end subroutine run_system

   !> The integrator of option NINT (C.3) with its settings.
   subroutine choose_stepper(m, stepper)
      type(model_t), intent(in) :: m
      class(stepper_t), allocatable, intent(out) :: stepper
      select case (m%options%nint)
      case (nint_adams)
         allocate (am_stepper_t :: stepper)
      case (nint_dopri)
         allocate (dopri_stepper_t :: stepper)
      case default
         allocate (rk4_stepper_t :: stepper)
      end select
      select type (s => stepper)
      type is (am_stepper_t)
         s%h = m%time%dt
         s%tol = m%time%corrector_tol
         s%max_iter = m%time%corrector_max_iter
         s%start = merge(am_start_rk4, am_start_euler, m%numerics%am_start == astart_rk4)
      type is (rk4_stepper_t)
         s%h = m%time%dt
      type is (dopri_stepper_t)
         s%h = m%time%dt
         s%rtol = m%time%rtol
         s%atol = m%time%atol
      end select
   end subroutine choose_stepper
end module simulation
