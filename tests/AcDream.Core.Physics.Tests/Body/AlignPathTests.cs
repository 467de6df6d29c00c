using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// ALIGNPATH_PS (UpdateObjectInternal → Frame::set_vector_heading → euler_set_rotate): a missile's frame points its +Y
/// axis along the quantum's offset. Expected rotations from the formula: yaw −((450° − atan2(y, x)) mod 360°) about Z,
/// pitch asin(z) about X, q = q_z(yaw)·q_x(pitch).
/// </summary>
public class AlignPathTests
{
    private static void Near(Quaternion expected, Quaternion actual)
    {
        Assert.Equal(expected.W, actual.W, 1e-5f);
        Assert.Equal(expected.X, actual.X, 1e-5f);
        Assert.Equal(expected.Y, actual.Y, 1e-5f);
        Assert.Equal(expected.Z, actual.Z, 1e-5f);
    }

    /// <summary>North (0, 1, 0): atan2 = 90°, yaw −(360 mod 360) = 0: the identity (an identity frame faces +Y).</summary>
    [Fact]
    public void North_IsTheIdentity() => Near(Quaternion.Identity, AlignPath.Heading(new Vector3(0, 3, 0), Quaternion.Identity));

    /// <summary>North-east, level: atan2 = 45°, yaw −(405 mod 360) = −45°: (cos −22.5°, 0, 0, sin −22.5°) = (0.92388, 0, 0, −0.38268).</summary>
    [Fact]
    public void NorthEast_TurnsMinus45DegreesAboutZ() =>
        Near(new Quaternion(0, 0, -0.38268343f, 0.9238795f), AlignPath.Heading(new Vector3(2, 2, 0), Quaternion.Identity));

    /// <summary>North, climbing at 30°: yaw 0, pitch asin(0.5) = 30°: (cos 15°, sin 15°, 0, 0) = (0.96593, 0.25882, 0, 0).</summary>
    [Fact]
    public void ClimbingNorth_PitchesAboutX() =>
        Near(new Quaternion(0.25881904f, 0, 0, 0.9659258f), AlignPath.Heading(new Vector3(0, MathF.Sqrt(3f) / 2, 0.5f), Quaternion.Identity));

    /// <summary>West, falling at 45°: yaw −(630 mod 360) = −270°, pitch −45°: q_z(−270°)·q_x(−45°).</summary>
    [Fact]
    public void FallingWest_CombinesYawAndPitch()
    {
        float cp = MathF.Cos(-MathF.PI / 8), sp = MathF.Sin(-MathF.PI / 8), cy = MathF.Cos(-3 * MathF.PI / 4), sy = MathF.Sin(-3 * MathF.PI / 4);
        Near(new Quaternion(sp * cy, sy * sp, cp * sy, cy * cp), AlignPath.Heading(new Vector3(-1, 0, -1), Quaternion.Identity));
    }

    [Fact]
    public void AnOffsetTooShortForADirection_KeepsTheOrientation()
    {
        var q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 1f);
        Assert.Equal(q, AlignPath.Heading(new Vector3(1e-5f, 0, 0), q));
    }

    /// <summary>
    /// In a flight: an arrow launched east with AlignPath ends its first quantum facing east (+Y of its frame along
    /// +X: yaw −90°, (cos −45°, 0, 0, sin −45°)); the same arrow without AlignPath keeps its launch orientation.
    /// </summary>
    [Fact]
    public void AnArrowWithAlignPath_FacesItsFlight_AndWithoutItKeepsItsOrientation()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var aligned = Missile.Launch(0x7300_0001, 0.05f, TestGeometry.At(100, 100, 2), new Vector3(20, 0, 0), gravity: false);
        engine.Step(aligned, 1.0 / 30);
        Near(new Quaternion(0, 0, -0.70710677f, 0.70710677f), aligned.State.Position.Frame.Orientation);

        var plain = new Missile(aligned.Description.With(physicsState: PhysicsState.Missile), TestGeometry.At(100, 100, 2), new Vector3(20, 0, 0));
        engine.Step(plain, 1.0 / 30);
        Assert.Equal(Quaternion.Identity, plain.State.Position.Frame.Orientation);
    }
}
