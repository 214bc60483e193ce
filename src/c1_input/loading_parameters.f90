!> The parameters of a loading law as a deck gives them (report C.4.e, C.4.f;
!! docs/loading.md): a loading curve - its form (NLOAD = 1 polynomial, 2
!! table), its coefficients or points and its rate terms - and the checks
!! every curve and every G, R pair must pass. They sit beside the model's
!! section types (C.1), which hold the deck's curves; the evaluation of a
!! curve and of recurrent loading is C.4's (loading_curves,
!! recurrent_loading).
module loading_parameters
   use kinds, only: wp
   use strings, only: itoa, num
   use error_handling, only: error_t, error_set, exit_deck
   implicit none
   private

   public :: loading_curve_t, curve_none, curve_polynomial, curve_table, max_order, x_far
   public :: curve_is_defined, curve_check, polynomial_minimum, recurrent_check, ratio_slack

   !> Forms of a curve: NLOAD = 1 and 2 of *OPTIONS (C.1).
   integer, parameter :: curve_none = 0, curve_polynomial = 1, curve_table = 2
   !> Highest polynomial order N ("fifth-order polynomials", C.4.f).
   integer, parameter :: max_order = 5
   !> Beyond any deformation or rate that means something (in, in/s): the
   !! searches stop there, so that no polynomial of the deck overflows.
   real(wp), parameter :: x_far = 1.0e50_wp

   !> One loading curve. Units: d in in, v in in/s, F in lb.
   type :: loading_curve_t
      integer :: form = curve_none
      integer :: order = 0                        !< N (polynomial)
      real(wp) :: sigma(max_order) = 0.0_wp       !< sigma_1..sigma_N (lb/in**n)
      real(wp) :: sigma_rate(max_order) = 0.0_wp  !< sigma_{N+1}..sigma_{2N} (lb*s**k/in**k)
      real(wp), allocatable :: defl(:)            !< table: deformations d_i (in)
      real(wp), allocatable :: force(:)           !< table: forces F_i (lb)
   end type loading_curve_t

   !> G and R that differ from the consistent R = 1 - G by less than this are
   !! taken as consistent (decks give decimals: 1 - 0.3 is not 0.7 in binary).
   real(wp), parameter :: ratio_slack = 1.0e-12_wp

