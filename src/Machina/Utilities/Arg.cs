using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Checks of the arguments of the public verbs, so that an <see cref="ArgumentException"/> names the parameter of the method the
/// user called (<c>MoveTo(x, y, z)</c> → "y"), not the parameter of an internal constructor ("translation").
/// </summary>
internal static class Arg
{
    /// <summary>The value, or an <see cref="ArgumentException"/> naming the caller's parameter when it is NaN or infinite.</summary>
    internal static double Finite(double value, [CallerArgumentExpression(nameof(value))] string name = "") =>
        double.IsFinite(value) ? value : throw new ArgumentException($"{name} must be a finite number, but it was {Num.R(value)}.", name);

    /// <summary>The vector, or an <see cref="ArgumentException"/> naming the caller's parameter when a component is NaN or infinite.</summary>
    internal static Vector Finite(Vector value, [CallerArgumentExpression(nameof(value))] string name = "") => value.RequireFinite(name);

    /// <summary>A vector of three finite numbers, each checked under its own parameter name.</summary>
    internal static Vector Vector(double x, double y, double z,
        [CallerArgumentExpression(nameof(x))] string xName = "", [CallerArgumentExpression(nameof(y))] string yName = "",
        [CallerArgumentExpression(nameof(z))] string zName = "") =>
        new(Finite(x, xName), Finite(y, yName), Finite(z, zName));

    /// <summary>
    /// Runs <paramref name="make"/>; an <see cref="ArgumentException"/> it throws for the parameter <paramref name="from"/> is thrown
    /// again (same type and message) for <paramref name="to"/>, the caller's parameter.
    /// </summary>
    internal static T Renamed<T, TState>(string from, string to, TState state, Func<TState, T> make)
    {
        try
        {
            return make(state);
        }
        catch (ArgumentException e) when (e.ParamName == from && from != to)
        {
            throw Rename(e, to);
        }
    }

    /// <summary>
    /// The rotation with these X and Y axes; an error about the X axis names <paramref name="xName"/>, any other (a zero or parallel Y
    /// axis) names <paramref name="yName"/>.
    /// </summary>
    internal static Rotation FromAxes(Vector xAxis, Vector yAxis, string xName, string yName)
    {
        try
        {
            return Rotation.FromAxes(xAxis, yAxis);
        }
        catch (ArgumentException e)
        {
            throw Rename(e, e.ParamName == "xAxis" ? xName : yName);
        }
    }

    private static ArgumentException Rename(ArgumentException e, string name)
    {
        string message = e.Message.Replace($" (Parameter '{e.ParamName}')", "", StringComparison.Ordinal);
        return e switch
        {
            ArgumentOutOfRangeException range => new ArgumentOutOfRangeException(name, range.ActualValue,
                message.Split(Environment.NewLine)[0]),
            ArgumentNullException => new ArgumentNullException(name, message),
            _ => new ArgumentException(message, name, e),
        };
    }
}
