using System.Numerics;

namespace AcDream.Core.Physics.Viewer;

/// <summary>
/// One collision shape placed in the frame of one landblock: a polygon (<see cref="Vertices"/>, with its sidedness), or
/// an object's cylinder (<see cref="Center"/> its low point) or sphere.
/// </summary>
internal sealed record ViewShape(ViewSource Source, OutlineForm Form, uint CellId, uint ObjectId, bool Collides,
    PolygonSides Sides, Vector3[] Vertices, Vector3 Center, float Radius, float Height, uint OtherCellId = 0);
