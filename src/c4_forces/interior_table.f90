!> The interior's parameter tables, as the listing prints them (C.4.f,
!! Table 3; docs/contacts.md): each surface as the scene resolves it (both
!! ends, direction, normal, padding), and the position's pairs that the
!! scene assembles with their materials, the undesired ones (Table 9)
!! marked. tools/draw-interior reads the surfaces' rows by their columns.
module interior_table
   use kinds, only: deg
   use strings, only: itoa
   use text_table, only: text_table_t, new_table, cell_text, cell_int, cell_fixed
   use model, only: model_t, arc_name
   use contact_tables, only: surface_name, contact_pair_t, is_undesired
   use interior_pairs, only: scene_pairs, surface_layers
   use contact_scene, only: resolved_surface
   use contact_geometry, only: contact_surface_t, surface_flat, surface_line, surface_circle
   implicit none
   private

   public :: surfaces_table, contact_pairs_table

   !> The surfaces' numbers k of *SURFACES.
   integer, parameter :: n_surfaces = 32

contains

   !> Each surface of the scene in the occupant's interior frame (no table
   !! when the deck describes no interior).
   function surfaces_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      type(contact_surface_t) :: sf
      logical :: ok
      integer :: k, n
      n = 0
      if (any(m%interior%given)) then
         do k = 1, n_surfaces
            call resolved_surface(m%interior, k, sf, ok)
            if (ok) n = n + 1
         end do
      end if
      t = new_table('INTERIOR SURFACES (C.4.f, TABLE 3; OCCUPANT''S INTERIOR FRAME)', keep=n + 3)
      if (.not. any(m%interior%given)) return
      call t%add_column('K', 4, cell_int, lead=3)
      call t%add_column('SURFACE', 24, cell_text)
      call t%add_column('KIND', 11, cell_text, lead=1)
      call t%add_column('X''''', 11, cell_fixed, 3, lead=1)
      call t%add_column('Y''''', 11, cell_fixed, 3)
      call t%add_column('PSI (deg)', 11, cell_fixed, 2, lead=3)
      call t%add_column('D', 11, cell_fixed, 3, lead=4)
      call t%add_column('D''''', 11, cell_fixed, 3, lead=5)
      call t%add_column('FAR END X', 11, cell_fixed, 3, lead=5)
      call t%add_column('FAR END Y', 11, cell_fixed, 3, lead=6)
      do k = 1, n_surfaces
         call resolved_surface(m%interior, k, sf, ok)
         if (.not. ok) cycle
         call t%new_row()
         call t%put(k)
         call t%put(surface_name(k))
         call t%put(surface_kind(sf%kind))
         call t%put(sf%s(1))
         call t%put(sf%s(2))
         call t%put(sf%psi/deg)
         call t%put(sf%d)
         ! (the head rest, 25, takes the seat back's padding)
         call t%put(m%interior%dpp(merge(5, k, k == 25)))
         call t%put(sf%s(1) - sf%d*cos(sf%psi))
         call t%put(sf%s(2) - sf%d*sin(sf%psi))
      end do
   contains
      pure function surface_kind(kind) result(text)
         integer, intent(in) :: kind
         character(len=10) :: text
         select case (kind)
         case (surface_flat); text = 'flat'
         case (surface_line); text = 'line'
         case (surface_circle); text = 'circle'
         case default; text = 'edge point'
         end select
      end function surface_kind
   end function surfaces_table

   !> The contact pairs of m's position (NBODY) the scene assembles, with
   !! their materials (Tables 7, 8, 10) and whether they are undesired
   !! (Table 9); no table when the deck describes no interior.
   function contact_pairs_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      type(contact_pair_t), allocatable :: pairs(:)
      integer :: q, l, lb
      allocate (pairs(0))
      if (any(m%interior%given)) pairs = scene_pairs(m)
      t = new_table('CONTACT PAIRS OF NBODY '//itoa(m%options%nbody)//' ASSEMBLED (TABLES 7, 8, 9, 10)', &
                     keep=size(pairs) + 3)
      if (.not. any(m%interior%given)) return
      call t%add_column('I', 4, cell_int, lead=3)
      call t%add_column('BODY POINT', 14, cell_text)
      call t%add_column('K', 5, cell_int, lead=4)
      call t%add_column('SURFACE', 24, cell_text)
      call t%add_column('MATERIAL', 6, cell_int, lead=1)
      call t%add_column('BACKING', 9, cell_int, lead=5)
      call t%add_column('UNDESIRED (TABLE 9)', 24, cell_text, lead=5)
      do q = 1, size(pairs)
         call surface_layers(m%interior, pairs(q)%k, l, lb)
         call t%new_row()
         call t%put(pairs(q)%i)
         call t%put(arc_name(pairs(q)%i))
         call t%put(pairs(q)%k)
         call t%put(surface_name(pairs(q)%k))
         call t%put(l)
         call t%put(lb)
         if (is_undesired(m%options%nbody, pairs(q)%i, pairs(q)%k)) call t%put('yes')
      end do
   end function contact_pairs_table
end module interior_table
