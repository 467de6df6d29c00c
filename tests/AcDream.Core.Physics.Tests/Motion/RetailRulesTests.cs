using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>Rules where the decompile and ACE disagree; each follows the decompile (docs/open-questions.md, "Differences from ACE in the motion layer").</summary>
public class RetailRulesTests
{
    [Fact]
    public void Subtract1_IsTheExactInverseOfCombine_ThroughTheResultingRotation()
    {
        // Frame::subtract1 (acclient.c:357321) rotates the removed offset by the resulting rotation, so it undoes
        // Frame::combine; ACE's AFrame.Subtract rotates it by the removed frame's own rotation and misses by
        // |offset| × angle (here 3.6 mm × 0.01 rad ≈ 3.6e-5 m).
        var start = new Frame(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f));
        var root = new Frame(new Vector3(0.003f, 0.002f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.01f));
        var back = start.Combine(root).Subtract(root);
        Assert.Equal(1f, back.Origin.X, 6);
        Assert.Equal(2f, back.Origin.Y, 6);
        Assert.Equal(start.Orientation.Z, back.Orientation.Z, 6);
        var combined = start.Combine(root);
        var aceStyle = combined.Origin - Vector3.Transform(root.Origin, root.Orientation);
        Assert.True(Vector3.Distance(aceStyle, new Vector3(1f, 2f, 3f)) > 1e-5f, "the operand's own rotation does not undo combine");
    }

    [Fact]
    public void Subtract1_RoundsTheRotatedXAndYToFloat_BeforeAddingTheOrigin()
    {
        // Frame::subtract1 (acclient.c:357321) stores the rotated x and y of the removed offset in float locals (ST1C_4,
        // ST20_4) and only then adds the origin's; the rotated z is added unrounded. Walk-cycle root frames taken off
        // parents at 360 headings and three places: every result must carry retail's roundings, and some of them must
        // differ from one rounding of the whole sum (else this test could not see the difference). Near the origin of
        // a frame (a part's frame, an offset being built) the two roundings differ often; at 60-130 m rarely.
        var root = new Frame(new Vector3(0.003f, 0.002f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.01f));
        int differing = 0;
        foreach (var place in new[] { new Vector3(60.1f, 128.3f, 1.005f), new Vector3(99.48f, 99.44f, 0.005f), new Vector3(0.0123f, -0.0071f, 0.0004f) })
            for (int degrees = 0; degrees < 360; degrees++)
            {
                var parent = new Frame(place, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f));
                var back = parent.Subtract(root);
                back.Matrix.Elements(out float m0, out float m1, out float m2, out float m3, out float m4, out float m5, out float m6, out float m7, out float m8);
                double vx = -root.Origin.X, vy = -root.Origin.Y, vz = -root.Origin.Z;
                double rx = m6 * vz + m0 * vx + m3 * vy, ry = m7 * vz + m1 * vx + m4 * vy, rz = m8 * vz + m2 * vx + m5 * vy;
                var retail = new Vector3((float)((double)(float)rx + place.X), (float)((double)(float)ry + place.Y), (float)(rz + place.Z));
                var once = new Vector3((float)(rx + place.X), (float)(ry + place.Y), (float)(rz + place.Z));
                Assert.True(VectorMath.SameBits(retail, back.Origin), $"heading {degrees} at {place}: expected {retail:R}, actual {back.Origin:R}");
                if (!VectorMath.SameBits(retail, once))
                    differing++;
            }
        Assert.True(differing > 0, "no case where the two roundings differ from one");
    }

    [Fact]
    public void MotionAllowsJump_ForbidsFallen_NotFalling()
    {
        // CMotionInterp::motion_allows_jump (CMotionInterp.c:19-40) lists Fallen 0x40000008; ACE lists Falling 0x40000015.
        Assert.Equal(MotionError.CantJumpFromThisPosition, MotionInterpreter.MotionAllowsJump(MotionCommand.Fallen));
        Assert.Equal(MotionError.None, MotionInterpreter.MotionAllowsJump(MotionCommand.Falling));
        Assert.Equal(MotionError.CantJumpFromThisPosition, MotionInterpreter.MotionAllowsJump(MotionCommand.Sleeping));
        Assert.Equal(MotionError.None, MotionInterpreter.MotionAllowsJump(MotionCommand.RunForward));
    }

    [Fact]
    public void SetHoldKeyRun_MakesRunTheCurrentKey_AndTheHeldWalkRuns()
    {
        // CMotionInterp::SetHoldKey (acclient.c:344501) handles Run too; ACE's handles only None.
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward);
        Assert.Equal(MotionCommand.WalkForward, rig.Motion.Interpreted.ForwardCommand);
        rig.Motion.SetHoldKey(HoldKey.Run, rig.Mover, ref rig.State, ref rig.Body);
        Assert.Equal(HoldKey.Run, rig.Motion.Raw.CurrentHoldKey);
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Interpreted.ForwardCommand);
        Assert.Equal(2.375f, rig.Motion.Interpreted.ForwardSpeed);
        rig.Motion.SetHoldKey(HoldKey.None, rig.Mover, ref rig.State, ref rig.Body);
        Assert.Equal(MotionCommand.WalkForward, rig.Motion.Interpreted.ForwardCommand);
    }

    [Fact]
    public void AHeldRun_SurvivesAJump_BecauseTheRawStateKeepsTheRunKey()
    {
        // LeaveGround and HitGround re-derive the interpreted state from the raw one (apply_raw_movement); with
        // SetHoldKey(Run) recorded there the run stays a run (with ACE's SetHoldKey it becomes a walk).
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        rig.Frames(3);
        rig.Jump(0.5f);
        rig.Frames(45);
        Assert.True(rig.State.OnWalkable);
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Interpreted.ForwardCommand);
        Assert.Equal(2.375f, rig.Motion.Interpreted.ForwardSpeed);
    }
}
