!> The vehicle's acceleration table from a CSV file (*PULSEFILE; C.1, C.3),
!! because that is how test data arrives. Each column is checked and
!! converted through the field specification of the *PULSE card it stands
!! for (T, XDDOT, YDDOT, PHIDDOT: units, ranges, blanks), so a CSV value and
!! a card value mean the same. A file that cannot be read is an
!! input/output error (exit status 4); a file whose content is wrong is a
!! deck error (2), each problem with the file, line and column.
module pulse_csv
   use kinds, only: wp
   use error_handling, only: error_t, error_append, exit_deck, exit_io
   use strings, only: itoa, read_real, escaped
   use text_io, only: string_t, read_text_file
   use deck_cards, only: group_spec_t, blank_required
   use field_values, only: convert_field_text
   use model, only: pulse_table_t
   implicit none
   private

   public :: read_pulse_csv

   !> Columns of a row: t, xddot, yddot, phiddot.
   integer, parameter :: n_columns = 4

contains

   !> Read the table at path; spec is the *PULSE group of the card table;
   !! named_at locates the card that names the file ("deck:line").
   subroutine read_pulse_csv(path, named_at, spec, table, err)
      character(len=*), intent(in) :: path, named_at
      type(group_spec_t), intent(in) :: spec
      type(pulse_table_t), intent(out) :: table
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: lines(:)
      type(error_t) :: io_err
      character(len=:), allocatable :: line
      real(wp), allocatable :: t(:), v(:, :)
      real(wp) :: row(n_columns)
      integer :: i, n, n_rows, last_good
      logical :: header_allowed, row_ok, is_header
      character(len=:), allocatable :: name

      name = escaped(path)   ! (one line in a message, whatever the name holds)

      call read_text_file(path, lines, io_err)
      if (io_err%failed()) then
         call error_append(err, exit_io, named_at//': *PULSEFILE card 1, field FILE: pulse file: '//io_err%message)
         return
      end if
      allocate (t(size(lines)), v(size(lines), 3))
      n = 0         ! rows read without error
      n_rows = 0    ! data rows, bad ones included
      header_allowed = .true.
      do i = 1, size(lines)
         line = trim(lines(i)%s)
         if (len(line) == 0) cycle
         if (line(1:1) == '#') cycle
         call convert_row(line, i, header_allowed, row, row_ok, is_header)
         header_allowed = .false.
         if (is_header) cycle
         n_rows = n_rows + 1
         if (.not. row_ok) cycle   ! its own error says what is wrong
         n = n + 1
         t(n) = row(1)
         v(n, :) = row(2:4)
         ! the file's first data row starts the table (a bad first row was
         ! reported; the next row is not taken for the first)
         if (n_rows == 1 .and. abs(t(1)) > 0.0_wp) call problem(i, 'column 1 (T): the first time must be 0; ' &
            //'found '//trim(adjustl(column_text(line, 1))))
         if (n > 1) then
            if (.not. t(n) > t(n - 1)) call problem(i, 'column 1 (T): times must increase; found ' &
               //trim(adjustl(column_text(line, 1)))//' after '//trim(adjustl(column_text(lines(last_good)%s, 1))))
         end if
         last_good = i
      end do
      if (n_rows == 0) then
         call problem(size(lines), 'no data rows (a row holds t, xddot[, yddot[, phiddot]])')
         return
      end if
      if (n == 0) return   ! every row was bad, and reported
      table%t = t(1:n)
      table%v = v(1:n, :)
      table%given = .true.
   contains
      !> Split "a, b, c" and convert each column through its field.
      subroutine convert_row(text, line_no, may_be_header, values, ok, header)
         character(len=*), intent(in) :: text
         integer, intent(in) :: line_no
         logical, intent(in) :: may_be_header
         real(wp), intent(out) :: values(n_columns)
         logical, intent(out) :: ok, header
         character(len=:), allocatable :: cell, expected
         integer :: start, comma, col, k
         logical :: good, numeric
         real(wp) :: x
         values = 0.0_wp
         ok = .true.
         header = .false.
         ! a first line whose time is not a number holds the column names
         ! (they may hold any text, "accel (m/s²)"); a typo further along a
         ! first row of numbers is an error
         if (may_be_header) then
            call read_real(trim(adjustl(column_text(text, 1))), x, numeric)
            if (.not. numeric) then
               header = .true.
               return
            end if
         end if
         do k = 1, len(text)
            if (iachar(text(k:k)) >= 32 .and. iachar(text(k:k)) <= 126) cycle
            call problem(line_no, 'byte '//itoa(iachar(text(k:k)))//' at character '//itoa(k)//' is not ' &
               //'printable ASCII; a pulse file is text: comma-separated numbers')
            ok = .false.
            return
         end do
         start = 1
         col = 0
         do
            comma = index(text(start:), ',')
            if (comma == 0) then
               cell = trim(adjustl(text(start:)))
            else
               cell = trim(adjustl(text(start:start + comma - 2)))
            end if
            col = col + 1
            if (col > n_columns) then
               call problem(line_no, 'expected at most '//itoa(n_columns)//' comma-separated columns (t, ' &
                  //'xddot, yddot, phiddot); found more')
               ok = .false.
               return
            end if
            k = col    ! column k is field k of *PULSE
            if (len(cell) == 0) then
               if (spec%field(k)%blank == blank_required) then
                  call problem(line_no, 'column '//itoa(col)//' ('//trim(spec%field(k)%name)//'): blank; ' &
                     //'it is required')
                  ok = .false.
               else
                  values(col) = spec%field(k)%default*spec%field(k)%scale
               end if
            else
               call convert_field_text(spec%field(k), cell, values(col), good, expected)
               if (.not. good) then
                  call problem(line_no, 'column '//itoa(col)//' ('//trim(spec%field(k)%name)//'): found "' &
                     //cell(1:min(len(cell), 40))//'"; expected '//expected)
                  ok = .false.
               end if
            end if
            if (comma == 0) exit
            start = start + comma
         end do
         if (col < 2) then
            call problem(line_no, 'expected 2 to 4 comma-separated columns (t, xddot[, yddot[, phiddot]]), ' &
               //'found '//itoa(col))
            ok = .false.
         end if
      end subroutine convert_row

      subroutine problem(line_no, message)
         integer, intent(in) :: line_no
         character(len=*), intent(in) :: message
         call error_append(err, exit_deck, name//':'//itoa(line_no)//': '//message)
      end subroutine problem

      !> The text of comma-separated column col of a row ('' beyond its last).
      function column_text(text, col) result(cell)
         character(len=*), intent(in) :: text
         integer, intent(in) :: col
         character(len=:), allocatable :: cell
         integer :: start, comma, k
         start = 1
         do k = 1, col - 1
            comma = index(text(start:), ',')
            if (comma == 0) then
               cell = ''
               return
            end if
            start = start + comma
         end do
         comma = index(text(start:), ',')
         if (comma == 0) then
            cell = text(start:)
         else
            cell = text(start:start + comma - 2)
         end if
      end function column_text
   end subroutine read_pulse_csv
end module pulse_csv
