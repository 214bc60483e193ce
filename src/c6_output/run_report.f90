!> The listing of a run (C.6), written as the run goes: the deck echoed
!! with card numbers, the parameter tables laid out like the report's
!! Tables 1-6 and the preliminary constants of C.2 when the run begins; the
!! time-history tables of the output registry chosen by NOUT, a page of
!! rows at a time for every table (so memory stays bounded whatever TMAX and
!! DTPRINT are); the summary at the end (maxima and when they occurred,
!! injuries, the end of the run, the energy balance, the cost).
module run_report
   use kinds, only: wp, deg, g_std, i8, pi
   use strings, only: itoa
   use model, only: model_t, n_seg, n_joint, n_injury, n_arc, joint_partner, segment_name, &
      joint_name, arc_name, form_name, form_table, integrator_name, end_option_name, nint_adams, &
      astart_name, solver_name, material_name, seat_none, seat_springs, seat_rigid_beam, seat_beams, &
      seat_form_name, n_belt_card, belt_card_lap2, coupling_name, nbelt_lap, nbelt_torso
   use deck_reader, only: deck_t, echo_bad, echo_header
   use deck_cards, only: group_spec_t, layout_indexed, layout_multi, kind_text, g_seat, g_seatbeaminit, &
      g_seatbeams
   use deck_fields, only: group_given
   use belt_geometry, only: belt_section_geometry_t, lap_belt_geometry
   use seat_beam_statics, only: n_beam_quantities, beam_quantity_name, bq_a, bq_ap, bq_w0, bq_fhps0, &
      bq_fs0, bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   use error_handling, only: error_t, error_set, exit_io
   use listing, only: listing_t
   use loading_curves, only: curve_is_defined, curve_polynomial, curve_table
   use number_format, only: fixed, es11_3, f10_5, right_int
   use output_series, only: output_series_t, max_listing_columns
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use contact_tables, only: surface_name, contact_pair_t, is_undesired
   use contact_scene, only: scene_pairs, resolved_surface, surface_layers
   use contact_geometry, only: contact_surface_t, surface_flat, surface_line, surface_circle
   use run_summary, only: run_summary_t, occupant_summary_t, extreme_t
   use force_injuries, only: fc_defined, fs_defined, fc_name, fs_name
   use acceleration_criteria, only: hic_result_t
   use event_text, only: event_description
   use end_tests, only: end_reason_text, end_failure, end_energy
   implicit none
   private

   public :: listing_sink_t, listing_sink_start, write_deck_echo

   !> Rows of a time-history table per page (60 lines less the page header,
   !! the table heading and the two column-heading lines).
   integer, parameter :: rows_per_page = 50

   !> The listing as an output sink. It keeps one page of rows of the
   !! tables NOUT selects, nothing more.
   type, extends(output_sink_t) :: listing_sink_t
      type(listing_t) :: lst
      type(deck_t) :: deck
      type(model_t) :: m
      character(len=:), allocatable :: version
      type(output_registry_t) :: reg
      integer, allocatable :: tables(:)          !< registry series printed (NOUT)
      real(wp), allocatable :: t(:), rows(:, :)  !< the pending page: times, frame values
      integer :: n_rows = 0
      logical :: begun = .false.
      character(len=:), allocatable :: effect_lines
   contains
      procedure :: begin => sink_begin
      procedure :: record => sink_record
      procedure :: event => sink_event
      procedure :: finish => sink_finish
   end type listing_sink_t

