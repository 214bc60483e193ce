!> How accurate a fixed-step run was (issue 15, section 2;
!! docs/accuracy.md): the local error estimates of the accepted steps (the
!! stepper's local_error) and the jumps of the right-hand side at the
!! steps' ends (switches an effect's memory took up to a step late),
!! accumulated into estimates of the errors of what a user reads: the joint
!! angles (degrees) and the head's peak acceleration (relative). Past a
!! threshold the run warns (accuracy_warnings), as it does when the
!! corrector reached its iteration limit (corrector_warning).
!!
!! The propagation is free motion: an error of a rate made at t_k has moved
!! its coordinate by (t - t_k) times itself at t. Restraints and contacts
!! pull errors back, so the estimate is an upper one for them (measured on
!! the shipped decks: docs/accuracy.md).
module accuracy_estimate
   use kinds, only: wp, i8, deg, g_std
   use model, only: n_dof, n_joint, joint_partner, joint_name
   use strings, only: num, itoa
   use text_io, only: string_t, append_string
   use ode_system, only: step_stats_t
   use effect_events, only: event_t
   use contact_events, only: event_ramp_widened
   implicit none
   private

   public :: accuracy_t, accuracy_warnings, corrector_warning, suggested_step, widened_ramp_warning
   public :: angle_threshold, head_threshold

   !> Thresholds past which a run warns (docs/accuracy.md, "Thresholds"):
   !! an estimated joint-angle error of 1 degree, an estimated error of the
   !! head's peak of 5 % of the peak.
   real(wp), parameter :: angle_threshold = 1.0_wp*deg
   real(wp), parameter :: head_threshold = 0.05_wp
   !> The head's sensitivity to the estimated state error is taken again
   !! each time its peak so far grows by this factor, from 1 g.
   real(wp), parameter :: head_regrowth = 1.05_wp

   !> One occupant's accumulated estimates.
   type :: accuracy_t
      logical :: on = .false.                !< the stepper gives local error estimates
      integer(i8) :: steps = 0               !< accepted steps estimated
      integer(i8) :: switches = 0            !< jumps of the right-hand side at a step's end counted
      !> the steps' truncation: sums over the accepted steps k of |local
      !! error| of z and of z', and of |local error of z'| t_k (so that
      !! their free propagation to t is vel*t - vel_t)
      real(wp) :: pos(n_dof) = 0.0_wp, vel(n_dof) = 0.0_wp, vel_t(n_dof) = 0.0_wp
      !> the same sums signed (the direction of the state error, for the
      !! head's sensitivity)
      real(wp) :: pos_s(n_dof) = 0.0_wp, vel_s(n_dof) = 0.0_wp, vel_t_s(n_dof) = 0.0_wp
      !> switches taken at the end of a step: each jump dz'' of the
      !! right-hand side at t_k, with a step h before it, missed on average
      !! h/2 of its impulse: sums of h/2 dz'' and of h/2 dz'' t_k, signed
      !! (a switch that chatters back undoes its predecessor)
      real(wp) :: late(n_dof) = 0.0_wp, late_t(n_dof) = 0.0_wp
      !> the head acceleration's change when the state is moved by its
      !! estimated error, at the accepted point where its peak so far was
      !! last taken (in/s^2), that acceleration, and the evaluations it cost
      real(wp) :: head_error = 0.0_wp, head_error_at = 0.0_wp
      integer(i8) :: head_evaluations = 0
   contains
      procedure :: add_step => accuracy_add_step
      procedure :: add_switch => accuracy_add_switch
      procedure :: truncation => accuracy_truncation
      procedure :: switching => accuracy_switching
      procedure :: joint_truncation => accuracy_joint_truncation
      procedure :: joint_switching => accuracy_joint_switching
      procedure :: joint_angle => accuracy_joint_angle
      procedure :: worst_joint => accuracy_worst_joint
      procedure :: state_error => accuracy_state_error
      procedure :: head_due => accuracy_head_due
      procedure :: head_relative => accuracy_head_relative
   end type accuracy_t

contains

   !> The step accepted at t with local error estimates le_z, le_zdot of
   !! z and z' (the stepper's, this occupant's slices).
   pure subroutine accuracy_add_step(this, t, le_z, le_zdot)
      class(accuracy_t), intent(inout) :: this
      real(wp), intent(in) :: t, le_z(n_dof), le_zdot(n_dof)
      this%on = .true.
      this%steps = this%steps + 1
      this%pos = this%pos + abs(le_z)
      this%vel = this%vel + abs(le_zdot)
      this%vel_t = this%vel_t + abs(le_zdot)*t
      this%pos_s = this%pos_s + le_z
      this%vel_s = this%vel_s + le_zdot
      this%vel_t_s = this%vel_t_s + le_zdot*t
   end subroutine accuracy_add_step

   !> The right-hand side jumped by dzdd (z'') at the accepted point t, the
   !! end of a step of size h inside which the switch happened (an effect's
   !! memory changed there: the step was taken with the old one): the
   !! impulse missed is h/2 dzdd on average (the switch anywhere in the
   !! step). Not for a switch located to the accepted point.
   pure subroutine accuracy_add_switch(this, t, h, dzdd)
      class(accuracy_t), intent(inout) :: this
      real(wp), intent(in) :: t, h, dzdd(n_dof)
      this%switches = this%switches + 1
      this%late = this%late + 0.5_wp*h*dzdd
      this%late_t = this%late_t + 0.5_wp*h*dzdd*t
   end subroutine accuracy_add_switch

   !> Coordinate k's estimated error at t (no earlier than the last step)
   !! from the steps' truncation.
   elemental real(wp) function accuracy_truncation(this, k, t) result(e)
      class(accuracy_t), intent(in) :: this
      integer, intent(in) :: k
      real(wp), intent(in) :: t
      e = this%pos(k) + max(0.0_wp, this%vel(k)*t - this%vel_t(k))
   end function accuracy_truncation

   !> Coordinate k's estimated error at t from the switches taken at the
   !! end of a step.
   elemental real(wp) function accuracy_switching(this, k, t) result(e)
      class(accuracy_t), intent(in) :: this
      integer, intent(in) :: k
      real(wp), intent(in) :: t
      e = abs(this%late(k)*t - this%late_t(k))
   end function accuracy_switching

   !> Joint i's angle alpha_i - alpha_m(i): its estimated error at t (rad)
   !! from the truncation, from the switches, and both.
   elemental real(wp) function accuracy_joint_truncation(this, i, t) result(e)
      class(accuracy_t), intent(in) :: this
      integer, intent(in) :: i
      real(wp), intent(in) :: t
      e = this%truncation(i, t) + this%truncation(joint_partner(i), t)
   end function accuracy_joint_truncation

   elemental real(wp) function accuracy_joint_switching(this, i, t) result(e)
      class(accuracy_t), intent(in) :: this
      integer, intent(in) :: i
      real(wp), intent(in) :: t
      e = abs((this%late(i) - this%late(joint_partner(i)))*t - (this%late_t(i) - this%late_t(joint_partner(i))))
   end function accuracy_joint_switching

   elemental real(wp) function accuracy_joint_angle(this, i, t) result(e)
      class(accuracy_t), intent(in) :: this
      integer, intent(in) :: i
      real(wp), intent(in) :: t
      e = this%joint_truncation(i, t) + this%joint_switching(i, t)
   end function accuracy_joint_angle

   !> The joint whose angle has the largest estimated error at t.
   pure integer function accuracy_worst_joint(this, t) result(worst)
      class(accuracy_t), intent(in) :: this
      real(wp), intent(in) :: t
      integer :: i
      worst = 1
      do i = 2, n_joint
         if (this%joint_angle(i, t) > this%joint_angle(worst, t)) worst = i
      end do
   end function accuracy_worst_joint

   !> The estimated error of z (ez) and z' (ev) at t, each with the sign of
   !! the signed sums (the truncation's) or of the switches' part.
   pure subroutine accuracy_state_error(this, t, ez, ev)
      class(accuracy_t), intent(in) :: this
      real(wp), intent(in) :: t
      real(wp), intent(out) :: ez(n_dof), ev(n_dof)
      integer :: k
      do k = 1, n_dof
         ez(k) = sign(this%truncation(k, t) + this%switching(k, t), &
                      this%pos_s(k) + this%vel_s(k)*t - this%vel_t_s(k) + this%late(k)*t - this%late_t(k))
         ev(k) = sign(this%vel(k) + abs(this%late(k)), this%vel_s(k) + this%late(k))
      end do
   end subroutine accuracy_state_error

   !> Whether the head's sensitivity is to be taken at a new peak so far
   !! a_head (in/s^2): from 1 g, each time the peak has grown by 5 %.
   elemental logical function accuracy_head_due(this, a_head) result(due)
      class(accuracy_t), intent(in) :: this
      real(wp), intent(in) :: a_head
      due = this%on .and. a_head >= max(head_regrowth*this%head_error_at, g_std)
   end function accuracy_head_due

   !> The head's peak's estimated error relative to the peak a_peak.
   elemental real(wp) function accuracy_head_relative(this, a_peak) result(r)
      class(accuracy_t), intent(in) :: this
      real(wp), intent(in) :: a_peak
      r = 0.0_wp
      if (a_peak > 0.0_wp) r = this%head_error/a_peak
   end function accuracy_head_relative

   !> A step DT/k for a run whose estimate must fall by the factor
   !! `ratio`: k the smallest divisor of a round kind (TMAX and DTPRINT stay
   !! whole multiples of DT/k) at least the ratio, at least 2.
   pure real(wp) function suggested_step(dt, ratio) result(h)
      real(wp), intent(in) :: dt, ratio
      integer, parameter :: divisors(*) = [2, 4, 5, 10, 20, 25, 50, 100, 200, 250, 500, 1000]
      integer :: i
      h = dt/real(divisors(size(divisors)), wp)
      do i = 1, size(divisors)
         if (real(divisors(i), wp) >= ratio) then
            h = dt/real(divisors(i), wp)
            return
         end if
      end do
   end function suggested_step

   !> The warnings of a fixed-step run of step dt whose estimates acc (of
   !! the occupant `who`: '' when it is alone) at its end t_end exceed their
   !! thresholds; a_peak: the head's peak acceleration (in/s^2). failed: the
   !! run ended at t_end in a numerical failure, where the estimates end too
   !! (a divergence the estimates had not yet seen grow): then, if they are
   !! within their thresholds, the step is named as its likely cause.
   function accuracy_warnings(acc, who, a_peak, t_end, dt, failed) result(w)
      type(accuracy_t), intent(in) :: acc
      character(len=*), intent(in) :: who
      real(wp), intent(in) :: a_peak, t_end, dt
      logical, intent(in), optional :: failed
      type(string_t), allocatable :: w(:)
      real(wp) :: angle, rel, ratio
      integer :: j
      allocate (w(0))
      if (.not. acc%on) return
      j = acc%worst_joint(t_end)
      angle = acc%joint_angle(j, t_end)
      rel = acc%head_relative(a_peak)
      if (angle <= angle_threshold .and. rel <= head_threshold) then
         if (present(failed)) then
            if (failed) call append_string(w, who//'the integration failed at t = '//num(t_end, 4) &
                                           //' s, its estimates within their thresholds until then: DT = ' &
                                           //num(dt)//' s (*TIME) is too large for this deck; try DT = ' &
                                           //num(suggested_step(dt, 2.0_wp))//' s (docs/accuracy.md)')
         end if
         return
      end if
      ! the factor the step must fall by: the truncation's part falls as
      ! DT^3 (an embedded estimate of order 3, docs/accuracy.md), the
      ! switches' and (measured) the head's in proportion to DT
      ratio = max((acc%joint_truncation(j, t_end)/angle_threshold)**(1.0_wp/3.0_wp), &
                  acc%joint_switching(j, t_end)/angle_threshold, rel/head_threshold)
      if (angle > angle_threshold) call append_string(w, who//'the estimated error of the joint angles, ' &
                                                      //num(angle/deg, 3)//' deg ('//trim(joint_name(j)) &
                                                      //'), exceeds '//num(angle_threshold/deg, 3)//' deg')
      if (rel > head_threshold) call append_string(w, who//'the estimated error of the peak head acceleration, ' &
                                                    //num(100.0_wp*rel, 3)//' % of it, exceeds ' &
                                                    //num(100.0_wp*head_threshold, 3)//' %')
      w(size(w))%s = w(size(w))%s//': DT = '//num(dt)//' s (*TIME) is too large for this deck; try DT = ' &
                     //num(suggested_step(dt, ratio))//' s (docs/accuracy.md)'
   end function accuracy_warnings

   !> The warning of a run whose corrector (Adams-Moulton and its modified
   !! Euler start) reached its iteration limit on some steps: how many, and
   !! the settings that change it. '' when none did.
   function corrector_warning(stats, ctol, citer) result(w)
      type(step_stats_t), intent(in) :: stats
      real(wp), intent(in) :: ctol
      integer, intent(in) :: citer
      character(len=:), allocatable :: w
      w = ''
      if (stats%corrector_at_limit <= 0) return
      w = 'the corrector reached its iteration limit CITER = '//itoa(citer)//' on ' &
          //count_text(stats%corrector_at_limit)//' of '//count_text(stats%corrector_solves) &
          //' corrector solves (one per step taken, also where a step was taken again to locate a switch) ' &
          //'without its successive ' &
          //'approximations agreeing within CTOL = '//num(ctol)//' (*TIME): those steps are not the ' &
          //'Adams-Moulton solution; a larger CITER, or a smaller DT (the iteration converges faster), ' &
          //'should help (docs/accuracy.md)'
   contains
      pure function count_text(n) result(text)
         integer(i8), intent(in) :: n
         character(len=:), allocatable :: text
         character(len=24) :: buf
         write (buf, '(i0)') n
         text = trim(buf)
      end function count_text
   end function corrector_warning

   !> The warning of a fixed-step run in which the step widened contact
   !! pairs' friction ramps (D-C18b; events(1:n) the run's events): there
   !! the friction is a damper too stiff for the step, which the step only
   !! keeps stable, so the answer depends on DT beyond the estimates above
   !! (the rear impact's angles moved by 14 deg from DT = 1e-4 s to 1.25e-5
   !! s while the estimate read 0.04 deg; issue 15). '' when none was.
   function widened_ramp_warning(events, n) result(w)
      type(event_t), intent(in) :: events(:)
      integer, intent(in) :: n
      character(len=:), allocatable :: w
      integer :: k, n_pairs
      real(wp) :: factor, t_first
      w = ''
      n_pairs = 0
      factor = 1.0_wp
      t_first = 0.0_wp
      do k = 1, n
         if (events(k)%kind /= event_ramp_widened) cycle
         n_pairs = n_pairs + 1
         if (n_pairs == 1) t_first = events(k)%t
         if (events(k)%limit > 0.0_wp) factor = max(factor, events(k)%value/events(k)%limit)
      end do
      if (n_pairs == 0) return
      w = 'the fixed step widened the friction ramps of '//itoa(n_pairs)//' contact pair(s) (from t = ' &
          //num(t_first, 4)//' s, at first up to '//num(factor, 3)//' times XI; D-C18b): their friction is a ' &
          //'damper too stiff for DT, and the answer depends on DT beyond the estimates; Dormand-Prince ' &
          //'(NINT = 3) resolves it, or a DT that widens no ramp (docs/accuracy.md)'
   end function widened_ramp_warning
end module accuracy_estimate
