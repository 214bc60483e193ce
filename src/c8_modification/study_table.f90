!> The results of a study's runs (report C.8): one row per run - its
!! number, status, the varied values as run, the criteria, whether it met
!! the study's limits, when it ended and why - as a CSV line (one file per
!! run while the study goes, so that it can resume; the table of the whole
!! study in results.csv) and read back from one. Numbers are written as the
!! shortest decimal that reads back as the same double, so that a table
!! read back (a resumed optimisation) gives the same bits, and any number
!! of worker processes write the same bytes.
module study_table
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, ieee_quiet_nan
   use kinds, only: wp
   use strings, only: itoa, read_real, read_int
   use text_io, only: string_t, append_string
   implicit none
   private

   public :: run_row_t, row_csv, row_from_csv, table_header, exact_text
   public :: status_completed, status_ended, status_failed, status_invalid, status_word

   !> A run's status: it reached TMAX; an end test ended it (C.7); the
   !! integration failed (exit 3's message); the variation is not a valid
   !! deck (a value its field refuses: the reason).
   integer, parameter :: status_completed = 1, status_ended = 2, status_failed = 3, status_invalid = 4

   type :: run_row_t
      integer :: run = 0
      integer :: status = 0
      real(wp), allocatable :: x(:)          !< the varied fields' values as run (deck units)
      real(wp), allocatable :: crit(:)       !< the criteria (their units); not for failed or invalid runs
      logical :: meets = .false.             !< every criterion within its limit
      real(wp) :: t_end = 0.0_wp
      character(len=:), allocatable :: reason
   end type run_row_t

contains

   pure function status_word(status) result(w)
      integer, intent(in) :: status
      character(len=:), allocatable :: w
      select case (status)
      case (status_completed)
         w = 'completed'
      case (status_ended)
         w = 'ended'
      case (status_failed)
         w = 'failed'
      case (status_invalid)
         w = 'invalid'
      case default
         w = 'unknown'
      end select
   end function status_word

   !> The table's header line.
   pure function table_header(var_columns, crit_columns) result(line)
      type(string_t), intent(in) :: var_columns(:), crit_columns(:)
      character(len=:), allocatable :: line
      integer :: k
      line = 'run,status'
      do k = 1, size(var_columns)
         line = line//','//var_columns(k)%s
      end do
      do k = 1, size(crit_columns)
         line = line//','//crit_columns(k)%s
      end do
      line = line//',meets_limits,t_end,reason'
   end function table_header

   !> A row as a CSV line (no line end). Criteria of a run without them
   !! are empty fields; the reason is quoted.
   pure function row_csv(row, n_crit) result(line)
      type(run_row_t), intent(in) :: row
      integer, intent(in) :: n_crit
      character(len=:), allocatable :: line
      integer :: k
      line = itoa(row%run)//','//status_word(row%status)
      do k = 1, size(row%x)
         line = line//','//exact_text(row%x(k))
      end do
      do k = 1, n_crit
         if (allocated(row%crit)) then
            if (size(row%crit) >= k) then
               line = line//','//exact_text(row%crit(k))
               cycle
            end if
         end if
         line = line//','
      end do
      line = line//','//trim(merge('yes', 'no ', row%meets))//','//exact_text(row%t_end)//','//quoted(row%reason)
   end function row_csv

   !> A row from its CSV line (row_csv's); ok = .false. when the line is not
   !! such a row of n_var values and n_crit criteria (a truncated file).
   subroutine row_from_csv(line, n_var, n_crit, row, ok)
      character(len=*), intent(in) :: line
      integer, intent(in) :: n_var, n_crit
      type(run_row_t), intent(out) :: row
      logical, intent(out) :: ok
      type(string_t), allocatable :: f(:)
      integer :: k
      logical :: good
      call split_csv(line, f)
      ok = size(f) == 2 + n_var + n_crit + 3
      if (.not. ok) return
      call read_int(f(1)%s, row%run, good)
      ok = good
      select case (f(2)%s)
      case ('completed')
         row%status = status_completed
      case ('ended')
         row%status = status_ended
      case ('failed')
         row%status = status_failed
      case ('invalid')
         row%status = status_invalid
      case default
         ok = .false.
      end select
      allocate (row%x(n_var))
      do k = 1, n_var
         call read_real(f(2 + k)%s, row%x(k), good)
         ok = ok .and. good
      end do
      if (len(f(3 + n_var)%s) > 0) then
         allocate (row%crit(n_crit))
         do k = 1, n_crit
            if (f(2 + n_var + k)%s == 'NaN') then
               ! a criterion without a value (exact_text: TMEET of an analog run
               ! whose occupants never meet)
               row%crit(k) = ieee_value(row%crit(k), ieee_quiet_nan)
               cycle
            end if
            call read_real(f(2 + n_var + k)%s, row%crit(k), good)
            ok = ok .and. good
         end do
      end if
      row%meets = f(3 + n_var + n_crit)%s == 'yes'
      call read_real(f(4 + n_var + n_crit)%s, row%t_end, good)
      ok = ok .and. good
      row%reason = f(5 + n_var + n_crit)%s
   end subroutine row_from_csv

   !> The shortest decimal (at most 17 significant digits) that reads back
   !! as x exactly: 0.25, 2500, 1.0000000000000002, -3.5E-07.
   pure function exact_text(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=40) :: buf
      character(len=16) :: fmt
      real(wp) :: back
      integer :: d, ios
      if (ieee_is_nan(x)) then
         s = 'NaN'   ! (a criterion without a value: TMEET where the analog's occupants never meet)
         return
      else if (.not. ieee_is_finite(x)) then
         s = trim(merge('-Infinity', 'Infinity ', x < 0.0_wp))
         return
      else if (.not. abs(x) > 0.0_wp) then
         s = '0'
         return
      end if
      do d = 1, 17
         write (fmt, '(a,i0,a,i0,a)') '(es', d + 10, '.', d - 1, 'e3)'
         write (buf, fmt) x
         read (buf, *, iostat=ios) back
         if (ios == 0 .and. .not. abs(back - x) > 0.0_wp) exit
      end do
      s = trim(adjustl(buf))
      s = plain(s)
   contains
      !> d.dddE+eee as a plain decimal where that is short (1e-3 to 1e7).
      pure function plain(t) result(p)
         character(len=*), intent(in) :: t
         character(len=:), allocatable :: p
         character(len=:), allocatable :: sgn, digits
         integer :: e, epos, k, ios2
         epos = index(t, 'E')
         read (t(epos + 1:), *, iostat=ios2) e
         p = t
         if (ios2 /= 0 .or. e < -3 .or. e > 6) return
         sgn = ''
         if (t(1:1) == '-') sgn = '-'
         digits = ''
         do k = 1, epos - 1
            if (t(k:k) >= '0' .and. t(k:k) <= '9') digits = digits//t(k:k)
         end do
         ! trailing zeros carry nothing
         k = len(digits)
         do while (k > 1 .and. digits(k:k) == '0')
            k = k - 1
         end do
         digits = digits(1:k)
         if (e >= 0) then
            if (len(digits) <= e + 1) then
               p = sgn//digits//repeat('0', e + 1 - len(digits))
            else
               p = sgn//digits(1:e + 1)//'.'//digits(e + 2:)
            end if
         else
            p = sgn//'0.'//repeat('0', -e - 1)//digits
         end if
      end function plain
   end function exact_text

   !> A CSV field in double quotes (a quote doubled; line ends as '; ').
   pure function quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: q
      integer :: i
      q = '"'
      do i = 1, len(text)
         select case (text(i:i))
         case ('"')
            q = q//'""'
         case (achar(10))
            q = q//'; '
         case (achar(13))
         case default
            q = q//text(i:i)
         end select
      end do
      q = q//'"'
   end function quoted

   !> The fields of a CSV line (quotes removed, doubled quotes undone).
   pure subroutine split_csv(line, fields)
      character(len=*), intent(in) :: line
      type(string_t), allocatable, intent(out) :: fields(:)
      character(len=:), allocatable :: cur
      logical :: in_quotes
      integer :: i
      allocate (fields(0))
      cur = ''
      in_quotes = .false.
      i = 1
      do while (i <= len(line))
         if (in_quotes) then
            if (line(i:i) == '"') then
               if (i < len(line)) then
                  if (line(i + 1:i + 1) == '"') then
                     cur = cur//'"'
                     i = i + 2
                     cycle
                  end if
               end if
               in_quotes = .false.
            else
               cur = cur//line(i:i)
            end if
         else if (line(i:i) == '"') then
            in_quotes = .true.
         else if (line(i:i) == ',') then
            call append_string(fields, cur)
            cur = ''
         else
            cur = cur//line(i:i)
         end if
         i = i + 1
      end do
      call append_string(fields, cur)
   end subroutine split_csv
end module study_table
