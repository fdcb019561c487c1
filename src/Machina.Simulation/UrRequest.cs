namespace Machina.Simulation;

/// <summary>One instruction read from a UR driver program's connection: id, code and its integer parameters.</summary>
/// <param name="Id">The id acknowledged after it runs.</param>
/// <param name="Code">The instruction code (spec online §7.3).</param>
/// <param name="Values">The parameters as received (scaled integers).</param>
/// <param name="Program">Which uploaded program read it; a request of a replaced program is dropped.</param>
/// <param name="Halts">True for a code our driver does not know: its program stops there.</param>
internal sealed record UrRequest(int Id, int Code, int[] Values, int Program, bool Halts = false)
{
    /// <summary>The request as text, for the request log: <c>id code v1 v2 …</c>.</summary>
    public override string ToString() => string.Join(' ', new[] { Id, Code }.Concat(Values).Select(v => v.ToString(Num.Inv)));
}
