using AcDream.Core.Physics.Queries;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// The camera arm walks a long stretch of its sub-steps in one go when a conservative test proves that
/// they touch nothing (see WorldQuery's skip): its answers must stay bit for bit the ones of the arm that
/// walks every sub-step. Checked two ways: against a table recorded from the walking arm before the skip
/// existed (origin, normal and cell as bits), and over many random arms against the walking arm itself.
/// </summary>
public class CameraArmSkipTests
{
    /// <summary>One recorded answer: the camera's cell and origin bits, placement, blocked, normal bits.</summary>
    private readonly record struct Recorded(string Name, uint Cell, uint X, uint Y, uint Z, CameraPlacement Placement, bool Blocked, uint Nx, uint Ny, uint Nz);

    // Recorded on main at 909926c (every sub-step walked), before the skip was written.
    private static readonly Recorded[] OnMain =
    [
        new("room, open, stays inside", 0xA9B40100, 0x42C60002, 0x42CCFFFD, 0x40000000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 99.000015 102.49998 2 n <0, 0, 0>
        new("room, 5 m, stops at the north wall", 0xA9B40100, 0x42C80000, 0x42CF666A, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0xBF800000, 0x00000000), // 100 103.70003 1.5 n <0, -1, 0>
        new("room, diagonal into the north-east corner", 0xA9B40100, 0x42CB6666, 0x42CF04BD, 0x40042AC7, CameraPlacement.Swept, true, 0xBF800000, 0x00000000, 0x00000000), // 101.7 103.509254 2.065111 n <-1, 0, 0>
        new("room, up into the ceiling", 0xA9B40100, 0x42C6B24F, 0x42CC87F3, 0x402CCCCD, CameraPlacement.Swept, true, 0x00000000, 0x00000000, 0xBF800000), // 99.34826 102.265526 2.7 n <0, 0, -1>
        new("room, towards the closed door", 0xA9B40100, 0x42C83333, 0x42C8CDD3, 0x3FB33333, CameraPlacement.Swept, true, 0x00000000, 0x3F800000, 0x00000000), // 100.1 100.402 1.4 n <0, 1, 0>
        new("room, through the open doorway", 0xA9B40025, 0x42C8666C, 0x42C00009, 0x3F800003, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100.20004 96.00007 1.0000004 n <0, 0, 0>
        new("room, beside the doorway into the south wall", 0xA9B40100, 0x42CA999A, 0x42C8999A, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0x3F800000, 0x00000000), // 101.3 100.3 1.5 n <0, 1, 0>
        new("room, down the stairwell portal into the cellar", 0xA9B40101, 0x42CA999D, 0x42CEFFFC, 0xBF333333, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 101.300026 103.49997 -0.7 n <0, 0, 0>
        new("cellar, up into the room", 0xA9B40100, 0x42C8CCCB, 0x42CBFFFD, 0x3FE66668, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100.39999 101.99998 1.8000002 n <0, 0, 0>
        new("outdoors, onto the door slab", 0xA9B40025, 0x42C80000, 0x42C761CB, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0xBF800000, 0x00000000), // 100 99.691 1.5 n <0, -1, 0>
        new("outdoors, into the ground", 0xA9B4001C, 0x42B40000, 0x42B6BE2F, 0x3E99999A, CameraPlacement.Swept, true, 0x00000000, 0x00000000, 0x3F800000), // 90 91.37145 0.3 n <0, 0, 1>
        new("outdoors, clear beside the door", 0xA9B4001D, 0x42C00000, 0x42CE0008, 0x3FC00000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 96 103.00006 1.5 n <0, 0, 0>
        new("outdoors, the door as the player", 0xA9B40025, 0x42C80000, 0x42CE0008, 0x3FC00000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100 103.00006 1.5 n <0, 0, 0>
        new("outdoors, grazing the trunk", 0xA9B40025, 0x42C962AB, 0x42C6D9D0, 0x3FB509DE, CameraPlacement.Swept, true, 0x3F4509C9, 0xBF237019, 0x00000000), // 100.69271 99.425415 1.4143636 n <0.76968056, -0.6384292, 0>
        new("outdoors, onto the boulder", 0xA9B40025, 0x42C5F2D3, 0x42C67475, 0x3F4D7572, CameraPlacement.Swept, true, 0xBF49FDBE, 0xBF1821DD, 0x3E1F90DA), // 98.974266 99.227455 0.8025733 n <-0.78902805, -0.5942667, 0.155826>
        new("outdoors, over the sloped ground", 0xA9B40002, 0x419FFFF7, 0x41F00014, 0x413FFFE7, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 19.999983 30.000038 11.999976 n <0, 0, 0>
        new("outdoors, into the slope", 0xA9B4000A, 0x4219F101, 0x4219F101, 0x4041E01A, CameraPlacement.Swept, true, 0x3D4C6B6D, 0x3D0F1801, 0x3F7F8647), // 38.485355 38.485355 3.029303 n <0.049907137, 0.034935, 0.99814266>
        new("outdoors, across a landblock's cells downhill", 0xA9B4000B, 0x421FFFDB, 0x4247FFFD, 0x421FFFDB, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 39.99986 49.99999 39.99986 n <0, 0, 0>
    ];

    [Fact]
    public void TheHandPickedArms_GiveTheAnswersRecordedBeforeTheSkip_BitForBit()
    {
        Assert.Equal(CameraArmCases.Table.Length, OnMain.Length);
        for (int i = 0; i < OnMain.Length; i++)
        {
            var arm = CameraArmCases.Table[i];
            var expected = OnMain[i];
            Assert.Equal(expected.Name, arm.Name);
            var r = CameraArmCases.QueryFor(arm.World).CameraArm(new Position(arm.Cell, arm.Pivot), arm.Desired, arm.Player);
            var o = r.Camera.Origin;
            var got = new Recorded(arm.Name, r.Camera.CellId, Bits(o.X), Bits(o.Y), Bits(o.Z), r.Placement, r.Blocked, Bits(r.Normal.X), Bits(r.Normal.Y), Bits(r.Normal.Z));
            Assert.True(expected == got, $"{arm.Name}: expected {expected}, got {got} ({o}, n {r.Normal})");
        }
    }

    private static uint Bits(float f) => (uint)BitConverter.SingleToInt32Bits(f);
}
