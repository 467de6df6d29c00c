using System.IO;
using System.Text.Json;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tool;
using AcDream.Core.Physics.Tool.View;
using AcDream.Core.Physics.Viewer;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.Viewer;

/// <summary>
/// <c>acdream-physics view</c>: the page it writes holds every frame of every mover exactly as the trajectory file holds
/// it (the same number texts), every collision shape of the world, the path breaks at blips and teleports, and nothing
/// fetched from outside; a trajectory beyond the caps is refused on one line with exit code 2.
/// </summary>
public sealed class ViewPageTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("acdream-view-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Tool(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = ToolProgram.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    private static string ReplayPath(string scene) => Path.Combine(AppContext.BaseDirectory, "Replays", $"{scene}.trajectory.json");

    /// <summary>Writes the page for a built-in scene and its committed trajectory; returns the page's text.</summary>
    private string Page(string scene, string? trajectory = null)
    {
        string html = Path.Combine(_dir, $"{scene}.html");
        var (code, output, err) = Tool("view", scene, trajectory ?? ReplayPath(scene), "--out", html);
        Assert.True(code == 0, $"view {scene} exited {code}: {err}");
        Assert.Contains($"view written to {html}", output);
        return File.ReadAllText(html);
    }

    /// <summary>The page's data: the text of its JSON script element.</summary>
    private static JsonDocument Data(string page)
    {
        var m = Regex.Match(page, "<script type=\"application/json\" id=\"view-data\">(.*?)</script>", RegexOptions.Singleline);
        Assert.True(m.Success, "the page has no data element");
        return JsonDocument.Parse(m.Groups[1].Value);
    }

    private static uint Id(JsonElement hexString) => Convert.ToUInt32(hexString.GetString()![2..], 16);

    /// <summary>A page column's entries <c>[width × f, width × (f + 1))</c>, as their JSON texts.</summary>
    private static string[] Slice(JsonElement column, int f, int width) =>
        Enumerable.Range(width * f, width).Select(i => column[i].GetRawText()).ToArray();

    private static string[] Texts(JsonElement array) => array.EnumerateArray().Select(e => e.GetRawText()).ToArray();

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void EveryFrameOfEveryMover_IsInThePage_WithTheTrajectorysNumberTexts(string scene)
    {
        using var data = Data(Page(scene));
        using var trajectory = JsonDocument.Parse(File.ReadAllText(ReplayPath(scene)));
        var movers = trajectory.RootElement.GetProperty("movers");
        var pageMovers = data.RootElement.GetProperty("movers");
        Assert.Equal(movers.GetArrayLength(), pageMovers.GetArrayLength());
        for (int m = 0; m < movers.GetArrayLength(); m++)
        {
            var frames = movers[m].GetProperty("frames");
            var page = pageMovers[m];
            Assert.Equal(movers[m].GetProperty("name").GetString(), page.GetProperty("name").GetString());
            Assert.Equal(frames.GetArrayLength(), page.GetProperty("frames").GetInt32());
            for (int f = 0; f < frames.GetArrayLength(); f++)
            {
                var fr = frames[f];
                string at = $"{scene} mover {m} frame {f}";
                void Same(string[] expected, string[] actual, string field) =>
                    Assert.True(expected.SequenceEqual(actual), $"{at}: {field} [{string.Join(", ", actual)}], trajectory [{string.Join(", ", expected)}]");
                Same(Texts(fr.GetProperty("position")), Slice(page.GetProperty("position"), f, 3), "position");
                Assert.Equal(Id(fr.GetProperty("cell")), page.GetProperty("cell")[f].GetUInt32());
                int flags = page.GetProperty("flags")[f].GetInt32();
                var cp = fr.GetProperty("contactPlane");
                Assert.True(fr.GetProperty("contact").GetBoolean() == ((flags & 1) != 0), $"{at}: contact");
                Assert.True(fr.GetProperty("onWalkable").GetBoolean() == ((flags & 2) != 0), $"{at}: onWalkable");
                Assert.True(cp.GetProperty("valid").GetBoolean() == ((flags & 4) != 0), $"{at}: contactPlane.valid");
                Assert.True(fr.GetProperty("collisionNormal").GetProperty("valid").GetBoolean() == ((flags & 8) != 0), $"{at}: collisionNormal.valid");
                Assert.True(fr.GetProperty("slidingNormal").GetProperty("valid").GetBoolean() == ((flags & 16) != 0), $"{at}: slidingNormal.valid");
                Assert.True(fr.GetProperty("succeeded").GetBoolean() == ((flags & 32) != 0), $"{at}: succeeded");
                Same(Texts(cp.GetProperty("normal")), Slice(page.GetProperty("contactNormal"), f, 3), "contactPlane.normal");
                Same([cp.GetProperty("d").GetRawText()], Slice(page.GetProperty("contactD"), f, 1), "contactPlane.d");
                Assert.Equal(Id(cp.GetProperty("cell")), page.GetProperty("contactCell")[f].GetUInt32());
                Same(Texts(fr.GetProperty("collisionNormal").GetProperty("vector")), Slice(page.GetProperty("collisionNormal"), f, 3), "collisionNormal");
                Same(Texts(fr.GetProperty("slidingNormal").GetProperty("vector")), Slice(page.GetProperty("slidingNormal"), f, 3), "slidingNormal");
                Assert.Equal(fr.GetProperty("collided").EnumerateArray().Select(Id), page.GetProperty("collided")[f].EnumerateArray().Select(e => e.GetUInt32()));
                if (fr.TryGetProperty("target", out var target))
                {
                    Same(Texts(target.GetProperty("origin")), Slice(page.GetProperty("targetOrigin"), f, 3), "target.origin");
                    Assert.Equal(Id(target.GetProperty("cell")), page.GetProperty("targetCell")[f].GetUInt32());
                    Same(Texts(target.GetProperty("rotation")), Slice(page.GetProperty("targetRotation"), f, 4), "target.rotation");
                }
                else
                {
                    var step = fr.GetProperty("step");
                    var body = fr.GetProperty("body");
                    Same([step.GetProperty("dt").GetRawText()], Slice(page.GetProperty("dt"), f, 1), "step.dt");
                    Same(Texts(step.GetProperty("velocity")), Slice(page.GetProperty("desiredVelocity"), f, 3), "step.velocity");
                    Same([step.GetProperty("jump").GetRawText()], Slice(page.GetProperty("jump"), f, 1), "step.jump");
                    Same(Texts(body.GetProperty("velocity")), Slice(page.GetProperty("velocity"), f, 3), "body.velocity");
                    Same([body.GetProperty("quanta").GetRawText()], Slice(page.GetProperty("quanta"), f, 1), "body.quanta");
                }
                if (fr.TryGetProperty("motion", out var motion))
                {
                    Same(Texts(motion.GetProperty("rotation")), Slice(page.GetProperty("rotation"), f, 4), "motion.rotation");
                    Assert.Equal(Id(motion.GetProperty("style")), page.GetProperty("style")[f].GetUInt32());
                    foreach (string name in new[] { "forward", "sideStep", "turn" })
                    {
                        Assert.Equal(Id(motion.GetProperty(name).GetProperty("command")), page.GetProperty(name)[f].GetUInt32());
                        Same([motion.GetProperty(name).GetProperty("speed").GetRawText()], Slice(page.GetProperty(name + "Speed"), f, 1), $"motion.{name}.speed");
                    }
                }
                var hits = page.GetProperty("missileHits").EnumerateArray().Where(h => h.GetProperty("frame").GetInt32() == f).ToArray();
                if (fr.TryGetProperty("hit", out var hit))
                {
                    var h = Assert.Single(hits);
                    Assert.Equal(hit.GetProperty("kind").GetString(), h.GetProperty("kind").GetString());
                    Assert.Equal(Id(hit.GetProperty("object")), h.GetProperty("object").GetUInt32());
                    Assert.Equal(hit.GetProperty("quantum").GetInt32(), h.GetProperty("quantum").GetInt32());
                }
                else
                    Assert.Empty(hits);
            }
        }
    }

    public static TheoryData<string> BuiltInScenes()
    {
        var names = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            names.Add(name);
        return names;
    }

    /// <summary>A shape as a comparable key: what it belongs to, its form, ids, and its numbers.</summary>
    private static string Key(string source, string form, uint cell, uint obj, bool collides, IEnumerable<float> numbers) =>
        $"{source} {form} 0x{cell:X8} 0x{obj:X8} {collides} [{string.Join(", ", numbers.Select(v => v.ToString("R", System.Globalization.CultureInfo.InvariantCulture)))}]";

    private static string PageKey(JsonElement s)
    {
        string form = s.GetProperty("form").GetString()!;
        var numbers = form == "polygon"
            ? s.GetProperty("vertices").EnumerateArray().Select(e => e.GetSingle())
            : s.GetProperty("center").EnumerateArray().Select(e => e.GetSingle()).Append(s.GetProperty("radius").GetSingle())
                .Concat(form == "cylinder" ? [s.GetProperty("height").GetSingle()] : []);
        return Key(s.GetProperty("source").GetString()!, form, s.GetProperty("cell").GetUInt32(),
            s.TryGetProperty("object", out var o) ? o.GetUInt32() : 0, s.GetProperty("collides").GetBoolean(), numbers);
    }

    [Theory]
    [InlineData("door")]
    [InlineData("cottage")]
    [InlineData("cellar")]
    [InlineData("arrows")]
    [InlineData("remote-smoothing")]
    public void EveryShapeOfTheWorld_IsInThePage(string sceneName)
    {
        using var data = Data(Page(sceneName));
        var scene = SceneLibrary.Load(sceneName);
        uint frameCell = data.RootElement.GetProperty("frameCell").GetUInt32();
        Assert.Equal(scene.Movers[0].Start.Position.CellId, frameCell);
        var shapes = data.RootElement.GetProperty("shapes").EnumerateArray().ToArray();

        // Indoor cells, building shells and objects: the same shapes, placed the same, as the plot's outline of the world.
        var expected = WorldOutline.Collect(scene.World, frameCell).Select(s => Key(
            s.Source switch { OutlineSource.EnvCell => "cell", OutlineSource.Building => "building", _ => "object" },
            s.Form.ToString().ToLowerInvariant(), s.CellId, s.ObjectId, s.Collides,
            s.Form == OutlineForm.Polygon ? s.Vertices.ToArray().SelectMany(v => new[] { v.X, v.Y, v.Z })
                : new[] { s.Center.X, s.Center.Y, s.Center.Z, s.Radius }.Concat(s.Form == OutlineForm.Cylinder ? [s.Height] : []))).Order().ToArray();
        var actual = shapes.Where(s => s.GetProperty("source").GetString() is not ("terrain" or "portal")).Select(PageKey).Order().ToArray();
        Assert.Equal(expected, actual);

        // Terrain: two triangles per land cell, their corners the cell's corners at the landblock's height (every built-in
        // scene's land is flat), in the view's frame.
        var landCells = scene.World.Cells.CellIds.Where(LandDefs.IsLandCell).ToHashSet();
        var terrain = shapes.Where(s => s.GetProperty("source").GetString() == "terrain").ToArray();
        Assert.Equal(2 * landCells.Count, terrain.Length);
        foreach (var cell in terrain.GroupBy(s => s.GetProperty("cell").GetUInt32()))
        {
            Assert.Contains(cell.Key, landCells);
            Assert.Equal(2, cell.Count());
            var shift = LandDefs.BlockOffset(frameCell, cell.Key);
            var c = LandDefs.LandCellCorner(cell.Key);
            var corner = new Vector2(c.X + shift.X, c.Y + shift.Y);
            float area = 0;
            foreach (var t in cell)
            {
                Assert.Equal("single", t.GetProperty("sides").GetString());
                var v = t.GetProperty("vertices").EnumerateArray().Select(e => e.GetSingle()).ToArray();
                Assert.Equal(9, v.Length);
                for (int i = 0; i < 9; i += 3)
                {
                    Assert.True(v[i] == corner.X || v[i] == corner.X + 24, $"terrain 0x{cell.Key:X8}: x {v[i]} is not a corner of the cell at {corner}");
                    Assert.True(v[i + 1] == corner.Y || v[i + 1] == corner.Y + 24, $"terrain 0x{cell.Key:X8}: y {v[i + 1]} is not a corner");
                    Assert.Equal(shift.Z, v[i + 2]);
                }
                // Counter-clockwise from above (the walkable side up): a positive area.
                float cross = (v[3] - v[0]) * (v[7] - v[1]) - (v[4] - v[1]) * (v[6] - v[0]);
                Assert.True(cross > 0, $"terrain 0x{cell.Key:X8}: a triangle faces down");
                area += cross / 2;
            }
            Assert.Equal(24f * 24f, area);
        }

        // Portals: every indoor cell's portals, with the cell they lead to; indoor polygons keep their sidedness.
        foreach (uint id in scene.World.Cells.CellIds.Where(c => !LandDefs.IsLandCell(c)))
        {
            var env = (EnvCell)scene.World.Cells.Get(id)!;
            var portals = shapes.Where(s => s.GetProperty("source").GetString() == "portal" && s.GetProperty("cell").GetUInt32() == id).ToArray();
            Assert.Equal(env.Portals.Length, portals.Length);
            for (int i = 0; i < portals.Length; i++)
            {
                Assert.Equal(env.Portals[i].OtherCellId, portals[i].GetProperty("otherCell").GetUInt32());
                Assert.False(portals[i].GetProperty("collides").GetBoolean());
                Assert.Equal(3 * env.Portals[i].Polygon.VertexCount, portals[i].GetProperty("vertices").GetArrayLength());
            }
            var walls = shapes.Where(s => s.GetProperty("source").GetString() == "cell" && s.GetProperty("cell").GetUInt32() == id).ToArray();
            var polygons = env.PhysicsBsp?.Polygons.ToArray() ?? [];
            Assert.Equal(polygons.Length, walls.Length);
            for (int i = 0; i < walls.Length; i++)
                Assert.Equal(polygons[i].Sides.ToString().ToLowerInvariant(), walls[i].GetProperty("sides").GetString());
        }
    }

    [Fact]
    public void TheCottagesPage_HoldsItsPortalsAndDoubleSidedPolygons()
    {
        // The cottage (docs/scene-format.md) has an indoor cell with a door portal: the page must show at least one portal.
        using var data = Data(Page("cottage"));
        var sources = data.RootElement.GetProperty("shapes").EnumerateArray().Select(s => s.GetProperty("source").GetString()).ToArray();
        Assert.Contains("portal", sources);
        Assert.Contains("building", sources);
        Assert.Contains("cell", sources);
    }

    [Fact]
    public void RemoteSmoothing_BreaksItsPathAtTheBlipAndTheTeleport_AndNowhereElse()
    {
        // remote-smoothing (its scene's comment): an update behind the door slab stops the remote player, which is blipped
        // to the update (2.03 m in one frame, frame 104), and at frame 120 an update 150 m north teleports it. Its other
        // movers walk 0.63 m a frame at most: no break.
        using var data = Data(Page("remote-smoothing"));
        var movers = data.RootElement.GetProperty("movers");
        Assert.Equal([104, 120], movers[0].GetProperty("breaks").EnumerateArray().Select(e => e.GetInt32()));
        Assert.Empty(movers[1].GetProperty("breaks").EnumerateArray());
        Assert.Empty(movers[2].GetProperty("breaks").EnumerateArray());
        // The landblock north of the start (0xA9B5) is 192 m north in the view's frame.
        var north = data.RootElement.GetProperty("landblocks").GetProperty(0xA9B5u.ToString(System.Globalization.CultureInfo.InvariantCulture));
        Assert.Equal([0f, 192f, 0f], north.EnumerateArray().Select(e => e.GetSingle()));
    }

    [Fact]
    public void ThePlot_OfRemoteSmoothing_SaysWhereTheTeleportWent_AndLeavesItOutOfItsScale()
    {
        // The plot breaks its paths the same way; the 150 m teleport at frame 120 is named on its own line, not drawn
        // into the scale (before, the scale ran 150 m north and the rest of the paths were a smear).
        string png = Path.Combine(_dir, "remote.png");
        var (code, output, err) = Tool("plot", "remote-smoothing", "--out", png);
        Assert.Equal(0, code);
        Assert.Equal("", err);
        var teleports = output.Split('\n').Where(l => l.Contains("teleported", StringComparison.Ordinal)).ToArray();
        Assert.StartsWith("  remote: teleported 150.0 m at frame 120 to (", Assert.Single(teleports));
        Assert.EndsWith("); what follows is outside the plot's scale", teleports[0].TrimEnd());
    }

    [Fact]
    public void AnArrowsFiveMetreFrames_AreNotBreaks()
    {
        // fast-post-10hz flies 5 m a frame (50 m/s at 10 Hz): every frame alike, so none is a blip.
        using var data = Data(Page("arrows"));
        var mover = data.RootElement.GetProperty("movers").EnumerateArray().Single(m => m.GetProperty("name").GetString() == "fast-post-10hz");
        Assert.Empty(mover.GetProperty("breaks").EnumerateArray());
    }

    [Fact]
    public void PathBreaks_FindAMoveOverAMetreBeyondWhatTheFrameAskedFor()
    {
        // Eleven points 0.1 m apart, each frame asking for 0.1 m; point 6 pulled 1.5 m east: the move into it (frame 5)
        // and out of it (frame 6) are 1.5 m beyond what was asked. Pulled 0.9 m instead: within the metre of slack.
        var asked = Enumerable.Repeat(0.1f, 10).ToArray();
        var walk = Enumerable.Range(0, 11).Select(i => new Vector3(0, 0.1f * i, 0)).ToArray();
        Assert.Empty(PathBreaks.Find(walk, asked));
        walk[6] += new Vector3(1.5f, 0, 0);
        Assert.Equal([5, 6], PathBreaks.Find(walk, asked));
        walk[6] -= new Vector3(0.6f, 0, 0);
        Assert.Empty(PathBreaks.Find(walk, asked));
        // A frame that asked for 5 m (an arrow at 50 m/s and 10 Hz) moving 5 m is no break.
        Assert.Empty(PathBreaks.Find([Vector3.Zero, new Vector3(5, 0, 0)], [5f]));
    }

    [Fact]
    public void DoorFrames_AreColouredByTheirOutcome()
    {
        // door's front-centre (the README's table): frame 15 slides along the slab (target y 99.6, ends at 99.49998),
        // frame 16 is refused, frame 0 moves freely.
        using var data = Data(Page("door"));
        var outcome = data.RootElement.GetProperty("movers")[0].GetProperty("outcome");
        Assert.Equal((int)ViewOutcome.Moved, outcome[0].GetInt32());
        Assert.Equal((int)ViewOutcome.Slid, outcome[15].GetInt32());
        Assert.Equal((int)ViewOutcome.Refused, outcome[16].GetInt32());
    }

    [Fact]
    public void ThePage_IsSelfContained()
    {
        string page = Page("door");
        Assert.DoesNotContain(ViewCommand.DataPlaceholder, page);
        Assert.Contains("Content-Security-Policy\" content=\"default-src 'none'", page);
        // Outside the two script elements, no tag loads anything.
        string markup = Regex.Replace(page, "<script[^>]*>.*?</script>", "", RegexOptions.Singleline);
        Assert.DoesNotMatch("(?i)<(script|link|img|iframe)[^>]*(src|href)=", markup);
        Assert.Equal(2, Regex.Matches(page, "<script").Count);
        Assert.Contains("<title>door: acdream-physics view</title>", page);
        Assert.Contains("Three.js Authors\n * SPDX-License-Identifier: MIT", page); // the library's licence notice is kept
    }

    [Fact]
    public void ASceneWithoutATrajectory_IsRunFirst()
    {
        string html = Path.Combine(_dir, "boulder.html");
        var (code, output, err) = Tool("view", "boulder", "-o", html);
        Assert.Equal(0, code);
        Assert.Equal("", err);
        Assert.StartsWith($"boulder: 4 movers, 160 frames; view written to {html} (", output);
        using var data = Data(File.ReadAllText(html));
        Assert.Equal(160, data.RootElement.GetProperty("movers").EnumerateArray().Sum(m => m.GetProperty("frames").GetInt32()));
    }

    [Fact]
    public void ATrajectoryFileOverTheReadersCap_IsRefusedOnOneLine()
    {
        string big = Path.Combine(_dir, "big.trajectory.json");
        using (var file = File.Create(big))
            file.SetLength(BoundedFile.MaxTrajectoryBytes + 1);
        var (code, output, err) = Tool("view", "door", big, "--out", Path.Combine(_dir, "big.html"));
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.Equal($"acdream-physics: {big}: is {BoundedFile.MaxTrajectoryBytes + 1} bytes; a trajectory file may be at most {BoundedFile.MaxTrajectoryBytes} bytes.", err.TrimEnd());
        Assert.False(File.Exists(Path.Combine(_dir, "big.html")));
    }

    [Fact]
    public void ATrajectoryWithMoreFramesThanAPageHolds_IsRefusedOnOneLine()
    {
        // MaxFrames + 1 frames (one frame object repeated): refused before any page is built.
        var frame = SceneRunner.Run(SceneLibrary.Load("door")).Movers[0].Frames[0];
        var many = new Trajectory("door", "", "", [new MoverTrajectory("front-centre", Enumerable.Repeat(frame, ViewCommand.MaxFrames + 1).ToArray())]);
        var ex = Assert.Throws<SceneFormatException>(() => ViewCommand.CheckCaps(many, "long.trajectory.json"));
        Assert.Equal($"long.trajectory.json: has {ViewCommand.MaxFrames + 1} frames; a view page holds at most {ViewCommand.MaxFrames} (view a shorter trajectory).", ex.Message);
        ViewCommand.CheckCaps(new Trajectory("door", "", "", [new MoverTrajectory("front-centre", Enumerable.Repeat(frame, ViewCommand.MaxFrames).ToArray())]), "x");
    }

    [Fact]
    public void ViewUsageErrors_AreOneLine()
    {
        var (code, _, err) = Tool("view");
        Assert.Equal(2, code);
        Assert.Equal("acdream-physics: view needs SCENE (run 'acdream-physics help' for usage)", err.TrimEnd());
        (code, _, err) = Tool("view", "door", "a", "b");
        Assert.Equal(2, code);
        Assert.Equal("acdream-physics: unexpected argument 'b' (run 'acdream-physics help' for usage)", err.TrimEnd());
    }
}
