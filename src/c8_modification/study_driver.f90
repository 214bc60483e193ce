!> A study, start to end (report C.8; docs/modification.md): the base deck
!! and its *STUDY read and checked once; the runs' values (study_sampling,
!! or a Nelder-Mead search for OPTIMIZE); each run made (study_runs) in this
!! process, in worker processes (--jobs) or in a slice (--shard, for a job
!! array); each run's row written at once, atomically, under the results
!! directory, so that a study killed or stopped resumes where it was; the
!! rows merged in run order into results.csv and the study's listing.
!! Nothing a run does ends the study: a run that fails is a row that says so.
module study_driver
   use, intrinsic :: iso_c_binding, only: c_long
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use kinds, only: wp
   use error_handling, only: error_t, error_set, exit_usage, exit_io, exit_study
   use strings, only: itoa, num, upper
   use text_io, only: string_t, append_string, read_text_file, standard_input_path
   use posix_files, only: file_info_t, posix_file_info, posix_make_dir, posix_error_text, kind_regular
   use posix_processes, only: posix_spawn_program, posix_wait, posix_sleep_ms
   use deck_reader, only: deck_t, deck_init, deck_add_file, deck_add_lines, deck_finish
   use default_deck, only: default_deck_lines
   use run_case_mod, only: builtin_deck_name, deck_text, pulse_file
   use model, only: model_t
   use model_builder, only: build_model
   use analog_input, only: deck_is_analog
   use equations_of_motion, only: crash_system_t, system_build
   use model_origin, only: deck_origin, problem
   use output_files, only: output_file_t, check_output_paths
   use study_h5, only: study_h5_t
   use version_info, only: hsri2d_version
   use study_input, only: study_t, read_study, has_study, method_optimize, method_ensemble, method_word
   use study_criteria, only: word_column, word_unit
   use study_runs, only: study_run
   use study_table, only: run_row_t, row_csv, row_from_csv, table_header, status_word, &
      status_completed, status_ended, status_failed, status_invalid
   use study_sampling, only: study_variable_t, study_points
   use nelder_mead, only: nm_t
   implicit none
   private

   public :: study_request_t, run_study, study_size, deck_has_study, progress_report

   !> What to do with a study deck and where its results go.
   type :: study_request_t
      type(string_t), allocatable :: decks(:)
      character(len=:), allocatable :: listing_file   !< '' = standard output
      character(len=:), allocatable :: results_dir    !< '' = rows kept in memory only
      character(len=:), allocatable :: h5_file        !< '' = no HDF5 file (study_h5)
      integer :: jobs = 1                             !< worker processes
      integer :: shard = 0, n_shards = 0              !< --shard K/N (0: the whole study)
      logical :: collect = .false.                    !< merge the rows, run nothing
      character(len=:), allocatable :: program        !< this program, for the workers
   end type study_request_t

   abstract interface
      !> Told after each run (or each poll of the workers): runs done,
      !! failed or invalid, and in all; the CPU or wall seconds so far.
      subroutine progress_report(done, bad, total, seconds)
         import :: wp
         integer, intent(in) :: done, bad, total
         real(wp), intent(in) :: seconds
      end subroutine progress_report
   end interface

   !> A study, read and checked.
   type :: study_case_t
      type(deck_t) :: deck
      type(study_t) :: st
      real(wp), allocatable :: points(:, :)   !< (variable, run); OPTIMIZE: none
      integer :: n_runs = 0
      character(len=:), allocatable :: identity   !< the deck's text (DIR/study.deck)
      type(string_t), allocatable :: pulse_file(:)   !< the files of the base deck's pulse (*PULSEFILE, *PULSEMME)
   end type study_case_t

   !> The rows of a study's runs: with a results directory, in its files,
   !! read when needed (memory does not grow with the rows); without one,
   !! in memory. have(r): run r has a row; n: the runs of the table.
   type :: row_store_t
      character(len=:), allocatable :: dir
      type(run_row_t), allocatable :: rows(:)   !< without a directory only
      logical, allocatable :: have(:)
      integer :: n = 0
      integer :: n_bad = 0                      !< rows of failed or invalid runs
   end type row_store_t

