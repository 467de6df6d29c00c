using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.World;

public class LandCellCollisionTests
{
    [Fact]
    public void ACheckPositionNamedInTheNextLandblock_MeetsThisCellsTerrainInThisCellsSpace()
    {
        // Landblock 0xA9B4 is flat at 0; its east neighbour 0xAAB4 rises 1 m per 24 m eastwards, so the
        // terrain of its south-west cell (0xAAB40001) is z = x / 24 in that landblock's space.
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        var heights = new float[Terrain.VerticesPerSide * Terrain.VerticesPerSide];
        for (int x = 0; x < Terrain.VerticesPerSide; x++)
            for (int y = 0; y < Terrain.VerticesPerSide; y++)
                heights[x * Terrain.VerticesPerSide + y] = x;
        world.Cells.AddLandblock(new Terrain(0xAAB4, heights));
        var east = world.Cells.Get(0xAAB40001)!;

        // The check position still carries the west landblock's cell (x 7, y 0: index 57) but stands 0.3 m
        // past the border: 0.3 m into the east cell, whose terrain is 0.0125 m high there. The sphere's
        // low point sits at z 0, so the terrain pushes it up by 0.3 / 24.
        var t = new Transition(world);
        t.SpherePath.InitSphere([new Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 1f);
        var check = new Position(0xA9B40039, new Vector3(192.3f, 5f, 0f));
        t.SpherePath.InitPath(null, check, check);
        t.SpherePath.SetCheckPos(check, world.Cells.Get(0xA9B40039));

        var state = CellCollisions.FindEnvCollisions(east, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Assert.Equal(0.3f / 24f, t.SpherePath.CheckPos.Frame.Origin.Z, 1e-5f);
        Assert.True(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(-1f / 24f, t.CollisionInfo.ContactPlane.Normal.X / t.CollisionInfo.ContactPlane.Normal.Z, 1e-5f);
    }
}