contains

   !> Prepare the listing (this%lst, created already: output_files) for
   !! the deck and model.
   subroutine listing_sink_start(this, deck, m, version)
      type(listing_sink_t), intent(inout) :: this
      type(deck_t), intent(in) :: deck
      type(model_t), intent(in) :: m
      character(len=*), intent(in) :: version
      this%deck = deck
      this%m = m
      this%version = version
      call this%lst%start('HSRI-2D '//version, m%title)
   end subroutine listing_sink_start

   subroutine sink_begin(this, sys, reg, first, err)
      class(listing_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      integer :: k
      logical, allocatable :: printed(:)
      associate (unused => err%code)
      end associate
      this%reg = reg
      allocate (printed(size(reg%series)))
      do k = 1, size(reg%series)
         printed(k) = this%m%options%nout >= reg%series(k)%nout
      end do
      this%tables = pack([(k, k=1, size(reg%series))], printed)
      allocate (this%t(rows_per_page), this%rows(reg%n_values, rows_per_page))
      this%begun = .true.
      call write_head(this)
      call write_preliminary(this%lst, sys, reg, first)
   end subroutine sink_begin

   !> The banner, the deck and the parameters: everything known before the run.
   subroutine write_head(this)
      class(listing_sink_t), intent(inout) :: this
      call write_banner(this%lst, this%deck, this%m, this%version)
      call write_deck_echo(this%lst, this%deck)
      call write_parameters(this%lst, this%m, this%deck)
   end subroutine write_head

   subroutine sink_record(this, frame, err)
      class(listing_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      if (.not. this%begun) then
         call error_set(err, exit_io, 'the listing received a record before the run began')
         return
      end if
      if (size(this%tables) == 0) return
      this%n_rows = this%n_rows + 1
      this%t(this%n_rows) = frame%t
      this%rows(:, this%n_rows) = frame%v
      if (this%n_rows == rows_per_page) call write_page_of_tables(this)
   end subroutine sink_record

   !> Events are listed in the summary.
   subroutine sink_event(this, e, err)
      class(listing_sink_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      associate (u1 => this%n_rows, u2 => e%t, u3 => err%code)
      end associate
   end subroutine sink_event

   subroutine sink_finish(this, summary, err)
      class(listing_sink_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      associate (unused => err%code)
      end associate
      if (.not. this%begun) call write_head(this)     ! a run that never began still says why
      if (this%n_rows > 0) call write_page_of_tables(this)
      call write_summary(this%lst, this%m, this%reg, summary)
   end subroutine sink_finish

   !> The pending rows of every table, each table on its own page(s), with
   !! its column headings; a table wider than a line is split.
   subroutine write_page_of_tables(this)
      class(listing_sink_t), intent(inout) :: this
      integer :: q, first, last, k, c
      character(len=132) :: line, names, units
      do q = 1, size(this%tables)
         associate (s => this%reg%series(this%tables(q)))
            do first = 1, size(s%col), max_listing_columns
               last = min(first + max_listing_columns - 1, size(s%col))
               call this%lst%new_page('TIME HISTORIES (C.6)')
               call this%lst%heading(s%title//' - '//s%name//trim(merge(' (continued)', '            ', first > 1)), 3)
               names = '      TIME'
               units = '       (s)'
               do c = first, last
                  names = names(1:10 + 11*(c - first))//adjustr(label(s%col(c)%name))
                  units = units(1:10 + 11*(c - first))//adjustr(' '//s%col(c)%listing_unit(1:10))
               end do
               call this%lst%put(names)
               call this%lst%put(units)
               do k = 1, this%n_rows
                  ! the row as write (line, '(f10.5,11es11.3)') would give it (number_format)
                  line = f10_5(this%t(k))
                  do c = first, last
                     line(11 + 11*(c - first):21 + 11*(c - first)) = &
                        es11_3(this%rows(s%offset + c, k)*s%col(c)%listing_scale)
                  end do
                  call this%lst%put(line)
               end do
            end do
         end associate
      end do
      this%n_rows = 0
   end subroutine write_page_of_tables

   !> A column heading: upper case, 11 columns wide, right-aligned.
   pure function label(text) result(h)
      character(len=*), intent(in) :: text
      character(len=11) :: h
      integer :: i
      h = ' '//text(1:min(len_trim(text), 10))
      do i = 1, len(h)
         if (h(i:i) >= 'a' .and. h(i:i) <= 'z') h(i:i) = achar(iachar(h(i:i)) - 32)
      end do
   end function label

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
      ! (a long path or warning continues under its start: listing_put)
      call lst%put(' TITLE   '//trim(m%title), indent=9)
      do i = 1, size(deck%source_name)
         call lst%put(' DECK    '//deck%source_name(i)%s, indent=9)
      end do
      call lst%put(' PULSE   '//m%vehicle%pulse_source, indent=9)
      call lst%put(' UNITS   inch, pound force, second; angles in degrees in the listing')
      do i = 1, size(m%warnings)
         call lst%put(' WARNING '//m%warnings(i)%s, indent=9)
      end do
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
            ! the card number right-aligned in 5 columns, and wider from 100,000 (never asterisks)
            write (line, '(a,2x,a1,2x,a28,1x,a)') repeat(' ', max(0, 5 - len(itoa(k))))//itoa(k), mark, where, e%text
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
   end function source_line

   !> Tables 1-6 of the report, as the run uses them, with the seat's
   !! parameters (C.1) and Table 2 for the belts.
   subroutine write_parameters(lst, m, deck)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(deck_t), intent(in) :: deck
      character(len=132) :: line
      integer :: i

      call lst%new_page('PARAMETERS (C.1, TABLES 1-6)')
      call lst%heading('OPTIONS AND TIME CONTROLS', 9)
      associate (o => m%options, tc => m%time, nc => m%numerics)
         write (line, '(a,i2,a,i2,a,i2,a,i2,a,i2,a,i2)') '  NBODY', o%nbody, '   NBELT', o%nbelt, &
            '   NEND', o%nend, '   NLOAD', o%nload, '   NOUT', o%nout, '   NINT', o%nint
         call lst%put(line)
         call lst%put('  integrator: '//trim(integrator_name(o%nint))//'    end test: '//trim(end_option_name(o%nend)))
         if (o%nint == nint_adams) call lst%put('  Adams-Moulton start: '//trim(astart_name(nc%am_start)))
         write (line, '(a,es11.4,a,es11.4,a,es11.4,a)') '  TMAX', tc%t_max, ' s   DT', tc%dt, ' s   DTPRINT', &
            tc%dt_print, ' s'
         call lst%put(line)
         write (line, '(a,es10.3,a,i4,a,es10.3,a,es10.3)') '  CTOL', tc%corrector_tol, '   CITER', &
            tc%corrector_max_iter, '   RTOL', tc%rtol, '   ATOL', tc%atol
         call lst%put(line)
         write (line, '(a,a,a,es10.3,a)') '  solver of A z'''' = b: ', trim(solver_name(nc%solver)), &
            '    energy balance tolerance', nc%energy_tol, merge(' (continue)', ' (stop)    ', nc%energy_continue)
         call lst%put(line)
         call lst%put('  G'//fixed(m%environment%gravity, 10, 4)//' in/s^2')
      end associate

      associate (b => m%body)
         call lst%heading('TABLE 1 - BODY SEGMENTS (I AS IN TABLE 5)', 12)
         call lst%put('   I  SEGMENT        MASS        WEIGHT     INERTIA     LENGTH L    CG DIST RHO')
         call lst%put('                     lb*s^2/in   lb         lb*in*s^2   in          in')
         do i = 1, n_seg
            write (line, '(i4,2x,a12,5es12.4)') i, segment_name(i), b%mass(i), b%mass(i)*g_std, &
               b%inertia(i), b%length(i), b%rho(i)
            call lst%put(line)
         end do
         write (line, '(6x,a12,2es12.4)') 'total', sum(b%mass), sum(b%mass)*g_std
         call lst%put(line)
      end associate

      call lst%heading('TABLE 1 - BODY JOINTS (TABLE 6: JOINT I COUPLES SEGMENTS I AND M)', 12)
      call lst%put('   I  JOINT         M  K           C''          XI        OMEGA     BOMEGA    ' &
                   //'T''          T-HAT''      FORM    DISLOCATION')
      call lst%put('                       in*lb/rad   in*lb       deg/s     deg       deg       ' &
                   //'in*lb/rad   in*lb/rad           deg      deg')
      do i = 1, n_joint
         associate (r => m%joints%restraint(i), jt => m%joints)
            write (line, '(i4,2x,a12,i3,2es12.4,4a,2es12.4,2x,a6,2a)') i, joint_name(i), &
               joint_partner(i), jt%k_elastic(i), jt%c_friction(i), fixed(jt%xi(i)/deg, 10, 4), &
               fixed(r%lower/deg, 10, 2), fixed(r%upper/deg, 10, 2), '', r%coef_lower(1), r%coef_upper(1), &
               form_name(r%form), fixed(r%dislocation_lower/deg, 9, 2), fixed(r%dislocation_upper/deg, 9, 2)
         end associate
         call lst%put(line)
      end do
      do i = 1, n_joint
         associate (r => m%joints%restraint(i))
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
         write (line, '(i4,3es18.4)') i, m%injury%f_shear(i), m%injury%f_compression(i), m%injury%f_tension(i)
         call lst%put(line)
      end do

      if (any(m%materials%given)) then
         call lst%heading('TABLE 4 - MATERIALS (THOSE THE DECK GIVES)', count(m%materials%given) + 2)
         call lst%put('   L  MATERIAL      MU          XI (in/s)   G           R')
         do i = 1, size(m%materials%given)
            if (.not. m%materials%given(i)) cycle
            write (line, '(i4,2x,a12,4es12.4)') i, material_name(i), m%materials%mu(i), m%materials%xi(i), &
               m%materials%g(i), m%materials%r(i)
            call lst%put(line)
         end do
      end if

      call write_loading_curves(lst, m)
      call write_seat(lst, m, deck)
      call write_belts(lst, m)
      call write_interior(lst, m)

      associate (b => m%body)
         call lst%heading('TABLE 1 - CONTACT ARCS', 13)
         call lst%put('   I  ARC           RADIUS R    RHO''        GAMMA (deg)')
         do i = 1, n_arc
            write (line, '(i4,2x,a12,2es12.4,a)') i, arc_name(i), b%r_arc(i), b%rho_arc(i), fixed(b%gamma_arc(i)/deg, 10, 2)
            call lst%put(line)
         end do
         write (line, '(i4,2x,a12,es12.4)') n_arc + 1, arc_name(n_arc + 1), b%r_arc(n_arc + 1)
         call lst%put(line)

         call lst%heading('INITIAL CONDITIONS (C.1) AND VEHICLE', 14)
         call lst%put('   I  SEGMENT        THETA0 (deg)  THETADOT0 (deg/s)')
         do i = 1, n_seg
            write (line, '(i4,2x,a12,2a)') i, segment_name(i), fixed(b%theta0(i)/deg, 12, 3), &
               fixed(b%theta_dot0(i)/deg, 16, 3)
            call lst%put(line)
         end do
      end associate
      associate (v => m%vehicle)
         write (line, '(a,es12.4,a,es12.4,a)') '  vehicle mass', v%mass, ' lb*s^2/in   pitch inertia', &
            v%inertia, ' lb*in*s^2'
         call lst%put(line)
         call lst%put('  XDOT0'//fixed(v%xc_dot0, 10, 3)//' in/s   YDOT0'//fixed(v%yc_dot0, 10, 3)//' in/s   PHI0' &
                      //fixed(v%phi0/deg, 9, 3)//' deg   PHIDOT0'//fixed(v%phi_dot0/deg, 10, 3)//' deg/s')
      end associate
      call write_pulse(lst, m)
   contains
      subroutine put_curve(prefix, d, t)
         character(len=*), intent(in) :: prefix
         real(wp), intent(in) :: d(:), t(:)
         integer :: k, j
         do k = 1, size(d), 5
            line = prefix
            do j = k, min(k + 4, size(d))
               line = trim(line)//fixed(d(j)/deg, 10, 3)//':'
               write (line(len_trim(line) + 1:), '(es10.3)') t(j)
            end do
            call lst%put(line)
         end do
      end subroutine put_curve
   end subroutine write_parameters

   !> The loading curves the deck gives (C.4.e, Tables 2 and 4;
   !! docs/loading.md) and who uses them.
   subroutine write_loading_curves(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      character(len=132) :: line
      integer :: k, j, n
      n = count([(curve_is_defined(m%loading%curve(k)), k=1, size(m%loading%curve))])
      if (n == 0) return
      call lst%heading('LOADING CURVES (C.4.e, TABLES 2 AND 4; NLOAD = '//itoa(m%options%nload)//')', n + 2)
      do k = 1, size(m%loading%curve)
         associate (c => m%loading%curve(k))
            select case (c%form)
            case (curve_polynomial)
               write (line, '(a,i3,a,i2,a,5es11.3)') '  curve', k, ': polynomial, N =', c%order, ', sigma', &
                  c%sigma(1:c%order)
               call lst%put(line)
               if (any(c%sigma_rate > 0.0_wp)) then
                  write (line, '(a,5es11.3)') '             rate terms', c%sigma_rate(1:c%order)
                  call lst%put(line)
               end if
            case (curve_table)
               write (line, '(a,i3,a)') '  curve', k, ': table of '//itoa(size(c%defl))//' points, deflection (in) : force (lb)'
               call lst%put(line)
               do j = 1, size(c%defl), 5
                  write (line, '(9x,5(es10.3,a,es10.3,2x))') (c%defl(n), ':', c%force(n), n=j, min(j + 4, size(c%defl)))
                  call lst%put(line)
               end do
               if (any(c%sigma_rate > 0.0_wp)) then
                  write (line, '(a,5es11.3)') '             rate terms', c%sigma_rate
                  call lst%put(line)
               end if
            end select
         end associate
      end do
      do k = 1, size(m%loading%material_curve)
         if (m%loading%material_curve(k) > 0) call lst%put('  material '//itoa(k)//' ('//trim(material_name(k)) &
            //') uses curve '//itoa(m%loading%material_curve(k)))
      end do
      do k = 1, size(m%loading%belt_curve)
         if (m%loading%belt_curve(k) > 0) call lst%put('  belt section '//itoa(k)//' uses curve ' &
            //itoa(m%loading%belt_curve(k)))
      end do
   end subroutine write_loading_curves

   !> The seat's parameters (C.1: "the present seat parameters are c_s, s,
   !! beta_1, beta_2, beta_3, z_o, z-hat, gamma_o, W_o and F'_so"; C.4.d for
   !! the beam seats; docs/seat.md), one a line: symbol, meaning, unit, value
   !! and the card field it comes from. Nothing when the deck has no seat.
   subroutine write_seat(lst, m, deck)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(deck_t), intent(in) :: deck
      character(len=*), parameter :: form_text(3) = [character(len=48) :: &
         'the present seat (figures 11-12)', 'a rigid beam on springs (figures 15-16)', &
         'a pair of non-rigid beams (figures 13-14)']
      real(wp) :: q(n_beam_quantities)
      integer :: j, n
      associate (p => m%seat)
         if (p%form == seat_none) return
         n = merge(16, merge(29, 14, p%form == seat_rigid_beam), p%form == seat_springs)
         call lst%heading('SEAT (C.1, C.4.d) - FORM '//trim(seat_form_name(p%form))//': '// &
                          trim(form_text(p%form)), n)
         call lst%put('  SYMBOL    PARAMETER                                UNIT             VALUE   FROM')
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
            call lst%put('  the ten quantities at t = 0: four given, six solved from the six initial relations (C.4.d)')
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
      subroutine put_value(symbol, meaning, unit, x, from)
         character(len=*), intent(in) :: symbol, meaning, unit, from
         real(wp), intent(in) :: x
         character(len=12) :: value
         write (value, '(es12.4)') x
         call put_text(symbol, meaning, unit, value, from)
      end subroutine put_value
      subroutine put_angle(symbol, meaning, x, from)
         character(len=*), intent(in) :: symbol, meaning, from
         real(wp), intent(in) :: x
         call put_text(symbol, meaning, 'deg', fixed(x/deg, 12, 3), from)
      end subroutine put_angle
      !> symbol (10 columns), meaning (41), unit (10), value (12), source.
      subroutine put_text(symbol, meaning, unit, value, from)
         character(len=*), intent(in) :: symbol, meaning, unit, value, from
         character(len=10) :: c_symbol, c_unit
         character(len=41) :: c_meaning
         character(len=12) :: c_value
         c_symbol = symbol
         c_meaning = meaning
         c_unit = unit
         c_value = adjustr(value)
         call lst%put('  '//c_symbol//c_meaning//c_unit//c_value//'   '//from)
      end subroutine put_text
      !> W_o or F'_so of the present seat: given on *SEAT as a check, or not.
      subroutine put_check(symbol, meaning, field)
         character(len=*), intent(in) :: symbol, meaning, field
         if (group_given(deck, g_seat, field)) then
            call put_value(symbol, meaning, 'lb', merge(m%seat%w0, m%seat%fps0, field == 'W0'), &
                           '*SEAT '//field//' (a check: the statics are in C.2 below)')
         else
            call put_text(symbol, meaning, 'lb', 'not given', '*SEAT '//field//' (the statics are in C.2 below)')
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
            call put_angle(symbol(k), meaning(k), x*deg, from)
         else
            call put_value(symbol(k), meaning(k), unit(k), x, from)
         end if
      end subroutine put_quantity
   end subroutine write_seat

   !> Table 2 of the report for the belts NBELT calls for: a column per
   !! section j (1 lap belt, 2 lower torso, 3 upper torso; 4 the lap belt's
   !! second side, LAPSIDES = 2), a row per parameter: h, l_o, phi_o, l'_o,
   !! phi'_o, the slack, the loading (curve, G, R; the curves' sigma_n and
   !! sigma_n+N are in the loading curves above) and the body surface under
   !! the section; then how the sections share their tension.
   subroutine write_belts(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      character(len=*), parameter :: section_name(n_belt_card) = [character(len=16) :: &
         '1. LAP BELT', '2. LOWER TORSO', '3. UPPER TORSO', '4. LAP, SIDE 2']
      character(len=132) :: line
      integer :: cols(n_belt_card), nc, j, k
      logical :: used(n_belt_card)
      real(wp) :: length10(n_belt_card), phi10(n_belt_card)
      associate (b => m%belts, ld => m%loading, nbelt => m%options%nbelt)
         if (nbelt == 0) return
         used = [nbelt_lap(nbelt), nbelt_torso(nbelt), nbelt_torso(nbelt), nbelt_lap(nbelt) .and. b%lap_sides == 2]
         nc = count(used)
         cols(1:nc) = pack([(j, j=1, n_belt_card)], used)
         ! the lap belt's length and angle at t = 0 (C.2 with errata C2-2, C2-3)
         length10 = 0.0_wp
         phi10 = 0.0_wp
         do k = 1, nc
            if (is_lap(cols(k))) call lap_initial(cols(k), length10(cols(k)), phi10(cols(k)))
         end do
         call lst%heading('TABLE 2 - BELTS (C.4.e, C.2): NBELT = '//itoa(nbelt), 17)
         line = '  PARAMETER (SUBSCRIPT J)                             UNIT'
         do k = 1, nc
            line(col(k):col(k) + 13) = adjustr(section_name(cols(k))(1:14))
         end do
         call lst%put(line)
         call put_row('h', 'wrap radius (lap); distance on the torso', 'in', b%h)
         line = row_head('l_o', 'length at t = 0', 'in')
         do k = 1, nc
            j = cols(k)
            if (is_lap(j)) then
               write (line(col(k):), '(es14.4,a)') length10(j), ' c'
            else
               write (line(col(k):), '(es14.4)') b%length0(j)
            end if
         end do
         call lst%put(line)
         line = row_head('phi_o', 'angle at t = 0, anchor to belt', 'deg')
         do k = 1, nc
            j = cols(k)
            if (is_lap(j)) then
               line(col(k):) = fixed(phi10(j)/deg, 14, 3)//' c'
            else
               line(col(k):) = fixed(b%phi0(j)/deg, 14, 3)
            end if
         end do
         call lst%put(line)
         line = row_head('l''_o', 'lap anchor to the initial hip', 'in')
         do k = 1, nc
            j = cols(k)
            if (is_lap(j)) then
               write (line(col(k):), '(es14.4)') b%length_anchor(j)
            else
               line(col(k):) = '             -'
            end if
         end do
         call lst%put(line)
         line = row_head('phi''_o', 'lap, anchor to the initial hip', 'deg')
         do k = 1, nc
            j = cols(k)
            if (is_lap(j)) then
               line(col(k):) = fixed(b%phi_anchor(j)/deg, 14, 3)
            else
               line(col(k):) = '             -'
            end if
         end do
         call lst%put(line)
         call put_row('Delta', 'slack', 'in', b%slack)
         line = row_head('k', 'loading curve (N: its order)', '-')
         do k = 1, nc
            j = cols(k)
            line(col(k):) = curve_text(ld%belt_curve(section(j)), b%lap_sides == 2 .and. is_lap(j))
         end do
         call lst%put(line)
         call put_row('G', 'residual / maximum deformation', '-', ld%belt_g([1, 2, 3, 1]))
         call put_row('R', 'energy conserved / absorbed', '-', ld%belt_r([1, 2, 3, 1]))
         line = row_head('', 'body under the section (Table 4)', '-')
         do k = 1, nc
            j = cols(k)
            line(col(k):) = body_text(merge(11, 12, is_lap(j)))
         end do
         call lst%put(line)
         call lst%put('  c: computed (C.2 with errata C2-2, C2-3); sigma_n, sigma_n+N: the loading curves above')
         if (b%lap_sides == 2) call lst%put('  the lap belt''s two sides: each carries half of the lap belt''s curve' &
                                            //' and of the abdomen''s (docs/belts.md 4)')
         call lst%put('  coupling '//trim(coupling_name(b%coupling))//': '//trim(coupling_text(b%coupling)) &
                      //'   lap sides '//itoa(b%lap_sides)//'   iteration limit '//itoa(b%max_iter))
      end associate
   contains
      pure logical function is_lap(j)
         integer, intent(in) :: j
         is_lap = j == 1 .or. j == belt_card_lap2
      end function is_lap
      !> The loading section (1-3) of card j.
      pure integer function section(j)
         integer, intent(in) :: j
         section = merge(1, j, j == belt_card_lap2)
      end function section
      !> The first column of section column k.
      pure integer function col(k)
         integer, intent(in) :: k
         col = 63 + 16*(k - 1)
      end function col
      !> symbol (10 columns), meaning (42), unit (8).
      function row_head(symbol, meaning, unit) result(h)
         character(len=*), intent(in) :: symbol, meaning, unit
         character(len=132) :: h
         character(len=10) :: c_symbol
         character(len=42) :: c_meaning
         character(len=8) :: c_unit
         c_symbol = symbol
         c_meaning = meaning
         c_unit = unit
         h = '  '//c_symbol//c_meaning//c_unit
      end function row_head
      subroutine put_row(symbol, meaning, unit, x)
         character(len=*), intent(in) :: symbol, meaning, unit
         real(wp), intent(in) :: x(n_belt_card)
         integer :: kk
         line = row_head(symbol, meaning, unit)
         do kk = 1, nc
            write (line(col(kk):), '(es14.4)') x(cols(kk))
         end do
         call lst%put(line)
      end subroutine put_row
      !> C.2 for lap card j: the free length with its wrap, and phi_10 =
      !! phi'_0 + asin(h / l'_0), from the initial hip (the interior origin).
      subroutine lap_initial(j, length, phi)
         integer, intent(in) :: j
         real(wp), intent(out) :: length, phi
         type(belt_section_geometry_t) :: g
         g = lap_belt_geometry(m%belts%h(j), m%belts%length_anchor(j), m%belts%phi_anchor(j), [0.0_wp, 0.0_wp], &
                               m%body%theta0(1))
         length = g%length0
         phi = m%belts%phi_anchor(j) + asin(m%belts%h(j)/m%belts%length_anchor(j))
         phi = modulo(phi + pi, 2.0_wp*pi) - pi
      end subroutine lap_initial
      function curve_text(kc, half) result(t)
         integer, intent(in) :: kc
         logical, intent(in) :: half
         character(len=14) :: t
         character(len=14) :: order
         order = 'table'
         if (m%loading%curve(kc)%form == curve_polynomial) order = 'N = '//itoa(m%loading%curve(kc)%order)
         t = merge('half ', '     ', half)//itoa(kc)//', '//trim(order)
         t = adjustr(t)
      end function curve_text
      function body_text(l) result(t)
         integer, intent(in) :: l
         character(len=14) :: t
         if (m%loading%material_curve(l) > 0) then
            t = itoa(l)//' '//trim(material_name(l))
         else
            t = itoa(l)//' rigid'
         end if
         t = adjustr(t)
      end function body_text
      function coupling_text(c) result(t)
         integer, intent(in) :: c
         character(len=:), allocatable :: t
         select case (c)
         case (1)
            t = 'every section its own tension (the report''s phase two)'
         case (2)
            t = 'the two torso sections one tension'
         case default
            t = 'the three sections one tension'
         end select
      end function coupling_text
   end subroutine write_belts

   subroutine write_pulse(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      character(len=132) :: line
      integer :: k, n
      associate (v => m%vehicle)
         n = size(v%pulse_acc%t)
         call lst%heading('VEHICLE ACCELERATION TABLE (C.1): '//itoa(n)//' POINTS', min(n, 20) + 2)
         call lst%put('   M    T_M (s)     XDDOT (g)   YDDOT (g)   PHIDDOT (deg/s^2)')
         do k = 1, n
            if (n > 40 .and. k > 20 .and. k < n - 9) then
               if (k == 21) call lst%put('   ...')
               cycle
            end if
            ! (the index widens from 100,000 rows: up to the table's limit)
            line = right_int(k, 5)//fixed(v%pulse_acc%t(k), 12, 5)//fixed(v%pulse_acc%v(k, 1)/g_std, 12, 4) &
                   //fixed(v%pulse_acc%v(k, 2)/g_std, 12, 4)//fixed(v%pulse_acc%v(k, 3)/deg, 16, 3)
            call lst%put(line)
         end do
         if (allocated(v%pulse_vel%t)) call lst%put('  vehicle rates tabulated for: '//given_axes(v%pulse_vel%given) &
                                                    //' ('//itoa(size(v%pulse_vel%t))//' points)')
         if (allocated(v%pulse_pos%t)) call lst%put('  vehicle positions tabulated for: ' &
                                                    //given_axes(v%pulse_pos%given)//' ('//itoa(size(v%pulse_pos%t)) &
                                                    //' points)')
      end associate
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
   subroutine write_preliminary(lst, sys, reg, first)
      type(listing_t), intent(inout) :: lst
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      character(len=132) :: line
      integer :: i, k, o, iz, izd, izdd, iacc, ien

      call lst%new_page('PRELIMINARY CALCULATIONS (C.2)')
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            if (size(sys%occupants) > 1) call lst%put(' '//trim(occ%label))
            call lst%heading('BODY MATRIX PARAMETERS A(1)-A(17)', 5)
            do k = 1, 17, 6
               write (line, '(6(a,i2,a,es12.5))') ('  a', i, ' =', occ%bc%a(i), i=k, min(k + 5, 17))
               call lst%put(line)
            end do
            call lst%heading('EFFECTS THIS SCENE CALLS FOR (C.4)', size(occ%effects) + 1)
            do k = 1, size(occ%effects)
               call lst%put('  '//occ%effects(k)%e%describe(), indent=6)
            end do
         end associate
         iz = series_at(reg, 'body/z', o)
         izd = series_at(reg, 'body/zdot', o)
         izdd = series_at(reg, 'body/zddot', o)
         iacc = series_at(reg, 'acceleration', o)
         ien = series_at(reg, 'energy/summary', o)
         call lst%heading('INITIAL STATE AND ACCELERATIONS', 14)
         if (.not. first%valid .or. min(iz, izd, izdd, iacc, ien) == 0) then
            call lst%put('  not available: the right-hand side could not be evaluated at t = 0 (see the summary)')
            cycle
         end if
         call lst%put('  COORDINATE    VALUE         RATE          ACCELERATION   (deg, deg/s, deg/s^2; in, in/s, in/s^2)')
         do i = 1, 10
            write (line, '(2x,a12,3es14.5)') reg%series(iz)%col(i)%name, (first%v(reg%series(iz)%offset + i) &
               *reg%series(iz)%col(i)%listing_scale), first%v(reg%series(izd)%offset + i)*reg%series(izd)%col(i)%listing_scale, &
               first%v(reg%series(izdd)%offset + i)*reg%series(izdd)%col(i)%listing_scale
            call lst%put(line)
         end do
         call lst%put('  head acceleration'//fixed(first%v(reg%series(iacc)%offset + 1)/g_std, 10, 4) &
                      //' g   chest acceleration'//fixed(first%v(reg%series(iacc)%offset + 2)/g_std, 10, 4)//' g')
         write (line, '(a,es13.5,a,es13.5,a)') '  kinetic energy: vehicle', first%v(reg%series(ien)%offset + 1), &
            '   body', first%v(reg%series(ien)%offset + 2), ' in*lb'
         call lst%put(line)
      end do
   end subroutine write_preliminary

   !> The series name (of occupant o) in the registry, or 0.
   pure integer function series_at(reg, name, o) result(k)
      type(output_registry_t), intent(in) :: reg
      character(len=*), intent(in) :: name
      integer, intent(in) :: o
      do k = 1, size(reg%series)
         if (reg%series(k)%occupant /= o) cycle
         associate (n => reg%series(k)%name)
            if (len(n) < len(name)) cycle
            if (n(len(n) - len(name) + 1:) == name) return
         end associate
      end do
      k = 0
   end function series_at

   !> Maxima and when, injuries, why the run ended, energy balance, cost.
   subroutine write_summary(lst, m, reg, res)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(output_registry_t), intent(in) :: reg
      type(run_summary_t), intent(in) :: res
      character(len=132) :: line
      character(len=:), allocatable :: head, ev
      integer :: i, o, k

      call lst%new_page('SUMMARY (C.6, C.7)')
      call lst%heading('END OF RUN', 3)
      call lst%put('  ended at t ='//fixed(res%t_end, 10, 5)//' s: '//end_reason_text(res%end_reason))
      if (res%end_reason == end_failure .or. res%end_reason == end_energy) call lst%put('  '//res%failure, indent=4)

      do o = 1, size(res%occ)
         associate (os => res%occ(o))
            call lst%heading('MAXIMA OVER ALL ACCEPTED STEPS', 4)
            call lst%put('  head acceleration  '//fixed(os%head_max%value/g_std, 10, 3)//' g   at t ='// &
                         fixed(os%head_max%t, 10, 5)//' s')
            call lst%put('  chest acceleration '//fixed(os%chest_max%value/g_std, 10, 3)//' g   at t ='// &
                         fixed(os%chest_max%t, 10, 5)//' s')
            call put_injury_criteria(lst, os)
            call put_peaks(lst, os)

            call lst%heading('JOINT ANGLE RANGES, ALPHA(I) - ALPHA(M) (deg)', 10)
            call lst%put('   I  JOINT          MINIMUM   AT t (s)    MAXIMUM   AT t (s)    STOPS            DISLOCATION')
            do i = 1, n_joint
               associate (r => m%joints%restraint(i))
                  write (line, '(i4,2x,a12,10a)') i, joint_name(i), fixed(os%joint_min(i)%value/deg, 10, 3), &
                     fixed(os%joint_min(i)%t, 11, 5), fixed(os%joint_max(i)%value/deg, 10, 3), &
                     fixed(os%joint_max(i)%t, 11, 5), '  ', fixed(r%lower/deg, 8, 2), fixed(r%upper/deg, 8, 2), ' ', &
                     fixed(r%dislocation_lower/deg, 8, 2), fixed(r%dislocation_upper/deg, 8, 2)
               end associate
               call lst%put(line)
            end do
         end associate
      end do

      call lst%heading('INJURY EVENTS (C.4.c FIGURE 10, C.4.f FIGURE 26)', 3)
      call put_events(.false.)
      if (any([(res%events(i)%note, i=1, res%n_events)])) then
         call lst%heading('NOTES (NOT INJURIES)', 3)
         call put_events(.true.)
      end if
      do o = 1, size(res%occ)
         if (res%occ(o)%force_checked) call put_force_maxima(lst, m, res%occ(o))
      end do

      do o = 1, size(res%occ)
         associate (os => res%occ(o))
            call lst%heading('ENERGY BALANCE (BODY KINETIC + STORED + DISSIPATED - SUPPLIED, AT PRINT TIMES)', 6)
            write (line, '(a,es13.5,a)') '  initial body energy     ', os%e_total0, ' in*lb'
            call lst%put(line)
            write (line, '(a,es13.5,a)') '  final balance error     ', os%e_error_final, ' in*lb'
            call lst%put(line)
            ! an error at the level of rounding has no meaningful time: say so,
            ! so that listings from different builds compare equal
            if (abs(os%energy_error_max%value) <= 1.0e-12_wp*max(1.0_wp, os%ke_max)) then
               call lst%put('  largest balance error    below 1.0E-12 of the largest body kinetic energy (rounding)')
            else
               write (line, '(a,es13.5,a,a,a,es10.3,a)') '  largest balance error   ', os%energy_error_max%value, &
                  ' in*lb at t =', fixed(os%energy_error_max%t, 10, 5), ' s (', &
                  abs(os%energy_error_max%value)/max(os%ke_max, tiny(1.0_wp)), ' of the largest body kinetic energy)'
               call lst%put(line)
            end if
            write (line, '(a,es10.3,a)') '  tolerance (EBTOL)        ', m%numerics%energy_tol, &
               ' of the largest body kinetic energy'
            call lst%put(line)
            if (os%energy_flagged) then
               call lst%put('  THE ENERGY BALANCE FAILED at t ='//fixed(os%t_flagged, 10, 5)//' s: the results are ' &
                            //'not trustworthy')
            else
               call lst%put('  within tolerance')
            end if
         end associate
      end do

      associate (st => res%stats)
         call lst%heading('INTEGRATION (C.3): '//trim(integrator_name(m%options%nint)), 12)
         call count_line('  accepted steps             ', st%steps)
         call count_line('  rejected steps             ', st%rejected)
         call count_line('  right-hand-side evaluations', st%evaluations)
         call count_line('  restarts after a jump      ', st%restarts)
         if (m%options%nint == nint_adams) then
            call count_line('  corrector iterations       ', st%corrector_iterations)
            call count_line('  steps at the iteration limit', st%corrector_at_limit)
         end if
         if (st%steps > 0) then
            write (line, '(a,es12.4,a,es12.4,a)') '  step size from          ', st%h_min, ' to', st%h_max, ' s'
            call lst%put(line)
         end if
      end associate
      call lst%put('  evaluations of each effect:')
      associate (unused => reg%n_values)
      end associate
      do o = 1, size(res%occ)
         do k = 1, size(res%counts, 1)
            if (res%effect_titles(k, o) == ' ') cycle
            call lst%put('    '//effect_label(o, k)//right_int(res%counts(k, o), 12))
         end do
      end do
   contains
      !> The events (notes = .false.) or the notes, each with its time
      !! (and occupant); a long one continues under its description.
      subroutine put_events(notes)
         logical, intent(in) :: notes
         integer :: j, n
         n = 0
         do j = 1, res%n_events
            associate (e => res%events(j))
               if (e%note .neqv. notes) cycle
               n = n + 1
               head = '  t ='//fixed(e%t, 10, 5)//' s  '
               if (size(res%occ) > 1) head = head//'occupant '//itoa(e%occupant)
               ev = head//' '//event_description(e)
               call lst%put(ev, indent=len(head) + 1)
            end associate
         end do
         if (n == 0) call lst%put('  none')
      end subroutine put_events
      subroutine count_line(text, n)
         character(len=*), intent(in) :: text
         integer(i8), intent(in) :: n
         call lst%put(text//right_int(n, 12))
      end subroutine count_line
      function effect_label(occupant, k) result(s)
         integer, intent(in) :: occupant, k
         character(len=40) :: s
         s = res%effect_titles(k, occupant)
      end function effect_label
   end subroutine write_summary

   !> The interior (C.4.f, Table 3; docs/contacts.md): each surface as the
   !! scene resolves it (both ends, direction, normal, padding), and the
   !! position's pairs that the scene assembles with their materials, the
   !! undesired ones (Table 9) marked.
   subroutine write_interior(lst, m)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(contact_pair_t), allocatable :: pairs(:)
      type(contact_surface_t) :: sf
      character(len=132) :: line
      logical :: ok
      integer :: q, k, n, l, lb
      if (.not. any(m%interior%given)) return
      allocate (pairs(0))
      pairs = scene_pairs(m)
      n = 0
      do k = 1, 32
         call resolved_surface(m%interior, k, sf, ok)
         if (ok) n = n + 1
      end do
      call lst%heading('INTERIOR SURFACES (C.4.f, TABLE 3; OCCUPANT''S INTERIOR FRAME)', n + 3)
      call lst%put('   K  SURFACE                KIND       X''''         Y''''         PSI (deg)   D           D''''' &
                   //'        FAR END X   FAR END Y')
      do k = 1, 32
         call resolved_surface(m%interior, k, sf, ok)
         if (.not. ok) cycle
         write (line, '(i4,2x,a22,1x,a10,7a)') k, name22(surface_name(k)), surface_kind(sf%kind), &
            fixed(sf%s(1), 11, 3), fixed(sf%s(2), 11, 3), fixed(sf%psi/deg, 11, 2), fixed(sf%d, 11, 3), &
            fixed(m%interior%dpp(merge(5, min(k, 32), k == 25)), 11, 3), &
            fixed(sf%s(1) - sf%d*cos(sf%psi), 11, 3), fixed(sf%s(2) - sf%d*sin(sf%psi), 11, 3)
         call lst%put(line)
      end do
      call lst%heading('CONTACT PAIRS OF NBODY '//itoa(m%options%nbody)//' ASSEMBLED (TABLES 7, 8, 9, 10)', &
                       size(pairs) + 3)
      call lst%put('   I  BODY POINT      K  SURFACE                MATERIAL  BACKING  UNDESIRED (TABLE 9)')
      do q = 1, size(pairs)
         call surface_layers(m%interior, pairs(q)%k, l, lb)
         write (line, '(i4,2x,a12,i5,2x,a22,i6,i9,5x,a)') pairs(q)%i, arc_name(pairs(q)%i), pairs(q)%k, &
            name22(surface_name(pairs(q)%k)), l, lb, &
            trim(merge('yes', '   ', is_undesired(m%options%nbody, pairs(q)%i, pairs(q)%k)))
         call lst%put(line)
      end do
   contains
      !> a name left-justified in 22 columns
      pure function name22(name) result(text)
         character(len=*), intent(in) :: name
         character(len=22) :: text
         text = name
      end function name22

      pure function surface_kind(kind) result(text)
         integer, intent(in) :: kind
         character(len=10) :: text
         select case (kind)
         case (surface_flat); text = 'flat'
         case (surface_line); text = 'line'
         case (surface_circle); text = 'circle'
         case default; text = 'edge point'
         end select
      end function surface_kind
   end subroutine write_interior

   !> HIC15, HIC36, GSI and the chest's 3 ms clip (docs/injury.md): not the
   !! report's criteria, which predate them, but what users now expect.
   subroutine put_injury_criteria(lst, os)
      type(listing_t), intent(inout) :: lst
      type(occupant_summary_t), intent(in) :: os
      type(hic_result_t) :: r
      call lst%heading('ACCELERATION CRITERIA OF HEAD AND CHEST (ACCEPTED STEPS)', 6)
      r = os%head_criteria%hic15()
      call lst%put('  head HIC15         '//fixed(r%value, 10, 1)//'     from t ='//fixed(r%t1, 10, 5) &
                   //' s to'//fixed(r%t2, 10, 5)//' s')
      r = os%head_criteria%hic36()
      call lst%put('  head HIC36         '//fixed(r%value, 10, 1)//'     from t ='//fixed(r%t1, 10, 5) &
                   //' s to'//fixed(r%t2, 10, 5)//' s')
      call lst%put('  head GSI           '//fixed(os%head_criteria%gsi, 10, 1))
      call lst%put('  chest GSI          '//fixed(os%chest_criteria%gsi, 10, 1))
      call lst%put('  chest 3 ms clip    '//fixed(os%chest_criteria%clip3ms(), 10, 3)//' g')
   end subroutine put_injury_criteria

   !> The largest values the effects kept over the accepted steps (the
   !! contact pairs' largest force, where and how deep it acted), an effect's
   !! title and a time where they change. Nothing when no effect kept one.
   subroutine put_peaks(lst, os)
      type(listing_t), intent(inout) :: lst
      type(occupant_summary_t), intent(in) :: os
      character(len=132) :: line
      integer :: i
      logical :: new_time
      if (.not. allocated(os%peaks)) return
      if (size(os%peaks) == 0) return
      call lst%heading('PEAKS OVER ALL ACCEPTED STEPS (THE SEAT; EACH CONTACT PAIR: WHERE, T, HOW DEEP, DELTA)', &
                       min(size(os%peaks), 12))
      do i = 1, size(os%peaks)
         associate (p => os%peaks(i))
            line = ' '
            if (i == 1) then
               line(3:42) = p%title
            else if (p%title /= os%peaks(i - 1)%title) then
               line(3:42) = p%title
            end if
            line(44:67) = p%label
            line(68:79) = fixed(p%value, 12, 3)
            line(81:88) = p%unit
            ! the time where the effect or the time changes (a pair's T and delta are at its peak's)
            new_time = len_trim(line(3:42)) > 0
            if (i > 1) new_time = new_time .or. p%t > os%peaks(i - 1)%t .or. p%t < os%peaks(i - 1)%t
            if (new_time) line(89:) = 'at t ='//fixed(p%t, 10, 5)//' s'
            call lst%put(line)
         end associate
      end do
   end subroutine put_peaks

   !> Table 5's force criteria: the largest tension at each joint and
   !! compression and shear of each bone over all accepted steps, with the
   !! deck's limits (0: not checked).
   subroutine put_force_maxima(lst, m, os)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(occupant_summary_t), intent(in) :: os
      character(len=132) :: line
      integer :: i
      call lst%heading('FORCE INJURY CRITERIA, LARGEST OVER ALL ACCEPTED STEPS (TABLE 5, NEWTON-EULER)', 21)
      call lst%put('   J  JOINT           TENSION   AT t (s)        FTD')
      do i = 1, n_joint
         write (line, '(i4,2x,a12,3a)') i, joint_name(i), fixed(os%ft_max(i)%value, 10, 1), &
            fixed(os%ft_max(i)%t, 11, 5), fixed(m%injury%f_tension(i), 11, 0)
         call lst%put(line)
      end do
      call lst%put('   I  BONE        COMPRESSION   AT t (s)        FCF    BONE              SHEAR   AT t (s)        FSF')
      do i = 1, n_injury
         if (.not. (fc_defined(i) .or. fs_defined(i) .or. m%injury%f_shear(i) > 0.0_wp &
                    .or. m%injury%f_compression(i) > 0.0_wp)) cycle
         write (line, '(i4,2x,2a)') i, cell(fc_defined(i), fc_name(i), os%fc_max(i), m%injury%f_compression(i)), &
            '    '//cell(fs_defined(i), fs_name(i), os%fs_max(i), m%injury%f_shear(i))
         call lst%put(line)
      end do
   contains
      !> name, largest value and its time, limit; '-' where the dynamics
      !! does not give it
      function cell(defined, name, e, limit) result(text)
         logical, intent(in) :: defined
         character(len=*), intent(in) :: name
         type(extreme_t), intent(in) :: e
         real(wp), intent(in) :: limit
         character(len=:), allocatable :: text
         character(len=12) :: who
         who = name
         if (defined) then
            text = who//fixed(e%value, 10, 1)//fixed(e%t, 11, 5)//fixed(limit, 11, 0)
         else
            text = who//'         -          -'//fixed(limit, 11, 0)
         end if
      end function cell
   end subroutine put_force_maxima
end module run_report
