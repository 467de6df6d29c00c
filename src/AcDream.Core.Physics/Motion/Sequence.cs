using System;
using System.Numerics;
using AcDream.Core.Physics.Body;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The animation sequence of one object, as far as physics needs it (retail CSequence,
/// acclient-src PORTAL/canim/CSequence.c): the list of animations to play (links first, then the cycle from
/// <see cref="FirstCyclic"/> on, which loops), the current animation and frame number, and the velocity and
/// omega the motions added. <see cref="Update"/> advances the frames by framerate × time and returns the
/// frame offset the object moves by: each whole frame crossed adds its root offset and velocity/framerate
/// (and turns by omega/framerate); a frame crossed backwards takes them away. No poses, no hooks except the
/// end of a link animation. The nodes live in one array reused from call to call: no allocation once warm.
/// </summary>
internal sealed class Sequence
{
    /// <summary>One animation in the list (retail AnimSequenceNode): the animation, its frame range and framerate (× the speed).</summary>
    internal struct Node
    {
        public Animation Animation;
        public float Framerate;
        public int LowFrame, HighFrame;

        // AnimSequenceNode::get_starting_frame / get_ending_frame: forwards from the low frame, backwards from just below high + 1.
        // (doubles, as retail keeps the frame number in an x87 register: CSeqPrim.c:61-83).
        public readonly double StartingFrame => Framerate >= 0f ? LowFrame : HighFrame + 1 - (double)PhysicsConstants.Epsilon;
        public readonly double EndingFrame => Framerate >= 0f ? HighFrame + 1 - (double)PhysicsConstants.Epsilon : LowFrame;
    }

    private Node[] _nodes = new Node[8];
    private int _count;

    /// <summary>The index of the first node of the cycle, −1 when the list is empty.</summary>
    public int FirstCyclic { get; private set; } = -1;
    /// <summary>The index of the node playing, −1 when the list is empty.</summary>
    public int Current { get; private set; } = -1;
    /// <summary>The frame number within the current node (a double, as retail's CSequence::frame_number; ACE keeps a float).</summary>
    public double FrameNumber;
    /// <summary>The velocity the motions added, m/s, body axes.</summary>
    public Vector3 Velocity;
    /// <summary>The omega the motions added, rad/s, body axes.</summary>
    public Vector3 Omega;

    public int Count => _count;
    public ref readonly Node this[int index] => ref _nodes[index];
    public bool HasAnims => _count != 0;

    /// <summary>Replaces the whole sequence (a snapshot's load; the caller has checked the indices and frame ranges).</summary>
    public void Restore(ReadOnlySpan<Node> nodes, int firstCyclic, int current, double frameNumber, Vector3 velocity, Vector3 omega)
    {
        Array.Clear(_nodes, 0, _count);
        if (_nodes.Length < nodes.Length)
            _nodes = new Node[nodes.Length];
        nodes.CopyTo(_nodes);
        _count = nodes.Length;
        FirstCyclic = firstCyclic;
        Current = current;
        FrameNumber = frameNumber;
        Velocity = velocity;
        Omega = omega;
    }

    /// <summary>Clears the animations and the physics (CSequence::clear).</summary>
    public void Clear()
    {
        ClearAnimations();
        ClearPhysics();
    }

    public void ClearAnimations()
    {
        Array.Clear(_nodes, 0, _count);
        _count = 0;
        FirstCyclic = -1;
        Current = -1;
        FrameNumber = 0.0;
    }

    public void ClearPhysics()
    {
        Velocity = Vector3.Zero;
        Omega = Vector3.Zero;
    }

    public void CombinePhysics(Vector3 velocity, Vector3 omega)
    {
        Velocity += velocity;
        Omega += omega;
    }

    public void SubtractPhysics(Vector3 velocity, Vector3 omega)
    {
        Velocity -= velocity;
        Omega -= omega;
    }

    /// <summary>
    /// CSequence::append_animation: adds an animation at the end and makes it the first cyclic one; the frame
    /// range is clamped to the animation as AnimSequenceNode::set_animation_id does (high −1 = the last frame).
    /// </summary>
    public void Append(Animation animation, in AnimData data, float speed)
    {
        if (_count == _nodes.Length)
            Array.Resize(ref _nodes, _nodes.Length * 2);
        int last = animation.FrameCount - 1;
        int low = data.LowFrame, high = data.HighFrame;
        if (high < 0) high = last;
        if (low > last) low = last;
        if (high > last) high = last;
        if (low > high) high = low;
        _nodes[_count] = new Node { Animation = animation, Framerate = data.Framerate * speed, LowFrame = low, HighFrame = high };
        FirstCyclic = _count;
        _count++;
        if (Current < 0)
        {
            Current = 0;
            FrameNumber = _nodes[0].StartingFrame;
        }
    }

    /// <summary>CSequence::remove_cyclic_anims: drops the cycle; a playing cycle hands over to the link before it (at its end).</summary>
    public void RemoveCyclicAnims()
    {
        if (FirstCyclic < 0)
            return;
        if (Current >= FirstCyclic)
        {
            Current = FirstCyclic - 1;
            FrameNumber = Current >= 0 ? _nodes[Current].EndingFrame : 0.0;
        }
        Array.Clear(_nodes, FirstCyclic, _count - FirstCyclic);
        _count = FirstCyclic;
        FirstCyclic = _count - 1;
    }

    /// <summary>CSequence::remove_link_animations: drops up to <paramref name="amount"/> links just before the cycle (a playing one hands over to the cycle's start).</summary>
    public void RemoveLinkAnimations(uint amount)
    {
        for (uint i = 0; i < amount && FirstCyclic > 0; i++)
            RemoveLinkBeforeCycle();
    }

    /// <summary>CSequence::remove_all_link_animations.</summary>
    public void RemoveAllLinkAnimations()
    {
        while (FirstCyclic > 0)
            RemoveLinkBeforeCycle();
    }

    private void RemoveLinkBeforeCycle()
    {
        int link = FirstCyclic - 1;
        if (Current == link)
        {
            Current = FirstCyclic;
            FrameNumber = _nodes[Current].StartingFrame;
        }
        RemoveAt(link);
    }

    /// <summary>CSequence::multiply_cyclic_animation_framerate (AnimSequenceNode::multiply_framerate: a negative factor swaps the frame range).</summary>
    public void MultiplyCyclicFramerate(float rate)
    {
        for (int i = Math.Max(FirstCyclic, 0); i < _count; i++)
        {
            ref var node = ref _nodes[i];
            if (rate < 0f)
                (node.LowFrame, node.HighFrame) = (node.HighFrame, node.LowFrame);
            node.Framerate *= rate;
        }
    }

    private void RemoveAt(int index)
    {
        Array.Copy(_nodes, index + 1, _nodes, index, _count - index - 1);
        _count--;
        _nodes[_count] = default;
        if (FirstCyclic > index) FirstCyclic--;
        if (Current > index) Current--;
    }

    /// <summary>
    /// CSequence::update: advances by <paramref name="quantum"/> seconds, adding what was crossed to
    /// <paramref name="offset"/> (body axes, starting at the identity); with no animation the velocity and
    /// omega apply over the whole quantum (apply_physics). Returns how many link animations ended (retail's
    /// AnimDone hooks, which the caller hands to the motion table manager).
    /// </summary>
    public int Update(float quantum, ref Frame offset)
    {
        if (_count == 0)
        {
            ApplyPhysics(ref offset, quantum, quantum);
            return 0;
        }
        int done = UpdateInternal(quantum, ref offset);
        Apricot();
        return done;
    }

    // CSequence::update_internal: the current node plays until its end (or start, backwards); the time left over
    // goes on with the next node (the loop stands for retail's tail call).
    private int UpdateInternal(double timeElapsed, ref Frame offset)
    {
        int linksDone = 0;
        while (true)
        {
            ref var node = ref _nodes[Current];
            double framerate = node.Framerate;
            double frameTime = framerate * timeElapsed;
            int lastFrame = (int)Math.Floor(FrameNumber);
            FrameNumber += frameTime;
            double leftOver = 0.0;
            bool animDone = false;
            if (frameTime > 0.0)
            {
                if (node.HighFrame < Math.Floor(FrameNumber))
                {
                    double past = FrameNumber - node.HighFrame - 1.0;
                    if (past < 0.0) past = 0.0;
                    if (Math.Abs(framerate) > PhysicsConstants.Epsilon)
                        leftOver = past / framerate;
                    FrameNumber = node.HighFrame;
                    animDone = true;
                }
                while (Math.Floor(FrameNumber) > lastFrame)
                {
                    CrossFrame(ref offset, node.Animation, lastFrame, add: true, framerate, timeElapsed);
                    lastFrame++;
                }
            }
            else if (frameTime < 0.0)
            {
                if (node.LowFrame > Math.Floor(FrameNumber))
                {
                    double past = FrameNumber - node.LowFrame;
                    if (past > 0.0) past = 0.0;
                    if (Math.Abs(framerate) > PhysicsConstants.Epsilon)
                        leftOver = past / framerate;
                    FrameNumber = node.LowFrame;
                    animDone = true;
                }
                while (Math.Floor(FrameNumber) < lastFrame)
                {
                    CrossFrame(ref offset, node.Animation, lastFrame, add: false, framerate, timeElapsed);
                    lastFrame--;
                }
            }
            else if (Math.Abs(timeElapsed) > PhysicsConstants.Epsilon)
            {
                ApplyPhysics(ref offset, timeElapsed, timeElapsed);
            }
            if (!animDone)
                return linksDone;
            // The AnimDone hook fires when a node ends while links are still ahead of the cycle in the list.
            if (FirstCyclic != 0)
                linksDone++;
            AdvanceToNextAnimation(timeElapsed, ref offset);
            timeElapsed = leftOver;
        }
    }

    // CSequence::advance_to_next_animation: leaving a node played backwards takes away the frame it stops on;
    // entering a node played forwards adds its first frame (and the reverse when time runs backwards).
    private void AdvanceToNextAnimation(double timeElapsed, ref Frame offset)
    {
        if (timeElapsed >= 0.0)
        {
            ref var leaving = ref _nodes[Current];
            if (leaving.Framerate < 0f)
            {
                CrossFrame(ref offset, leaving.Animation, (int)FrameNumber, add: false, leaving.Framerate, timeElapsed);
            }
            Current = Current + 1 < _count ? Current + 1 : FirstCyclic;
            ref var entering = ref _nodes[Current];
            FrameNumber = entering.StartingFrame;
            if (entering.Framerate > 0f)
            {
                CrossFrame(ref offset, entering.Animation, (int)FrameNumber, add: true, entering.Framerate, timeElapsed);
            }
        }
        else
        {
            ref var leaving = ref _nodes[Current];
            if (leaving.Framerate >= 0f)
            {
                CrossFrame(ref offset, leaving.Animation, (int)FrameNumber, add: false, leaving.Framerate, timeElapsed);
            }
            Current = Current > 0 ? Current - 1 : _count - 1;
            ref var entering = ref _nodes[Current];
            FrameNumber = entering.EndingFrame;
            if (entering.Framerate < 0f)
            {
                CrossFrame(ref offset, entering.Animation, (int)FrameNumber, add: true, entering.Framerate, timeElapsed);
            }
        }
    }

    // CSequence::apricot: links already played are dropped from the head of the list.
    private void Apricot()
    {
        while (_count > 0 && Current > 0 && FirstCyclic > 0)
            RemoveAt(0);
    }

    // CSequence::apply_physics: velocity × t and a turn by omega × t (t's sign from the elapsed time's).
    // The rounding as retail's: x in one step, y and z through a float product (CSequence.c:213-244).
    private void ApplyPhysics(ref Frame offset, double time, double sign)
    {
        double t = sign >= 0.0 ? Math.Abs(time) : -Math.Abs(time);
        var o = offset.Origin;
        o.X = (float)(t * Velocity.X + o.X);
        o.Y = (float)((float)(t * Velocity.Y) + o.Y);
        o.Z = (float)((float)(t * Velocity.Z) + o.Z);
        offset.Origin = o;
        var w = new Vector3((float)(t * Omega.X), (float)(t * Omega.Y), (float)(t * Omega.Z));
        // Frame::rotate: the body-axes rotation vector turned into the frame's parent axes, then grotate.
        offset.Orientation = BodyMotion.Rotate(offset.Orientation, offset.LocalToGlobalVec(w));
    }

    // One frame crossed (update_internal, advance_to_next_animation): its root frame combined onto the offset (add) or
    // taken off it, then the motions' velocity and omega over one frame's time (none at a framerate within EPSILON of 0).
    private void CrossFrame(ref Frame offset, Animation animation, int frame, bool add, double framerate, double timeElapsed)
    {
        if (add)
            AddRootFrame(ref offset, animation, frame);
        else
            SubtractRootFrame(ref offset, animation, frame);
        if (Math.Abs(framerate) > PhysicsConstants.Epsilon)
            ApplyPhysics(ref offset, 1.0 / framerate, timeElapsed);
    }

    private static void AddRootFrame(ref Frame offset, Animation animation, int frame)
    {
        if (!animation.HasRootFrames || (uint)frame >= (uint)animation.RootFrameCount)
            return;
        ref readonly var root = ref animation.RootFrame(frame);
        offset = offset.Combine(new Frame(root.Origin, root.Orientation));
    }

    // Frame::subtract1 (CFrame.c, acclient.c:357321): the frame's turn undone, then its move taken away through the resulting rotation.
    private static void SubtractRootFrame(ref Frame offset, Animation animation, int frame)
    {
        if (!animation.HasRootFrames || (uint)frame >= (uint)animation.RootFrameCount)
            return;
        ref readonly var root = ref animation.RootFrame(frame);
        offset = offset.Subtract(new Frame(root.Origin, root.Orientation));
    }
}
