using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>A scene's world taken through DAT files: written as DAT objects, read back, converted, assembled.</summary>
internal static class DatPath
{
    public static PhysicsWorld Through(PhysicsWorld world, string? sceneJson = null)
    {
        var dat = WorldDat.From(world, sceneJson);
        using var files = WrittenDats.Write(dat);
        return new DatWorldAssembly(files.Portal, files.Cell, dat.LandDefs, (owner, index) => dat.Objects[(owner, index)]).Load(dat.Landblocks);
    }

    /// <summary>The scene with its world replaced by the DAT path's; the movers are the scene's.</summary>
    public static Scene Through(Scene scene, string? sceneJson = null) => new(scene.Name, scene.Description, scene.Sha256, Through(scene.World, sceneJson), scene.Movers);
}
