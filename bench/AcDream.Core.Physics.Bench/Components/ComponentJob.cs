using System.Diagnostics;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Bench.Components;

/// <summary>
/// <c>components [--slide | --collide] [NAME...]</c>: what each part of one transition costs, to see where a
/// frame's time goes. The frame is the door scene's player walking 2 m/s at 30 Hz towards the door from
/// 0.2 m short (a free move whose one sub-step tests the terrain and the door's BSP). The 45° NE slide along
/// the door's face (the timing driver's slide-ne: 0.1 m per frame from (99.6, 99.0)) alternates two kinds of
/// frame once it reaches the door: <c>--slide</c> times its eleventh frame, which carries the sliding normal
/// and moves along the face in one insert; <c>--collide</c> its tenth, which carries none, hits the face,
/// tries to step up (three inserts) and slides. Each component runs on the transition as
/// the frame leaves it, 40 rounds of 50,000 calls after 200,000 to warm up; the fastest round is printed in
/// ns per call. Components nest (<c>setup</c> includes <c>validate</c>, <c>insert</c> includes
/// <c>cells</c>, <c>cells</c> includes <c>land</c> and <c>objects</c>…). For repeatable numbers run it with
/// <c>DOTNET_TieredCompilation=0</c> (the optimizing compiler at once, no profile-guided variation between
/// runs), several times, and keep the fastest.
/// </summary>
public static class ComponentJob
{
    /// <summary>The components, in report order, with what each times.</summary>
    public static readonly (string Name, string What)[] All =
    [
        ("resolve", "PhysicsEngine.Resolve of the whole frame"),
        ("validate", "the input checks: both poses, the state's cell, distance and planes"),
        ("setup", "validate + resetting the path and collision info + the path's start"),
        ("transition", "setup + find_transitional_position"),
        ("collect", "building the MoveResult"),
        ("cell-array", "build_cell_array with the containing cell (the cell search)"),
        ("land", "the land cell's terrain test"),
        ("objects", "the cell's objects: the cull and the door's dispatch"),
        ("door", "the door's BSP part: local-space spheres and the BSP query"),
        ("local-space", "the spheres in the door part's space"),
        ("current-spheres", "the spheres at the current position"),
        ("cells", "one cell's collisions: terrain, building, objects"),
        ("insert", "transitional_insert of the check position (3 attempts)"),
        ("set-check", "setting the check position to the current one"),
    ];

    /// <summary>Runs the job; exit 2 on an unknown component.</summary>
    public static int Run(string[] args)
    {
        int slideFrame = args.Contains("--slide") ? 10 : args.Contains("--collide") ? 9 : -1;
        args = args.Where(a => a != "--slide" && a != "--collide").ToArray();
        foreach (string name in args)
            if (Array.FindIndex(All, c => c.Name == name) < 0)
            {
                Console.Error.WriteLine($"components: unknown component '{name}' (known: {string.Join(", ", Array.ConvertAll(All, c => c.Name))})");
                return 2;
            }
        var frame = new FreeFrame(slideFrame);
        Console.WriteLine("| component | ns per call | what |");
        Console.WriteLine("|---|---:|---|");
        foreach (var (name, what) in All)
        {
            if (args.Length > 0 && Array.IndexOf(args, name) < 0)
                continue;
            Console.WriteLine($"| {name} | {frame.Time(name):F1} | {what} |");
        }
        return 0;
    }

    /// <summary>The measured frame and the engine internals each component calls.</summary>
    private sealed class FreeFrame
    {
        private readonly PhysicsEngine _engine;
        private readonly Transition _t;
        private readonly MoverDescription _player = MoverDescription.Player();
        private readonly MoverState _state;
        private readonly Position _target;
        private readonly World.Cell _cell;
        private readonly World.ShadowEntry _door;
        private float _sink;

