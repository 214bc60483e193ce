!> A line-printer table as data: a title, columns (heading, unit, width,
!! form of its numbers), rows filled cell by cell through the columns'
!! forms, and free lines among or after the rows. Any layer declares its
!! tables with it (each subsystem its parameter table, docs/architecture.md,
!! "How to add an effect"); the listing prints any of them the same way
!! (listing_t%table: the title as a heading, then `lines`).
!!
!! A column spans `width` columns of the line, after the columns before
!! it. Its heading, its unit and the text of its cells start `lead`
!! columns into it; numbers (and text in a numeric column) end at its last
!! column, written in its whole width by the column's edit (ES, F through
!! number_format's `fixed`, never asterisks; integers by `right_int`). A
!! cell wider than its column pushes the cells after it to the right, as
!! concatenated fields would. A mark (a footnote's letter) may follow a
!! cell, in the columns after it.
module text_table
   use kinds, only: wp
   use text_io, only: string_t, append_string
   use number_format, only: fixed, right_int
   implicit none
   private

   public :: text_table_t, new_table, append_table, cell_text, cell_int, cell_es, cell_fixed

   !> Forms of a column's cells: text, integers, ES and F editing of reals.
   integer, parameter :: cell_text = 1, cell_int = 2, cell_es = 3, cell_fixed = 4
   !> The longest row a table builds; the most columns it has.
   integer, parameter :: row_len = 200, max_columns = 16

   type :: table_column_t
      character(len=32) :: name = ' '
      character(len=16) :: unit = ' '
      integer :: first = 1          !< its first column in the line
      integer :: width = 12
      integer :: lead = 2           !< where its heading, unit and text start, past first
      integer :: form = cell_es
      integer :: decimals = 4
      logical :: head_right = .false.  !< heading and unit end at its last column, as its numbers
      character(len=16) :: edit = ' '  !< its ES edit descriptor, built once
   end type table_column_t

   type :: text_table_t
      character(len=:), allocatable :: title
      !> lines that must fit below the title on its page (the listing's
      !! heading); 0: the whole table
      integer :: keep = 0
      integer :: n_col = 0
      type(table_column_t) :: col(max_columns)
      type(string_t), allocatable :: body(:)   !< the rows and free lines, in order
      integer :: next = 1           !< the next cell of the last row
      integer :: shift = 0          !< how far a wide cell pushed the last row's cells
      integer :: last = 0           !< the last row's last column written
   contains
      procedure :: add_column => table_add_column
      procedure :: new_row => table_new_row
      procedure, private :: put_real => table_put_real
      procedure, private :: put_int => table_put_int
      procedure, private :: put_text => table_put_text
      generic :: put => put_real, put_int, put_text
      procedure :: skip => table_skip
      procedure :: add_line => table_add_line
      procedure :: lines => table_lines
      procedure :: keep_lines => table_keep_lines
   end type text_table_t

contains

   !> An empty table with this title; keep: see text_table_t.
   function new_table(title, keep) result(t)
      character(len=*), intent(in) :: title
      integer, intent(in), optional :: keep
      type(text_table_t) :: t
      t%title = title
      if (present(keep)) t%keep = keep
      allocate (t%body(0))
   end function new_table

   !> A column after the others (at most 16): its heading (up to 32
   !! characters), width and form (default ES with 4 decimals); its unit (a
   !! second heading line when any column has one), lead (2) and heading
   !! alignment.
   subroutine table_add_column(this, name, width, form, decimals, unit, lead, head_right)
      class(text_table_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: width
      integer, intent(in), optional :: form, decimals, lead
      character(len=*), intent(in), optional :: unit
      logical, intent(in), optional :: head_right
      type(table_column_t) :: c
      c%name = name
      c%width = width
      if (present(unit)) c%unit = unit
      if (present(form)) c%form = form
      if (present(decimals)) c%decimals = decimals
      if (present(lead)) c%lead = lead
      if (present(head_right)) c%head_right = head_right
      if (this%n_col > 0) c%first = this%col(this%n_col)%first + this%col(this%n_col)%width
      c%edit = es_edit(c%width, c%decimals)
      this%n_col = this%n_col + 1
      this%col(this%n_col) = c
   end subroutine table_add_column

   !> Start a row; its cells follow with put (or skip), column by column.
   pure subroutine table_new_row(this)
      class(text_table_t), intent(inout) :: this
      call append_string(this%body, '')
      this%next = 1
      this%shift = 0
      this%last = 0
   end subroutine table_new_row

   !> A real in the next cell, in the column's form (or form, decimals
   !! given here), a mark after it.
   subroutine table_put_real(this, x, form, decimals, mark)
      class(text_table_t), intent(inout) :: this
      real(wp), intent(in) :: x
      integer, intent(in), optional :: form, decimals
      character(len=*), intent(in), optional :: mark
      character(len=64) :: buf
      integer :: f, d
      associate (c => this%col(this%next))
         f = c%form
         d = c%decimals
         if (present(form)) f = form
         if (present(decimals)) d = decimals
         if (f == cell_fixed) then
            call place(this, fixed(x, c%width, d), .true., mark)
         else if (d == c%decimals) then
            write (buf, c%edit) x
            call place(this, buf(1:c%width), .true., mark)
         else
            write (buf, es_edit(c%width, d)) x
            call place(this, buf(1:c%width), .true., mark)
         end if
      end associate
   end subroutine table_put_real

   !> An integer in the next cell, right-aligned.
   subroutine table_put_int(this, n, mark)
      class(text_table_t), intent(inout) :: this
      integer, intent(in) :: n
      character(len=*), intent(in), optional :: mark
      call place(this, right_int(n, this%col(this%next)%width), .true., mark)
   end subroutine table_put_int

   !> Text in the next cell: from the column's lead in a text column; in a
   !! numeric column, or when right is true, ending at its last column.
   subroutine table_put_text(this, text, right, mark)
      class(text_table_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      logical, intent(in), optional :: right
      character(len=*), intent(in), optional :: mark
      logical :: r
      r = this%col(this%next)%form /= cell_text
      if (present(right)) r = right
      call place(this, text, r, mark)
   end subroutine table_put_text

   !> Leave the next cell blank.
   pure subroutine table_skip(this)
      class(text_table_t), intent(inout) :: this
      this%next = this%next + 1
   end subroutine table_skip

   !> A line of its own (under the rows, or between them).
   pure subroutine table_add_line(this, text)
      class(text_table_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      call append_string(this%body, text)
   end subroutine table_add_line

   !> The table's lines: the headings (and units) when it has columns, then
   !! its rows and lines; none when it has neither columns nor lines (a
   !! subsystem the deck leaves out declares no table).
   function table_lines(this) result(lines)
      class(text_table_t), intent(in) :: this
      type(string_t), allocatable :: lines(:)
      character(len=row_len) :: names, units
      integer :: k
      allocate (lines(0))
      if (this%n_col == 0 .and. size(this%body) == 0) return
      if (this%n_col > 0) then
         names = ' '
         units = ' '
         do k = 1, this%n_col
            call put_heading(names, this%col(k), this%col(k)%name)
            call put_heading(units, this%col(k), this%col(k)%unit)
         end do
         call append_string(lines, trim(names))
         if (len_trim(units) > 0) call append_string(lines, trim(units))
      end if
      do k = 1, size(this%body)
         call append_string(lines, this%body(k)%s)
      end do
   end function table_lines

   !> The lines to keep with the title: keep, or all of them.
   integer function table_keep_lines(this) result(n)
      class(text_table_t), intent(in) :: this
      type(string_t), allocatable :: lines(:)
      n = this%keep
      if (n > 0) return
      lines = this%lines()
      n = size(lines)
   end function table_keep_lines

   !> text into the last row's next cell: right-aligned (ending at the
   !! column's last column, pushed right by the cells before it when they
   !! were wider than theirs) or from the column's lead, cut at its end (as
   !! an A edit descriptor would); mark after it. Only the text's nonblank
   !! part is written: its leading blanks leave a mark before it standing.
   subroutine place(this, text, right, mark)
      class(text_table_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      logical, intent(in) :: right
      character(len=*), intent(in), optional :: mark
      character(len=row_len) :: row
      integer :: start, first, finish, lead_blanks
      associate (c => this%col(this%next), n => size(this%body))
         if (right) then
            start = c%first + c%width - len(text) + this%shift
            finish = start + len(text) - 1
         else
            start = c%first + c%lead + this%shift
            finish = min(start + len(text), c%first + c%width + this%shift) - 1
         end if
         lead_blanks = max(verify(text, ' '), 1) - 1
         first = start + lead_blanks
         ! a cell's text may begin only after what the row holds (a wide cell
         ! before it; the row's first column)
         if (first <= this%last .and. len_trim(text) > 0) then
            this%shift = this%shift + this%last - first + 1
            finish = finish + this%last - first + 1
            start = start + this%last - first + 1
            first = this%last + 1
         end if
         row = this%body(n)%s
         if (finish >= first) row(first:finish) = text(lead_blanks + 1:lead_blanks + 1 + finish - first)
         if (len_trim(text) > 0) this%last = max(this%last, start + len_trim(text(1:finish - start + 1)) - 1)
         if (present(mark)) then
            row(finish + 1:finish + len(mark)) = mark
            this%last = max(this%last, finish + len_trim(mark))
         end if
         this%body(n)%s = trim(row)
      end associate
      this%next = this%next + 1
   end subroutine place

   !> A heading or unit text in its column's place on a heading line.
   pure subroutine put_heading(line, c, text)
      character(len=*), intent(inout) :: line
      type(table_column_t), intent(in) :: c
      character(len=*), intent(in) :: text
      integer :: start
      if (len_trim(text) == 0) return
      start = c%first + c%lead
      if (c%head_right) start = c%first + c%width - len_trim(text)
      line(start:start + len_trim(text) - 1) = trim(text)
   end subroutine put_heading

   !> Add t to the end of a list of tables (by hand: an array constructor of
   !! values with allocatable components leaks in gfortran 12).
   subroutine append_table(list, t)
      type(text_table_t), allocatable, intent(inout) :: list(:)
      type(text_table_t), intent(in) :: t
      type(text_table_t), allocatable :: longer(:)
      allocate (longer(size(list) + 1))
      longer(1:size(list)) = list
      longer(size(longer)) = t
      call move_alloc(longer, list)
   end subroutine append_table

   !> "(ESw.d)"
   pure function es_edit(w, d) result(edit)
      integer, intent(in) :: w, d
      character(len=16) :: edit
      write (edit, '(a,i0,a,i0,a)') '(es', w, '.', d, ')'
   end function es_edit
end module text_table
