!> The vehicle's acceleration table from an ISO-MME data set (ISO/TS 13499;
!! *PULSEMME; C.1, C.3), the form in which test laboratories and NHTSA
!! publish crash tests: the data set's .mme file, its channel index
!! CHANNEL/<name>.chn ("Name of channel 001 :code / words") and the channel
!! files CHANNEL/<name>.001, ... (header lines "name :value", then one
!! sample a line). One acceleration channel, chosen by its code, becomes the
!! XDDOT (direction X) or YDDOT (direction Z) column of the table
!! (docs/pulse.md): its unit converted, its sign turned into the
!! program's, its dropouts (NOVALUE) bridged, optionally filtered (SAE J211,
!! cfc_filter), its time origin moved to the run's t = 0. A file that cannot
!! be read is an input/output error (exit status 4); a data set whose
!! content is wrong, or a channel the data set does not hold, is a deck
!! error (2), each with the file and line.
module pulse_mme
   use kinds, only: wp, g_std, inch_m
   use error_handling, only: error_t, error_append, exit_deck, exit_io
   use strings, only: itoa, num, read_real, read_int, escaped, upper
   use text_io, only: string_t, read_text_file, append_string
   use deck_cards, only: group_spec_t
   use model, only: pulse_table_t
   use channel_filter, only: cfc_filter
   implicit none
   private

   public :: read_pulse_mme, mme_channel_classes, mme_max_gap

   !> The channel classes *PULSEMME's CFC accepts (SAE J211-1, ISO 6487).
   integer, parameter :: mme_channel_classes(4) = [60, 180, 600, 1000]
   !> The longest stretch of NOVALUE samples bridged (s): a linear bridge
   !! over more would invent the pulse rather than mend a dropout.
   real(wp), parameter :: mme_max_gap = 1.0e-3_wp
   !> The filter needs at least this many samples per period of its class
   !! (the design frequency 2.0775 CFC far below the Nyquist frequency).
   real(wp), parameter :: min_samples_per_class_period = 10.0_wp
   !> The sampling intervals read (s): from 10 MHz, beyond any crash test's
   !! acquisition (a finer one would make the filter's start-up extension,
   !! J211-1's 10 ms, tens of millions of samples), to 1 s
   real(wp), parameter :: mme_interval_range(2) = [1.0e-7_wp, 1.0_wp]
   !> The latest time of the table (s), as *PULSE's T
   real(wp), parameter :: mme_max_time = 1.0e3_wp
   !> What a data set's missing value is written as (ISO/TS 13499).
   character(len=*), parameter :: novalue = 'NOVALUE'

contains

   !> Read channel `code` of the data set whose .mme file is mme_path into
   !! table (times from the run's t = 0, internal units); cfc: the filter's
   !! class (0 none); t_zero: the data set's time that is the run's t = 0.
   !! named_at(1:2): "deck:line" of *PULSEMME's cards 1 and 2. source: the
   !! listing's line; inputs: the files read (outputs may not overwrite them).
   subroutine read_pulse_mme(mme_path, code, cfc, t_zero, named_at, spec, table, source, inputs, err)
      character(len=*), intent(in) :: mme_path, code
      integer, intent(in) :: cfc
      real(wp), intent(in) :: t_zero
      type(string_t), intent(in) :: named_at(2)
      type(group_spec_t), intent(in) :: spec
      type(pulse_table_t), intent(out) :: table
      character(len=:), allocatable, intent(out) :: source
      type(string_t), allocatable, intent(out) :: inputs(:)
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: lines(:)
      character(len=:), allocatable :: dir, base, chn_path, channel_path, number, unit_text
      real(wp), allocatable :: samples(:)
      logical, allocatable :: missing(:)
      real(wp) :: dt, t_first, to_internal, sign
      integer :: column, n_before

      allocate (inputs(0))
      source = escaped(mme_path)//' channel '//code
      call split_path(mme_path, dir, base)

      ! the .mme file: header lines only (its content is not needed, but a
      ! file that is not one is named here rather than its missing index)
      if (.not. read_file(mme_path, 'ISO-MME file', named_at(1)%s//': *PULSEMME card 1', lines)) return
      call check_header_only(mme_path, lines)
      if (err%failed()) return

      ! the channel index
      chn_path = find_index(dir, base)
      if (len(chn_path) == 0) then
         call error_append(err, exit_io, named_at(1)%s//': *PULSEMME card 1: no channel index '//escaped(dir) &
            //'CHANNEL/'//escaped(base)//'.chn beside the .mme file (nor in Channel/ or channel/, nor .CHN)')
         return
      end if
      if (.not. read_file(chn_path, 'ISO-MME channel index', named_at(1)%s//': *PULSEMME card 1', lines)) return
      call find_channel(chn_path, lines, number)
      if (err%failed()) return

      ! the channel
      channel_path = chn_path(1:len(chn_path) - 3)//number
      if (.not. read_file(channel_path, 'ISO-MME channel '//number, named_at(2)%s//': *PULSEMME card 2', lines)) return
      call read_channel(channel_path, lines, dt, t_first, unit_text, to_internal, column, sign, samples, missing)
      if (err%failed()) return
      call bridge_dropouts(channel_path, lines, samples, missing, dt, n_before)
      if (err%failed()) return
      if (cfc > 0) then
         if (dt > 1.0_wp/(min_samples_per_class_period*real(cfc, wp))) then
            call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, CFC: '//escaped(channel_path) &
               //' is sampled every '//num(dt)//' s; CFC '//itoa(cfc)//' needs at least ' &
               //num(min_samples_per_class_period*real(cfc, wp))//' samples a second')
            return
         end if
         block
            real(wp), allocatable :: filtered(:)
            integer :: stat
            ! (on the heap, with the samples' own size: a long channel
            ! would not fit on the stack)
            allocate (filtered(size(samples)), stat=stat)
            if (stat /= 0) then
               call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2: '//escaped(channel_path) &
                  //': no memory to filter its '//itoa(size(samples))//' samples')
               return
            end if
            call cfc_filter(samples, real(cfc, wp), dt, filtered)
            samples = filtered
         end block
      end if
      call make_table()
      if (err%failed()) return
      source = source//' ('//unit_text//', every '//num(dt)//' s'
      if (cfc > 0) then
         source = source//', CFC '//itoa(cfc)
      else
         source = source//', unfiltered'
      end if
      source = source//', t = 0 at its '//num(t_zero)//' s)'
   contains
      !> Read a file whole; an input/output error (exit 4) if it cannot be.
      logical function read_file(path, what, where, text)
         character(len=*), intent(in) :: path, what, where
         type(string_t), allocatable, intent(out) :: text(:)
         type(error_t) :: io_err
         call read_text_file(path, text, io_err)
         read_file = .not. io_err%failed()
         if (read_file) then
            call append_string(inputs, path)
         else
            call error_append(err, exit_io, where//': '//what//': '//io_err%message)
         end if
      end function read_file

      !> Every non-blank line of the .mme file is "name :value".
      subroutine check_header_only(path, text)
         character(len=*), intent(in) :: path
         type(string_t), intent(in) :: text(:)
         integer :: i
         do i = 1, size(text)
            if (len_trim(text(i)%s) == 0) cycle
            if (index(text(i)%s, ':') == 0) call problem(path, i, 'expected a header line "name :value"; found "' &
               //shown(text(i)%s)//'"')
         end do
      end subroutine check_header_only

      !> The channel coded `code` (case ignored) in the index: its number as
      !! the channel file's extension (3 digits). The index's "Number of
      !! channels" must count its "Name of channel" lines.
      subroutine find_channel(path, text, found)
         character(len=*), intent(in) :: path
         type(string_t), intent(in) :: text(:)
         character(len=:), allocatable, intent(out) :: found
         character(len=:), allocatable :: key, value, this_code, codes, tail
         character(len=3) :: digits
         integer :: i, n_names, n_declared, declared_at, found_at, k, slash
         logical :: good
         found = ''
         codes = ''
         n_names = 0
         n_declared = -1
         declared_at = 0
         found_at = 0
         do i = 1, size(text)
            if (len_trim(text(i)%s) == 0) cycle
            if (.not. split_header(text(i)%s, key, value)) then
               call problem(path, i, 'expected a header line "name :value"; found "'//shown(text(i)%s)//'"')
               cycle
            end if
            if (upper(key) == 'NUMBER OF CHANNELS') then
               call read_int(value, n_declared, good)
               if (.not. good .or. n_declared < 0) then
                  call problem(path, i, 'Number of channels: found "'//shown(value)//'"; expected a whole number')
                  n_declared = -1
               end if
               declared_at = i
            else if (index(upper(key), 'NAME OF CHANNEL') == 1) then
               n_names = n_names + 1
               tail = trim(adjustl(key(len('NAME OF CHANNEL') + 1:)))
               call read_int(tail, k, good)
               if (.not. good .or. k < 1 .or. k > 999) then
                  call problem(path, i, '"'//shown(key)//'": expected a channel number from 1 to 999 after ' &
                     //'"Name of channel"')
                  cycle
               end if
               ! "code / description"
               slash = index(value, '/')
               if (slash > 0) then
                  this_code = trim(value(1:slash - 1))
               else
                  this_code = trim(value)
               end if
               if (n_names > 1 .and. n_names <= 12) codes = codes//','
               if (n_names <= 12) codes = codes//' '//shown(this_code)
               if (n_names == 13) codes = codes//', ...'
               if (upper(this_code) /= upper(code)) cycle
               if (found_at > 0) then
                  call problem(path, i, 'channel '//tail//' has the code '//shown(this_code)//' of channel ' &
                     //found//' (line '//itoa(found_at)//'): the code names no single channel')
                  cycle
               end if
               found_at = i
               write (digits, '(i3.3)') k   ! (the channel file's extension: 3 digits)
               found = digits
            end if
         end do
         if (err%failed()) return
         if (n_declared >= 0 .and. n_declared /= n_names) then
            call problem(path, declared_at, 'Number of channels is '//itoa(n_declared)//' but the index names ' &
               //itoa(n_names)//' ("Name of channel NNN :code" lines)')
         else if (n_declared < 0) then
            call problem(path, max(1, size(text)), 'no "Number of channels" line')
         end if
         if (err%failed()) return
         if (found_at == 0) then
            if (n_names == 0) codes = ' none'
            call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, CHANNEL: no channel coded "' &
               //shown(code)//'" in '//escaped(path)//' (its '//itoa(n_names)//' channels:'//codes//')')
         end if
      end subroutine find_channel

      !> The channel file: its header (the sampling, unit, dimension,
      !! direction, number of samples) and samples (NOVALUE: missing).
      subroutine read_channel(path, text, interval, first_time, unit_name, scale, col, sgn, x, gap)
         character(len=*), intent(in) :: path
         type(string_t), intent(in) :: text(:)
         real(wp), intent(out) :: interval, first_time, scale, sgn
         character(len=:), allocatable, intent(out) :: unit_name
         integer, intent(out) :: col
         real(wp), allocatable, intent(out) :: x(:)
         logical, allocatable, intent(out) :: gap(:)
         character(len=:), allocatable :: key, value, file_code, dimension, direction, line
         integer :: i, n, n_declared, declared_at, first_sample_line, unit_at
         logical :: good, in_data, have_interval, have_first
         real(wp) :: y

         interval = 0.0_wp
         first_time = 0.0_wp
         scale = 1.0_wp
         sgn = 1.0_wp
         col = 1
         unit_name = ''
         file_code = ''
         dimension = ''
         direction = ''
         n_declared = -1
         declared_at = 0
         unit_at = 0
         first_sample_line = 0
         have_interval = .false.
         have_first = .false.
         in_data = .false.
         allocate (x(size(text)), gap(size(text)))
         n = 0
         do i = 1, size(text)
            line = trim(adjustl(text(i)%s))
            if (len(line) == 0) cycle
            if (.not. in_data) then
               if (split_header(line, key, value)) then
                  select case (upper(key))
                  case ('SAMPLING INTERVAL')
                     call read_real(value, interval, good)
                     if (.not. good .or. .not. (interval >= mme_interval_range(1) .and. &
                                                interval <= mme_interval_range(2))) then
                        call problem(path, i, 'Sampling interval: found "'//shown(value)//'"; expected a time ' &
                           //'from '//num(mme_interval_range(1))//' to '//num(mme_interval_range(2))//' s')
                     else
                        have_interval = .true.
                     end if
                  case ('TIME OF FIRST SAMPLE')
                     call read_real(value, first_time, good)
                     if (.not. good .or. .not. abs(first_time) <= mme_max_time) then
                        call problem(path, i, 'Time of first sample: found "'//shown(value)//'"; expected a ' &
                           //'time from '//num(-mme_max_time)//' to '//num(mme_max_time)//' s')
                     else
                        have_first = .true.
                     end if
                  case ('NUMBER OF SAMPLES')
                     call read_int(value, n_declared, good)
                     if (.not. good .or. n_declared < 2) then
                        call problem(path, i, 'Number of samples: found "'//shown(value)//'"; expected a ' &
                           //'whole number, at least 2')
                        n_declared = -1
                     end if
                     declared_at = i
                  case ('UNIT')
                     unit_name = value
                     unit_at = i
                  case ('DIMENSION')
                     dimension = upper(value)
                     if (dimension /= 'AC' .and. dimension /= novalue) call problem(path, i, 'Dimension: ' &
                        //shown(value)//'; the pulse is an acceleration channel (AC)')
                  case ('DIRECTION')
                     direction = upper(value)
                  case ('CHANNEL CODE')
                     file_code = value
                  end select
                  cycle
               end if
               call read_real(line, y, good)
               if (.not. good .and. upper(line) /= novalue) then
                  call problem(path, i, 'expected a header line "name :value" or a sample (a number or ' &
                     //novalue//'); found "'//shown(line)//'"')
                  return
               end if
               in_data = .true.
               first_sample_line = i
            end if
            n = n + 1
            if (upper(line) == novalue) then
               x(n) = 0.0_wp
               gap(n) = .true.
               cycle
            end if
            call read_real(line, y, good)
            if (.not. good) then
               call problem(path, i, 'sample '//itoa(n)//': found "'//shown(line)//'"; expected a number or ' &
                  //novalue)
               x(n) = 0.0_wp
               gap(n) = .false.
               cycle
            end if
            x(n) = y
            gap(n) = .false.
         end do
         x = x(1:n)
         gap = gap(1:n)
         if (.not. have_interval .and. .not. err%failed()) call problem(path, 1, 'no "Sampling interval" line')
         if (.not. have_first .and. .not. err%failed()) call problem(path, 1, 'no "Time of first sample" line')
         if (n_declared < 0 .and. .not. err%failed()) call problem(path, 1, 'no "Number of samples" line')
         if (err%failed()) return
         if (n /= n_declared) then
            call problem(path, declared_at, 'Number of samples is '//itoa(n_declared)//' but the file holds '// &
               itoa(n)//' samples (lines '//itoa(first_sample_line)//'-'//itoa(size(text))//')')
            return
         end if
         ! the channel code's own letters (ISO/TS 13499: 13-14 dimension,
         ! 15 direction) where the header does not say
         if (len(file_code) >= 15 .and. len(direction) /= 1) direction = upper(file_code(15:15))
         if (len(code) >= 15 .and. len(direction) /= 1) direction = upper(code(15:15))
         if ((len(dimension) == 0 .or. dimension == novalue) .and. len(code) >= 14) then
            if (upper(code(13:14)) /= 'AC') call problem(path, 1, 'channel '//shown(code)//' is not an ' &
               //'acceleration (its dimension letters are '//code(13:14)//', not AC)')
         end if
         ! sign conventions: ISO/TS 13499 and SAE J211 measure x forward,
         ! y right, z down; the program's vehicle axes are x forward, y up
         ! (docs/interiors.md), so X is XDDOT as it is and Z is -YDDOT
         select case (direction)
         case ('X')
            col = 1
            sgn = 1.0_wp
         case ('Z')
            col = 2
            sgn = -1.0_wp
         case default
            call problem(path, 1, 'the direction of channel '//shown(code)//' is "'//shown(direction)//'"; the ' &
               //'pulse is a vehicle acceleration along X (XDDOT) or Z (YDDOT), the motion in the plane of ' &
               //'the model')
            return
         end select
         ! units to in/s^2
         select case (unit_key(unit_name))
         case ('G')
            scale = g_std
         case ('M/S2')
            scale = 1.0_wp/inch_m
         case ('FT/S2')
            scale = 12.0_wp
         case ('IN/S2')
            scale = 1.0_wp
         case default
            if (unit_at == 0) then
               call problem(path, 1, 'no "Unit" line; expected g, m/s**2, ft/s**2 or in/s**2')
            else
               call problem(path, unit_at, 'Unit: found "'//shown(unit_name)//'"; expected g, m/s**2, ' &
                  //'ft/s**2 or in/s**2')
            end if
         end select
         if (err%failed()) return
         ! the *PULSE card's range (deck units g) holds here too
         associate (f => spec%field(col + 1))
            do i = 1, n
               if (gap(i)) cycle
               y = sgn*x(i)*scale/f%scale
               if (y < f%low .or. y > f%high) then
                  call problem(path, first_sample_line + line_offset(text, first_sample_line, i), 'sample ' &
                     //itoa(i)//': '//num(x(i))//' '//unit_name//' is '//num(y)//' '//trim(f%unit) &
                     //'; expected '//trim(f%name)//' from '//num(f%low)//' to '//num(f%high)//' ' &
                     //trim(f%unit))
                  return
               end if
            end do
         end associate
         x = sgn*x*scale
      end subroutine read_channel

      !> Dropouts (NOVALUE) at either end of the record are cut off; those
      !! inside it are bridged linearly between the samples around them,
      !! if they last at most mme_max_gap. n_lead: the samples cut at the start.
      subroutine bridge_dropouts(path, text, x, gap, interval, n_lead)
         character(len=*), intent(in) :: path
         type(string_t), intent(in) :: text(:)
         real(wp), allocatable, intent(inout) :: x(:)
         logical, allocatable, intent(inout) :: gap(:)
         real(wp), intent(in) :: interval
         integer, intent(out) :: n_lead
         integer :: first, last, i, j, k, data_line
         first = findloc(gap, .false., 1)
         last = findloc(gap, .false., 1, back=.true.)
         n_lead = 0
         data_line = first_data_line(text)
         if (first == 0) then
            call problem(path, data_line, 'every sample is '//novalue)
            return
         end if
         n_lead = first - 1
         i = first
         do while (i < last)
            if (.not. gap(i + 1)) then
               i = i + 1
               cycle
            end if
            j = i + 1
            do while (gap(j))
               j = j + 1
            end do
            ! samples i + 1 .. j - 1 are missing
            ! (the time the missing samples stand for)
            if (real(j - i - 1, wp)*interval > mme_max_gap*(1.0_wp + 1.0e-9_wp)) then
               call problem(path, data_line + line_offset(text, data_line, i + 1), 'samples ' &
                  //itoa(i + 1)//' to '//itoa(j - 1)//' are '//novalue//': '//num(real(j - i - 1, wp)*interval) &
                  //' s of the pulse missing; at most '//num(mme_max_gap)//' s of dropouts are bridged')
               return
            end if
            do k = i + 1, j - 1
               x(k) = x(i) + (x(j) - x(i))*real(k - i, wp)/real(j - i, wp)
            end do
            i = j
         end do
         x = x(first:last)
         gap = gap(first:last)
      end subroutine bridge_dropouts

      !> The table from the run's t = 0: samples before it dropped, a row at
      !! t = 0 interpolated between the samples around it.
      subroutine make_table()
         real(wp), allocatable :: tau(:)
         integer :: n, k, first
         real(wp) :: tol, w
         n = size(samples)
         allocate (tau(n))
         do k = 1, n
            tau(k) = t_first + real(n_before + k - 1, wp)*dt - t_zero
         end do
         tol = 1.0e-6_wp*dt   ! (a sample at T0 within rounding is at 0)
         where (abs(tau) < tol) tau = 0.0_wp
         if (tau(1) > 0.0_wp) then
            call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, T0: '//escaped(channel_path) &
               //'''s first sample with a value is at '//num(tau(1) + t_zero)//' s, after T0 = '//num(t_zero) &
               //' s, the run''s t = 0')
            return
         end if
         if (.not. tau(n) <= mme_max_time) then
            call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2: '//escaped(channel_path) &
               //'''s last sample is at '//num(tau(n))//' s of the run, beyond the '//num(mme_max_time) &
               //' s a pulse table may reach (*PULSE''s T)')
            return
         end if
         if (tau(n) < 0.0_wp) then
            call error_append(err, exit_deck, named_at(2)%s//': *PULSEMME card 2, T0: '//escaped(channel_path) &
               //'''s last sample is at '//num(tau(n) + t_zero)//' s, before T0 = '//num(t_zero)//' s, ' &
               //'the run''s t = 0')
            return
         end if
         first = findloc(tau >= 0.0_wp, .true., 1)
         allocate (table%t(n - first + 1 + merge(1, 0, tau(first) > 0.0_wp)), table%v(size(table%t), 3))
         table%v = 0.0_wp
         k = 0
         if (tau(first) > 0.0_wp) then
            ! linear between the samples around t = 0, as the table is between its rows
            w = -tau(first - 1)/(tau(first) - tau(first - 1))
            k = 1
            table%t(1) = 0.0_wp
            table%v(1, column) = samples(first - 1) + w*(samples(first) - samples(first - 1))
         end if
         table%t(k + 1:) = tau(first:n)
         table%v(k + 1:, column) = samples(first:n)
         table%given = .true.
      end subroutine make_table

      subroutine problem(path, line_no, message)
         character(len=*), intent(in) :: path, message
         integer, intent(in) :: line_no
         call error_append(err, exit_deck, escaped(path)//':'//itoa(line_no)//': '//message)
      end subroutine problem
   end subroutine read_pulse_mme

   !> "name :value" split at the first colon (names are padded with blanks).
   logical function split_header(line, key, value)
      character(len=*), intent(in) :: line
      character(len=:), allocatable, intent(out) :: key, value
      integer :: p
      p = index(line, ':')
      split_header = p > 0
      if (.not. split_header) then
         key = ''
         value = ''
         return
      end if
      key = trim(adjustl(line(1:p - 1)))
      value = trim(adjustl(line(p + 1:)))
   end function split_header

   !> A unit's spelling reduced to one of G, M/S2, FT/S2, IN/S2 (or itself):
   !! "m/s**2", "m/s^2", "m/s2", "m/s²" (UTF-8 or Latin-1) are one unit.
   function unit_key(unit_name) result(key)
      character(len=*), intent(in) :: unit_name
      character(len=:), allocatable :: key, u
      integer :: i
      u = upper(trim(adjustl(unit_name)))
      key = ''
      do i = 1, len(u)
         select case (u(i:i))
         case ('*', '^', ' ')
            cycle
         case default
            if (u(i:i) == char(178)) then        ! ² in Latin-1 and the tail of its UTF-8
               key = key//'2'
            else if (u(i:i) == char(194)) then   ! (the lead byte of UTF-8's ²)
               cycle
            else
               key = key//u(i:i)
            end if
         end select
      end do
   end function unit_key

   !> Where path's file name starts (dir, with its slash, or '') and that
   !! name without its last extension.
   subroutine split_path(path, dir, base)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: dir, base
      integer :: slash, dot
      slash = index(path, '/', back=.true.)
      dir = path(1:slash)
      base = path(slash + 1:)
      dot = index(base, '.', back=.true.)
      if (dot > 1) base = base(1:dot - 1)
   end subroutine split_path

   !> The channel index of the data set in dir called base: CHANNEL/base.chn
   !! (ISO/TS 13499), or the spellings of other writers; '' when none.
   function find_index(dir, base) result(path)
      character(len=*), intent(in) :: dir, base
      character(len=:), allocatable :: path
      character(len=*), parameter :: folders(3) = ['CHANNEL', 'Channel', 'channel']
      character(len=*), parameter :: extensions(2) = ['.chn', '.CHN']
      integer :: i, j
      logical :: exists
      do i = 1, size(folders)
         do j = 1, size(extensions)
            path = dir//folders(i)//'/'//base//extensions(j)
            inquire (file=path, exist=exists)
            if (exists) return
         end do
      end do
      path = ''
   end function find_index

   !> The line of text, from line first_line on, that holds sample k (blank lines skipped).
   integer function line_offset(text, first_line, k) result(offset)
      type(string_t), intent(in) :: text(:)
      integer, intent(in) :: first_line, k
      integer :: i, seen
      seen = 0
      offset = 0
      do i = first_line, size(text)
         if (len_trim(text(i)%s) == 0) cycle
         seen = seen + 1
         if (seen == k) then
            offset = i - first_line
            return
         end if
      end do
   end function line_offset

   !> The line of the first sample (the first non-blank line without a colon).
   integer function first_data_line(text) result(i)
      type(string_t), intent(in) :: text(:)
      do i = 1, size(text)
         if (len_trim(text(i)%s) == 0) cycle
         if (index(text(i)%s, ':') == 0) return
      end do
      i = size(text)
   end function first_data_line

   !> Text from a file for a message: one line, at most 40 characters.
   function shown(text) result(s)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: s
      s = escaped(text(1:min(len(text), 40)))
   end function shown
end module pulse_mme
