using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// Retail frame math: a frame transforms through the 3×3 matrix retail caches (Frame::cache,
/// acclient.c:356983), global→local by its transpose (Frame::globaltolocal, :143717), evaluated at the
/// x87 unit's 53-bit precision (ClientMain::ConfigureFPU, :60884) and rounded to float where retail
/// stores a float; rotations are normalized by the reciprocal length (Frame::set_rotate, :357062) and a
/// valid one is used as given. A default frame is the identity rotation.
/// </summary>
public class RetailFrameMathTests
{
    // +30° about Z, as the ACE parity file door-yaw30 gives it ([w, x, y, z]); its cached matrix holds
    // cos 30° = 0.8660254 and sin 30° = 0.5 (m0 = m4 = 0.8660254, m1 = 0.5, m3 = -0.5).
    private static readonly Quaternion Yaw30 = new(0f, 0f, 0.25881904f, 0.9659258f);
    private const float Cos30 = 0.8660254f, Sin30 = 0.5f;

    private static uint Bits(float f) => BitConverter.SingleToUInt32Bits(f);

    [Fact]
    public void DefaultFrame_HasTheIdentityRotation()
    {
        Assert.Equal(Quaternion.Identity, default(Frame).Orientation);
        Assert.Equal(Quaternion.Identity, Frame.Identity.Orientation);
        var frame = new Frame { Origin = new Vector3(10, 20, 3) };
        Assert.Equal(Quaternion.Identity, frame.Orientation);
        Assert.Equal(new Vector3(11.5f, 18f, 3.25f), frame.LocalToGlobal(new Vector3(1.5f, -2f, 0.25f)));
        Assert.Equal(new Vector3(1.5f, -2f, 0.25f), frame.GlobalToLocal(new Vector3(11.5f, 18f, 3.25f)));
    }

    [Fact]
    public void DefaultFrame_IsAcceptedByTheEngine_AsTheIdentity()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        uint cell = LandDefs.LandCellAt(0xA9B4, new Vector3(100, 100, 0));
        var withDefault = MoverState.OnFloor(new Position(cell, new Frame { Origin = new Vector3(100, 100, 0) }), 0f);
        var withIdentity = MoverState.OnFloor(new Position(cell, new Frame(new Vector3(100, 100, 0), Quaternion.Identity)), 0f);
        var target = new Position(cell, new Frame { Origin = new Vector3(100.5f, 100, 0) });

        var a = engine.Resolve(player, withDefault, target);
        var b = engine.Resolve(player, withIdentity, target);

