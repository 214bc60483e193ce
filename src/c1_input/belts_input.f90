!> The belts from the deck (report C.1, Table 2, C.2, C.4.e; docs/belts.md):
!! *BELTS and *BELTOPTIONS - the section's builder, which reads the geometry
!! of each section and the options by the names of the card table, and its
!! validator, which checks what single fields cannot.
module belts_input
   use error_handling, only: error_t
   use strings, only: itoa, num
   use text_io, only: string_t
   use deck_cards, only: g_options, g_segments, g_beltloading, g_belts, g_beltoptions
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, group_int
   use model_origin, only: model_origin_t, cards, group_present, field_given, header_of, first_card, indexed_card, &
      card_ref, problem, problem_at, warning
   use model, only: body_section_t, loading_section_t, belts_section_t, n_belt_card, n_belt_section, belt_card_lap2, &
      coupling_torso, coupling_all, nbelt_lap, nbelt_torso
   implicit none
   private

   public :: build_belts, check_belts

contains

   !> *BELTS and *BELTOPTIONS (Table 2, C.2, C.4.e): the geometry of each
   !! section the deck gives, and the options.
   subroutine build_belts(deck, bt)
      type(deck_t), intent(in) :: deck
      type(belts_section_t), intent(out) :: bt
      integer :: k, j

      bt%coupling = group_int(deck, g_beltoptions, 'COUPLING')
      bt%lap_sides = group_int(deck, g_beltoptions, 'LAPSIDES')
      bt%max_iter = group_int(deck, g_beltoptions, 'ITER')
      associate (g => deck%group(g_belts))
         do k = 1, g%n
            j = g%card(k)%index
            bt%given(j) = .true.
            bt%h(j) = card_value(deck, g_belts, g%card(k), 'H')
            bt%length0(j) = card_value(deck, g_belts, g%card(k), 'LENGTH')
            bt%phi0(j) = card_value(deck, g_belts, g%card(k), 'PHI')
            bt%length_anchor(j) = card_value(deck, g_belts, g%card(k), 'LPRIME')
            bt%phi_anchor(j) = card_value(deck, g_belts, g%card(k), 'PHIPRIME')
            bt%slack(j) = card_value(deck, g_belts, g%card(k), 'SLACK')
         end do
      end associate
   end subroutine build_belts

   !> What single fields cannot check: which fields each kind of section
   !! takes, the lap anchor outside the wrap, the belt points on their
   !! segments, the cards and loading the sections NBELT calls for, the
   !! options that go together.
   subroutine check_belts(bt, nbelt, body, ld, orig, warnings, err)
      type(belts_section_t), intent(in) :: bt
      integer, intent(in) :: nbelt
      type(body_section_t), intent(in) :: body
      type(loading_section_t), intent(in) :: ld
      type(model_origin_t), intent(in) :: orig
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: where
      logical :: used(n_belt_card)
      type(card_t), allocatable :: cs(:)
      type(card_t) :: c, options, loading
      character(len=:), allocatable :: asker, no_belts, no_loading
      integer :: k, j

      used = [nbelt_lap(nbelt), nbelt_torso(nbelt), nbelt_torso(nbelt), nbelt_lap(nbelt) .and. bt%lap_sides == 2]

      options = first_card(orig, g_options)
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_belts)
      do k = 1, size(cs)
         c = cs(k)
         j = c%index
         where = 'section '//itoa(j)
         if (j == 1 .or. j == belt_card_lap2) then
            ! the lap belt: its free length and angle follow from l'_0, phi'_0 (C.2, C2-2, C2-3)
            call forbid('LENGTH', 'the lap belt''s free length is computed from LPRIME and PHIPRIME ' &
                        //'(C.2, errata C2-2)')
            call forbid('PHI', 'the lap belt''s angle is computed from LPRIME and PHIPRIME (C.2, errata C2-3)')
            call need('LPRIME', 'the lap belt''s anchor lies LPRIME from the initial hip')
            call need('PHIPRIME', 'PHIPRIME is the direction from the lap belt''s anchor to the initial hip')
            if (field_given(orig, g_belts, c, 'LPRIME') .and. .not. bt%length_anchor(j) > bt%h(j)) &
               call problem(orig, err, c, where//': LPRIME = '//num(bt%length_anchor(j)) &
               //' in must exceed the wrap radius H = '//num(bt%h(j))//' in (the anchor lies outside ' &
               //'the circle the belt wraps; figure 17)', 'H LPRIME')
         else
            call forbid('LPRIME', 'LPRIME belongs to the lap belt (sections 1 and 4)')
            call forbid('PHIPRIME', 'PHIPRIME belongs to the lap belt (sections 1 and 4)')
            call need('LENGTH', 'LENGTH is the initial distance from the anchor to the belt point (C.2)')
            call need('PHI', 'PHI is the direction from the anchor to the belt point (C.2)')
            ! the belt point on its segment: section 2 below the upper-spine joint, 3 below the neck
            if (bt%h(j) > body%length(j)) then
               if (j == 2) then
                  where = where//': H = '//num(bt%h(j))//' in lies beyond the upper-spine joint (L2 = '
               else
                  where = where//': H = '//num(bt%h(j))//' in lies beyond the neck (L3 = '
               end if
               call problem(orig, err, c, where//num(body%length(j))//' in of '//card_ref(orig, &
                  indexed_card(orig, g_segments, j))//') on the segment that carries the belt', 'H')
            end if
         end if
      end do

      if (nbelt == 0) then
         if (group_present(orig, g_belts)) call warning(orig, warnings, header_of(orig, g_belts), &
            'not used: NBELT = 0 ('//card_ref(orig, options)//')')
         if (group_present(orig, g_beltoptions)) call warning(orig, warnings, &
            header_of(orig, g_beltoptions), 'not used: NBELT = 0 ('//card_ref(orig, options)//')')
         return
      end if
      c = first_card(orig, g_beltoptions)
      no_belts = ''
      no_loading = ''
      ! the sections NBELT calls for need their cards and their loading
      do j = 1, n_belt_card
         if (.not. used(j)) then
            if (bt%given(j)) call warning(orig, warnings, indexed_card(orig, g_belts, j), &
               'section '//itoa(j)//' is not used: NBELT = '//itoa(nbelt)//' ('//card_ref(orig, options) &
               //'), LAPSIDES = '//itoa(bt%lap_sides)//' ('//card_ref(orig, c)//')')
            cycle
         end if
         if (.not. bt%given(j)) then
            asker = 'NBELT = '//itoa(nbelt)
            if (j == belt_card_lap2) asker = asker//' with LAPSIDES = 2 ('//card_ref(orig, c)//')'
            if (group_present(orig, g_belts)) then
               call problem_at(orig, err, g_belts, 'no card for section '//itoa(j)//', which '//asker//' (' &
                  //card_ref(orig, options)//') needs: give its card')
            else
               call add_to_list(no_belts, itoa(j))   ! (one message for the group: below)
            end if
         end if
         ! card 4, the lap belt's second side, takes the lap belt's loading
         if (ld%belt_curve(min(j, n_belt_section)) < 1 .and. j <= n_belt_section) then
            loading = indexed_card(orig, g_beltloading, j)
            if (loading%number > 0) then
               call problem(orig, err, loading, 'section '//itoa(j)//' is used ' &
                  //'(NBELT = '//itoa(nbelt)//', '//card_ref(orig, options)//'): give its loading curve', 'CURVE')
            else if (group_present(orig, g_beltloading)) then
               call problem_at(orig, err, g_beltloading, 'no card for section '//itoa(j)//', which NBELT = ' &
                  //itoa(nbelt)//' ('//card_ref(orig, options)//') uses: give its loading (CURVE, G, R)')
            else
               call add_to_list(no_loading, itoa(j))
            end if
         end if
      end do
      if (len(no_belts) > 0) call problem(orig, err, options, 'NBELT = '//itoa(nbelt)//' needs *BELTS ' &
         //sections(no_belts)//', and the deck has no *BELTS card group: give their cards', 'NBELT')
      if (len(no_loading) > 0) call problem(orig, err, options, 'NBELT = '//itoa(nbelt)//' uses belt ' &
         //sections(no_loading)//', and the deck has no *BELTLOADING card group: give their loading (CURVE, ' &
         //'G, R)', 'NBELT')
      if (bt%coupling == coupling_torso .and. .not. nbelt_torso(nbelt)) call problem(orig, err, c, &
         'COUPLING = TORSO: the torso sections share a tension, but NBELT = '//itoa(nbelt)//' (' &
         //card_ref(orig, options)//') uses no torso belt', 'COUPLING')
      if (bt%coupling == coupling_all .and. nbelt /= 3) call problem(orig, err, c, 'COUPLING = ALL: the three ' &
         //'sections share a tension, but NBELT = '//itoa(nbelt)//' ('//card_ref(orig, options)//') does not ' &
         //'use all three', 'COUPLING')
      if (bt%coupling == coupling_all .and. bt%lap_sides == 2) call problem(orig, err, c, 'with COUPLING = ALL ' &
         //'the lap belt is one section (LAPSIDES = 1)', 'COUPLING LAPSIDES')
      if (bt%lap_sides == 2 .and. .not. nbelt_lap(nbelt)) call problem(orig, err, c, 'LAPSIDES = 2: NBELT = ' &
         //itoa(nbelt)//' ('//card_ref(orig, options)//') uses no lap belt', 'LAPSIDES')
   contains
      !> Add a section's number to a list "1 2".
      pure subroutine add_to_list(list, item)
         character(len=:), allocatable, intent(inout) :: list
         character(len=*), intent(in) :: item
         if (len(list) > 0) list = list//' '
         list = list//item
      end subroutine add_to_list
      !> "section 1", "sections 1 and 2", "sections 1, 2 and 3" from "1 2 3".
      pure function sections(list) result(text)
         character(len=*), intent(in) :: list
         character(len=:), allocatable :: text, rest
         integer :: blank, n
         text = ''
         rest = list
         n = 0
         do while (len(rest) > 0)
            blank = index(rest, ' ')
            if (blank == 0) blank = len(rest) + 1
            n = n + 1
            if (n > 1 .and. blank > len(rest)) then
               text = text//' and '
            else if (n > 1) then
               text = text//', '
            end if
            text = text//rest(1:blank - 1)
            rest = rest(min(blank + 1, len(rest) + 1):)
         end do
         text = trim(merge('sections', 'section ', n > 1))//' '//text
      end function sections
      !> A field this kind of section does not take.
      subroutine forbid(name, why)
         character(len=*), intent(in) :: name, why
         if (field_given(orig, g_belts, c, name)) call problem(orig, err, c, where//': leave '//name//' blank: ' &
            //why, name)
      end subroutine forbid
      !> A field this kind of section needs.
      subroutine need(name, why)
         character(len=*), intent(in) :: name, why
         if (.not. field_given(orig, g_belts, c, name)) call problem(orig, err, c, where//': '//name &
            //' is required: '//why, name)
      end subroutine need
   end subroutine check_belts

end module belts_input
