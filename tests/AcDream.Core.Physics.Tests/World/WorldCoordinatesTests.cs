using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// Global points and landblock-local points to positions and back (retail LandDefs: 192 m landblocks,
/// 24 m cells numbered 1..64 column-major, index = x * 8 + y + 1). Every expected id is computed by hand
/// in the comment beside it.
/// </summary>
public class WorldCoordinatesTests
{
    [Fact]
    public void FromGlobal_FindsTheLandblockCellAndLocalOrigin()
    {
        // 0xA9 * 192 = 32448, 0xB4 * 192 = 34560; local (100, 98.125): column 4, row 4 → 4 * 8 + 4 + 1 = 37 = 0x25.
        var p = Position.FromGlobal(new Vector3(32548f, 34658.125f, 1.5f));
        Assert.Equal(0xA9B40025u, p.CellId);
        Assert.Equal(new Vector3(100f, 98.125f, 1.5f), p.Origin);
        Assert.Equal(Quaternion.Identity, p.Frame.Orientation);
    }

    [Theory]
    [InlineData(191.5f, 23.9f, 0xA9B40039u)] // column 7, row 0 → 57 = 0x39
    [InlineData(0f, 24f, 0xA9B40002u)]       // column 0, row 1 → 2
    [InlineData(24f, 0f, 0xA9B40009u)]       // column 1, row 0 → 9
    [InlineData(191.9f, 191.9f, 0xA9B40040u)] // column 7, row 7 → 64 = 0x40
    public void Outdoor_WithinTheBlock_NumbersCellsColumnMajor(float x, float y, uint expected)
    {
        var p = Position.Outdoor(0xA9B4, new Vector3(x, y, 0f));
        Assert.Equal(expected, p.CellId);
        Assert.Equal(new Vector3(x, y, 0f), p.Origin);
    }

    [Fact]
    public void Outdoor_WestOfTheBlock_MovesToTheWesternNeighbour()
    {
        // x = -1 is 191 m into landblock 0xA8B4, column 7, row 0 → 0x39.
        var p = Position.Outdoor(0xA9B4, new Vector3(-1f, 5f, 0f));
        Assert.Equal(0xA8B40039u, p.CellId);
        Assert.Equal(new Vector3(191f, 5f, 0f), p.Origin);
    }

    [Fact]
    public void Outdoor_SeveralBlocksAway_MovesByWholeLandblocks()
    {
        // (200, 400) is one block east and two north: 0xAAB6, local (8, 16), cell 1.
        var p = Position.Outdoor(0xA9B4, new Vector3(200f, 400f, 2f));
        Assert.Equal(0xAAB60001u, p.CellId);
        Assert.Equal(new Vector3(8f, 16f, 2f), p.Origin);
    }

    [Fact]
    public void Outdoor_SnapsCoordinatesWithinEpsilonOfZero_AsRetailAdjustToOutside()
    {
        // LandDefs::adjust_to_outside zeroes |x| < 0.0002 before choosing the block.
        var snapped = Position.Outdoor(0xA9B4, new Vector3(-0.0001f, 5f, 0f));
        Assert.Equal(0xA9B40001u, snapped.CellId);
        Assert.Equal(0f, snapped.Origin.X);
        var moved = Position.Outdoor(0xA9B4, new Vector3(-0.0003f, 5f, 0f));
        Assert.Equal(0xA8B40039u, moved.CellId);
        Assert.Equal(191.9997f, moved.Origin.X, 4);
    }

    [Fact]
    public void Outdoor_JustBelowABlockEdge_StaysInsideItsCell()
    {
        // The float just below -192 is two blocks west (0xA7B4), one ulp below that block's east edge: column 7.
        var p = Position.Outdoor(0xA9B4, new Vector3(-192.00001f, 5f, 0f));
        Assert.Equal(0xA7B40039u, p.CellId);
        Assert.True(p.Origin.X < 192f, $"x = {p.Origin.X}");
        Assert.Equal(p.CellId, LandDefs.LandCellAt(0xA7B4, p.Origin));
    }

