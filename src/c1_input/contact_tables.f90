!> Tables 7-11 of C.4.f (docs/contacts.md 5): which body point i may strike
!! which surface k in each occupant position (NBODY 1 driver, 2 front-seat
!! passenger, 3 rear-seat passenger), which of those contacts are
!! undesired (Table 9, the end test of C.7) and which share deflection
!! with the body (Table 11), and each surface's composition (Table 10).
!! Starred surfaces are coded 20 + k: 21 = 1*, 25 = 5* (the lower panel's
!! edge), 26 = 6*, 29 = 9*, 30 = 10*, 32 = 12*.
module contact_tables
   implicit none
   private

   public :: contact_pair_t, position_pairs, is_undesired, is_shared, surface_materials, body_material
   public :: surface_name, n_surface_codes, surface_codes, surface_code_valid

   !> One contact: body point i against surface k.
   type :: contact_pair_t
      integer :: i = 0, k = 0
   end type contact_pair_t

   !> The surfaces a deck describes on *SURFACES (Table 3 and the starred
   !! ones of Table 7 that are surfaces of their own; 5* and 10* are derived).
   integer, parameter :: n_surface_codes = 16
   integer, parameter :: surface_codes(n_surface_codes) = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 21, 26, 29, 32]

contains

   pure logical function surface_code_valid(k)
      integer, intent(in) :: k
      surface_code_valid = any(surface_codes == k)
   end function surface_code_valid

   pure function surface_name(k) result(name)
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      select case (k)
      case (1); name = 'head rest'
      case (2); name = 'windshield'
      case (3); name = 'sun visor'
      case (4); name = 'upper panel'
      case (5); name = 'lower panel'
      case (6); name = 'toeboard'
      case (7); name = 'back of front seat'
      case (8); name = 'steering column'
      case (9); name = 'seat back'
      case (10); name = 'steering wheel rim'
      case (11); name = 'roof'
      case (12); name = 'floor'
      case (21); name = 'back of front head rest'
      case (25); name = 'lower panel edge'
      case (26); name = 'sloping rear floor'
      case (29); name = 'rear seat back'
      case (30); name = 'side rim of wheel'
      case (32); name = 'rear seat floor'
      case default; name = '?'
      end select
   end function surface_name

   !> The pairs of a position (Table 8, the specials (4, 1) and (9, 5*),
   !! and the rear passenger's foot on the sloping floor 6*, D-C27), in the
   !! order i, then k as the table lists them.
   pure function position_pairs(nbody) result(pairs)
      integer, intent(in) :: nbody
      type(contact_pair_t), allocatable :: pairs(:)
      allocate (pairs(0))
      select case (nbody)
      case (1)                                            ! driver: 20
         call add(1, [9])
         call add(2, [9])
         call add(3, [8, 10])
         call add(4, [1, 2, 3, 8, 9, 10, 11])
         call add(5, [30])
         call add(6, [9])
         call add(7, [5])
         call add(8, [6, 12])
         call add(9, [25])
         call add(10, [5, 30, 11])
      case (2)                                            ! front-seat passenger: 18
         call add(1, [9])
         call add(2, [9])
         call add(3, [4])
         call add(4, [1, 2, 3, 4, 9, 11])
         call add(6, [9])
         call add(7, [5])
         call add(8, [5, 6, 12])
         call add(9, [25])
         call add(10, [4, 5, 11])
      case (3)                                            ! rear-seat passenger: 15 (D-C27)
         call add(1, [29])
         call add(2, [29])
         call add(3, [7])
         call add(4, [1, 21, 7, 29, 11])
         call add(6, [29])
         call add(7, [7])
         call add(8, [26, 7, 32])
         call add(10, [7, 11])
      end select
   contains
      pure subroutine add(i, ks)
         integer, intent(in) :: i, ks(:)
         integer :: q
         do q = 1, size(ks)
            pairs = [pairs, contact_pair_t(i, ks(q))]
         end do
      end subroutine add
   end function position_pairs

   !> Table 9: the contacts that end the run under NEND = 2.
   pure logical function is_undesired(nbody, i, k)
      integer, intent(in) :: nbody, i, k
      is_undesired = .false.
      select case (nbody)
      case (1)
         select case (i)
         case (3); is_undesired = any(k == [8, 10])
         case (4); is_undesired = any(k == [2, 3, 8, 10, 11])
         case (5); is_undesired = k == 30
         case (7); is_undesired = k == 5
         case (9); is_undesired = k == 25
         case (10); is_undesired = any(k == [5, 30, 11])
         end select
      case (2)
         select case (i)
         case (3); is_undesired = k == 4
         case (4); is_undesired = any(k == [2, 3, 4, 11])
         case (7, 8); is_undesired = k == 5
         case (9); is_undesired = k == 25
         case (10); is_undesired = any(k == [4, 5, 11])
         end select
      case (3)
         select case (i)
         case (3, 7, 8); is_undesired = k == 7
         case (4); is_undesired = any(k == [21, 7, 11])
         case (10); is_undesired = any(k == [7, 11])
         end select
      end select
   end function is_undesired

   !> Table 11: the contacts whose deflection the body shares (figure 23).
   pure logical function is_shared(nbody, i, k)
      integer, intent(in) :: nbody, i, k
      is_shared = .false.
      select case (nbody)
      case (1)
         is_shared = (any(i == [3, 4]) .and. any(k == [8, 10])) .or. (i == 5 .and. k == 30)
      case (2)
         is_shared = any(i == [3, 4]) .and. k == 4
      case (3)
         is_shared = (i == 3 .and. k == 7) .or. (i == 4 .and. any(k == [21, 7]))
      end select
   end function is_shared

   !> Table 10: the surface's materials l, outer first (the starred ones as
   !! their models, D-C19).
   pure function surface_materials(k) result(l)
      integer, intent(in) :: k
      integer, allocatable :: l(:)
      select case (k)
      case (1, 21); l = [8]
      case (2); l = [2]
      case (3); l = [9]
      case (4, 5, 11, 25); l = [3, 6]
      case (6, 12, 26, 32); l = [4, 5]
      case (7, 9, 29); l = [1]
      case (8); l = [3, 10]
      case (10, 30); l = [7]
      case default; allocate (l(0))
      end select
   end function surface_materials

   !> Table 10's body materials: chest 12, face 13, shoulder 14 (the
   !! abdomen, 11, is under the lap belt only); 0 for the other points.
   pure integer function body_material(i) result(l)
      integer, intent(in) :: i
      select case (i)
      case (3); l = 12
      case (4); l = 13
      case (5); l = 14
      case default; l = 0
      end select
   end function body_material
end module contact_tables
