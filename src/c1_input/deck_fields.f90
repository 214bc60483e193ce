!> Reading a deck's fields by name, as the card table names them, so that
!! the builders of the model sections never depend on a field's position
!! on its card.
module deck_fields
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp
   use deck_reader, only: deck_t, card_t
   implicit none
   private

   public :: field_number, card_value, card_int, card_given, group_value, group_int, group_given
   public :: single_card, default_value

contains

   !> The position of field `name` in group gid, or 0. A name the card table
   !! does not hold is a defect of the program, never of a deck (its value
   !! is then NaN, -huge or .false.): the test cli_field_names
   !! (tests/cli/check_field_names.py) checks every name that every call of
   !! these accessors, and every field list of the builder's messages, can
   !! pass against the card table, whether a test runs that call or not, at
   !! no cost to a run (docs/architecture.md, "Errors": why no run-time
   !! check is added).
   pure integer function field_number(deck, gid, name) result(k)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      do k = 1, deck%spec(gid)%n_fields
         if (deck%spec(gid)%field(k)%name == name) return
      end do
      k = 0
   end function field_number

   !> A field of a card, in internal units (a blank field holds its default).
   pure real(wp) function card_value(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      if (k == 0) then
         card_value = ieee_value(0.0_wp, ieee_quiet_nan)
      else
         card_value = c%value(k)
      end if
   end function card_value

   !> An integer field of a card, or the number of a word field's word.
   pure integer function card_int(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      card_int = -huge(1)
      if (k > 0) card_int = nint(c%value(k))
   end function card_int

   !> True when the field was not blank on the card.
   pure logical function card_given(deck, gid, c, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      card_given = .false.
      if (k > 0) card_given = c%given(k)
   end function card_given

   !> A field's default, in internal units.
   pure real(wp) function default_value(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      if (k == 0) then
         default_value = ieee_value(0.0_wp, ieee_quiet_nan)
      else
         default_value = deck%spec(gid)%field(k)%default*deck%spec(gid)%field(k)%scale
      end if
   end function default_value

   !> True when group gid is in the deck with its card.
   pure logical function single_card(deck, gid)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      single_card = deck%group(gid)%present .and. deck%group(gid)%n >= 1
   end function single_card

   !> A field of a one-card group: the card's value, or the field's default
   !! when the deck leaves the group out.
   pure real(wp) function group_value(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      if (k == 0) then
         group_value = ieee_value(0.0_wp, ieee_quiet_nan)
      else if (single_card(deck, gid)) then
         group_value = deck%group(gid)%card(1)%value(k)
      else
         group_value = deck%spec(gid)%field(k)%default*deck%spec(gid)%field(k)%scale
      end if
   end function group_value

   pure integer function group_int(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      integer :: k
      k = field_number(deck, gid, name)
      group_int = -huge(1)
      if (k == 0) return
      if (single_card(deck, gid)) then
         group_int = nint(deck%group(gid)%card(1)%value(k))
      else
         group_int = nint(deck%spec(gid)%field(k)%default)
      end if
   end function group_int

   !> True when a one-card group is present and the field was not blank.
   pure logical function group_given(deck, gid, name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      group_given = .false.
      if (single_card(deck, gid)) group_given = card_given(deck, gid, deck%group(gid)%card(1), name)
   end function group_given
end module deck_fields
