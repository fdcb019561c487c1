MODULE Machina_Monitor
    ! Machina monitor for ABB IRC5 controllers (second task T_MACHINA_MONITOR, needs option 623-1 Multitasking).
    ! A TCP server on the driver port + 1 that reports the robot state every monitorUpdateInterval seconds as
    ! "$24 x y z q1 q2 q3 q4>" "j1 ... j6>" "e1 ... e6;", and "$26 id code;" when a motion error stops the driver's
    ! task (its error trap). Placeholders are filled by Machina.
    ! Out of band, while the driver's task moves, it takes one-character commands from the host: "P" pause (StopMove: the arm
    ! holds on its path), "R" resume (StartMove), "S" stop (the arm holds, then the driver's task fails the move under way and
    ! drops everything after it), each answered "$28 n;" once done (1 paused, 2 resumed, 3 stopped).
    ! "M" asks which arm this is, answered "$@0 101 3 <GetSysInfo(\RobotType)>;".

    PERS string SERVER_IP := "{{HOSTNAME}}";
    CONST num MONITOR_PORT := {{PORT}};
    PERS bool USE_STRICT := TRUE;
    PERS bool isMachinaDriverAvailable := TRUE;
    PERS num monitorUpdateInterval := {{MONITOR_INTERVAL}};
    ! Id of the driver's motion request being run (set by Machina_Driver before each move).
    PERS num machinaMotionId := 0;
    ! Set by this task on the host's stop; the driver's task has an interrupt on it (IPers) and clears it.
    PERS bool machinaStopRequest := FALSE;
    PERS tooldata cursorTool := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 0.001], [1, 0, 0, 0], 0, 0, 0]];
    PERS wobjdata cursorWObj := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];

    CONST num WAIT_MAX := 8388608;

    VAR socketdev serverSocket;
    VAR socketdev clientSocket;
    VAR intnum motionError;
    ! A failure report the trap left for the main loop, which sends it between two state reports (never inside one).
    VAR string failureReport := "";

    PROC Main()
        IF NOT isMachinaDriverAvailable THEN
            TPWrite "Machina monitor: the Machina driver is not loaded";
            EXIT;
        ENDIF
        ! A motion error stops the motion task before it can say anything: this task reports it for the driver. The trap is
        ! ordered before the first client is awaited: a move that fails before a host watches is kept in failureReport and
        ! sent to the first client that connects.
        IDelete motionError;
        CONNECT motionError WITH MotionErrorTrap;
        IError MOTION_ERR, TYPE_ERR, motionError;
        ServerStart;
        WHILE TRUE DO
            Report;
            Listen;
            WaitTime monitorUpdateInterval;
        ENDWHILE
    ENDPROC

    ! As in the driver: after a lost client only the client socket is closed; the server socket keeps listening (its queue).
    PROC ServerStart()
        SocketClose clientSocket;
        IF SocketGetStatus(serverSocket) <> SOCKET_LISTENING THEN
            SocketClose serverSocket;
            SocketCreate serverSocket;
            SocketBind serverSocket, SERVER_IP, MONITOR_PORT;
            SocketListen serverSocket;
        ENDIF
        SocketAccept serverSocket, clientSocket \Time:=WAIT_MAX;
    ERROR
        IF ERRNO = ERR_SOCK_TIMEOUT THEN
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    ! Pose and joints are read together so they match: the TCP of the driver's current tool in its work object.
    PROC Report()
        VAR jointtarget joints;
        VAR robtarget pose;
        IF failureReport <> "" THEN
            SocketSend clientSocket \Str:=failureReport;
            failureReport := "";
        ENDIF
        joints := CJointT();
        pose := CalcRobT(joints, cursorTool \WObj:=cursorWObj);
        SocketSend clientSocket \Str:="$24 " + NumToStr(pose.trans.x, 3) + " " + NumToStr(pose.trans.y, 3) + " " + NumToStr(pose.trans.z, 3) + " ";
        SocketSend clientSocket \Str:=NumToStr(pose.rot.q1, 4) + " " + NumToStr(pose.rot.q2, 4) + " " + NumToStr(pose.rot.q3, 4) + " " + NumToStr(pose.rot.q4, 4) + ">";
        SocketSend clientSocket \Str:=NumToStr(joints.robax.rax_1, 3) + " " + NumToStr(joints.robax.rax_2, 3) + " " + NumToStr(joints.robax.rax_3, 3) + " ";
        SocketSend clientSocket \Str:=NumToStr(joints.robax.rax_4, 3) + " " + NumToStr(joints.robax.rax_5, 3) + " " + NumToStr(joints.robax.rax_6, 3) + ">";
        SocketSend clientSocket \Str:=AxisText(joints.extax.eax_a) + " " + AxisText(joints.extax.eax_b) + " " + AxisText(joints.extax.eax_c) + " ";
        SocketSend clientSocket \Str:=AxisText(joints.extax.eax_d) + " " + AxisText(joints.extax.eax_e) + " " + AxisText(joints.extax.eax_f) + ";";
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            ServerStart;
            RETURN;
        ENDIF
        TPWrite "Machina monitor: something went wrong";
        IF USE_STRICT THEN
            EXIT;
        ENDIF
        STOP;
    ENDPROC

    ! Commands waiting on the socket (SocketPeek: none, no wait). StopMove and StartMove act on the motion of every motion task
    ! from this task without motion (\AllMotionTasks); the motion stops on its path, where the arm is.
    PROC Listen()
        VAR string commands;
        VAR string c;
        IF SocketPeek(clientSocket) <= 0 THEN
            RETURN;
        ENDIF
        SocketReceive clientSocket \Str:=commands \Time:=1;
        FOR i FROM 1 TO StrLen(commands) DO
            c := StrPart(commands, i, 1);
            IF c = "P" THEN
                StopMove \AllMotionTasks;
                SocketSend clientSocket \Str:="$28 1;";
            ELSEIF c = "R" THEN
                StartMove \AllMotionTasks;
                SocketSend clientSocket \Str:="$28 2;";
            ELSEIF c = "S" THEN
                StopMove \AllMotionTasks;
                machinaStopRequest := TRUE;
                SocketSend clientSocket \Str:="$28 3;";
            ELSEIF c = "M" THEN
                ! Which arm this controller runs (e.g. "IRB 120-3/0.6"): the host learns its model when it connects.
                SocketSend clientSocket \Str:="$@0 101 3 " + GetSysInfo(\RobotType) + ";";
            ENDIF
        ENDFOR
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            ServerStart;
            RETURN;
        ENDIF
        IF ERRNO = ERR_SOCK_TIMEOUT THEN
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! "$26 id code;": the driver's motion request id could not run; code is the event number (domain * 10000 + number,
    ! e.g. 50050 "Position outside reach"). Left for the main loop, so that it never splits a state report.
    TRAP MotionErrorTrap
        VAR trapdata errData;
        VAR errdomain domain;
        VAR num number;
        VAR errtype kind;
        GetTrapData errData;
        ReadErrData errData, domain, number, kind;
        failureReport := "$26 " + NumToStr(machinaMotionId, 0) + " " + NumToStr(domain * 10000 + number, 0) + ";";
    ENDTRAP

    FUNC string AxisText(num value)
        IF value >= 9E9 THEN
            RETURN "9E9";
        ENDIF
        RETURN NumToStr(value, 3);
    ENDFUNC
ENDMODULE
