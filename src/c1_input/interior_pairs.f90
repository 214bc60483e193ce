!> The pairs a deck's interior assembles (C.4.f; docs/contacts.md 2, 3.1):
!! those of the occupant's position (Tables 7, 8), less the ones *CONTACTOFF
!! switches off, whose surface the deck describes - directly, or through
!! the surfaces f.2's relations derive it from - and each surface's layers
!! (Table 10 with its D''). They follow from the deck alone, with no
!! geometry: the deck's checks (C.1) and the scene (contact_scene, C.4.f,
!! which resolves the surfaces' geometry) both read them here.
module interior_pairs
   use kinds, only: wp
   use model, only: model_t, interior_section_t
   use contact_tables, only: contact_pair_t, position_pairs, surface_materials
   implicit none
   private

   public :: surface_sources, surface_described, scene_pairs, surface_layers

contains

   !> The *SURFACES codes surface k is built from: itself, and the surface
   !! f.2's relations take its position or angle from (the upper panel 4
   !! and the roof 11 from the windshield 2, D-C6; the rim 10 and the side
   !! rim 30 = 10* from the column 8, D-C11, D-C12; the floor 12 from the
   !! toeboard 6); the lower panel's edge 25 = 5* is the lower panel 5's.
   pure function surface_sources(k) result(codes)
      integer, intent(in) :: k
      integer, allocatable :: codes(:)
      select case (k)
      case (4, 11)
         codes = [k, 2]
      case (10, 30)
         codes = [10, 8]
      case (12)
         codes = [12, 6]
      case (25)
         codes = [5]
      case default
         codes = [k]
      end select
   end function surface_sources

   !> The deck describes surface k: every surface it is built from has a
   !! *SURFACES card, and the side rim 10* its length D_s (*INTERIOR DS).
   !! (contact_scene's resolved_surface builds exactly these: a test holds
   !! the two together.)
   pure logical function surface_described(it, k) result(described)
      type(interior_section_t), intent(in) :: it
      integer, intent(in) :: k
      integer, allocatable :: codes(:)
      described = .false.
      if (k < 1 .or. k > size(it%given)) return
      allocate (codes(0))      ! (realloc on assignment: a descriptor set first)
      codes = surface_sources(k)
      described = all(it%given(codes))
      if (k == 30) described = described .and. it%ds > 0.0_wp
   end function surface_described

   !> Surface k's composition (Table 10) as the scene uses it: its outer
   !! material l (0: none; D-C22: a padded surface's padding or mat when
   !! D'' > 0, else its backing) and the backing lb behind a padding or mat
   !! with D'' > 0 that bottoms out (figure 25, D-C19; 0: none). The rear
   !! floor 25 takes the toeboard 5's D''.
   pure subroutine surface_layers(it, k, l, lb)
      type(interior_section_t), intent(in) :: it
      integer, intent(in) :: k
      integer, intent(out) :: l, lb
      integer, allocatable :: comp(:)
      integer :: kd
      allocate (comp(0))      ! (realloc on assignment: a descriptor set first)
      comp = surface_materials(k)
      l = 0
      lb = 0
      if (size(comp) == 0) return
      kd = k
      if (k == 25) kd = 5
      l = comp(1)
      if (size(comp) > 1) then
         if (it%dpp(kd) > 0.0_wp) then
            lb = comp(2)
         else
            l = comp(2)
         end if
      end if
   end subroutine surface_layers

   !> The pairs the scene assembles: the position's, less those switched
   !! off, whose surface the deck describes.
   pure function scene_pairs(m) result(pairs)
      type(model_t), intent(in) :: m
      type(contact_pair_t), allocatable :: pairs(:), candidates(:)
      logical :: off
      integer :: q, r
      allocate (pairs(0), candidates(0))
      candidates = position_pairs(m%options%nbody)
      if (.not. any(m%interior%given)) return
      do q = 1, size(candidates)
         off = .false.
         if (allocated(m%interior%off)) then
            do r = 1, size(m%interior%off, 2)
               off = off .or. (m%interior%off(1, r) == candidates(q)%i .and. m%interior%off(2, r) == candidates(q)%k)
            end do
         end if
         if (surface_described(m%interior, candidates(q)%k) .and. .not. off) pairs = [pairs, candidates(q)]
      end do
   end function scene_pairs
end module interior_pairs
