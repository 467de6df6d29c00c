namespace AcDream.Core.Physics.World;

/// <summary>
/// How much of a land cell, or of a landblock, is water (retail LandDefs::WaterType). Computed from the
/// terrain types of the height-grid vertices; see docs/water.md.
/// </summary>
public enum WaterType
{
    /// <summary>No water: no corner of the cell (no cell of the landblock) is water.</summary>
    NotWater = 0,
    /// <summary>Some water: some but not all corners of the cell (cells of the landblock) are water.</summary>
    PartiallyWater = 1,
    /// <summary>All water: every corner of the cell is water; for a landblock, every cell is.</summary>
    EntirelyWater = 2,
}
