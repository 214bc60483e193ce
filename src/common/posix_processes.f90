!> Worker processes for a study's runs (report C.8, `hsri2d --jobs N`):
!! start a copy of the program, wait for it, tell a terminal. The C side
!! is src/common/posix_processes.c. Every operation returns 0 or the errno
!! value of its failure (posix_files' posix_error_text names it).
module posix_processes
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long, c_null_char
   use text_io, only: string_t
   implicit none
   private

   public :: posix_spawn_program, posix_wait, posix_is_terminal, posix_sleep_ms

   interface
      integer(c_int) function c_spawn(path, args, n_args, pid) bind(c, name='hsri2d_spawn')
         import :: c_int, c_char, c_long
         character(kind=c_char), intent(in) :: path(*), args(*)
         integer(c_int), value :: n_args
         integer(c_long), intent(out) :: pid
      end function c_spawn

      integer(c_int) function c_wait(pid, nohang, done, status) bind(c, name='hsri2d_wait')
         import :: c_int, c_long
         integer(c_long), value :: pid
         integer(c_int), value :: nohang
         integer(c_int), intent(out) :: done, status
      end function c_wait

      integer(c_int) function c_is_terminal(fd) bind(c, name='hsri2d_is_terminal')
         import :: c_int
         integer(c_int), value :: fd
      end function c_is_terminal

      subroutine c_sleep_ms(ms) bind(c, name='hsri2d_sleep_ms')
         import :: c_int
         integer(c_int), value :: ms
      end subroutine c_sleep_ms
   end interface

contains

   !> Start program `path` with arguments args (args(1) is its argv[0]);
   !! pid: the process.
   integer function posix_spawn_program(path, args, pid) result(errno)
      character(len=*), intent(in) :: path
      type(string_t), intent(in) :: args(:)
      integer(c_long), intent(out) :: pid
      character(len=:), allocatable :: packed
      integer :: k
      packed = ''
      do k = 1, size(args)
         packed = packed//args(k)%s//c_null_char
      end do
      pid = 0
      errno = int(c_spawn(path//c_null_char, packed//c_null_char, int(size(args), c_int), pid))
   end function posix_spawn_program

   !> Wait for process pid (without blocking when nohang); done once it has
   !! ended, status its exit status (128 + a signal that killed it).
   integer function posix_wait(pid, nohang, done, status) result(errno)
      integer(c_long), intent(in) :: pid
      logical, intent(in) :: nohang
      logical, intent(out) :: done
      integer, intent(out) :: status
      integer(c_int) :: d, st
      errno = int(c_wait(pid, merge(1_c_int, 0_c_int, nohang), d, st))
      done = d /= 0
      status = int(st)
   end function posix_wait

   !> Descriptor fd (2: standard error) is a terminal.
   logical function posix_is_terminal(fd)
      integer, intent(in) :: fd
      posix_is_terminal = c_is_terminal(int(fd, c_int)) /= 0
   end function posix_is_terminal

   subroutine posix_sleep_ms(ms)
      integer, intent(in) :: ms
      call c_sleep_ms(int(ms, c_int))
   end subroutine posix_sleep_ms
end module posix_processes
