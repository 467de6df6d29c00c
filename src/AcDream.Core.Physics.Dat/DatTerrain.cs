using System;
using DatReaderWriter.DBObjs;
using DatLandDefs = DatReaderWriter.Types.LandDefs;

namespace AcDream.Core.Physics.Dat;

/// <summary>A LandBlock (cell DAT 0xXXYYFFFF, retail CLandBlockStruct) to the runtime's <see cref="Terrain"/>.</summary>
public static class DatTerrain
{
    /// <summary>
    /// The landblock's terrain: each of the 81 vertex heights (<c>Height[i]</c>, an index into the Region's
    /// <c>LandDefs.LandHeightTable</c> of 256 metres, retail <c>LandDefs::land_height_table</c>) at the same index,
    /// <c>i = x * 9 + y</c> (x east, y north). The cut of each land cell is computed by the runtime from the
    /// cell's global coordinates, as retail does. The per-vertex terrain words (<c>Terrain[i]</c>, a
    /// <c>TerrainInfo</c>: road bits 0–1, terrain type 2–6, scenery 11–15) go to the terrain as stored, same index:
    /// the runtime reads the type, which makes land cells water (retail <c>CLandBlockStruct::CalcWater</c>).
    /// </summary>
    /// <param name="block">The LandBlock as read (id 0xXXYYFFFF).</param>
    /// <param name="landDefs">The Region's (portal DAT 0x13000000) <c>LandDefs</c>.</param>
    /// <exception cref="DatObjectException">The id is not a LandBlock id, a list does not have its size, or the runtime refuses the terrain (a landblock outside the world, a height not finite); the message names the LandBlock id.</exception>
    public static Terrain ToTerrain(LandBlock block, DatLandDefs landDefs)
    {
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(landDefs);
        uint id = block.Id;
        if ((id & 0xFFFF) != 0xFFFF)
            throw new DatObjectException(id, "id: a LandBlock's id is 0xXXYYFFFF.");
        const int count = Terrain.VerticesPerSide * Terrain.VerticesPerSide;
        if (block.Height is not { Length: count })
            throw new DatObjectException(id, $"height: expected {count} vertex heights (9×9), got {block.Height?.Length ?? 0}.");
        var table = landDefs.LandHeightTable;
        if (table is not { Length: 256 })
            throw new DatObjectException(0x1300_0000, $"landDefs.landHeightTable: expected 256 heights, got {table?.Length ?? 0}.");
        if (block.Terrain is not { Length: count })
            throw new DatObjectException(id, $"terrain: expected {count} terrain words (9×9), got {block.Terrain?.Length ?? 0}.");
        // The loop is in its own method: a method with both a stack buffer and a loop is compiled fully optimized at
        // its first call (on-stack replacement cannot take it), which costs a process's first load more than the
        // quick first compilation this method, called once per load, gets without one.
        Span<float> heights = stackalloc float[count];
        Span<ushort> words = stackalloc ushort[count];
        Gather(block, table, heights, words);
        try
        {
            return new Terrain(id >> 16, heights, words, $"LandBlock 0x{id:X8}");
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(id, ex.Message, ex);
        }
    }

    // Each vertex's height through the table and its terrain word, by index.
    private static void Gather(LandBlock block, float[] table, Span<float> heights, Span<ushort> words)
    {
        for (int i = 0; i < heights.Length; i++)
        {
            heights[i] = table[block.Height[i]];
            words[i] = block.Terrain[i];
        }
    }
}
