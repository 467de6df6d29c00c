// A server's creature, the recipe of docs/creatures.md: it chases a player who walks a circle, with retail's MoveTo
// (re-issued whenever it has ended and the player is out of reach), holds the player in melee by sticking to it at
// every swing, and is then shot by an archer standing off, the arrow passing the player beside it. The page's code
// is the regions marked "recipe" below (a test checks that they are the same text).
// Exit code: 0 when the creature reaches the player within 10 s, is in melee reach for at least 80 % of the ticks
// from then on, and the arrow hits it; 1 otherwise.

#region recipe
using System;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Scenes;                                    // the built-in humanoid motion table

const uint landblock = 0xA9B4;
var world = new PhysicsWorld();
world.Cells.AddLandblock(Terrain.Flat(landblock, 0f));
var engine = new PhysicsEngine(world);
const float radius = 0.48f, height = 1.835f;                         // the retail humanoid's cylinder
var cylinder = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, radius, height)], Height = height, Radius = radius };

// Players and monsters are both creatures, with a weenie: an arrow aimed at one creature passes every other
// creature (the archer it leaves, the player beside its target) and hits its target. Not Static: a static object's
// hit is reported as the environment's.
const ShadowFlags creatureFlags = ShadowFlags.IsCreature | ShadowFlags.HasWeenie;

// The player: its client moves it; the server only writes the positions it reports into the registry.
const uint playerId = 0x5000_0001;
static Position PlayerAt(int tick)                                    // a 6 m circle at 2.5 m/s
{
    float a = tick * (2.5f / 30f / 6f);
    return Position.Outdoor(landblock, new Vector3(70f + 6f * MathF.Cos(a), 66f + 6f * MathF.Sin(a), 0f));
}
var player = PlayerAt(0);
world.Objects.Register(playerId, cylinder, player, 1f, PhysicsState.Gravity, ShadowFlags.IsPlayer | creatureFlags);

// The creature: a humanoid moved by its motion table, 40 m off, registered like the player.
const uint creatureId = 0x8000_0001;
var creature = MoverDescription.Player(creatureId).With(physicsState: PhysicsState.Gravity, flags: ObjectInfoState.None);
var state = engine.Place(creature, Position.Outdoor(landblock, new Vector3(40f, 40f, 0f))).Next;
var body = BodyState.Creature();
var motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill: 200, jumpSkill: 200));
motion.SetCylinder(radius, height);                                   // MoveTo measures between the two cylinders
motion.Place(creature, state, ref body);
world.Objects.Register(creatureId, cylinder, state.Position, 1f, PhysicsState.Gravity, creatureFlags);
#endregion

#region recipe
// The chase, one server tick (1/30 s) at a time. A MoveTo ends when it arrives (within 0.6 m of the player, between
// the cylinders) and does not follow the player on from there: the server gives a new one whenever the last has
// ended and the player is out of reach. With Sticky, the arrival sticks the creature to the player for 1 s (it keeps
// a 0.3 m gap and faces the player); each swing sticks it again. When a stick runs out before the next swing, the
// player walks out of reach and the next MoveTo brings the creature back.
var chase = MoveToParameters.Default with
{
    Flags = MoveToFlags.RetailDefault | MoveToFlags.Sticky,
    // Walk or run is decided when the move starts: it runs when farther than this beyond the 0.6 m. Retail's
    // default is 15 m, so a creature sent after a player 10 m off walks (3 m/s) and never catches a runner; a server
    // that wants its monsters to run the last stretch says so (ACE's MovementParameters default to 1 m).
    WalkRunThreshold = 1f,
};
const float meleeReach = 1f;                                          // gap between the cylinders a swing reaches
const int swingTicks = 45;                                            // a swing every 1.5 s; a stick lasts 1 s
int lastSwing = -swingTicks, swings = 0, moves = 0, firstInReach = -1, inReach = 0;
const int ticks = 20 * 30;
for (int tick = 0; tick < ticks; tick++)
{
    player = PlayerAt(tick);                                          // the player's client reported it
    world.Objects.Move(playerId, player);

    float gap = Vector3.Distance(state.Position.Origin, player.Origin) - 2 * radius;
    if (motion.MoveToStatus is MoveToStatus.Idle or MoveToStatus.Ended)
    {
        if (gap > meleeReach)
        {
            motion.MoveToObject(playerId, radius, height, chase, creature, state, body);
            motion.UpdateMoveToTarget(playerId, player, creature, state, body);     // nothing moves before the first
            moves++;
        }
        else if (tick - lastSwing >= swingTicks)
        {
            motion.PositionManager.StickTo(playerId, radius, height, creature);    // a swing: hold on for 1 s more
            lastSwing = tick;
            swings++;
        }
    }
    else
        motion.UpdateMoveToTarget(playerId, player, creature, state, body);         // steer at where the player is now
    motion.PositionManager.UpdateTarget(playerId, player);                          // the stick follows it too

    var step = engine.Step(creature, state, body, motion, 1.0 / 30);
    state = step.Next;
    body = step.Body;
    world.Objects.Move(creatureId, state.Position);                  // the one writer, between the creatures' steps

    if (Vector3.Distance(state.Position.Origin, player.Origin) - 2 * radius <= meleeReach)
    {
        inReach++;
        if (firstInReach < 0) firstInReach = tick;
    }
}
Console.WriteLine($"in reach from tick {firstInReach}, then {inReach} of {ticks - firstInReach} ticks; {moves} MoveTos, {swings} swings");
#endregion

#region recipe
// An archer 12 m off, behind the player, shoots the creature. The arrow starts inside the archer's cylinder and
// passes it, then passes through the player in front of the target: both are creatures with a weenie, and the arrow
// has a target (an untargeted arrow hits the first creature in its way).
const uint archerId = 0x8000_0002, arrowId = 0x8000_00A0;
var behindPlayer = Vector3.Normalize((player.Origin - state.Position.Origin) with { Z = 0f });
var archerAt = Position.Outdoor(landblock, state.Position.Origin + behindPlayer * 12f);
world.Objects.Register(archerId, cylinder, archerAt, 1f, PhysicsState.Gravity, creatureFlags);
var chest = new Vector3(0f, 0f, 1.3f);
var from = Position.Outdoor(landblock, archerAt.Origin + chest);
var aim = Vector3.Normalize(state.Position.Origin + chest - from.Origin);
var arrow = Missile.Launch(arrowId, radius: 0.05f, from, velocity: aim * 40f, targetId: creatureId);
MissileHit hit = default;
for (int i = 0; i < 60 && arrow.InFlight; i++)
    hit = engine.Step(arrow, 1.0 / 30).Hit;
Console.WriteLine($"the arrow: {hit.Kind} 0x{hit.ObjectId:X8}");
#endregion

bool held = firstInReach >= 0 && firstInReach < 10 * 30 && inReach >= 0.8 * (ticks - firstInReach);
bool shot = hit.Kind == MissileHitKind.Object && hit.ObjectId == creatureId;
if (!held || !shot)
{
    Console.Error.WriteLine(held ? "the arrow missed the creature" : "the creature did not hold the player in melee");
    return 1;
}
return 0;
