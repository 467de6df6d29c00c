using System.IO;
using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// A scene mover's full start state ("start"): a sloped contact plane with its cell and a carried sliding
/// normal are read into the mover's <see cref="MoverState"/> as written, a recorded situation runs from
/// the tool without a harness, and every bad value is refused naming its JSON path.
/// </summary>
public class StartStateTests
{
    private const string Scene = """
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }, { "center": [0, 0, 1.35], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{
            "name": "wedged", "setup": "player", "state": ["Gravity", "EdgeSlide"], "objectInfo": ["IsPlayer"],
            "start": {
              "position": [100, 98, 0.005], "cell": "0xA9B40025", "rotation": [1, 0, 0, 0],
              "contact": 1, "walkable": 1,
              "contactPlane": [0, -0.6, 0.8, 0.5], "contactPlaneCell": "0xA9B40025", "water": 0,
              "sliding": [0, -1, 0] },
            "motion": [{ "offset": [0, 0.1, 0], "count": 3 }]
          }]
        }
        """;

    private static JsonObject Doc() => JsonNode.Parse(Scene)!.AsObject();
    private static JsonObject Start(JsonObject doc) => doc["movers"]![0]!["start"]!.AsObject();

    private static void Refused(JsonObject doc, string path, string detail)
    {
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.Equal(path, ex.JsonPath);
        Assert.Contains(detail, ex.Detail);
    }

    [Fact]
    public void AFullStartState_IsTheMoversStateAsWritten()
    {
        var start = SceneLoader.Load(Scene).Movers[0].Start;

        Assert.Equal(0xA9B40025u, start.Position.CellId);
        Assert.Equal(new Vector3(100, 98, 0.005f), start.Position.Frame.Origin);
        Assert.Equal(Quaternion.Identity, start.Position.Frame.Orientation);
        Assert.True(start.Contact);
        Assert.True(start.OnWalkable);
        Assert.Equal(new Plane(0, -0.6f, 0.8f, 0.5f), start.ContactPlane);
        Assert.Equal(0xA9B40025u, start.ContactPlaneCellId);
        Assert.False(start.ContactPlaneIsWater);
        Assert.True(start.SlidingNormalValid);
        Assert.Equal(new Vector3(0, -1, 0), start.SlidingNormal);
    }

    [Fact]
    public void NoPlaneKnown_IsCellZeroWithAZeroPlane()
    {
        var doc = Doc();
        var s = Start(doc);
        s["contact"] = 0;
        s["walkable"] = 0;
        s["contactPlane"] = new JsonArray(0, 0, 0, 0);
        s["contactPlaneCell"] = "0x00000000";
        s.Remove("sliding");

        var start = SceneLoader.Load(doc.ToJsonString()).Movers[0].Start;

        Assert.False(start.Contact);
        Assert.Equal(0u, start.ContactPlaneCellId);
        Assert.False(start.SlidingNormalValid);
    }

    [Fact]
    public void ACarriedSlidingNormal_CancelsTheMotionIntoIt_RunFromTheTool()
    {
        // The sliding normal (0, -1, 0) carried into the frame removes the whole +Y request (retail
        // AdjustOffset), so every frame is refused and the mover stays where the state put it.
        string file = Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}-wedged.json");
        try
        {
            File.WriteAllText(file, Scene);
            var stdout = new StringWriter();
            int code = ToolProgram.Run(["run", file], stdout, new StringWriter());

            Assert.Equal(0, code);
            var lines = stdout.ToString().TrimEnd().Split('\n');
            Assert.Equal(1 + 3 + 1, lines.Length);
            for (int f = 1; f <= 3; f++)
            {
                Assert.Contains("100.0000    98.0000   0.0050 0xA9B40025", lines[f]);
                Assert.EndsWith("REFUSED", lines[f].TrimEnd());
            }
            Assert.EndsWith("3 refused", lines[^1].TrimEnd());
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public void StartWithFloorZOrAirborne_IsRefused()
    {
        var doc = Doc();
        doc["movers"]![0]!["floorZ"] = 0;
        Refused(doc, "movers[0]", "exactly one of");
        doc = Doc();
        doc["movers"]![0]!["airborne"] = true;
        Refused(doc, "movers[0]", "exactly one of");
    }

    [Fact]
    public void APlacementBesideStart_IsRefused()
    {
        var doc = Doc();
        doc["movers"]![0]!["position"] = new JsonArray(100, 98, 0);
        Refused(doc, "movers[0].position", "inside \"start\"");
    }

    [Theory]
    [InlineData("contactPlane", "[0, 0, 2, 0]", "movers[0].start.contactPlane.normal", "must be a unit vector")]
    [InlineData("contactPlane", "[0, 0, 1]", "movers[0].start.contactPlane", "needs 4 numbers")]
    [InlineData("contactPlaneCell", "\"0xA9B40999\"", "movers[0].start.contactPlaneCell", "unknown cell 0xA9B40999")]
    [InlineData("cell", "\"0xA9B50025\"", "movers[0].start.cell", "unknown cell 0xA9B50025")]
    [InlineData("contact", "2", "movers[0].start.contact", "expected true, false, 0 or 1")]
    [InlineData("sliding", "[0, \"x\", 0]", "movers[0].start.sliding[1]", "expected a number")]
    [InlineData("rotation", "[0, 0, 0, 0]", "movers[0].start.rotation", "zero length")]
    [InlineData("slope", "1", "movers[0].start.slope", "unknown field")]
    public void ABadValue_IsRefusedNamingItsPath(string field, string value, string path, string detail)
    {
        var doc = Doc();
        Start(doc)[field] = JsonNode.Parse(value);
        Refused(doc, path, detail);
    }

    [Fact]
    public void InconsistentFlags_AreRefused()
    {
        var doc = Doc();
        Start(doc).Remove("contactPlane");
        Refused(doc, "movers[0].start.contactPlane", "required when \"contact\"");
        doc = Doc();
        Start(doc)["contact"] = 0;
        Refused(doc, "movers[0].start.walkable", "must also be in contact");
        doc = Doc();
        Start(doc)["contactPlaneCell"] = "0x00000000";
        Refused(doc, "movers[0].start.contactPlaneCell", "not all zero");
    }
}
