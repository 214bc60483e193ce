!> Turns the plain tables of a deck into the model (report C.1): one builder
!! per section of model_t, each reading its fields by the names of the card
!! table, and each checking what single fields cannot: relations between
!! fields (omega < Omega, times increasing, the step dividing the print
!! interval, ...), and the options this version supports. Every problem is
!! reported with the file and line of the card concerned.
module model_builder
   use kinds, only: wp, deg
   use error_handling, only: error_t, error_append, exit_deck
   use strings, only: itoa, num, escaped
   use text_io, only: append_string
   use deck_cards, only: g_title, g_options, g_time, g_segments, g_joints, g_restraints, &
      g_stopcurve, g_injury, g_arcs, g_initial, g_vehicle, g_gravity, g_pulse, g_pulserates, &
      g_pulsepos, g_pulsefile, g_endtests, g_numerics, g_materials, &
      g_loadpoly, g_loadrate, g_loadtable, g_beltloading, g_seat, g_seatsprings, g_seatbeam, &
      g_seatbeaminit, g_seatbeams, g_belts, g_beltoptions, g_surfaces, g_interior, g_contactoff
   use deck_reader, only: deck_t, group_t, card_t, deck_names
   use deck_fields, only: card_value, card_int, card_given, group_value, group_int, single_card, default_value, &
      group_given
   use seat_beam_statics, only: beam_statics_t, beam_statics_solve, n_beam_quantities, beam_quantity_name, &
      statics_ok, bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   use pulse_csv, only: read_pulse_csv
   use vehicle_motion, only: vehicle_motion_t, vehicle_state_t, vehicle_motion_init, vehicle_state_at
   use contact_tables, only: contact_pair_t, position_pairs, surface_code_valid, surface_name, is_undesired, &
      surface_codes
   use interior_pairs, only: scene_pairs, surface_layers, surface_sources
   use model, only: interior_section_t
   use model, only: model_t, pulse_table_t, stop_curve_t, options_section_t, time_section_t, &
      numerics_section_t, body_section_t, joints_section_t, injury_section_t, vehicle_section_t, &
      materials_section_t, &
      environment_section_t, end_tests_section_t, n_seg, n_joint, n_arc, joint_partner, &
      form_cubic, form_table, nint_adams, nint_rk4, nend_contact, loading_section_t, max_curves, &
      seat_none, seat_springs, seat_rigid_beam, seat_beams, seat_form_name, &
      belts_section_t, n_belt_card, n_belt_section, belt_card_lap2, coupling_torso, coupling_all, &
      nbelt_lap, nbelt_torso
   use text_io, only: string_t
   use loading_parameters, only: loading_curve_t, curve_polynomial, curve_table, curve_is_defined, &
      curve_check, max_order, recurrent_check
   implicit none
   private

   public :: build_model

