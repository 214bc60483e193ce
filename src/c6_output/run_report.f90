!> The listing of a run (C.6), written as the run goes: the deck echoed
!! with card numbers, the scene's parameter tables (each declared by its
!! subsystem as a text_table, the report's Tables 1-11 as the run uses
!! them) and the preliminary constants of C.2 when the run begins; the
!! time-history tables of the output registry chosen by NOUT, a page of
!! rows at a time for every table (so memory stays bounded whatever TMAX and
!! DTPRINT are); the printer plots *PRINTERPLOT asks for (printer_plot);
!! the summary at the end (maxima and when they occurred,
!! injuries, the end of the run, the energy balance, the cost).
module run_report
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use kinds, only: wp, deg, g_std, i8
   use strings, only: itoa, num
   use model, only: model_t, n_joint, n_injury, joint_name, integrator_name, nint_adams
   use deck_reader, only: deck_t, echo_bad, echo_header
   use deck_cards, only: group_spec_t, layout_indexed, layout_multi, kind_text
   use error_handling, only: error_t, error_set, exit_io
   use listing, only: listing_t
   use number_format, only: fixed, es11_3, f10_5, right_int
   use text_table, only: text_table_t
   use output_series, only: max_listing_columns
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use effect_factory, only: scene_parameter_tables
   use run_summary, only: run_summary_t, occupant_summary_t, extreme_t
   use force_injuries, only: fc_defined, fs_defined, fc_name, fs_name
   use acceleration_criteria, only: hic_result_t
   use fmvss_table, only: fmvss_row_t
   use event_text, only: event_description
   use end_tests, only: end_reason_text, end_failure, end_energy
   use accuracy_estimate, only: accuracy_warnings, corrector_warning, angle_threshold, head_threshold, &
      widened_ramp_warning
   use text_io, only: string_t, append_string
   use printer_plot, only: printer_plot_t
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
      type(printer_plot_t) :: plots              !< *PRINTERPLOT's pictures (issue 18)
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
      call this%plots%begin(this%m%printer_plot, this%m%time%t_max, sys, reg)
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
      call this%plots%record(frame)
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
      call this%plots%write(this%lst)
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
            if (e%varied) mark = 'V'             ! a field set by a study (C.8)
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
      if (any(deck%echo(1:deck%n_echo)%varied)) &
         call lst%put('    V = card with a field the study set for this run (C.8; docs/modification.md).')
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

   !> The parameter tables of the scene (effect_factory's list: the model's
   !! sections' and each subsystem's), each under its title.
   subroutine write_parameters(lst, m, deck)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(deck_t), intent(in) :: deck
      type(text_table_t), allocatable :: tables(:)
      integer :: k
      call lst%new_page('PARAMETERS (C.1, TABLES 1-6)')
      allocate (tables(0))   ! (gfortran 12 -Wuninitialized: the assignment reads the descriptor)
      tables = scene_parameter_tables(m, deck)
      do k = 1, size(tables)
         call lst%table(tables(k))
      end do
   end subroutine write_parameters

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
      if (res%end_reason == end_failure .or. res%end_reason == end_energy) call lst%put('  '//res%failure%message, indent=4)

      do o = 1, size(res%occ)
         associate (os => res%occ(o))
            call lst%heading('MAXIMA OVER ALL ACCEPTED STEPS', 4)
            head = '  head acceleration  '//fixed(os%head_max%value/g_std, 10, 3)//' g   at t ='// &
                   fixed(os%head_max%t, 10, 5)//' s'
            ! its estimated error, beside it (docs/accuracy.md)
            if (os%accuracy%on .and. os%accuracy%head_evaluations > 0) &
               head = head//'   estimated error'//fixed(os%accuracy%head_error/g_std, 10, 3)//' g (' &
                                       //fixed(100.0_wp*os%accuracy%head_relative(os%head_max%value), 6, 2)//' %)'
            call lst%put(head)
            call lst%put('  chest acceleration '//fixed(os%chest_max%value/g_std, 10, 3)//' g   at t ='// &
                         fixed(os%chest_max%t, 10, 5)//' s')
            call put_injury_criteria(lst, os)
            if (allocated(os%fmvss)) call put_fmvss(lst, os%fmvss)
            call put_peaks(lst, os)

            call lst%heading('JOINT ANGLE RANGES, ALPHA(I) - ALPHA(M) (deg)', 10)
            head = '   I  JOINT          MINIMUM   AT t (s)    MAXIMUM   AT t (s)    STOPS            DISLOCATION'
            if (os%accuracy%on) head = head//'    EST. ERROR'
            call lst%put(head)
            do i = 1, n_joint
               associate (r => m%joints%restraint(i))
                  write (line, '(i4,2x,a12,10a)') i, joint_name(i), fixed(os%joint_min(i)%value/deg, 10, 3), &
                     fixed(os%joint_min(i)%t, 11, 5), fixed(os%joint_max(i)%value/deg, 10, 3), &
                     fixed(os%joint_max(i)%t, 11, 5), '  ', fixed(r%lower/deg, 8, 2), fixed(r%upper/deg, 8, 2), ' ', &
                     fixed(r%dislocation_lower/deg, 8, 2), fixed(r%dislocation_upper/deg, 8, 2)
               end associate
               ! the angle's estimated error at the end of the run (docs/accuracy.md)
               if (os%accuracy%on) line = trim(line)//'    '//fixed(os%accuracy%joint_angle(i, res%t_end)/deg, 10, 3)
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
            write (line, '(a,es13.5,a)') '  scale                   ', os%energy_scale, &
               ' in*lb: largest body kinetic energy or work the vehicle supplied (D-17a)'
            call lst%put(line)
            if (abs(os%energy_error_max%value) <= 1.0e-12_wp*max(1.0_wp, os%energy_scale)) then
               call lst%put('  largest balance error    below 1.0E-12 of the scale (rounding)')
            else
               write (line, '(a,es13.5,a,a,a,es10.3,a)') '  largest balance error   ', os%energy_error_max%value, &
                  ' in*lb at t =', fixed(os%energy_error_max%t, 10, 5), ' s (', &
                  abs(os%energy_error_max%value)/max(os%energy_scale, tiny(1.0_wp)), ' of the scale)'
               call lst%put(line)
            end if
            write (line, '(a,es10.3,a)') '  tolerance (EBTOL)        ', m%numerics%energy_tol, ' of the scale'
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
         if (st%switch_evaluations > 0) then
            call count_line('  switches located           ', st%switches_located)
            call count_line('  steps taken again to them  ', st%retaken)
            if (st%gaps_crossed > 0) call count_line('  reached on their extension', st%gaps_crossed)
            if (st%switches_predicted > 0) call count_line('  predicted and stepped onto ', st%switches_predicted)
            call count_line('  switches not located (chatter)', st%switches_unlocated)
            call count_line('  switch-function evaluations', st%switch_evaluations)
         end if
         if (st%kinks > 0) call count_line('  steps onto the pulse''s kinks', st%kinks)
         if (m%options%nint == nint_adams) then
            call count_line('  corrector iterations       ', st%corrector_iterations)
            call count_line('  corrector solves           ', st%corrector_solves)
            call count_line('  solves at the iteration limit', st%corrector_at_limit)
            ev = corrector_warning(st, m%time%corrector_tol, m%time%corrector_max_iter)
            if (len(ev) > 0) call lst%put('  WARNING: '//ev, indent=11)
         end if
         if (st%steps > 0) then
            write (line, '(a,es12.4,a,es12.4,a)') '  step size from          ', st%h_min, ' to', st%h_max, ' s'
            call lst%put(line)
         end if
      end associate
      call put_accuracy(lst, m, res)
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

   !> How accurate the fixed step was (docs/accuracy.md): each occupant's
   !! estimates, their parts and thresholds, and the warnings past them.
   subroutine put_accuracy(lst, m, res)
      type(listing_t), intent(inout) :: lst
      type(model_t), intent(in) :: m
      type(run_summary_t), intent(in) :: res
      type(string_t), allocatable :: w(:)
      character(len=:), allocatable :: who
      integer :: o, j, k
      do o = 1, size(res%occ)
         associate (a => res%occ(o)%accuracy, os => res%occ(o))
            if (.not. a%on) cycle
            who = ''
            if (size(res%occ) > 1) who = ', OCCUPANT '//itoa(o)
            call lst%heading('ACCURACY OF THE FIXED STEP DT = '//num(m%time%dt)//' s'//who &
                             //': LOCAL ERROR ESTIMATES ACCUMULATED (docs/accuracy.md)', 8)
            j = a%worst_joint(res%t_end)
            call lst%put('  joint angles: largest estimated error'//fixed(a%joint_angle(j, res%t_end)/deg, 10, 3) &
                         //' deg ('//trim(joint_name(j))//'): steps'' truncation' &
                         //fixed(a%joint_truncation(j, res%t_end)/deg, 10, 3)//', switches at a step''s end' &
                         //fixed(a%joint_switching(j, res%t_end)/deg, 10, 3))
            if (a%head_evaluations > 0) then
               call lst%put('  head acceleration: estimated error of its peak'//fixed(a%head_error/g_std, 10, 3)//' g,' &
                            //fixed(100.0_wp*a%head_relative(os%head_max%value), 8, 3)//' % of it')
            else
               call lst%put('  head acceleration: its peak not estimated (below 1 g, or at t = 0)')
            end if
            call lst%put('  steps estimated'//right_int(a%steps, 12)//',  switches at a step''s end'//right_int(a%switches, 10) &
                         //',  evaluations for the head''s estimate'//right_int(a%head_evaluations, 8))
            call lst%put('  thresholds: '//fixed(angle_threshold/deg, 4, 1)//' deg on a joint angle, ' &
                         //fixed(100.0_wp*head_threshold, 4, 1)//' % of the peak head acceleration')
            w = accuracy_warnings(a, '', os%head_max%value, res%t_end, m%time%dt, &
                                  failed=res%end_reason == end_failure .or. res%end_reason == end_energy)
            if (size(w) == 0) call lst%put('  within the thresholds')
            ! what the estimate cannot see (docs/accuracy.md)
            if (allocated(res%events) .and. o == 1) then
               who = widened_ramp_warning(res%events, res%n_events)
               if (len(who) > 0) call append_string(w, who)
            end if
            do k = 1, size(w)
               call lst%put('  WARNING: '//w(k)%s, indent=11)
            end do
         end associate
      end do
   end subroutine put_accuracy

   !> HIC15, HIC36, GSI and the chest's 3 ms clip (docs/injury.md): not the
   !! report's criteria, which predate them, but what users now expect.
   subroutine put_injury_criteria(lst, os)
      type(listing_t), intent(inout) :: lst
      type(occupant_summary_t), intent(in) :: os
      type(hic_result_t) :: r
      call lst%heading('ACCELERATION CRITERIA OF HEAD AND CHEST, UNFILTERED (ACCEPTED STEPS)', 6)
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

   !> The table "FMVSS 208 (50th male)" (fmvss_table, docs/injury.md): each
   !! criterion from its channel filtered at its SAE J211 class, in SI as
   !! FMVSS 208 S6 states its limits, its limit, when, pass or fail, and the
   !! unfiltered value of the accepted steps beside it where there is one;
   !! "n/a" where the model does not give the quantity.
   subroutine put_fmvss(lst, rows)
      type(listing_t), intent(inout) :: lst
      type(fmvss_row_t), intent(in) :: rows(:)
      character(len=132) :: line
      integer :: i
      call lst%heading('FMVSS 208 (50TH MALE): FILTERED CHANNELS (SAE J211-1; HEAD 20 KHZ, OTHERS 10 KHZ), ' &
                       //'SI UNITS', size(rows) + 2)
      call lst%put('  CRITERION                    CHANNEL        VALUE  UNIT        LIMIT   AT t (s)   TO t (s)' &
                   //'  RESULT   UNFILTERED')
      do i = 1, size(rows)
         associate (r => rows(i))
            line = ' '
            line(3:30) = r%label
            line(32:39) = r%channel
            if (r%available) then
               line(40:51) = fixed(r%value, 12, 3)
            else
               line(40:51) = '         n/a'
            end if
            line(54:57) = r%unit
            if (r%has_limit) line(58:68) = fixed(r%limit, 11, 1)
            if (r%available .and. .not. ieee_is_nan(r%t)) line(69:79) = fixed(r%t, 11, 5)
            if (r%available .and. r%window) line(80:90) = fixed(r%t_end, 11, 5)
            if (r%has_limit) then
               if (.not. r%available) then
                  line(93:98) = '-'
               else if (r%value <= r%limit) then
                  line(93:98) = 'pass'
               else
                  line(93:98) = 'FAIL'
               end if
            end if
            if (r%has_unfiltered) line(99:110) = fixed(r%unfiltered, 12, 3)
            call lst%put(line)
         end associate
      end do
   end subroutine put_fmvss

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
