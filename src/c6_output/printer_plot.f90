!> Printer plots in the listing (C.6, *PRINTERPLOT; issue 18), as programs
!! of the report's era drew them on the 132-column page: the occupant over
!! the interior at chosen times - the surfaces, the seat's cushion line and
!! front edge, the belts from their anchors, the body's segments and head,
!! in the interior frame at the printer's aspect (a line is 5/3 as tall as
!! a column is wide: 10 characters to the inch, 6 lines) - and the head's
!! and chest's resultant accelerations against time.
!!
!! Its memory is bounded whatever TMAX and DTPRINT are: the posture at each
!! chosen time (at the first print time at or after it), and the largest
!! acceleration of each of the plot's columns of time; it draws when the
!! run ends. The geometry is the scene's (scene_geometry, the HDF5 file's
!! /scene), so the listing's picture and tools/plot's draw the same scene.
module printer_plot
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp, g_std
   use strings, only: itoa
   use number_format, only: fixed
   use model, only: printer_plot_section_t, max_plot_times, n_joint, n_seg
   use output_registry, only: output_registry_t, output_frame_t
   use equations_of_motion, only: crash_system_t
   use scene_geometry, only: scene_table_t, occupant_scene
   use listing, only: listing_t
   implicit none
   private

   public :: printer_plot_t

   !> The occupant's picture: columns and lines of the drawing area.
   integer, parameter :: pic_width = 120, pic_lines = 46
   !> A line of print is this many times as tall as a column is wide.
   real(wp), parameter :: line_aspect = 10.0_wp/6.0_wp
   !> The acceleration plots: columns of time and lines of value.
   integer, parameter :: acc_columns = 100, acc_lines = 20
   !> The scene's tables, by their place in occupant_scene's result.
   integer, parameter :: t_segments = 1, t_points = 2, t_surfaces = 3, t_belts = 4, t_seat = 5

   type :: printer_plot_t
      private
      logical :: on = .false.
      type(printer_plot_section_t) :: sec
      real(wp) :: t_max = 0.0_wp, t_last = 0.0_wp
      type(scene_table_t) :: scene(5)
      !> where occupant 1's joints, segment angles and accelerations are in a frame
      integer :: at_x = -1, at_y = -1, at_theta = -1, at_acc = -1
      logical :: taken(max_plot_times) = .false.
      real(wp) :: t_taken(max_plot_times) = 0.0_wp
      real(wp) :: joints(2, n_joint, max_plot_times) = 0.0_wp, theta(n_seg, max_plot_times) = 0.0_wp
      !> the largest head and chest acceleration (g) of each column of time
      real(wp) :: acc(2, acc_columns) = 0.0_wp
      logical :: has(acc_columns) = .false.
   contains
      procedure :: begin => plot_begin
      procedure :: record => plot_record
      procedure :: write => plot_write
   end type printer_plot_t