    [Fact]
    public void ToGlobal_AddsTheBlockCorner_ForOutdoorAndIndoorCells()
    {
        // 0xA8 * 192 + 191 = 32447, 0xB4 * 192 + 5 = 34565.
        Assert.Equal(new Vector3(32447f, 34565f, 0f), new Position(0xA8B40039, new Vector3(191f, 5f, 0f)).ToGlobal());
        // An indoor cell's origin is landblock-local too: 32448 + 10, 34560 + 20.
        Assert.Equal(new Vector3(32458f, 34580f, 3f), new Position(0xA9B40105, new Vector3(10f, 20f, 3f)).ToGlobal());
        Assert.Equal(new Vector3(32448f, 34560f, 0f), LandDefs.BlockCorner(0xA9B40105));
    }

    [Fact]
    public void FromGlobal_OfToGlobal_GivesTheSamePosition()
    {
        var p = new Position(0x12340017, new Vector3(50f, 160.5f, 7f)); // column 2, row 6 → 2 * 8 + 6 + 1 = 23 = 0x17
        var back = Position.FromGlobal(p.ToGlobal());
        Assert.Equal(p.CellId, back.CellId);
        Assert.Equal(p.Origin, back.Origin);
    }

    [Theory]
    [InlineData(0x0000u, -1f, 0f)]   // west of the world
    [InlineData(0xFE00u, 192f, 0f)]  // east of block 0xFE
    [InlineData(0x00FEu, 0f, 192f)]  // north of block 0xFE
    public void Outdoor_OutsideTheWorld_Throws_NamingLocal(uint landblock, float x, float y)
    {
        var ex = Assert.Throws<ArgumentException>(() => Position.Outdoor(landblock, new Vector3(x, y, 0f)));
        Assert.Equal("local", ex.ParamName);
    }

    [Theory]
    [InlineData(0xFF00u)]
    [InlineData(0x00FFu)]
    [InlineData(0xA9B40001u)]
    public void Outdoor_LandblockNotInTheWorld_Throws_NamingLandblock(uint landblock)
    {
        var ex = Assert.Throws<ArgumentException>(() => Position.Outdoor(landblock, Vector3.Zero));
        Assert.Equal("landblock", ex.ParamName);
    }

    [Fact]
    public void FromGlobal_BadPoints_Throw_NamingGlobal()
    {
        Assert.Equal("global", Assert.Throws<ArgumentException>(() => Position.FromGlobal(new Vector3(float.NaN, 0f, 0f))).ParamName);
        Assert.Equal("global", Assert.Throws<ArgumentException>(() => Position.FromGlobal(new Vector3(48960f, 0f, 0f))).ParamName);
        Assert.Equal(0xFE000039u, Position.FromGlobal(new Vector3(48959.99f, 0f, 0f)).CellId); // last column of the last block
    }

    [Fact]
    public void TryAdjustToOutside_FromAnIndoorCell_GivesTheOutdoorCellBelow()
    {
        uint cell = 0xA9B40100;
        var local = new Vector3(30f, 50f, -2f); // column 1, row 2 → 1 * 8 + 2 + 1 = 11 = 0x0B
        Assert.True(LandDefs.TryAdjustToOutside(ref cell, ref local));
        Assert.Equal(0xA9B4000Bu, cell);
        Assert.Equal(new Vector3(30f, 50f, -2f), local);
    }

    [Theory]
    [InlineData(0xA9B40000u)] // cell index 0
    [InlineData(0xA9B40041u)] // between the land cells (1..0x40) and the env cells (0x100..)
    [InlineData(0xA9B4FFFEu)]
    public void TryAdjustToOutside_InvalidCellIndex_SetsTheCellToZero_AsRetail(uint id)
    {
        // adjust_to_outside (acclient.c:467433): a failure writes 0 into the cell id; the point is not touched.
        uint cell = id;
        var local = new Vector3(-5f, 5f, 0f);
        Assert.False(LandDefs.TryAdjustToOutside(ref cell, ref local));
        Assert.Equal(0u, cell);
        Assert.Equal(new Vector3(-5f, 5f, 0f), local);
    }