contains

   !> True when the curve has been given (a polynomial or a table).
   pure logical function curve_is_defined(c)
      type(loading_curve_t), intent(in) :: c
      curve_is_defined = c%form == curve_polynomial .or. c%form == curve_table
   end function curve_is_defined

   !> What is wrong with a curve (docs/loading.md 2): a deck error in err,
   !! without location (the validator puts it at the curve's card and
   !! fields). point: the table point (or, for a polynomial, the
   !! coefficient) concerned, 0 when the whole curve is or none is wrong.
   pure subroutine curve_check(c, point, err)
      type(loading_curve_t), intent(in) :: c
      integer, intent(out) :: point
      type(error_t), intent(inout) :: err
      real(wp) :: dq(0:max_order - 1), q_min, at
      integer :: k, n
      point = 0
      if (any(c%sigma_rate < 0.0_wp)) then
         point = minloc(c%sigma_rate, 1)
         call error_set(err, exit_deck, 'a rate coefficient is negative: the rate term would feed energy into ' &
                        //'the motion')
         return
      end if
      select case (c%form)
      case (curve_polynomial)
         if (c%order < 1 .or. c%order > max_order) then
            call error_set(err, exit_deck, 'the order N must be from 1 to '//itoa(max_order))
            return
         end if
         if (any(abs(c%sigma(c%order + 1:)) > 0.0_wp)) then
            point = c%order + findloc(abs(c%sigma(c%order + 1:)) > 0.0_wp, .true., 1)
            call error_set(err, exit_deck, 'coefficient '//itoa(point)//' lies beyond the order N = '//itoa(c%order))
            return
         end if
         if (.not. any(abs(c%sigma) > 0.0_wp)) then
            call error_set(err, exit_deck, 'every coefficient is zero: the curve gives no force')
            return
         end if
         ! F_e' = sum n sigma_n d**(n-1) >= 0 on d >= 0: F_e never decreases, and never pulls
         dq = 0.0_wp
         do k = 1, c%order
            dq(k - 1) = real(k, wp)*c%sigma(k)
         end do
         call polynomial_minimum(dq(0:c%order - 1), q_min, at)
         if (at >= huge(1.0_wp)) then
            call error_set(err, exit_deck, 'the force decreases, and finally pulls, as the deformation grows ' &
                           //'(the highest coefficient is negative)')
         else if (q_min < -1.0e-12_wp*maxval(abs(dq))*max(1.0_wp, at)**(c%order - 1)) then
            ! (the tolerance: rounding in F_e' at d = at)
            call error_set(err, exit_deck, 'the force decreases with the deformation near d = '//num(at, 6) &
                           //' in (slope '//num(q_min, 6)//' lb/in); a loading curve must not decrease, ' &
                           //'so that it never pulls')
         end if
      case (curve_table)
         if (.not. (allocated(c%defl) .and. allocated(c%force))) then
            call error_set(err, exit_deck, 'the table has no points')
            return
         end if
         n = size(c%defl)
         if (n < 2 .or. size(c%force) /= n) then
            point = n
            call error_set(err, exit_deck, 'a table needs at least two points')
            return
         end if
         if (abs(c%defl(1)) > 0.0_wp .or. abs(c%force(1)) > 0.0_wp) then
            point = 1
            call error_set(err, exit_deck, 'the first point must be (0, 0)')
            return
         end if
         do k = 2, n
            point = k
            if (.not. c%defl(k) > c%defl(k - 1)) then
               call error_set(err, exit_deck, 'the deformations must increase from point to point')
               return
            end if
            if (c%force(k) < c%force(k - 1)) then
               call error_set(err, exit_deck, 'the force must not decrease from point to point (a loading curve ' &
                              //'never pulls)')
               return
            end if
         end do
         point = 0
         if (.not. c%force(n) > 0.0_wp) call error_set(err, exit_deck, 'every force is zero: the curve gives no force')
      case default
         call error_set(err, exit_deck, 'the curve is not defined')
      end select
   end subroutine curve_check

   !> The minimum of q(x) = sum c(j) x**j over 0 <= x <= x_far, and where it
   !! is (at = huge when q falls without bound). Exact up to rounding: q's
   !! minimum lies at 0 or at a real root of q' (found by isolating the
   !! roots of each derivative between those of the next), all of which lie
   !! within the Cauchy bound of q' (beyond x_far = 1e50 only when the
   !! highest coefficient is some 1e50 times smaller than the others: a
   !! deformation far beyond any meaning).
   pure subroutine polynomial_minimum(c, q_min, at)
      real(wp), intent(in) :: c(0:)
      real(wp), intent(out) :: q_min, at
      real(wp) :: dc(0:max(size(c) - 2, 0)), roots(max(size(c), 1)), bound, q
      integer :: n, j, nr
      n = degree(c)
      q_min = c(0)
      at = 0.0_wp
      if (n <= 0) return
      if (c(n) < 0.0_wp) then
         q_min = -huge(1.0_wp)
         at = huge(1.0_wp)
         return
      end if
      if (n == 1) return   ! rising line: its minimum is at 0
      do j = 1, n
         dc(j - 1) = real(j, wp)*c(j)
      end do
      ! every critical point lies within the Cauchy bound of q' (searched up
      ! to x_far at most, so that q never overflows there)
      bound = x_far
      if (maxval(abs(dc(0:n - 2))) < x_far*abs(dc(n - 1))) &
         bound = 1.0_wp + maxval(abs(dc(0:n - 2)))/abs(dc(n - 1))
      call real_roots(dc(0:n - 1), 0.0_wp, bound, roots, nr)
      do j = 1, nr
         q = horner(c(0:n), roots(j))
         if (q < q_min) then
            q_min = q
            at = roots(j)
         end if
      end do
   end subroutine polynomial_minimum

   ! --- helpers ------------------------------------------------------------

   !> The real roots of sum c(j) x**j in the open interval (a, b), increasing.
   !! Between consecutive roots of the derivative (and a, b) the polynomial
   !! is monotone: each sign change there holds one root, found by bisection.
   pure recursive subroutine real_roots(c, a, b, roots, nr)
      real(wp), intent(in) :: c(0:), a, b
      real(wp), intent(inout) :: roots(:)
      integer, intent(out) :: nr
      real(wp) :: dc(0:max(size(c) - 2, 0)), knots(size(c) + 1), lo, hi, mid, flo, fmid
      integer :: n, j, nk, it
      nr = 0
      n = degree(c)
      if (n <= 0) return
      if (n == 1) then
         if (abs(c(0)) < max(abs(a), abs(b))*abs(c(1))) then   ! the root is finite
            mid = -c(0)/c(1)
            if (mid > a .and. mid < b) then
               nr = 1
               roots(1) = mid
            end if
         end if
         return
      end if
      do j = 1, n
         dc(j - 1) = real(j, wp)*c(j)
      end do
      call real_roots(dc(0:n - 1), a, b, knots(2:), nk)
      knots(1) = a
      knots(nk + 2) = b
      do j = 1, nk + 1
         lo = knots(j)
         hi = knots(j + 1)
         flo = horner(c(0:n), lo)
         if (j > 1 .and. .not. abs(flo) > 0.0_wp) then
            nr = nr + 1
            roots(nr) = lo
            cycle
         end if
         if (flo*horner(c(0:n), hi) >= 0.0_wp) cycle
         do it = 1, 200
            mid = 0.5_wp*(lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            fmid = horner(c(0:n), mid)
            if (.not. abs(fmid) > 0.0_wp) exit
            if (fmid*flo < 0.0_wp) then
               hi = mid
            else
               lo = mid
               flo = fmid
            end if
         end do
         nr = nr + 1
         roots(nr) = mid
      end do
   end subroutine real_roots

   pure integer function degree(c) result(n)
      real(wp), intent(in) :: c(0:)
      do n = ubound(c, 1), 0, -1
         if (abs(c(n)) > 0.0_wp) return
      end do
      n = -1
   end function degree

   pure real(wp) function horner(c, x) result(q)
      real(wp), intent(in) :: c(0:), x
      integer :: j
      q = 0.0_wp
      do j = ubound(c, 1), 0, -1
         q = q*x + c(j)
      end do
   end function horner

   !> What is wrong with G and R (docs/loading.md 3), as a deck error in err
   !! without location (the validator puts it at the card's G and R): 0 <= G <= 1,
   !! 0 <= R <= 1, R <= 1 - G, and G = 1 where R = 0. An unloading curve that ends at G d_max and
   !! does not rise above the loading curve returns at most (1 - G) times the
   !! loading work along the curves of docs/loading.md; more would need an
   !! unloading path above the loading path, which would create energy on the
   !! next reloading.
   pure subroutine recurrent_check(g, r, err)
      real(wp), intent(in) :: g, r
      type(error_t), intent(inout) :: err
      if (g < 0.0_wp .or. g > 1.0_wp) then
         call error_set(err, exit_deck, 'G = '//num(g)//' must lie from 0 to 1')
      else if (r < 0.0_wp .or. r > 1.0_wp) then
         call error_set(err, exit_deck, 'R = '//num(r)//' must lie from 0 to 1')
      else if (r <= 0.0_wp .and. g < 1.0_wp - ratio_slack) then
         call error_set(err, exit_deck, 'R = 0 needs G = 1 (here G = '//num(g)//'): an element that returns ' &
                        //'none of the energy it absorbed falls straight to zero force at its maximum deformation ' &
                        //'and keeps all of it (docs/loading.md 3)')
      else if (r > 1.0_wp - g + ratio_slack) then
         call error_set(err, exit_deck, 'R = '//num(r)//' exceeds 1 - G = '//num(1.0_wp - g)//': an element ' &
                        //'that keeps G of its maximum deformation cannot return more than 1 - G of the energy ' &
                        //'it absorbed (docs/loading.md 3)')
      end if
   end subroutine recurrent_check
end module loading_parameters
