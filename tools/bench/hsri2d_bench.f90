!> hsri2d_bench: what runs cost, in CPU time of this process (not wall
!! time: the machines are shared). For each deck named it measures, as
!! medians over many repetitions interleaved across the decks:
!!   read   - reading the deck and building the model (C.1);
!!   run    - the simulation alone, no output (C.2-C.7);
!!   +lst   - the simulation writing its listing (to /dev/null);
!!   +h5    - the simulation writing its listing and its HDF5 file;
!! and prints them with the cost per simulated second and per right-hand-side
!! evaluation; then the cost of each effect's add_forces per evaluation, at
!! the deck's initial state (median of repeated blocks of calls), and of the
!! solve of A z'' = b. tools/bench builds it in Release and runs it on the
!! shipped decks; docs/performance.md keeps the figures.
!!
!!   hsri2d_bench [--repeat N] [--run-only] [--at T] DECK [DECK ...]
!!
!! --run-only times the simulation alone, and nothing else (for a profiler:
!! perf, callgrind);
!! --at T measures the effects' costs at the state RK4 reaches at time T
!! (the deck's DT; the effects' memories updated after each step, as the
!! simulation does), e.g. where the belts carry load or unload, rather than
!! at the initial state.
program hsri2d_bench
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use kinds, only: wp
   use error_handling, only: error_t
   use text_io, only: string_t, append_string
   use deck_reader, only: deck_t
   use model, only: model_t
   use simulation, only: run_simulation
   use run_summary, only: run_summary_t
   use run_case_mod, only: run_request_t, run_case, read_case_deck
   use equations_of_motion, only: crash_system_t, system_build, system_initial_y, system_body_state
   use body_state, only: body_state_t
   use effect_events, only: accept_result_t
   use body_matrix, only: body_accelerations
   use model, only: n_dof
   use runge_kutta4, only: rk4_stepper_t
   implicit none

   integer, parameter :: n_parts = 4, p_read = 1, p_run = 2, p_lst = 3, p_h5 = 4
   integer :: repeat, i, k, d, n_decks, ios
   character(len=512) :: arg
   type(string_t), allocatable :: decks(:)
   real(wp), allocatable :: times(:, :, :)       ! (repetition, part, deck)
   type(model_t), allocatable :: models(:)
   type(run_summary_t), allocatable :: results(:)
   logical, allocatable :: usable(:)
   character(len=*), parameter :: h5_scratch = '/tmp/hsri2d_bench_scratch.h5'
   logical :: run_only
   real(wp) :: t_at

   repeat = 21
   run_only = .false.
   t_at = 0.0_wp
   allocate (decks(0))
   i = 0
   do while (i < command_argument_count())
      i = i + 1
      call get_command_argument(i, arg)
      if (arg == '--repeat') then
         i = i + 1
         call get_command_argument(i, arg)
         read (arg, *, iostat=ios) repeat
         if (ios /= 0 .or. repeat < 1) then
            write (error_unit, '(a)') 'hsri2d_bench: --repeat needs a positive integer'
            stop 1
         end if
         cycle
      end if
      if (arg == '--run-only') then
         run_only = .true.
         cycle
      end if
      if (arg == '--at') then
         i = i + 1
         call get_command_argument(i, arg)
         read (arg, *, iostat=ios) t_at
         if (ios /= 0 .or. .not. t_at >= 0.0_wp) then
            write (error_unit, '(a)') 'hsri2d_bench: --at needs a time >= 0 (s)'
            stop 1
         end if
         cycle
      end if
      call append_string(decks, trim(arg))
   end do
   n_decks = size(decks)
   allocate (times(repeat, n_parts, n_decks), models(n_decks), results(n_decks), usable(n_decks))

   ! the decks must read and run
   do d = 1, n_decks
      block
         type(error_t) :: err
         type(deck_t) :: deck
         call read_case_deck(request(d, .false.), deck, models(d), err)
         if (.not. err%failed()) call run_simulation(models(d), results(d), err)
         usable(d) = .not. err%failed() .and. results(d)%evaluations > 0
         if (.not. usable(d)) write (error_unit, '(a)') decks(d)%s//': skipped: '//err%message
      end block
   end do

   ! interleaved: every repetition runs every part of every deck once
   do k = 1, repeat
      do d = 1, n_decks
         if (.not. usable(d)) cycle
         times(k, :, d) = 0.0_wp
         times(k, p_run, d) = cpu_of_run(d)
         if (run_only) cycle
         times(k, p_read, d) = cpu_of_read(d)
         times(k, p_lst, d) = cpu_of_case(d, .false.)
         times(k, p_h5, d) = cpu_of_case(d, .true.)
      end do
   end do

   write (output_unit, '(a,i0,a)') '  CPU time per run, median of ', repeat, ' interleaved repetitions'
   write (output_unit, '(a)') '  deck                         read (ms)   run (ms)  +lst (ms)   +h5 (ms)  per sim s (ms)' &
      //'  per eval (us)  evaluations    steps'
   do d = 1, n_decks
      if (.not. usable(d)) cycle
      associate (r => results(d), run => median_of(times(:, p_run, d)))
         write (output_unit, '(2x,a28,4f11.3,f16.3,f15.3,i13,i9)') basename(decks(d)%s), &
            1.0e3_wp*median_of(times(:, p_read, d)), 1.0e3_wp*run, 1.0e3_wp*median_of(times(:, p_lst, d)), &
            1.0e3_wp*median_of(times(:, p_h5, d)), 1.0e3_wp*run/r%t_end, 1.0e6_wp*run/real(r%evaluations, wp), &
            r%evaluations, r%stats%steps
      end associate
   end do
   if (run_only) stop
   write (output_unit, '(a)') ''
   if (t_at > 0.0_wp) then
      write (output_unit, '(a)') '  CPU time of each effect''s add_forces and of the solve, per evaluation, at the state ' &
         //'of t = '//number(t_at)//' s (memories as at t = 0; median of 21 blocks of 20000 calls)'
   else
      write (output_unit, '(a)') '  CPU time of each effect''s add_forces and of the solve, per evaluation, at the ' &
         //'initial state (median of 21 blocks of 20000 calls)'
   end if
   do d = 1, n_decks
      if (usable(d)) call effect_costs(d)
   end do
   open (newunit=k, file=h5_scratch, status='old', iostat=ios)
   if (ios == 0) close (k, status='delete')

