using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>Every kind of bad scene input is refused with a message that starts with the JSON path of the bad value.</summary>
public class SceneLoaderTests
{
    private const string Valid = """
        {
          "version": 1,
          "models": { "slab": { "box": { "min": [-0.5, -0.1, 0], "max": [0.5, 0.1, 2] } } },
          "setups": {
            "door": { "parts": [{ "model": "slab" }], "cylSpheres": [{ "lowPoint": [0, 0, 0], "radius": 0.5, "height": 0.2 }] },
            "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 }
          },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "objects": [{ "id": "0x70000001", "setup": "door", "position": [100, 100, 0], "state": ["ReportCollisions"] }],
          "movers": [{ "name": "m", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [[0, 0.1, 0], { "offset": [0, 0.1, 0], "count": 3 }] }]
        }
        """;

    private static JsonObject Doc() => JsonNode.Parse(Valid)!.AsObject();

    private static SceneFormatException Refused(JsonObject doc) => Refused(doc.ToJsonString());

    private static SceneFormatException Refused(string json) => Assert.Throws<SceneFormatException>(() => SceneLoader.Load(json));

    private static void AssertPath(SceneFormatException ex, string path, string detail)
    {
        Assert.StartsWith(path + ": ", ex.Message);
        Assert.Equal(path, ex.JsonPath);
        Assert.Contains(detail, ex.Message);
    }

    [Fact]
    public void TheValidScene_Loads()
    {
        var scene = SceneLoader.Load(Valid, "valid");
        Assert.Equal("valid", scene.Name);
        Assert.Single(scene.Movers);
        Assert.Equal(4, scene.Movers[0].FrameCount);
        Assert.True(scene.World.Objects.Contains(0x70000001));
        Assert.Equal(SceneLoader.Sha256Of(Valid), scene.Sha256);
        Assert.Equal(SceneLoader.Sha256Of(Valid.Replace("\n", "\r\n")), scene.Sha256);
    }

    [Fact]
    public void BadJson_NamesTheLine()
    {
        var ex = Refused("{\n  \"version\": 1,\n  \"movers\": [\n}");
        Assert.Equal("", ex.JsonPath);
        Assert.StartsWith("invalid JSON at line 4", ex.Message);
    }

    [Fact]
    public void WrongType_NamesThePath()
    {
        var doc = Doc();
        doc["objects"]![0]!["position"] = "here";
        AssertPath(Refused(doc), "objects[0].position", "expected an array, got the string \"here\"");
    }

    [Fact]
    public void WrongTypeInsideAVector_NamesTheElement()
    {
        var doc = Doc();
        doc["movers"]![0]!["position"]![1] = true;
        AssertPath(Refused(doc), "movers[0].position[1]", "expected a number, got true");
    }

    [Fact]
    public void UnknownField_IsATypo()
    {
        var doc = Doc();
        doc["objects"]![0]!["rotaton"] = new JsonArray(1, 0, 0, 0);
        AssertPath(Refused(doc), "objects[0].rotaton", "unknown field");
    }

    /// <summary>
    /// The typo rule: a misspelt field is reported as unknown, at its own path, before the missing-field
    /// error it causes ("position" is required, and the mover has "postion").
    /// </summary>
    [Fact]
    public void MisspeltRequiredField_IsReportedAsUnknown_BeforeTheMissingField()
    {
        var doc = Doc();
        var mover = doc["movers"]![0]!.AsObject();
        mover["postion"] = mover["position"]!.DeepClone();
        mover.Remove("position");
        var ex = Refused(doc);
        Assert.Equal("movers[0].postion: unknown field \"postion\"; did you mean \"position\"?", ex.Message);
        Assert.Equal("movers[0].postion", ex.JsonPath);
    }

