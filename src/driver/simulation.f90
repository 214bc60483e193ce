!> The driver of one run (report figure 6): preliminary calculations (C.2),
!! scene assembly, then the loop integrate (C.3) -> forces (C.4) -> solve
!! (C.5), with output (C.6) and the end tests (C.7) after each accepted
!! step. Everything with memory - maxima, dislocated joints, the rest timer
!! - is updated here, on accepted steps only; the integrators' trial
!! evaluations change nothing.
module simulation
   use kinds, only: wp, i8
   use error_handling, only: error_t, error_set, exit_numerical
   use strings, only: num
   use model, only: model_t, n_dof, n_seg, n_joint, joint_partner, nint_adams, nint_rk4, nint_dopri, &
      nend_rest
   use preliminary, only: body_constants_t, body_constants, initial_state
   use generalized_forces, only: scene_t, force_counts_t, scene_assemble
   use equations_of_motion, only: body_system_t, body_system_init, state_size, rhs_status_text
   use ode_system, only: stepper_t, step_stats_t, step_ok, step_rhs_failed, step_status_text
   use runge_kutta4, only: rk4_stepper_t
   use adams_moulton, only: am_stepper_t
   use dormand_prince, only: dopri_stepper_t
   use vehicle_motion, only: vehicle_motion_t, vehicle_motion_init, vehicle_state_at, vehicle_state_t
   use body_kinematics, only: segment_cg_state, point_state_t
   use output_calc, only: output_record_t, output_compute, head_chest_acceleration
   use output_sink, only: output_sink_t
   use joint_injury, only: injury_event_t, dislocation_check
   use end_tests, only: end_state_t, end_none, end_time, end_failure, end_test_update, body_at_rest
   implicit none
   private

   public :: run_result_t, extreme_t, run_simulation

   !> A running extreme and when it happened.
   type :: extreme_t
      real(wp) :: value = 0.0_wp
      real(wp) :: t = 0.0_wp
   end type extreme_t

   !> What a run produced.
   type :: run_result_t
      integer :: end_reason = end_none
      character(len=:), allocatable :: failure
      real(wp) :: t_end = 0.0_wp
      type(body_constants_t) :: bc
      type(scene_t) :: scene
      type(output_record_t), allocatable :: records(:)
      integer :: n_records = 0
      type(injury_event_t), allocatable :: events(:)
      integer :: n_events = 0
      type(step_stats_t) :: stats
      type(force_counts_t) :: counts
      integer(i8) :: evaluations = 0
      type(extreme_t) :: head_max, chest_max, energy_error_max
      type(extreme_t) :: joint_min(n_joint), joint_max(n_joint)
      real(wp) :: e_total0 = 0.0_wp
   end type run_result_t

