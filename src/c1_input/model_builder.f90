!> Turns the plain tables of a deck into the model (report C.1) and checks
!! what single fields cannot: relations between fields (omega < Omega,
!! times increasing, the step dividing the print interval, ...), and the
!! options this version supports. Every problem is reported with the file
!! and line of the card concerned.
module model_builder
   use kinds, only: wp, deg, g_std
   use error_handling, only: error_t, error_append, exit_deck
   use strings, only: itoa, num, read_real
   use text_io, only: string_t, read_text_file
   use deck_cards, only: g_title, g_options, g_time, g_segments, g_joints, g_restraints, &
      g_stopcurve, g_injury, g_arcs, g_initial, g_vehicle, g_gravity, g_pulse, g_pulserates, &
      g_pulsepos, g_pulsefile, g_endtests
   use deck_reader, only: deck_t, group_t, card_t
   use model, only: model_t, pulse_table_t, stop_curve_t, n_seg, n_joint, n_injury, n_arc, &
      joint_partner, form_linear, form_cubic, form_table, nint_adams, nint_rk4, nend_contact
   implicit none
   private

   public :: build_model

contains

   !> Fill m from the deck's tables; append every problem found to err.
   subroutine build_model(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err

      call take_defaults(deck, m)
      call read_options(deck, m, err)
      call read_time(deck, m, err)
      call read_body(deck, m, err)
      call read_joints(deck, m, err)
      call read_injury_and_arcs(deck, m, err)
      call read_vehicle(deck, m, err)
   end subroutine build_model

   !> Field defaults for the single-card groups that the deck leaves out.
   subroutine take_defaults(deck, m)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      m%title = ' '
      m%nbody = int_default(deck, g_options, 1)
      m%nbelt = int_default(deck, g_options, 2)
      m%nend = int_default(deck, g_options, 3)
      m%nload = int_default(deck, g_options, 4)
      m%nout = int_default(deck, g_options, 5)
      m%nint = int_default(deck, g_options, 6)
      m%t_max = real_default(deck, g_time, 1)
      m%dt = real_default(deck, g_time, 2)
      m%dt_print = real_default(deck, g_time, 3)
      m%corrector_tol = real_default(deck, g_time, 4)
      m%corrector_max_iter = int_default(deck, g_time, 5)
      m%rtol = real_default(deck, g_time, 6)
      m%atol = real_default(deck, g_time, 7)
      m%gravity = real_default(deck, g_gravity, 1)
      m%rest_speed = real_default(deck, g_endtests, 1)
      m%rest_rate = real_default(deck, g_endtests, 2)
      m%rest_hold = real_default(deck, g_endtests, 3)
      m%xi = real_default(deck, g_joints, 3)
   end subroutine take_defaults

   real(wp) function real_default(deck, gid, k)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid, k
      real_default = deck%spec(gid)%field(k)%default*deck%spec(gid)%field(k)%scale
   end function real_default

   integer function int_default(deck, gid, k)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid, k
      int_default = nint(deck%spec(gid)%field(k)%default)
   end function int_default

   subroutine read_options(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      if (deck%group(g_title)%present .and. deck%group(g_title)%n > 0) &
         m%title = deck%group(g_title)%card(1)%text
      associate (g => deck%group(g_options))
         if (.not. single(g)) return
         m%nbody = nint(g%card(1)%value(1))
         m%nbelt = nint(g%card(1)%value(2))
         m%nend = nint(g%card(1)%value(3))
         m%nload = nint(g%card(1)%value(4))
         m%nout = nint(g%card(1)%value(5))
         m%nint = nint(g%card(1)%value(6))
         if (m%nbelt /= 0) call problem(deck, err, g%card(1), 'field NBELT = '//itoa(m%nbelt) &
            //': belt forces (report C.4.e) are not implemented in this version; use 0')
         if (m%nend == nend_contact) call problem(deck, err, g%card(1), 'field NEND = 2: the ' &
            //'undesired-contact test needs contact surfaces (C.4.f), not implemented in this version')
      end associate
   end subroutine read_options

   subroutine read_time(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      type(card_t) :: c
      associate (g => deck%group(g_time))
         if (single(g)) then
            c = g%card(1)
            m%t_max = c%value(1)
            m%dt = c%value(2)
            m%dt_print = c%value(3)
            m%corrector_tol = c%value(4)
            m%corrector_max_iter = nint(c%value(5))
            m%rtol = c%value(6)
            m%atol = c%value(7)
         else
            c%source = 0
         end if
      end associate
      if (m%dt > m%dt_print) call problem(deck, err, c, 'DT = '//num(m%dt) &
         //' s exceeds DTPRINT = '//num(m%dt_print)//' s')
      if (m%nint == nint_adams .or. m%nint == nint_rk4) then
         if (.not. whole_multiple(m%t_max, m%dt)) call problem(deck, err, c, 'TMAX = ' &
            //num(m%t_max)//' s is not a whole multiple of DT = '//num(m%dt)//' s (needed by the ' &
            //'fixed-step integrators)')
         if (.not. whole_multiple(m%dt_print, m%dt)) call problem(deck, err, c, 'DTPRINT = ' &
            //num(m%dt_print)//' s is not a whole multiple of DT = '//num(m%dt)//' s')
      end if
      ! step and print counts must stay countable (and far from integer overflow)
      if (m%t_max/m%dt > 1.0e9_wp) call problem(deck, err, c, 'TMAX/DT is more than 1e9 steps')
      if (m%dt_print/m%dt > 1.0e9_wp) call problem(deck, err, c, 'DTPRINT/DT is more than 1e9 steps')
   end subroutine read_time

   !> Table 1 segment columns and the initial position.
   subroutine read_body(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      integer :: k, i
      integer, parameter :: chain(6) = [1, 2, 3, 4, 5, 7]

      associate (g => deck%group(g_segments))
         do k = 1, g%n
            i = g%card(k)%index
            m%mass(i) = g%card(k)%value(1)
            m%inertia(i) = g%card(k)%value(2)
            m%length(i) = g%card(k)%value(3)
            m%rho(i) = g%card(k)%value(4)
         end do
         do k = 1, g%n
            i = g%card(k)%index
            ! the lengths that join segments together (section B) must be positive
            if (any(chain == i) .and. .not. m%length(i) > 0.0_wp) call problem(deck, err, g%card(k), &
               'segment '//itoa(i)//': L must be > 0 (it places the next joint; section B)')
            if (any([1, 2, 5, 7] == i) .and. m%rho(i) > m%length(i) .and. m%length(i) > 0.0_wp) &
               call problem(deck, err, g%card(k), 'segment '//itoa(i)//': RHO = '//num(m%rho(i)) &
               //' in lies beyond the far joint (L = '//num(m%length(i))//' in)')
         end do
      end associate
      associate (g => deck%group(g_initial))
         do k = 1, g%n
            i = g%card(k)%index
            m%theta0(i) = g%card(k)%value(1)
            m%theta_dot0(i) = g%card(k)%value(2)
         end do
      end associate
   end subroutine read_body

   !> Table 1 joint columns, the restraint forms and their curves.
   subroutine read_joints(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      integer :: k, i, side
      real(wp) :: rel0

      associate (g => deck%group(g_joints))
         do k = 1, g%n
            i = g%card(k)%index
            m%k_elastic(i) = g%card(k)%value(1)
            m%c_friction(i) = g%card(k)%value(2)
            m%xi(i) = g%card(k)%value(3)
            m%restraint(i)%lower = g%card(k)%value(4)
            m%restraint(i)%upper = g%card(k)%value(5)
            m%restraint(i)%coef_lower = [g%card(k)%value(6), 0.0_wp, 0.0_wp]
            m%restraint(i)%coef_upper = [g%card(k)%value(7), 0.0_wp, 0.0_wp]
            m%restraint(i)%dislocation_lower = m%restraint(i)%lower
            m%restraint(i)%dislocation_upper = m%restraint(i)%upper
            if (.not. m%restraint(i)%lower < m%restraint(i)%upper) then
               call problem(deck, err, g%card(k), 'joint '//itoa(i)//': OMEGA must be less than BOMEGA')
            else if (deck%group(g_initial)%present) then
               ! the stops act on the relative angle alpha_i - alpha_m itself (docs/errata.md D-3)
               rel0 = m%theta0(i) - m%theta0(joint_partner(i))
               if (rel0 < m%restraint(i)%lower .or. rel0 > m%restraint(i)%upper) &
                  call problem(deck, err, g%card(k), 'joint '//itoa(i)//': the initial relative angle ' &
                  //'Theta_'//itoa(i)//' - Theta_'//itoa(joint_partner(i))//' = '//num(rel0/deg) &
                  //' deg lies outside OMEGA..BOMEGA = '//num(m%restraint(i)%lower/deg)//'..' &
                  //num(m%restraint(i)%upper/deg)//' deg')
            end if
         end do
      end associate

      associate (g => deck%group(g_restraints))
         do k = 1, g%n
            i = g%card(k)%index
            m%restraint(i)%form = nint(g%card(k)%value(1))
            m%restraint(i)%coef_lower(2:3) = g%card(k)%value(2:3)
            m%restraint(i)%coef_upper(2:3) = g%card(k)%value(4:5)
            if (m%restraint(i)%form /= form_cubic .and. any(g%card(k)%given(2:5))) &
               call problem(deck, err, g%card(k), 'joint '//itoa(i)//': C2LOW..C3HIGH are ' &
               //'used only with FORM = CUBIC')
            if (g%card(k)%given(6)) m%restraint(i)%dislocation_lower = g%card(k)%value(6)
            if (g%card(k)%given(7)) m%restraint(i)%dislocation_upper = g%card(k)%value(7)
            if (m%restraint(i)%dislocation_lower > m%restraint(i)%lower) call problem(deck, err, &
               g%card(k), 'joint '//itoa(i)//': DISLOW must not exceed the lower stop angle OMEGA')
            if (m%restraint(i)%dislocation_upper < m%restraint(i)%upper) call problem(deck, err, &
               g%card(k), 'joint '//itoa(i)//': DISHIGH must not be below the upper stop angle BOMEGA')
         end do
      end associate

      associate (g => deck%group(g_stopcurve))
         do i = 1, n_joint
            do side = 1, 2
               call read_curve(deck, g, i, side, m, err)
            end do
            if (m%restraint(i)%form == form_table) then
               if (.not. (allocated(m%restraint(i)%curve_lower%depth) .and. &
                          allocated(m%restraint(i)%curve_upper%depth))) then
                  call problem_at(deck, err, g_restraints, 'joint '//itoa(i)//': FORM = TABLE needs ' &
                     //'*STOPCURVE cards for both its LOWER and UPPER stops')
               end if
            else if (allocated(m%restraint(i)%curve_lower%depth) .or. &
                     allocated(m%restraint(i)%curve_upper%depth)) then
               call problem_at(deck, err, g_stopcurve, 'joint '//itoa(i)//' has *STOPCURVE cards ' &
                  //'but its restraint form is not TABLE (add a *RESTRAINTS card with FORM TABLE)')
            end if
         end do
      end associate
   end subroutine read_joints

   !> The points of one side of one joint's stop curve.
   subroutine read_curve(deck, g, joint, side, m, err)
      type(deck_t), intent(in) :: deck
      type(group_t), intent(in) :: g
      integer, intent(in) :: joint, side
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      integer :: k, n
      type(stop_curve_t) :: c
      integer :: last

      n = 0
      do k = 1, g%n
         if (g%card(k)%index == joint .and. nint(g%card(k)%value(1)) == side) n = n + 1
      end do
      if (n == 0) return
      allocate (c%depth(n), c%torque(n))
      n = 0
      last = 0
      do k = 1, g%n
         if (g%card(k)%index /= joint .or. nint(g%card(k)%value(1)) /= side) cycle
         n = n + 1
         c%depth(n) = g%card(k)%value(2)
         c%torque(n) = g%card(k)%value(3)
         if (n == 1 .and. c%depth(1) > 0.0_wp) call problem(deck, err, g%card(k), 'joint ' &
            //itoa(joint)//': the first point of a stop curve must have DEPTH = 0')
         if (n > 1) then
            if (.not. c%depth(n) > c%depth(n - 1)) call problem(deck, err, g%card(k), 'joint ' &
               //itoa(joint)//': DEPTH must increase from card to card of a stop curve')
         end if
         last = k
      end do
      if (n < 2) call problem(deck, err, g%card(last), 'joint '//itoa(joint)//': a stop curve needs ' &
         //'at least two points')
      if (side == 1) then
         m%restraint(joint)%curve_lower = c
      else
         m%restraint(joint)%curve_upper = c
      end if
   end subroutine read_curve

   subroutine read_injury_and_arcs(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      integer :: k, i
      associate (g => deck%group(g_injury))
         do k = 1, g%n
            i = g%card(k)%index
            m%f_shear(i) = g%card(k)%value(1)
            m%f_compression(i) = g%card(k)%value(2)
            m%f_tension(i) = g%card(k)%value(3)
            ! Table 1: FSF for rows 1-9, FCF for 1-3 and 5-8, FTD for joints 1-7
            if (i == 10 .and. g%card(k)%given(1)) call problem(deck, err, g%card(k), &
               'row 10: Table 1 has no shear fracture force FSF here')
            if (any([4, 9, 10] == i) .and. g%card(k)%given(2)) call problem(deck, err, g%card(k), &
               'row '//itoa(i)//': Table 1 has no compression fracture force FCF here')
            if (i > n_joint .and. g%card(k)%given(3)) call problem(deck, err, g%card(k), &
               'row '//itoa(i)//': FTD applies to joints 1-7 only')
         end do
      end associate
      associate (g => deck%group(g_arcs))
         do k = 1, g%n
            i = g%card(k)%index
            m%r_arc(i) = g%card(k)%value(1)
            if (i <= n_arc) then
               m%rho_arc(i) = g%card(k)%value(2)
               m%gamma_arc(i) = g%card(k)%value(3)
            end if
            if (.not. any([2, 3, 4] == i) .and. g%card(k)%given(2)) call problem(deck, err, g%card(k), &
               'arc '//itoa(i)//': RHOP is defined for arcs 2-4 only (Table 1)')
            if (.not. any([2, 3] == i) .and. g%card(k)%given(3)) call problem(deck, err, g%card(k), &
               'arc '//itoa(i)//': GAMMA is defined for arcs 2-3 only (Table 1)')
         end do
      end associate
   end subroutine read_injury_and_arcs

   !> Vehicle constants, initial motion and its time tables (C.1, C.3).
   subroutine read_vehicle(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      type(card_t) :: c

      associate (g => deck%group(g_vehicle))
         if (single(g)) then
            m%vehicle_mass = g%card(1)%value(1)
            m%vehicle_inertia = g%card(1)%value(2)
            m%xc_dot0 = g%card(1)%value(3)
            m%yc_dot0 = g%card(1)%value(4)
            m%phi0 = g%card(1)%value(5)
            m%phi_dot0 = g%card(1)%value(6)
         end if
      end associate
      associate (g => deck%group(g_gravity))
         if (single(g)) m%gravity = g%card(1)%value(1)
      end associate
      associate (g => deck%group(g_endtests))
         if (single(g)) then
            m%rest_speed = g%card(1)%value(1)
            m%rest_rate = g%card(1)%value(2)
            m%rest_hold = g%card(1)%value(3)
         end if
      end associate

      if (deck%group(g_pulsefile)%present .and. deck%group(g_pulsefile)%n > 0) then
         c = deck%group(g_pulsefile)%card(1)
         call read_pulse_csv(deck, c, m, err)
      else if (deck%group(g_pulse)%present) then
         call table_from_group(deck, deck%group(g_pulse), m%pulse_acc, .true., err)
         m%pulse_source = 'cards'
      else
         ! no pulse: the vehicle moves at its initial velocity
         allocate (m%pulse_acc%t(1), m%pulse_acc%v(1, 3))
         m%pulse_acc%t = 0.0_wp
         m%pulse_acc%v = 0.0_wp
         m%pulse_acc%given = .true.
         m%pulse_source = 'none (constant velocity)'
      end if
      if (deck%group(g_pulserates)%present) then
         call table_from_group(deck, deck%group(g_pulserates), m%pulse_vel, .false., err)
         call check_start(deck, deck%group(g_pulserates), m%pulse_vel, &
            [m%xc_dot0, m%yc_dot0, m%phi_dot0], ['XDOT  ', 'YDOT  ', 'PHIDOT'], &
            [1.0_wp, 1.0_wp, deg], ['in/s ', 'in/s ', 'deg/s'], err)
      end if
      if (deck%group(g_pulsepos)%present) then
         call table_from_group(deck, deck%group(g_pulsepos), m%pulse_pos, .false., err)
         call check_start(deck, deck%group(g_pulsepos), m%pulse_pos, [0.0_wp, 0.0_wp, m%phi0], &
            ['X     ', 'Y     ', 'PHI   '], [1.0_wp, 1.0_wp, deg], ['in ', 'in ', 'deg'], err)
      end if
   end subroutine read_vehicle

   !> A time table from list cards (T and three value columns).
   subroutine table_from_group(deck, g, table, all_given, err)
      type(deck_t), intent(in) :: deck
      type(group_t), intent(in) :: g
      type(pulse_table_t), intent(out) :: table
      logical, intent(in) :: all_given
      type(error_t), intent(inout) :: err
      integer :: k, j, n_given
      n_given = 0
      allocate (table%t(g%n), table%v(g%n, 3))
      do k = 1, g%n
         table%t(k) = g%card(k)%value(1)
         table%v(k, :) = g%card(k)%value(2:4)
         if (k == 1 .and. table%t(1) > 0.0_wp) call problem(deck, err, g%card(k), &
            'the first time of a vehicle table must be 0')
         if (k > 1) then
            if (.not. table%t(k) > table%t(k - 1)) call problem(deck, err, g%card(k), &
               'T must increase from card to card')
         end if
      end do
      do j = 1, 3
         if (all_given) then
            table%given(j) = .true.
         else
            n_given = count([(g%card(k)%given(j + 1), k=1, g%n)])
            table%given(j) = n_given > 0
            if (n_given > 0 .and. n_given < g%n) call problem_at(deck, err, g_pulserates, &
               'column '//trim(deck%spec(g_pulserates)%field(j + 1)%name)//' is given on some cards ' &
               //'and blank on others; give it on every card or on none')
         end if
      end do
   end subroutine table_from_group

   !> Tabulated rates or positions must start where the initial conditions do.
   subroutine check_start(deck, g, table, start, names, scale, units, err)
      type(deck_t), intent(in) :: deck
      type(group_t), intent(in) :: g
      type(pulse_table_t), intent(in) :: table
      real(wp), intent(in) :: start(3), scale(3)
      character(len=*), intent(in) :: names(3), units(3)
      type(error_t), intent(inout) :: err
      integer :: j
      do j = 1, 3
         if (.not. table%given(j) .or. size(table%t) == 0) cycle
         if (abs(table%v(1, j) - start(j)) > 1.0e-9_wp*max(1.0_wp, abs(start(j)))) &
            call problem(deck, err, g%card(1), trim(names(j))//' at t = 0 is '//num(table%v(1, j)/scale(j)) &
            //' '//trim(units(j))//' but the initial conditions (*VEHICLE) give '//num(start(j)/scale(j)))
      end do
   end subroutine check_start

   !> The acceleration table from a CSV file named on a *PULSEFILE card.
   subroutine read_pulse_csv(deck, c, m, err)
      type(deck_t), intent(in) :: deck
      type(card_t), intent(in) :: c
      type(model_t), intent(inout) :: m
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: lines(:)
      type(error_t) :: io_err
      character(len=:), allocatable :: path, line, bad_text
      real(wp), allocatable :: t(:), v(:, :)
      real(wp) :: row(4), scale(4)
      integer :: i, n, nfield, bad
      logical :: header_allowed

      path = trim(adjustl(c%text))
      if (path(1:1) /= '/') path = deck%source_dir(c%source)%s//path
      call read_text_file(path, lines, io_err)
      if (io_err%failed()) then
         call problem(deck, err, c, 'pulse file: '//io_err%message)
         return
      end if
      scale = [1.0_wp, g_std, g_std, deg]
      allocate (t(size(lines)), v(size(lines), 3))
      n = 0
      bad = 0
      header_allowed = .true.
      do i = 1, size(lines)
         line = trim(lines(i)%s)
         if (len(line) == 0) cycle
         if (line(1:1) == '#') cycle
         call split_csv_row(line, row, nfield, bad, bad_text)
         if (bad > 0 .and. header_allowed) then
            header_allowed = .false.    ! a first line of column names
            cycle
         end if
         header_allowed = .false.
         if (bad > 0) then
            call csv_problem(path, i, 'field '//itoa(bad)//': found "'//bad_text//'"; expected a number')
            cycle
         end if
         if (nfield < 2 .or. nfield > 4) then
            call csv_problem(path, i, 'expected 2 to 4 comma-separated numbers (t, xddot[, yddot[, ' &
               //'phiddot]]), found '//itoa(nfield))
            cycle
         end if
         n = n + 1
         t(n) = row(1)
         v(n, :) = row(2:4)*scale(2:4)
         if (n == 1 .and. abs(t(1)) > 0.0_wp) call csv_problem(path, i, 'the first time must be 0')
         if (n > 1) then
            if (.not. t(n) > t(n - 1)) call csv_problem(path, i, 'times must increase')
         end if
         if (any(abs(row(2:3)) > 1.0e4_wp)) call csv_problem(path, i, 'acceleration beyond 10000 g')
      end do
      if (n == 0) then
         call csv_problem(path, size(lines), 'no data rows')
         return
      end if
      m%pulse_acc%t = t(1:n)
      m%pulse_acc%v = v(1:n, :)
      m%pulse_acc%given = .true.
      m%pulse_source = path
   contains
      subroutine csv_problem(file, line_no, message)
         character(len=*), intent(in) :: file, message
         integer, intent(in) :: line_no
         call error_append(err, exit_deck, file//':'//itoa(line_no)//': '//message)
      end subroutine csv_problem
   end subroutine read_pulse_csv

   !> Split "a, b, c" into numbers; bad is the first field that is not a
   !! number (0 if none) and bad_text its text; missing fields are 0.
   subroutine split_csv_row(line, row, nfield, bad, bad_text)
      character(len=*), intent(in) :: line
      real(wp), intent(out) :: row(4)
      integer, intent(out) :: nfield, bad
      character(len=:), allocatable, intent(out) :: bad_text
      integer :: start, comma
      logical :: ok
      character(len=:), allocatable :: f
      row = 0.0_wp
      nfield = 0
      bad = 0
      bad_text = ''
      start = 1
      do
         comma = index(line(start:), ',')
         if (comma == 0) then
            f = trim(adjustl(line(start:)))
         else
            f = trim(adjustl(line(start:start + comma - 2)))
         end if
         nfield = nfield + 1
         if (nfield <= 4) then
            call read_real(f, row(nfield), ok)
            if (.not. ok .and. bad == 0) then
               bad = nfield
               bad_text = f(1:min(len(f), 40))
            end if
         end if
         if (comma == 0) exit
         start = start + comma
      end do
   end subroutine split_csv_row

   ! --- helpers ----------------------------------------------------------

   logical function single(g)
      type(group_t), intent(in) :: g
      single = g%present .and. g%n >= 1
   end function single

   !> fixed-step runs need t to be n*dt for a whole n (to 1e-9 relative)
   logical function whole_multiple(t, dt)
      real(wp), intent(in) :: t, dt
      real(wp) :: q
      q = t/dt
      whole_multiple = abs(q - anint(q)) <= 1.0e-9_wp*max(1.0_wp, q) .and. anint(q) >= 1.0_wp
   end function whole_multiple

   !> A problem located at a card.
   subroutine problem(deck, err, c, message)
      type(deck_t), intent(in) :: deck
      type(error_t), intent(inout) :: err
      type(card_t), intent(in) :: c
      character(len=*), intent(in) :: message
      if (c%source > 0) then
         call error_append(err, exit_deck, deck%source_name(c%source)%s//':'//itoa(c%line)//': ' &
            //message)
      else
         call error_append(err, exit_deck, 'deck: '//message)
      end if
   end subroutine problem

   !> A problem located at a group's header card.
   subroutine problem_at(deck, err, gid, message)
      type(deck_t), intent(in) :: deck
      type(error_t), intent(inout) :: err
      integer, intent(in) :: gid
      character(len=*), intent(in) :: message
      associate (g => deck%group(gid))
         if (g%present .and. g%source > 0) then
            call error_append(err, exit_deck, deck%source_name(g%source)%s//':'//itoa(g%line)//': *' &
               //trim(deck%spec(gid)%name)//': '//message)
         else
            call error_append(err, exit_deck, 'deck: *'//trim(deck%spec(gid)%name)//': '//message)
         end if
      end associate
   end subroutine problem_at

end module model_builder
