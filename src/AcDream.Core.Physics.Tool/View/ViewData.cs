using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Viewer;

namespace AcDream.Core.Physics.Tool.View;

/// <summary>
/// The data a view page draws, written as one JSON document (docs/viewer.md, "The page's data"): the scene's shapes in
/// the view's landblock frame, and per mover its spheres, its start, and every frame's recorded numbers in columns
/// (floats written exactly as the trajectory writes them, so the page shows the same digits), the frame's outcome and
/// where its drawn path breaks.
/// </summary>
internal static class ViewData
{
    /// <summary>The data format's version.</summary>
    public const int Version = 1;

    /// <summary>The frame-state flags, one bit each in a frame's <c>flags</c> value.</summary>
    [Flags]
    public enum FrameFlags
    {
        /// <summary>None.</summary>
        None = 0,
        /// <summary>Touches a contact plane.</summary>
        Contact = 1,
        /// <summary>Stands on walkable ground.</summary>
        OnWalkable = 2,
        /// <summary>The contact plane is valid.</summary>
        ContactPlaneValid = 4,
        /// <summary>A collision normal was recorded.</summary>
        CollisionNormalValid = 8,
        /// <summary>The mover is sliding.</summary>
        SlidingNormalValid = 16,
        /// <summary>The move was accepted.</summary>
        Succeeded = 32,
    }

    /// <summary>The landblock whose frame the view uses: the first mover's start cell's, else the world's first cell's.</summary>
    public static uint FrameCell(Scene scene) =>
        scene.Movers.Count > 0 ? scene.Movers[0].Start.Position.CellId : scene.World.Cells.CellIds.Order().FirstOrDefault();

    /// <summary>A frame's flags.</summary>
    public static FrameFlags FlagsOf(TrajectoryFrame f) =>
        (f.Contact ? FrameFlags.Contact : 0) | (f.OnWalkable ? FrameFlags.OnWalkable : 0)
        | (f.ContactPlaneValid ? FrameFlags.ContactPlaneValid : 0) | (f.CollisionNormalValid ? FrameFlags.CollisionNormalValid : 0)
        | (f.SlidingNormalValid ? FrameFlags.SlidingNormalValid : 0) | (f.Succeeded ? FrameFlags.Succeeded : 0);

    /// <summary>A frame's outcome, <paramref name="previous"/> being where it started (same landblock frame).</summary>
    public static ViewOutcome OutcomeOf(TrajectoryFrame frame, Vector3 previous, Vector3 at) => FrameOutcomes.Of(frame, previous) switch
    {
        FrameOutcome.Free => ViewOutcome.Moved,
        FrameOutcome.Slid => ViewOutcome.Slid,
        FrameOutcome.Stepped => at.Z > previous.Z ? ViewOutcome.SteppedUp : ViewOutcome.SteppedDown,
        FrameOutcome.Refused => ViewOutcome.Refused,
        _ => ViewOutcome.Airborne,
    };

    /// <summary>Writes the document for <paramref name="scene"/> and <paramref name="trajectory"/>.</summary>
    public static void Write(Stream stream, Scene scene, Trajectory trajectory, IReadOnlyList<ViewShape> shapes, uint frameCell)
    {
        using var w = new Utf8JsonWriter(stream);
        w.WriteStartObject();
        w.WriteString("format", "acdream-view");
        w.WriteNumber("version", Version);
        w.WriteString("scene", scene.Name);
        w.WriteString("description", scene.Description);
        w.WriteString("trajectoryScene", trajectory.SceneName);
        w.WriteNumber("frameCell", frameCell);
        WriteLandblocks(w, trajectory, scene, frameCell);
        WriteShapes(w, shapes);
        w.WriteStartArray("movers");
        foreach (var mover in trajectory.Movers)
            WriteMover(w, mover, scene.Movers.FirstOrDefault(m => m.Name == mover.Name), frameCell);
        w.WriteEndArray();
        w.WriteStartObject("commandNames");
        foreach (uint id in CommandIds(trajectory))
            w.WriteString(id.ToString(System.Globalization.CultureInfo.InvariantCulture), MotionCommandNames.Name(id));
        w.WriteEndObject();
        w.WriteEndObject();
    }

