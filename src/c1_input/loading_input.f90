!> The materials and loading curves from the deck (report C.1, C.4.e,
!! C.4.f, Tables 2 and 4; docs/loading.md): *MATERIALS, *LOADPOLY or
!! *LOADTABLE (as NLOAD selects) with *LOADRATE, and *BELTLOADING - each
!! section's builder, which reads the fields by the names of the card
!! table, and its validator, which checks what single fields cannot: the
!! fields each material takes, orders, curves that never pull, curves that
!! exist, R <= 1 - G.
module loading_input
   use kinds, only: wp
   use error_handling, only: error_t
   use strings, only: itoa
   use text_io, only: string_t
   use deck_cards, only: g_options, g_materials, g_loadpoly, g_loadrate, g_loadtable, g_beltloading
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, card_int, card_given, default_value
   use model_origin, only: model_origin_t, cards, group_present, field_given, header_of, first_card, indexed_card, &
      card_ref, problem, warning
   use model, only: materials_section_t, loading_section_t, max_curves
   use loading_parameters, only: loading_curve_t, curve_polynomial, curve_table, curve_is_defined, curve_check, &
      max_order, recurrent_check
   implicit none
   private

   public :: build_materials, check_materials, build_loading, check_loading

   character(len=1), parameter :: digit(max_order) = ['1', '2', '3', '4', '5']

