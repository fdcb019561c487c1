namespace Machina;

/// <summary>What kind of device a brand is: it decides whether an arm model, a driver or a virtual controller applies to it.</summary>
internal enum BrandKind
{
    /// <summary>An industrial arm: it takes an arm model and can have online control.</summary>
    Arm,

    /// <summary>A 3D printer (G-code): compiled only, no arm model.</summary>
    Printer,

    /// <summary>A text listing (Machina's own instructions, or a human-readable one): compiled only.</summary>
    Listing,
}
