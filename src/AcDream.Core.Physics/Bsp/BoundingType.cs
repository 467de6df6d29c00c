using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Bsp;

/// <summary>Where a sphere lies against a cell BSP (retail BoundingType).</summary>
internal enum BoundingType
{
    /// <summary>Entirely outside.</summary>
    Outside = 0,
    /// <summary>Partly inside.</summary>
    PartiallyInside = 1,
    /// <summary>Entirely inside.</summary>
    EntirelyInside = 2,
}
