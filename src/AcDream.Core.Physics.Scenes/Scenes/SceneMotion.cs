using System.Collections.Generic;
using System;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// What drives a motion mover of a scene (one with "commands"): its motion table, its skills and its commands
/// in frame order. Immutable; every run makes its own <see cref="ObjectMotion"/> (<see cref="Start"/>).
/// </summary>
internal sealed class SceneMotion
{
    private readonly SceneCommand[] _commands;

    public SceneMotion(MotionTable table, RetailSkills? skills, SceneCommand[] commands)
    {
        Table = table;
        Skills = skills;
        _commands = commands;
    }

    /// <summary>The motion table.</summary>
    public MotionTable Table { get; }
    /// <summary>The skills (retail's formulas), or null for an object without them (run rate 1, jumps at 10 m/s).</summary>
    public RetailSkills? Skills { get; }
    /// <summary>The commands, in frame order.</summary>
    public ReadOnlySpan<SceneCommand> Commands => _commands;

    /// <summary>A fresh motion layer placed at the mover's start (the body's velocity as the placement leaves it).</summary>
    /// <param name="mover">The mover.</param>
    /// <param name="state">Its start.</param>
    /// <param name="body">Its body.</param>
    /// <param name="earlier">The movers run before this one (their start and frames): what a StickTo command follows.</param>
    public Cursor Start(MoverDescription mover, in MoverState state, ref BodyState body, IReadOnlyList<(SceneMover Mover, IReadOnlyList<TrajectoryFrame> Frames)>? earlier = null)
    {
        var motion = new ObjectMotion(Table, Skills);
        motion.Place(mover, state, ref body);
        // The MoveTo distances' cylinder: the mover's spheres' widest radius and highest top (the retail player's
        // setup says 0.48 and 1.835; its spheres reach 1.83).
        float radius = 0f, height = 0f;
        foreach (var s in mover.Spheres)
        {
            radius = MathF.Max(radius, s.Radius);
            height = MathF.Max(height, s.Center.Z + s.Radius);
        }
        motion.SetCylinder(radius, height);
        return new Cursor(this, motion, earlier ?? []);
    }

    /// <summary>One run of a motion mover: its motion layer and the next command to give.</summary>
    internal sealed class Cursor(SceneMotion script, ObjectMotion motion, IReadOnlyList<(SceneMover Mover, IReadOnlyList<TrajectoryFrame> Frames)> earlier)
    {
        private int _next;
        private int _followed = -1;

        public ObjectMotion Motion { get; } = motion;

        /// <summary>
        /// Gives the commands of <paramref name="frame"/> (and any earlier ones not yet given), in order. A command the
        /// motion layer refuses with an <see cref="ArgumentException"/> becomes a <see cref="SceneFormatException"/>
        /// naming the command's JSON path; refusals by rule (a jump in the air) are retail behaviour, not errors.
        /// </summary>
        public void Give(int frame, MoverDescription mover, ref MoverState state, ref BodyState body)
        {
            var commands = script.Commands;
            while (_next < commands.Length && commands[_next].Frame <= frame)
            {
                ref readonly var c = ref commands[_next++];
                try
                {
                    Apply(c, mover, ref state, ref body);
                }
                catch (ArgumentException ex)
                {
                    throw SceneFormatException.Wrap(c.Path, ex);
                }
            }
            // The followed mover's position where this frame starts (its start, or its frame before), as a target
            // manager's update reports it; ignored by the sticky manager once the stick has ended.
            if (_followed >= 0)
            {
                var (target, frames) = earlier[_followed];
                var at = frame == 0 ? target.Start.Position : new Position(frames[frame - 1].Cell, frames[frame - 1].Position);
                Motion.PositionManager.UpdateTarget(target.Description.ObjectId, at);
            }
        }

        private void Apply(in SceneCommand c, MoverDescription mover, ref MoverState state, ref BodyState body)
        {
            switch (c.Kind)
            {
                case SceneCommandKind.Do:
                    Motion.DoMotion(c.Motion, new MotionParameters(c.Speed, c.HoldKey), mover, ref state, ref body);
                    break;
                case SceneCommandKind.Stop:
                    Motion.StopMotion(c.Motion, new MotionParameters(c.Speed, c.HoldKey), mover, ref state, ref body);
                    break;
                case SceneCommandKind.StopCompletely:
                    Motion.StopCompletely(mover, ref state, ref body);
                    break;
                case SceneCommandKind.SetHoldKey:
                    Motion.SetHoldKey(c.HoldKey, mover, ref state, ref body);
                    break;
                case SceneCommandKind.MoveTo:
                {
                    uint cell = LandDefs.LandCellAt(state.Position.CellId >> 16, c.Target);
                    if (cell == 0)
                        throw new ArgumentException($"moveTo: {c.Target} is outside the mover's landblock (0..192 m on X and Y).", "moveTo");
                    Motion.MoveToProgressRule = c.ProgressRule;
                    Motion.MoveToPosition(new Position(cell, c.Target), c.MoveTo, mover, state, body);
                    break;
                }
                case SceneCommandKind.Jump:
                    // A player's jump: charge_jump on the key press, jump on its release (MotionRig does the same).
                    if (Motion.ChargeJump(mover, state, body) == MotionError.None)
                        Motion.Jump(c.Extent, c.Stamina, mover, ref state, ref body);
                    break;
                case SceneCommandKind.InterpolateTo:
                    Motion.PositionManager.InterpolateTo(c.Position, c.KeepHeading, mover, ref state);
                    break;
                case SceneCommandKind.StickTo:
                    if (c.TargetMover >= earlier.Count)
                        throw new SceneFormatException(c.Path, $"sticks to mover #{c.TargetMover}, whose frames this run was not given (run the scene's movers in order).");
                    Motion.PositionManager.StickTo(earlier[c.TargetMover].Mover.Description.ObjectId, c.Radius, c.Height, mover);
                    _followed = c.TargetMover;
                    break;
                case SceneCommandKind.UnStick:
                    Motion.PositionManager.UnStick();
                    _followed = -1;
                    break;
            }
        }
    }
}
