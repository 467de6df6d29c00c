using AcDream.Core.Physics.Motion;
using AnimationFlags = DatReaderWriter.Enums.AnimationFlags;
using AnimationFrame = DatReaderWriter.Types.AnimationFrame;
using DrwFrame = DatReaderWriter.Types.Frame;
using MotionCommandData = DatReaderWriter.Types.MotionCommandData;
using DrwAnimation = DatReaderWriter.DBObjs.Animation;
using DrwAnimData = DatReaderWriter.Types.AnimData;
using DrwMotionData = DatReaderWriter.Types.MotionData;
using DrwMotionTable = DatReaderWriter.DBObjs.MotionTable;
using DrwMotionDataFlags = DatReaderWriter.Enums.MotionDataFlags;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// Writes one of our motion tables as the DAT objects retail stores it in: a MotionTable and one Animation per
/// animation (one part, identity part frames, the root frames as PosFrames under flag 1). The test side of the
/// round trip; the adapter reads the other way.
/// </summary>
internal static class MotionTableWriter
{
    public static DrwMotionTable Table(MotionTable table)
    {
        var drw = new DrwMotionTable { Id = table.Id, DefaultStyle = (DatReaderWriter.Enums.MotionCommand)table.DefaultStyle };
        foreach (var (style, substate) in table.StyleDefaults)
            drw.StyleDefaults[(DatReaderWriter.Enums.MotionCommand)style] = (DatReaderWriter.Enums.MotionCommand)substate;
        foreach (var (key, data) in table.Cycles)
            drw.Cycles[unchecked((int)key)] = Data(data);
        foreach (var (key, data) in table.Modifiers)
            drw.Modifiers[unchecked((int)key)] = Data(data);
        foreach (uint outer in table.LinkKeys)
        {
            var inner = new MotionCommandData();
            foreach (var (motion, data) in table.LinksFrom(outer)!)
                inner.MotionData[unchecked((int)motion)] = Data(data);
            drw.Links[unchecked((int)outer)] = inner;
        }
        return drw;
    }

    public static DrwMotionData Data(MotionData data)
    {
        var drw = new DrwMotionData { Bitfield = data.Bitfield, Flags = (DrwMotionDataFlags)(byte)data.Flags, Velocity = data.Velocity, Omega = data.Omega };
        foreach (var a in data.Anims)
            drw.Anims.Add(new DrwAnimData { AnimId = a.AnimationId, LowFrame = a.LowFrame, HighFrame = a.HighFrame, Framerate = a.Framerate });
        return drw;
    }

    public static DrwAnimation Animation(Animation animation)
    {
        var drw = new DrwAnimation { Id = animation.Id, NumParts = 1 };
        if (animation.RootFrames.Length != 0)
            drw.Flags = AnimationFlags.PosFrames;
        foreach (var root in animation.RootFrames)
            drw.PosFrames.Add(new DrwFrame { Origin = root.Origin, Orientation = root.Orientation });
        for (int i = 0; i < animation.FrameCount; i++)
            drw.PartFrames.Add(new AnimationFrame(1) { Frames = [new DrwFrame { Orientation = Quaternion.Identity }] });
        return drw;
    }

    /// <summary>The table and its animations, as a portal DAT's objects.</summary>
    public static IEnumerable<DatReaderWriter.Types.DBObj> Objects(MotionTable table)
    {
        yield return Table(table);
        foreach (var (_, animation) in table.Animations)
            yield return Animation(animation);
    }
}
