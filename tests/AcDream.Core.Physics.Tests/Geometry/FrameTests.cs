namespace AcDream.Core.Physics.Tests.Geometry;

public class FrameTests
{
    [Fact]
    public void LocalToGlobal_AndBack_RoundTrips()
    {
        var frame = new Frame(new Vector3(10, 20, 3), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.7f));
        var p = new Vector3(1.5f, -2f, 0.25f);
        var back = frame.GlobalToLocal(frame.LocalToGlobal(p));
        Assert.True(Vector3.Distance(p, back) < 1e-5f);
    }

    [Fact]
    public void LocalToGlobal_RotatesThenTranslates()
    {
        var frame = new Frame(new Vector3(10, 0, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2));
        var g = frame.LocalToGlobal(Vector3.UnitX);
        Assert.True(Vector3.Distance(new Vector3(10, 1, 0), g) < 1e-5f);
    }
}
