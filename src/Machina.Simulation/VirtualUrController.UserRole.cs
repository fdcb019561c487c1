namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The user roles a CB-Series dashboard takes (<c>setUserRole</c>), as <c>getUserRole</c> names them.</summary>
    private static readonly string[] UserRoles = ["PROGRAMMER", "OPERATOR", "NONE", "LOCKED", "RESTRICTED"];

    private string _userRole = "NONE";

    /// <summary>
    /// The user role the dashboard set last (<c>setUserRole</c>, software 3.x only): PROGRAMMER, OPERATOR, NONE (the start),
    /// LOCKED or RESTRICTED. The twin has no pendant whose buttons it would lock: the role is kept and reported, nothing more.
    /// </summary>
    internal string UserRole => Volatile.Read(ref _userRole);

    /// <summary>
    /// <c>setUserRole ROLE</c> and <c>getUserRole</c> as a CB-Series (software 3.x) dashboard answers them: the role matched
    /// without regard to letter case and echoed as sent (<c>Setting user role: operator</c>), <c>getUserRole</c> naming it in
    /// capitals; no role is NONE. Null for any other command, and on software 5 and later, whose dashboard has neither command
    /// (it answers them "could not understand").
    /// </summary>
    private string? UserRoleCommand(string command)
    {
        if (SoftwareVersion.Major >= 5)
        {
            return null;
        }
        if (command.Equals("getUserRole", StringComparison.OrdinalIgnoreCase))
        {
            return UserRole;
        }
        const string Set = "setUserRole";
        if (!command.StartsWith(Set, StringComparison.OrdinalIgnoreCase) || (command.Length > Set.Length && command[Set.Length] != ' '))
        {
            return null;
        }
        string role = command[Set.Length..].Trim();
        string? known = role.Length == 0 ? "NONE" : Array.Find(UserRoles, r => r.Equals(role, StringComparison.OrdinalIgnoreCase));
        if (known is null)
        {
            return "Failed setting user role: " + role;
        }
        Volatile.Write(ref _userRole, known);
        return "Setting user role: " + (role.Length == 0 ? "none" : role);
    }
}
