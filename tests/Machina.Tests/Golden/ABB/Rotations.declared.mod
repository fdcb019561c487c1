MODULE Rotations

! Program "Rotations" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  CONST speeddata vel20 := [20,20,20,20];

  CONST robtarget target0 := [[300, 200, 400], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target1 := [[300, 200, 400], [0, -0.3827, 0.9239, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target2 := [[300, 200, 400], [0.099, -0.3696, 0.8924, -0.2391], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target3 := [[307.071, 192.929, 382.679], [0.099, -0.3696, 0.8924, -0.2391], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target4 := [[307.071, 192.929, 382.679], [0, 0.7071, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target5 := [[350, 250, 450], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target6 := [[350, 250, 450], [-0.1736, 0, 0.9848, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    MoveL target0, vel20, z5, Tool0\WObj:=WObj0;  ! [Move to [300, 200, 400] mm]
    MoveL target1, vel20, z5, Tool0\WObj:=WObj0;  ! [Rotate 45 deg around [0, 0, 1]]
    ! [Set reference coordinate system to 'Local']
    MoveL target2, vel20, z5, Tool0\WObj:=WObj0;  ! [Rotate 30 deg around [1, 0, 0]]
    MoveL target3, vel20, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 20] mm]
    ! [Set reference coordinate system to 'World']
    MoveL target4, vel20, z5, Tool0\WObj:=WObj0;  ! [Rotate to [[0, 1, 0], [1, 0, 0], [0, 0, -1]]]
    MoveL target5, vel20, z5, Tool0\WObj:=WObj0;  ! [Transform: move to [350, 250, 450] mm and rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]]
    MoveL target6, vel20, z5, Tool0\WObj:=WObj0;  ! [Rotate 20 deg around [0, 1, 0]]

  ENDPROC

ENDMODULE
