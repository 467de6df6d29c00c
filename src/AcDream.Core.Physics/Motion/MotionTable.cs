using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// A motion table (the DAT's MotionTable, 0x09… file) with the animations it plays: per style its default
/// substate; cycles keyed by <c>(style &lt;&lt; 16) | (motion &amp; 0xFFFFFF)</c> (the style's high bits are shifted
/// out, as retail's CMotionTable does); modifiers under the same key (or the motion alone, any style); links
/// keyed first by <c>(style &lt;&lt; 16) | (from-substate &amp; 0xFFFFFF)</c> and then by the full target motion id.
/// Checked on construction: every error names its field (<see cref="ArgumentException"/>), and the table is
/// immutable afterwards.
/// </summary>
public sealed class MotionTable
{
    private readonly Dictionary<uint, uint> _styleDefaults;
    private readonly Dictionary<uint, MotionData> _cycles;
    private readonly Dictionary<uint, MotionData> _modifiers;
    private readonly Dictionary<uint, Dictionary<uint, MotionData>> _links;
    private readonly Dictionary<uint, Animation> _animations;

    /// <summary>
    /// The most animations one motion may list, the most frames an animation may have, and the most entries a table may
    /// hold: its animations, cycles, modifiers and links (every target motion under every link key) together. The
    /// constructor enforces them, and the reader stops at the same numbers.
    /// </summary>
    public const int MaxAnimsPerMotion = 64, MaxFrames = 100_000, MaxEntries = 100_000;

    /// <summary>The largest framerate accepted, frames/s (retail's tables use 10 to 60).</summary>
    public const float MaxFramerate = 1000f;

    /// <summary>Builds and checks a table (every collection is copied).</summary>
    /// <param name="id">The 0x09… id.</param>
    /// <param name="defaultStyle">The style an object starts in (a key of <paramref name="styleDefaults"/>).</param>
    /// <param name="styleDefaults">Style → its default substate; each needs a cycle.</param>
    /// <param name="cycles">Cycle key → motion data.</param>
    /// <param name="modifiers">Modifier key → motion data.</param>
    /// <param name="links">Outer key (style, from-substate) → target motion → motion data.</param>
    /// <param name="animations">Every animation the motions play.</param>
    /// <exception cref="ArgumentException">A missing default cycle, a dangling reference, an empty animation, a zero or non-finite framerate, a non-finite vector, a frame range outside its animation; the message names the field.</exception>
    public MotionTable(uint id, uint defaultStyle, IReadOnlyDictionary<uint, uint> styleDefaults, IReadOnlyDictionary<uint, MotionData> cycles,
        IReadOnlyDictionary<uint, MotionData> modifiers, IReadOnlyDictionary<uint, IReadOnlyDictionary<uint, MotionData>> links,
        IEnumerable<Animation> animations)
    {
        ArgumentNullException.ThrowIfNull(styleDefaults);
        ArgumentNullException.ThrowIfNull(cycles);
        ArgumentNullException.ThrowIfNull(modifiers);
        ArgumentNullException.ThrowIfNull(links);
        ArgumentNullException.ThrowIfNull(animations);
        // The size first, before anything is checked or copied: one count for the reader and the constructor.
        long entries = (long)cycles.Count + modifiers.Count;
        foreach (var (_, inner) in links)
            entries += inner?.Count ?? 0;
        var animationList = new List<Animation>();
        foreach (var animation in animations)
        {
            if (entries + animationList.Count >= MaxEntries)
                throw new ArgumentException($"entries: a table holds at most {MaxEntries} entries (animations, cycles, modifiers and links together), got more.", nameof(cycles));
            animationList.Add(animation);
        }
        if (entries + animationList.Count > MaxEntries)
            throw new ArgumentException($"entries: a table holds at most {MaxEntries} entries (animations, cycles, modifiers and links together), got {entries + animationList.Count}.", nameof(cycles));
        Id = id;
        DefaultStyle = defaultStyle;
        _animations = new Dictionary<uint, Animation>();
        int a = 0;
        foreach (var animation in animationList)
        {
            string at = $"animations[{a++}]";
            if (animation is null)
                throw new ArgumentException($"{at}: is null.", nameof(animations));
            CheckAnimation(animation, $"animations[0x{animation.Id:X8}]");
            if (!_animations.TryAdd(animation.Id, animation))
                throw new ArgumentException($"{at}: animation 0x{animation.Id:X8} is listed twice.", nameof(animations));
        }
        _styleDefaults = new Dictionary<uint, uint>(styleDefaults);
        _cycles = Copy(cycles, "cycles");
        _modifiers = Copy(modifiers, "modifiers");
        _links = new Dictionary<uint, Dictionary<uint, MotionData>>();
        foreach (var (outer, inner) in links)
        {
            if (inner is null)
                throw new ArgumentException($"links[0x{outer:X8}]: is null.", nameof(links));
            _links[outer] = Copy(inner, $"links[0x{outer:X8}]");
        }
        if (!_styleDefaults.ContainsKey(defaultStyle))
            throw new ArgumentException($"defaultStyle: style 0x{defaultStyle:X8} has no entry in styleDefaults.", nameof(defaultStyle));
        foreach (var (style, substate) in _styleDefaults)
        {
            uint key = CycleKey(style, substate);
            if (!_cycles.ContainsKey(key))
                throw new ArgumentException($"styleDefaults[0x{style:X8}]: no cycle 0x{key:X8} for its default substate 0x{substate:X8}.", nameof(styleDefaults));
        }
    }

