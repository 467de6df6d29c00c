using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Reference;

/// <summary>
/// The ground truth for the door benchmark: the mover's spheres swept continuously (no sub-steps) with
/// the exact times of impact of <see cref="TimeOfImpact"/> against every shape of a <see cref="ReferenceScene"/>;
/// the mover moves to the earliest contact and slides along it, up to <see cref="MaxContacts"/> times per
/// move (two non-parallel walls stop a grounded mover; three planes stop a free one). A grounded mover
/// moves horizontally only and slides along the horizontal part of each contact normal (no step-up or
/// step-down: it is meant for a flat floor). Slow, allocation-free, thread-safe for concurrent moves.
/// Not retail: retail behaviour lives in <see cref="PhysicsEngine"/>.
/// </summary>
public sealed class ReferenceSweep
{
    /// <summary>Creates a sweep over a scene.</summary>
    public ReferenceSweep(ReferenceScene scene) => Scene = scene ?? throw new ArgumentNullException(nameof(scene));

    /// <summary>The geometry.</summary>
    public ReferenceScene Scene { get; }

    /// <summary>Keep the mover on its floor: horizontal motion, horizontal slide normals (default true).</summary>
    public bool Grounded { get; init; } = true;

    /// <summary>How many contacts one move resolves before it stops (default 8).</summary>
    public int MaxContacts { get; init; } = 8;

    /// <summary>
    /// Moves a mover whose spheres (mover space, axes aligned with the world) are <paramref name="spheres"/>
    /// from <paramref name="from"/> towards <paramref name="to"/> (a grounded mover ignores the height of
    /// <paramref name="to"/>).
    /// </summary>
    public ReferenceMoveResult Move(ReadOnlySpan<Sphere> spheres, Vector3 from, Vector3 to)
    {
        var pos = from;
        var rem = to - from;
        if (Grounded)
            rem.Z = 0f;
        Span<Vector3> planes = stackalloc Vector3[3];
        int planeCount = 0, contacts = 0;
        var first = Vector3.Zero;
        var last = Vector3.Zero;
        float firstDistance = rem.Length();
        float travelled = 0f;
        for (int iter = 0; iter < MaxContacts; iter++)
        {
            if (rem.LengthSquared() < 1e-14f)
                break;
            if (!Earliest(spheres, pos, rem, out var hit))
            {
                pos += rem;
                break;
            }
            pos += hit.Time * rem;
            travelled += hit.Time * rem.Length();
            rem *= 1f - hit.Time;
            var n = hit.Normal;
            if (Grounded)
            {
                n.Z = 0f;
                if (n.LengthSquared() < 1e-12f)
                {
                    rem = Vector3.Zero;
                    contacts++;
                    break;
                }
                n = Vector3.Normalize(n);
            }
            if (contacts == 0)
            {
                first = n;
                firstDistance = travelled;
            }
            last = n;
            contacts++;
            rem = Clip(rem, n);
            bool blocked = false;
            for (int i = 0; i < planeCount; i++)
            {
                if (Vector3.Dot(rem, planes[i]) >= -1e-7f || Vector3.Dot(planes[i], n) > 0.9999f)
                    continue;
                if (Grounded || planeCount >= 2)
                {
                    blocked = true;
                    break;
                }
                var crease = Vector3.Cross(planes[i], n);
                float len = crease.Length();
                if (len < 1e-6f)
                {
                    blocked = true;
                    break;
                }
                crease /= len;
                rem = crease * Vector3.Dot(rem, crease);
            }
            if (blocked)
            {
                rem = Vector3.Zero;
                break;
            }
            if (planeCount < planes.Length)
                planes[planeCount++] = n;
        }
        return new ReferenceMoveResult(pos, contacts, first, last, contacts == 0 ? travelled + rem.Length() : firstDistance);
    }

    /// <summary>The earliest contact of any of the mover's spheres (at <paramref name="origin"/>) moving by <paramref name="displacement"/>.</summary>
    internal bool Earliest(ReadOnlySpan<Sphere> spheres, Vector3 origin, Vector3 displacement, out ImpactHit hit)
    {
        hit = default;
        bool found = false;
        float best = float.PositiveInfinity;
        for (int s = 0; s < spheres.Length; s++)
        {
            var c = origin + spheres[s].Center;
            float r = spheres[s].Radius;
            var polygons = Scene.Polygons;
            for (int i = 0; i < polygons.Count; i++)
                Consider(TimeOfImpact.Polygon(c, displacement, r, polygons[i], out var h), h, ref best, ref hit, ref found);
            var cylinders = Scene.Cylinders;
            for (int i = 0; i < cylinders.Count; i++)
                Consider(TimeOfImpact.Cylinder(c, displacement, r, cylinders[i], out var h), h, ref best, ref hit, ref found);
            var obstacles = Scene.Spheres;
            for (int i = 0; i < obstacles.Count; i++)
                Consider(TimeOfImpact.Sphere(c, displacement, r, obstacles[i], out var h), h, ref best, ref hit, ref found);
        }
        return found;
    }

    private static void Consider(bool ok, in ImpactHit candidate, ref float best, ref ImpactHit hit, ref bool found)
    {
        if (!ok || candidate.Time >= best)
            return;
        best = candidate.Time;
        hit = candidate;
        found = true;
    }

    private static Vector3 Clip(Vector3 motion, Vector3 normal)
    {
        float into = Vector3.Dot(motion, normal);
        return into < 0f ? motion - into * normal : motion;
    }
}
