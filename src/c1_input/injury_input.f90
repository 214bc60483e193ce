!> The injury criteria and the end of the run from the deck (report C.1,
!! Table 1, Table 5, C.7): *INJURY and *ENDTESTS - each section's builder,
!! which reads the fields by the names of the card table, and the validator
!! of *INJURY, which checks the fields each row of Table 1 defines.
module injury_input
   use error_handling, only: error_t
   use strings, only: itoa
   use deck_cards, only: g_injury, g_endtests
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, group_value
   use model_origin, only: model_origin_t, cards, field_given, problem
   use model, only: injury_section_t, end_tests_section_t, n_joint
   implicit none
   private

   public :: build_injury, check_injury, build_end_tests

contains

   !> Table 1 force injury criteria (Table 5 rows).
   subroutine build_injury(deck, inj)
      type(deck_t), intent(in) :: deck
      type(injury_section_t), intent(out) :: inj
      integer :: k, i
      associate (g => deck%group(g_injury))
         do k = 1, g%n
            i = g%card(k)%index
            inj%f_shear(i) = card_value(deck, g_injury, g%card(k), 'FSF')
            inj%f_compression(i) = card_value(deck, g_injury, g%card(k), 'FCF')
            inj%f_tension(i) = card_value(deck, g_injury, g%card(k), 'FTD')
         end do
      end associate
   end subroutine build_injury

   !> Table 1: FSF for rows 1-9, FCF for 1-3 and 5-8, FTD for joints 1-7 (a
   !! field Table 1 does not define, given on a card, is refused; the
   !! section's values need no check of their own).
   subroutine check_injury(orig, err)
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      integer :: k, i
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_injury)
      do k = 1, size(cs)
         i = cs(k)%index
         if (i == 10 .and. field_given(orig, g_injury, cs(k), 'FSF')) call problem(orig, err, cs(k), &
            'row 10: Table 1 has no shear fracture force here (rows 1-9); expected blank', 'FSF')
         if (any([4, 9, 10] == i) .and. field_given(orig, g_injury, cs(k), 'FCF')) &
            call problem(orig, err, cs(k), 'row '//itoa(i)//': Table 1 has no compression fracture force ' &
            //'here (rows 1-3, 5-8); expected blank', 'FCF')
         if (i > n_joint .and. field_given(orig, g_injury, cs(k), 'FTD')) call problem(orig, err, &
            cs(k), 'row '//itoa(i)//': the tension dislocation force applies to joints 1-7 only; expected ' &
            //'blank', 'FTD')
      end do
   end subroutine check_injury

   !> *ENDTESTS: the thresholds of the cessation of motion (C.7).
   function build_end_tests(deck) result(et)
      type(deck_t), intent(in) :: deck
      type(end_tests_section_t) :: et
      et = end_tests_section_t(group_value(deck, g_endtests, 'VREST'), group_value(deck, g_endtests, 'WREST'), &
                               group_value(deck, g_endtests, 'THOLD'))
   end function build_end_tests
end module injury_input
