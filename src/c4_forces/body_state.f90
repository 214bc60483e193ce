!> What every effect sees at one evaluation (C.4): the state an effect's
!! forces are a function of, filled by the occupant (occupant_state,
!! occupant_vehicle, occupant_frame) at every evaluation.
module body_state
   use kinds, only: wp
   use model, only: n_dof, n_seg
   use vehicle_motion, only: vehicle_state_t
   implicit none
   private

   public :: body_state_t

   !> What every effect sees at one evaluation: the time, the occupant's
   !! generalized coordinates and rates, the sines and cosines of the
   !! segment angles, and the vehicle's state (filled only when an effect of
   !! the occupant needs it); after the vehicle's state, when an effect needs
   !! them (needs_joints: the contact pairs' bound, pair_far, reads them 20
   !! times an evaluation), the segments' joints and axes in the interior
   !! frame and the sizes that bound them (occupant_frame). No default
   !! values: it is filled at every evaluation (occupant_state), and
   !! initializing it there would cost as much as a force.
   type :: body_state_t
      real(wp) :: t
      real(wp) :: z(n_dof), zdot(n_dof)
      real(wp) :: c(n_seg), s(n_seg)
      type(vehicle_state_t) :: vehicle
      !> segment i's proximal joint and its e(theta_i) in the interior frame
      !! (x = R(Phi)(X - x_c), the start of C.4)
      real(wp) :: frame_joint(2, n_seg), frame_axis(2, n_seg)
      !> |X| + |Y| of segment i's joint (inertial) + |x_c| + |y_c|: the
      !! coordinates' size; sum |z'| + sum |vehicle rates|: the rates' size
      real(wp) :: joint_size(n_seg), rate_size
   end type body_state_t
end module body_state
