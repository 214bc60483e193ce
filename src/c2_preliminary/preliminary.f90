!> Report C.2, preliminary calculations: the body-matrix parameters a_1..a_17
!! and the couplings of figure 27, computed once per run, and the initial
!! state of the generalized coordinates.
module preliminary
   use kinds, only: wp
   use model, only: body_section_t, vehicle_section_t, n_seg, n_dof, hip_x, hip_y
   implicit none
   private

   public :: body_constants_t, body_constants, initial_state, n_pairs

   !> Segment pairs coupled in the body matrix (figure 27).
   integer, parameter :: n_pairs = 14

   !> Constants of the body matrix (C.2, fig. 27, with errata E-C2a..c).
   type :: body_constants_t
      real(wp) :: a(17) = 0.0_wp
      !> coupling(i,j): A(i,j) = coupling(i,j)*cos(alpha_i - alpha_j) for i /= j
      !! (the compact rule of errata.md); zero for segments not in one chain.
      real(wp) :: coupling(n_seg, n_seg) = 0.0_wp
      !> the same couplings as a list of the 14 coupled pairs (i < j), for
      !! the loops that run on every evaluation
      integer :: pair_i(n_pairs) = 0, pair_j(n_pairs) = 0
      real(wp) :: pair_c(n_pairs) = 0.0_wp
      real(wp) :: total_mass = 0.0_wp
   end type body_constants_t

contains

   !> a_1..a_17 of C.2. a_i (i <= 8) is the first moment of the mass carried
   !! by segment i about its proximal joint; a_9 the total mass; a_10..a_17
   !! the moments of inertia of those masses about the same joint.
   pure function body_constants(body) result(bc)
      type(body_section_t), intent(in) :: body
      type(body_constants_t) :: bc
      real(wp) :: ms(n_seg), rh(n_seg), ln(n_seg), in(n_seg)
      integer :: i, n
      integer, parameter :: pair_i(n_pairs) = [1, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 5, 7]
      integer, parameter :: pair_j(n_pairs) = [2, 3, 4, 5, 6, 3, 4, 5, 6, 4, 5, 6, 6, 8]
      integer, parameter :: pair_l(n_pairs) = [1, 1, 1, 1, 1, 2, 2, 2, 2, 3, 4, 4, 5, 7]

      ms = body%mass
      rh = body%rho
      ln = body%length
      in = body%inertia
      ! C.2: i = 4,6,8
      bc%a(4) = ms(4)*rh(4)
      bc%a(6) = ms(6)*rh(6)
      bc%a(8) = ms(8)*rh(8)
      ! i = 5,7
      bc%a(5) = ms(5)*rh(5) + ms(6)*ln(5)
      bc%a(7) = ms(7)*rh(7) + ms(8)*ln(7)
      ! i = 1,2: segments 2..6 (resp. 3..6) hang at L_i
      bc%a(1) = ms(1)*rh(1) + ln(1)*sum(ms(2:6))
      bc%a(2) = ms(2)*rh(2) + ln(2)*sum(ms(3:6))
      ! a_3: the head hangs at the neck offset L3, the arms at the shoulder offset L4
      bc%a(3) = ms(3)*rh(3) + ms(4)*ln(3) + (ms(5) + ms(6))*ln(4)
      bc%a(9) = sum(ms)
      ! i = 10,11 with L squared (erratum E-C2a; rule not applied to a_12, E-C2b)
      bc%a(10) = in(1) + ms(1)*rh(1)**2 + ln(1)**2*sum(ms(2:6))
      bc%a(11) = in(2) + ms(2)*rh(2)**2 + ln(2)**2*sum(ms(3:6))
      bc%a(12) = in(3) + ms(3)*rh(3)**2 + ms(4)*ln(3)**2 + (ms(5) + ms(6))*ln(4)**2
      ! i = 13,15,17: I_{i-9} (erratum E-C2c)
      do i = 13, 17, 2
         bc%a(i) = in(i - 9) + ms(i - 9)*rh(i - 9)**2
      end do
      ! i = 14,16
      bc%a(14) = in(5) + ms(5)*rh(5)**2 + ln(5)**2*ms(6)
      bc%a(16) = in(7) + ms(7)*rh(7)**2 + ln(7)**2*ms(8)
      bc%total_mass = bc%a(9)

      ! figure 27 off-diagonal terms (with errata E-27a, E-27b): segment i
      ! carries j at the length L_k, giving coupling L_k a_j
      bc%coupling = 0.0_wp
      do n = 1, n_pairs
         bc%coupling(pair_i(n), pair_j(n)) = ln(pair_l(n))*bc%a(pair_j(n))
         bc%coupling(pair_j(n), pair_i(n)) = bc%coupling(pair_i(n), pair_j(n))
      end do
      bc%pair_i = pair_i
      bc%pair_j = pair_j
      bc%pair_c = [(bc%coupling(pair_i(n), pair_j(n)), n=1, n_pairs)]
   end function body_constants

   !> Initial generalized coordinates and rates (C.1, C.2): alpha_i0 =
   !! Theta_i0 - Phi_0; the hip starts at the origin with the vehicle's
   !! velocity; segment rates relative to the interior are converted to
   !! inertial rates (alpha-dot = Theta-dot - Phi-dot).
   pure subroutine initial_state(body, vehicle, z, zdot)
      type(body_section_t), intent(in) :: body
      type(vehicle_section_t), intent(in) :: vehicle
      real(wp), intent(out) :: z(n_dof), zdot(n_dof)
      z(1:n_seg) = body%theta0 - vehicle%phi0
      z(hip_x) = 0.0_wp
      z(hip_y) = 0.0_wp
      zdot(1:n_seg) = body%theta_dot0 - vehicle%phi_dot0
      zdot(hip_x) = vehicle%xc_dot0
      zdot(hip_y) = vehicle%yc_dot0
   end subroutine initial_state
end module preliminary
