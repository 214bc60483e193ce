!> The scene's contacts (C.4.f; docs/contacts.md 2, 3.1): the surfaces the
!! deck describes, with f.2's relations resolved (the upper panel from the
!! windshield's lower end, the rim at the column's angle with its opening,
!! the side rim 10*, roof and floor, the lower panel's edge 5*), and the
!! pairs of the occupant's position (Tables 7, 8) whose surface the deck
!! describes and does not switch off, each with the laws of its chain: the
!! body's material where Table 11 shares the deflection, the surface's
!! outer material and its backing (docs/contacts.md 3.4).
module contact_scene
   use kinds, only: wp, pi
   use model, only: model_t, interior_section_t, nint_dopri
   use contact_geometry, only: contact_surface_t, surface_flat, surface_line, surface_circle, surface_point, e
   use contact_tables, only: contact_pair_t, is_undesired, is_shared, body_material
   use interior_pairs, only: scene_pairs, surface_layers   ! (the deck's own: C.1 checks them)
   use contact_forces, only: contact_pair_effect_t, contact_pair_effect
   use recurrent_loading, only: recurrent_law_t, material_law
   implicit none
   private

   public :: resolved_surface, surface_layers, scene_pairs, scene_contact_effects

contains

   !> Surface k with f.2's relations resolved; ok false when the deck does
   !! not describe it (or what it derives from).
   pure subroutine resolved_surface(it, k, sf, ok)
      type(interior_section_t), intent(in) :: it
      integer, intent(in) :: k
      type(contact_surface_t), intent(out) :: sf
      logical, intent(out) :: ok
      real(wp) :: c_w(2)
      ok = .false.
      select case (k)
      case (1)                                   ! the head rest: a circle (F24-1)
         if (.not. it%given(1)) return
         sf = contact_surface_t(kind=surface_circle, s=[it%x(1), it%y(1)], psi=it%psi(1), d=it%d(1))
      case (4)                                   ! from the windshield's lower end
         if (.not. (it%given(4) .and. it%given(2))) return
         sf = contact_surface_t(kind=surface_flat, s=[it%x(2), it%y(2)] - it%d(2)*e(it%psi(2)), psi=it%psi(4), &
                                d=it%d(4))
      case (10)                                  ! the rim, at the column's angle, with its opening (D-C11)
         if (.not. (it%given(10) .and. it%given(8))) return
         sf = contact_surface_t(kind=surface_flat, s=[it%x(10), it%y(10)], psi=it%psi(8), d=it%d(10))
         if (it%di > 0.0_wp) sf%t_open = 0.5_wp*[it%d(10) - it%di, it%d(10) + it%di]
      case (30)                                  ! the side rim: D_s about the wheel's centre (D-C12)
         if (.not. (it%given(10) .and. it%given(8) .and. it%ds > 0.0_wp)) return
         c_w = [it%x(10), it%y(10)] - 0.5_wp*it%d(10)*e(it%psi(8))
         sf = contact_surface_t(kind=surface_flat, s=c_w + 0.5_wp*it%ds*e(it%psi(8)), psi=it%psi(8), d=it%ds)
      case (11)                                  ! the roof at the windshield's upper end (D-C6)
         if (.not. (it%given(11) .and. it%given(2))) return
         sf = contact_surface_t(kind=surface_line, s=[0.0_wp, it%y(2)], psi=pi)
      case (12)                                  ! the floor at the toeboard's lower end
         if (.not. (it%given(12) .and. it%given(6))) return
         sf = contact_surface_t(kind=surface_line, s=[0.0_wp, it%y(6) - it%d(6)*sin(it%psi(6))], psi=0.0_wp)
      case (32)                                  ! the rear-seat floor, level at Y
         if (.not. it%given(32)) return
         sf = contact_surface_t(kind=surface_line, s=[0.0_wp, it%y(32)], psi=0.0_wp)
      case (25)                                  ! the lower panel's lower edge, for the shin
         if (.not. it%given(5)) return
         sf = contact_surface_t(kind=surface_point, s=[it%x(5), it%y(5)] - it%d(5)*e(it%psi(5)))
      case default                               ! a flat piece of its own
         if (k < 1 .or. k > size(it%given)) return
         if (.not. it%given(k)) return
         sf = contact_surface_t(kind=surface_flat, s=[it%x(k), it%y(k)], psi=it%psi(k), d=it%d(k))
      end select
      ok = .true.
   end subroutine resolved_surface

   !> Table 11 (figure 23): the body material (chest 12, face 13, shoulder
   !! 14) that shares a pair's deflection, when it has a loading curve (a
   !! body material without one is rigid, D-B6); 0 otherwise.
   pure integer function shared_material(m, pair) result(l)
      type(model_t), intent(in) :: m
      type(contact_pair_t), intent(in) :: pair
      l = 0
      if (.not. is_shared(m%options%nbody, pair%i, pair%k)) return
      if (body_material(pair%i) == 0) return
      if (m%loading%material_curve(body_material(pair%i)) > 0) l = body_material(pair%i)
   end function shared_material

   !> The contact effects of the scene, one per pair (D-C15). A backing
   !! (padding or mat bottoming out at eta D'' on it) and the body's own
   !! material in front (Table 11, figure 23) are passed only where the
   !! scene has them: an unallocated actual argument is an absent optional.
   function scene_contact_effects(m) result(effects)
      type(model_t), intent(in) :: m
      type(contact_pair_effect_t), allocatable :: effects(:)
      type(contact_pair_t), allocatable :: pairs(:)
      type(contact_surface_t) :: sf
      type(recurrent_law_t), allocatable :: backing, body_law
      real(wp), allocatable :: cap
      logical :: ok
      integer :: q, l, lb
      allocate (pairs(0))
      pairs = scene_pairs(m)
      allocate (effects(size(pairs)))
      do q = 1, size(pairs)
         call resolved_surface(m%interior, pairs(q)%k, sf, ok)
         call surface_layers(m%interior, pairs(q)%k, l, lb)
         associate (kd => merge(5, pairs(q)%k, pairs(q)%k == 25), lbody => shared_material(m, pairs(q)))
            if (allocated(backing)) deallocate (backing, cap)
            if (allocated(body_law)) deallocate (body_law)
            if (lb > 0) then
               backing = material_law(m%materials, m%loading, lb)
               cap = m%materials%eta(l)*m%interior%dpp(kd)
            end if
            if (lbody > 0) body_law = material_law(m%materials, m%loading, lbody)
            effects(q) = contact_pair_effect(m%body, pairs(q)%i, pairs(q)%k, sf, &
                                             material_law(m%materials, m%loading, l), m%materials%mu(l), &
                                             m%materials%xi(l), is_undesired(m%options%nbody, pairs(q)%i, pairs(q)%k), &
                                             merge(m%materials%fsw, 0.0_wp, l == 2), backing=backing, cap=cap, &
                                             body_law=body_law, gated=lb == 10, &
                                             dt_fixed=merge(0.0_wp, m%time%dt, m%options%nint == nint_dopri))
         end associate
      end do
   end function scene_contact_effects
end module contact_scene
