using System;

namespace AcDream.Core.Physics;

/// <summary>Retail PhysicsState bits of a physics object (acclient.h PhysicsState; ACE PhysicsState.cs).</summary>
[Flags]
public enum PhysicsState : uint
{
    /// <summary>No bit set.</summary>
    None = 0,
    /// <summary>STATIC_PS.</summary>
    Static = 0x1,
    /// <summary>ETHEREAL_PS: passes through other objects.</summary>
    Ethereal = 0x4,
    /// <summary>REPORT_COLLISIONS_PS.</summary>
    ReportCollisions = 0x8,
    /// <summary>IGNORE_COLLISIONS_PS.</summary>
    IgnoreCollisions = 0x10,
    /// <summary>NODRAW_PS.</summary>
    NoDraw = 0x20,
    /// <summary>MISSILE_PS: a projectile in flight.</summary>
    Missile = 0x40,
    /// <summary>PUSHABLE_PS.</summary>
    Pushable = 0x80,
    /// <summary>ALIGNPATH_PS.</summary>
    AlignPath = 0x100,
    /// <summary>PATHCLIPPED_PS.</summary>
    PathClipped = 0x200,
    /// <summary>GRAVITY_PS.</summary>
    Gravity = 0x400,
    /// <summary>LIGHTING_ON_PS.</summary>
    LightingOn = 0x800,
    /// <summary>PARTICLE_EMITTER_PS.</summary>
    ParticleEmitter = 0x1000,
    /// <summary>HIDDEN_PS.</summary>
    Hidden = 0x4000,
    /// <summary>SCRIPTED_COLLISION_PS.</summary>
    ScriptedCollision = 0x8000,
    /// <summary>
    /// HAS_PHYSICS_BSP_PS: the object collides through its parts' physics BSPs only, never through its
    /// cylspheres or spheres (unless the missile-ignore or PvP exemption applies). Set at creation from the
    /// parts' geometry (retail CacheHasPhysicsBSP), not only taken from the wire.
    /// </summary>
    HasPhysicsBsp = 0x10000,
    /// <summary>INELASTIC_PS.</summary>
    Inelastic = 0x20000,
    /// <summary>HAS_DEFAULT_ANIM_PS.</summary>
    HasDefaultAnim = 0x40000,
    /// <summary>HAS_DEFAULT_SCRIPT_PS.</summary>
    HasDefaultScript = 0x80000,
    /// <summary>CLOAKED_PS.</summary>
    Cloaked = 0x100000,
    /// <summary>REPORT_COLLISIONS_AS_ENVIRONMENT_PS.</summary>
    ReportCollisionsAsEnvironment = 0x200000,
    /// <summary>EDGE_SLIDE_PS.</summary>
    EdgeSlide = 0x400000,
    /// <summary>SLEDDING_PS.</summary>
    Sledding = 0x800000,
    /// <summary>FROZEN_PS.</summary>
    Frozen = 0x1000000,
}
