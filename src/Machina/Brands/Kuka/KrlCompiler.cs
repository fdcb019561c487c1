namespace Machina;

/// <summary>
/// Writes KUKA Robot Language (KRL) programs: <c>name.src</c> with the motions, and with declared (not inline) targets also
/// <c>name.dat</c> holding them. Positions in mm, A, B, C in degrees, speeds in m/s, accelerations in m/s², waits in seconds.
/// </summary>
internal sealed class KrlCompiler : Compiler
{
    internal override RobotType Brand => RobotType.KUKA;

    internal override string CommentPrefix => ";";

    internal override void Emit(CompileJob job, ProgramOutput output) => new KrlWriter(this, job, output).Write();
}
