using System.Text.RegularExpressions;

namespace Machina.Bridge;

/// <summary>
/// The instructions the original clients send under names Machina never had (spec bridge §2): Processing's and Python's
/// <c>Tool.Create("pen",…)</c> (Python writes <c>Tool.create</c> and a trailing comma, Processing an empty argument before the
/// weight), <c>Attach("pen")</c> and <c>Detach()</c>. A message that is one such statement is read as <c>DefineTool</c>,
/// <c>AttachTool</c> or <c>DetachTool</c>; anything else is left as it is.
/// </summary>
internal static partial class ClientAliases
{
    /// <summary>The text to issue for <paramref name="message"/>: the Machina instruction for an alias, else the message itself.</summary>
    internal static string Translate(string message)
    {
        ReadOnlySpan<char> statement = message.AsSpan().Trim();
        if (statement.StartsWith("Attach(", StringComparison.Ordinal))
        {
            return "AttachTool" + statement["Attach".Length..].ToString();
        }
        if (statement.StartsWith("Detach(", StringComparison.Ordinal))
        {
            return "DetachTool" + statement["Detach".Length..].ToString();
        }
        if (statement.StartsWith("Tool.Create(", StringComparison.Ordinal) || statement.StartsWith("Tool.create(", StringComparison.Ordinal))
        {
            return "DefineTool(" + WithoutEmptyNumbers(statement["Tool.Create(".Length..].ToString());
        }
        return message;
    }

    /// <summary>Drops the empty arguments the clients' formatting leaves among the numbers after the quoted tool name.</summary>
    private static string WithoutEmptyNumbers(string arguments)
    {
        // The name is the first argument, in quotes; after it come only numbers, so commas there separate numbers.
        int open = arguments.IndexOf('"', StringComparison.Ordinal);
        int close = open < 0 ? -1 : arguments.IndexOf('"', open + 1);
        if (close < 0 || arguments.AsSpan(0, open).Trim().Length > 0)
        {
            return arguments;
        }
        return arguments[..(close + 1)] + EmptyArgument().Replace(arguments[(close + 1)..], "");
    }

    /// <summary>A comma followed (after white space) by another comma or the closing parenthesis.</summary>
    [GeneratedRegex(@",\s*(?=[,)])")]
    private static partial Regex EmptyArgument();
}
