!> Table 2 of the report for the belts NBELT calls for, as the listing
!! prints it (C.4.e, C.2; docs/belts.md): a column per section j (1 lap
!! belt, 2 lower torso, 3 upper torso; 4 the lap belt's second side,
!! LAPSIDES = 2), a row per parameter: h, l_o, phi_o, l'_o, phi'_o, the
!! slack, the loading (curve, G, R; the curves' sigma_n and sigma_n+N are
!! in the loading curves' table) and the body surface under the section;
!! then how the sections share their tension.
module belts_table
   use kinds, only: wp, deg, pi
   use strings, only: itoa
   use text_table, only: text_table_t, new_table, cell_text, cell_fixed
   use model, only: model_t, n_belt_card, belt_card_lap2, coupling_name, nbelt_lap, nbelt_torso, material_name
   use loading_parameters, only: curve_polynomial
   use belt_geometry, only: belt_section_geometry_t, lap_belt_geometry
   implicit none
   private

   public :: belts_parameter_table

contains

   !> The belts of m (no rows when NBELT = 0).
   function belts_parameter_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      character(len=*), parameter :: section_name(n_belt_card) = [character(len=16) :: &
         '1. LAP BELT', '2. LOWER TORSO', '3. UPPER TORSO', '4. LAP, SIDE 2']
      integer :: cols(n_belt_card), nc, j, k
      logical :: used(n_belt_card)
      real(wp) :: length10(n_belt_card), phi10(n_belt_card)
      associate (b => m%belts, ld => m%loading, nbelt => m%options%nbelt)
         t = new_table('TABLE 2 - BELTS (C.4.e, C.2): NBELT = '//itoa(nbelt), keep=17)
         if (nbelt == 0) return
         used = [nbelt_lap(nbelt), nbelt_torso(nbelt), nbelt_torso(nbelt), nbelt_lap(nbelt) .and. b%lap_sides == 2]
         nc = count(used)
         cols(1:nc) = pack([(j, j=1, n_belt_card)], used)
         ! the lap belt's length and angle at t = 0 (C.2 with errata C2-2, C2-3)
         length10 = 0.0_wp
         phi10 = 0.0_wp
         do k = 1, nc
            if (is_lap(cols(k))) call lap_initial(cols(k), length10(cols(k)), phi10(cols(k)))
         end do
         call t%add_column('PARAMETER (SUBSCRIPT J)', 12, cell_text)
         call t%add_column('', 42, cell_text, lead=0)
         call t%add_column('UNIT', 6, cell_text, lead=0)
         do k = 1, nc
            call t%add_column(section_name(cols(k))(1:14), 16, head_right=.true.)
         end do
         call put_row('h', 'wrap radius (lap); distance on the torso', 'in', b%h)
         call lap_row('l_o', 'length at t = 0', 'in', length10, b%length0)
         call lap_row('phi_o', 'angle at t = 0, anchor to belt', 'deg', phi10, b%phi0)
         call lap_row('l''_o', 'lap anchor to the initial hip', 'in', b%length_anchor)
         call lap_row('phi''_o', 'lap, anchor to the initial hip', 'deg', b%phi_anchor)
         call put_row('Delta', 'slack', 'in', b%slack)
         call row_head('k', 'loading curve (N: its order)', '-')
         do k = 1, nc
            j = cols(k)
            call t%put(curve_text(ld%belt_curve(section(j)), b%lap_sides == 2 .and. is_lap(j)))
         end do
         call put_row('G', 'residual / maximum deformation', '-', ld%belt_g([1, 2, 3, 1]))
         call put_row('R', 'energy conserved / absorbed', '-', ld%belt_r([1, 2, 3, 1]))
         call row_head('', 'body under the section (Table 4)', '-')
         do k = 1, nc
            j = cols(k)
            call t%put(body_text(merge(11, 12, is_lap(j))))
         end do
         call t%add_line('  c: computed (C.2 with errata C2-2, C2-3); sigma_n, sigma_n+N: the loading curves above')
         if (b%lap_sides == 2) call t%add_line('  the lap belt''s two sides: each carries half of the lap belt''s ' &
                                               //'curve and of the abdomen''s (docs/belts.md 4)')
         call t%add_line('  coupling '//trim(coupling_name(b%coupling))//': '//trim(coupling_text(b%coupling)) &
                         //'   lap sides '//itoa(b%lap_sides)//'   iteration limit '//itoa(b%max_iter))
      end associate
   contains
      pure logical function is_lap(j)
         integer, intent(in) :: j
         is_lap = j == 1 .or. j == belt_card_lap2
      end function is_lap
      !> The loading section (1-3) of card j.
      pure integer function section(j)
         integer, intent(in) :: j
         section = merge(1, j, j == belt_card_lap2)
      end function section
      !> A row's symbol, meaning and unit; its sections' cells follow.
      subroutine row_head(symbol, meaning, unit)
         character(len=*), intent(in) :: symbol, meaning, unit
         call t%new_row()
         call t%put(symbol)
         call t%put(meaning)
         call t%put(unit)
      end subroutine row_head
      !> A row of the lap sections' lap (computed, marked c, when other is
      !! given for the torso sections; '-' there otherwise); angles (unit
      !! deg) in degrees, F editing.
      subroutine lap_row(symbol, meaning, unit, lap, other)
         character(len=*), intent(in) :: symbol, meaning, unit
         real(wp), intent(in) :: lap(n_belt_card)
         real(wp), intent(in), optional :: other(n_belt_card)
         real(wp) :: x
         character(len=2) :: mark
         integer :: kk
         call row_head(symbol, meaning, unit)
         do kk = 1, nc
            mark = merge(' c', '  ', present(other) .and. is_lap(cols(kk)))
            if (is_lap(cols(kk))) then
               x = lap(cols(kk))
            else if (present(other)) then
               x = other(cols(kk))
            else
               call t%put('-')
               cycle
            end if
            if (unit == 'deg') then
               call t%put(x/deg, form=cell_fixed, decimals=3, mark=mark)
            else
               call t%put(x, mark=mark)
            end if
         end do
      end subroutine lap_row
      subroutine put_row(symbol, meaning, unit, x)
         character(len=*), intent(in) :: symbol, meaning, unit
         real(wp), intent(in) :: x(n_belt_card)
         integer :: kk
         call row_head(symbol, meaning, unit)
         do kk = 1, nc
            call t%put(x(cols(kk)))
         end do
      end subroutine put_row
      !> C.2 for lap card j: the free length with its wrap, and phi_10 =
      !! phi'_0 + asin(h / l'_0), from the initial hip (the interior origin).
      subroutine lap_initial(j, length, phi)
         integer, intent(in) :: j
         real(wp), intent(out) :: length, phi
         type(belt_section_geometry_t) :: g
         g = lap_belt_geometry(m%belts%h(j), m%belts%length_anchor(j), m%belts%phi_anchor(j), [0.0_wp, 0.0_wp], &
                               m%body%theta0(1))
         length = g%length0
         phi = m%belts%phi_anchor(j) + asin(m%belts%h(j)/m%belts%length_anchor(j))
         phi = modulo(phi + pi, 2.0_wp*pi) - pi
      end subroutine lap_initial
      function curve_text(kc, half) result(text)
         integer, intent(in) :: kc
         logical, intent(in) :: half
         character(len=:), allocatable :: text
         character(len=14) :: order
         order = 'table'
         if (m%loading%curve(kc)%form == curve_polynomial) order = 'N = '//itoa(m%loading%curve(kc)%order)
         text = merge('half ', '     ', half)//itoa(kc)//', '//trim(order)
         text = trim(adjustl(text))
      end function curve_text
      function body_text(l) result(text)
         integer, intent(in) :: l
         character(len=:), allocatable :: text
         if (m%loading%material_curve(l) > 0) then
            text = itoa(l)//' '//trim(material_name(l))
         else
            text = itoa(l)//' rigid'
         end if
      end function body_text
      function coupling_text(c) result(text)
         integer, intent(in) :: c
         character(len=:), allocatable :: text
         select case (c)
         case (1)
            text = 'every section its own tension (the report''s phase two)'
         case (2)
            text = 'the two torso sections one tension'
         case default
            text = 'the three sections one tension'
         end select
      end function coupling_text
   end function belts_parameter_table
end module belts_table
