using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// What a retail Setup carries for collision, and nothing more: parts with physics models, cylspheres,
/// spheres, the object's height and radius, and its step heights. Setup-space, unscaled.
/// </summary>
public sealed class PhysicsSetup
{
    /// <summary>The parts, in retail order.</summary>
    public IReadOnlyList<SetupPart> Parts { get; init; } = Array.Empty<SetupPart>();
    /// <summary>The collision cylinders (axis world Z).</summary>
    public IReadOnlyList<CylSphere> CylSpheres { get; init; } = Array.Empty<CylSphere>();
    /// <summary>The collision spheres.</summary>
    public IReadOnlyList<Sphere> Spheres { get; init; } = Array.Empty<Sphere>();
    /// <summary>
    /// The Setup's height, metres, unscaled (DAT Setup <c>Height</c>). Not used for collision: no transition,
    /// query or registry code reads it; <see cref="Validate"/> only checks it (finite, in
    /// [0, <see cref="InputLimits.MaxExtent"/>]). Objects collide by their parts' BSPs, cylspheres and
    /// spheres. Retail reads it, times the object's Z scale (CPartArray::GetHeight), outside collision: for
    /// distances between objects in movement (MoveToManager's cylinder distance), sticking to a target and
    /// combat's attack height. Kept so a setup carries what the Setup does; 0 when unknown.
    /// </summary>
    public float Height { get; init; }
    /// <summary>
    /// The Setup's radius, metres, unscaled (DAT Setup <c>Radius</c>). Not used for collision, like
    /// <see cref="Height"/>: only <see cref="Validate"/> reads it. Retail scales it by the object's Z scale
    /// (CPartArray::GetRadius) for movement distances, sticking and combat, never in a transition; the
    /// collision extent of an object comes from its shapes' bounding spheres. 0 when unknown.
    /// </summary>
    public float Radius { get; init; }
    /// <summary>How high a mover with this setup may step up.</summary>
    public float StepUpHeight { get; init; }
    /// <summary>How far a mover with this setup steps down to stay grounded.</summary>
    public float StepDownHeight { get; init; }

    /// <summary>True when any part has a physics BSP (retail CacheHasPhysicsBSP).</summary>
    public bool HasPhysicsBsp
    {
        get
        {
            foreach (var part in Parts)
                if (part?.Model is not null)
                    return true;
            return false;
        }
    }

    /// <summary>
    /// Checks every field; throws an <see cref="ArgumentException"/> naming the first bad one: null lists or
    /// parts, non-finite or out-of-range frames, centres and low points (±<see cref="InputLimits.MaxCoordinate"/>),
    /// zero-length part rotations, radii not in (0, <see cref="InputLimits.MaxExtent"/>], heights and step
    /// heights not in [0, <see cref="InputLimits.MaxExtent"/>].
    /// </summary>
    public void Validate(string name = "setup")
    {
        if (Parts is null) throw new ArgumentException($"{name}.parts: is null.", $"{name}.parts");
        if (CylSpheres is null) throw new ArgumentException($"{name}.cylSpheres: is null.", $"{name}.cylSpheres");
        if (Spheres is null) throw new ArgumentException($"{name}.spheres: is null.", $"{name}.spheres");
        for (int i = 0; i < Parts.Count; i++)
        {
            if (Parts[i] is null) throw new ArgumentException($"{name}.parts[{i}]: is null.", $"{name}.parts[{i}]");
            Guard.Frame(Parts[i].Frame, $"{name}.parts[{i}].frame");
            Guard.Positive(Parts[i].DefaultScale, $"{name}.parts[{i}].defaultScale");
        }
        for (int i = 0; i < CylSpheres.Count; i++)
            Guard.CylSphere(CylSpheres[i], $"{name}.cylSpheres[{i}]");
        for (int i = 0; i < Spheres.Count; i++)
            Guard.Sphere(Spheres[i], $"{name}.spheres[{i}]");
        Guard.Extent(Height, true, $"{name}.height");
        Guard.Extent(Radius, true, $"{name}.radius");
        Guard.Extent(StepUpHeight, true, $"{name}.stepUpHeight");
        Guard.Extent(StepDownHeight, true, $"{name}.stepDownHeight");
    }
}