    /// <summary>The 0x09… id.</summary>
    public uint Id { get; }
    /// <summary>The style an object starts in.</summary>
    public uint DefaultStyle { get; }
    /// <summary>Style → default substate.</summary>
    public IReadOnlyDictionary<uint, uint> StyleDefaults => _styleDefaults;
    /// <summary>Cycle key → motion data.</summary>
    public IReadOnlyDictionary<uint, MotionData> Cycles => _cycles;
    /// <summary>Modifier key → motion data.</summary>
    public IReadOnlyDictionary<uint, MotionData> Modifiers => _modifiers;
    /// <summary>The animations by id.</summary>
    public IReadOnlyDictionary<uint, Animation> Animations => _animations;

    /// <summary>The links from <paramref name="outerKey"/> (style, from-substate), or null.</summary>
    public IReadOnlyDictionary<uint, MotionData>? LinksFrom(uint outerKey) => _links.TryGetValue(outerKey, out var inner) ? inner : null;

    /// <summary>The outer keys of the links.</summary>
    public IEnumerable<uint> LinkKeys => _links.Keys;

    /// <summary>The key of a cycle or modifier: <c>(style &lt;&lt; 16) | (motion &amp; 0xFFFFFF)</c> in 32 bits.</summary>
    public static uint CycleKey(uint style, uint motion) => (style << 16) | (motion & MotionCommandMask.Command);

    internal bool TryStyleDefault(uint style, out uint substate) => _styleDefaults.TryGetValue(style, out substate);
    internal MotionData? Cycle(uint key) => _cycles.TryGetValue(key, out var d) ? d : null;
    internal MotionData? Modifier(uint key) => _modifiers.TryGetValue(key, out var d) ? d : null;
    internal MotionData? Link(uint outerKey, uint motion) =>
        _links.TryGetValue(outerKey, out var inner) && inner.TryGetValue(motion, out var d) ? d : null;
    internal bool HasLinksFrom(uint outerKey, out Dictionary<uint, MotionData> inner) => _links.TryGetValue(outerKey, out inner!);
    internal Animation Animation(uint id) => _animations[id];

    /// <summary>Whether the table has anything for a command: a style, a cycle or modifier in one of its styles, a modifier of any style, or a link to it.</summary>
    internal bool Knows(uint motion)
    {
        if ((motion & MotionCommandMask.Style) != 0 && _styleDefaults.ContainsKey(motion))
            return true;
        foreach (var (style, _) in _styleDefaults)
            if (_cycles.ContainsKey(CycleKey(style, motion)) || _modifiers.ContainsKey(CycleKey(style, motion)))
                return true;
        if (_modifiers.ContainsKey(motion & MotionCommandMask.Command))
            return true;
        foreach (var (_, inner) in _links)
            if (inner.ContainsKey(motion))
                return true;
        return false;
    }

