!> hsri2d_bench: how long runs take. For each deck named, reads it once,
!! runs the simulation (without writing a listing) several times and prints
!! the median wall time per run, per simulated second and per right-hand-side
!! evaluation, with the evaluation and step counts. tools/bench builds it in
!! Release and runs it on the shipped decks; docs/performance.md keeps the
!! figures.
!!
!!   hsri2d_bench [--repeat N] DECK [DECK ...]
program hsri2d_bench
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use kinds, only: wp
   use error_handling, only: error_t
   use deck_reader, only: deck_t, deck_init, deck_add_file, deck_finish
   use model_builder, only: build_model
   use model, only: model_t
   use simulation, only: run_simulation
   use run_summary, only: run_summary_t
   implicit none

   integer :: repeat, i, k, n_args
   character(len=512) :: arg
   real(wp), allocatable :: times(:)
   type(model_t) :: m
   type(run_summary_t) :: res
   type(error_t) :: err
   type(deck_t) :: deck
   integer(int64) :: t0, t1, rate
   real(wp) :: median

   repeat = 21
   n_args = command_argument_count()
   write (output_unit, '(a)') '  deck                          runs   median run (ms)  per sim s (ms)  per eval (us)' &
      //'   evaluations      steps'
   i = 0
   do while (i < n_args)
      i = i + 1
      call get_command_argument(i, arg)
      if (arg == '--repeat') then
         i = i + 1
         call get_command_argument(i, arg)
         read (arg, *) repeat
         cycle
      end if
      err = error_t()
      call deck_init(deck)
      call deck_add_file(deck, trim(arg), err)
      call deck_finish(deck, err)
      if (.not. err%failed()) call build_model(deck, m, err)
      if (err%failed()) then
         write (error_unit, '(a)') err%message
         cycle
      end if
      allocate (times(repeat))
      do k = 1, repeat
         call system_clock(t0, rate)
         call run_simulation(m, res, err)
         call system_clock(t1)
         times(k) = real(t1 - t0, wp)/real(rate, wp)
      end do
      median = median_of(times)
      if (err%failed()) then
         write (error_unit, '(a)') trim(arg)//': the run failed: '//err%message
         deallocate (times)
         cycle
      else if (res%evaluations == 0 .or. .not. res%t_end > 0.0_wp) then
         write (error_unit, '(a)') trim(arg)//': the run took no step'
         deallocate (times)
         cycle
      end if
      write (output_unit, '(2x,a30,i6,f18.3,f16.3,f15.3,i14,i11)') basename(trim(arg)), repeat, 1.0e3_wp*median, &
         1.0e3_wp*median/res%t_end, 1.0e6_wp*median/real(res%evaluations, wp), res%evaluations, res%stats%steps
      deallocate (times)
   end do

contains

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
