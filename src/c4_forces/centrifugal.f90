!> Report C.4.a: the generalized forces quadratic in the angular rates
!! (centrifugal terms), already on the right-hand side of A z'' = b.
module centrifugal
   use kinds, only: wp
   use model, only: n_seg, n_dof
   use preliminary, only: body_constants_t, n_pairs
   implicit none
   private

   public :: centrifugal_forces

contains

   !> Add C_1..C_10 to b. C.4.a with A_ij = alpha-dot_j**2 sin(alpha_j - alpha_i)
   !! (erratum E-Cb: no divisor) and C_1 summed over j = 2..6 (erratum E-Ca);
   !! in general C_i = sum_j coupling(i,j) A_ij, the coupling being that of
   !! figure 27. sin(alpha_j - alpha_i) = s_j c_i - c_j s_i avoids more trig.
   pure subroutine centrifugal_forces(bc, c, s, zdot, b)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg), zdot(n_dof)
      real(wp), intent(inout) :: b(n_dof)
      real(wp) :: w2(n_seg), sji
      integer :: p, i, j
      w2 = zdot(1:n_seg)**2
      ! each coupled pair (i, j) adds to C_i and, with the opposite sine, to C_j
      do p = 1, n_pairs
         i = bc%pair_i(p)
         j = bc%pair_j(p)
         sji = bc%pair_c(p)*(s(j)*c(i) - c(j)*s(i))
         b(i) = b(i) + sji*w2(j)
         b(j) = b(j) - sji*w2(i)
      end do
      ! C_9, C_10
      b(9) = b(9) + sum(bc%a(1:n_seg)*w2*c)
      b(10) = b(10) + sum(bc%a(1:n_seg)*w2*s)
   end subroutine centrifugal_forces
end module centrifugal
