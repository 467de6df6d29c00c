using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Viewer;

/// <summary>
/// Every shape of a world the viewer draws — terrain triangles, indoor cells' polygons and portals, building shells,
/// objects' BSP polygons, cylinders and spheres — in the frame of one landblock. It reads the world's internals (the
/// terrain triangles, the shadow rows) that the runtime does not publish; tooling only, allocates.
/// </summary>
internal static class ViewShapes
{
    /// <summary>The shapes, cell by cell in id order (each object shape once), in the frame of <paramref name="frameCellId"/>'s landblock.</summary>
    public static List<ViewShape> Collect(PhysicsWorld world, uint frameCellId)
    {
        ArgumentNullException.ThrowIfNull(world);
        var shapes = new List<ViewShape>();
        var seen = new HashSet<(uint, ShadowShapeKind, int)>();
        foreach (uint id in world.Cells.CellIds.Order())
        {
            var cell = world.Cells.Get(id);
            var shift = LandDefs.BlockOffset(frameCellId, id);
            if (cell is LandCell land)
            {
                var (first, second) = land.Triangles;
                // The triangles are landblock-local already: only shifted into the view's landblock.
                foreach (var triangle in new[] { first, second })
                    shapes.Add(new ViewShape(ViewSource.Terrain, OutlineForm.Polygon, id, 0, true, triangle.Sides,
                        triangle.Vertices.ToArray().Select(v => v + shift).ToArray(), default, 0f, 0f));
                if (land.Building is { } building)
                    foreach (var polygon in building.Shell.Bsp.Polygons)
                        AddPolygon(shapes, ViewSource.Building, id, 0, true, polygon, building.Position.Frame, shift, 1f);
            }
            if (cell is EnvCell env)
            {
                if (env.PhysicsBsp is { } bsp)
                    foreach (var polygon in bsp.Polygons)
                        AddPolygon(shapes, ViewSource.EnvCell, id, 0, true, polygon, env.Position.Frame, shift, 1f);
                foreach (var portal in env.Portals)
                    AddPolygon(shapes, ViewSource.Portal, id, 0, false, portal.Polygon, env.Position.Frame, shift, 1f, portal.OtherCellId);
            }
            foreach (var row in world.Objects.RowsInCell(id))
                if (seen.Add((row.EntityId, row.Kind, row.Shape.Index)))
                    AddObjectShape(shapes, row, frameCellId);
        }
        return shapes;
    }

    private static void AddObjectShape(List<ViewShape> shapes, in ShadowEntry row, uint frameCellId)
    {
        // The rung of retail's dispatch ladder the object collides by: its BSP parts, else its cylspheres, else its spheres.
        bool collides = row.Kind == ObjectCollisions.PlainDispatchRung(row);
        uint cell = row.Position.CellId;
        var shift = LandDefs.BlockOffset(frameCellId, cell);
        var shape = row.Shape;
        switch (shape.Kind)
        {
            case ShadowShapeKind.Bsp:
                var frame = row.Position.Frame.Combine(shape.PartFrame);
                foreach (var polygon in shape.Model!.Bsp.Polygons)
                    AddPolygon(shapes, ViewSource.Object, cell, row.EntityId, collides, polygon, frame, shift, shape.ModelScale);
                break;
            case ShadowShapeKind.Cylinder:
                var c = shape.Cylinder;
                shapes.Add(new ViewShape(ViewSource.Object, OutlineForm.Cylinder, cell, row.EntityId, collides, PolygonSides.Single,
                    Array.Empty<Vector3>(), row.Position.LocalToGlobal(c.LowPoint) + shift, c.Radius, c.Height));
                break;
            default:
                var s = shape.Sphere;
                shapes.Add(new ViewShape(ViewSource.Object, OutlineForm.Sphere, cell, row.EntityId, collides, PolygonSides.Single,
                    Array.Empty<Vector3>(), row.Position.LocalToGlobal(s.Center) + shift, s.Radius, 0f));
                break;
        }
    }

    private static void AddPolygon(List<ViewShape> shapes, ViewSource source, uint cellId, uint objectId, bool collides,
        Polygon polygon, in Frame frame, Vector3 shift, float scale, uint otherCellId = 0)
    {
        var local = polygon.Vertices;
        var placed = new Vector3[local.Length];
        for (int i = 0; i < local.Length; i++)
            placed[i] = frame.LocalToGlobal(local[i] * scale) + shift;
        shapes.Add(new ViewShape(source, OutlineForm.Polygon, cellId, objectId, collides, polygon.Sides, placed, default, 0f, 0f, otherCellId));
    }
}
