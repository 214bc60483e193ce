!> Report C.5: the body matrix A(z) of figure 27 and the solution of
!! A z'' = b. A is the mass matrix of the Lagrangian of section B, hence
!! symmetric positive definite, and its sparsity is fixed by the body's
!! chains (figure 27): segments i /= j are coupled only for the pairs
!! (1,2) (1,3) (1,4) (1,5) (1,6) (2,3) (2,4) (2,5) (2,6) (3,4) (3,5) (3,6)
!! (5,6) (7,8); the hip rows 9 (x_h) and 10 (y_h) couple to every segment;
!! A(9,10) = 0. The legs (7, 8) reach the rest only through rows 9-10 and
!! the head (4) does not touch the arm (5, 6).
!!
!! Two solvers, chosen by body_accelerations' optional argument:
!!
!! * solver_structured (the default): a factorization P A P**T = L D L**T
!!   (L unit lower triangular, D diagonal) written for that structure, with the leaves eliminated first
!!   and the hip last (elimination_order below). In that order the factor
!!   fills in exactly one entry, L(y_h, x_h); its nonzeros below the
!!   diagonal are, row by row, one unbroken run of columns (first_col), so
!!   a profile ("skyline") factorization whose loops run over those runs
!!   reads and writes only the 31 structurally nonzero entries: no zero is
!!   ever touched, no BLAS, no allocation, no square root. Reciprocal
!!   pivots are stored. The
!!   loops carry gfortran's `!GCC$ unroll` directive (a comment to other
!!   compilers): unrolled completely, every bound is a constant and the
!!   loop overhead, which outweighed the arithmetic, goes away (2,400 ->
!!   880 instructions per solve at -O2, docs/performance.md).
!! * solver_dense: LAPACK's unblocked dpotf2 and two BLAS dtrsv (what dpotrs
!!   does), on the whole lower triangle. It is the reference the structured
!!   solve is tested against, and the path for any scene whose coupled
!!   degrees of freedom differ from the body's (body_structure_matches is
!!   false): the structured solve knows only figure 27's pattern.
!!
!! docs/performance.md gives the measurements behind the choice.
module body_matrix
   use kinds, only: wp
   use model, only: n_seg, n_dof
   use preliminary, only: body_constants_t, n_pairs
   use lapack_interfaces, only: dpotf2, dtrsv
   implicit none
   private

   public :: body_matrix_assemble, body_accelerations, body_structure_matches
   public :: solver_structured, solver_dense

   integer, parameter :: solver_structured = 1 !< L D L**T for figure 27's structure (default)
   integer, parameter :: solver_dense = 2      !< LAPACK dpotf2 + BLAS dtrsv, any SPD matrix

   !> The coupled segment pairs of figure 27 that the structured solve is
   !! written for (i < j); preliminary::body_constants lists the same.
   integer, parameter :: coupled_i(n_pairs) = [1, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 5, 7]
   integer, parameter :: coupled_j(n_pairs) = [2, 3, 4, 5, 6, 3, 4, 5, 6, 4, 5, 6, 6, 8]

   !> Elimination order: the generalized coordinate eliminated at step p.
   !! Leaves first - the lower then the upper leg (8, 7), the head (4), the
   !! lower then the upper arm (6, 5) - then the chain 3, 2, 1 and the hip
   !! x_h, y_h last. Eliminating a coordinate couples the coordinates still
   !! to come that it touches; in this order those are already coupled with
   !! each other, except x_h with y_h (every segment touches both): the one
   !! fill-in is L(y_h, x_h).
   integer, parameter :: elimination_order(n_dof) = [8, 7, 4, 6, 5, 3, 2, 1, 9, 10]
   !> The inverse: the step at which coordinate k is eliminated.
   integer, parameter :: step_of(n_dof) = [8, 7, 6, 3, 5, 4, 2, 1, 9, 10]
   !> Row p of L (steps numbered as above) is nonzero from column
   !! first_col(p) to the diagonal and zero left of it:
   !!   p  coordinate  nonzero columns (coordinates)
   !!   1  alpha_8     -
   !!   2  alpha_7     alpha_8
   !!   3  alpha_4     -
   !!   4  alpha_6     -
   !!   5  alpha_5     alpha_6
   !!   6  alpha_3     alpha_4 alpha_6 alpha_5
   !!   7  alpha_2     alpha_4 alpha_6 alpha_5 alpha_3
   !!   8  alpha_1     alpha_4 alpha_6 alpha_5 alpha_3 alpha_2
   !!   9  x_h         all eight segments
   !!  10  y_h         all eight segments, and x_h (the fill-in)
   !! 31 entries below the diagonal: A's 14 pairs, its 16 hip entries and
   !! the fill-in. The other 14 are structural zeros that stay zero: the
   !! head with the arm, (4,5) (4,6), and the legs with the upper body,
   !! (7 or 8, 1..6).
   integer, parameter :: first_col(n_dof) = [1, 1, 3, 4, 4, 3, 3, 3, 1, 1]

