!> Report C.5: the body matrix A(z) of figure 27 and the solution of
!! A z'' = b with LAPACK. A is the mass matrix of the Lagrangian of section
!! B, hence symmetric positive definite: Cholesky factorization by LAPACK's
!! dpotf2, then two triangular solves (BLAS dtrsv, as dpotrs does). For a
!! 10 x 10 matrix the unblocked dpotf2 is about twice as fast as dposv,
!! whose blocked dpotrf recurses into level-3 BLAS (docs/performance.md).
module body_matrix
   use kinds, only: wp
   use model, only: n_seg, n_dof
   use preliminary, only: body_constants_t, n_pairs
   use lapack_interfaces, only: dpotf2, dtrsv
   implicit none
   private

   public :: body_matrix_assemble, body_accelerations

contains

   !> Figure 27 (with errata E-27a, E-27b), from cos and sin of the inertial
   !! segment angles: cos(Theta_i - Theta_j) = cos(alpha_i - alpha_j) and
   !! Theta_i - Phi = alpha_i. Only the lower triangle is needed by the
   !! solver, but the whole matrix is filled for tests and checks.
   pure subroutine body_matrix_assemble(bc, c, s, a)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg)
      real(wp), intent(out) :: a(n_dof, n_dof)
      integer :: i, j
      do j = 1, n_seg
         a(j, j) = bc%a(9 + j)
         do i = j + 1, n_seg
            a(i, j) = bc%coupling(i, j)*(c(i)*c(j) + s(i)*s(j))
            a(j, i) = a(i, j)
         end do
         a(9, j) = -bc%a(j)*s(j)
         a(10, j) = bc%a(j)*c(j)
         a(j, 9) = a(9, j)
         a(j, 10) = a(10, j)
      end do
      a(9, 9) = bc%a(9)
      a(10, 10) = bc%a(9)
      a(9, 10) = 0.0_wp
      a(10, 9) = 0.0_wp
   end subroutine body_matrix_assemble

   !> The lower triangle of A, all the factorization reads (the same
   !! entries as body_matrix_assemble, filled pair by pair).
   pure subroutine lower_triangle(bc, c, s, a)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg)
      real(wp), intent(out) :: a(n_dof, n_dof)
      integer :: p, j
      a(1:n_seg, 1:n_seg) = 0.0_wp
      do j = 1, n_seg
         a(j, j) = bc%a(9 + j)
         a(9, j) = -bc%a(j)*s(j)
         a(10, j) = bc%a(j)*c(j)
      end do
      do p = 1, n_pairs
         a(bc%pair_j(p), bc%pair_i(p)) = bc%pair_c(p)*(c(bc%pair_i(p))*c(bc%pair_j(p)) &
                                                       + s(bc%pair_i(p))*s(bc%pair_j(p)))
      end do
      a(9, 9) = bc%a(9)
      a(10, 9) = 0.0_wp
      a(10, 10) = bc%a(9)
   end subroutine lower_triangle

   !> Solve A z'' = b. info /= 0 means A was not positive definite (the
   !! caller reports a numerical failure); z'' is then meaningless.
   pure subroutine body_accelerations(bc, c, s, b, zdd, info)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg), b(n_dof)
      real(wp), intent(out) :: zdd(n_dof)
      integer, intent(out) :: info
      real(wp) :: a(n_dof, n_dof)
      call lower_triangle(bc, c, s, a)
      zdd = b
      call dpotf2('L', n_dof, a, n_dof, info)
      if (info /= 0) return
      call dtrsv('L', 'N', 'N', n_dof, a, n_dof, zdd, 1)
      call dtrsv('L', 'T', 'N', n_dof, a, n_dof, zdd, 1)
   end subroutine body_accelerations
end module body_matrix
