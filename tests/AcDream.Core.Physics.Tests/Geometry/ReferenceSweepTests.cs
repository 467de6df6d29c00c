using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>The reference sweep's move-and-slide.</summary>
public class ReferenceSweepTests
{
    private static readonly Sphere[] Ball = [new Sphere(new Vector3(0, 0, 1), 0.5f)];

    /// <summary>A wall in the y = 0 plane facing −Y, 20 m wide and 3 m tall.</summary>
    private static ReferenceSweep Wall()
    {
        var scene = new ReferenceScene();
        scene.Add(new Polygon([new(-10, 0, 0), new(10, 0, 0), new(10, 0, 3), new(-10, 0, 3)]));
        return new ReferenceSweep(scene);
    }

    [Fact]
    public void Diagonal_SlidesAlongTheFace()
    {
        var r = Wall().Move(Ball, new Vector3(0, -1, 0), new Vector3(1, 0, 0));
        // Contact after half the motion at y = −0.5; the other half's x part slides on.
        Assert.True(Vector3.Distance(new Vector3(1f, -0.5f, 0), r.Position) < 1e-5f, r.Position.ToString());
        Assert.Equal(1, r.Contacts);
        Assert.Equal(-Vector3.UnitY, r.FirstNormal);
        Assert.Equal(MathF.Sqrt(0.5f), r.FirstContactDistance, 1e-5f);
    }

    [Fact]
    public void HeadOn_StopsTouching_AndStaysPutWhenPushedAgain()
    {
        var sweep = Wall();
        var r = sweep.Move(Ball, new Vector3(0, -3, 0), new Vector3(0, 5, 0));
        Assert.True(Vector3.Distance(new Vector3(0, -0.5f, 0), r.Position) < 1e-5f, r.Position.ToString());
        var again = sweep.Move(Ball, r.Position, r.Position + new Vector3(0, 1, 0));
        Assert.Equal(r.Position, again.Position);
    }

    [Fact]
    public void Grounded_IgnoresTheRequestedHeight()
    {
        var r = Wall().Move(Ball, new Vector3(0, -3, 0), new Vector3(0, -2, 7));
        Assert.Equal(new Vector3(0, -2, 0), r.Position);
        Assert.Equal(0, r.Contacts);
    }

    [Fact]
    public void Corner_OfTwoWalls_Stops()
    {
        var scene = new ReferenceScene();
        scene.Add(new Polygon([new(-10, 0, 0), new(10, 0, 0), new(10, 0, 3), new(-10, 0, 3)]));      // faces −Y
        scene.Add(new Polygon([new(0, -10, 0), new(0, -10, 3), new(0, 10, 3), new(0, 10, 0)]));      // faces −X
        var r = new ReferenceSweep(scene).Move(Ball, new Vector3(-2, -2, 0), new Vector3(2, 1, 0));
        Assert.True(Vector3.Distance(new Vector3(-0.5f, -0.5f, 0), r.Position) < 1e-4f, r.Position.ToString());
    }

    [Fact]
    public void Object_WithABsp_KeepsOnlyItsPolygons()
    {
        var slab = new PhysicsModel(BspShapes.Box(new Vector3(-0.5f, -0.1f, 0), new Vector3(0.5f, 0.1f, 2)));
        var setup = new PhysicsSetup
        {
            Parts = [new SetupPart(slab, Frame.Identity)],
            CylSpheres = [new CylSphere(Vector3.Zero, 0.5f, 0.2f)],
        };
        var scene = new ReferenceScene();
        scene.AddObject(setup, new Frame(new Vector3(10, 10, 0)));
        Assert.Equal(6, scene.Polygons.Count);
        Assert.Empty(scene.Cylinders);
        var r = new ReferenceSweep(scene).Move(Ball, new Vector3(10, 8, 0), new Vector3(10, 12, 0));
        Assert.Equal(10 - 0.1f - 0.5f, r.Position.Y, 1e-4f);
    }
}
