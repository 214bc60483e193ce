!> Report C.4.c, figure 9: the angular restraint (stop) torque of a joint
!! as a function of its relative angle, in the linear, cubic and tabulated
!! forms, and the energy stored in it.
!!
!! The figure is lost in the OCR; the reading adopted (docs/errata.md, D-3):
!! the stops act on the relative angle delta = alpha_i - alpha_m itself;
!! beyond the lower stop omega the penetration is d = omega - delta and the
!! torque on segment i is +f(d); beyond the upper stop Omega, d = delta -
!! Omega and the torque is -f(d); f(d) = c1 d + c2 d^2 + c3 d^3 (linear:
!! c2 = c3 = 0; c1 = T' or T-hat') or the tabulated curve. Coefficients
!! are magnitudes; the report prints the knee's T-hat as -474.7 in its
!! torque sign convention.
module joint_restraints
   use kinds, only: wp
   use table_search, only: bracket_index
   use model, only: restraint_t, stop_curve_t, form_table
   implicit none
   private

   public :: restraint_torque, restraint_energy, restraint_is_active

contains

   !> True when the restraint can exert a torque at all (a non-zero
   !! coefficient, or a curve): only such joints enter the scene's stop list.
   pure logical function restraint_is_active(r)
      type(restraint_t), intent(in) :: r
      if (r%form == form_table) then
         restraint_is_active = .true.
      else
         restraint_is_active = any(abs(r%coef_lower) > 0.0_wp) .or. any(abs(r%coef_upper) > 0.0_wp)
      end if
   end function restraint_is_active

   !> Torque on segment i (reaction -torque on segment m) at relative angle delta.
   pure real(wp) function restraint_torque(r, delta) result(torque)
      type(restraint_t), intent(in) :: r
      real(wp), intent(in) :: delta
      if (delta < r%lower) then
         torque = side_torque(r%form, r%coef_lower, r%curve_lower, r%lower - delta)
      else if (delta > r%upper) then
         torque = -side_torque(r%form, r%coef_upper, r%curve_upper, delta - r%upper)
      else
         torque = 0.0_wp
      end if
   end function restraint_torque

   !> Energy stored in the restraint: the integral of f over the penetration.
   pure real(wp) function restraint_energy(r, delta) result(energy)
      type(restraint_t), intent(in) :: r
      real(wp), intent(in) :: delta
      if (delta < r%lower) then
         energy = side_energy(r%form, r%coef_lower, r%curve_lower, r%lower - delta)
      else if (delta > r%upper) then
         energy = side_energy(r%form, r%coef_upper, r%curve_upper, delta - r%upper)
      else
         energy = 0.0_wp
      end if
   end function restraint_energy

   pure real(wp) function side_torque(form, coef, curve, d) result(f)
      integer, intent(in) :: form
      real(wp), intent(in) :: coef(3), d
      type(stop_curve_t), intent(in) :: curve
      integer :: k
      if (form == form_table) then
         k = bracket_index(curve%depth, d)
         f = curve%torque(k) + (curve%torque(k + 1) - curve%torque(k)) &
             *(d - curve%depth(k))/(curve%depth(k + 1) - curve%depth(k))
      else
         f = d*(coef(1) + d*(coef(2) + d*coef(3)))
      end if
   end function side_torque

   pure real(wp) function side_energy(form, coef, curve, d) result(e)
      integer, intent(in) :: form
      real(wp), intent(in) :: coef(3), d
      type(stop_curve_t), intent(in) :: curve
      integer :: k, j
      real(wp) :: fd
      if (form == form_table) then
         ! exact integral of the piecewise-linear curve (trapezoids)
         k = bracket_index(curve%depth, d)
         e = 0.0_wp
         do j = 1, k - 1
            e = e + 0.5_wp*(curve%torque(j) + curve%torque(j + 1))*(curve%depth(j + 1) - curve%depth(j))
         end do
         fd = side_torque(form, coef, curve, d)
         e = e + 0.5_wp*(curve%torque(k) + fd)*(d - curve%depth(k))
      else
         e = d**2*(coef(1)/2.0_wp + d*(coef(2)/3.0_wp + d*coef(3)/4.0_wp))
      end if
   end function side_energy

end module joint_restraints
