!> The run's channels as an ISO-MME data set (ISO/TS 13499; `--mme DIR`;
!! docs/pulse.md, "The run as an ISO-MME data set"), so that the tools
!! crash engineers use read a simulated run beside a test: DIR/<name>.mme,
!! DIR/CHANNEL/<name>.chn and a channel file a channel, <name> the folder's
!! own name. The channels are those the FMVSS 208 table samples (fmvss_table,
!! channel_record: 10 kHz, the head's 20 kHz, from the run's accepted
!! steps), unfiltered (the
!! code's filter class 0, "Channel frequency class :NOVALUE"), each with
!! the SAE J211-1 class to filter it at in its comment: the vehicle's x and
!! z accelerations (ISO's axes: z down), and of each occupant the head's
!! and chest's accelerations (x, z, resultant), the neck's axial force and
!! flexion/extension moment, the femurs' axial force, the chest's
!! deflection and each belt section's tension, in SAE J211's signs. They
!! are written when the run ends; no file is ever overwritten (each is
!! created new; one that exists is an input/output error before the run
!! starts) and every write is checked.
module mme_sink
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_io
   use strings, only: itoa, escaped
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use run_summary, only: run_summary_t
   use channel_record, only: channel_record_t
   use vehicle_motion, only: vehicle_motion_t
   use fmvss_table, only: fmvss_channels_t, vehicle_channel, cfc_head, cfc_chest, cfc_neck, cfc_femur, &
      cfc_deflection, cfc_belt, cfc_vehicle
   use posix_files, only: posix_make_dir, posix_error_text
   implicit none
   private

   public :: mme_sink_t, mme_sink_open, mme_check_dir

   !> The class SAE J211-1 (its Appendix E, as Euro NCAP's TB 021 and UN R94
   !! 5.2.2 read it) gives the upper neck's forces: CFC 1000 (the moment's
   !! is CFC 600). The FMVSS 208 table filters both at CFC 600, as FMVSS 208
   !! computes Nij (fmvss_table, docs/injury.md).
   real(wp), parameter :: cfc_neck_force_j211 = 1000.0_wp

   !> Where a channel's samples come from: a record of the occupant's
   !! channels (fmvss_channels_t) or the vehicle's motion.
   integer, parameter :: src_vehicle = 1, src_head = 2, src_chest = 3, src_neck = 4, src_femur = 5, &
      src_deflection = 6, src_belt = 7

   !> One channel: its code and header, where its samples come from.
   type :: channel_t
      character(len=16) :: code = ' '
      character(len=:), allocatable :: name
      character(len=8) :: unit = ' '
      character(len=2) :: dimension = ' '
      character(len=1) :: direction = ' '
      character(len=4) :: location = ' '
      character(len=8) :: reference = ' '   !< its reference system
      integer :: source = 0                 !< src_*
      integer :: occupant = 1
      integer :: component = 0              !< of the record (0: the resultant of its two)
      character(len=24) :: effect = ' '     !< a belt section's: its effect and label
      character(len=16) :: section = ' '
      real(wp) :: scale = 1.0_wp            !< the record's unit and sign to the channel's
      real(wp) :: cfc = 0.0_wp              !< the SAE J211-1 class to filter it at
   end type channel_t

   type, extends(output_sink_t) :: mme_sink_t
      character(len=:), allocatable :: dir, name, title
      type(channel_t), allocatable :: ch(:)
      type(vehicle_motion_t) :: vm          !< the vehicle's motion, for its channels
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

   !> The channels of the run (its occupants' and their effects'); none of
   !! their files may exist. The codes follow ISO/TS 13499's layout: test
   !! object 1, position p (the occupant's number in the run, not ISO's
   !! seat), main location, three fine locations (the third, the dummy's
   !! type, 00: not a Hybrid III), dimension, direction, filter class 0.
   subroutine sink_begin(this, sys, reg, first, err)
      class(mme_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      type(channel_t), allocatable :: ch(:)
      integer :: k, c, o, i
      character(len=1) :: p
      character(len=:), allocatable :: what, effect
      associate (u2 => first)
      end associate
      this%vm = sys%vm
      ! ISO/TS 13499 and SAE J211: x forward, z down; the program's y is up
      ! (allocated first: gfortran's -Wuninitialized takes the assignment to
      ! an unallocated array for a read of its descriptor)
      allocate (ch(0))
      ch = [ch, channel('10VEHCCG0000ACX0', 'vehicle acceleration x', 'g', 'AC', 'X', 'VEHC', 'local', src_vehicle, 1, &
                    1, 1.0_wp, cfc_vehicle), &
            channel('10VEHCCG0000ACZ0', 'vehicle acceleration z', 'g', 'AC', 'Z', 'VEHC', 'local', src_vehicle, 1, &
                    2, -1.0_wp, cfc_vehicle)]
      do o = 1, size(sys%occupants)
         p = char(iachar('0') + min(o, 9))
         what = ''
         if (o > 1) what = 'occupant '//itoa(o)//' '
         ! the head's and chest's accelerations at their centres of gravity, in
         ! the model's inertial frame (x forward, ISO's z down), and resultant
         ch = [ch, channel('1'//p//'HEAD000000ACX0', what//'head CG acceleration x', 'g', 'AC', 'X', 'HEAD', &
                           'global', src_head, o, 1, 1.0_wp, cfc_head), &
               channel('1'//p//'HEAD000000ACZ0', what//'head CG acceleration z', 'g', 'AC', 'Z', 'HEAD', &
                       'global', src_head, o, 2, -1.0_wp, cfc_head), &
               channel('1'//p//'HEAD000000ACR0', what//'head CG resultant acceleration', 'g', 'AC', 'R', 'HEAD', &
                       'global', src_head, o, 0, 1.0_wp, cfc_head), &
               channel('1'//p//'CHST000000ACX0', what//'chest CG acceleration x', 'g', 'AC', 'X', 'CHST', &
                       'global', src_chest, o, 1, 1.0_wp, cfc_chest), &
               channel('1'//p//'CHST000000ACZ0', what//'chest CG acceleration z', 'g', 'AC', 'Z', 'CHST', &
                       'global', src_chest, o, 2, -1.0_wp, cfc_chest), &
               channel('1'//p//'CHST000000ACR0', what//'chest CG resultant acceleration', 'g', 'AC', 'R', 'CHST', &
                       'global', src_chest, o, 0, 1.0_wp, cfc_chest)]
         ! the neck joint's loads (SAE J211: Fz + tension, My + flexion), one
         ! femur's axial force (compression -) written for both femurs (the
         ! thigh segment is both), the chest's deflection (compression -)
         ch = [ch, channel('1'//p//'NECKUP0000FOZ0', what//'neck axial force', 'N', 'FO', 'Z', 'NECK', 'local', &
                           src_neck, o, 1, 1.0_wp, cfc_neck_force_j211), &
               channel('1'//p//'NECKUP0000MOY0', what//'neck flexion/extension moment', 'Nm', 'MO', 'Y', 'NECK', &
                       'local', src_neck, o, 2, 1.0_wp, cfc_neck), &
               channel('1'//p//'FEMRLE0000FOZ0', what//'femur left axial force', 'N', 'FO', 'Z', 'FEMR', 'local', &
                       src_femur, o, 1, -1.0_wp, cfc_femur), &
               channel('1'//p//'FEMRRI0000FOZ0', what//'femur right axial force', 'N', 'FO', 'Z', 'FEMR', 'local', &
                       src_femur, o, 1, -1.0_wp, cfc_femur)]
         if (any([(sys%occupants(o)%effects(i)%e%deflects_chest, i=1, size(sys%occupants(o)%effects))])) &
            ch = [ch, channel('1'//p//'CHST000000DSX0', what//'chest deflection', 'mm', 'DS', 'X', 'CHST', 'local', &
                              src_deflection, o, 1, -1.0_wp, cfc_deflection)]
      end do
      ! each belt section's tension (SEBE, the seat belt; B6 the lap belt's
      ! outer side, B5 its inner, B3 and B4 the torso belt's upper and lower
      ! sections: the program's lap or lap_a, lap_b, torso2, torso3)
      do k = 1, size(reg%series)
         associate (s => reg%series(k))
            if (s%name /= 'effects/lap_belt/force' .and. s%name /= 'effects/torso_belt/force') cycle
            o = s%occupant
            p = char(iachar('0') + min(o, 9))
            what = ''
            if (o > 1) what = 'occupant '//itoa(o)//' '
            effect = s%name(len('effects/') + 1:len(s%name) - len('/force'))
            do c = 1, size(s%col)
               select case (trim(s%col(c)%name))
               case ('lap', 'lap_a')
                  ch = [ch, belt('B6', what//trim(s%col(c)%name)//' belt tension')]
               case ('lap_b')
                  ch = [ch, belt('B5', what//'lap_b belt tension')]
               case ('torso2')
                  ch = [ch, belt('B3', what//'torso belt upper section tension')]
               case ('torso3')
                  ch = [ch, belt('B4', what//'torso belt lower section tension')]
               end select
            end do
         end associate
      end do
      call move_alloc(ch, this%ch)
      ! nothing overwritten: a file there already stops the run before it starts
      do k = 0, size(this%ch) + 1
         if (err%failed()) return
         call refuse_existing(file_name(this, k), err)
      end do
   contains
      pure function channel(code, name, unit, dimension, direction, location, reference, source, occupant, &
                            component, scale, cfc) result(c)
         character(len=*), intent(in) :: code, name, unit, dimension, direction, location, reference
         integer, intent(in) :: source, occupant, component
         real(wp), intent(in) :: scale, cfc
         type(channel_t) :: c
         c%code = code
         c%name = name
         c%unit = unit
         c%dimension = dimension
         c%direction = direction
         c%location = location
         c%reference = reference
         c%source = source
         c%occupant = occupant
         c%component = component
         c%scale = scale
         c%cfc = cfc
      end function channel
      !> section c of series k: a belt's channel at fine location fine
      function belt(fine, name) result(b)
         character(len=2), intent(in) :: fine
         character(len=*), intent(in) :: name
         type(channel_t) :: b
         b = channel('1'//p//'SEBE0000'//fine//'FO00', name, 'N', 'FO', '0', 'SEBE', 'local', src_belt, o, 0, &
                     1.0_wp, cfc_belt)
         b%effect = effect
         b%section = reg%series(k)%col(c)%name
      end function belt
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

   !> (The channels come from the summary's records, at the end.)
   subroutine sink_record(this, frame, err)
      class(mme_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      associate (u1 => this, u2 => frame%t, u3 => err)
      end associate
   end subroutine sink_record

   subroutine sink_event(this, e, err)
      class(mme_sink_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      associate (u1 => this, u2 => e, u3 => err)
      end associate
   end subroutine sink_event

   !> The data set: each channel's samples on its record's uniform grid
   !! (10 kHz from the run's t = 0 to its end, a numerical failure's
   !! included), unfiltered.
   subroutine sink_finish(this, summary, err)
      class(mme_sink_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      integer :: c
      character(len=3) :: digits
      if (err%failed() .or. .not. allocated(this%ch)) return
      if (.not. allocated(summary%occ)) return
      call write_file(0, [character(len=200) :: line('Data format', 'ISO-MME'), line('Version', '1.6'), &
         line('Test number', this%name), line('Name of the test', this%title), &
         line('Test type', 'simulation (hsri2d, the HSRI phase two 2-D model)'), &
         line('Laboratory name', 'hsri2d'), line('Number of test objects', '1'), &
         line('Comments', 'Time zero: the run''s t = 0; channels at 10 or 20 kHz, unfiltered (class 0)')])
      if (err%failed()) return
      block
         character(len=200) :: index_lines(size(this%ch) + 2)
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
         character(len=200) :: text
         text = key
         text(29:) = ':'//value
      end function line

      !> Channel c from its occupant's records (or the vehicle's motion on
      !! the first occupant's 10 kHz grid).
      subroutine write_channel(c)
         integer, intent(in) :: c
         character(len=24) :: interval, count, first
         character(len=8) :: class
         real(wp), allocatable :: v(:)
         real(wp) :: t0, h
         associate (ch => this%ch(c))
            call channel_samples(summary%occ(min(ch%occupant, size(summary%occ)))%channels, ch, this%vm, t0, h, v)
            write (interval, '(es16.9)') h
            write (first, '(es16.9)') t0
            write (count, '(i0)') size(v)
            write (class, '(i0)') nint(ch%cfc)
            call write_file(c, [character(len=200) :: line('Channel code', ch%code), &
               line('Laboratory channel code', ch%code), line('Name of the channel', ch%name), &
               line('Location', ch%location), line('Direction', ch%direction), line('Data source', 'calculation'), &
               line('Channel frequency class', 'NOVALUE'), &
               line('Comments', 'unfiltered; filter at CFC '//trim(class)//' (SAE J211-1)'), &
               line('Reference system', ch%reference), &
               line('Sampling interval', trim(adjustl(interval))), line('Unit', trim(ch%unit)), &
               line('Time of first sample', trim(adjustl(first))), line('Number of samples', trim(count)), &
               line('Dimension', ch%dimension), line('Data status', 'ok')], v)
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

   !> Channel ch's samples v (its unit and sign) from the occupant's
   !! records rec (or the vehicle's motion vm on the chest's 10 kHz grid), and the
   !! grid they are on: t0 + k h.
   subroutine channel_samples(rec, ch, vm, t0, h, v)
      type(fmvss_channels_t), intent(in) :: rec
      type(channel_t), intent(in) :: ch
      type(vehicle_motion_t), intent(in) :: vm
      real(wp), intent(out) :: t0, h
      real(wp), allocatable, intent(out) :: v(:)
      real(wp), allocatable :: a(:, :)
      integer :: k
      t0 = 0.0_wp
      h = rec%head%h
      select case (ch%source)
      case (src_vehicle)
         call grid(rec%chest)
         a = vehicle_channel(vm, rec%chest)
         v = ch%scale*a(ch%component, :)
      case (src_head)
         call grid(rec%head)
         v = component(rec%head)
      case (src_chest)
         call grid(rec%chest)
         v = component(rec%chest)
      case (src_neck)
         call grid(rec%neck)
         v = component(rec%neck)
      case (src_femur)
         call grid(rec%femur)
         v = component(rec%femur)
      case (src_deflection)
         call grid(rec%deflection)
         v = component(rec%deflection)
      case (src_belt)
         allocate (v(0))
         if (.not. allocated(rec%belts)) return
         do k = 1, size(rec%belts)
            if (rec%belts(k)%effect_name == ch%effect .and. rec%belts(k)%section == ch%section) then
               call grid(rec%belts(k)%rec)
               v = component(rec%belts(k)%rec)
            end if
         end do
      end select
   contains
      subroutine grid(r)
         type(channel_record_t), intent(in) :: r
         t0 = r%t0
         h = r%h
      end subroutine grid
      !> the channel's component of record r (0: the resultant), scaled
      function component(r) result(x)
         type(channel_record_t), intent(in) :: r
         real(wp) :: x(r%n)
         if (r%n == 0) return
         if (ch%component == 0) then
            x = ch%scale*norm2(r%values(1:r%n_comp, 0:r%n - 1), dim=1)
         else
            x = ch%scale*r%values(ch%component, 0:r%n - 1)
         end if
      end function component
   end subroutine channel_samples
end module mme_sink
