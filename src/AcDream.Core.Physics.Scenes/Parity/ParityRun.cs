namespace AcDream.Core.Physics.Parity;

/// <summary>One mover (or one approach) of a parity file: who moves, from which state, and the expected frames.</summary>
/// <param name="Name">The mover's name or a description of the approach, for messages.</param>
/// <param name="Mover">The mover.</param>
/// <param name="Start">Its state before the first frame.</param>
/// <param name="Frames">The frames, in order.</param>
internal sealed record ParityRun(string Name, MoverDescription Mover, MoverState Start, ParityFrame[] Frames);
