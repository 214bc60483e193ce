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
!! - FS_i, the load across bone i from outside: the component normal to
!!   its axis of the point forces on its segment that load it across
!!   (not gravity, not the seat's hip force at the joint; the belts' and
!!   the front edge's now, the contacts' later): bones 1-3 (the lower,
!!   centre and upper spine: the lap belt and the torso sections, the
!!   report's FS_1-FS_3), 7 (the upper leg: the front edge's F'_s, F7-1), 8
!!   (the lower leg). FS_4-6 and FS_9 (skull, back, rib, face) are contact
!!   forces of particular body points: they come with the contacts.
module force_injuries
   use kinds, only: wp
   use model, only: body_section_t, n_seg, n_dof, n_joint, n_injury
   use effect_base, only: point_force_list_t
   use joint_reactions, only: joint_reaction_forces, bone_components
   implicit none
   private

   public :: bone_loads_t, bone_loads, fc_defined, fs_defined, fc_name, fs_name

   !> Table 5: the bones of the compression and shear fracture criteria.
   character(len=12), parameter :: fc_name(n_injury) = [character(len=12) :: 'lower spine', 'center spine', &
      'upper spine', '-', 'upper arm', 'lower arm', 'upper leg', 'lower leg', '-', '-']
   character(len=12), parameter :: fs_name(n_injury) = [character(len=12) :: 'lower spine', 'center spine', &
      'upper spine', 'skull', 'back', 'rib', 'upper leg', 'lower leg', 'face', '-']

   !> The bones whose compression Table 5 defines (not the skull, 4).
   logical, parameter :: fc_defined(n_injury) = [.true., .true., .true., .false., .true., .true., .true., .true., &
                                                 .false., .false.]
   !> The bones whose shear the dynamics gives now (the others need contacts).
   logical, parameter :: fs_defined(n_injury) = [.true., .true., .true., .false., .false., .false., .true., .true., &
                                                 .false., .false.]
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
      real(wp) :: r(2, n_joint), shear(n_joint), across(n_seg)
      integer :: i, k
      r = joint_reaction_forces(body, z, zdot, zdd, forces)
      call bone_components(r, z, bl%ft, shear)
      do i = 1, n_seg
         if (fc_defined(i)) bl%fc(i) = r(1, fc_joint(i))*cos(z(i)) + r(2, fc_joint(i))*sin(z(i))
      end do
      across = 0.0_wp
      do k = 1, forces%n
         associate (f => forces%f(k))
            if (.not. f%across_bone) cycle
            across(f%segment) = across(f%segment) - f%force(1)*sin(z(f%segment)) + f%force(2)*cos(z(f%segment))
         end associate
      end do
      do i = 1, n_seg
         if (fs_defined(i)) bl%fs(i) = abs(across(i))
      end do
   end function bone_loads
end module force_injuries
