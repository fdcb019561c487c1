using Machina.Tests.Conventions;
using Machina.Tests.Support;

namespace Machina.Tests.State;

/// <summary>
/// Online, an action the wire cannot carry is undone from what it changed (<see cref="RobotCursor.Mark"/>, <see cref="RobotCursor.Undo"/>)
/// instead of from a copy of the whole cursor: every field must then be as it was, for every kind of action.
/// </summary>
public class CursorUndoTests
{
    [Theory]
    [InlineData(null)]
    [InlineData("IRB 120")]
    public void Undo_EveryKindOfAction_EveryFieldAsBefore(string? model)
    {
        var cursor = new RobotCursor { Model = model is null ? null : RobotModels.Get(model) };
        int applied = 0;
        foreach (RobotAction action in Instructions.Enumerate(EveryActionKindTests.EveryKind))
        {
            Dictionary<string, object?> before = CursorFields.Of(cursor);
            RobotCursor.UndoPoint point = cursor.Mark(action);
            Assert.Null(cursor.TryApply(action));
            Assert.Same(action, cursor.LastAction);
            cursor.Undo(point);

            CursorFields.AssertSame(before, CursorFields.Of(cursor), action.ToInstruction());
            Assert.Null(cursor.TryApply(action));   // then on, so that the next action starts from a state with this one in it
            applied++;
        }
        Assert.True(applied > 40, $"{applied} actions");
    }

    /// <summary>The collections: a tool defined again, outputs written again or for the first time, the settings stack both ways.</summary>
    [Fact]
    public void Undo_RewrittenEntriesAndTheSettingsStack_PutBackWhatWasThere()
    {
        var cursor = new RobotCursor();
        foreach (RobotAction setup in Instructions.Parse("""
            DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50); AttachTool("pen");
            WriteDigital(1, true); WriteAnalog(2, 0.5); SpeedTo(50); PushSettings(); SpeedTo(70); PushSettings(); SpeedTo(90);
            """))
        {
            Assert.Null(cursor.TryApply(setup));
        }
        RobotAction[] changes =
        [
            .. Instructions.Parse("""
                DefineTool("pen", 0, 0, 150, 1, 0, 0, 0, 1, 0, 1.5, 0, 0, 50); DefineTool("brush", 0, 0, 20, 1, 0, 0, 0, 1, 0, 0.1, 0, 0, 5);
                WriteDigital(1, false); WriteDigital(3, true); WriteAnalog(2, 0.75); WriteAnalog(4, 0.25); PopSettings(); PushSettings();
                DetachTool(); TemperatureTo(200, "extruder");
                """),
            new ActionIODigital("1", false, isToolPin: true),
            new ActionIOAnalog("2", 0.5, isToolPin: true),
        ];
        foreach (RobotAction action in changes)
        {
            Dictionary<string, object?> before = CursorFields.Of(cursor);
            RobotCursor.UndoPoint point = cursor.Mark(action);
            Assert.Null(cursor.TryApply(action));
            cursor.Undo(point);
            CursorFields.AssertSame(before, CursorFields.Of(cursor), action.ToInstruction());
        }
        Assert.Equal(0.5, cursor.Tools["pen"].Weight);
        Assert.False(cursor.Tools.ContainsKey("brush"));
        Assert.True(cursor.DigitalOutputs["1"]);
        Assert.False(cursor.DigitalOutputs.ContainsKey("3"));
        Assert.False(cursor.DigitalOutputs.ContainsKey("tool:1"));
        Assert.Equal([70.0, 50.0], cursor.SettingsStack.Select(s => s.Speed));
        Assert.Equal(90, cursor.Speed);
    }
}
