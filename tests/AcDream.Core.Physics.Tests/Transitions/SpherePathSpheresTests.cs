using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// The spheres the sphere path expresses in other spaces: at the current and check positions in their
/// landblocks (retail Position::localtoglobal of each sphere centre and the low point) and in a tested
/// space (Position::localtolocal, then divided by the space's scale). The path computes them side by side
/// and remembers them per position (not retail; changes no result); these compare every value with the
/// retail scalar forms on <see cref="Position"/>, through the orders of calls a move makes: a fresh check
/// position, the check position moved by an offset (whose shifted spheres are not the ones a transform
/// gives), the current position turned in place, the check position accepted as current, and the mover's
/// spheres changed. The current and check positions lie in two landblocks and the spaces in one or the
/// other, so each lane crosses by its own block offset.
/// </summary>
public class SpherePathSpheresTests
{
    private const float MoverScale = 1.1f;
    private static readonly Sphere[] TwoSpheres = [new(new Vector3(0.01f, -0.02f, 0.475f), 0.475f), new(new Vector3(0.03f, 0f, 1.35f), 0.5f)];

    private static readonly Position Current = new(0xA9B40031, new Frame(new Vector3(23.7f, 191.3f, 12.05f), Turn(0.3f, 0.2f, 1f, 0.7f)));
    private static readonly Position Check = new(0xA9B50031, new Frame(new Vector3(23.9f, 0.2f, 12.1f), Turn(0f, 0f, 1f, 0.75f)));
    private static readonly Position SpaceInCheckBlock = new(0xA9B50031, new Frame(new Vector3(25f, 1f, 12f), Turn(0f, 0f, 1f, -1.2f)));
    private static readonly Position SpaceInCurrentBlock = new(0xA9B40031, new Frame(new Vector3(-3.25f, 180.5f, 11.75f), Turn(1f, -0.4f, 0.2f, 2.1f)));

