namespace AcDream.Core.Physics.Tests.Support;

internal static class AssertVec
{
    public static void Near(Vector3 expected, Vector3 actual, float tolerance = 1e-5f)
    {
        if (!(Vector3.Distance(expected, actual) <= tolerance))
            throw new Xunit.Sdk.XunitException($"Expected {expected} ± {tolerance}, got {actual} (off by {Vector3.Distance(expected, actual)}).");
    }
}
