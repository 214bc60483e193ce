!> A channel sampled uniformly, as a test laboratory's data acquisition
!! samples a transducer: one or more components at the points t0 + k h of
!! a grid (10 kHz unless the caller says; the head's 20 kHz,
!! channel_grid_head), filled from the run's accepted steps one at a time, for
!! the filters of SAE J211 (channel_filter), which need the whole record
!! (they run backward too). docs/injury.md.
!!
!! Between two accepted steps a sample comes from one of two interpolants:
!!
!! - add_motion(t, a, v): a point's acceleration vector a and velocity v
!!   (dv/dt = a). The velocity is the cubic Hermite interpolant of v and a
!!   at both ends of the step and the acceleration its derivative, a
!!   quadratic (acceleration_criteria's, hermite_acceleration): third order
!!   in the step for a, exact in its integral over the step.
!! - add(t, x): any other quantity known at accepted steps only (a joint's
!!   force or moment, a deflection): linear between them (second order).
!!
!! A jump (two samples at one time) leaves a grid point at that time with
!! the value before it. The record's room is reserved at the start for the
!! run's length (nothing allocated at a step), and doubles if it is passed.
module channel_record
   use kinds, only: wp
   implicit none
   private

   public :: channel_record_t, channel_grid_default, channel_grid_head, hermite_acceleration, max_components

   !> The grid's spacing (s): 10 kHz.
   real(wp), parameter :: channel_grid_default = 1.0e-4_wp
   !> The head's (s): 20 kHz. J211-1's filter for CFC 1000 at 10 kHz falls
   !! below its corridor between 3.3 and 3.5 kHz (the bilinear transform's
   !! warping near the 5 kHz Nyquist frequency); at 20 kHz it is inside
   !! (test_cfc_j211_corridor; docs/injury.md, "Corridor").
   real(wp), parameter :: channel_grid_head = 5.0e-5_wp
   !> The most components a record holds (a vector in the plane; a force and
   !! a moment): the work arrays are of this fixed size, so that a step
   !! allocates nothing.
   integer, parameter :: max_components = 2

   type :: channel_record_t
      integer :: n_comp = 0
      real(wp) :: h = channel_grid_default
      real(wp) :: t0 = 0.0_wp                    !< grid point 0, the first sample's time
      integer :: n = 0                           !< grid points filled: 0 .. n - 1
      logical :: started = .false.
      real(wp) :: t = 0.0_wp                     !< the last sample's time
      real(wp) :: x(max_components) = 0.0_wp     !< its value
      real(wp) :: v(max_components) = 0.0_wp     !< its velocity (add_motion)
      logical :: motion = .false.                !< the last sample came with a velocity
      real(wp), allocatable :: values(:, :)      !< (n_comp, 0 : room - 1)
   contains
      procedure :: reserve => record_reserve
      procedure :: add => record_add
      procedure :: add_motion => record_add_motion
      procedure :: times => record_times
   end type channel_record_t

contains

   !> An empty record of n_comp components, with room for a run of
   !! duration (s) on a grid of spacing h (default channel_grid_default).
   pure subroutine record_reserve(this, n_comp, duration, h)
      class(channel_record_t), intent(inout) :: this
      integer, intent(in) :: n_comp
      real(wp), intent(in) :: duration
      real(wp), intent(in), optional :: h
      integer :: room
      if (present(h)) this%h = h
      if (allocated(this%values)) deallocate (this%values)
      this%started = .false.
      this%motion = .false.
      this%n = 0
      this%n_comp = n_comp
      room = 16
      if (duration > 0.0_wp .and. duration/this%h < 1.0e8_wp) room = max(room, int(duration/this%h) + 3)
      allocate (this%values(n_comp, 0:room - 1))
      this%x = 0.0_wp
      this%v = 0.0_wp
   end subroutine record_reserve

   !> The grid's times, t0 + k h, k = 0 .. n - 1.
   pure function record_times(this) result(t)
      class(channel_record_t), intent(in) :: this
      real(wp) :: t(this%n)
      integer :: k
      t = [(this%t0 + real(k, wp)*this%h, k=0, this%n - 1)]
   end function record_times

   !> The value x at t (not before the last sample), linear from the last.
   pure subroutine record_add(this, t, x)
      class(channel_record_t), intent(inout) :: this
      real(wp), intent(in) :: t, x(:)
      real(wp) :: dt, tk, s, xs(max_components)
      logical :: first
      integer :: m
      m = size(x)
      call start(this, t, x, first)
      if (first) return
      dt = t - this%t
      if (.not. dt >= 0.0_wp) return                 ! (time does not go back)
      do
         tk = this%t0 + real(this%n, wp)*this%h
         if (tk > t) exit
         s = 0.0_wp
         if (dt > 0.0_wp) s = (tk - this%t)/dt
         xs(1:m) = this%x(1:m) + s*(x - this%x(1:m))
         call put(this, xs)
      end do
      this%t = t
      this%x(1:m) = x
      this%motion = .false.
   end subroutine record_add

   !> A point's acceleration a and velocity v (dv/dt = a) at t: between
   !! this and the last sample the acceleration is the derivative of the
   !! velocity's cubic Hermite interpolant (linear after a sample of add).
   pure subroutine record_add_motion(this, t, a, v)
      class(channel_record_t), intent(inout) :: this
      real(wp), intent(in) :: t, a(:), v(:)
      real(wp) :: dt, tk, s, c(max_components, 0:2), a2(max_components), v2(max_components), xs(max_components)
      logical :: smooth, first
      integer :: m
      m = size(a)
      a2 = 0.0_wp
      v2 = 0.0_wp
      a2(1:m) = a
      v2(1:m) = v
      smooth = this%motion
      call start(this, t, a, first)
      if (.not. first) then
         dt = t - this%t
         if (.not. dt >= 0.0_wp) return              ! (time does not go back)
         if (smooth .and. dt > 0.0_wp) then
            c = hermite_acceleration(this%x, this%v, a2, v2, dt)
            do
               tk = this%t0 + real(this%n, wp)*this%h
               if (tk > t) exit
               s = (tk - this%t)/dt
               xs = c(:, 0) + s*(c(:, 1) + s*c(:, 2))
               call put(this, xs)
            end do
            this%t = t
            this%x = a2
         else
            call this%add(t, a)
         end if
      end if
      this%v = v2
      this%motion = .true.
   end subroutine record_add_motion

   !> The acceleration a(s) = c0 + c1 s + c2 s^2, s = (t' - t0)/dt, of a
   !! step from (a0, v0) to (a1, v1) of length dt: the derivative of the
   !! velocity's cubic Hermite interpolant (issue 15; it integrates to
   !! v1 - v0 exactly over the step).
   pure function hermite_acceleration(a0, v0, a1, v1, dt) result(c)
      real(wp), intent(in) :: a0(max_components), v0(max_components), a1(max_components), v1(max_components), dt
      real(wp) :: c(max_components, 0:2)
      c(:, 0) = a0
      c(:, 1) = 6.0_wp*(v1 - v0)/dt - 4.0_wp*a0 - 2.0_wp*a1
      c(:, 2) = -6.0_wp*(v1 - v0)/dt + 3.0_wp*a0 + 3.0_wp*a1
   end function hermite_acceleration

   !> first: this is the first sample, taken (grid point 0 at t).
   pure subroutine start(this, t, x, first)
      class(channel_record_t), intent(inout) :: this
      real(wp), intent(in) :: t, x(:)
      logical, intent(out) :: first
      first = .not. this%started
      if (.not. first) return
      if (.not. allocated(this%values)) call this%reserve(size(x), 0.0_wp)
      this%started = .true.
      this%t0 = t
      this%t = t
      this%x = 0.0_wp
      this%x(1:size(x)) = x
      this%n = 0
      call put(this, this%x)
   end subroutine start

   !> The next grid point's value (its first n_comp components).
   pure subroutine put(this, x)
      class(channel_record_t), intent(inout) :: this
      real(wp), intent(in) :: x(max_components)
      real(wp), allocatable :: longer(:, :)
      if (this%n == size(this%values, 2)) then
         allocate (longer(this%n_comp, 0:2*this%n - 1))
         longer(:, 0:this%n - 1) = this%values
         call move_alloc(longer, this%values)
      end if
      this%values(:, this%n) = x(1:this%n_comp)
      this%n = this%n + 1
   end subroutine put
end module channel_record
