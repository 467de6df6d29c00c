using System;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;

namespace AcDream.Core.Physics.Dat;

/// <summary>A GfxObj (portal DAT 0x01xxxxxx, retail CGfxObj) to the runtime's part model.</summary>
public static class DatModels
{
    /// <summary>
    /// The GfxObj's physics model: its physics BSP and physics polygons (<see cref="DatGeometry.ToPhysicsBsp"/>),
    /// bounded by the root node's sphere as retail's <c>BSPTREE::GetSphere</c> is (CGfxObj's physics sphere).
    /// Null when the GfxObj has no physics (<c>Flags</c> without <c>HasPhysics</c>, or no physics tree): a part
    /// drawn but never collided with. The drawing polygons, drawing BSP, surfaces and sort centre are not read.
    /// One model per GfxObj id can be shared by every object and part that uses it.
    /// </summary>
    /// <param name="gfxObj">The GfxObj as read.</param>
    /// <exception cref="DatObjectException">The physics content is refused; the message names the GfxObj id.</exception>
    public static PhysicsModel? ToPhysicsModel(GfxObj gfxObj)
    {
        ArgumentNullException.ThrowIfNull(gfxObj);
        if (!gfxObj.Flags.HasFlag(GfxObjFlags.HasPhysics) || gfxObj.PhysicsBSP?.Root is null)
            return null;
        var tree = DatGeometry.ToPhysicsBsp(gfxObj.Id, "physicsBSP", gfxObj.PhysicsBSP, gfxObj.PhysicsPolygons, gfxObj.VertexArray);
        try
        {
            return new PhysicsModel(tree, boundingSphere: null, $"GfxObj 0x{gfxObj.Id:X8}");
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(gfxObj.Id, $"physicsBSP: {ex.Message}", ex);
        }
    }
}