    [Theory]
    [InlineData("setup", "setpu", "setup")]        // two letters swapped, in "exactly one of setup or spheres"
    [InlineData("floorZ", "floorz", "floorZ")]     // the case, in "exactly one of floorZ, airborne or start"
    [InlineData("name", "nme", "name")]            // a letter left out of a short name
    public void MisspeltField_NamesTheFieldMeant(string field, string typo, string meant)
    {
        var doc = Doc();
        var mover = doc["movers"]![0]!.AsObject();
        mover[typo] = mover[field]!.DeepClone();
        mover.Remove(field);
        AssertPath(Refused(doc), $"movers[0].{typo}", $"unknown field \"{typo}\"; did you mean \"{meant}\"?");
    }

    [Fact]
    public void MisspeltOptionalField_IsUnknown_WithADidYouMean()
    {
        var doc = Doc();
        doc["objects"]![0]!["rotaton"] = new JsonArray(1, 0, 0, 0);
        AssertPath(Refused(doc), "objects[0].rotaton", "unknown field \"rotaton\" (did you mean \"rotation\"? expected one of:");
    }

    [Fact]
    public void AMissingField_WithAnUnrelatedUnknownField_IsStillRequired()
    {
        var doc = Doc();
        var mover = doc["movers"]![0]!.AsObject();
        mover.Remove("position");
        mover["colour"] = "red";
        AssertPath(Refused(doc), "movers[0].position", "is required");
    }

    [Fact]
    public void UnknownTopLevelField_IsATypo()
    {
        var doc = Doc();
        doc["mover"] = new JsonArray();
        AssertPath(Refused(doc), "mover", "unknown field");
    }

    [Fact]
    public void ZeroQuaternion()
    {
        var doc = Doc();
        doc["objects"]![0]!["rotation"] = new JsonArray(0, 0, 0, 0);
        Assert.Equal("objects[0].rotation: quaternion has zero length.", Refused(doc).Message);
    }

    [Fact]
    public void QuaternionWithThreeNumbers()
    {
        var doc = Doc();
        doc["objects"]![0]!["rotation"] = new JsonArray(1, 0, 0);
        AssertPath(Refused(doc), "objects[0].rotation", "needs 4 numbers");
    }

    [Fact]
    public void NegativeRadius()
    {
        var doc = Doc();
        doc["setups"]!["player"]!["spheres"]![0]!["radius"] = -0.48;
        AssertPath(Refused(doc), "setups.player.spheres[0].radius", "greater than zero");
    }

    [Fact]
    public void NegativeCylinderHeight()
    {
        var doc = Doc();
        doc["setups"]!["door"]!["cylSpheres"]![0]!["height"] = -1;
        AssertPath(Refused(doc), "setups.door.cylSpheres[0].height", "zero or more");
    }

    [Fact]
    public void UnknownCell()
    {
        var doc = Doc();
        doc["objects"]![0]!["cell"] = "0xA9B40100";
        AssertPath(Refused(doc), "objects[0].cell", "unknown cell 0xA9B40100");
    }

    [Fact]
    public void PositionOutsideTheLandblock()
    {
        var doc = Doc();
        doc["movers"]![0]!["position"] = new JsonArray(-5, 98, 0);
        AssertPath(Refused(doc), "movers[0].position", "outside landblock 0xA9B4");
    }

    [Fact]
    public void BrokenBspChildIndex()
    {
        var doc = Doc();
        doc["models"]!["slab"] = JsonNode.Parse("""
            { "polygons": [{ "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0]] }],
              "nodes": [{ "splitPlane": { "normal": [0, 0, 1], "d": 0 }, "front": 1, "back": 9 }, { "leaf": true, "polygons": [0] }] }
            """);
        AssertPath(Refused(doc), "models.slab.nodes[0].back", "child index 9 is out of range 0..1");
    }

    [Fact]
    public void BspPolygonIndexOutOfRange()
    {
        var doc = Doc();
        doc["models"]!["slab"] = JsonNode.Parse("""
            { "polygons": [{ "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0]] }], "nodes": [{ "leaf": true, "polygons": [0, 3] }] }
            """);
        AssertPath(Refused(doc), "models.slab.nodes[0].polygons[1]", "polygon index 3 is out of range");
    }

