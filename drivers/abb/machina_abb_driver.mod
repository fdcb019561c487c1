MODULE Machina_Driver
    ! Machina driver for ABB IRC5 controllers (motion task T_ROB1).
    ! A TCP server: reads requests "@id code "text" p1 ... pN;", executes them in order and answers "@id code;"
    ! after each one. A request that cannot run is never acknowledged: "$26 id code;" reports it and the program stops. Protocol: docs/protocol-abb.md in the Machina repository. Placeholders are filled by Machina.

    CONST string DRIVER_VERSION_MAJOR := "1";
    CONST string DRIVER_VERSION_MINOR := "7";
    CONST string DRIVER_VERSION_PATCH := "0";

    PERS string SERVER_IP := "{{HOSTNAME}}";
    CONST num SERVER_PORT := {{PORT}};
    PERS bool USE_STRICT := TRUE;
    PERS bool isMachinaDriverAvailable := TRUE;
    PERS num monitorUpdateInterval := {{MONITOR_INTERVAL}};
    ! Id of the motion request being run, shared with the monitor task: its error trap reports it when a motion error
    ! (event 50050 "Position outside reach" and the rest of the motion domain) stops this task ("$26 id code;").
    PERS num machinaMotionId := 0;
    ! Robot.Stop: set by the monitor task after it held the motion (StopMove); this task's interrupt on it (IPers) clears the
    ! path, fails the request under way ("$26 id 4;") and drops every request after it until the host connects again.
    PERS bool machinaStopRequest := FALSE;
    ! A user error number (1..90) raised from StopTrap into ExecuteNext's error handler.
    CONST errnum ERR_MACHINA_STOP := 77;
    VAR intnum stopInterrupt;
    ! TRUE while ExecuteNext runs a request; TRUE in discarding from a stop until the next client.
    VAR bool executing := FALSE;
    VAR bool discarding := FALSE;
    PERS tooldata cursorTool := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 0.001], [1, 0, 0, 0], 0, 0, 0]];
    PERS wobjdata cursorWObj := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];

    ! Longest wait of a socket call (a RobotWare 5 compatible "forever").
    CONST num WAIT_MAX := 8388608;
    CONST num BUFFER_SIZE := 1000;
    ! Stop reading while fewer free slots remain: one 80-character chunk holds at most 16 requests.
    CONST num READ_MARGIN := 20;
    ! The characters that end a token outside quoted text (space, tab, line feed, carriage return, ';', '"', '@').
    CONST string TOKEN_ENDS := " \09\0A\0D;""@";
    ! The characters of a request of numbers alone, "@id code p1 ... pN;" up to its ';' (ReadWhole).
    CONST string NUMBER_REQUEST := "@0123456789 .+-Ee";

    RECORD MachinaRequest
        num id;
        num code;
        string s1;
        num p1;
        num p2;
        num p3;
        num p4;
        num p5;
        num p6;
        num p7;
        num p8;
        num p9;
        num p10;
        num p11;
    ENDRECORD

    VAR MachinaRequest requests{BUFFER_SIZE};
    VAR num readIndex := 1;
    VAR num writeIndex := 1;
    VAR num requestCount := 0;

    ! Parser state, kept between socket reads so a request may be split anywhere.
    VAR MachinaRequest parsing;
    VAR string token := "";
    VAR num field := 0;
    VAR bool inText := FALSE;
    VAR bool corrupt := FALSE;
    ! The start of a request of numbers that the last chunk ended in, kept for the next one (JoinPending); "" when none.
    VAR string pending := "";
    ! The numbers of the request ReadWhole reads (id, code, p1..p11, and one more that shows a 12th parameter). Every slot above
    ! valuesUsed holds 0, so that only the slots an earlier, longer request used are cleared for a shorter one.
    VAR num values{14};
    VAR num valuesUsed := 14;

    VAR socketdev serverSocket;
    VAR socketdev clientSocket;
    VAR bool clientConnected := FALSE;

    ! Progress reported in the handshake ($25), so that a reconnecting host sends nothing twice: the id of the last request
    ! executed and of the last one received (0 until then). Plain VARs: they start again at 0 when the program restarts.
    VAR num lastExecutedId := 0;
    VAR num lastReceivedId := 0;

    VAR robtarget cursorTarget;
    VAR jointtarget cursorJoints;
    VAR speeddata cursorSpeed;
    VAR zonedata cursorZone;
    ! The orientation of the next arc's through point (request 31, sent just before its MoveC, 30); without one, the current.
    VAR orient arcThroughRot;
    VAR bool arcThroughGiven := FALSE;
    VAR signaldo outDigital;
    VAR signalao outAnalog;
    VAR signaldi inDigital;
    VAR signalai inAnalog;

    PROC Main()
        TPErase;
        TPWrite "Machina driver " + DRIVER_VERSION_MAJOR + "." + DRIVER_VERSION_MINOR + "." + DRIVER_VERSION_PATCH;
        ConfJ \Off;
        ConfL \Off;
        CirPathMode \PathFrame;
        InitializeState;
        machinaStopRequest := FALSE;
        IDelete stopInterrupt;
        CONNECT stopInterrupt WITH StopTrap;
        IPers machinaStopRequest, stopInterrupt;
        ServerStart;
        WHILE TRUE DO
            IF requestCount = 0 THEN
                ReadRequests;
            ENDIF
            WHILE requestCount > 0 DO
                ExecuteNext;
            ENDWHILE
        ENDWHILE
    ENDPROC

    PROC InitializeState()
        readIndex := 1;
        writeIndex := 1;
        requestCount := 0;
        ResetParser;
        cursorTool := tool0;
        cursorWObj := wobj0;
        cursorTarget := CRobT(\Tool:=tool0 \WObj:=wobj0);
        cursorTarget.robconf := [0, 0, 0, 0];
        cursorJoints := CJointT();
        cursorSpeed := v20;
        cursorZone := z5;
        arcThroughGiven := FALSE;
        isMachinaDriverAvailable := TRUE;
    ENDPROC

    ! Waits for a client that takes the handshake.
    PROC ServerStart()
        clientConnected := FALSE;
        WHILE NOT clientConnected DO
            AcceptClient;
        ENDWHILE
    ENDPROC

    ! After a lost client the server socket still listens: only the client socket is closed, so that a host reconnecting while
    ! this task ran its buffer waits in the listen queue (closing the server socket would reset that connection). A client that
    ! left before its handshake was written (a host that gave up waiting in that queue) is closed, and the next one accepted.
    PROC AcceptClient()
        SocketClose clientSocket;
        IF SocketGetStatus(serverSocket) <> SOCKET_LISTENING THEN
            SocketClose serverSocket;
            SocketCreate serverSocket;
            SocketBind serverSocket, SERVER_IP, SERVER_PORT;
            SocketListen serverSocket;
        ENDIF
        TPWrite "Machina driver waiting for a client on " + SERVER_IP + ":" + NumToStr(SERVER_PORT, 0);
        SocketAccept serverSocket, clientSocket \Time:=WAIT_MAX;
        discarding := FALSE;
        arcThroughGiven := FALSE;
        TPWrite "Machina client connected";
        ResetParser;
        SendHandshake;
        clientConnected := TRUE;
    ERROR
        IF ERRNO = ERR_SOCK_TIMEOUT THEN
            RETRY;
        ELSEIF ERRNO = ERR_SOCK_CLOSED THEN
            TPWrite "Machina client left before its handshake";
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    PROC SendHandshake()
        VAR robtarget flange;
        VAR jointtarget joints;
        flange := CRobT(\Tool:=tool0 \WObj:=wobj0);
        joints := CJointT();
        SocketSend clientSocket \Str:="$20 " + DRIVER_VERSION_MAJOR + " " + DRIVER_VERSION_MINOR + " " + DRIVER_VERSION_PATCH + ";";
        SocketSend clientSocket \Str:="$21 " + NumToStr(flange.trans.x, 3) + " " + NumToStr(flange.trans.y, 3) + " " + NumToStr(flange.trans.z, 3) + " ";
        SocketSend clientSocket \Str:=NumToStr(flange.rot.q1, 4) + " " + NumToStr(flange.rot.q2, 4) + " " + NumToStr(flange.rot.q3, 4) + " " + NumToStr(flange.rot.q4, 4) + ";";
        SocketSend clientSocket \Str:="$22 " + NumToStr(joints.robax.rax_1, 3) + " " + NumToStr(joints.robax.rax_2, 3) + " " + NumToStr(joints.robax.rax_3, 3) + " ";
        SocketSend clientSocket \Str:=NumToStr(joints.robax.rax_4, 3) + " " + NumToStr(joints.robax.rax_5, 3) + " " + NumToStr(joints.robax.rax_6, 3) + ";";
        SocketSend clientSocket \Str:="$23 " + AxisText(flange.extax.eax_a) + " " + AxisText(flange.extax.eax_b) + " " + AxisText(flange.extax.eax_c) + " ";
        SocketSend clientSocket \Str:=AxisText(flange.extax.eax_d) + " " + AxisText(flange.extax.eax_e) + " " + AxisText(flange.extax.eax_f) + ";";
        SocketSend clientSocket \Str:="$25 " + NumToStr(lastExecutedId, 0) + " " + NumToStr(lastReceivedId, 0) + ";";
    ENDPROC

    FUNC string AxisText(num value)
        IF value >= 9E9 THEN
            RETURN "9E9";
        ENDIF
        RETURN NumToStr(value, 3);
    ENDFUNC

    ! Reads socket chunks until at least one complete request is buffered (or the buffer is nearly full).
    PROC ReadRequests()
        VAR string chunk;
        WHILE requestCount = 0 DO
            SocketReceive clientSocket \Str:=chunk \Time:=WAIT_MAX;
            ParseChunk chunk;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_SOCK_TIMEOUT THEN
            RETRY;
        ELSEIF ERRNO = ERR_SOCK_CLOSED THEN
            clientConnected := FALSE;
            TPWrite "Machina client disconnected";
            ServerStart;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    ! Feeds a chunk to the parser. Requests of numbers alone ("@id code p1 ... pN;", single spaces) are read whole (ReadWhole), a
    ! request the chunk ends in joined to the start of the next chunk (JoinPending); everything else goes to the token parser
    ! (ParseRuns) from its '@'. Both read the same requests and make the same complaints.
    PROC ParseChunk(string chunk)
        VAR num runStart := 1;
        IF pending <> "" THEN
            JoinPending chunk, runStart;
        ENDIF
        ReadWhole chunk, runStart;
        IF runStart <= StrLen(chunk) THEN
            ParseRuns chunk, runStart;
        ENDIF
    ENDPROC

    ! Reads whole requests from runStart on while the parser is between requests, each "@id code p1 ... pN;" of numbers apart
    ! by single spaces: a StrToVal per number, and the request buffered at once. It stops at anything else (a text, other
    ! whitespace, an empty or corrupt number, more than 11 parameters, an id alone), which the token parser then reads from
    ! that '@' as before; runStart is then where it stopped. A request of numbers that the chunk ends in waits in pending.
    PROC ReadWhole(string chunk, INOUT num runStart)
        VAR num chunkLength;
        VAR num requestEnd;
        VAR num position;
        VAR num gap;
        VAR num n;
        IF field <> 0 OR token <> "" OR inText OR corrupt THEN
            RETURN;
        ENDIF
        chunkLength := StrLen(chunk);
        WHILE runStart <= chunkLength DO
            requestEnd := StrFind(chunk, runStart, NUMBER_REQUEST \NotInSet);
            IF requestEnd > chunkLength OR StrPart(chunk, runStart, 1) <> "@" THEN
                ! A request that starts here and goes on in the next chunk waits in pending.
                IF StrPart(chunk, runStart, 1) = "@" THEN
                    pending := StrPart(chunk, runStart, requestEnd - runStart);
                    runStart := requestEnd;
                ENDIF
                RETURN;
            ENDIF
            IF StrPart(chunk, requestEnd, 1) <> ";" OR StrMatch(chunk, runStart, "  ") < requestEnd OR StrPart(chunk, runStart + 1, 1) = " " THEN
                RETURN;
            ENDIF
            n := 0;
            position := runStart + 1;
            WHILE position < requestEnd DO
                gap := StrFind(chunk, position, " ;");
                n := n + 1;
                IF n > 13 OR NOT StrToVal(StrPart(chunk, position, gap - position), values{n}) THEN
                    valuesUsed := 14;
                    RETURN;
                ENDIF
                position := gap + 1;
            ENDWHILE
            ! valuesUsed is 2 or more: a request of fewer numbers (an id alone) is never buffered here.
            IF n <> valuesUsed THEN
                IF n < 2 THEN
                    RETURN;
                ENDIF
                WHILE valuesUsed > n DO
                    values{valuesUsed} := 0;
                    valuesUsed := valuesUsed - 1;
                ENDWHILE
                valuesUsed := n;
            ENDIF
            ! Buffered as Buffer does, without its call and the copy of its parameter, and without its check for a full buffer: a
            ! chunk is read only into an empty buffer (ReadRequests), and one chunk and the request joined to it hold at most 17.
            requests{writeIndex} := [values{1}, values{2}, "", values{3}, values{4}, values{5}, values{6}, values{7}, values{8}, values{9}, values{10}, values{11}, values{12}, values{13}];
            writeIndex := writeIndex MOD BUFFER_SIZE + 1;
            requestCount := requestCount + 1;
            IF values{1} > 0 AND NOT discarding THEN
                lastReceivedId := values{1};
            ENDIF
            runStart := requestEnd + 1;
        ENDWHILE
    ENDPROC

    ! The request the last chunk ended in (pending) and this chunk's characters up to its ';' are read whole when they make one
    ! request of numbers of at most 80 characters; otherwise the token parser reads pending first, then the chunk. runStart is
    ! where the chunk goes on.
    PROC JoinPending(string chunk, INOUT num runStart)
        VAR string started;
        VAR num requestEnd;
        VAR num joinedStart := 1;
        started := pending;
        pending := "";
        requestEnd := StrFind(chunk, 1, NUMBER_REQUEST \NotInSet);
        IF requestEnd > StrLen(chunk) OR StrLen(started) + requestEnd > 80 THEN
            ParseRuns started, 1;
            RETURN;
        ENDIF
        started := started + StrPart(chunk, 1, requestEnd);
        ReadWhole started, joinedStart;
        IF joinedStart <= StrLen(started) THEN
            ParseRuns started, joinedStart;
        ENDIF
        runStart := requestEnd + 1;
    ENDPROC

    ! The token parser: takes a run of characters at a time: StrFind finds the next character that ends a token (a space, tab,
    ! line feed, carriage return, ';', '"' or '@'; in quoted text only the closing '"'), and the run before it is added to the
    ! token at once. A request may start in one chunk and end in another; a token keeps its first 80 characters. After each
    ! request, ReadWhole reads on.
    PROC ParseRuns(string chunk, num first)
        VAR num runStart;
        VAR num chunkLength;
        VAR num runEnd;
        VAR string c;
        runStart := first;
        chunkLength := StrLen(chunk);
        WHILE runStart <= chunkLength DO
            IF inText THEN
                runEnd := StrFind(chunk, runStart, """");
            ELSE
                runEnd := StrFind(chunk, runStart, TOKEN_ENDS);
            ENDIF
            IF runEnd > runStart THEN
                IF StrLen(token) + runEnd - runStart <= 80 THEN
                    token := token + StrPart(chunk, runStart, runEnd - runStart);
                ELSEIF StrLen(token) < 80 THEN
                    token := token + StrPart(chunk, runStart, 80 - StrLen(token));
                ENDIF
            ENDIF
            IF runEnd > chunkLength THEN
                RETURN;
            ENDIF
            ! A space, the commonest end of a token, first (in quoted text the run ends at '"').
            c := StrPart(chunk, runEnd, 1);
            IF c = " " THEN
                FinishToken;
            ELSEIF inText THEN
                inText := FALSE;
                parsing.s1 := token;
                token := "";
            ELSEIF c = ";" THEN
                FinishToken;
                FinishRequest;
                runStart := runEnd + 1;
                ReadWhole chunk, runStart;
                runEnd := runStart - 1;
            ELSEIF c = """" THEN
                FinishToken;
                inText := TRUE;
            ELSEIF c = "@" THEN
                IF field = 0 AND token = "" THEN
                    field := -1;
                ELSEIF StrLen(token) < 80 THEN
                    token := token + c;
                ENDIF
            ELSE
                FinishToken;
            ENDIF
            runStart := runEnd + 1;
        ENDWHILE
    ENDPROC

    ! Stores the token just read: id (after @), then code, then numeric parameters p1..p11.
    PROC FinishToken()
        VAR num value;
        IF token = "" THEN
            RETURN;
        ENDIF
        IF NOT StrToVal(token, value) THEN
            TPWrite token;
            Complain "received corrupt value";
            corrupt := TRUE;
        ELSEIF field > 11 THEN
            Complain "more than 11 parameters";
            corrupt := TRUE;
        ELSEIF field >= 1 THEN
            TEST field
            CASE 1:
                parsing.p1 := value;
            CASE 2:
                parsing.p2 := value;
            CASE 3:
                parsing.p3 := value;
            CASE 4:
                parsing.p4 := value;
            CASE 5:
                parsing.p5 := value;
            CASE 6:
                parsing.p6 := value;
            CASE 7:
                parsing.p7 := value;
            CASE 8:
                parsing.p8 := value;
            CASE 9:
                parsing.p9 := value;
            CASE 10:
                parsing.p10 := value;
            DEFAULT:
                parsing.p11 := value;
            ENDTEST
            field := field + 1;
        ELSEIF field = 0 THEN
            parsing.code := value;
            field := 1;
        ELSE
            parsing.id := value;
            field := 0;
        ENDIF
        token := "";
    ENDPROC

    PROC FinishRequest()
        IF field >= 1 AND NOT corrupt AND NOT inText THEN
            Buffer parsing;
        ELSEIF field <> 0 OR corrupt THEN
            Complain "received corrupt request";
        ENDIF
        ResetParser;
    ENDPROC

    ! Puts a request read in the buffer (or complains that the buffer is full).
    PROC Buffer(MachinaRequest request)
        IF requestCount >= BUFFER_SIZE THEN
            Complain "request buffer full";
            RETURN;
        ENDIF
        requests{writeIndex} := request;
        writeIndex := writeIndex MOD BUFFER_SIZE + 1;
        requestCount := requestCount + 1;
        ! While discarding after a stop, what still arrives is dropped unrun: it is not counted received either, so the next
        ! client's handshake ($25) shows an idle driver, not requests it will never run.
        IF request.id > 0 AND NOT discarding THEN
            lastReceivedId := request.id;
        ENDIF
    ENDPROC

    ! The parameters a request does not give read as 0.
    PROC ResetParser()
        parsing := [0, 0, "", 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];
        token := "";
        field := 0;
        inText := FALSE;
        corrupt := FALSE;
        pending := "";
    ENDPROC

    ! Reports a protocol problem on the pendant; in strict mode the program stops (the host sees no more acks).
    PROC Complain(string message)
        TPWrite "Machina: " + message;
        IF USE_STRICT THEN
            EXIT;
        ENDIF
    ENDPROC

    PROC ExecuteNext()
        VAR MachinaRequest r;
        r := requests{readIndex};
        readIndex := readIndex MOD BUFFER_SIZE + 1;
        requestCount := requestCount - 1;
        IF discarding THEN
            RETURN;
        ENDIF
        executing := TRUE;
        ! Before each move (1, 2, 3, 30): a speed of 0 would never end, so the driver reports "$26 id 1;" and stops instead of
        ! starting it; otherwise the move's id is shared with the monitor, whose trap reports a motion error of this move. The
        ! target's robconf is [0, 0, 0, 0] from InitializeState on: a move sets its trans and rot.
        TEST r.code
        CASE 1:
            IF cursorSpeed.v_tcp <= 0 THEN
                Fail r, 1;
            ENDIF
            machinaMotionId := r.id;
            cursorTarget.trans := [r.p1, r.p2, r.p3];
            cursorTarget.rot := [r.p4, r.p5, r.p6, r.p7];
            MoveL cursorTarget, cursorSpeed, cursorZone, cursorTool \WObj:=cursorWObj;
        CASE 2:
            IF cursorSpeed.v_tcp <= 0 THEN
                Fail r, 1;
            ENDIF
            machinaMotionId := r.id;
            cursorTarget.trans := [r.p1, r.p2, r.p3];
            cursorTarget.rot := [r.p4, r.p5, r.p6, r.p7];
            MoveJ cursorTarget, cursorSpeed, cursorZone, cursorTool \WObj:=cursorWObj;
        CASE 3:
            IF cursorSpeed.v_tcp <= 0 THEN
                Fail r, 1;
            ENDIF
            machinaMotionId := r.id;
            cursorJoints.robax := [r.p1, r.p2, r.p3, r.p4, r.p5, r.p6];
            MoveAbsJ cursorJoints, cursorSpeed, cursorZone, cursorTool \WObj:=cursorWObj;
        CASE 4:
            cursorSpeed := [r.p1, OrDefault(r.p2, r.p1), OrDefault(r.p3, r.p1), OrDefault(r.p4, r.p1)];
        CASE 5:
            IF r.p1 = 0 THEN
                cursorZone := fine;
            ELSE
                cursorZone := [FALSE, r.p1, OrDefault(r.p2, 1.5 * r.p1), OrDefault(r.p3, 1.5 * r.p1), OrDefault(r.p4, 0.1 * r.p1), OrDefault(r.p5, 1.5 * r.p1), OrDefault(r.p6, 0.1 * r.p1)];
            ENDIF
        CASE 6:
            WaitTime r.p1;
        CASE 7:
            TPWrite r.s1;
        CASE 8:
            cursorTool := [TRUE, [[r.p1, r.p2, r.p3], [r.p4, r.p5, r.p6, r.p7]], [OrDefault(r.p8, 1), [OrDefault(r.p9, 0.5 * r.p1), OrDefault(r.p10, 0.5 * r.p2), OrDefault(r.p11, 0.5 * r.p3)], [1, 0, 0, 0], 0, 0, 0]];
        CASE 9:
            cursorTool := tool0;
        CASE 10:
            AliasIO r.s1, outDigital;
            IF r.p1 = 0 THEN
                SetDO outDigital, 0;
            ELSE
                SetDO outDigital, 1;
            ENDIF
        CASE 11:
            AliasIO r.s1, outAnalog;
            SetAO outAnalog, r.p1;
        CASE 12:
            cursorTarget.extax := [r.p1, r.p2, r.p3, r.p4, r.p5, r.p6];
            cursorJoints.extax := [r.p1, r.p2, r.p3, r.p4, r.p5, r.p6];
        CASE 13:
            ! Acceleration in m/s2 (the host converts from mm/s2).
            IF r.p1 > 0 THEN
                WorldAccLim \On:=r.p1;
            ELSE
                WorldAccLim \Off;
            ENDIF
        CASE 14:
            IF r.p1 = 0 THEN
                SingArea \Off;
            ELSE
                SingArea \Wrist;
            ENDIF
        CASE 15:
            cursorTarget.extax := [r.p1, r.p2, r.p3, r.p4, r.p5, r.p6];
        CASE 16:
            cursorJoints.extax := [r.p1, r.p2, r.p3, r.p4, r.p5, r.p6];
        CASE 17:
            TPWrite "Machina custom action request" \Num:=r.p1;
        CASE 18:
            cursorWObj := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[r.p1, r.p2, r.p3], [r.p4, r.p5, r.p6, r.p7]]];
        CASE 19:
            cursorWObj := wobj0;
        CASE 20:
            ! Wait for a digital input; with a time limit (s), ERR_WAIT_MAXTIME is reported as failure code 3.
            AliasIO r.s1, inDigital;
            IF r.p2 > 0 THEN
                WaitDI inDigital, r.p1 \MaxTime:=r.p2;
            ELSE
                WaitDI inDigital, r.p1;
            ENDIF
        CASE 21:
            ! Read a digital input: "$27 id value;" just before the acknowledgement.
            AliasIO r.s1, inDigital;
            SendIfConnected "$27 " + NumToStr(r.id, 0) + " " + NumToStr(DInput(inDigital), 0) + ";";
        CASE 22:
            ! Read an analog input: "$27 id value;" just before the acknowledgement.
            AliasIO r.s1, inAnalog;
            SendIfConnected "$27 " + NumToStr(r.id, 0) + " " + NumToStr(AInput(inAnalog), 6) + ";";
        CASE 30:
            IF cursorSpeed.v_tcp <= 0 THEN
                Fail r, 1;
            ENDIF
            machinaMotionId := r.id;
            ! The through point has the orientation request 31 gave (what a compiled MoveC's CirPoint has), else the current one.
            IF NOT arcThroughGiven THEN
                arcThroughRot := CRobT(\Tool:=cursorTool \WObj:=cursorWObj).rot;
            ENDIF
            arcThroughGiven := FALSE;
            cursorTarget := [[r.p1, r.p2, r.p3], [r.p4, r.p5, r.p6, r.p7], [0, 0, 0, 0], cursorTarget.extax];
            MoveC [[r.p8, r.p9, r.p10], arcThroughRot, [0, 0, 0, 0], cursorTarget.extax], cursorTarget, cursorSpeed, cursorZone, cursorTool \WObj:=cursorWObj;
        CASE 31:
            arcThroughRot := [r.p1, r.p2, r.p3, r.p4];
            arcThroughGiven := TRUE;
        CASE 100:
            Acknowledge r;
            SocketClose clientSocket;
            SocketClose serverSocket;
            isMachinaDriverAvailable := FALSE;
            TPWrite "Machina driver stopped by the host";
            EXIT;
        CASE 101:
            IF r.p1 = 2 THEN
                SendIfConnected "$@" + NumToStr(r.id, 0) + " 101 2 " + SERVER_IP + " " + NumToStr(SERVER_PORT, 0) + ";";
            ELSE
                SendIfConnected "$@" + NumToStr(r.id, 0) + " 101 1 " + DRIVER_VERSION_MAJOR + "." + DRIVER_VERSION_MINOR + "." + DRIVER_VERSION_PATCH + ";";
            ENDIF
        CASE 103:
            IF r.p1 > 0 THEN
                monitorUpdateInterval := r.p1;
            ENDIF
        DEFAULT:
            TPWrite "Machina: don't understand action code " + NumToStr(r.code, 0);
        ENDTEST
        executing := FALSE;
        Acknowledge r;
    ERROR
        IF ERRNO = ERR_MACHINA_STOP THEN
            executing := FALSE;
            TPWrite "Machina: stopped by the host";
            SendIfConnected "$26 " + NumToStr(r.id, 0) + " 4;";
            DropRequests;
            RETURN;
        ENDIF
        IF ERRNO = ERR_ALIASIO_DEF OR ERRNO = ERR_NO_ALIASIO_DEF THEN
            TPWrite "Machina: could not find signal";
            TPWrite r.s1;
            IF USE_STRICT THEN
                EXIT;
            ENDIF
            STOP;
        ENDIF
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            Fail r, 3;
        ENDIF
        RAISE;
    ENDPROC

    ! Robot.Stop (see machinaStopRequest): the path is cleared and motion allowed again, then the request under way fails through
    ! ExecuteNext's error handler (an error raised by a trap's error handler goes to the routine that was running); when no
    ! request runs, what is buffered is dropped.
    TRAP StopTrap
        IF NOT machinaStopRequest THEN
            RETURN;
        ENDIF
        machinaStopRequest := FALSE;
        ClearPath;
        StartMove;
        IF executing THEN
            RAISE ERR_MACHINA_STOP;
        ENDIF
        DropRequests;
    ERROR
        RAISE;
    ENDTRAP

    ! Forgets every buffered request and ignores what still arrives until the next client: nothing after a stop runs.
    PROC DropRequests()
        requestCount := 0;
        readIndex := writeIndex;
        lastReceivedId := lastExecutedId;
        discarding := TRUE;
    ENDPROC

    ! Reports that request r could not run ("$26 id code;", never acknowledged) and ends the program: nothing after it runs.
    PROC Fail(MachinaRequest r, num code)
        TPWrite "Machina: request " + NumToStr(r.id, 0) + " failed, code " + NumToStr(code, 0);
        SendIfConnected "$26 " + NumToStr(r.id, 0) + " " + NumToStr(code, 0) + ";";
        isMachinaDriverAvailable := FALSE;
        EXIT;
    ENDPROC

    FUNC num OrDefault(num value, num fallback)
        IF value = 0 THEN
            RETURN fallback;
        ENDIF
        RETURN value;
    ENDFUNC

    ! Acknowledges once per request, after it returned: "@id code;" or "code;" for id 0. It sends as SendIfConnected does (one
    ! routine call less per request); a request with an id, to a connected host, takes one condition, one assignment and the send.
    PROC Acknowledge(MachinaRequest r)
        IF NOT clientConnected THEN
            IF r.id > 0 THEN
                lastExecutedId := r.id;
            ENDIF
        ELSEIF r.id > 0 THEN
            lastExecutedId := r.id;
            SocketSend clientSocket \Str:="@" + NumToStr(r.id, 0) + " " + NumToStr(r.code, 0) + ";";
        ELSEIF r.id = 0 THEN
            SocketSend clientSocket \Str:=NumToStr(r.code, 0) + ";";
        ELSE
            SocketSend clientSocket \Str:="@" + NumToStr(r.id, 0) + " " + NumToStr(r.code, 0) + ";";
        ENDIF
    ERROR
        LostSend ERRNO;
        TRYNEXT;
    ENDPROC

    PROC SendIfConnected(string message)
        IF NOT clientConnected THEN
            RETURN;
        ENDIF
        SocketSend clientSocket \Str:=message;
    ERROR
        LostSend ERRNO;
        TRYNEXT;
    ENDPROC

    ! From the ERROR handler of a send that failed with sendError: reports it; a closed socket is a lost client.
    PROC LostSend(errnum sendError)
        IF sendError = ERR_SOCK_CLOSED THEN
            clientConnected := FALSE;
            TPWrite "Machina: acknowledgement lost, client disconnected";
            RETURN;
        ENDIF
        TPWrite "Machina: could not send an acknowledgement";
    ENDPROC
ENDMODULE
