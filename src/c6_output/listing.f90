!> A line-printer listing: 132 columns, pages of a fixed number of lines,
!! each page headed by the program, the run title, the section and the
!! page number. A form feed starts every page after the first. Nothing in
!! it depends on the clock, so the same run gives the same bytes.
!!
!! A listing is an output file (output_files): create it with
!! `create_text(path, 'listing', err)` ('' = standard output), `start` it,
!! write it, and end it with `commit` (or `deliver_outputs`) or `discard`.
!! Every write is checked; `flush` and `commit` report a failure.
module listing
   use strings, only: itoa
   use text_io, only: string_t
   use text_table, only: text_table_t
   use output_files, only: output_file_t
   implicit none
   private

   public :: listing_t, listing_width

   integer, parameter :: listing_width = 132

   type, extends(output_file_t) :: listing_t
      integer :: page = 0
      integer :: line = 0
      integer :: lines_per_page = 60
      character(len=72) :: title = ' '
      character(len=60) :: section = ' '
      character(len=24) :: program = ' '
   contains
      procedure :: start => listing_start
      procedure :: new_page => listing_new_page
      procedure :: put => listing_put
      procedure :: blank => listing_blank
      procedure :: heading => listing_heading
      procedure :: keep => listing_keep
      procedure :: table => listing_table
   end type listing_t

contains

   !> Begin the first page (the file is created already, by create_text).
   subroutine listing_start(this, program, title)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: program, title
      this%program = program
      this%title = title
      this%page = 0
      this%line = this%lines_per_page   ! the first put opens page 1
   end subroutine listing_start

   !> Start a new page for a new section.
   subroutine listing_new_page(this, section)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: section
      this%section = section
      call page_header(this)
   end subroutine listing_new_page

   subroutine page_header(this)
      class(listing_t), intent(inout) :: this
      character(len=listing_width) :: head
      character(len=:), allocatable :: pg
      this%page = this%page + 1
      pg = 'PAGE '//itoa(this%page)
      head = ' '
      head(1:) = this%program
      head(27:) = this%title
      head(listing_width - len(pg) + 1:) = pg
      if (this%page > 1) call emit(this, achar(12)//trim(head))
      if (this%page == 1) call emit(this, trim(head))
      call emit(this, trim(this%section))
      call emit(this, '')
      this%line = 3
   end subroutine page_header

   !> One line, opening a new page when the page is full. A text wider
   !! than the listing (132 columns) is wrapped, never cut off: broken at a
   !! blank in the second half of the line (or, where there is none, such as
   !! in a long path, at the last column), each continuation line indented
   !! by indent columns (default: the text's own indentation plus 4).
   subroutine listing_put(this, text, indent)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      integer, intent(in), optional :: indent
      integer :: n, start, cut, width, lead, cont, blank
      n = len_trim(text)
      if (n <= listing_width) then
         call put_one(this, text(1:n))
         return
      end if
      lead = max(0, verify(text, ' ') - 1)
      cont = lead + 4
      if (present(indent)) cont = indent
      cont = min(max(cont, 0), listing_width/2)
      start = 1
      width = listing_width
      do while (start <= n)
         if (start > 1) then
            start = start + verify(text(start:n), ' ') - 1   ! (no blanks at a continuation's start)
            width = listing_width - cont
         end if
         cut = n
         if (n - start + 1 > width) then
            cut = start + width - 1
            ! the last blank up to the column after a full line, if it leaves
            ! at least half a line here
            blank = index(text(start:cut + 1), ' ', back=.true.)
            if (blank > width/2) cut = start + blank - 2
         end if
         if (start == 1) then
            call put_one(this, text(1:cut))
         else
            call put_one(this, repeat(' ', cont)//text(start:cut))
         end if
         start = cut + 1
      end do
   end subroutine listing_put

   subroutine put_one(this, text)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      if (this%line >= this%lines_per_page) call page_header(this)
      call emit(this, trim(text))
      this%line = this%line + 1
   end subroutine put_one

   subroutine listing_blank(this)
      class(listing_t), intent(inout) :: this
      if (this%line > 3) call this%put('')
   end subroutine listing_blank

   !> A heading with at least min_lines lines of room below it.
   subroutine listing_heading(this, text, min_lines)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      integer, intent(in) :: min_lines
      call this%keep(min_lines + 3)
      call this%blank()
      call this%put(' '//text)
      call this%put(' '//repeat('-', len_trim(text)))
   end subroutine listing_heading

   !> Any table (text_table: each subsystem declares its parameter table
   !! so): its title as a heading, kept on one page with its first lines
   !! (keep_lines), then its lines; nothing for a table without lines.
   subroutine listing_table(this, t)
      class(listing_t), intent(inout) :: this
      type(text_table_t), intent(in) :: t
      type(string_t), allocatable :: lines(:)
      integer :: i
      allocate (lines(0))   ! (gfortran 12 -Wuninitialized: the assignment reads the descriptor)
      lines = t%lines()
      if (size(lines) == 0) return
      call this%heading(t%title, t%keep_lines())
      do i = 1, size(lines)
         call this%put(lines(i)%s)
      end do
   end subroutine listing_table

   !> Open a new page unless n more lines fit on this one.
   subroutine listing_keep(this, n)
      class(listing_t), intent(inout) :: this
      integer, intent(in) :: n
      if (this%line + n > this%lines_per_page) call page_header(this)
   end subroutine listing_keep

   subroutine emit(this, text)
      class(listing_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      call this%put_line(text)
   end subroutine emit
end module listing
