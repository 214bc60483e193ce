!> The HDF5 time-history file as an output sink (C.6): every series of the
!! output registry at every print time, with its columns, units and
!! description, written as the run goes and flushed regularly, so a run
!! stopped midway leaves a readable file; at the end, the summary's maxima
!! and their times; at the start, the scene's fixed geometry (/scene,
!! scene_geometry).
module history_sink
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_io
   use model, only: n_joint, n_injury
   use strings, only: itoa
   use output_registry, only: output_registry_t, output_frame_t
   use output_sink, only: output_sink_t
   use equations_of_motion, only: crash_system_t
   use effect_events, only: event_t
   use event_text, only: event_description
   use force_injuries, only: fc_defined, fs_defined
   use run_summary, only: run_summary_t
   use channel_record, only: channel_record_t
   use acceleration_criteria, only: hic_result_t
   use history_h5, only: history_file_t, event_text_len
   use scene_geometry, only: scene_table_t, occupant_scene
   use vehicle_motion, only: vehicle_motion_t
   use fmvss_table, only: vehicle_channel, cfc_belt, cfc_vehicle, belt_channel_t
   implicit none
   private

   public :: history_sink_t, history_sink_open

   !> Records between flushes of the file.
   integer, parameter :: flush_every = 50

   type, extends(output_sink_t) :: history_sink_t
      type(history_file_t) :: file
      type(output_registry_t) :: reg
      integer :: id_time = 0
      integer, allocatable :: id(:)
      integer :: n_records = 0
      !> the vehicle's motion, for its acceleration on the channels' grid
      type(vehicle_motion_t) :: vm
   contains
      procedure :: begin => sink_begin
      procedure :: record => sink_record
      procedure :: event => sink_event
      procedure :: finish => sink_finish
      procedure :: close => sink_close
   end type history_sink_t