contains

   !> Table 4: the materials the deck gives; the others keep the section's
   !! values (no friction, elastic) and the XI default.
   subroutine build_materials(deck, mat)
      type(deck_t), intent(in) :: deck
      type(materials_section_t), intent(out) :: mat
      integer :: k, l
      mat%xi = default_value(deck, g_materials, 'XI')
      associate (g => deck%group(g_materials))
         do k = 1, g%n
            l = g%card(k)%index
            mat%mu(l) = card_value(deck, g_materials, g%card(k), 'MU')
            mat%xi(l) = card_value(deck, g_materials, g%card(k), 'XI')
            mat%g(l) = card_value(deck, g_materials, g%card(k), 'G')
            mat%r(l) = card_value(deck, g_materials, g%card(k), 'R')
            mat%given(l) = .true.
            ! Table 4's "other": eta for padding and floormat, FSW for glass
            mat%eta(l) = card_value(deck, g_materials, g%card(k), 'ETA')
            if (card_given(deck, g_materials, g%card(k), 'FSW') .and. l == 2) &
               mat%fsw = card_value(deck, g_materials, g%card(k), 'FSW')
         end do
      end associate
   end subroutine build_materials

   !> Table 4's "other" fields: ETA for padding (3) and floormat (4), FSW
   !! for glass (2) only. (G and R: with the loading, check_loading.)
   subroutine check_materials(orig, err)
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      integer :: k, l
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_materials)
      do k = 1, size(cs)
         l = cs(k)%index
         if (field_given(orig, g_materials, cs(k), 'ETA') .and. .not. any(l == [3, 4])) &
            call problem(orig, err, cs(k), 'material '//itoa(l)//': ETA belongs to padding (3) and ' &
                         //'floormat (4) only; expected blank', 'ETA')
         if (field_given(orig, g_materials, cs(k), 'FSW') .and. l /= 2) &
            call problem(orig, err, cs(k), 'material '//itoa(l)//': FSW belongs to glass (2) only; ' &
                         //'expected blank', 'FSW')
      end do
   end subroutine check_materials

   !> Loading curves (C.4.e, C.4.f; docs/loading.md): those of the form NLOAD
   !! selects (*LOADPOLY or *LOADTABLE) with their *LOADRATE terms, the curve
   !! each material (*MATERIALS CURVE) and belt section (*BELTLOADING) names.
   subroutine build_loading(deck, nload, ld)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: nload
      type(loading_section_t), intent(out) :: ld
      integer :: k, i, n

      if (nload == 1) then
         call build_polynomials(deck, ld)
      else
         call build_tables(deck, ld)
      end if
      associate (g => deck%group(g_loadrate))
         do k = 1, g%n
            i = g%card(k)%index
            if (.not. curve_is_defined(ld%curve(i))) cycle   ! (refused by check_loading)
            do n = 1, max_order
               ld%curve(i)%sigma_rate(n) = card_value(deck, g_loadrate, g%card(k), 'RATE'//digit(n))
            end do
         end do
      end associate
      associate (g => deck%group(g_materials))
         do k = 1, g%n
            ld%material_curve(g%card(k)%index) = card_int(deck, g_materials, g%card(k), 'CURVE')
         end do
      end associate
      associate (g => deck%group(g_beltloading))
         do k = 1, g%n
            i = g%card(k)%index
            ld%belt_curve(i) = card_int(deck, g_beltloading, g%card(k), 'CURVE')
            ld%belt_g(i) = card_value(deck, g_beltloading, g%card(k), 'G')
            ld%belt_r(i) = card_value(deck, g_beltloading, g%card(k), 'R')
         end do
      end associate
   end subroutine build_loading

   !> The polynomial curves of *LOADPOLY (NLOAD = 1): coefficients up to
   !! the order N.
   subroutine build_polynomials(deck, ld)
      type(deck_t), intent(in) :: deck
      type(loading_section_t), intent(inout) :: ld
      type(loading_curve_t) :: cv
      integer :: k, n
      associate (g => deck%group(g_loadpoly))
         do k = 1, g%n
            cv = loading_curve_t()
            cv%form = curve_polynomial
            cv%order = card_int(deck, g_loadpoly, g%card(k), 'N')
            do n = 1, min(cv%order, max_order)
               cv%sigma(n) = card_value(deck, g_loadpoly, g%card(k), 'SIGMA'//digit(n))
            end do
            ld%curve(g%card(k)%index) = cv
         end do
      end associate
   end subroutine build_polynomials

   !> The tabulated curves of *LOADTABLE (NLOAD = 2): the points of each
   !! curve in the order of its cards.
   subroutine build_tables(deck, ld)
      type(deck_t), intent(in) :: deck
      type(loading_section_t), intent(inout) :: ld
      integer, allocatable :: cards(:)
      integer :: k, i
      associate (g => deck%group(g_loadtable))
         do i = 1, max_curves
            cards = pack([(k, k=1, g%n)], [(g%card(k)%index == i, k=1, g%n)])
            if (size(cards) == 0) cycle
            associate (cv => ld%curve(i))
               cv%form = curve_table
               cv%defl = [(card_value(deck, g_loadtable, g%card(cards(k)), 'DEFL'), k=1, size(cards))]
               cv%force = [(card_value(deck, g_loadtable, g%card(cards(k)), 'FORCE'), k=1, size(cards))]
            end associate
         end do
      end associate
   end subroutine build_tables

   !> The curves of the selected form (curve_check), the other form's group
   !! not used (a warning), the rate terms of curves that exist within their
   !! order, the curves the materials and belt sections name, and their G
   !! and R (recurrent_check).
   subroutine check_loading(ld, mat, nload, orig, warnings, err)
      type(loading_section_t), intent(in) :: ld
      type(materials_section_t), intent(in) :: mat
      integer, intent(in) :: nload
      type(model_origin_t), intent(in) :: orig
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      character(len=:), allocatable :: where, selected
      type(error_t) :: law
      integer :: k, i, n

      selected = trim(merge('*LOADPOLY ', '*LOADTABLE', nload == 1))
      if (nload == 1) then
         call check_polynomials(ld, orig, err)
         call unused(g_loadtable, '*LOADPOLY')
      else
         call check_tables(ld, orig, err)
         call unused(g_loadpoly, '*LOADTABLE')
      end if

      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_loadrate)
      do k = 1, size(cs)
         i = cs(k)%index
         where = 'curve '//itoa(i)
         if (.not. curve_is_defined(ld%curve(i))) then
            call problem(orig, err, cs(k), 'curve k (columns 1-2) = '//itoa(i)//': no such curve in ' &
               //selected//' (NLOAD = '//itoa(nload)//' of '//card_ref(orig, first_card(orig, g_options))//')')
            cycle
         end if
         do n = 1, max_order
            if (ld%curve(i)%form == curve_polynomial .and. n > ld%curve(i)%order .and. &
                field_given(orig, g_loadrate, cs(k), 'RATE'//digit(n))) &
               call problem(orig, err, cs(k), where//': beyond the order N = '//itoa(ld%curve(i)%order) &
               //' of the curve ('//card_ref(orig, indexed_card(orig, g_loadpoly, i))//'; the report pairs ' &
               //'sigma_n+N with sigma_n); expected blank', 'RATE'//digit(n))
         end do
      end do

      call check_laws(g_materials, 'material ', ld%material_curve, mat%g, mat%r)
      call check_laws(g_beltloading, 'section ', ld%belt_curve, ld%belt_g, ld%belt_r)
   contains
      !> The laws of group gid's rows (materials, belt sections: what): the
      !! curve each names, its G and R.
      subroutine check_laws(gid, what, curve, g, r)
         integer, intent(in) :: gid, curve(:)
         character(len=*), intent(in) :: what
         real(wp), intent(in) :: g(:), r(:)
         cs = cards(orig, gid)
         do k = 1, size(cs)
            i = cs(k)%index
            where = what//itoa(i)
            call check_reference(cs(k), curve(i))
            law = error_t()
            call recurrent_check(g(i), r(i), law)
            if (law%failed()) call problem(orig, err, cs(k), where//': '//law%message, 'G R')
         end do
      end subroutine check_laws
      !> A curve named on a card must exist in the selected form.
      subroutine check_reference(c, curve)
         type(card_t), intent(in) :: c
         integer, intent(in) :: curve
         if (curve < 1 .or. curve > max_curves) return
         if (.not. curve_is_defined(ld%curve(curve))) call problem(orig, err, c, where//': no curve ' &
            //itoa(curve)//' in '//selected//' (NLOAD = '//itoa(nload)//' of '//card_ref(orig, &
            first_card(orig, g_options))//')', 'CURVE')
      end subroutine check_reference
      !> The other form's group is read but not used: say so.
      subroutine unused(gid, used)
         integer, intent(in) :: gid
         character(len=*), intent(in) :: used
         if (.not. group_present(orig, gid)) return
         call warning(orig, warnings, header_of(orig, gid), 'not used: NLOAD = '//itoa(nload) &
            //' ('//card_ref(orig, first_card(orig, g_options))//') selects '//used)
      end subroutine unused
   end subroutine check_loading

   !> Each polynomial curve: no coefficient beyond its order N, and what
   !! curve_check finds (at N, or at the coefficients).
   subroutine check_polynomials(ld, orig, err)
      type(loading_section_t), intent(in) :: ld
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      character(len=:), allocatable :: where, fields
      type(error_t) :: curve
      integer :: k, i, n, point
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_loadpoly)
      do k = 1, size(cs)
         i = cs(k)%index
         where = 'curve '//itoa(i)
         associate (cv => ld%curve(i))
            do n = max(cv%order, 0) + 1, max_order
               if (field_given(orig, g_loadpoly, cs(k), 'SIGMA'//digit(n))) call problem(orig, err, cs(k), &
                  where//': beyond the order N = '//itoa(cv%order)//'; leave it blank or raise N', 'N SIGMA'//digit(n))
            end do
            curve = error_t()
            call curve_check(cv, point, curve)
            if (curve%failed()) then
               if (index(curve%message, 'order') > 0) then
                  fields = 'N'
               else
                  fields = ''
                  do n = 1, max(1, min(cv%order, max_order))
                     fields = fields//' SIGMA'//digit(n)
                  end do
               end if
               call problem(orig, err, cs(k), where//': '//curve%message, fields)
            end if
         end associate
      end do
   end subroutine check_polynomials

   !> Each tabulated curve, at the card of the point curve_check names (its
   !! last, when it names none).
   subroutine check_tables(ld, orig, err)
      type(loading_section_t), intent(in) :: ld
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:), points(:)
      type(error_t) :: curve
      integer :: k, i, point
      allocate (cs(0), points(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_loadtable)
      do i = 1, max_curves
         if (ld%curve(i)%form /= curve_table) cycle
         points = pack(cs, [(cs(k)%index == i, k=1, size(cs))])
         curve = error_t()
         call curve_check(ld%curve(i), point, curve)
         if (curve%failed()) then
            if (point < 1) point = size(points)
            if (point >= 1 .and. point <= size(points)) then
               call problem(orig, err, points(point), 'curve '//itoa(i)//', point '//itoa(point)//': '//curve%message, &
                            'DEFL FORCE')
            else
               call problem(orig, err, header_of(orig, g_loadtable), 'curve '//itoa(i)//', point '//itoa(point) &
                            //': '//curve%message, 'DEFL FORCE')
            end if
         end if
      end do
   end subroutine check_tables
end module loading_input
