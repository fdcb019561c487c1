using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Routine frames reused from call to call and IN structure parameters that hold the caller's local (issue 45, perf56k): a local
/// starts at its initial value at every call, a frame a TRIGGER or INTERRUPT DECL keeps is not reused, and an IN parameter is the
/// routine's own value (a write of it, an OUT argument of one of its components, or a TRIGGER of the caller during the call never
/// reaches the caller's variable, and the caller's variable never changes it).
/// </summary>
public class KrlFrameReuseTests
{
    private static KrlTwinController Run(string source, string data)
    {
        var twin = new KrlTwinController();
        twin.Load([("prog.src", source), ("prog.dat", data)]);
        KrlProgramState state = twin.Run();
        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    private static double Real(KrlTwinController twin, string name) => KrlValues.ToReal(twin.Modules["prog"].Data[name].Value);

    private static KrlRoutine Routine(KrlTwinController twin, string name) =>
        twin.Modules["prog"].Routines.Single(r => string.Equals(r.Name, name, StringComparison.OrdinalIgnoreCase));

    [Fact]
    public void LocalsStartAtTheirInitialValue_AtEveryCall_AfterAnotherRoutineOfAsManyLocalsRan()
    {
        const string Data = """
            DEFDAT prog
              DECL REAL seen = 0.0
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL INT k
              FOR k = 1 TO 3
                use( )
                other( )
              ENDFOR
            END

            DEF use( )
              DECL FRAME t
              DECL INT n
              DECL REAL r
              seen = seen + t.X + t.C + n + r
              t.X = 5
              t.C = 6
              n = 7
              r = 8
            END

            DEF other( )
              DECL E6POS q
              DECL INT a
              DECL REAL b
              q.X = 50
              a = 70
              b = 80
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        Assert.Equal(0.0, Real(twin, "seen")); // each call's FRAME, INT and REAL start at 0 (a reused frame is cleared)
    }

    [Fact]
    public void ATriggersAction_ReadsTheLocalsOfTheRoutineThatGaveIt_AfterThatRoutineReturned()
    {
        const string Data = """
            DEFDAT prog
              DECL INT result = 0
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              PTP {AXIS: A1 0, A2 -90, A3 90, A4 0, A5 30, A6 0}
              arm( )
              other( )
              PTP {AXIS: A1 10, A2 -90, A3 90, A4 0, A5 30, A6 0}
            END

            DEF arm( )
              DECL INT v
              v = 42
              TRIGGER WHEN DISTANCE=0 DELAY=0 DO result = v
            END

            DEF other( )
              DECL INT w
              w = 99
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        Assert.Equal(42, (int)twin.Modules["prog"].Data["result"].Value); // arm's frame was kept, not handed to other( )
    }

    [Fact]
    public void AnInStructureParameter_IsTheRoutinesOwn_WhateverTheRoutineOrTheCallerDoes()
    {
        const string Data = """
            DEFDAT prog
              DECL REAL inside = 0.0
              DECL REAL x1 = 0.0
              DECL REAL y2 = 0.0
              DECL REAL sum3 = 0.0
              DECL REAL seen4 = 0.0
              DECL REAL x5 = 0.0
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL FRAME t
              t = {X 1, Y 2, Z 3, A 0, B 0, C 0}
              writes(t)
              x1 = t.X
              passes(t)
              y2 = t.Y
              reads(t)
              watched( )
            END

            DEF writes(p:IN)
              DECL FRAME p
              p.X = 99
              inside = p.X
            END

            DEF passes(p:IN)
              DECL FRAME p
              sets(p.Y)
            END

            DEF sets(v:OUT)
              DECL REAL v
              v = 77
            END

            DEF reads(p:IN)
              DECL FRAME p
              sum3 = p.X + p.Z
            END

            DEF watched( )
              DECL FRAME t
              t = {X 1, Y 2, Z 3, A 0, B 0, C 0}
              PTP {AXIS: A1 0, A2 -90, A3 90, A4 0, A5 30, A6 0}
              TRIGGER WHEN DISTANCE=0 DELAY=0 DO t.X = 50
              moves(t)
              x5 = t.X
            END

            DEF moves(p:IN)
              DECL FRAME p
              PTP {AXIS: A1 10, A2 -90, A3 90, A4 0, A5 30, A6 0}
              seen4 = p.X
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        Assert.Equal(99.0, Real(twin, "inside"));
        Assert.Equal(1.0, Real(twin, "x1")); // writes( ) changed its own copy
        Assert.Equal(2.0, Real(twin, "y2")); // passes( ) handed its own copy's Y to an OUT parameter
        Assert.Equal(4.0, Real(twin, "sum3"));
        Assert.Equal(1.0, Real(twin, "seen4")); // the caller's TRIGGER changed the caller's t during moves( ), not moves( )'s p
        Assert.Equal(50.0, Real(twin, "x5"));

        // Which parameters are only read, and which calls hand their local over without a copy.
        Assert.Equal(0, Routine(twin, "writes").Reads.ReadOnlyParameters);
        Assert.Equal(0, Routine(twin, "passes").Reads.ReadOnlyParameters);
        Assert.Equal(1, Routine(twin, "reads").Reads.ReadOnlyParameters);
        Assert.Equal(1, Routine(twin, "moves").Reads.ReadOnlyParameters);
        Assert.False(Routine(twin, "prog").Reads.KeepsFrame);
        Assert.True(Routine(twin, "watched").Reads.KeepsFrame);
        List<KrlStmt> body = Routine(twin, "prog").Body;
        Assert.Equal([0, 0, 1], body.OfType<KrlCallStmt>().Take(3).Select(c => c.Call.SharedArguments));
        Assert.Equal(0, Routine(twin, "watched").Body.OfType<KrlCallStmt>().Single().Call.SharedArguments); // its TRIGGER may write t meanwhile
    }

    [Fact]
    public void TheDriversTargetCheck_HoldsTheCallersFrame_AndARecursiveRoutineIsWalkedOnce()
    {
        const string Source = """
            DEF prog( )
              DECL FRAME t
              depth(3, t)
            END

            DEF depth(n:IN, p:IN)
              DECL INT n
              DECL FRAME p
              IF n > 0 THEN
                depth(n - 1, p)
              ENDIF
            END
            """;
        using KrlTwinController twin = Run(Source, "DEFDAT prog\nENDDAT\n");

        Assert.Equal(3, Routine(twin, "depth").Reads.ReadOnlyParameters);
        Assert.Equal(2, Routine(twin, "depth").Body.OfType<KrlIf>().Single().Then.OfType<KrlCallStmt>().Single().Call.SharedArguments);

        IReadOnlyDictionary<string, string> files = global::Machina.KukaDriverModules.Create("127.0.0.1", 54600);
        using var driver = new KrlTwinController();
        driver.Load([("machina_kuka_driver.src", files["machina_kuka_driver.src"]), ("machina_kuka_driver.dat", files["machina_kuka_driver.dat"])]);
        KrlModule module = driver.Modules["machina_kuka_driver"];
        KrlRoutine run = module.Routines.Single(r => r.Name.Equals("machina_run", StringComparison.OrdinalIgnoreCase));
        Assert.Equal(3, module.Routines.Single(r => r.Name.Equals("machina_check_target", StringComparison.OrdinalIgnoreCase)).Reads.ReadOnlyParameters); // id and target: only read
        run.Reads.MarkCalls();
        KrlSwitch actions = run.Body.OfType<KrlSwitch>().Single();
        KrlCall check = actions.Cases[0].Body.OfType<KrlIf>().Single().Then.OfType<KrlCallStmt>().Single().Call;
        Assert.Equal("machina_check_target", check.Name);
        Assert.Equal(3, check.SharedArguments); // the LIN's FRAME is handed over without a copy (its INT id is a value anyway)
    }
}
