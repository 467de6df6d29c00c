using AcDream.Core.Physics.Tests.Bsp;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// The solid-hit memo (SpherePath.KnownSolidHit): a BSP test that finds sphere 0 touching a polygon is
/// remembered, and a placement test of the same tree at the same check position is then answered
/// Collided without walking the tree. These pin that the memo is set by the hits that prove it, that the
/// answer it gives is the one the real placement test computes, and that it answers for nothing else.
/// </summary>
public class SolidHitMemoTests
{
    private static readonly object Owner = new();
    private static readonly Position Space = new(BoxFixtures.Cell, Vector3.Zero);

    /// <summary>
    /// Not in contact, moving from x = 2 to 1.3 (radius 0.5): sphere 0 reaches into the box's +X face at
    /// x = 1 (BspQueryTests: a step-up candidate). The hit is remembered; the placement test there, run for
    /// real with the memo forgotten, is Collided, as the memo says.
    /// </summary>
    [Fact]
    public void FrontHit_IsRemembered_AndTheRealPlacementTestAgrees() =>
        AssertRememberedAndTheRealPlacementTestAgrees(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0));

    /// <summary>
    /// Retail quirk: a polygon grazed from behind (moving away from the +X face, x 1.2 → 1.3) still counts as
    /// a hit and is remembered; the real placement test there is Collided too.
    /// </summary>
    [Fact]
    public void GrazedFromBehind_IsRemembered_AndTheRealPlacementTestAgrees() =>
        AssertRememberedAndTheRealPlacementTestAgrees(new Vector3(1.2f, 0, 0), new Vector3(1.3f, 0, 0));

    // A move's test (not in contact) from `from` to `to` hits the box (a step-up candidate); the hit is known
    // only to a placement insert, and the real placement test there, with the memo forgotten, is Collided.
    private static void AssertRememberedAndTheRealPlacementTestAgrees(Vector3 from, Vector3 to)
    {
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(from, to, 0.5f, shortcuts: Shortcuts.All);
        var path = t.SpherePath;
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(tree, t, 1f, Owner));
        Assert.False(path.KnownSolidHit(Owner, Space, 1f)); // a move's insert is not a placement
        path.InsertType = InsertType.Placement;
        Assert.True(path.KnownSolidHit(Owner, Space, 1f));

        path.SolidHit.Forget();
        Assert.False(path.KnownSolidHit(Owner, Space, 1f));
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(tree, t, 1f));
    }

    /// <summary>
    /// In contact, the same front hit is a step-up (retail step_sphere_up); the hit is remembered for the
    /// check position it was found at before the step-up runs (here it fails and slides, moving the check
    /// position on), and the real placement test at that position is Collided.
    /// </summary>
    [Fact]
    public void ContactHit_IsRememberedAtItsCheckPosition_AndTheRealPlacementTestAgrees()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f, shortcuts: Shortcuts.All);
        t.ObjectInfo.State |= ObjectInfoState.Contact;
        var path = t.SpherePath;
        var hitAt = path.CheckPos;
        BspResponses.FindCollisions(tree, t, 1f, Owner);
        Assert.True(path.SolidHit.Holds(Owner, Space, 1f, hitAt));

        var placement = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f, shortcuts: Shortcuts.All);
        placement.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(tree, placement, 1f));
    }

    /// <summary>A test that finds nothing (x 3 → 2.5, clear of the box) remembers nothing.</summary>
    [Fact]
    public void Miss_IsNotRemembered()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(2.5f, 0, 0), 0.5f, shortcuts: Shortcuts.All);
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f, Owner));
        t.SpherePath.InsertType = InsertType.Placement;
        Assert.False(t.SpherePath.KnownSolidHit(Owner, Space, 1f));
    }

    /// <summary>
    /// The memo answers only for the same owner, space, scale and check position: another of each (the
    /// check position moved 1 mm, the space moved 1 mm or placed in another cell, the scale 2) is not known,
    /// and neither is anything after a new move starts (Reset) or the spheres change.
    /// </summary>
    [Fact]
    public void AnswersOnlyForTheSameOwnerSpaceScaleAndCheckPosition()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f, shortcuts: Shortcuts.All);
        var path = t.SpherePath;
        BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f, Owner);
        path.InsertType = InsertType.Placement;
        Assert.True(path.KnownSolidHit(Owner, Space, 1f));
        Assert.False(path.KnownSolidHit(new object(), Space, 1f));
        Assert.False(path.KnownSolidHit(Owner, Space, 2f));
        Assert.False(path.KnownSolidHit(Owner, new Position(BoxFixtures.Cell, new Vector3(0.001f, 0, 0)), 1f));
        Assert.False(path.KnownSolidHit(Owner, new Position(BoxFixtures.Cell + 1, Vector3.Zero), 1f));

        var check = path.CheckPos;
        path.SetCheckPos(new Position(BoxFixtures.Cell, new Vector3(1.301f, 0, 0)), null);
        Assert.False(path.KnownSolidHit(Owner, Space, 1f));
        path.SetCheckPos(check, null);
        Assert.True(path.KnownSolidHit(Owner, Space, 1f));

        path.InitSphere([new Sphere(Vector3.Zero, 0.4f)], 1f);
        Assert.False(path.KnownSolidHit(Owner, Space, 1f));
        BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), Remade(t), 1f, Owner);
        path.InsertType = InsertType.Placement;
        Assert.True(path.KnownSolidHit(Owner, Space, 1f));
        path.Reset();
        path.InsertType = InsertType.Placement;
        Assert.False(path.KnownSolidHit(Owner, Space, 1f));
    }

    // The path's local-space spheres prepared again after its spheres changed, as a move's test would, and
    // the first test's step-up candidate dropped.
    private static Transition Remade(Transition t)
    {
        t.SpherePath.InsertType = InsertType.Transition;
        t.SpherePath.Collide = false;
        t.SpherePath.CacheLocalSpaceSphere(Space, 1f);
        return t;
    }
}
