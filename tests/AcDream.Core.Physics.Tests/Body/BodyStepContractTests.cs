using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>PhysicsEngine.Step's contract: bad input is refused naming the field, and a warm step allocates nothing.</summary>
public class BodyStepContractTests
{
    public static TheoryData<string, string> BadInputs() => new()
    {
        { "elapsed NaN", "elapsed" },
        { "elapsed negative", "elapsed" },
        { "elapsed +∞", "elapsed" },
        { "desired velocity NaN", "desiredVelocity" },
        { "jump velocity negative", "jumpVelocity" },
        { "jump velocity NaN", "jumpVelocity" },
        { "body velocity +∞", "body.velocity" },
        { "body omega NaN", "body.omega" },
        { "friction above 1", "body.friction" },
        { "elasticity NaN", "body.elasticity" },
        { "state origin NaN", "state.position.origin" },
    };

    [Theory]
    [MemberData(nameof(BadInputs))]
    public void BadInput_ThrowsNamingTheField(string row, string field)
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var state = MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f);
        var body = BodyState.Creature();
        double elapsed = 1.0 / 30;
        var desired = Vector3.Zero;
        float jump = 0f;
        switch (row)
        {
            case "elapsed NaN": elapsed = double.NaN; break;
            case "elapsed negative": elapsed = -0.01; break;
            case "elapsed +∞": elapsed = double.PositiveInfinity; break;
            case "desired velocity NaN": desired = new Vector3(float.NaN, 0, 0); break;
            case "jump velocity negative": jump = -1f; break;
            case "jump velocity NaN": jump = float.NaN; break;
            case "body velocity +∞": body.Velocity = new Vector3(0, float.PositiveInfinity, 0); break;
            case "body omega NaN": body.Omega = new Vector3(0, 0, float.NaN); break;
            case "friction above 1": body.Friction = 1.5f; break;
            case "elasticity NaN": body.Elasticity = float.NaN; break;
            case "state origin NaN": state.Position.Frame.Origin = new Vector3(float.NaN, 100, 0); break;
        }
        var before = (state, body);
        var ex = Assert.ThrowsAny<ArgumentException>(() => engine.Step(MoverDescription.Player(), state, body, elapsed, desired, jump));
        Assert.StartsWith(field, ex.Message);
        Assert.Equal(before, (state, body));
    }

    [Fact]
    public void Step_AllocatesNothing_OnceWarm()
    {
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var start = MoverState.OnFloor(TestGeometry.At(100.3f, 98.5f, 0), 0f);
        var body = BodyState.Creature();
        var run = new Vector3(0.5f, 3f, 0);
        void Walk()
        {
            var s = start;
            var b = body;
            for (int i = 0; i < 60; i++)
            {
                var r = engine.Step(mover, s, b, 1.0 / 30, run, i == 10 ? 4f : 0f);
                s = r.Next;
                b = r.Body;
            }
        }
        Assert.Equal(0, Allocations.PerRound(Walk, Walk));
    }

    /// <summary>The same inputs give bit-identical outputs, run to run.</summary>
    [Fact]
    public void Step_IsDeterministic()
    {
        Vector3 Run()
        {
            var engine = new PhysicsEngine(TestScenes.Door());
            var s = MoverState.OnFloor(TestGeometry.At(100.3f, 98.5f, 0), 0f);
            var b = BodyState.Creature();
            for (int i = 0; i < 90; i++)
            {
                var r = engine.Step(MoverDescription.Player(), s, b, 1.0 / 60 + (i % 3) * 0.004, new Vector3(0.5f, 3f, 0), i == 10 ? 4f : 0f);
                s = r.Next;
                b = r.Body;
            }
            return s.Position.Origin + b.Velocity * 1000f;
        }
        Assert.Equal(Run(), Run());
    }
}
