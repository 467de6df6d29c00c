using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

public class CollisionInfoTests
{
    [Fact]
    public void CollidedObjects_KeepsEveryObjectOnceInOrder_BeyondItsFirstBuffer()
    {
        var ci = new CollisionInfo();
        // 20 distinct ids (more than the 8 the list starts with), each added twice; every fifth one stopped the mover.
        for (uint id = 1; id <= 20; id++)
        {
            var state = id % 5 == 0 ? TransitionState.Collided : TransitionState.OK;
            ci.AddObject(100 + id, state);
            ci.AddObject(100 + id, TransitionState.Collided);
        }
        var expected = new uint[20];
        for (int i = 0; i < 20; i++)
            expected[i] = 101 + (uint)i;
        Assert.Equal(expected, ci.CollidedObjects.ToArray());
        Assert.Equal(120u, ci.LastCollidedObject);

        ci.Reset();
        Assert.Equal(0, ci.CollidedObjects.Length);
        ci.AddObject(7, TransitionState.OK);
        Assert.Equal(new uint[] { 7 }, ci.CollidedObjects.ToArray());
        Assert.Equal(0u, ci.LastCollidedObject);
    }
}
