using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>An independent sphere-versus-oriented-box distance check (no library geometry involved).</summary>
internal static class Penetration
{
    /// <summary>How deep a sphere reaches into a box (positive: overlap; ≤ 0: clear by that much).</summary>
    public static float SphereIntoBox(Vector3 centre, float radius, SceneFuzzer.Solid box)
    {
        var local = Vector3.Transform(centre - box.Origin, Quaternion.Conjugate(box.Rotation));
        var h = box.HalfSize;
        var q = Vector3.Abs(local) - h;
        float outside = Vector3.Max(q, Vector3.Zero).Length();
        float inside = MathF.Min(MathF.Max(q.X, MathF.Max(q.Y, q.Z)), 0f);
        return radius - (outside + inside);
    }

    /// <summary>The deepest reach of the case's mover at a position into any of the case's solids (−∞ when none).</summary>
    public static float Worst(SceneFuzzer.Case c, in Position position) => Worst(c, position, out _);

    public static float Worst(SceneFuzzer.Case c, in Position position, out uint solidId)
    {
        float worst = float.NegativeInfinity;
        solidId = 0;
        foreach (var s in c.Mover.Spheres)
        {
            var centre = position.Frame.LocalToGlobal(s.Center * c.Mover.Scale);
            foreach (var solid in c.Solids)
            {
                float d = SphereIntoBox(centre, s.Radius * c.Mover.Scale, solid);
                if (d > worst) { worst = d; solidId = solid.Id; }
            }
        }
        return worst;
    }
}
