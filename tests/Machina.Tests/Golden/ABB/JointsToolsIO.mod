MODULE JointsToolsIO

! Program "JointsToolsIO" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  ! This program sets IO signals: each signal name must exist in the controller's IO configuration.

  PERS tooldata pen := [TRUE,[[0,0,100],[0.7071,0,0,0.7071]],[0.5,[0,0,50],[1,0,0,0],0,0,0]];
  CONST speeddata vel20 := [20,20,20,20];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\WObj:=WObj0;  ! [Set joint rotations to [0, 0, 0, 0, 90, 0] deg]
    ! [Set motion type to 'Joint']
    MoveJ [[400, 0, 400], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\WObj:=WObj0;  ! [Transform: move to [400, 0, 400] mm and rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]]
    ! Tool "pen" defined  ! [Define tool "pen" on the Robot.]
    ! Tool "pen" attached  ! [Attach tool "pen" to robot flange.]
    ! [Set motion type to 'Linear']
    MoveL [[400, 0, 250], [0, 0.7071, 0.7071, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, pen\WObj:=WObj0;  ! [Move [0, 0, -50] mm]
    ! NOT SUPPORTED ON ABB: Turn digital IO 1 ON
    ! NOT SUPPORTED ON ABB: Set analog IO 2 to 0.5
    WaitTime 0.5;  ! [Wait 500 ms]
    SetDO DO_Gripper, 0;  ! [Turn tool digital IO "DO_Gripper" OFF]
    ! All tools detached  ! [Detach all tools from robot.]
    MoveAbsJ [[0, -30, 30, 0, 60, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\WObj:=WObj0;  ! [Set joint rotations to [0, -30, 30, 0, 60, 0] deg]
    MoveAbsJ [[10, -30, 30, 0, 60, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\WObj:=WObj0;  ! [Increase joint rotations by [10, 0, 0, 0, 0, 0] deg]

  ENDPROC

ENDMODULE
