!> The seat from the deck (report C.1's seat parameters, C.4.d; docs/seat.md):
!! *SEAT, *SEATSPRINGS, *SEATBEAM, *SEATBEAMINIT, *SEATBEAMS - the section's
!! builder, which reads the groups its form uses by the names of the card
!! table, and its validator: the groups and fields the form uses, the checks
!! between fields. The rigid beam's initial relations are solved for the
!! quantities the deck does not give by C.2 (seat_beam_statics), whose
!! failure rigid_beam_problem locates. Friction: material 1 of *MATERIALS.
module seat_input
   use kinds, only: wp
   use error_handling, only: error_t
   use strings, only: num
   use deck_cards, only: g_seat, g_seatsprings, g_seatbeam, g_seatbeaminit, g_seatbeams, g_arcs, g_segments
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: group_value, group_int, group_given
   use model_origin, only: model_origin_t, group_present, has_card, group_field_given, group_name, first_card, &
      indexed_card, card_ref, problem, problem_at
   use model, only: seat_section_t, body_section_t, materials_section_t, seat_none, seat_springs, seat_rigid_beam, &
      seat_beams, seat_form_name, n_beam_quantities, beam_quantity_name, bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, &
      bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   implicit none
   private

   public :: build_seat, check_seat, rigid_beam_problem

contains

   !> The seat's form and the fields of the groups it uses; for the rigid
   !! beam, which of its ten initial quantities the deck gives, and their
   !! values.
   subroutine build_seat(deck, body, mat, p)
      type(deck_t), intent(in) :: deck
      type(body_section_t), intent(in) :: body
      type(materials_section_t), intent(in) :: mat
      type(seat_section_t), intent(out) :: p
      integer :: j, gid
      real(wp) :: q

      p%form = group_int(deck, g_seat, 'FORM') - 1
      p%z0 = group_value(deck, g_seat, 'Z0')
      p%z_hat = group_value(deck, g_seat, 'ZHAT')
      p%gamma0 = group_value(deck, g_seat, 'GAMMA0')
      p%w0 = group_value(deck, g_seat, 'W0')
      p%fps0 = group_value(deck, g_seat, 'FPS0')
      p%c_s = group_value(deck, g_seatsprings, 'CS')
      p%s = group_value(deck, g_seatsprings, 'S')
      p%beta = [group_value(deck, g_seatsprings, 'BETA1'), group_value(deck, g_seatsprings, 'BETA2'), &
                group_value(deck, g_seatsprings, 'BETA3')]
      p%mu = mat%mu(1)
      p%xi = mat%xi(1)
      select case (p%form)
      case (seat_rigid_beam)
         p%m_s = group_value(deck, g_seatbeam, 'MS')
         p%i_s = group_value(deck, g_seatbeam, 'IS')
         p%y_gu = group_value(deck, g_seatbeam, 'YGU')
         p%gamma_u = group_value(deck, g_seatbeam, 'GAMMAU')
         p%k_hip = group_value(deck, g_seatbeam, 'KHIP')
         p%k_edge = group_value(deck, g_seatbeam, 'KEDGE')
         ! the ten quantities are fields of *SEATBEAMINIT and of *SEAT (W0, FPS0, GAMMA0)
         do j = 1, n_beam_quantities
            gid = g_seatbeaminit
            if (any(j == [bq_w0, bq_fps0, bq_gamma0])) gid = g_seat
            p%beam_given(j) = group_given(deck, gid, trim(beam_quantity_name(j)))
            if (.not. p%beam_given(j)) cycle
            q = group_value(deck, gid, trim(beam_quantity_name(j)))
            select case (j)
            case (bq_a); p%a = q
            case (bq_ap); p%a_prime = q
            case (bq_w0); p%w0 = q
            case (bq_fhps0); p%fhps0 = q
            case (bq_fs0); p%fs0 = q
            case (bq_fps0); p%fps0 = q
            case (bq_ds0); p%ds0 = q
            case (bq_dz0); p%dz0 = q
            case (bq_yg0); p%yg0 = q
            case (bq_gamma0); p%gamma0 = q
            end select
         end do
      case (seat_beams)
         p%ell = group_value(deck, g_seatbeams, 'L')
         p%k_ratio = group_value(deck, g_seatbeams, 'K')
         p%e1 = group_value(deck, g_seatbeams, 'E1')
         p%e2 = group_value(deck, g_seatbeams, 'E2')
         p%x_sc = group_value(deck, g_seatbeams, 'XSC')
         ! by default the cushion line touches the hip arc at t = 0
         p%y_sc = -body%r_arc(1) + p%x_sc*tan(p%gamma0)
         if (group_given(deck, g_seatbeams, 'YSC')) p%y_sc = group_value(deck, g_seatbeams, 'YSC')
      end select
   end subroutine build_seat

   !> The groups the form uses (no other seat group), the fields each form
   !! takes, a hip spring that pushes at every compression, the front
   !! region behind the initial hip, the hip on the hip beam and the leg's
   !! underside (FORM = BEAMS).
   subroutine check_seat(p, body, orig, err)
      type(seat_section_t), intent(in) :: p
      type(body_section_t), intent(in) :: body
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      integer, parameter :: groups(4) = [g_seatsprings, g_seatbeam, g_seatbeaminit, g_seatbeams]
      logical :: uses(4)
      integer :: k
      type(card_t) :: seat
      character(len=:), allocatable :: form

      form = trim(seat_form_name(p%form))
      ! every seat group must serve the form chosen
      uses = [any(p%form == [seat_springs, seat_rigid_beam]), p%form == seat_rigid_beam, &
              p%form == seat_rigid_beam, p%form == seat_beams]
      do k = 1, size(groups)
         if (group_present(orig, groups(k)) .and. .not. uses(k)) call problem_at(orig, err, groups(k), &
            'not used with FORM = '//form//' ('//card_ref(orig, first_card(orig, g_seat))//')')
      end do
      if (p%form == seat_none) return
      seat = first_card(orig, g_seat)
      if (p%form /= seat_springs .and. group_field_given(orig, g_seat, 'ZHAT')) &
         call problem(orig, err, seat, 'ZHAT is used only with FORM = SPRINGS; expected blank', 'FORM ZHAT')
      if (p%form == seat_beams .and. (group_field_given(orig, g_seat, 'W0') .or. group_field_given(orig, g_seat, &
                                                                                                     'FPS0'))) &
         call problem(orig, err, seat, 'W0 and FPS0 are not used with FORM = BEAMS; expected blank', 'FORM W0 FPS0')
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
         if (.not. p%z_hat < p%z0) call problem(orig, err, seat, 'ZHAT = '//num(p%z_hat) &
            //' in must be less than Z0 = '//num(p%z0)//' in (the hip starts behind the front region)', 'Z0 ZHAT')
         if (p%z_hat > 0.0_wp .and. .not. p%beta(1) > 0.0_wp) call problem_in(g_seatsprings, seat, &
            'a front region (ZHAT = '//num(p%z_hat)//' in > 0 on '//card_ref(orig, seat)//') needs BETA1 > 0: ' &
            //'its linear spring starts from beta_1 for a hip that is not pressed in', 'BETA1')
      case (seat_beams)
         if (.not. p%z0 < p%ell) call problem(orig, err, seat, 'Z0 = '//num(p%z0) &
            //' in: the hip must start on the hip beam, Z0 < L = '//num(p%ell)//' in (' &
            //card_ref(orig, first_card(orig, g_seatbeams))//')', 'Z0')
         if (.not. abs(body%r_arc(1) - body%r_arc(7)) < body%length(7) .or. &
             .not. abs(body%r_arc(7) - body%r_arc(11)) < body%length(8)) call problem(orig, err, seat, &
            'FORM = BEAMS: the leg''s underside needs |r_1 - r_7| < L7 and |r_7 - r_A| < L8: here |' &
            //num(body%r_arc(1))//' - '//num(body%r_arc(7))//'| against '//num(body%length(7))//' in and |' &
            //num(body%r_arc(7))//' - '//num(body%r_arc(11))//'| against '//num(body%length(8))//' in (' &
            //card_ref(orig, indexed_card(orig, g_arcs, 1))//', arcs 7 and 11, '//card_ref(orig, &
            indexed_card(orig, g_segments, 7))//' and segment 8)', 'FORM')
      end select
   contains
      !> A problem with a group that the *SEAT card's form calls for: at its
      !! card and fields when the deck holds it, else at the *SEAT card,
      !! naming the group (its fields then take their defaults).
      subroutine problem_in(gid, asker, message, fields)
         integer, intent(in) :: gid
         type(card_t), intent(in) :: asker
         character(len=*), intent(in) :: message, fields
         if (has_card(orig, gid)) then
            call problem(orig, err, first_card(orig, gid), message, fields)
         else
            call problem(orig, err, asker, 'FORM = '//form//' uses *'//group_name(orig, gid)//', which the ' &
               //'deck does not give (its '//fields//' take their defaults): '//message, 'FORM')
         end if
      end subroutine problem_in
   end subroutine check_seat

   !> Why the rigid beam's initial relations cannot be solved for the
   !! quantities the deck does not give (why: seat_beam_statics' error,
   !! without location), at the *SEATBEAMINIT card and the quantities it
   !! gives, or at the *SEAT card when the deck has none.
   subroutine rigid_beam_problem(p, orig, why, err)
      type(seat_section_t), intent(in) :: p
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(in) :: why
      type(error_t), intent(inout) :: err
      ! the ten quantities are fields of *SEATBEAMINIT and of *SEAT (W0, FPS0, GAMMA0)
      if (has_card(orig, g_seatbeaminit)) then
         call problem(orig, err, first_card(orig, g_seatbeaminit), why%message//' (with W0, FPS0 and GAMMA0 of ' &
                      //card_ref(orig, first_card(orig, g_seat))//')', given_names())
      else
         call problem(orig, err, first_card(orig, g_seat), 'FORM = RIGIDBEAM: '//why%message//' (the deck has ' &
                      //'no *SEATBEAMINIT card)', 'FORM')
      end if
   contains
      !> The names of the *SEATBEAMINIT quantities the deck gives.
      function given_names() result(names)
         character(len=:), allocatable :: names
         integer :: k
         names = ''
         do k = 1, n_beam_quantities
            if (p%beam_given(k) .and. .not. any(k == [bq_w0, bq_fps0, bq_gamma0])) names = names//' ' &
               //trim(beam_quantity_name(k))
         end do
      end function given_names
   end subroutine rigid_beam_problem
end module seat_input