    [Fact]
    public void TryAdjustToOutside_APointOutsideTheWorld_SetsTheCellToZero_AfterTheSnap()
    {
        // Retail snaps |x| below EPSILON to 0 before it finds the point outside the world (here 1 km west of 0x0000).
        uint cell = 0x00000001;
        var local = new Vector3(-1000f, 1e-5f, 3f);
        Assert.False(LandDefs.TryAdjustToOutside(ref cell, ref local));
        Assert.Equal(0u, cell);
        Assert.Equal(new Vector3(-1000f, 0f, 3f), local);
        // And from the landblock's own id 0x….FFFF, which retail takes as a landblock's cell.
        cell = 0xA9B4FFFF;
        local = new Vector3(30f, 50f, 0f);
        Assert.True(LandDefs.TryAdjustToOutside(ref cell, ref local));
        Assert.Equal(0xA9B4000Bu, cell);
    }

    [Theory]
    // inbound_valid_cellid (acclient.c:209467): cell part 1..0x40, 0x100..0xFFFD or 0xFFFF; x and y bytes below 0xFF.
    [InlineData(0xA9B4FFFFu, true, false)]  // the landblock's own id: retail's check takes it; no cell has it
    [InlineData(0xA9B40001u, true, true)]
    [InlineData(0xA9B40040u, true, true)]
    [InlineData(0xA9B40100u, true, true)]
    [InlineData(0xA9B4FFFDu, true, true)]
    [InlineData(0xA9B40000u, false, false)]
    [InlineData(0xA9B40041u, false, false)]
    [InlineData(0xA9B4FFFEu, false, false)]
    [InlineData(0xFFB4FFFFu, false, false)] // x byte 0xFF: outside the world
    [InlineData(0xA9FF0001u, false, false)]
    public void IsValidCellId_IsRetailsInboundValidCellid_AndIsValidCellOfWorld_LeavesOutTheLandblocksOwnId(uint id, bool retail, bool cell)
    {
        Assert.Equal(retail, LandDefs.IsValidCellId(id));
        Assert.Equal(cell, LandDefs.IsValidCellOfWorld(id));
    }

    [Fact]
    public void CellBox_ContainsExactlyThePointsInsideTheBox_InCellSpace()
    {
        // A 4 × 6 × 3 m room turned 90° about Z, its frame at (100, 100, 0): cell space (x, y) is landblock (100 - y, 100 + x).
        var frame = new Frame(new Vector3(100f, 100f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2));
        var cell = new EnvCell(0xA9B40100, frame, null, BspShapes.CellBox(new Vector3(-2f, -3f, 0f), new Vector3(2f, 3f, 3f)));
        Assert.True(cell.ContainsPoint(new Vector3(100f, 101.9f, 1f)));  // cell space (1.9, 0, 1)
        Assert.True(cell.ContainsPoint(new Vector3(97.1f, 100f, 1f)));   // cell space (0, 2.9, 1)
        Assert.False(cell.ContainsPoint(new Vector3(100f, 102.1f, 1f))); // cell space x = 2.1
        Assert.False(cell.ContainsPoint(new Vector3(103.1f, 100f, 1f))); // cell space (0, -3.1, 1)
        Assert.False(cell.ContainsPoint(new Vector3(100f, 100f, 3.1f))); // above the ceiling
    }

    [Fact]
    public void CellBox_FlatBox_Throws_NamingTheAxis()
    {
        var ex = Assert.Throws<ArgumentException>(() => BspShapes.CellBox(new Vector3(0f, 0f, 1f), new Vector3(1f, 1f, 1f)));
        Assert.Contains("max.Z", ex.Message);
    }
}
