using System;
using System.Numerics;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Viewer;

/// <summary>One collision shape of the world placed in one landblock frame, for drawing.</summary>
internal sealed class OutlineShape
{
    internal OutlineShape(OutlineSource source, OutlineForm form, uint cellId, uint objectId, bool collides,
        Vector3[] vertices, Vector3 center, float radius, float height)
    {
        Source = source;
        Form = form;
        CellId = cellId;
        ObjectId = objectId;
        Collides = collides;
        _vertices = vertices;
        Center = center;
        Radius = radius;
        Height = height;
    }

    private readonly Vector3[] _vertices;

    /// <summary>What it belongs to.</summary>
    public OutlineSource Source { get; }
    /// <summary>Its form.</summary>
    public OutlineForm Form { get; }
    /// <summary>The cell (the indoor cell, the land cell a building stands in, the object's cell).</summary>
    public uint CellId { get; }
    /// <summary>The object's id, or 0.</summary>
    public uint ObjectId { get; }
    /// <summary>
    /// False for an object shape that its object never collides by (retail's dispatch ladder: a
    /// HasPhysicsBsp object collides by its BSP parts only, a cylsphere object by its cylspheres); true otherwise.
    /// </summary>
    public bool Collides { get; }
    /// <summary>A polygon's vertices.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;
    /// <summary>A cylinder's low point or a sphere's centre.</summary>
    public Vector3 Center { get; }
    /// <summary>A cylinder's or sphere's radius.</summary>
    public float Radius { get; }
    /// <summary>A cylinder's height.</summary>
    public float Height { get; }
}
