!> POSIX file operations that Fortran's own I/O cannot do, or does without
!! reporting failures (gfortran 12 gives iostat = 0 on WRITE, FLUSH and
!! CLOSE even when the disk is full): checked writes to a file descriptor,
!! fsync, rename, remove, file identity, canonical paths, exclusive
!! creation of temporary files. The C side is src/common/posix_files.c.
!!
!! Every operation returns 0 or the errno value of its failure;
!! `posix_error_text` turns that into the system's words.
module posix_files
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_size_t, c_int64_t, c_null_char
   implicit none
   private

   public :: file_info_t, posix_file_info, posix_fd_info, posix_real_path, posix_target_path, posix_check_writable
   public :: posix_create_temp, posix_open_for_writing, posix_write, posix_sync, posix_close
   public :: posix_sync_path, posix_rename, posix_remove, posix_error_text, posix_make_dir
   public :: posix_ignore_output_signals, posix_clear_errno, posix_errno
   public :: kind_none, kind_regular, kind_directory, kind_other, kind_character, stdin_fd, stdout_fd
   public :: errno_not_found

   !> Kinds of file (the values of posix_files.c); kind_character: a
   !! character device (a terminal, /dev/null), kind_other: a pipe, a
   !! socket, a block device.
   integer, parameter :: kind_none = 0, kind_regular = 1, kind_directory = 2, kind_other = 3, kind_character = 4
   !> The descriptors of standard input and standard output.
   integer, parameter :: stdin_fd = 0, stdout_fd = 1
   !> ENOENT on Linux (and every POSIX system in use).
   integer, parameter :: errno_not_found = 2
   !> Room for a path coming back from C.
   integer, parameter :: max_path = 4096

   !> What stat says about a file: its kind, identity and permission bits.
   type :: file_info_t
      integer :: kind = kind_none
      integer(c_int64_t) :: dev = 0, ino = 0
      integer :: mode = 0
   end type file_info_t

   interface
      integer(c_int) function c_ignore_output_signals() bind(c, name='hsri2d_ignore_output_signals')
         import :: c_int
      end function c_ignore_output_signals

      integer(c_int) function c_file_info(path, kind, dev, ino, mode) bind(c, name='hsri2d_file_info')
         import :: c_int, c_char, c_int64_t
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: kind, mode
         integer(c_int64_t), intent(out) :: dev, ino
      end function c_file_info

      integer(c_int) function c_fd_info(fd, kind, dev, ino, mode) bind(c, name='hsri2d_fd_info')
         import :: c_int, c_int64_t
         integer(c_int), value :: fd
         integer(c_int), intent(out) :: kind, mode
         integer(c_int64_t), intent(out) :: dev, ino
      end function c_fd_info

      integer(c_int) function c_real_path(path, out, cap, len) bind(c, name='hsri2d_real_path')
         import :: c_int, c_char, c_size_t
         character(kind=c_char), intent(in) :: path(*)
         character(kind=c_char), intent(out) :: out(*)
         integer(c_size_t), value :: cap
         integer(c_size_t), intent(out) :: len
      end function c_real_path

      integer(c_int) function c_target_path(path, out, cap, len) bind(c, name='hsri2d_target_path')
         import :: c_int, c_char, c_size_t
         character(kind=c_char), intent(in) :: path(*)
         character(kind=c_char), intent(out) :: out(*)
         integer(c_size_t), value :: cap
         integer(c_size_t), intent(out) :: len
      end function c_target_path

      integer(c_int) function c_check_writable(path) bind(c, name='hsri2d_check_writable')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_check_writable

      integer(c_int) function c_create_temp(prefix, mode, out, cap, fd) bind(c, name='hsri2d_create_temp')
         import :: c_int, c_char, c_size_t
         character(kind=c_char), intent(in) :: prefix(*)
         integer(c_int), value :: mode
         character(kind=c_char), intent(out) :: out(*)
         integer(c_size_t), value :: cap
         integer(c_int), intent(out) :: fd
      end function c_create_temp

      integer(c_int) function c_open_for_writing(path, fd) bind(c, name='hsri2d_open_for_writing')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: fd
      end function c_open_for_writing

      integer(c_int) function c_write_all(fd, buf, n) bind(c, name='hsri2d_write_all')
         import :: c_int, c_char, c_size_t
         integer(c_int), value :: fd
         character(kind=c_char), intent(in) :: buf(*)
         integer(c_size_t), value :: n
      end function c_write_all

      integer(c_int) function c_sync(fd) bind(c, name='hsri2d_sync')
         import :: c_int
         integer(c_int), value :: fd
      end function c_sync

      integer(c_int) function c_close(fd) bind(c, name='hsri2d_close')
         import :: c_int
         integer(c_int), value :: fd
      end function c_close

      integer(c_int) function c_sync_path(path) bind(c, name='hsri2d_sync_path')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_sync_path

      integer(c_int) function c_rename(from, to) bind(c, name='hsri2d_rename')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: from(*), to(*)
      end function c_rename

      integer(c_int) function c_remove(path) bind(c, name='hsri2d_remove')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_remove

      integer(c_int) function c_make_dir(path) bind(c, name='hsri2d_make_dir')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_make_dir

      subroutine c_error_text(errnum, out, cap, len) bind(c, name='hsri2d_error_text')
         import :: c_int, c_char, c_size_t
         integer(c_int), value :: errnum
         character(kind=c_char), intent(out) :: out(*)
         integer(c_size_t), value :: cap
         integer(c_size_t), intent(out) :: len
      end subroutine c_error_text

      subroutine c_clear_errno() bind(c, name='hsri2d_clear_errno')
      end subroutine c_clear_errno

      integer(c_int) function c_errno() bind(c, name='hsri2d_errno')
         import :: c_int
      end function c_errno
   end interface