contains

   !> Ready to draw when the deck asks for it (sec%wanted): the scene and
   !! where the frame holds what the plots need.
   subroutine plot_begin(this, sec, t_max, sys, reg)
      class(printer_plot_t), intent(inout) :: this
      type(printer_plot_section_t), intent(in) :: sec
      real(wp), intent(in) :: t_max
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(in) :: reg
      this%on = sec%wanted .and. size(sys%occupants) > 0 .and. t_max > 0.0_wp
      if (.not. this%on) return
      this%sec = sec
      this%t_max = t_max
      this%scene = occupant_scene(sys%occupants(1))
      this%at_x = offset_of(reg, 'joints/x')
      this%at_y = offset_of(reg, 'joints/y')
      this%at_theta = offset_of(reg, 'body/theta')
      this%at_acc = offset_of(reg, 'acceleration')
      this%on = min(this%at_x, this%at_y, this%at_theta, this%at_acc) >= 0
   end subroutine plot_begin

   !> The offset in a frame of occupant 1's series `name`, -1 if none.
   pure integer function offset_of(reg, name) result(at)
      type(output_registry_t), intent(in) :: reg
      character(len=*), intent(in) :: name
      integer :: k
      at = -1
      do k = 1, size(reg%series)
         if (reg%series(k)%occupant == 1 .and. reg%series(k)%name == name) then
            at = reg%series(k)%offset
            return
         end if
      end do
   end function offset_of

   !> A print time: the posture for each chosen time reached, the
   !! accelerations into their column of time.
   subroutine plot_record(this, frame)
      class(printer_plot_t), intent(inout) :: this
      type(output_frame_t), intent(in) :: frame
      integer :: k, c
      real(wp) :: a(2)
      if (.not. this%on .or. .not. frame%valid) return
      this%t_last = frame%t
      do k = 1, max_plot_times
         if (.not. this%sec%given(k) .or. this%taken(k)) cycle
         ! the first print time at or after T_k (a print time equal to T_k up to rounding counts)
         if (frame%t < this%sec%times(k) - 1.0e-9_wp*this%t_max) cycle
         this%taken(k) = .true.
         this%t_taken(k) = frame%t
         this%joints(1, :, k) = frame%v(this%at_x + 1:this%at_x + n_joint)
         this%joints(2, :, k) = frame%v(this%at_y + 1:this%at_y + n_joint)
         this%theta(:, k) = frame%v(this%at_theta + 1:this%at_theta + n_seg)
      end do
      c = min(acc_columns, 1 + int(frame%t/this%t_max*acc_columns))
      a = frame%v(this%at_acc + 1:this%at_acc + 2)/g_std
      if (.not. all(ieee_is_finite(a))) return        ! (a failing run's last values)
      if (this%has(c)) then
         this%acc(:, c) = max(this%acc(:, c), a)
      else
         this%acc(:, c) = a
         this%has(c) = .true.
      end if
   end subroutine plot_record

   !> The plots' pages, when the deck asked for them.
   subroutine plot_write(this, lst)
      class(printer_plot_t), intent(in) :: this
      type(listing_t), intent(inout) :: lst
      real(wp) :: box(4), scale
      integer :: k
      if (.not. this%on) return
      box = picture_box(this)
      ! inches per column: the box fits the drawing area, lines 5/3 as tall
      scale = max((box(2) - box(1))/(pic_width - 1), (box(4) - box(3))/((pic_lines - 1)*line_aspect))
      do k = 1, max_plot_times
         if (.not. this%sec%given(k)) cycle
         call lst%new_page('PRINTER PLOTS (C.6)')
         if (.not. this%taken(k)) then
            call lst%put(' THE OCCUPANT AT T'//itoa(k)//' ='//fixed(this%sec%times(k), 9, 5)//' S: not drawn, ' &
                         //'the run''s last print time is t ='//fixed(this%t_last, 9, 5)//' s')
            cycle
         end if
         call occupant_picture(this, lst, k, box, scale)
      end do
      call acceleration_plots(this, lst)
   end subroutine plot_write

   !> x0, x1, y0, y1 (in): the interior's surfaces (but its lines), the
   !! belts' anchors, the seat, and the body at every time drawn.
   pure function picture_box(this) result(box)
      type(printer_plot_t), intent(in) :: this
      real(wp) :: box(4)
      real(wp) :: p(2)
      integer :: r, k, i
      box = [huge(1.0_wp), -huge(1.0_wp), huge(1.0_wp), -huge(1.0_wp)]
      associate (sf => this%scene(t_surfaces)%values, bl => this%scene(t_belts)%values, &
                 seat => this%scene(t_seat)%values)
         do r = 1, size(sf, 2)
            select case (nint(sf(2, r)))
            case (1)
               call take(sf(3:4, r))
               call take(sf(3:4, r) - sf(6, r)*[cos(sf(5, r)), sin(sf(5, r))])
            case (3)
               call take(sf(3:4, r) - 0.5_wp*sf(6, r))
               call take(sf(3:4, r) + 0.5_wp*sf(6, r))
            case (4)
               call take(sf(3:4, r))
            end select
         end do
         do r = 1, size(bl, 2)
            call take(bl(5:6, r))
         end do
         if (size(seat, 2) > 0) call take([seat(2, 1), seat(2, 1)*tan(seat(3, 1))])
      end associate
      do k = 1, max_plot_times
         if (.not. this%taken(k)) cycle
         do i = 1, n_joint
            call take(this%joints(:, i, k))
         end do
         do i = 1, size(this%scene(t_points)%values, 2)
            p = point_centre(this, k, i)
            call take(p - this%scene(t_points)%values(5, i))
            call take(p + this%scene(t_points)%values(5, i))
         end do
      end do
      if (box(1) > box(2)) box = [-10.0_wp, 10.0_wp, -10.0_wp, 10.0_wp]
      box = box + [-3.0_wp, 3.0_wp, -3.0_wp, 3.0_wp]
   contains
      pure subroutine take(q)
         real(wp), intent(in) :: q(2)
         if (.not. all(ieee_is_finite(q))) return
         box = [min(box(1), q(1)), max(box(2), q(1)), min(box(3), q(2)), max(box(4), q(2))]
      end subroutine take
   end function picture_box

   !> The centre of body point i (a contact arc of f.1) at chosen time k.
   pure function point_centre(this, k, i) result(p)
      type(printer_plot_t), intent(in) :: this
      integer, intent(in) :: k, i
      real(wp) :: p(2)
      real(wp) :: th
      associate (row => this%scene(t_points)%values(:, i))
         th = this%theta(nint(row(1)), k)
         p = this%joints(:, nint(row(2)), k) + row(3)*[cos(th), sin(th)] + row(4)*[-sin(th), cos(th)]
      end associate
   end function point_centre

   !> The occupant over the interior at chosen time k, with its axes (in).
   subroutine occupant_picture(this, lst, k, box, scale)
      type(printer_plot_t), intent(in) :: this
      type(listing_t), intent(inout) :: lst
      integer, intent(in) :: k
      real(wp), intent(in) :: box(4), scale
      character(len=pic_width) :: grid(pic_lines)
      character(len=132) :: line
      real(wp) :: centre(2), p(2), q(2), e1(2), th, far, x, y, d
      integer :: r, i, col, row, s
      centre = [0.5_wp*(box(1) + box(2)), 0.5_wp*(box(3) + box(4))]
      grid = ' '
      ! the interior: flat surfaces '#', lines '-', the head rest 'o', the panel's edge '+'
      associate (sf => this%scene(t_surfaces)%values)
         do r = 1, size(sf, 2)
            e1 = [cos(sf(5, r)), sin(sf(5, r))]
            select case (nint(sf(2, r)))
            case (1)
               if (sf(8, r) > sf(7, r)) then      ! the rim's opening
                  call segment(sf(3:4, r), sf(3:4, r) - sf(7, r)*e1, '#')
                  call segment(sf(3:4, r) - sf(8, r)*e1, sf(3:4, r) - sf(6, r)*e1, '#')
               else
                  call segment(sf(3:4, r), sf(3:4, r) - sf(6, r)*e1, '#')
               end if
            case (2)
               far = 2.0_wp*(box(2) - box(1) + box(4) - box(3))
               call segment(sf(3:4, r) - far*e1, sf(3:4, r) + far*e1, '-')
            case (3)
               call circle(sf(3:4, r), 0.5_wp*sf(6, r), 'o')
            case default
               call mark(sf(3:4, r), '+')
            end select
         end do
      end associate
      ! the seat: its cushion line through the initial hip to the front edge, '='
      associate (seat => this%scene(t_seat)%values)
         if (size(seat, 2) > 0) then
            p = [seat(2, 1), seat(2, 1)*tan(seat(3, 1))]
            call segment([box(1), box(1)*tan(seat(3, 1))], p, '=')
            call segment(p, p - [0.0_wp, 4.0_wp], '=')
         end if
      end associate
      ! the belts from their anchors 'A', ':' (figure 17)
      associate (bl => this%scene(t_belts)%values, hip => this%joints(:, 1, k))
         do r = 1, size(bl, 2)
            s = nint(bl(3, r))
            th = this%theta(s, k)
            if (nint(bl(2, r)) == 2) then
               q = this%joints(:, nint(bl(4, r)), k) + bl(7, r)*[cos(th), sin(th)]
            else                                  ! the lap belt: to the tangent point on the hip's circle
               d = norm2(hip - bl(5:6, r))
               x = 0.5_wp*acos(-1.0_wp)
               if (d > bl(7, r)) x = asin(bl(7, r)/d)
               y = x + atan2(hip(2) - bl(6, r), hip(1) - bl(5, r)) + 0.5_wp*acos(-1.0_wp)
               q = hip + bl(7, r)*[cos(y), sin(y)]
            end if
            call segment(bl(5:6, r), q, ':')
            call mark(bl(5:6, r), 'A')
         end do
      end associate
      ! the body: segments 'X' (never '*': asterisks in a listing mean a number
      ! too wide), the hand and the ankle at their segments' ends, the head 'O', joints '@'
      associate (j => this%joints(:, :, k), t => this%theta(:, k), len => this%scene(t_segments)%values(2, :))
         call segment(j(:, 1), j(:, 2), 'X')
         call segment(j(:, 2), j(:, 3), 'X')
         call segment(j(:, 3), j(:, 4), 'X')
         call segment(j(:, 3), j(:, 5), 'X')
         call segment(j(:, 5), j(:, 6), 'X')
         call segment(j(:, 6), j(:, 6) + len(6)*[cos(t(6)), sin(t(6))], 'X')
         call segment(j(:, 1), j(:, 7), 'X')
         call segment(j(:, 7), j(:, 7) + len(8)*[cos(t(8)), sin(t(8))], 'X')
         call circle(point_centre(this, k, 4), this%scene(t_points)%values(5, 4), 'O')
         do i = 1, n_joint
            call mark(j(:, i), '@')
         end do
      end associate

      call lst%put(' THE OCCUPANT AT T ='//fixed(this%t_taken(k), 9, 5)//' S (T'//itoa(k)//' ='// &
                   fixed(this%sec%times(k), 9, 5)//' S), INTERIOR FRAME: X FORWARD, Y UP, INCHES; ' &
                   //'ONE COLUMN'//fixed(scale, 7, 3)//' IN, ONE LINE'//fixed(scale*line_aspect, 7, 3)//' IN')
      call lst%put(' # SURFACE   - ROOF, FLOOR   o HEAD REST   + PANEL EDGE   = SEAT   A BELT ANCHOR   : BELT   ' &
                   //'X SEGMENT   @ JOINT   O HEAD')
      call lst%put(repeat(' ', 8)//'+'//repeat('-', pic_width)//'+')
      do row = 1, pic_lines
         y = centre(2) + ((pic_lines + 1)*0.5_wp - row)*scale*line_aspect
         line = repeat(' ', 8)//'|'//grid(row)//'|'
         ! the height at every line that crosses a multiple of 10 in
         if (floor((y + 0.5_wp*scale*line_aspect)/10.0_wp) /= floor((y - 0.5_wp*scale*line_aspect)/10.0_wp)) &
            line(1:7) = fixed(10.0_wp*floor((y + 0.5_wp*scale*line_aspect)/10.0_wp), 7, 0)
         call lst%put(line)
      end do
      call lst%put(repeat(' ', 8)//'+'//repeat('-', pic_width)//'+')
      line = ' '
      do col = 1, pic_width
         x = centre(1) + (col - (pic_width + 1)*0.5_wp)*scale
         if (floor((x + 0.5_wp*scale)/10.0_wp) /= floor((x - 0.5_wp*scale)/10.0_wp) .and. col + 10 <= 132) then
            if (line(col + 6:col + 11) == ' ') line(col + 6:col + 11) = fixed(10.0_wp*floor((x + 0.5_wp*scale) &
                                                                                         /10.0_wp), 6, 0)
         end if
      end do
      call lst%put(line)
   contains
      !> The character c at (x, y) in the drawing area, if it falls there.
      subroutine mark(pt, c)
         real(wp), intent(in) :: pt(2)
         character(len=1), intent(in) :: c
         integer :: cc, rr
         if (.not. all(ieee_is_finite(pt))) return
         if (abs(pt(1) - centre(1)) > 2.0_wp*pic_width*scale .or. &
             abs(pt(2) - centre(2)) > 2.0_wp*pic_lines*scale*line_aspect) return
         cc = nint((pt(1) - centre(1))/scale + (pic_width + 1)*0.5_wp)
         rr = nint((pic_lines + 1)*0.5_wp - (pt(2) - centre(2))/(scale*line_aspect))
         if (cc >= 1 .and. cc <= pic_width .and. rr >= 1 .and. rr <= pic_lines) grid(rr)(cc:cc) = c
      end subroutine mark

      !> The points of the segment from a to b, every half column.
      subroutine segment(a, b, c)
         real(wp), intent(in) :: a(2), b(2)
         character(len=1), intent(in) :: c
         integer :: n, m
         if (.not. (all(ieee_is_finite(a)) .and. all(ieee_is_finite(b)))) return
         n = max(1, min(100000, ceiling(min(1.0e6_wp, 2.0_wp*norm2(b - a)/scale))))
         do m = 0, n
            call mark(a + (b - a)*real(m, wp)/n, c)
         end do
      end subroutine segment

      subroutine circle(ctr, radius, c)
         real(wp), intent(in) :: ctr(2), radius
         character(len=1), intent(in) :: c
         integer :: n, m
         real(wp) :: a
         if (.not. (all(ieee_is_finite(ctr)) .and. ieee_is_finite(radius))) return
         n = max(12, min(100000, ceiling(min(1.0e6_wp, 4.0_wp*acos(-1.0_wp)*radius/scale))))
         do m = 0, n - 1
            a = 2.0_wp*acos(-1.0_wp)*m/n
            call mark(ctr + radius*[cos(a), sin(a)], c)
         end do
      end subroutine circle
   end subroutine occupant_picture

   !> The head's and the chest's resultant accelerations (g) against time:
   !! in each column of time, the largest at a print time within it.
   subroutine acceleration_plots(this, lst)
      type(printer_plot_t), intent(in) :: this
      type(listing_t), intent(inout) :: lst
      character(len=*), parameter :: names(2) = ['HEAD ', 'CHEST']
      !> the points: the plot's initial (never '*', which means a number too wide)
      character(len=1), parameter :: marks(2) = ['H', 'C']
      character(len=132) :: line
      character(len=acc_columns) :: grid(acc_lines)
      real(wp) :: top, step, v
      integer :: which, c, row
      call lst%new_page('PRINTER PLOTS (C.6)')
      do which = 1, 2
         top = nice_top(maxval(this%acc(which, :), mask=this%has))
         step = top/acc_lines
         grid = ' '
         do c = 1, acc_columns
            if (.not. this%has(c)) cycle
            row = acc_lines - nint(this%acc(which, c)/step) + 1
            row = min(acc_lines, max(1, row))
            grid(row)(c:c) = marks(which)
         end do
         call lst%heading(trim(names(which))//' RESULTANT ACCELERATION (G) AGAINST TIME (S): THE LARGEST AT A ' &
                          //'PRINT TIME IN EACH COLUMN OF'//fixed(this%t_max/acc_columns, 9, 5)//' S', acc_lines + 5)
         call lst%put(repeat(' ', 10)//'+'//repeat('-', acc_columns)//'+')
         do row = 1, acc_lines
            v = top - (row - 1)*step
            line = repeat(' ', 10)//'|'//grid(row)//'|'
            if (mod(row - 1, 5) == 0) line(1:9) = fixed(v, 9, 1)
            call lst%put(line)
         end do
         line = repeat(' ', 9)//'0 +'//repeat('-', acc_columns)//'+'
         call lst%put(line)
         line = ' '
         do c = 0, acc_columns, 20
            line(c + 2:c + 11) = fixed(this%t_max*c/acc_columns, 10, 3)
         end do
         call lst%put(line)
         call lst%blank()
      end do
   end subroutine acceleration_plots

   !> The plot's top: 1, 2 or 5 times a power of ten at or above v (and
   !! at least 1 g), so that its lines fall on round values.
   pure real(wp) function nice_top(v) result(top)
      real(wp), intent(in) :: v
      real(wp) :: p
      integer :: i
      real(wp), parameter :: steps(3) = [1.0_wp, 2.0_wp, 5.0_wp]
      top = 1.0_wp
      if (.not. (v > 1.0_wp)) return
      p = 10.0_wp**floor(log10(v))
      do i = 1, 3
         top = steps(i)*p
         if (top >= v) return
      end do
      top = 10.0_wp*p
   end function nice_top
end module printer_plot
