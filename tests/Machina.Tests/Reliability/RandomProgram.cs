namespace Machina.Tests.Reliability;

/// <summary>Seeded random programs for the reliability tests: motions that stay inside a box the arm reaches.</summary>
internal static class RandomProgram
{
    /// <summary>The lowest corner of a box every brand's arm reaches with the tool pointing down, mm.</summary>
    internal static readonly Vector ReachableLow = new(300, -80, 420);

    /// <summary>The highest corner of that box, mm.</summary>
    internal static readonly Vector ReachableHigh = new(420, 80, 560);

    /// <summary>
    /// Issues <paramref name="count"/> actions, each one request on every brand: a move to the box's centre, then relative
    /// moves of up to 5 mm per axis, turned back at the box's edges. With <paramref name="jumps"/>, one action in ten changes
    /// the speed and one in ten moves to a random point of the box. Returns where the last one leaves the robot.
    /// </summary>
    internal static Vector Issue(Robot bot, Random random, int count, Vector low, Vector high, bool jumps)
    {
        var at = new Vector(Math.Round((low.X + high.X) / 2), Math.Round((low.Y + high.Y) / 2), Math.Round((low.Z + high.Z) / 2));
        bot.MoveTo(at.X, at.Y, at.Z);
        for (int i = 1; i < count; i++)
        {
            switch (jumps ? random.Next(10) : -1)
            {
                case 0:
                    bot.SpeedTo(random.Next(10, 200));
                    break;
                case 1:
                    at = new Vector(random.Next((int)low.X, (int)high.X), random.Next((int)low.Y, (int)high.Y), random.Next((int)low.Z, (int)high.Z));
                    bot.MoveTo(at.X, at.Y, at.Z);
                    break;
                default:
                    var by = new Vector(StepWithin(random, at.X, low.X, high.X), StepWithin(random, at.Y, low.Y, high.Y), StepWithin(random, at.Z, low.Z, high.Z));
                    at += by;
                    bot.Move(by.X, by.Y, by.Z);
                    break;
            }
        }
        return at;
    }

    /// <summary>A step of -5 to 5 mm (seeded) that keeps <paramref name="at"/> inside [<paramref name="low"/>, <paramref name="high"/>].</summary>
    internal static int StepWithin(Random random, double at, double low, double high)
    {
        int step = random.Next(-5, 6);
        return at + step < low || at + step > high ? -step : step;
    }
}
