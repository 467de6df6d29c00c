using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Reference;

/// <summary>
/// World-space geometry for <see cref="ReferenceSweep"/>: polygons, world-Z cylinders and spheres, in
/// whatever frame the caller moves the mover in (for example a landblock's local frame).
/// </summary>
public sealed class ReferenceScene
{
    private readonly List<Polygon> _polygons = new();
    private readonly List<CylSphere> _cylinders = new();
    private readonly List<Sphere> _spheres = new();

    /// <summary>The polygons (convex).</summary>
    public IReadOnlyList<Polygon> Polygons => _polygons;
    /// <summary>The cylinders (axis world Z).</summary>
    public IReadOnlyList<CylSphere> Cylinders => _cylinders;
    /// <summary>The spheres.</summary>
    public IReadOnlyList<Sphere> Spheres => _spheres;

    /// <summary>Adds a world-space polygon.</summary>
    public void Add(Polygon polygon) => _polygons.Add(polygon ?? throw new ArgumentNullException(nameof(polygon)));

    /// <summary>Adds a world-space cylinder.</summary>
    public void Add(CylSphere cylinder) => _cylinders.Add(cylinder);

    /// <summary>Adds a world-space sphere.</summary>
    public void Add(Sphere sphere) => _spheres.Add(sphere);

    /// <summary>
    /// Adds an object placed at <paramref name="frame"/> with a uniform <paramref name="scale"/>, keeping the
    /// shapes the retail dispatch collides with: the parts' physics BSP polygons when any part has one
    /// (a door is its slab, never its foot cylinder), otherwise its cylinders, otherwise its spheres.
    /// </summary>
    public void AddObject(PhysicsSetup setup, Frame frame, float scale = 1f)
    {
        ArgumentNullException.ThrowIfNull(setup);
        if (setup.HasPhysicsBsp)
        {
            foreach (var part in setup.Parts)
            {
                if (part?.Model is null)
                    continue;
                foreach (var polygon in part.Model.Bsp.Polygons)
                {
                    var v = polygon.Vertices;
                    var world = new Vector3[v.Length];
                    for (int i = 0; i < v.Length; i++)
                        world[i] = frame.LocalToGlobal(scale * part.Frame.LocalToGlobal(v[i]));
                    _polygons.Add(new Polygon(world, polygon.Sides, "reference polygon"));
                }
            }
        }
        else if (setup.CylSpheres.Count > 0)
        {
            foreach (var cyl in setup.CylSpheres)
                _cylinders.Add(new CylSphere(frame.LocalToGlobal(scale * cyl.LowPoint), cyl.Radius * scale, cyl.Height * scale));
        }
        else
        {
            foreach (var sphere in setup.Spheres)
                _spheres.Add(new Sphere(frame.LocalToGlobal(scale * sphere.Center), sphere.Radius * scale));
        }
    }
}
