using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>How the text on a script port is cut into programs (script manual: def/sec and end in column 1).</summary>
public class UrScriptIntakeTests
{
    [Theory]
    [InlineData("def p():\n  x = 1\nend", "def p():\n  x = 1\nend")] // complete at its end, no line break needed
    [InlineData("def p():\n  x = 1\nend\nmore", "def p():\n  x = 1\nend\n")]
    [InlineData("# c\n\ndef p():\n  x = 1\nen", null)]
    [InlineData("def p():\n  x = 1\n  end\n", null)] // an indented end closes a block, not the program
    [InlineData("textmsg(1)", null)] // a one-line program waits for its line break
    [InlineData("textmsg(1)\ndef p():\n", "textmsg(1)")]
    [InlineData("sec s():\n  x = 1\nend\r\n", "sec s():\n  x = 1\nend\r\n")]
    public void TakeProgram_ProgramCompleteAtItsEnd_OneLinerAtItsLineBreak(string text, string? expected)
    {
        var intake = new UrScriptIntake();
        intake.Append(text);
        Assert.Equal(expected, intake.TakeProgram());
    }

    [Theory]
    [InlineData("def machina_ur_driver():\n  x = 1\nend\nmachina_ur_driver()\ntextmsg(2)\n")]
    [InlineData("# header\ndef machina_ur_driver():\n  x = 1\nend\n\n\nmachina_ur_driver()\ntextmsg(2)\n")]
    public void TakeProgram_CallLineAfterTheDefinition_BelongsToIt(string text)
    {
        var intake = new UrScriptIntake();
        intake.Append(text);
        Assert.StartsWith("def machina_ur_driver():", intake.TakeProgram(), StringComparison.Ordinal);
        Assert.Equal("textmsg(2)", intake.TakeProgram()); // the call line was skipped, the next line is a new program
        Assert.Null(intake.TakeProgram());
    }

    [Theory]
    [InlineData("def machina_ur_driver():\n  x = 1\nend\n\n\n# Kickstart\nmachina_ur_driver()", "def machina_stop():\n  textmsg(\"Stopping\")\nend\n")]
    [InlineData("def machina_ur_driver():\n  x = 1\nend\nmachina_ur", "_driver()def machina_stop():\n  textmsg(\"Stopping\")\nend\n")]
    public void TakeProgram_CallWithoutLineBreak_ThenTheNextProgram_AsTheOriginalHostSendsThem(string first, string second)
    {
        string[] pieces = [first, second];
        var intake = new UrScriptIntake();
        var programs = new List<string>();
        foreach (string piece in pieces)
        {
            intake.Append(piece);
            while (intake.TakeProgram() is { } program)
            {
                programs.Add(program);
            }
        }
        Assert.Equal(2, programs.Count);
        Assert.StartsWith("def machina_ur_driver():", programs[0], StringComparison.Ordinal);
        Assert.Equal("def machina_stop():\n  textmsg(\"Stopping\")\nend\n", programs[1]);
    }

    [Fact]
    public void TakeProgram_OtherCallAfterTheDefinition_IsANewProgram()
    {
        var intake = new UrScriptIntake();
        intake.Append("def p():\n  x = 1\nend\nother()\n");
        Assert.Equal("def p():\n  x = 1\nend\n", intake.TakeProgram());
        Assert.Equal("other()", intake.TakeProgram());
    }

    [Fact]
    public void TakeProgram_TextInPieces_SameProgram()
    {
        var intake = new UrScriptIntake();
        const string program = "def p():\n  if True:\n    x = 1\n  end\nend";
        foreach (char c in program[..^1])
        {
            intake.Append(c.ToString());
            Assert.Null(intake.TakeProgram());
        }
        intake.Append("d");
        Assert.Equal(program, intake.TakeProgram());
    }
}
