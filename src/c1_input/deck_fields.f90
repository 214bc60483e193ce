!> Reading a deck's fields by name, as the card table names them, so that
!! the builders of the model sections never depend on a field's position
!! on its card.
module deck_fields
   use kinds, only: wp
   use deck_reader, only: deck_t, card_t
   implicit none
   private

   public :: field_number, card_value, card_int, card_given, group_value, group_int, group_given
   public :: single_card

contains

   !> The position of field `name` in group gid. A name the card table does
   !! not hold is a defect of the program, never of a deck.
   integer function field_number(deck, gid, name) result(k)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      do k = 1, deck%spec(gid)%n_fields
         if (deck%spec(gid)%field(k)%name == name) return
      end do
      error stop 'hsri2d internal error: a builder asks for a field the card table does not have'
   end function field_number

   !> A field of a card, in internal units (a blank field holds its default).
   real(wp) function card_value(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      card_value = c%value(field_number(deck, gid, name))
   end function card_value

   !> An integer field of a card, or the number of a word field's word.
   integer function card_int(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      card_int = nint(card_value(deck, gid, c, name))
   end function card_int

   !> True when the field was not blank on the card.
   logical function card_given(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      card_given = c%given(field_number(deck, gid, name))
   end function card_given

   !> True when group gid is in the deck with its card.
   logical function single_card(deck, gid)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      single_card = deck%group(gid)%present .and. deck%group(gid)%n >= 1
   end function single_card

   !> A field of a one-card group: the card's value, or the field's default
   !! when the deck leaves the group out.
   real(wp) function group_value(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      if (single_card(deck, gid)) then
         group_value = deck%group(gid)%card(1)%value(k)
      else
         group_value = deck%spec(gid)%field(k)%default*deck%spec(gid)%field(k)%scale
      end if
   end function group_value

   integer function group_int(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      group_int = nint(group_value(deck, gid, name))
   end function group_int

   !> True when a one-card group is present and the field was not blank.
   logical function group_given(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      group_given = .false.
      if (single_card(deck, gid)) group_given = deck%group(gid)%card(1)%given(field_number(deck, gid, name))
   end function group_given
end module deck_fields