    [Fact]
    public void PolygonWithTwoVertices()
    {
        var doc = Doc();
        doc["models"]!["slab"] = JsonNode.Parse("""{ "polygons": [{ "vertices": [[0, 0, 0], [1, 0, 0]] }] }""");
        AssertPath(Refused(doc), "models.slab.polygons[0].vertices", "at least 3 vertices, got 2");
    }

    /// <summary>The library's own validation (here Polygon's degenerate check) is wrapped: the message starts with the JSON path.</summary>
    [Fact]
    public void DegeneratePolygon_LibraryErrorIsWrappedWithThePath()
    {
        var doc = Doc();
        doc["models"]!["slab"] = JsonNode.Parse("""{ "polygons": [{ "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0]] }] }""");
        var ex = Refused(doc);
        AssertPath(ex, "models.slab.polygons[0]", "degenerate polygon");
        Assert.IsAssignableFrom<ArgumentException>(ex.InnerException);
    }

    [Fact]
    public void LibraryErrorWithoutAPath_GetsThePathPrefixed()
    {
        var doc = Doc();
        doc["envCells"] = JsonNode.Parse("""[{ "id": "0xA9B40100", "position": [100, 100, 0], "cellModel": "slab" }]""");
        doc["buildings"] = JsonNode.Parse("""
            [{ "shell": "slab", "position": [100, 100, 0], "entranceCells": ["0xA9B40100"] },
             { "shell": "slab", "position": [101, 101, 0] }]
            """);
        var ex = Refused(doc);
        Assert.StartsWith("buildings[1]: ", ex.Message);
        Assert.Contains("already has a building", ex.Message);
        Assert.DoesNotContain("(Parameter", ex.Message);
    }

    [Fact]
    public void UnknownSetupReference_ListsTheKnownOnes()
    {
        var doc = Doc();
        doc["objects"]![0]!["setup"] = "dor";
        AssertPath(Refused(doc), "objects[0].setup", "unknown setup \"dor\" (known: door, player)");
    }

    [Fact]
    public void UnknownModelReference()
    {
        var doc = Doc();
        doc["setups"]!["door"]!["parts"]![0]!["model"] = "slob";
        AssertPath(Refused(doc), "setups.door.parts[0].model", "unknown model \"slob\"");
    }

    [Fact]
    public void UnsupportedVersion()
    {
        var doc = Doc();
        doc["version"] = 2;
        AssertPath(Refused(doc), "version", "unsupported scene format version 2");
    }

    [Fact]
    public void MissingRequiredField()
    {
        var doc = Doc();
        doc.Remove("movers");
        AssertPath(Refused(doc), "movers", "is required");
    }

    [Fact]
    public void UnknownFlagName()
    {
        var doc = Doc();
        doc["objects"]![0]!["state"] = new JsonArray("ReportCollisions", "HasPhysicsBSP");
        AssertPath(Refused(doc), "objects[0].state[1]", "unknown PhysicsState flag \"HasPhysicsBSP\"");
    }

    [Fact]
    public void BadHexId()
    {
        var doc = Doc();
        doc["objects"]![0]!["id"] = "0xZZ";
        AssertPath(Refused(doc), "objects[0].id", "expected an id");
    }

    [Fact]
    public void DuplicateObjectId()
    {
        var doc = Doc();
        doc["objects"]!.AsArray().Add(JsonNode.Parse("""{ "id": "0x70000001", "setup": "door", "position": [110, 100, 0] }"""));
        AssertPath(Refused(doc), "objects[1].id", "appears twice");
    }

    [Fact]
    public void ZeroRepeatCount()
    {
        var doc = Doc();
        doc["movers"]![0]!["motion"]![1]!["count"] = 0;
        AssertPath(Refused(doc), "movers[0].motion[1].count", "must be 1 or more");
    }

