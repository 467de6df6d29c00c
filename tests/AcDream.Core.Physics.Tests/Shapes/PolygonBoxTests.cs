using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Shapes;

/// <summary>
/// The box of a BSP part's polygons that lets a move skip the part's test when no check sphere reaches it
/// (<see cref="PartCollision.MayTouchPolygons"/>): it must hold every placed polygon, and it must never
/// skip a part that a sphere hits by retail's precise polygon test.
/// </summary>
public class PolygonBoxTests
{
    // The door slab turned 30° about Z and 10° about X, scaled 1.7, standing at (100, 100, 0).
    private static readonly Quaternion Turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6) * Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI / 18);
    private const float Scale = 1.7f;

    private static ShadowEntry TurnedDoorRow() => DoorRow(Turn);

    // The slab turned about Z only: it stands upright.
    private static ShadowEntry UprightDoorRow() => DoorRow(Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6));

    private static ShadowEntry DoorRow(Quaternion turn)
    {
        var shapes = ShadowShapeBuilder.FromSetup(TestGeometry.DoorSetup(), Scale);
        var part = shapes.First(s => s.Kind == ShadowShapeKind.Bsp);
        var position = new Position(TestGeometry.At(100, 100, 0).CellId, new Frame(new Vector3(100, 100, 0), turn));
        return new ShadowEntry(TestScenes.DoorId, part, position, Scale, PhysicsState.HasPhysicsBsp, ShadowFlags.None, 0, 0);
    }

    /// <summary>
    /// In the walkable searches (step down, the step-up search, the walkable check) only polygons facing the
    /// world's up more than the walkable allowance count: for the upright slab no sphere that hits such a
    /// polygon (its top) is skipped, while spheres touching only its faces are; for the tilted slab, and for
    /// an allowance too small to rule out level faces, the box of all polygons is used.
    /// </summary>
    [Theory]
    [InlineData(true, 0.0871557f)]
    [InlineData(true, 0.002f)]
    [InlineData(true, 0.0015f)]
    [InlineData(false, 0.0871557f)]
    public void InTheWalkableSearches_NoSphereThatHitsAWalkablePolygon_IsSkipped(bool upright, float allowance)
    {
        var row = upright ? UprightDoorRow() : TurnedDoorRow();
        var polygons = row.Shape.Model!.Bsp.Polygons;
        var up = row.PartPosition.GlobalToLocalVec(Vector3.UnitZ);
        int walkableHits = 0, faceOnlySkipped = 0;
        foreach (var mode in new[] { "stepDown", "collide", "checkWalkable" })
        {
            var path = new SpherePath
            {
                NumSphere = 1, InsertType = InsertType.Transition, WalkableAllowance = allowance,
                StepDown = mode == "stepDown", Collide = mode == "collide", CheckWalkable = mode == "checkWalkable",
            };
            for (float x = 98f; x <= 102f; x += 0.25f)
                for (float y = 98f; y <= 102f; y += 0.25f)
                    for (float z = -0.5f; z <= 4.5f; z += 0.25f)
                    {
                        var centre = new Vector3(x, y, z);
                        var local = new Sphere(row.PartPosition.GlobalToLocalVec(centre - row.PartPosition.Frame.Origin) / Scale, 0.48f / Scale);
                        bool walkableHit = false, anyHit = false;
                        foreach (var polygon in polygons)
                        {
                            bool hit = PolygonQuery.HitsSphere(polygon, local);
                            anyHit |= hit;
                            walkableHit |= hit && PolygonQuery.WalkableHitsSphere(polygon, local, up, allowance);
                        }
                        path.CheckPos = new Position(row.PartPosition.CellId, centre);
                        path.GlobalSphere[0] = new Sphere(centre, 0.48f);
                        bool mayTouch = PartCollision.MayTouchPolygons(path, row);
                        Assert.True(mayTouch || !walkableHit, $"{mode}: sphere at {centre} hits a walkable polygon but was skipped");
                        if (walkableHit) walkableHits++;
                        if (anyHit && !mayTouch) faceOnlySkipped++;
                    }
        }
        Assert.True(walkableHits > 100, $"the grid should reach the top; {walkableHits} walkable hits");
        bool walkableBoxUsed = upright && allowance >= 0.002f;
        Assert.True(walkableBoxUsed == (faceOnlySkipped > 0), $"spheres touching only non-walkable faces skipped: {faceOnlySkipped}");
    }

    [Fact]
    public void TheBox_HoldsEveryPolygonVertex_AsPlacedAndScaled()
    {
        var row = TurnedDoorRow();
        foreach (var polygon in row.Shape.Model!.Bsp.Polygons)
            foreach (var vertex in polygon.Vertices)
            {
                var placed = row.PartPosition.LocalToGlobal(vertex * Scale);
                Assert.True(placed.X >= row.PolygonsMin.X && placed.Y >= row.PolygonsMin.Y && placed.Z >= row.PolygonsMin.Z
                    && placed.X <= row.PolygonsMax.X && placed.Y <= row.PolygonsMax.Y && placed.Z <= row.PolygonsMax.Z,
                    $"vertex {vertex} placed at {placed} is outside the box {row.PolygonsMin}..{row.PolygonsMax}");
            }
    }

    /// <summary>
    /// On a grid of spheres around the turned, scaled slab (seen from its own landblock and from the one to
    /// the east), every sphere that retail's precise test finds touching a polygon is let through; spheres
    /// clear of the slab but inside its bounding sphere are skipped (the point of the box).
    /// </summary>
    [Fact]
    public void NoSphereThatHitsAPolygon_IsSkipped()
    {
        var row = TurnedDoorRow();
        var polygons = row.Shape.Model!.Bsp.Polygons;
        var path = new SpherePath { NumSphere = 1, InsertType = InsertType.Transition };
        var bounds = row.Shape.Bounds;
        int hits = 0, skippedInsideBounds = 0;
        foreach (float radius in new[] { 0.48f, 0.2f })
            for (float x = 97.5f; x <= 102.5f; x += 0.125f)
                for (float y = 97.5f; y <= 102.5f; y += 0.125f)
                    for (float z = -0.5f; z <= 4.5f; z += 0.25f)
                    {
                        var centre = new Vector3(x, y, z);
                        var local = row.PartPosition.GlobalToLocalVec(centre - row.PartPosition.Frame.Origin) / Scale;
                        var localSphere = new Sphere(local, radius / Scale);
                        bool hit = false;
                        foreach (var polygon in polygons)
                            hit |= PolygonQuery.HitsSphere(polygon, localSphere);
                        foreach (bool east in new[] { false, true })
                        {
                            uint cell = row.PartPosition.CellId;
                            var seen = centre;
                            if (east)
                            {
                                cell += 0x0100_0000;
                                seen.X -= PhysicsConstants.LandblockLength;
                            }
                            path.CheckPos = new Position(cell, seen);
                            path.GlobalSphere[0] = new Sphere(seen, radius);
                            bool mayTouch = PartCollision.MayTouchPolygons(path, row);
                            Assert.True(mayTouch || !hit, $"sphere r {radius} at {centre} (east: {east}) hits a polygon but was skipped");
                            if (hit) hits++;
                            if (!mayTouch && Vector3.Distance(centre, row.Position.LocalToGlobal(bounds.Center)) < bounds.Radius + radius) skippedInsideBounds++;
                        }
                    }
        // Placement and an ethereal obstruction run solid tests, which the box does not answer: never skipped.
        path.CheckPos = new Position(row.PartPosition.CellId, new Vector3(97.5f, 97.5f, 4.5f));
        path.GlobalSphere[0] = new Sphere(path.CheckPos.Origin, 0.2f);
        Assert.False(PartCollision.MayTouchPolygons(path, row));
        path.InsertType = InsertType.Placement;
        Assert.True(PartCollision.MayTouchPolygons(path, row));
        path.InsertType = InsertType.Transition;
        path.ObstructionEthereal = true;
        Assert.True(PartCollision.MayTouchPolygons(path, row));
        Assert.True(hits > 1000, $"the grid should graze the slab often; {hits} hits");
        Assert.True(skippedInsideBounds > 1000, $"the box should skip spheres within the bounding sphere; {skippedInsideBounds} skipped");
    }
}
