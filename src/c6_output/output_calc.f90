!> Report C.6, output calculations for one occupant at one accepted state:
!! head and chest accelerations, the vehicle's motion, the generalized
!! coordinates, angles relative to the interior, joint angles and positions
!! relative to the interior (C.4), kinetic energies of the vehicle and the
!! segments. The series these fill are declared here (body_series) for the
!! output registry; the energies of the effects come from the effects.
module output_calc
   use kinds, only: wp, deg, g_std
   use model, only: body_section_t, vehicle_section_t, n_dof, n_seg, n_joint, hip_x, hip_y
   use body_kinematics, only: point_state_t, segment_cg_state, joint_state, to_interior, to_interior_cs, joint_segment
   use body_state, only: body_state_t
   use joint_coupling, only: relative_angle, joint_columns
   use output_series, only: output_series_t, output_column_t, series_new, column
   implicit none
   private

   public :: body_outputs_t, body_outputs_compute, head_chest_acceleration, head_chest_motion, body_series, body_series_values
   public :: body_kinetic_energy, head_interior_x

   !> Segments whose centre-of-gravity accelerations C.6 prints.
   integer, parameter :: chest = 3, head = 4

   !> The C.6 quantities of one occupant at one time (internal units).
   type :: body_outputs_t
      real(wp) :: head_acc = 0.0_wp, chest_acc = 0.0_wp   !< resultant, in/s^2
      real(wp) :: veh_pos(3) = 0.0_wp, veh_vel(3) = 0.0_wp, veh_acc(3) = 0.0_wp
      real(wp) :: z(n_dof) = 0.0_wp, zdot(n_dof) = 0.0_wp, zdd(n_dof) = 0.0_wp
      real(wp) :: theta(n_seg) = 0.0_wp         !< segment angles relative to the interior
      real(wp) :: joint_angle(n_joint) = 0.0_wp !< alpha_i - alpha_m
      real(wp) :: joint_x(n_joint) = 0.0_wp, joint_y(n_joint) = 0.0_wp !< relative to the interior
      real(wp) :: ke_vehicle = 0.0_wp
      real(wp) :: ke_seg(n_seg) = 0.0_wp
   end type body_outputs_t

   !> The series body_series declares, in order.
   integer, parameter :: s_acc = 1, s_vehicle = 2, s_z = 3, s_zdot = 4, s_zdd = 5, s_theta = 6, &
      s_joint_angle = 7, s_ke = 8, s_joint_x = 9, s_joint_y = 10, n_body_series = 10

