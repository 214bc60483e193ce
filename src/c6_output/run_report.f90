!> The listing of a run (C.6): the deck echoed with card numbers, the
!! parameter tables laid out like the report's Tables 1-6, the preliminary
!! constants of C.2, the time-history tables chosen by NOUT and a summary
!! (maxima and when they occurred, injuries, the end of the run, the energy
!! balance, the cost of the integration).
module run_report
   use kinds, only: wp, deg, g_std
   use strings, only: itoa
   use model, only: model_t, n_seg, n_joint, n_injury, n_arc, joint_partner, segment_name, &
      joint_name, arc_name, form_name, form_table, integrator_name, end_option_name
   use deck_reader, only: deck_t, echo_bad, echo_header
   use deck_cards, only: group_spec_t, layout_indexed, layout_multi, kind_text
   use listing, only: listing_t
   use simulation, only: run_result_t
   use output_calc, only: output_record_t
   use generalized_forces, only: effect_name, n_effect_kinds, effect_joint_elastic, effect_joint_friction, &
      effect_joint_stops
   use joint_injury, only: event_kind_name
   use end_tests, only: end_reason_text, end_failure
   implicit none
   private

   public :: write_listing, write_deck_echo

   character(len=*), parameter :: fmt_row = '(f10.5,11es11.3)'

