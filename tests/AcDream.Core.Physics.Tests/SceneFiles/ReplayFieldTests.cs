using System.IO;
using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The replay compares every recorded output field: changing any one of them in a committed frame (the
/// door's first frame with a collision, where every field is set) fails the replay at that frame, naming
/// that field.
/// </summary>
public class ReplayFieldTests
{
    private static readonly string DoorReplay = Path.Combine(AppContext.BaseDirectory, "Replays", "door.trajectory.json");

    public static TheoryData<string, string> Fields() => new()
    {
        // JSON path inside the frame, the field the replay must name.
        { "position/0", "position.x" },
        { "position/1", "position.y" },
        { "position/2", "position.z" },
        { "cell", "cell" },
        { "contact", "contact" },
        { "onWalkable", "onWalkable" },
        { "contactPlane/valid", "contactPlane.valid" },
        { "contactPlane/normal/0", "contactPlane.normal.x" },
        { "contactPlane/normal/2", "contactPlane.normal.z" },
        { "contactPlane/d", "contactPlane.d" },
        { "contactPlane/cell", "contactPlane.cell" },
        { "collisionNormal/valid", "collisionNormal.valid" },
        { "collisionNormal/vector/1", "collisionNormal.vector.y" },
        { "slidingNormal/valid", "slidingNormal.valid" },
        { "slidingNormal/vector/1", "slidingNormal.vector.y" },
        { "collided/0", "collided" },
        { "succeeded", "succeeded" },
    };

    [Theory]
    [MemberData(nameof(Fields))]
    public void ChangingOneRecordedField_FailsTheReplay_NamingIt(string path, string field)
    {
        var doc = JsonNode.Parse(File.ReadAllText(DoorReplay))!;
        var frames = doc["movers"]![0]!["frames"]!.AsArray();
        int index = frames.IndexOf(frames.First(f => f!["collided"]!.AsArray().Count > 0));
        var parts = path.Split('/');
        JsonNode parent = frames[index]!;
        for (int i = 0; i < parts.Length - 1; i++)
            parent = int.TryParse(parts[i], out int k) ? parent[k]! : parent[parts[i]]!;
        string last = parts[^1];
        JsonNode value = int.TryParse(last, out int j) ? parent[j]! : parent[last]!;
        JsonNode changed = value.GetValueKind() switch
        {
            System.Text.Json.JsonValueKind.True => JsonValue.Create(false),
            System.Text.Json.JsonValueKind.False => JsonValue.Create(true),
            System.Text.Json.JsonValueKind.Number => JsonValue.Create(value.GetValue<float>() + 0.5f),
            _ => JsonValue.Create("0xA9B40026"), // a cell or object id
        };
        if (int.TryParse(last, out j)) parent[j] = changed; else parent[last] = changed;

        var result = TrajectoryReplay.Replay(SceneLibrary.Load("door"), Trajectory.Parse(doc.ToJsonString()));

        Assert.False(result.Matches, $"changing {path} went unnoticed");
        Assert.Equal(index, result.FirstDifference!.Frame);
        Assert.Equal(field, result.FirstDifference.Field);
    }

    [Fact]
    public void TheUnchangedRecording_Replays_ExactlyAtToleranceZero()
    {
        var result = TrajectoryReplay.Replay(SceneLibrary.Load("door"), Trajectory.LoadFile(DoorReplay), ReplayTests.Exact);
        Assert.True(result.Matches, result.FirstDifference?.ToString());
    }
}
