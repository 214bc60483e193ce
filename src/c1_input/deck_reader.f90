!> Reads card decks (report C.1) into plain tables, checking every card and
!! field against the card table (deck_cards). Every problem found is
!! reported, each with file, line, card group, field, columns, the text found
!! and what was expected; nothing a deck holds can end in a runtime error.
!! Several sources may be read one after another: a later card group
!! replaces the earlier group of its kind (how a sweep swaps a pulse).
module deck_reader
   use kinds, only: wp
   use strings, only: itoa, num, upper, read_real, read_int
   use error_handling, only: error_t, error_append, exit_deck
   use text_io, only: string_t, read_text_file, append_string
   use deck_cards, only: group_spec_t, field_spec_t, card_table, max_fields, card_width, &
      index_first_col, index_last_col, data_last_col, field_first_col, field_last_col, &
      kind_real, kind_int, kind_word, kind_text, blank_default, blank_required, blank_absent, &
      layout_single, layout_indexed, layout_list, layout_multi, n_groups
   implicit none
   private

   public :: card_t, group_t, echo_line_t, deck_t
   public :: deck_init, deck_add_file, deck_add_lines, deck_finish
   public :: echo_comment, echo_header, echo_data, echo_blank, echo_bad
   public :: max_reported_errors

   !> Stop listing problems after this many (the count is still given).
   integer, parameter :: max_reported_errors = 200

   !> One data card, its fields converted to internal units.
   type :: card_t
      integer :: source = 0, line = 0
      integer :: index = 0                       !< row index (indexed groups)
      real(wp) :: value(max_fields) = 0.0_wp     !< reals, integers, word numbers
      logical :: given(max_fields) = .false.     !< the field was not blank
      character(len=:), allocatable :: text      !< the text field, if the group has one
   end type card_t

   !> One card group as read.
   type :: group_t
      logical :: present = .false.
      integer :: source = 0, line = 0            !< where its header card is
      integer :: n = 0
      type(card_t), allocatable :: card(:)
   end type group_t

   integer, parameter :: echo_blank = 0, echo_comment = 1, echo_header = 2, echo_data = 3, echo_bad = 4

   !> A line of a deck, kept for the echo in the listing and the HDF5 file.
   type :: echo_line_t
      integer :: source = 0, line = 0
      integer :: kind = echo_blank
      integer :: group = 0                       !< the group it belongs to (0: none)
      character(len=:), allocatable :: text
   end type echo_line_t

   !> The tables of a deck, built from one or more sources.
   type :: deck_t
      type(group_spec_t) :: spec(n_groups)
      type(string_t), allocatable :: source_name(:)
      type(string_t), allocatable :: source_dir(:)   !< for relative file names on cards
      type(echo_line_t), allocatable :: echo(:)
      integer :: n_echo = 0
      type(group_t) :: group(n_groups)
      integer :: n_errors = 0
   end type deck_t