contains

   !> Resultant accelerations of the head and chest centres of gravity
   !! (C.6; the kinematic acceleration, as the report defines it). Written
   !! out for the two chains (hip - L1 - L2 - upper torso - L3 - head) as it
   !! runs on every accepted step.
   pure subroutine head_chest_acceleration(body, c, s, zdot, zdd, a_head, a_chest)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: c(n_seg), s(n_seg), zdot(n_dof), zdd(n_dof)
      real(wp), intent(out) :: a_head, a_chest
      real(wp) :: head_cg(2), chest_cg(2), v_head(2), v_chest(2)
      call head_chest_motion(body, c, s, zdot, zdd, head_cg, chest_cg, v_head, v_chest)
      a_head = hypot(head_cg(1), head_cg(2))
      a_chest = hypot(chest_cg(1), chest_cg(2))
   end subroutine head_chest_acceleration

   !> The head's and chest's centres of gravity: their acceleration vectors
   !! (as head_chest_acceleration, whose resultants they are) and velocity
   !! vectors, in the frame of z, for the criteria's interpolant between
   !! accepted steps (acceleration_criteria: dv/dt = a exactly).
   pure subroutine head_chest_motion(body, c, s, zdot, zdd, a_head, a_chest, v_head, v_chest)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: c(n_seg), s(n_seg), zdot(n_dof), zdd(n_dof)
      real(wp), intent(out) :: a_head(2), a_chest(2), v_head(2), v_chest(2)
      real(wp) :: spine(2)
      spine = [zdd(hip_x), zdd(hip_y)] + link_acc(1, body%length(1)) + link_acc(2, body%length(2))
      a_chest = spine + link_acc(chest, body%rho(chest))
      a_head = spine + link_acc(chest, body%length(3)) + link_acc(head, body%rho(head))
      spine = [zdot(hip_x), zdot(hip_y)] + link_vel(1, body%length(1)) + link_vel(2, body%length(2))
      v_chest = spine + link_vel(chest, body%rho(chest))
      v_head = spine + link_vel(chest, body%length(3)) + link_vel(head, body%rho(head))
   contains
      !> velocity of a point len along segment j relative to its joint
      pure function link_vel(j, len) result(v)
         integer, intent(in) :: j
         real(wp), intent(in) :: len
         real(wp) :: v(2)
         v(1) = -len*zdot(j)*s(j)
         v(2) = len*zdot(j)*c(j)
      end function link_vel
      !> its acceleration, the derivative of link_vel
      pure function link_acc(j, len) result(a)
         integer, intent(in) :: j
         real(wp), intent(in) :: len
         real(wp) :: a(2)
         a(1) = -len*(zdd(j)*s(j) + zdot(j)**2*c(j))
         a(2) = len*(zdd(j)*c(j) - zdot(j)**2*s(j))
      end function link_acc
   end subroutine head_chest_motion

   !> The head centre of gravity's x relative to the vehicle interior (in;
   !! x forward, the frame of C.4: x = R(Phi)(X - x_c), its first row), from
   !! the segment angles' cosines c and sines s at hand and the vehicle's
   !! position vpos (x_c, y_c, Phi): the chain hip - L1 - L2 - upper torso
   !! (L3) - head (rho_4) of head_chest_motion. For the head's excursion
   !! (run_summary), on every accepted step: a few products, and a cosine
   !! and sine only when the vehicle pitches.
   pure real(wp) function head_interior_x(body, z, c, s, vpos) result(x)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), c(n_seg), s(n_seg), vpos(3)
      real(wp) :: dx, dy
      dx = z(hip_x) + body%length(1)*c(1) + body%length(2)*c(2) + body%length(3)*c(chest) &
           + body%rho(head)*c(head) - vpos(1)
      if (abs(vpos(3)) > 0.0_wp) then
         dy = z(hip_y) + body%length(1)*s(1) + body%length(2)*s(2) + body%length(3)*s(chest) &
              + body%rho(head)*s(head) - vpos(2)
         x = dx*cos(vpos(3)) - dy*sin(vpos(3))
      else
         x = dx
      end if
   end function head_interior_x

   !> Kinetic energy of each segment (C.6, erratum E-65).
   pure function body_kinetic_energy(body, z, zdot) result(ke)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof)
      real(wp) :: ke(n_seg)
      type(point_state_t) :: p(n_seg)
      real(wp) :: zero(n_dof)
      integer :: i
      zero = 0.0_wp
      do i = 1, n_seg
         p(i) = segment_cg_state(body, z, zdot, zero, i)
      end do
      ke = kinetic_energy_at(body, zdot, p)
   end function body_kinetic_energy

   !> body_kinetic_energy from the centres of gravity cg (segment_cg_state,
   !! whatever the accelerations: the velocities do not depend on them).
   pure function kinetic_energy_at(body, zdot, cg) result(ke)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: zdot(n_dof)
      type(point_state_t), intent(in) :: cg(n_seg)
      real(wp) :: ke(n_seg)
      integer :: i
      do i = 1, n_seg
         ke(i) = 0.5_wp*body%mass(i)*(cg(i)%vx**2 + cg(i)%vy**2) + 0.5_wp*body%inertia(i)*zdot(i)**2
      end do
   end function kinetic_energy_at

   !> The C.6 quantities at the state st, with the accelerations zdd there;
   !! cg: the segments' centres of gravity there, when at hand (for the
   !! kinetic energies); joint: each segment's proximal joint there, when at
   !! hand (body_kinematics' body_points: joint_state's bits).
   pure subroutine body_outputs_compute(body, vehicle, st, zdd, r, cg, joint)
      type(body_section_t), intent(in) :: body
      type(vehicle_section_t), intent(in) :: vehicle
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: zdd(n_dof)
      type(body_outputs_t), intent(out) :: r
      type(point_state_t), intent(in), optional :: cg(n_seg), joint(n_seg)
      type(point_state_t) :: p
      real(wp) :: c_pitch, s_pitch
      integer :: i
      associate (vs => st%vehicle)
         r%z = st%z
         r%zdot = st%zdot
         r%zdd = zdd
         r%veh_pos = vs%pos
         r%veh_vel = vs%vel
         r%veh_acc = vs%acc
         call head_chest_acceleration(body, st%c, st%s, r%zdot, r%zdd, r%head_acc, r%chest_acc)
         ! Theta_i = alpha_i + Phi (section B)
         r%theta = r%z(1:n_seg) + vs%pos(3)
         if (present(joint)) then
            ! (the pitch's cosine and sine once: to_interior's, the scalar library's)
            c_pitch = cos(vs%pos(3))
            s_pitch = sin(vs%pos(3))
            do i = 1, n_joint
               r%joint_angle(i) = relative_angle(r%z, i)
               p = to_interior_cs(joint(joint_segment(i)), vs%pos, vs%vel, c_pitch, s_pitch)
               r%joint_x(i) = p%x
               r%joint_y(i) = p%y
            end do
         else
            do i = 1, n_joint
               r%joint_angle(i) = relative_angle(r%z, i)
               p = to_interior(joint_state(body, r%z, r%zdot, r%zdd, i), vs%pos, vs%vel)
               r%joint_x(i) = p%x
               r%joint_y(i) = p%y
            end do
         end if
         ! C.6 kinetic energies: vehicle, and segments with erratum E-65
         r%ke_vehicle = 0.5_wp*vehicle%mass*(vs%vel(1)**2 + vs%vel(2)**2) + 0.5_wp*vehicle%inertia*vs%vel(3)**2
         if (present(cg)) then
            r%ke_seg = kinetic_energy_at(body, r%zdot, cg)
         else
            r%ke_seg = body_kinetic_energy(body, r%z, r%zdot)
         end if
      end associate
   end subroutine body_outputs_compute

   !> The series of C.6 (without the energy summary, which depends on the
   !! effects): name, columns, units, listing units, NOUT level.
   function body_series() result(s)
      type(output_series_t) :: s(n_body_series)
      character(len=8) :: seg(n_seg)
      type(output_column_t) :: dof(n_dof)
      integer :: i
      do i = 1, n_seg
         write (seg(i), '(a,i0)') 'segment', i
      end do
      s(s_acc) = series_new('acceleration', 'HEAD AND CHEST ACCELERATIONS', &
                            'resultant accelerations of the head and chest centres of gravity (C.6)', 1)
      s(s_acc)%col = [column('head', 'in/s^2', 'g', 1.0_wp/g_std), column('chest', 'in/s^2', 'g', 1.0_wp/g_std)]
      s(s_vehicle) = series_new('vehicle', 'VEHICLE MOTION', &
                                'vehicle position, rate and acceleration; pitch positive front end down (C.1, C.3)', 1)
      s(s_vehicle)%col = [column('x_c', 'in'), column('y_c', 'in'), column('phi', 'rad', 'deg', 1.0_wp/deg), &
                          column('xdot_c', 'in/s'), column('ydot_c', 'in/s'), column('phidot', 'rad/s', 'deg/s', 1.0_wp/deg), &
                          column('xddot_c', 'in/s^2', 'g', 1.0_wp/g_std), column('yddot_c', 'in/s^2', 'g', 1.0_wp/g_std), &
                          column('phiddot', 'rad/s^2', 'deg/s^2', 1.0_wp/deg)]
      s(s_z) = series_new('body/z', 'GENERALIZED COORDINATES', 'generalized coordinates alpha_1..alpha_8, x_h, y_h ' &
                          //'(section B)', 2)
      call dof_columns('', 'rad', 'in', 'deg')
      s(s_z)%col = dof
      s(s_zdot) = series_new('body/zdot', 'GENERALIZED VELOCITIES', 'generalized velocities', 2)
      call dof_columns('dot', 'rad/s', 'in/s', 'deg/s')
      s(s_zdot)%col = dof
      s(s_zdd) = series_new('body/zddot', 'GENERALIZED ACCELERATIONS', 'generalized accelerations (C.5)', 2)
      call dof_columns('ddot', 'rad/s^2', 'in/s^2', 'deg/s^2')
      s(s_zdd)%col = dof
      s(s_theta) = series_new('body/theta', 'SEGMENT ANGLES RELATIVE TO THE INTERIOR', &
                              'segment angles relative to the interior, Theta = alpha + Phi (section B)', 2)
      s(s_theta)%col = [(column(trim(seg(i)), 'rad', 'deg', 1.0_wp/deg), i=1, n_seg)]
      s(s_joint_angle) = series_new('joints/angle', 'JOINT ANGLES', 'joint angles alpha_i - alpha_m (Table 6)', 2)
      s(s_joint_angle)%col = joint_columns('rad')
      s(s_joint_angle)%col(:)%listing_unit = 'deg'
      s(s_joint_angle)%col(:)%listing_scale = 1.0_wp/deg
      s(s_ke) = series_new('energy/segment_kinetic', 'SEGMENT KINETIC ENERGIES', &
                           'kinetic energy of each segment (C.6, erratum E-65)', 3)
      s(s_ke)%col = [(column(trim(seg(i)), 'in*lb'), i=1, n_seg)]
      s(s_joint_x) = series_new('joints/x', 'JOINT POSITIONS RELATIVE TO THE INTERIOR, X', &
                                'joint x relative to the interior (C.4)', 3)
      s(s_joint_x)%col = joint_columns('in')
      s(s_joint_y) = series_new('joints/y', 'JOINT POSITIONS RELATIVE TO THE INTERIOR, Y', &
                                'joint y relative to the interior (C.4)', 3)
      s(s_joint_y)%col = joint_columns('in')
      do i = 1, n_body_series
         s(i)%producer = 0
         s(i)%item = i
      end do
   contains
      subroutine dof_columns(suffix, angle_unit, hip_unit, angle_listing)
         character(len=*), intent(in) :: suffix, angle_unit, hip_unit, angle_listing
         integer :: k
         character(len=12) :: name
         do k = 1, n_seg
            write (name, '(a,i0,a)') 'alpha', k, suffix
            dof(k) = column(trim(name), angle_unit, angle_listing, 1.0_wp/deg)
         end do
         dof(hip_x) = column('x_h'//suffix, hip_unit)
         dof(hip_y) = column('y_h'//suffix, hip_unit)
      end subroutine dof_columns
   end function body_series

   !> The values of body series item.
   pure subroutine body_series_values(item, r, values)
      integer, intent(in) :: item
      type(body_outputs_t), intent(in) :: r
      real(wp), intent(out) :: values(:)
      select case (item)
      case (s_acc)
         values = [r%head_acc, r%chest_acc]
      case (s_vehicle)
         values = [r%veh_pos, r%veh_vel, r%veh_acc]
      case (s_z)
         values = r%z
      case (s_zdot)
         values = r%zdot
      case (s_zdd)
         values = r%zdd
      case (s_theta)
         values = r%theta
      case (s_joint_angle)
         values = r%joint_angle
      case (s_ke)
         values = r%ke_seg
      case (s_joint_x)
         values = r%joint_x
      case default
         values = r%joint_y
      end select
   end subroutine body_series_values
end module output_calc
