!> hsri2d: read card decks, run the simulation, write the listing (and
!! the HDF5 time histories). The only place that prints errors and chooses
!! the exit status (docs/usage.md).
program hsri2d
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use error_handling, only: error_t, error_set, exit_ok, exit_usage, exit_deck, exit_numerical, error_category_name
   use text_io, only: string_t
   use command_line, only: options_t, parse_command_line, usage_text
   use deck_doc, only: deck_format_lines
   use default_deck, only: default_deck_lines
   use run_case_mod, only: run_request_t, run_case, describe_outputs, refine_case
   use output_files, only: output_file_t
   use posix_files, only: posix_ignore_output_signals
   use version_info, only: hsri2d_version
   use strings, only: itoa
   use posix_processes, only: posix_is_terminal
   use study_progress, only: show_progress
   use study_driver, only: study_request_t, run_study, study_size, deck_has_study
   implicit none

   interface
      !> C's exit(): ends with a status and no message (Fortran STOP prints one).
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   type(options_t) :: opts
   type(run_request_t) :: req
   type(error_t) :: err
   type(string_t), allocatable :: builtin(:), warnings(:)
   type(study_request_t) :: study
   integer :: ignore, i, ios, n_runs
   logical :: is_study

   ! A file-size limit (ulimit -f) or a pipe closed by its reader (hsri2d |
   ! head) then makes writes fail with an error that is reported (exit
   ! status 4, temporary files removed) instead of killing the program.
   ignore = posix_ignore_output_signals()

   call parse_command_line(opts, err)
   if (err%failed()) call quit(err)
   ! --help and --version print on standard output whatever else is given
   if (opts%help) then
      call say([string_t(usage_text())], '')
      call finish(exit_ok)
   end if
   if (opts%version) then
      call say([string_t('hsri2d '//hsri2d_version)], '')
      call finish(exit_ok)
   end if
   if (opts%deck_format) then
      call say(deck_format_lines(), opts%listing_file)
      call finish(exit_ok)
   end if
   builtin = default_deck_lines()
   if (opts%print_default_deck) then
      call say(builtin, opts%listing_file)
      call finish(exit_ok)
   end if

   ! C.1-C.7: the whole case is one library call
   req%decks = opts%decks
   req%listing_file = opts%listing_file
   req%h5_file = opts%h5_file
   req%mme_dir = opts%mme_dir
   req%check_only = opts%check_only
   if (opts%outputs) then
      call describe_outputs(req, builtin, err)
      if (err%failed()) call quit(err)
      call say(builtin, opts%listing_file)
      call finish(exit_ok)
   end if
   if (opts%refine) then
      ! issue 16: the convergence check, a table on standard output (or -o)
      call refine_case(req, builtin, err)
      if (err%failed()) call quit(err)
      call say(builtin, opts%listing_file)
      call finish(exit_ok)
   end if
   ! C.8: a deck with *STUDY (or a study's option) runs a study
   is_study = deck_has_study(opts%decks)
   if (opts%collect .or. opts%study_size .or. opts%n_shards > 0 .or. len(opts%results_dir) > 0 .or. &
       opts%jobs > 1 .or. is_study) then
      if (len(opts%mme_dir) > 0) then
         call error_set(err, exit_usage, 'a study writes no ISO-MME data set (each run''s outputs: *STUDY''s KEEP); ' &
                        //'--mme would be ignored')
         call quit(err)
      end if
      study%decks = opts%decks
      study%listing_file = opts%listing_file
      study%results_dir = opts%results_dir
      study%h5_file = opts%h5_file
      study%jobs = opts%jobs
      study%shard = opts%shard
      study%n_shards = opts%n_shards
      study%collect = opts%collect
      study%program = '/proc/self/exe'
      if (opts%study_size) then
         call study_size(study, n_runs, err)
         if (err%failed()) call quit(err)
         call say([string_t(itoa(n_runs))], opts%listing_file)
         call finish(exit_ok)
      end if
      if (opts%check_only) then
         call study_size(study, n_runs, err)
         if (err%failed()) call quit(err)
         call say([string_t('hsri2d: the study deck is valid ('//itoa(n_runs)//' runs)')], '')
         call finish(exit_ok)
      end if
      if (posix_is_terminal(2)) then
         call run_study(study, err, show_progress)
         write (error_unit, '(a)', iostat=ios) ''
      else
         call run_study(study, err)
      end if
      if (err%failed()) call quit(err)
      call finish(exit_ok)
   end if
   call run_case(req, err, warnings=warnings)
   do i = 1, size(warnings)
      write (error_unit, '(a)', iostat=ios) 'hsri2d: warning: '//warnings(i)%s
   end do
   if (err%failed()) call quit(err)
   if (opts%check_only) call say([string_t('hsri2d: the deck is valid')], '')
   call finish(exit_ok)

contains

   !> Lines to `path` ('' = standard output) as the listing would be
   !! written there (docs/usage.md, "Output files"), every write checked
   !! (Fortran's own writes to standard output do not report a full disk or
   !! a closed pipe).
   subroutine say(lines, path)
      type(string_t), intent(in) :: lines(:)
      character(len=*), intent(in) :: path
      type(output_file_t) :: out
      type(error_t) :: e
      integer :: k
      call out%create_text(path, 'output', e)
      if (e%failed()) call quit(e)
      do k = 1, size(lines)
         call out%put_line(lines(k)%s)
      end do
      call out%commit(e)
      if (e%failed()) call quit(e)
   end subroutine say

   !> Print an error report on standard error and exit with its status
   !! (iostat: a standard error that cannot be written must not turn into
   !! a runtime error and another status).
   subroutine quit(e)
      type(error_t), intent(in) :: e
      integer :: code, ios
      code = e%code
      write (error_unit, '(a)', iostat=ios) 'hsri2d: '//error_category_name(code)//':'
      write (error_unit, '(a)', iostat=ios) e%message
      if (code == exit_deck) write (error_unit, '(a)', iostat=ios) 'hsri2d: see docs/deck-format.md or hsri2d --deck-format'
      if (code == exit_numerical) write (error_unit, '(a)', iostat=ios) 'hsri2d: the listing holds the run up to the failure'
      call finish(code)
   end subroutine quit

   subroutine finish(code)
      integer, intent(in) :: code
      integer :: ios
      ! iostat: a failure here must not become a runtime error message.
      flush (output_unit, iostat=ios)
      flush (error_unit, iostat=ios)
      call c_exit(int(code, c_int))
   end subroutine finish
end program hsri2d