contains

   !> Figure 27 (with errata E-27a, E-27b), from cos and sin of the inertial
   !! segment angles: cos(Theta_i - Theta_j) = cos(alpha_i - alpha_j) and
   !! Theta_i - Phi = alpha_i. The solvers fill only what they read
   !! (lower_triangle, structured_fill); the whole matrix is for tests and
   !! checks.
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

   !> True when the body constants couple no segment pair outside figure
   !! 27's pattern, so that the structured solve applies (an entry that
   !! happens to vanish, for a massless segment say, is harmless).
   pure logical function body_structure_matches(bc)
      type(body_constants_t), intent(in) :: bc
      logical :: coupled(n_seg, n_seg)
      integer :: p
      coupled = .false.
      do p = 1, n_seg
         coupled(p, p) = .true.
      end do
      do p = 1, n_pairs
         coupled(coupled_i(p), coupled_j(p)) = .true.
         coupled(coupled_j(p), coupled_i(p)) = .true.
      end do
      ! exactly zero (<= avoids -Wcompare-reals; a NaN counts as coupled)
      body_structure_matches = all(coupled .or. abs(bc%coupling) <= 0.0_wp)
   end function body_structure_matches

   !> Solve A z'' = b. info /= 0 means A was not positive definite and z''
   !! is set to zero: the structured solve returns the coordinate whose
   !! pivot was not positive and finite, the dense one LAPACK's column index
   !! (dpotf2's info, mapped here). An outcome of the right-hand side's
   !! evaluation, not an error: the system answers the stepper with it, and
   !! explains it only if the stepper gives up (docs/architecture.md,
   !! "Errors"). solver (default solver_structured) picks the method; an
   !! unknown one gives info = -7, LAPACK's convention for an invalid
   !! argument (the seventh; occupant_build sets only the two known).
   pure subroutine body_accelerations(bc, c, s, b, zdd, info, solver)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg), b(n_dof)
      real(wp), intent(out) :: zdd(n_dof)
      integer, intent(out) :: info
      integer, intent(in), optional :: solver
      real(wp) :: a(n_dof, n_dof), rdiag(n_dof)
      integer :: method

      method = solver_structured
      if (present(solver)) method = solver
      select case (method)
      case (solver_structured)
         call structured_fill(bc, c, s, a)
         call structured_factor(a, rdiag, info)
         if (info == 0) call structured_solve(a, rdiag, b, zdd)
      case (solver_dense)
         call lower_triangle(bc, c, s, a)
         zdd = b
         call dpotf2('L', n_dof, a, n_dof, info)
         if (info == 0) then
            call dtrsv('L', 'N', 'N', n_dof, a, n_dof, zdd, 1)
            call dtrsv('L', 'T', 'N', n_dof, a, n_dof, zdd, 1)
         end if
      case default
         info = -7
      end select
      if (info /= 0) zdd = 0.0_wp
   end subroutine body_accelerations

   !> The lower triangle of A, all dpotf2 reads (the same entries as
   !! body_matrix_assemble, filled pair by pair).
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

   !> The structurally nonzero entries of P A P**T into u, stored as the
   !! upper triangle (u(q, p) = A(row p, column q) for q <= p, steps in
   !! elimination_order), so that row p of L is the contiguous column u(:, p).
   !! Entries outside the profile are left undefined and never read.
   pure subroutine structured_fill(bc, c, s, u)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg)
      real(wp), intent(out) :: u(n_dof, n_dof)
      integer :: k, i, j
      !GCC$ unroll 8
      do k = 1, n_seg
         ! figure 27 diagonal a_10..a_17 and hip rows -a_k sin, a_k cos
         u(step_of(k), step_of(k)) = bc%a(9 + k)
         u(step_of(k), 9) = -bc%a(k)*s(k)
         u(step_of(k), 10) = bc%a(k)*c(k)
      end do
      !GCC$ unroll 14
      do k = 1, n_pairs
         ! figure 27: coupling(i, j) cos(alpha_i - alpha_j); i is eliminated after j
         i = coupled_i(k)
         j = coupled_j(k)
         u(step_of(j), step_of(i)) = bc%coupling(i, j)*(c(i)*c(j) + s(i)*s(j))
      end do
      ! figure 27: a_9 on the hip diagonal, A(9,10) = 0 where the fill-in goes
      u(9, 9) = bc%a(9)
      u(9, 10) = 0.0_wp
      u(10, 10) = bc%a(9)
   end subroutine structured_fill

   !> C.5: profile L D L**T factorization, row by row (L unit lower, in u as
   !! structured_fill stores A): with c_pq = L(p,q) D(q),
   !! c_pq = A(p,q) - sum_k c_pk L(q,k) for q in the profile of row p,
   !! L(p,q) = c_pq / D(q), then D(p) = A(p,p) - sum_q c_pq L(p,q). The sums
   !! run over the columns both rows hold, from max(first_col(p),
   !! first_col(q)). rdiag(p) = 1/D(p). Without Cholesky's square roots the
   !! chain of dependent pivots (alpha_6 -> alpha_5 -> alpha_3 -> ... -> y_h)
   !! is shorter, which is what sets the solve's time (docs/performance.md).
   !! A pivot that is not positive and finite means A is not positive
   !! definite: info = the coordinate eliminated there.
   pure subroutine structured_factor(u, rdiag, info)
      real(wp), intent(inout) :: u(n_dof, n_dof)
      real(wp), intent(out) :: rdiag(n_dof)
      integer, intent(out) :: info
      real(wp) :: pivot, c(n_dof), l_pq
      integer :: p, q, k
      info = 0
      !GCC$ unroll 10
      do p = 1, n_dof
         pivot = u(p, p)
         !GCC$ unroll 9
         do q = first_col(p), p - 1
            c(q) = u(q, p)
            !GCC$ unroll 9
            do k = max(first_col(p), first_col(q)), q - 1
               c(q) = c(q) - c(k)*u(k, q)
            end do
            l_pq = c(q)*rdiag(q)
            u(q, p) = l_pq
            pivot = pivot - c(q)*l_pq
         end do
         ! (a subnormal pivot too: its reciprocal would overflow)
         if (.not. (pivot >= tiny(pivot) .and. pivot <= huge(pivot))) then
            info = elimination_order(p)
            return
         end if
         rdiag(p) = 1.0_wp/pivot
      end do
   end subroutine structured_factor

   !> C.5: z'' = x = A**-1 b from the factor: L y = P b forward by rows,
   !! v = D**-1 y, L**T w = v backward by columns (both over the profile
   !! only), x = P**T w.
   pure subroutine structured_solve(u, rdiag, b, x)
      real(wp), intent(in) :: u(n_dof, n_dof), rdiag(n_dof), b(n_dof)
      real(wp), intent(out) :: x(n_dof)
      real(wp) :: y(n_dof), t
      integer :: p, k
      !GCC$ unroll 10
      do p = 1, n_dof
         t = b(elimination_order(p))
         !GCC$ unroll 9
         do k = first_col(p), p - 1
            t = t - u(k, p)*y(k)
         end do
         y(p) = t
      end do
      !GCC$ unroll 10
      do p = 1, n_dof
         y(p) = y(p)*rdiag(p)
      end do
      !GCC$ unroll 10
      do p = n_dof, 1, -1
         t = y(p)
         !GCC$ unroll 9
         do k = first_col(p), p - 1
            y(k) = y(k) - u(k, p)*t
         end do
         x(elimination_order(p)) = t
      end do
   end subroutine structured_solve
end module body_matrix
