using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// StrToVal into records, arrays and strings (the Reference Manual: Val is of any value data type, "atomic, record, record component,
/// array or array element"; the data are unchanged when the conversion fails). A published socket server (EricssonResearch/arms,
/// other/abb/server.mod) reads each request as <c>ok := StrToVal(recv_string, recv_params)</c> into a <c>num{10}</c> and answers -3
/// when that fails: the twin stopped it with ERR_ARGVALERR ("converts to num, dnum and bool only").
/// </summary>
public class ThirdPartyRapidStrToValTests
{
    private static List<string> Run(string body, string data = "")
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.Equal(RapidProgramState.Finished, twin.Run());
        return [.. twin.Pendant.Lines];
    }

    [Fact]
    public void NumArray_IsReadFromItsAggregate_AsTheArmsServerSendsIt()
    {
        List<string> lines = Run(
            """
              ok := StrToVal("[1,0,0,0,0,0,0,0,0,9]", params);
              TPWrite ValToStr(ok) + " " + ValToStr(params{1}) + " " + ValToStr(params{10});
              ok := StrToVal(" [ -2.5 , 1E3,0,0,0,0,0,0,0,7 ] ", params);
              TPWrite ValToStr(ok) + " " + ValToStr(params{1}) + " " + ValToStr(params{2}) + " " + ValToStr(params{10});
            """,
            "VAR num params{10};\nVAR bool ok;");

        Assert.Equal(["TRUE 1 9", "TRUE -2.5 1000 7"], lines);
    }

    [Theory]
    [InlineData("[1,0,0]")]
    [InlineData("[0,1,2,3,4,5,6,7,8,9,10,11,12]")]
    [InlineData("[0,1,2,3,4,5,6,7,8,9")]
    [InlineData("123")]
    [InlineData("abc")]
    [InlineData("[")]
    [InlineData("[0,1,2,3,4,5,6,7,8,x]")]
    [InlineData("[0,1,2,3,4,5,6,7,8,9]x")]
    public void TextThatIsNotTheArraysLiteral_GivesFalse_AndLeavesTheDataUnchanged(string text)
    {
        List<string> lines = Run(
            $$"""
              params{3} := 42;
              ok := StrToVal("{{text}}", params);
              TPWrite ValToStr(ok) + " " + ValToStr(params{3}) + " " + ValToStr(params{1});
            """,
            "VAR num params{10};\nVAR bool ok := TRUE;");

        Assert.Equal(["FALSE 42 0"], lines);
    }

    [Fact]
    public void Records_AreReadFromTheirAggregates_NestedOnesToo()
    {
        List<string> lines = Run(
            """
              ok := StrToVal("[600, 500, 225.3]", pos15);
              TPWrite ValToStr(ok) + " " + ValToStr(pos15);
              ok := StrToVal("[[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]", target);
              TPWrite ValToStr(ok) + " " + ValToStr(target.trans.z) + " " + ValToStr(target.rot.q1);
              ok := StrToVal("[1,2]", pos15);
              TPWrite ValToStr(ok) + " " + ValToStr(pos15.z);
            """,
            "VAR pos pos15;\nVAR robtarget target;\nVAR bool ok;");

        Assert.Equal(["TRUE [600,500,225.3]", "TRUE 3 1", "FALSE 225.3"], lines);
    }

    [Fact]
    public void StringsAndTwoDimensionalArrays_AreReadFromTheirLiterals()
    {
        List<string> lines = Run(
            """""
              ok := StrToVal("""abc """"d""", s);
              TPWrite ValToStr(ok) + " " + s;
              ok := StrToVal("[[1,2,3],[4,5,6]]", grid);
              TPWrite ValToStr(ok) + " " + ValToStr(grid{1,3}) + " " + ValToStr(grid{2,1});
              ok := StrToVal("[TRUE,false]", flags);
              TPWrite ValToStr(ok) + " " + ValToStr(flags{2});
            """"",
            "VAR string s;\nVAR num grid{2,3};\nVAR bool flags{2} := [FALSE, TRUE];\nVAR bool ok;");

        Assert.Equal(["TRUE abc \"d", "TRUE 3 4", "TRUE FALSE"], lines);
    }
}
