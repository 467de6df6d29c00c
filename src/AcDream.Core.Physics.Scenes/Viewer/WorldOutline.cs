using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Viewer;

/// <summary>
/// Every collision shape of a world — indoor cells' and buildings' polygons, objects' BSP polygons,
/// cylinders and spheres — placed in one landblock frame, for tools that draw a scene. Allocates; not
/// for the per-frame path.
/// </summary>
internal static class WorldOutline
{
    /// <summary>The shapes, in the frame of <paramref name="frameCellId"/>'s landblock; each object shape once.</summary>
    public static IReadOnlyList<OutlineShape> Collect(PhysicsWorld world, uint frameCellId)
    {
        ArgumentNullException.ThrowIfNull(world);
        var shapes = new List<OutlineShape>();
        var seen = new HashSet<(uint, ShadowShapeKind, int)>();
        foreach (uint id in world.Cells.CellIds)
        {
            var cell = world.Cells.Get(id);
            var shift = LandDefs.BlockOffset(frameCellId, id);
            if (cell is EnvCell { PhysicsBsp: { } bsp } env)
                AddTree(shapes, bsp, env.Position.Frame, shift, 1f, OutlineSource.EnvCell, id, 0, true);
            if (cell is LandCell { Building: { } building })
                AddTree(shapes, building.Shell.Bsp, building.Position.Frame, shift, 1f, OutlineSource.Building, id, 0, true);
            foreach (var row in world.Objects.RowsInCell(id))
                if (seen.Add((row.EntityId, row.Kind, row.Shape.Index)))
                    AddObjectShape(shapes, row, frameCellId);
        }
        return shapes;
    }

    private static void AddObjectShape(List<OutlineShape> shapes, in ShadowEntry row, uint frameCellId)
    {
        bool collides = row.Kind == ObjectCollisions.PlainDispatchRung(row);
        var shift = LandDefs.BlockOffset(frameCellId, row.Position.CellId);
        var shape = row.Shape;
        switch (shape.Kind)
        {
            case ShadowShapeKind.Bsp:
                AddTree(shapes, shape.Model!.Bsp, row.Position.Frame.Combine(shape.PartFrame), shift, shape.ModelScale,
                    OutlineSource.Object, row.Position.CellId, row.EntityId, collides);
                break;
            case ShadowShapeKind.Cylinder:
                var c = shape.Cylinder;
                shapes.Add(new OutlineShape(OutlineSource.Object, OutlineForm.Cylinder, row.Position.CellId, row.EntityId, collides,
                    Array.Empty<Vector3>(), row.Position.LocalToGlobal(c.LowPoint) + shift, c.Radius, c.Height));
                break;
            default:
                var s = shape.Sphere;
                shapes.Add(new OutlineShape(OutlineSource.Object, OutlineForm.Sphere, row.Position.CellId, row.EntityId, collides,
                    Array.Empty<Vector3>(), row.Position.LocalToGlobal(s.Center) + shift, s.Radius, 0f));
                break;
        }
    }

    private static void AddTree(List<OutlineShape> shapes, BspTree tree, in Frame frame, Vector3 shift, float scale,
        OutlineSource source, uint cellId, uint objectId, bool collides)
    {
        foreach (var polygon in tree.Polygons)
        {
            var local = polygon.Vertices;
            var placed = new Vector3[local.Length];
            for (int i = 0; i < local.Length; i++)
                placed[i] = frame.LocalToGlobal(local[i] * scale) + shift;
            shapes.Add(new OutlineShape(source, OutlineForm.Polygon, cellId, objectId, collides, placed, default, 0f, 0f));
        }
    }
}
