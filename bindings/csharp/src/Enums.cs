// SPDX-License-Identifier: Apache-2.0
// The C header's #define families as enums (every one is passed as int32_t). Their values
// are the header's; new values are only ever added at the end.
using System;

namespace Enteron
{
    /// <summary>Effects a scene may simulate (ENT_EFFECT_*). A scene runs only those it names.</summary>
    public enum Effect
    {
        /// <summary>axial elasticity (stiff)</summary>
        Stretch = 0,
        /// <summary>bending elasticity (soft)</summary>
        Bend = 1,
        /// <summary>drag and internal damping</summary>
        Damping = 2,
        /// <summary>uniform gravity</summary>
        Gravity = 3,
        /// <summary>tension-only springs to the mesenteric root</summary>
        Mesentery = 4,
        /// <summary>control points held fixed in space</summary>
        Pinned = 5,
        /// <summary>contact with the cavity and organs (on with the first obstacle)</summary>
        Environment = 6,
        /// <summary>folds of the bowel that touch push apart</summary>
        SelfCollision = 7,
        /// <summary>contact and grasp of surgical tools (on with the first tool)</summary>
        Tools = 8,
    }

    /// <summary>A set of effects: the bits of ent_scene_desc.effects (ENT_EFFECT_BIT).</summary>
    [Flags]
    public enum Effects : uint
    {
        /// <summary>no effect</summary>
        None = 0,
        /// <summary><see cref="Effect.Stretch"/></summary>
        Stretch = 1u << (int)Effect.Stretch,
        /// <summary><see cref="Effect.Bend"/></summary>
        Bend = 1u << (int)Effect.Bend,
        /// <summary><see cref="Effect.Damping"/></summary>
        Damping = 1u << (int)Effect.Damping,
        /// <summary><see cref="Effect.Gravity"/></summary>
        Gravity = 1u << (int)Effect.Gravity,
        /// <summary><see cref="Effect.Mesentery"/></summary>
        Mesentery = 1u << (int)Effect.Mesentery,
        /// <summary><see cref="Effect.Pinned"/></summary>
        Pinned = 1u << (int)Effect.Pinned,
        /// <summary><see cref="Effect.Environment"/></summary>
        Environment = 1u << (int)Effect.Environment,
        /// <summary><see cref="Effect.SelfCollision"/></summary>
        SelfCollision = 1u << (int)Effect.SelfCollision,
        /// <summary><see cref="Effect.Tools"/></summary>
        Tools = 1u << (int)Effect.Tools,
    }

    /// <summary>Initial shape of the intestine axis (ENT_SHAPE_*).</summary>
    public enum Shape
    {
        /// <summary>straight, from shape_center_m along shape_direction</summary>
        Line = 0,
        /// <summary>horizontal back-and-forth legs centred on shape_center_m</summary>
        Serpentine = 1,
        /// <summary>vertical helix rising from shape_center_m</summary>
        Helix = 2,
        /// <summary>the control points given to <see cref="Scene.FromDescription"/></summary>
        Points = 3,
    }

    /// <summary>Time integrator (ENT_INTEGRATOR_*).</summary>
    public enum Integrator
    {
        /// <summary>classic 4th-order Runge-Kutta, explicit</summary>
        Rk4 = 0,
        /// <summary>semi-implicit Euler, explicit, 1st order</summary>
        SymplecticEuler = 1,
        /// <summary>linearised backward Euler, banded solve (the default)</summary>
        ImplicitEuler = 2,
        /// <summary>linearised BDF2, banded solve, 2nd order</summary>
        Bdf2 = 3,
    }

    /// <summary>Which ends are pinned or clamped (ENT_PIN_*).</summary>
    public enum PinnedEnds
    {
        /// <summary>neither end</summary>
        None = 0,
        /// <summary>the first end</summary>
        First = 1,
        /// <summary>the last end</summary>
        Last = 2,
        /// <summary>both ends</summary>
        Both = 3,
    }

    /// <summary>Kind of a rigid obstacle (ENT_OBSTACLE_*).</summary>
    public enum ObstacleKind
    {
        /// <summary>the inside of an axis-aligned box: the abdominal cavity</summary>
        BoxInside = 0,
        /// <summary>a plane; the bowel is kept on the side its normal points to</summary>
        Plane = 1,
        /// <summary>a solid sphere (an organ)</summary>
        Sphere = 2,
        /// <summary>a solid capsule (an organ, a vessel)</summary>
        Capsule = 3,
        /// <summary>a triangle mesh, met through its signed distance field</summary>
        Mesh = 4,
    }

    /// <summary>How a tool meets the bowel (ENT_TOOL_MODE_*; docs/haptics.md).</summary>
    public enum ToolMode
    {
        /// <summary>a proxy kept out of the tube, joined to the commanded pose by a virtual coupling</summary>
        Proxy = 0,
        /// <summary>the capsule is where the caller puts it</summary>
        Direct = 1,
    }

    /// <summary>What a contact of the bowel touches (ENT_CONTACT_*).</summary>
    public enum ContactKind
    {
        /// <summary>another fold of the bowel</summary>
        Self = 0,
        /// <summary>an obstacle (Contact.index: its index)</summary>
        Obstacle = 1,
        /// <summary>a tool (Contact.index: its id)</summary>
        Tool = 2,
    }

    /// <summary>Skinning methods (ENT_SKIN_*; docs/skinning.md).</summary>
    public enum SkinMethod
    {
        /// <summary>rings on rotation-minimising frames: fastest</summary>
        Tube = 0,
        /// <summary>distance surface of point skeletons, marching cubes</summary>
        PointSkeleton = 1,
        /// <summary>local convolution surface of the axis segments (the default)</summary>
        Convolution = 2,
    }

    /// <summary>Level of a log line (ENT_LOG_*).</summary>
    public enum LogLevel
    {
        /// <summary>ENT_LOG_DEBUG</summary>
        Debug = 0,
        /// <summary>ENT_LOG_INFO</summary>
        Info = 1,
        /// <summary>ENT_LOG_WARNING</summary>
        Warning = 2,
        /// <summary>ENT_LOG_ERROR</summary>
        Error = 3,
    }
}
