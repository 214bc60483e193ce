!> The interior from the deck (report C.1, C.4.f, Table 3; docs/contacts.md
!! 2.4): *SURFACES, *INTERIOR, *CONTACTOFF - the section's builder, which
!! reads the fields by the names of the card table, and its validators: each
!! surface's fields as Table 3 marks them and the pairs left out
!! (check_interior), and the interior as the scene will assemble it, once
!! the rest of the model is sound (check_scene: D-C14's checks of the
!! derived surfaces, the rims, the shin and the materials of the pairs, and
!! the warnings of surfaces that build nothing or face away).
module interior_input
   use kinds, only: wp, deg
   use error_handling, only: error_t
   use strings, only: itoa, num
   use deck_cards, only: g_options, g_surfaces, g_interior, g_contactoff, g_arcs, g_segments, g_materials
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, card_int, card_given, group_value, single_card
   use model_origin, only: model_origin_t, cards, field_given, has_card, first_card, indexed_card, list_card, &
      card_ref, field_where, problem, warning
   use model, only: model_t, interior_section_t, nend_contact
   use contact_tables, only: contact_pair_t, position_pairs, surface_code_valid, surface_name, is_undesired, &
      surface_codes
   use interior_pairs, only: scene_pairs, surface_layers, surface_sources
   implicit none
   private

   public :: build_interior, check_interior, check_scene

