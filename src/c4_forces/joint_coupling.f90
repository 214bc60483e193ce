!> Report C.4.c, Table 6: joint i couples segment i and its partner m(i)
!! through the relative angle alpha_i - alpha_m; a joint torque tau acts
!! +tau on segment i and -tau on segment m, which reproduces every J_i of
!! C.4.c (docs/errata.md, "Joint springs"). Shared by the joint effects.
module joint_coupling
   use kinds, only: wp
   use model, only: n_dof, n_joint, joint_partner
   use output_series, only: output_column_t, output_series_t, column, series_new
   implicit none
   private

   public :: relative_angle, relative_rate, apply_joint_torque, joint_columns, joint_list_text, per_joint_series

contains

   !> alpha_i - alpha_m(i).
   pure real(wp) function relative_angle(z, i)
      real(wp), intent(in) :: z(n_dof)
      integer, intent(in) :: i
      relative_angle = z(i) - z(joint_partner(i))
   end function relative_angle

   !> alpha-dot_i - alpha-dot_m(i).
   pure real(wp) function relative_rate(zdot, i)
      real(wp), intent(in) :: zdot(n_dof)
      integer, intent(in) :: i
      relative_rate = zdot(i) - zdot(joint_partner(i))
   end function relative_rate

   !> +tau on segment i, -tau on its partner.
   pure subroutine apply_joint_torque(b, i, tau)
      real(wp), intent(inout) :: b(n_dof)
      integer, intent(in) :: i
      real(wp), intent(in) :: tau
      b(i) = b(i) + tau
      b(joint_partner(i)) = b(joint_partner(i)) - tau
   end subroutine apply_joint_torque

   !> One output column per joint, in the given unit.
   pure function joint_columns(unit) result(cols)
      character(len=*), intent(in) :: unit
      type(output_column_t) :: cols(n_joint)
      character(len=*), parameter :: names(n_joint) = [character(len=8) :: &
         'hip', 'lspine', 'uspine', 'neck', 'shoulder', 'elbow', 'knee']
      integer :: i
      do i = 1, n_joint
         cols(i) = column(trim(names(i)), unit)
      end do
   end function joint_columns

   !> An effect's one output series of a value per joint in in*lb (the
   !! joints' energies or work), printed from NOUT = 3.
   pure function per_joint_series(name, title, description) result(series)
      character(len=*), intent(in) :: name, title, description
      type(output_series_t), allocatable :: series(:)
      allocate (series(1))
      series(1) = series_new(name, title, description, 3)
      series(1)%col = joint_columns('in*lb')
   end function per_joint_series

   !> "joints 1 2 5" for the listing.
   pure function joint_list_text(joints) result(s)
      integer, intent(in) :: joints(:)
      character(len=:), allocatable :: s
      character(len=4) :: buf
      integer :: q
      s = 'joints'
      do q = 1, size(joints)
         write (buf, '(i0)') joints(q)
         s = s//' '//trim(buf)
      end do
   end function joint_list_text
end module joint_coupling
