!> The run's time histories as an ISO-MME data set (ISO/TS 13499; `--mme
!! DIR`; docs/pulse.md, "The run as an ISO-MME data set"), so that the tools
!! crash engineers use read a simulated run beside a test: DIR/<name>.mme,
!! DIR/CHANNEL/<name>.chn and a channel file a channel, <name> the folder's
!! own name. The channels: the vehicle's x and z accelerations (ISO's axes:
!! z down), and of each occupant the head's and chest's resultant
!! accelerations (g) and each belt section's tension (N), sampled at the
!! print times (the sampling interval DTPRINT, unfiltered: filter class
!! letter 0). Channels are kept as the run goes (a few values a print time)
!! and written when it ends; no file is ever overwritten (each is created
!! new; one that exists is an input/output error before the run starts)
!! and every write is checked.
module mme_sink
   use kinds, only: wp, g_std, pound_force_n
   use error_handling, only: error_t, error_set, exit_io
   use strings, only: itoa, escaped
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use run_summary, only: run_summary_t
   use posix_files, only: posix_make_dir, posix_error_text
   implicit none
   private

   public :: mme_sink_t, mme_sink_open, mme_check_dir, mme_lb_to_n

   !> One pound force in newtons (the international avoirdupois pound and g_n).
   real(wp), parameter :: mme_lb_to_n = pound_force_n
   !> Samples kept before the arrays grow.
   integer, parameter :: first_capacity = 256

   !> One channel: where its value is in a frame, how it is converted.
   type :: channel_t
      character(len=16) :: code = ' '
      character(len=:), allocatable :: name
      character(len=8) :: unit = ' '
      character(len=2) :: dimension = ' '
      character(len=1) :: direction = ' '
      character(len=4) :: location = ' '
      integer :: at = 0                 !< its index in a frame's values
      real(wp) :: scale = 1.0_wp        !< internal unit to the channel's
   end type channel_t

   type, extends(output_sink_t) :: mme_sink_t
      character(len=:), allocatable :: dir, name, title
      type(channel_t), allocatable :: ch(:)
      real(wp), allocatable :: t(:), v(:, :)   !< (sample, channel)
      integer :: n = 0
   contains
      procedure :: begin => sink_begin
      procedure :: record => sink_record
      procedure :: event => sink_event
      procedure :: finish => sink_finish
   end type mme_sink_t

contains

   !> What --check can say before a run (nothing created): the folder's
   !! name is usable, its .mme file and index are not there yet.
   subroutine mme_check_dir(dir, err)
      character(len=*), intent(in) :: dir
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: folder, name
      call folder_and_name(dir, folder, name, err)
      if (err%failed()) return
      call refuse_existing(folder//'/'//name//'.mme', err)
      if (.not. err%failed()) call refuse_existing(folder//'/CHANNEL/'//name//'.chn', err)
   end subroutine mme_check_dir

   !> The folder without trailing slashes, and its own name (the test's).
   subroutine folder_and_name(dir, folder, name, err)
      character(len=*), intent(in) :: dir
      character(len=:), allocatable, intent(out) :: folder, name
      type(error_t), intent(inout) :: err
      integer :: last
      last = len_trim(dir)
      do while (last > 1 .and. dir(last:last) == '/')
         last = last - 1
      end do
      folder = dir(1:last)
      name = folder(index(folder, '/', back=.true.) + 1:)
      if (len(name) == 0 .or. name == '.' .or. name == '..') call error_set(err, exit_io, 'ISO-MME data set ' &
         //escaped(dir)//': name its folder (--mme DIR): the folder''s name is the test''s, DIR/<name>.mme')
   end subroutine folder_and_name

   !> The data set's folder (created if it is not there) and the run's title.
   subroutine mme_sink_open(this, dir, title, err)
      type(mme_sink_t), intent(inout) :: this
      character(len=*), intent(in) :: dir, title
      type(error_t), intent(inout) :: err
      integer :: errno
      this%title = title
      call folder_and_name(dir, this%dir, this%name, err)
      if (err%failed()) return
      errno = posix_make_dir(this%dir)
      if (errno == 0) errno = posix_make_dir(this%dir//'/CHANNEL')
      if (errno /= 0) then
         call error_set(err, exit_io, 'ISO-MME data set '//escaped(this%dir)//': '//posix_error_text(errno))
         return
      end if
      ! a data set there already is refused before the run (its channel
      ! files, known when the run begins, are checked then)
      allocate (this%ch(0))
      call refuse_existing(file_name(this, 0), err)
      if (.not. err%failed()) call refuse_existing(this%dir//'/CHANNEL/'//this%name//'.chn', err)
      deallocate (this%ch)
   end subroutine mme_sink_open

   !> The channels of the run's series; none of their files may exist.
   subroutine sink_begin(this, sys, reg, first, err)
      class(mme_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      type(channel_t), allocatable :: ch(:)
      integer :: k, c, o
      character(len=1) :: pos
      character(len=:), allocatable :: what
      associate (u1 => sys, u2 => first)
      end associate
      allocate (ch(0))
      do k = 1, size(reg%series)
         associate (s => reg%series(k))
            o = s%occupant
            pos = char(iachar('0') + min(o, 9))
            what = ''
            if (o > 1) what = 'occupant '//itoa(o)//' '
            select case (s%name)
            case ('vehicle')
               if (o /= 1) cycle   ! (one vehicle)
               ! ISO/TS 13499 and SAE J211: x forward, z down; the program's y is up
               do c = 1, size(s%col)
                  if (s%col(c)%name == 'xddot_c') ch = [ch, channel('10VEHCCG0000ACX0', 'vehicle acceleration x', &
                     'g', 'AC', 'X', 'VEHC', s%offset + c, 1.0_wp/g_std)]
                  if (s%col(c)%name == 'yddot_c') ch = [ch, channel('10VEHCCG0000ACZ0', 'vehicle acceleration z', &
                     'g', 'AC', 'Z', 'VEHC', s%offset + c, -1.0_wp/g_std)]
               end do
            case ('acceleration')
               do c = 1, size(s%col)
                  if (s%col(c)%name == 'head') ch = [ch, channel('1'//pos//'HEAD000000ACR0', what// &
                     'head CG resultant acceleration', 'g', 'AC', 'R', 'HEAD', s%offset + c, 1.0_wp/g_std)]
                  if (s%col(c)%name == 'chest') ch = [ch, channel('1'//pos//'CHST000000ACR0', what// &
                     'chest CG resultant acceleration', 'g', 'AC', 'R', 'CHST', s%offset + c, 1.0_wp/g_std)]
               end do
            case ('effects/lap_belt/force', 'effects/torso_belt/force')
               do c = 1, size(s%col)
                  ! SEBE: the seat belt; B6 the lap belt, B3 and B4 the torso
                  ! belt's upper and lower sections (the program's sections 2, 3)
                  select case (trim(s%col(c)%name))
                  case ('lap')
                     ch = [ch, channel('1'//pos//'SEBE0000B6FO00', what//'lap belt tension', 'N', 'FO', '0', &
                        'SEBE', s%offset + c, mme_lb_to_n)]
                  case ('torso2')
                     ch = [ch, channel('1'//pos//'SEBE0000B3FO00', what//'torso belt upper section tension', 'N', &
                        'FO', '0', 'SEBE', s%offset + c, mme_lb_to_n)]
                  case ('torso3')
                     ch = [ch, channel('1'//pos//'SEBE0000B4FO00', what//'torso belt lower section tension', 'N', &
                        'FO', '0', 'SEBE', s%offset + c, mme_lb_to_n)]
                  end select
               end do
            end select
         end associate
      end do
      call move_alloc(ch, this%ch)
      allocate (this%t(first_capacity), this%v(first_capacity, size(this%ch)))
      this%n = 0
      ! nothing overwritten: a file there already stops the run before it starts
      do k = 0, size(this%ch) + 1
         if (err%failed()) return
         call refuse_existing(file_name(this, k), err)
      end do
   contains
      pure function channel(code, name, unit, dimension, direction, location, at, scale) result(c)
         character(len=*), intent(in) :: code, name, unit, dimension, direction, location
         integer, intent(in) :: at
         real(wp), intent(in) :: scale
         type(channel_t) :: c
         c = channel_t(code, name, unit, dimension, direction, location, at, scale)
      end function channel
   end subroutine sink_begin

   !> A file of the data set that exists already: an input/output error.
   subroutine refuse_existing(path, err)
      character(len=*), intent(in) :: path
      type(error_t), intent(inout) :: err
      logical :: exists
      inquire (file=path, exist=exists)
      if (exists) call error_set(err, exit_io, 'ISO-MME data set: '//escaped(path)//' exists; it is not ' &
         //'overwritten (name a new folder with --mme, or remove the data set)')
   end subroutine refuse_existing

   !> The path of file k of the data set: 0 the .mme file, size(ch) + 1 the
   !! channel index, else channel k.
   function file_name(this, k) result(path)
      class(mme_sink_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=:), allocatable :: path
      character(len=3) :: digits
      if (k == 0) then
         path = this%dir//'/'//this%name//'.mme'
      else if (k == size(this%ch) + 1) then
         path = this%dir//'/CHANNEL/'//this%name//'.chn'
      else
         write (digits, '(i3.3)') k
         path = this%dir//'/CHANNEL/'//this%name//'.'//digits
      end if
   end function file_name

   subroutine sink_record(this, frame, err)
      class(mme_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      real(wp), allocatable :: t(:), v(:, :)
      integer :: c
      if (err%failed() .or. .not. frame%valid .or. .not. allocated(this%t)) return
      if (this%n == size(this%t)) then
         allocate (t(2*this%n), v(2*this%n, size(this%ch)))
         t(1:this%n) = this%t
         v(1:this%n, :) = this%v
         call move_alloc(t, this%t)
         call move_alloc(v, this%v)
      end if
      this%n = this%n + 1
      this%t(this%n) = frame%t
      do c = 1, size(this%ch)
         this%v(this%n, c) = frame%v(this%ch(c)%at)*this%ch(c)%scale
      end do
   end subroutine sink_record

   subroutine sink_event(this, e, err)
      class(mme_sink_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      associate (u1 => this, u2 => e, u3 => err)
      end associate
   end subroutine sink_event

   !> The data set: the samples at the print times from t = 0 on the
   !! uniform grid of the first interval (a last record off it, the time a
   !! run ended between print times, is left out: ISO-MME samples are
   !! uniform).
   subroutine sink_finish(this, summary, err)
      class(mme_sink_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      real(wp) :: dt
      integer :: n, k, c
      character(len=3) :: digits
      associate (u1 => summary)
      end associate
      if (err%failed() .or. .not. allocated(this%t)) return
      n = this%n
      dt = 0.0_wp
      if (n >= 2) then
         dt = this%t(2) - this%t(1)
         do k = 3, n
            if (abs(this%t(k) - (this%t(1) + real(k - 1, wp)*dt)) > 1.0e-6_wp*dt) then
               n = k - 1
               exit
            end if
         end do
      end if
      call write_file(0, [character(len=80) :: line('Data format', 'ISO-MME'), line('Version', '1.6'), &
         line('Test number', this%name), line('Name of the test', this%title), &
         line('Test type', 'simulation (hsri2d, the HSRI phase two 2-D model)'), &
         line('Laboratory name', 'hsri2d'), line('Number of test objects', '1'), &
         line('Comments', 'Time zero: the run''s t = 0; channels at the print times, unfiltered')])
      if (err%failed()) return
      block
         character(len=80) :: index_lines(size(this%ch) + 2)
         index_lines(1) = line('Instrumentation standard', 'NOVALUE')
         index_lines(2) = line('Number of channels', itoa(size(this%ch)))
         do c = 1, size(this%ch)
            write (digits, '(i3.3)') c
            index_lines(c + 2) = line('Name of channel '//digits, this%ch(c)%code//' / '//this%ch(c)%name)
         end do
         call write_file(size(this%ch) + 1, index_lines)
      end block
      do c = 1, size(this%ch)
         if (err%failed()) return
         call write_channel(c)
      end do
   contains
      !> "name :value", the name padded to 28 columns (as ISO-MME writers do).
      function line(key, value) result(text)
         character(len=*), intent(in) :: key, value
         character(len=80) :: text
         text = key
         text(29:) = ':'//value
      end function line

      subroutine write_channel(c)
         integer, intent(in) :: c
         character(len=24) :: interval, count
         write (interval, '(es16.9)') dt
         write (count, '(i0)') n
         associate (ch => this%ch(c))
            call write_file(c, [character(len=80) :: line('Channel code', ch%code), &
               line('Laboratory channel code', ch%code), line('Name of the channel', ch%name), &
               line('Location', ch%location), line('Direction', ch%direction), line('Data source', 'calculation'), &
               line('Channel frequency class', 'NOVALUE'), line('Reference system', 'local'), &
               line('Sampling interval', trim(adjustl(interval))), line('Unit', trim(ch%unit)), &
               line('Time of first sample', '0.000000000E+00'), line('Number of samples', trim(count)), &
               line('Dimension', ch%dimension), line('Data status', 'ok')], this%v(1:n, c))
         end associate
      end subroutine write_channel

      !> File k, new: its header lines, then its samples (one a line).
      subroutine write_file(k, header, samples)
         integer, intent(in) :: k
         character(len=*), intent(in) :: header(:)
         real(wp), intent(in), optional :: samples(:)
         character(len=:), allocatable :: path
         character(len=256) :: msg
         integer :: unit, ios, i
         path = file_name(this, k)
         open (newunit=unit, file=path, status='new', action='write', form='formatted', iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call error_set(err, exit_io, 'ISO-MME data set: cannot create '//escaped(path)//': '//trim(msg))
            return
         end if
         do i = 1, size(header)
            if (ios == 0) write (unit, '(a)', iostat=ios, iomsg=msg) trim(header(i))
         end do
         if (present(samples)) then
            do i = 1, size(samples)
               if (ios == 0) write (unit, '(es17.9e3)', iostat=ios, iomsg=msg) samples(i)
            end do
         end if
         if (ios /= 0) then
            close (unit, iostat=i)
            call error_set(err, exit_io, 'ISO-MME data set: cannot write '//escaped(path)//': '//trim(msg))
            return
         end if
         close (unit, iostat=ios, iomsg=msg)
         if (ios /= 0) call error_set(err, exit_io, 'ISO-MME data set: cannot write '//escaped(path)//': ' &
            //trim(msg))
      end subroutine write_file
   end subroutine sink_finish
end module mme_sink
