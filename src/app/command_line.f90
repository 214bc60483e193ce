!> The command line of hsri2d (docs/usage.md).
module command_line
   use error_handling, only: error_t, error_set, exit_usage
   use run_case_mod, only: builtin_deck_name
   use text_io, only: string_t, append_string, standard_input_path
   implicit none
   private

   public :: options_t, parse_command_line, usage_text


   type :: options_t
      type(string_t), allocatable :: decks(:)
      character(len=:), allocatable :: listing_file   !< '' = standard output
      character(len=:), allocatable :: h5_file        !< '' = none
      character(len=:), allocatable :: mme_dir        !< --mme DIR: the run as an ISO-MME data set ('' = none)
      logical :: help = .false., version = .false.
      logical :: deck_format = .false., print_default_deck = .false., check_only = .false.
      logical :: outputs = .false.
      logical :: refine = .false.   !< --refine: the convergence check (issue 16)
      !> a study (C.8; docs/modification.md)
      character(len=:), allocatable :: results_dir   !< --results DIR ('' = none)
      integer :: jobs = 1                            !< --jobs N
      integer :: shard = 0, n_shards = 0             !< --shard K/N
      logical :: collect = .false., study_size = .false.
   end type options_t

contains

   subroutine parse_command_line(opts, err)
      type(options_t), intent(out) :: opts
      type(error_t), intent(inout) :: err
      integer :: i, n, ios, slash
      character(len=:), allocatable :: arg
      logical :: options_done, stdin_named, listing_named, h5_named, results_named, ok, mme_named
      character(len=:), allocatable :: text

      allocate (opts%decks(0))
      opts%listing_file = ''
      opts%h5_file = ''
      opts%mme_dir = ''
      mme_named = .false.
      opts%results_dir = ''
      results_named = .false.
      options_done = .false.
      stdin_named = .false.
      listing_named = .false.
      h5_named = .false.
      n = command_argument_count()
      i = 0
      do while (i < n)
         i = i + 1
         arg = argument(i)
         if (arg == standard_input_path .and. len(arg) == len(standard_input_path)) then
            ! a lone '-' is standard input, after '--' too (a file named '-' is ./-);
            ! it can be read once only
            if (stdin_named) then
               call error_set(err, exit_usage, 'standard input ('//standard_input_path &
                  //') may be named only once')
               return
            end if
            stdin_named = .true.
            call append_string(opts%decks, arg)
            cycle
         end if
         if (options_done .or. len(arg) == 0) then
            call append_string(opts%decks, arg)
            cycle
         end if
         if (arg(1:1) /= '-') then
            call append_string(opts%decks, arg)
            cycle
         end if
         select case (arg)
         case ('-h', '--help')
            opts%help = .true.
         case ('-V', '--version')
            opts%version = .true.
         case ('--deck-format')
            opts%deck_format = .true.
         case ('--default-deck')
            opts%print_default_deck = .true.
         case ('--check')
            opts%check_only = .true.
         case ('--outputs')
            opts%outputs = .true.
         case ('--refine')
            opts%refine = .true.
         case ('-o', '--output')
            if (.not. value_of(opts%listing_file, listing_named, 'the listing file (-o, --output)')) return
            ! '-' is standard output, where the listing goes without -o
            if (opts%listing_file == standard_input_path .and. len(opts%listing_file) == 1) opts%listing_file = ''
         case ('--h5')
            if (.not. value_of(opts%h5_file, h5_named, 'the HDF5 file (--h5)')) return
            if (opts%h5_file == standard_input_path .and. len(opts%h5_file) == 1) then
               call error_set(err, exit_usage, 'option --h5 needs a file: an HDF5 file cannot be written to ' &
                              //'standard output (-)')
               return
            end if
         case ('--mme')
            if (.not. value_of(opts%mme_dir, mme_named, 'the ISO-MME data set''s folder (--mme)')) return
         case ('--results')
            if (.not. value_of(opts%results_dir, results_named, 'the results directory (--results)')) return
         case ('--jobs')
            text = ''
            ok = i < n
            if (ok) then
               i = i + 1
               text = argument(i)
               read (text, *, iostat=ios) opts%jobs
               ok = ios == 0 .and. verify(text, '0123456789') == 0 .and. len(text) > 0 .and. len(text) <= 4
               if (ok) ok = opts%jobs >= 1
            end if
            if (.not. ok) then
               call error_set(err, exit_usage, 'option --jobs needs a number of worker processes from 1 to 9999; '// &
                              'found "'//text//'"')
               return
            end if
         case ('--shard')
            text = ''
            ok = i < n
            if (ok) then
               i = i + 1
               text = argument(i)
               slash = index(text, '/')
               ok = slash > 1 .and. slash < len(text)
               if (ok) ok = verify(text(1:slash - 1), '0123456789') == 0 .and. &
                            verify(text(slash + 1:), '0123456789') == 0 .and. len(text) <= 19
               if (ok) then
                  read (text(1:slash - 1), *, iostat=ios) opts%shard
                  if (ios == 0) read (text(slash + 1:), *, iostat=ios) opts%n_shards
                  ok = ios == 0
               end if
               if (ok) ok = opts%n_shards >= 1 .and. opts%shard >= 1 .and. opts%shard <= opts%n_shards
            end if
            if (.not. ok) then
               call error_set(err, exit_usage, 'option --shard needs K/N, slice K of N (1 <= K <= N), e.g. '// &
                              '--shard 3/20; found "'//text//'"')
               return
            end if
         case ('--collect')
            opts%collect = .true.
         case ('--study-size')
            opts%study_size = .true.
         case ('--')
            options_done = .true.
         case default
            call error_set(err, exit_usage, 'unknown option "'//arg//'"; try hsri2d --help')
            return
         end select
      end do
      if (.not. (opts%help .or. opts%version)) call check_combination(opts, h5_named, err)
      if (.not. (opts%help .or. opts%version .or. err%failed()) .and. mme_named .and. &
          (opts%deck_format .or. opts%print_default_deck .or. opts%outputs .or. opts%refine .or. opts%collect .or. &
           opts%study_size .or. opts%n_shards > 0 .or. len(opts%results_dir) > 0 .or. opts%jobs > 1)) &
         call error_set(err, exit_usage, 'only a run of a deck writes an ISO-MME data set; --mme would be ignored')
   contains
      !> The value of option `arg`, which names `what` once only (`named`:
      !! whether it was named already).
      logical function value_of(target, named, what)
         character(len=:), allocatable, intent(inout) :: target
         logical, intent(inout) :: named
         character(len=*), intent(in) :: what
         value_of = .not. named
         if (.not. value_of) then
            call error_set(err, exit_usage, what//' is named twice; name it once')
            return
         end if
         named = .true.
         value_of = i < n
         if (.not. value_of) then
            call error_set(err, exit_usage, 'option '//arg//' needs a file name')
            return
         end if
         i = i + 1
         target = argument(i)
         if (len(target) == 0) then
            call error_set(err, exit_usage, 'option '//arg//' needs a non-empty file name')
            value_of = .false.
         end if
      end function value_of
   end subroutine parse_command_line

   !> Options that cannot go together, or would be ignored (docs/usage.md,
   !! "The command line"): one of --deck-format, --default-deck, --outputs,
   !! --check at most; no deck for the first two; no --h5 but with a run or
   !! --check. (--help and --version print and ignore the rest.)
   subroutine check_combination(opts, h5_named, err)
      type(options_t), intent(in) :: opts
      logical, intent(in) :: h5_named
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: mode, other
      mode = ''
      other = ''
      call take(opts%deck_format, '--deck-format')
      call take(opts%print_default_deck, '--default-deck')
      call take(opts%outputs, '--outputs')
      call take(opts%check_only, '--check')
      call take(opts%refine, '--refine')
      call take(opts%collect, '--collect')
      call take(opts%study_size, '--study-size')
      call take(opts%n_shards > 0, '--shard')
      if (len(other) > 0) then
         call error_set(err, exit_usage, mode//' and '//other//' cannot go together; give one of them')
      else if ((opts%deck_format .or. opts%print_default_deck) .and. size(opts%decks) > 0) then
         call error_set(err, exit_usage, mode//' reads no deck; "'//opts%decks(1)%s//'" would be ignored')
      else if (h5_named .and. (opts%deck_format .or. opts%print_default_deck .or. opts%outputs .or. opts%refine)) then
         call error_set(err, exit_usage, mode//' writes no HDF5 file; --h5 would be ignored')
      else if (opts%jobs > 1 .and. len(mode) > 0 .and. mode /= '--shard') then
         call error_set(err, exit_usage, mode//' runs no study''s runs; --jobs would be ignored')
      else if (h5_named .and. (opts%study_size .or. opts%n_shards > 0)) then
         call error_set(err, exit_usage, mode//' writes no HDF5 file (the study''s is written by the run of the '// &
                        'whole study or --collect); --h5 would be ignored')
      end if
   contains
      subroutine take(given, name)
         logical, intent(in) :: given
         character(len=*), intent(in) :: name
         if (.not. given) return
         if (len(mode) == 0) then
            mode = name
         else if (len(other) == 0) then
            other = name
         end if
      end subroutine take
   end subroutine check_combination

   function argument(i) result(arg)
      integer, intent(in) :: i
      character(len=:), allocatable :: arg
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      if (length > 0) call get_command_argument(i, arg)
   end function argument

   function usage_text() result(s)
      character(len=:), allocatable :: s
      character(len=1), parameter :: nl = new_line('a')
      s = 'usage: hsri2d [options] [DECK ...]'//nl//nl// &
          'Runs the HSRI phase-two two-dimensional crash-victim simulation on card decks.'//nl// &
          'With no DECK, runs the built-in default deck. Several decks are read in order;'//nl// &
          'a later card group replaces the earlier group of its kind. The name '//builtin_deck_name//nl// &
          'stands for the built-in default deck (e.g. hsri2d '//builtin_deck_name//' pulse.deck),'//nl// &
          'and '//standard_input_path//' for standard input (e.g. make-deck | hsri2d '//standard_input_path//').'//nl//nl// &
          'options:'//nl// &
          '  -o, --output FILE   write the listing (or what --outputs, --refine, --deck-format'//nl// &
          '                      or --default-deck print) to FILE; - or no -o: standard output'//nl// &
          '  --h5 FILE           write the time histories to the HDF5 file FILE'//nl// &
          '  --mme DIR           write the run as an ISO-MME data set DIR/<DIR''s name>.mme'//nl// &
          '  --check             read and check the decks (and that -o and --h5 would not'//nl// &
          '                      overwrite an input), run nothing, write nothing'//nl// &
          '  --outputs           print the output series the decks would write (HDF5 datasets, '//nl// &
          '                      listing tables) and exit'//nl// &
          '  --refine            run the decks at their step or tolerance and at a refined'//nl// &
          '                      one (DT/2, or RTOL/100) and print how far each criterion,'//nl// &
          '                      peak and angle moved, with a verdict; writes nothing else'//nl// &
          '  --deck-format       print the card reference (docs/deck-format.md) and exit'//nl// &
          nl//'a study (a deck with *STUDY, report C.8; docs/modification.md):'//nl// &
          '  --results DIR       keep each run''s result in DIR (made if missing) and the table'//nl// &
          '                      in DIR/results.csv; running again resumes the study'//nl// &
          '  --jobs N            run the study''s runs on N worker processes (needs --results)'//nl// &
          '  --shard K/N         run slice K of N of the runs (a job array; needs --results)'//nl// &
          '  --collect           merge the rows in DIR into the table and the listing; run nothing'//nl// &
          '  --h5 FILE           (a study) the table in FILE''s /study'//nl// &
          '  --study-size        print the number of runs of the study and exit'//nl//nl// &
          '  --default-deck      print the built-in default deck and exit'//nl// &
          '  -V, --version       print the version and exit'//nl// &
          '  -h, --help          print this help and exit'//nl//nl// &
          'exit status: 0 success, 1 bad command line, 2 deck error, 3 numerical failure,'//nl// &
          '             4 input/output error, 5 a study with runs missing or none that succeeded'
   end function usage_text
end module command_line
