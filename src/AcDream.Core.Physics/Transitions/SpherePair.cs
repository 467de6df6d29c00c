using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// Storage for a mover's spheres without a heap array: retail movers have at most two
/// (SpherePath caps num_sphere at 2).
/// </summary>
[InlineArray(2)]
internal struct SpherePair
{
    private Sphere _first;
}
