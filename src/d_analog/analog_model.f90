!> Report Section D: a simple analog to the collision between a front and a
!! rear auto occupant. Each occupant's upper body pivots about its hip (A
!! front, B rear). The front occupant is held by a shoulder harness (spring
!! k1 and damper c at the lever arm l1) and a hip torque T of constant size
!! opposing the motion; the rear occupant pivots freely until the front seat
!! back stops him at theta2 = 60 deg. Both start upright with the angular
!! velocity the collision gives them, m v rho = I0 omega.
!!
!! Solved in closed form, piecewise: while theta1' keeps its sign the
!! front occupant's equation is linear with a constant torque, so each such
!! phase is the free motion of a damped oscillator about a shifted centre
!! (undamped, under-, critically or over-damped alike); a phase ends where
!! theta1' = 0, found in closed form too, and the body stays there when the
!! harness's moment cannot overcome T (docs/analog.md: why not the steppers
!! of C.3). Where the report's printed equations are wrong the code follows
!! the physics and docs/errata.md says why (errata D-1 to D-6).
module analog_model
   use kinds, only: wp, deg, g_std
   implicit none
   private

   public :: analog_body_t, analog_case_t, front_phase_t, analog_solution_t, contact_t
   public :: analog_solve, front_state, rear_state, separation, free_motion, phase_end
   public :: initial_rate, harness_stiffness, critical_damping, harness_frequency

   !> One occupant's upper body, Section D: the 95th-percentile male, about
   !! 110 lb and 38 in, its centre of gravity 17 in from the hip, I0 = 117
   !! lb*in*s^2 about the hip; the rear occupant's rigid stop at 60 deg.
   type :: analog_body_t
      real(wp) :: weight = 110.0_wp         !< lb
      real(wp) :: length = 38.0_wp          !< in, hip to the top of the head
      real(wp) :: rho = 17.0_wp             !< in, hip to the centre of gravity
      real(wp) :: inertia = 117.0_wp        !< lb*in*s^2, about the hip
      real(wp) :: stop_angle = 60.0_wp*deg  !< rad, the front seat back stops the rear occupant
   end type analog_body_t

   !> One case of the analog (a card of *ANALOG), in internal units.
   type :: analog_case_t
      real(wp) :: speed = 0.0_wp       !< in/s, the collision's speed v
      real(wp) :: k1 = 0.0_wp          !< lb/in, the harness's spring
      real(wp) :: l1 = 0.0_wp          !< in, hip to the harness's line of action
      real(wp) :: zeta = 0.0_wp        !< the harness's damping ratio (1: critical)
      real(wp) :: torque = 0.0_wp      !< in*lb, the front occupant's hip torque T
      real(wp) :: spacing = 0.0_wp     !< in, L: the hips' horizontal distance
      real(wp) :: t_max = 0.125_wp     !< s
      !> in*lb: a hip torque on the rear occupant too (the report's remark
      !! that it lengthens his motion by 8 %, erratum D-6); 0 in the report's
      !! model and on the cards
      real(wp) :: rear_torque = 0.0_wp
      type(analog_body_t) :: body
   end type analog_case_t

   !> A phase of the front occupant's motion from t0: theta1' of one sign
   !! (the hip torque constant), or at rest.
   type :: front_phase_t
      real(wp) :: t0 = 0.0_wp, theta0 = 0.0_wp, rate0 = 0.0_wp
      real(wp) :: centre = 0.0_wp          !< rad, the equilibrium the torque shifts to
      real(wp) :: t_end = huge(1.0_wp)     !< s, where theta1' = 0 (huge: never)
      logical :: at_rest = .false.         !< the harness cannot overcome T: stays at theta0
   end type front_phase_t

   !> A contact between the occupants: from t_begin to t_end (huge: still
   !! in contact at TMAX).
   type :: contact_t
      real(wp) :: t_begin = 0.0_wp, t_end = huge(1.0_wp)
   end type contact_t

   !> The solved case.
   type :: analog_solution_t
      type(analog_case_t) :: c
      real(wp) :: omega0 = 0.0_wp      !< rad/s, m v rho / I0
      real(wp) :: kappa = 0.0_wp       !< lb*in/rad, l1**2 k1
      real(wp) :: damping = 0.0_wp     !< lb*in*s/rad, zeta times critical
      real(wp) :: wn = 0.0_wp          !< rad/s, sqrt(kappa / I0)
      integer :: n_phase = 0
      type(front_phase_t), allocatable :: phase(:)
      real(wp) :: t_rear_stop = huge(1.0_wp)   !< s, the rear occupant reaches the stop
      integer :: n_contact = 0
      type(contact_t), allocatable :: contact(:)
      real(wp) :: min_gap = huge(1.0_wp), t_min_gap = 0.0_wp   !< in, s
   end type analog_solution_t

   !> The scan for contacts: at most this step (s), refined by bisection to t_tol.
   real(wp), parameter :: scan_step = 1.0e-5_wp, t_tol = 1.0e-12_wp

