using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.World;

public class ShadowShapeBuilderTests
{
    [Fact]
    public void FromSetup_Door_KeepsBspCylinderAndSphere()
    {
        var shapes = ShadowShapeBuilder.FromSetup(TestGeometry.DoorSetup());
        Assert.Equal(new[] { ShadowShapeKind.Bsp, ShadowShapeKind.Cylinder, ShadowShapeKind.Sphere }, shapes.Select(s => s.Kind));
    }

    [Fact]
    public void FromSetup_ScalesEveryShapeTheRetailWay()
    {
        var setup = TestGeometry.DoorSetup();
        var withOffsetPart = new PhysicsSetup
        {
            Parts = [new SetupPart(setup.Parts[0].Model, new Frame(new Vector3(1, 2, 3)))],
            CylSpheres = setup.CylSpheres,
            Spheres = setup.Spheres,
        };
        var shapes = ShadowShapeBuilder.FromSetup(withOffsetPart, 1.5f);
        var part = shapes[0];
        AssertVec.Near(new Vector3(1.5f, 3f, 4.5f), part.PartFrame.Origin);
        Assert.Equal(1.5f, part.ModelScale);
        var cyl = shapes[1].Cylinder;
        AssertVec.Near(new Vector3(0, 0.18f, 0), cyl.LowPoint);
        Assert.Equal(0.75f, cyl.Radius, 6);
        Assert.Equal(0.3f, cyl.Height, 6);
        var sphere = shapes[2].Sphere;
        Assert.Equal(0.15f, sphere.Radius, 6);
        AssertVec.Near(new Vector3(0, 0.09f, 0.15f), sphere.Center);
    }

    [Fact]
    public void FromSetup_PartWithoutModel_EmitsNoShape()
    {
        var setup = new PhysicsSetup { Parts = [new SetupPart(null, Frame.Identity)], Spheres = [new Sphere(Vector3.Zero, 1)] };
        Assert.Single(ShadowShapeBuilder.FromSetup(setup));
        Assert.False(setup.HasPhysicsBsp);
        Assert.True(TestGeometry.DoorSetup().HasPhysicsBsp);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(-1f)]
    [InlineData(float.NaN)]
    public void FromSetup_BadScale_Throws(float scale)
    {
        var ex = Assert.Throws<ArgumentException>(() => ShadowShapeBuilder.FromSetup(TestGeometry.DoorSetup(), scale));
        Assert.Contains("scale", ex.Message);
    }

    [Fact]
    public void FromSetup_BrokenPartReference_NamesThePart()
    {
        var setup = new PhysicsSetup { Parts = [new SetupPart(null, Frame.Identity), null!] };
        var ex = Assert.Throws<ArgumentException>(() => ShadowShapeBuilder.FromSetup(setup));
        Assert.Contains("parts[1]", ex.Message);
    }

    [Fact]
    public void FromSetup_NegativeCylinderRadius_NamesTheField()
    {
        var setup = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, -0.5f, 1f)] };
        var ex = Assert.Throws<ArgumentException>(() => ShadowShapeBuilder.FromSetup(setup));
        Assert.Contains("cylSpheres[0].radius", ex.Message);
    }

    [Fact]
    public void FromSetup_PartDefaultScale_MultipliesTheObjectScale()
    {
        var model = TestGeometry.DoorSetup().Parts[0].Model;
        var setup = new PhysicsSetup { Parts = [new SetupPart(model, new Frame(new Vector3(0, 0, 1)), defaultScale: 2f)] };
        var part = ShadowShapeBuilder.FromSetup(setup, 1.5f)[0];
        Assert.Equal(3f, part.ModelScale, 6);
        AssertVec.Near(new Vector3(0, 0, 1.5f), part.PartFrame.Origin); // the origin takes the object's scale only
    }

    [Fact]
    public void FromSetup_ZeroPartDefaultScale_NamesThePart()
    {
        var setup = new PhysicsSetup { Parts = [new SetupPart(null, Frame.Identity, defaultScale: 0f)] };
        var ex = Assert.Throws<ArgumentException>(() => ShadowShapeBuilder.FromSetup(setup));
        Assert.Contains("parts[0].defaultScale", ex.Message);
    }
}
