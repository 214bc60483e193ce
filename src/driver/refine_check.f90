!> A convergence check for the user's own deck (issue 16, section 2;
!! `hsri2d --refine DECK...`, docs/usage.md): the deck run at its own
!! setting and at a refined one - half the step under a fixed step (RK4,
!! Adams-Moulton), RTOL and ATOL divided by 100 under Dormand-Prince -
!! and the quantities users read compared: HIC15, HIC36, the head's and
!! chest's peaks, the chest's 3 ms clip, every effect's peaks (the seat's
!! and each contact pair's largest force), and each joint's least and
!! largest relative angle. A quantity has converged when the two runs agree
!! within the engineering accuracy of docs/accuracy.md: 1 % of its value
!! (criteria, peaks) or 0.1 deg (angles). Neither run writes any output;
!! the table is the result.
module refine_check
   use kinds, only: wp, deg, g_std
   use error_handling, only: error_t
   use strings, only: num
   use number_format, only: fixed
   use text_io, only: string_t, append_string
   use model, only: model_t, n_joint, joint_name, nint_dopri
   use simulation, only: run_simulation
   use run_summary, only: run_summary_t
   use acceleration_criteria, only: hic_result_t
   implicit none
   private

   public :: refine_table, refined_model, relative_accuracy, angle_accuracy

   !> The engineering accuracy (docs/accuracy.md, "Engineering accuracy"):
   !! of a criterion or peak, relative to its refined value; of an angle.
   real(wp), parameter :: relative_accuracy = 0.01_wp
   real(wp), parameter :: angle_accuracy = 0.1_wp*deg
   !> A peak below this fraction of the largest of its kind is left out
   !! (a contact that barely touches: its 1 % would be noise).
   real(wp), parameter :: peak_floor = 0.05_wp

