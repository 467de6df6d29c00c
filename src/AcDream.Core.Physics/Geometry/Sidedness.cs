namespace AcDream.Core.Physics.Geometry;

/// <summary>Which side of a plane something lies on (retail Sidedness).</summary>
internal enum Sidedness
{
    /// <summary>In front of the plane (retail POSITIVE).</summary>
    Positive = 0,
    /// <summary>Behind the plane (retail NEGATIVE).</summary>
    Negative = 1,
    /// <summary>In the plane (retail IN_PLANE).</summary>
    InPlane = 2,
    /// <summary>Across the plane (retail CROSSING).</summary>
    Crossing = 3,
}