    private Dictionary<uint, MotionData> Copy(IReadOnlyDictionary<uint, MotionData> source, string field)
    {
        var copy = new Dictionary<uint, MotionData>();
        foreach (var (key, data) in source)
        {
            string at = $"{field}[0x{key:X8}]";
            CheckMotion(data, at);
            copy[key] = data;
        }
        return copy;
    }

    private void CheckMotion(MotionData? data, string at)
    {
        if (data is null)
            throw new ArgumentException($"{at}: is null.", at);
        // The reader's limit on flags (0 to 3): no bits but HasVelocity and HasOmega.
        if ((data.Flags & ~(MotionDataFlags.HasVelocity | MotionDataFlags.HasOmega)) != 0)
            throw new ArgumentException($"{at}.flags: must be 0 to 3 (1 HasVelocity, 2 HasOmega), got {(int)data.Flags}.", at);
        if (data.Anims.Length > MaxAnimsPerMotion)
            throw new ArgumentException($"{at}.anims: at most {MaxAnimsPerMotion} animations, got {data.Anims.Length}.", at);
        Finite(data.Velocity, $"{at}.velocity");
        Finite(data.Omega, $"{at}.omega");
        if ((data.Flags & MotionDataFlags.HasVelocity) == 0 && data.Velocity != Vector3.Zero)
            throw new ArgumentException($"{at}.velocity: must be zero when flags lack HasVelocity, got {data.Velocity}.", at);
        if ((data.Flags & MotionDataFlags.HasOmega) == 0 && data.Omega != Vector3.Zero)
            throw new ArgumentException($"{at}.omega: must be zero when flags lack HasOmega, got {data.Omega}.", at);
        var anims = data.Anims;
        for (int i = 0; i < anims.Length; i++)
        {
            string ai = $"{at}.anims[{i}]";
            var anim = anims[i];
            if (!_animations.TryGetValue(anim.AnimationId, out var animation))
                throw new ArgumentException($"{ai}.animId: animation 0x{anim.AnimationId:X8} is not in the table's animations.", at);
            if (!float.IsFinite(anim.Framerate) || anim.Framerate == 0f || MathF.Abs(anim.Framerate) > MaxFramerate)
                throw new ArgumentException($"{ai}.framerate: must be finite, not zero and within ±{MaxFramerate} frames/s, got {anim.Framerate}.", at);
            if (anim.LowFrame < 0 || anim.LowFrame >= animation.FrameCount)
                throw new ArgumentException($"{ai}.lowFrame: must be a frame of the animation (0 to {animation.FrameCount - 1}), got {anim.LowFrame}.", at);
            if (anim.HighFrame != -1 && (anim.HighFrame < anim.LowFrame || anim.HighFrame >= animation.FrameCount))
                throw new ArgumentException($"{ai}.highFrame: must be -1 or a frame from lowFrame to {animation.FrameCount - 1}, got {anim.HighFrame}.", at);
        }
    }

    private static void CheckAnimation(Animation animation, string at)
    {
        if (animation.FrameCount <= 0)
            throw new ArgumentException($"{at}.numFrames: an animation needs at least one frame, got {animation.FrameCount}.", at);
        if (animation.FrameCount > MaxFrames)
            throw new ArgumentException($"{at}.numFrames: at most {MaxFrames} frames, got {animation.FrameCount}.", at);
        var roots = animation.RootFrames;
        if (roots.Length != 0 && roots.Length != animation.FrameCount)
            throw new ArgumentException($"{at}.posFrames: none or one per frame ({animation.FrameCount}), got {roots.Length}.", at);
        for (int i = 0; i < roots.Length; i++)
        {
            Finite(roots[i].Origin, $"{at}.posFrames[{i}].origin");
            var q = roots[i].Orientation;
            if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W) || MathF.Abs(q.LengthSquared() - 1f) > 1e-3f)
                throw new ArgumentException($"{at}.posFrames[{i}].orientation: must be a unit quaternion, got {q}.", at);
        }
    }

    private static void Finite(Vector3 v, string field)
    {
        if (!float.IsFinite(v.X) || !float.IsFinite(v.Y) || !float.IsFinite(v.Z) || MathF.Abs(v.X) > 1e4f || MathF.Abs(v.Y) > 1e4f || MathF.Abs(v.Z) > 1e4f)
            throw new ArgumentException($"{field}: must be finite and within ±10000, got {v}.", field);
    }
}
