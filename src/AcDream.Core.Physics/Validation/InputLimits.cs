namespace AcDream.Core.Physics.Validation;

/// <summary>
/// The ranges every public entry point accepts, so that no arithmetic inside a query can overflow to
/// infinity or NaN. These are the library's own limits, not retail values (retail checks nothing).
/// </summary>
public static class InputLimits
{
    /// <summary>
    /// The largest absolute value of any coordinate given to the library (positions, vertices, centres,
    /// heights, plane distances), in metres: 100 km, twice the width of the retail world, so a point of
    /// any landblock can be written in any other landblock's frame. Products of three such values stay
    /// far below float's range.
    /// </summary>
    public const float MaxCoordinate = 100_000f;

    /// <summary>
    /// The largest size of any single thing, in metres: 1 km, for sphere, cylinder and model radii (after
    /// scaling), heights, step heights and scales. Retail's largest objects are a few hundred metres across.
    /// </summary>
    public const float MaxExtent = 1_000f;
}
