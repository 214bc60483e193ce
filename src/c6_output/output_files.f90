!> Output files that never lie and never get lost (docs/usage.md, "Output
!! files"):
!!
!! - an output file is written under a temporary name next to its target,
!!   `TARGET.XXXXXX.part` (XXXXXX: six letters or digits, unique to the
!!   run), and renamed over the target only when the run has ended with a
!!   result worth keeping (`deliver_outputs`): another run aimed at the same
!!   target never touches a file being read or written, a failed run never
!!   truncates an earlier result, and a killed run leaves its partial files
!!   under their temporary names;
!! - every write is checked, through POSIX calls (posix_files), because
!!   gfortran's own I/O does not report write errors;
!! - an output may not be one of the run's input files (`check_output_paths`).
!!
!! Targets that are not regular files (standard output, a terminal, a pipe,
!! /dev/null, /dev/full, anything under /dev or /proc) are written in
!! place: there is nothing to rename.
module output_files
   use error_handling, only: error_t, error_set, exit_ok, exit_usage, exit_numerical, exit_io
   use text_io, only: string_t, standard_input_path, standard_input_name
   use posix_files, only: file_info_t, posix_file_info, posix_fd_info, posix_real_path, posix_target_path, &
                          posix_check_writable, posix_create_temp, posix_open_for_writing, posix_write, &
                          posix_sync, posix_close, posix_sync_path, posix_rename, posix_remove, posix_error_text, &
                          kind_regular, kind_directory, kind_character, stdin_fd, stdout_fd, errno_not_found
   implicit none
   private

   public :: output_file_t, check_output_paths, deliver_outputs, same_file, temp_name_pattern

   !> How temporary names are made (for messages and documentation).
   character(len=*), parameter :: temp_name_pattern = 'TARGET.XXXXXX.part'

   !> Bytes of text collected before they are written.
   integer, parameter :: buffer_bytes = 65536

   !> An output file: a text file written through a buffer (`create_text`,
   !! `put_line`, `flush`) or a file another library writes by name
   !! (`reserve`, `writing_path`); `commit` puts it in place of its target,
   !! `discard` withdraws it.
   type :: output_file_t
      private
      !> What the file is, for messages: "listing", "HDF5 file".
      character(len=:), allocatable :: label
      !> The path as the user named it; '' for standard output.
      character(len=:), allocatable :: target
      !> The file the result replaces (symbolic links resolved).
      character(len=:), allocatable :: dest
      !> The temporary name; '' when the target is written in place.
      character(len=:), allocatable :: temp
      !> The temporary name even after commit or discard, so that messages
      !! naming it can be made to name the target instead.
      character(len=:), allocatable :: temp_used
      !> Open descriptor of a text file (-1: none).
      integer :: fd = -1
      logical :: active = .false.
      character(len=:), allocatable :: buf
      integer :: nbuf = 0
      !> First write failure (errno), 0 when none.
      integer :: write_errno = 0
   contains
      !> Start a text file at `path` ('' = standard output).
      procedure :: create_text => output_file_create_text
      !> Reserve a temporary name for a file written by another library.
      procedure :: reserve => output_file_reserve
      !> The name to write to: the temporary name, or the target itself.
      procedure :: writing_path => output_file_writing_path
      !> Add one line of text (a newline is appended).
      procedure :: put_line => output_file_put_line
      !> Write the buffered text; reports the first write failure.
      procedure :: flush => output_file_flush
      !> Write, synchronize, close and rename over the target.
      procedure :: commit => output_file_commit
      !> Close and remove the temporary file; the target stays as it was.
      procedure :: discard => output_file_discard
      !> True between create_text/reserve and commit/discard.
      procedure :: is_active => output_file_is_active
      !> The target as the user named it, or "standard output".
      procedure :: display_name => output_file_display_name
   end type output_file_t

contains

   !> Start a text output. `path` '' means standard output. A regular file
   !! (existing or not) gets a temporary name in its directory; other
   !! existing files (devices, pipes) are opened as they are.
   subroutine output_file_create_text(this, path, label, err)
      class(output_file_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: label
      type(error_t), intent(inout) :: err
      logical :: in_place
      integer :: mode, errno

      call reset(this, path, label)
      if (.not. allocated(this%buf)) allocate (character(len=buffer_bytes) :: this%buf)
      if (len(path) == 0) then
         this%fd = stdout_fd
         this%active = .true.
         return
      end if
      call resolve_target(path, this%dest, in_place, mode, errno, err, 'cannot write the '//label//' to '//path)
      if (err%failed()) return
      if (in_place) then
         errno = posix_open_for_writing(path, this%fd)
      else
         errno = posix_create_temp(this%dest, mode, this%temp, this%fd)
         this%temp_used = this%temp
      end if
      if (errno /= 0) then
         call error_set(err, exit_io, 'cannot write the '//label//' to '//path//': '//posix_error_text(errno) &
                        //directory_note(errno, path))
         return
      end if
      this%active = .true.
   end subroutine output_file_create_text

   !> Reserve a temporary name next to `path` for a file that another
   !! library (HDF5) creates and writes by name: the empty file is created
   !! here, exclusively, so the name is this run's alone. Only regular files
   !! (or names not yet taken) can be targets.
   subroutine output_file_reserve(this, path, label, err)
      class(output_file_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: label
      type(error_t), intent(inout) :: err
      logical :: in_place
      integer :: mode, errno, fd, ignore

      call reset(this, path, label)
      call resolve_target(path, this%dest, in_place, mode, errno, err, 'cannot create '//label//' '//path)
      if (err%failed()) return
      if (in_place) then
         call error_set(err, exit_io, 'cannot create '//label//' '//path//': not a regular file')
         return
      end if
      errno = posix_create_temp(this%dest, mode, this%temp, fd)
      this%temp_used = this%temp
      if (errno /= 0) then
         call error_set(err, exit_io, 'cannot create '//label//' '//path//': '//posix_error_text(errno) &
                        //directory_note(errno, path))
         return
      end if
      ignore = posix_close(fd)
      this%active = .true.
   end subroutine output_file_reserve

   !> Where the contents go while the run lasts.
   function output_file_writing_path(this) result(path)
      class(output_file_t), intent(in) :: this
      character(len=:), allocatable :: path
      path = ''
      if (.not. this%active) return
      path = this%dest
      if (len(this%temp) > 0) path = this%temp
   end function output_file_writing_path

   !> Add `text` and a newline. After a write failure nothing more is
   !! written; `flush` and `commit` report it.
   subroutine output_file_put_line(this, text)
      class(output_file_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      integer :: n
      if (.not. this%active .or. this%fd < 0 .or. this%write_errno /= 0) return
      n = len(text) + 1
      if (this%nbuf + n > len(this%buf)) call write_buffer(this)
      if (n > len(this%buf)) then
         if (this%write_errno == 0) this%write_errno = posix_write(this%fd, text//new_line('a'))
         return
      end if
      this%buf(this%nbuf + 1:this%nbuf + n) = text//new_line('a')
      this%nbuf = this%nbuf + n
   end subroutine output_file_put_line

   !> Write what is buffered. `err` gets the first write failure unless it
   !! already holds an error.
   subroutine output_file_flush(this, err)
      class(output_file_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      if (.not. this%active) return
      if (this%fd >= 0) call write_buffer(this)
      if (this%write_errno /= 0 .and. .not. err%failed()) &
         call error_set(err, exit_io, 'cannot write the '//this%label//' to '//this%display_name()//': ' &
                        //posix_error_text(this%write_errno))
   end subroutine output_file_flush

   !> Put the file in place of its target: write what is buffered, have
   !! the system write it to the disk, close it and rename it over the
   !! target (or, for a file written in place, just close it). On failure
   !! the temporary file is removed, the target is left as it was, and
   !! `err` says why (unless it already holds an error).
   subroutine output_file_commit(this, err)
      class(output_file_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      type(error_t) :: local
      integer :: errno, close_errno, ignore
      character(len=:), allocatable :: step

      if (.not. this%active) return
      call this%flush(local)
      errno = 0
      step = ''
      if (.not. local%failed() .and. this%fd >= 0 .and. this%fd /= stdout_fd) then
         ! fsync first: after a system crash the target holds either the
         ! old contents or the whole new file, never an empty one.
         if (len(this%temp) > 0) errno = posix_sync(this%fd)
         ! Closed whatever the sync gave; the first failure is reported.
         close_errno = posix_close(this%fd)
         if (errno == 0) errno = close_errno
         this%fd = -1
         step = 'cannot write the '//this%label//' to '//this%display_name()
      else if (.not. local%failed() .and. this%fd < 0 .and. len(this%temp) > 0) then
         errno = posix_sync_path(this%temp)
         step = 'cannot write '//this%label//' '//this%display_name()
      end if
      if (errno == 0 .and. .not. local%failed() .and. len(this%temp) > 0) then
         errno = posix_rename(this%temp, this%dest)
         step = 'cannot put the new '//this%label//' in place of '//this%display_name()
         ! The rename is durable once the directory is synchronized; a
         ! failure there leaves the new file in place, so it is not reported.
         if (errno == 0) ignore = posix_sync_path(parent_directory(this%dest))
         if (errno == 0) this%temp = ''
      end if
      if (errno /= 0 .and. .not. local%failed()) call error_set(local, exit_io, step//': '//posix_error_text(errno))
      if (local%failed()) then
         call this%discard()
         if (.not. err%failed()) call error_set(err, local%code, local%message)
         return
      end if
      this%active = .false.
   end subroutine output_file_commit

   !> Withdraw the file: close it and remove the temporary file. The target
   !! keeps whatever it held. What was written in place stays written.
   subroutine output_file_discard(this)
      class(output_file_t), intent(inout) :: this
      integer :: ignore
      if (this%fd >= 0 .and. this%fd /= stdout_fd) ignore = posix_close(this%fd)
      this%fd = -1
      if (allocated(this%temp)) then
         if (len(this%temp) > 0) ignore = posix_remove(this%temp)
         this%temp = ''
      end if
      this%nbuf = 0
      this%active = .false.
   end subroutine output_file_discard

   pure logical function output_file_is_active(this)
      class(output_file_t), intent(in) :: this
      output_file_is_active = this%active
   end function output_file_is_active

   function output_file_display_name(this) result(name)
      class(output_file_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'standard output'
      if (allocated(this%target)) then
         if (len(this%target) > 0) name = this%target
      end if
   end function output_file_display_name

   !> End a run's outputs according to how the run ended (`err`):
   !!
   !! - success or a numerical failure (the outputs hold the run up to the
   !!   failure): every output is committed; a failure to commit one turns
   !!   `err` into an input/output error, and the outputs not yet committed
   !!   are discarded;
   !! - anything else (an input/output error): every output is discarded,
   !!   the targets keep what they held, and the message says so.
   !!
   !! Messages name the targets, never the temporary names.
   subroutine deliver_outputs(err, first, second)
      type(error_t), intent(inout) :: err
      class(output_file_t), intent(inout) :: first
      class(output_file_t), intent(inout), optional :: second
      type(error_t) :: commit_err
      character(len=:), allocatable :: kept, also

      if (err%code == exit_ok .or. err%code == exit_numerical) then
         call first%commit(commit_err)
         if (present(second)) then
            if (commit_err%failed()) call second%discard()
            call second%commit(commit_err)
         end if
         if (commit_err%failed()) err = commit_err
      else
         kept = unchanged_target(first)
         call first%discard()
         if (present(second)) then
            also = unchanged_target(second)
            if (len(kept) > 0 .and. len(also) > 0) kept = kept//' and '
            kept = kept//also
            call second%discard()
         end if
         if (err%code == exit_io .and. len(kept) > 0) &
            err%message = err%message//new_line('a')//kept//': left as before; the partial output was removed'
      end if
      call name_targets(err, first)
      if (present(second)) call name_targets(err, second)
   end subroutine deliver_outputs

   !> Refuse (exit status 1) outputs that would overwrite an input: the
   !! listing (`listing_file`, '' = standard output) or the HDF5 file
   !! (`h5_file`, '' = none) being one of the decks (`-` = standard input)
   !! or the pulse's files (`pulse_files`: the CSV file, the ISO-MME data set's), or both outputs being the
   !! same file (also standard output redirected to the HDF5 file). An
   !! output and an input are the same file when they have the same device
   !! and inode, whatever the names (`-o /dev/stdin`, `>> run.deck`); a
   !! character device (a terminal, /dev/null) is exempt: writing to it
   !! destroys nothing. Runs before any output file is created.
   subroutine check_output_paths(decks, pulse_files, listing_file, h5_file, err)
      type(string_t), intent(in) :: decks(:), pulse_files(:)
      character(len=*), intent(in) :: listing_file, h5_file
      type(error_t), intent(inout) :: err
      type(file_info_t) :: listing_info, h5_info
      logical :: listing_exists, h5_exists
      integer :: k

      if (len(listing_file) > 0 .and. len(h5_file) > 0) then
         if (same_file(listing_file, h5_file)) then
            call error_set(err, exit_usage, '-o and --h5 name the same file: '//listing_file//' and '//h5_file)
            return
         end if
      end if
      if (len(listing_file) == 0) then
         listing_exists = posix_fd_info(stdout_fd, listing_info) == 0
      else
         listing_exists = posix_file_info(listing_file, listing_info) == 0
      end if
      h5_exists = .false.
      if (len(h5_file) > 0) h5_exists = posix_file_info(h5_file, h5_info) == 0
      if (len(listing_file) == 0 .and. listing_exists .and. h5_exists) then
         if (clash(listing_info, h5_info)) then
            call error_set(err, exit_usage, 'standard output is the HDF5 file '//h5_file// &
                           '; write the listing elsewhere (-o)')
            return
         end if
      end if
      do k = 1, size(decks)
         call refuse(decks(k)%s, 'input deck')
      end do
      do k = 1, size(pulse_files)
         call refuse(pulse_files(k)%s, 'pulse file')
      end do
   contains
      subroutine refuse(input, kind)
         character(len=*), intent(in) :: input, kind
         type(file_info_t) :: input_info
         character(len=:), allocatable :: shown
         integer :: errno
         if (err%failed()) return
         shown = input
         if (input == standard_input_path .and. len(input) == len(standard_input_path)) then
            errno = posix_fd_info(stdin_fd, input_info)
            shown = standard_input_name
         else
            errno = posix_file_info(input, input_info)
         end if
         if (errno /= 0) return
         if (listing_exists) then
            if (clash(listing_info, input_info)) then
               if (len(listing_file) > 0) then
                  call error_set(err, exit_usage, 'the listing file '//listing_file//' is the '//kind//' '//shown// &
                                 '; refusing to overwrite it')
               else
                  call error_set(err, exit_usage, 'standard output is the '//kind//' '//shown// &
                                 '; refusing to overwrite it')
               end if
               return
            end if
         end if
         if (h5_exists) then
            if (clash(h5_info, input_info)) then
               call error_set(err, exit_usage, 'the HDF5 file '//h5_file//' is the '//kind//' '//shown// &
                              '; refusing to overwrite it')
               return
            end if
         end if
      end subroutine refuse
   end subroutine check_output_paths

   !> Whether writing to `output` would overwrite `input`: the same file,
   !! unless it is a character device (a terminal, /dev/null).
   pure logical function clash(output, input)
      type(file_info_t), intent(in) :: output, input
      clash = output%dev == input%dev .and. output%ino == input%ino .and. input%kind /= kind_character
   end function clash

   !> Whether paths `a` and `b` name the same file: the same device and
   !! inode when both exist, otherwise the same file to be created (symbolic
   !! links that point to nothing yet followed, the directory resolved).
   logical function same_file(a, b)
      character(len=*), intent(in) :: a, b
      type(file_info_t) :: ia, ib
      integer :: errno_a, errno_b
      errno_a = posix_file_info(a, ia)
      errno_b = posix_file_info(b, ib)
      if (errno_a == 0 .and. errno_b == 0) then
         same_file = ia%dev == ib%dev .and. ia%ino == ib%ino
      else
         same_file = target_path(a) == target_path(b)
      end if
   end function same_file

   ! ---------------------------------------------------------------- helpers

   subroutine reset(this, path, label)
      class(output_file_t), intent(inout) :: this
      character(len=*), intent(in) :: path, label
      if (this%active) call this%discard()
      this%label = label
      this%target = path
      this%dest = path
      this%temp = ''
      this%temp_used = ''
      this%fd = -1
      this%nbuf = 0
      this%write_errno = 0
   end subroutine reset

   !> Where the result of writing `path` goes: `dest` (links resolved),
   !! whether the file is written in place (it exists and is not a regular
   !! file, or lies under /dev or /proc), and the permission bits to give
   !! the new file (those of the file it replaces; -1: the default).
   !! Failures go to `err` after `prefix`.
   subroutine resolve_target(path, dest, in_place, mode, errno, err, prefix)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: dest
      logical, intent(out) :: in_place
      integer, intent(out) :: mode, errno
      type(error_t), intent(inout) :: err
      character(len=*), intent(in) :: prefix
      type(file_info_t) :: info

      dest = path
      mode = -1
      errno = posix_file_info(path, info)
      in_place = starts_with(path, '/dev/') .or. starts_with(path, '/proc/')
      if (errno == 0 .and. info%kind == kind_directory) then
         call error_set(err, exit_io, prefix//': it is a directory')
         return
      end if
      if (errno == 0 .and. info%kind /= kind_regular) in_place = .true.
      if (in_place) return
      if (errno == 0) then
         ! An existing file: replaced only where it could be overwritten.
         errno = posix_check_writable(path)
         if (errno == 0) errno = posix_real_path(path, dest)
         if (errno /= 0) then
            call error_set(err, exit_io, prefix//': '//posix_error_text(errno))
            return
         end if
         mode = info%mode
         return
      end if
      if (errno /= errno_not_found) then
         call error_set(err, exit_io, prefix//': '//posix_error_text(errno)//directory_note(errno, path))
         return
      end if
      if (len(last_name(path)) == 0) then
         call error_set(err, exit_io, prefix//': it is a directory')
         return
      end if
      ! A new file, or a symbolic link that points to nothing yet: the file
      ! is created where the link points, and the link stays.
      errno = posix_target_path(path, dest)
      if (errno /= 0) then
         call error_set(err, exit_io, prefix//': '//posix_error_text(errno)//directory_note(errno, dest))
         return
      end if
   end subroutine resolve_target

   !> " (directory D)" after a failure that concerns the directory of
   !! `path` (missing, not a directory, not writable).
   function directory_note(errno, path) result(note)
      integer, intent(in) :: errno
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: note
      integer, parameter :: eperm = 1, eacces = 13, enotdir = 20, erofs = 30
      note = ''
      if (errno == errno_not_found .or. errno == eperm .or. errno == eacces .or. errno == enotdir &
          .or. errno == erofs) note = ' (directory '//parent_directory(path)//')'
   end function directory_note

   !> Write the buffered text (once a write has failed, nothing more).
   subroutine write_buffer(this)
      type(output_file_t), intent(inout) :: this
      if (this%nbuf > 0 .and. this%write_errno == 0) &
         this%write_errno = posix_write(this%fd, this%buf(1:this%nbuf))
      this%nbuf = 0
   end subroutine write_buffer

   !> The file a write to `path` would create or replace (posix_target_path),
   !! or `path` itself when that cannot be resolved.
   function target_path(path) result(target)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: target
      if (posix_target_path(path, target) /= 0) target = path
   end function target_path

   !> Replace the temporary name of `file` by its target in err's message.
   subroutine name_targets(err, file)
      type(error_t), intent(inout) :: err
      class(output_file_t), intent(in) :: file
      integer :: at
      if (.not. allocated(err%message) .or. .not. allocated(file%temp_used)) return
      if (len(file%temp_used) == 0) return
      do
         at = index(err%message, file%temp_used)
         if (at == 0) exit
         err%message = err%message(1:at - 1)//file%target//err%message(at + len(file%temp_used):)
      end do
   end subroutine name_targets

   !> "out.h5" when `file` has a target that stays unchanged, else ''.
   function unchanged_target(file) result(name)
      class(output_file_t), intent(in) :: file
      character(len=:), allocatable :: name
      name = ''
      if (.not. file%active .or. .not. allocated(file%temp)) return
      if (len(file%temp) > 0) name = file%target
   end function unchanged_target

   pure function parent_directory(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: slash
      slash = index(path, '/', back=.true.)
      if (slash == 0) then
         dir = '.'
      else if (slash == 1) then
         dir = '/'
      else
         dir = path(1:slash - 1)
      end if
   end function parent_directory

   pure function last_name(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function last_name

   pure logical function starts_with(text, prefix)
      character(len=*), intent(in) :: text, prefix
      starts_with = len(text) >= len(prefix)
      if (starts_with) starts_with = text(1:len(prefix)) == prefix
   end function starts_with
end module output_files
