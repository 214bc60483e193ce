!> What the listing shows of a solved analog case (report Section D;
!! docs/analog.md), as tables (text_table) the driver prints on the
!! listing's pages: the case's parameters and what follows from them, its
!! events (the front occupant's stops, the rear occupant's stop, the
!! contacts between them and their least separation), its time history at
!! 1 ms, and one line per case for the deck's summary.
module analog_report
   use kinds, only: wp, deg
   use strings, only: itoa
   use number_format, only: fixed
   use text_io, only: string_t, append_string
   use text_table, only: text_table_t, new_table, append_table, cell_text, cell_fixed
   use analog_model, only: analog_solution_t, front_state, rear_state, separation, initial_rate, critical_damping
   implicit none
   private

   public :: analog_parameter_table, analog_event_table, analog_history_tables, analog_summary_table
   public :: analog_history_times, meeting_text, print_interval

   !> The time history's interval, s (the report's table is in ms: 0.026,
   !! 0.050, 0.068, 0.075, 0.125 s are all on it).
   real(wp), parameter :: print_interval = 1.0e-3_wp
   !> Rows of a time-history table per page (docs: run_report's page of rows).
   integer, parameter :: rows_per_page = 50

contains

   !> The case's parameters, as given and as derived.
   function analog_parameter_table(sol, n) result(t)
      type(analog_solution_t), intent(in) :: sol
      integer, intent(in) :: n
      type(text_table_t) :: t
      t = new_table('PARAMETERS OF CASE '//itoa(n)//' (SECTION D)')
      call t%add_column('QUANTITY', 48, form=cell_text, lead=1)
      call t%add_column('VALUE', 14, form=cell_fixed, decimals=4)
      call t%add_column('UNIT', 14, form=cell_text)
      call t%add_column('SOURCE', 50, form=cell_text)
      associate (c => sol%c, b => sol%c%body)
         call row('collision speed v', c%speed/17.6_wp, 'mph', '*ANALOG V')
         call row('harness spring k1', c%k1, 'lb/in', '*ANALOG K1')
         call row('hip to harness l1', c%l1, 'in', '*ANALOG L1')
         call row('harness damping ratio', c%zeta, '-', '*ANALOG ZETA (1: critical)')
         call row('harness damper c', c%zeta*critical_damping(c), 'lb*s/in', 'ZETA times critical (SD-2)')
         call row('front hip torque T', c%torque, 'in*lb', '*ANALOG T')
         call row('seat spacing L, hip to hip', c%spacing, 'in', '*ANALOG L')
         call row('upper body weight W', b%weight, 'lb', 'Section D: 95th-percentile male')
         call row('upper body length, hip to head', b%length, 'in', 'Section D')
         call row('hip to centre of gravity rho', b%rho, 'in', 'Section D')
         call row('moment of inertia about the hip I0', b%inertia, 'lb*in*s^2', 'Section D')
         call row('rear occupant stopped by the seat back at', b%stop_angle/deg, 'deg', 'Section D')
         call row('initial angular velocity omega', initial_rate(c%speed, b), 'rad/s', 'm v rho = I0 omega (SD-5)')
         call row('harness moment per radian l1**2 k1', sol%kappa, 'in*lb/rad', 'SD-2')
         call row('harness natural frequency', sol%wn, 'rad/s', 'sqrt(l1**2 k1 / I0)')
         call row('harness damping moment l1**2 c', sol%damping, 'in*lb*s/rad', 'SD-2')
         call row('torque over stiffness T / (l1**2 k1)', c%torque/sol%kappa/deg, 'deg', 'the centre''s shift')
         call row('duration TMAX', c%t_max, 's', '*ANALOG TMAX')
      end associate
   contains
      subroutine row(name, value, unit, source)
         character(len=*), intent(in) :: name, unit, source
         real(wp), intent(in) :: value
         call t%new_row()
         call t%put(name)
         call t%put(value)
         call t%put(unit)
         call t%put(source)
      end subroutine row
   end function analog_parameter_table

   !> What happens, in time order: the front occupant's stops (theta1' = 0)
   !! and rest, the rear occupant's stop, the contacts; then the least
   !! separation and whether the occupants meet.
   function analog_event_table(sol, n) result(t)
      type(analog_solution_t), intent(in) :: sol
      integer, intent(in) :: n
      type(text_table_t) :: t
      real(wp), allocatable :: when(:)
      type(string_t), allocatable :: what(:)
      real(wp) :: th1, r1, th2, r2
      integer :: k, i
      integer, allocatable :: order(:)
      allocate (when(0), what(0))
      do k = 1, sol%n_phase
         associate (p => sol%phase(k))
            if (p%at_rest) then
               call add(p%t0, 'front occupant at rest at theta1 = '//deg_text(p%theta0)// &
                        ' deg: the harness''s moment no more than T')
            else if (p%t_end <= sol%c%t_max) then
               call front_state(sol, p%t_end, th1, r1)
               call add(p%t_end, 'front occupant stops (theta1'' = 0) at theta1 = '//deg_text(th1)//' deg')
            end if
         end associate
      end do
      if (sol%t_rear_stop <= sol%c%t_max) then
         call front_state(sol, sol%t_rear_stop, th1, r1)
         call add(sol%t_rear_stop, 'rear occupant reaches the front seat back (theta2 = ' &
                  //deg_text(sol%c%body%stop_angle)//' deg); theta1 = '//deg_text(th1)//' deg')
      end if
      do k = 1, sol%n_contact
         associate (ct => sol%contact(k))
            call front_state(sol, ct%t_begin, th1, r1)
            call rear_state(sol%c, sol%omega0, ct%t_begin, th2, r2)
            call add(ct%t_begin, 'THE OCCUPANTS MEET: theta1 = '//deg_text(th1)//' deg, theta2 = '// &
                     deg_text(th2)//' deg')
            if (ct%t_end <= sol%c%t_max) call add(ct%t_end, 'the occupants part (in the analog they pass '// &
                                                  'through each other)')
         end associate
      end do
      ! in time order, ties in the order found
      allocate (order(size(when)))
      order = [(k, k=1, size(when))]
      do k = 2, size(order)
         i = k
         do while (i > 1)
            if (when(order(i - 1)) <= when(order(i))) exit
            order([i - 1, i]) = order([i, i - 1])
            i = i - 1
         end do
      end do
      t = new_table('EVENTS OF CASE '//itoa(n))
      call t%add_column('TIME', 12, form=cell_fixed, decimals=5, unit='s')
      call t%add_column('EVENT', 110, form=cell_text, lead=3)
      do k = 1, size(order)
         call t%new_row()
         call t%put(when(order(k)))
         call t%put(what(order(k))%s)
      end do
      call t%add_line('')
      call t%add_line(' '//meeting_text(sol))
   contains
      subroutine add(time, text)
         real(wp), intent(in) :: time
         character(len=*), intent(in) :: text
         when = [when, time]
         call append_string(what, text)
      end subroutine add
   end function analog_event_table

   !> The case's outcome in one sentence: whether and when the occupants meet.
   function meeting_text(sol) result(s)
      type(analog_solution_t), intent(in) :: sol
      character(len=:), allocatable :: s
      if (sol%n_contact > 0) then
         s = 'THE OCCUPANTS MEET at t = '//trim(adjustl(fixed(sol%contact(1)%t_begin, 12, 5)))//' s'
         if (sol%contact(1)%t_end <= sol%c%t_max) then
            s = s//' (to t = '//trim(adjustl(fixed(sol%contact(1)%t_end, 12, 5)))//' s)'
         else
            s = s//' (still at TMAX)'
         end if
         s = s//'; deepest overlap '//trim(adjustl(fixed(-sol%min_gap, 12, 3)))//' in at t = ' &
             //trim(adjustl(fixed(sol%t_min_gap, 12, 5)))//' s'
      else
         s = 'THE OCCUPANTS DO NOT MEET before t = '//trim(adjustl(fixed(sol%c%t_max, 12, 5)))//' s; least ' &
             //'separation '//trim(adjustl(fixed(sol%min_gap, 12, 3)))//' in at t = ' &
             //trim(adjustl(fixed(sol%t_min_gap, 12, 5)))//' s'
      end if
   end function meeting_text

   !> The times of the time history: every print_interval from 0, and TMAX.
   pure function analog_history_times(t_max) result(times)
      real(wp), intent(in) :: t_max
      real(wp), allocatable :: times(:)
      integer :: n, k
      n = floor(t_max/print_interval + 1.0e-9_wp)
      times = [(k*print_interval, k=0, n)]
      if (t_max - times(n + 1) > 1.0e-9_wp) times = [times, t_max]
   end function analog_history_times

   !> The time history, a table per page of rows: t, theta1 and its rate,
   !! theta2 and its rate (degrees), the separation of the occupants.
   function analog_history_tables(sol, n) result(tables)
      type(analog_solution_t), intent(in) :: sol
      integer, intent(in) :: n
      type(text_table_t), allocatable :: tables(:)
      type(text_table_t) :: t
      real(wp), allocatable :: times(:)
      real(wp) :: th1, r1, th2, r2, gap
      integer :: k
      allocate (tables(0), times(0))
      times = analog_history_times(sol%c%t_max)
      do k = 1, size(times)
         if (mod(k - 1, rows_per_page) == 0) then
            if (k > 1) call append_table(tables, t)
            if (k == 1) then
               t = new_table('TIME HISTORY OF CASE '//itoa(n), keep=rows_per_page + 2)
            else
               t = new_table('TIME HISTORY OF CASE '//itoa(n)//' (CONTINUED)', keep=rows_per_page + 2)
            end if
            call t%add_column('TIME', 12, form=cell_fixed, decimals=4, unit='s')
            call t%add_column('THETA1', 12, form=cell_fixed, decimals=3, unit='deg')
            call t%add_column('THETA1DOT', 12, form=cell_fixed, decimals=2, unit='deg/s')
            call t%add_column('THETA2', 12, form=cell_fixed, decimals=3, unit='deg')
            call t%add_column('THETA2DOT', 12, form=cell_fixed, decimals=2, unit='deg/s')
            call t%add_column('SEPARATION', 13, form=cell_fixed, decimals=3, unit='in')
            call t%add_column('', 10, form=cell_text)
         end if
         call front_state(sol, times(k), th1, r1)
         call rear_state(sol%c, sol%omega0, times(k), th2, r2)
         gap = separation(sol, times(k))
         call t%new_row()
         call t%put(times(k))
         call t%put(th1/deg)
         call t%put(r1/deg)
         call t%put(th2/deg)
         call t%put(r2/deg)
         call t%put(gap)
         if (gap <= 0.0_wp) then
            call t%put('CONTACT')
         else
            call t%skip()
         end if
      end do
      call t%add_line('')
      call t%add_line(' Angles from the vertical, forward positive. SEPARATION: the least distance of either '// &
                      'head from the other''s body line, negative past it.')
      call append_table(tables, t)
   end function analog_history_tables

   !> One line per case: what it is and whether and when the occupants meet.
   function analog_summary_table(sols) result(t)
      type(analog_solution_t), intent(in) :: sols(:)
      type(text_table_t) :: t
      integer :: k
      t = new_table('SUMMARY OF THE CASES')
      call t%add_column('CASE', 6, form=cell_text, lead=1)
      call t%add_column('V', 8, form=cell_fixed, decimals=2, unit='mph')
      call t%add_column('K1', 12, form=cell_fixed, decimals=2, unit='lb/in')
      call t%add_column('L1', 8, form=cell_fixed, decimals=2, unit='in')
      call t%add_column('ZETA', 8, form=cell_fixed, decimals=3, unit='-')
      call t%add_column('T', 10, form=cell_fixed, decimals=1, unit='in*lb')
      call t%add_column('L', 8, form=cell_fixed, decimals=2, unit='in')
      call t%add_column('THETA1 MAX', 11, form=cell_fixed, decimals=2, unit='deg')
      call t%add_column('AT', 9, form=cell_fixed, decimals=4, unit='s')
      call t%add_column('MEET', 6, form=cell_text, lead=2)
      call t%add_column('FROM', 9, form=cell_fixed, decimals=4, unit='s')
      call t%add_column('TO', 9, form=cell_fixed, decimals=4, unit='s')
      call t%add_column('LEAST SEP.', 11, form=cell_fixed, decimals=3, unit='in')
      call t%add_column('AT', 9, form=cell_fixed, decimals=4, unit='s')
      do k = 1, size(sols)
         associate (s => sols(k), c => sols(k)%c)
            call t%new_row()
            call t%put(itoa(k))
            call t%put(c%speed/17.6_wp)
            call t%put(c%k1)
            call t%put(c%l1)
            call t%put(c%zeta)
            call t%put(c%torque)
            call t%put(c%spacing)
            call first_stop(s)
            if (s%n_contact > 0) then
               call t%put('YES')
               call t%put(s%contact(1)%t_begin)
               if (s%contact(1)%t_end <= c%t_max) then
                  call t%put(s%contact(1)%t_end)
               else
                  call t%put('TMAX')
               end if
            else
               call t%put('NO')
               call t%skip()
               call t%skip()
            end if
            call t%put(s%min_gap)
            call t%put(s%t_min_gap)
         end associate
      end do
      call t%add_line('')
      call t%add_line(' THETA1 MAX: where the harness first stops the front occupant. MEET: the first contact '// &
                      'of the occupants before TMAX. LEAST SEP.: negative, the deepest overlap.')
   contains
      subroutine first_stop(s)
         type(analog_solution_t), intent(in) :: s
         real(wp) :: th1, r1
         if (s%n_phase > 0 .and. s%phase(1)%t_end <= s%c%t_max) then
            call front_state(s, s%phase(1)%t_end, th1, r1)
            call t%put(th1/deg)
            call t%put(s%phase(1)%t_end)
         else
            call t%skip()
            call t%skip()
         end if
      end subroutine first_stop
   end function analog_summary_table

   !> An angle in degrees, as the events write it.
   function deg_text(angle) result(s)
      real(wp), intent(in) :: angle
      character(len=:), allocatable :: s
      s = trim(adjustl(fixed(angle/deg, 12, 2)))
   end function deg_text
end module analog_report