contains

   !> Create the file (its series are added when the run begins).
   subroutine history_sink_open(this, path, title, deck_lines, err)
      type(history_sink_t), intent(inout) :: this
      character(len=*), intent(in) :: path, title
      character(len=*), intent(in) :: deck_lines(:)
      type(error_t), intent(inout) :: err
      call this%file%open(path, title, deck_lines, err)
   end subroutine history_sink_open

   !> One dataset per series of the registry, and /time.
   subroutine sink_begin(this, sys, reg, first, err)
      class(history_sink_t), intent(inout) :: this
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      type(output_frame_t), intent(in) :: first
      type(error_t), intent(inout) :: err
      type(scene_table_t) :: scene(5)
      character(len=:), allocatable :: prefix
      integer :: k, c, o
      associate (u1 => first%t)
      end associate
      this%reg = reg
      this%vm = sys%vm
      allocate (this%id(size(reg%series)))
      this%id = 0
      if (err%failed()) return
      call this%file%add_series('time', [character(len=4) :: 't'], [character(len=4) :: 's'], &
                                'print times (C.6)', this%id_time, err, flush=.false.)
      do k = 1, size(reg%series)
         if (err%failed()) return
         associate (s => reg%series(k))
            call add_one(s%name, [(s%col(c)%name, c=1, size(s%col))], [(s%col(c)%unit, c=1, size(s%col))], &
                         s%description, this%id(k))
         end associate
      end do
      ! the scene's fixed geometry, for pictures of the motion (tools/plot)
      do o = 1, size(sys%occupants)
         prefix = ''
         if (size(sys%occupants) > 1) prefix = 'occupant_'//itoa(o)//'/'
         scene = occupant_scene(sys%occupants(o))
         do k = 1, size(scene)
            if (err%failed()) return
            call this%file%add_table(prefix//scene(k)%name, scene(k)%columns, scene(k)%units, &
                                     scene(k)%description, scene(k)%values, err, labels=scene(k)%labels)
         end do
      end do
      ! one flush for the whole structure, after its last series (one per series
      ! costs little more, some 1.5 M instructions for the default deck's file)
      if (.not. err%failed()) call this%file%flush(err)
   contains
      subroutine add_one(name, columns, units, description, id)
         character(len=*), intent(in) :: name, columns(:), units(:), description
         integer, intent(out) :: id
         call this%file%add_series(name, columns, units, description, id, err, flush=.false.)
      end subroutine add_one
   end subroutine sink_begin

   subroutine sink_record(this, frame, err)
      class(history_sink_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      type(error_t), intent(inout) :: err
      integer :: k
      if (err%failed()) return
      if (.not. allocated(this%id)) then
         call error_set(err, exit_io, 'the HDF5 file received a record before the run began')
         return
      end if
      call this%file%append(this%id_time, [frame%t], err)
      do k = 1, size(this%reg%series)
         if (err%failed()) return
         associate (s => this%reg%series(k))
            call this%file%append(this%id(k), frame%v(s%offset + 1:s%offset + size(s%col)), err)
         end associate
      end do
      this%n_records = this%n_records + 1
      if (mod(this%n_records, flush_every) == 0 .and. .not. err%failed()) call this%file%flush(err)
   end subroutine sink_record

   subroutine sink_event(this, e, err)
      class(history_sink_t), intent(inout) :: this
      type(event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      character(len=event_text_len) :: text
      if (err%failed()) return
      text = event_description(e)
      call this%file%add_event(e%t, e%kind, e%index, text, err)
      ! the event on disk at once; the series' pending rows wait for the next
      ! flush (every flush_every records), as they would without it
      if (.not. err%failed()) call this%file%flush(err, rows=.false.)
   end subroutine sink_event

   !> The summary's maxima and their times: /summary/maxima (values) and
   !! /summary/maxima_time, one row each, a column per maximum.
   subroutine sink_finish(this, summary, err)
      class(history_sink_t), intent(inout) :: this
      type(run_summary_t), intent(in) :: summary
      type(error_t), intent(inout) :: err
      character(len=24), allocatable :: names(:), units(:)
      real(wp), allocatable :: values(:), times(:)
      integer :: o, i, n, id_v, id_t
      character(len=8) :: prefix
      if (err%failed()) return
      n = size(summary%occ)*(2 + 2*n_joint + n_joint + 2*n_injury)
      do o = 1, size(summary%occ)
         if (allocated(summary%occ(o)%peaks)) n = n + size(summary%occ(o)%peaks)
      end do
      allocate (names(n), units(n), values(n), times(n))
      n = 0
      do o = 1, size(summary%occ)
         prefix = ''
         if (size(summary%occ) > 1) write (prefix, '(a,i0,a)') 'occ', o, '_'
         associate (os => summary%occ(o))
            call put(trim(prefix)//'head_acceleration', 'in/s^2', os%head_max%value, os%head_max%t)
            call put(trim(prefix)//'chest_acceleration', 'in/s^2', os%chest_max%value, os%chest_max%t)
            do i = 1, n_joint
               call put(trim(prefix)//'joint_'//char(48 + i)//'_min', 'rad', os%joint_min(i)%value, os%joint_min(i)%t)
               call put(trim(prefix)//'joint_'//char(48 + i)//'_max', 'rad', os%joint_max(i)%value, os%joint_max(i)%t)
            end do
            if (os%force_checked) then     ! Table 5 (force_injuries)
               do i = 1, n_joint
                  call put(trim(prefix)//'tension_'//char(48 + i), 'lb', os%ft_max(i)%value, os%ft_max(i)%t)
               end do
               do i = 1, n_injury
                  if (fc_defined(i)) call put(trim(prefix)//'compression_'//trim(itoa(i)), 'lb', os%fc_max(i)%value, &
                                              os%fc_max(i)%t)
                  if (fs_defined(i)) call put(trim(prefix)//'shear_'//trim(itoa(i)), 'lb', os%fs_max(i)%value, &
                                              os%fs_max(i)%t)
               end do
            end if
            ! the effects' peaks (the contact pairs' largest force, and where and how deep then)
            if (allocated(os%peaks)) then
               do i = 1, size(os%peaks)
                  call put(trim(prefix)//os%peaks(i)%name, os%peaks(i)%unit, os%peaks(i)%value, os%peaks(i)%t)
               end do
            end if
         end associate
      end do
      call this%file%add_series('summary/maxima', names(1:n), units(1:n), 'maxima (minima for joint_*_min) over ' &
                                //'all accepted steps, as the listing''s summary gives them', id_v, err)
      units = 's'
      if (.not. err%failed()) call this%file%add_series('summary/maxima_time', names(1:n), units(1:n), &
                                                       'when each maximum happened', id_t, err)
      if (.not. err%failed()) call this%file%append(id_v, values(1:n), err)
      if (.not. err%failed()) call this%file%append(id_t, times(1:n), err)
      if (.not. err%failed()) call put_criteria()
      if (.not. err%failed()) call put_fmvss()
      if (.not. err%failed()) call put_channels()
      ! written at close
   contains
      !> /summary/injury_criteria: one row, a column per criterion (docs/injury.md).
      subroutine put_criteria()
         character(len=24), allocatable :: cn(:), cu(:)
         real(wp), allocatable :: cv(:)
         type(hic_result_t) :: h15, h36
         integer :: id
         allocate (cn(0), cu(0), cv(0))
         do o = 1, size(summary%occ)
            prefix = ''
            if (size(summary%occ) > 1) write (prefix, '(a,i0,a)') 'occ', o, '_'
            associate (os => summary%occ(o))
               h15 = os%head_criteria%hic15()
               h36 = os%head_criteria%hic36()
               cn = [character(len=24) :: cn, trim(prefix)//'head_hic15', trim(prefix)//'head_hic15_t1', &
                     trim(prefix)//'head_hic15_t2', trim(prefix)//'head_hic36', trim(prefix)//'head_hic36_t1', &
                     trim(prefix)//'head_hic36_t2', trim(prefix)//'head_gsi', trim(prefix)//'chest_gsi', &
                     trim(prefix)//'chest_clip3ms']
               cu = [character(len=24) :: cu, '1', 's', 's', '1', 's', 's', '1', '1', 'g']
               cv = [cv, h15%value, h15%t1, h15%t2, h36%value, h36%t1, h36%t2, os%head_criteria%gsi, &
                     os%chest_criteria%gsi, os%chest_criteria%clip3ms()]
            end associate
         end do
         call this%file%add_series('summary/injury_criteria', cn, cu, 'HIC15 and HIC36 of the head with ' &
                                   //'their windows, the Gadd Severity Index of head and chest, the chest''s ' &
                                   //'cumulative 3 ms clip; from the accelerations in g at accepted steps', id, err)
         if (.not. err%failed()) call this%file%append(id, cv, err)
      end subroutine put_criteria

      !> /summary/criteria: the FMVSS 208 table (fmvss_table), a column per
      !! criterion and a row each for its value, limit, time, window's end,
      !! pass (1) or fail (0), and the unfiltered value; NaN where there is
      !! none (a quantity the model does not give, a criterion without a
      !! limit). Attributes: units (SI, as FMVSS 208 states its limits),
      !! filter_class (SAE J211-1), rows.
      subroutine put_fmvss()
         character(len=24), allocatable :: cn(:), cu(:), cf(:)
         real(wp), allocatable :: cv(:, :)
         real(wp) :: nan
         integer :: id, k, i
         nan = ieee_value(0.0_wp, ieee_quiet_nan)
         allocate (cn(0), cu(0), cf(0), cv(6, 0))
         do o = 1, size(summary%occ)
            prefix = ''
            if (size(summary%occ) > 1) write (prefix, '(a,i0,a)') 'occ', o, '_'
            if (.not. allocated(summary%occ(o)%fmvss)) cycle
            associate (rows => summary%occ(o)%fmvss)
               do i = 1, size(rows)
                  associate (r => rows(i))
                     cn = [character(len=24) :: cn, trim(prefix)//r%name]
                     cu = [character(len=24) :: cu, r%unit]
                     cf = [character(len=24) :: cf, r%channel]
                     cv = reshape([cv, merge(r%value, nan, r%available), merge(r%limit, nan, r%has_limit), &
                                   merge(r%t, nan, r%available), merge(r%t_end, nan, r%available), &
                                   merge(merge(1.0_wp, 0.0_wp, r%value <= r%limit), nan, &
                                         r%available .and. r%has_limit), &
                                   merge(r%unfiltered, nan, r%has_unfiltered)], [6, size(cn)])
                  end associate
               end do
            end associate
         end do
         if (size(cn) == 0) return
         call this%file%add_series('summary/criteria', cn, cu, 'FMVSS 208 (50th male): each criterion from its ' &
                                   //'channel filtered as SAE J211-1 specifies (attribute filter_class), sampled ' &
                                   //'at 10 kHz (the head 20 kHz), in SI as FMVSS 208 states its limits; rows: ' &
                                   //'value, limit, time, ' &
                                   //'end of the window (HIC), pass (1) or fail (0), unfiltered value; NaN: none', &
                                   id, err)
         if (.not. err%failed()) call this%file%add_attribute(id, 'filter_class', cf, err)
         if (.not. err%failed()) call this%file%add_attribute(id, 'rows', [character(len=24) :: 'value', 'limit', &
                                                              'time', 'time_end', 'pass', 'unfiltered'], err, per_column=.false.)
         do k = 1, 6
            if (.not. err%failed()) call this%file%append(id, cv(k, :), err)
         end do
      end subroutine put_fmvss

      !> /channels: each occupant's channels as the FMVSS 208 table read
      !! them (fmvss_table), unfiltered, on their 10 kHz grid (/channels/time;
      !! the head's on its 20 kHz grid, /channels/head_time), each with the
      !! SAE J211 class the table filters it at (attribute filter_class): for
      !! a reader's own filtering, plots, ISO-MME.
      subroutine put_channels()
         logical :: timed, head_timed
         timed = .false.
         head_timed = .false.
         do o = 1, size(summary%occ)
            prefix = ''
            if (size(summary%occ) > 1) write (prefix, '(a,i0,a)') 'occ', o, '_'
            associate (ch => summary%occ(o)%channels)
               if (.not. timed .and. ch%chest%n > 0) then
                  call channel('time', ch%chest, [character(len=8) :: 't'], [character(len=8) :: 's'], ' ', .true.)
                  timed = .true.
               end if
               if (.not. head_timed .and. ch%head%n > 0) then
                  call channel('head_time', ch%head, [character(len=8) :: 't'], [character(len=8) :: 's'], ' ', &
                               .true.)
                  head_timed = .true.
               end if
               call channel(trim(prefix)//'head_acceleration', ch%head, [character(len=8) :: 'x', 'y'], &
                            [character(len=8) :: 'g', 'g'], 'CFC 1000', .false.)
               call channel(trim(prefix)//'chest_acceleration', ch%chest, [character(len=8) :: 'x', 'y'], &
                            [character(len=8) :: 'g', 'g'], 'CFC 180', .false.)
               if (ch%neck_kept) call channel(trim(prefix)//'neck_loads', ch%neck, &
                                              [character(len=8) :: 'axial', 'moment'], &
                                              [character(len=8) :: 'N', 'N m'], 'CFC 600', .false.)
               if (ch%femur_kept) call channel(trim(prefix)//'femur_force', ch%femur, [character(len=8) :: 'axial'], &
                                               [character(len=8) :: 'N'], 'CFC 600', .false.)
               if (ch%deflection_kept) call channel(trim(prefix)//'chest_deflection', ch%deflection, &
                                                    [character(len=10) :: 'deflection'], [character(len=8) :: 'mm'], &
                                                    'CFC 180', .false.)
               if (ch%belts_kept) call belt_channels(trim(prefix)//'belt_forces', ch%belts)
               ! the vehicle's acceleration, once, on the first occupant's 10 kHz grid
               if (o == 1 .and. ch%chest%n > 0) &
                  call matrix_channel('vehicle_acceleration', [character(len=8) :: 'x', 'y'], &
                                      [character(len=8) :: 'g', 'g'], cfc_vehicle, vehicle_channel(this%vm, ch%chest), &
                                      'the vehicle''s accelerations x (forward) and y (up) at /channels/time, exact ' &
                                      //'(its tables are linear in time)')
            end associate
         end do
      end subroutine put_channels

      !> The belt sections' tensions (N), one column each (its label), at
      !! /channels/time.
      subroutine belt_channels(name, belts)
         character(len=*), intent(in) :: name
         type(belt_channel_t), intent(in) :: belts(:)
         real(wp), allocatable :: v(:, :)
         integer :: k, n
         if (size(belts) == 0) return
         n = minval(belts%rec%n)
         if (n == 0) return
         allocate (v(size(belts), n))
         do k = 1, size(belts)
            v(k, :) = belts(k)%rec%values(1, 0:n - 1)
         end do
         call matrix_channel(name, [(belts(k)%section, k=1, size(belts))], [character(len=8) :: ('N', k=1, &
                             size(belts))], cfc_belt, v, 'each belt section''s tension (N), unfiltered samples on ' &
                             //'/channels/time (filter them at filter_class)')
      end subroutine belt_channels

      !> A channel of columns cols given as a matrix v (column, sample).
      subroutine matrix_channel(name, cols, col_units, cfc, v, description)
         character(len=*), intent(in) :: name, cols(:), col_units(:), description
         real(wp), intent(in) :: cfc, v(:, :)
         integer :: id, k
         character(len=16) :: class
         if (err%failed() .or. size(v, 2) == 0) return
         write (class, '(a,i0)') 'CFC ', nint(cfc)
         call this%file%add_series('channels/'//name, cols, col_units, description, id, err, flush=.false.)
         if (.not. err%failed()) call this%file%add_attribute(id, 'filter_class', [class], err, per_column=.false.)
         do k = 1, size(v, 2)
            if (err%failed()) return
            call this%file%append(id, v(:, k), err)
         end do
      end subroutine matrix_channel

      !> One channel of put_channels (times: a grid, /channels/name).
      subroutine channel(name, rec, cols, col_units, cfc, times)
            character(len=*), intent(in) :: name, cols(:), col_units(:), cfc
            type(channel_record_t), intent(in) :: rec
            logical, intent(in) :: times
            integer :: id, k
            if (err%failed() .or. rec%n == 0) return
            if (times) then
               call this%file%add_series('channels/'//name, cols, col_units, 'a grid of the channels: t0 + k h, ' &
                                         //merge('20 kHz, the head''s', '10 kHz, the others', name == 'head_time') &
                                         //' (channel_record)', id, err, flush=.false.)
            else
               call this%file%add_series('channels/'//name, cols, col_units, 'unfiltered samples on ' &
                                         //trim(merge('/channels/head_time', '/channels/time     ', &
                                                    index(name, 'head_acceleration') > 0)) &
                                         //' (the FMVSS 208 table filters them at filter_class)', &
                                         id, err, flush=.false.)
               if (.not. err%failed()) call this%file%add_attribute(id, 'filter_class', [cfc], err, &
                                                                    per_column=.false.)
            end if
            do k = 0, rec%n - 1
               if (err%failed()) return
               if (times) then
                  call this%file%append(id, [rec%t0 + real(k, wp)*rec%h], err)
               else
                  call this%file%append(id, rec%values(:, k), err)
               end if
            end do
      end subroutine channel

      subroutine put(name, unit, value, t)
         character(len=*), intent(in) :: name, unit
         real(wp), intent(in) :: value, t
         n = n + 1
         names(n) = name
         units(n) = unit
         values(n) = value
         times(n) = t
      end subroutine put
   end subroutine sink_finish

   subroutine sink_close(this, err)
      class(history_sink_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      call this%file%close(err)
   end subroutine sink_close
end module history_sink
