using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Geometry;

public class PortableRotationTests
{
    [Fact]
    public void AQuarterTurnAboutZ_TakesXToY()
    {
        var quarter = new Quaternion(0, 0, MathF.Sqrt(0.5f), MathF.Sqrt(0.5f));
        var v = PortableRotation.Apply(Vector3.UnitX, quarter);
        Assert.Equal(0f, v.X, 6);
        Assert.Equal(1f, v.Y, 6);
        Assert.Equal(0f, v.Z, 6);
        Assert.Equal(new Vector3(1, 2, 3), PortableRotation.Apply(new Vector3(1, 2, 3), Quaternion.Identity));
    }

    [Fact]
    public void AgreesWithVector3Transform_WithinRounding()
    {
        var r = new Random(8);
        for (int i = 0; i < 10_000; i++)
        {
            var q = Quaternion.Normalize(new Quaternion(r.NextSingle() - 0.5f, r.NextSingle() - 0.5f, r.NextSingle() - 0.5f, r.NextSingle() - 0.5f));
            var v = new Vector3(r.NextSingle() * 20 - 10, r.NextSingle() * 20 - 10, r.NextSingle() * 20 - 10);
            var d = PortableRotation.Apply(v, q) - Vector3.Transform(v, q);
            Assert.True(d.Length() <= 1e-5f, $"rotating {v} by {q}: off by {d}");
        }
    }
}