    /// <summary>Every landblock a frame, target, contact plane or start names: its offset into the view's frame.</summary>
    private static void WriteLandblocks(Utf8JsonWriter w, Trajectory trajectory, Scene scene, uint frameCell)
    {
        var blocks = new SortedSet<uint> { frameCell >> 16 };
        foreach (var m in scene.Movers)
            blocks.Add(m.Start.Position.CellId >> 16);
        foreach (var mover in trajectory.Movers)
            foreach (var f in mover.Frames)
            {
                blocks.Add(f.Cell >> 16);
                blocks.Add(f.Target.CellId >> 16);
                blocks.Add(f.ContactPlaneCell >> 16);
            }
        w.WriteStartObject("landblocks");
        foreach (uint block in blocks)
        {
            w.WriteStartArray(block.ToString(System.Globalization.CultureInfo.InvariantCulture));
            var o = LandDefs.BlockOffset(frameCell, block << 16);
            w.WriteNumberValue(o.X); w.WriteNumberValue(o.Y); w.WriteNumberValue(o.Z);
            w.WriteEndArray();
        }
        w.WriteEndObject();
    }

    private static string SourceName(ViewSource s) => s switch
    {
        ViewSource.Terrain => "terrain",
        ViewSource.EnvCell => "cell",
        ViewSource.Portal => "portal",
        ViewSource.Building => "building",
        _ => "object",
    };

    private static string SidesName(PolygonSides s) => s switch
    {
        PolygonSides.Single => "single",
        PolygonSides.Double => "double",
        _ => "both",
    };

    private static void WriteShapes(Utf8JsonWriter w, IReadOnlyList<ViewShape> shapes)
    {
        w.WriteStartArray("shapes");
        foreach (var s in shapes)
        {
            w.WriteStartObject();
            w.WriteString("source", SourceName(s.Source));
            w.WriteString("form", s.Form switch { OutlineForm.Polygon => "polygon", OutlineForm.Cylinder => "cylinder", _ => "sphere" });
            w.WriteNumber("cell", s.CellId);
            if (s.ObjectId != 0)
                w.WriteNumber("object", s.ObjectId);
            w.WriteBoolean("collides", s.Collides);
            if (s.Form == OutlineForm.Polygon)
            {
                w.WriteString("sides", SidesName(s.Sides));
                w.WriteStartArray("vertices");
                foreach (var v in s.Vertices)
                {
                    w.WriteNumberValue(v.X); w.WriteNumberValue(v.Y); w.WriteNumberValue(v.Z);
                }
                w.WriteEndArray();
                if (s.Source == ViewSource.Portal)
                    w.WriteNumber("otherCell", s.OtherCellId);
            }
            else
            {
                Vec(w, "center", s.Center);
                w.WriteNumber("radius", s.Radius);
                if (s.Form == OutlineForm.Cylinder)
                    w.WriteNumber("height", s.Height);
            }
            w.WriteEndObject();
        }
        w.WriteEndArray();
    }

