!> The cases of an analog deck (*ANALOG, report Section D; docs/analog.md),
!! from the deck's cards in internal units. The card table checks each
!! field's range; nothing else can be wrong with a case.
module analog_input
   use kinds, only: wp
   use deck_reader, only: deck_t
   use deck_cards, only: g_analog, g_title
   use deck_fields, only: card_value
   use analog_model, only: analog_case_t
   implicit none
   private

   public :: deck_is_analog, analog_cases, analog_title

contains

   !> The deck runs Section D's analog (the reader refuses any other group
   !! beside *ANALOG but *TITLE).
   pure logical function deck_is_analog(deck)
      type(deck_t), intent(in) :: deck
      deck_is_analog = deck%group(g_analog)%present
   end function deck_is_analog

   !> One case per *ANALOG card, in the deck's order.
   pure function analog_cases(deck) result(cases)
      type(deck_t), intent(in) :: deck
      type(analog_case_t), allocatable :: cases(:)
      integer :: k
      allocate (cases(deck%group(g_analog)%n))
      do k = 1, size(cases)
         associate (card => deck%group(g_analog)%card(k))
            cases(k)%speed = card_value(deck, g_analog, card, 'V')
            cases(k)%k1 = card_value(deck, g_analog, card, 'K1')
            cases(k)%l1 = card_value(deck, g_analog, card, 'L1')
            cases(k)%zeta = card_value(deck, g_analog, card, 'ZETA')
            cases(k)%torque = card_value(deck, g_analog, card, 'T')
            cases(k)%spacing = card_value(deck, g_analog, card, 'L')
            cases(k)%t_max = card_value(deck, g_analog, card, 'TMAX')
         end associate
      end do
   end function analog_cases

   !> The deck's title ('' without *TITLE).
   pure function analog_title(deck) result(title)
      type(deck_t), intent(in) :: deck
      character(len=:), allocatable :: title
      title = ''
      if (deck%group(g_title)%present .and. deck%group(g_title)%n > 0) then
         if (allocated(deck%group(g_title)%card(1)%text)) title = trim(deck%group(g_title)%card(1)%text)
      end if
   end function analog_title
end module analog_input
