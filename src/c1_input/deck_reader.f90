!> Reads card decks (report C.1) into plain tables, checking every card and
!! field against the card table (deck_cards). Every problem found is
!! reported, each with file, line, card group, field, columns, the text found
!! and what was expected; nothing a deck holds can end in a runtime error.
!! Several sources may be read one after another: a later card group
!! replaces the earlier group of its kind (how a sweep swaps a pulse).
module deck_reader
   use kinds, only: wp
   use strings, only: itoa, num, upper, read_real, read_int, escaped
   use error_handling, only: error_t, error_append, exit_deck
   use text_io, only: string_t, read_text_file, read_standard_input, append_string, &
      standard_input_path, standard_input_name
   use posix_files, only: file_info_t, posix_file_info, kind_regular
   use field_values, only: field_expectation, word_position
   use deck_cards, only: group_spec_t, field_spec_t, card_table, max_fields, card_width, &
      index_first_col, index_last_col, data_last_col, field_first_col, field_last_col, &
      kind_real, kind_int, kind_word, kind_text, blank_default, blank_required, blank_absent, &
      layout_single, layout_indexed, layout_list, layout_multi, n_groups, g_analog, g_title, g_study, g_vary, &
      g_values, g_criteria
   implicit none
   private

   public :: card_t, group_t, echo_line_t, deck_t
   public :: deck_init, deck_add_file, deck_add_lines, deck_finish
   public :: echo_comment, echo_header, echo_data, echo_blank, echo_bad
   public :: max_reported_errors, deck_names
   public :: deck_field_address, deck_set_field, field_text

   !> Stop listing problems after this many (the count is still given).
   integer, parameter :: max_reported_errors = 200

   !> One data card, its fields converted to internal units.
   type :: card_t
      integer :: source = 0, line = 0
      integer :: group = 0                       !< its group in the card table (0: none, a header)
      integer :: number = 0                      !< its number in the group, as written (bad cards counted)
      integer :: index = 0                       !< row index (indexed groups)
      real(wp) :: value(max_fields) = 0.0_wp     !< reals, integers, word numbers
      logical :: given(max_fields) = .false.     !< the field was not blank
      character(len=:), allocatable :: text      !< the text field, if the group has one
   end type card_t

   !> One card group as read. card(1:n) holds the cards that were read
   !! without error; cards with errors are reported and only remembered for
   !! the checks of the whole group (so that they do not also count as
   !! missing, and card numbers count them).
   type :: group_t
      logical :: present = .false.
      integer :: source = 0, line = 0            !< where its header card is
      integer :: n = 0
      type(card_t), allocatable :: card(:)
      integer :: n_written = 0                   !< data cards as written, bad ones included
      integer :: n_rejected = 0                  !< data cards with errors
      integer, allocatable :: rejected_line(:)   !< their lines
      integer, allocatable :: rejected_index(:)  !< their row index (0: not readable)
   end type group_t

   integer, parameter :: echo_blank = 0, echo_comment = 1, echo_header = 2, echo_data = 3, echo_bad = 4

   !> A line of a deck, kept for the echo in the listing and the HDF5 file.
   type :: echo_line_t
      integer :: source = 0, line = 0
      integer :: kind = echo_blank
      integer :: group = 0                       !< the group it belongs to (0: none)
      character(len=:), allocatable :: text      !< at most card_width bytes (see echo_text)
      logical :: varied = .false.                !< a field set by deck_set_field (C.8)
   end type echo_line_t

   !> The tables of a deck, built from one or more sources.
   type :: deck_t
      type(group_spec_t), allocatable :: spec(:)   !< the card table (large: not on the stack)
      type(string_t), allocatable :: source_name(:)
      type(string_t), allocatable :: source_dir(:)   !< for relative file names on cards
      type(echo_line_t), allocatable :: echo(:)
      integer :: n_echo = 0
      type(group_t) :: group(n_groups)
      integer :: n_errors = 0
      type(string_t), allocatable :: warnings(:)   !< located, for the model's warnings
      !> a header card of the group was refused for its characters (a tab,
      !! ...): the group is not reported missing as well
      logical :: header_rejected(n_groups) = .false.
      !> such a header whose group could not be told: no group is reported missing
      logical :: unknown_header_rejected = .false.
   end type deck_t

