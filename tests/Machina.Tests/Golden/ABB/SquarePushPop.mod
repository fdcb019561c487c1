MODULE SquarePushPop

! Program "SquarePushPop" written by Machina 0.1.0 for ABB.
! Safety: this program moves a machine that can hurt people. Check it in simulation first,
! run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.

  CONST speeddata vel50 := [50,50,50,50];
  CONST speeddata vel200 := [200,200,200,200];

  PROC main()
    ConfJ \Off;
    ConfL \Off;
    WorldAccLim \Off;

    ! [Set motion speed to 50 mm/s or deg/s]
    WorldAccLim \On := 0.5;  ! [Set motion acceleration to 500 mm/s^2 or deg/s^2]
    MoveL [[300, 0, 300], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel50, z5, Tool0\WObj:=WObj0;  ! [Move to [300, 0, 300] mm]
    ! [Push settings to buffer]
    ! [Set motion speed to 200 mm/s or deg/s]
    ! [Set precision radius to 10 mm]
    WorldAccLim \On := 1;  ! [Set motion acceleration to 1000 mm/s^2 or deg/s^2]
    MoveL [[350, 0, 300], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel200, z10, Tool0\WObj:=WObj0;  ! [Move [50, 0, 0] mm]
    MoveL [[350, 50, 300], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel200, z10, Tool0\WObj:=WObj0;  ! [Move [0, 50, 0] mm]
    MoveL [[300, 50, 300], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel200, z10, Tool0\WObj:=WObj0;  ! [Move [-50, 0, 0] mm]
    MoveL [[300, 0, 300], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel200, z10, Tool0\WObj:=WObj0;  ! [Move [0, -50, 0] mm]
    WorldAccLim \On := 0.5;  ! [Pop settings]
    MoveL [[300, 0, 350], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel50, z5, Tool0\WObj:=WObj0;  ! [Move [0, 0, 50] mm]

  ENDPROC

ENDMODULE
