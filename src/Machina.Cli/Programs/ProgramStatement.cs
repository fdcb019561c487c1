namespace Machina.Cli.Programs;

/// <summary>One action read from a program, with the line and column (from 1) where its statement starts.</summary>
internal readonly record struct ProgramStatement(RobotAction Action, int Line, int Column);
