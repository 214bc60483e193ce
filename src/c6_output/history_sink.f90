!> The HDF5 time-history file as an output sink (C.6): every output
!! variable at every print time, written as the run goes and flushed
!! regularly, so a run stopped midway leaves a readable file.
module history_sink
   use kinds, only: wp
   use error_handling, only: error_t
   use model, only: n_seg, n_joint
   use output_calc, only: output_record_t
   use joint_injury, only: injury_event_t, event_kind_name
   use output_sink, only: output_sink_t
   use history_h5, only: history_file_t
   implicit none
   private

   public :: history_sink_t, history_sink_open

   !> Records between flushes of the file.
   integer, parameter :: flush_every = 50

   type, extends(output_sink_t) :: history_sink_t
      type(history_file_t) :: file
      integer :: id_time = 0, id_acc = 0, id_veh = 0, id_z = 0, id_zdot = 0, id_zdd = 0
      integer :: id_theta = 0, id_joint = 0, id_jx = 0, id_jy = 0
      integer :: id_energy = 0, id_ke = 0, id_spring = 0, id_stop = 0, id_fric = 0
      integer :: n_records = 0
   contains
      procedure :: record => sink_record
      procedure :: event => sink_event
      procedure :: close => sink_close
   end type history_sink_t

contains

   !> Create the file and its series.
   subroutine history_sink_open(this, path, title, deck_lines, err)
      type(history_sink_t), intent(inout) :: this
      character(len=*), intent(in) :: path, title
      character(len=*), intent(in) :: deck_lines(:)
      type(error_t), intent(inout) :: err
      character(len=12) :: seg(n_seg), jnt(n_joint), dof(10), u_dof(10)
      integer :: i

      do i = 1, n_seg
         write (seg(i), '(a,i0)') 'segment_', i
      end do
      do i = 1, n_joint
         write (jnt(i), '(a,i0)') 'joint_', i
      end do
      dof(1:8) = [character(len=12) :: 'alpha_1', 'alpha_2', 'alpha_3', 'alpha_4', 'alpha_5', 'alpha_6', &
                  'alpha_7', 'alpha_8']
      dof(9:10) = [character(len=12) :: 'x_h', 'y_h']
      u_dof(1:8) = 'rad'
      u_dof(9:10) = 'in'

      call this%file%open(path, title, deck_lines, err)
      if (err%failed()) return
      call add('time', [character(len=12) :: 't'], [character(len=12) :: 's'], 'time', this%id_time)
      call add('acceleration', [character(len=12) :: 'head', 'chest'], [character(len=12) :: 'in/s^2', 'in/s^2'], &
               'resultant accelerations of the head and chest centres of gravity (C.6)', this%id_acc)
      call add('vehicle', [character(len=12) :: 'x_c', 'y_c', 'phi', 'xdot_c', 'ydot_c', 'phidot', 'xddot_c', &
                           'yddot_c', 'phiddot'], &
               [character(len=12) :: 'in', 'in', 'rad', 'in/s', 'in/s', 'rad/s', 'in/s^2', 'in/s^2', 'rad/s^2'], &
               'vehicle motion; pitch positive front end down (C.1, C.3)', this%id_veh)
      call add('body/z', dof, u_dof, 'generalized coordinates (section B)', this%id_z)
      u_dof(1:8) = 'rad/s'
      u_dof(9:10) = 'in/s'
      call add('body/zdot', dof, u_dof, 'generalized velocities', this%id_zdot)
      u_dof(1:8) = 'rad/s^2'
      u_dof(9:10) = 'in/s^2'
      call add('body/zddot', dof, u_dof, 'generalized accelerations (C.5)', this%id_zdd)
      call add('body/theta', seg, [('rad', i=1, n_seg)], 'segment angles relative to the interior', this%id_theta)
      call add('joints/angle', jnt, [('rad', i=1, n_joint)], 'joint angles alpha_i - alpha_m (Table 6)', &
               this%id_joint)
      call add('joints/x', jnt, [('in ', i=1, n_joint)], 'joint x relative to the interior (C.4)', this%id_jx)
      call add('joints/y', jnt, [('in ', i=1, n_joint)], 'joint y relative to the interior (C.4)', this%id_jy)
      call add('energy/summary', [character(len=14) :: 'ke_vehicle', 'ke_body', 'gravity', 'joint_elastic', &
                                  'joint_stops', 'friction', 'total_body', 'balance_err'], &
               [('in*lb', i=1, 8)], 'energies (C.6); total_body is conserved when nothing external acts', &
               this%id_energy)
      call add('energy/segment_kinetic', seg, [('in*lb', i=1, n_seg)], 'segment kinetic energies', this%id_ke)
      call add('energy/joint_elastic', jnt, [('in*lb', i=1, n_joint)], 'joint elastic energy', this%id_spring)
      call add('energy/joint_stops', jnt, [('in*lb', i=1, n_joint)], 'joint stop energy', this%id_stop)
      call add('energy/joint_friction', jnt, [('in*lb', i=1, n_joint)], 'friction work dissipated', this%id_fric)
   contains
      subroutine add(name, columns, units, description, id)
         character(len=*), intent(in) :: name, columns(:), units(:), description
         integer, intent(out) :: id
         id = 0
         if (err%failed()) return
         call this%file%add_series(name, columns, units, description, id, err)
      end subroutine add
   end subroutine history_sink_open

   subroutine sink_record(this, r, err)
      class(history_sink_t), intent(inout) :: this
      type(output_record_t), intent(in) :: r
      type(error_t), intent(inout) :: err
      call put(this%id_time, [r%t])
      call put(this%id_acc, [r%head_acc, r%chest_acc])
      call put(this%id_veh, [r%veh_pos, r%veh_vel, r%veh_acc])
      call put(this%id_z, r%z)
      call put(this%id_zdot, r%zdot)
      call put(this%id_zdd, r%zdd)
      call put(this%id_theta, r%theta)
      call put(this%id_joint, r%joint_angle)
      call put(this%id_jx, r%joint_x)
      call put(this%id_jy, r%joint_y)
      call put(this%id_energy, [r%ke_vehicle, sum(r%ke_seg), sum(r%pe_gravity), sum(r%e_spring), sum(r%e_stop), &
                                sum(r%w_friction), r%e_total, r%e_error])
      call put(this%id_ke, r%ke_seg)
      call put(this%id_spring, r%e_spring)
      call put(this%id_stop, r%e_stop)
      call put(this%id_fric, r%w_friction)
      this%n_records = this%n_records + 1
      if (mod(this%n_records, flush_every) == 0 .and. .not. err%failed()) call this%file%flush(err)
   contains
      subroutine put(id, values)
         integer, intent(in) :: id
         real(wp), intent(in) :: values(:)
         if (err%failed()) return
         call this%file%append(id, values, err)
      end subroutine put
   end subroutine sink_record

   subroutine sink_event(this, e, err)
      class(history_sink_t), intent(inout) :: this
      type(injury_event_t), intent(in) :: e
      type(error_t), intent(inout) :: err
      character(len=80) :: text
      write (text, '(a,i0,a,es12.5,a)') trim(event_kind_name(e%kind))//' of joint ', e%index, &
         ': relative angle ', e%value, ' rad'
      call this%file%add_event(e%t, e%kind, e%index, text, err)
      if (.not. err%failed()) call this%file%flush(err)
   end subroutine sink_event

   subroutine sink_close(this, err)
      class(history_sink_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      call this%file%close(err)
   end subroutine sink_close
end module history_sink
