!> Driver for the killed-run test (h5_killed_run.sh): writes a history
!! file, flushes it, writes more without flushing, then announces it is
!! ready by creating a marker file and waits to be killed.
!!
!! Usage: h5_writer_demo FILE MARKER N_FLUSHED N_UNFLUSHED
!!
!! Row i of /time is i; row i of /body/z is 1000*i + j in column j
!! (j = 1..10), so the checker can recompute every value. One event (kind
!! 1, index 2, time N_FLUSHED) precedes the flush, another (kind 9) follows
!! it. Exits with status 3 if nobody kills it within two minutes.
program h5_writer_demo
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use kinds, only: wp
   use error_handling, only: error_t
   use history_h5, only: history_file_t
   implicit none

   integer, parameter :: ncols = 10
   type(history_file_t) :: h
   type(error_t) :: err
   character(len=1024) :: path, marker, arg
   character(len=80) :: deck(2)
   integer :: n_flushed, n_unflushed, id_t, id_z, i, j, u
   integer(int64) :: t0, t, rate
   character(len=8) :: names(ncols), units(ncols)

   if (command_argument_count() /= 4) then
      write (error_unit, '(a)') 'usage: h5_writer_demo FILE MARKER N_FLUSHED N_UNFLUSHED'
      error stop 2
   end if
   call get_command_argument(1, path)
   call get_command_argument(2, marker)
   call get_command_argument(3, arg)
   read (arg, *) n_flushed
   call get_command_argument(4, arg)
   read (arg, *) n_unflushed

   deck(1) = 'killed-run demo deck'
   deck(2) = 'END'
   do j = 1, ncols
      write (names(j), '(a,i0)') 'q_', j
   end do
   units = 'in'

   call h%open(trim(path), 'killed-run demo', deck, err)
   call check()
   call h%add_series('time', ['t'], ['s'], 'time', id_t, err)
   call check()
   call h%add_series('body/z', names, units, 'demo coordinates', id_z, err)
   call check()

   do i = 1, n_flushed
      call put_row(i)
   end do
   call h%add_event(real(n_flushed, wp), 1, 2, 'event before the flush', err)
   call check()
   call h%flush(err)
   call check()

   ! Not flushed: the file must not depend on any of this.
   do i = n_flushed + 1, n_flushed + n_unflushed
      call put_row(i)
   end do
   call h%add_event(real(n_flushed + n_unflushed, wp), 9, 9, 'event after the flush', err)
   call check()

   open (newunit=u, file=trim(marker), status='replace', action='write')
   write (u, '(a)') 'ready'
   close (u)

   ! Busy wait (standard Fortran has no sleep); killed long before the end.
   call system_clock(t0, rate)
   do
      call system_clock(t)
      if (t - t0 > 120*rate) exit
   end do
   write (error_unit, '(a)') 'h5_writer_demo: not killed within two minutes'
   error stop 3

contains

   subroutine put_row(i)
      integer, intent(in) :: i
      integer :: k
      call h%append(id_t, [real(i, wp)], err)
      call check()
      call h%append(id_z, [(1000.0_wp*i + k, k=1, ncols)], err)
      call check()
   end subroutine put_row

   subroutine check()
      if (err%failed()) then
         write (error_unit, '(a)') 'h5_writer_demo: '//err%message
         error stop 1
      end if
   end subroutine check
end program h5_writer_demo
