MODULE Print3D

! Program "Print3D" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  CONST speeddata vel30 := [30,30,30,30];

  CONST robtarget target0 := [[50, 50, 0.3], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target1 := [[70, 50, 0.3], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target2 := [[70, 70, 0.3], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target3 := [[50, 70, 0.3], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target4 := [[50, 50, 0.3], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target5 := [[50, 50, 0.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target6 := [[70, 50, 0.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target7 := [[70, 70, 0.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target8 := [[50, 70, 0.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target9 := [[50, 50, 0.5], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target10 := [[50, 50, 0.7], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget target11 := [[50, 50, 10.7], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    ! Initialize this device. (nothing to do on an ABB robot)
    ! NOT SUPPORTED ON ABB: Set Bed temperature to 60 C
    ! NOT SUPPORTED ON ABB: Set Extruder temperature to 210 C and wait
    ! NOT SUPPORTED ON ABB: Set Bed temperature to 60 C and wait
    ! [Set motion speed to 30 mm/s or deg/s]
    MoveL target0, vel30, z5, Tool0\WObj:=WObj0;  ! [Move to [50, 50, 0.3] mm]
    ! NOT SUPPORTED ON ABB: Set extrusion rate to 0.05 mm/mm
    ! NOT SUPPORTED ON ABB: Turn extrusion on
    MoveL target1, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [20, 0, 0] mm]
    MoveL target2, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, 20, 0] mm]
    MoveL target3, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [-20, 0, 0] mm]
    MoveL target4, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, -20, 0] mm]
    MoveL target5, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 0.2] mm]
    MoveL target6, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [20, 0, 0] mm]
    MoveL target7, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, 20, 0] mm]
    MoveL target8, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [-20, 0, 0] mm]
    MoveL target9, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, -20, 0] mm]
    MoveL target10, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 0.2] mm]
    ! NOT SUPPORTED ON ABB: Turn extrusion off
    MoveL target11, vel30, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 10] mm]
    ! Terminate this device. (nothing to do on an ABB robot)

  ENDPROC

ENDMODULE
