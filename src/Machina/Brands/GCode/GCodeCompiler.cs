namespace Machina;

/// <summary>
/// Writes G-code for 3D printers (<c>name.gcode</c>) in one of two flavours: ZMorph (as the original library) or generic Marlin.
/// Positions in mm, feed rates in mm/min, waits in ms, temperatures in °C, extrusion as the absolute filament length in mm.
/// </summary>
internal sealed class GCodeCompiler(GCodeFlavor flavor) : Compiler
{
    /// <summary>The dialect written.</summary>
    internal GCodeFlavor Flavor { get; } = flavor;

    internal override RobotType Brand => Flavor.Brand;

    internal override string CommentPrefix => ";";

    internal override void Emit(CompileJob job, ProgramOutput output) => new GCodeWriter(this, job, output).Write();
}
