using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Shapes;

/// <summary>Turns a setup into the collision shapes that represent an object (the retail CPartArray's physics content).</summary>
internal static class ShadowShapeBuilder
{
    /// <summary>
    /// Emits every shape of the setup, scaled as retail scales them: one BSP shape per part that has a
    /// physics model (part origin × scale, model scale = scale × the part's default scale), one cylinder per cylsphere (low point,
    /// radius and height × scale), one sphere per sphere (centre and radius × scale). All are kept: retail
    /// stores both a door's BSP and its cylinder and chooses between them when colliding.
    /// Order: BSP parts, then cylinders, then spheres, each in setup order.
    /// Throws <see cref="ArgumentException"/> naming the field for an invalid setup (see
    /// <see cref="PhysicsSetup.Validate"/>), a scale that is not in (0, <see cref="InputLimits.MaxExtent"/>],
    /// or a shape whose scaled bounds exceed <see cref="InputLimits.MaxExtent"/>.
    /// </summary>
    public static ShadowShape[] FromSetup(PhysicsSetup setup, float scale = 1f, string name = "setup")
    {
        ArgumentNullException.ThrowIfNull(setup);
        Guard.Extent(scale, false, $"{name}.scale");
        setup.Validate(name);
        var shapes = new List<ShadowShape>(setup.Parts.Count + setup.CylSpheres.Count + setup.Spheres.Count);
        for (int i = 0; i < setup.Parts.Count; i++)
        {
            var part = setup.Parts[i];
            if (part.Model is null)
                continue;
            var frame = new Frame(part.Frame.Origin * scale, Guard.Rotation(part.Frame.Orientation, $"{name}.parts[{i}].frame.orientation"));
            shapes.Add(ShadowShape.ForPart(i, part.Model, frame, scale * part.DefaultScale));
        }
        for (int i = 0; i < setup.CylSpheres.Count; i++)
        {
            var c = setup.CylSpheres[i];
            shapes.Add(ShadowShape.ForCylinder(i, new CylSphere(c.LowPoint * scale, c.Radius * scale, c.Height * scale)));
        }
        for (int i = 0; i < setup.Spheres.Count; i++)
        {
            var s = setup.Spheres[i];
            shapes.Add(ShadowShape.ForSphere(i, new Sphere(s.Center * scale, s.Radius * scale)));
        }
        foreach (var shape in shapes)
        {
            string kind = shape.Kind == ShadowShapeKind.Bsp ? "parts" : shape.Kind == ShadowShapeKind.Cylinder ? "cylSpheres" : "spheres";
            Guard.Extent(shape.Bounds.Radius, true, $"{name}.{kind}[{shape.Index}]", ".bounds.radius × scale");
            Guard.Finite(shape.Bounds.Center, $"{name}.{kind}[{shape.Index}]", ".bounds.center × scale");
        }
        return shapes.ToArray();
    }
}