contains

   !> Start an empty deck.
   subroutine deck_init(deck)
      type(deck_t), intent(out) :: deck
      deck%spec = card_table()
      allocate (deck%source_name(0), deck%source_dir(0), deck%echo(64))
   end subroutine deck_init

   !> Read and parse one deck file. An unreadable file is an I/O error;
   !! problems in its cards are deck errors (all of them are appended).
   subroutine deck_add_file(deck, path, err)
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(in) :: path
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: lines(:)
      type(error_t) :: io_err
      call read_text_file(path, lines, io_err)
      if (io_err%failed()) then
         call error_append(err, io_err%code, io_err%message)
         return
      end if
      call deck_add_lines(deck, path, directory_of(path), lines, err)
   end subroutine deck_add_file

   !> Parse one source already split into lines (a file, or the built-in deck).
   subroutine deck_add_lines(deck, name, directory, lines, err)
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(in) :: name, directory
      type(string_t), intent(in) :: lines(:)
      type(error_t), intent(inout) :: err
      integer :: src, i, gid, current, first_line(n_groups)
      character(len=:), allocatable :: text, word

      call append_string(deck%source_name, name)
      call append_string(deck%source_dir, directory)
      src = size(deck%source_name)
      current = 0
      first_line = 0
      if (size(lines) == 0) call report(deck, err, src, 0, 'the deck is empty')

      do i = 1, size(lines)
         text = lines(i)%s
         if (.not. card_is_clean(deck, err, src, i, text)) then
            call add_echo(deck, src, i, echo_bad, current, printable(text))
            cycle
         end if
         if (len_trim(text) == 0) then
            call add_echo(deck, src, i, echo_blank, 0, '')
         else if (text(1:1) == '$') then
            call add_echo(deck, src, i, echo_comment, 0, text)
         else if (text(1:1) == '*') then
            word = upper(first_word(text(2:)))
            gid = group_by_name(deck, word)
            call add_echo(deck, src, i, echo_header, gid, text)
            current = -1   ! cards up to the next valid header are not read
            if (gid == 0) then
               call report(deck, err, src, i, 'unknown card group "*'//word//'"; expected one of: ' &
                  //group_names(deck))
            else if (first_line(gid) > 0) then
               call report(deck, err, src, i, 'card group *'//trim(deck%spec(gid)%name) &
                  //' appears twice in this file (first at line '//itoa(first_line(gid))//')')
            else if (same_kind_in_file(deck, first_line, gid) > 0) then
               call report(deck, err, src, i, 'card group *'//trim(deck%spec(gid)%name) &
                  //' and *'//trim(deck%spec(same_kind_in_file(deck, first_line, gid))%name) &
                  //' give the same table; use one of them')
            else
               first_line(gid) = i
               call start_group(deck, gid, src, i)
               current = gid
            end if
         else if (current == 0) then
            call add_echo(deck, src, i, echo_data, 0, text)
            call report(deck, err, src, i, 'data card before any card group header; a header card '// &
               'has "*" in column 1 followed by the group name, e.g. *TIME')
         else if (current < 0) then
            call add_echo(deck, src, i, echo_data, 0, text)   ! under a rejected header
         else
            call add_echo(deck, src, i, echo_data, current, text)
            call parse_data_card(deck, err, current, src, i, text)
         end if
      end do
   end subroutine deck_add_lines

   !> Checks that need the whole deck: required groups, complete indexed
   !! groups, card counts. Call once after the last source.
   subroutine deck_finish(deck, err)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer :: gid, k, idx
      logical, allocatable :: seen(:)

      do gid = 1, n_groups
         associate (g => deck%group(gid), s => deck%spec(gid))
            if (.not. g%present) then
               if (s%required .and. .not. kind_present(deck, gid)) &
                  call report(deck, err, 0, 0, 'the deck has no *'//trim(s%name)//' card group (' &
                  //trim(s%title)//'); it is required')
               cycle
            end if
            if (g%n < s%min_cards) then
               call report(deck, err, g%source, g%line, '*'//trim(s%name)//' needs at least ' &
                  //itoa(s%min_cards)//' data card(s); found '//itoa(g%n))
            end if
            if (s%layout == layout_indexed) then
               allocate (seen(s%max_index), source=.false.)
               do k = 1, g%n
                  idx = g%card(k)%index
                  if (idx < 1) cycle
                  if (seen(idx)) then
                     call report(deck, err, g%card(k)%source, g%card(k)%line, '*'//trim(s%name) &
                        //': a second card for '//trim(s%index_name)//' = '//itoa(idx))
                  end if
                  seen(idx) = .true.
               end do
               if (s%all_rows) then
                  do idx = 1, s%max_index
                     if (.not. seen(idx)) call report(deck, err, g%source, g%line, '*'//trim(s%name) &
                        //': no card for '//trim(s%index_name)//' = '//itoa(idx)//' (one card for each of ' &
                        //'1 to '//itoa(s%max_index)//' is required)')
                  end do
               end if
               deallocate (seen)
            end if
         end associate
      end do
      if (deck%n_errors > max_reported_errors) then
         call error_append(err, exit_deck, '... and '//itoa(deck%n_errors - max_reported_errors) &
            //' more problems not listed')
      end if
      ! mark echo lines of groups that a later source replaced
      do k = 1, deck%n_echo
         associate (e => deck%echo(k))
            if (e%group > 0 .and. (e%kind == echo_header .or. e%kind == echo_data)) then
               if (.not. deck%group(e%group)%present) then
                  e%group = -e%group
               else if (deck%group(e%group)%source /= e%source) then
                  e%group = -e%group
               end if
            end if
         end associate
      end do
   end subroutine deck_finish

   ! --- card checks -----------------------------------------------------------

   !> A card must be printable ASCII without tabs and fit in 80 columns.
   logical function card_is_clean(deck, err, src, line, text) result(ok)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: src, line
      character(len=*), intent(in) :: text
      integer :: i, c
      ok = .true.
      do i = 1, len(text)
         c = iachar(text(i:i))
         if (c == 9) then
            call report(deck, err, src, line, 'tab character in column '//itoa(i) &
               //'; cards have fixed columns, use spaces')
            ok = .false.
            return
         else if (c < 32 .or. c > 126) then
            call report(deck, err, src, line, 'character that is not printable ASCII (code ' &
               //itoa(c)//') in column '//itoa(i)//'; is this a text deck?')
            ok = .false.
            return
         end if
      end do
      if (len_trim(text) > card_width) then
         call report(deck, err, src, line, 'card image of '//itoa(len_trim(text)) &
            //' columns; a card has at most '//itoa(card_width))
         ok = .false.
      end if
   end function card_is_clean

   !> Parse one data card of group gid into the group's table.
   subroutine parse_data_card(deck, err, gid, src, line, text)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: gid, src, line
      character(len=*), intent(in) :: text
      character(len=card_width) :: c
      type(card_t) :: card
      integer :: k, last_used
      logical :: ok
      character(len=:), allocatable :: where

      c = text
      card%source = src
      card%line = line
      associate (s => deck%spec(gid), g => deck%group(gid))
         where = '*'//trim(s%name)//' card '//itoa(g%n + 1)
         if (g%n >= s%max_cards) then
            call report(deck, err, src, line, where//': too many cards; *'//trim(s%name) &
               //' takes at most '//itoa(s%max_cards))
            return
         end if
         ok = .true.
         ! columns 1-2: the row index, or blank
         if (s%layout == layout_indexed .or. s%layout == layout_multi) then
            call parse_index(deck, err, s, where, src, line, c, card%index, ok)
         else if (s%field(1)%kind /= kind_text .and. len_trim(c(index_first_col:index_last_col)) > 0) then
            call report(deck, err, src, line, where//', columns 1-2: found "' &
               //c(index_first_col:index_last_col)//'"; they must be blank in *'//trim(s%name) &
               //' (is the card shifted?)')
            ok = .false.
         end if
         last_used = 0
         do k = 1, s%n_fields
            call parse_field(deck, err, s%field(k), where, src, line, c, card, k, ok)
            last_used = max(last_used, s%field(k)%last_col)
         end do
         if (last_used < data_last_col) then
            if (len_trim(c(last_used + 1:data_last_col)) > 0) then
               call report(deck, err, src, line, where//', columns '//itoa(last_used + 1)//'-' &
                  //itoa(data_last_col)//': found "'//trim(adjustl(c(last_used + 1:data_last_col))) &
                  //'"; *'//trim(s%name)//' has no field there (is the card shifted?)')
               ok = .false.
            end if
         end if
         ! a bad card is not stored; its errors are reported and the run stops
         if (ok) call append_card(g, card)
      end associate
   end subroutine parse_data_card

   subroutine parse_index(deck, err, s, where, src, line, c, idx, ok)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      type(group_spec_t), intent(in) :: s
      character(len=*), intent(in) :: where, c
      integer, intent(in) :: src, line
      integer, intent(out) :: idx
      logical, intent(inout) :: ok
      character(len=:), allocatable :: f
      logical :: good
      idx = 0
      f = trim(adjustl(c(index_first_col:index_last_col)))
      call read_int(f, idx, good)
      if (len(f) == 0) then
         call report(deck, err, src, line, where//', '//trim(s%index_name)//' (columns 1-2): blank; ' &
            //'expected an integer from 1 to '//itoa(s%max_index))
         ok = .false.
      else if (.not. good .or. idx < 1 .or. idx > s%max_index) then
         call report(deck, err, src, line, where//', '//trim(s%index_name)//' (columns 1-2): found "' &
            //f//'"; expected an integer from 1 to '//itoa(s%max_index))
         ok = .false.
         idx = 0
      end if
   end subroutine parse_index

   !> Parse field k of a card: blank handling, syntax, range; store it.
   subroutine parse_field(deck, err, f, where, src, line, c, card, k, ok)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      type(field_spec_t), intent(in) :: f
      character(len=*), intent(in) :: where, c
      integer, intent(in) :: src, line, k
      type(card_t), intent(inout) :: card
      logical, intent(inout) :: ok
      character(len=:), allocatable :: raw, head
      real(wp) :: x
      integer :: n, w
      logical :: good

      raw = trim(adjustl(c(f%first_col:f%last_col)))
      head = where//', field '//trim(f%name)//' (columns '//itoa(f%first_col)//'-'//itoa(f%last_col)//')'
      if (len(raw) == 0) then
         select case (f%blank)
         case (blank_required)
            call report(deck, err, src, line, head//': blank; expected '//expectation(f))
            ok = .false.
         case (blank_default)
            card%value(k) = f%default*f%scale
            if (f%kind == kind_text) card%text = ''
         case (blank_absent)
            card%value(k) = 0.0_wp
         end select
         return
      end if
      card%given(k) = .true.
      select case (f%kind)
      case (kind_text)
         card%text = trim(c(f%first_col:f%last_col))
      case (kind_word)
         w = word_number(f%words, upper(raw))
         if (w == 0) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//expectation(f))
            ok = .false.
         else
            card%value(k) = real(w, wp)
         end if
      case (kind_int)
         call read_int(raw, n, good)
         if (.not. good) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//expectation(f))
            ok = .false.
         else if (real(n, wp) < f%low .or. real(n, wp) > f%high) then
            call report(deck, err, src, line, head//': found '//raw//'; expected '//expectation(f))
            ok = .false.
         else
            card%value(k) = real(n, wp)
         end if
      case (kind_real)
         call read_real(raw, x, good)
         if (.not. good) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//expectation(f))
            ok = .false.
         else if (x < f%low .or. x > f%high .or. (f%low_open .and. .not. x > f%low)) then
            call report(deck, err, src, line, head//': found '//raw//'; expected '//expectation(f))
            ok = .false.
         else
            card%value(k) = x*f%scale
         end if
      end select
   end subroutine parse_field

   !> What a field accepts, in words, for error messages.
   function expectation(f) result(s)
      type(field_spec_t), intent(in) :: f
      character(len=:), allocatable :: s
      character(len=:), allocatable :: unit
      unit = ''
      if (f%unit /= '-' .and. f%unit /= ' ') unit = ' ('//trim(f%unit)//')'
      select case (f%kind)
      case (kind_text)
         s = 'text'
      case (kind_word)
         s = 'one of '//trim(f%words)
      case (kind_int)
         s = 'an integer from '//itoa(nint(f%low))//' to '//itoa(nint(f%high))
      case default
         if (f%low > -huge(1.0_wp) .and. f%high < huge(1.0_wp)) then
            if (f%low_open) then
               s = 'a number > '//num(f%low)//' and <= '//num(f%high)//unit
            else
               s = 'a number from '//num(f%low)//' to '//num(f%high)//unit
            end if
         else if (f%low > -huge(1.0_wp)) then
            if (f%low_open) then
               s = 'a number > '//num(f%low)//unit
            else
               s = 'a number >= '//num(f%low)//unit
            end if
         else
            s = 'a number'//unit
         end if
      end select
   end function expectation

   ! --- lexical helpers ---------------------------------------------------

   !> Position of word w in the '|'-separated list, or 0.
   pure integer function word_number(list, w)
      character(len=*), intent(in) :: list, w
      integer :: start, k, bar
      word_number = 0
      start = 1
      k = 0
      do
         k = k + 1
         bar = index(list(start:), '|')
         if (bar == 0) then
            if (trim(list(start:)) == w) word_number = k
            return
         end if
         if (list(start:start + bar - 2) == w) then
            word_number = k
            return
         end if
         start = start + bar
      end do
   end function word_number

   pure function first_word(s) result(w)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: w
      integer :: b
      w = trim(adjustl(s))
      b = index(w, ' ')
      if (b > 0) w = w(1:b - 1)
   end function first_word

   !> Show a bad line safely: non-printable bytes become '?'.
   pure function printable(s) result(p)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: p
      integer :: i, n
      n = min(len(s), card_width)
      allocate (character(len=n) :: p)
      do i = 1, n
         if (iachar(s(i:i)) < 32 .or. iachar(s(i:i)) > 126) then
            p(i:i) = '?'
         else
            p(i:i) = s(i:i)
         end if
      end do
   end function printable

   !> The directory part of a path ('' for none), for files named on cards.
   pure function directory_of(path) result(d)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: d
      integer :: slash
      slash = index(path, '/', back=.true.)
      if (slash == 0) then
         d = ''
      else
         d = path(1:slash)
      end if
   end function directory_of

   ! --- bookkeeping -------------------------------------------------------

   integer function group_by_name(deck, name)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      integer :: i
      group_by_name = 0
      do i = 1, n_groups
         if (deck%spec(i)%name == name) group_by_name = i
      end do
   end function group_by_name

   function group_names(deck) result(s)
      type(deck_t), intent(in) :: deck
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, n_groups
         s = s//'*'//trim(deck%spec(i)%name)
         if (i < n_groups) s = s//' '
      end do
   end function group_names

   !> Another group of the same kind already started in this source.
   integer function same_kind_in_file(deck, first_line, gid)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: first_line(:), gid
      integer :: j
      same_kind_in_file = 0
      do j = 1, n_groups
         if (j /= gid .and. first_line(j) > 0 .and. deck%spec(j)%kind == deck%spec(gid)%kind) &
            same_kind_in_file = j
      end do
   end function same_kind_in_file

   !> Some group of gid's kind is present (for required groups).
   logical function kind_present(deck, gid)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      integer :: j
      kind_present = .false.
      do j = 1, n_groups
         if (deck%group(j)%present .and. deck%spec(j)%kind == deck%spec(gid)%kind) kind_present = .true.
      end do
   end function kind_present

   !> A new group replaces any earlier group of its kind.
   subroutine start_group(deck, gid, src, line)
      type(deck_t), intent(inout) :: deck
      integer, intent(in) :: gid, src, line
      integer :: j
      do j = 1, n_groups
         if (deck%spec(j)%kind == deck%spec(gid)%kind) then
            deck%group(j)%present = .false.
            deck%group(j)%n = 0
         end if
      end do
      deck%group(gid)%present = .true.
      deck%group(gid)%source = src
      deck%group(gid)%line = line
      deck%group(gid)%n = 0
      if (.not. allocated(deck%group(gid)%card)) allocate (deck%group(gid)%card(8))
   end subroutine start_group

   subroutine append_card(g, card)
      type(group_t), intent(inout) :: g
      type(card_t), intent(in) :: card
      type(card_t), allocatable :: tmp(:)
      if (g%n == size(g%card)) then
         allocate (tmp(2*size(g%card)))
         tmp(1:g%n) = g%card(1:g%n)
         call move_alloc(tmp, g%card)
      end if
      g%n = g%n + 1
      g%card(g%n) = card
   end subroutine append_card

   subroutine add_echo(deck, src, line, kind, group, text)
      type(deck_t), intent(inout) :: deck
      integer, intent(in) :: src, line, kind, group
      character(len=*), intent(in) :: text
      type(echo_line_t), allocatable :: tmp(:)
      if (deck%n_echo == size(deck%echo)) then
         allocate (tmp(2*size(deck%echo)))
         tmp(1:deck%n_echo) = deck%echo(1:deck%n_echo)
         call move_alloc(tmp, deck%echo)
      end if
      deck%n_echo = deck%n_echo + 1
      deck%echo(deck%n_echo)%source = src
      deck%echo(deck%n_echo)%line = line
      deck%echo(deck%n_echo)%kind = kind
      deck%echo(deck%n_echo)%group = max(group, 0)
      deck%echo(deck%n_echo)%text = text
   end subroutine add_echo

   !> Append one problem, located as "file:line: message".
   subroutine report(deck, err, src, line, message)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: src, line
      character(len=*), intent(in) :: message
      character(len=:), allocatable :: loc
      deck%n_errors = deck%n_errors + 1
      if (deck%n_errors > max_reported_errors) return
      if (src > 0 .and. line > 0) then
         loc = deck%source_name(src)%s//':'//itoa(line)//': '
      else if (src > 0) then
         loc = deck%source_name(src)%s//': '
      else
         loc = 'deck: '
      end if
      call error_append(err, exit_deck, loc//message)
   end subroutine report

end module deck_reader
