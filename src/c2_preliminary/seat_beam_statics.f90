!> Report C.4.d, the rigid-beam seat at t = 0: the six relations among the
!! ten quantities a, a', W_o, F-hat'_so, F_so, F'_so, Delta_so, Delta_zo,
!! y_go, gamma_o ("any four of the remaining ten will determine the other
!! six"), solved for the six the deck does not give. Erratum A-RB: not every
!! choice of four determines the rest (F_so and Delta_so are tied by the
!! support law, F'_so and Delta_zo too); such a choice is found before any
!! arithmetic, by a one-to-one assignment of relations to unknowns, and
!! refused with a message. The model builder calls this (rigid_beam_statics)
!! once the seat's section is built and checked: a choice that does not
!! determine the rest, or has no physical solution, is a deck error (an
!! error_t, exit_deck, without location: the seat's validator adds the
!! card and fields).
module seat_beam_statics
   use kinds, only: wp, pi
   use error_handling, only: error_t, error_set, exit_deck
   use model, only: seat_section_t, n_beam_quantities, beam_quantity_name, bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, &
      bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   implicit none
   private

   public :: beam_statics_t, beam_statics_solve, beam_residuals
   public :: n_beam_quantities, n_beam_relations, beam_quantity_name, beam_relation_text
   public :: bq_a, bq_ap, bq_w0, bq_fhps0, bq_fs0, bq_fps0, bq_ds0, bq_dz0, bq_yg0, bq_gamma0
   public :: poly_force, rigid_beam_statics

   integer, parameter :: n_beam_relations = 6
   character(len=64), parameter :: beam_relation_text(n_beam_relations) = [character(len=64) :: &
      'F_so + F''_so = W_o + F-hat''_so + m_s g', &
      'a''(F''_so - F-hat''_so) + (a'' - a)F_so + W_o(z_o - a'') = 0', &
      'F_so = beta_1 Delta_so + beta_2 Delta_so**2 + beta_3 Delta_so**3', &
      'F''_so = s Delta_zo', &
      'Delta_so = y_gu - y_go + (a - a'')(tan gamma_o - tan gamma_u)', &
      'Delta_zo = y_gu - y_go + a''(tan gamma_u - tan gamma_o)']
   !> Which quantities each relation involves.
   logical, parameter :: incidence(n_beam_relations, n_beam_quantities) = reshape([ &
      ! a       a'      W_o     F^'so   F_so    F'_so   D_so    D_zo    y_go    gamma_o
      .false., .true., .false., .false., .true., .false., &     ! a      (relations 1..6)
      .false., .true., .false., .false., .true., .true., &      ! a'
      .true., .true., .false., .false., .false., .false., &     ! W_o
      .true., .true., .false., .false., .false., .false., &     ! F-hat'_so
      .true., .true., .true., .false., .false., .false., &      ! F_so
      .true., .true., .false., .true., .false., .false., &      ! F'_so
      .false., .false., .true., .false., .true., .false., &     ! Delta_so
      .false., .false., .false., .true., .false., .true., &     ! Delta_zo
      .false., .false., .false., .false., .true., .true., &     ! y_go
      .false., .false., .false., .false., .true., .true.], &    ! gamma_o
      [n_beam_relations, n_beam_quantities])

   !> What is measured (C.4.d: z_o, m_s, y_gu, gamma_u, s and the beta_m) and
   !! the apparent gravity g cos(Phi_o) in the interior frame.
   type :: beam_statics_t
      real(wp) :: z0 = 0.0_wp, m_s = 0.0_wp, g = 0.0_wp
      real(wp) :: y_gu = 0.0_wp, gamma_u = 0.0_wp, s = 0.0_wp, beta(3) = 0.0_wp
   end type beam_statics_t

contains

   !> C.4.d (A-S3): the seat cushion's polynomial sum beta_m u^m.
   pure real(wp) function poly_force(beta, u)
      real(wp), intent(in) :: beta(3), u
      poly_force = u*(beta(1) + u*(beta(2) + u*beta(3)))
   end function poly_force

   !> The rigid-beam seat at t = 0 (C.4.d, A-RB): the four of the ten
   !! quantities that seat section p gives (beam_given), the other six
   !! solved for and set in p, under the apparent gravity g (g cos(Phi_o)
   !! in the interior frame). err as beam_statics_solve's; p is unchanged
   !! when it fails (err comes in with nothing recorded).
   pure subroutine rigid_beam_statics(p, g, err)
      type(seat_section_t), intent(inout) :: p
      real(wp), intent(in) :: g
      type(error_t), intent(inout) :: err
      real(wp) :: q(n_beam_quantities)
      q = merge([p%a, p%a_prime, p%w0, p%fhps0, p%fs0, p%fps0, p%ds0, p%dz0, p%yg0, p%gamma0], 0.0_wp, p%beam_given)
      call beam_statics_solve(beam_statics_t(z0=p%z0, m_s=p%m_s, g=g, y_gu=p%y_gu, gamma_u=p%gamma_u, s=p%s, &
                                             beta=p%beta), p%beam_given, q, err)
      if (err%failed()) return
      p%a = q(bq_a)
      p%a_prime = q(bq_ap)
      p%w0 = q(bq_w0)
      p%fhps0 = q(bq_fhps0)
      p%fs0 = q(bq_fs0)
      p%fps0 = q(bq_fps0)
      p%ds0 = q(bq_ds0)
      p%dz0 = q(bq_dz0)
      p%yg0 = q(bq_yg0)
      p%gamma0 = q(bq_gamma0)
   end subroutine rigid_beam_statics

   !> The six relations at q (q(bq_gamma0) is the angle), scaled to be of
   !! order one: forces by f_ref, moments by f_ref z_o, lengths by z_o.
   pure subroutine beam_residuals(p, q, r)
      type(beam_statics_t), intent(in) :: p
      real(wp), intent(in) :: q(n_beam_quantities)
      real(wp), intent(out) :: r(n_beam_relations)
      real(wp) :: f_ref, l_ref, tg, tu
      f_ref = max(1.0_wp, p%m_s*p%g, abs(q(bq_w0)), abs(q(bq_fs0)))
      l_ref = max(1.0_wp, p%z0)
      tg = tan(q(bq_gamma0))
      tu = tan(p%gamma_u)
      ! C.4.d, the m_s y_g'' equation at rest
      r(1) = (q(bq_fs0) + q(bq_fps0) - q(bq_w0) - q(bq_fhps0) - p%m_s*p%g)/f_ref
      ! C.4.d, the I_s gamma'' equation at rest, with RB-1 (z - a') and z(0) = z_o
      r(2) = (q(bq_ap)*(q(bq_fps0) - q(bq_fhps0)) + (q(bq_ap) - q(bq_a))*q(bq_fs0) &
              + q(bq_w0)*(p%z0 - q(bq_ap)))/(f_ref*l_ref)
      ! C.4.d, F_s = sum beta_m Delta_s**m (at rest: no damper) and F'_s = s Delta_z
      r(3) = (q(bq_fs0) - poly_force(p%beta, q(bq_ds0)))/f_ref
      r(4) = (q(bq_fps0) - p%s*q(bq_dz0))/f_ref
      ! C.4.d, Delta_s and Delta_z of the tan-gamma kinematics
      r(5) = (q(bq_ds0) - (p%y_gu - q(bq_yg0) + (q(bq_a) - q(bq_ap))*(tg - tu)))/l_ref
      r(6) = (q(bq_dz0) - (p%y_gu - q(bq_yg0) + q(bq_ap)*(tu - tg)))/l_ref
   end subroutine beam_residuals

   !> Solve for the quantities not given. q holds the given ones on entry and
   !! all ten when solved; otherwise err (a deck error) says why: not four
   !! given, four that do not determine the other six, or no physical
   !! solution (q then unchanged).
   pure subroutine beam_statics_solve(p, given, q, err)
      type(beam_statics_t), intent(in) :: p
      logical, intent(in) :: given(n_beam_quantities)
      real(wp), intent(inout) :: q(n_beam_quantities)
      type(error_t), intent(inout) :: err
      integer :: unknown(n_beam_relations), n, j, start
      real(wp) :: trial(n_beam_quantities)
      logical :: converged

      if (count(given) /= 4) then
         call error_set(err, exit_deck, 'give exactly four of the ten quantities ' &
                        //names_of(spread(.true., 1, n_beam_quantities))//' (found '//names_of(given)//')')
         return
      end if
      n = 0
      do j = 1, n_beam_quantities
         if (.not. given(j)) then
            n = n + 1
            unknown(n) = j
         end if
      end do
      if (.not. assignable(unknown)) then
         call error_set(err, exit_deck, 'the four given ('//names_of(given)//') do not determine the other six (' &
                        //names_of(.not. given)//')'//tied_text())
         return
      end if
      ! Newton from a few starting points; the first solution that is physical wins
      do start = 1, 4
         trial = q
         call first_guess(p, given, start, trial)
         call newton(p, unknown, trial, converged)
         if (converged) then
            if (physical(trial)) then
               q = trial
               return
            end if
         end if
      end do
      call error_set(err, exit_deck, 'no physical solution of the six relations for '//names_of(.not. given) &
                     //' from the four given ('//names_of(given)//'): a, a'' > 0, forces and deflections >= 0, ' &
                     //'|gamma_o| <= 45 deg')
   contains
      !> A relation among given quantities only makes the rest undetermined.
      pure function tied_text() result(t)
         character(len=:), allocatable :: t
         integer :: i
         t = ''
         do i = 1, n_beam_relations
            if (.not. any(incidence(i, :) .and. .not. given)) &
               t = t//'; relation '//trim(beam_relation_text(i))//' involves given quantities only'
         end do
      end function tied_text
   end subroutine beam_statics_solve

   !> A one-to-one assignment of the six relations to the six unknowns exists
   !! (augmenting paths): otherwise the relations cannot fix them all.
   pure logical function assignable(unknown)
      integer, intent(in) :: unknown(n_beam_relations)
      integer :: owner(n_beam_relations), i
      logical :: seen(n_beam_relations), found
      owner = 0      ! owner(u): the relation assigned to unknown u
      assignable = .true.
      do i = 1, n_beam_relations
         seen = .false.
         call augment(i, owner, seen, found)
         if (.not. found) then
            assignable = .false.
            return
         end if
      end do
   contains
      pure recursive subroutine augment(rel, own, visited, found)
         integer, intent(in) :: rel
         integer, intent(inout) :: own(n_beam_relations)
         logical, intent(inout) :: visited(n_beam_relations)
         logical, intent(out) :: found
         integer :: u, holder
         logical :: deeper
         found = .false.
         do u = 1, n_beam_relations
            if (.not. incidence(rel, unknown(u)) .or. visited(u)) cycle
            visited(u) = .true.
            if (own(u) == 0) then
               own(u) = rel
               found = .true.
               return
            end if
            holder = own(u)       ! a copy: own changes inside
            call augment(holder, own, visited, deeper)
            if (deeper) then
               own(u) = rel
               found = .true.
               return
            end if
         end do
      end subroutine augment
   end function assignable

   !> Starting values of the unknowns: a typical seat (a' mid-seat, a near its
   !! back, loads a fraction of the weight an adult puts on a seat), scaled by
   !! the start number.
   pure subroutine first_guess(p, given, start, q)
      type(beam_statics_t), intent(in) :: p
      logical, intent(in) :: given(n_beam_quantities)
      integer, intent(in) :: start
      real(wp), intent(inout) :: q(n_beam_quantities)
      real(wp) :: guess(n_beam_quantities), f
      real(wp), parameter :: scale(4) = [1.0_wp, 0.3_wp, 3.0_wp, 0.1_wp]
      f = 100.0_wp*scale(start)
      guess = [1.3_wp*p%z0, 0.6_wp*p%z0, f, 0.3_wp*f, f + 0.5_wp*p%m_s*p%g, 0.3_wp*f + 0.5_wp*p%m_s*p%g, &
               0.5_wp*scale(start), 0.5_wp*scale(start), p%y_gu - 0.5_wp*scale(start), p%gamma_u]
      where (.not. given) q = guess
   end subroutine first_guess

   !> Damped Newton on the unknowns (central-difference Jacobian, Gaussian
   !! elimination with partial pivoting). True when the scaled residual
   !! falls below 1e-12.
   pure subroutine newton(p, unknown, q, ok)
      type(beam_statics_t), intent(in) :: p
      integer, intent(in) :: unknown(n_beam_relations)
      real(wp), intent(inout) :: q(n_beam_quantities)
      logical, intent(out) :: ok
      real(wp) :: r(n_beam_relations), rp(n_beam_relations), rm(n_beam_relations), jac(n_beam_relations, n_beam_relations)
      real(wp) :: dx(n_beam_relations), trial(n_beam_quantities), h, norm0, lambda
      integer :: iter, j, halving
      logical :: solved
      ok = .false.
      call beam_residuals(p, q, r)
      do iter = 1, 100
         norm0 = maxval(abs(r))
         if (norm0 < 1.0e-12_wp) then
            ok = .true.
            return
         end if
         do j = 1, n_beam_relations
            h = 1.0e-6_wp*max(1.0_wp, abs(q(unknown(j))))
            trial = q
            trial(unknown(j)) = q(unknown(j)) + h
            call beam_residuals(p, trial, rp)
            trial(unknown(j)) = q(unknown(j)) - h
            call beam_residuals(p, trial, rm)
            jac(:, j) = (rp - rm)/(2.0_wp*h)
         end do
         call gauss_solve(jac, -r, dx, solved)
         if (.not. solved) return
         lambda = 1.0_wp
         do halving = 1, 30
            trial = q
            trial(unknown) = q(unknown) + lambda*dx
            ! the angle stays where tan is finite
            trial(bq_gamma0) = max(-1.4_wp, min(1.4_wp, trial(bq_gamma0)))
            call beam_residuals(p, trial, rp)
            if (maxval(abs(rp)) < norm0) exit
            lambda = 0.5_wp*lambda
         end do
         if (.not. maxval(abs(rp)) < norm0) return
         q = trial
         r = rp
      end do
   end subroutine newton

   !> a x = b for a small dense a; solved false when a pivot vanishes.
   pure subroutine gauss_solve(a, b, x, solved)
      real(wp), intent(in) :: a(:, :), b(:)
      real(wp), intent(out) :: x(:)
      logical, intent(out) :: solved
      real(wp) :: m(size(b), size(b) + 1), row(size(b) + 1), piv
      integer :: n, k, i, ip
      n = size(b)
      m(:, 1:n) = a
      m(:, n + 1) = b
      x = 0.0_wp
      solved = .false.
      do k = 1, n
         ip = k - 1 + maxloc(abs(m(k:n, k)), dim=1)
         piv = m(ip, k)
         if (.not. abs(piv) > 1.0e-14_wp*max(1.0_wp, maxval(abs(m(:, 1:n))))) return
         if (ip /= k) then
            row = m(k, :)
            m(k, :) = m(ip, :)
            m(ip, :) = row
         end if
         do i = k + 1, n
            m(i, k:) = m(i, k:) - m(i, k)/piv*m(k, k:)
         end do
      end do
      do k = n, 1, -1
         x(k) = (m(k, n + 1) - sum(m(k, k + 1:n)*x(k + 1:n)))/m(k, k)
      end do
      solved = .true.
   end subroutine gauss_solve

   !> a, a' > 0; loads and deflections >= 0 (a cushion does not pull); the
   !! beam no steeper than 45 degrees.
   pure logical function physical(q)
      real(wp), intent(in) :: q(n_beam_quantities)
      real(wp), parameter :: slack = -1.0e-9_wp
      physical = q(bq_a) > 0.0_wp .and. q(bq_ap) > 0.0_wp .and. &
                 all(q([bq_w0, bq_fhps0, bq_fs0, bq_fps0, bq_ds0, bq_dz0]) >= slack) .and. &
                 abs(q(bq_gamma0)) <= 0.25_wp*pi + 1.0e-12_wp
   end function physical

   !> "A, AP, W0" for the quantities selected, or all of them.
   pure function names_of(selected) result(t)
      logical, intent(in) :: selected(n_beam_quantities)
      character(len=:), allocatable :: t
      integer :: j
      t = ''
      do j = 1, n_beam_quantities
         if (.not. selected(j)) cycle
         if (len(t) > 0) t = t//', '
         t = t//trim(beam_quantity_name(j))
      end do
      if (len(t) == 0) t = 'none'
   end function names_of

end module seat_beam_statics
