!> The loading curves the deck gives (C.4.e, Tables 2 and 4;
!! docs/loading.md) and who uses them, as the listing prints them: lines,
!! not columns (text_table).
module loading_table
   use kinds, only: wp
   use strings, only: itoa
   use text_table, only: text_table_t, new_table
   use model, only: model_t, material_name
   use loading_parameters, only: curve_is_defined, curve_polynomial, curve_table
   implicit none
   private

   public :: loading_curves_table

contains

   !> Each curve (polynomial: its sigmas; tabulated: its points), the
   !! materials and belt sections that use one; no lines without curves.
   function loading_curves_table(m) result(t)
      type(model_t), intent(in) :: m
      type(text_table_t) :: t
      character(len=132) :: line
      integer :: k, j, n
      n = count([(curve_is_defined(m%loading%curve(k)), k=1, size(m%loading%curve))])
      t = new_table('LOADING CURVES (C.4.e, TABLES 2 AND 4; NLOAD = '//itoa(m%options%nload)//')', keep=n + 2)
      if (n == 0) return
      do k = 1, size(m%loading%curve)
         associate (c => m%loading%curve(k))
            select case (c%form)
            case (curve_polynomial)
               write (line, '(a,i3,a,i2,a,5es11.3)') '  curve', k, ': polynomial, N =', c%order, ', sigma', &
                  c%sigma(1:c%order)
               call t%add_line(line)
               if (any(c%sigma_rate > 0.0_wp)) then
                  write (line, '(a,5es11.3)') '             rate terms', c%sigma_rate(1:c%order)
                  call t%add_line(line)
               end if
            case (curve_table)
               write (line, '(a,i3,a)') '  curve', k, ': table of '//itoa(size(c%defl))//' points, deflection (in) : force (lb)'
               call t%add_line(line)
               do j = 1, size(c%defl), 5
                  write (line, '(9x,5(es10.3,a,es10.3,2x))') (c%defl(n), ':', c%force(n), n=j, min(j + 4, size(c%defl)))
                  call t%add_line(line)
               end do
               if (any(c%sigma_rate > 0.0_wp)) then
                  write (line, '(a,5es11.3)') '             rate terms', c%sigma_rate
                  call t%add_line(line)
               end if
            end select
         end associate
      end do
      do k = 1, size(m%loading%material_curve)
         if (m%loading%material_curve(k) > 0) call t%add_line('  material '//itoa(k)//' ('//trim(material_name(k)) &
            //') uses curve '//itoa(m%loading%material_curve(k)))
      end do
      do k = 1, size(m%loading%belt_curve)
         if (m%loading%belt_curve(k) > 0) call t%add_line('  belt section '//itoa(k)//' uses curve ' &
            //itoa(m%loading%belt_curve(k)))
      end do
   end function loading_curves_table
end module loading_table
