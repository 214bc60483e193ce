!> Reading a text file whole, robustly: any bytes, any line length, with or
!! without a final newline, LF or CR-LF endings. The deck reader and the CSV
!! reader check the lines themselves, so nothing here can end in a Fortran
!! runtime error.
module text_io
   use error_handling, only: error_t, error_set, exit_io
   implicit none
   private

   public :: string_t, read_text_file, split_lines, append_string, max_file_bytes

   !> A line of text of any length.
   type :: string_t
      character(len=:), allocatable :: s
   end type string_t

   !> Files larger than this are refused (a deck or a pulse table is far smaller).
   integer, parameter :: max_file_bytes = 64*1024*1024

contains

   !> Read the file at path into lines (line terminators removed).
   subroutine read_text_file(path, lines, err)
      character(len=*), intent(in) :: path
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: buffer
      integer :: unit, ios, nbytes
      character(len=256) :: msg
      logical :: exists

      inquire (file=path, exist=exists)
      if (.not. exists) then
         call error_set(err, exit_io, trim(path)//': no such file')
         return
      end if
      open (newunit=unit, file=path, access='stream', form='unformatted', &
            status='old', action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call error_set(err, exit_io, trim(path)//': cannot open: '//trim(msg))
         return
      end if
      inquire (unit=unit, size=nbytes)
      if (nbytes < 0) then
         call error_set(err, exit_io, trim(path)//': cannot tell the file size (not a regular file?)')
         close (unit)
         return
      end if
      if (nbytes > max_file_bytes) then
         call error_set(err, exit_io, trim(path)//': file too large for a deck or table')
         close (unit)
         return
      end if
      allocate (character(len=nbytes) :: buffer)
      if (nbytes > 0) then
         read (unit, iostat=ios, iomsg=msg) buffer
         if (ios /= 0) then
            call error_set(err, exit_io, trim(path)//': cannot read: '//trim(msg))
            close (unit)
            return
         end if
      end if
      close (unit)
      call split_lines(buffer, lines)
   end subroutine read_text_file

   !> Split text at LF; a CR before the LF is dropped; a final line without
   !! LF is kept; a final LF does not start an extra empty line.
   pure subroutine split_lines(text, lines)
      character(len=*), intent(in) :: text
      type(string_t), allocatable, intent(out) :: lines(:)
      integer :: n, i, start, last, k

      n = 0
      do i = 1, len(text)
         if (text(i:i) == achar(10)) n = n + 1
      end do
      if (len(text) > 0) then
         if (text(len(text):len(text)) /= achar(10)) n = n + 1
      end if
      allocate (lines(n))
      start = 1
      k = 0
      do i = 1, len(text)
         if (text(i:i) == achar(10) .or. i == len(text)) then
            last = i
            if (text(i:i) == achar(10)) last = i - 1
            if (last >= start) then
               if (text(last:last) == achar(13)) last = last - 1
            end if
            k = k + 1
            lines(k)%s = text(start:last)
            start = i + 1
         end if
      end do
   end subroutine split_lines
   !> Add one string to a list (by hand: an array constructor of derived
   !! values with allocatable components leaks in gfortran 12).
   pure subroutine append_string(list, text)
      type(string_t), allocatable, intent(inout) :: list(:)
      character(len=*), intent(in) :: text
      type(string_t), allocatable :: tmp(:)
      integer :: k
      allocate (tmp(size(list) + 1))
      do k = 1, size(list)
         call move_alloc(list(k)%s, tmp(k)%s)
      end do
      tmp(size(tmp))%s = text
      call move_alloc(tmp, list)
   end subroutine append_string

end module text_io