contains

   !> The whole listing of a run.
   subroutine write_listing(lst, deck, m, res, version)
      type(listing_t), intent(inout) :: lst
      type(deck_t), intent(in) :: deck
      type(model_t), intent(in) :: m
      type(run_result_t), intent(in) :: res
      character(len=*), intent(in) :: version

      call write_banner(lst, deck, m, version)
      call write_deck_echo(lst, deck)
      call write_parameters(lst, m)
      call write_preliminary(lst, res)
      if (m%nout >= 1) call write_histories(lst, m, res)
      call write_summary(lst, m, res)
   end subroutine write_listing

   subroutine write_banner(lst, deck, m, version)
      type(listing_t), intent(inout) :: lst
      type(deck_t), intent(in) :: deck
      type(model_t), intent(in) :: m
      character(len=*), intent(in) :: version
      integer :: i
      call lst%new_page('RUN')
      call lst%put(' HSRI-2D '//version//'  phase-two two-dimensional crash-victim simulation')
      call lst%put(' after J. M. Becker and D. H. Robbins, Mathematical Simulation of Collision, I,')
      call lst%put(' Highway Safety Research Institute, The University of Michigan (appendix C, phase two)')
      call lst%blank()
      call lst%put(' TITLE   '//trim(m%title))
      do i = 1, size(deck%source_name)
         call lst%put(' DECK    '//deck%source_name(i)%s)
      end do
      call lst%put(' PULSE   '//m%pulse_source)
      call lst%put(' UNITS   inch, pound force, second; angles in degrees in the listing')
   end subroutine write_banner

   !> Every card image with its card number and where it came from.
   subroutine write_deck_echo(lst, deck)
      type(listing_t), intent(inout) :: lst
      type(deck_t), intent(in) :: deck
      integer :: k
      character(len=132) :: line
      character(len=28) :: where
      character(len=1) :: mark
      call lst%new_page('INPUT DECK (C.1)')
      call lst%put(' CARD  M  SOURCE:LINE                  ' &
                   //'         1         2         3         4         5         6         7         8')
      call lst%put('                                       ' &
                   //'12345678901234567890123456789012345678901234567890123456789012345678901234567890')
      do k = 1, deck%n_echo
         associate (e => deck%echo(k))
            mark = ' '
            if (e%group < 0) mark = 'R'          ! replaced by a later deck
            if (e%kind == echo_bad) mark = '?'
            where = source_line(deck, e%source, e%line)
            write (line, '(i5,2x,a1,2x,a28,1x,a)') k, mark, where, e%text
            call lst%put(line)
            ! under each group header, the group's fields at their columns (card table)
            if (e%kind == echo_header .and. e%group /= 0) then
               write (line, '(5x,2x,a1,2x,a28,1x,a)') ':', '', field_ruler(deck%spec(abs(e%group)))
               if (len_trim(line(40:)) > 0) call lst%put(line)
            end if
         end associate
      end do
      call lst%blank()
      call lst%put(' M: R = card of a group replaced by a later deck; the listing uses the later group.')
      call lst%put('    : the fields of the group and their columns, from the card table (docs/deck-format.md).')
   end subroutine write_deck_echo

   !> The names of a group's fields placed at their columns, and 'i' over
   !! the index columns of an indexed group.
   function field_ruler(spec) result(r)
      type(group_spec_t), intent(in) :: spec
      character(len=80) :: r
      integer :: k
      r = ' '
      if (spec%layout == layout_indexed .or. spec%layout == layout_multi) r(2:2) = 'i'
      do k = 1, spec%n_fields
         if (spec%field(k)%kind == kind_text) cycle
         r(spec%field(k)%first_col:spec%field(k)%last_col) = '['//trim(spec%field(k)%name)
         r(spec%field(k)%last_col:spec%field(k)%last_col) = ']'
      end do
   end function field_ruler

   function source_line(deck, src, line) result(s)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: src, line
      character(len=:), allocatable :: s
      character(len=:), allocatable :: name
      name = deck%source_name(src)%s
      if (len(name) > 22) name = '...'//name(len(name) - 18:)
      s = name//':'//itoa(line)
      ! left-aligned in its column (A editing would right-align a short string)
   end function source_line

   !> Tables 1-6 of the report, as the run uses them.
   subroutine write_parameters(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      character(len=132) :: line
      integer :: i

      call lst%new_page('PARAMETERS (C.1, TABLES 1-6)')
      call lst%heading('OPTIONS AND TIME CONTROLS', 8)
      write (line, '(a,i2,a,i2,a,i2,a,i2,a,i2,a,i2)') '  NBODY', m%nbody, '   NBELT', m%nbelt, &
         '   NEND', m%nend, '   NLOAD', m%nload, '   NOUT', m%nout, '   NINT', m%nint
      call lst%put(line)
      call lst%put('  integrator: '//trim(integrator_name(m%nint))//'    end test: '//trim(end_option_name(m%nend)))
      write (line, '(a,es11.4,a,es11.4,a,es11.4,a)') '  TMAX', m%t_max, ' s   DT', m%dt, ' s   DTPRINT', &
         m%dt_print, ' s'
      call lst%put(line)
      write (line, '(a,es10.3,a,i4,a,es10.3,a,es10.3)') '  CTOL', m%corrector_tol, '   CITER', &
         m%corrector_max_iter, '   RTOL', m%rtol, '   ATOL', m%atol
      call lst%put(line)
      write (line, '(a,f10.4,a)') '  G', m%gravity, ' in/s^2'
      call lst%put(line)

      call lst%heading('TABLE 1 - BODY SEGMENTS (I AS IN TABLE 5)', 12)
      call lst%put('   I  SEGMENT        MASS        WEIGHT     INERTIA     LENGTH L    CG DIST RHO')
      call lst%put('                     lb*s^2/in   lb         lb*in*s^2   in          in')
      do i = 1, n_seg
         write (line, '(i4,2x,a12,5es12.4)') i, segment_name(i), m%mass(i), m%mass(i)*g_std, &
            m%inertia(i), m%length(i), m%rho(i)
         call lst%put(line)
      end do
      write (line, '(6x,a12,2es12.4)') 'total', sum(m%mass), sum(m%mass)*g_std
      call lst%put(line)

      call lst%heading('TABLE 1 - BODY JOINTS (TABLE 6: JOINT I COUPLES SEGMENTS I AND M)', 12)
      call lst%put('   I  JOINT         M  K           C''          XI        OMEGA     BOMEGA    ' &
                   //'T''          T-HAT''      FORM    DISLOCATION')
      call lst%put('                       in*lb/rad   in*lb       deg/s     deg       deg       ' &
                   //'in*lb/rad   in*lb/rad           deg      deg')
      do i = 1, n_joint
         associate (r => m%restraint(i))
            write (line, '(i4,2x,a12,i3,2es12.4,f10.4,2f10.2,2es12.4,2x,a6,2f9.2)') i, joint_name(i), &
               joint_partner(i), m%k_elastic(i), m%c_friction(i), m%xi(i)/deg, r%lower/deg, r%upper/deg, &
               r%coef_lower(1), r%coef_upper(1), form_name(r%form), r%dislocation_lower/deg, &
               r%dislocation_upper/deg
         end associate
         call lst%put(line)
      end do
      do i = 1, n_joint
         associate (r => m%restraint(i))
            if (r%form == form_table) then
               call lst%put('  joint '//itoa(i)//': tabulated stop torques, depth (deg) : torque (in*lb)')
               call put_curve('    lower', r%curve_lower%depth, r%curve_lower%torque)
               call put_curve('    upper', r%curve_upper%depth, r%curve_upper%torque)
            else if (any(abs(r%coef_lower(2:3)) > 0.0_wp) .or. any(abs(r%coef_upper(2:3)) > 0.0_wp)) then
               write (line, '(a,i2,a,2es11.3,a,2es11.3)') '  joint', i, ' cubic terms c2, c3: lower', &
                  r%coef_lower(2:3), '   upper', r%coef_upper(2:3)
               call lst%put(line)
            end if
         end associate
      end do

      call lst%heading('TABLE 1 - INJURY CRITERIA (TABLE 5 ROWS; 0 = NOT CHECKED)', 13)
      call lst%put('   I  SHEAR FRACTURE FSF  COMPRESSION FCF  TENSION DISLOCATION FTD   (lb)')
      do i = 1, n_injury
         write (line, '(i4,3es18.4)') i, m%f_shear(i), m%f_compression(i), m%f_tension(i)
         call lst%put(line)
      end do

      call lst%heading('TABLE 1 - CONTACT ARCS', 13)
      call lst%put('   I  ARC           RADIUS R    RHO''        GAMMA (deg)')
      do i = 1, n_arc
         write (line, '(i4,2x,a12,2es12.4,f10.2)') i, arc_name(i), m%r_arc(i), m%rho_arc(i), m%gamma_arc(i)/deg
         call lst%put(line)
      end do
      write (line, '(i4,2x,a12,es12.4)') n_arc + 1, arc_name(n_arc + 1), m%r_arc(n_arc + 1)
      call lst%put(line)

      call lst%heading('INITIAL CONDITIONS (C.1) AND VEHICLE', 14)
      call lst%put('   I  SEGMENT        THETA0 (deg)  THETADOT0 (deg/s)')
      do i = 1, n_seg
         write (line, '(i4,2x,a12,f12.3,f16.3)') i, segment_name(i), m%theta0(i)/deg, m%theta_dot0(i)/deg
         call lst%put(line)
      end do
      write (line, '(a,es12.4,a,es12.4,a)') '  vehicle mass', m%vehicle_mass, ' lb*s^2/in   pitch inertia', &
         m%vehicle_inertia, ' lb*in*s^2'
      call lst%put(line)
      write (line, '(a,f10.3,a,f10.3,a,f8.3,a,f9.3,a)') '  XDOT0', m%xc_dot0, ' in/s   YDOT0', m%yc_dot0, &
         ' in/s   PHI0', m%phi0/deg, ' deg   PHIDOT0', m%phi_dot0/deg, ' deg/s'
      call lst%put(line)
      call write_pulse(lst, m)
   contains
      subroutine put_curve(label, d, t)
         character(len=*), intent(in) :: label
         real(wp), intent(in) :: d(:), t(:)
         integer :: k, j
         do k = 1, size(d), 5
            write (line, '(a,5(f9.3,a,es10.3))') label, (d(j)/deg, ':', t(j), j=k, min(k + 4, size(d)))
            call lst%put(line)
         end do
      end subroutine put_curve
   end subroutine write_parameters

   subroutine write_pulse(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      character(len=132) :: line
      integer :: k, n
      n = size(m%pulse_acc%t)
      call lst%heading('VEHICLE ACCELERATION TABLE (C.1): '//itoa(n)//' POINTS', min(n, 20) + 2)
      call lst%put('   M    T_M (s)     XDDOT (g)   YDDOT (g)   PHIDDOT (deg/s^2)')
      do k = 1, n
         if (n > 40 .and. k > 20 .and. k < n - 9) then
            if (k == 21) call lst%put('   ...')
            cycle
         end if
         write (line, '(i5,f12.5,2f12.4,f16.3)') k, m%pulse_acc%t(k), m%pulse_acc%v(k, 1)/g_std, &
            m%pulse_acc%v(k, 2)/g_std, m%pulse_acc%v(k, 3)/deg
         call lst%put(line)
      end do
      if (allocated(m%pulse_vel%t)) call lst%put('  vehicle rates tabulated for: '//given_axes(m%pulse_vel%given) &
                                                 //' ('//itoa(size(m%pulse_vel%t))//' points)')
      if (allocated(m%pulse_pos%t)) call lst%put('  vehicle positions tabulated for: ' &
                                                 //given_axes(m%pulse_pos%given)//' ('//itoa(size(m%pulse_pos%t))//' points)')
   end subroutine write_pulse

   function given_axes(given) result(s)
      logical, intent(in) :: given(3)
      character(len=:), allocatable :: s
      s = ''
      if (given(1)) s = s//'x '
      if (given(2)) s = s//'y '
      if (given(3)) s = s//'pitch'
      if (len(s) == 0) s = 'none'
   end function given_axes

   !> C.2: a_1..a_17, the scene, the initial state and accelerations.
   subroutine write_preliminary(lst, res)
      type(listing_t), intent(inout) :: lst
      type(run_result_t), intent(in) :: res
      character(len=132) :: line
      integer :: i, k

      call lst%new_page('PRELIMINARY CALCULATIONS (C.2)')
      call lst%heading('BODY MATRIX PARAMETERS A(1)-A(17)', 5)
      do k = 1, 17, 6
         write (line, '(6(a,i2,a,es12.5))') ('  a', i, ' =', res%bc%a(i), i=k, min(k + 5, 17))
         call lst%put(line)
      end do
      call lst%heading('EFFECTS THIS SCENE CALLS FOR (C.4)', 8)
      do k = 1, res%scene%n_effects
         call lst%put('  '//trim(effect_name(res%scene%effect(k)))//joints_of(res%scene%effect(k)))
      end do
      if (res%n_records > 0) then
         associate (r => res%records(1))
            call lst%heading('INITIAL STATE AND ACCELERATIONS', 14)
            call lst%put('  COORDINATE    VALUE         RATE          ACCELERATION   (deg, deg/s, deg/s^2; in, in/s, in/s^2)')
            do i = 1, 10
               if (i <= n_seg) then
                  write (line, '(a,i1,a,3es14.5)') '  alpha', i, '     ', r%z(i)/deg, r%zdot(i)/deg, r%zdd(i)/deg
               else
                  write (line, '(a,3es14.5)') merge('  x_h         ', '  y_h         ', i == 9), r%z(i), r%zdot(i), r%zdd(i)
               end if
               call lst%put(line)
            end do
            write (line, '(a,f10.4,a,f10.4,a)') '  head acceleration', r%head_acc/g_std, ' g   chest acceleration', &
               r%chest_acc/g_std, ' g'
            call lst%put(line)
            write (line, '(a,es13.5,a,es13.5,a)') '  kinetic energy: vehicle', r%ke_vehicle, '   body', sum(r%ke_seg), &
               ' in*lb'
            call lst%put(line)
         end associate
      end if
   contains
      function joints_of(kind) result(s)
         integer, intent(in) :: kind
         character(len=:), allocatable :: s
         s = ''
         select case (kind)
         case (effect_joint_elastic)
            s = list(res%scene%elastic_joints)
         case (effect_joint_friction)
            s = list(res%scene%friction_joints)
         case (effect_joint_stops)
            s = list(res%scene%stop_joints)
         end select
      end function joints_of
      function list(j) result(s)
         integer, intent(in) :: j(:)
         character(len=:), allocatable :: s
         integer :: q
         s = ': joints'
         do q = 1, size(j)
            s = s//' '//itoa(j(q))
         end do
      end function list
   end subroutine write_preliminary

   !> The time-history tables selected by NOUT.
   subroutine write_histories(lst, m, res)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(run_result_t), intent(in) :: res
      integer :: k
      real(wp) :: v(11)

      call table('ACCELERATIONS (g) AND VEHICLE MOTION', &
         '      TIME     HEAD G    CHEST G     XC in      YC in   PHI deg  XCDOT in/s YCDOT in/s' &
         //' PHIDOT d/s XCDDOT g   YCDDOT g  PHIDDOT d/s2', 1)
      call table('ENERGIES (in*lb)', '      TIME  KE VEHICLE   KE BODY    GRAVITY   JT ELASTIC  JT STOPS' &
         //'  FRICTION   TOTAL BODY  BAL ERROR', 2)
      if (m%nout >= 2) then
         call table('GENERALIZED COORDINATES: ALPHA (deg), HIP (in)', head_z('    '), 3)
         call table('GENERALIZED VELOCITIES (deg/s, in/s)', head_z('DOT '), 4)
         call table('GENERALIZED ACCELERATIONS (deg/s^2, in/s^2)', head_z('DDOT'), 5)
         call table('SEGMENT ANGLES RELATIVE TO THE INTERIOR, THETA = ALPHA + PHI (deg)', &
            '      TIME   THETA1     THETA2     THETA3     THETA4     THETA5     THETA6     THETA7     THETA8', 6)
         call table('JOINT ANGLES ALPHA(I) - ALPHA(M) (deg)', &
            '      TIME   HIP 1-7    LSPINE 2-1 USPINE 3-2 NECK 4-3   SHLDR 5-3  ELBOW 6-5  KNEE 7-8', 7)
      end if
      if (m%nout >= 3) then
         call table('SEGMENT KINETIC ENERGIES (in*lb)', &
            '      TIME   KE1        KE2        KE3        KE4        KE5        KE6        KE7        KE8', 8)
         call table('JOINT ELASTIC ENERGY (in*lb)', joint_head(), 9)
         call table('JOINT STOP ENERGY (in*lb)', joint_head(), 10)
         call table('JOINT FRICTION WORK DISSIPATED (in*lb)', joint_head(), 11)
         call table('JOINT POSITIONS RELATIVE TO THE INTERIOR, X (in) (C.4)', joint_head(), 12)
         call table('JOINT POSITIONS RELATIVE TO THE INTERIOR, Y (in) (C.4)', joint_head(), 13)
      end if
   contains
      subroutine table(title, head, which)
         character(len=*), intent(in) :: title, head
         integer, intent(in) :: which
         character(len=132) :: line
         integer :: nv
         call lst%new_page('TIME HISTORIES (C.6)')
         call lst%heading(title, 4)
         call lst%put(head)
         do k = 1, res%n_records
            call values_of(res%records(k), which, v, nv)
            write (line, fmt_row) res%records(k)%t, v(1:nv)
            call lst%put(line)
            if (lst%line == 3) then   ! a new page: repeat the column heads
               call lst%put(' '//title//' (continued)')
               call lst%put(head)
            end if
         end do
      end subroutine table

      function head_z(suffix) result(h)
         character(len=*), intent(in) :: suffix
         character(len=:), allocatable :: h
         integer :: i
         h = '      TIME'
         do i = 1, n_seg
            h = h//'  A'//itoa(i)//suffix//'    '
         end do
         h = h//'  XH'//suffix//'     YH'//suffix
      end function head_z

      function joint_head() result(h)
         character(len=:), allocatable :: h
         h = '      TIME   HIP        LSPINE     USPINE     NECK       SHOULDER   ELBOW      KNEE'
      end function joint_head
   end subroutine write_histories

   !> The values of table `which` in listing units.
   subroutine values_of(r, which, v, nv)
      type(output_record_t), intent(in) :: r
      integer, intent(in) :: which
      real(wp), intent(out) :: v(11)
      integer, intent(out) :: nv
      v = 0.0_wp
      select case (which)
      case (1)
         v = [r%head_acc/g_std, r%chest_acc/g_std, r%veh_pos(1), r%veh_pos(2), r%veh_pos(3)/deg, &
              r%veh_vel(1), r%veh_vel(2), r%veh_vel(3)/deg, r%veh_acc(1)/g_std, r%veh_acc(2)/g_std, &
              r%veh_acc(3)/deg]
         nv = 11
      case (2)
         v(1:8) = [r%ke_vehicle, sum(r%ke_seg), sum(r%pe_gravity), sum(r%e_spring), sum(r%e_stop), &
                   sum(r%w_friction), r%e_total, r%e_error]
         nv = 8
      case (3)
         v(1:10) = [r%z(1:n_seg)/deg, r%z(9:10)]
         nv = 10
      case (4)
         v(1:10) = [r%zdot(1:n_seg)/deg, r%zdot(9:10)]
         nv = 10
      case (5)
         v(1:10) = [r%zdd(1:n_seg)/deg, r%zdd(9:10)]
         nv = 10
      case (6)
         v(1:8) = r%theta/deg
         nv = 8
      case (7)
         v(1:7) = r%joint_angle/deg
         nv = 7
      case (8)
         v(1:8) = r%ke_seg
         nv = 8
      case (9)
         v(1:7) = r%e_spring
         nv = 7
      case (10)
         v(1:7) = r%e_stop
         nv = 7
      case (11)
         v(1:7) = r%w_friction
         nv = 7
      case (12)
         v(1:7) = r%joint_x
         nv = 7
      case default
         v(1:7) = r%joint_y
         nv = 7
      end select
   end subroutine values_of

   !> Maxima and when, injuries, why the run ended, energy balance, cost.
   subroutine write_summary(lst, m, res)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(run_result_t), intent(in) :: res
      character(len=132) :: line
      integer :: i
      real(wp) :: ke_max
      real(wp), parameter :: round_off = 1.0e-12_wp

      call lst%new_page('SUMMARY (C.6, C.7)')
      call lst%heading('END OF RUN', 3)
      write (line, '(a,f10.5,a)') '  ended at t =', res%t_end, ' s: '//end_reason_text(res%end_reason)
      call lst%put(line)
      if (res%end_reason == end_failure) call lst%put('  '//res%failure)

      call lst%heading('MAXIMA OVER ALL ACCEPTED STEPS', 4)
      write (line, '(a,f10.3,a,f10.5,a)') '  head acceleration  ', res%head_max%value/g_std, ' g   at t =', &
         res%head_max%t, ' s'
      call lst%put(line)
      write (line, '(a,f10.3,a,f10.5,a)') '  chest acceleration ', res%chest_max%value/g_std, ' g   at t =', &
         res%chest_max%t, ' s'
      call lst%put(line)

      call lst%heading('JOINT ANGLE RANGES, ALPHA(I) - ALPHA(M) (deg)', 10)
      call lst%put('   I  JOINT          MINIMUM   AT t (s)    MAXIMUM   AT t (s)    STOPS            DISLOCATION')
      do i = 1, n_joint
         associate (r => m%restraint(i))
            write (line, '(i4,2x,a12,2(f10.3,f11.5),2x,2f8.2,1x,2f8.2)') i, joint_name(i), &
               res%joint_min(i)%value/deg, res%joint_min(i)%t, res%joint_max(i)%value/deg, res%joint_max(i)%t, &
               r%lower/deg, r%upper/deg, r%dislocation_lower/deg, r%dislocation_upper/deg
         end associate
         call lst%put(line)
      end do

      call lst%heading('INJURY EVENTS (C.4.c FIGURE 10)', 3)
      if (res%n_events == 0) call lst%put('  none')
      do i = 1, res%n_events
         associate (e => res%events(i))
            write (line, '(a,f10.5,a,a12,a,a,f9.3,a,f9.3,a)') '  t =', e%t, ' s  joint ', joint_name(e%index), &
               '  '//trim(event_kind_name(e%kind)), ': angle', e%value/deg, ' deg, limit', e%limit/deg, ' deg'
         end associate
         call lst%put(line)
      end do

      call lst%heading('ENERGY BALANCE (BODY: KINETIC + GRAVITY + JOINTS + FRICTION WORK)', 4)
      ke_max = 0.0_wp
      do i = 1, res%n_records
         ke_max = max(ke_max, sum(res%records(i)%ke_seg))
      end do
      write (line, '(a,es13.5,a)') '  initial body energy     ', res%e_total0, ' in*lb'
      call lst%put(line)
      if (res%n_records > 0) then
         write (line, '(a,es13.5,a)') '  final balance error     ', res%records(res%n_records)%e_error, ' in*lb'
         call lst%put(line)
      end if
      ! an error at the level of rounding has no meaningful time: say so,
      ! so that listings from different builds compare equal
      if (abs(res%energy_error_max%value) <= round_off*max(1.0_wp, ke_max)) then
         write (line, '(a,es9.1,a)') '  largest balance error    below', round_off, &
            ' of the largest body kinetic energy (rounding)'
      else
         write (line, '(a,es13.5,a,f10.5,a,es10.3,a)') '  largest balance error   ', res%energy_error_max%value, &
            ' in*lb at t =', res%energy_error_max%t, ' s (', &
            abs(res%energy_error_max%value)/max(ke_max, tiny(1.0_wp)), &
            ' of the largest body kinetic energy)'
      end if
      call lst%put(line)

      call lst%heading('INTEGRATION (C.3): '//trim(integrator_name(m%nint)), 10)
      write (line, '(a,i12)') '  accepted steps             ', res%stats%steps
      call lst%put(line)
      write (line, '(a,i12)') '  rejected steps             ', res%stats%rejected
      call lst%put(line)
      write (line, '(a,i12)') '  right-hand-side evaluations', res%stats%evaluations
      call lst%put(line)
      if (m%nint == 1) then
         write (line, '(a,i12)') '  corrector iterations       ', res%stats%corrector_iterations
         call lst%put(line)
         write (line, '(a,i12)') '  steps at the iteration limit', res%stats%corrector_at_limit
         call lst%put(line)
      end if
      if (res%stats%steps > 0) then
         write (line, '(a,es12.4,a,es12.4,a)') '  step size from          ', res%stats%h_min, ' to', &
            res%stats%h_max, ' s'
         call lst%put(line)
      end if
      call lst%put('  evaluations of each effect:')
      do i = 1, n_effect_kinds
         write (line, '(4x,a20,i12)') effect_name(i), res%counts%evaluations(i)
         call lst%put(line)
      end do
   end subroutine write_summary
end module run_report
