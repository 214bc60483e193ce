!> Where each part of a model came from, for the validators' messages
!! (report C.1): the cards of each group in the order the deck gives them,
!! which fields a card gave, and the location of a card or a field - "file:
!! line: *GROUP card n, field F (columns a-b): message", as the deck reader
!! locates its own problems (README, docs/usage.md). The validators of the
!! model's sections read the values from the sections and only the
!! locations from here, never a field's value from the deck: a model built
!! or changed in code can be checked by the same validators, given an
!! origin that names the deck's groups and fields without files and lines.
!! Built from the deck by deck_origin.
module model_origin
   use error_handling, only: error_t, error_append, exit_deck
   use strings, only: itoa
   use text_io, only: string_t, append_string
   use deck_reader, only: deck_t, card_t, deck_names
   use deck_fields, only: card_given, card_int, single_card, group_given
   implicit none
   private

   public :: model_origin_t, deck_origin
   public :: cards, group_present, has_card, field_given, group_field_given, card_key, group_name
   public :: header_of, first_card, indexed_card, list_card, card_ref, field_where, located
   public :: problem, problem_at, warning

   !> The origin of a model: for one built from a deck, the deck's cards
   !! (their values are not read here but for the key field of a list of
   !! curves, card_key).
   type :: model_origin_t
      private
      type(deck_t) :: deck
   end type model_origin_t

