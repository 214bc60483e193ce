!> The points of a C.8 study (report section C.8: the program "changes
!! certain input parameters or data, and then initiates a new run",
!! systematically or randomly, singly or all at once): for each run, the
!! value of every varied input. This module knows nothing of decks or runs;
!! the study runner maps its variables to deck fields.
!!
!! A variable (study_variable_t) has bounds LOW <= HIGH, a COUNT of values,
!! an optional explicit list VALUES (when allocated with at least one
!! element it replaces LOW, HIGH and COUNT as the variable's values for
!! OAT, GRID, RANDOM and LHS), the BASE deck's value, a SPREAD (ENSEMBLE's
!! standard deviation) and INTEGER_VALUED. A variable's values for OAT and
!! GRID are its list, or COUNT values evenly spaced from LOW to HIGH, both
!! included (LOW and HIGH exactly; COUNT = 1: the midpoint).
!!
!! study_points(method, vars, n_runs, seed, points, err) gives points(j, r),
!! the value of variable j in run r:
!!
!! - OAT, one at a time about the base deck: run 1 has every variable at its
!!   base; then, for each variable in order, one run for each of its values
!!   in order, the other variables at their bases. 1 + the sum of the
!!   numbers of values runs; n_runs and seed are not used.
!! - GRID, all at once on a full grid: one run for each combination of the
!!   variables' values, the first variable varying fastest (runs 1, 2, ...
!!   step through the first variable's values with the others at their
!!   first). The product of the numbers of values runs; n_runs and seed are
!!   not used.
!! - RANDOM: n_runs runs, each variable uniform on [LOW, HIGH] (a list
!!   variable: one of its values, each equally likely), from the stream of
!!   `seed`, one uniform per value drawn run by run and, within a run,
!!   variable by variable: LOW + (HIGH - LOW)*u, or the list's value
!!   1 + int(u*n_values).
!! - LHS, Latin hypercube: n_runs runs; each variable's [LOW, HIGH] cut into
!!   n_runs equal strata, one uniform point in each (stratum k, of 0-based
!!   index k-1: LOW + (HIGH - LOW)*(k - 1 + u)/n_runs), and the strata dealt
!!   to the runs in an order shuffled independently for each variable (run
!!   r takes stratum perm(r)). A list variable has no points within strata:
!!   its values are dealt cyclically to the strata (stratum k takes value
!!   1 + mod(k - 1, n_values)), then shuffled the same way. The draws, from
!!   the stream of `seed`, go variable by variable: a range variable's
!!   n_runs uniforms for strata 1, 2, ..., n_runs, then its shuffle
!!   (Fisher-Yates: perm = 1..n_runs; for i = n_runs down to 2, one uniform
!!   u, m = 1 + int(u*i), swap perm(i) and perm(m)); a list variable only
!!   its shuffle.
!! - ENSEMBLE: n_runs runs; run 1 has every variable at its base; in runs
!!   2..n_runs each variable is BASE + SPREAD*z, z standard normal, clipped
!!   to [LOW, HIGH], drawn run by run and, within a run, variable by
!!   variable, one uniform per value (z = normal_quantile(u)). A list is not
!!   used.
!!
!! Every value of an integer-valued variable is then rounded to the nearest
!! integer, halves away from zero (ANINT), after any clipping: its bounds
!! should be integers. RANDOM and LHS values are kept within [LOW, HIGH]
!! against the rounding of the arithmetic. The same inputs give the same
!! points bit for bit with the same build: the stream is exact integer
!! arithmetic on every compiler and platform, but a compiler that fuses a
!! multiply and an add (FMA, gfortran's default where the target has it)
!! may round LOW + (HIGH - LOW) u differently on another machine; ENSEMBLE's normal deviates use SQRT and LOG only in the tails
!! (u < 0.02425 or u > 0.97575), where a platform's LOG could differ in the
!! last bit.
!!
!! Errors (err, exit_deck; every problem found, one per line): no variable;
!! an unknown method; n_runs < 1 or seed < 1 for RANDOM, LHS and ENSEMBLE;
!! LOW > HIGH; a bound, base, spread or list value not a number within
!! +-1e300; COUNT < 1 without a list for OAT and GRID; a negative SPREAD for
!! ENSEMBLE; more than max_study_points (1,000,000) runs.
!! On an error, points has no columns.
module study_sampling
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use strings, only: itoa, num
   use kinds, only: wp, i8
   use error_handling, only: error_t, error_append, error_set, exit_deck
   implicit none
   private

   public :: rng_t, rng_seed, rng_uniform, rng_normal, rng_state, normal_quantile
   public :: method_oat, method_grid, method_random, method_lhs, method_ensemble
   public :: study_variable_t, study_points, max_study_points

   !> The study methods (report C.8: systematically, singly or all at once,
   !! or randomly; and an ensemble about the base deck).
   integer, parameter :: method_oat = 1, method_grid = 2, method_random = 3, method_lhs = 4, &
                         method_ensemble = 5
   !> The most runs a study may have (the points are held in memory).
   integer, parameter :: max_study_points = 1000000
   !> Inputs beyond this magnitude are refused (no overflow in any formula).
   real(wp), parameter :: value_limit = 1.0e300_wp

   ! MRG32k3a (P. L'Ecuyer, "Good parameters and implementations for combined
   ! multiple recursive random number generators", Operations Research 47
   ! (1999) 159-164): two recurrences of order 3,
   !   x1(n) = (a12*x1(n-2) - a13n*x1(n-3)) mod m1,
   !   x2(n) = (a21*x2(n-1) - a23n*x2(n-3)) mod m2,
   ! u(n) = ((x1(n) - x2(n)) mod m1, or m1 where that is 0)/(m1 + 1).
   integer(i8), parameter :: m1 = 4294967087_i8, m2 = 4294944443_i8
   integer(i8), parameter :: a12 = 1403580_i8, a13n = 810728_i8
   integer(i8), parameter :: a21 = 527612_i8, a23n = 1370589_i8
   !> 1/(m1 + 1), as the published implementation's constant.
   real(wp), parameter :: norm = 2.328306549295727688e-10_wp
   !> The recurrences' matrices raised to 2^127 (L'Ecuyer, Simard, Chen and
   !! Kelton, "An object-oriented random-number package with many long
   !! streams and substreams", Operations Research 50 (2002) 1073-1075):
   !! the distance between two consecutive streams of that package.
   integer(i8), parameter :: a1p127(3, 3) = reshape([ &
      2427906178_i8, 226153695_i8, 1988835001_i8, &
      3580155704_i8, 1230515664_i8, 986791581_i8, &
      949770784_i8, 3580155704_i8, 1230515664_i8], [3, 3])
   integer(i8), parameter :: a2p127(3, 3) = reshape([ &
      1464411153_i8, 32183930_i8, 2824425944_i8, &
      277697599_i8, 1464411153_i8, 32183930_i8, &
      1610723613_i8, 1022607788_i8, 2093834863_i8], [3, 3])
   !> The package's first stream starts at 12345 six times.
   integer(i8), parameter :: standard_seed = 12345_i8

   !> A random stream: MRG32k3a's six-integer state (x1(n-3), x1(n-2),
   !! x1(n-1), then the same of x2), in exact int64 arithmetic (no product
   !! reaches 2^53), so every compiler and platform draws the same numbers.
   !! Unseeded, it is stream 1 (12345 six times).
   type :: rng_t
      private
      integer(i8) :: s1(3) = standard_seed
      integer(i8) :: s2(3) = standard_seed
   end type rng_t

   !> One varied input (public components; see the module's header).
   type :: study_variable_t
      real(wp) :: low = 0.0_wp
      real(wp) :: high = 0.0_wp
      integer :: count = 1
      real(wp), allocatable :: values(:)
      real(wp) :: base = 0.0_wp
      real(wp) :: spread = 0.0_wp
      logical :: integer_valued = .false.
   end type study_variable_t

contains

   !> Start `rng` at stream `seed` of L'Ecuyer et al.'s package (2002):
   !! seed 1 is the state 12345 x 6; seed k is that state advanced by
   !! (k - 1)*2^127 steps (the state times (A^(2^127))^(k-1), mod m1 and m2,
   !! by binary powers). Every seed 1..huge(1) gives a valid state, and the
   !! streams of different seeds do not overlap (2^31 streams of 2^127
   !! numbers in a period of about 2^191). A seed below 1 gives stream 1
   !! (study_points refuses it before).
   pure subroutine rng_seed(rng, seed)
      type(rng_t), intent(out) :: rng
      integer, intent(in) :: seed
      integer(i8) :: jump1(3, 3), jump2(3, 3), power1(3, 3), power2(3, 3)
      integer(i8) :: steps
      jump1 = a1p127
      jump2 = a2p127
      power1 = identity()
      power2 = identity()
      steps = max(0_i8, int(seed, i8) - 1_i8)
      do while (steps > 0)
         if (mod(steps, 2_i8) == 1) then
            power1 = mat_mul_mod(power1, jump1, m1)
            power2 = mat_mul_mod(power2, jump2, m2)
         end if
         steps = steps/2
         if (steps > 0) then
            jump1 = mat_mul_mod(jump1, jump1, m1)
            jump2 = mat_mul_mod(jump2, jump2, m2)
         end if
      end do
      rng%s1 = mat_vec_mod(power1, [standard_seed, standard_seed, standard_seed], m1)
      rng%s2 = mat_vec_mod(power2, [standard_seed, standard_seed, standard_seed], m2)
   end subroutine rng_seed

   !> The next number of the stream, in (0, 1): k/(m1 + 1), k in 1..m1.
   subroutine rng_uniform(rng, u)
      type(rng_t), intent(inout) :: rng
      real(wp), intent(out) :: u
      integer(i8) :: p1, p2
      p1 = modulo(a12*rng%s1(2) - a13n*rng%s1(1), m1)   ! products < 2^53
      rng%s1 = [rng%s1(2), rng%s1(3), p1]
      p2 = modulo(a21*rng%s2(3) - a23n*rng%s2(1), m2)
      rng%s2 = [rng%s2(2), rng%s2(3), p2]
      if (p1 > p2) then
         u = real(p1 - p2, wp)*norm
      else
         u = real(p1 - p2 + m1, wp)*norm
      end if
   end subroutine rng_uniform

   !> A standard normal deviate from one uniform of the stream, by the
   !! inverse of the normal distribution (normal_quantile).
   subroutine rng_normal(rng, z)
      type(rng_t), intent(inout) :: rng
      real(wp), intent(out) :: z
      real(wp) :: u
      call rng_uniform(rng, u)
      z = normal_quantile(u)
   end subroutine rng_normal

   !> The stream's six integers (x1(n-3), x1(n-2), x1(n-1), x2(n-3),
   !! x2(n-2), x2(n-1)), as L'Ecuyer's package prints a state.
   pure function rng_state(rng) result(state)
      type(rng_t), intent(in) :: rng
      integer(i8) :: state(6)
      state = [rng%s1, rng%s2]
   end function rng_state

   !> The standard normal quantile at p in (0, 1) by P. J. Acklam's rational
   !! approximation ("An algorithm for computing the inverse normal
   !! cumulative distribution function", 2003; relative error below
   !! 1.15e-9): a rational function of p - 1/2 in the middle, of
   !! sqrt(-2 ln p) (or of 1 - p) in the tails below 0.02425 and above
   !! 0.97575. p <= 0 gives -huge, p >= 1 gives +huge.
   pure real(wp) function normal_quantile(p) result(z)
      real(wp), intent(in) :: p
      real(wp), parameter :: a(6) = [-3.969683028665376e+01_wp, 2.209460984245205e+02_wp, &
                                     -2.759285104469687e+02_wp, 1.383577518672690e+02_wp, &
                                     -3.066479806614716e+01_wp, 2.506628277459239e+00_wp]
      real(wp), parameter :: b(5) = [-5.447609879822406e+01_wp, 1.615858368580409e+02_wp, &
                                     -1.556989798598866e+02_wp, 6.680131188771972e+01_wp, &
                                     -1.328068155288572e+01_wp]
      real(wp), parameter :: c(6) = [-7.784894002430293e-03_wp, -3.223964580411365e-01_wp, &
                                     -2.400758277161838e+00_wp, -2.549732539343734e+00_wp, &
                                     4.374664141464968e+00_wp, 2.938163982698783e+00_wp]
      real(wp), parameter :: d(4) = [7.784695709041462e-03_wp, 3.224671290700398e-01_wp, &
                                     2.445134137142996e+00_wp, 3.754408661907416e+00_wp]
      real(wp), parameter :: p_low = 0.02425_wp, p_high = 1.0_wp - p_low
      real(wp) :: q, r
      if (ieee_is_nan(p)) then
         z = 0.0_wp
      else if (p <= 0.0_wp) then
         z = -huge(1.0_wp)
      else if (p >= 1.0_wp) then
         z = huge(1.0_wp)
      else if (p < p_low) then
         q = sqrt(-2.0_wp*log(p))
         z = tail(q)
      else if (p <= p_high) then
         q = p - 0.5_wp
         r = q*q
         z = (((((a(1)*r + a(2))*r + a(3))*r + a(4))*r + a(5))*r + a(6))*q &
             /(((((b(1)*r + b(2))*r + b(3))*r + b(4))*r + b(5))*r + 1.0_wp)
      else
         q = sqrt(-2.0_wp*log(1.0_wp - p))
         z = -tail(q)
      end if
   contains
      pure real(wp) function tail(s)
         real(wp), intent(in) :: s
         tail = (((((c(1)*s + c(2))*s + c(3))*s + c(4))*s + c(5))*s + c(6)) &
                /((((d(1)*s + d(2))*s + d(3))*s + d(4))*s + 1.0_wp)
      end function tail
   end function normal_quantile

   !> The points of a study (the module's header gives the rules):
   !! points(j, r) is variable j's value in run r.
   subroutine study_points(method, vars, n_runs, seed, points, err)
      integer, intent(in) :: method
      type(study_variable_t), intent(in) :: vars(:)
      integer, intent(in) :: n_runs
      integer, intent(in) :: seed
      real(wp), allocatable, intent(out) :: points(:, :)
      type(error_t), intent(inout) :: err
      type(error_t) :: problems
      integer :: j

      allocate (points(size(vars), 0))
      call check_study(method, vars, n_runs, seed, problems)
      if (problems%failed()) then
         call error_set(err, problems%code, problems%message)
         return
      end if
      select case (method)
      case (method_oat)
         call oat_points(vars, points, problems)
      case (method_grid)
         call grid_points(vars, points, problems)
      case (method_random)
         call random_points(vars, n_runs, seed, points, problems)
      case (method_lhs)
         call lhs_points(vars, n_runs, seed, points, problems)
      case (method_ensemble)
         call ensemble_points(vars, n_runs, seed, points, problems)
      end select
      if (problems%failed()) then
         call error_set(err, problems%code, problems%message)
         return
      end if
      do j = 1, size(vars)
         if (vars(j)%integer_valued) points(j, :) = anint(points(j, :))
      end do
   end subroutine study_points

   !> points with room for n_vars variables of n_runs runs; a problem (not a
   !! run-time error) where the memory cannot be had.
   subroutine reserve(points, n_vars, n_runs, problems)
      real(wp), allocatable, intent(inout) :: points(:, :)
      integer, intent(in) :: n_vars, n_runs
      type(error_t), intent(inout) :: problems
      integer :: stat
      if (allocated(points)) deallocate (points)
      allocate (points(n_vars, n_runs), stat=stat)
      if (stat /= 0) then
         call error_append(problems, exit_deck, 'no memory for the study''s '//itoa(n_runs)//' runs of ' &
                           //itoa(n_vars)//' variables')
         allocate (points(n_vars, 0))
      end if
   end subroutine reserve

   !> Every problem of the study's inputs, one per line.
   subroutine check_study(method, vars, n_runs, seed, problems)
      integer, intent(in) :: method
      type(study_variable_t), intent(in) :: vars(:)
      integer, intent(in) :: n_runs, seed
      type(error_t), intent(inout) :: problems
      character(len=:), allocatable :: what
      logical :: seeded, by_values
      integer :: j

      if (size(vars) < 1) call error_append(problems, exit_deck, 'a study needs at least one variable')
      if (method < method_oat .or. method > method_ensemble) then
         call error_append(problems, exit_deck, 'unknown study method '//itoa(method) &
                           //' (1 OAT, 2 GRID, 3 RANDOM, 4 LHS, 5 ENSEMBLE)')
         return
      end if
      seeded = method == method_random .or. method == method_lhs .or. method == method_ensemble
      by_values = method == method_oat .or. method == method_grid
      if (seeded .and. n_runs < 1) call error_append(problems, exit_deck, 'the '//method_name(method) &
                                                     //' method needs at least 1 run (got '//itoa(n_runs)//')')
      if (seeded .and. seed < 1) call error_append(problems, exit_deck, 'the '//method_name(method) &
                                                   //' method needs a seed of at least 1 (got '//itoa(seed)//')')
      if (seeded .and. n_runs > max_study_points) call error_append(problems, exit_deck, 'the ' &
         //method_name(method)//' study would have '//itoa(n_runs)//' runs, more than '//itoa(max_study_points))
      do j = 1, size(vars)
         what = 'study variable '//itoa(j)//': '
         associate (v => vars(j))
            if (.not. (usable(v%low) .and. usable(v%high) .and. usable(v%base) .and. usable(v%spread))) then
               call error_append(problems, exit_deck, what//'its low, high, base and spread must be numbers within +-1e300')
            else if (v%low > v%high) then
               call error_append(problems, exit_deck, what//'low '//num(v%low)//' is above high '//num(v%high))
            end if
            if (has_list(v)) then
               if (.not. all(usable(v%values))) &
                  call error_append(problems, exit_deck, what//'its values must be numbers within +-1e300')
            else if (by_values .and. v%count < 1) then
               call error_append(problems, exit_deck, what//'the '//method_name(method) &
                                 //' method needs a list of values or a count of at least 1 (got '//itoa(v%count)//')')
            end if
            if (method == method_ensemble .and. v%spread < 0.0_wp) &
               call error_append(problems, exit_deck, what//'its spread '//num(v%spread)//' is negative')
         end associate
      end do
   end subroutine check_study

   !> OAT: the base, then each variable's values in turn about it.
   subroutine oat_points(vars, points, problems)
      type(study_variable_t), intent(in) :: vars(:)
      real(wp), allocatable, intent(inout) :: points(:, :)
      type(error_t), intent(inout) :: problems
      real(wp), allocatable :: values(:)
      integer(i8) :: total
      integer :: i, j, run

      total = 1
      do j = 1, size(vars)
         total = total + value_count(vars(j))
      end do
      if (total > max_study_points) then
         call error_append(problems, exit_deck, 'the OAT study would have '//num(real(total, wp)) &
                           //' runs, more than '//itoa(max_study_points))
         return
      end if
      call reserve(points, size(vars), int(total), problems)
      if (problems%failed()) return
      points(:, 1) = vars(:)%base
      run = 1
      do j = 1, size(vars)
         values = variable_values(vars(j))
         do i = 1, size(values)
            points(:, run + i) = points(:, 1)
            points(j, run + i) = values(i)
         end do
         run = run + size(values)
      end do
   end subroutine oat_points

   !> GRID: every combination, the first variable varying fastest.
   subroutine grid_points(vars, points, problems)
      type(study_variable_t), intent(in) :: vars(:)
      real(wp), allocatable, intent(inout) :: points(:, :)
      type(error_t), intent(inout) :: problems
      integer :: counts(size(vars)), at(size(vars))
      integer(i8) :: total
      integer :: j, run

      total = 1
      do j = 1, size(vars)
         counts(j) = int(value_count(vars(j)))
         total = total*counts(j)
         if (total > max_study_points) then   ! checked each time: the product cannot overflow
            call error_append(problems, exit_deck, 'the GRID study would have more than ' &
                              //itoa(max_study_points)//' runs (the product of the variables'' numbers of values)')
            return
         end if
      end do
      call reserve(points, size(vars), int(total), problems)
      if (problems%failed()) return
      at = 1
      do run = 1, int(total)
         do j = 1, size(vars)
            points(j, run) = variable_value(vars(j), at(j))
         end do
         ! the next combination: an odometer whose first wheel turns fastest
         do j = 1, size(vars)
            if (at(j) < counts(j)) then
               at(j) = at(j) + 1
               exit
            end if
            at(j) = 1
         end do
      end do
   end subroutine grid_points

   !> RANDOM: run by run, variable by variable, one uniform each.
   subroutine random_points(vars, n_runs, seed, points, problems)
      type(study_variable_t), intent(in) :: vars(:)
      integer, intent(in) :: n_runs, seed
      real(wp), allocatable, intent(inout) :: points(:, :)
      type(error_t), intent(inout) :: problems
      type(rng_t) :: rng
      real(wp) :: u
      integer :: j, run, n

      call reserve(points, size(vars), n_runs, problems)
      if (problems%failed()) return
      call rng_seed(rng, seed)
      do run = 1, n_runs
         do j = 1, size(vars)
            call rng_uniform(rng, u)
            if (has_list(vars(j))) then
               n = size(vars(j)%values)
               points(j, run) = vars(j)%values(min(n, 1 + int(u*n)))
            else
               points(j, run) = in_range(vars(j), vars(j)%low + (vars(j)%high - vars(j)%low)*u)
            end if
         end do
      end do
   end subroutine random_points

   !> LHS: variable by variable, a point in each stratum, then the strata
   !! shuffled over the runs.
   subroutine lhs_points(vars, n_runs, seed, points, problems)
      type(study_variable_t), intent(in) :: vars(:)
      integer, intent(in) :: n_runs, seed
      real(wp), allocatable, intent(inout) :: points(:, :)
      type(error_t), intent(inout) :: problems
      type(rng_t) :: rng
      real(wp), allocatable :: strata(:)
      integer, allocatable :: perm(:)
      real(wp) :: u
      integer :: j, k, i, m, swap, stat

      call reserve(points, size(vars), n_runs, problems)
      if (problems%failed()) return
      allocate (strata(n_runs), perm(n_runs), stat=stat)
      if (stat /= 0) then
         call error_append(problems, exit_deck, 'no memory for the LHS study''s '//itoa(n_runs)//' strata')
         return
      end if
      call rng_seed(rng, seed)
      do j = 1, size(vars)
         associate (v => vars(j))
            if (has_list(v)) then
               do k = 1, n_runs
                  strata(k) = v%values(1 + mod(k - 1, size(v%values)))
               end do
            else
               do k = 1, n_runs
                  call rng_uniform(rng, u)
                  strata(k) = in_range(v, v%low + (v%high - v%low)*((real(k - 1, wp) + u)/real(n_runs, wp)))
               end do
            end if
         end associate
         perm = [(k, k = 1, n_runs)]
         do i = n_runs, 2, -1   ! Fisher-Yates
            call rng_uniform(rng, u)
            m = min(i, 1 + int(u*real(i, wp)))
            swap = perm(i)
            perm(i) = perm(m)
            perm(m) = swap
         end do
         points(j, :) = strata(perm)
      end do
   end subroutine lhs_points

   !> ENSEMBLE: the base, then normal perturbations clipped to the bounds.
   subroutine ensemble_points(vars, n_runs, seed, points, problems)
      type(study_variable_t), intent(in) :: vars(:)
      integer, intent(in) :: n_runs, seed
      real(wp), allocatable, intent(inout) :: points(:, :)
      type(error_t), intent(inout) :: problems
      type(rng_t) :: rng
      real(wp) :: z
      integer :: j, run

      call reserve(points, size(vars), n_runs, problems)
      if (problems%failed()) return
      call rng_seed(rng, seed)
      points(:, 1) = vars(:)%base
      do run = 2, n_runs
         do j = 1, size(vars)
            call rng_normal(rng, z)
            points(j, run) = in_range(vars(j), vars(j)%base + vars(j)%spread*z)
         end do
      end do
   end subroutine ensemble_points

   !> The number of a variable's values for OAT and GRID.
   pure integer(i8) function value_count(v)
      type(study_variable_t), intent(in) :: v
      if (has_list(v)) then
         value_count = size(v%values)
      else
         value_count = v%count
      end if
   end function value_count

   !> A variable's values for OAT and GRID, in order.
   pure function variable_values(v) result(values)
      type(study_variable_t), intent(in) :: v
      real(wp), allocatable :: values(:)
      integer :: i
      allocate (values(value_count(v)))
      do i = 1, size(values)
         values(i) = variable_value(v, i)
      end do
   end function variable_values

   !> A variable's i-th value: its list's, or the i-th of COUNT even steps
   !! from LOW to HIGH (the ends exactly; one value: the midpoint).
   pure real(wp) function variable_value(v, i) result(x)
      type(study_variable_t), intent(in) :: v
      integer, intent(in) :: i
      if (has_list(v)) then
         x = v%values(i)
      else if (v%count == 1) then
         x = 0.5_wp*(v%low + v%high)
      else if (i == 1) then
         x = v%low
      else if (i == v%count) then
         x = v%high
      else
         x = in_range(v, v%low + (v%high - v%low)*(real(i - 1, wp)/real(v%count - 1, wp)))
      end if
   end function variable_value

   !> A value clipped to the variable's bounds.
   pure real(wp) function in_range(v, x)
      type(study_variable_t), intent(in) :: v
      real(wp), intent(in) :: x
      in_range = min(max(x, v%low), v%high)
   end function in_range

   pure logical function has_list(v)
      type(study_variable_t), intent(in) :: v
      has_list = .false.
      if (allocated(v%values)) has_list = size(v%values) > 0
   end function has_list

   !> A number, not NaN, within +-value_limit.
   elemental logical function usable(x)
      real(wp), intent(in) :: x
      usable = .false.
      if (.not. ieee_is_nan(x)) usable = abs(x) <= value_limit
   end function usable

   pure function method_name(method) result(name)
      integer, intent(in) :: method
      character(len=:), allocatable :: name
      character(len=*), parameter :: names(5) = ['OAT     ', 'GRID    ', 'RANDOM  ', 'LHS     ', 'ENSEMBLE']
      name = trim(names(method))
   end function method_name




   pure function identity() result(e)
      integer(i8) :: e(3, 3)
      integer :: i
      e = 0
      do i = 1, 3
         e(i, i) = 1
      end do
   end function identity

   !> a*b mod m for a, b in [0, m), m < 2^32, without a product above 2^49:
   !! b is split into its high and low 16 bits.
   pure integer(i8) function mul_mod(a, b, m)
      integer(i8), intent(in) :: a, b, m
      integer(i8), parameter :: two16 = 65536_i8
      integer(i8) :: high
      high = b/two16
      mul_mod = modulo(a*high, m)
      mul_mod = modulo(mul_mod*two16, m)
      mul_mod = modulo(mul_mod + a*(b - high*two16), m)
   end function mul_mod

   pure function mat_mul_mod(a, b, m) result(c)
      integer(i8), intent(in) :: a(3, 3), b(3, 3), m
      integer(i8) :: c(3, 3)
      integer :: i, j, k
      c = 0
      do j = 1, 3
         do i = 1, 3
            do k = 1, 3
               c(i, j) = modulo(c(i, j) + mul_mod(a(i, k), b(k, j), m), m)
            end do
         end do
      end do
   end function mat_mul_mod

   pure function mat_vec_mod(a, x, m) result(y)
      integer(i8), intent(in) :: a(3, 3), x(3), m
      integer(i8) :: y(3)
      integer :: i, k
      y = 0
      do i = 1, 3
         do k = 1, 3
            y(i) = modulo(y(i) + mul_mod(a(i, k), x(k), m), m)
         end do
      end do
   end function mat_vec_mod
end module study_sampling
