!> Report C.1/C.3: the vehicle's motion from its time tables. For each of
!! x_c, y_c and the pitch Phi the acceleration table is given; the rate
!! and position tables are optional, and where given "some or all of the
!! integrations for the vehicle may be omitted and the proper values read
!! in from the table" (C.3).
!!
!! Between the t_m (docs/errata.md, D-5): accelerations vary linearly and
!! the rate and position are their exact integrals (no integration error);
!! a tabulated rate varies linearly and the position is its exact
!! integral; a tabulated position varies linearly. After the last t_m the
!! acceleration holds its last value and tabulated rates and positions
!! continue along their last interval. The report evaluates the tables only
!! at the t_m (Phi(t_m)); here they are evaluated at the time itself.
module vehicle_motion
   use kinds, only: wp
   use table_search, only: bracket_index
   use model, only: vehicle_section_t, pulse_table_t
   implicit none
   private

   public :: vehicle_motion_t, vehicle_state_t, vehicle_motion_init, vehicle_state_at, vehicle_table_differences
   public :: vehicle_kinks

   !> The motion of one coordinate (x_c, y_c or Phi).
   type :: axis_t
      !> false when its tables and initial values are all zero: its position,
      !! rate and acceleration are then 0 at every time (the y_c and Phi of a
      !! sled pulse), and are set without evaluating the tables
      logical :: moves = .true.
      real(wp), allocatable :: acc(:)                 !< acceleration table (times: vehicle_motion_t%ta)
      real(wp), allocatable :: acc_v(:), acc_x(:)     !< its integrals at the knots
      real(wp), allocatable :: acc_slope(:)           !< its slope on each interval (0 after the last knot)
      logical :: rate_given = .false., pos_given = .false.
      real(wp), allocatable :: vel(:), vel_x(:)       !< rate table and its integral (times: tv)
      real(wp), allocatable :: vel_slope(:)           !< its slope on each interval (after the last knot: the last's)
      real(wp), allocatable :: pos(:), pos_slope(:)   !< position table and its slopes (times: tx)
   end type axis_t

   !> The three axes share the times of each kind of table (one *PULSE
   !! table, one of rates, one of positions: C.1), so one interval search
   !! per kind serves them all, and none when a kind's times are the
   !! acceleration table's.
   type :: vehicle_motion_t
      type(axis_t) :: axis(3)
      real(wp), allocatable :: ta(:), tv(:), tx(:)    !< the knot times of the three kinds of table
      logical :: any_rate = .false., any_pos = .false. !< some axis has a rate (position) table
      logical :: tv_is_ta = .false., tx_is_ta = .false. !< those times are the acceleration table's
   end type vehicle_motion_t

   !> Vehicle state at a time: x_c, y_c, Phi; their rates; their accelerations.
   type :: vehicle_state_t
      real(wp) :: pos(3), vel(3), acc(3)
   end type vehicle_state_t

contains

   !> Prepare the tables: cumulative integrals at the knots and the slope
   !! of every interval, once per run (the evaluation then only looks them up).
   pure subroutine vehicle_motion_init(m, vm)
      type(vehicle_section_t), intent(in) :: m
      type(vehicle_motion_t), intent(out) :: vm
      real(wp) :: v0(3), x0(3)
      integer :: j, k, n
      real(wp) :: h

      v0 = [m%xc_dot0, m%yc_dot0, m%phi_dot0]
      x0 = [0.0_wp, 0.0_wp, m%phi0]
      vm%ta = m%pulse_acc%t
      n = size(vm%ta)
      if (allocated(m%pulse_vel%t)) then
         vm%tv = m%pulse_vel%t
         vm%any_rate = any(m%pulse_vel%given)
         vm%tv_is_ta = same_times(vm%tv, vm%ta)
      end if
      if (allocated(m%pulse_pos%t)) then
         vm%tx = m%pulse_pos%t
         vm%any_pos = any(m%pulse_pos%given)
         vm%tx_is_ta = same_times(vm%tx, vm%ta)
      end if
      do j = 1, 3
         associate (ax => vm%axis(j))
            allocate (ax%acc(n), ax%acc_v(n), ax%acc_x(n), ax%acc_slope(n))
            ax%acc(:) = m%pulse_acc%v(:, j)
            ax%acc_v(1) = v0(j)
            ax%acc_x(1) = x0(j)
            ax%acc_slope(n) = 0.0_wp     ! after the last t_m the acceleration holds
            do k = 1, n - 1
               h = vm%ta(k + 1) - vm%ta(k)
               ax%acc_slope(k) = (ax%acc(k + 1) - ax%acc(k))/(vm%ta(k + 1) - vm%ta(k))
               ax%acc_v(k + 1) = ax%acc_v(k) + 0.5_wp*h*(ax%acc(k) + ax%acc(k + 1))
               ax%acc_x(k + 1) = ax%acc_x(k) + h*ax%acc_v(k) + h**2*(2.0_wp*ax%acc(k) + ax%acc(k + 1))/6.0_wp
            end do
            ax%moves = abs(v0(j)) > 0.0_wp .or. abs(x0(j)) > 0.0_wp .or. any(abs(ax%acc) > 0.0_wp)
            if (allocated(m%pulse_vel%t)) ax%rate_given = m%pulse_vel%given(j)
            if (ax%rate_given) then
               ax%vel = m%pulse_vel%v(:, j)
               ax%vel_slope = slopes(vm%tv, ax%vel)
               allocate (ax%vel_x(size(vm%tv)))
               ax%vel_x(1) = x0(j)
               do k = 1, size(vm%tv) - 1
                  ax%vel_x(k + 1) = ax%vel_x(k) + 0.5_wp*(vm%tv(k + 1) - vm%tv(k))*(ax%vel(k) + ax%vel(k + 1))
               end do
               ax%moves = ax%moves .or. any(abs(ax%vel) > 0.0_wp)
            end if
            if (allocated(m%pulse_pos%t)) ax%pos_given = m%pulse_pos%given(j)
            if (ax%pos_given) then
               ax%pos = m%pulse_pos%v(:, j)
               ax%pos_slope = slopes(vm%tx, ax%pos)
               ax%moves = ax%moves .or. any(abs(ax%pos) > 0.0_wp)
            end if
         end associate
      end do
   end subroutine vehicle_motion_init

   !> Whether two tables have the same knot times (then one search serves both).
   pure logical function same_times(a, b)
      real(wp), intent(in) :: a(:), b(:)
      same_times = size(a) == size(b)
      if (same_times) same_times = .not. any(abs(a - b) > 0.0_wp)   ! (exactly equal)
   end function same_times

   !> (C.3) Tabulated rates and positions replace integrations, so they
   !! should be the integrals of the tables below them; measured data never
   !! quite are, and where they disagree the vehicle's inertial forces (from
   !! the accelerations) and its pitch, rates and anchorage motion (from the
   !! tables) describe different motions, which the energy balance need not
   !! show (vehicle_input checks the tables against these integrals). Per
   !! axis (x, y, pitch), the largest |difference| at the knots of the rate
   !! table against the integral of the accelerations, and
   !! at the knots of the position table against the integral of the rates
   !! (tabulated or integrated), with the time of each (0 where not given).
   pure subroutine vehicle_table_differences(v, rate_diff, rate_time, pos_diff, pos_time)
      type(vehicle_section_t), intent(in) :: v
      real(wp), intent(out) :: rate_diff(3), rate_time(3), pos_diff(3), pos_time(3)
      type(vehicle_section_t) :: lower
      rate_diff = 0.0_wp
      rate_time = 0.0_wp
      pos_diff = 0.0_wp
      pos_time = 0.0_wp
      lower = v
      if (allocated(lower%pulse_pos%t)) then
         deallocate (lower%pulse_pos%t, lower%pulse_pos%v)
         call largest_difference(lower, v%pulse_pos, .true., pos_diff, pos_time)
      end if
      if (allocated(lower%pulse_vel%t)) then
         deallocate (lower%pulse_vel%t, lower%pulse_vel%v)
         call largest_difference(lower, v%pulse_vel, .false., rate_diff, rate_time)
      end if
   contains
      !> Table tab against the motion of `lower` (the tables below it):
      !! positions if is_pos, else rates.
      pure subroutine largest_difference(lower, tab, is_pos, diff, time)
         type(vehicle_section_t), intent(in) :: lower
         type(pulse_table_t), intent(in) :: tab
         logical, intent(in) :: is_pos
         real(wp), intent(inout) :: diff(3), time(3)
         type(vehicle_motion_t) :: vm
         type(vehicle_state_t) :: vs
         real(wp) :: moved(3)
         integer :: k, j
         call vehicle_motion_init(lower, vm)
         do k = 1, size(tab%t)
            vs = vehicle_state_at(vm, tab%t(k))
            moved = merge(vs%pos, vs%vel, is_pos)
            do j = 1, 3
               if (.not. tab%given(j)) cycle
               if (abs(tab%v(k, j) - moved(j)) > diff(j)) then
                  diff(j) = abs(tab%v(k, j) - moved(j))
                  time(j) = tab%t(k)
               end if
            end do
         end do
      end subroutine largest_difference
   end subroutine vehicle_table_differences

   !> The vehicle's position, rate and acceleration at time t.
   pure function vehicle_state_at(vm, t) result(vs)
      type(vehicle_motion_t), intent(in) :: vm
      real(wp), intent(in) :: t
      type(vehicle_state_t) :: vs
      integer :: j, k, ka, kv, kx
      real(wp) :: tau, da
      ! one search per kind of table serves the three axes (they share its
      ! times, C.1); a kind whose times are the acceleration table's needs none
      ka = interval(vm%ta, t)
      kv = ka
      if (vm%any_rate .and. .not. vm%tv_is_ta) kv = interval(vm%tv, t)
      kx = ka
      if (vm%any_pos .and. .not. vm%tx_is_ta) kx = interval(vm%tx, t)
      do j = 1, 3
         associate (ax => vm%axis(j))
            if (.not. ax%moves) then      ! every table and initial value zero: so is the motion
               vs%acc(j) = 0.0_wp
               vs%vel(j) = 0.0_wp
               vs%pos(j) = 0.0_wp
               cycle
            end if
            ! acceleration table and its exact integrals
            k = ka
            tau = t - vm%ta(k)
            da = ax%acc_slope(k)
            vs%acc(j) = ax%acc(k) + da*tau
            vs%vel(j) = ax%acc_v(k) + tau*(ax%acc(k) + 0.5_wp*da*tau)
            vs%pos(j) = ax%acc_x(k) + tau*(ax%acc_v(k) + tau*(0.5_wp*ax%acc(k) + da*tau/6.0_wp))
            ! tabulated rates replace the first integration
            if (ax%rate_given) then
               k = kv
               tau = t - vm%tv(k)
               da = ax%vel_slope(k)
               vs%vel(j) = ax%vel(k) + da*tau
               vs%pos(j) = ax%vel_x(k) + tau*(ax%vel(k) + 0.5_wp*da*tau)
            end if
            ! tabulated positions replace the second
            if (ax%pos_given) then
               k = kx
               vs%pos(j) = ax%pos(k) + ax%pos_slope(k)*(t - vm%tx(k))
            end if
         end associate
      end do
   end function vehicle_state_at

   !> Issue 15: the times in (0, t_max) where the vehicle's motion is not
   !! smooth - a knot of a table the motion uses (a moving axis's) where its
   !! slope changes: the acceleration kinks there (the seat's sliding
   !! constraint follows it, errata D-5b), a tabulated rate kinks, a
   !! tabulated position's rate jumps. Increasing, each once; a knot where every slope goes on (a
   !! plateau, a straight piece cut in two) is none. The run steps onto
   !! each (print_schedule), as onto a located switch.
   pure function vehicle_kinks(vm, t_max) result(tk)
      type(vehicle_motion_t), intent(in) :: vm
      real(wp), intent(in) :: t_max
      real(wp), allocatable :: tk(:)
      real(wp), allocatable :: times(:)
      integer :: j, k, n
      allocate (times(0))
      do j = 1, 3
         associate (ax => vm%axis(j))
            if (.not. ax%moves) cycle
            ! (after the last knot the acceleration holds: slope 0)
            call add(vm%ta, ax%acc_slope, times)
            if (ax%rate_given) call add(vm%tv, ax%vel_slope, times)
            if (ax%pos_given) call add(vm%tx, ax%pos_slope, times)
         end associate
      end do
      ! sorted (each table's knots are), each time once
      n = size(times)
      do k = 2, n
         j = k
         do while (j > 1)
            if (.not. times(j - 1) > times(j)) exit
            times(j - 1:j) = [times(j), times(j - 1)]
            j = j - 1
         end do
      end do
      allocate (tk(0))
      do k = 1, n
         if (k > 1) then
            if (.not. times(k) > times(k - 1)) cycle
         end if
         tk = [tk, times(k)]
      end do
   contains
      !> The knots t(i), 1 < i, of a table whose slopes sl(i - 1) and sl(i)
      !! differ, inside (0, t_max), added to list.
      pure subroutine add(t, sl, list)
         real(wp), intent(in) :: t(:), sl(:)
         real(wp), allocatable, intent(inout) :: list(:)
         integer :: i
         do i = 2, size(t)
            if (.not. (t(i) > 0.0_wp .and. t(i) < t_max)) cycle
            if (abs(sl(i - 1) - sl(i)) > 0.0_wp) list = [list, t(i)]
         end do
      end subroutine add
   end function vehicle_kinks

   !> The knot interval holding t: t(k) <= t < t(k+1), or the last knot
   !! beyond the table (k = size) and the first before it.
   pure integer function interval(tk, t) result(k)
      real(wp), intent(in) :: tk(:), t
      if (t >= tk(size(tk))) then
         k = size(tk)
      else
         k = bracket_index(tk, t)
      end if
   end function interval

   !> The slope of every interval k of a table (v(k+1) - v(k))/(t(k+1) -
   !! t(k)); at the last knot, beyond the table, that of the last interval
   !! (a tabulated rate or position continues along it); 0 for one knot.
   pure function slopes(tk, v) result(sl)
      real(wp), intent(in) :: tk(:), v(:)
      real(wp) :: sl(size(tk))
      integer :: k
      sl = 0.0_wp
      do k = 1, size(tk) - 1
         sl(k) = (v(k + 1) - v(k))/(tk(k + 1) - tk(k))
      end do
      if (size(tk) >= 2) sl(size(tk)) = sl(size(tk) - 1)
   end function slopes
end module vehicle_motion