contains

   !> Run the model. A numerical failure ends the run with everything
   !! computed so far kept in res, res%end_reason = end_failure and err set
   !! (exit_numerical). sink, when present, receives records and events as
   !! they are made; an error it reports stops the run.
   subroutine run_simulation(m, res, err, sink)
      type(model_t), intent(in) :: m
      type(run_result_t), intent(out) :: res
      type(error_t), intent(inout) :: err
      class(output_sink_t), intent(inout), optional :: sink
      type(body_system_t) :: sys
      class(stepper_t), allocatable :: stepper
      type(vehicle_motion_t) :: vm
      type(end_state_t) :: end_state
      real(wp), allocatable :: y(:)
      real(wp) :: z0(n_dof), zdot0(n_dof), y_cg0(n_seg), t, t_limit
      logical :: dislocated(n_joint), fixed_step, print_now
      integer :: status, reason, i
      integer(i8) :: n, n_steps, print_every, next_print
      type(point_state_t) :: p

      ! C.2 preliminary calculations and the scene, once
      res%bc = body_constants(m)
      call initial_state(m, z0, zdot0)
      call scene_assemble(m, z0, res%scene)
      call body_system_init(sys, m, res%bc, res%scene)
      call vehicle_motion_init(m, vm)
      do i = 1, n_seg
         p = segment_cg_state(m, z0, zdot0, [(0.0_wp, n=1, n_dof)], i)
         y_cg0(i) = p%y
      end do
      allocate (y(state_size(res%scene)))
      y = 0.0_wp
      y(1:n_dof) = z0
      y(n_dof + 1:2*n_dof) = zdot0
      allocate (res%records(64), res%events(8))
      dislocated = .false.
      do i = 1, n_joint
         res%joint_min(i) = extreme_t(z0(i) - z0(joint_partner(i)), 0.0_wp)
         res%joint_max(i) = res%joint_min(i)
      end do

      select case (m%nint)
      case (nint_adams)
         allocate (am_stepper_t :: stepper)
      case (nint_dopri)
         allocate (dopri_stepper_t :: stepper)
      case default
         allocate (rk4_stepper_t :: stepper)
      end select
      select type (s => stepper)
      type is (am_stepper_t)
         s%h = m%dt
         s%tol = m%corrector_tol
         s%max_iter = m%corrector_max_iter
      type is (rk4_stepper_t)
         s%h = m%dt
      type is (dopri_stepper_t)
         s%h = m%dt
         s%rtol = m%rtol
         s%atol = m%atol
      end select
      fixed_step = m%nint == nint_adams .or. m%nint == nint_rk4

      t = 0.0_wp
      call stepper%init(sys, t, y, status)
      if (status /= step_ok) then
         call fail(stepper, t, status)
         call finish()
         return
      end if
      ! initial output: C.2's initial energies and accelerations
      res%e_total0 = 0.0_wp
      call make_record(t, .true.)
      if (err%failed()) return
      call on_accepted(t, reason)

      n_steps = nint(m%t_max/m%dt, i8)
      print_every = max(1_i8, nint(m%dt_print/m%dt, i8))
      next_print = 1
      n = 0
      reason = end_none
      do while (reason == end_none)
         if (fixed_step) then
            t_limit = huge(1.0_wp)
         else
            t_limit = min(real(next_print, wp)*m%dt_print, m%t_max)
         end if
         call stepper%advance(sys, t, y, t_limit, status)
         if (status /= step_ok) then
            ! keep the last accepted state in the output, then stop
            if (res%records(res%n_records)%t < t) call make_record(t, .false.)
            call fail(stepper, t, status)
            exit
         end if
         n = n + 1
         call on_accepted(t, reason)
         if (fixed_step) then
            print_now = mod(n, print_every) == 0
            if (n >= n_steps .and. reason == end_none) reason = end_time
         else
            print_now = t >= t_limit
            if (print_now) next_print = next_print + 1
            if (t >= m%t_max .and. reason == end_none) reason = end_time
         end if
         if (print_now .or. reason /= end_none) call make_record(t, .false.)
         if (err%failed()) exit
      end do
      if (reason /= end_none) res%end_reason = reason
      call finish()

   contains

      subroutine finish()
         res%t_end = t
         res%stats = stepper%stats
         res%counts = sys%counts
         res%evaluations = sys%evaluations
      end subroutine finish

      !> Memory updates after an accepted step (design.md, rule 1).
      subroutine on_accepted(t_now, reason_out)
         real(wp), intent(in) :: t_now
         integer, intent(out) :: reason_out
         real(wp) :: a_head, a_chest, delta
         type(injury_event_t) :: new_events(n_joint)
         integer :: n_new, k
         logical :: at_rest
         type(vehicle_state_t) :: vs

         associate (z => y(1:n_dof), zdot => y(n_dof + 1:2*n_dof), zdd => stepper%f(n_dof + 1:2*n_dof))
            call head_chest_acceleration(m, z, zdot, zdd, a_head, a_chest)
            call raise(res%head_max, a_head, t_now)
            call raise(res%chest_max, a_chest, t_now)
            do k = 1, n_joint
               delta = z(k) - z(joint_partner(k))
               if (delta < res%joint_min(k)%value) res%joint_min(k) = extreme_t(delta, t_now)
               if (delta > res%joint_max(k)%value) res%joint_max(k) = extreme_t(delta, t_now)
            end do
            call dislocation_check(m, t_now, z, dislocated, new_events, n_new)
            do k = 1, n_new
               call add_event(new_events(k))
            end do
            at_rest = .false.
            if (m%nend == nend_rest) then
               vs = vehicle_state_at(vm, t_now)
               at_rest = body_at_rest(m, z, zdot, vs)
            end if
         end associate
         call end_test_update(m, end_state, t_now, res%n_events > 0, at_rest, reason_out)
      end subroutine on_accepted

      !> An output record at t (C.6), kept and passed to the sink.
      subroutine make_record(t_now, first)
         real(wp), intent(in) :: t_now
         logical, intent(in) :: first
         type(output_record_t) :: r
         type(output_record_t), allocatable :: tmp(:)
         call output_compute(m, res%scene, t_now, y, stepper%f(n_dof + 1:2*n_dof), vehicle_state_at(vm, t_now), &
                             y_cg0, res%e_total0, r)
         if (first) then
            res%e_total0 = r%e_total
            r%e_error = 0.0_wp
         end if
         if (abs(r%e_error) > abs(res%energy_error_max%value)) res%energy_error_max = extreme_t(r%e_error, t_now)
         if (res%n_records == size(res%records)) then
            allocate (tmp(2*size(res%records)))
            tmp(1:res%n_records) = res%records(1:res%n_records)
            call move_alloc(tmp, res%records)
         end if
         res%n_records = res%n_records + 1
         res%records(res%n_records) = r
         if (present(sink)) call sink%record(r, err)
      end subroutine make_record

      subroutine add_event(e)
         type(injury_event_t), intent(in) :: e
         type(injury_event_t), allocatable :: tmp(:)
         if (res%n_events == size(res%events)) then
            allocate (tmp(2*size(res%events)))
            tmp(1:res%n_events) = res%events(1:res%n_events)
            call move_alloc(tmp, res%events)
         end if
         res%n_events = res%n_events + 1
         res%events(res%n_events) = e
         if (present(sink)) call sink%event(e, err)
      end subroutine add_event

      subroutine fail(st, t_now, code)
         class(stepper_t), intent(in) :: st
         real(wp), intent(in) :: t_now
         integer, intent(in) :: code
         character(len=:), allocatable :: why
         why = step_status_text(code)
         if (code == step_rhs_failed) why = why//': '//rhs_status_text(st%rhs_status)//' at t = ' &
                                            //num(sys%last_t)//' s'
         res%failure = 'integration stopped after t = '//num(t_now)//' s: '//why
         res%end_reason = end_failure
         call error_set(err, exit_numerical, res%failure)
      end subroutine fail
   end subroutine run_simulation

   pure subroutine raise(e, value, t)
      type(extreme_t), intent(inout) :: e
      real(wp), intent(in) :: value, t
      if (value > e%value) then
         e%value = value
         e%t = t
      end if
   end subroutine raise
end module simulation
