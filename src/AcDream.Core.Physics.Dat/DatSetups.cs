using System;
using System.Collections.Generic;
using DatReaderWriter.DBObjs;
using AcDream.Core.Physics.Validation;
using DatReaderWriter.Enums;

namespace AcDream.Core.Physics.Dat;

/// <summary>A Setup (portal DAT 0x02xxxxxx, retail CSetup) to the runtime's <see cref="PhysicsSetup"/>.</summary>
public static class DatSetups
{
    /// <summary>The most parts a setup may have (retail's largest setups have a few dozen).</summary>
    public const int MaxParts = 256;

    /// <summary>The most spheres or cylinder-spheres a setup may have.</summary>
    public const int MaxShapes = 256;

    /// <summary>
    /// Converts a setup: its parts in order, each with its GfxObj's model (<paramref name="partModel"/>, null for
    /// a part without physics) placed by the setup's resting placement frame, else its default one (retail
    /// places parts by placement 0x65 and falls back to 0: <c>CPartArray::SetPlacementFrame</c>), scaled by the
    /// Z of its default scale when <c>HasDefaultScale</c> is set (retail collides a part's BSP with the Z
    /// component); its cylinder-spheres and spheres in order; height, radius, step-up and step-down heights.
    /// <c>HasPhysicsBSP</c> is not copied: the registry sets <see cref="PhysicsState.HasPhysicsBsp"/> from the
    /// parts (<see cref="PhysicsSetup.HasPhysicsBsp"/>, retail <c>CacheHasPhysicsBSP</c>). Parent indices,
    /// holding locations, connection points, sorting and selection spheres, lights and defaults are not read.
    /// </summary>
    /// <param name="setup">The setup as read.</param>
    /// <param name="partModel">The model of a part's GfxObj id (e.g. <see cref="DatModels.ToPhysicsModel"/> through a cache), or null when it has none.</param>
    /// <exception cref="DatObjectException">A count is beyond <see cref="MaxParts"/> or <see cref="MaxShapes"/>, a placement frame or default scale list does not match the parts, or the runtime refuses a value (<see cref="PhysicsSetup.Validate"/>); the message names the setup id.</exception>
    public static PhysicsSetup ToPhysicsSetup(Setup setup, Func<uint, PhysicsModel?> partModel)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(partModel);
        uint id = setup.Id;
        int count = setup.Parts?.Count ?? 0;
        if (count > MaxParts)
            throw new DatObjectException(id, $"parts: a setup has at most {MaxParts} parts (DatSetups.MaxParts), got {count}.");
        if ((setup.CylSpheres?.Count ?? 0) > MaxShapes || (setup.Spheres?.Count ?? 0) > MaxShapes)
            throw new DatObjectException(id, $"spheres: a setup has at most {MaxShapes} spheres and {MaxShapes} cylSpheres (DatSetups.MaxShapes), got {setup.Spheres?.Count ?? 0} and {setup.CylSpheres?.Count ?? 0}.");
        bool scaled = setup.Flags.HasFlag(SetupFlags.HasDefaultScale);
        if (scaled && (setup.DefaultScale?.Count ?? 0) != count)
            throw new DatObjectException(id, $"defaultScale: HasDefaultScale is set but the list has {setup.DefaultScale?.Count ?? 0} entries for {count} parts.");
        var frames = PlacementFrames(setup, count);
        var parts = new SetupPart[count];
        for (int i = 0; i < count; i++)
        {
            var model = partModel(setup.Parts![i].DataId);
            var frame = frames is null ? Frame.Identity : ToFrame(frames[i], id, $"placementFrames.frames[{i}]");
            float scale = scaled ? setup.DefaultScale![i].Z : 1f;
            parts[i] = new SetupPart(model, frame, scale);
        }
        var cylSpheres = new List<CylSphere>(setup.CylSpheres?.Count ?? 0);
        foreach (var c in setup.CylSpheres ?? [])
            cylSpheres.Add(c is null
                ? throw new DatObjectException(id, $"cylSpheres[{cylSpheres.Count}]: is null.")
                : new CylSphere(c.Origin, c.Radius, c.Height));
        var spheres = new List<Sphere>(setup.Spheres?.Count ?? 0);
        foreach (var s in setup.Spheres ?? [])
            spheres.Add(s is null
                ? throw new DatObjectException(id, $"spheres[{spheres.Count}]: is null.")
                : new Sphere(s.Origin, s.Radius));
        var result = new PhysicsSetup
        {
            Parts = parts,
            CylSpheres = cylSpheres,
            Spheres = spheres,
            Height = setup.Height,
            Radius = setup.Radius,
            StepUpHeight = setup.StepUpHeight,
            StepDownHeight = setup.StepDownHeight,
        };
        try
        {
            result.Validate($"Setup 0x{id:X8}");
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(id, ex.Message, ex);
        }
        return result;
    }

    /// <summary>
    /// The setup of an object placed directly by a GfxObj id (a landblock's or a cell's static object whose id
    /// is 0x01xxxxxx): one part, its model at the identity frame, no spheres.
    /// </summary>
    /// <param name="model">The GfxObj's model, or null when it has no physics.</param>
    public static PhysicsSetup FromModel(PhysicsModel? model) => new() { Parts = [new SetupPart(model, Frame.Identity)] };

    /// <summary>The part frames retail places a new object's parts by: placement Resting (0x65), else Default (0); none when the setup has neither.</summary>
    private static List<DatReaderWriter.Types.Frame>? PlacementFrames(Setup setup, int count)
    {
        if (setup.PlacementFrames is null)
            return null;
        foreach (var placement in new[] { Placement.Resting, Placement.Default })
        {
            if (!setup.PlacementFrames.TryGetValue(placement, out var animationFrame) || animationFrame is null)
                continue;
            int have = animationFrame.Frames?.Count ?? 0;
            if (have != count)
                throw new DatObjectException(setup.Id, $"placementFrames[{placement}]: has {have} frames for {count} parts.");
            return animationFrame.Frames;
        }
        return null;
    }

    /// <summary>A DAT frame (origin, quaternion as stored) as the runtime's; the runtime's checks run where it is used.</summary>
    internal static Frame ToFrame(DatReaderWriter.Types.Frame? frame, uint objectId, string field) =>
        frame is null
            ? throw new DatObjectException(objectId, $"{field}: is missing.")
            : new Frame(frame.Origin, frame.Orientation);

    /// <summary>
    /// A static object's frame, checked as the world checks an object it registers (an origin within the coordinate
    /// limit, a rotation it can normalize), so a damaged one is refused where it is read, naming the DAT object and
    /// the field, rather than by the world naming only the object's game id.
    /// </summary>
    internal static Frame ToPlacementFrame(DatReaderWriter.Types.Frame? frame, uint objectId, string field)
    {
        var result = ToFrame(frame, objectId, field);
        if (!Guard.IsValidFrame(result))
        {
            try
            {
                Guard.Frame(result, field);
            }
            catch (ArgumentException ex)
            {
                throw new DatObjectException(objectId, ex.Message, ex);
            }
        }
        return result;
    }
}
