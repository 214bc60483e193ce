!> The vehicle and its environment from the deck (report C.1, C.3): *VEHICLE,
!! the pulse (*PULSE or *PULSEFILE), *PULSERATES, *PULSEPOS and *GRAVITY -
!! the section's builder, which reads the fields by the names of the card
!! table (and the pulse's CSV file), and its validators: the tables' times
!! and columns, their start at the initial conditions, and their
!! consistency with each other (the integral of the tables below each).
module vehicle_input
   use kinds, only: wp, deg
   use error_handling, only: error_t, error_append, exit_deck
   use strings, only: itoa, num, escaped, read_int, read_real
   use text_io, only: string_t
   use deck_cards, only: g_vehicle, g_gravity, g_pulse, g_pulserates, g_pulsepos, g_pulsefile, g_pulsemme
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, card_given, group_value, single_card
   use model_origin, only: model_origin_t, cards, field_given, first_card, list_card, card_ref, problem, warning
   use model, only: vehicle_section_t, pulse_table_t, environment_section_t
   use pulse_csv, only: read_pulse_csv
   use pulse_mme, only: read_pulse_mme, mme_channel_classes
   use vehicle_motion, only: vehicle_motion_t, vehicle_state_t, vehicle_motion_init, vehicle_state_at
   implicit none
   private

   public :: build_vehicle, check_vehicle, check_vehicle_tables, build_environment

contains

   !> *GRAVITY.
   function build_environment(deck) result(env)
      type(deck_t), intent(in) :: deck
      type(environment_section_t) :: env
      env = environment_section_t(group_value(deck, g_gravity, 'G'))
   end function build_environment

   !> Vehicle constants, initial motion and its time tables (C.1, C.3):
   !! the pulse from *PULSEFILE's CSV file (its own problems in err) or the
   !! *PULSE cards, and the tables of rates and positions the deck gives.
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
         allocate (v%pulse_inputs(1))
         v%pulse_inputs(1)%s = path
      else if (single_card(deck, g_pulsemme)) then
         call pulse_from_mme(deck, v, err)
      else if (deck%group(g_pulse)%present) then
         call table_from_group(deck, g_pulse, ['XDDOT  ', 'YDDOT  ', 'PHIDDOT'], v%pulse_acc, .true.)
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
         call table_from_group(deck, g_pulserates, ['XDOT  ', 'YDOT  ', 'PHIDOT'], v%pulse_vel, .false.)
      end if
      if (deck%group(g_pulsepos)%present) then
         call table_from_group(deck, g_pulsepos, ['X  ', 'Y  ', 'PHI'], v%pulse_pos, .false.)
      end if
   end subroutine build_vehicle

   !> *PULSEMME (docs/pulse.md): card 1 the data set's .mme file (a
   !! path as *PULSEFILE's), card 2 the channel code (columns 1-20), the
   !! filter's class CFC (21-30) and T0 (31-40), each checked as a field.
   subroutine pulse_from_mme(deck, v, err)
      type(deck_t), intent(in) :: deck
      type(vehicle_section_t), intent(inout) :: v
      type(error_t), intent(inout) :: err
      type(card_t) :: c1, c2
      type(string_t) :: named_at(2)
      character(len=:), allocatable :: path, text, code, raw
      real(wp) :: t_zero
      integer :: cfc
      logical :: good, card_ok
      ! (checked as it is read, as a CSV pulse: a bad card leaves no table)
      v%pulse_from_file = .true.
      v%pulse_source = 'ISO-MME'
      associate (g => deck%group(g_pulsemme))
         if (g%n < 2) return   ! (the reader reported the missing card)
         c1 = g%card(1)
         c2 = g%card(2)
      end associate
      named_at(1)%s = deck%source_name(c1%source)%s//':'//itoa(c1%line)
      named_at(2)%s = deck%source_name(c2%source)%s//':'//itoa(c2%line)
      path = trim(adjustl(c1%text))
      if (path(1:1) /= '/') path = deck%source_dir(c1%source)%s//path
      text = c2%text//repeat(' ', 40)
      code = trim(adjustl(text(1:20)))
      good = len(code) > 0 .and. index(code, ' ') == 0
      card_ok = good
      if (.not. good) call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, CHANNEL (columns ' &
         //'1-20): found "'//escaped(trim(text(1:20)))//'"; expected a channel code, one word (such as ' &
         //'10VEHC0000CGACXD)')
      cfc = 0
      raw = trim(adjustl(text(21:30)))
      if (len(raw) > 0) then
         call read_int(raw, cfc, good)
         if (good) good = cfc == 0 .or. any(cfc == mme_channel_classes)
         card_ok = card_ok .and. good
         if (.not. good) call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, CFC (columns ' &
            //'21-30): found "'//escaped(raw)//'"; expected 0 (no filter), 60, 180, 600 or 1000')
      end if
      t_zero = 0.0_wp
      raw = trim(adjustl(text(31:40)))
      if (len(raw) > 0) then
         call read_real(raw, t_zero, good)
         if (good) good = abs(t_zero) <= 1.0e3_wp
         card_ok = card_ok .and. good
         if (.not. good) call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, T0 (columns ' &
            //'31-40): found "'//escaped(raw)//'"; expected a time from -1000 to 1000 (s)')
      end if
      if (len_trim(text(41:)) > 0) then
         call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2: columns 41-72 must be blank; ' &
            //'found "'//escaped(trim(adjustl(text(41:))))//'"')
         card_ok = .false.
      end if
      if (.not. card_ok) return
      call read_pulse_mme(path, code, cfc, t_zero, named_at, deck%spec(g_pulse), v%pulse_acc, v%pulse_source, &
                          v%pulse_inputs, err)
      v%pulse_source = 'ISO-MME '//v%pulse_source
   end subroutine pulse_from_mme

   !> A time table from list cards: the time T and the columns named for
   !! x, y and the pitch (a column is given when some card gives it; all
   !! when all_given).
   subroutine table_from_group(deck, gid, columns, table, all_given)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid
      character(len=*), intent(in) :: columns(3)
      type(pulse_table_t), intent(out) :: table
      logical, intent(in) :: all_given
      integer :: k, j
      associate (g => deck%group(gid))
         allocate (table%t(g%n), table%v(g%n, 3))
         do k = 1, g%n
            table%t(k) = card_value(deck, gid, g%card(k), 'T')
            do j = 1, 3
               table%v(k, j) = card_value(deck, gid, g%card(k), trim(columns(j)))
            end do
         end do
         do j = 1, 3
            table%given(j) = all_given .or. any([(card_given(deck, gid, g%card(k), trim(columns(j))), k=1, g%n)])
         end do
      end associate
   end subroutine table_from_group

   !> The vehicle's tables: times from 0 and increasing, a column given on
   !! every card of its table or on none, tabulated rates and positions
   !! starting where the initial conditions do (check_start); the
   !! consistency of the tables with each other: check_vehicle_tables.
   subroutine check_vehicle(v, orig, err)
      type(vehicle_section_t), intent(in) :: v
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      ! (a CSV pulse was checked as it was read)
      if (.not. v%pulse_from_file) &
         call check_table(orig, g_pulse, ['XDDOT  ', 'YDDOT  ', 'PHIDDOT'], v%pulse_acc, .true., err)
      if (allocated(v%pulse_vel%t)) then
         call check_table(orig, g_pulserates, ['XDOT  ', 'YDOT  ', 'PHIDOT'], v%pulse_vel, .false., err)
         call check_start(orig, g_pulserates, v%pulse_vel, [v%xc_dot0, v%yc_dot0, v%phi_dot0], &
            ['XDOT  ', 'YDOT  ', 'PHIDOT'], ['XDOT0  ', 'YDOT0  ', 'PHIDOT0'], [1.0_wp, 1.0_wp, deg], &
            ['in/s ', 'in/s ', 'deg/s'], err)
      end if
      if (allocated(v%pulse_pos%t)) then
         call check_table(orig, g_pulsepos, ['X  ', 'Y  ', 'PHI'], v%pulse_pos, .false., err)
         call check_start(orig, g_pulsepos, v%pulse_pos, [0.0_wp, 0.0_wp, v%phi0], &
            ['X     ', 'Y     ', 'PHI   '], ['       ', '       ', 'PHI0   '], [1.0_wp, 1.0_wp, deg], &
            ['in ', 'in ', 'deg'], err)
      end if
   end subroutine check_vehicle

   !> A time table of group gid: T from 0, increasing from row to row (row k
   !! at the group's k-th card); a column the cards give on some and not on
   !! others, unless all_given.
   subroutine check_table(orig, gid, columns, table, all_given, err)
      type(model_origin_t), intent(in) :: orig
      integer, intent(in) :: gid
      character(len=*), intent(in) :: columns(3)
      type(pulse_table_t), intent(in) :: table
      logical, intent(in) :: all_given
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      integer :: k, j, n_given
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, gid)
      do k = 1, size(table%t)
         if (k == 1 .and. table%t(1) > 0.0_wp) call problem(orig, err, list_card(orig, gid, cs, k), &
            'T = '//num(table%t(1))//' s; the first time of a vehicle table must be 0', 'T')
         if (k > 1) then
            if (.not. table%t(k) > table%t(k - 1)) call problem(orig, err, list_card(orig, gid, cs, k), 'T = ' &
               //num(table%t(k))//' s after '//num(table%t(k - 1))//' s on '//card_ref(orig, &
               list_card(orig, gid, cs, k - 1))//'; T must increase from card to card', 'T')
         end if
      end do
      if (all_given) return
      do j = 1, 3
         n_given = count([(field_given(orig, gid, cs(k), trim(columns(j))), k=1, size(cs))])
         if (n_given > 0 .and. n_given < size(cs)) then
            ! at the first card that differs from the first card
            k = findloc([(field_given(orig, gid, cs(k), trim(columns(j))) .neqv. &
                          field_given(orig, gid, cs(1), trim(columns(j))), k=1, size(cs))], .true., 1)
            call problem(orig, err, cs(k), 'column '//trim(columns(j))//' is ' &
               //trim(merge('given', 'blank', field_given(orig, gid, cs(k), trim(columns(j))))) &
               //' here and '//trim(merge('given', 'blank', field_given(orig, gid, cs(1), trim(columns(j))))) &
               //' on '//card_ref(orig, cs(1))//' ('//itoa(n_given)//' of '//itoa(size(cs))//' cards give ' &
               //'it); give it on every card or on none', trim(columns(j)))
         end if
      end do
   end subroutine check_table

   !> Tabulated rates or positions must start where the initial conditions
   !! do (*VEHICLE's field initial(j); blank: the interior's origin, 0).
   subroutine check_start(orig, gid, table, start, names, initial, scale, units, err)
      type(model_origin_t), intent(in) :: orig
      integer, intent(in) :: gid
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
                   //card_ref(orig, first_card(orig, g_vehicle))//')'
         else
            from = 'the vehicle starts at 0 (its initial position is the origin)'
         end if
         if (abs(table%v(1, j) - start(j)) > 1.0e-9_wp*max(1.0_wp, abs(start(j)))) &
            call problem(orig, err, list_card(orig, gid, cards(orig, gid), 1), trim(names(j))//' at t = 0 is ' &
            //num(table%v(1, j)/scale(j))//' '//trim(units(j))//' but '//from, trim(names(j)))
      end do
   end subroutine check_start


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
   subroutine check_vehicle_tables(v, orig, warnings, err)
      type(vehicle_section_t), intent(in) :: v
      type(model_origin_t), intent(in) :: orig
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
               call problem(orig, err, list_card(orig, gid, cards(orig, gid), at), text//'; a table may differ from ' &
                  //'the integral ' &
                  //'by at most 10 % (measurement error; the inertial forces come from the accelerations, C.3): ' &
                  //'is a unit, a column or a digit wrong?', trim(names(j)))
            else
               call warning(orig, warnings, list_card(orig, gid, cards(orig, gid), at), text//': the run takes the ' &
                  //'inertial forces from the accelerations and the motion from this table (C.3)', trim(names(j)))
            end if
         end do
      end subroutine compare
   end subroutine check_vehicle_tables

end module vehicle_input
