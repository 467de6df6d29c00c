using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Viewer;

namespace AcDream.Core.Physics.Tests.Viewer;

/// <summary>The drawable outline of a world: every shape once, placed, marked by whether its object collides by it.</summary>
public class WorldOutlineTests
{
    [Fact]
    public void TheCottage_HasTheRoomsEightPolygons_TheShellsSeven_AndTheDoorsSlabCylinderAndSphere()
    {
        var shapes = WorldOutline.Collect(SceneLibrary.Load("cottage").World, 0xA9B40025);
        Assert.Equal(8, shapes.Count(s => s.Source == OutlineSource.EnvCell && s.CellId == 0xA9B40100));
        Assert.Equal(7, shapes.Count(s => s.Source == OutlineSource.Building));
        var door = shapes.Where(s => s.ObjectId == 0x7000_0001).ToList();
        // The door is listed in two cells (outside and the room); its shapes appear once each.
        Assert.Equal(6, door.Count(s => s.Form == OutlineForm.Polygon && s.Collides));
        var foot = Assert.Single(door, s => s.Form == OutlineForm.Cylinder);
        Assert.False(foot.Collides);                    // HasPhysicsBsp: the door collides by its slab only
        Assert.Equal(new Vector3(100, 99.97f, 0), foot.Center);   // low point (0, 0.12, 0) of the door at (100, 99.85, 0)
        Assert.Equal(0.5f, foot.Radius);
        Assert.False(Assert.Single(door, s => s.Form == OutlineForm.Sphere).Collides);
        // The slab's front face, placed: y = 99.85 - 0.009.
        Assert.Contains(door, s => s.Form == OutlineForm.Polygon && s.Vertices.ToArray().All(v => MathF.Abs(v.Y - 99.841f) < 1e-4f));
    }

    [Fact]
    public void ACylinderOnlyObject_CollidesByItsCylinder()
    {
        var trunk = Assert.Single(WorldOutline.Collect(SceneLibrary.Load("trunk").World, 0xA9B40025));
        Assert.Equal(OutlineForm.Cylinder, trunk.Form);
        Assert.True(trunk.Collides);
        Assert.Equal(4f, trunk.Height);
    }
}
