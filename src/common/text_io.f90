!> Reading a text file whole, robustly: any bytes, any line length, with or
!! without a final newline, LF or CR-LF endings, a UTF-8 byte-order mark at
!! the start dropped. Regular files, pipes, FIFOs, process substitution and
!! standard input are all read to their end. The deck reader and the CSV
!! reader check the lines themselves, so nothing here can end in a Fortran
!! runtime error.
module text_io
   use, intrinsic :: iso_fortran_env, only: int64, iostat_end
   use error_handling, only: error_t, error_set, exit_io
   use strings, only: itoa, escaped
   implicit none
   private

   public :: string_t, read_text_file, read_standard_input, split_lines, append_string
   public :: max_file_bytes, standard_input_path, standard_input_name

   !> A line of text of any length.
   type :: string_t
      character(len=:), allocatable :: s
   end type string_t

   !> Files larger than this are refused (a deck or a pulse table is far smaller).
   integer, parameter :: max_file_bytes = 64*1024*1024

   !> The name that stands for standard input on the command line, and how
   !! messages and the listing name it.
   character(len=*), parameter :: standard_input_path = '-'
   character(len=*), parameter :: standard_input_name = '(standard input)'

   !> Where Linux (and most Unix systems) let a program open its standard
   !! input by name; Fortran cannot switch the preconnected unit to stream access.
   character(len=*), parameter :: stdin_device = '/dev/stdin'

   !> The UTF-8 encoding of U+FEFF, which some editors write at the start of a file.
   character(len=*), parameter :: utf8_bom = char(239)//char(187)//char(191)

contains

   !> Read the file at path into lines (line terminators removed); its
   !! messages name it escaped (a newline in a name would split them).
   subroutine read_text_file(path, lines, err)
      character(len=*), intent(in) :: path
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      logical :: exists

      inquire (file=path, exist=exists)
      if (.not. exists) then
         call error_set(err, exit_io, escaped(trim(path))//': no such file')
         allocate (lines(0))
         return
      end if
      call read_stream(path, escaped(trim(path)), lines, err)
   end subroutine read_text_file

   !> Read standard input to its end into lines; messages name it
   !! standard_input_name.
   subroutine read_standard_input(lines, err)
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      call read_stream(stdin_device, standard_input_name, lines, err)
   end subroutine read_standard_input

   !> Open path as a byte stream and read it to its end. A regular file is
   !! read in one piece of the size the system reports; whatever follows (all
   !! of a pipe, FIFO or terminal, which report no size, or a file that grew)
   !! is read one byte at a time: a read of several bytes that meets the end
   !! of the data leaves them undefined, and from a pipe it may meet a
   !! momentary end, so only one-byte reads are exact everywhere.
   subroutine read_stream(path, name, lines, err)
      character(len=*), intent(in) :: path, name
      type(string_t), allocatable, intent(out) :: lines(:)
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: buffer
      integer(int64) :: reported_size
      integer :: unit, ios, n, first
      character(len=1) :: byte
      character(len=256) :: msg
      character(len=:), allocatable :: too_large

      allocate (lines(0))
      too_large = 'more than '//itoa(max_file_bytes/2**20)//' MiB, too large for a deck or table'
      open (newunit=unit, file=path, access='stream', form='unformatted', &
            status='old', action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call error_set(err, exit_io, name//': cannot open: '//trim(msg))
         return
      end if
      inquire (unit=unit, size=reported_size)
      if (reported_size > max_file_bytes) then
         call fail(too_large)
         return
      end if
      n = int(max(reported_size, 0_int64))
      allocate (character(len=max(n, 4096)) :: buffer)
      if (n > 0) then
         read (unit, iostat=ios, iomsg=msg) buffer(1:n)
         if (ios == iostat_end) then
            call fail('the file is shorter than its size (did it change while being read?)')
            return
         else if (ios /= 0) then
            call fail(trim(msg))
            return
         end if
      end if
      do
         read (unit, iostat=ios, iomsg=msg) byte
         if (ios == iostat_end) exit
         if (ios /= 0) then
            call fail(trim(msg))
            return
         end if
         if (n == max_file_bytes) then
            call fail(too_large)
            return
         end if
         if (n == len(buffer)) call grow(buffer, n)
         n = n + 1
         buffer(n:n) = byte
      end do
      close (unit)
      first = 1
      if (n >= len(utf8_bom)) then
         if (buffer(1:len(utf8_bom)) == utf8_bom) first = len(utf8_bom) + 1
      end if
      call split_lines(buffer(first:n), lines)
   contains
      subroutine fail(reason)
         character(len=*), intent(in) :: reason
         call error_set(err, exit_io, name//': cannot read: '//reason)
         close (unit)
      end subroutine fail
   end subroutine read_stream

   !> Double the buffer's length (up to the largest file read), keeping its
   !! first n characters.
   pure subroutine grow(buffer, n)
      character(len=:), allocatable, intent(inout) :: buffer
      integer, intent(in) :: n
      character(len=:), allocatable :: larger
      allocate (character(len=min(2*len(buffer), max_file_bytes)) :: larger)
      larger(1:n) = buffer(1:n)
      call move_alloc(larger, buffer)
   end subroutine grow

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
