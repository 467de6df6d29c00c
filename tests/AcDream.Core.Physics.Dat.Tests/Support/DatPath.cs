using AcDream.Core.Physics.Scenes;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>
/// A world taken through DAT files and the package's own loader: written as DAT objects (<see cref="WorldDat"/>,
/// plus a Region holding its height table), opened with <see cref="DatFiles"/> and loaded landblock by landblock
/// by <see cref="DatWorld"/>, each static object described as the scene described it.
/// </summary>
internal static class DatPath
{
    /// <summary>The world written as DAT files in a temporary folder (deleted with the returned object).</summary>
    public static TempDats Write(WorldDat dat) => new(
        dat.GfxObjs.Cast<DBObj>().Concat(dat.Setups).Concat(dat.Environments).Append(WorldWriter.Region(dat.LandDefs)),
        dat.LandBlocks.Cast<DBObj>().Concat(dat.Infos).Concat(dat.EnvCells));

    /// <summary>A loader over the files that describes each static object as the written world did.</summary>
    public static DatWorld Loader(DatFiles files, WorldDat dat) => new(files, describe: (landblock, index, owner, ownerIndex, placement) =>
    {
        var d = dat.Objects[(owner, ownerIndex)];
        return new DatObjectDescription(d.Id, d.Scale, d.State, d.Flags);
    });

    /// <summary>The world through DAT files; <paramref name="sceneJson"/>, when given, supplies the landblocks'
    /// terrain types (the built world keeps no terrain words to write back).</summary>
    public static PhysicsWorld Through(PhysicsWorld world, string? sceneJson = null)
    {
        var dat = WorldDat.From(world, sceneJson);
        using var dats = Write(dat);
        using var files = dats.Open();
        var loader = Loader(files, dat);
        foreach (uint landblock in dat.Landblocks)
            loader.LoadLandblock(landblock);
        return loader.World;
    }

    /// <summary>The scene with its world replaced by the DAT path's; the movers are the scene's.</summary>
    public static Scene Through(Scene scene, string? sceneJson = null) => scene.WithWorld(Through(scene.World, sceneJson));
}
