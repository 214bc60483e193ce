!> The seat's parameter table, as the listing prints it (C.1: "the present
!! seat parameters are c_s, s, beta_1, beta_2, beta_3, z_o, z-hat, gamma_o,
!! W_o and F'_so"; C.4.d for the beam seats; docs/seat.md): one parameter
!! a row, its symbol, meaning, unit, value and the card field it comes from.
module seat_table
   use kinds, only: wp, deg
   use text_table, only: text_table_t, new_table, cell_text, cell_fixed
   use model, only: model_t, seat_none, seat_springs, seat_rigid_beam, seat_beams, seat_form_name
   use deck_reader, only: deck_t
   use deck_cards, only: g_seat, g_seatbeaminit, g_seatbeams
   use deck_fields, only: group_given
   use seat_beam_statics, only: n_beam_quantities, beam_quantity_name, bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, &
      bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   implicit none
   private

   public :: seat_parameter_table

contains

   !> The seat of m in its form (deck: which fields it gives); no rows
   !! when the deck has no seat.
   function seat_parameter_table(m, deck) result(t)
      type(model_t), intent(in) :: m
      type(deck_t), intent(in) :: deck
      type(text_table_t) :: t
      character(len=*), parameter :: form_text(3) = [character(len=48) :: &
         'the present seat (figures 11-12)', 'a rigid beam on springs (figures 15-16)', &
         'a pair of non-rigid beams (figures 13-14)']
      real(wp) :: q(n_beam_quantities)
      integer :: j
      associate (p => m%seat)
         if (p%form == seat_none) then
            t = new_table('SEAT')
            return
         end if
         t = new_table('SEAT (C.1, C.4.d) - FORM '//trim(seat_form_name(p%form))//': '//trim(form_text(p%form)), &
                        keep=merge(16, merge(29, 14, p%form == seat_rigid_beam), p%form == seat_springs))
         call t%add_column('SYMBOL', 12, cell_text)
         call t%add_column('PARAMETER', 41, cell_text, lead=0)
         call t%add_column('UNIT', 10, cell_text, lead=0)
         call t%add_column('VALUE', 12, head_right=.true.)
         call t%add_column('FROM', 60, cell_text, lead=3)
         select case (p%form)
         case (seat_springs)
            call put_value('z_o', 'hip to front edge', 'in', p%z0, '*SEAT Z0')
            call put_value('z-hat', 'front region (linear hip spring)', 'in', p%z_hat, '*SEAT ZHAT')
            call put_angle('gamma_o', 'undeflected cushion angle', p%gamma0, '*SEAT GAMMA0')
            call put_check('W_o', 'static load at the hip', 'W0')
            call put_check('F''_so', 'static load on the front edge', 'FPS0')
            call put_value('c_s', 'hip damper', 'lb*s/in', p%c_s, '*SEATSPRINGS CS')
            call put_value('s', 'front-edge spring', 'lb/in', p%s, '*SEATSPRINGS S')
            call put_value('beta_1', 'hip spring, coefficient of d', 'lb/in', p%beta(1), '*SEATSPRINGS BETA1')
            call put_value('beta_2', 'hip spring, coefficient of d^2', 'lb/in^2', p%beta(2), '*SEATSPRINGS BETA2')
            call put_value('beta_3', 'hip spring, coefficient of d^3', 'lb/in^3', p%beta(3), '*SEATSPRINGS BETA3')
         case (seat_rigid_beam)
            call put_value('z_o', 'hip to front edge', 'in', p%z0, '*SEAT Z0')
            call put_value('c_s', 'rear support damper', 'lb*s/in', p%c_s, '*SEATSPRINGS CS')
            call put_value('s', 'front support spring', 'lb/in', p%s, '*SEATSPRINGS S')
            call put_value('beta_1', 'rear support, coefficient of d', 'lb/in', p%beta(1), '*SEATSPRINGS BETA1')
            call put_value('beta_2', 'rear support, coefficient of d^2', 'lb/in^2', p%beta(2), '*SEATSPRINGS BETA2')
            call put_value('beta_3', 'rear support, coefficient of d^3', 'lb/in^3', p%beta(3), '*SEATSPRINGS BETA3')
            call put_value('m_s', 'beam mass', 'lb*s^2/in', p%m_s, '*SEATBEAM MS')
            call put_value('I_s', 'beam moment of inertia', 'lb*in*s^2', p%i_s, '*SEATBEAM IS')
            call put_value('y_gu', 'unloaded height of the beam''s CG', 'in', p%y_gu, '*SEATBEAM YGU')
            call put_angle('gamma_u', 'unloaded beam angle', p%gamma_u, '*SEATBEAM GAMMAU')
            call put_value('k_hip', 'hip contact stiffness', 'lb/in', p%k_hip, '*SEATBEAM KHIP')
            call put_value('k_edge', 'leg contact stiffness at the front edge', 'lb/in', p%k_edge, '*SEATBEAM KEDGE')
            call t%add_line('  the ten quantities at t = 0: four given, six solved from the six initial relations (C.4.d)')
            q = 0.0_wp
            q([bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0]) = &
               [p%a, p%a_prime, p%w0, p%fhps0, p%fs0, p%fps0, p%ds0, p%dz0, p%yg0, p%gamma0/deg]
            do j = 1, n_beam_quantities
               call put_quantity(j, q(j))
            end do
         case (seat_beams)
            call put_value('z_o', 'hip to front edge', 'in', p%z0, '*SEAT Z0')
            call put_angle('gamma_o', 'undeflected cushion angle', p%gamma0, '*SEAT GAMMA0')
            call put_value('l', 'hip beam length (built in at both ends)', 'in', p%ell, '*SEATBEAMS L')
            call put_value('k', 'cantilever length / l', '-', p%k_ratio, '*SEATBEAMS K')
            call put_value('e_1', 'hip beam 3 E I', 'lb*in^2', p%e1, '*SEATBEAMS E1')
            call put_value('e_2', 'cantilever 3 E I', 'lb*in^2', p%e2, '*SEATBEAMS E2')
            call put_value('x''''_sc', 'a point of the cushion line, x', 'in', p%x_sc, '*SEATBEAMS XSC')
            if (group_given(deck, g_seatbeams, 'YSC')) then
               call put_value('y''''_sc', 'a point of the cushion line, y', 'in', p%y_sc, '*SEATBEAMS YSC')
            else
               call put_value('y''''_sc', 'a point of the cushion line, y', 'in', p%y_sc, &
                              'default: touches the hip arc at t = 0')
            end if
         end select
         call put_value('mu', 'friction at the hip', '-', p%mu, '*MATERIALS 1 MU')
         call put_value('xi', 'friction velocity limit', 'in/s', p%xi, '*MATERIALS 1 XI')
      end associate
   contains
      !> A row: symbol, meaning, unit; the value (or, when x is absent, value_text); where it comes from.
      subroutine put_row(symbol, meaning, unit, from, x, value_text, angle)
         character(len=*), intent(in) :: symbol, meaning, unit, from
         real(wp), intent(in), optional :: x
         character(len=*), intent(in), optional :: value_text
         logical, intent(in), optional :: angle
         call t%new_row()
         call t%put(symbol)
         call t%put(meaning)
         call t%put(unit)
         if (present(value_text)) then
            call t%put(value_text)
         else if (present(angle)) then
            call t%put(x/deg, form=cell_fixed, decimals=3)
         else
            call t%put(x)
         end if
         call t%put(from)
      end subroutine put_row
      subroutine put_value(symbol, meaning, unit, x, from)
         character(len=*), intent(in) :: symbol, meaning, unit, from
         real(wp), intent(in) :: x
         call put_row(symbol, meaning, unit, from, x)
      end subroutine put_value
      subroutine put_angle(symbol, meaning, x, from)
         character(len=*), intent(in) :: symbol, meaning, from
         real(wp), intent(in) :: x
         call put_row(symbol, meaning, 'deg', from, x, angle=.true.)
      end subroutine put_angle
      !> W_o or F'_so of the present seat: given on *SEAT as a check, or not.
      subroutine put_check(symbol, meaning, field)
         character(len=*), intent(in) :: symbol, meaning, field
         if (group_given(deck, g_seat, field)) then
            call put_value(symbol, meaning, 'lb', merge(m%seat%w0, m%seat%fps0, field == 'W0'), &
                           '*SEAT '//field//' (a check: the statics are in C.2 below)')
         else
            call put_row(symbol, meaning, 'lb', '*SEAT '//field//' (the statics are in C.2 below)', &
                         value_text='not given')
         end if
      end subroutine put_check
      !> One of the rigid beam's ten initial quantities, given or solved.
      subroutine put_quantity(k, x)
         integer, intent(in) :: k
         real(wp), intent(in) :: x
         character(len=*), parameter :: symbol(n_beam_quantities) = [character(len=10) :: &
            'a', 'a''', 'W_o', 'F-hat''_so', 'F_so', 'F''_so', 'Delta_so', 'Delta_zo', 'y_go', 'gamma_o']
         character(len=*), parameter :: meaning(n_beam_quantities) = [character(len=41) :: &
            'front edge to rear support', 'front edge to beam CG', 'static load at the hip', &
            'static leg load on the front edge', 'rear support force', 'front support force', &
            'rear support deflection', 'front support deflection', 'height of the beam''s CG', 'beam angle']
         character(len=*), parameter :: unit(n_beam_quantities) = [character(len=10) :: &
            'in', 'in', 'lb', 'lb', 'lb', 'lb', 'in', 'in', 'in', 'deg']
         integer :: gid
         character(len=:), allocatable :: from
         gid = g_seatbeaminit
         if (any(k == [bq_w0, bq_fps0, bq_gamma0])) gid = g_seat
         if (group_given(deck, gid, trim(beam_quantity_name(k)))) then
            from = 'given: *'//trim(merge('SEAT        ', 'SEATBEAMINIT', gid == g_seat))//' '//trim(beam_quantity_name(k))
         else
            from = 'solved'
         end if
         if (k == bq_gamma0) then
            call put_angle(trim(symbol(k)), trim(meaning(k)), x*deg, from)
         else
            call put_value(trim(symbol(k)), trim(meaning(k)), trim(unit(k)), x, from)
         end if
      end subroutine put_quantity
   end function seat_parameter_table
end module seat_table