contains

   !> Start an empty deck.
   subroutine deck_init(deck)
      type(deck_t), intent(out) :: deck
      deck%spec = card_table()
      allocate (deck%source_name(0), deck%source_dir(0), deck%echo(64), deck%warnings(0))
   end subroutine deck_init

   !> Read and parse one deck file; the path standard_input_path ('-') reads
   !! standard input, named standard_input_name in messages. Files named on
   !! cards (*PULSEFILE) are relative to the deck's directory when the deck
   !! is a regular file (or a link to one), else - standard input, a pipe, a
   !! FIFO, a process substitution's /dev/fd/N - to the current directory
   !! (/dev/fd/ holds no pulse file). An unreadable file is an I/O error;
   !! problems in its cards are deck errors (all of them are appended).
   subroutine deck_add_file(deck, path, err)
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(in) :: path
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: lines(:)
      type(error_t) :: io_err
      type(file_info_t) :: info
      logical :: from_stdin, regular
      from_stdin = path == standard_input_path .and. len(path) == len(standard_input_path)
      regular = .false.
      if (.not. from_stdin) regular = posix_file_info(path, info) == 0 .and. info%kind == kind_regular
      if (from_stdin) then
         call read_standard_input(lines, io_err)
      else
         call read_text_file(path, lines, io_err)
      end if
      if (io_err%failed()) then
         call error_append(err, io_err%code, io_err%message)
         return
      end if
      if (from_stdin) then
         call deck_add_lines(deck, standard_input_name, '', lines, err)
      else if (regular) then
         call deck_add_lines(deck, path, directory_of(path), lines, err)
      else
         call deck_add_lines(deck, path, '', lines, err)
      end if
   end subroutine deck_add_file

   !> Parse one source already split into lines (a file, or the built-in deck).
   subroutine deck_add_lines(deck, name, directory, lines, err)
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(in) :: name, directory
      type(string_t), intent(in) :: lines(:)
      type(error_t), intent(inout) :: err
      integer :: src, i, gid, current, first_line(n_groups)
      character(len=:), allocatable :: text, word

      ! one line in messages and the echo, and never empty
      if (len(name) == 0) then
         call append_string(deck%source_name, '(unnamed deck)')
      else
         call append_string(deck%source_name, escaped(name))
      end if
      call append_string(deck%source_dir, directory)
      src = size(deck%source_name)
      current = 0
      first_line = 0
      if (size(lines) == 0) call report(deck, err, src, 0, 'the deck is empty')

      do i = 1, size(lines)
         text = lines(i)%s
         if (.not. card_is_clean(deck, err, src, i, text, bad_card_place(deck, current, text))) then
            call add_echo(deck, src, i, echo_bad, current, printable(text))
            if (text(1:1) == '*') then
               ! a header refused for its characters: its group is not read,
               ! and not reported missing as well
               gid = group_by_name(deck, upper(leading_name(text(2:))))
               if (gid > 0) then
                  deck%header_rejected(gid) = .true.
               else
                  deck%unknown_header_rejected = .true.
               end if
               current = -1
            else if (text(1:1) /= '$' .and. current > 0) then
               ! a data card refused for its characters is a bad card of its
               ! group: counted, and not reported missing as well
               call count_bad_card(deck%group(current), deck%spec(current), i, text)
            end if
            cycle
         end if
         if (len_trim(text) == 0) then
            call add_echo(deck, src, i, echo_blank, 0, '')
         else if (text(1:1) == '$') then
            call add_echo(deck, src, i, echo_comment, 0, echo_text(text))
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
                  //' (line '//itoa(first_line(same_kind_in_file(deck, first_line, gid)))//') give the same ' &
                  //'table; use one of them')
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
      integer :: gid, k
      logical :: analog

      ! Section D's analog is a deck of its own: *TITLE and *ANALOG alone, and
      ! a study's groups (C.8: a study of the analog, docs/analog.md)
      analog = deck%group(g_analog)%present .or. deck%header_rejected(g_analog)
      do gid = 1, n_groups
         if (analog .and. deck%group(gid)%present .and. .not. any(gid == [g_analog, g_title, g_study, g_vary, &
                                                                            g_values, g_criteria])) &
            call report(deck, err, deck%group(gid)%source, deck%group(gid)%line, 'card group *' &
            //trim(deck%spec(gid)%name)//' in a deck with *ANALOG (line '//itoa(deck%group(g_analog)%line) &
            //' of '//deck%source_name(deck%group(g_analog)%source)%s//'): an analog deck (report Section D, ' &
            //'docs/analog.md) holds *TITLE and *ANALOG only, and a study''s *STUDY, *VARY, *VALUES and *CRITERIA')
      end do
      do gid = 1, n_groups
         associate (g => deck%group(gid), s => deck%spec(gid))
            if (.not. g%present) then
               ! (when no source held a line, "the deck is empty" says it all;
               ! an analog deck needs none of the occupant's groups)
               if (s%required .and. .not. analog .and. .not. kind_present(deck, gid) .and. deck%n_echo > 0 .and. .not. &
                   (deck%header_rejected(gid) .or. deck%unknown_header_rejected)) &
                  call report(deck, err, 0, 0, 'the deck has no *'//trim(s%name)//' card group (' &
                  //trim(s%title)//'); it is required')
               cycle
            end if
            if (g%n_written == 0 .and. blank_card_allowed(s)) then
               ! blank cards are skipped, so a header alone is the blank card
               ! ("blank means empty" for *TITLE)
               call append_card(g, blank_card(s, g%source, g%line))
            else if (g%n_written < s%min_cards .and. .not. (s%layout == layout_indexed .and. s%all_rows)) then
               ! bad cards count as written: their own errors say what is wrong
               ! (a group that needs every row says which are missing, below)
               call report(deck, err, g%source, g%line, '*'//trim(s%name)//' needs at least ' &
                  //itoa(s%min_cards)//' data card(s); found '//itoa(g%n_written))
            end if
            if (s%layout == layout_indexed) call check_rows(deck, err, g, s)
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

   !> An indexed group: no row twice, and every row where all are required.
   !! A card rejected for another field still holds its row. A card whose
   !! index could not be read may be any missing row, so missing rows are
   !! reported only when there are more of them than such cards (otherwise
   !! the index errors already say all there is).
   subroutine check_rows(deck, err, g, s)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      type(group_t), intent(in) :: g
      type(group_spec_t), intent(in) :: s
      logical :: seen(s%max_index), take_good
      integer :: good, bad, idx, line, n_unreadable, first_line(s%max_index), n_missing
      character(len=:), allocatable :: missing

      seen = .false.
      first_line = 0
      good = 1
      bad = 1
      ! good and rejected cards merged in the order of their lines
      do while (good <= g%n .or. bad <= g%n_rejected)
         if (bad > g%n_rejected) then
            take_good = .true.
         else if (good > g%n) then
            take_good = .false.
         else
            take_good = g%card(good)%line < g%rejected_line(bad)
         end if
         if (take_good) then
            idx = g%card(good)%index
            line = g%card(good)%line
            good = good + 1
         else
            idx = g%rejected_index(bad)
            line = g%rejected_line(bad)
            bad = bad + 1
         end if
         if (idx < 1 .or. idx > s%max_index) cycle
         if (seen(idx)) then
            call report(deck, err, g%source, line, '*'//trim(s%name)//', '//trim(s%index_name) &
               //' (columns 1-2): a second card for '//trim(s%index_name)//' = '//itoa(idx)//'; the first is at line ' &
               //itoa(first_line(idx)))
         else
            first_line(idx) = line
         end if
         seen(idx) = .true.
      end do
      if (.not. s%all_rows) return
      n_unreadable = count(g%rejected_index(1:g%n_rejected) < 1)
      if (count(.not. seen) <= n_unreadable) return
      ! the rows missing, in one message
      missing = ''
      n_missing = 0
      do idx = 1, s%max_index
         if (.not. seen(idx)) call add_to_list(missing, n_missing, itoa(idx))
      end do
      call report(deck, err, g%source, g%line, '*'//trim(s%name)//', '//trim(s%index_name) &
         //' (columns 1-2): '//trim(merge('no card  ', 'no cards ', n_missing == 1))//' for '//trim(s%index_name) &
         //' = '//missing//' (one card for each of 1 to '//itoa(s%max_index)//' is required)')
   end subroutine check_rows

   !> A single card holding only a text field that may be blank (*TITLE):
   !! its blank card cannot be told from the blank cards that are skipped.
   pure logical function blank_card_allowed(s)
      type(group_spec_t), intent(in) :: s
      blank_card_allowed = s%layout == layout_single .and. s%n_fields == 1
      if (blank_card_allowed) blank_card_allowed = s%field(1)%kind == kind_text &
         .and. s%field(1)%blank == blank_default
   end function blank_card_allowed

   !> The card a blank card image gives: every field its blank value.
   pure function blank_card(s, src, line) result(card)
      type(group_spec_t), intent(in) :: s
      integer, intent(in) :: src, line
      type(card_t) :: card
      integer :: k
      card%source = src
      card%line = line
      do k = 1, s%n_fields
         if (s%field(k)%blank == blank_default) card%value(k) = s%field(k)%default*s%field(k)%scale
         if (s%field(k)%kind == kind_text) card%text = ''
      end do
   end function blank_card

   ! --- card checks -----------------------------------------------------------

   !> A card holds printable ASCII without tabs in at most 80 columns. A
   !! comment card ($ in column 1) may also hold UTF-8 text; its columns are
   !! counted in characters. A problem is reported after `place` (the
   !! group and card number of a data card, '' for other lines).
   logical function card_is_clean(deck, err, src, line, text, place) result(ok)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: src, line
      character(len=*), intent(in) :: text, place
      integer :: i, c, column, n_bytes, code_point, width
      logical :: comment

      ok = .false.
      comment = .false.
      if (len(text) > 0) comment = text(1:1) == '$'
      i = 1
      column = 0
      do while (i <= len(text))
         column = column + 1
         c = iachar(text(i:i))
         n_bytes = 1
         if (c == 9) then
            call report(deck, err, src, line, place//'tab character in column '//itoa(column) &
               //'; cards have fixed columns, use spaces')
            return
         else if (c < 32 .or. c == 127) then
            call report(deck, err, src, line, place//'control character (code '//itoa(c)//') in column ' &
               //itoa(column)//'; is this a text deck?')
            return
         else if (c > 127) then
            call utf8_character(text(i:), n_bytes, code_point)
            if (n_bytes == 0) then
               call report(deck, err, src, line, place//'byte '//itoa(c)//' in column '//itoa(column) &
                  //' is not part of a UTF-8 character (nor printable ASCII); is this a text deck?')
               return
            else if (.not. comment) then
               call report(deck, err, src, line, place//'non-ASCII character "'//text(i:i + n_bytes - 1) &
                  //'" in column '//itoa(column)//'; only comment cards ($ in column 1) may hold ' &
                  //'non-ASCII text, data and header cards are ASCII')
               return
            else if (code_point < 160) then
               call report(deck, err, src, line, place//'control character (U+00'//hex_byte(code_point) &
                  //') in column '//itoa(column)//'; is this a text deck?')
               return
            end if
         end if
         i = i + n_bytes
      end do
      ! every byte but the continuation bytes of UTF-8 starts a character
      width = 0
      do i = 1, len_trim(text)
         c = iachar(text(i:i))
         if (c < 128 .or. c >= 192) width = width + 1
      end do
      if (width > card_width) then
         call report(deck, err, src, line, place//'card image of '//itoa(width) &
            //' columns; a card has at most '//itoa(card_width))
         return
      end if
      ok = .true.
   end function card_is_clean

   !> Where a line refused for its characters is, for its message: the
   !! group and number it would have as a data card of the group being read
   !! ("*TIME card 2: "), a header card (of its group when its name can be
   !! read) or a comment card; nothing for a line outside any group.
   function bad_card_place(deck, current, text) result(place)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: current
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: place
      integer :: gid
      place = ''
      if (len(text) == 0) return
      if (text(1:1) == '$') then
         place = 'comment card: '
      else if (text(1:1) == '*') then
         gid = group_by_name(deck, upper(leading_name(text(2:))))
         place = 'header card: '
         if (gid > 0) place = 'header card of *'//trim(deck%spec(gid)%name)//': '
      else if (current > 0) then
         place = '*'//trim(deck%spec(current)%name)//' card '//itoa(deck%group(current)%n_written + 1)//': '
      end if
   end function bad_card_place

   !> A data card refused for its characters: counted as written and as
   !! rejected, with its row index when columns 1-2 hold a valid one, so
   !! that its group's checks do not also report it missing.
   subroutine count_bad_card(g, s, line, text)
      type(group_t), intent(inout) :: g
      type(group_spec_t), intent(in) :: s
      integer, intent(in) :: line
      character(len=*), intent(in) :: text
      character(len=index_last_col) :: columns
      integer :: row
      logical :: good
      g%n_written = g%n_written + 1
      if (g%n_written > s%max_cards) return
      row = 0
      if (s%layout == layout_indexed .or. s%layout == layout_multi) then
         columns = text
         call read_int(trim(adjustl(printable(columns))), row, good)
         if (.not. good .or. row < 1 .or. row > s%max_index) row = 0
      end if
      call note_rejected(g, line, row)
   end subroutine count_bad_card

   !> The UTF-8 character starting s (whose first byte is not ASCII): its
   !! length in bytes and its code point; n_bytes = 0 when s does not start
   !! with a well-formed UTF-8 character (RFC 3629: no overlong forms, no
   !! surrogates, nothing beyond U+10FFFF).
   pure subroutine utf8_character(s, n_bytes, code_point)
      character(len=*), intent(in) :: s
      integer, intent(out) :: n_bytes, code_point
      integer :: lead, low, high, k, b

      n_bytes = 0
      code_point = 0
      lead = iachar(s(1:1))
      low = 128
      high = 191
      select case (lead)
      case (194:223)
         n_bytes = 2
         code_point = lead - 192
      case (224:239)
         n_bytes = 3
         code_point = lead - 224
         if (lead == 224) low = 160    ! no overlong forms
         if (lead == 237) high = 159   ! no surrogates
      case (240:244)
         n_bytes = 4
         code_point = lead - 240
         if (lead == 240) low = 144    ! no overlong forms
         if (lead == 244) high = 143   ! nothing beyond U+10FFFF
      case default
         return
      end select
      if (len(s) < n_bytes) then
         n_bytes = 0
         return
      end if
      do k = 2, n_bytes
         b = iachar(s(k:k))
         if (k > 2) then
            low = 128
            high = 191
         end if
         if (b < low .or. b > high) then
            n_bytes = 0
            return
         end if
         code_point = 64*code_point + (b - 128)
      end do
   end subroutine utf8_character

   !> Two hexadecimal digits of a byte value, for U+00XX.
   pure function hex_byte(value) result(h)
      integer, intent(in) :: value
      character(len=2) :: h
      character(len=*), parameter :: digits = '0123456789ABCDEF'
      h = digits(value/16 + 1:value/16 + 1)//digits(mod(value, 16) + 1:mod(value, 16) + 1)
   end function hex_byte

   !> Parse one data card of group gid into the group's table.
   subroutine parse_data_card(deck, err, gid, src, line, text)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: gid, src, line
      character(len=*), intent(in) :: text
      character(len=card_width) :: c
      type(card_t) :: card
      integer :: k, last_used
      logical :: ok, in_run(max_fields), tail_in_run
      character(len=:), allocatable :: where

      c = text
      card%source = src
      card%line = line
      card%group = gid
      associate (s => deck%spec(gid), g => deck%group(gid))
         ! cards are numbered as written, bad ones included
         g%n_written = g%n_written + 1
         card%number = g%n_written
         where = '*'//trim(s%name)//' card '//itoa(g%n_written)
         if (g%n_written > s%max_cards) then
            ! reported once, at the first card too many (docs/deck-format.md)
            if (g%n_written == s%max_cards + 1) call report(deck, err, src, line, where//': too many cards; *' &
               //trim(s%name)//' takes at most '//itoa(s%max_cards)//' (docs/deck-format.md): this card ' &
               //'and every later card of the group are left out')
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
            last_used = max(last_used, s%field(k)%last_col)
         end do
         call check_runs_across(deck, err, s, where, src, line, c, last_used, in_run, tail_in_run, ok)
         do k = 1, s%n_fields
            if (in_run(k)) cycle   ! reported as a whole
            call parse_field(deck, err, s%field(k), where, src, line, c, card, k, ok)
         end do
         if (ok) call warn_run_into_id(deck, s, where, src, line, c)
         if (last_used < data_last_col .and. .not. tail_in_run) then
            if (len_trim(c(last_used + 1:data_last_col)) > 0) then
               call report(deck, err, src, line, where//', columns '//itoa(last_used + 1)//'-' &
                  //itoa(data_last_col)//': found "'//trim(adjustl(c(last_used + 1:data_last_col))) &
                  //'"; *'//trim(s%name)//' has no field there (is the card shifted?)')
               ok = .false.
            end if
         end if
         ! a bad card is not stored; its errors are reported and the run stops
         if (ok) then
            call append_card(g, card)
         else
            call note_rejected(g, line, card%index)
         end if
      end associate
   end subroutine parse_data_card

   !> Columns 73-80 hold the card's identification and are not read (the
   !! card convention), so a number that runs on from column 72 into them
   !! without a blank is cut short: "1200." in columns 70-74 reads as 120.
   !! An archival deck may have sequence numbers there right after a value,
   !! so this is a warning, not an error. Text (a title, a file name) that
   !! runs on into them is warned about too.
   subroutine warn_run_into_id(deck, s, where, src, line, c)
      type(deck_t), intent(inout) :: deck
      type(group_spec_t), intent(in) :: s
      character(len=*), intent(in) :: where, c
      integer, intent(in) :: src, line
      integer :: k, first, last
      if (c(data_last_col:data_last_col) == ' ' .or. c(data_last_col + 1:data_last_col + 1) == ' ') return
      do k = 1, s%n_fields
         if (s%field(k)%last_col /= data_last_col) cycle
         if (s%field(k)%kind == kind_text) then
            ! a title or a file name cut at column 72
            call append_string(deck%warnings, card_place(deck, src, line)//where//', field ' &
               //trim(s%field(k)%name)//' (columns '//itoa(s%field(k)%first_col)//'-'//itoa(data_last_col) &
               //'): the text runs on into columns 73-80, the card''s identification, which is not read: "' &
               //trim(c(data_last_col + 1:))//'" is left out')
            cycle
         end if
         if (index('0123456789.+-EeDd', c(data_last_col + 1:data_last_col + 1)) == 0) cycle
         call run_around(c, data_last_col, s%field(k)%first_col, card_width, first, last)
         call append_string(deck%warnings, card_place(deck, src, line)//where//', field ' &
            //trim(s%field(k)%name)//' (columns '//itoa(s%field(k)%first_col)//'-'//itoa(data_last_col) &
            //'): "'//c(first:last)//'" runs on into columns 73-80, the card''s identification, which is not ' &
            //'read: the value read is "'//c(first:data_last_col)//'"')
      end do
   end subroutine warn_run_into_id

   !> "file:line: " of a card, or nothing for lines without a source.
   function card_place(deck, src, line) result(text)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: src, line
      character(len=:), allocatable :: text
      text = ''
      if (src > 0 .and. src <= size(deck%source_name)) text = deck%source_name(src)%s//':'//itoa(line)//': '
   end function card_place

   !> The run of non-blank columns through edge and edge + 1: back from edge
   !! to no further than lo, on from edge + 1 to no further than hi.
   pure subroutine run_around(c, edge, lo, hi, first, last)
      character(len=*), intent(in) :: c
      integer, intent(in) :: edge, lo, hi
      integer, intent(out) :: first, last
      first = edge
      do while (first > lo)
         if (c(first - 1:first - 1) == ' ') exit
         first = first - 1
      end do
      last = edge + 1
      do while (last < hi)
         if (c(last + 1:last + 1) == ' ') exit
         last = last + 1
      end do
   end subroutine run_around

   !> Values must stay inside their fields: text that runs from the last
   !! column of one field into the first column of the next would otherwise
   !! be read as two values, both wrong. Each such run is one problem naming
   !! the fields it touches (and the columns after the last field, where a
   !! group has no field); in_run marks the fields not to be read on their own.
   subroutine check_runs_across(deck, err, s, where, src, line, c, last_used, in_run, tail_in_run, ok)
      type(deck_t), intent(inout) :: deck
      type(error_t), intent(inout) :: err
      type(group_spec_t), intent(in) :: s
      character(len=*), intent(in) :: where, c
      integer, intent(in) :: src, line, last_used
      logical, intent(out) :: in_run(max_fields), tail_in_run
      logical, intent(inout) :: ok
      integer :: k, j, edge, first, last, n_named, n_edges
      character(len=:), allocatable :: names, edges

      in_run = .false.
      tail_in_run = .false.
      last = 0
      do k = 1, s%n_fields
         if (s%field(k)%kind == kind_text) cycle
         edge = s%field(k)%last_col
         if (edge <= last .or. edge >= data_last_col) cycle   ! inside a run already reported
         if (c(edge:edge) == ' ' .or. c(edge + 1:edge + 1) == ' ') cycle
         ! the run: back to its first column (never into the index, columns 1-2), on to its last
         call run_around(c, edge, index_last_col + 1, data_last_col, first, last)
         names = ''
         edges = ''
         n_named = 0
         n_edges = 0
         do j = 1, s%n_fields
            if (s%field(j)%kind == kind_text) cycle
            if (s%field(j)%last_col < first .or. s%field(j)%first_col > last) cycle
            in_run(j) = .true.
            call add_to_list(names, n_named, trim(s%field(j)%name)//' (columns ' &
               //itoa(s%field(j)%first_col)//'-'//itoa(s%field(j)%last_col)//')')
            if (s%field(j)%last_col < last) call add_to_list(edges, n_edges, itoa(s%field(j)%last_col))
         end do
         if (n_named == 1) then
            names = 'field '//names
         else
            names = 'fields '//names
         end if
         if (last > last_used) then
            tail_in_run = .true.
            names = names//' and columns '//itoa(last_used + 1)//'-'//itoa(data_last_col) &
               //', where *'//trim(s%name)//' has no field'
         end if
         if (n_edges == 1) then
            edges = 'boundary after column '//edges
         else
            edges = 'boundaries after columns '//edges
         end if
         call report(deck, err, src, line, where//', '//names//': found "'//c(first:last) &
            //'" in columns '//itoa(first)//'-'//itoa(last)//', across the field '//edges &
            //'; expected each value inside its own field')
         ok = .false.
      end do
   end subroutine check_runs_across

   !> Append an item to an English list: "a", "a and b", "a, b and c".
   pure subroutine add_to_list(list, n, item)
      character(len=:), allocatable, intent(inout) :: list
      integer, intent(inout) :: n
      character(len=*), intent(in) :: item
      integer :: last_and
      if (n == 0) then
         list = item
      else
         last_and = index(list, ' and ', back=.true.)
         if (n >= 2 .and. last_and > 0) list = list(1:last_and - 1)//', '//list(last_and + 5:)
         list = list//' and '//item
      end if
      n = n + 1
   end subroutine add_to_list

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
            call report(deck, err, src, line, head//': blank; expected '//field_expectation(f))
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
         w = word_position(f%words, upper(raw))
         if (w == 0) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//field_expectation(f))
            ok = .false.
         else
            card%value(k) = real(w, wp)
         end if
      case (kind_int)
         call read_int(raw, n, good)
         if (.not. good) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//field_expectation(f))
            ok = .false.
         else if (real(n, wp) < f%low .or. real(n, wp) > f%high) then
            call report(deck, err, src, line, head//': found '//raw//'; expected '//field_expectation(f))
            ok = .false.
         else
            card%value(k) = real(n, wp)
         end if
      case (kind_real)
         call read_real(raw, x, good)
         if (.not. good) then
            call report(deck, err, src, line, head//': found "'//raw//'"; expected '//field_expectation(f))
            ok = .false.
         else if (x < f%low .or. x > f%high .or. (f%low_open .and. .not. x > f%low)) then
            call report(deck, err, src, line, head//': found '//raw//'; expected '//field_expectation(f))
            ok = .false.
         else
            card%value(k) = x*f%scale
         end if
      end select
   end subroutine parse_field

   ! --- lexical helpers ---------------------------------------------------


   !> The letters and digits that start s after any blanks (a group name
   !! followed by a character that is refused).
   pure function leading_name(s) result(w)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: w
      integer :: i
      w = adjustl(s)
      do i = 1, len(w)
         if (index('ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789', w(i:i)) == 0) then
            w = w(1:i - 1)
            return
         end if
      end do
   end function leading_name

   pure function first_word(s) result(w)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: w
      integer :: b
      w = trim(adjustl(s))
      b = index(w, ' ')
      if (b > 0) w = w(1:b - 1)
   end function first_word

   !> The echo of a comment card: as written when it fits in card_width
   !! bytes, which the listing and the HDF5 file allow a card image; a UTF-8
   !! comment of up to 80 characters may take more, and is then cut at a
   !! character boundary and marked '...'.
   pure function echo_text(s) result(e)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: e
      character(len=*), parameter :: mark = '...'
      integer :: cut
      if (len_trim(s) <= card_width) then
         e = trim(s)
         return
      end if
      cut = card_width - len(mark)
      ! back to the start of a character: a UTF-8 continuation byte is 128-191
      do while (cut > 0)
         if (iachar(s(cut + 1:cut + 1)) < 128 .or. iachar(s(cut + 1:cut + 1)) >= 192) exit
         cut = cut - 1
      end do
      e = s(1:cut)//mark
   end function echo_text

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

   !> The names of the deck's sources, for a problem of the whole deck:
   !! "@default, mine.deck" ("deck" before any source).
   function deck_names(deck) result(names)
      type(deck_t), intent(in) :: deck
      character(len=:), allocatable :: names
      integer :: k
      names = ''
      do k = 1, size(deck%source_name)
         if (k > 1) names = names//', '
         names = names//deck%source_name(k)%s
      end do
      if (len(names) == 0) names = 'deck'
   end function deck_names

   integer function group_by_name(deck, name)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      integer :: i
      group_by_name = 0
      if (len_trim(name) == 0) return   ! (an unnamed slot of the table is no group)
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
         if (deck%spec(i)%name == ' ') cycle
         if (len(s) > 0) s = s//' '
         s = s//'*'//trim(deck%spec(i)%name)
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
            deck%group(j)%n_written = 0
            deck%group(j)%n_rejected = 0
         end if
      end do
      deck%group(gid)%present = .true.
      deck%group(gid)%source = src
      deck%group(gid)%line = line
      if (.not. allocated(deck%group(gid)%card)) allocate (deck%group(gid)%card(8))
      if (.not. allocated(deck%group(gid)%rejected_line)) &
         allocate (deck%group(gid)%rejected_line(8), deck%group(gid)%rejected_index(8))
   end subroutine start_group

   !> Remember a card that had errors: its line and its row index (0 if unreadable).
   subroutine note_rejected(g, line, row)
      type(group_t), intent(inout) :: g
      integer, intent(in) :: line, row
      integer, allocatable :: tmp(:)
      if (g%n_rejected == size(g%rejected_line)) then
         allocate (tmp(2*size(g%rejected_line)))
         tmp(1:g%n_rejected) = g%rejected_line(1:g%n_rejected)
         call move_alloc(tmp, g%rejected_line)
         allocate (tmp(2*size(g%rejected_index)))
         tmp(1:g%n_rejected) = g%rejected_index(1:g%n_rejected)
         call move_alloc(tmp, g%rejected_index)
      end if
      g%n_rejected = g%n_rejected + 1
      g%rejected_line(g%n_rejected) = line
      g%rejected_index(g%n_rejected) = row
   end subroutine note_rejected

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
         loc = deck_names(deck)//': '   ! (a problem of the whole deck: every file of it)
      end if
      call error_append(err, exit_deck, loc//message)
   end subroutine report

   ! --- a field set by name (C.8) ---------------------------------------------

   !> Where field `field` of card `card_ref` of group `group` is in deck: the
   !! group gid, the card's position ic in deck%group(gid)%card and the
   !! field's number k; or why not (why /= ''). card_ref is the row index in
   !! an indexed group (one card per index: *BELTS 3), else the card's
   !! number in its group as read (1 for a single card; *LOADTABLE 2 is the
   !! table's second card, whatever its curve).
   !! Only numbers (real and integer fields) can be set.
   subroutine deck_field_address(deck, group, card_ref, field, gid, ic, k, why)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: group, field
      integer, intent(in) :: card_ref
      integer, intent(out) :: gid, ic, k
      character(len=:), allocatable, intent(out) :: why
      integer :: j
      why = ''
      ic = 0
      k = 0
      gid = group_by_name(deck, upper(trim(adjustl(group))))
      if (gid == 0) then
         why = 'no card group *'//trim(adjustl(group))//'; expected one of: '//group_names(deck)
         return
      end if
      associate (s => deck%spec(gid), g => deck%group(gid))
         if (.not. g%present) then
            why = 'the deck has no *'//trim(s%name)//' group, so it has no field to vary there'
            return
         end if
         do j = 1, s%n_fields
            if (s%field(j)%name == upper(trim(adjustl(field)))) k = j
         end do
         if (k == 0) then
            why = '*'//trim(s%name)//' has no field '//trim(adjustl(field))//'; its fields are: '//field_names(s)
            return
         end if
         if (s%field(k)%kind /= kind_real .and. s%field(k)%kind /= kind_int) then
            why = 'field '//trim(s%field(k)%name)//' of *'//trim(s%name)//' holds a word or a text; only numbers '// &
               'can be varied'
            k = 0
            return
         end if
         if (s%layout == layout_indexed) then
            do j = 1, g%n
               if (g%card(j)%index == card_ref) then
                  ic = j
                  exit
               end if
            end do
            if (ic == 0) why = '*'//trim(s%name)//' has no card with '//trim(s%index_name)//' = '//itoa(card_ref)
         else if (card_ref >= 1 .and. card_ref <= g%n) then
            ic = card_ref
         else
            why = '*'//trim(s%name)//' has '//itoa(g%n)//' card(s); there is no card '//itoa(card_ref)
         end if
      end associate
   end subroutine deck_field_address

   !> Set field k of card ic of group gid (deck_field_address) to x, in the
   !! field's deck units (C.8: a variation is a deck as a user could have
   !! written it). x is written into the field's columns of the card image
   !! (field_text: an integer field takes the nearest integer) and read
   !! back by the same check as every card, so a value the field refuses is
   !! an error located at the card, as a deck's own; the card then holds
   !! the value read. The echo shows the new card, marked varied. written:
   !! the value the card's text holds, in deck units (x rounded to what the
   !! field's columns hold).
   subroutine deck_set_field(deck, gid, ic, k, x, err, written)
      type(deck_t), intent(inout) :: deck
      integer, intent(in) :: gid, ic, k
      real(wp), intent(in) :: x
      type(error_t), intent(inout) :: err
      real(wp), intent(out), optional :: written
      character(len=card_width) :: c
      character(len=:), allocatable :: t, where
      type(card_t) :: card
      type(field_spec_t) :: f
      integer :: e, w
      logical :: ok
      f = deck%spec(gid)%field(k)
      card = deck%group(gid)%card(ic)
      e = echo_of(deck, card%source, card%line)
      c = ' '
      if (e > 0) c = deck%echo(e)%text
      w = f%last_col - f%first_col + 1
      if (f%kind == kind_int) then
         t = itoa(nint(x))
      else
         t = field_text(x, w)
      end if
      c(f%first_col:f%last_col) = repeat(' ', max(0, w - len(t)))//t(1:min(len(t), w))
      if (present(written)) then
         call read_real(trim(adjustl(c(f%first_col:f%last_col))), written, ok)
         if (.not. ok) written = x
      end if
      where = '*'//trim(deck%spec(gid)%name)//' card '//itoa(card%number)
      ok = .true.
      call parse_field(deck, err, f, where//' (varied)', card%source, card%line, c, card, k, ok)
      if (.not. ok) return
      deck%group(gid)%card(ic) = card
      if (e == 0) return   ! (every card read has its echo line)
      deck%echo(e)%text = trim(c)
      deck%echo(e)%varied = .true.
   end subroutine deck_set_field

   !> x as a deck's field of `width` columns would hold it: the shortest
   !! decimal that reads back as x (strings' num), else x to the most
   !! significant digits that fit.
   pure function field_text(x, width) result(t)
      real(wp), intent(in) :: x
      integer, intent(in) :: width
      character(len=:), allocatable :: t
      integer :: d
      do d = 15, 1, -1
         t = num(x, d)
         if (len(t) <= width) return
      end do
   end function field_text

   !> The echo line of a card (source, line).
   pure integer function echo_of(deck, src, line) result(e)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: src, line
      do e = 1, deck%n_echo
         if (deck%echo(e)%source == src .and. deck%echo(e)%line == line) return
      end do
      e = 0
   end function echo_of

   !> A group's field names, for a message.
   pure function field_names(s) result(names)
      type(group_spec_t), intent(in) :: s
      character(len=:), allocatable :: names
      integer :: j
      names = ''
      do j = 1, s%n_fields
         if (j > 1) names = names//', '
         names = names//trim(s%field(j)%name)
      end do
   end function field_names

end module deck_reader