    private static void Vec(Utf8JsonWriter w, string name, Vector3 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X); w.WriteNumberValue(v.Y); w.WriteNumberValue(v.Z);
        w.WriteEndArray();
    }

    /// <summary>A column of floats: <paramref name="get"/> of every frame.</summary>
    private static void Floats(Utf8JsonWriter w, string name, IReadOnlyList<TrajectoryFrame> frames, Func<TrajectoryFrame, float> get)
    {
        w.WriteStartArray(name);
        foreach (var f in frames) w.WriteNumberValue(get(f));
        w.WriteEndArray();
    }

    /// <summary>A column of vectors, three numbers per frame.</summary>
    private static void Vectors(Utf8JsonWriter w, string name, IReadOnlyList<TrajectoryFrame> frames, Func<TrajectoryFrame, Vector3> get)
    {
        w.WriteStartArray(name);
        foreach (var f in frames)
        {
            var v = get(f);
            w.WriteNumberValue(v.X); w.WriteNumberValue(v.Y); w.WriteNumberValue(v.Z);
        }
        w.WriteEndArray();
    }

    private static void Uints(Utf8JsonWriter w, string name, IReadOnlyList<TrajectoryFrame> frames, Func<TrajectoryFrame, uint> get)
    {
        w.WriteStartArray(name);
        foreach (var f in frames) w.WriteNumberValue(get(f));
        w.WriteEndArray();
    }

    private static void Quaternions(Utf8JsonWriter w, string name, IReadOnlyList<TrajectoryFrame> frames, Func<TrajectoryFrame, Quaternion> get)
    {
        w.WriteStartArray(name);
        foreach (var f in frames)
        {
            var q = get(f);
            w.WriteNumberValue(q.W); w.WriteNumberValue(q.X); w.WriteNumberValue(q.Y); w.WriteNumberValue(q.Z);
        }
        w.WriteEndArray();
    }

    /// <summary>The mover's path in the view's frame: its start, then every frame's position.</summary>
    public static Vector3[] PathPoints(MoverTrajectory mover, SceneMover? sceneMover, uint frameCell)
    {
        var points = new Vector3[mover.Frames.Count + 1];
        for (int f = 0; f < mover.Frames.Count; f++)
            points[f + 1] = mover.Frames[f].Position + LandDefs.BlockOffset(frameCell, mover.Frames[f].Cell);
        points[0] = sceneMover is null
            ? (mover.Frames.Count > 0 ? points[1] : Vector3.Zero)
            : sceneMover.Start.Position.Origin + LandDefs.BlockOffset(frameCell, sceneMover.Start.Position.CellId);
        return points;
    }

    private static void WriteMover(Utf8JsonWriter w, MoverTrajectory mover, SceneMover? sceneMover, uint frameCell)
    {
        var frames = mover.Frames;
        var points = PathPoints(mover, sceneMover, frameCell);
        w.WriteStartObject();
        w.WriteString("name", mover.Name);
        w.WriteString("kind", sceneMover is null ? "unknown" : sceneMover.IsMotion ? "motion" : sceneMover.IsMissile ? "missile" : sceneMover.IsBody ? "body" : "offset");
        w.WriteStartArray("spheres");
        if (sceneMover is not null)
        {
            float scale = sceneMover.Description.Scale;
            foreach (var s in sceneMover.Description.Spheres)
            {
                w.WriteStartArray();
                w.WriteNumberValue(s.Center.X * scale); w.WriteNumberValue(s.Center.Y * scale); w.WriteNumberValue(s.Center.Z * scale);
                w.WriteNumberValue(s.Radius * scale);
                w.WriteEndArray();
            }
        }
        w.WriteEndArray();
        Vec(w, "start", points[0]);
        w.WriteNumber("startCell", sceneMover?.Start.Position.CellId ?? (frames.Count > 0 ? frames[0].Cell : 0));
        w.WriteStartArray("reports");
        if (sceneMover is not null)
            foreach (var p in sceneMover.ReportedPositions)
            {
                var v = p.Origin + LandDefs.BlockOffset(frameCell, p.CellId);
                w.WriteNumberValue(v.X); w.WriteNumberValue(v.Y); w.WriteNumberValue(v.Z);
            }
        w.WriteEndArray();
        w.WriteNumber("frames", frames.Count);
        Vectors(w, "position", frames, f => f.Position);
        Uints(w, "cell", frames, f => f.Cell);
        w.WriteStartArray("flags");
        foreach (var f in frames) w.WriteNumberValue((int)FlagsOf(f));
        w.WriteEndArray();
        w.WriteStartArray("outcome");
        for (int f = 0; f < frames.Count; f++) w.WriteNumberValue((int)OutcomeOf(frames[f], points[f], points[f + 1]));
        w.WriteEndArray();
        w.WriteStartArray("breaks");
        foreach (int f in PathBreaks.Of(frames, points, frameCell)) w.WriteNumberValue(f);
        w.WriteEndArray();
        Vectors(w, "contactNormal", frames, f => f.ContactPlane.Normal);
        Floats(w, "contactD", frames, f => f.ContactPlane.D);
        Uints(w, "contactCell", frames, f => f.ContactPlaneCell);
        Vectors(w, "collisionNormal", frames, f => f.CollisionNormal);
        Vectors(w, "slidingNormal", frames, f => f.SlidingNormal);
        w.WriteStartArray("collided");
        foreach (var f in frames)
        {
            w.WriteStartArray();
            foreach (uint id in f.CollidedObjects) w.WriteNumberValue(id);
            w.WriteEndArray();
        }
        w.WriteEndArray();
        bool body = frames.Any(f => f.Step is not null);
        if (!body)
        {
            Vectors(w, "targetOrigin", frames, f => f.Target.Frame.Origin);
            Uints(w, "targetCell", frames, f => f.Target.CellId);
            Quaternions(w, "targetRotation", frames, f => f.Target.Frame.Orientation);
        }
        else
        {
            w.WriteStartArray("dt");
            foreach (var f in frames) w.WriteNumberValue(f.Step?.Elapsed ?? 0);
            w.WriteEndArray();
            Vectors(w, "desiredVelocity", frames, f => f.Step?.DesiredVelocity ?? default);
            Floats(w, "jump", frames, f => f.Step?.JumpVelocity ?? 0f);
            Vectors(w, "velocity", frames, f => f.Velocity);
            w.WriteStartArray("quanta");
            foreach (var f in frames) w.WriteNumberValue(f.Quanta);
            w.WriteEndArray();
        }
        if (frames.Any(f => f.Motion is not null))
        {
            Quaternions(w, "rotation", frames, f => f.Motion?.Rotation ?? Quaternion.Identity);
            Uints(w, "style", frames, f => f.Motion?.Interpreted.Style ?? 0);
            Uints(w, "forward", frames, f => f.Motion?.Interpreted.ForwardCommand ?? 0);
            Floats(w, "forwardSpeed", frames, f => f.Motion?.Interpreted.ForwardSpeed ?? 0f);
            Uints(w, "sideStep", frames, f => f.Motion?.Interpreted.SideStepCommand ?? 0);
            Floats(w, "sideStepSpeed", frames, f => f.Motion?.Interpreted.SideStepSpeed ?? 0f);
            Uints(w, "turn", frames, f => f.Motion?.Interpreted.TurnCommand ?? 0);
            Floats(w, "turnSpeed", frames, f => f.Motion?.Interpreted.TurnSpeed ?? 0f);
        }
        w.WriteStartArray("missileHits");
        for (int f = 0; f < frames.Count; f++)
            if (frames[f].Hit is { } hit)
            {
                w.WriteStartObject();
                w.WriteNumber("frame", f);
                w.WriteString("kind", hit.Kind.ToString());
                w.WriteNumber("object", hit.ObjectId);
                w.WriteNumber("quantum", hit.Quantum);
                w.WriteEndObject();
            }
        w.WriteEndArray();
        w.WriteEndObject();
    }

    private static SortedSet<uint> CommandIds(Trajectory trajectory)
    {
        var ids = new SortedSet<uint>();
        foreach (var mover in trajectory.Movers)
            foreach (var f in mover.Frames)
                if (f.Motion is { } m)
                {
                    ids.Add(m.Interpreted.Style);
                    ids.Add(m.Interpreted.ForwardCommand);
                    ids.Add(m.Interpreted.SideStepCommand);
                    ids.Add(m.Interpreted.TurnCommand);
                }
        return ids;
    }
}