contains

   !> *SURFACES, *INTERIOR, *CONTACTOFF (C.4.f, Table 3; docs/contacts.md
   !! 2.4): each surface the deck describes (a code of Table 3 or 7), the
   !! interior's dimensions, and the pairs left out, in the deck's order.
   subroutine build_interior(deck, it)
      type(deck_t), intent(in) :: deck
      type(interior_section_t), intent(out) :: it
      integer :: q, k
      associate (g => deck%group(g_surfaces))
         do q = 1, g%n
            k = g%card(q)%index
            if (.not. surface_code_valid(k)) cycle   ! (refused by check_interior)
            it%given(k) = .true.
            it%x(k) = card_value(deck, g_surfaces, g%card(q), 'X')
            it%y(k) = card_value(deck, g_surfaces, g%card(q), 'Y')
            it%psi(k) = card_value(deck, g_surfaces, g%card(q), 'PSI')
            it%d(k) = card_value(deck, g_surfaces, g%card(q), 'D')
            it%dpp(k) = card_value(deck, g_surfaces, g%card(q), 'DPP')
         end do
      end associate
      if (single_card(deck, g_interior)) then
         it%dfr = group_value(deck, g_interior, 'DFR')
         it%di = group_value(deck, g_interior, 'DI')
         if (card_given(deck, g_interior, deck%group(g_interior)%card(1), 'DS')) &
            it%ds = group_value(deck, g_interior, 'DS')
      end if
      associate (g => deck%group(g_contactoff))
         allocate (it%off(2, g%n))
         do q = 1, g%n
            it%off(:, q) = [card_int(deck, g_contactoff, g%card(q), 'I'), card_int(deck, g_contactoff, g%card(q), 'K')]
         end do
      end associate
   end subroutine build_interior

   !> Each surface's fields as Table 3 marks them, the ones f.2's relations
   !! derive left blank (D-C5); the pairs left out belonging to the
   !! occupant's position (D-C13), each once.
   subroutine check_interior(it, nbody, orig, err)
      type(interior_section_t), intent(in) :: it
      integer, intent(in) :: nbody
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      character(len=3), parameter :: names(4) = ['X  ', 'Y  ', 'PSI', 'D  ']
      type(contact_pair_t), allocatable :: pairs(:)
      type(card_t), allocatable :: cs(:)
      type(card_t) :: c
      logical :: need(4), derived(4)
      integer :: q, k, f, i, kk, j, first
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_surfaces)
      do q = 1, size(cs)
         k = cs(q)%index
         if (.not. surface_code_valid(k)) then
            call problem(orig, err, cs(q), 'surface i (columns 1-2) = '//itoa(k)//': not a surface of ' &
                         //'Table 3 or 7; expected 1-12, 21 (1*), 26 (6*), 29 (9*) or 32 (12*)')
            cycle
         end if
         call table3(k, need, derived)
         do f = 1, 4
            if (derived(f) .and. field_given(orig, g_surfaces, cs(q), trim(names(f)))) then
               call problem(orig, err, cs(q), 'surface '//itoa(k)//' ('//surface_name(k)//'): ' &
                            //trim(names(f))//' follows from f.2''s relations; leave it blank', trim(names(f)))
            else if (need(f) .and. .not. field_given(orig, g_surfaces, cs(q), trim(names(f)))) then
               call problem(orig, err, cs(q), 'surface '//itoa(k)//' ('//surface_name(k)//'): ' &
                            //trim(names(f))//' is required (Table 3)', trim(names(f)))
            end if
         end do
      end do
      allocate (pairs(0))
      pairs = position_pairs(nbody)
      cs = cards(orig, g_contactoff)
      do q = 1, size(it%off, 2)
         i = it%off(1, q)
         kk = it%off(2, q)
         c = list_card(orig, g_contactoff, cs, q)
         if (.not. any(pairs%i == i .and. pairs%k == kk)) then
            call problem(orig, err, c, 'the pair ('//itoa(i)//', '//itoa(kk)//') is not one of NBODY ' &
                         //itoa(nbody)//'''s (Tables 7, 8; '//card_ref(orig, first_card(orig, g_options)) &
                         //'); body point '//itoa(i)//' has '//surfaces_of(i), 'I K')
            cycle
         end if
         first = findloc([(it%off(1, j) == i .and. it%off(2, j) == kk, j=1, q - 1)], .true., 1)
         if (first > 0) then
            call problem(orig, err, c, 'the pair ('//itoa(i)//', '//itoa(kk)//') is switched off twice ' &
                         //'(first by '//card_ref(orig, list_card(orig, g_contactoff, cs, first))//')', 'I K')
            cycle
         end if
      end do
   contains
      !> Table 3 with f.2's relations: which of X, Y, PSI, D surface k needs
      !! and which are derived (D-C5).
      pure subroutine table3(k, need, derived)
         integer, intent(in) :: k
         logical, intent(out) :: need(4), derived(4)
         need = .true.
         derived = .false.
         select case (k)
         case (4)
            derived = [.true., .true., .false., .false.]
         case (10)
            derived = [.false., .false., .true., .false.]
         case (11, 12)
            derived = .true.
         case (32)
            derived = [.true., .false., .true., .true.]
         end select
         need = need .and. .not. derived
      end subroutine table3

      function surfaces_of(ii) result(text)
         integer, intent(in) :: ii
         character(len=:), allocatable :: text
         integer :: p
         text = ''
         do p = 1, size(pairs)
            if (pairs(p)%i == ii) text = text//' '//itoa(pairs(p)%k)
         end do
         if (len(text) == 0) text = ' none'
         text = 'surfaces'//text
      end function surfaces_of
   end subroutine check_interior

   !> D-C14: the surfaces f.2's relations derive from are described, and
   !! every assembled pair's material has a loading curve (a contact
   !! without one would be rigid).
   subroutine check_contact_materials(m, orig, err)
      type(model_t), intent(in) :: m
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(contact_pair_t), allocatable :: pairs(:)
      type(card_t) :: rim, interior
      integer :: q, l, k, lb
      integer, allocatable :: source(:)
      logical :: reported(32)
      allocate (source(0))      ! (realloc on assignment: a descriptor set first)
      do q = 1, size(surface_codes)
         k = surface_codes(q)
         source = surface_sources(k)
         if (size(source) < 2) cycle
         if (m%interior%given(k) .and. .not. m%interior%given(source(2))) call problem(orig, err, &
            indexed_card(orig, g_surfaces, k), 'surface '//itoa(k)//' ('//surface_name(k) &
            //') follows from surface '//itoa(source(2))//' ('//surface_name(source(2))//') by f.2''s relations: ' &
            //'give surface '//itoa(source(2))//' a *SURFACES card too')
      end do
      allocate (pairs(0))      ! (realloc on assignment: a descriptor set first)
      pairs = scene_pairs(m)
      rim = indexed_card(orig, g_surfaces, 10)
      interior = first_card(orig, g_interior)
      ! an opening narrower than a body point's arc would flip its force at the
      ! middle (only the nearer edge acts): refused (review of issue 7)
      ! D-C12: the driver's side rim 10* needs DS (0 < D_s <= D_10) once the
      ! wheel is described; without it the pairs (5, 10*) and (10, 10*),
      ! undesired contacts of Table 9, would be left out without a word
      if (m%options%nbody == 1 .and. m%interior%given(10) .and. m%interior%given(8)) then
         if (.not. m%interior%ds > 0.0_wp) then
            if (has_card(orig, g_interior)) then
               call problem(orig, err, interior, 'blank, but the driver''s wheel ('//card_ref(orig, rim) &
                  //') needs the side rim''s equivalent length D_s for the shoulder and hand pairs (10*, D-C12); ' &
                  //'expected 0 < DS <= D = '//num(m%interior%d(10))//' in', 'DS')
            else
               call problem(orig, err, rim, 'the driver''s wheel needs the side rim''s equivalent length D_s for ' &
                  //'the shoulder and hand pairs (10*, D-C12): give an *INTERIOR card with ' &
                  //field_where(orig, g_interior, 'DS')//', 0 < DS <= D = '//num(m%interior%d(10))//' in', 'D')
            end if
         else if (m%interior%ds > m%interior%d(10)) then
            call problem(orig, err, interior, 'DS = '//num(m%interior%ds)//' in: the side rim cannot be longer ' &
               //'than the rim, D = '//num(m%interior%d(10))//' in ('//card_ref(orig, rim)//', D-C12)', 'DS')
         end if
      end if
      if (m%interior%di > 0.0_wp) then
         ! an opening as wide as the rim would leave no rim (D-C11)
         if (m%interior%given(10) .and. .not. m%interior%di < m%interior%d(10)) call problem(orig, err, interior, &
            'DI = '//num(m%interior%di)//' in: the rim''s opening must be narrower than the rim, D = ' &
            //num(m%interior%d(10))//' in ('//card_ref(orig, rim)//')', 'DI')
         do q = 1, size(pairs)
            if (pairs(q)%k /= 10) cycle
            if (m%interior%di < 2.0_wp*m%body%r_arc(pairs(q)%i)) call problem(orig, err, interior, &
               'DI = '//num(m%interior%di)//' in: the rim''s opening is narrower than the arc of body point ' &
               //itoa(pairs(q)%i)//' (diameter '//num(2.0_wp*m%body%r_arc(pairs(q)%i))//' in, ' &
               //card_ref(orig, indexed_card(orig, g_arcs, pairs(q)%i))//'), which would meet both its edges; ' &
               //'give DI at least that, or 0 for no opening', 'DI')
         end do
      end if
      ! the shin (body point 9) is the common tangent of the knee and ankle
      ! circles (D-C2, alpha_0 of C.2): it needs |r_7 - r_A| < L8
      if (any(pairs%i == 9) .and. .not. abs(m%body%r_arc(7) - m%body%r_arc(11)) < m%body%length(8)) &
         call problem(orig, err, indexed_card(orig, g_arcs, 7), 'the shin''s contacts need |r_7 - r_A| < L8 ' &
            //'(the knee arc here, the ankle arc of '//card_ref(orig, indexed_card(orig, g_arcs, 11)) &
            //' and the lower leg''s length of '//card_ref(orig, indexed_card(orig, g_segments, 8))//'): here |' &
            //num(m%body%r_arc(7))//' - '//num(m%body%r_arc(11))//'| against '//num(m%body%length(8))//' in', 'R')
      if (m%options%nend == nend_contact) then
         if (.not. any([(is_undesired(m%options%nbody, pairs(q)%i, pairs(q)%k), q=1, size(pairs))])) &
            call problem(orig, err, first_card(orig, g_options), 'NEND = 2: the undesired-contact test ' &
                         //'needs a contact of Table 9 for NBODY '//itoa(m%options%nbody)//' among the pairs the ' &
                         //'deck''s *SURFACES assemble (docs/contacts.md)', 'NEND')
      end if
      reported = .false.
      do q = 1, size(pairs)
         k = pairs(q)%k
         if (reported(k)) cycle
         call surface_layers(m%interior, k, l, lb)
         if (m%loading%material_curve(l) == 0) then
            reported(k) = .true.
            call material_problem(k, l, 'surface '//itoa(k)//' ('//surface_name(k)//') is made of material ' &
               //itoa(l)//', which has no loading curve, so the contact of body point '//itoa(pairs(q)%i) &
               //' with it would be rigid; expected the number of a curve')
         else if (lb > 0) then
            if (m%loading%material_curve(lb) == 0) then
               reported(k) = .true.
               call material_problem(k, lb, 'surface '//itoa(k)//' ('//surface_name(k)//'): its padding bottoms ' &
                  //'out at ETA*DPP onto material '//itoa(lb)//', which has no loading curve; expected the ' &
                  //'number of a curve, or DPP = 0 on *SURFACES for no padding')
            end if
         end if
         ! D-C18a: the contacts' friction ramps up to mu P over XI; with XI = 0
         ! it is the bare Coulomb sign, which an adaptive step cannot resolve
         if (.not. reported(k) .and. m%materials%mu(l) > 0.0_wp .and. .not. m%materials%xi(l) > 0.0_wp) then
            reported(k) = .true.
            call material_problem(k, l, 'surface '//itoa(k)//' ('//surface_name(k)//') is made of material ' &
               //itoa(l)//', whose friction MU > 0 has XI = 0: the contacts'' friction ramps up to MU P over ' &
               //'the sliding velocity XI (docs/contacts.md D-C18a); expected XI > 0 (4 in/s in the shipped ' &
               //'interiors)', 'XI')
         end if
      end do
   contains
      !> At material l's *MATERIALS card and its field (CURVE when not
      !! given), naming surface k's card, when the deck has one; else at
      !! surface k's *SURFACES card, naming the card to give.
      subroutine material_problem(k, l, message, field)
         integer, intent(in) :: k, l
         character(len=*), intent(in) :: message
         character(len=*), intent(in), optional :: field
         character(len=:), allocatable :: name
         type(card_t) :: c
         name = 'CURVE'
         if (present(field)) name = field
         c = indexed_card(orig, g_materials, l)
         if (c%number > 0) then
            call problem(orig, err, c, 'material '//itoa(l)//': '//message//' ('//card_ref(orig, &
                         indexed_card(orig, g_surfaces, k))//')', name)
         else
            call problem(orig, err, indexed_card(orig, g_surfaces, k), message//': give material '//itoa(l) &
                         //' a *MATERIALS card with '//field_where(orig, g_materials, name))
         end if
      end subroutine material_problem
   end subroutine check_contact_materials


   !> D-C14 (7): a *SURFACES card that builds nothing - no pair of the
   !! scene strikes the surface or one that f.2's relations derive from it
   !! (the upper panel and the roof from the windshield, the rim and the
   !! side rim from the column, the floor from the toeboard, the panel's edge
   !! from the lower panel) - is most likely a slip (another occupant
   !! position's surface, a pair switched off): a warning at its card.
   subroutine warn_unused_surfaces(m, orig)
      type(model_t), intent(inout) :: m
      type(model_origin_t), intent(in) :: orig
      type(card_t), allocatable :: cs(:)
      type(contact_pair_t), allocatable :: pairs(:)
      logical :: used(32)
      integer :: q, k
      allocate (pairs(0))
      pairs = scene_pairs(m)
      used = .false.
      do q = 1, size(pairs)
         used(surface_sources(pairs(q)%k)) = .true.
      end do
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_surfaces)
      do q = 1, size(cs)
         k = cs(q)%index
         if (k < 1 .or. k > size(used)) cycle
         if (used(k)) cycle
         call warning(orig, m%warnings, cs(q), 'surface '//itoa(k)//' (' &
            //surface_name(k)//') builds nothing: no pair of NBODY '//itoa(m%options%nbody) &
            //' strikes it (Tables 7, 8, less *CONTACTOFF) nor a surface derived from it')
      end do
   end subroutine warn_unused_surfaces


   !> D-C14 (7): a surface's PSI outside the range its orientation allows
   !! (docs/contacts.md 2.1: the occupant is on the left of e(PSI), so a
   !! reversed angle turns the surface's face away from him) - a warning at
   !! its card. The circle, the lines and the derived surfaces have none.
   subroutine warn_surface_angles(m, orig)
      type(model_t), intent(inout) :: m
      type(model_origin_t), intent(in) :: orig
      type(card_t), allocatable :: cs(:)
      integer, parameter :: n_ranged = 11
      integer, parameter :: code(n_ranged) = [21, 2, 3, 4, 5, 6, 7, 8, 9, 29, 26]
      real(wp), parameter :: low(n_ranged) = [45.0_wp, 95.0_wp, 45.0_wp, -45.0_wp, 45.0_wp, 10.0_wp, 45.0_wp, &
                                              20.0_wp, -135.0_wp, -135.0_wp, 0.0_wp]
      real(wp), parameter :: high(n_ranged) = [135.0_wp, 175.0_wp, 180.0_wp, 60.0_wp, 135.0_wp, 80.0_wp, 150.0_wp, &
                                               110.0_wp, -45.0_wp, -45.0_wp, 80.0_wp]
      real(wp) :: psi
      integer :: q, k, r
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_surfaces)
      do q = 1, size(cs)
         k = cs(q)%index
         r = findloc(code, k, 1)
         if (r == 0) cycle
         if (.not. field_given(orig, g_surfaces, cs(q), 'PSI')) cycle
         psi = modulo(m%interior%psi(k)/deg + 180.0_wp, 360.0_wp) - 180.0_wp   ! (-180, 180]
         if (psi <= -180.0_wp) psi = psi + 360.0_wp
         if (psi >= low(r) .and. psi <= high(r)) cycle
         call warning(orig, m%warnings, cs(q), 'surface '//itoa(k)//' (' &
            //surface_name(k)//'): PSI = '//num(psi)//' deg is outside the usual ' &
            //num(low(r))//' to '//num(high(r))//' deg (docs/contacts.md 2.1): the occupant must be on the ' &
            //'left of e(PSI), the direction from the far end to (X, Y); is the angle reversed?', 'PSI')
      end do
   end subroutine warn_surface_angles


   !> The interior as the scene will assemble it, once the model is
   !! otherwise sound (D-C14): check_contact_materials, then the warnings of
   !! surfaces that build nothing and of angles outside their usual range,
   !! and of an NBODY that selects nothing.
   subroutine check_scene(m, orig, err)
      type(model_t), intent(inout) :: m
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      if (.not. err%failed()) call check_contact_materials(m, orig, err)
      if (.not. err%failed()) call warn_unused_surfaces(m, orig)
      if (.not. err%failed()) call warn_surface_angles(m, orig)
      if (m%options%nbody /= 1 .and. .not. any(m%interior%given)) call warning(orig, m%warnings, &
         first_card(orig, g_options), 'NBODY = '//itoa(m%options%nbody)//' (the ' &
         //trim(merge('front-seat passenger', 'rear-seat passenger ', m%options%nbody == 2))//') selects the ' &
         //'interior contacts (Tables 7, 8); without *SURFACES it changes nothing', 'NBODY')
   end subroutine check_scene
end module interior_input
