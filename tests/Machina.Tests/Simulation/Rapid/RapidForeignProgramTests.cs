using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// What RAPID written by other people needs of the twin (issue 42), each in a small program of our own: predefined constants and
/// error numbers, error lists, UNDO, ExitCycle, the error-log instructions, raw bytes and raw sockets, data by name, semaphores,
/// WaitUntil, and tasks that share PERS data with labelled pendant lines.
/// </summary>
public class RapidForeignProgramTests
{
    private static RapidTwinController Run(string body, string data = "", RapidProgramState expected = RapidProgramState.Finished)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        RapidProgramState state = twin.Run();
        Assert.True(expected == state, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void PredefinedConstants_WaitMaxModesAndErrorNumbers_AreKnown_AndAProgramMayHideThem()
    {
        RapidTwinController twin = Run(
            """
              TPWrite "wait " \Num:=WAIT_MAX;
              TPWrite "auto " \Bool:=OpMode() = OP_AUTO;
              TPWrite "cycle " \Bool:=RunMode() = RUN_CONT_CYCLE;
              TPWrite "distinct " \Bool:=ERR_SYM_ACCESS <> ERR_SOCK_TIMEOUT AND ERR_RCVDATA <> ERR_SYM_ACCESS;
              TPWrite "dint " \Num:=DINT;
              TPWrite "own " \Num:=STR_DIGIT;
            """,
            "PERS num STR_DIGIT := 7;");

        Assert.Equal(["wait 8388608", "auto TRUE", "cycle TRUE", "distinct TRUE", "dint -4", "own 7"], twin.Pendant.Lines);
    }

    [Fact]
    public void ErrorList_TakesOnlyItsErrors_AndUndoRunsWhenAnErrorLeavesTheRoutine()
    {
        RapidTwinController twin = Run(
            """
              Outer;
              TPWrite "after";
            ERROR
              TPWrite "main takes " \Bool:=ERRNO = ERR_DIVZERO;
              TRYNEXT;
            """,
            """
            VAR num zero := 0;
            PROC Outer()
              Inner;
              TPWrite "not here";
            ERROR (ERR_SOCK_TIMEOUT, ERR_WAIT_MAXTIME)
              TPWrite "outer must not take it";
            UNDO
              TPWrite "undo outer";
            ENDPROC
            PROC Inner()
              VAR num x;
              x := 1 / zero;
            UNDO
              TPWrite "undo inner";
            ENDPROC
            PROC Unused()
              TPWrite "x";
            ERROR (LONG_JMP_ALL_ERR)
              RETURN;
            ENDPROC
            """);

        Assert.Equal(["undo inner", "undo outer", "main takes TRUE", "after"], twin.Pendant.Lines);
    }

    [Fact]
    public void ExitCycle_StartsMainAgain_WithTheDataKept()
    {
        RapidTwinController twin = Run(
            """
              Incr cycles;
              TPWrite "cycle " \Num:=cycles;
              IF cycles < 3 ExitCycle;
              TPWrite "done";
            """,
            "VAR num cycles := 0;");

        Assert.Equal(["cycle 1", "cycle 2", "cycle 3", "done"], twin.Pendant.Lines);
    }

    [Fact]
    public void ErrWriteErrLogBookErrNoSkipWarn_WriteTheEventLog_AndABookedNumberIsRaisedAndTaken()
    {
        RapidTwinController twin = Run(
            """
              BookErrNo ERR_MINE;
              ErrWrite \W, "Header", "Reason" \RL2:="more";
              ErrLog 4800, "a", 2, "c", "d", "e";
              SkipWarn;
              RAISE ERR_MINE;
            ERROR
              TPWrite "mine " \Bool:=ERRNO = ERR_MINE AND ERR_MINE > 0;
              TRYNEXT;
            """,
            "VAR errnum ERR_MINE := -1;");

        Assert.Equal(["Event (warning, ErrWrite): Header: Reason more", "Event 4800 (error, ErrLog): a, 2, c, d, e", "mine TRUE"], twin.Pendant.Lines);
    }

    [Fact]
    public void RawBytes_PackLittleEndianUnlessNetwork_UnpackCopyClearAndLength()
    {
        RapidTwinController twin = Run(
            """
              VAR rawbytes raw;
              VAR rawbytes copy;
              VAR num n;
              VAR string s;
              PackRawBytes 258, raw, 1 \IntX:=DINT;
              PackRawBytes 258, raw \Network, 5 \IntX:=UINT;
              PackRawBytes 1.5, raw, 7 \Float4;
              PackRawBytes "AB", raw, 11 \ASCII;
              PackRawBytes -2, raw, 13 \IntX:=SINT;
              TPWrite "len " \Num:=RawBytesLen(raw);
              UnpackRawBytes raw, 1, n \IntX:=UDINT;
              TPWrite "le " \Num:=n;
              UnpackRawBytes raw, 1, n \IntX:=USINT;
              TPWrite "first byte " \Num:=n;
              UnpackRawBytes raw \Network, 5, n \IntX:=UINT;
              TPWrite "be " \Num:=n;
              UnpackRawBytes raw, 5, n \IntX:=USINT;
              TPWrite "high byte first " \Num:=n;
              UnpackRawBytes raw, 7, n \Float4;
              TPWrite "float " \Num:=n;
              UnpackRawBytes raw, 13, n \IntX:=SINT;
              TPWrite "signed " \Num:=n;
              CopyRawBytes raw, 11, copy, 1 \NoOfBytes:=2;
              UnpackRawBytes copy, 1, s \ASCII:=2;
              TPWrite "copied " + s \Num:=RawBytesLen(copy);
              ClearRawBytes raw \FromIndex:=5;
              TPWrite "cleared " \Num:=RawBytesLen(raw);
            """);

        Assert.Equal(["len 13", "le 258", "first byte 2", "be 258", "high byte first 1", "float 1.5", "signed -2", "copied AB2", "cleared 4"], twin.Pendant.Lines);
    }

    [Fact]
    public void GetDataValSetDataVal_ByName_AndAnUnknownNameRaisesErrSymAccess()
    {
        RapidTwinController twin = Run(
            """
              VAR num got;
              GetDataVal "speed", got;
              TPWrite "got " \Num:=got;
              SetDataVal "speed", 42;
              TPWrite "set " \Num:=speed;
              GetDataVal "nothing", got;
              TPWrite "next";
            ERROR
              TPWrite "sym access " \Bool:=ERRNO = ERR_SYM_ACCESS;
              TRYNEXT;
            """,
            "VAR num speed := 7;");

        Assert.Equal(["got 7", "set 42", "sym access TRUE", "next"], twin.Pendant.Lines);
    }

    [Fact]
    public void TestAndSetWaitUntilIncrOffsDim_RunAsTheManualSays()
    {
        RapidTwinController twin = Run(
            """
              VAR bool late;
              VAR robtarget p := [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              TPWrite "first " \Bool:=TestAndSet(flag);
              TPWrite "second " \Bool:=TestAndSet(flag);
              WaitUntil flag \MaxTime:=1;
              WaitUntil NOT flag \MaxTime:=0.2 \TimeFlag:=late;
              TPWrite "late " \Bool:=late;
              Decr count;
              Add count, 10;
              p := Offs(p, 10, 20, 30);
              TPWrite ValToStr(p.trans) \Num:=Dim(values, 1) + count;
              WaitUntil NOT flag \MaxTime:=0.1;
            ERROR
              TPWrite "timeout " \Bool:=ERRNO = ERR_WAIT_MAXTIME;
            """,
            "VAR bool flag := FALSE;\nVAR num count := 0;\nVAR num values{4};");

        Assert.Equal(["first TRUE", "second FALSE", "late TRUE", "[11,22,33]13", "timeout TRUE"], twin.Pendant.Lines);
    }

    [Fact]
    public void SocketRawData_ReceivesBytesAndSendsThemBack_AndClientAddressIsTheClients()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        var twin = new RapidTwinController();
        twin.Reserve(listener);
        twin.Load(("S.mod", $$"""
            MODULE S
              VAR socketdev server;
              VAR socketdev client;
              VAR rawbytes raw;
              VAR string address;
              VAR num n;
              PROC main()
                SocketCreate server;
                SocketBind server, "127.0.0.1", {{port}};
                SocketListen server;
                SocketAccept server, client \ClientAddress:=address \Time:=WAIT_MAX;
                TPWrite "from " + address;
                SocketReceive client \RawData:=raw \ReadNoOfBytes:=4 \Time:=10;
                UnpackRawBytes raw \Network, 1, n \IntX:=DINT;
                TPWrite "got " \Num:=n;
                ClearRawBytes raw;
                PackRawBytes n + 1, raw \Network, 1 \IntX:=DINT;
                SocketSend client \RawData:=raw;
                SocketClose client;
                SocketClose server;
              ENDPROC
            ENDMODULE
            """));

        twin.StartTasks();
        using var client = new TcpClient();
        client.Connect(IPAddress.Loopback, port);
        NetworkStream stream = client.GetStream();
        stream.Write([0, 0, 1, 2]); // 258, big-endian, in one write: \ReadNoOfBytes takes what has arrived, at most four
        var answer = new byte[4];
        stream.ReadTimeout = 10_000;
        stream.ReadExactly(answer);
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(10));