        public FreeFrame(int slideFrame)
        {
            bool slide = slideFrame >= 0;
            var world = SceneLibrary.Load("door").World;
            _engine = new PhysicsEngine(world);
            _t = _engine.Transition;
            var p = slide ? new Vector3(99.6f, 99.0f, 0) : new Vector3(100f, DoorScene.DoorOrigin.Y - 0.009f - DoorScene.PlayerRadius - 0.2f, 0);
            var step = slide ? new Vector3(0.0707f, 0.0707f, 0) : new Vector3(0, 2f / 30f, 0);
            _state = MoverState.OnFloor(new Position(LandDefs.LandCellAt(0xA9B4, p), p), 0f);
            for (int i = 0; i < slideFrame; i++)
            {
                var next = _state.Position;
                next.Frame.Origin += step;
                _state = _engine.Resolve(_player, _state, next).Next;
            }
            _target = _state.Position;
            _target.Frame.Origin += step;
            Setup();
            _t.SpherePath.SetCheckPos(_t.SpherePath.CurPos, _t.SpherePath.CurCell);
            _cell = _t.SpherePath.CheckCell!;
            _door = world.Objects.ObjectsInCell(_cell.Id).RowsOf(0)[0];
        }

        private World.Cell Validate()
        {
            var begin = _state.Position;
            var target = _target;
            Guard.Pose(ref begin.Frame, "state.position");
            Guard.Pose(ref target.Frame, "target");
            return _engine.ValidateState(_player, _state, begin, target.CellId);
        }

        private void Setup()
        {
            var cell = Validate();
            var begin = _state.Position;
            PhysicsEngine.Prepare(_t, _player, _state);
            _t.SpherePath.InitSphere(_player);
            _t.SpherePath.InitPath(cell, in begin, in _target);
        }

        private void Once(string name)
        {
            var path = _t.SpherePath;
            switch (name)
            {
                case "resolve": _sink += _engine.Resolve(_player, _state, _target).Next.Position.Frame.Origin.Y; break;
                case "validate": _sink += Validate().Id; break;
                case "setup": Setup(); break;
                case "transition": Setup(); _sink += _t.FindTransitionalPosition() ? 1 : 0; break;
                case "collect": _sink += PhysicsEngine.Collect(_t, true, _state).Next.Position.Frame.Origin.Y; break;
                case "cell-array": _sink += _t.BuildCellArray(true)!.Id; break;
                case "land": _sink += (int)CellCollisions.FindEnvCollisions(_cell, _t); break;
                case "objects": _sink += (int)ObjectCollisions.FindInCell(_t, _cell.Id); break;
                case "door": _sink += (int)PartCollision.Collide(_t, _door.Shape.Model!, _door.PartPosition, _door.Shape.ModelScale); break;
                case "local-space": path.CacheLocalSpaceSphere(_door.PartPosition, 1f); break;
                case "current-spheres": path.CacheGlobalCurrCenter(); break;
                case "cells": _sink += (int)_t.FindCollisions(_cell); break;
                case "insert": path.SetCheckPos(path.CurPos, path.CurCell); _sink += (int)_t.TransitionalInsert(3); break;
                case "set-check": path.SetCheckPos(path.CurPos, path.CurCell); break;
            }
        }

        /// <summary>The fastest of 40 rounds of 50,000 calls, in ns per call, after 200,000 calls of warm-up.</summary>
        public double Time(string name)
        {
            Setup();
            _t.SpherePath.SetCheckPos(_t.SpherePath.CurPos, _t.SpherePath.CurCell);
            for (int i = 0; i < 200_000; i++)
                Once(name);
            double best = double.MaxValue;
            for (int round = 0; round < 40; round++)
            {
                var clock = Stopwatch.StartNew();
                for (int i = 0; i < 50_000; i++)
                    Once(name);
                best = Math.Min(best, clock.Elapsed.TotalNanoseconds / 50_000);
            }
            return _sink == float.MinValue ? 0 : best;
        }
    }
}
