!> A study from the deck's cards (report C.8: "change certain input
!! parameters or data, and then initiate a new run ... systematic or random
!! ... singly or all at the same time"): *STUDY (the method), *VARY (the
!! fields varied, each addressed as a user would write it: group, card,
!! field), *VALUES (their lists) and *CRITERIA (how each run is judged).
!! Every problem is a deck error located at its card and field, like every
!! other card's (docs/modification.md).
module study_input
   use kinds, only: wp
   use error_handling, only: error_t
   use strings, only: itoa, num
   use deck_reader, only: deck_t, card_t, deck_field_address
   use deck_cards, only: g_study, g_vary, g_values, g_criteria, g_analog, study_methods, kind_int
   use field_values, only: field_expectation
   use model_origin, only: model_origin_t, deck_origin, problem, problem_at
   use study_sampling, only: method_oat, method_grid, method_random, method_lhs, method_ensemble
   use study_criteria, only: criterion_index, analog_criterion_index, analog_criterion_words
   use analog_input, only: deck_is_analog
   implicit none
   private

   public :: study_t, study_var_t, study_crit_t, read_study, has_study, method_word
   public :: method_oat, method_grid, method_random, method_lhs, method_ensemble, method_optimize
   public :: keep_none, keep_listing, keep_h5, keep_both

   !> *STUDY's METHOD words, in order (deck_cards' study_methods): the
   !! sampled ones study_sampling's, then the search
   integer, parameter :: method_optimize = method_ensemble + 1
   !> *STUDY's KEEP words.
   integer, parameter :: keep_none = 1, keep_listing = 2, keep_h5 = 3, keep_both = 4

   !> One varied field: where it is in the deck, its values' description
   !! (in the field's deck units), and its column name in the results.
   type :: study_var_t
      integer :: gid = 0, ic = 0, k = 0      !< group, card position, field (deck_field_address)
      character(len=:), allocatable :: column   !< e.g. belts_2_k1
      character(len=:), allocatable :: label    !< e.g. *BELTS card 2 K1
      real(wp) :: base = 0.0_wp              !< the deck's own value
      logical :: integer_valued = .false.
      real(wp) :: low = 0.0_wp, high = 0.0_wp
      logical :: has_range = .false.
      integer :: count = 0                   !< 0: not given
      real(wp) :: spread = 0.0_wp
      real(wp), allocatable :: values(:)     !< *VALUES (size 0: none)
   end type study_var_t

   !> One criterion the runs are judged by.
   type :: study_crit_t
      character(len=8) :: word = ' '         !< as on the card (study_criteria names it)
      integer :: occupant = 1
      logical :: has_limit = .false.
      real(wp) :: limit = 0.0_wp
      type(card_t) :: card                   !< where it came from (none: a default criterion)
   end type study_crit_t

   !> A study as its cards give it.
   type :: study_t
      integer :: method = 0
      integer :: runs = 0                    !< RANDOM, LHS, ENSEMBLE; OPTIMIZE: the budget
      integer :: seed = 0
      real(wp) :: tol = 1.0e-3_wp
      character(len=8) :: objective = ' '    !< OPTIMIZE: the criterion minimised
      integer :: objective_occupant = 1
      integer :: keep = keep_none
      !> the deck is Section D's analog (*ANALOG, one case): each run solves
      !! it, judged by the analog's criteria (docs/analog.md)
      logical :: analog = .false.
      type(card_t) :: card                   !< the *STUDY card, for messages
      type(study_var_t), allocatable :: vars(:)
      type(study_crit_t), allocatable :: crits(:)
   end type study_t

   !> *VALUES' fields, for the messages.
   character(len=2), parameter :: value_fields(7) = ['V1', 'V2', 'V3', 'V4', 'V5', 'V6', 'V7']

   !> The criteria reported when the deck gives no *CRITERIA.
   character(len=8), parameter :: default_criteria(5) = &
      [character(len=8) :: 'HIC15', 'CLIP3MS', 'BELTF', 'UNWANTED', 'INJURY']
   !> ... and an analog deck's (Section D: whether, when, how near).
   character(len=8), parameter :: default_analog_criteria(3) = [character(len=8) :: 'MEET', 'TMEET', 'SEPMIN']

contains

   !> The deck holds a study (*STUDY).
   pure logical function has_study(deck)
      type(deck_t), intent(in) :: deck
      has_study = deck%group(g_study)%present
   end function has_study

   !> The study of deck (which has_study); every problem appended to err.
   subroutine read_study(deck, st, err)
      type(deck_t), intent(in) :: deck
      type(study_t), intent(out) :: st
      type(error_t), intent(inout) :: err
      type(model_origin_t) :: o
      type(card_t) :: c
      integer :: i, j, n, v, order(0:size(deck%group(g_vary)%card))
      logical :: random_method
      o = deck_origin(deck)
      if (deck%group(g_study)%n < 1) then
         allocate (st%vars(0), st%crits(0))
         return   ! (the reader reported the missing card)
      end if
      c = deck%group(g_study)%card(1)
      st%card = c
      st%analog = deck_is_analog(deck)
      ! a run of an analog study is one case: the one *ANALOG card *VARY sets
      if (st%analog .and. deck%group(g_analog)%n > 1) &
         call problem(o, err, deck%group(g_analog)%card(2), 'a study of the analog varies one case: this deck has '// &
                      itoa(deck%group(g_analog)%n)//' *ANALOG cards; keep one (the study''s *VARY makes the others)')
      st%method = nint(c%value(1))
      st%runs = nint(c%value(2))
      st%seed = nint(c%value(3))
      st%tol = c%value(4)
      if (c%given(5)) st%objective = word_of(deck, g_study, 5, c)
      st%objective_occupant = nint(c%value(6))
      st%keep = nint(c%value(7))
      random_method = st%method == method_random .or. st%method == method_lhs .or. st%method == method_ensemble
      if ((random_method .or. st%method == method_optimize) .and. .not. c%given(2)) &
         call problem(o, err, c, 'METHOD '//method_word(st%method)//' needs the number of runs', 'RUNS')
      if (random_method .and. .not. c%given(3)) &
         call problem(o, err, c, 'METHOD '//method_word(st%method)//' draws at random: give a SEED (any '// &
                      'positive integer; the same seed gives the same runs)', 'SEED')
      if (st%method == method_optimize .and. .not. c%given(5)) &
         call problem(o, err, c, 'METHOD OPTIMIZE needs the criterion to minimise', 'OBJECT')

      ! *VARY: the variables in the order of their index v
      if (.not. deck%group(g_vary)%present .or. deck%group(g_vary)%n == 0) then
         call problem_at(o, err, g_study, 'a study needs a *VARY card group naming the fields to vary')
         allocate (st%vars(0))
      else
         associate (g => deck%group(g_vary))
            order = 0
            do i = 1, g%n
               v = g%card(i)%index
               if (order(min(v, ubound(order, 1))) /= 0 .or. v > g%n) then
                  call problem(o, err, g%card(i), 'variable '//itoa(v)//' is given twice or out of order: '// &
                               'number the *VARY cards 1, 2, 3, ... in columns 1-2')
                  cycle
               end if
               order(v) = i
            end do
            n = count(order(1:) > 0)
            allocate (st%vars(n))
            j = 0
            do v = 1, g%n
               if (order(v) == 0) cycle
               j = j + 1
               call read_variable(deck, o, g%card(order(v)), st, st%vars(j), err)
            end do
            ! one field varied twice would be two variables fighting over one value
            do i = 1, size(st%vars)
               do j = 1, i - 1
                  if (st%vars(i)%gid == st%vars(j)%gid .and. st%vars(i)%ic == st%vars(j)%ic .and. &
                      st%vars(i)%k == st%vars(j)%k .and. st%vars(i)%gid > 0) &
                     call problem(o, err, g%card(order(i)), 'this field is already variable '//itoa(j), 'FIELD')
               end do
            end do
         end associate
      end if
      call read_values(deck, o, st, err)
      call check_variables(deck, o, st, err)

      ! *CRITERIA
      if (deck%group(g_criteria)%present .and. deck%group(g_criteria)%n > 0) then
         associate (g => deck%group(g_criteria))
            allocate (st%crits(g%n))
            do i = 1, g%n
               st%crits(i)%word = word_of(deck, g_criteria, 1, g%card(i))
               st%crits(i)%occupant = nint(g%card(i)%value(2))
               st%crits(i)%has_limit = g%card(i)%given(3)
               st%crits(i)%limit = g%card(i)%value(3)
               st%crits(i)%card = g%card(i)
            end do
         end associate
      else if (st%analog) then
         allocate (st%crits(size(default_analog_criteria)))
         st%crits(:)%word = default_analog_criteria
      else
         allocate (st%crits(size(default_criteria)))
         st%crits(:)%word = default_criteria
      end if
      call check_criteria_kind(o, st, err)
      ! the objective is a column of the table, whether *CRITERIA names it or not
      if (len_trim(st%objective) > 0) then
         if (.not. any(st%crits(:)%word == st%objective .and. st%crits(:)%occupant == st%objective_occupant)) &
            st%crits = [st%crits, study_crit_t(word=st%objective, occupant=st%objective_occupant)]
      end if
   end subroutine read_study

   !> An analog deck is judged by the analog's criteria only, of both
   !! occupants together (OCC blank); any other deck by the occupant's.
   subroutine check_criteria_kind(o, st, err)
      type(model_origin_t), intent(in) :: o
      type(study_t), intent(in) :: st
      type(error_t), intent(inout) :: err
      integer :: k
      do k = 1, size(st%crits)
         associate (cr => st%crits(k))
            if (cr%card%line == 0) cycle   ! (a default criterion)
            call check_word(cr%card, cr%word, 'CRIT', 2)
         end associate
      end do
      if (len_trim(st%objective) > 0) call check_word(st%card, st%objective, 'OBJECT', 6)
   contains
      subroutine check_word(c, word, field, occ_field)
         type(card_t), intent(in) :: c
         character(len=*), intent(in) :: word, field
         integer, intent(in) :: occ_field
         if (st%analog .and. analog_criterion_index(word) == 0) then
            call problem(o, err, c, trim(word)//' is a criterion of the occupant simulation; a deck with *ANALOG '// &
                         '(report Section D) is judged by '//words_text(analog_criterion_words), field)
         else if (.not. st%analog .and. criterion_index(word) == 0) then
            call problem(o, err, c, trim(word)//' is a criterion of report Section D''s analog, for a deck with '// &
                         '*ANALOG; this deck''s occupants are judged by the criteria of docs/modification.md', field)
         else if (st%analog .and. c%given(occ_field)) then
            call problem(o, err, c, 'an analog criterion is of both occupants together: leave OCC blank', 'OCC')
         end if
      end subroutine check_word
   end subroutine check_criteria_kind

   !> A '|'-separated word list as text: 'A, B or C'.
   pure function words_text(list) result(t)
      character(len=*), intent(in) :: list
      character(len=:), allocatable :: t
      integer :: last
      t = list
      last = index(t, '|', back=.true.)
      if (last > 0) t = t(1:last - 1)//' or '//t(last + 1:)
      do while (index(t, '|') > 0)
         t = t(1:index(t, '|') - 1)//', '//t(index(t, '|') + 1:)
      end do
   end function words_text

   !> One *VARY card: the field it names (located at GROUP, CARD, FIELD when
   !! the deck has no such field) and its values' description.
   subroutine read_variable(deck, o, c, st, var, err)
      type(deck_t), intent(in) :: deck
      type(model_origin_t), intent(in) :: o
      type(card_t), intent(in) :: c
      type(study_t), intent(in) :: st
      type(study_var_t), intent(out) :: var
      type(error_t), intent(inout) :: err
      character(len=:), allocatable :: why, group
      integer :: gid, ic, k
      group = word_of(deck, g_vary, 1, c)
      call deck_field_address(deck, group, nint(c%value(2)), c%text, gid, ic, k, why)
      allocate (var%values(0))
      if (len(why) > 0) then
         call problem(o, err, c, why, 'GROUP CARD FIELD')
         return
      end if
      var%gid = gid
      var%ic = ic
      var%k = k
      associate (f => deck%spec(gid)%field(k), card => deck%group(gid)%card(ic))
         var%base = card%value(k)/f%scale
         var%integer_valued = f%kind == kind_int
         var%column = lower(trim(deck%spec(gid)%name))//'_'//itoa(nint(c%value(2)))//'_'//lower(trim(f%name))
         var%label = '*'//trim(deck%spec(gid)%name)//' '//itoa(nint(c%value(2)))//' '//trim(f%name)
      end associate
      var%has_range = c%given(4) .and. c%given(5)
      var%low = c%value(4)
      var%high = c%value(5)
      if (c%given(6)) var%count = nint(c%value(6))
      var%spread = c%value(7)
      if (c%given(4) .neqv. c%given(5)) &
         call problem(o, err, c, 'give both LOW and HIGH, or neither', 'LOW HIGH')
      if (var%has_range .and. var%low > var%high) &
         call problem(o, err, c, 'LOW '//num(var%low)//' is above HIGH '//num(var%high), 'LOW HIGH')
      if (st%method == method_ensemble .and. .not. c%given(7)) &
         call problem(o, err, c, 'METHOD ENSEMBLE perturbs each field by SPREAD times a normal draw: give SPREAD', &
                      'SPREAD')
   end subroutine read_variable

   !> *VALUES: each variable's list, every value in its field's range.
   subroutine read_values(deck, o, st, err)
      type(deck_t), intent(in) :: deck
      type(model_origin_t), intent(in) :: o
      type(study_t), intent(inout) :: st
      type(error_t), intent(inout) :: err
      integer :: i, j, v
      real(wp) :: x
      if (.not. deck%group(g_values)%present) return
      associate (g => deck%group(g_values))
         do i = 1, g%n
            v = g%card(i)%index
            if (v > size(st%vars)) then
               call problem(o, err, g%card(i), 'there is no *VARY card for variable '//itoa(v))
               cycle
            end if
            if (st%vars(v)%gid == 0) cycle
            do j = 1, 7
               if (.not. g%card(i)%given(j)) cycle
               x = g%card(i)%value(j)
               if (.not. in_field_range(deck, st%vars(v), x)) then
                  call problem(o, err, g%card(i), 'value '//num(x)//' is outside the range of '// &
                               st%vars(v)%label//': expected '//field_expectation(deck%spec(st%vars(v)%gid)% &
                               field(st%vars(v)%k)), value_fields(j))
               else
                  st%vars(v)%values = [st%vars(v)%values, x]
               end if
            end do
         end do
      end associate
   end subroutine read_values

   !> What each method needs of each variable, and LOW and HIGH within the
   !! field's own range.
   subroutine check_variables(deck, o, st, err)
      type(deck_t), intent(in) :: deck
      type(model_origin_t), intent(in) :: o
      type(study_t), intent(in) :: st
      type(error_t), intent(inout) :: err
      integer :: v, i
      type(card_t) :: c
      logical :: listed
      do v = 1, size(st%vars)
         associate (x => st%vars(v))
            if (x%gid == 0) cycle
            do i = 1, deck%group(g_vary)%n
               if (deck%group(g_vary)%card(i)%index == v) c = deck%group(g_vary)%card(i)
            end do
            listed = size(x%values) > 0
            if (x%has_range) then
               if (.not. in_field_range(deck, x, x%low) .or. .not. in_field_range(deck, x, x%high)) &
                  call problem(o, err, c, 'LOW and HIGH must lie in the range of '//x%label//': expected '// &
                               field_expectation(deck%spec(x%gid)%field(x%k)), 'LOW HIGH')
            end if
            select case (st%method)
            case (method_oat, method_grid)
               if (.not. listed .and. .not. (x%has_range .and. x%count > 0)) &
                  call problem(o, err, c, 'METHOD '//method_word(st%method)//' needs the values of '//x%label// &
                               ': a *VALUES list for variable '//itoa(v)//', or LOW, HIGH and COUNT', &
                               'LOW HIGH COUNT')
            case (method_random, method_lhs)
               if (.not. listed .and. .not. x%has_range) &
                  call problem(o, err, c, 'METHOD '//method_word(st%method)//' draws '//x%label// &
                               ' within LOW-HIGH or from a *VALUES list: give one', 'LOW HIGH')
            case (method_optimize)
               if (listed .or. .not. x%has_range) &
                  call problem(o, err, c, 'METHOD OPTIMIZE searches '//x%label//' within LOW-HIGH: give both '// &
                               '(and no *VALUES list)', 'LOW HIGH')
            end select
         end associate
      end do
   end subroutine check_variables

   !> x lies in the range the deck's field accepts (deck units).
   pure logical function in_field_range(deck, var, x) result(ok)
      type(deck_t), intent(in) :: deck
      type(study_var_t), intent(in) :: var
      real(wp), intent(in) :: x
      associate (f => deck%spec(var%gid)%field(var%k))
         ok = x >= f%low .and. x <= f%high
         if (f%low_open) ok = ok .and. x > f%low
         if (f%kind == kind_int) ok = ok .and. abs(x) < real(huge(1), wp)
      end associate
   end function in_field_range

   !> The word a word field of card c holds.
   function word_of(deck, gid, k, c) result(w)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: gid, k
      type(card_t), intent(in) :: c
      character(len=:), allocatable :: w
      w = nth_word(deck%spec(gid)%field(k)%words, nint(c%value(k)))
   end function word_of

   !> A method's word.
   function method_word(method) result(w)
      integer, intent(in) :: method
      character(len=:), allocatable :: w
      w = nth_word(study_methods, method)
   end function method_word

   !> Word n of a '|'-separated list.
   pure function nth_word(list, n) result(w)
      character(len=*), intent(in) :: list
      integer, intent(in) :: n
      character(len=:), allocatable :: w
      integer :: i, start, found
      start = 1
      found = 0
      w = ''
      do i = 1, len_trim(list) + 1
         if (i > len_trim(list) .or. list(min(i, len(list)):min(i, len(list))) == '|') then
            found = found + 1
            if (found == n) then
               w = list(start:i - 1)
               return
            end if
            start = i + 1
         end if
      end do
   end function nth_word

   pure function lower(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(s)
         if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
      end do
   end function lower
end module study_input
