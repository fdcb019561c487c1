namespace Machina;

/// <summary>Facts about this build of the library.</summary>
internal static class LibraryInfo
{
    /// <summary>The library's version.</summary>
    internal const string Version = "0.1.0";

    /// <summary>The library's name and version, used in program headers.</summary>
    internal const string NameAndVersion = "Machina " + Version;
}