        Assert.True(a.Succeeded);
        Assert.Equal(b.Position.Frame.Origin, a.Position.Frame.Origin);
        Assert.Equal(Quaternion.Identity, a.Position.Frame.Orientation);
    }

    [Fact]
    public void GlobalToLocal_IsTheTransposedMatrix_SummedInDouble()
    {
        var frame = new Frame(new Vector3(100, 100, 0), Yaw30);
        var v = new Vector3(-0.647f, -0.862f, 0f);
        // Retail: y = m3·x + m4·y in double, stored as float.
        float expectedY = (float)((double)-Sin30 * v.X + (double)Cos30 * v.Y);
        float expectedX = (float)((double)Cos30 * v.X + (double)Sin30 * v.Y);

        var local = frame.GlobalToLocalVec(v);

        Assert.Equal(Bits(expectedX), Bits(local.X));
        Assert.Equal(Bits(expectedY), Bits(local.Y));
        // This vector tells the forms apart: float sums and the conjugate quaternion round differently.
        Assert.NotEqual(Bits(expectedY), Bits(-Sin30 * v.X + Cos30 * v.Y));
        Assert.NotEqual(Bits(expectedY), Bits(Vector3.Transform(v, Quaternion.Conjugate(Yaw30)).Y));
        // The point form subtracts the origin first, in float, as retail stores the differences.
        var point = frame.Origin + v;
        var d = point - frame.Origin;
        Assert.Equal(Bits((float)((double)-Sin30 * d.X + (double)Cos30 * d.Y)), Bits(frame.GlobalToLocal(point).Y));
    }

    [Fact]
    public void LocalToGlobal_IsTheMatrix_SummedInDouble()
    {
        var frame = new Frame(new Vector3(100, 100, 0), Yaw30);
        var v = new Vector3(-0.862f, 0.647f, 0f);
        float expectedX = (float)((double)Cos30 * v.X + (double)-Sin30 * v.Y);
        float expectedY = (float)((double)Sin30 * v.X + (double)Cos30 * v.Y);

        var global = frame.LocalToGlobalVec(v);

        Assert.Equal(Bits(expectedX), Bits(global.X));
        Assert.Equal(Bits(expectedY), Bits(global.Y));
        Assert.Equal(Bits((float)((double)Cos30 * v.X + (double)-Sin30 * v.Y + 100.0)), Bits(frame.LocalToGlobal(v).X));
    }

    [Theory]
    [InlineData(0f, 1f)]                       // 180°, a cottage cell's frame
    [InlineData(0.70710677f, 0.70710677f)]     // 90°
    [InlineData(0.9659258f, 0.25881904f)]      // 30°
    public void RotationAboutZ_KeepsTheVerticalExactly(float w, float z)
    {
        // m8 = 1 − 2x² − 2y² is exactly 1 for any rotation about Z, so a floor's normal stays (0, 0, 1)
        // (ACE's quaternion transform gives 0.99999994 in the 180° cell).
        var frame = new Frame(Vector3.Zero, new Quaternion(0, 0, z, w));
        Assert.Equal(1f, frame.LocalToGlobalVec(Vector3.UnitZ).Z);
        Assert.Equal(1f, frame.GlobalToLocalVec(Vector3.UnitZ).Z);
        Assert.Equal(1f, new Position(0xA9B40100, frame).LocalToGlobalVec(Vector3.UnitZ).Z);
    }

    [Fact]
    public void ValidRotation_IsUsedAsGiven()
    {
        // |Yaw30|² rounds to 0.99999994; normalizing would change its bits (W 0.96592593). Retail keeps a
        // rotation that passes Frame::IsValid (|q|² within 0.001 of 1) as it is.
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        var setup = new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.5f)] };
        world.Objects.Register(0x7000_0001, setup, new Position(LandDefs.LandCellAt(0xA9B4, new Vector3(100, 100, 0)), new Frame(new Vector3(100, 100, 0), Yaw30)));

        var stored = world.Objects.PositionOf(0x7000_0001).Frame.Orientation;

        Assert.Equal(Bits(Yaw30.W), Bits(stored.W));
        Assert.Equal(Bits(Yaw30.Z), Bits(stored.Z));
        Assert.NotEqual(Bits(Quaternion.Normalize(Yaw30).W), Bits(stored.W));
    }

    [Fact]
    public void NonUnitRotation_IsNormalizedByTheReciprocalLength()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        var setup = new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.5f)] };
        uint cell = LandDefs.LandCellAt(0xA9B4, new Vector3(100, 100, 0));
        world.Objects.Register(1, setup, new Position(cell, new Frame(new Vector3(100, 100, 0), new Quaternion(0, 0, 4, 3))));
        world.Objects.Register(2, setup, new Position(cell, new Frame(new Vector3(100, 100, 0), new Quaternion(0, 0, 0, 2))));

        Assert.Equal(new Quaternion(0, 0, (float)(4 * (1.0 / 5.0)), (float)(3 * (1.0 / 5.0))), world.Objects.PositionOf(1).Frame.Orientation);
        Assert.Equal(Quaternion.Identity, world.Objects.PositionOf(2).Frame.Orientation);
    }

    [Fact]
    public void InterpolateRotation_BlendsLinearlyNearby_AndSphericallyFarApart()
    {
        var frame = default(Frame);
        var from = new Frame(Vector3.Zero, Yaw30);
        frame.InterpolateRotation(from, from, 1f / 3f);
        Assert.True(Quaternion.Dot(Yaw30, frame.Orientation) > 0.9999999f);

        var identity = Frame.Identity;
        var quarter = new Frame(Vector3.Zero, new Quaternion(0, 0, 0.70710677f, 0.70710677f));
        frame.InterpolateRotation(identity, quarter, 0.5f);
        // Halfway between 0° and 90° about Z is 45°: (cos 22.5°, sin 22.5°) = (0.9238795, 0.3826834).
        Assert.Equal(0.9238795f, frame.Orientation.W, 6);
        Assert.Equal(0.3826834f, frame.Orientation.Z, 6);
    }

    [Fact]
    public void Combine_PlacesAPartThroughTheMatrix()
    {
        var owner = new Frame(new Vector3(100, 100, 0), Yaw30);
        var part = new Frame(new Vector3(1, 0, 2), Quaternion.Identity);

        var placed = owner.Combine(part);

        Assert.Equal(Bits((float)((double)Cos30 * 1 + 100.0)), Bits(placed.Origin.X));
        Assert.Equal(Bits((float)((double)Sin30 * 1 + 100.0)), Bits(placed.Origin.Y));
        Assert.Equal(2f, placed.Origin.Z);
        Assert.True(Quaternion.Dot(Yaw30, placed.Orientation) > 0.9999999f);
    }

    [Fact]
    public void GRotate_TurnsOnTheWorldSide_AndIgnoresTinyVectors()
    {
        // A quarter turn about Z from the identity: (cos 45°, 0, 0, sin 45°).
        var quarter = AcDream.Core.Physics.Body.BodyMotion.Rotate(Quaternion.Identity, new Vector3(0, 0, MathF.PI / 2));
        Assert.Equal(0.70710677f, quarter.W, 6);
        Assert.Equal(0.70710677f, quarter.Z, 6);
        // World side: after the Z turn local X points along world Y, and a turn about world X takes world Y
        // to world Z.
        var both = AcDream.Core.Physics.Body.BodyMotion.Rotate(quarter, new Vector3(MathF.PI / 2, 0, 0));
        var x = new Frame(Vector3.Zero, both).LocalToGlobalVec(Vector3.UnitX);
        Assert.Equal(0f, x.X, 6);
        Assert.Equal(0f, x.Y, 6);
        Assert.Equal(1f, x.Z, 6);
        // Shorter than EPSILON: unchanged to the bit.
        Assert.Equal(Yaw30, AcDream.Core.Physics.Body.BodyMotion.Rotate(Yaw30, new Vector3(0, 0, 1e-4f)));
    }
}
