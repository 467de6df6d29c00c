using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Viewer;

/// <summary>The form of an <see cref="OutlineShape"/>.</summary>
internal enum OutlineForm : byte
{
    /// <summary>A polygon (<see cref="OutlineShape.Vertices"/>).</summary>
    Polygon,
    /// <summary>A world-Z cylinder (<see cref="OutlineShape.Center"/> is its low point).</summary>
    Cylinder,
    /// <summary>A sphere.</summary>
    Sphere,
}