contains

   !> The model refined: half the step under a fixed step, RTOL and ATOL
   !! over 100 under Dormand-Prince (the print times unchanged).
   pure function refined_model(m) result(r)
      type(model_t), intent(in) :: m
      type(model_t) :: r
      r = m
      if (m%options%nint == nint_dopri) then
         r%time%rtol = m%time%rtol/100.0_wp
         r%time%atol = m%time%atol/100.0_wp
      else
         r%time%dt = 0.5_wp*m%time%dt
      end if
   end function refined_model

   !> Run m and its refinement and tabulate them (lines, for standard
   !! output); converged: every quantity within the engineering accuracy.
   !! err: a run that failed (the other's figures are then not compared).
   subroutine refine_table(m, lines, converged, err)
      type(model_t), intent(in) :: m
      type(string_t), allocatable, intent(out) :: lines(:)
      logical, intent(out) :: converged
      type(error_t), intent(inout) :: err
      type(model_t) :: r
      type(run_summary_t) :: a, b
      real(wp) :: cpu(2), c0, c1, largest, v_ref
      integer :: k, j, o, n_out
      character(len=:), allocatable :: setting, refined
      allocate (lines(0))
      converged = .false.
      r = refined_model(m)
      call cpu_time(c0)
      call run_simulation(m, a, err)
      call cpu_time(c1)
      cpu(1) = c1 - c0
      if (err%failed()) return
      call run_simulation(r, b, err)
      call cpu_time(c0)
      cpu(2) = c0 - c1
      if (err%failed()) return
      if (m%options%nint == nint_dopri) then
         setting = 'RTOL '//num(m%time%rtol)//', ATOL '//num(m%time%atol)
         refined = 'RTOL '//num(r%time%rtol)//', ATOL '//num(r%time%atol)
      else
         setting = 'DT '//num(m%time%dt)//' s'
         refined = 'DT '//num(r%time%dt)//' s'
      end if
      call append_string(lines, 'hsri2d --refine: '//trim(m%title))
      call append_string(lines, '  the deck at its setting ('//setting//') against a refined one ('//refined//'); '// &
                         'engineering accuracy: '//num(100.0_wp*relative_accuracy)//' % on criteria and peaks, ' &
                         //num(angle_accuracy/deg)//' deg on angles (docs/accuracy.md)')
      call append_string(lines, '')
      call append_string(lines, '  quantity                                             value       refined    difference  verdict')
      converged = .true.
      n_out = 0
      do o = 1, size(a%occ)
         associate (x => a%occ(o), y => b%occ(o))
            if (size(a%occ) > 1) call append_string(lines, '  occupant '//num(real(o, wp)))
            call compare('head HIC15', hic(x%head_criteria%hic15()), hic(y%head_criteria%hic15()), .false.)
            call compare('head HIC36', hic(x%head_criteria%hic36()), hic(y%head_criteria%hic36()), .false.)
            call compare('head acceleration, peak (g)', x%head_max%value/g_std, y%head_max%value/g_std, .false.)
            call compare('chest acceleration, peak (g)', x%chest_max%value/g_std, y%chest_max%value/g_std, .false.)
            call compare('chest 3 ms clip (g)', x%chest_criteria%clip3ms(), y%chest_criteria%clip3ms(), .false.)
            if (allocated(x%peaks) .and. allocated(y%peaks)) then
               ! the forces (lb) worth comparing, matched by name (a pair that
               ! touches in one run only has a peak in that run only)
               largest = 0.0_wp
               do k = 1, size(y%peaks)
                  if (trim(y%peaks(k)%unit) == 'lb') largest = max(largest, abs(y%peaks(k)%value))
               end do
               do k = 1, size(x%peaks)
                  if (trim(x%peaks(k)%unit) /= 'lb') cycle
                  v_ref = 0.0_wp
                  do j = 1, size(y%peaks)
                     if (y%peaks(j)%name == x%peaks(k)%name) v_ref = y%peaks(j)%value
                  end do
                  if (max(abs(v_ref), abs(x%peaks(k)%value)) < peak_floor*largest) cycle
                  call compare(trim(short_title(x%peaks(k)%title))//': '//trim(x%peaks(k)%label)//' (lb)', &
                               x%peaks(k)%value, v_ref, .false.)
               end do
               do j = 1, size(y%peaks)
                  if (trim(y%peaks(j)%unit) /= 'lb' .or. any(x%peaks(:)%name == y%peaks(j)%name)) cycle
                  if (abs(y%peaks(j)%value) < peak_floor*largest) cycle
                  call compare(trim(short_title(y%peaks(j)%title))//': '//trim(y%peaks(j)%label)//' (lb)', &
                               0.0_wp, y%peaks(j)%value, .false.)
               end do
            end if
            do k = 1, n_joint
               call compare(trim(joint_name(k))//', least angle (deg)', x%joint_min(k)%value/deg, &
                            y%joint_min(k)%value/deg, .true.)
               call compare(trim(joint_name(k))//', largest angle (deg)', x%joint_max(k)%value/deg, &
                            y%joint_max(k)%value/deg, .true.)
            end do
         end associate
      end do
      call append_string(lines, '')
      call append_string(lines, '  CPU time: '//fixed(cpu(1), 8, 3)//' s at the setting, '//fixed(cpu(2), 8, 3) &
                         //' s refined; steps '//num(real(a%stats%steps, wp))//' and '//num(real(b%stats%steps, wp)))
      if (converged) then
         call append_string(lines, '  verdict: converged - every quantity within the engineering accuracy at the deck''s ' &
                            //'setting')
      else
         call append_string(lines, '  verdict: NOT CONVERGED - '//num(real(n_out, wp))//' quantities differ by more than ' &
                            //'the engineering accuracy: the deck''s setting is too coarse for them; run it at the ' &
                            //'refined setting (and --refine that) or see docs/accuracy.md')
      end if
   contains
      !> An effect's title without its report section ("contact 4 on 8").
      function short_title(title) result(t)
         character(len=*), intent(in) :: title
         character(len=:), allocatable :: t
         integer :: p
         p = index(title, ' (')
         t = title
         if (p > 1) t = title(1:p - 1)
      end function short_title

      real(wp) function hic(h)
         type(hic_result_t), intent(in) :: h
         hic = h%value
      end function hic

      !> One row: name, the two values, their difference, the verdict.
      subroutine compare(name, v, v_ref, angle)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: v, v_ref
         logical, intent(in) :: angle
         character(len=52) :: label
         logical :: ok
         character(len=:), allocatable :: diff
         label = name
         if (angle) then
            ok = abs(v - v_ref) <= angle_accuracy/deg
            diff = fixed(v - v_ref, 12, 4)//'   '
         else
            ok = abs(v - v_ref) <= relative_accuracy*abs(v_ref)
            if (abs(v_ref) > 0.0_wp) then
               diff = fixed(100.0_wp*(v - v_ref)/abs(v_ref), 11, 3)//' % '
            else
               diff = fixed(v - v_ref, 12, 4)//'   '
            end if
         end if
         if (.not. ok) then
            converged = .false.
            n_out = n_out + 1
         end if
         call append_string(lines, '  '//label//' '//fixed(v, 12, 4)//'  '//fixed(v_ref, 12, 4)//'  '//diff &
                            //merge('ok        ', 'TOO COARSE', ok))
      end subroutine compare
   end subroutine refine_table
end module refine_check
