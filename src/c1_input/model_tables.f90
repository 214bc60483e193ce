!> The parameter tables of the model's own sections, as the listing prints
!! them (Tables 1, 4, 5 and 6 of the report, the options, the initial
!! conditions, the vehicle's pulse): each section describes its table as
!! data (text_table), and the listing prints every table the same way.
!! The effects' subsystems declare theirs beside their code (seat_table,
!! belts_table, interior_table, loading_table); effect_factory lists them all.
module model_tables
   use kinds, only: wp, deg, g_std
   use strings, only: itoa
   use number_format, only: fixed
   use text_table, only: text_table_t, new_table, cell_text, cell_int, cell_fixed
   use model, only: model_t, n_seg, n_joint, n_injury, n_arc, joint_partner, segment_name, joint_name, arc_name, &
      form_name, form_table, integrator_name, end_option_name, nint_adams, astart_name, solver_name, material_name
   implicit none
   private

   public :: options_table, body_table, joints_table, injury_table, materials_table, arcs_table, initial_table
   public :: pulse_table

contains

   !> *OPTIONS, *TIME, *NUMERICS and the environment's G: lines, not columns.
   function options_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      character(len=132) :: line
      t = new_table('OPTIONS AND TIME CONTROLS', keep=9)
      associate (o => m%options, tc => m%time, nc => m%numerics)
         write (line, '(a,i2,a,i2,a,i2,a,i2,a,i2,a,i2)') '  NBODY', o%nbody, '   NBELT', o%nbelt, &
            '   NEND', o%nend, '   NLOAD', o%nload, '   NOUT', o%nout, '   NINT', o%nint
         call t%add_line(line)
         call t%add_line('  integrator: '//trim(integrator_name(o%nint))//'    end test: '//trim(end_option_name(o%nend)))
         if (o%nint == nint_adams) call t%add_line('  Adams-Moulton start: '//trim(astart_name(nc%am_start)))
         write (line, '(a,es11.4,a,es11.4,a,es11.4,a)') '  TMAX', tc%t_max, ' s   DT', tc%dt, ' s   DTPRINT', &
            tc%dt_print, ' s'
         call t%add_line(line)
         write (line, '(a,es10.3,a,i4,a,es10.3,a,es10.3)') '  CTOL', tc%corrector_tol, '   CITER', &
            tc%corrector_max_iter, '   RTOL', tc%rtol, '   ATOL', tc%atol
         call t%add_line(line)
         write (line, '(a,a,a,es10.3,a)') '  solver of A z'''' = b: ', trim(solver_name(nc%solver)), &
            '    energy balance tolerance', nc%energy_tol, merge(' (continue)', ' (stop)    ', nc%energy_continue)
         call t%add_line(line)
         call t%add_line('  G'//fixed(m%environment%gravity, 10, 4)//' in/s^2')
      end associate
   end function options_table

   !> Table 1's segments: mass, weight, inertia, length, centre of gravity.
   function body_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      integer :: i
      t = new_table('TABLE 1 - BODY SEGMENTS (I AS IN TABLE 5)', keep=12)
      call add_item_columns(t, 'I', 'SEGMENT')
      call t%add_column('MASS', 12, unit='lb*s^2/in', lead=3)
      call t%add_column('WEIGHT', 12, unit='lb', lead=3)
      call t%add_column('INERTIA', 12, unit='lb*in*s^2')
      call t%add_column('LENGTH L', 12, unit='in')
      call t%add_column('CG DIST RHO', 12, unit='in')
      associate (b => m%body)
         do i = 1, n_seg
            call item_row(t, i, segment_name(i))
            call t%put(b%mass(i))
            call t%put(b%mass(i)*g_std)
            call t%put(b%inertia(i))
            call t%put(b%length(i))
            call t%put(b%rho(i))
         end do
         call t%new_row()
         call t%skip()
         call t%put('total', right=.true.)
         call t%put(sum(b%mass))
         call t%put(sum(b%mass)*g_std)
      end associate
   end function body_table

   !> Table 1's joints (Table 6's coupling): elasticity, friction, stops
   !! (figure 9) and dislocation limits (figure 10); the stops' tabulated
   !! torques and cubic terms under it.
   function joints_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      character(len=132) :: line
      integer :: i
      t = new_table('TABLE 1 - BODY JOINTS (TABLE 6: JOINT I COUPLES SEGMENTS I AND M)', keep=12)
      call add_item_columns(t, 'I', 'JOINT')
      call t%add_column('M', 3, cell_int, lead=2)
      call t%add_column('K', 12, unit='in*lb/rad')
      call t%add_column('C''', 12, unit='in*lb')
      call t%add_column('XI', 10, cell_fixed, 4, unit='deg/s')
      call t%add_column('OMEGA', 10, cell_fixed, 2, unit='deg')
      call t%add_column('BOMEGA', 10, cell_fixed, 2, unit='deg')
      call t%add_column('T''', 12, unit='in*lb/rad')
      call t%add_column('T-HAT''', 12, unit='in*lb/rad')
      call t%add_column('FORM', 8, cell_text)
      call t%add_column('DISLOCATION', 9, cell_fixed, 2, unit='deg')
      call t%add_column('', 9, cell_fixed, 2, unit='deg')
      do i = 1, n_joint
         associate (r => m%joints%restraint(i), jt => m%joints)
            call item_row(t, i, joint_name(i))
            call t%put(joint_partner(i))
            call t%put(jt%k_elastic(i))
            call t%put(jt%c_friction(i))
            call t%put(jt%xi(i)/deg)
            call t%put(r%lower/deg)
            call t%put(r%upper/deg)
            call t%put(r%coef_lower(1))
            call t%put(r%coef_upper(1))
            call t%put(form_name(r%form))
            call t%put(r%dislocation_lower/deg)
            call t%put(r%dislocation_upper/deg)
         end associate
      end do
      do i = 1, n_joint
         associate (r => m%joints%restraint(i))
            if (r%form == form_table) then
               call t%add_line('  joint '//itoa(i)//': tabulated stop torques, depth (deg) : torque (in*lb)')
               call add_curve('    lower', r%curve_lower%depth, r%curve_lower%torque)
               call add_curve('    upper', r%curve_upper%depth, r%curve_upper%torque)
            else if (any(abs(r%coef_lower(2:3)) > 0.0_wp) .or. any(abs(r%coef_upper(2:3)) > 0.0_wp)) then
               write (line, '(a,i2,a,2es11.3,a,2es11.3)') '  joint', i, ' cubic terms c2, c3: lower', &
                  r%coef_lower(2:3), '   upper', r%coef_upper(2:3)
               call t%add_line(line)
            end if
         end associate
      end do
   contains
      !> depth : torque pairs, five a line
      subroutine add_curve(prefix, d, torque)
         character(len=*), intent(in) :: prefix
         real(wp), intent(in) :: d(:), torque(:)
         integer :: k, j
         do k = 1, size(d), 5
            line = prefix
            do j = k, min(k + 4, size(d))
               line = trim(line)//fixed(d(j)/deg, 10, 3)//':'
               write (line(len_trim(line) + 1:), '(es10.3)') torque(j)
            end do
            call t%add_line(line)
         end do
      end subroutine add_curve
   end function joints_table

   !> Table 5's limits as the deck gives them (0: not checked).
   function injury_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      integer :: i
      t = new_table('TABLE 1 - INJURY CRITERIA (TABLE 5 ROWS; 0 = NOT CHECKED)', keep=13)
      call t%add_column('I', 4, cell_int, lead=3)
      call t%add_column('SHEAR FRACTURE FSF', 18)
      call t%add_column('COMPRESSION FCF', 18, lead=4)
      call t%add_column('TENSION DISLOCATION FTD', 18, lead=3)
      call t%add_column('(lb)', 12, cell_text, lead=11)
      do i = 1, n_injury
         call t%new_row()
         call t%put(i)
         call t%put(m%injury%f_shear(i))
         call t%put(m%injury%f_compression(i))
         call t%put(m%injury%f_tension(i))
      end do
   end function injury_table

   !> Table 4's materials the deck gives (none: no table).
   function materials_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      integer :: i
      t = new_table('TABLE 4 - MATERIALS (THOSE THE DECK GIVES)', keep=count(m%materials%given) + 2)
      if (.not. any(m%materials%given)) return
      call add_item_columns(t, 'L', 'MATERIAL')
      call t%add_column('MU', 12)
      call t%add_column('XI (in/s)', 12)
      call t%add_column('G', 12)
      call t%add_column('R', 12)
      do i = 1, size(m%materials%given)
         if (.not. m%materials%given(i)) cycle
         call t%new_row()
         call t%put(i)
         call t%put(material_name(i), right=.true.)
         call t%put(m%materials%mu(i))
         call t%put(m%materials%xi(i))
         call t%put(m%materials%g(i))
         call t%put(m%materials%r(i))
      end do
   end function materials_table

   !> Table 1's contact arcs (the body points of C.4.f.1) and the ankle's radius.
   function arcs_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      integer :: i
      t = new_table('TABLE 1 - CONTACT ARCS', keep=13)
      call add_item_columns(t, 'I', 'ARC')
      call t%add_column('RADIUS R', 12)
      call t%add_column('RHO''', 12)
      call t%add_column('GAMMA (deg)', 10, cell_fixed, 2)
      associate (b => m%body)
         do i = 1, n_arc
            call item_row(t, i, arc_name(i))
            call t%put(b%r_arc(i))
            call t%put(b%rho_arc(i))
            call t%put(b%gamma_arc(i)/deg)
         end do
         call item_row(t, n_arc + 1, arc_name(n_arc + 1))
         call t%put(b%r_arc(n_arc + 1))
      end associate
   end function arcs_table

   !> The initial angles and rates (C.1) and the vehicle's mass, inertia and initial motion.
   function initial_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      character(len=132) :: line
      integer :: i
      t = new_table('INITIAL CONDITIONS (C.1) AND VEHICLE', keep=14)
      call add_item_columns(t, 'I', 'SEGMENT')
      call t%add_column('THETA0 (deg)', 12, cell_fixed, 3, lead=3)
      call t%add_column('THETADOT0 (deg/s)', 16, cell_fixed, 3, lead=5)
      do i = 1, n_seg
         call item_row(t, i, segment_name(i))
         call t%put(m%body%theta0(i)/deg)
         call t%put(m%body%theta_dot0(i)/deg)
      end do
      associate (v => m%vehicle)
         write (line, '(a,es12.4,a,es12.4,a)') '  vehicle mass', v%mass, ' lb*s^2/in   pitch inertia', &
            v%inertia, ' lb*in*s^2'
         call t%add_line(line)
         call t%add_line('  XDOT0'//fixed(v%xc_dot0, 10, 3)//' in/s   YDOT0'//fixed(v%yc_dot0, 10, 3)//' in/s   PHI0' &
                         //fixed(v%phi0/deg, 9, 3)//' deg   PHIDOT0'//fixed(v%phi_dot0/deg, 10, 3)//' deg/s')
      end associate
   end function initial_table

   !> The vehicle's acceleration table (C.1; its middle left out past 40
   !! rows) and which rates and positions are tabulated too.
   function pulse_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      integer :: k, n
      associate (v => m%vehicle)
         n = size(v%pulse_acc%t)
         t = new_table('VEHICLE ACCELERATION TABLE (C.1): '//itoa(n)//' POINTS', keep=min(n, 20) + 2)
         ! (the index widens from 100,000 rows, pushing the row right: up to the table's limit)
         call t%add_column('M', 5, cell_int, lead=3)
         call t%add_column('T_M (s)', 12, cell_fixed, 5, lead=3)
         call t%add_column('XDDOT (g)', 12, cell_fixed, 4, lead=3)
         call t%add_column('YDDOT (g)', 12, cell_fixed, 4, lead=3)
         call t%add_column('PHIDDOT (deg/s^2)', 16, cell_fixed, 3, lead=3)
         do k = 1, n
            if (n > 40 .and. k > 20 .and. k < n - 9) then
               if (k == 21) call t%add_line('   ...')
               cycle
            end if
            call t%new_row()
            call t%put(k)
            call t%put(v%pulse_acc%t(k))
            call t%put(v%pulse_acc%v(k, 1)/g_std)
            call t%put(v%pulse_acc%v(k, 2)/g_std)
            call t%put(v%pulse_acc%v(k, 3)/deg)
         end do
         if (allocated(v%pulse_vel%t)) call t%add_line('  vehicle rates tabulated for: '//given_axes(v%pulse_vel%given) &
                                                       //' ('//itoa(size(v%pulse_vel%t))//' points)')
         if (allocated(v%pulse_pos%t)) call t%add_line('  vehicle positions tabulated for: ' &
                                                       //given_axes(v%pulse_pos%given)//' (' &
                                                       //itoa(size(v%pulse_pos%t))//' points)')
      end associate
   end function pulse_table

   !> The first two columns of Table 1's tables: the item's number and its name.
   subroutine add_item_columns(t, index_heading, name_heading)
      type(text_table_t), intent(inout) :: t
      character(len=*), intent(in) :: index_heading, name_heading
      call t%add_column(index_heading, 4, cell_int, lead=3)
      call t%add_column(name_heading, 14, cell_text)
   end subroutine add_item_columns

   !> A row's first two cells: the item's number and its name.
   subroutine item_row(t, i, name)
      type(text_table_t), intent(inout) :: t
      integer, intent(in) :: i
      character(len=*), intent(in) :: name
      call t%new_row()
      call t%put(i)
      call t%put(name)
   end subroutine item_row

   function given_axes(given) result(s)
      logical, intent(in) :: given(3)
      character(len=:), allocatable :: s
      s = ''
      if (given(1)) s = s//'x '
      if (given(2)) s = s//'y '
      if (given(3)) s = s//'pitch'
      if (len(s) == 0) s = 'none'
   end function given_axes
end module model_tables
