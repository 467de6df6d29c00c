using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>The cliff arm of edge slide: a grounded edge-sliding mover at the top of terrain too steep to walk down.</summary>
public class CliffSlideTests
{
    /// <summary>
    /// A plateau at z = 40 for x ≤ 96 (grid columns 0..4) falling to 0 at x = 120: the fall has normal
    /// (40, 0, 24) / 46.65, z = 0.514, steeper than FloorZ.
    /// </summary>
    private static PhysicsWorld Plateau()
    {
        var heights = new float[81];
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                heights[x * 9 + y] = x <= 4 ? 40f : 0f;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(new Terrain(TestGeometry.Landblock, heights));
        return world;
    }

    // The player walks diagonally, 0.1 m per frame at 45° (0.0707, 0.0707), from x = 95.5 towards the edge
    // at x = 96. Seven frames reach x = 95.99497; the eighth's sub-step (x = 96.066) has its low point over
    // the steep face, finds no walkable ground within the step-down probes (the face is 0.11 m below, but
    // too steep), and edge_slide takes the cliff arm (the probe left a contact plane steeper than the
    // walkable limit). Retail restores the check position first, then cliff_slide removes the part of
    // the sub-step along the horizontal perpendicular of the cliff line: cross(n, up) = (0, −0.857, 0),
    // perpendicular (0.857, 0, 0) → (1, 0, 0); the move's part along it (+0.0707) is taken off. So from the
    // eighth frame on x stays at 95.99497 and y still gains 0.0707 per frame, at z = 40.005 (the player's
    // origin rests 0.005 above the ground), grounded.

    [Fact]
    public void AtACliffEdge_TheMoverSlidesAlongIt_RestoringBeforeSliding()
    {
        var player = new Mover(Plateau(), MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(95.5f, 100, 40f), 40f));
        var step = new Vector3(0.0707f, 0.0707f, 0);
        player.Walk(step, 16);
        float edgeX = 95.5f + 7 * 0.0707f;
        for (int f = 7; f < 16; f++)
        {
            var frame = player.Frames[f];
            string at = $"frame {f}: {frame.Before} -> {frame.After}";
            Assert.True(MathF.Abs(frame.After.X - edgeX) <= 1e-4f, at);
            Assert.True(MathF.Abs(frame.After.Y - frame.Before.Y - 0.0707f) <= 1e-4f, at);
            Assert.True(MathF.Abs(frame.After.Z - 40.005f) <= 1e-3f, at); // the player's sphere 0 (centre 0.475, r 0.48) rests 0.005 below its origin
        }
        Assert.True(player.State.Contact && player.State.OnWalkable);
    }
}
