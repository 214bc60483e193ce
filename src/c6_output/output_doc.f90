!> The table of output series a run writes, in Markdown, from the output
!! registry: `hsri2d --outputs` prints it, and the HDF5 section of
!! docs/usage.md holds it for the default deck (a test compares), so the
!! documentation and the files cannot disagree.
module output_doc
   use strings, only: itoa
   use text_io, only: string_t, append_string
   use output_registry, only: output_registry_t
   use event_text, only: event_kind_catalogue
   implicit none
   private

   public :: output_table_lines

contains

   !> One row per series: HDF5 dataset, shape, columns and units, the NOUT
   !! level from which the listing prints it, and its description.
   function output_table_lines(reg) result(lines)
      type(output_registry_t), intent(in) :: reg
      type(string_t), allocatable :: lines(:)
      character(len=:), allocatable :: cols, shape
      integer :: k, c
      allocate (lines(0))
      call append_string(lines, '| dataset | shape | columns (units) | listing from NOUT | content |')
      call append_string(lines, '|---|---|---|---|---|')
      call append_string(lines, '| `/time` | (n) | t (s) | every table | print times (C.6) |')
      do k = 1, size(reg%series)
         associate (s => reg%series(k))
            cols = ''
            do c = 1, size(s%col)
               if (c > 1) cols = cols//', '
               cols = cols//trim(s%col(c)%name)//' ('//trim(s%col(c)%unit)//')'
            end do
            if (size(s%col) == 1) then
               shape = '(n)'
            else
               shape = '(n, '//itoa(size(s%col))//')'
            end if
            call append_string(lines, '| `/'//s%name//'` | '//shape//' | '//escaped(cols)//' | '//itoa(s%nout)//' | ' &
                               //escaped(s%description)//' |')
         end associate
      end do
      call append_string(lines, '| `/summary/maxima`, `/summary/maxima_time` | (1, m) | head_acceleration, ' &
                         //'chest_acceleration (in/s^2), joint_i_min, joint_i_max (rad); with limits tension_j, ' &
                         //'compression_i, shear_i (lb); the spring seat''s seat_hip_force, seat_edge_force (lb); ' &
                         //'for each contact pair that touched contact_i_k_force (lb), contact_i_k_pos and ' &
                         //'contact_i_k_delta (in) at its largest force; the times (s) | ' &
                         //'summary | the maxima over all accepted steps and when they happened, as the listing''s ' &
                         //'summary gives them |')
      call append_string(lines, '| `/summary/injury_criteria` | (1, 9) | head_hic15, head_hic15_t1, head_hic15_t2, ' &
                         //'head_hic36, head_hic36_t1, head_hic36_t2, head_gsi, chest_gsi, chest_clip3ms (g) | ' &
                         //'summary | HIC15 and HIC36 of the head with their windows (s), the Gadd Severity Index ' &
                         //'of head and chest, the chest''s cumulative 3 ms clip; from the accelerations at ' &
                         //'accepted steps (docs/injury.md) |')
      call append_string(lines, '| `/summary/criteria` | (6, 11) | head_hic15, head_hic36, head_gsi, chest_clip3ms (g), ' &
                         //'chest_gsi, chest_deflection (mm), chest_vc (m/s), neck_nij, neck_tension (N), ' &
                         //'neck_compression (N), femur_compression (N); rows value, limit, time, time_end, pass, ' &
                         //'unfiltered; attributes filter_class, rows | summary | the table FMVSS 208 (50th male): ' &
                         //'each criterion from its channel filtered as SAE J211-1 specifies, in SI, its limit ' &
                         //'(*FMVSS208), when, pass (1) or fail (0), the unfiltered value beside it; NaN: none ' &
                         //'(docs/injury.md) |')
      call append_string(lines, '| `/channels/time`, `/channels/head_time`, `/channels/head_acceleration`, ' &
                         //'`/channels/chest_acceleration`, ' &
                         //'`/channels/neck_loads`, `/channels/femur_force`, `/channels/chest_deflection`, ' &
                         //'`/channels/belt_forces`, `/channels/vehicle_acceleration` | (k, c) | ' &
                         //'t (s); t (s); x, y (g); x, y (g); axial (N), moment (N m); axial (N); deflection (mm); ' &
                         //'a column a belt section (N); x, y (g) | summary | ' &
                         //'the channels the FMVSS 208 table reads, unfiltered, on their 10 kHz grid (the head''s ' &
                         //'on its 20 kHz grid, /channels/head_time), each with the ' &
                         //'SAE J211 class it is filtered at (attribute filter_class); the chest''s deflection where ' &
                         //'an effect deflects it; the belts'' tensions (CFC 60) and the vehicle''s acceleration ' &
                         //'(CFC 60, exact from its tables) for the ISO-MME channels (docs/pulse.md) |')
      call append_string(lines, '| `/events/time`, `/events/kind`, `/events/index`, `/events/text` | (k) | - | summary | ' &
                         //'the events as they happened, by kind (a code never renumbered; a new kind takes the next): ' &
                         //event_kinds(.false.)//'; and notes, not injuries ' &
                         //'(their text begins "note:", the listing''s NOTES): '//event_kinds(.true.)//' |')
      call append_string(lines, '| `/input/deck` | (cards) | - | deck echo | the deck''s card images |')
   end function output_table_lines

   !> The event kinds (event_text's catalogue) that are notes, or those that
   !! are not: "1 dislocation (below limit), 2 ...".
   function event_kinds(notes) result(s)
      logical, intent(in) :: notes
      character(len=:), allocatable :: s
      integer :: k
      s = ''
      do k = 1, size(event_kind_catalogue)
         associate (kind => event_kind_catalogue(k))
            if (kind%note .neqv. notes) cycle
            if (len(s) > 0) s = s//', '
            s = s//itoa(kind%code)//' '//trim(kind%name)
         end associate
      end do
   end function event_kinds

   !> Markdown text: | would end a cell and * start emphasis.
   pure function escaped(text) result(s)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, len(text)
         select case (text(i:i))
         case ('|', '*')
            s = s//'\'//text(i:i)
         case default
            s = s//text(i:i)
         end select
      end do
   end function escaped
end module output_doc
