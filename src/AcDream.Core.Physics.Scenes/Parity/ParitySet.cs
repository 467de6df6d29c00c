using System.Collections.Generic;

namespace AcDream.Core.Physics.Parity;

/// <summary>A parity file read into a world and the runs to walk through it.</summary>
/// <param name="Name">The file's name, for messages.</param>
/// <param name="World">The world every run walks through (alone).</param>
/// <param name="Runs">The runs.</param>
/// <param name="RequireBitIdentical">Every position must match to the last bit (the ACE door file); otherwise within <see cref="ParityCheck.Tolerance"/>.</param>
/// <param name="Motion">For a motion-layer file ("ace-motion-parity"), the file read; its runs are then empty.</param>
/// <param name="MoveTo">For a MoveTo file of the managers' data ("ace-manager-parity"), the file read.</param>
/// <param name="Positions">For a position managers' file of the managers' data (sticky, interpolate), the file read.</param>
internal sealed record ParitySet(string Name, PhysicsWorld World, IReadOnlyList<ParityRun> Runs, bool RequireBitIdentical,
    MotionParityFile? Motion = null, MoveToParityFile? MoveTo = null,
    PositionManagerParityFile? Positions = null);