    private static Quaternion Turn(float x, float y, float z, float radians) =>
        Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(x, y, z)), radians);

    private static uint[] Bits(Vector3 v) => [BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z)];

    private static Vector3 LocalCentre(Sphere[] spheres, int i) => spheres[i].Center * MoverScale;

    private static SpherePath PathAt(Sphere[] spheres)
    {
        var path = new Transition(new PhysicsWorld()).SpherePath;
        path.InitSphere(spheres, MoverScale);
        path.InitPath(null, Current, Current);
        return path;
    }

    private static void AssertGlobalSpheres(SpherePath path, Sphere[] spheres, in Position current, in Position check)
    {
        for (int i = 0; i < spheres.Length; i++)
        {
            Assert.Equal(Bits(current.LocalToGlobal(LocalCentre(spheres, i))), Bits(path.GlobalCurrCenter[i].Center));
            Assert.Equal(Bits(check.LocalToGlobal(LocalCentre(spheres, i))), Bits(path.GlobalSphere[i].Center));
            Assert.Equal(spheres[i].Radius * MoverScale, path.GlobalCurrCenter[i].Radius);
            Assert.Equal(spheres[i].Radius * MoverScale, path.GlobalSphere[i].Radius);
        }
        var low = LocalCentre(spheres, 0) - new Vector3(0, 0, spheres[0].Radius * MoverScale);
        Assert.Equal(Bits(check.LocalToGlobal(low)), Bits(path.GlobalLowPoint));
    }

    private static void AssertLocalSpaceSpheres(SpherePath path, Sphere[] spheres, in Position space, float scale)
    {
        float inverse = 1f / scale;
        for (int i = 0; i < spheres.Length; i++)
        {
            Assert.Equal(Bits(space.LocalToLocal(path.CheckPos, LocalCentre(spheres, i)) * inverse), Bits(path.LocalSpaceSphere[i].Center));
            Assert.Equal(spheres[i].Radius * MoverScale * inverse, path.LocalSpaceSphere[i].Radius);
        }
        Assert.Equal(Bits(space.LocalToLocal(path.CurPos, LocalCentre(spheres, 0)) * inverse), Bits(path.LocalSpaceCurrCenter.Center));
        Assert.Equal(spheres[0].Radius * MoverScale * inverse, path.LocalSpaceCurrCenter.Radius);
        Assert.Equal(Bits(space.GlobalToLocalVec(Vector3.UnitZ)), Bits(path.LocalSpaceZ));
        Assert.True(Position.SameBits(space, path.LocalSpacePos));
    }

    [Fact]
    public void SpheresAtTheCurrentAndCheckPositions_AreRetailsTransforms()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Current, null);
        AssertGlobalSpheres(path, TwoSpheres, Current, Current);
        path.SetCheckPos(Check, null);
        AssertGlobalSpheres(path, TwoSpheres, Current, Check);
    }

    [Fact]
    public void SpheresInATestedSpace_AreRetailsLocalToLocal_InEitherLandblock_AndAtAnyScale()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Check, null);
        foreach (var space in new[] { SpaceInCheckBlock, SpaceInCurrentBlock })
            foreach (float scale in new[] { 1f, 2.5f, 0.3f })
            {
                path.CacheLocalSpaceSphere(space, scale);
                AssertLocalSpaceSpheres(path, TwoSpheres, space, scale);
            }
    }

    /// <summary>
    /// Moving the check position by an offset shifts the global spheres by that offset (a float sum, retail's
    /// add_offset_to_check_pos), which is not what a transform at the new position gives: the spheres in a
    /// tested space are then transformed again from the new position, not taken from the shifted ones.
    /// </summary>
    [Fact]
    public void AfterAnOffset_TheSpacesSpheresComeFromTheNewCheckPosition()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Check, null);
        path.CacheLocalSpaceSphere(SpaceInCheckBlock, 1f);
        var offset = new Vector3(0.3f, -0.2f, 0.01f);
        var shifted = path.GlobalSphere[0].Center + offset;
        path.AddOffsetToCheckPos(offset);
        Assert.Equal(Bits(shifted), Bits(path.GlobalSphere[0].Center));
        path.CacheLocalSpaceSphere(SpaceInCheckBlock, 1f);
        AssertLocalSpaceSpheres(path, TwoSpheres, SpaceInCheckBlock, 1f);
        // Coming back to the position it left (a step-up restoring its saved check position) recomputes it too.
        path.SetCheckPos(Check, null);
        AssertGlobalSpheres(path, TwoSpheres, Current, Check);
    }

    /// <summary>
    /// A free-rotating mover's current position is turned in place (FindTransitionalPosition) without the
    /// current spheres being cached again: the space's current sphere follows the turned position, and so do
    /// the current spheres once they are cached.
    /// </summary>
    [Fact]
    public void ACurrentPositionTurnedInPlace_IsTransformedAgain()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Check, null);
        path.CacheLocalSpaceSphere(SpaceInCurrentBlock, 1f);
        path.CurPos.Frame.Orientation = Turn(0f, 1f, 0.1f, -0.9f);
        path.CacheLocalSpaceSphere(SpaceInCurrentBlock, 1f);
        AssertLocalSpaceSpheres(path, TwoSpheres, SpaceInCurrentBlock, 1f);
        path.CacheGlobalCurrCenter();
        AssertGlobalSpheres(path, TwoSpheres, path.CurPos, Check);
    }

    [Fact]
    public void AcceptingTheCheckPosition_MakesItsSpheresTheCurrentOnes()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Check, null);
        path.CacheLocalSpaceSphere(SpaceInCheckBlock, 1f);
        path.CurPos = path.CheckPos;
        path.CacheGlobalCurrCenter();
        path.CacheGlobalSphere();
        AssertGlobalSpheres(path, TwoSpheres, Check, Check);
        path.CacheLocalSpaceSphere(SpaceInCurrentBlock, 2f);
        AssertLocalSpaceSpheres(path, TwoSpheres, SpaceInCurrentBlock, 2f);
    }

    /// <summary>New spheres at the same positions: nothing remembered for the old ones is used.</summary>
    [Fact]
    public void NewSpheres_AreTransformedAgain_AtTheSamePositions()
    {
        var path = PathAt(TwoSpheres);
        path.SetCheckPos(Check, null);
        path.CacheLocalSpaceSphere(SpaceInCheckBlock, 1f);
        Sphere[] one = [new(new Vector3(0f, 0.05f, 0.6f), 0.6f)];
        path.InitSphere(one, MoverScale);
        path.CacheGlobalCurrCenter();
        path.CacheGlobalSphere();
        AssertGlobalSpheres(path, one, Current, Check);
        path.CacheLocalSpaceSphere(SpaceInCheckBlock, 1f);
        AssertLocalSpaceSpheres(path, one, SpaceInCheckBlock, 1f);
    }

    /// <summary>
    /// Within one landblock the zero block offsets are not added, which only turns −0 into +0; that matters
    /// when the space's origin has a +0 coordinate: here the sphere centre's global X is −0 and the space sits
    /// at X = +0, so retail's difference (−0 + 0) − (+0) is +0, and the transformed X keeps that sign.
    /// </summary>
    [Fact]
    public void ANegativeZeroCoordinate_AgainstASpaceAtPositiveZero_KeepsRetailsSign()
    {
        Sphere[] sphere = [new(new Vector3(-0f, -1f, -1f), 0.5f)];
        var at = new Position(0xA9B40031, new Frame(new Vector3(-0f, 10f, 5f)));
        var space = new Position(0xA9B40031, new Frame(new Vector3(0f, 20f, 20f)));
        var path = new Transition(new PhysicsWorld()).SpherePath;
        path.InitSphere(sphere, 1f);
        path.InitPath(null, at, at);
        path.SetCheckPos(at, null);
        Assert.True(float.IsNegative(path.GlobalSphere[0].Center.X), "the global X is -0");
        path.CacheLocalSpaceSphere(space, 1f);
        var expected = space.LocalToLocal(at, sphere[0].Center);
        Assert.False(float.IsNegative(expected.X), "retail's local X is +0");
        Assert.Equal(Bits(expected), Bits(path.LocalSpaceSphere[0].Center));
        Assert.Equal(Bits(expected), Bits(path.LocalSpaceCurrCenter.Center));
    }
}