contains

   !> Section D: m v rho = I0 omega, m = W / g.
   pure real(wp) function initial_rate(speed, body) result(omega)
      real(wp), intent(in) :: speed
      type(analog_body_t), intent(in) :: body
      omega = (body%weight/g_std)*speed*body%rho/body%inertia
   end function initial_rate

   !> The harness's moment per radian about the hip: the spring k1 at l1
   !! stretches l1 theta1, pulls k1 l1 theta1 and turns l1 k1 l1 theta1
   !! (erratum D-2: the report's l1 k1 is a force, not a moment).
   pure real(wp) function harness_stiffness(c) result(kappa)
      type(analog_case_t), intent(in) :: c
      kappa = c%l1**2*c%k1
   end function harness_stiffness

   !> The harness's natural frequency, rad/s.
   pure real(wp) function harness_frequency(c) result(wn)
      type(analog_case_t), intent(in) :: c
      wn = sqrt(harness_stiffness(c)/c%body%inertia)
   end function harness_frequency

   !> The damper c (lb*s/in at l1) that damps the harness critically:
   !! (l1**2 c)**2 = 4 I0 l1**2 k1 (erratum D-2).
   pure real(wp) function critical_damping(c) result(c_crit)
      type(analog_case_t), intent(in) :: c
      c_crit = 2.0_wp*sqrt(c%body%inertia*harness_stiffness(c))/c%l1**2
   end function critical_damping

   !> x'' + 2 zeta wn x' + wn**2 x = 0 from x0, v0 after tau: x and x'.
   !! One formula for every damping, x = e**(-a tau) (x0 C + (v0 + a x0) S),
   !! a = zeta wn, with C = cos(w tau), S = sin(w tau)/w, w**2 = wn**2 (1 -
   !! zeta**2); C = 1, S = tau at zeta = 1; cosh and sinh above it (as
   !! exponentials of their own, so that no factor overflows).
   pure subroutine free_motion(zeta, wn, x0, v0, tau, x, v)
      real(wp), intent(in) :: zeta, wn, x0, v0, tau
      real(wp), intent(out) :: x, v
      real(wp) :: a, sigma, w, cpart, spart, e, ep, em
      a = zeta*wn
      sigma = wn**2*(1.0_wp - zeta**2)
      if (sigma > 0.0_wp) then
         w = sqrt(sigma)
         e = exp(-a*tau)
         cpart = e*cos(w*tau)
         if (w*tau < 1.0e-8_wp) then
            spart = e*tau
         else
            spart = e*sin(w*tau)/w
         end if
      else if (sigma < 0.0_wp) then
         w = sqrt(-sigma)
         ep = exp((w - a)*tau)
         em = exp(-(w + a)*tau)
         cpart = 0.5_wp*(ep + em)
         if (w*tau < 1.0e-8_wp) then
            spart = exp(-a*tau)*tau
         else
            spart = 0.5_wp*(ep - em)/w
         end if
      else
         cpart = exp(-a*tau)
         spart = cpart*tau
      end if
      x = x0*cpart + (v0 + a*x0)*spart
      v = v0*cpart - (wn**2*x0 + a*v0)*spart
   end subroutine free_motion

   !> The first tau > 0 where x' = 0 in free_motion, the motion starting
   !! in the direction s (+1 or -1; v0 = 0 or of that sign); huge when x'
   !! never returns to 0. From x' = e**(-a tau) (v0 C - q S), q = wn**2 x0 +
   !! a v0: tan(w tau) = v0 w / q (w real), tau = v0 / q (critical), tanh(w
   !! tau) = v0 w / q (w imaginary).
   pure real(wp) function phase_end(zeta, wn, x0, v0, s) result(tau)
      real(wp), intent(in) :: zeta, wn, x0, v0, s
      real(wp) :: q, sigma, w, r
      q = s*(wn**2*x0 + zeta*wn*v0)
      sigma = wn**2*(1.0_wp - zeta**2)
      tau = huge(1.0_wp)
      if (sigma > 0.0_wp) then
         w = sqrt(sigma)
         ! (abs: s v0 >= 0, and from rest atan2 must see +0, not -0, to give pi)
         tau = atan2(abs(v0)*w, q)/w
      else if (sigma < 0.0_wp) then
         w = sqrt(-sigma)
         if (q > 0.0_wp) then
            r = abs(v0)*w/q
            if (r < 1.0_wp) tau = atanh(r)/w
         end if
      else if (q > 0.0_wp) then
         tau = abs(v0)/q
      end if
      if (.not. tau > 0.0_wp) tau = huge(1.0_wp)
   end function phase_end

   !> Solve case c up to its TMAX: the front occupant's phases, the rear
   !! occupant's stop, the contacts between them and their least separation.
   pure function analog_solve(c) result(sol)
      type(analog_case_t), intent(in) :: c
      type(analog_solution_t) :: sol
      sol%c = c
      sol%omega0 = initial_rate(c%speed, c%body)
      sol%kappa = harness_stiffness(c)
      sol%wn = harness_frequency(c)
      sol%damping = c%zeta*2.0_wp*sqrt(c%body%inertia*sol%kappa)
      call solve_front(sol)
      sol%t_rear_stop = rear_stop_time(c, sol%omega0)
      call find_contacts(sol)
   end function analog_solve

   !> Section D's front occupant, I0 theta1'' + l1**2 c theta1' + l1**2 k1
   !! theta1 + s T = 0 with s the sign of theta1' (errata D-1, D-2), phase by
   !! phase. At theta1' = 0 the body stays when |l1**2 k1 theta1| <= T (the
   !! hip torque is friction: it holds up to T), else it starts back the way
   !! the harness pulls it.
   pure subroutine solve_front(sol)
      type(analog_solution_t), intent(inout) :: sol
      real(wp) :: t, theta, rate, s, tau, x, v
      allocate (sol%phase(16))
      t = 0.0_wp
      theta = 0.0_wp
      rate = sol%omega0
      if (.not. abs(rate) > 0.0_wp) then
         call add_phase(sol, front_phase_t(t0=t, theta0=theta, rate0=0.0_wp, centre=theta, at_rest=.true.))
         return
      end if
      s = sign(1.0_wp, rate)
      do
         associate (p => front_phase_t(t0=t, theta0=theta, rate0=rate, centre=-s*sol%c%torque/sol%kappa))
            tau = phase_end(sol%c%zeta, sol%wn, p%theta0 - p%centre, p%rate0, s)
            call add_phase(sol, p)
         end associate
         if (tau > sol%c%t_max - t) exit
         associate (p => sol%phase(sol%n_phase))
            p%t_end = t + tau
            call free_motion(sol%c%zeta, sol%wn, p%theta0 - p%centre, p%rate0, tau, x, v)
            theta = p%centre + x
         end associate
         t = t + tau
         rate = 0.0_wp
         if (sol%kappa*abs(theta) <= sol%c%torque) then
            call add_phase(sol, front_phase_t(t0=t, theta0=theta, rate0=0.0_wp, centre=theta, at_rest=.true.))
            exit
         end if
         s = -sign(1.0_wp, theta)
      end do
   end subroutine solve_front

   pure subroutine add_phase(sol, p)
      type(analog_solution_t), intent(inout) :: sol
      type(front_phase_t), intent(in) :: p
      type(front_phase_t), allocatable :: more(:)
      if (sol%n_phase == size(sol%phase)) then
         allocate (more(2*size(sol%phase)))
         more(1:sol%n_phase) = sol%phase(1:sol%n_phase)
         call move_alloc(more, sol%phase)
      end if
      sol%n_phase = sol%n_phase + 1
      sol%phase(sol%n_phase) = p
   end subroutine add_phase

   !> theta1 and theta1' (rad, rad/s) at t.
   pure subroutine front_state(sol, t, theta, rate)
      type(analog_solution_t), intent(in) :: sol
      real(wp), intent(in) :: t
      real(wp), intent(out) :: theta, rate
      integer :: k, lo, hi, mid
      real(wp) :: x
      ! the last phase starting at or before t, by bisection (a stiff harness
      ! over TMAX makes many phases, and the contact scan asks often)
      lo = 1
      hi = sol%n_phase
      do while (lo < hi)
         mid = (lo + hi + 1)/2
         if (sol%phase(mid)%t0 <= t) then
            lo = mid
         else
            hi = mid - 1
         end if
      end do
      k = lo
      associate (p => sol%phase(k))
         if (p%at_rest) then
            theta = p%theta0
            rate = 0.0_wp
         else
            call free_motion(sol%c%zeta, sol%wn, p%theta0 - p%centre, p%rate0, t - p%t0, x, rate)
            theta = p%centre + x
            if (t >= p%t_end) rate = 0.0_wp
         end if
      end associate
   end subroutine front_state

   !> Section D's rear occupant, I0 theta2'' = 0 (erratum D-4): theta2 =
   !! omega t up to the stop, then held there. With a hip torque T2 of his
   !! own (rear_torque), I0 theta2'' = -T2 while he turns forward.
   pure subroutine rear_state(c, omega, t, theta, rate)
      type(analog_case_t), intent(in) :: c
      real(wp), intent(in) :: omega, t
      real(wp), intent(out) :: theta, rate
      real(wp) :: alpha, te
      alpha = c%rear_torque/c%body%inertia
      te = min(t, rear_stop_time(c, omega))
      if (alpha > 0.0_wp) te = min(te, omega/alpha)   ! the torque brought him to rest first
      theta = omega*te - 0.5_wp*alpha*te**2
      rate = omega - alpha*te
      if (t >= rear_stop_time(c, omega) .or. rate <= 0.0_wp) rate = 0.0_wp
   end subroutine rear_state

   !> When the rear occupant reaches the stop (huge: never).
   pure real(wp) function rear_stop_time(c, omega) result(ts)
      type(analog_case_t), intent(in) :: c
      real(wp), intent(in) :: omega
      real(wp) :: alpha, disc
      alpha = c%rear_torque/c%body%inertia
      ts = huge(1.0_wp)
      if (omega <= 0.0_wp) return
      if (.not. alpha > 0.0_wp) then
         ts = c%body%stop_angle/omega
      else
         ! omega t - alpha t**2 / 2 = stop: the smaller root, if any
         disc = omega**2 - 2.0_wp*alpha*c%body%stop_angle
         if (disc >= 0.0_wp) ts = 2.0_wp*c%body%stop_angle/(omega + sqrt(disc))
      end if
   end function rear_stop_time

   !> The separation of the occupants (in) at t: the least of the rear
   !! occupant's head from the front occupant's body line and the front
   !! occupant's head from the rear occupant's; negative when a head is past
   !! the other's line (the analog has no force between them: the bodies are
   !! lines and pass through each other; docs/analog.md). Hips at the same
   !! height, B behind A by L; angles from the vertical, forward positive.
   pure real(wp) function separation(sol, t) result(gap)
      type(analog_solution_t), intent(in) :: sol
      real(wp), intent(in) :: t
      real(wp) :: th1, th2, r1, r2, len
      real(wp) :: a(2), b(2), u1(2), u2(2), n1(2), n2(2)
      call front_state(sol, t, th1, r1)
      call rear_state(sol%c, sol%omega0, t, th2, r2)
      len = sol%c%body%length
      b = [0.0_wp, 0.0_wp]
      a = [sol%c%spacing, 0.0_wp]
      u1 = [sin(th1), cos(th1)]
      u2 = [sin(th2), cos(th2)]
      n1 = [-cos(th1), sin(th1)]   ! the front body's rear side
      n2 = [cos(th2), -sin(th2)]   ! the rear body's front side
      gap = min(point_to_body(b + len*u2, a, u1, n1, len), point_to_body(a + len*u1, b, u2, n2, len))
   end function separation

   !> A head p against a body from its hip h along u (length len): the
   !! signed distance along n where p lies beside the body, else its
   !! distance from the body's nearer end.
   pure real(wp) function point_to_body(p, h, u, n, len) result(d)
      real(wp), intent(in) :: p(2), h(2), u(2), n(2), len
      real(wp) :: along
      along = dot_product(p - h, u)
      if (along < 0.0_wp) then
         d = norm2(p - h)
      else if (along > len) then
         d = norm2(p - h - len*u)
      else
         d = dot_product(p - h, n)
      end if
   end function point_to_body

   !> The contacts (separation <= 0) up to TMAX: scanned at scan_step (or
   !! finer for a stiff harness), each change located by bisection.
   pure subroutine find_contacts(sol)
      type(analog_solution_t), intent(inout) :: sol
      real(wp) :: h, t0, t1, g0, g1
      integer :: n, k
      allocate (sol%contact(4))
      h = scan_step
      if (sol%wn > 0.0_wp) h = min(h, 0.02_wp/sol%wn)
      n = max(1, ceiling(sol%c%t_max/h))
      h = sol%c%t_max/n
      t0 = 0.0_wp
      g0 = separation(sol, t0)
      sol%min_gap = g0
      sol%t_min_gap = t0
      if (g0 <= 0.0_wp) call begin_contact(sol, 0.0_wp)
      do k = 1, n
         t1 = min(k*h, sol%c%t_max)
         g1 = separation(sol, t1)
         if (g1 < sol%min_gap) then
            sol%min_gap = g1
            sol%t_min_gap = t1
         end if
         if (g0 > 0.0_wp .and. g1 <= 0.0_wp) call begin_contact(sol, crossing(t0, t1))
         if (g0 <= 0.0_wp .and. g1 > 0.0_wp) sol%contact(sol%n_contact)%t_end = crossing(t0, t1)
         t0 = t1
         g0 = g1
      end do
   contains
      pure subroutine begin_contact(sol, t)
         type(analog_solution_t), intent(inout) :: sol
         real(wp), intent(in) :: t
         type(contact_t), allocatable :: more(:)
         if (sol%n_contact == size(sol%contact)) then
            allocate (more(2*size(sol%contact)))
            more(1:sol%n_contact) = sol%contact(1:sol%n_contact)
            call move_alloc(more, sol%contact)
         end if
         sol%n_contact = sol%n_contact + 1
         sol%contact(sol%n_contact) = contact_t(t_begin=t)
      end subroutine begin_contact
      !> Where the separation changes sign in [lo, hi] (to t_tol).
      pure real(wp) function crossing(lo_in, hi_in) result(t)
         real(wp), intent(in) :: lo_in, hi_in
         real(wp) :: lo, hi, mid
         logical :: lo_apart
         lo = lo_in
         hi = hi_in
         lo_apart = separation(sol, lo) > 0.0_wp
         do while (hi - lo > t_tol)
            mid = 0.5_wp*(lo + hi)
            if (mid <= lo .or. mid >= hi) exit
            if ((separation(sol, mid) > 0.0_wp) .eqv. lo_apart) then
               lo = mid
            else
               hi = mid
            end if
         end do
         t = hi
      end function crossing
   end subroutine find_contacts
end module analog_model
