using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

public class UrScriptLanguageTests
{
    private static UrTwinController RunProgram(string program, out UrProgramState state)
    {
        var twin = new UrTwinController();
        state = twin.Run(program, CancellationToken.None);
        return twin;
    }

    private static IReadOnlyList<string> Messages(string program)
    {
        using UrTwinController twin = RunProgram(program, out UrProgramState state);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void Arithmetic_IntFloatAndPrecedence_AsTheManualDefines()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              textmsg("a=", 1 + 2 * 3)
              textmsg("b=", (1 + 2) * 3)
              textmsg("c=", 7 % 3)
              textmsg("d=", 7 / 2)
              textmsg("e=", -2147483648)
              textmsg("f=", 2 < 3 and not (1 == 1.0))
              textmsg("g=", 0.1 + 0.2 == 0.3 or 1 != 2)
              textmsg("h=", floor(2.7) + ceil(2.1))
              textmsg("i=", str_cat("x", to_str(p[0.1, 0, 0, 0, 0, 0])))
              v = [2, 3]
              textmsg("j=", p[1 / 4, v[0] * 0.75, 7 % 2.5, v[1] - 0.5, 1 + 1, -v[0] / 1000.0])
              textmsg("k=", [1, 2] == [1, 2.0])
              textmsg("l=", 2.0 == 2 and 3 != 4 and not (3 == 4))
            end
            """);
        Assert.Equal(["a=7", "b=9", "c=1", "d=3.5", "e=-2147483648", "f=False", "g=True", "h=5", "i=xp[0.1, 0, 0, 0, 0, 0]",
            "j=p[0.25, 1.5, 2, 2.5, 2, -0.002]", "k=True", "l=True"], lines);
    }

    [Fact]
    public void Functions_LocalsGlobalsListsAndLoops_FollowTheScopingRules()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              counter = 0
              a = 5
              def shadow():
                a = 1
                return a
              end
              def hide():
                local a = 7
                return a
              end
              def bump(step=2):
                global counter
                counter = counter + step
              end
              def fact(n):
                if n <= 1:
                  return 1
                end
                return n * fact(n - 1)
              end
              r = shadow()
              h = hide()
              bump()
              bump(step=10)
              v = [1, 2, 3]
              v[1] = 20
              q = p[0, 0, 0, 0, 0, 0]
              q[2] = 0.5
              i = 0
              total = 0
              while True:
                i = i + 1
                if i == 2:
                  continue
                elif i > 4:
                  break
                else:
                  total = total + i
                end
              end
              textmsg(r, a)
              textmsg(h, a)
              textmsg(counter, "")
              textmsg(fact(5), "")
              textmsg(v, q)
              textmsg(total, length(v))
            end
            """);
        // The manual's scoping rules: a free variable assigned in a function is the program's variable of that name (a is 1
        // after shadow()); a local one hides it.
        Assert.Equal(["11", "71", "12", "120", "[1, 20, 3]p[0, 0, 0.5, 0, 0, 0]", "83"], lines);
    }

    [Fact]
    public void Threads_RunJoinAndKill_ShareGlobals()
    {
        IReadOnlyList<string> lines = Messages("""
            def prog():
              done = 0
              thread worker():
                global done
                done = done + 1
              end
              thread forever():
                while True:
                  sync()
                end
              end
              t = run worker()
              join t
              f = run forever()
              kill f
              textmsg("done=", done)
            end
            """);
        Assert.Equal(["done=1"], lines);
    }

    [Theory]
    [InlineData("def prog():\n  movx(p[0.4, 0, 0.4, 0, 3.14, 0])\nend", "Compile error: line 2: unknown function 'movx'")]
    [InlineData("def prog():\n  x = 1\n  textmsg(y)\nend", "Compile error: line 3: variable 'y' is not defined")]
    [InlineData("def prog():\n  movel(p[0.4, 0, 0.4, 0, 3.14, 0], speed=1)\nend", "Compile error: line 2: movel has no parameter 'speed'")]
    [InlineData("def prog():\n  sleep()\nend", "Compile error: line 2: sleep is missing its argument 't'")]
    [InlineData("def prog():\n  sleep(1, 2)\nend", "Compile error: line 2: sleep takes at most 1 arguments, 2 given")]
    [InlineData("def prog():\n  if True:\n    sleep(1)\nend", "Compile error: line 4: 'end' is missing before the end of the program")]
    [InlineData("def prog():\n  x = p[1, 2]\nend", "Compile error: line 2: a pose needs 6 numbers, not 2")]
    [InlineData("def prog():\n  x = \"open\nend", "Compile error: line 2: the string does not end on its line")]
    [InlineData("def prog():\n  set_payload(1.5, (0, 0, 0.1))\nend", "Compile error: line 2: expected ')' but found ',': URScript has no tuples, a list is written [a, b, c]")]
    [InlineData("def prog():\n  digital_out[3] = True\nend", "Compile error: line 2: variable 'digital_out' is not defined")]
    public void Compile_Mistake_IsRefusedWithItsLineAndNothingRuns(string program, string expected)
    {
        using UrTwinController twin = RunProgram("def first():\n  set_standard_digital_out(1, True)\nend", out _);
        Assert.Equal(UrProgramState.Failed, twin.Run(program, CancellationToken.None));
        Assert.Equal(expected, twin.Error);
        Assert.Equal(1, twin.ProgramsStarted);
        Assert.Equal(expected, Assert.Single(twin.Pendant.Lines));
    }

    [Theory]
    [InlineData("  x = [1, 2]\n  textmsg(x[2])", "Runtime error: line 3: index 2 is out of range (length 2)")]
    [InlineData("  x = 1 / 0", "Runtime error: line 2: division by zero")]
    [InlineData("  set_standard_digital_out(8, True)", "Runtime error: line 2: set_standard_digital_out: there is no signal 8 (0 to 7)")]
    [InlineData("  movej([0, 0, 0, 0, 0, 0], v=0)", "Runtime error: line 2: movej: speed 'v' and acceleration 'a' must be positive")]
    [InlineData("  movel(p[3, 0, 0.4, 0, 3.141593, 0])", "Runtime error: line 2: movel: no inverse kinematics solution: the target pose is out of reach")]
    [InlineData("  movej([7, 0, 0, 0, 0, 0])", "Runtime error: line 2: movej: joint 1 target 401.07 deg is beyond its limits [-360, 360] deg")]
    [InlineData("  textmsg(\"a\" + 1)", "Runtime error: line 2: '+' cannot be applied to string and int")]
    [InlineData("  x = p[[1, 2] * 2, 0, 0, 0, 0, 0]", "Runtime error: line 2: a pose element must be a number, not array")]
    [InlineData("  x = p[0, 1.5 / 0, 0, 0, 0, 0]", "Runtime error: line 2: division by zero")]
    [InlineData("  x = p[0, 0, 1 < 2.5, 0, 0, 0]", "Runtime error: line 2: a pose element must be a number, not bool")]
    public void Runtime_Error_StopsTheProgramWithTheMessage(string body, string expected)
    {
        using UrTwinController twin = RunProgram($"def prog():\n{body}\n  textmsg(\"after\")\nend", out UrProgramState state);
        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal(expected, twin.Error);
        Assert.DoesNotContain("after", twin.Pendant.Lines);
        Assert.Equal(new Joints(0, -90, 90, -90, -90, 0), twin.Arm.Joints);
    }
}
