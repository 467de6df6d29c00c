using System.Numerics;
using System.Threading.Tasks;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>Ways a method can fail an approach (several may apply).</summary>
[Flags]
public enum DoorFailure
{
    /// <summary>No failure.</summary>
    None = 0,
    /// <summary>Collision normals alternated frame to frame (n_k ≠ n_k−1, n_k = n_k−2).</summary>
    Jitter = 1,
    /// <summary>The mover stayed put while the reference moved and the requested motion along the face per sub-step exceeded √EPSILON.</summary>
    Stuck = 2,
    /// <summary>A sphere ended a frame deeper than EPSILON inside the slab.</summary>
    Penetration = 4,
    /// <summary>The mover crossed the slab.</summary>
    Tunnel = 8,
    /// <summary>A non-finite position, or the method threw.</summary>
    NaN = 16,
}
