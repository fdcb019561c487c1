namespace Machina;

/// <summary>Writes URScript for Universal Robots: one <c>.script</c> file with a function holding the program, then a call to it.</summary>
internal sealed class UrScriptCompiler : Compiler
{
    internal override RobotType Brand => RobotType.UR;

    internal override string CommentPrefix => "#";

    internal override void Emit(CompileJob job, ProgramOutput output) => throw new NotImplementedException();
}