contains

   !> The deck files hold a *STUDY group: a header card "*STUDY" (the cards
   !! scanned, not parsed: a plain run pays one read of its files' text).
   !! Only regular files: standard input, a pipe or a FIFO is read once, by
   !! the run (run_case refuses a study there).
   logical function deck_has_study(decks)
      type(string_t), intent(in) :: decks(:)
      type(string_t), allocatable :: lines(:)
      type(error_t) :: ignored
      type(file_info_t) :: info
      character(len=:), allocatable :: word
      integer :: k, i, e
      deck_has_study = .false.
      do k = 1, size(decks)
         if (decks(k)%s == standard_input_path .or. decks(k)%s == builtin_deck_name) cycle
         if (posix_file_info(decks(k)%s, info) /= 0) cycle
         if (info%kind /= kind_regular) cycle
         call read_text_file(decks(k)%s, lines, ignored)
         if (ignored%failed()) cycle
         do i = 1, size(lines)
            if (len(lines(i)%s) < 6) cycle
            if (lines(i)%s(1:1) /= '*') cycle
            e = scan(lines(i)%s(2:)//' ', ' ')
            word = upper(lines(i)%s(2:e))
            if (word == 'STUDY') then
               deck_has_study = .true.
               return
            end if
         end do
      end do
   end function deck_has_study

   !> The number of runs of the study (OPTIMIZE: its budget).
   subroutine study_size(req, n, err)
      type(study_request_t), intent(in) :: req
      integer, intent(out) :: n
      type(error_t), intent(inout) :: err
      type(study_case_t), allocatable :: sc
      allocate (sc)
      n = 0
      call read_case(req, sc, err)
      if (.not. err%failed()) n = sc%n_runs
   end subroutine study_size

   !> Run (or collect) the study of req; err: exit 2 for the deck, 1 for
   !! the command line or a results directory of another study, 4 for a
   !! file, 5 when runs are missing (--collect) or every run failed.
   subroutine run_study(req, err, progress)
      type(study_request_t), intent(in) :: req
      type(error_t), intent(inout) :: err
      procedure(progress_report), optional :: progress
      type(study_case_t), allocatable :: sc
      type(row_store_t) :: store
      type(run_row_t) :: row
      integer :: r, n_made

      allocate (sc)
      call read_case(req, sc, err)
      if (err%failed()) return
      call check_request(req, sc, err)
      if (err%failed()) return
      if (len(req%results_dir) > 0) then
         call prepare_directory(req%results_dir, sc%identity, err)
         if (err%failed()) return
      end if
      call store_init(store, req%results_dir, sc%n_runs)

      if (req%collect) then
         call store_scan(store, sc)
      else if (sc%st%method == method_optimize) then
         call optimize(req, sc, store, n_made, err, progress)
         if (err%failed()) return
         ! a search that converged before its budget: the runs it made
         store%n = n_made
      else if (req%jobs > 1) then
         call run_workers(req, sc, err, progress)
         if (err%failed()) return
         if (req%n_shards > 0) return   ! a slice writes its rows only
         call store_scan(store, sc)
      else
         do r = 1, sc%n_runs
            if (req%n_shards > 0) then
               if (mod(r - 1, req%n_shards) /= req%shard - 1) cycle
            end if
            call one_run(req, sc, r, sc%points(:, r), row, err)
            if (err%failed()) return
            call store_keep(store, row)
            if (present(progress)) call progress(count(store%have), store%n_bad, sc%n_runs, cpu_now())
         end do
      end if
      if (req%n_shards > 0) return   ! a slice writes its rows only
      call write_results(req, sc, store, err)
      if (err%failed()) return
      if (.not. all(store%have(1:store%n))) then
         call error_set(err, exit_study, 'the study has '//itoa(count(.not. store%have(1:store%n)))// &
                        ' run(s) without a result in '//req%results_dir//': '//missing_list(store%have(1:store%n)) &
                        //' (run their shards, then --collect again)')
      else if (store%n_bad == store%n) then
         call error_set(err, exit_study, 'every run of the study failed or was invalid; the reasons are in the '// &
                        'table')
      end if
   end subroutine run_study

   ! --- reading -----------------------------------------------------------

   !> The decks read and checked (the base deck builds a model as any
   !! deck), the study read, the runs' values made.
   subroutine read_case(req, sc, err)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(inout) :: sc
      type(error_t), intent(inout) :: err
      type(model_t), allocatable :: m
      type(study_variable_t), allocatable :: vars(:)
      integer :: k, n_occ
      allocate (m)
      call deck_init(sc%deck)
      do k = 1, size(req%decks)
         if (req%decks(k)%s == builtin_deck_name .and. len(req%decks(k)%s) == len(builtin_deck_name)) then
            call deck_add_lines(sc%deck, builtin_deck_name, '', default_deck_lines(), err)
         else
            call deck_add_file(sc%deck, req%decks(k)%s, err)
         end if
      end do
      if (err%code == exit_io) return
      call deck_finish(sc%deck, err)
      if (err%failed()) return
      if (.not. has_study(sc%deck)) then
         call error_set(err, exit_usage, 'the deck has no *STUDY card group: the study options (--results, '// &
                        '--jobs, --shard, --collect, --study-size) need one (docs/modification.md)')
         return
      end if
      ! Section D's analog has no occupant model: each run solves its closed
      ! form (study_runs), and its deck reads no pulse
      if (.not. deck_is_analog(sc%deck)) call build_model(sc%deck, m, err)
      call read_study(sc%deck, sc%st, err)
      if (err%failed()) return
      if (sc%st%analog) then
         allocate (sc%pulse_file(0))
      else
         ! a deck's model has one occupant (NBODY is its position, not a count)
         n_occ = occupants_of(m)
         do k = 1, size(sc%st%crits)
            if (sc%st%crits(k)%occupant > n_occ) call problem(deck_origin(sc%deck), err, sc%st%crits(k)%card, &
               'the deck''s model has '//itoa(n_occ)//' occupant(s); there is no occupant '// &
               itoa(sc%st%crits(k)%occupant), 'OCC')
         end do
         if (sc%st%objective_occupant > n_occ .and. len_trim(sc%st%objective) > 0) &
            call problem(deck_origin(sc%deck), err, sc%st%card, 'the deck''s model has '//itoa(n_occ)// &
                         ' occupant(s); there is no occupant '//itoa(sc%st%objective_occupant), 'OCC')
         if (err%failed()) return
         sc%pulse_file = pulse_file(sc%deck, m)
      end if
      sc%identity = study_text(sc%deck)
      if (sc%st%method == method_optimize) then
         sc%n_runs = sc%st%runs
         allocate (sc%points(size(sc%st%vars), 0))
         return
      end if
      allocate (vars(size(sc%st%vars)))
      do k = 1, size(vars)
         associate (v => sc%st%vars(k))
            vars(k)%low = v%low
            vars(k)%high = v%high
            if (.not. v%has_range .and. sc%st%method == method_ensemble) then
               ! perturbations kept within what the field itself accepts
               vars(k)%low = max(sc%deck%spec(v%gid)%field(v%k)%low, -1.0e300_wp)
               vars(k)%high = min(sc%deck%spec(v%gid)%field(v%k)%high, 1.0e300_wp)
            else if (.not. v%has_range) then
               vars(k)%low = v%base
               vars(k)%high = v%base
               if (size(v%values) > 0) then
                  vars(k)%low = minval(v%values)
                  vars(k)%high = maxval(v%values)
               end if
            end if
            vars(k)%count = v%count
            vars(k)%values = v%values
            vars(k)%base = v%base
            vars(k)%spread = v%spread
            vars(k)%integer_valued = v%integer_valued
         end associate
      end do
      call study_points(sc%st%method, vars, sc%st%runs, sc%st%seed, sc%points, err)
      if (.not. err%failed()) sc%n_runs = size(sc%points, 2)
   end subroutine read_case

   !> What the command line asks must suit the study.
   subroutine check_request(req, sc, err)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      type(error_t), intent(inout) :: err
      type(string_t), allocatable :: files(:)
      integer :: k
      ! the listing and the HDF5 file never overwrite an input (output_files)
      allocate (files(0))
      do k = 1, size(req%decks)
         if (req%decks(k)%s /= builtin_deck_name) call append_string(files, req%decks(k)%s)
      end do
      call check_output_paths(files, sc%pulse_file, req%listing_file, req%h5_file, err)
      if (err%failed()) return
      if (len(req%results_dir) == 0 .and. (req%jobs > 1 .or. req%n_shards > 0 .or. req%collect)) then
         call error_set(err, exit_usage, '--jobs, --shard and --collect need --results DIR, the directory that '// &
                        'holds each run''s result')
      else if (len(req%results_dir) == 0 .and. sc%st%keep > 1) then
         call error_set(err, exit_usage, '*STUDY KEEP writes each run''s own listing or HDF5 file under the '// &
                        'results directory: give --results DIR')
      else if (sc%st%method == method_optimize .and. (req%jobs > 1 .or. req%n_shards > 0)) then
         call error_set(err, exit_usage, 'METHOD OPTIMIZE makes one run after another (each depends on the '// &
                        'last): --jobs and --shard apply to the other methods')
      end if
   end subroutine check_request

   ! --- the results directory -----------------------------------------------

   !> DIR and DIR/runs made; DIR/study.deck holds the deck the rows belong
   !! to: a directory of another study (or of the deck since changed) is
   !! refused, never mixed.
   subroutine prepare_directory(dir, text, err)
      character(len=*), intent(in) :: dir, text
      type(error_t), intent(inout) :: err
      type(output_file_t) :: f
      type(file_info_t) :: info
      type(string_t), allocatable :: lines(:)
      character(len=:), allocatable :: old
      integer :: errno, k
      errno = posix_make_dir(dir)
      if (errno == 0) errno = posix_make_dir(dir//'/runs')
      if (errno /= 0) then
         call error_set(err, exit_io, 'cannot make the results directory '//dir//': '//posix_error_text(errno))
         return
      end if
      if (posix_file_info(dir//'/study.deck', info) == 0 .and. info%kind == kind_regular) then
         call read_text_file(dir//'/study.deck', lines, err)
         if (err%failed()) return
         old = ''
         do k = 1, size(lines)
            old = old//lines(k)%s//new_line('a')
         end do
         if (old /= text .or. len(old) /= len(text)) call error_set(err, exit_usage, dir//' holds the results of '// &
            'another study (its study.deck is not this deck): give another --results directory, or remove '//dir)
         return
      end if
      call f%create_text(dir//'/study.deck', 'study deck', err)
      if (err%failed()) return
      call put_text(f, text)
      call f%commit(err)
   end subroutine prepare_directory

   !> The file of run r's row.
   pure function row_path(dir, r) result(path)
      character(len=*), intent(in) :: dir
      integer, intent(in) :: r
      character(len=:), allocatable :: path
      character(len=:), allocatable :: digits
      digits = itoa(r)
      path = dir//'/runs/'//repeat('0', max(0, 6 - len(digits)))//digits
   end function row_path

   !> Run r's row from the results directory, when a whole one is there.
   subroutine read_row(dir, sc, r, row, ok)
      character(len=*), intent(in) :: dir
      type(study_case_t), intent(in) :: sc
      integer, intent(in) :: r
      type(run_row_t), intent(out) :: row
      logical, intent(out) :: ok
      type(file_info_t) :: info
      type(string_t), allocatable :: lines(:)
      type(error_t) :: err
      ok = .false.
      if (posix_file_info(row_path(dir, r)//'.row', info) /= 0) return
      if (info%kind /= kind_regular) return
      call read_text_file(row_path(dir, r)//'.row', lines, err)
      if (err%failed() .or. size(lines) /= 1) return
      call row_from_csv(lines(1)%s, size(sc%st%vars), size(sc%st%crits), row, ok)
      ok = ok .and. row%run == r
   end subroutine read_row

   !> An empty store of n runs' rows, in directory dir ('' = in memory).
   subroutine store_init(store, dir, n)
      type(row_store_t), intent(out) :: store
      character(len=*), intent(in) :: dir
      integer, intent(in) :: n
      store%dir = dir
      store%n = n
      allocate (store%have(n))
      store%have = .false.
      if (len(dir) == 0) allocate (store%rows(n))
   end subroutine store_init

   !> A run's row made: counted (and kept, without a directory, where the
   !! row's file is already written).
   subroutine store_keep(store, row)
      type(row_store_t), intent(inout) :: store
      type(run_row_t), intent(in) :: row
      store%have(row%run) = .true.
      if (row%status == status_failed .or. row%status == status_invalid) store%n_bad = store%n_bad + 1
      if (len(store%dir) == 0) store%rows(row%run) = row
   end subroutine store_keep

   !> Every row the directory holds, counted.
   subroutine store_scan(store, sc)
      type(row_store_t), intent(inout) :: store
      type(study_case_t), intent(in) :: sc
      type(run_row_t) :: row
      integer :: r
      logical :: ok
      do r = 1, store%n
         if (store%have(r)) cycle
         call read_row(store%dir, sc, r, row, ok)
         if (ok) call store_keep(store, row)
      end do
   end subroutine store_scan

   !> Run r's row, when it has one.
   subroutine store_get(store, sc, r, row, ok)
      type(row_store_t), intent(in) :: store
      type(study_case_t), intent(in) :: sc
      integer, intent(in) :: r
      type(run_row_t), intent(out) :: row
      logical, intent(out) :: ok
      ok = store%have(r)
      if (.not. ok) return
      if (len(store%dir) == 0) then
         row = store%rows(r)
      else
         call read_row(store%dir, sc, r, row, ok)
      end if
   end subroutine store_get

   !> Run r at values x, or its row from the directory when it is there
   !! (a resumed study); the row written at once, atomically.
   subroutine one_run(req, sc, r, x, row, err)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      integer, intent(in) :: r
      real(wp), intent(in) :: x(:)
      type(run_row_t), intent(out) :: row
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: lst, h5
      logical :: ok
      if (len(req%results_dir) > 0) then
         call read_row(req%results_dir, sc, r, row, ok)
         if (ok) return
      end if
      lst = ''
      h5 = ''
      if (sc%st%keep == 2 .or. sc%st%keep == 4) lst = row_path(req%results_dir, r)//'.lst'
      if (sc%st%keep == 3 .or. sc%st%keep == 4) h5 = row_path(req%results_dir, r)//'.h5'
      call study_run(sc%deck, sc%st, r, x, lst, h5, row)
      call store_row(req, sc, row, err)
   end subroutine one_run

   !> A row to its file under the results directory (none without one),
   !! atomically: a temporary file renamed.
   subroutine store_row(req, sc, row, err)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      type(run_row_t), intent(in) :: row
      type(error_t), intent(inout) :: err
      type(output_file_t) :: f
      if (len(req%results_dir) == 0) return
      call f%create_text(row_path(req%results_dir, row%run)//'.row', 'result of run '//itoa(row%run), err)
      if (err%failed()) return
      call f%put_line(row_csv(row, size(sc%st%crits)))
      call f%commit(err)
   end subroutine store_row

   ! --- worker processes --------------------------------------------------

   !> --jobs J: J copies of the program, copy j running --shard j/J; this
   !! process waits for them (reporting the rows as they appear). Within
   !! slice K of N (--shard K/N --jobs J, a job array's task on J cores),
   !! copy j runs slice K + N (j - 1) of N J: the runs of slice K, dealt
   !! out among the copies.
   subroutine run_workers(req, sc, err, progress)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      type(error_t), intent(inout) :: err
      procedure(progress_report), optional :: progress
      integer(c_long) :: pid(req%jobs)
      logical :: running(req%jobs), done
      type(string_t), allocatable :: args(:)
      integer :: k, j, errno, status, n_done, n_bad, r
      integer(int64) :: c0, c1, rate
      type(run_row_t) :: row
      logical :: ok, seen(sc%n_runs)
      running = .false.
      seen = .false.
      n_done = 0
      n_bad = 0
      call system_clock(c0, rate)
      do k = 1, req%jobs
         allocate (args(0))
         call append_string(args, req%program)
         call append_string(args, '--shard')
         if (req%n_shards > 0) then
            call append_string(args, itoa(req%shard + req%n_shards*(k - 1))//'/'//itoa(req%n_shards*req%jobs))
         else
            call append_string(args, itoa(k)//'/'//itoa(req%jobs))
         end if
         call append_string(args, '--results')
         call append_string(args, req%results_dir)
         call append_string(args, '--')
         do j = 1, size(req%decks)
            call append_string(args, req%decks(j)%s)
         end do
         errno = posix_spawn_program(req%program, args, pid(k))
         deallocate (args)
         if (errno /= 0) then
            call error_set(err, exit_io, 'cannot start worker '//itoa(k)//' ('//req%program//'): '// &
                           posix_error_text(errno))
            exit
         end if
         running(k) = .true.
      end do
      do while (any(running))
         do k = 1, req%jobs
            if (.not. running(k)) cycle
            ! without progress to show, wait for each worker in turn (no polling)
            errno = posix_wait(pid(k), present(progress), done, status)
            if (errno /= 0) then
               running(k) = .false.
            else if (done) then
               running(k) = .false.
               if (status /= 0 .and. .not. err%failed()) call error_set(err, exit_study, 'worker '//itoa(k)// &
                  ' (--shard '//itoa(k)//'/'//itoa(req%jobs)//') ended with status '//itoa(status)// &
                  '; the rows it wrote are kept: run the study again to finish it')
            end if
         end do
         if (present(progress)) then
            ! the rows that appeared since the last look
            do r = 1, sc%n_runs
               if (seen(r)) cycle
               call read_row(req%results_dir, sc, r, row, ok)
               if (.not. ok) cycle
               seen(r) = .true.
               n_done = n_done + 1
               if (row%status == status_failed .or. row%status == status_invalid) n_bad = n_bad + 1
            end do
            call system_clock(c1)
            call progress(n_done, n_bad, sc%n_runs, real(c1 - c0, wp)/real(rate, wp))
         end if
         if (any(running) .and. present(progress)) call posix_sleep_ms(100)
      end do
   end subroutine run_workers

   ! --- optimisation ------------------------------------------------------

   !> OPTIMIZE: Nelder-Mead over the variables within LOW-HIGH, from the
   !! base deck's values, minimising OBJECT plus a penalty for each limit
   !! exceeded; a failed or invalid run counts as the worst value. Runs are
   !! numbered in the order asked, so a resumed search replays the same
   !! points from its rows.
   subroutine optimize(req, sc, store, n_made, err, progress)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      type(row_store_t), intent(inout) :: store
      integer, intent(out) :: n_made
      type(error_t), intent(inout) :: err
      procedure(progress_report), optional :: progress
      type(nm_t) :: nm
      real(wp), allocatable :: x(:), lo(:), hi(:), x0(:), asked(:, :)
      type(run_row_t) :: row
      logical :: done, ok
      integer :: r, n, k, ko, j
      n = size(sc%st%vars)
      allocate (lo(n), hi(n), x0(n), x(n))
      do k = 1, n
         lo(k) = sc%st%vars(k)%low
         hi(k) = sc%st%vars(k)%high
         x0(k) = min(max(sc%st%vars(k)%base, lo(k)), hi(k))
      end do
      ko = objective_column(sc%st)
      call nm%init(x0, lo, hi, sc%st%tol, sc%n_runs, err)
      if (err%failed()) return
      n_made = 0
      allocate (asked(n, sc%n_runs))
      do r = 1, sc%n_runs
         call nm%ask(x, done)
         if (done) exit
         n_made = r
         asked(:, r) = x
         ! a point asked again (projected onto the same bound) is not run again
         j = 0
         do k = 1, r - 1
            if (.not. any(abs(asked(:, k) - x) > 0.0_wp)) j = k
         end do
         if (j > 0) then
            call store_get(store, sc, j, row, ok)
            row%run = r
            row%reason = 'the values of run '//itoa(j)//': not run again'
            call store_row(req, sc, row, err)
         else
            call one_run(req, sc, r, x, row, err)
         end if
         if (err%failed()) return
         call store_keep(store, row)
         call nm%tell(penalised(sc%st, row, ko))
         if (present(progress)) call progress(count(store%have), store%n_bad, sc%n_runs, cpu_now())
      end do
   end subroutine optimize

   !> The column of the criteria that holds the objective (read_study adds
   !! it to the criteria when *CRITERIA does not name it).
   pure integer function objective_column(st) result(k)
      type(study_t), intent(in) :: st
      do k = 1, size(st%crits)
         if (st%crits(k)%word == st%objective .and. st%crits(k)%occupant == st%objective_occupant) return
      end do
      k = 0
   end function objective_column

   !> The value the search minimises: the objective, plus for each limit
   !! exceeded 1000 (1 + |objective|) times its relative excess; huge for a
   !! run without criteria (failed, invalid).
   pure real(wp) function penalised(st, row, ko) result(f)
      type(study_t), intent(in) :: st
      type(run_row_t), intent(in) :: row
      integer, intent(in) :: ko
      integer :: k
      f = huge(1.0_wp)
      if (.not. allocated(row%crit) .or. ko == 0) return
      if (ieee_is_nan(row%crit(ko))) return   ! (an objective without a value: the worst)
      f = row%crit(ko)
      do k = 1, size(st%crits)
         if (.not. st%crits(k)%has_limit) cycle
         if (row%crit(k) > st%crits(k)%limit) f = f + 1000.0_wp*(1.0_wp + abs(row%crit(ko)))* &
            (row%crit(k) - st%crits(k)%limit)/max(abs(st%crits(k)%limit), 1.0e-12_wp)
      end do
   end function penalised

   ! --- the outputs -------------------------------------------------------

   !> results.csv (with a results directory) and the study's listing.
   subroutine write_results(req, sc, store, err)
      type(study_request_t), intent(in) :: req
      type(study_case_t), intent(in) :: sc
      type(row_store_t), intent(in) :: store
      type(error_t), intent(inout) :: err
      type(output_file_t) :: csv, lst
      type(study_h5_t) :: h5
      type(run_row_t) :: row
      integer :: r
      logical :: ok
      if (len(req%results_dir) > 0) then
         call csv%create_text(req%results_dir//'/results.csv', 'results table', err)
         if (err%failed()) return
         call csv%put_line(table_header(var_columns(sc%st), crit_columns(sc%st)))
         do r = 1, store%n
            call store_get(store, sc, r, row, ok)
            if (ok) call csv%put_line(row_csv(row, size(sc%st%crits)))
         end do
         call csv%commit(err)
         if (err%failed()) return
      end if
      if (len(req%h5_file) > 0) then
         call h5%open(req%h5_file, title_of(sc%deck), deck_text(sc%deck), var_columns(sc%st), var_units(sc), &
                      crit_columns(sc%st), crit_units(sc%st), err)
         do r = 1, store%n
            if (err%failed()) exit
            call store_get(store, sc, r, row, ok)
            if (ok) call h5%add(row, err)
         end do
         call h5%close(err)
         if (err%failed()) return
      end if
      call lst%create_text(req%listing_file, 'listing', err)
      if (err%failed()) return
      call write_listing(lst, sc, store)
      call lst%commit(err)
   end subroutine write_results

   function var_columns(st) result(c)
      type(study_t), intent(in) :: st
      type(string_t), allocatable :: c(:)
      integer :: k
      allocate (c(0))
      do k = 1, size(st%vars)
         call append_string(c, st%vars(k)%column)
      end do
   end function var_columns

   function var_units(sc) result(u)
      type(study_case_t), intent(in) :: sc
      type(string_t), allocatable :: u(:)
      integer :: k
      allocate (u(0))
      do k = 1, size(sc%st%vars)
         associate (v => sc%st%vars(k))
            call append_string(u, trim(sc%deck%spec(v%gid)%field(v%k)%unit))
         end associate
      end do
   end function var_units

   function crit_units(st) result(u)
      type(study_t), intent(in) :: st
      type(string_t), allocatable :: u(:)
      integer :: k
      allocate (u(0))
      do k = 1, size(st%crits)
         call append_string(u, word_unit(st%crits(k)%word))
      end do
   end function crit_units

   function crit_columns(st) result(c)
      type(study_t), intent(in) :: st
      type(string_t), allocatable :: c(:)
      integer :: k
      allocate (c(0))
      do k = 1, size(st%crits)
         if (st%crits(k)%occupant > 1) then
            call append_string(c, word_column(st%crits(k)%word)//'_occ'//itoa(st%crits(k)%occupant))
         else
            call append_string(c, word_column(st%crits(k)%word))
         end if
      end do
   end function crit_columns

   !> The study's listing: what was varied and how each run was judged,
   !! the table of runs, the counts, the best run.
   subroutine write_listing(lst, sc, store)
      type(output_file_t), intent(inout) :: lst
      type(study_case_t), intent(in) :: sc
      type(row_store_t), intent(in) :: store
      type(run_row_t) :: row, best_row
      logical :: ok
      integer :: n_meet, n_status(4)
      character(len=:), allocatable :: line
      integer :: k, r, best, ko, n_cols, first, last, width
      type(string_t), allocatable :: vc(:), cc(:)
      !> the line printer's width; a column's least width
      integer, parameter :: line_width = 132, column_width = 13
      if (sc%st%analog) then
         call lst%put_line(' hsri2d '//hsri2d_version//'   STUDY (report C.8: the program varies its own inputs) '// &
                           'of the analog of section D')
      else
         call lst%put_line(' hsri2d '//hsri2d_version//'   STUDY (report C.8: the program varies its own inputs)')
      end if
      call lst%put_line(' TITLE   '//trim(title_of(sc%deck)))
      call lst%put_line(' METHOD  '//method_word(sc%st%method)//';  runs '//itoa(sc%n_runs))
      call lst%put_line('')
      call lst%put_line(' VARIED FIELDS (deck units; the deck''s own value)')
      do k = 1, size(sc%st%vars)
         call lst%put_line('   '//itoa(k)//'  '//sc%st%vars(k)%label//'  ('//sc%st%vars(k)%column//'),  '// &
                            'deck value '//num(sc%st%vars(k)%base))
      end do
      call lst%put_line('')
      call lst%put_line(' CRITERIA (a run meets the study''s limits when each is at most its limit)')
      do k = 1, size(sc%st%crits)
         if (sc%st%analog) then
            ! (Section D's criteria are of the two occupants together)
            line = '   '//pad(trim(sc%st%crits(k)%word), 9)//' both occupants  '//word_unit(sc%st%crits(k)%word)
         else
            line = '   '//pad(trim(sc%st%crits(k)%word), 9)//' occupant '//itoa(sc%st%crits(k)%occupant)//'  '// &
                   word_unit(sc%st%crits(k)%word)
         end if
         if (sc%st%crits(k)%has_limit) line = line//'   limit '//num(sc%st%crits(k)%limit)
         call lst%put_line(line)
      end do
      call lst%put_line('')
      call lst%put_line(' RUNS')
      vc = var_columns(sc%st)
      cc = crit_columns(sc%st)
      ! the varied fields, then the criteria, as many columns a panel as fit
      ! the line printer's 132 (a reason under its run, in the first panel)
      n_cols = size(vc) + size(cc)
      first = 1
      do while (first <= max(n_cols, 1))
         ! as many columns as fit, each as wide as its name or 13
         last = first
         width = 19 + 1 + col_width(first)
         do while (last < n_cols)
            if (width + 1 + col_width(last + 1) > line_width - 8) exit
            last = last + 1
            width = width + 1 + col_width(last)
         end do
         last = min(last, n_cols)
         line = '    run  status    '
         do k = first, last
            line = line//' '//rpad(column_name(k), col_width(k))
         end do
         if (last == n_cols) line = line//'  limits'
         call lst%put_line(line)
         do r = 1, store%n
            call store_get(store, sc, r, row, ok)
            if (.not. ok) then
               call lst%put_line(' '//rpad(itoa(r), 6)//'  (no result)')
               cycle
            end if
            line = ' '//rpad(itoa(r), 6)//'  '//pad(status_word(row%status), 9)
            do k = first, last
               line = line//' '//rpad(cell(row, k), col_width(k))
            end do
            if (last == n_cols) line = line//'  '//trim(merge('meets', 'no   ', row%meets))
            call lst%put_line(line)
            if (first == 1 .and. len(row%reason) > 0) call lst%put_line('          '//row%reason)
         end do
         first = last + 1
         if (first <= n_cols) call lst%put_line('')
      end do
      call lst%put_line('')
      ! the counts, and the best run within the limits (one pass over the rows)
      ko = objective_column(sc%st)
      n_status = 0
      n_meet = 0
      best = 0
      do r = 1, store%n
         call store_get(store, sc, r, row, ok)
         if (.not. ok) cycle
         if (row%status >= 1 .and. row%status <= 4) n_status(row%status) = n_status(row%status) + 1
         if (.not. row%meets) cycle
         n_meet = n_meet + 1
         if (ko == 0 .or. .not. allocated(row%crit)) cycle
         if (best == 0) then
            best = r
            best_row = row
         else if (row%crit(ko) < best_row%crit(ko)) then
            best = r
            best_row = row
         end if
      end do
      call lst%put_line(' SUMMARY  '//itoa(count(store%have(1:store%n)))//' of '//itoa(store%n)// &
                        ' runs have a result: '//itoa(n_status(status_completed))//' completed, '// &
                        itoa(n_status(status_ended))//' ended by an end test, '//itoa(n_status(status_failed))// &
                        ' failed, '//itoa(n_status(status_invalid))//' invalid; '//itoa(n_meet)//' meet the limits')
      call statistics_lines(lst, sc, store, cc)
      if (ko > 0) then
         if (best > 0) then
            line = ' BEST     run '//itoa(best)//': '//trim(sc%st%objective)//' = '//num(best_row%crit(ko), 6)// &
                   ' within the limits, at'
            do k = 1, size(vc)
               line = line//' '//vc(k)%s//' = '//num(best_row%x(k), 6)
            end do
            call lst%put_line(line)
         else
            call lst%put_line(' BEST     no run meets the limits')
         end if
      end if
      call lst%put_line(' TABLE    one row per run, every digit: results.csv in the results directory '// &
                         '(docs/modification.md)')
   contains
      pure integer function col_width(k)
         integer, intent(in) :: k
         col_width = max(column_width, len(column_name(k)) + 1)
      end function col_width

      !> Column k of the table: a varied field, then a criterion.
      pure function column_name(k) result(name)
         integer, intent(in) :: k
         character(len=:), allocatable :: name
         if (k <= size(vc)) then
            name = vc(k)%s
         else
            name = cc(k - size(vc))%s
         end if
      end function column_name

      function cell(row, k) result(text)
         type(run_row_t), intent(in) :: row
         integer, intent(in) :: k
         character(len=:), allocatable :: text
         text = '-'
         if (k <= size(vc)) then
            text = num(row%x(k), 6)
         else if (allocated(row%crit)) then
            text = num(row%crit(k - size(vc)), 6)
            ! a criterion without a value (TMEET of an analog run whose
            ! occupants never meet)
            if (ieee_is_nan(row%crit(k - size(vc)))) text = 'none'
         end if
      end function cell

   end subroutine write_listing

   !> Each criterion's count, mean, standard deviation and range over the
   !! runs that have criteria (completed, or ended by an end test) and a
   !! value of it (TMEET has none where the analog's occupants never meet):
   !! with ENSEMBLE, how robust each output is to the inputs' small changes.
   subroutine statistics_lines(lst, sc, store, cc)
      type(output_file_t), intent(inout) :: lst
      type(study_case_t), intent(in) :: sc
      type(row_store_t), intent(in) :: store
      type(string_t), intent(in) :: cc(:)
      type(run_row_t) :: row
      logical :: ok
      real(wp) :: mean(size(cc)), m2(size(cc)), lo(size(cc)), hi(size(cc)), delta
      integer :: k, r, n(size(cc))
      if (size(cc) == 0) return
      ! one pass over the rows (Welford's running mean and sum of squares)
      n = 0
      mean = 0.0_wp
      m2 = 0.0_wp
      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      do r = 1, store%n
         call store_get(store, sc, r, row, ok)
         if (.not. ok) cycle
         if (.not. allocated(row%crit)) cycle
         do k = 1, size(cc)
            if (ieee_is_nan(row%crit(k))) cycle
            n(k) = n(k) + 1
            delta = row%crit(k) - mean(k)
            mean(k) = mean(k) + delta/n(k)
            m2(k) = m2(k) + delta*(row%crit(k) - mean(k))
            lo(k) = min(lo(k), row%crit(k))
            hi(k) = max(hi(k), row%crit(k))
         end do
      end do
      call lst%put_line(' STATISTICS over the runs with criteria (completed or ended; standard deviation '// &
                        'with n - 1)')
      call lst%put_line('   criterion          runs          mean     std. dev.       least     largest')
      do k = 1, size(cc)
         if (n(k) == 0) then
            call lst%put_line('   '//pad(cc(k)%s, 13)//rpad('0', 9))
            cycle
         end if
         call lst%put_line('   '//pad(cc(k)%s, 13)//rpad(itoa(n(k)), 9)//' '//rpad(num(mean(k), 6), 13)//' '// &
                           rpad(num(sqrt(m2(k)/max(n(k) - 1, 1)), 6), 13)//' '//rpad(num(lo(k), 6), 11)//' '// &
                           rpad(num(hi(k), 6), 11))
      end do
   end subroutine statistics_lines

   ! --- small helpers -----------------------------------------------------

   !> The occupants of model m's system.
   integer function occupants_of(m) result(n)
      type(model_t), intent(in) :: m
      type(crash_system_t), allocatable :: sys
      allocate (sys)
      call system_build(m, sys)
      n = size(sys%occupants)
   end function occupants_of

   function missing_list(have) result(s)
      logical, intent(in) :: have(:)
      character(len=:), allocatable :: s
      integer :: r, n
      s = ''
      n = 0
      do r = 1, size(have)
         if (have(r)) cycle
         n = n + 1
         if (n > 20) then
            s = s//', ...'
            return
         end if
         if (n > 1) s = s//', '
         s = s//'run '//itoa(r)
      end do
   end function missing_list

   real(wp) function cpu_now()
      call cpu_time(cpu_now)
   end function cpu_now

   !> The deck's card images, one line each (the identity of a study).
   function study_text(d) result(text)
      type(deck_t), intent(in) :: d
      character(len=:), allocatable :: text
      integer :: k
      text = ''
      do k = 1, d%n_echo
         text = text//d%echo(k)%text//new_line('a')
      end do
   end function study_text

   subroutine put_text(f, text)
      type(output_file_t), intent(inout) :: f
      character(len=*), intent(in) :: text
      integer :: a, b
      a = 1
      do while (a <= len(text))
         b = index(text(a:), new_line('a'))
         if (b == 0) then
            call f%put_line(text(a:))
            return
         end if
         call f%put_line(text(a:a + b - 2))
         a = a + b
      end do
   end subroutine put_text

   function title_of(d) result(t)
      type(deck_t), intent(in) :: d
      character(len=:), allocatable :: t
      t = ''
      if (d%group(1)%n > 0) then
         if (allocated(d%group(1)%card(1)%text)) t = d%group(1)%card(1)%text
      end if
   end function title_of

   pure function pad(s, w) result(t)
      character(len=*), intent(in) :: s
      integer, intent(in) :: w
      character(len=:), allocatable :: t
      t = s//repeat(' ', max(0, w - len(s)))
   end function pad

   pure function rpad(s, w) result(t)
      character(len=*), intent(in) :: s
      integer, intent(in) :: w
      character(len=:), allocatable :: t
      t = repeat(' ', max(0, w - len(s)))//s
   end function rpad
end module study_driver
