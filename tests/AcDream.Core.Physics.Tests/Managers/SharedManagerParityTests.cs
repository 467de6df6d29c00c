using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Numerics;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>
/// The managers against ACE's recordings in the shared folder (shared/ace-managers), frame by frame where ACE follows
/// retail, and the first frame where it does not, asserted as retail's outcome (docs/open-questions.md says why).
/// Compiled only when the folder exists (see the test project).
/// </summary>
public partial class SharedManagerParityTests
{
    private const float Tolerance = 1e-3f;

    private static JsonElement Load(string name)
    {
        string path = Path.Combine(Parity.SharedFolders.Find("ace-managers")!, name + ".json.gz");
        using var gz = new GZipStream(File.OpenRead(path), CompressionMode.Decompress);
        return JsonDocument.Parse(gz).RootElement.Clone();
    }

    private static Vector3 Vec(JsonElement e) => new(e[0].GetSingle(), e[1].GetSingle(), e[2].GetSingle());

    private static void Same(JsonElement frame, ManagerRig rig, int index)
    {
        var expected = Vec(frame.GetProperty("origin"));
        uint cell = Convert.ToUInt32(frame.GetProperty("cell").GetString()![2..], 16);
        Assert.True(cell >> 16 == rig.State.Position.CellId >> 16, $"frame {index}: landblock 0x{rig.State.Position.CellId:X8}, ACE 0x{cell:X8}");
        Assert.True(Vector3.Distance(expected, rig.Origin) < Tolerance, $"frame {index}: origin {rig.Origin}, ACE {expected}");
        InterpolationTests.AssertHeading(frame.GetProperty("aceHeading").GetSingle(), rig.Heading);
    }

    [GeneratedRegex(@"^InterpolateTo\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\)")]
    private static partial Regex InterpolateCall();

    [Fact]
    public void InterpolateAppliedOffset_MatchesAceUntilTheWall_ThenBlipsAsRetailDoes()
    {
        // ACE (with its two slips neutralised) follows retail for the 5 Hz updates and the approach to the door: the
        // progress check of frame 99 passes in both (0.95 m made since frame 94: 30 % of 19 m/s × 5/30 s), the check of
        // frame 104 finds no progress and fails the last node in both. Then retail's UseTime blips to the failed node
        // (blipto_position) in the same quantum; ACE's throws (PositionQueue.Last of an empty queue) and the object stays
        // at the door. From frame 120 (the 150 m update: a blip in both) the two agree again.
        var file = Load("interpolate-applied-offset");
        var frames = file.GetProperty("frames");
        var calls = new Dictionary<int, Vector3>();
        foreach (var e in file.GetProperty("events").EnumerateArray())
        {
            var m = InterpolateCall().Match(e.GetProperty("command").GetString()!);
            Assert.True(m.Success);
            calls[e.GetProperty("frame").GetInt32()] = new Vector3(Parse(m.Groups[1].Value), Parse(m.Groups[2].Value), Parse(m.Groups[3].Value));
        }
        var rig = new ManagerRig(100f, 84f);
        for (int f = 0; f < frames.GetArrayLength(); f++)
        {
            if (calls.TryGetValue(f, out var g))
            {
                uint block = g.Y >= 192f ? ManagerRig.NorthBlock : ManagerRig.Block;
                rig.InterpolateTo(g.X, g.Y >= 192f ? g.Y - 192f : g.Y, block);
            }
            rig.Frame();
            if (f < 104 || f >= 120)
                Same(frames[f], rig, f);
            else
                Assert.Equal(new Vector2(100f, 101.5f), new Vector2(rig.Origin.X, rig.Origin.Y)); // retail: blipped behind the door
        }
    }

    [Fact]
    public void Sticky_MatchesAce_TheStickEndingOneQuantumEarlierOnTheQuantumClock()
    {
        // stick_to_object at frame 3; the target moves after the mover's quantum from frame 6 on (ACE reads it live:
        // the caller's UpdateTarget before each frame gives the position after the previous one). Both end the stick
        // 1 s after StickTo; ours counts quanta of (float)(1/30) (33 of them exceed 3 + 1 s: frame 32), ACE's timer adds
        // a double 1/30 (frame 33), so ACE moves once more at frame 33.
        var file = Load("sticky");
        var frames = file.GetProperty("frames");
        const uint target = 0x50000002;
        var rig = new ManagerRig(60f, 60f);
        var targetAt = ManagerRig.At(60f, 61.6f);
        for (int f = 0; f < frames.GetArrayLength(); f++)
        {
            if (f == 3)
                rig.Manager.StickTo(target, 0.48f, 1.835f, rig.Mover);
            if (f >= 3)
                rig.Manager.UpdateTarget(target, targetAt);
            rig.Frame();
            if (f <= 32)
                Same(frames[f], rig, f);
            if (f == 32)
                Assert.Equal(0u, rig.Manager.StickyTargetId);
            var other = frames[f].GetProperty("others")[0];
            targetAt = new Position(targetAt.CellId, Vec(other.GetProperty("origin")));
        }
        Assert.Equal(0u, rig.Manager.StickyTargetId);
        Assert.True(Vector3.Distance(Vec(frames[32].GetProperty("origin")), rig.Origin) < Tolerance);
    }

    private static float Parse(string s) => float.Parse(s, CultureInfo.InvariantCulture);
}
