!> Working precision and the physical constants every module shares.
!! Units are the report's (section A, list of parameters): inch, pound force,
!! second, radian; mass in lb*s^2/in.
module kinds
   use, intrinsic :: iso_fortran_env, only: real64, int64
   implicit none
   private

   public :: wp, i8, pi, deg, g_std, inch_m, inch_mm, pound_force_n

   !> Working precision: IEEE double.
   integer, parameter :: wp = real64
   !> Long integers for counters (evaluations, steps).
   integer, parameter :: i8 = int64

   real(wp), parameter :: pi = 3.14159265358979323846264338327950288_wp
   !> One degree in radians (decks give angles in degrees).
   real(wp), parameter :: deg = pi/180.0_wp
   !> Standard gravity in in/s^2 (9.80665 m/s^2 / 0.0254 m/in).
   real(wp), parameter :: g_std = 9.80665_wp/0.0254_wp
   !> The inch in metres and in millimetres, and the pound-force in newtons
   !! (exact by definition: the SI figures of the FMVSS table and ISO-MME).
   real(wp), parameter :: inch_m = 0.0254_wp, inch_mm = 25.4_wp
   real(wp), parameter :: pound_force_n = 4.4482216152605_wp
end module kinds