contains

   !> Make a write past a file-size limit fail with EFBIG and a write to a
   !! pipe nobody reads any more fail with EPIPE (errors the program
   !! reports) rather than kill the process with SIGXFSZ or SIGPIPE.
   integer function posix_ignore_output_signals() result(errno)
      errno = int(c_ignore_output_signals())
   end function posix_ignore_output_signals

   !> Kind, identity and permission bits of the file at `path` (links
   !! followed); errno_not_found when there is none.
   integer function posix_file_info(path, info) result(errno)
      character(len=*), intent(in) :: path
      type(file_info_t), intent(out) :: info
      integer(c_int) :: kind, mode
      errno = int(c_file_info(c_string(path), kind, info%dev, info%ino, mode))
      info%kind = int(kind)
      info%mode = int(mode)
   end function posix_file_info

   !> The same for an open file descriptor.
   integer function posix_fd_info(fd, info) result(errno)
      integer, intent(in) :: fd
      type(file_info_t), intent(out) :: info
      integer(c_int) :: kind, mode
      errno = int(c_fd_info(int(fd, c_int), kind, info%dev, info%ino, mode))
      info%kind = int(kind)
      info%mode = int(mode)
   end function posix_fd_info

   !> The canonical absolute path of an existing file (links and `..`
   !! resolved); '' on failure.
   integer function posix_real_path(path, real) result(errno)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: real
      character(kind=c_char) :: buf(max_path)
      integer(c_size_t) :: n
      errno = int(c_real_path(c_string(path), buf, int(max_path, c_size_t), n))
      real = from_c(buf, int(n))
   end function posix_real_path

   !> The canonical absolute path of the file a write to `path` creates or
   !! replaces: the file itself when it exists, otherwise the name a chain
   !! of symbolic links pointing to nothing yet ends at, in its canonical
   !! directory. On failure `target` is the path reached (for messages).
   integer function posix_target_path(path, target) result(errno)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: target
      character(kind=c_char) :: buf(max_path)
      integer(c_size_t) :: n
      errno = int(c_target_path(c_string(path), buf, int(max_path, c_size_t), n))
      target = from_c(buf, int(n))
   end function posix_target_path

   !> 0 when this process may write the existing file at `path`.
   integer function posix_check_writable(path) result(errno)
      character(len=*), intent(in) :: path
      errno = int(c_check_writable(c_string(path)))
   end function posix_check_writable

   !> Create a new, unique file `prefix.XXXXXX.part` for writing; `path`
   !! is its name, `fd` its open descriptor. `mode` (when not negative)
   !! gives its permission bits.
   integer function posix_create_temp(prefix, mode, path, fd) result(errno)
      character(len=*), intent(in) :: prefix
      integer, intent(in) :: mode
      character(len=:), allocatable, intent(out) :: path
      integer, intent(out) :: fd
      character(kind=c_char) :: buf(max_path)
      integer(c_int) :: cfd
      integer :: n
      errno = int(c_create_temp(c_string(prefix), int(mode, c_int), buf, int(max_path, c_size_t), cfd))
      fd = int(cfd)
      path = ''
      if (errno /= 0) return
      n = 0
      do while (buf(n + 1) /= c_null_char)
         n = n + 1
      end do
      path = from_c(buf, n)
   end function posix_create_temp

   !> Open an existing file (a terminal, a pipe, a device) for writing as it is.
   integer function posix_open_for_writing(path, fd) result(errno)
      character(len=*), intent(in) :: path
      integer, intent(out) :: fd
      integer(c_int) :: cfd
      errno = int(c_open_for_writing(c_string(path), cfd))
      fd = int(cfd)
   end function posix_open_for_writing

   !> Write every byte of `text` to `fd`.
   integer function posix_write(fd, text) result(errno)
      integer, intent(in) :: fd
      character(len=*), intent(in) :: text
      errno = 0
      if (len(text) == 0) return
      errno = int(c_write_all(int(fd, c_int), text, int(len(text), c_size_t)))
   end function posix_write

   !> fsync; not an error for pipes, terminals and devices.
   integer function posix_sync(fd) result(errno)
      integer, intent(in) :: fd
      errno = int(c_sync(int(fd, c_int)))
   end function posix_sync

   integer function posix_close(fd) result(errno)
      integer, intent(in) :: fd
      errno = int(c_close(int(fd, c_int)))
   end function posix_close

   !> fsync the file or directory at `path`.
   integer function posix_sync_path(path) result(errno)
      character(len=*), intent(in) :: path
      errno = int(c_sync_path(c_string(path)))
   end function posix_sync_path

   !> Rename `from` to `to`, replacing `to` atomically (same file system).
   integer function posix_rename(from, to) result(errno)
      character(len=*), intent(in) :: from, to
      errno = int(c_rename(c_string(from), c_string(to)))
   end function posix_rename

   integer function posix_remove(path) result(errno)
      character(len=*), intent(in) :: path
      errno = int(c_remove(c_string(path)))
   end function posix_remove

   !> Make directory path (its parent must exist); one that exists is fine.
   integer function posix_make_dir(path) result(errno)
      character(len=*), intent(in) :: path
      errno = int(c_make_dir(c_string(path)))
   end function posix_make_dir

   !> The system's words for an errno value ("No space left on device").
   function posix_error_text(errno) result(text)
      integer, intent(in) :: errno
      character(len=:), allocatable :: text
      character(kind=c_char) :: buf(256)
      integer(c_size_t) :: n
      call c_error_text(int(errno, c_int), buf, int(size(buf), c_size_t), n)
      text = from_c(buf, int(n))
   end function posix_error_text

   !> Clear errno, before a library call that fails without saying why.
   subroutine posix_clear_errno()
      call c_clear_errno()
   end subroutine posix_clear_errno

   !> errno as it is now (0 when nothing set it since posix_clear_errno).
   integer function posix_errno() result(errno)
      errno = int(c_errno())
   end function posix_errno

   ! ---------------------------------------------------------------- helpers

   pure function c_string(text) result(s)
      character(len=*), intent(in) :: text
      character(kind=c_char, len=len(text) + 1) :: s
      s = text//c_null_char
   end function c_string

   pure function from_c(buf, n) result(s)
      character(kind=c_char), intent(in) :: buf(:)
      integer, intent(in) :: n
      character(len=:), allocatable :: s
      integer :: k
      allocate (character(len=max(0, n)) :: s)
      do k = 1, n
         s(k:k) = buf(k)
      end do
   end function from_c
end module posix_files