        Assert.True(joined);
        Assert.Equal(new byte[] { 0, 0, 1, 3 }, answer);
        Assert.Equal(["from 127.0.0.1", "got 258"], twin.Pendant.Lines);
    }

    [Fact]
    public void Tasks_SharePers_AndLabelTheirPendantLines_WhenSeveralRun()
    {
        var twin = new RapidTwinController { LabelsTasks = true };
        twin.Task().Load([("A.sys", "MODULE A(SYSMODULE)\n  PERS num handshake := 0;\nENDMODULE"),
            ("M.mod", "MODULE M\n  PERS num handshake;\n  PROC main()\n    WaitUntil handshake = 1 \\MaxTime:=10;\n    TPWrite \"seen\";\n    handshake := 2;\n  ENDPROC\nENDMODULE")]);
        twin.Task("T_BACK").Load([("B.mod", "MODULE B\n  PERS num handshake := 0;\n  PROC main()\n    handshake := 1;\n    WaitUntil handshake = 2 \\MaxTime:=10;\n    TPWrite \"done\";\n  ENDPROC\nENDMODULE")]);

        twin.StartTasks();
        bool joined = twin.StopTasksWhenEnded(TimeSpan.FromSeconds(20));

        Assert.True(joined);
        Assert.Equal(RapidProgramState.Finished, twin.Task().State);
        Assert.Equal(RapidProgramState.Finished, twin.Task("T_BACK").State);
        Assert.Equal(["[T_ROB1] seen", "[T_BACK] done"], twin.Pendant.Lines);
    }
}
