using System.Threading;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// The registry's writes: <c>Move</c> allocates nothing once warm, and removal keeps retail's
/// swap-with-last order exactly while finding each object's place without searching the cell's list.
/// </summary>
public class RegistryCostTests
{
    private static PhysicsSetup Balls(int count)
    {
        var spheres = new List<Sphere>();
        for (int i = 0; i < count; i++)
            spheres.Add(new Sphere(new Vector3(0, 0, 0.5f * i), 0.3f));
        return new PhysicsSetup { Spheres = spheres };
    }

    [Fact]
    public void Move_AllocatesNothing_OnceWarm()
    {
        long allocated = -1;
        Exception? failure = null;
        // A dedicated thread: GetAllocatedBytesForCurrentThread sees only this work.
        var thread = new Thread(() =>
        {
            try
            {
                var world = TestGeometry.FlatWorld();
                var reg = world.Objects;
                reg.Register(1, TestGeometry.DoorSetup(), TestGeometry.At(100, 100, 0), 1f, PhysicsState.ReportCollisions);
                reg.Register(2, Balls(2), TestGeometry.At(30, 30, 0));
                reg.Register(3, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.5f, 2f)] }, TestGeometry.At(50, 50, 0));
                for (uint id = 10; id < 30; id++)
                    reg.Register(id, Balls(1 + (int)(id % 3)), TestGeometry.At(40 + id, 45, 0));
                // Positions across cell borders (one object in up to four cells), rotated.
                var positions = new List<Position>();
                for (int i = 0; i < 16; i++)
                {
                    var p = TestGeometry.At(20 + i * 7.3f, 23 + i * 5.1f, 0);
                    p.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, i * 0.4f);
                    positions.Add(p);
                }
                void Cycle()
                {
                    foreach (var p in positions)
                    {
                        reg.Move(1, p);
                        reg.Move(2, p);
                        reg.Move(3, p);
                        reg.Move(15, p);
                    }
                }
                Cycle();
                Cycle();
                long before = GC.GetAllocatedBytesForCurrentThread();
                Cycle();
                allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            }
            catch (Exception e)
            {
                failure = e;
            }
        });
        thread.Start();
        thread.Join();
        Assert.Null(failure);
        Assert.Equal(0, allocated);
    }

    [Fact]
    public void ManyObjectsInOneCell_RemovedAndMovedInAnyOrder_KeepRetailsSwapWithLastOrder()
    {
        var world = TestGeometry.FlatWorld();
        var reg = world.Objects;
        var here = TestGeometry.At(12, 12, 0);
        uint cell = here.CellId;
        var model = new List<uint>();   // the cell's object order, by retail's rules
        var shapeCount = new Dictionary<uint, int>();
        for (uint id = 1; id <= 3000; id++)
        {
            int n = 1 + (int)(id % 3);
            reg.Register(id, Balls(n), here);
            model.Add(id);
            shapeCount[id] = n;
        }
        var random = new Random(14);
        for (int op = 0; op < 2500; op++)
        {
            uint id = model[random.Next(model.Count)];
            // Retail: remove moves the cell's last object into the hole; a move re-appends.
            int hole = model.IndexOf(id);
            model[hole] = model[^1];
            model.RemoveAt(model.Count - 1);
            if (op % 5 == 0)
            {
                reg.Move(id, here);
                model.Add(id);
            }
            else
            {
                Assert.True(reg.Unregister(id));
            }
            if (op % 250 != 0 && op != 2499)
                continue;
            var expected = model.SelectMany(o => Enumerable.Repeat(o, shapeCount[o])).ToArray();
            Assert.Equal(expected, reg.RowsInCell(cell).ToArray().Select(r => r.EntityId).ToArray());
        }
        Assert.Equal(model.Count, reg.Count);
    }
}
