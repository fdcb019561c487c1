using System.Text;

namespace Machina.Simulation;

/// <summary>
/// Takes out of what a primary-interface connection sends the lines a UR controller takes there besides URScript
/// (<c>power on</c>, <c>power off</c>, <c>set robotmode run</c>, <c>set unlock protective stop</c>, <c>stop program</c>) and
/// passes the rest on as script text, however TCP chunks it. Only a line that may still become one of those is held back.
/// </summary>
internal sealed class VirtualUrPrimaryCommands(Action<string> onCommand)
{
    /// <summary>The commands a controller takes on its primary port besides URScript.</summary>
    public static readonly string[] Commands = ["power on", "power off", "set robotmode run", "set unlock protective stop", "stop program"];

    private readonly StringBuilder _held = new();
    private bool _holding = true; // at the start of a line

    /// <summary>The script text of <paramref name="text"/>: everything but whole command lines, which go to the callback.</summary>
    public string Filter(string text)
    {
        var script = new StringBuilder(text.Length);
        foreach (char c in text)
        {
            if (!_holding)
            {
                script.Append(c);
                _holding = c == '\n';
                continue;
            }
            if (c == '\n')
            {
                string line = _held.ToString().TrimEnd('\r', ' ');
                _held.Clear();
                if (Array.IndexOf(Commands, line) >= 0)
                {
                    onCommand(line);
                }
                else
                {
                    script.Append(line).Append('\n');
                }
                continue;
            }
            _held.Append(c);
            string sofar = _held.ToString().TrimEnd('\r', ' ');
            if (!Array.Exists(Commands, command => command.StartsWith(sofar, StringComparison.Ordinal)))
            {
                script.Append(_held);
                _held.Clear();
                _holding = false;
            }
        }
        return script.ToString();
    }
}
