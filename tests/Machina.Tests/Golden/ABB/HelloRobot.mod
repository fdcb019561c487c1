MODULE HelloRobot

! Program "HelloRobot" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  CONST speeddata vel100 := [100,100,100,100];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    TPWrite "Hello Robot!";  ! [Display message "Hello Robot!"]
    ! [Set motion speed to 100 mm/s or deg/s]
    MoveL [[400, 300, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;  ! [Move to [400, 300, 500] mm]
    MoveL [[400, 300, 500], [0.7071, 0, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;  ! [Rotate -90 deg around [0, 1, 0]]
    MoveL [[400, 300, 750], [0.7071, 0, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 250] mm]
    WaitTime 2;  ! [Wait 2000 ms]
    MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;  ! [Set joint rotations to [0, 0, 0, 0, 90, 0] deg]

  ENDPROC

ENDMODULE