contains

   function request(d, with_h5) result(req)
      integer, intent(in) :: d
      logical, intent(in) :: with_h5
      type(run_request_t) :: req
      allocate (req%decks(1))
      req%decks(1) = decks(d)
      req%listing_file = '/dev/null'   ! written in place (output_files)
      req%h5_file = ''
      if (with_h5) req%h5_file = h5_scratch
   end function request

   real(wp) function cpu_of_read(d) result(dt)
      integer, intent(in) :: d
      type(error_t) :: err
      type(deck_t) :: deck
      type(model_t) :: m
      real(wp) :: t0, t1
      call cpu_time(t0)
      call read_case_deck(request(d, .false.), deck, m, err)
      call cpu_time(t1)
      dt = t1 - t0
   end function cpu_of_read

   real(wp) function cpu_of_run(d) result(dt)
      integer, intent(in) :: d
      type(error_t) :: err
      type(run_summary_t) :: res
      real(wp) :: t0, t1
      call cpu_time(t0)
      call run_simulation(models(d), res, err)
      call cpu_time(t1)
      dt = t1 - t0
   end function cpu_of_run

   !> The whole case through the library (deck reading included, which
   !! the read column lets one subtract).
   real(wp) function cpu_of_case(d, with_h5) result(dt)
      integer, intent(in) :: d
      logical, intent(in) :: with_h5
      type(error_t) :: err
      real(wp) :: t0, t1
      call cpu_time(t0)
      call run_case(request(d, with_h5), err)
      call cpu_time(t1)
      dt = t1 - t0
      if (err%failed()) write (error_unit, '(a)') decks(d)%s//': '//err%message
   end function cpu_of_case

   !> The cost of each effect of deck d's occupant, and of the solve.
   subroutine effect_costs(d)
      integer, intent(in) :: d
      integer, parameter :: calls = 20000, blocks = 21
      type(crash_system_t) :: sys
      type(body_state_t) :: st
      real(wp), allocatable :: y(:), rate(:), rate2(:)
      real(wp) :: b(n_dof), zdd(n_dof), t0, t1, cost(blocks), sink
      integer :: k, blk, i, info, xo, ao
      character(len=:), allocatable :: line
      real(wp) :: t
      line = '  '//basename(decks(d)%s)//':'
      call system_build(models(d), sys)
      call system_initial_y(sys, y)
      allocate (rate(size(y)), rate2(size(y)))
      t = 0.0_wp
      if (t_at > 0.0_wp) call advance_to(models(d)%time%dt, t_at, sys, t, y, line)
      st = system_body_state(sys, 1, t, y)
      sink = 0.0_wp
      associate (occ => sys%occupants(1))
         do k = 1, size(occ%effects)
            xo = occ%extra_offset(k)
            ao = occ%aux_offset(k)
            associate (e => occ%effects(k)%e)
               if (.not. e%acts) cycle
               do blk = 1, blocks
                  call cpu_time(t0)
                  do i = 1, calls
                     b = 0.0_wp
                     call e%add_forces(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), b, &
                                       rate(xo + 1:xo + 2*e%n_extra), rate2(ao + 1:ao + e%n_aux))
                     sink = sink + b(1)
                  end do
                  call cpu_time(t1)
                  cost(blk) = (t1 - t0)/real(calls, wp)
               end do
               line = line//' '//trim(e%name)//' '//number(1.0e6_wp*median_of(cost))
            end associate
         end do
         do blk = 1, blocks
            call cpu_time(t0)
            do i = 1, calls
               b = real(i, wp)
               call body_accelerations(occ%bc, st%c, st%s, b, zdd, info, occ%solver)
               sink = sink + zdd(1)
            end do
            call cpu_time(t1)
            cost(blk) = (t1 - t0)/real(calls, wp)
         end do
         line = line//' | solve '//number(1.0e6_wp*median_of(cost))//' (us)'
      end associate
      ! the sum keeps the calls from being optimised away
      if (.not. sink < huge(1.0_wp)) line = line//' (!)'
      write (output_unit, '(a)') line
   end subroutine effect_costs

   !> RK4 at step h from (t, y) to t_end, each effect with memory told of
   !! every accepted step (as the run's step_bookkeeping, without its outputs
   !! and end tests); line notes where it stopped if the run failed.
   subroutine advance_to(h, t_end, sys, t, y, line)
      real(wp), intent(in) :: h, t_end
      type(crash_system_t), intent(inout) :: sys
      real(wp), intent(inout) :: t, y(:)
      character(len=:), allocatable, intent(inout) :: line
      type(rk4_stepper_t) :: rk
      type(accept_result_t) :: ar
      type(body_state_t) :: st
      type(error_t) :: err
      integer :: q, k, xo, ao
      rk%h = h
      call rk%init(sys, t, y, err)
      do while (t < t_end .and. .not. err%failed())
         call rk%advance(sys, t, y, t_end, err)
         if (err%failed()) exit
         st = system_body_state(sys, 1, t, y)
         ar%restart = .false.
         associate (occ => sys%occupants(1))
            do q = 1, size(occ%remembering)
               k = occ%remembering(q)
               xo = occ%extra_offset(k)
               ao = occ%aux_offset(k)
               ar%n_events = 0
               associate (e => occ%effects(k)%e)
                  call e%accept(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), ar)
               end associate
            end do
         end associate
         if (ar%restart) call rk%restart(sys, t, y, err)
      end do
      if (err%failed()) line = line//' (stopped at t = '//number(t)//' s)'
   end subroutine advance_to

   function number(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=16) :: buf
      write (buf, '(f8.4)') x
      s = trim(adjustl(buf))
   end function number

   real(wp) function median_of(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: s(size(x)), tmp
      integer :: a, b
      s = x
      do a = 2, size(s)          ! insertion sort: a few dozen values
         tmp = s(a)
         b = a - 1
         do while (b >= 1)
            if (s(b) <= tmp) exit
            s(b + 1) = s(b)
            b = b - 1
         end do
         s(b + 1) = tmp
      end do
      median_of = s((size(s) + 1)/2)
   end function median_of

   function basename(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function basename
end program hsri2d_bench