    [Fact]
    public void MoverWithThreeSpheres()
    {
        var doc = Doc();
        doc["movers"]![0]!.AsObject().Remove("setup");
        doc["movers"]![0]!["spheres"] = JsonNode.Parse("""[{ "center": [0,0,0.5], "radius": 0.5 }, { "center": [0,0,1], "radius": 0.5 }, { "center": [0,0,1.5], "radius": 0.5 }]""");
        doc["movers"]![0]!["stepUpHeight"] = 0.6;
        doc["movers"]![0]!["stepDownHeight"] = 0.04;
        AssertPath(Refused(doc), "movers[0].spheres", "one or two spheres, got 3");
    }

    [Fact]
    public void MoverNeitherGroundedNorAirborne()
    {
        var doc = Doc();
        doc["movers"]![0]!.AsObject().Remove("floorZ");
        AssertPath(Refused(doc), "movers[0]", "\"floorZ\"");
    }

    [Fact]
    public void LandblockWithEightyHeights()
    {
        var doc = Doc();
        doc["landblocks"]![0]!.AsObject().Remove("height");
        doc["landblocks"]![0]!["heights"] = new JsonArray(Enumerable.Repeat(0, 80).Select(v => (JsonNode?)v).ToArray());
        AssertPath(Refused(doc), "landblocks[0].heights", "expected 81 values");
    }

    [Fact]
    public void NumberTooLargeForAFloat()
    {
        var doc = Doc();
        doc["objects"]![0]!["scale"] = JsonNode.Parse("1e39");
        AssertPath(Refused(doc), "objects[0].scale", "out of range for a float");
    }

    [Fact]
    public void DuplicateField()
    {
        string json = Valid.Replace("\"floorZ\": 0,", "\"floorZ\": 0, \"floorZ\": 1,");
        AssertPath(Refused(json), "movers[0].floorZ", "more than once");
    }

    /// <summary>
    /// A scene's <c>portalSide</c> says the owning cell lies in front of the portal polygon; retail's portal_side
    /// (<see cref="CellPortal.PortalSide"/>, <c>!(flags &amp; 2)</c> in CCellPortal::UnPack) is true when it lies behind:
    /// the loader gives the opposite. The cottage's doorway ("portalSide": true) faces +y into the room's cell box
    /// (y 0 to 4), whose centre is in front of it, so retail's side is false.
    /// </summary>
    [Fact]
    public void PortalSide_IsRetailsPortalSide_TheOppositeOfTheScenesFlag()
    {
        var room = Assert.IsType<EnvCell>(SceneLibrary.Load("cottage").World.Cells.Get(0xA9B40100));
        var doorway = Assert.Single(room.Portals.ToArray());
        Assert.True(AcDream.Core.Physics.Geometry.VectorMath.Distance(doorway.Polygon.Plane, new Vector3(0f, 2f, 1.5f)) > 0f);
        Assert.False(doorway.PortalSide);
    }

    [Fact]
    public void PortalToAnUnknownCell()
    {
        var doc = Doc();
        doc["envCells"] = JsonNode.Parse("""
            [{ "id": "0xA9B40100", "position": [100, 100, 0], "cellModel": "slab",
               "portals": [{ "polygon": { "vertices": [[0, 0, 0], [1, 0, 0], [1, 0, 1]] }, "otherCell": "0xA9B40105", "portalSide": true }] }]
            """);
        AssertPath(Refused(doc), "envCells[0].portals[0].otherCell", "unknown cell 0xA9B40105");
    }

    [Fact]
    public void TrajectoryFile_UnknownFieldInAFrame_NamesThePath()
    {
        string json = SceneRunner.Run(SceneLoader.Load(Valid)).ToJson().Replace("\"succeeded\":true}", "\"succeeded\":true,\"extra\":1}");
        var ex = Assert.Throws<SceneFormatException>(() => Trajectory.Parse(json));
        Assert.StartsWith("movers[0].frames[0].extra: unknown field", ex.Message);
    }
}
