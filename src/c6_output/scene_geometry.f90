!> The scene's fixed geometry as tables, for pictures of the motion drawn
!! from the HDF5 file (issue 18: tools/plot): the segments and the body's
!! contact points (Table 1, f.1), the surfaces of the interior as the
!! contact pairs resolved them (C.4.f), the belts' anchorages and where
!! they meet the body (C.4.e, figure 17), the seat's cushion line and front
!! edge (C.4.d, figure 11). Everything in the occupant's interior frame (x
!! forward, y up, inches, radians), the frame of /joints/x and /joints/y;
!! together with /joints/x, /joints/y and /body/theta at a record they give
!! the whole picture at that time. The tables are data: the HDF5 sink writes
!! them under /scene (docs/usage.md, "The HDF5 file").
!!
!! The effects' geometry is read through their types (select type) here, in
!! the output layer, rather than through a procedure of every effect: a
!! picture needs four kinds of effect and no effect's code changes for it.
module scene_geometry
   use kinds, only: wp
   use model, only: n_seg, n_arc, segment_name, arc_name, seat_form_name, seat_none
   use occupant, only: occupant_t
   use contact_geometry, only: arc_segment, contact_surface_t
   use contact_tables, only: surface_name
   use contact_forces, only: contact_pair_effect_t
   use belt_forces, only: belt_effect_t
   use belt_geometry, only: belt_lap
   use seat_springs, only: seat_springs_t
   use seat_rigid_beam, only: seat_rigid_beam_t
   use seat_beams, only: seat_beams_t
   implicit none
   private

   public :: scene_table_t, occupant_scene

   !> One table: its name under the occupant's group (e.g. "scene/surfaces"),
   !! a name and unit per column, a description, values(ncols, nrows) and a
   !! label per row.
   type :: scene_table_t
      character(len=:), allocatable :: name, description
      character(len=16), allocatable :: columns(:), units(:)
      character(len=32), allocatable :: labels(:)
      real(wp), allocatable :: values(:, :)
   end type scene_table_t

   !> The proximal joint of each segment (the hip for 1 and 7), the column of
   !! /joints/x it is in (body_kinematics' joint_segment, inverted)
   integer, parameter :: proximal_joint(n_seg) = [1, 2, 3, 4, 5, 6, 1, 7]

contains

   !> The scene tables of one occupant: segments, body points, surfaces,
   !! belts, seat (a table of no rows where the scene has none).
   function occupant_scene(occ) result(tables)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: tables(5)
      tables(1) = segments(occ)
      tables(2) = body_points(occ)
      tables(3) = surfaces(occ)
      tables(4) = belts(occ)
      tables(5) = seat(occ)
   end function occupant_scene

   !> Segment i runs from its proximal joint along e(theta_i) (Table 1).
   function segments(occ) result(t)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: t
      integer :: i
      t%name = 'scene/segments'
      t%description = 'the segments (Table 1): segment i starts at its proximal joint (a column of ' &
                      //'/joints/x, 1 hip .. 7 knee) and lies along e(theta_i) of /body/theta; L_i its ' &
                      //'length, except L_4, the upper spine to the shoulder along segment 3 (the neck is ' &
                      //'L_3 along it); rho_i its centre of gravity'
      call set_columns(t, [character(len=16) :: 'joint', 'length', 'cg'], &
                       [character(len=16) :: '-', 'in', 'in'])
      allocate (t%values(3, n_seg), t%labels(n_seg))
      do i = 1, n_seg
         t%values(:, i) = [real(proximal_joint(i), wp), occ%body%length(i), occ%body%rho(i)]
         t%labels(i) = segment_name(i)
      end do
   end function segments

   !> The contact arcs' centres (f.1 with F1-1, F1-2; D-C1, D-C2), each
   !! joint + along e(theta) + across e(theta + 90 deg) of its segment.
   function body_points(occ) result(t)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: t
      real(wp) :: along, across
      integer :: i, seg
      t%name = 'scene/body_points'
      t%description = 'the body''s contact arcs (f.1, TABLE 1 - CONTACT ARCS): a circle of radius r centred ' &
                      //'at joint + along e(theta) + across e(theta + 90 deg), joint (a column of /joints/x) ' &
                      //'and theta (of /body/theta) those of the segment carrying it; row 9, the shin, is the ' &
                      //'capsule tangent to its circle (the knee''s, r_7) and row 11''s (the ankle''s, r_A)'
      call set_columns(t, [character(len=16) :: 'segment', 'joint', 'along', 'across', 'r'], &
                       [character(len=16) :: '-', '-', 'in', 'in', 'in'])
      allocate (t%values(5, n_arc + 1), t%labels(n_arc + 1))
      do i = 1, n_arc
         seg = arc_segment(i)
         along = 0.0_wp
         across = 0.0_wp
         select case (i)
         case (2, 3)         ! upper back, chest: rho'_i at gamma_i from the torso line
            along = occ%body%rho_arc(i)*cos(occ%body%gamma_arc(i))
            across = occ%body%rho_arc(i)*sin(occ%body%gamma_arc(i))
         case (4)            ! head: rho'_4 along its centre line (F1-1)
            along = occ%body%rho_arc(4)
         case (6, 7, 8, 10)  ! elbow, knee, foot, hand: the segment's far end
            along = occ%body%length(seg)
         end select
         ! the shin (9) is drawn from the knee's circle, r_7 (D-C2)
         t%values(:, i) = [real(seg, wp), real(proximal_joint(seg), wp), along, across, &
                           occ%body%r_arc(merge(7, i, i == 9))]
         t%labels(i) = arc_name(i)
      end do
      ! the ankle's circle of the shin (D-C2), at the lower leg's far end
      t%values(:, n_arc + 1) = [8.0_wp, real(proximal_joint(8), wp), occ%body%length(8), 0.0_wp, &
                                occ%body%r_arc(n_arc + 1)]
      t%labels(n_arc + 1) = arc_name(n_arc + 1)
   end function body_points

   !> Each surface a contact pair of the scene meets, once (C.4.f, Table 3).
   function surfaces(occ) result(t)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: t
      real(wp), allocatable :: v(:, :)
      character(len=32), allocatable :: names(:)
      integer :: k, n
      integer, allocatable :: seen(:)
      t%name = 'scene/surfaces'
      t%description = 'the interior''s surfaces that a contact pair meets (C.4.f; the listing''s INTERIOR ' &
                      //'SURFACES): k, kind (1 flat: from (x, y) back along -e(psi) for d, the body on the side ' &
                      //'of e(psi + 90 deg); 2 line: through (x, y) at psi; 3 circle: of diameter d centred at ' &
                      //'(x, y); 4 point: the lower panel''s edge), an opening from open_from to open_to along ' &
                      //'a flat surface when open_to > open_from'
      call set_columns(t, [character(len=16) :: 'k', 'kind', 'x', 'y', 'psi', 'd', 'open_from', 'open_to'], &
                       [character(len=16) :: '-', '-', 'in', 'in', 'rad', 'in', 'in', 'in'])
      allocate (v(8, 0), names(0), seen(0))
      do n = 1, size(occ%effects)
         select type (e => occ%effects(n)%e)
         type is (contact_pair_effect_t)
            k = e%k
            if (any(seen == k)) cycle
            seen = [seen, k]
            v = reshape([v, [real(k, wp), real(e%surface%kind, wp), e%surface%s, e%surface%psi, e%surface%d, &
                             e%surface%t_open]], [8, size(v, 2) + 1])
            names = [character(len=32) :: names, surface_name(k)]
         end select
      end do
      ! in the order of k, as the listing's table
      do n = 2, size(seen)
         k = n
         do while (k > 1)
            if (seen(k - 1) < seen(k)) exit
            seen([k - 1, k]) = seen([k, k - 1])
            v(:, [k - 1, k]) = v(:, [k, k - 1])
            names([k - 1, k]) = names([k, k - 1])
            k = k - 1
         end do
      end do
      call move_alloc(v, t%values)
      call move_alloc(names, t%labels)
   end function surfaces

   !> Each belt section's anchorage and where it meets the body (C.4.e,
   !! figure 17; the anchorages from C.2).
   function belts(occ) result(t)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: t
      real(wp), allocatable :: v(:, :)
      character(len=32), allocatable :: names(:)
      integer :: n, j
      t%name = 'scene/belts'
      t%description = 'the belt sections (C.4.e, figure 17): section (its *BELTS card), kind (1 lap: from the ' &
                      //'anchor (anchor_x, anchor_y) to its tangent point on the circle of radius h about the hip, ' &
                      //'then clockwise over the top to the hip + h e(theta_1), straight where that wrap would be ' &
                      //'negative; 2 torso: straight to joint + h e(theta) of its segment), segment, joint (a ' &
                      //'column of /joints/x)'
      call set_columns(t, [character(len=16) :: 'section', 'kind', 'segment', 'joint', 'anchor_x', 'anchor_y', 'h'], &
                       [character(len=16) :: '-', '-', '-', '-', 'in', 'in', 'in'])
      allocate (v(7, 0), names(0))
      do n = 1, size(occ%effects)
         select type (e => occ%effects(n)%e)
         type is (belt_effect_t)
            do j = 1, e%n_sections
               associate (g => e%geom(j))
                  v = reshape([v, [real(e%card(j), wp), real(g%kind, wp), real(g%segment, wp), &
                                   real(proximal_joint(g%segment), wp), g%anchor, g%h]], [7, size(v, 2) + 1])
                  names = [character(len=32) :: names, merge('lap     ', e%label(j), &
                                                             g%kind == belt_lap .and. len_trim(e%label(j)) == 0)]
               end associate
            end do
         end select
      end do
      call move_alloc(v, t%values)
      call move_alloc(names, t%labels)
   end function belts

   !> The seat (C.4.d): its form, the front edge at x = z_o and the
   !! undeflected cushion line at gamma_o through the initial hip (A-S2);
   !! the rigid beam's extent a and its CG's distance a' behind the front
   !! edge (figure 15), the non-rigid beams' l and k (figure 13), so that a
   !! picture draws the seat as its series move it (tools/plot).
   function seat(occ) result(t)
      type(occupant_t), intent(in) :: occ
      type(scene_table_t) :: t
      integer :: n, form
      real(wp) :: z0, gamma0, a, a_prime, ell, k, x_line, y_line
      t%name = 'scene/seat'
      t%description = 'the seat (C.4.d, figure 11): form (1 springs, 2 rigid beam, 3 non-rigid beams), the ' &
                      //'front edge at x = z_o, the undeflected cushion line through the initial hip (the ' &
                      //'origin) at gamma_o (a beam seat''s at t = 0); the rigid beam''s length a behind the ' &
                      //'front edge and its CG''s a'' (figure 15), the non-rigid beams'' l and k (figure 13), 0 ' &
                      //'for another form; x_line, y_line: a point of the undeflected cushion line (the ' &
                      //'origin but for the non-rigid beams, x''''_sc, y''''_sc: NB-2); its motion: ' &
                      //'effects/seat/beam (y_g, gamma) and effects/seat/loads (delta_A, w, z); no row without a seat'
      call set_columns(t, [character(len=16) :: 'form', 'z_o', 'gamma_o', 'a', 'a_prime', 'l', 'k', 'x_line', &
                            'y_line'], [character(len=16) :: '-', 'in', 'rad', 'in', 'in', 'in', '-', 'in', 'in'])
      form = seat_none
      z0 = 0.0_wp
      gamma0 = 0.0_wp
      a = 0.0_wp
      a_prime = 0.0_wp
      ell = 0.0_wp
      k = 0.0_wp
      x_line = 0.0_wp
      y_line = 0.0_wp
      do n = 1, size(occ%effects)
         select type (e => occ%effects(n)%e)
         type is (seat_springs_t)
            form = e%p%form
            z0 = e%p%z0
            gamma0 = e%p%gamma0
         type is (seat_rigid_beam_t)
            form = e%p%form
            z0 = e%p%z0
            gamma0 = e%p%gamma0
            a = e%p%a
            a_prime = e%p%a_prime
         type is (seat_beams_t)
            form = e%p%form
            z0 = e%p%z0
            gamma0 = e%p%gamma0
            ell = e%p%ell
            k = e%p%k_ratio
            x_line = e%p%x_sc
            y_line = e%p%y_sc
         end select
      end do
      if (form == seat_none) then
         allocate (t%values(9, 0), t%labels(0))
      else
         t%values = reshape([real(form, wp), z0, gamma0, a, a_prime, ell, k, x_line, y_line], [9, 1])
         t%labels = [character(len=32) :: seat_form_name(form)]
      end if
   end function seat

   !> A table's column names and units (allocated first: gfortran 12's
   !! -Wuninitialized takes an assignment to an unallocated component for a
   !! read of its descriptor).
   pure subroutine set_columns(t, columns, units)
      type(scene_table_t), intent(inout) :: t
      character(len=*), intent(in) :: columns(:), units(:)
      allocate (t%columns(size(columns)), t%units(size(units)))
      t%columns(:) = columns
      t%units(:) = units
   end subroutine set_columns
end module scene_geometry
