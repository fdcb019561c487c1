using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>
/// The <c>steady-</c> rows (the plain program's stream on a robot connected once) beside the <c>plain-</c> rows: named apart, so that
/// asking for a plain row runs that row alone.
/// </summary>
public class SteadyRowsTests
{
    [Fact]
    public void Catalog_HasASteadyRowPerBrand_AndAPlainRowSelectsOnlyItself()
    {
        IReadOnlyList<Scenario> all = Catalog.All(new Workloads());

        Assert.Equal(["steady-abb", "steady-ur", "steady-kuka"], all.Select(s => s.Name).Where(n => n.StartsWith("steady", StringComparison.Ordinal)));
        Options plain = Options.Parse(["--scenario", "plain-abb"]);
        Assert.Equal(["plain-abb"], all.Where(plain.Selects).Select(s => s.Name));
        Options steady = Options.Parse(["--scenario", "steady"]);
        Assert.Equal(["steady-abb", "steady-ur", "steady-kuka"], all.Where(steady.Selects).Select(s => s.Name));
    }
}