contains

   !> Fill m from the deck's tables, section by section; append every
   !! problem found to err.
   subroutine build_model(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err

      m%warnings = deck%warnings
      m%title = ' '
      if (single_card(deck, g_title)) m%title = deck%group(g_title)%card(1)%text
      call build_options(deck, m%options)
      call build_time(deck, m%options%nint, m%time, err)
      call build_numerics(deck, m%numerics)
      call build_body(deck, m%body, err)
      call build_joints(deck, m%body, m%joints, err)
      call build_injury(deck, m%injury, err)
      call build_materials(deck, m%materials, err)
      call build_loading(deck, m%options%nload, m%materials, m%loading, m%warnings, err)
      call build_belts(deck, m%options%nbelt, m%body, m%loading, m%belts, m%warnings, err)
      call build_vehicle(deck, m%vehicle, err)
      if (.not. err%failed()) call check_vehicle_tables(deck, m%vehicle, m%warnings, err)
      m%environment = environment_section_t(group_value(deck, g_gravity, 'G'))
      m%end_tests = end_tests_section_t(group_value(deck, g_endtests, 'VREST'), &
                                        group_value(deck, g_endtests, 'WREST'), &
                                        group_value(deck, g_endtests, 'THOLD'))
      call build_seat(deck, m, err)
      call build_interior(deck, m%options%nbody, m%interior, err)
      if (.not. err%failed()) call check_contact_materials(deck, m, err)
      if (.not. err%failed()) call warn_unused_surfaces(deck, m)
      if (.not. err%failed()) call warn_surface_angles(deck, m)
      if (m%options%nbody /= 1 .and. .not. any(m%interior%given)) call append_string(m%warnings, &
         located(deck, first_card(deck, g_options), 'NBODY = '//itoa(m%options%nbody)//' (the ' &
         //trim(merge('front-seat passenger', 'rear-seat passenger ', m%options%nbody == 2))//') selects the ' &
         //'interior contacts (Tables 7, 8); without *SURFACES it changes nothing', 'NBODY'))
   end subroutine build_model

   !> D-C14: the surfaces f.2's relations derive from are described, and
   !! every assembled pair's material has a loading curve (a contact
   !! without one would be rigid).
   subroutine check_contact_materials(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(in) :: m
      type(error_t), intent(inout) :: err
      type(contact_pair_t), allocatable :: pairs(:)
      type(card_t) :: rim, interior
      integer :: q, l, k, lb
      integer, allocatable :: source(:)
      logical :: reported(32)
      do q = 1, size(surface_codes)
         k = surface_codes(q)
         source = surface_sources(k)
         if (size(source) < 2) cycle
         if (m%interior%given(k) .and. .not. m%interior%given(source(2))) call problem(deck, err, &
            indexed_card(deck, g_surfaces, k), 'surface '//itoa(k)//' ('//surface_name(k) &
            //') follows from surface '//itoa(source(2))//' ('//surface_name(source(2))//') by f.2''s relations: ' &
            //'give surface '//itoa(source(2))//' a *SURFACES card too')
      end do
      allocate (pairs(0))      ! (realloc on assignment: a descriptor set first)
      pairs = scene_pairs(m)
      rim = indexed_card(deck, g_surfaces, 10)
      interior = first_card(deck, g_interior)
      ! an opening narrower than a body point's arc would flip its force at the
      ! middle (only the nearer edge acts): refused (review of issue 7)
      ! D-C12: the driver's side rim 10* needs DS (0 < D_s <= D_10) once the
      ! wheel is described; without it the pairs (5, 10*) and (10, 10*),
      ! undesired contacts of Table 9, would be left out without a word
      if (m%options%nbody == 1 .and. m%interior%given(10) .and. m%interior%given(8)) then
         if (.not. m%interior%ds > 0.0_wp) then
            if (single_card(deck, g_interior)) then
               call problem(deck, err, interior, 'blank, but the driver''s wheel ('//card_ref(deck, rim) &
                  //') needs the side rim''s equivalent length D_s for the shoulder and hand pairs (10*, D-C12); ' &
                  //'expected 0 < DS <= D = '//num(m%interior%d(10))//' in', 'DS')
            else
               call problem(deck, err, rim, 'the driver''s wheel needs the side rim''s equivalent length D_s for ' &
                  //'the shoulder and hand pairs (10*, D-C12): give an *INTERIOR card with ' &
                  //field_where(deck, g_interior, 'DS')//', 0 < DS <= D = '//num(m%interior%d(10))//' in', 'D')
            end if
         else if (m%interior%ds > m%interior%d(10)) then
            call problem(deck, err, interior, 'DS = '//num(m%interior%ds)//' in: the side rim cannot be longer ' &
               //'than the rim, D = '//num(m%interior%d(10))//' in ('//card_ref(deck, rim)//', D-C12)', 'DS')
         end if
      end if
      if (m%interior%di > 0.0_wp) then
         ! an opening as wide as the rim would leave no rim (D-C11)
         if (m%interior%given(10) .and. .not. m%interior%di < m%interior%d(10)) call problem(deck, err, interior, &
            'DI = '//num(m%interior%di)//' in: the rim''s opening must be narrower than the rim, D = ' &
            //num(m%interior%d(10))//' in ('//card_ref(deck, rim)//')', 'DI')
         do q = 1, size(pairs)
            if (pairs(q)%k /= 10) cycle
            if (m%interior%di < 2.0_wp*m%body%r_arc(pairs(q)%i)) call problem(deck, err, interior, &
               'DI = '//num(m%interior%di)//' in: the rim''s opening is narrower than the arc of body point ' &
               //itoa(pairs(q)%i)//' (diameter '//num(2.0_wp*m%body%r_arc(pairs(q)%i))//' in, ' &
               //card_ref(deck, indexed_card(deck, g_arcs, pairs(q)%i))//'), which would meet both its edges; ' &
               //'give DI at least that, or 0 for no opening', 'DI')
         end do
      end if
      ! the shin (body point 9) is the common tangent of the knee and ankle
      ! circles (D-C2, alpha_0 of C.2): it needs |r_7 - r_A| < L8
      if (any(pairs%i == 9) .and. .not. abs(m%body%r_arc(7) - m%body%r_arc(11)) < m%body%length(8)) &
         call problem(deck, err, indexed_card(deck, g_arcs, 7), 'the shin''s contacts need |r_7 - r_A| < L8 ' &
            //'(the knee arc here, the ankle arc of '//card_ref(deck, indexed_card(deck, g_arcs, 11)) &
            //' and the lower leg''s length of '//card_ref(deck, indexed_card(deck, g_segments, 8))//'): here |' &
            //num(m%body%r_arc(7))//' - '//num(m%body%r_arc(11))//'| against '//num(m%body%length(8))//' in', 'R')
      if (m%options%nend == nend_contact) then
         if (.not. any([(is_undesired(m%options%nbody, pairs(q)%i, pairs(q)%k), q=1, size(pairs))])) &
            call problem(deck, err, first_card(deck, g_options), 'NEND = 2: the undesired-contact test ' &
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
         c = indexed_card(deck, g_materials, l)
         if (c%number > 0) then
            call problem(deck, err, c, 'material '//itoa(l)//': '//message//' ('//card_ref(deck, &
                         indexed_card(deck, g_surfaces, k))//')', name)
         else
            call problem(deck, err, indexed_card(deck, g_surfaces, k), message//': give material '//itoa(l) &
                         //' a *MATERIALS card with '//field_where(deck, g_materials, name))
         end if
      end subroutine material_problem
   end subroutine check_contact_materials

   !> The card of row i of an indexed group (the first, for a group that
   !! may hold several), or its header when the deck has none (a card's
   !! number is then 0; its source 0 when the group is absent).
   function indexed_card(deck, gid, i) result(c)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid, i
      type(card_t) :: c
      integer :: k
      do k = 1, deck%group(gid)%n
         if (deck%group(gid)%card(k)%index /= i) cycle
         c = deck%group(gid)%card(k)
         return
      end do
      c = header_of(deck, gid)
   end function indexed_card

   !> D-C14 (7): a *SURFACES card that builds nothing - no pair of the
   !! scene strikes the surface or one that f.2's relations derive from it
   !! (the upper panel and the roof from the windshield, the rim and the
   !! side rim from the column, the floor from the toeboard, the panel's edge
   !! from the lower panel) - is most likely a slip (another occupant
   !! position's surface, a pair switched off): a warning at its card.
   subroutine warn_unused_surfaces(deck, m)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(contact_pair_t), allocatable :: pairs(:)
      logical :: used(32)
      integer :: q, k
      allocate (pairs(0))
      pairs = scene_pairs(m)
      used = .false.
      do q = 1, size(pairs)
         used(surface_sources(pairs(q)%k)) = .true.
      end do
      associate (g => deck%group(g_surfaces))
         do q = 1, g%n
            k = g%card(q)%index
            if (k < 1 .or. k > size(used)) cycle
            if (used(k)) cycle
            call append_string(m%warnings, located(deck, g%card(q), 'surface '//itoa(k)//' (' &
               //surface_name(k)//') builds nothing: no pair of NBODY '//itoa(m%options%nbody) &
               //' strikes it (Tables 7, 8, less *CONTACTOFF) nor a surface derived from it'))
         end do
      end associate
   end subroutine warn_unused_surfaces

   !> D-C14 (7): a surface's PSI outside the range its orientation allows
   !! (docs/contacts.md 2.1: the occupant is on the left of e(PSI), so a
   !! reversed angle turns the surface's face away from him) - a warning at
   !! its card. The circle, the lines and the derived surfaces have none.
   subroutine warn_surface_angles(deck, m)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      integer, parameter :: n_ranged = 11
      integer, parameter :: code(n_ranged) = [21, 2, 3, 4, 5, 6, 7, 8, 9, 29, 26]
      real(wp), parameter :: low(n_ranged) = [45.0_wp, 95.0_wp, 45.0_wp, -45.0_wp, 45.0_wp, 10.0_wp, 45.0_wp, &
                                              20.0_wp, -135.0_wp, -135.0_wp, 0.0_wp]
      real(wp), parameter :: high(n_ranged) = [135.0_wp, 175.0_wp, 180.0_wp, 60.0_wp, 135.0_wp, 80.0_wp, 150.0_wp, &
                                               110.0_wp, -45.0_wp, -45.0_wp, 80.0_wp]
      real(wp) :: psi
      integer :: q, k, r
      associate (g => deck%group(g_surfaces))
         do q = 1, g%n
            k = g%card(q)%index
            r = findloc(code, k, 1)
            if (r == 0) cycle
            if (.not. card_given(deck, g_surfaces, g%card(q), 'PSI')) cycle
            psi = modulo(m%interior%psi(k)/deg + 180.0_wp, 360.0_wp) - 180.0_wp   ! (-180, 180]
            if (psi <= -180.0_wp) psi = psi + 360.0_wp
            if (psi >= low(r) .and. psi <= high(r)) cycle
            call append_string(m%warnings, located(deck, g%card(q), 'surface '//itoa(k)//' (' &
               //surface_name(k)//'): PSI = '//num(psi)//' deg is outside the usual ' &
               //num(low(r))//' to '//num(high(r))//' deg (docs/contacts.md 2.1): the occupant must be on the ' &
               //'left of e(PSI), the direction from the far end to (X, Y); is the angle reversed?', 'PSI'))
         end do
      end associate
   end subroutine warn_surface_angles

   !> *SURFACES, *INTERIOR, *CONTACTOFF (C.4.f, Table 3; docs/contacts.md
   !! 2.4): each surface's fields as Table 3 marks them, the ones f.2's
   !! relations derive left blank (D-C5), the pairs left out belonging to
   !! the occupant's position (D-C13).
   subroutine build_interior(deck, nbody, it, err)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: nbody
      type(interior_section_t), intent(out) :: it
      type(error_t), intent(inout) :: err
      character(len=3), parameter :: names(4) = ['X  ', 'Y  ', 'PSI', 'D  ']
      type(contact_pair_t), allocatable :: pairs(:)
      logical :: need(4), derived(4)
      integer :: q, k, f, i, kk, j, first
      associate (g => deck%group(g_surfaces))
         do q = 1, g%n
            k = g%card(q)%index
            if (.not. surface_code_valid(k)) then
               call problem(deck, err, g%card(q), 'surface i (columns 1-2) = '//itoa(k)//': not a surface of ' &
                            //'Table 3 or 7; expected 1-12, 21 (1*), 26 (6*), 29 (9*) or 32 (12*)')
               cycle
            end if
            call table3(k, need, derived)
            do f = 1, 4
               if (derived(f) .and. card_given(deck, g_surfaces, g%card(q), trim(names(f)))) then
                  call problem(deck, err, g%card(q), 'surface '//itoa(k)//' ('//surface_name(k)//'): ' &
                               //trim(names(f))//' follows from f.2''s relations; leave it blank', trim(names(f)))
               else if (need(f) .and. .not. card_given(deck, g_surfaces, g%card(q), trim(names(f)))) then
                  call problem(deck, err, g%card(q), 'surface '//itoa(k)//' ('//surface_name(k)//'): ' &
                               //trim(names(f))//' is required (Table 3)', trim(names(f)))
               end if
            end do
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
      allocate (pairs(0))
      pairs = position_pairs(nbody)
      allocate (it%off(2, 0))
      associate (g => deck%group(g_contactoff))
         do q = 1, g%n
            i = card_int(deck, g_contactoff, g%card(q), 'I')
            kk = card_int(deck, g_contactoff, g%card(q), 'K')
            if (.not. any(pairs%i == i .and. pairs%k == kk)) then
               call problem(deck, err, g%card(q), 'the pair ('//itoa(i)//', '//itoa(kk)//') is not one of NBODY ' &
                            //itoa(nbody)//'''s (Tables 7, 8; '//card_ref(deck, first_card(deck, g_options)) &
                            //'); body point '//itoa(i)//' has '//surfaces_of(i), 'I K')
               cycle
            end if
            first = findloc([(card_int(deck, g_contactoff, g%card(j), 'I') == i .and. &
                              card_int(deck, g_contactoff, g%card(j), 'K') == kk, j=1, q - 1)], .true., 1)
            if (first > 0) then
               call problem(deck, err, g%card(q), 'the pair ('//itoa(i)//', '//itoa(kk)//') is switched off twice ' &
                            //'(first by '//card_ref(deck, g%card(first))//')', 'I K')
               cycle
            end if
            it%off = reshape([it%off, [i, kk]], [2, size(it%off, 2) + 1])
         end do
      end associate
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
   end subroutine build_interior

   !> *OPTIONS (C.1). (NEND = 2 needs a contact of Table 9: checked with
   !! the interior, check_contact_materials.)
   subroutine build_options(deck, o)
      type(deck_t), intent(in) :: deck
      type(options_section_t), intent(out) :: o
      o%nbody = group_int(deck, g_options, 'NBODY')
      o%nbelt = group_int(deck, g_options, 'NBELT')
      o%nend = group_int(deck, g_options, 'NEND')
      o%nload = group_int(deck, g_options, 'NLOAD')
      o%nout = group_int(deck, g_options, 'NOUT')
      o%nint = group_int(deck, g_options, 'NINT')
   end subroutine build_options

   !> *TIME (C.3, C.6, C.7).
   subroutine build_time(deck, nint, tc, err)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: nint
      type(time_section_t), intent(out) :: tc
      type(error_t), intent(inout) :: err
      type(card_t) :: c
      character(len=:), allocatable :: integrator
      tc%t_max = group_value(deck, g_time, 'TMAX')
      tc%dt = group_value(deck, g_time, 'DT')
      tc%dt_print = group_value(deck, g_time, 'DTPRINT')
      tc%corrector_tol = group_value(deck, g_time, 'CTOL')
      tc%corrector_max_iter = group_int(deck, g_time, 'CITER')
      tc%rtol = group_value(deck, g_time, 'RTOL')
      tc%atol = group_value(deck, g_time, 'ATOL')
      c = first_card(deck, g_time)
      integrator = '(NINT = '//itoa(nint)//' of '//card_ref(deck, first_card(deck, g_options))//')'
      if (tc%dt > tc%dt_print) call problem(deck, err, c, 'DT = '//num(tc%dt) &
         //' s exceeds DTPRINT = '//num(tc%dt_print)//' s', 'DT DTPRINT')
      if (nint == nint_adams .or. nint == nint_rk4) then
         if (.not. whole_multiple(tc%t_max, tc%dt)) call problem(deck, err, c, 'TMAX = ' &
            //num(tc%t_max)//' s is not a whole multiple of DT = '//num(tc%dt)//' s, as the fixed-step ' &
            //'integrators need '//integrator, 'TMAX DT')
         if (.not. whole_multiple(tc%dt_print, tc%dt)) call problem(deck, err, c, 'DTPRINT = ' &
            //num(tc%dt_print)//' s is not a whole multiple of DT = '//num(tc%dt)//' s, as the fixed-step ' &
            //'integrators need '//integrator, 'DT DTPRINT')
      end if
      ! step and print counts must stay countable (and far from integer overflow)
      if (tc%t_max/tc%dt > 1.0e9_wp) call problem(deck, err, c, 'TMAX/DT = '//num(tc%t_max/tc%dt, 4) &
         //' steps: more than 1e9', 'TMAX DT')
      if (tc%dt_print/tc%dt > 1.0e9_wp) call problem(deck, err, c, 'DTPRINT/DT = '//num(tc%dt_print/tc%dt, 4) &
         //' steps: more than 1e9', 'DT DTPRINT')
   end subroutine build_time

   !> *NUMERICS: the program's own numerical controls.
   subroutine build_numerics(deck, nc)
      type(deck_t), intent(in) :: deck
      type(numerics_section_t), intent(out) :: nc
      nc%am_start = group_int(deck, g_numerics, 'ASTART')
      nc%solver = group_int(deck, g_numerics, 'SOLVER')
      nc%energy_tol = group_value(deck, g_numerics, 'EBTOL')
      nc%energy_continue = group_int(deck, g_numerics, 'EBFAIL') == 2
   end subroutine build_numerics

   !> Table 1 segment columns, the contact arcs and the initial position.
   subroutine build_body(deck, b, err)
      type(deck_t), intent(in) :: deck
      type(body_section_t), intent(out) :: b
      type(error_t), intent(inout) :: err
      integer :: k, i
      integer, parameter :: chain(6) = [1, 2, 3, 4, 5, 7]

      associate (g => deck%group(g_segments))
         do k = 1, g%n
            i = g%card(k)%index
            b%mass(i) = card_value(deck, g_segments, g%card(k), 'M')
            b%inertia(i) = card_value(deck, g_segments, g%card(k), 'I')
            b%length(i) = card_value(deck, g_segments, g%card(k), 'L')
            b%rho(i) = card_value(deck, g_segments, g%card(k), 'RHO')
         end do
         do k = 1, g%n
            i = g%card(k)%index
            ! the lengths that join segments together (section B) must be positive
            if (any(chain == i) .and. .not. b%length(i) > 0.0_wp) call problem(deck, err, g%card(k), &
               'segment '//itoa(i)//': L = '//num(b%length(i))//' in; expected L > 0 (it places the next joint; ' &
               //'section B)', 'L')
            if (any([1, 2, 5, 7] == i) .and. b%rho(i) > b%length(i) .and. b%length(i) > 0.0_wp) &
               call problem(deck, err, g%card(k), 'segment '//itoa(i)//': RHO = '//num(b%rho(i)) &
               //' in lies beyond the far joint (L = '//num(b%length(i))//' in)', 'L RHO')
         end do
      end associate
      associate (g => deck%group(g_initial))
         do k = 1, g%n
            i = g%card(k)%index
            b%theta0(i) = card_value(deck, g_initial, g%card(k), 'THETA')
            b%theta_dot0(i) = card_value(deck, g_initial, g%card(k), 'THETADOT')
         end do
      end associate
      associate (g => deck%group(g_arcs))
         do k = 1, g%n
            i = g%card(k)%index
            b%r_arc(i) = card_value(deck, g_arcs, g%card(k), 'R')
            if (i <= n_arc) then
               b%rho_arc(i) = card_value(deck, g_arcs, g%card(k), 'RHOP')
               b%gamma_arc(i) = card_value(deck, g_arcs, g%card(k), 'GAMMA')
            end if
            if (.not. any([2, 3, 4] == i) .and. card_given(deck, g_arcs, g%card(k), 'RHOP')) &
               call problem(deck, err, g%card(k), 'arc '//itoa(i)//': RHOP is defined for arcs 2-4 only (Table 1); ' &
               //'expected blank', 'RHOP')
            if (.not. any([2, 3] == i) .and. card_given(deck, g_arcs, g%card(k), 'GAMMA')) &
               call problem(deck, err, g%card(k), 'arc '//itoa(i)//': GAMMA is defined for arcs 2-3 only (Table 1); ' &
               //'expected blank', 'GAMMA')
         end do
      end associate
   end subroutine build_body

   !> Table 1 joint columns, the restraint forms and their curves. The
   !! initial relative angles of the body must lie between the stops.
   subroutine build_joints(deck, body, jt, err)
      type(deck_t), intent(in) :: deck
      type(body_section_t), intent(in) :: body
      type(joints_section_t), intent(out) :: jt
      type(error_t), intent(inout) :: err
      integer :: k, i, side
      type(card_t) :: rc
      real(wp) :: rel0

      jt%xi = group_value(deck, g_joints, 'XI')   ! the default, for joints without a card
      associate (g => deck%group(g_joints))
         do k = 1, g%n
            i = g%card(k)%index
            jt%k_elastic(i) = card_value(deck, g_joints, g%card(k), 'K')
            jt%c_friction(i) = card_value(deck, g_joints, g%card(k), 'CF')
            jt%xi(i) = card_value(deck, g_joints, g%card(k), 'XI')
            associate (r => jt%restraint(i))
               r%lower = card_value(deck, g_joints, g%card(k), 'OMEGA')
               r%upper = card_value(deck, g_joints, g%card(k), 'BOMEGA')
               r%coef_lower = [card_value(deck, g_joints, g%card(k), 'TLOW'), 0.0_wp, 0.0_wp]
               r%coef_upper = [card_value(deck, g_joints, g%card(k), 'THIGH'), 0.0_wp, 0.0_wp]
               r%dislocation_lower = r%lower
               r%dislocation_upper = r%upper
               if (.not. r%lower < r%upper) then
                  call problem(deck, err, g%card(k), 'joint '//itoa(i)//': OMEGA = '//num(r%lower/deg) &
                     //' deg must be less than BOMEGA = '//num(r%upper/deg)//' deg', 'OMEGA BOMEGA')
               else if (deck%group(g_initial)%present) then
                  ! the stops act on the relative angle alpha_i - alpha_m itself (docs/errata.md D-3)
                  rel0 = body%theta0(i) - body%theta0(joint_partner(i))
                  if (rel0 < r%lower .or. rel0 > r%upper) &
                     call problem(deck, err, g%card(k), 'joint '//itoa(i)//': the initial relative angle ' &
                     //'Theta_'//itoa(i)//' - Theta_'//itoa(joint_partner(i))//' = '//num(rel0/deg) &
                     //' deg lies outside OMEGA..BOMEGA = '//num(r%lower/deg)//'..'//num(r%upper/deg)//' deg (' &
                     //card_ref(deck, indexed_card(deck, g_initial, i))//' and ' &
                     //card_ref(deck, indexed_card(deck, g_initial, joint_partner(i)))//')', 'OMEGA BOMEGA')
               end if
            end associate
         end do
      end associate

      associate (g => deck%group(g_restraints))
         do k = 1, g%n
            i = g%card(k)%index
            associate (r => jt%restraint(i), c => g%card(k))
               r%form = card_int(deck, g_restraints, c, 'FORM')
               r%coef_lower(2:3) = [card_value(deck, g_restraints, c, 'C2LOW'), &
                                    card_value(deck, g_restraints, c, 'C3LOW')]
               r%coef_upper(2:3) = [card_value(deck, g_restraints, c, 'C2HIGH'), &
                                    card_value(deck, g_restraints, c, 'C3HIGH')]
               if (r%form /= form_cubic .and. (card_given(deck, g_restraints, c, 'C2LOW') &
                   .or. card_given(deck, g_restraints, c, 'C3LOW') .or. card_given(deck, g_restraints, c, 'C2HIGH') &
                   .or. card_given(deck, g_restraints, c, 'C3HIGH'))) &
                  call problem(deck, err, c, 'joint '//itoa(i)//': C2LOW..C3HIGH are used only with FORM = CUBIC; ' &
                  //'expected them blank', 'FORM C2LOW C3LOW C2HIGH C3HIGH')
               if (card_given(deck, g_restraints, c, 'DISLOW')) &
                  r%dislocation_lower = card_value(deck, g_restraints, c, 'DISLOW')
               if (card_given(deck, g_restraints, c, 'DISHIGH')) &
                  r%dislocation_upper = card_value(deck, g_restraints, c, 'DISHIGH')
               if (r%dislocation_lower > r%lower) call problem(deck, err, c, 'joint '//itoa(i) &
                  //': DISLOW = '//num(r%dislocation_lower/deg)//' deg must not exceed the lower stop angle OMEGA = ' &
                  //num(r%lower/deg)//' deg ('//card_ref(deck, indexed_card(deck, g_joints, i))//')', 'DISLOW')
               if (r%dislocation_upper < r%upper) call problem(deck, err, c, 'joint '//itoa(i) &
                  //': DISHIGH = '//num(r%dislocation_upper/deg)//' deg must not be below the upper stop angle ' &
                  //'BOMEGA = '//num(r%upper/deg)//' deg ('//card_ref(deck, indexed_card(deck, g_joints, i))//')', &
                  'DISHIGH')
            end associate
         end do
      end associate

      associate (g => deck%group(g_stopcurve))
         do i = 1, n_joint
            do side = 1, 2
               call build_curve(deck, g, i, side, jt, err)
            end do
            associate (r => jt%restraint(i))
               if (r%form == form_table) then
                  if (.not. (allocated(r%curve_lower%depth) .and. allocated(r%curve_upper%depth))) &
                     call problem(deck, err, indexed_card(deck, g_restraints, i), 'joint '//itoa(i)//': FORM = ' &
                     //'TABLE needs *STOPCURVE cards for both its LOWER and UPPER stops', 'FORM')
               else if (allocated(r%curve_lower%depth) .or. allocated(r%curve_upper%depth)) then
                  rc = indexed_card(deck, g_restraints, i)
                  if (rc%number > 0) then
                     call problem(deck, err, indexed_card(deck, g_stopcurve, i), 'joint '//itoa(i)//' has ' &
                        //'*STOPCURVE cards but its restraint form is not TABLE ('//card_ref(deck, rc) &
                        //'): give FORM TABLE there')
                  else
                     call problem(deck, err, indexed_card(deck, g_stopcurve, i), 'joint '//itoa(i)//' has ' &
                        //'*STOPCURVE cards but its restraint form is not TABLE: add a *RESTRAINTS card with ' &
                        //'FORM TABLE for it')
                  end if
               end if
            end associate
         end do
      end associate
   end subroutine build_joints

   !> The points of one side (1 lower, 2 upper) of one joint's stop curve.
   subroutine build_curve(deck, g, joint, side, jt, err)
      type(deck_t), intent(in) :: deck
      type(group_t), intent(in) :: g
      integer, intent(in) :: joint, side
      type(joints_section_t), intent(inout) :: jt
      type(error_t), intent(inout) :: err
      integer :: k, n, last, prev
      type(stop_curve_t) :: c

      n = 0
      do k = 1, g%n
         if (on_curve(g%card(k))) n = n + 1
      end do
      if (n == 0) return
      allocate (c%depth(n), c%torque(n))
      n = 0
      last = 0
      prev = 0
      do k = 1, g%n
         if (.not. on_curve(g%card(k))) cycle
         n = n + 1
         c%depth(n) = card_value(deck, g_stopcurve, g%card(k), 'DEPTH')
         c%torque(n) = card_value(deck, g_stopcurve, g%card(k), 'TORQUE')
         if (n == 1 .and. c%depth(1) > 0.0_wp) call problem(deck, err, g%card(k), 'joint ' &
            //itoa(joint)//', '//trim(merge('LOWER', 'UPPER', side == 1))//' stop: DEPTH = '//num(c%depth(1)/deg) &
            //' deg; the first point of a stop curve must have DEPTH = 0', 'DEPTH')
         if (n > 1) then
            if (.not. c%depth(n) > c%depth(n - 1)) call problem(deck, err, g%card(k), 'joint ' &
               //itoa(joint)//', '//trim(merge('LOWER', 'UPPER', side == 1))//' stop: DEPTH = ' &
               //num(c%depth(n)/deg)//' deg after '//num(c%depth(n - 1)/deg)//' deg ('//card_ref(deck, g%card(prev)) &
               //'); DEPTH must increase from card to card of a stop curve', 'DEPTH')
         end if
         prev = k
         last = k
      end do
      if (n < 2) call problem(deck, err, g%card(last), 'joint '//itoa(joint)//', ' &
         //trim(merge('LOWER', 'UPPER', side == 1))//' stop: a stop curve needs at least two points; this is its ' &
         //'only card', 'SIDE')
      if (side == 1) then
         jt%restraint(joint)%curve_lower = c
      else
         jt%restraint(joint)%curve_upper = c
      end if
   contains
      logical function on_curve(card)
         type(card_t), intent(in) :: card
         on_curve = card%index == joint .and. card_int(deck, g_stopcurve, card, 'SIDE') == side
      end function on_curve
   end subroutine build_curve

   !> Table 1 force injury criteria (Table 5 rows).
   subroutine build_injury(deck, inj, err)
      type(deck_t), intent(in) :: deck
      type(injury_section_t), intent(out) :: inj
      type(error_t), intent(inout) :: err
      integer :: k, i
      associate (g => deck%group(g_injury))
         do k = 1, g%n
            i = g%card(k)%index
            inj%f_shear(i) = card_value(deck, g_injury, g%card(k), 'FSF')
            inj%f_compression(i) = card_value(deck, g_injury, g%card(k), 'FCF')
            inj%f_tension(i) = card_value(deck, g_injury, g%card(k), 'FTD')
            ! Table 1: FSF for rows 1-9, FCF for 1-3 and 5-8, FTD for joints 1-7
            if (i == 10 .and. card_given(deck, g_injury, g%card(k), 'FSF')) call problem(deck, err, g%card(k), &
               'row 10: Table 1 has no shear fracture force here (rows 1-9); expected blank', 'FSF')
            if (any([4, 9, 10] == i) .and. card_given(deck, g_injury, g%card(k), 'FCF')) &
               call problem(deck, err, g%card(k), 'row '//itoa(i)//': Table 1 has no compression fracture force ' &
               //'here (rows 1-3, 5-8); expected blank', 'FCF')
            if (i > n_joint .and. card_given(deck, g_injury, g%card(k), 'FTD')) call problem(deck, err, &
               g%card(k), 'row '//itoa(i)//': the tension dislocation force applies to joints 1-7 only; expected ' &
               //'blank', 'FTD')
         end do
      end associate
   end subroutine build_injury

   !> Table 4: the materials the deck gives; the others keep the section's
   !! values (no friction, elastic) and the XI default.
   subroutine build_materials(deck, mat, err)
      type(deck_t), intent(in) :: deck
      type(materials_section_t), intent(out) :: mat
      type(error_t), intent(inout) :: err
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
            if (card_given(deck, g_materials, g%card(k), 'ETA') .and. .not. any(l == [3, 4])) &
               call problem(deck, err, g%card(k), 'material '//itoa(l)//': ETA belongs to padding (3) and ' &
                            //'floormat (4) only; expected blank', 'ETA')
            if (card_given(deck, g_materials, g%card(k), 'FSW')) then
               if (l == 2) then
                  mat%fsw = card_value(deck, g_materials, g%card(k), 'FSW')
               else
                  call problem(deck, err, g%card(k), 'material '//itoa(l)//': FSW belongs to glass (2) only; ' &
                               //'expected blank', 'FSW')
               end if
            end if
         end do
      end associate
   end subroutine build_materials

   !> Loading curves (C.4.e, C.4.f; docs/loading.md): those of the form NLOAD
   !! selects (*LOADPOLY or *LOADTABLE) with their *LOADRATE terms, the curve
   !! each material (*MATERIALS CURVE) and belt section (*BELTLOADING) names,
   !! and what single fields cannot check: orders, curves that never pull,
   !! curves that exist, R <= 1 - G.
   subroutine build_loading(deck, nload, mat, ld, warnings, err)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: nload
      type(materials_section_t), intent(in) :: mat
      type(loading_section_t), intent(out) :: ld
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(error_t), intent(inout) :: err
      character(len=1), parameter :: digit(max_order) = ['1', '2', '3', '4', '5']
      character(len=:), allocatable :: where, message, selected
      integer :: k, i, n

      selected = trim(merge('*LOADPOLY ', '*LOADTABLE', nload == 1))
      if (nload == 1) then
         call build_polynomials(deck, ld, err)
         call unused(g_loadtable, '*LOADPOLY')
      else
         call build_tables(deck, ld, err)
         call unused(g_loadpoly, '*LOADTABLE')
      end if

      associate (g => deck%group(g_loadrate))
         do k = 1, g%n
            i = g%card(k)%index
            where = 'curve '//itoa(i)
            if (.not. curve_is_defined(ld%curve(i))) then
               call problem(deck, err, g%card(k), 'curve k (columns 1-2) = '//itoa(i)//': no such curve in ' &
                  //selected//' (NLOAD = '//itoa(nload)//' of '//card_ref(deck, first_card(deck, g_options))//')')
               cycle
            end if
            do n = 1, max_order
               ld%curve(i)%sigma_rate(n) = card_value(deck, g_loadrate, g%card(k), 'RATE'//digit(n))
               if (ld%curve(i)%form == curve_polynomial .and. n > ld%curve(i)%order .and. &
                   card_given(deck, g_loadrate, g%card(k), 'RATE'//digit(n))) &
                  call problem(deck, err, g%card(k), where//': beyond the order N = '//itoa(ld%curve(i)%order) &
                  //' of the curve ('//card_ref(deck, indexed_card(deck, g_loadpoly, i))//'; the report pairs ' &
                  //'sigma_n+N with sigma_n); expected blank', 'RATE'//digit(n))
            end do
         end do
      end associate

      associate (g => deck%group(g_materials))
         do k = 1, g%n
            i = g%card(k)%index
            where = 'material '//itoa(i)
            ld%material_curve(i) = card_int(deck, g_materials, g%card(k), 'CURVE')
            call check_reference(g%card(k), ld%material_curve(i))
            message = recurrent_check(mat%g(i), mat%r(i))
            if (len(message) > 0) call problem(deck, err, g%card(k), where//': '//message, 'G R')
         end do
      end associate

      associate (g => deck%group(g_beltloading))
         do k = 1, g%n
            i = g%card(k)%index
            where = 'section '//itoa(i)
            ld%belt_curve(i) = card_int(deck, g_beltloading, g%card(k), 'CURVE')
            ld%belt_g(i) = card_value(deck, g_beltloading, g%card(k), 'G')
            ld%belt_r(i) = card_value(deck, g_beltloading, g%card(k), 'R')
            call check_reference(g%card(k), ld%belt_curve(i))
            message = recurrent_check(ld%belt_g(i), ld%belt_r(i))
            if (len(message) > 0) call problem(deck, err, g%card(k), where//': '//message, 'G R')
         end do
      end associate
   contains
      !> A curve named on a card must exist in the selected form.
      subroutine check_reference(c, curve)
         type(card_t), intent(in) :: c
         integer, intent(in) :: curve
         if (curve < 1 .or. curve > max_curves) return
         if (.not. curve_is_defined(ld%curve(curve))) call problem(deck, err, c, where//': no curve ' &
            //itoa(curve)//' in '//selected//' (NLOAD = '//itoa(nload)//' of '//card_ref(deck, &
            first_card(deck, g_options))//')', 'CURVE')
      end subroutine check_reference
      !> The other form's group is read but not used: say so.
      subroutine unused(gid, used)
         integer, intent(in) :: gid
         character(len=*), intent(in) :: used
         if (.not. deck%group(gid)%present) return
         call append_string(warnings, located(deck, header_of(deck, gid), 'not used: NLOAD = '//itoa(nload) &
            //' ('//card_ref(deck, first_card(deck, g_options))//') selects '//used))
      end subroutine unused
   end subroutine build_loading

   !> The polynomial curves of *LOADPOLY (NLOAD = 1).
   subroutine build_polynomials(deck, ld, err)
      type(deck_t), intent(in) :: deck
      type(loading_section_t), intent(inout) :: ld
      type(error_t), intent(inout) :: err
      character(len=1), parameter :: digit(max_order) = ['1', '2', '3', '4', '5']
      character(len=:), allocatable :: where, message, fields
      type(loading_curve_t) :: cv
      integer :: k, i, n, point
      associate (g => deck%group(g_loadpoly))
         do k = 1, g%n
            i = g%card(k)%index
            where = 'curve '//itoa(i)
            cv = loading_curve_t()
            cv%form = curve_polynomial
            cv%order = card_int(deck, g_loadpoly, g%card(k), 'N')
            do n = 1, max_order
               if (n <= cv%order) then
                  cv%sigma(n) = card_value(deck, g_loadpoly, g%card(k), 'SIGMA'//digit(n))
               else if (card_given(deck, g_loadpoly, g%card(k), 'SIGMA'//digit(n))) then
                  call problem(deck, err, g%card(k), where//': beyond the order N = '//itoa(cv%order) &
                     //'; leave it blank or raise N', 'N SIGMA'//digit(n))
               end if
            end do
            call curve_check(cv, message, point)
            if (len(message) > 0) then
               if (index(message, 'order') > 0) then
                  fields = 'N'
               else
                  fields = ''
                  do n = 1, max(1, min(cv%order, max_order))
                     fields = fields//' SIGMA'//digit(n)
                  end do
               end if
               call problem(deck, err, g%card(k), where//': '//message, fields)
            end if
            ld%curve(i) = cv
         end do
      end associate
   end subroutine build_polynomials

   !> The tabulated curves of *LOADTABLE (NLOAD = 2): the points of each
   !! curve in the order of its cards.
   subroutine build_tables(deck, ld, err)
      type(deck_t), intent(in) :: deck
      type(loading_section_t), intent(inout) :: ld
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: message
      integer, allocatable :: cards(:)
      integer :: k, i, point
      associate (g => deck%group(g_loadtable))
         do i = 1, max_curves
            cards = pack([(k, k=1, g%n)], [(g%card(k)%index == i, k=1, g%n)])
            if (size(cards) == 0) cycle
            associate (cv => ld%curve(i))
               cv%form = curve_table
               cv%defl = [(card_value(deck, g_loadtable, g%card(cards(k)), 'DEFL'), k=1, size(cards))]
               cv%force = [(card_value(deck, g_loadtable, g%card(cards(k)), 'FORCE'), k=1, size(cards))]
               call curve_check(cv, message, point)
               if (len(message) > 0) then
                  if (point < 1) point = size(cards)
                  call problem(deck, err, g%card(cards(point)), 'curve '//itoa(i)//', point ' &
                     //itoa(point)//': '//message, 'DEFL FORCE')
               end if
            end associate
         end do
      end associate
   end subroutine build_tables
   !> The seat (C.1's seat parameters, C.4.d; docs/seat.md): its form, the
   !! groups and fields the form uses, the checks between fields, and for the
   !! rigid beam the six initial relations solved for the quantities the deck
   !! does not give (erratum A-RB). Friction: material 1 of *MATERIALS.
   subroutine build_seat(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      integer, parameter :: groups(4) = [g_seatsprings, g_seatbeam, g_seatbeaminit, g_seatbeams]
      logical :: uses(4)
      integer :: k
      type(card_t) :: seat
      character(len=:), allocatable :: form

      associate (p => m%seat)
         p%form = group_int(deck, g_seat, 'FORM') - 1
         form = trim(seat_form_name(p%form))
         p%z0 = group_value(deck, g_seat, 'Z0')
         p%z_hat = group_value(deck, g_seat, 'ZHAT')
         p%gamma0 = group_value(deck, g_seat, 'GAMMA0')
         p%w0 = group_value(deck, g_seat, 'W0')
         p%fps0 = group_value(deck, g_seat, 'FPS0')
         p%c_s = group_value(deck, g_seatsprings, 'CS')
         p%s = group_value(deck, g_seatsprings, 'S')
         p%beta = [group_value(deck, g_seatsprings, 'BETA1'), group_value(deck, g_seatsprings, 'BETA2'), &
                   group_value(deck, g_seatsprings, 'BETA3')]
         p%mu = m%materials%mu(1)
         p%xi = m%materials%xi(1)
         ! every seat group must serve the form chosen
         uses = [any(p%form == [seat_springs, seat_rigid_beam]), p%form == seat_rigid_beam, &
                 p%form == seat_rigid_beam, p%form == seat_beams]
         do k = 1, size(groups)
            if (deck%group(groups(k))%present .and. .not. uses(k)) call problem_at(deck, err, groups(k), &
               'not used with FORM = '//form//' ('//card_ref(deck, first_card(deck, g_seat))//')')
         end do
         if (p%form == seat_none) return
         seat = first_card(deck, g_seat)
         if (p%form /= seat_springs .and. group_given(deck, g_seat, 'ZHAT')) &
            call problem(deck, err, seat, 'ZHAT is used only with FORM = SPRINGS; expected blank', 'FORM ZHAT')
         if (p%form == seat_beams .and. (group_given(deck, g_seat, 'W0') .or. group_given(deck, g_seat, 'FPS0'))) &
            call problem(deck, err, seat, 'W0 and FPS0 are not used with FORM = BEAMS; expected blank', 'FORM W0 FPS0')
         if (p%form /= seat_beams) then
            ! the hip (rear support) spring pushes at every compression d > 0:
            ! beta_1 + beta_2 d + beta_3 d**2 >= 0 (docs/seat.md)
            if (.not. any(p%beta > 0.0_wp)) call problem_in(g_seatsprings, seat, &
               'the hip spring has no stiffness: give BETA1, BETA2 or BETA3 > 0', 'BETA1 BETA2 BETA3')
            if (p%beta(2) < -2.0_wp*sqrt(p%beta(1)*p%beta(3))) call problem_in(g_seatsprings, seat, &
               'BETA2 = '//num(p%beta(2))//' lb/in^2 is below -2 sqrt(BETA1 BETA3) = ' &
               //num(-2.0_wp*sqrt(p%beta(1)*p%beta(3)))//': the spring would pull at some compression', &
               'BETA1 BETA2 BETA3')
         end if
         select case (p%form)
         case (seat_springs)
            if (.not. p%z_hat < p%z0) call problem(deck, err, seat, 'ZHAT = '//num(p%z_hat) &
               //' in must be less than Z0 = '//num(p%z0)//' in (the hip starts behind the front region)', 'Z0 ZHAT')
            if (p%z_hat > 0.0_wp .and. .not. p%beta(1) > 0.0_wp) call problem_in(g_seatsprings, seat, &
               'a front region (ZHAT = '//num(p%z_hat)//' in > 0 on '//card_ref(deck, seat)//') needs BETA1 > 0: ' &
               //'its linear spring starts from beta_1 for a hip that is not pressed in', 'BETA1')
         case (seat_rigid_beam)
            call build_rigid_beam(deck, m, err)
         case (seat_beams)
            p%ell = group_value(deck, g_seatbeams, 'L')
            p%k_ratio = group_value(deck, g_seatbeams, 'K')
            p%e1 = group_value(deck, g_seatbeams, 'E1')
            p%e2 = group_value(deck, g_seatbeams, 'E2')
            p%x_sc = group_value(deck, g_seatbeams, 'XSC')
            ! by default the cushion line touches the hip arc at t = 0
            p%y_sc = -m%body%r_arc(1) + p%x_sc*tan(p%gamma0)
            if (group_given(deck, g_seatbeams, 'YSC')) p%y_sc = group_value(deck, g_seatbeams, 'YSC')
            if (.not. p%z0 < p%ell) call problem(deck, err, seat, 'Z0 = '//num(p%z0) &
               //' in: the hip must start on the hip beam, Z0 < L = '//num(p%ell)//' in (' &
               //card_ref(deck, first_card(deck, g_seatbeams))//')', 'Z0')
            if (.not. abs(m%body%r_arc(1) - m%body%r_arc(7)) < m%body%length(7) .or. &
                .not. abs(m%body%r_arc(7) - m%body%r_arc(11)) < m%body%length(8)) call problem(deck, err, seat, &
               'FORM = BEAMS: the leg''s underside needs |r_1 - r_7| < L7 and |r_7 - r_A| < L8: here |' &
               //num(m%body%r_arc(1))//' - '//num(m%body%r_arc(7))//'| against '//num(m%body%length(7))//' in and |' &
               //num(m%body%r_arc(7))//' - '//num(m%body%r_arc(11))//'| against '//num(m%body%length(8))//' in (' &
               //card_ref(deck, indexed_card(deck, g_arcs, 1))//', arcs 7 and 11, '//card_ref(deck, &
               indexed_card(deck, g_segments, 7))//' and segment 8)', 'FORM')
         end select
      end associate
   contains
      !> A problem with a group that the *SEAT card's form calls for: at its
      !! card and fields when the deck holds it, else at the *SEAT card,
      !! naming the group (its fields then take their defaults).
      subroutine problem_in(gid, asker, message, fields)
         integer, intent(in) :: gid
         type(card_t), intent(in) :: asker
         character(len=*), intent(in) :: message, fields
         if (single_card(deck, gid)) then
            call problem(deck, err, first_card(deck, gid), message, fields)
         else
            call problem(deck, err, asker, 'FORM = '//form//' uses *'//trim(deck%spec(gid)%name)//', which the ' &
               //'deck does not give (its '//fields//' take their defaults): '//message, 'FORM')
         end if
      end subroutine problem_in
   end subroutine build_seat

   !> The rigid-beam seat: its parameters and the four of the ten initial
   !! quantities the deck gives, solved for the other six (C.4.d, A-RB).
   subroutine build_rigid_beam(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      type(beam_statics_t) :: bs
      logical :: given(n_beam_quantities)
      real(wp) :: q(n_beam_quantities)
      integer :: j, status, gid
      character(len=:), allocatable :: message
      associate (p => m%seat)
         p%m_s = group_value(deck, g_seatbeam, 'MS')
         p%i_s = group_value(deck, g_seatbeam, 'IS')
         p%y_gu = group_value(deck, g_seatbeam, 'YGU')
         p%gamma_u = group_value(deck, g_seatbeam, 'GAMMAU')
         p%k_hip = group_value(deck, g_seatbeam, 'KHIP')
         p%k_edge = group_value(deck, g_seatbeam, 'KEDGE')
         do j = 1, n_beam_quantities
            gid = g_seatbeaminit
            if (any(j == [bq_w0, bq_fps0, bq_gamma0])) gid = g_seat
            given(j) = group_given(deck, gid, trim(beam_quantity_name(j)))
            q(j) = 0.0_wp
            if (given(j)) q(j) = group_value(deck, gid, trim(beam_quantity_name(j)))
         end do
         ! the apparent gravity at t = 0 in the interior frame
         bs = beam_statics_t(z0=p%z0, m_s=p%m_s, g=m%environment%gravity*cos(m%vehicle%phi0), y_gu=p%y_gu, &
                             gamma_u=p%gamma_u, s=p%s, beta=p%beta)
         call beam_statics_solve(bs, given, q, status, message)
         if (status /= statics_ok) then
            ! the ten quantities are fields of *SEATBEAMINIT and of *SEAT (W0, FPS0, GAMMA0)
            if (single_card(deck, g_seatbeaminit)) then
               call problem(deck, err, first_card(deck, g_seatbeaminit), message//' (with W0, FPS0 and GAMMA0 of ' &
                            //card_ref(deck, first_card(deck, g_seat))//')', given_names())
            else
               call problem(deck, err, first_card(deck, g_seat), 'FORM = RIGIDBEAM: '//message//' (the deck has ' &
                            //'no *SEATBEAMINIT card)', 'FORM')
            end if
            return
         end if
         p%a = q(bq_a)
         p%a_prime = q(bq_ap)
         p%w0 = q(bq_w0)
         p%fhps0 = q(bq_fhps0)
         p%fs0 = q(bq_fs0)
         p%fps0 = q(bq_fps0)
         p%ds0 = q(bq_ds0)
         p%dz0 = q(bq_dz0)
         p%yg0 = q(bq_yg0)
         p%gamma0 = q(bq_gamma0)
      end associate
   contains
      !> The names of the *SEATBEAMINIT quantities the deck gives.
      function given_names() result(names)
         character(len=:), allocatable :: names
         integer :: k
         names = ''
         do k = 1, n_beam_quantities
            if (given(k) .and. .not. any(k == [bq_w0, bq_fps0, bq_gamma0])) names = names//' ' &
               //trim(beam_quantity_name(k))
         end do
      end function given_names
   end subroutine build_rigid_beam

   !> *BELTS and *BELTOPTIONS (Table 2, C.2, C.4.e; docs/belts.md): the
   !! geometry of each section, the options, and what single fields cannot
   !! check: which fields each kind of section takes, the lap anchor outside
   !! the wrap, the belt points on their segments, the cards and loading the
   !! sections NBELT calls for, the options that go together.
   subroutine build_belts(deck, nbelt, body, ld, bt, warnings, err)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: nbelt
      type(body_section_t), intent(in) :: body
      type(loading_section_t), intent(in) :: ld
      type(belts_section_t), intent(out) :: bt
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: where
      logical :: used(n_belt_card)
      type(card_t) :: c, options, loading
      character(len=:), allocatable :: asker, no_belts, no_loading
      integer :: k, j

      bt%coupling = group_int(deck, g_beltoptions, 'COUPLING')
      bt%lap_sides = group_int(deck, g_beltoptions, 'LAPSIDES')
      bt%max_iter = group_int(deck, g_beltoptions, 'ITER')
      used = [nbelt_lap(nbelt), nbelt_torso(nbelt), nbelt_torso(nbelt), nbelt_lap(nbelt) .and. bt%lap_sides == 2]

      options = first_card(deck, g_options)
      associate (g => deck%group(g_belts))
         do k = 1, g%n
            c = g%card(k)
            j = c%index
            where = 'section '//itoa(j)
            bt%given(j) = .true.
            bt%h(j) = card_value(deck, g_belts, c, 'H')
            bt%length0(j) = card_value(deck, g_belts, c, 'LENGTH')
            bt%phi0(j) = card_value(deck, g_belts, c, 'PHI')
            bt%length_anchor(j) = card_value(deck, g_belts, c, 'LPRIME')
            bt%phi_anchor(j) = card_value(deck, g_belts, c, 'PHIPRIME')
            bt%slack(j) = card_value(deck, g_belts, c, 'SLACK')
            if (j == 1 .or. j == belt_card_lap2) then
               ! the lap belt: its free length and angle follow from l'_0, phi'_0 (C.2, C2-2, C2-3)
               call forbid('LENGTH', 'the lap belt''s free length is computed from LPRIME and PHIPRIME ' &
                           //'(C.2, errata C2-2)')
               call forbid('PHI', 'the lap belt''s angle is computed from LPRIME and PHIPRIME (C.2, errata C2-3)')
               call need('LPRIME', 'the lap belt''s anchor lies LPRIME from the initial hip')
               call need('PHIPRIME', 'PHIPRIME is the direction from the lap belt''s anchor to the initial hip')
               if (card_given(deck, g_belts, c, 'LPRIME') .and. .not. bt%length_anchor(j) > bt%h(j)) &
                  call problem(deck, err, c, where//': LPRIME = '//num(bt%length_anchor(j)) &
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
                  call problem(deck, err, c, where//num(body%length(j))//' in of '//card_ref(deck, &
                     indexed_card(deck, g_segments, j))//') on the segment that carries the belt', 'H')
               end if
            end if
         end do
      end associate

      if (nbelt == 0) then
         if (deck%group(g_belts)%present) call append_string(warnings, located(deck, header_of(deck, g_belts), &
            'not used: NBELT = 0 ('//card_ref(deck, options)//')'))
         if (deck%group(g_beltoptions)%present) call append_string(warnings, located(deck, &
            header_of(deck, g_beltoptions), 'not used: NBELT = 0 ('//card_ref(deck, options)//')'))
         return
      end if
      c = first_card(deck, g_beltoptions)
      no_belts = ''
      no_loading = ''
      ! the sections NBELT calls for need their cards and their loading
      do j = 1, n_belt_card
         if (.not. used(j)) then
            if (bt%given(j)) call append_string(warnings, located(deck, indexed_card(deck, g_belts, j), &
               'section '//itoa(j)//' is not used: NBELT = '//itoa(nbelt)//' ('//card_ref(deck, options) &
               //'), LAPSIDES = '//itoa(bt%lap_sides)//' ('//card_ref(deck, c)//')'))
            cycle
         end if
         if (.not. bt%given(j)) then
            asker = 'NBELT = '//itoa(nbelt)
            if (j == belt_card_lap2) asker = asker//' with LAPSIDES = 2 ('//card_ref(deck, c)//')'
            if (deck%group(g_belts)%present) then
               call problem_at(deck, err, g_belts, 'no card for section '//itoa(j)//', which '//asker//' (' &
                  //card_ref(deck, options)//') needs: give its card')
            else
               call add_to_list(no_belts, itoa(j))   ! (one message for the group: below)
            end if
         end if
         ! card 4, the lap belt's second side, takes the lap belt's loading
         if (ld%belt_curve(min(j, n_belt_section)) < 1 .and. j <= n_belt_section) then
            loading = indexed_card(deck, g_beltloading, j)
            if (loading%number > 0) then
               call problem(deck, err, loading, 'section '//itoa(j)//' is used ' &
                  //'(NBELT = '//itoa(nbelt)//', '//card_ref(deck, options)//'): give its loading curve', 'CURVE')
            else if (deck%group(g_beltloading)%present) then
               call problem_at(deck, err, g_beltloading, 'no card for section '//itoa(j)//', which NBELT = ' &
                  //itoa(nbelt)//' ('//card_ref(deck, options)//') uses: give its loading (CURVE, G, R)')
            else
               call add_to_list(no_loading, itoa(j))
            end if
         end if
      end do
      if (len(no_belts) > 0) call problem(deck, err, options, 'NBELT = '//itoa(nbelt)//' needs *BELTS ' &
         //sections(no_belts)//', and the deck has no *BELTS card group: give their cards', 'NBELT')
      if (len(no_loading) > 0) call problem(deck, err, options, 'NBELT = '//itoa(nbelt)//' uses belt ' &
         //sections(no_loading)//', and the deck has no *BELTLOADING card group: give their loading (CURVE, ' &
         //'G, R)', 'NBELT')
      if (bt%coupling == coupling_torso .and. .not. nbelt_torso(nbelt)) call problem(deck, err, c, &
         'COUPLING = TORSO: the torso sections share a tension, but NBELT = '//itoa(nbelt)//' (' &
         //card_ref(deck, options)//') uses no torso belt', 'COUPLING')
      if (bt%coupling == coupling_all .and. nbelt /= 3) call problem(deck, err, c, 'COUPLING = ALL: the three ' &
         //'sections share a tension, but NBELT = '//itoa(nbelt)//' ('//card_ref(deck, options)//') does not ' &
         //'use all three', 'COUPLING')
      if (bt%coupling == coupling_all .and. bt%lap_sides == 2) call problem(deck, err, c, 'with COUPLING = ALL ' &
         //'the lap belt is one section (LAPSIDES = 1)', 'COUPLING LAPSIDES')
      if (bt%lap_sides == 2 .and. .not. nbelt_lap(nbelt)) call problem(deck, err, c, 'LAPSIDES = 2: NBELT = ' &
         //itoa(nbelt)//' ('//card_ref(deck, options)//') uses no lap belt', 'LAPSIDES')
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
         if (card_given(deck, g_belts, c, name)) call problem(deck, err, c, where//': leave '//name//' blank: ' &
            //why, name)
      end subroutine forbid
      !> A field this kind of section needs.
      subroutine need(name, why)
         character(len=*), intent(in) :: name, why
         if (.not. card_given(deck, g_belts, c, name)) call problem(deck, err, c, where//': '//name &
            //' is required: '//why, name)
      end subroutine need
   end subroutine build_belts

   !> Vehicle constants, initial motion and its time tables (C.1, C.3).
   subroutine build_vehicle(deck, v, err)
      type(deck_t), intent(in) :: deck
      type(vehicle_section_t), intent(out) :: v
      type(error_t), intent(inout) :: err
      type(card_t) :: c
      character(len=:), allocatable :: path

      v%mass = group_value(deck, g_vehicle, 'MASS')
      v%inertia = group_value(deck, g_vehicle, 'INERTIA')
      v%xc_dot0 = group_value(deck, g_vehicle, 'XDOT0')
      v%yc_dot0 = group_value(deck, g_vehicle, 'YDOT0')
      v%phi0 = group_value(deck, g_vehicle, 'PHI0')
      v%phi_dot0 = group_value(deck, g_vehicle, 'PHIDOT0')

      if (single_card(deck, g_pulsefile)) then
         c = deck%group(g_pulsefile)%card(1)
         path = trim(adjustl(c%text))
         if (path(1:1) /= '/') path = deck%source_dir(c%source)%s//path
         call read_pulse_csv(path, deck%source_name(c%source)%s//':'//itoa(c%line), deck%spec(g_pulse), &
                             v%pulse_acc, err)
         v%pulse_source = escaped(path)   ! (for the listing: one line whatever the name holds)
         v%pulse_from_file = .true.
      else if (deck%group(g_pulse)%present) then
         call table_from_group(deck, g_pulse, ['XDDOT  ', 'YDDOT  ', 'PHIDDOT'], v%pulse_acc, .true., err)
         v%pulse_source = 'cards'
      else
         ! no pulse: the vehicle moves at its initial velocity
         allocate (v%pulse_acc%t(1), v%pulse_acc%v(1, 3))
         v%pulse_acc%t = 0.0_wp
         v%pulse_acc%v = 0.0_wp
         v%pulse_acc%given = .true.
         v%pulse_source = 'none (constant velocity)'
      end if
      if (deck%group(g_pulserates)%present) then
         call table_from_group(deck, g_pulserates, ['XDOT  ', 'YDOT  ', 'PHIDOT'], v%pulse_vel, .false., err)
         call check_start(deck, deck%group(g_pulserates), v%pulse_vel, [v%xc_dot0, v%yc_dot0, v%phi_dot0], &
            ['XDOT  ', 'YDOT  ', 'PHIDOT'], ['XDOT0  ', 'YDOT0  ', 'PHIDOT0'], [1.0_wp, 1.0_wp, deg], &
            ['in/s ', 'in/s ', 'deg/s'], err)
      end if
      if (deck%group(g_pulsepos)%present) then
         call table_from_group(deck, g_pulsepos, ['X  ', 'Y  ', 'PHI'], v%pulse_pos, .false., err)
         call check_start(deck, deck%group(g_pulsepos), v%pulse_pos, [0.0_wp, 0.0_wp, v%phi0], &
            ['X     ', 'Y     ', 'PHI   '], ['       ', '       ', 'PHI0   '], [1.0_wp, 1.0_wp, deg], &
            ['in ', 'in ', 'deg'], err)
      end if
   end subroutine build_vehicle

   !> (C.3) Tabulated rates and positions replace integrations of the
   !! tables below them, but the vehicle's inertial forces always come from
   !! its accelerations: where a table is not their integral the two
   !! describe different motions, and nothing in the run shows it (review
   !! of issue 14: a velocity 100,000 in/s off ran with a 37,000 g head and
   !! a balanced energy). Each tabulated column is compared at its knots
   !! with the integral of the tables below it (vehicle_motion: exact
   !! integrals of the piecewise-linear tables, so the comparison carries no
   !! integration error) against the scale of its kind of quantity: for x
   !! and y together the largest speed (or displacement) of the tables and
   !! integrals, at least 1 in/s (1 in), and for the pitch its own, at least
   !! 1 deg/s (1 deg). Measured tables differ by a few per cent (calibration
   !! and drift of the accelerometers a pulse is integrated from); a unit
   !! slip (ft/s for in/s: a factor 12, g for in/s^2: 386), a wrong column
   !! or a typo in a leading digit differs by far more. So a difference
   !! beyond 10 % of the scale is a deck error at the card and field where
   !! it is largest, and one beyond 1 % a warning with the figures.
   subroutine check_vehicle_tables(deck, v, warnings, err)
      type(deck_t), intent(in) :: deck
      type(vehicle_section_t), intent(in) :: v
      type(string_t), allocatable, intent(inout) :: warnings(:)
      type(error_t), intent(inout) :: err
      character(len=*), parameter :: rate_name(3) = ['XDOT  ', 'YDOT  ', 'PHIDOT'], pos_name(3) = ['X  ', 'Y  ', 'PHI']
      character(len=*), parameter :: rate_unit(3) = ['in/s ', 'in/s ', 'deg/s'], pos_unit(3) = ['in ', 'in ', 'deg']
      real(wp), parameter :: to_deck(3) = [1.0_wp, 1.0_wp, 1.0_wp/deg]
      real(wp), parameter :: error_share = 0.1_wp, warning_share = 0.01_wp
      type(vehicle_section_t) :: lower
      if (allocated(v%pulse_vel%t)) then
         ! the rates against the integral of the accelerations
         lower = v
         deallocate (lower%pulse_vel%t, lower%pulse_vel%v)
         if (allocated(lower%pulse_pos%t)) deallocate (lower%pulse_pos%t, lower%pulse_pos%v)
         call compare(g_pulserates, v%pulse_vel, lower, .false., rate_name, rate_unit, 'the *PULSE accelerations')
      end if
      if (allocated(v%pulse_pos%t)) then
         ! the positions against the integral of the rates (tabulated, or of the accelerations)
         lower = v
         deallocate (lower%pulse_pos%t, lower%pulse_pos%v)
         if (allocated(v%pulse_vel%t)) then
            call compare(g_pulsepos, v%pulse_pos, lower, .true., pos_name, pos_unit, 'the *PULSERATES rates')
         else
            call compare(g_pulsepos, v%pulse_pos, lower, .true., pos_name, pos_unit, 'the *PULSE accelerations')
         end if
      end if
   contains
      subroutine compare(gid, tab, below, is_pos, names, units, source)
         integer, intent(in) :: gid
         type(pulse_table_t), intent(in) :: tab
         type(vehicle_section_t), intent(in) :: below
         logical, intent(in) :: is_pos
         character(len=*), intent(in) :: names(3), units(3), source
         type(vehicle_motion_t) :: vm
         type(vehicle_state_t) :: vs
         real(wp) :: integral(size(tab%t), 3), scale(3), diff, worst
         integer :: k, j, at
         character(len=:), allocatable :: text, unit_text, what
         call vehicle_motion_init(below, vm)
         do k = 1, size(tab%t)
            vs = vehicle_state_at(vm, tab%t(k))
            integral(k, :) = merge(vs%pos, vs%vel, is_pos)
         end do
         ! the scale of each kind of quantity (x and y together; the pitch), in deck units
         scale = 1.0_wp
         do j = 1, 3
            scale(j) = max(scale(j), maxval(abs(integral(:, j)))*to_deck(j))
            if (tab%given(j)) scale(j) = max(scale(j), maxval(abs(tab%v(:, j)))*to_deck(j))
         end do
         scale(1:2) = maxval(scale(1:2))
         do j = 1, 3
            if (.not. tab%given(j)) cycle
            worst = 0.0_wp
            at = 0
            do k = 1, size(tab%t)
               diff = abs(tab%v(k, j) - integral(k, j))*to_deck(j)
               if (diff > worst) then
                  worst = diff
                  at = k
               end if
            end do
            if (.not. worst > warning_share*scale(j)) cycle
            unit_text = ' '//trim(units(j))
            if (j == 3) then
               what = trim(merge('pitch angle', 'pitch rate ', is_pos))
            else
               what = trim(merge('displacement', 'speed       ', is_pos))
            end if
            text = trim(names(j))//' = '//num(tab%v(at, j)*to_deck(j))//unit_text//' at T = '//num(tab%t(at)) &
               //' s, where '//source//' integrate to '//num(integral(at, j)*to_deck(j), 6)//unit_text &
               //' (from *VEHICLE''s initial motion): a difference of '//num(worst, 4)//unit_text//', ' &
               //num(100.0_wp*worst/scale(j), 3)//' % of the tables'' largest '//what//', ' &
               //num(scale(j), 6)//unit_text
            if (worst > error_share*scale(j)) then
               call problem(deck, err, deck%group(gid)%card(at), text//'; a table may differ from the integral ' &
                  //'by at most 10 % (measurement error; the inertial forces come from the accelerations, C.3): ' &
                  //'is a unit, a column or a digit wrong?', trim(names(j)))
            else
               call append_string(warnings, located(deck, deck%group(gid)%card(at), text//': the run takes the ' &
                  //'inertial forces from the accelerations and the motion from this table (C.3)', trim(names(j))))
            end if
         end do
      end subroutine compare
   end subroutine check_vehicle_tables

   !> A time table from list cards: the time T and the columns named for
   !! x, y and the pitch.
   subroutine table_from_group(deck, gid, columns, table, all_given, err)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: columns(3)
      type(pulse_table_t), intent(out) :: table
      logical, intent(in) :: all_given
      type(error_t), intent(inout) :: err
      integer :: k, j, n_given
      associate (g => deck%group(gid))
         allocate (table%t(g%n), table%v(g%n, 3))
         do k = 1, g%n
            table%t(k) = card_value(deck, gid, g%card(k), 'T')
            do j = 1, 3
               table%v(k, j) = card_value(deck, gid, g%card(k), trim(columns(j)))
            end do
            if (k == 1 .and. table%t(1) > 0.0_wp) call problem(deck, err, g%card(k), &
               'T = '//num(table%t(1))//' s; the first time of a vehicle table must be 0', 'T')
            if (k > 1) then
               if (.not. table%t(k) > table%t(k - 1)) call problem(deck, err, g%card(k), 'T = ' &
                  //num(table%t(k))//' s after '//num(table%t(k - 1))//' s on '//card_ref(deck, g%card(k - 1)) &
                  //'; T must increase from card to card', 'T')
            end if
         end do
         do j = 1, 3
            if (all_given) then
               table%given(j) = .true.
            else
               n_given = count([(card_given(deck, gid, g%card(k), trim(columns(j))), k=1, g%n)])
               table%given(j) = n_given > 0
               if (n_given > 0 .and. n_given < g%n) then
                  ! at the first card that differs from the first card
                  k = findloc([(card_given(deck, gid, g%card(k), trim(columns(j))) .neqv. &
                                card_given(deck, gid, g%card(1), trim(columns(j))), k=1, g%n)], .true., 1)
                  call problem(deck, err, g%card(k), 'column '//trim(columns(j))//' is ' &
                     //trim(merge('given', 'blank', card_given(deck, gid, g%card(k), trim(columns(j))))) &
                     //' here and '//trim(merge('given', 'blank', card_given(deck, gid, g%card(1), trim(columns(j))))) &
                     //' on '//card_ref(deck, g%card(1))//' ('//itoa(n_given)//' of '//itoa(g%n)//' cards give ' &
                     //'it); give it on every card or on none', trim(columns(j)))
               end if
            end if
         end do
      end associate
   end subroutine table_from_group

   !> Tabulated rates or positions must start where the initial conditions
   !! do (*VEHICLE's field initial(j); blank: the interior's origin, 0).
   subroutine check_start(deck, g, table, start, names, initial, scale, units, err)
      type(deck_t), intent(in) :: deck
      type(group_t), intent(in) :: g
      type(pulse_table_t), intent(in) :: table
      real(wp), intent(in) :: start(3), scale(3)
      character(len=*), intent(in) :: names(3), initial(3), units(3)
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: from
      integer :: j
      do j = 1, 3
         if (.not. table%given(j) .or. size(table%t) == 0) cycle
         if (len_trim(initial(j)) > 0) then
            from = 'the initial conditions give '//num(start(j)/scale(j))//' ('//trim(initial(j))//' of ' &
                   //card_ref(deck, first_card(deck, g_vehicle))//')'
         else
            from = 'the vehicle starts at 0 (its initial position is the origin)'
         end if
         if (abs(table%v(1, j) - start(j)) > 1.0e-9_wp*max(1.0_wp, abs(start(j)))) &
            call problem(deck, err, g%card(1), trim(names(j))//' at t = 0 is '//num(table%v(1, j)/scale(j)) &
            //' '//trim(units(j))//' but '//from, trim(names(j)))
      end do
   end subroutine check_start

   ! --- helpers ----------------------------------------------------------

   !> fixed-step runs need t to be n*dt for a whole n (to 1e-9 relative)
   logical function whole_multiple(t, dt)
      real(wp), intent(in) :: t, dt
      real(wp) :: q
      q = t/dt
      whole_multiple = abs(q - anint(q)) <= 1.0e-9_wp*max(1.0_wp, q) .and. anint(q) >= 1.0_wp
   end function whole_multiple

   !> A problem's or warning's text, located as the deck reader locates
   !! its own (README, docs/usage.md): "file:line: *GROUP card n, field F
   !! (columns a-b): message" for a data card; "file:line: *GROUP: message"
   !! for a group's header (header_of); fields is a blank-separated list of
   !! the fields concerned ('' for none). A card of a group the deck does
   !! not hold (source 0) is "a.deck, b.deck: *GROUP: ..." - callers that
   !! have a card asking for that group locate the problem there instead.
   function located(deck, c, message, fields) result(text)
      type(deck_t), intent(in) :: deck
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      character(len=:), allocatable :: text
      if (c%source > 0) then
         text = deck%source_name(c%source)%s//':'//itoa(c%line)//': '
      else
         text = deck_names(deck)//': '
      end if
      if (c%group > 0) then
         text = text//'*'//trim(deck%spec(c%group)%name)
         if (c%number > 0) text = text//' card '//itoa(c%number)
         if (present(fields)) then
            if (len_trim(fields) > 0) text = text//', '//field_list(deck, c%group, fields)
         end if
         text = text//': '
      end if
      text = text//message
   end function located

   !> The header card of group gid as a card to locate problems at (source
   !! 0 when the deck does not hold the group).
   function header_of(deck, gid) result(c)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t) :: c
      c%group = gid
      c%number = 0
      if (deck%group(gid)%present) then
         c%source = deck%group(gid)%source
         c%line = deck%group(gid)%line
      end if
   end function header_of

   !> The card of a one-card group, or its header (source 0 when absent).
   function first_card(deck, gid) result(c)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      type(card_t) :: c
      if (single_card(deck, gid)) then
         c = deck%group(gid)%card(1)
      else
         c = header_of(deck, gid)
      end if
   end function first_card

   !> Where another card is, for a problem that involves two: "*OPTIONS
   !! card 1 at default.deck:12" (or "*OPTIONS, not in the deck").
   function card_ref(deck, c) result(text)
      type(deck_t), intent(in) :: deck
      type(card_t), intent(in) :: c
      character(len=:), allocatable :: text
      text = '*'//trim(deck%spec(c%group)%name)
      if (c%number > 0) text = text//' card '//itoa(c%number)
      if (c%source > 0) then
         text = text//' at '//deck%source_name(c%source)%s//':'//itoa(c%line)
      else
         text = text//', not in the deck (its defaults)'
      end if
   end function card_ref

   !> Field `name` of group gid with its columns, for messages: 'X (columns 3-12)'.
   function field_where(deck, gid, name) result(text)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: j
      text = name
      do j = 1, deck%spec(gid)%n_fields
         if (trim(deck%spec(gid)%field(j)%name) == name) text = name//' (columns ' &
            //itoa(deck%spec(gid)%field(j)%first_col)//'-'//itoa(deck%spec(gid)%field(j)%last_col)//')'
      end do
   end function field_where

   !> "field X (columns a-b)", "fields X (columns a-b) and Y (columns c-d)",
   !! "fields X (...), Y (...) and Z (...)" from blank-separated names.
   function field_list(deck, gid, names) result(text)
      type(deck_t), intent(in) :: deck
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
            text = field_where(deck, gid, name)
         else if (len(rest) == 0) then
            text = text//' and '//field_where(deck, gid, name)
         else
            text = text//', '//field_where(deck, gid, name)
         end if
      end do
      text = trim(merge('fields', 'field ', n > 1))//' '//text
   end function field_list

   !> A problem located at a card (see located).
   subroutine problem(deck, err, c, message, fields)
      type(deck_t), intent(in) :: deck
      type(error_t), intent(inout) :: err
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      if (present(fields)) then
         call error_append(err, exit_deck, located(deck, c, message, fields))
      else
         call error_append(err, exit_deck, located(deck, c, message))
      end if
   end subroutine problem

   !> A problem located at a group's header card.
   subroutine problem_at(deck, err, gid, message, fields)
      type(deck_t), intent(in) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: gid
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: fields
      if (present(fields)) then
         call problem(deck, err, header_of(deck, gid), message, fields)
      else
         call problem(deck, err, header_of(deck, gid), message)
      end if
   end subroutine problem_at

end module model_builder
