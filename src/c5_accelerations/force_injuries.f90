!> Table 5's force criteria (C.4.f, figure 26) from the solved dynamics:
!! tension dislocation of joint j (FT_j against FTD_j), compression
!! fracture of bone i (FC_i against FCF_i), shear fracture of bone i (FS_i
!! against FSF_i), in place of the printed f.5-f.7 (F5-1; docs/injury.md).
!!
!! - FT_j = -R_j . e, R_j the joint reaction on the distal side, e the
!!   distal bone's axis (joint_reactions).
!! - FC_i, the axial compression of bone i at the joint through which it
!!   is loaded from the body's root side: R_j . e_i for the joint j at its
!!   proximal end whose distal side starts with it (bones 2-8: the lower
!!   spine joint, upper spine, neck, shoulder, elbow, hip for the thigh,
!!   knee for the shank); for bone 1, whose proximal end is the hip, where
!!   the seat acts, the upper body's push at its top, R_2 . e_1. Table 5
!!   has no compression limit for bone 4 (the skull): FC_4 is omitted.
!! - FS_i, the load across bone i from outside. For the spine (1-3) and
!!   the leg bones (7, 8): the component normal to the bone of the belts'
!!   and the seat's forces on its segment that load it across (not gravity,
!!   not the seat's hip force at the joint): the lap belt and the torso
!!   sections (the report's FS_1-FS_3), the front edge's F'_s on the thigh
!!   (F7-1). From the contacts (f.7): the skull (4) the head's contact
!!   force P_4 on surfaces it does not meet face-on, the back (5) and the
!!   ribs (6) those of the upper back (P_2) and the chest (P_3), the lower
!!   leg (8) the shin's P_9, the face (9) the head's on the windshield,
!!   panel, front seat back, column and rims (F7-1).
module force_injuries
   use kinds, only: wp
   use model, only: body_section_t, n_seg, n_dof, n_joint, n_injury, joint_name
   use number_format, only: fixed
   use point_forces, only: point_force_list_t
   use effect_events, only: event_t, event_kind_t, event_of
   use joint_reactions, only: joint_reaction_forces, bone_components
   implicit none
   private

   public :: bone_loads_t, bone_loads, fc_defined, fs_defined, fc_name, fs_name
   public :: force_injury_event, force_event_kinds, event_tension, event_compression, event_shear

   !> The criteria's events' codes (/events/kind, docs/usage.md) and kinds: joint j's
   !! tension, bone i's compression or shear passed its limit (an injury).
   integer, parameter :: event_tension = 3, event_compression = 4, event_shear = 5
   type(event_kind_t), parameter :: force_event_kinds(3) = [event_kind_t(event_tension, 'tension dislocation'), &
      event_kind_t(event_compression, 'compression fracture'), event_kind_t(event_shear, 'shear fracture')]

   !> Table 5: the bones of the compression and shear fracture criteria.
   character(len=12), parameter :: fc_name(n_injury) = [character(len=12) :: 'lower spine', 'center spine', &
      'upper spine', '-', 'upper arm', 'lower arm', 'upper leg', 'lower leg', '-', '-']
   character(len=12), parameter :: fs_name(n_injury) = [character(len=12) :: 'lower spine', 'center spine', &
      'upper spine', 'skull', 'back', 'rib', 'upper leg', 'lower leg', 'face', '-']

   !> The bones whose compression Table 5 defines (not the skull, 4).
   logical, parameter :: fc_defined(n_injury) = [.true., .true., .true., .false., .true., .true., .true., .true., &
                                                 .false., .false.]
   !> The bones with a shear fracture criterion (Table 5: all but row 10).
   logical, parameter :: fs_defined(n_injury) = [.true., .true., .true., .true., .true., .true., .true., .true., &
                                                 .true., .false.]
   !> The surfaces the face meets head-on (F7-1): windshield, upper panel,
   !! back of the front seat and of its head rest (1*), column, rim, side
   !! rim; the head's other contacts load the skull.
   integer, parameter :: face_on(7) = [2, 4, 7, 8, 10, 21, 30]
   !> The joint at whose reaction bone i's compression is taken (i = 1..8).
   integer, parameter :: fc_joint(n_seg) = [2, 2, 3, 4, 5, 6, 1, 7]

   type :: bone_loads_t
      real(wp) :: ft(n_joint) = 0.0_wp      !< tension at each joint (lb; negative: compression)
      real(wp) :: fc(n_injury) = 0.0_wp     !< compression of each bone (lb; negative: tension)
      real(wp) :: fs(n_injury) = 0.0_wp     !< load across each bone from outside (lb, >= 0)
   end type bone_loads_t

contains

   pure function bone_loads(body, z, zdot, zdd, forces) result(bl)
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: z(n_dof), zdot(n_dof), zdd(n_dof)
      type(point_force_list_t), intent(in) :: forces
      type(bone_loads_t) :: bl
      real(wp) :: r(2, n_joint), shear(n_joint), across(n_seg), contact(n_injury)
      integer :: i, k
      r = joint_reaction_forces(body, z, zdot, zdd, forces)
      call bone_components(r, z, bl%ft, shear)
      do i = 1, n_seg
         if (fc_defined(i)) bl%fc(i) = r(1, fc_joint(i))*cos(z(i)) + r(2, fc_joint(i))*sin(z(i))
      end do
      across = 0.0_wp
      contact = 0.0_wp
      do k = 1, forces%n
         associate (f => forces%f(k))
            if (.not. f%across_bone) cycle
            select case (f%arc)
            case (0)            ! belts and the seat: their normal component on the bone
               across(f%segment) = across(f%segment) - f%force(1)*sin(z(f%segment)) + f%force(2)*cos(z(f%segment))
            case (2)            ! the upper back's contact: the back (Table 5 row 5; P itself, F7-2)
               contact(5) = contact(5) + f%normal_force
            case (3)            ! the chest's: the ribs (row 6; F7-2)
               contact(6) = contact(6) + f%normal_force
            case (4)            ! the head's: the face head-on (row 9, F7-1), else the skull (row 4, F7-2)
               if (any(face_on == f%surface)) then
                  contact(9) = contact(9) + f%normal_force
               else
                  contact(4) = contact(4) + f%normal_force
               end if
            case (9)            ! the shin's: the lower leg (row 8; with the seat's and belts', F7-2)
               contact(8) = contact(8) + f%normal_force
            end select
         end associate
      end do
      bl%fs = merge(contact, 0.0_wp, fs_defined)
      do i = 1, n_seg
         if (.not. any(i == [4, 5, 6])) bl%fs(i) = bl%fs(i) + abs(across(i))
      end do
   end function bone_loads

   !> The injury event at time t of criterion code (event_tension: joint
   !! index; event_compression, event_shear: bone index) whose load value
   !! passed its limit.
   function force_injury_event(code, t, index, value, limit) result(e)
      integer, intent(in) :: code, index
      real(wp), intent(in) :: t, value, limit
      type(event_t) :: e
      character(len=:), allocatable :: what
      type(event_kind_t) :: k
      k = force_event_kinds(code - event_tension + 1)
      if (code == event_tension) then
         what = 'joint '//joint_name(index)
      else
         what = 'bone '//merge(fc_name(index), fs_name(index), code == event_compression)
      end if
      e = event_of(k, t, index, value, what//'  '//trim(k%name)//': force'//fixed(value, 10, 1)//' lb, limit' &
                   //fixed(limit, 10, 1)//' lb', limit=limit, injury=.true.)
   end function force_injury_event
end module force_injuries
