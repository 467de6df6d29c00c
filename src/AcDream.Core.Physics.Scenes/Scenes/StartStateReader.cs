using System;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Reads a mover's full start state — the <see cref="MoverState"/> a recorded situation carries from the
/// frame before: position, cell and rotation, contact and walkable flags, the contact plane with the cell
/// whose landblock space it is in (sloped or not), the water flag and a carried sliding normal. One
/// reader for the scene format's mover "start" object and the real-cell parity files' "start" object
/// (docs/scene-format.md). Every error names the JSON path of the bad value.
/// </summary>
internal static class StartStateReader
{
    /// <summary>Reads the object at <paramref name="path"/>; cells must exist in <paramref name="world"/>.</summary>
    public static MoverState Read(JsonElement e, string path, PhysicsWorld world)
    {
        var o = new JsonObj(e, path);
        var origin = o.Vec3("position");
        Check(o.Child("position"), () => Guard.Finite(origin, o.Child("position")));
        uint cell = Cell(o, "cell", world);
        var rotation = o.Rotation("rotation");
        bool contact = Flag(o, "contact");
        bool walkable = Flag(o, "walkable");
        bool water = Flag(o, "water");
        var state = new MoverState
        {
            Position = new Position(cell, new Frame(origin, rotation)),
            Contact = contact,
            OnWalkable = walkable,
            ContactPlaneIsWater = water,
        };
        // A contact plane cell of 0 says "no plane known" (a mover that has not touched the ground yet);
        // the plane, if written, must then be all zero.
        bool noPlane = o.Opt("contactPlaneCell") is { } cpc && JsonRead.Id(cpc, o.Child("contactPlaneCell")) == 0;
        if (o.Opt("contactPlane") is { } cp && !(noPlane && IsZeroPlane(cp)))
        {
            string cpPath = o.Child("contactPlane");
            if (noPlane)
                throw new SceneFormatException(o.Child("contactPlaneCell"), "is 0 (no plane known), but \"contactPlane\" is not all zero.");
            var items = JsonRead.Array(cp, cpPath);
            if (items.Count != 4)
                throw new SceneFormatException(cpPath, $"a plane [nx, ny, nz, d] needs 4 numbers, got {items.Count}.");
            var normal = new Vector3(JsonRead.Float(items[0].Value, items[0].Path), JsonRead.Float(items[1].Value, items[1].Path),
                JsonRead.Float(items[2].Value, items[2].Path));
            float d = JsonRead.Float(items[3].Value, items[3].Path);
            Check(cpPath, () => Guard.UnitNormal(normal, cpPath, ".normal"));
            Check(items[3].Path, () => Guard.Coordinate(d, items[3].Path));
            state.ContactPlane = new Plane(normal, d);
            state.ContactPlaneCellId = o.Has("contactPlaneCell") ? Cell(o, "contactPlaneCell", world) : cell;
        }
        else
        {
            if (contact)
                throw o.Missing(o.Child("contactPlane"), "is required when \"contact\" is set.", "contactPlane");
            if (o.Has("contactPlaneCell") && !noPlane)
                throw new SceneFormatException(o.Child("contactPlaneCell"), "needs a \"contactPlane\".");
            if (water)
                throw new SceneFormatException(o.Child("water"), "needs a \"contactPlane\".");
        }
        if (walkable && !contact)
            throw new SceneFormatException(o.Child("walkable"), "a mover on walkable ground must also be in contact.");
        if (o.Opt("sliding") is { } sl)
        {
            var normal = JsonRead.Vec3(sl, o.Child("sliding"));
            Check(o.Child("sliding"), () => Guard.Finite(normal, o.Child("sliding")));
            state.SlidingNormalValid = true;
            state.SlidingNormal = normal;
        }
        o.End();
        return state;
    }

    private static bool IsZeroPlane(JsonElement e)
    {
        if (e.ValueKind != JsonValueKind.Array)
            return false;
        foreach (var item in e.EnumerateArray())
            if (item.ValueKind != JsonValueKind.Number || !item.TryGetDouble(out double v) || v != 0)
                return false;
        return true;
    }

    private static uint Cell(JsonObj o, string name, PhysicsWorld world)
    {
        uint cell = o.Id(name);
        if (world.Cells.Get(cell) is null)
            throw new SceneFormatException(o.Child(name), $"unknown cell 0x{cell:X8}.");
        return cell;
    }

    // A flag written as true/false or 0/1 (the parity files write 0/1); absent means false.
    private static bool Flag(JsonObj o, string name)
    {
        if (o.Opt(name) is not { } v)
            return false;
        if (v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out int n) && n is 0 or 1)
            return n == 1;
        if (v.ValueKind is JsonValueKind.True or JsonValueKind.False)
            return v.ValueKind == JsonValueKind.True;
        throw new SceneFormatException(o.Child(name), $"expected true, false, 0 or 1, got {JsonRead.Kind(v)}.");
    }

    private static void Check(string path, Action check)
    {
        try
        {
            check();
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap(path, ex);
        }
    }
}
