!> Issue 15, section 4: the hard cases' harness. A case is a list of deck
!! files (a shipped deck and override decks of tests/hard, later groups
!! replacing earlier ones, as on the command line); it is run as a user
!! runs it (run_case: listing and all) under each integrator (NINT 1
!! Adams-Moulton, 2 RK4, 3 Dormand-Prince) at two settings (the fixed
!! steps DT and DT/2, or the case's; Dormand-Prince at RTOL 1e-6 and 1e-8),
!! and it must:
!!
!! - end with status 0 (or, where the case allows it, fail cleanly: status
!!   3, the time and the cause named, the listing kept);
!! - print no NaN, Inf or asterisks in its listing (the deck's echo aside);
!! - keep its energy balance within 0.5 % of the largest body kinetic
!!   energy (at the print times, as the listing checks it);
!! - agree between the two settings: HIC15, the head's and chest's peak
!!   accelerations and the effects' largest forces (those above 5 % of the
!!   run's largest) within 2 %, the joint angles' extremes within the
!!   case's tolerance in degrees (default 0.5, docs/accuracy.md's order).
!!
!! A case whose fixed step is too large on purpose (large_dt) may instead
!! end cleanly with status 3 or say in its listing that its error exceeds
!! the thresholds (docs/accuracy.md): never be silently wrong.
!!
!! The environment variable HSRI2D_HARD_LOCATION=off runs every case with
!! the switches left unlocated (model_t%options%locate_switches), to show
!! what location buys (docs/validation.md, "Hard cases"); each run prints
!! its figures on standard output either way.
module hard_cases
   use, intrinsic :: iso_fortran_env, only: output_unit
   use kinds, only: wp, g_std
   use error_handling, only: error_t, exit_ok, exit_numerical
   use text_io, only: string_t
   use run_case_mod, only: run_request_t, run_case, read_case_deck
   use deck_reader, only: deck_t
   use model, only: model_t, nint_adams, nint_rk4, nint_dopri
   use run_summary, only: run_summary_t
   use acceleration_criteria, only: hic_result_t
   implicit none
   private

   public :: hard_case_t, hard_case, hard_check

   real(wp), parameter :: deg = 57.295779513082321_wp
   real(wp), parameter :: energy_tol = 0.005_wp     !< of the largest body kinetic energy
   real(wp), parameter :: peak_tol = 0.02_wp        !< HIC and peaks between the two settings
   real(wp), parameter :: force_floor = 0.05_wp     !< forces compared: above this of the largest

   type :: hard_case_t
      character(len=:), allocatable :: name
      type(string_t), allocatable :: decks(:)   !< relative to the project's directory
      real(wp) :: t_max = 0.0_wp                !< 0: the deck's
      real(wp) :: dt_print = 0.0_wp             !< 0: the deck's
      real(wp) :: dt(2) = 0.0_wp                !< the fixed steps; 0: the deck's DT and DT/2
      real(wp) :: rtol(2) = [1.0e-6_wp, 1.0e-8_wp]
      real(wp) :: angle_tol = 0.5_wp            !< deg, the joint angles' extremes
      !> a step too large on purpose: a fixed-step run may end with status 3
      !! or warn of its error instead of agreeing
      logical :: large_step = .false.
   end type hard_case_t

   !> What one run gave.
   type :: outcome_t
      integer :: status = exit_ok
      character(len=:), allocatable :: message
      logical :: warned = .false.              !< the listing warns of the estimated error
      character(len=:), allocatable :: listing_problem
      real(wp) :: t_end = 0.0_wp
      real(wp) :: energy = 0.0_wp              !< largest balance error / largest kinetic energy
      integer :: n_q = 0
      character(len=24), allocatable :: q_name(:)
      real(wp), allocatable :: q(:)
      logical, allocatable :: q_angle(:), q_force(:)
   end type outcome_t

contains

   !> A case of the deck files `decks` (relative to the project's directory).
   function hard_case(name, decks) result(c)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: decks(:)
      type(hard_case_t) :: c
      integer :: k
      c%name = name
      allocate (c%decks(size(decks)))
      do k = 1, size(decks)
         c%decks(k)%s = trim(decks(k))
      end do
   end function hard_case

   !> Run case c under each integrator at its two settings; failures:
   !! what went wrong, one line each (none: the case holds).
   subroutine hard_check(c, failures)
      type(hard_case_t), intent(in) :: c
      character(len=:), allocatable, intent(out) :: failures
      type(outcome_t) :: out(2)
      type(model_t) :: m
      type(run_request_t) :: req
      type(deck_t) :: deck
      type(error_t) :: err
      character(len=4096) :: root, location
      character(len=:), allocatable :: settings, tag
      integer :: nint, s, k, length, status
      real(wp) :: dt(2), t_max, dt_print
      failures = ''
      call get_environment_variable('HSRI2D_SOURCE_DIR', root, length, status)
      if (status /= 0) root = '../../..'    ! (from build/<config>/tests)
      call get_environment_variable('HSRI2D_HARD_LOCATION', location, length, status)
      if (status /= 0) location = 'on'
      allocate (req%decks(size(c%decks)))
      do k = 1, size(c%decks)
         req%decks(k)%s = trim(root)//'/'//c%decks(k)%s
      end do
      req%h5_file = ''
      req%locate_switches = trim(location) /= 'off'
      ! the case's own options and time controls, then its settings after them
      call read_case_deck(req, deck, m, err)
      if (err%failed()) then
         failures = c%name//': its decks do not read: '//err%message
         return
      end if
      req%decks = [req%decks, string_t('hard_'//c%name//'_settings.deck')]
      t_max = merge(c%t_max, m%time%t_max, c%t_max > 0.0_wp)
      dt_print = merge(c%dt_print, m%time%dt_print, c%dt_print > 0.0_wp)
      dt = c%dt
      if (dt(1) <= 0.0_wp) dt = [m%time%dt, 0.5_wp*m%time%dt]
      do nint = nint_adams, nint_dopri
         do s = 1, 2
            if (nint == nint_dopri) then
               settings = 'RTOL '//real_text(c%rtol(s))
            else
               settings = 'DT '//real_text(dt(s))
            end if
            tag = c%name//' NINT '//int_text(nint)//' '//settings
            call write_settings(req%decks(size(req%decks))%s, m, nint, t_max, merge(m%time%dt, dt(s), &
                                nint == nint_dopri), dt_print, c%rtol(s), err)
            if (err%failed()) then
               call add(failures, tag//': '//err%message)
               return
            end if
            req%listing_file = 'hard_'//c%name//'_'//int_text(nint)//'_'//int_text(s)//'.lst'
            call run_one(req, out(s))
            call report(tag, trim(location), out(s))
            call check_run(c, nint, tag, out(s), failures)
         end do
         call compare(c, nint, c%name//' NINT '//int_text(nint), out, failures)
      end do
   end subroutine hard_check

   !> The override deck of one setting: *OPTIONS with NINT, *TIME.
   subroutine write_settings(path, m, nint, t_max, dt, dt_print, rtol, err)
      character(len=*), intent(in) :: path
      type(model_t), intent(in) :: m
      integer, intent(in) :: nint
      real(wp), intent(in) :: t_max, dt, dt_print, rtol
      type(error_t), intent(inout) :: err
      integer :: unit, ios
      open (newunit=unit, file=path, status='replace', action='write', iostat=ios)
      if (ios == 0) write (unit, '(a/2x,6i10)', iostat=ios) '*OPTIONS', m%options%nbody, m%options%nbelt, &
         m%options%nend, m%options%nload, m%options%nout, nint
      if (ios == 0) write (unit, '(a/2x,3es10.3,es10.3,i10,2es10.3)', iostat=ios) '*TIME', t_max, dt, dt_print, &
         m%time%corrector_tol, m%time%corrector_max_iter, rtol, 1.0e-2_wp*rtol   ! (ATOL: the decks' ratio)
      if (ios == 0) close (unit, iostat=ios)
      if (ios /= 0) then
         err%code = 4
         err%message = path//': cannot be written'
      end if
   end subroutine write_settings

   !> One run as the program makes it, and what its summary and listing say.
   subroutine run_one(req, out)
      type(run_request_t), intent(in) :: req
      type(outcome_t), intent(out) :: out
      type(error_t) :: err
      type(run_summary_t) :: res
      type(string_t), allocatable :: warnings(:)
      type(hic_result_t) :: hic
      integer :: o, k, n
      call run_case(req, err, res, warnings)
      out%status = err%code
      out%message = err%message
      out%t_end = res%t_end
      call read_listing(req%listing_file, out)
      if (.not. allocated(res%occ)) return
      n = 0
      do o = 1, size(res%occ)
         n = n + 3 + 2*size(res%occ(o)%joint_min) + size(res%occ(o)%peaks)
      end do
      allocate (out%q_name(n), out%q(n), out%q_angle(n), out%q_force(n))
      out%q_angle = .false.
      out%q_force = .false.
      do o = 1, size(res%occ)
         associate (r => res%occ(o))
            if (r%ke_max > 0.0_wp) out%energy = max(out%energy, abs(r%energy_error_max%value)/r%ke_max)
            hic = r%head_criteria%hic15()
            call put(out, 'HIC15', hic%value)
            call put(out, 'head peak (g)', r%head_max%value/g_std)
            call put(out, 'chest peak (g)', r%chest_max%value/g_std)
            do k = 1, size(r%joint_min)
               call put(out, 'joint '//int_text(k)//' min (deg)', r%joint_min(k)%value*deg, angle=.true.)
               call put(out, 'joint '//int_text(k)//' max (deg)', r%joint_max(k)%value*deg, angle=.true.)
            end do
            do k = 1, size(r%peaks)
               ! (the forces; where a pair was struck and how deep are not peaks)
               if (r%peaks(k)%unit == 'lb') call put(out, trim(r%peaks(k)%name), r%peaks(k)%value, force=.true.)
            end do
         end associate
      end do
   end subroutine run_one

   subroutine put(out, name, value, angle, force)
      type(outcome_t), intent(inout) :: out
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: value
      logical, intent(in), optional :: angle, force
      out%n_q = out%n_q + 1
      out%q_name(out%n_q) = name
      out%q(out%n_q) = value
      if (present(angle)) out%q_angle(out%n_q) = angle
      if (present(force)) out%q_force(out%n_q) = force
   end subroutine put

   !> The listing's problems: NaN, Inf or asterisks outside the deck's
   !! echo (which shows the cards as written); whether it warns of the
   !! estimated error of a fixed step.
   subroutine read_listing(path, out)
      character(len=*), intent(in) :: path
      type(outcome_t), intent(inout) :: out
      character(len=2000) :: line
      integer :: unit, ios, number
      logical :: in_echo
      out%listing_problem = ''
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         out%listing_problem = path//': no listing'
         return
      end if
      in_echo = .false.
      number = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         number = number + 1
         if (line(1:1) == achar(12)) line = line(2:)
         if (index(line, 'INPUT DECK') == 1) in_echo = .true.
         if (index(line, 'PARAMETERS') == 1 .or. index(line, 'RUN') == 1) in_echo = .false.
         if (index(line, 'WARNING: the estimated error') > 0 .or. index(line, 'WARNING: the fixed step widened') > 0) &
            out%warned = .true.
         if (in_echo .or. len(out%listing_problem) > 0) cycle
         if (index(line, '**') > 0 .or. has_word(line, 'NaN') .or. has_word(line, 'nan') .or. &
             has_word(line, 'Inf') .or. has_word(line, 'Infinity')) &
            out%listing_problem = path//':'//int_text(number)//': '//trim(line(1:100))
      end do
      close (unit)
   end subroutine read_listing

   !> word stands alone in line (not inside a longer word).
   pure logical function has_word(line, word)
      character(len=*), intent(in) :: line, word
      integer :: at, from
      has_word = .false.
      from = 1
      do
         at = index(line(from:), word)
         if (at == 0) return
         at = at + from - 1
         if (.not. letter_at(line, at - 1) .and. .not. letter_at(line, at + len(word))) then
            has_word = .true.
            return
         end if
         from = at + 1
      end do
   end function has_word

   pure logical function letter_at(line, k)
      character(len=*), intent(in) :: line
      integer, intent(in) :: k
      letter_at = .false.
      if (k < 1 .or. k > len(line)) return
      letter_at = verify(line(k:k), 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ') == 0
   end function letter_at

   !> The run's status, listing and energy balance.
   subroutine check_run(c, nint, tag, out, failures)
      type(hard_case_t), intent(in) :: c
      integer, intent(in) :: nint
      character(len=*), intent(in) :: tag
      type(outcome_t), intent(in) :: out
      character(len=:), allocatable, intent(inout) :: failures
      logical :: clean
      if (len(out%listing_problem) > 0) call add(failures, tag//': '//out%listing_problem)
      if (out%status == exit_numerical) then
         ! a clean failure: when and why said, the listing kept and saying when it ended
         clean = index(out%message, 't =') > 0 .and. len(out%listing_problem) == 0 .and. out%n_q > 0
         if (.not. clean) call add(failures, tag//': status 3, not a clean failure: '//out%message)
         if (.not. (c%large_step .and. nint /= nint_dopri)) &
            call add(failures, tag//': ended with status 3 at t = '//real_text(out%t_end)//': '//first_line(out%message))
         return
      else if (out%status /= exit_ok) then
         call add(failures, tag//': status '//int_text(out%status)//': '//first_line(out%message))
         return
      end if
      if (out%energy > energy_tol) call add(failures, tag//': energy balance error '// &
                                            real_text(100*out%energy)//' % of the largest kinetic energy')
   end subroutine check_run

   !> The two settings' HIC and peaks.
   subroutine compare(c, nint, tag, out, failures)
      type(hard_case_t), intent(in) :: c
      integer, intent(in) :: nint
      character(len=*), intent(in) :: tag
      type(outcome_t), intent(in) :: out(2)
      character(len=:), allocatable, intent(inout) :: failures
      real(wp) :: largest, worst_angle, worst_rel, d, a, b
      character(len=24) :: angle_name, rel_name
      character(len=:), allocatable :: problems
      integer :: k
      if (any(out%status /= exit_ok)) return
      largest = 0.0_wp
      do k = 1, out(1)%n_q
         if (out(1)%q_force(k)) largest = max(largest, abs(out(1)%q(k)), abs(other(k)))
      end do
      worst_angle = 0.0_wp
      worst_rel = 0.0_wp
      angle_name = '-'
      rel_name = '-'
      problems = ''
      do k = 1, out(1)%n_q
         a = out(1)%q(k)
         b = other(k)
         if (out(1)%q_angle(k)) then
            d = abs(a - b)
            if (d > worst_angle) then
               worst_angle = d
               angle_name = out(1)%q_name(k)
            end if
            if (d > c%angle_tol) problems = problems//'; '//trim(out(1)%q_name(k))//' '//real_text(a)//' and '// &
                                            real_text(b)
            cycle
         end if
         if (out(1)%q_force(k) .and. max(abs(a), abs(b)) < force_floor*largest) cycle
         if (max(abs(a), abs(b)) < 1.0_wp) cycle    ! (HIC below 1, peaks below 1 g or 1 lb: nothing)
         d = abs(a - b)/max(abs(a), abs(b))
         if (d > worst_rel) then
            worst_rel = d
            rel_name = out(1)%q_name(k)
         end if
         if (d > peak_tol) problems = problems//'; '//trim(out(1)%q_name(k))//' '//real_text(a)//' and '//real_text(b)
      end do
      ! an effect's peak the second setting has and the first has not
      do k = 1, out(2)%n_q
         if (out(2)%q_force(k) .and. .not. any(out(1)%q_name(1:out(1)%n_q) == out(2)%q_name(k)) .and. &
             abs(out(2)%q(k)) >= force_floor*largest) &
            problems = problems//'; '//trim(out(2)%q_name(k))//' 0 and '//real_text(out(2)%q(k))
      end do
      write (output_unit, '(a)') 'hard: '//tag//': the two settings differ by '//real_text(worst_angle)// &
         ' deg ('//trim(angle_name)//'), '//real_text(100*worst_rel)//' % ('//trim(rel_name)//')'
      if (len(problems) == 0) return
      if (c%large_step .and. nint /= nint_dopri .and. out(1)%warned) return   ! (the listing says it is wrong)
      call add(failures, tag//': the two settings disagree: '//problems(3:))
   contains
      !> The second setting's value of the first's quantity k (0: it has none).
      real(wp) function other(k)
         integer, intent(in) :: k
         integer :: j
         other = 0.0_wp
         do j = 1, out(2)%n_q
            if (out(2)%q_name(j) == out(1)%q_name(k)) then
               other = out(2)%q(j)
               return
            end if
         end do
      end function other
   end subroutine compare

   !> One line of figures per run.
   subroutine report(tag, location, out)
      character(len=*), intent(in) :: tag, location
      type(outcome_t), intent(in) :: out
      character(len=:), allocatable :: line
      line = 'hard: '//tag//' (location '//location//'): status '//int_text(out%status)//', t = '// &
             real_text(out%t_end)//' s'
      if (out%n_q >= 3) line = line//', HIC15 '//real_text(out%q(1))//', head '//real_text(out%q(2))// &
                               ' g, chest '//real_text(out%q(3))//' g, balance '//real_text(100*out%energy)//' %'
      if (out%warned) line = line//', error warned'
      if (out%status /= exit_ok) line = line//': '//first_line(out%message)
      write (output_unit, '(a)') line
   end subroutine report

   subroutine add(failures, line)
      character(len=:), allocatable, intent(inout) :: failures
      character(len=*), intent(in) :: line
      failures = failures//new_line('a')//'  '//line
   end subroutine add

   function first_line(text) result(s)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: s
      integer :: at
      at = index(text, new_line('a'))
      if (at == 0) then
         s = text
      else
         s = text(1:at - 1)
      end if
   end function first_line

   function real_text(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buffer
      write (buffer, '(g0.5)') x
      s = trim(adjustl(buffer))
   end function real_text

   function int_text(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=16) :: buffer
      write (buffer, '(i0)') i
      s = trim(buffer)
   end function int_text
end module hard_cases
