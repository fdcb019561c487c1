MODULE HelloRobot

! Program "HelloRobot" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  CONST speeddata vel100 := [100,100,100,100];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    TPWrite "Hello Robot!";
    MoveL [[400, 300, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;
    MoveL [[400, 300, 500], [0.7071, 0, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;
    MoveL [[400, 300, 750], [0.7071, 0, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;
    WaitTime 2;
    MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\WObj:=WObj0;

  ENDPROC

ENDMODULE