contains

   !> The origin of a model built from deck: its card table, file names and
   !! cards (not its echo, which no message needs).
   function deck_origin(deck) result(o)
      type(deck_t), intent(in) :: deck
      type(model_origin_t) :: o
      o%deck%spec = deck%spec
      o%deck%source_name = deck%source_name
      o%deck%group = deck%group
   end function deck_origin

   !> The cards of group gid, in the deck's order.
   function cards(o, gid) result(cs)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      type(card_t), allocatable :: cs(:)
      cs = o%deck%group(gid)%card(1:o%deck%group(gid)%n)
   end function cards

   !> The deck holds group gid (its header, with or without cards).
   pure logical function group_present(o, gid)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      group_present = o%deck%group(gid)%present
   end function group_present

   !> The deck holds the card of the one-card group gid.
   pure logical function has_card(o, gid)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      has_card = single_card(o%deck, gid)
   end function has_card

   !> Field `name` of card c (of group gid) was not blank.
   pure logical function field_given(o, gid, c, name)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      field_given = card_given(o%deck, gid, c, name)
   end function field_given

   !> The one-card group gid is present and its field `name` was not blank.
   pure logical function group_field_given(o, gid, name)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      group_field_given = group_given(o%deck, gid, name)
   end function group_field_given

   !> The key field `name` of card c: which of a row's lists the card
   !! belongs to (*STOPCURVE's SIDE).
   pure integer function card_key(o, gid, c, name)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      card_key = card_int(o%deck, gid, c, name)
   end function card_key

   !> The name of group gid, without its star: 'SEATSPRINGS'.
   function group_name(o, gid) result(name)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      character(len=:), allocatable :: name
      name = trim(o%deck%spec(gid)%name)
   end function group_name

   !> The header card of group gid as a card to locate problems at (source
   !! 0 when the deck does not hold the group).
   function header_of(o, gid) result(c)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      type(card_t) :: c
      c%group = gid
      c%number = 0
      if (o%deck%group(gid)%present) then
         c%source = o%deck%group(gid)%source
         c%line = o%deck%group(gid)%line
      end if
   end function header_of

   !> The card of a one-card group, or its header (source 0 when absent).
   function first_card(o, gid) result(c)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      type(card_t) :: c
      if (single_card(o%deck, gid)) then
         c = o%deck%group(gid)%card(1)
      else
         c = header_of(o, gid)
      end if
   end function first_card

   !> The card of row i of an indexed group (the first, for a group that
   !! may hold several), or its header when the deck has none (a card's
   !! number is then 0; its source 0 when the group is absent).
   function indexed_card(o, gid, i) result(c)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid, i
      type(card_t) :: c
      integer :: k
      do k = 1, o%deck%group(gid)%n
         if (o%deck%group(gid)%card(k)%index /= i) cycle
         c = o%deck%group(gid)%card(k)
         return
      end do
      c = header_of(o, gid)
   end function indexed_card

   !> Card n of cs, a list of group gid's cards (row n of a table, point n
   !! of a curve), or the group's header when the list is shorter (an origin
   !! without the cards: a model built in code).
   function list_card(orig, gid, cs, n) result(c)
      type(model_origin_t), intent(in) :: orig
      integer, intent(in) :: gid
      type(card_t), intent(in) :: cs(:)
      integer, intent(in) :: n
      type(card_t) :: c
      if (n >= 1 .and. n <= size(cs)) then
         c = cs(n)
      else
         c = header_of(orig, gid)
      end if
   end function list_card

   !> Where another card is, for a problem that involves two: "*OPTIONS
   !! card 1 at default.deck:12" (or "*OPTIONS, not in the deck").
   function card_ref(o, c) result(text)
      type(model_origin_t), intent(in) :: o
      type(card_t), intent(in) :: c
      character(len=:), allocatable :: text
      text = '*'//trim(o%deck%spec(c%group)%name)
      if (c%number > 0) text = text//' card '//itoa(c%number)
      if (c%source > 0) then
         text = text//' at '//o%deck%source_name(c%source)%s//':'//itoa(c%line)
      else
         text = text//', not in the deck (its defaults)'
      end if
   end function card_ref

   !> Field `name` of group gid with its columns, for messages: 'X (columns 3-12)'.
   function field_where(o, gid, name) result(text)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: j
      text = name
      do j = 1, o%deck%spec(gid)%n_fields
         if (trim(o%deck%spec(gid)%field(j)%name) == name) text = name//' (columns ' &
            //itoa(o%deck%spec(gid)%field(j)%first_col)//'-'//itoa(o%deck%spec(gid)%field(j)%last_col)//')'
      end do
   end function field_where

   !> "field X (columns a-b)", "fields X (columns a-b) and Y (columns c-d)",
   !! "fields X (...), Y (...) and Z (...)" from blank-separated names.
   function field_list(o, gid, names) result(text)
      type(model_origin_t), intent(in) :: o
      integer, intent(in) :: gid
      character(len=*), intent(in) :: names
      character(len=:), allocatable :: text, rest, name
      integer :: n, blank
      text = ''
      n = 0
      rest = trim(adjustl(names))
      do while (len(rest) > 0)
         blank = index(rest, ' ')
         if (blank == 0) blank = len(rest) + 1
         name = rest(1:blank - 1)
         rest = trim(adjustl(rest(blank:)))
         n = n + 1
         if (n == 1) then
            text = field_where(o, gid, name)
         else if (len(rest) == 0) then
            text = text//' and '//field_where(o, gid, name)
         else
            text = text//', '//field_where(o, gid, name)
         end if
      end do
      text = trim(merge('fields', 'field ', n > 1))//' '//text
   end function field_list

   !> A problem's or warning's text, located as the deck reader locates
   !! its own (README, docs/usage.md): "file:line: *GROUP card n, field F
   !! (columns a-b): message" for a data card; "file:line: *GROUP: message"
   !! for a group's header (header_of); fields is a blank-separated list of
   !! the fields concerned ('' for none). A card of a group the deck does
   !! not hold (source 0) is "a.deck, b.deck: *GROUP: ..." - callers that
   !! have a card asking for that group locate the problem there instead.
   function located(o, c, message, fields) result(text)
      type(model_origin_t), intent(in) :: o
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      character(len=:), allocatable :: text
      if (c%source > 0) then
         text = o%deck%source_name(c%source)%s//':'//itoa(c%line)//': '
      else
         text = deck_names(o%deck)//': '
      end if
      if (c%group > 0) then
         text = text//'*'//trim(o%deck%spec(c%group)%name)
         if (c%number > 0) text = text//' card '//itoa(c%number)
         if (present(fields)) then
            if (len_trim(fields) > 0) text = text//', '//field_list(o, c%group, fields)
         end if
         text = text//': '
      end if
      text = text//message
   end function located

   !> A problem located at a card (see located).
   subroutine problem(o, err, c, message, fields)
      type(model_origin_t), intent(in) :: o
      type(error_t), intent(inout) :: err
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      if (present(fields)) then
         call error_append(err, exit_deck, located(o, c, message, fields))
      else
         call error_append(err, exit_deck, located(o, c, message))
      end if
   end subroutine problem

   !> A problem located at a group's header card.
   subroutine problem_at(o, err, gid, message, fields)
      type(model_origin_t), intent(in) :: o
      type(error_t), intent(inout) :: err
      integer, intent(in) :: gid
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      if (present(fields)) then
         call problem(o, err, header_of(o, gid), message, fields)
      else
         call problem(o, err, header_of(o, gid), message)
      end if
   end subroutine problem_at

   !> A warning located at a card (see located), added to the model's.
   subroutine warning(o, warnings, c, message, fields)
      type(model_origin_t), intent(in) :: o
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      if (present(fields)) then
         call append_string(warnings, located(o, c, message, fields))
      else
         call append_string(warnings, located(o, c, message))
      end if
   end subroutine warning
end module model_origin
