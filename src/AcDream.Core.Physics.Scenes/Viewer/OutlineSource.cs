using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Viewer;

/// <summary>What an <see cref="OutlineShape"/> belongs to.</summary>
internal enum OutlineSource : byte
{
    /// <summary>An indoor cell's physics BSP.</summary>
    EnvCell,
    /// <summary>A building's shell.</summary>
    Building,
    /// <summary>A registered object.</summary>
    Object,
}
