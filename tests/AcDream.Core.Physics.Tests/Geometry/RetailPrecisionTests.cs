using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// Retail runs its physics on the x87 stack at double precision (ClientMain::ConfigureFPU sets 53-bit
/// precision, acclient.c:60885; the D3D device is created with FPU_PRESERVE) and rounds to float only where
/// the code stores a float. Where that changes a result — square roots, reciprocals, divisions — the
/// library computes in double too. Each case below is worked by hand; the float computation it replaced
/// gives a different value, named in the comment.
/// </summary>
public class RetailPrecisionTests
{
    /// <summary>
    /// normalize_check_small (acclient.c:143621): length and reciprocal in double, each component rounded
    /// once. (0.1f, 0.5f, 0) / √0.26… = (0.196116137948…, 0.980580675128…), rounded:
    /// (0.19611613452434540, 0.98058068752288818). Dividing by a float length gives X = 0.19611614942550659.
    /// </summary>
    [Fact]
    public void CollisionNormal_IsTheUnitVectorRoundedOnce()
    {
        var info = new CollisionInfo();
        info.SetCollisionNormal(new Vector3(0.1f, 0.5f, 0f));
        Assert.Equal(new Vector3(0.19611613452434540f, 0.98058068752288818f, 0f), info.CollisionNormal);

        info.SetSlidingNormal(new Vector3(0.1f, 0.5f, 3f));
        Assert.Equal(new Vector3(0.19611613452434540f, 0.98058068752288818f, 0f), info.SlidingNormal);
    }

    /// <summary>
    /// adjust_sphere_to_plane (acclient.c:359533): a sphere of radius 0.48 whose centre sank to 0.0011 above
    /// a floor while stepping down 0.75 backs off (0.0011 − 0.48) / −0.75 of the step in double and rests
    /// exactly on the radius, z = 0.48f; walk_interp = f(1 − 0.63853333…) = 0.36146667599678040. In float
    /// the centre ends at 0.47999995946884155 (inside the floor's reach) and walk_interp at 0.36146670579910278.
    /// </summary>
    [Fact]
    public void AdjustSphereToPlane_RestsExactlyOnTheRadius()
    {
        var floor = new Polygon([new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0)]);
        var sphere = new Sphere(new Vector3(0, 0, 0.0011f), 0.48f);
        float interp = 1f;

        Assert.True(PolygonQuery.AdjustSphereToPlane(floor, ref sphere, new Vector3(0, 0, -0.75f), ref interp));

        Assert.Equal(0.48f, sphere.Center.Z);
        Assert.Equal(0.36146667599678040f, interp);
    }

    /// <summary>
    /// find_crossed_edge (acclient.c:360396) normalizes the edge normal with a double length and reciprocal.
    /// The triangle (0,0,0), (1,0,0), (0.2,0.1,0) seen from (−0.3, 0.3) is crossed first at its edge from
    /// the last vertex to the first, whose inward normal (0.1, −0.2, 0) / √0.05 = (0.447213595…,
    /// −0.894427191…) rounds once to (0.44721359014511108, −0.89442718029022217, 0); scaling by a float
    /// reciprocal length gives (0.44721356034278870, −0.89442712068557739, 0).
    /// </summary>
    [Fact]
    public void FindCrossedEdge_NormalIsRoundedOnce()
    {
        var triangle = new Polygon([new(0, 0, 0), new(1, 0, 0), new(0.2f, 0.1f, 0)]);

        Assert.True(PolygonQuery.FindCrossedEdge(triangle, new Sphere(new Vector3(-0.3f, 0.3f, 0.3f), 0.48f), Vector3.UnitZ, out var normal));

        Assert.Equal(new Vector3(0.44721359014511108f, -0.89442718029022217f, 0f), normal);
    }

    /// <summary>
    /// calc_num_steps (acclient.c:311763) scales the per-step offset by 1.0 / n in double: 0.9615f m in three
    /// steps is 0.9615f / 3 = 0.32049999634…, rounded once to 0.32049998641014099. Multiplying by the float
    /// 1/3 gives 0.32050001621246338.
    /// </summary>
    [Fact]
    public void CalcNumSteps_PerStepOffsetIsRoundedOnce()
    {
        int steps = Transition.CalcNumSteps(new Vector3(0, 0.9615f, 0), 0.48f, false, out var perStep);

        Assert.Equal(3, steps);
        Assert.Equal(0.32049998641014099f, perStep.Y);
    }
}
