!> The right-hand side integrated by C.3: the system of the occupants in
!! the pitching, decelerating vehicle. The state y holds, for each occupant,
!! its generalized coordinates z, their rates z' and its effects' own
!! quantities (state_layout); f = (z', z'', ...) with z'' from A z'' = b
!! (C.4, C.5). The vehicle's motion comes from its tables (C.3), evaluated
!! only when an effect needs it.
!!
!! An evaluation that cannot be completed (A not positive definite, rates
!! that are not finite, a state beyond any physical motion) is an outcome
!! for the stepper (rhs's status, a code of this module's own): nothing is
!! allocated or written for it at the time. Why it failed is told only when
!! a stepper gives up (failure_text, the cold path), from the state of the
!! evaluation that failed.
module equations_of_motion
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp, i8
   use strings, only: num, itoa
   use model, only: model_t, n_dof, n_seg
   use ode_system, only: ode_system_t
   use state_layout, only: state_layout_t
   use vehicle_motion, only: vehicle_motion_t, vehicle_motion_init
   use body_state, only: body_state_t
   use occupant, only: occupant_t, occupant_build, occupant_state, occupant_rhs, occupant_rhs_kept, occupant_initial_y, &
      occupant_add_effect, occupant_vehicle, occupant_settle, slides_overflow
   use sliding_constraints, only: max_slides
   use effect_base, only: effect_t
   implicit none
   private

   public :: crash_system_t, system_build, system_add_occupant, system_add_effect, system_initial_y
   public :: system_body_state, system_settle
   public :: max_angle, max_position, max_rate, max_speed

   !> rhs's outcomes (its status) other than 0, explained by failure_text
   integer, parameter :: rhs_not_positive_definite = 1
   integer, parameter :: rhs_not_finite = 2
   integer, parameter :: rhs_diverged = 3
   integer, parameter :: rhs_too_many_slides = 4

   !> Bounds of any physical state (rad, in, rad/s, in/s), far beyond any
   !! motion a valid deck can produce (TMAX <= 1000 s, speeds and rates
   !! bounded by the deck's ranges and by energy): a state beyond them means
   !! the integration has diverged. Stopping there, before any arithmetic
   !! can overflow, ends the run with a message (and keeps Debug builds,
   !! which trap overflow, from crashing).
   real(wp), parameter :: max_angle = 1.0e9_wp, max_position = 1.0e11_wp
   real(wp), parameter :: max_rate = 1.0e7_wp, max_speed = 1.0e9_wp

   !> The occupants in their vehicle. Read-only during a run except the
   !! evaluation counters.
   type, extends(ode_system_t) :: crash_system_t
      type(occupant_t), allocatable :: occupants(:)
      type(vehicle_motion_t) :: vm
      type(state_layout_t) :: layout
      logical :: needs_vehicle = .false.
      !> evaluations of each effect (effect, occupant)
      integer(i8), allocatable :: counts(:, :)
      integer(i8) :: evaluations = 0
      !> the evaluation that ends a step keeps, in the effects that keep,
      !! what their accept needs there (rhs_end; issue 16 section 4):
      !! .false. evaluates it as any other (a test compares the two)
      logical :: keep_for_accept = .true.
      logical :: keeps = .false.          !< an occupant keeps (occupant_t%keeps)
   contains
      procedure :: rhs => system_rhs
      procedure :: rhs_end => system_rhs_end
      procedure :: error_controlled => system_error_controlled
      procedure :: failure_text => system_failure_text
   end type crash_system_t

contains

   !> The layout's error-controlled entries (every one but the searches'
   !! starting values, D-B7).
   pure function system_error_controlled(this, n) result(mask)
      class(crash_system_t), intent(in) :: this
      integer, intent(in) :: n
      logical :: mask(n)
      mask = .true.
      if (n == this%layout%n) mask = this%layout%error_controlled()
   end function system_error_controlled

   !> The system of one model: the vehicle and the model's occupant.
   subroutine system_build(m, sys)
      type(model_t), intent(in) :: m
      type(crash_system_t), intent(out) :: sys
      call vehicle_motion_init(m%vehicle, sys%vm)
      allocate (sys%occupants(0), sys%counts(0, 0))
      call system_add_occupant(sys, m)
   end subroutine system_build

   !> One more occupant, from the body, joints and options of m (the vehicle
   !! stays that of the first model).
   subroutine system_add_occupant(sys, m)
      type(crash_system_t), intent(inout) :: sys
      type(model_t), intent(in) :: m
      type(occupant_t), allocatable :: longer(:)
      integer(i8), allocatable :: counts(:, :)
      integer :: n, k
      n = size(sys%occupants) + 1
      allocate (longer(n))
      do k = 1, n - 1
         longer(k) = sys%occupants(k)
      end do
      call occupant_build(m, 'occupant '//itoa(n), sys%layout, longer(n))
      call move_alloc(longer, sys%occupants)
      allocate (counts(max(size(sys%counts, 1), size(sys%occupants(n)%effects)), n))
      counts = 0
      counts(1:size(sys%counts, 1), 1:n - 1) = sys%counts
      call move_alloc(counts, sys%counts)
      sys%needs_vehicle = sys%needs_vehicle .or. sys%occupants(n)%needs_vehicle
      sys%keeps = sys%keeps .or. sys%occupants(n)%keeps
   end subroutine system_add_occupant

   !> One more effect for occupant o (its quantities go at the end of y).
   subroutine system_add_effect(sys, o, e)
      type(crash_system_t), intent(inout) :: sys
      integer, intent(in) :: o
      class(effect_t), intent(in) :: e
      integer(i8), allocatable :: counts(:, :)
      call occupant_add_effect(sys%occupants(o), e, sys%layout)
      allocate (counts(max(size(sys%counts, 1), size(sys%occupants(o)%effects)), size(sys%occupants)))
      counts = 0
      counts(1:size(sys%counts, 1), :) = sys%counts
      call move_alloc(counts, sys%counts)
      sys%needs_vehicle = sys%needs_vehicle .or. sys%occupants(o)%needs_vehicle
      sys%keeps = sys%keeps .or. sys%occupants(o)%keeps
   end subroutine system_add_effect

   !> The initial state vector.
   subroutine system_initial_y(sys, y)
      type(crash_system_t), intent(in) :: sys
      real(wp), allocatable, intent(out) :: y(:)
      integer :: o
      allocate (y(sys%layout%n))
      y = 0.0_wp
      do o = 1, size(sys%occupants)
         call occupant_initial_y(sys%occupants(o), y)
      end do
   end subroutine system_initial_y

   !> What occupant o's effects see at (t, y), with the vehicle's state.
   pure function system_body_state(sys, o, t, y) result(st)
      type(crash_system_t), intent(in) :: sys
      integer, intent(in) :: o
      real(wp), intent(in) :: t, y(:)
      type(body_state_t) :: st
      call occupant_state(sys%occupants(o), t, y, st)
      call occupant_vehicle(sys%occupants(o), sys%vm, t, st)
   end function system_body_state

   !> On the accepted state (t, y), after the effects' accept: each
   !! occupant's sliding constraints whose multipliers left their ranges
   !! leave their surfaces (occupant_settle, issue 15); changed: the
   !! right-hand side jumped (the stepper must restart).
   subroutine system_settle(sys, t, y, changed, rates, counts)
      type(crash_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      logical, intent(out) :: changed
      real(wp), intent(inout), contiguous :: rates(:)    !< workspace: y's size
      integer(i8), intent(inout) :: counts(:)            !< workspace: the effects of any occupant
      type(body_state_t) :: st
      logical :: changed_o
      integer :: o
      changed = .false.
      do o = 1, size(sys%occupants)
         if (sys%occupants(o)%n_slide == 0) cycle
         st = system_body_state(sys, o, t, y)
         call occupant_settle(sys%occupants(o), st, y, changed_o, rates, counts)
         changed = changed .or. changed_o
      end do
   end subroutine system_settle

   subroutine system_rhs(this, t, y, dydt, status)
      class(crash_system_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: dydt(:)
      integer, intent(out) :: status
      type(body_state_t) :: st
      integer :: o, info

      this%evaluations = this%evaluations + 1
      status = 0
      do o = 1, size(this%occupants)
         associate (occ => this%occupants(o))
            if (.not. in_range(occ, y)) then
               status = rhs_diverged
               return
            end if
            call occupant_state(occ, t, y, st)
            if (occ%needs_vehicle) call occupant_vehicle(occ, this%vm, t, st)
            call occupant_rhs(occ, st, y, dydt, this%counts(:, o), info)
            if (info /= 0) then
               status = rhs_not_positive_definite
               if (info == slides_overflow) status = rhs_too_many_slides
               return
            end if
         end associate
      end do
      ! every rate: z'', and the effects' extra and auxiliary quantities
      if (.not. all(ieee_is_finite(dydt))) status = rhs_not_finite
   end subroutine system_rhs

   !> rhs at the evaluation that ends a step (ode_system's rhs_end): the
   !! same f, and the effects that keep keep what their accept needs at (t,
   !! y) (occupant_rhs_kept), unless keep_for_accept is off (issue 16
   !! section 4). (system_rhs's loop written out again, so that rhs, at
   !! every other evaluation, stays as it was.)
   subroutine system_rhs_end(this, t, y, dydt, status)
      class(crash_system_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out), contiguous :: dydt(:)
      integer, intent(out) :: status
      type(body_state_t) :: st
      integer :: o, info

      if (.not. (this%keep_for_accept .and. this%keeps)) then
         call system_rhs(this, t, y, dydt, status)
         return
      end if
      this%evaluations = this%evaluations + 1
      status = 0
      do o = 1, size(this%occupants)
         associate (occ => this%occupants(o))
            if (.not. in_range(occ, y)) then
               status = rhs_diverged
               return
            end if
            call occupant_state(occ, t, y, st)
            if (occ%needs_vehicle) call occupant_vehicle(occ, this%vm, t, st)
            ! (an occupant whose effects keep nothing evaluates them as rhs
            ! does; occupant_rhs is called from rhs alone, where it is inlined)
            call occupant_rhs_kept(occ, st, y, dydt, this%counts(:, o), info)
            if (info /= 0) then
               status = rhs_not_positive_definite
               if (info == slides_overflow) status = rhs_too_many_slides
               return
            end if
         end associate
      end do
      if (.not. all(ieee_is_finite(dydt))) status = rhs_not_finite
   end subroutine system_rhs_end

   !> Why the evaluation at (t, y) failed with code (system_rhs's status),
   !! when a stepper gives up: the code's reason and, for a state out of
   !! range, which coordinate or rate left it; for rates that are not
   !! finite, the first effect that can say why (effect_t%failure_text).
   function system_failure_text(this, t, y, code) result(text)
      class(crash_system_t), intent(in) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      character(len=:), allocatable :: detail
      integer :: o
      text = rhs_status_text(code)
      detail = ''
      do o = 1, size(this%occupants)
         associate (occ => this%occupants(o))
            if (code == rhs_too_many_slides .and. occ%n_slide > max_slides) then
               detail = trim(occ%label)//'''s effects may hold '//itoa(occ%n_slide)
            else if (code == rhs_diverged .and. .not. in_range(occ, y)) then
               detail = out_of_range(occ%label, y(occ%z_offset + 1:occ%z_offset + n_dof), &
                                     y(occ%zdot_offset + 1:occ%zdot_offset + n_dof))
            else if (code == rhs_not_finite) then
               detail = effect_failure(this, o, t, y)
            end if
         end associate
         if (len(detail) > 0) exit
      end do
      if (len(detail) > 0) text = text//' ('//detail//')'
   end function system_failure_text

   !> Why occupant o's rates at (t, y) are not finite, when one of its
   !! effects can say (effect_t%failure_text: the first that does), or ''.
   function effect_failure(sys, o, t, y) result(why)
      type(crash_system_t), intent(in) :: sys
      integer, intent(in) :: o
      real(wp), intent(in) :: t, y(:)
      character(len=:), allocatable :: why
      type(body_state_t) :: st
      integer :: k, xo, ao
      why = ''
      st = system_body_state(sys, o, t, y)
      associate (occ => sys%occupants(o))
         do k = 1, size(occ%effects)
            xo = occ%extra_offset(k)
            ao = occ%aux_offset(k)
            associate (e => occ%effects(k)%e)
               why = e%failure_text(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux))
            end associate
            if (len(why) > 0) then
               why = trim(occ%label)//': '//why
               return
            end if
         end do
      end associate
   end function effect_failure

   !> The occupant's coordinates and rates are finite and within the bounds
   !! of any physical state (NaN fails every comparison).
   pure logical function in_range(occ, y) result(ok)
      type(occupant_t), intent(in) :: occ
      real(wp), intent(in) :: y(:)
      associate (z => y(occ%z_offset + 1:occ%z_offset + n_dof), zd => y(occ%zdot_offset + 1:occ%zdot_offset + n_dof))
         ok = all(abs(z(1:n_seg)) <= max_angle) .and. all(abs(z(n_seg + 1:)) <= max_position) .and. &
              all(abs(zd(1:n_seg)) <= max_rate) .and. all(abs(zd(n_seg + 1:)) <= max_speed)
      end associate
   end function in_range

   !> Which coordinate or rate left its range, for the failure message.
   pure function out_of_range(label, z, zd) result(text)
      character(len=*), intent(in) :: label
      real(wp), intent(in) :: z(n_dof), zd(n_dof)
      character(len=:), allocatable :: text
      character(len=6), parameter :: names(n_dof) = [character(len=6) :: 'alpha1', 'alpha2', 'alpha3', &
         'alpha4', 'alpha5', 'alpha6', 'alpha7', 'alpha8', 'x_h', 'y_h']
      real(wp) :: bound
      character(len=:), allocatable :: name, unit
      integer :: i
      text = trim(label)//': the state left its range'
      do i = 1, n_dof
         name = trim(names(i))
         bound = merge(max_angle, max_position, i <= n_seg)
         unit = trim(merge('rad', 'in ', i <= n_seg))
         if (.not. ieee_is_finite(z(i))) then
            text = trim(label)//': '//name//' is not finite'
            return
         else if (abs(z(i)) > bound) then
            text = trim(label)//': |'//name//'| = '//num(abs(z(i)), 6)//' '//unit//' > '//num(bound)//' '//unit
            return
         end if
         bound = merge(max_rate, max_speed, i <= n_seg)
         unit = unit//'/s'
         if (.not. ieee_is_finite(zd(i))) then
            text = trim(label)//': '//name//' dot is not finite'
            return
         else if (abs(zd(i)) > bound) then
            text = trim(label)//': |'//name//' dot| = '//num(abs(zd(i)), 6)//' '//unit//' > '//num(bound)//' '//unit
            return
         end if
      end do
   end function out_of_range

   !> The reason of each of system_rhs's codes.
   pure function rhs_status_text(status) result(text)
      integer, intent(in) :: status
      character(len=:), allocatable :: text
      select case (status)
      case (rhs_not_positive_definite)
         text = 'the body matrix A (figure 27) is not positive definite (a pivot of its factorization is not positive and finite)'
      case (rhs_too_many_slides)
         text = 'the effects of an occupant may hold more sliding constraints than the solve has room for (at most ' &
                //itoa(max_slides)//', max_slides of sliding_constraints)'
      case (rhs_not_finite)
         text = 'the accelerations are not finite'
      case (rhs_diverged)
         text = 'the state left the range of any physical motion (|angle| <= '//num(max_angle) &
                //' rad, |hip position| <= '//num(max_position)//' in, |rate| <= '//num(max_rate) &
                //' rad/s, |hip speed| <= '//num(max_speed)//' in/s, bounds no valid deck''s motion ' &
                //'reaches): the integration diverged; try a smaller DT, or NINT = 3 with tighter RTOL/ATOL'
      case default
         text = 'unknown right-hand-side failure'
      end select
   end function rhs_status_text
end module equations_of_motion
