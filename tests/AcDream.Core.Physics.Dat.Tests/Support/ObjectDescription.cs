using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatCylSphere = DatReaderWriter.Types.CylSphere;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;
using DatFrame = DatReaderWriter.Types.Frame;
using DatLandDefs = DatReaderWriter.Types.LandDefs;
using DatSphere = DatReaderWriter.Types.Sphere;
using EnvCell = AcDream.Core.Physics.EnvCell;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>What the game (not the DAT) says about a placed object: its id, scale, state and flags.</summary>
internal readonly record struct ObjectDescription(uint Id, float Scale, PhysicsState State, ShadowFlags Flags);
