using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>Everything observable about a world's content, as comparable text.</summary>
internal static class WorldSnapshot
{
    public static string Take(PhysicsWorld world)
    {
        var sb = new System.Text.StringBuilder();
        var ids = world.Cells.CellIds.OrderBy(i => i).ToList();
        sb.Append("cells ").Append(ids.Count).Append('\n');
        foreach (uint id in ids)
        {
            var cell = world.Cells.Get(id)!;
            sb.Append($"{id:X8} {cell.GetType().Name} {(cell is LandCell { Building: not null } ? "building" : "")}\n");
            foreach (var row in world.Objects.RowsInCell(id))
                sb.Append($"  {row.EntityId:X8} {row.Kind}[{row.Shape.Index}] {row.Position} {row.Position.Frame.Orientation} {row.Scale} {row.State} {row.Flags}\n");
        }
        sb.Append("objects ").Append(world.Objects.Count);
        return sb.ToString();
    }
}
