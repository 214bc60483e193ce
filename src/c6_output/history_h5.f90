!> The run's time histories in an HDF5 file, written as the run goes (C.6).
!!
!! Layout, format_version 3 (h5py shapes; Fortran shapes are the reverse):
!!
!! - root attributes `format_version` (integer, 3), `program` (= "hsri2d"),
!!   `version` (the program's version), `title`, `units`;
!! - `/input/deck`: the deck's card images, 1-D fixed-length strings;
!! - one dataset per series, e.g. `/time`, `/body/z`: float64 growing along
!!   rows, chunked; 1-D, (rows), for a series of one column such as
!!   `/time`, otherwise 2-D, (rows, ncols) (`add_series`'s `rank` can make
!!   a one-column series 2-D);
!! - tables of fixed rows (`add_table`, e.g. `/scene/surfaces`): float64,
!!   2-D (rows, ncols), with a `rows` attribute naming each row when given;
!! - `/events/time` (float64), `/events/kind` (int32), `/events/index`
!!   (int32), `/events/text` (120-character strings): 1-D, one entry per
!!   event, present (empty) even when no event happens.
!!
!! Every dataset, /input/deck and /events/* included, carries `columns` and
!! `units` (one string per column; "-" for a dimensionless or text column)
!! and `description`. Attribute strings are variable-length UTF-8 (h5py 3
!! reads them as `str`); string datasets are fixed-length, null-padded
!! UTF-8 (h5py: `.asstr()`; a deck's comment cards may hold UTF-8).
!!
!! Rows are kept in memory per series and written in blocks of
!! `block_rows` (also the chunk length), which amortizes HDF5's
!! extend/select/write cost; `flush` writes whatever is pending, then
!! H5Fflush(H5F_SCOPE_GLOBAL) hands everything to the operating system
!! (no fsync: this survives a killed process, not a system crash). `open`
!! and `add_series` flush too, so the file is readable from the start
!! (a caller adding many series at once may ask add_series not to, and
!! flush once after the last).
!!
!! A run killed between flushes leaves a readable file holding the series'
!! rows up to the last flush and every event added (the sink flushes
!! HDF5's part, add_event's writes, at each event; tests/h5/h5_killed_run.sh). This relies on the
!! HDF5 default file format (libver bounds earliest..latest, superblock
!! v0), whose superblock has no "open for writing" flag: with libver
!! latest (and so with SWMR, which needs it) a killed writer leaves a file
!! that HDF5 1.10 refuses to open until `h5clear -s` is run. HDF5 1.10 has
!! no journal, so a kill in the middle of a flush can leave the newest
!! chunks unreadable; `h5clear --increment FILE` usually repairs that.
!! When the caller flushes at least every `block_rows` rows, only
!! `add_event` touches the file between flushes.
!!
!! Write failures (a full disk, a file-size limit). Once a write or flush
!! has failed the file is abandoned: every later call returns that failure
!! without calling HDF5, and `close` releases nothing of the file. The
!! reason: HDF5 1.10 (fixed in 1.14) frees a dataset or file whose close
!! fails but leaves its identifier registered, so any later use of it, by
!! us or by HDF5's own clean-up at exit, reads freed memory (a segmentation
!! fault after "cannot close HDF5 file"). For the same reason HDF5's
!! clean-up at exit is switched off (H5dont_atexit, before the library
!! starts): every file this module opens is closed by `close`, so there is
!! nothing for it to do but trip over an abandoned file. An abandoned file
!! keeps its memory and descriptor until the process ends. Messages of
!! write failures end with the system's reason (errno) when there is one.
!!
!! No times are stored in object headers (object time tracking is off for
!! the root group, groups and datasets), so the same calls with the same
!! HDF5 library give a byte-identical file.
module history_h5
   use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_loc, c_null_char
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_io
   use posix_files, only: posix_clear_errno, posix_errno, posix_error_text
   use version_info, only: hsri2d_version
   use hdf5, only: hid_t, hsize_t, size_t, &
                   h5open_f, h5dont_atexit_f, h5eset_auto_f, h5iis_valid_f, &
                   h5fcreate_f, h5fclose_f, h5fflush_f, h5f_acc_trunc_f, h5f_scope_global_f, h5f_close_strong_f, &
                   h5pcreate_f, h5pclose_f, h5pset_obj_track_times_f, h5pset_fclose_degree_f, h5pset_chunk_f, &
                   h5p_file_create_f, h5p_file_access_f, h5p_group_create_f, h5p_dataset_create_f, &
                   h5p_dataset_access_f, h5pset_chunk_cache_f, h5p_dataset_xfer_f, h5pset_buffer_f, &
                   h5gcreate_f, h5gclose_f, h5lexists_f, &
                   h5screate_f, h5screate_simple_f, h5sclose_f, h5sselect_hyperslab_f, &
                   h5s_scalar_f, h5s_unlimited_f, h5s_select_set_f, &
                   h5dcreate_f, h5dclose_f, h5dset_extent_f, h5dget_space_f, h5dwrite_f, &
                   h5acreate_f, h5aclose_f, h5awrite_f, &
                   h5tcopy_f, h5tclose_f, h5tset_size_f, h5tset_strpad_f, h5tset_cset_f, h5t_str_nullpad_f, &
                   h5t_cset_utf8_f, h5t_c_s1, &
                   h5t_native_character, h5t_native_double, h5t_native_integer, h5t_ieee_f64le, h5t_std_i32le
   implicit none
   private

   public :: history_file_t, history_format_version, event_text_len

   !> Version of the file layout, the root attribute `format_version`: 2
   !! since /time became 1-D, the root got `version` and attribute strings
   !! became variable-length UTF-8; 3 since the string datasets are UTF-8
   !! (a reader's memory type must say so: HDF5 converts no character sets).
   integer, parameter :: history_format_version = 3

   !> Rows kept in memory per series before they are written; also the
   !! chunk length along rows.
   integer, parameter :: block_rows = 64
   !> Chunk length of the event datasets (events are few).
   integer, parameter :: event_chunk = 32
   !> Length of an event's text in the file.
   integer, parameter :: event_text_len = 120
   !> First capacity of the series table (it grows as needed).
   integer, parameter :: first_capacity = 16

   !> Identifier value meaning "nothing open".
   integer(hid_t), parameter :: no_id = -1_hid_t
   !> H5T_VARIABLE, C's (size_t)-1, which HDF5 1.10's Fortran interface
   !! does not name; its h5tset_size_f hands the value on to C unchanged.
   integer(size_t), parameter :: variable_length = -1_size_t

   character(len=*), parameter :: units_text = &
      'inch, pound force, second, radian unless an attribute says otherwise'

   !> One time series: its dataset and the rows not yet written.
   type :: series_t
      character(len=:), allocatable :: name
      integer(hid_t) :: dset = no_id
      integer :: ncols = 0
      !> 1: one value per row, a 1-D dataset; 2: (rows, ncols).
      integer :: rank = 2
      !> Rows already in the file.
      integer(hsize_t) :: rows_written = 0
      !> Rows waiting in buf(:, 1:nbuf).
      integer :: nbuf = 0
      real(wp), allocatable :: buf(:, :)
   end type series_t

   !> An HDF5 time-history file being written. Components are private; use
   !! the bound procedures. Call `close` before the object goes away:
   !! pending rows are written only by `flush` and `close`.
   type :: history_file_t
      private
      character(len=:), allocatable :: path
      integer(hid_t) :: file = no_id
      !> Group creation properties (no times) for every group we create.
      integer(hid_t) :: gcpl = no_id
      integer :: nseries = 0
      type(series_t), allocatable :: series(:)
      integer(hid_t) :: ev_time = no_id, ev_kind = no_id, ev_index = no_id, ev_text = no_id
      integer(hsize_t) :: nevents = 0
      !> The first write failure; once set, the file is abandoned (see above)
      !! and every later call returns it.
      type(error_t) :: failure
   contains
      !> Create (truncate) the file: root attributes, /input/deck, /events.
      procedure :: open => history_file_open
      !> Add a series (a dataset growing by rows); returns its id.
      procedure :: add_series => history_file_add_series
      !> Append one row to a series.
      procedure :: append => history_file_append
      !> One more string attribute of a series, one string per column.
      procedure :: add_attribute => history_file_add_attribute
      !> Add a table of fixed rows (the scene's geometry), written at once.
      procedure :: add_table => history_file_add_table
      !> Append one event.
      procedure :: add_event => history_file_add_event
      !> Write pending rows and flush the file to the operating system.
      procedure :: flush => history_file_flush
      !> Write pending rows and close; harmless when not open.
      procedure :: close => history_file_close
      !> True between a successful `open` and `close`.
      procedure :: is_open => history_file_is_open
   end type history_file_t

contains

   !> Create the file at `path` (replacing any file there), with the root
   !! attributes, the deck's card images as /input/deck and the empty
   !! /events datasets. Also silences HDF5's own error printing: failures
   !! come back in `err` only.
   subroutine history_file_open(this, path, title, deck_lines, err)
      class(history_file_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: title
      character(len=*), intent(in) :: deck_lines(:)
      type(error_t), intent(inout) :: err
      type(error_t) :: local
      integer(hid_t) :: fcpl, fapl, grp
      integer :: hdferr, ignore

      if (this%is_open()) then
         call error_set(err, exit_io, 'cannot open HDF5 file '//path//': '//this%path//' is still open')
         return
      end if
      this%path = path
      this%failure = error_t()

      call init_hdf5(hdferr)
      if (hdferr < 0) then
         call error_set(err, exit_io, 'cannot initialize the HDF5 library to write '//path)
         return
      end if
      call h5eset_auto_f(0, hdferr)
      if (hdferr < 0) then
         call error_set(err, exit_io, 'cannot silence HDF5 error printing to write '//path)
         return
      end if

      fcpl = no_id
      fapl = no_id
      call h5pcreate_f(h5p_file_create_f, fcpl, hdferr)
      ! The root group is created with the file: no times in its header.
      if (hdferr >= 0) call h5pset_obj_track_times_f(fcpl, .false., hdferr)
      if (hdferr >= 0) call h5pcreate_f(h5p_file_access_f, fapl, hdferr)
      ! Closing the file then releases every object in it.
      if (hdferr >= 0) call h5pset_fclose_degree_f(fapl, h5f_close_strong_f, hdferr)
      if (hdferr >= 0) call h5pcreate_f(h5p_group_create_f, this%gcpl, hdferr)
      if (hdferr >= 0) call h5pset_obj_track_times_f(this%gcpl, .false., hdferr)
      if (hdferr < 0) then
         call error_set(err, exit_io, 'cannot set up HDF5 properties to write '//path)
      else
         call posix_clear_errno()
         call h5fcreate_f(path, h5f_acc_trunc_f, this%file, hdferr, creation_prp=fcpl, access_prp=fapl)
         if (hdferr < 0) then
            this%file = no_id
            call error_set(err, exit_io, 'cannot create HDF5 file '//path//system_reason())
         end if
      end if
      if (fcpl > 0) call h5pclose_f(fcpl, ignore)
      if (fapl > 0) call h5pclose_f(fapl, ignore)
      if (hdferr < 0) then
         call release(this)
         return
      end if

      this%nseries = 0
      this%nevents = 0
      allocate (this%series(first_capacity))

      ! `local`, not `err`, says whether a step failed: `err` may hold an
      ! earlier, unrelated error.
      call write_int_attribute(this%file, this%path, '/', 'format_version', history_format_version, local)
      if (.not. local%failed()) &
         call write_string_attribute(this%file, this%path, '/', 'program', ['hsri2d'], .true., local)
      if (.not. local%failed()) &
         call write_string_attribute(this%file, this%path, '/', 'version', [hsri2d_version], .true., local)
      if (.not. local%failed()) &
         call write_string_attribute(this%file, this%path, '/', 'title', [title], .true., local)
      if (.not. local%failed()) &
         call write_string_attribute(this%file, this%path, '/', 'units', [units_text], .true., local)
      if (.not. local%failed()) call write_deck(this%file, this%gcpl, this%path, deck_lines, local)
      if (.not. local%failed()) then
         call create_group(this%file, this%gcpl, this%path, 'events', grp, local)
         if (grp > 0) call h5gclose_f(grp, ignore)
      end if
      if (.not. local%failed()) &
         call create_growing(this%file, this%path, 'events/time', h5t_ieee_f64le, 0, event_chunk, this%ev_time, local)
      if (.not. local%failed()) &
         call describe(this%ev_time, this%path, 'events/time', ['t'], ['s'], 'time of each event or note', local)
      if (.not. local%failed()) &
         call create_growing(this%file, this%path, 'events/kind', h5t_std_i32le, 0, event_chunk, this%ev_kind, local)
      if (.not. local%failed()) &
         call describe(this%ev_kind, this%path, 'events/kind', ['kind'], ['-'], &
                       'kind of each event, a code (docs/usage.md; events/text says it in words, a note''s ' &
                       //'beginning "note:")', local)
      if (.not. local%failed()) &
         call create_growing(this%file, this%path, 'events/index', h5t_std_i32le, 0, event_chunk, this%ev_index, local)
      if (.not. local%failed()) &
         call describe(this%ev_index, this%path, 'events/index', ['index'], ['-'], &
                       'the joint or segment each event concerns, numbered from 1', local)
      if (.not. local%failed()) call create_event_text(this%file, this%path, this%ev_text, local)
      if (.not. local%failed()) &
         call describe(this%ev_text, this%path, 'events/text', ['text'], ['-'], &
                       'each event in words, as the listing''s summary (up to 120 characters)', local)
      ! Flushed now so that even a run killed before its first flush leaves
      ! a readable file (with the deck).
      if (.not. local%failed()) call flush_file(this, 'cannot create HDF5 file '//this%path, local)
      if (local%failed()) then
         call release(this)
         call error_set(err, local%code, local%message)
      end if
   end subroutine history_file_open

   !> Add a series `name` (a path such as "body/z"; missing groups are
   !! created) with one column per entry of `columns` and `units`. `rank`
   !! chooses the dataset's shape: 1, rows only, for a series of one
   !! column (such as /time); 2, (rows, ncols). By default a one-column
   !! series is 1-D and any other 2-D. `id` is what `append` takes; 0 when
   !! it fails. flush (default true): flush the file after it.
   subroutine history_file_add_series(this, name, columns, units, description, id, err, rank, flush)
      class(history_file_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: columns(:)
      character(len=*), intent(in) :: units(:)
      character(len=*), intent(in) :: description
      integer, intent(out) :: id
      type(error_t), intent(inout) :: err
      integer, intent(in), optional :: rank
      logical, intent(in), optional :: flush
      type(series_t), allocatable :: bigger(:)
      type(error_t) :: local
      integer(hid_t) :: dset
      integer :: i, ignore, shape_rank

      id = 0
      if (.not. this%is_open()) then
         call error_set(err, exit_io, 'cannot add series '//name//': no HDF5 file is open')
         return
      end if
      if (len_trim(name) == 0) then
         call error_set(err, exit_io, 'cannot add a series without a name to '//this%path)
         return
      end if
      if (size(columns) < 1 .or. size(columns) /= size(units)) then
         call error_set(err, exit_io, 'cannot add series '//trim(name)//' to '//this%path// &
                        ': it needs at least one column and one unit per column')
         return
      end if
      shape_rank = merge(1, 2, size(columns) == 1)
      if (present(rank)) shape_rank = rank
      if (shape_rank /= 2 .and. (shape_rank /= 1 .or. size(columns) /= 1)) then
         call error_set(err, exit_io, 'cannot add series '//trim(name)//' to '//this%path// &
                        ': rank 1 takes one column, and the rank is 1 or 2')
         return
      end if
      if (this%failure%failed()) then
         err = this%failure
         return
      end if

      ! Groups on the way, e.g. "body" for "body/z".
      do i = 2, len_trim(name)
         if (name(i:i) == '/' .and. name(i - 1:i - 1) /= '/') then
            call ensure_group(this%file, this%gcpl, this%path, name(1:i - 1), local)
            if (local%failed()) then
               call error_set(err, local%code, local%message)
               return
            end if
         end if
      end do

      call create_growing(this%file, this%path, trim(name), h5t_ieee_f64le, &
                          merge(0, size(columns), shape_rank == 1), block_rows, dset, local)
      if (.not. local%failed()) call describe(dset, this%path, trim(name), columns, units, description, local)
      if (local%failed()) then
         if (dset > 0) call h5dclose_f(dset, ignore)
         call error_set(err, local%code, local%message)
         return
      end if

      if (this%nseries == size(this%series)) then
         allocate (bigger(2*size(this%series)))
         bigger(1:this%nseries) = this%series(1:this%nseries)
         call move_alloc(bigger, this%series)
      end if
      this%nseries = this%nseries + 1
      id = this%nseries
      associate (s => this%series(id))
         s%name = trim(name)
         s%dset = dset
         s%ncols = size(columns)
         s%rank = shape_rank
         s%rows_written = 0
         s%nbuf = 0
         allocate (s%buf(s%ncols, block_rows))
      end associate
      ! The file's structure is then on disk even if no row ever is.
      if (present(flush)) then
         if (.not. flush) return
      end if
      call flush_file(this, 'cannot add series '//trim(name)//' to HDF5 file '//this%path, local)
      if (local%failed()) call error_set(err, local%code, local%message)
   end subroutine history_file_add_series

   !> Append one row to series `id`; `values` holds one value per column.
   !! The row reaches the file when the series' block fills, or at `flush`
   !! or `close`.
   subroutine history_file_append(this, id, values, err)
      class(history_file_t), intent(inout) :: this
      integer, intent(in) :: id
      real(wp), intent(in) :: values(:)
      type(error_t), intent(inout) :: err
      character(len=24) :: got, want

      if (.not. this%is_open()) then
         call error_set(err, exit_io, 'cannot append a row: no HDF5 file is open')
         return
      end if
      if (id < 1 .or. id > this%nseries) then
         write (got, '(i0)') id
         call error_set(err, exit_io, 'cannot append a row to series '//trim(got)//' in '//this%path// &
                        ': no such series')
         return
      end if
      associate (s => this%series(id))
         if (size(values) /= s%ncols) then
            write (got, '(i0)') size(values)
            write (want, '(i0)') s%ncols
            call error_set(err, exit_io, 'cannot append a row of '//trim(got)//' values to dataset '//s%name// &
                           ' in '//this%path//': it has '//trim(want)//' columns')
            return
         end if
         if (this%failure%failed()) then
            err = this%failure
            return
         end if
         s%nbuf = s%nbuf + 1
         s%buf(:, s%nbuf) = values
         if (s%nbuf == block_rows) call write_block(this, s, err)
      end associate
   end subroutine history_file_append

   !> A string attribute `name` of series `id`, one of `values` per column
   !! (beside its columns and units: a criterion's filter class), or, with
   !! per_column false, a list of its own (the names of its rows).
   subroutine history_file_add_attribute(this, id, name, values, err, per_column)
      class(history_file_t), intent(inout) :: this
      integer, intent(in) :: id
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: values(:)
      type(error_t), intent(inout) :: err
      logical, intent(in), optional :: per_column
      type(error_t) :: local
      logical :: each
      each = .true.
      if (present(per_column)) each = per_column
      if (.not. this%is_open()) then
         call error_set(err, exit_io, 'cannot add attribute '//name//': no HDF5 file is open')
         return
      end if
      if (id < 1 .or. id > this%nseries) then
         call error_set(err, exit_io, 'cannot add attribute '//name//' in '//this%path//': no such series')
         return
      end if
      if (this%failure%failed()) then
         err = this%failure
         return
      end if
      associate (s => this%series(id))
         if (size(values) < 1 .or. (each .and. size(values) /= s%ncols)) then
            call error_set(err, exit_io, 'cannot add attribute '//name//' to dataset '//s%name//' in ' &
                           //this%path//': it needs one value per column')
            return
         end if
         call write_string_attribute(s%dset, this%path, s%name, name, values, .false., local)
      end associate
      if (local%failed()) call error_set(err, local%code, local%message)
   end subroutine history_file_add_attribute
   !> A table of fixed rows, `values(ncols, nrows)` (h5py: (nrows, ncols)),
   !! added as a 2-D series of those rows and written at once, with the
   !! series' attributes and, when `labels` is given, `rows` (a string per
   !! row). A table of no rows is a dataset of shape (0, ncols).
   subroutine history_file_add_table(this, name, columns, units, description, values, err, labels)
      class(history_file_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: columns(:)
      character(len=*), intent(in) :: units(:)
      character(len=*), intent(in) :: description
      real(wp), intent(in) :: values(:, :)
      type(error_t), intent(inout) :: err
      character(len=*), intent(in), optional :: labels(:)
      type(error_t) :: local
      integer :: id, r

      if (size(values, 1) /= size(columns)) then
         call error_set(err, exit_io, 'cannot add table '//trim(name)//' to '//this%path// &
                        ': its rows do not have one value per column')
         return
      end if
      if (present(labels)) then
         if (size(labels) /= size(values, 2)) then
            call error_set(err, exit_io, 'cannot add table '//trim(name)//' to '//this%path// &
                           ': it needs one label per row')
            return
         end if
      end if
      call this%add_series(name, columns, units, description, id, local, rank=2, flush=.false.)
      do r = 1, size(values, 2)
         if (local%failed()) exit
         call this%append(id, values(:, r), local)
      end do
      if (.not. local%failed() .and. present(labels)) then
         call write_string_attribute(this%series(id)%dset, this%path, trim(name), 'rows', labels, .false., local)
         if (local%failed()) this%failure = local   ! abandoned, as after any failed write
      end if
      if (.not. local%failed()) call write_block(this, this%series(id), local)
      if (local%failed()) call error_set(err, local%code, local%message)
   end subroutine history_file_add_table

   !> Append one event: its time, kind, index (e.g. the joint) and a text
   !! of up to 120 characters (longer text is cut). Written at once.
   subroutine history_file_add_event(this, time, kind, index, text, err)
      class(history_file_t), intent(inout) :: this
      real(wp), intent(in) :: time
      integer, intent(in) :: kind
      integer, intent(in) :: index
      character(len=*), intent(in) :: text
      type(error_t), intent(inout) :: err
      integer(hsize_t) :: n_new(1), start(1), one(1)
      integer(hid_t) :: fspace, mspace, memtype, dxpl
      character(len=event_text_len) :: line(1)
      integer :: hdferr, ignore

      if (.not. this%is_open()) then
         call error_set(err, exit_io, 'cannot add an event: no HDF5 file is open')
         return
      end if
      if (this%failure%failed()) then
         err = this%failure
         return
      end if
      start = this%nevents
      one = 1
      n_new = this%nevents + 1
      line(1) = text

      call posix_clear_errno()
      call select_new_rows(this%ev_time, n_new, start, one, fspace, mspace, hdferr)
      if (hdferr >= 0) call h5dwrite_f(this%ev_time, h5t_native_double, [time], one, hdferr, &
                                       mem_space_id=mspace, file_space_id=fspace)
      call close_spaces(fspace, mspace)
      if (hdferr < 0) then
         call write_failed(this, 'cannot write dataset events/time in '//this%path, err)
         return
      end if

      call select_new_rows(this%ev_kind, n_new, start, one, fspace, mspace, hdferr)
      if (hdferr >= 0) call h5dwrite_f(this%ev_kind, h5t_native_integer, [kind], one, hdferr, &
                                       mem_space_id=mspace, file_space_id=fspace)
      call close_spaces(fspace, mspace)
      if (hdferr < 0) then
         call write_failed(this, 'cannot write dataset events/kind in '//this%path, err)
         return
      end if

      call select_new_rows(this%ev_index, n_new, start, one, fspace, mspace, hdferr)
      if (hdferr >= 0) call h5dwrite_f(this%ev_index, h5t_native_integer, [index], one, hdferr, &
                                       mem_space_id=mspace, file_space_id=fspace)
      call close_spaces(fspace, mspace)
      if (hdferr < 0) then
         call write_failed(this, 'cannot write dataset events/index in '//this%path, err)
         return
      end if

      memtype = no_id
      dxpl = no_id
      call select_new_rows(this%ev_text, n_new, start, one, fspace, mspace, hdferr)
      if (hdferr >= 0) call string_type(event_text_len, .false., memtype, hdferr)
      if (hdferr >= 0) call small_conversion_buffer(dxpl, hdferr)
      if (hdferr >= 0) call h5dwrite_f(this%ev_text, memtype, line, one, hdferr, &
                                       mem_space_id=mspace, file_space_id=fspace, xfer_prp=dxpl)
      if (dxpl > 0) call h5pclose_f(dxpl, ignore)
      if (memtype > 0) call h5tclose_f(memtype, ignore)
      call close_spaces(fspace, mspace)
      if (hdferr < 0) then
         call write_failed(this, 'cannot write dataset events/text in '//this%path, err)
         return
      end if
      this%nevents = this%nevents + 1
   end subroutine history_file_add_event

   !> Write every pending row, then have HDF5 write all it holds to the
   !! file: a run stopped after this leaves a readable file with everything
   !! appended so far. rows = .false.: HDF5's part only - what add_event and
   !! the series' full blocks wrote, the rows still pending left for the
   !! next flush (an event made durable at once without the partial block
   !! of every series, which was most of a flush's cost).
   subroutine history_file_flush(this, err, rows)
      class(history_file_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      logical, intent(in), optional :: rows
      type(error_t) :: local
      logical :: with_rows

      if (.not. this%is_open()) then
         call error_set(err, exit_io, 'cannot flush: no HDF5 file is open')
         return
      end if
      with_rows = .true.
      if (present(rows)) with_rows = rows
      call flush_file(this, 'cannot flush HDF5 file '//this%path, local, with_rows)
      if (local%failed()) call error_set(err, local%code, local%message)
   end subroutine history_file_flush

   !> Write pending rows and close the file. Everything is released even
   !! when a write fails (an abandoned file: only our handles on it); an
   !! error already in `err` is kept rather than replaced. Does nothing
   !! when the file is not open.
   subroutine history_file_close(this, err)
      class(history_file_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      type(error_t) :: local

      if (.not. this%is_open()) return
      call release(this, local)
      if (local%failed() .and. .not. err%failed()) call error_set(err, local%code, local%message)
   end subroutine history_file_close

   !> True while the file is open.
   pure logical function history_file_is_open(this)
      class(history_file_t), intent(in) :: this
      history_file_is_open = this%file > 0
   end function history_file_is_open

   ! ---------------------------------------------------------------- helpers

   !> Record a write failure: `message` and the system's reason, if any,
   !! become the file's failure (it is abandoned from now on) and go to err.
   subroutine write_failed(this, message, err)
      class(history_file_t), intent(inout) :: this
      character(len=*), intent(in) :: message
      type(error_t), intent(inout) :: err
      if (.not. this%failure%failed()) call error_set(this%failure, exit_io, message//system_reason())
      err = this%failure
   end subroutine write_failed

   !> ": No space left on device" when errno says why an HDF5 call that
   !! writes to the file failed (cleared just before the call), else ''.
   function system_reason() result(reason)
      character(len=:), allocatable :: reason
      integer :: errno
      errno = posix_errno()
      reason = ''
      if (errno /= 0) reason = ': '//posix_error_text(errno)
   end function system_reason

   !> Close everything and return the object to its never-opened state.
   !! Pending rows are written and the file flushed first, so closing has
   !! nothing left to write. A file whose writes failed is abandoned
   !! instead (see the module's notes). Failures go to `err` when present.
   subroutine release(this, err)
      class(history_file_t), intent(inout) :: this
      type(error_t), intent(inout), optional :: err
      type(error_t) :: local
      integer :: k, ignore, hdferr

      if (this%file > 0 .and. .not. this%failure%failed()) &
         call flush_file(this, 'cannot close HDF5 file '//this%path, local)
      if (this%failure%failed()) then
         if (present(err)) err = this%failure
      else
         do k = 1, this%nseries
            if (this%series(k)%dset > 0) call h5dclose_f(this%series(k)%dset, ignore)
         end do
         call close_dataset(this%ev_time)
         call close_dataset(this%ev_kind)
         call close_dataset(this%ev_index)
         call close_dataset(this%ev_text)
         if (this%file > 0) then
            call posix_clear_errno()
            call h5fclose_f(this%file, hdferr)
            if (hdferr < 0 .and. present(err)) &
               call error_set(err, exit_io, 'cannot close HDF5 file '//this%path//system_reason())
         end if
      end if
      if (allocated(this%series)) deallocate (this%series)
      this%nseries = 0
      this%ev_time = no_id
      this%ev_kind = no_id
      this%ev_index = no_id
      this%ev_text = no_id
      this%nevents = 0
      this%file = no_id
      ! A property list belongs to no file: always safe to close.
      if (this%gcpl > 0) call h5pclose_f(this%gcpl, ignore)
      this%gcpl = no_id
   end subroutine release

   !> Initialize HDF5's Fortran interface unless that is done already:
   !! h5open_f creates the predefined types anew at every call (some 30 kB
   !! that h5close_f alone frees), so it is called only when they are not
   !! valid yet. HDF5's clean-up at exit is switched off first (see the
   !! module's notes); that call fails, harmlessly, once the library has
   !! started.
   subroutine init_hdf5(hdferr)
      integer, intent(out) :: hdferr
      logical :: ready
      call h5dont_atexit_f(hdferr)
      call h5iis_valid_f(h5t_native_double, ready, hdferr)
      if (hdferr < 0 .or. .not. ready) call h5open_f(hdferr)
   end subroutine init_hdf5

   !> Write the pending rows of every series, then have HDF5 write
   !! everything it holds for the file (metadata, chunk caches) to the
   !! operating system. `what` says what failed if that does.
   subroutine flush_file(this, what, err, rows)
      class(history_file_t), intent(inout) :: this
      character(len=*), intent(in) :: what
      type(error_t), intent(inout) :: err
      logical, intent(in), optional :: rows
      integer :: k, hdferr

      if (this%failure%failed()) then
         err = this%failure
         return
      end if
      do k = 1, this%nseries
         if (present(rows)) then
            if (.not. rows) exit                ! (the pending rows stay pending)
         end if
         call write_block(this, this%series(k), err)
         if (this%failure%failed()) return
      end do
      call posix_clear_errno()
      call h5fflush_f(this%file, h5f_scope_global_f, hdferr)
      if (hdferr < 0) call write_failed(this, what, err)
   end subroutine flush_file

   subroutine close_dataset(dset)
      integer(hid_t), intent(inout) :: dset
      integer :: ignore
      if (dset > 0) call h5dclose_f(dset, ignore)
      dset = no_id
   end subroutine close_dataset

   !> Write the pending rows of one series to its dataset (nothing to do
   !! when none are pending).
   subroutine write_block(this, s, err)
      class(history_file_t), intent(inout) :: this
      type(series_t), intent(inout) :: s
      type(error_t), intent(inout) :: err
      integer(hsize_t), allocatable :: n_new(:), start(:), count(:)
      integer(hid_t) :: fspace, mspace
      integer :: hdferr

      if (s%nbuf == 0) return
      if (this%failure%failed()) then
         err = this%failure
         return
      end if
      if (s%rank == 1) then
         n_new = [s%rows_written + s%nbuf]
         start = [s%rows_written]
         count = [int(s%nbuf, hsize_t)]
      else
         n_new = [int(s%ncols, hsize_t), s%rows_written + s%nbuf]
         start = [0_hsize_t, s%rows_written]
         count = [int(s%ncols, hsize_t), int(s%nbuf, hsize_t)]
      end if
      call posix_clear_errno()
      call select_new_rows(s%dset, n_new, start, count, fspace, mspace, hdferr)
      ! A 1-D series' buffer (1, nbuf) is the same memory as its nbuf values.
      if (hdferr >= 0) call h5dwrite_f(s%dset, h5t_native_double, s%buf(:, 1:s%nbuf), &
                                       [int(s%ncols, hsize_t), int(s%nbuf, hsize_t)], hdferr, &
                                       mem_space_id=mspace, file_space_id=fspace)
      call close_spaces(fspace, mspace)
      if (hdferr < 0) then
         call write_failed(this, 'cannot write dataset '//s%name//' in '//this%path, err)
         return
      end if
      s%rows_written = s%rows_written + s%nbuf
      s%nbuf = 0
   end subroutine write_block

   !> Grow `dset` to `n_new` and select the block at `start` of extent
   !! `count` in its file space; `mspace` describes that block in memory.
   !! The spaces are returned even on failure, for `close_spaces`.
   subroutine select_new_rows(dset, n_new, start, count, fspace, mspace, hdferr)
      integer(hid_t), intent(in) :: dset
      integer(hsize_t), intent(in) :: n_new(:), start(:), count(:)
      integer(hid_t), intent(out) :: fspace, mspace
      integer, intent(out) :: hdferr
      fspace = no_id
      mspace = no_id
      call h5dset_extent_f(dset, n_new, hdferr)
      if (hdferr >= 0) call h5dget_space_f(dset, fspace, hdferr)
      if (hdferr >= 0) call h5sselect_hyperslab_f(fspace, h5s_select_set_f, start, count, hdferr)
      if (hdferr >= 0) call h5screate_simple_f(size(count), count, mspace, hdferr)
   end subroutine select_new_rows

   subroutine close_spaces(fspace, mspace)
      integer(hid_t), intent(inout) :: fspace, mspace
      integer :: ignore
      if (fspace > 0) call h5sclose_f(fspace, ignore)
      if (mspace > 0) call h5sclose_f(mspace, ignore)
      fspace = no_id
      mspace = no_id
   end subroutine close_spaces

   !> Create an empty dataset that grows along its last dimension: 1-D when
   !! `ncols` is 0, otherwise ncols x rows. Chunked by `chunk_rows` rows.
   subroutine create_growing(file, path, name, file_type, ncols, chunk_rows, dset, err)
      integer(hid_t), intent(in) :: file
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: file_type
      integer, intent(in) :: ncols, chunk_rows
      integer(hid_t), intent(out) :: dset
      type(error_t), intent(inout) :: err
      integer(hsize_t), allocatable :: dims(:), maxdims(:), chunk(:)
      integer(hid_t) :: space, dcpl, dapl
      integer :: hdferr, ignore

      if (ncols == 0) then
         dims = [0_hsize_t]
         maxdims = [h5s_unlimited_f]
         chunk = [int(chunk_rows, hsize_t)]
      else
         dims = [int(ncols, hsize_t), 0_hsize_t]
         maxdims = [int(ncols, hsize_t), h5s_unlimited_f]
         chunk = [int(ncols, hsize_t), int(chunk_rows, hsize_t)]
      end if
      dset = no_id
      space = no_id
      dcpl = no_id
      dapl = no_id
      call h5screate_simple_f(size(dims), dims, space, hdferr, maxdims)
      if (hdferr >= 0) call h5pcreate_f(h5p_dataset_create_f, dcpl, hdferr)
      if (hdferr >= 0) call h5pset_chunk_f(dcpl, size(chunk), chunk, hdferr)
      if (hdferr >= 0) call h5pset_obj_track_times_f(dcpl, .false., hdferr)
      ! No chunk cache: every chunk is written whole, once, and never read
      ! back; HDF5's default cache (1 MiB per dataset) would keep about that
      ! much of every series in memory and make a long run's memory grow.
      if (hdferr >= 0) call h5pcreate_f(h5p_dataset_access_f, dapl, hdferr)
      if (hdferr >= 0) call h5pset_chunk_cache_f(dapl, 0_size_t, 0_size_t, 0.75, hdferr)
      if (hdferr >= 0) call h5dcreate_f(file, name, file_type, space, dset, hdferr, dcpl_id=dcpl, dapl_id=dapl)
      if (hdferr < 0) then
         dset = no_id
         call error_set(err, exit_io, 'cannot create dataset '//name//' in '//path)
      end if
      if (dcpl > 0) call h5pclose_f(dcpl, ignore)
      if (dapl > 0) call h5pclose_f(dapl, ignore)
      if (space > 0) call h5sclose_f(space, ignore)
   end subroutine create_growing

   !> The attributes every dataset carries: `columns` and `units` (one
   !! string per column) and `description`.
   subroutine describe(dset, path, name, columns, units, description, err)
      integer(hid_t), intent(in) :: dset
      character(len=*), intent(in) :: path, name
      character(len=*), intent(in) :: columns(:), units(:), description
      type(error_t), intent(inout) :: err
      type(error_t) :: local
      call write_string_attribute(dset, path, name, 'columns', columns, .false., local)
      if (.not. local%failed()) call write_string_attribute(dset, path, name, 'units', units, .false., local)
      if (.not. local%failed()) &
         call write_string_attribute(dset, path, name, 'description', [description], .true., local)
      if (local%failed()) call error_set(err, local%code, local%message)
   end subroutine describe

   !> A transfer property list whose type-conversion buffer is 64 KiB, for
   !! the string writes (blank-padded in memory, null-padded in the file):
   !! HDF5's default, 1 MiB, is allocated and cleared at the first
   !! conversion, 256 pages of fresh memory for some kilobytes of text (a
   !! longer deck is converted in pieces).
   subroutine small_conversion_buffer(dxpl, hdferr)
      integer(hid_t), intent(out) :: dxpl
      integer, intent(out) :: hdferr
      integer :: ignore
      call h5pcreate_f(h5p_dataset_xfer_f, dxpl, hdferr)
      if (hdferr < 0) then
         dxpl = no_id
         return
      end if
      call h5pset_buffer_f(dxpl, 65536_hsize_t, hdferr)
      if (hdferr < 0) then
         call h5pclose_f(dxpl, ignore)
         dxpl = no_id
      end if
   end subroutine small_conversion_buffer

   !> The 120-character event text dataset (its type is not a predefined one).
   subroutine create_event_text(file, path, dset, err)
      integer(hid_t), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: dset
      type(error_t), intent(inout) :: err
      integer(hid_t) :: ftype
      integer :: hdferr, ignore
      call string_type(event_text_len, .true., ftype, hdferr)
      if (hdferr < 0) then
         dset = no_id
         call error_set(err, exit_io, 'cannot create dataset events/text in '//path)
         return
      end if
      call create_growing(file, path, 'events/text', ftype, 0, event_chunk, dset, err)
      call h5tclose_f(ftype, ignore)
   end subroutine create_event_text

   !> A fixed-length string type of `n` characters: as stored in the file
   !! (null-padded, what C and Python readers expect) or as held in Fortran
   !! memory (blank-padded); HDF5 converts between the two.
   subroutine string_type(n, in_file, type_id, hdferr)
      integer, intent(in) :: n
      logical, intent(in) :: in_file
      integer(hid_t), intent(out) :: type_id
      integer, intent(out) :: hdferr
      integer :: ignore
      call h5tcopy_f(h5t_native_character, type_id, hdferr)
      if (hdferr < 0) then
         type_id = no_id
         return
      end if
      call h5tset_size_f(type_id, int(n, size_t), hdferr)
      if (hdferr >= 0 .and. in_file) call h5tset_strpad_f(type_id, h5t_str_nullpad_f, hdferr)
      ! UTF-8, in memory and file alike (HDF5 converts no character sets): a deck's
      ! comment card may hold UTF-8, and h5py's .asstr() decodes by the type's set.
      if (hdferr >= 0) call h5tset_cset_f(type_id, h5t_cset_utf8_f, hdferr)
      if (hdferr < 0) then
         call h5tclose_f(type_id, ignore)
         type_id = no_id
      end if
   end subroutine string_type

   !> Attach a string attribute to object `obj` (named `obj_name` in
   !! messages): a scalar when `scalar` (values has one element), else a
   !! 1-D array. Variable-length UTF-8 strings (h5py 3 reads them as str),
   !! trailing blanks trimmed.
   subroutine write_string_attribute(obj, path, obj_name, name, values, scalar, err)
      integer(hid_t), intent(in) :: obj
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: obj_name, name
      character(len=*), intent(in) :: values(:)
      logical, intent(in) :: scalar
      type(error_t), intent(inout) :: err
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), allocatable, target :: starts(:)
      integer(hsize_t) :: dims(1)
      integer(hid_t) :: space, vtype, attr
      integer :: hdferr, ignore, k, i, at, n

      ! The C strings, one after the other, and a pointer to each.
      allocate (chars(sum(len_trim(values)) + size(values)), starts(max(1, size(values))))
      at = 1
      do k = 1, size(values)
         n = len_trim(values(k))
         starts(k) = c_loc(chars(at))
         do i = 1, n
            chars(at + i - 1) = values(k)(i:i)
         end do
         chars(at + n) = c_null_char
         at = at + n + 1
      end do

      dims = size(values, kind=hsize_t)
      space = no_id
      vtype = no_id
      attr = no_id
      if (scalar) then
         call h5screate_f(h5s_scalar_f, space, hdferr)
      else
         call h5screate_simple_f(1, dims, space, hdferr)
      end if
      if (hdferr >= 0) call h5tcopy_f(h5t_c_s1, vtype, hdferr)
      if (hdferr >= 0) call h5tset_size_f(vtype, variable_length, hdferr)
      if (hdferr >= 0) call h5tset_cset_f(vtype, h5t_cset_utf8_f, hdferr)
      if (hdferr >= 0) call h5acreate_f(obj, name, vtype, space, attr, hdferr)
      if (hdferr >= 0 .and. size(values) > 0) call h5awrite_f(attr, vtype, c_loc(starts(1)), hdferr)
      if (hdferr < 0) call error_set(err, exit_io, 'cannot write attribute '//name//' of '//obj_name// &
                                     ' in '//path)
      if (attr > 0) call h5aclose_f(attr, ignore)
      if (vtype > 0) call h5tclose_f(vtype, ignore)
      if (space > 0) call h5sclose_f(space, ignore)
   end subroutine write_string_attribute

   !> Attach a scalar 32-bit integer attribute to object `obj`.
   subroutine write_int_attribute(obj, path, obj_name, name, value, err)
      integer(hid_t), intent(in) :: obj
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: obj_name, name
      integer, intent(in) :: value
      type(error_t), intent(inout) :: err
      integer(hsize_t) :: dims(1)
      integer(hid_t) :: space, attr
      integer :: hdferr, ignore
      dims = 1
      space = no_id
      attr = no_id
      call h5screate_f(h5s_scalar_f, space, hdferr)
      if (hdferr >= 0) call h5acreate_f(obj, name, h5t_std_i32le, space, attr, hdferr)
      if (hdferr >= 0) call h5awrite_f(attr, h5t_native_integer, value, dims, hdferr)
      if (hdferr < 0) call error_set(err, exit_io, 'cannot write attribute '//name//' of '//obj_name// &
                                     ' in '//path)
      if (attr > 0) call h5aclose_f(attr, ignore)
      if (space > 0) call h5sclose_f(space, ignore)
   end subroutine write_int_attribute

   !> Width of strings stored for `values`: the longest with trailing
   !! blanks trimmed, at least 1. HDF5 trims the rest when it converts the
   !! blank-padded memory strings to the null-padded file type.
   pure integer function stored_width(values)
      character(len=*), intent(in) :: values(:)
      stored_width = 1
      if (size(values) > 0) stored_width = max(1, maxval(len_trim(values)))
   end function stored_width

   !> /input/deck: one fixed-length string per card image.
   subroutine write_deck(file, gcpl, path, deck_lines, err)
      integer(hid_t), intent(in) :: file, gcpl
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: deck_lines(:)
      type(error_t), intent(inout) :: err
      integer(hsize_t) :: dims(1)
      integer(hid_t) :: grp, space, ftype, mtype, dcpl, dset, dxpl
      integer :: hdferr, ignore

      call create_group(file, gcpl, path, 'input', grp, err)
      if (grp <= 0) return
      call h5gclose_f(grp, ignore)

      dims = size(deck_lines, kind=hsize_t)
      space = no_id
      ftype = no_id
      mtype = no_id
      dcpl = no_id
      dset = no_id
      dxpl = no_id
      call h5screate_simple_f(1, dims, space, hdferr)
      if (hdferr >= 0) call string_type(stored_width(deck_lines), .true., ftype, hdferr)
      if (hdferr >= 0) call string_type(max(1, len(deck_lines)), .false., mtype, hdferr)
      if (hdferr >= 0) call h5pcreate_f(h5p_dataset_create_f, dcpl, hdferr)
      if (hdferr >= 0) call h5pset_obj_track_times_f(dcpl, .false., hdferr)
      if (hdferr >= 0) call h5dcreate_f(file, 'input/deck', ftype, space, dset, hdferr, dcpl_id=dcpl)
      ! Nothing to write for an empty deck or one of zero-length lines (the
      ! dataset then holds empty strings, the fill value).
      if (hdferr >= 0 .and. size(deck_lines) > 0 .and. len(deck_lines) > 0) then
         call small_conversion_buffer(dxpl, hdferr)
         if (hdferr >= 0) call h5dwrite_f(dset, mtype, deck_lines, dims, hdferr, xfer_prp=dxpl)
      end if
      if (hdferr < 0) call error_set(err, exit_io, 'cannot write dataset input/deck in '//path)
      if (hdferr >= 0) call describe(dset, path, 'input/deck', ['card'], ['-'], &
                                     'the card images of the deck, in the order read', err)
      if (dset > 0) call h5dclose_f(dset, ignore)
      if (dcpl > 0) call h5pclose_f(dcpl, ignore)
      if (dxpl > 0) call h5pclose_f(dxpl, ignore)
      if (mtype > 0) call h5tclose_f(mtype, ignore)
      if (ftype > 0) call h5tclose_f(ftype, ignore)
      if (space > 0) call h5sclose_f(space, ignore)
   end subroutine write_deck

   !> Create group `name`, without times in its header; `grp` is left open.
   subroutine create_group(file, gcpl, path, name, grp, err)
      integer(hid_t), intent(in) :: file, gcpl
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: name
      integer(hid_t), intent(out) :: grp
      type(error_t), intent(inout) :: err
      integer :: hdferr
      call h5gcreate_f(file, name, grp, hdferr, gcpl_id=gcpl)
      if (hdferr < 0) then
         grp = no_id
         call error_set(err, exit_io, 'cannot create group '//name//' in '//path)
      end if
   end subroutine create_group

   !> Create group `name` unless a link of that name exists already.
   subroutine ensure_group(file, gcpl, path, name, err)
      integer(hid_t), intent(in) :: file, gcpl
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: name
      type(error_t), intent(inout) :: err
      logical :: exists
      integer(hid_t) :: grp
      integer :: hdferr, ignore
      call h5lexists_f(file, name, exists, hdferr)
      if (hdferr < 0) then
         call error_set(err, exit_io, 'cannot look up group '//name//' in '//path)
         return
      end if
      if (exists) return
      call create_group(file, gcpl, path, name, grp, err)
      if (grp > 0) call h5gclose_f(grp, ignore)
   end subroutine ensure_group
end module history_h5
