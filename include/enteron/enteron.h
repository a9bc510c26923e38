/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Enteron: a real-time model of the human small intestine for surgery simulators.
 *
 * This is the one public header of libenteron. It is plain C99 (it also compiles as C++),
 * exposes only opaque handles and description structs that start with `struct_size`, and
 * passes every enum as int32_t, so that a program built against it keeps working with
 * later releases of the same major version.
 *
 * Units are SI everywhere: metres, kilograms, seconds, newtons. A field's unit is in its
 * name (`radius_m`, `timestep_s`) or in its comment.
 *
 * Errors: every call that can fail returns an ent_status. ENT_OK (0) is success; any other
 * value names the failure, ent_status_string() spells it out and ent_last_error() gives
 * the message of the failing call on the calling thread (it names the bad input). A
 * failing call changes nothing: the scene is exactly as it was before the call (only the
 * work counters of ent_stats and ent_effect_stats record a step the guard gave up on).
 *
 * Threads (a physics thread at 1 kHz, a haptic thread, a render thread):
 * - The driving calls change (or read) the live simulation: ent_scene_step,
 *   ent_scene_add_obstacle, ent_tool_add, ent_scene_save_state, ent_scene_restore_state,
 *   and the changes between steps of the anatomy (ent_obstacle_set_pose,
 *   _set_velocity, _set_friction, ent_scene_remove_obstacle, ent_obstacle_mesh,
 *   ent_scene_set_gravity, ent_scene_pin_point, ent_scene_unpin_point,
 *   ent_scene_attach_mesentery, ent_scene_attach_clamped_end). One of them at a time per
 *   scene: a driving call made while another runs on the same scene on another thread
 *   returns ENT_ERROR_BUSY at once and changes nothing
 *   (the check costs one atomic operation). The driving thread may change between calls.
 * - The tool commands (ent_tool_set_pose, ent_tool_grasp, ent_tool_release) are safe from
 *   any thread, at any time, never wait and allocate nothing: each goes into the tool's
 *   mailbox, which the next ent_scene_step takes at its start (the last command posted
 *   before that wins). A haptic thread posts poses while the physics thread steps.
 * - The queries read the last published snapshot: ent_scene_axis,
 *   ent_scene_control_points, ent_scene_stats, ent_scene_effect_stats, the contacts
 *   (ent_scene_contacts, ent_scene_contact_summary), each tool's output
 *   (ent_tool_read_feedback, ent_tool_wrench, ent_tool_state, ent_tool_read_contacts),
 *   each obstacle's pose (ent_obstacle_pose, ent_scene_obstacle_count) and the exposure of a
 *   target (ent_scene_exposure; one thread at a time per ent_exposure). A snapshot is an
 *   immutable copy of the state made at creation, after each driving call and at the end
 *   of every step (a step that fails publishes the same state with its work counters).
 *   Any number of threads may query at the same time as each other and as the step; each
 *   query sees one whole snapshot, never a mix of two, and snapshots seen by one thread
 *   never go back in the order they were published (a restore publishes an earlier
 *   instant as a new snapshot: its time and step count go back). A query pins a snapshot only while it copies from it, and the
 *   stepping thread never waits for a copy: it publishes into a free slot of a small pool
 *   (8 slots; with up to 7 queries running at once every step is published, beyond that a
 *   publication may be skipped and the next one goes through).
 * - A skin is used by one thread at a time (its own lock, or one skin per thread): a call
 *   on a skin made while another runs on the same skin on another thread returns
 *   ENT_ERROR_BUSY and does nothing. It reads the snapshots like a query, so it never waits
 *   for the step either.
 * - Lifetimes: a scene (or skin) must not be used after its destroy call returned: a call
 *   begun after it is the caller's bug, as in any C API (the handle may be gone). A destroy
 *   that races with calls already running on other threads is safe: those calls finish (or
 *   fail with a status) and the last of them to return releases the memory, on its thread
 *   (through the scene's release callback, if any; keep the callbacks' user_data valid
 *   until then). The check costs each call two atomic operations; the step still
 *   allocates nothing and makes no system call. A skin may outlive its scene: it shares
 *   the published snapshots and keeps working on the last state the scene published. A
 *   skin's mesh view is valid until that skin's next update or destroy.
 * - Different scenes are independent; the calls that take no scene (ent_version,
 *   ent_status_string, ent_last_error, ent_effect_name, the _init/_default functions)
 *   are safe from any thread. ent_last_error is per thread. Callbacks run on the thread
 *   of the call that triggers them.
 * docs/c-api.md tells the same with the three threads of a simulator as an example.
 *
 * The library never prints, never aborts and never exits. It logs only through the
 * optional callback given in ent_callbacks.
 *
 * Typical use:
 * @code
 *   ent_scene* scene = NULL;
 *   if (ent_scene_create_json(json, strlen(json), &scene) != ENT_OK) {
 *       fprintf(stderr, "enteron: %s\n", ent_last_error());
 *       return 1;
 *   }
 *   for (int i = 0; i < 1000; ++i) ent_scene_step(scene, 0.001);
 *   double axis[100 * 3];
 *   ent_scene_axis(scene, 100, axis);
 *   ent_scene_destroy(scene);
 * @endcode
 */
#ifndef ENTERON_ENTERON_H
#define ENTERON_ENTERON_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#  if defined(ENTERON_BUILDING_LIBRARY)
#    define ENT_API __declspec(dllexport)
#  else
#    define ENT_API __declspec(dllimport)
#  endif
#else
#  define ENT_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------------------ */
/* Version                                                                              */
/* ------------------------------------------------------------------------------------ */

#define ENT_VERSION_MAJOR 0
#define ENT_VERSION_MINOR 1
#define ENT_VERSION_PATCH 0
/** The version this header describes: (major << 16) | (minor << 8) | patch. */
#define ENT_VERSION ((ENT_VERSION_MAJOR << 16) | (ENT_VERSION_MINOR << 8) | ENT_VERSION_PATCH)

/**
 * The version of the library actually loaded, packed like ENT_VERSION. Compare its major
 * part with ENT_VERSION_MAJOR at start-up: a different major version is not compatible.
 * Thread-safe; never fails.
 */
ENT_API uint32_t ent_version(void);

/* ------------------------------------------------------------------------------------ */
/* Status and errors                                                                    */
/* ------------------------------------------------------------------------------------ */

/** The result of every call that can fail. ENT_OK is 0; the others are ENT_ERROR_*. */
typedef int32_t ent_status;

#define ENT_OK 0
/** A NULL handle or pointer, a non-finite number, or a value out of its range. */
#define ENT_ERROR_INVALID_ARGUMENT 1
/** A struct_size this library does not know: zero, garbage, or from a newer header. */
#define ENT_ERROR_VERSION 2
/** The JSON text is not well-formed JSON. */
#define ENT_ERROR_PARSE 3
/** The scene description is well-formed but wrong: unknown key, wrong type, bad value. */
#define ENT_ERROR_INVALID_SCENE 4
/** The step could not be made stable even with subdivided substeps; nothing changed. */
#define ENT_ERROR_UNSTABLE 5
/** An allocation failed (or the allocator callback returned NULL). */
#define ENT_ERROR_OUT_OF_MEMORY 6
/** An id (tool, effect) that does not exist in this scene. */
#define ENT_ERROR_NOT_FOUND 7
/** The caller's buffer is smaller than the data; the needed size is reported. */
#define ENT_ERROR_BUFFER_TOO_SMALL 8
/** A bug in the library. Please report it with the message of ent_last_error(). */
#define ENT_ERROR_INTERNAL 9
/** Another driving call (step, add obstacle, add tool) is running on this scene on another
 *  thread, or another call on this skin (ent_skin_update, _mesh, _metrics); nothing was
 *  done. Added in 0.1 after the first tools. */
#define ENT_ERROR_BUSY 10

/**
 * A short constant English text for a status ("ok", "invalid argument", ...). Unknown codes
 * give "unknown status". The string is owned by the library and lives forever.
 */
ENT_API const char* ent_status_string(ent_status status);

/**
 * The message of the last failing call made on the calling thread, naming the bad input
 * ("intestine.radius must be > 0, got -1"), or "" if no call has failed on this thread.
 * Owned by the library; valid until the next failing call on this thread.
 */
ENT_API const char* ent_last_error(void);

/* ------------------------------------------------------------------------------------ */
/* Callbacks                                                                            */
/* ------------------------------------------------------------------------------------ */

#define ENT_LOG_DEBUG 0
#define ENT_LOG_INFO 1
#define ENT_LOG_WARNING 2
#define ENT_LOG_ERROR 3

/**
 * Optional per-scene hooks. With none given the library is silent and allocates with
 * malloc/free. The callbacks are called on the thread that makes the call which logs or
 * allocates; they must not call back into the scene. No reference to this struct is kept,
 * but the function pointers and user_data must stay valid until the scene and all its
 * skins are destroyed (the snapshots that skins share come from the allocator).
 */
typedef struct ent_callbacks {
    uint32_t struct_size; /**< sizeof(ent_callbacks); set by ent_callbacks_default. */
    /** Receives log lines (level ENT_LOG_*); NULL for silence. message is valid only during the call. */
    void (*log)(void* user_data, int32_t level, const char* message);
    /** Allocates size bytes aligned to alignment (a power of two); NULL on failure. Both or neither of allocate/release. */
    void* (*allocate)(void* user_data, size_t size, size_t alignment);
    /** Releases memory from allocate; size and alignment are those given to allocate. */
    void (*release)(void* user_data, void* memory, size_t size, size_t alignment);
    /** Passed unchanged to every callback. */
    void* user_data;
} ent_callbacks;

/**
 * Fills the first struct_size bytes of *callbacks with no hooks (silent, malloc/free) and
 * sets callbacks->struct_size to struct_size; nothing past struct_size is written. Call it
 * through ent_callbacks_default, which passes the size from the header the program was
 * compiled with, so a program built against an older header never has its smaller struct
 * overrun by a newer library.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (callbacks NULL); ENT_ERROR_VERSION (a size
 *         no release of ent_callbacks has; nothing written).
 */
ENT_API ent_status ent_callbacks_init(ent_callbacks* callbacks, uint32_t struct_size);

/** Fills *callbacks with no hooks (silent, malloc/free) and sets struct_size. NULL is ignored. */
#define ent_callbacks_default(callbacks) \
    ((void)ent_callbacks_init((callbacks), (uint32_t)sizeof(ent_callbacks)))

/* ------------------------------------------------------------------------------------ */
/* Scene description                                                                    */
/* ------------------------------------------------------------------------------------ */

/**
 * Effects a scene may simulate. A scene runs only the effects it names; an effect it does
 * not name is never allocated and costs nothing (its ent_effect_stats show zero calls).
 * Passed as int32_t; new effects are only ever added at the end.
 */
#define ENT_EFFECT_STRETCH 0        /**< axial elasticity (stiff), intestine stretch_stiffness */
#define ENT_EFFECT_BEND 1           /**< bending elasticity (soft), intestine bend_stiffness */
#define ENT_EFFECT_DAMPING 2        /**< drag and internal damping */
#define ENT_EFFECT_GRAVITY 3        /**< uniform gravity */
#define ENT_EFFECT_MESENTERY 4      /**< tension-only springs to the mesenteric root */
#define ENT_EFFECT_PINNED 5         /**< control points held fixed in space */
#define ENT_EFFECT_ENVIRONMENT 6    /**< contact with the cavity and organs (on with the first obstacle) */
#define ENT_EFFECT_SELF_COLLISION 7 /**< folds of the bowel that touch push apart */
#define ENT_EFFECT_TOOLS 8          /**< contact and grasp of surgical tools (on with the first tool) */
#define ENT_EFFECT_COUNT 9          /**< number of effects this header knows */
/** The bit of an effect in ent_scene_desc.effects. */
#define ENT_EFFECT_BIT(effect) (1u << (effect))

/** Initial shape of the intestine axis (ent_scene_desc.shape). */
#define ENT_SHAPE_LINE 0        /**< straight, from shape_center_m along shape_direction */
#define ENT_SHAPE_SERPENTINE 1  /**< horizontal back-and-forth legs centred on shape_center_m */
#define ENT_SHAPE_HELIX 2       /**< vertical helix rising from shape_center_m */
#define ENT_SHAPE_POINTS 3      /**< the control points given in shape_points_xyz_m */

/** Time integrator (ent_scene_desc.integrator). */
#define ENT_INTEGRATOR_RK4 0              /**< classic 4th-order Runge-Kutta, explicit */
#define ENT_INTEGRATOR_SYMPLECTIC_EULER 1 /**< semi-implicit Euler, explicit, 1st order */
#define ENT_INTEGRATOR_IMPLICIT_EULER 2   /**< linearised backward Euler, banded solve */
#define ENT_INTEGRATOR_BDF2 3             /**< linearised BDF2, banded solve, 2nd order (docs/accuracy.md) */

/** Which ends are held fixed (ent_scene_desc.pinned_ends) or clamped (ent_scene_desc.clamped_ends). */
#define ENT_PIN_NONE 0
#define ENT_PIN_FIRST 1
#define ENT_PIN_LAST 2
#define ENT_PIN_BOTH 3

/**
 * Everything needed to create a scene from C. Fill it with ent_scene_desc_default, change
 * what you need, then call ent_scene_create. No reference to it (or to the arrays it points
 * to) is kept after the call. The JSON description (ent_scene_create_json) offers the same
 * settings with the same defaults (one set: an elastic bowel; C also turns on gravity and
 * damping); docs/scene-json.md documents both, key by key, with the plausible range of
 * each value.
 */
typedef struct ent_scene_desc {
    uint32_t struct_size; /**< sizeof(ent_scene_desc); set by ent_scene_desc_default. */
    /** The effects to simulate: OR of ENT_EFFECT_BIT(ENT_EFFECT_*). Default: stretch, bend, damping, gravity. */
    uint32_t effects;

    /* The intestine */
    double length_m;                    /**< rest length of the axis, m (default 6). A points shape with length_m 0
                                             takes the length of the spline through its points, so that it starts at
                                             rest; a length given that differs from that one by more than 1 % is used,
                                             and logged as a warning (the bowel starts stretched or compressed). */
    double radius_m;                    /**< tube radius R, m (default 0.0125). */
    uint32_t control_points;            /**< spline control points, >= 4 (default 240). */
    double linear_density_kg_per_m;     /**< mass per unit length, kg/m (default 0.3). */
    double stretch_stiffness_N;         /**< axial stiffness EA, N (default 100). */
    double bend_stiffness_N_m2;         /**< bending stiffness EI, N m^2 (default 2.5e-3). */

    /* Initial shape; control points are spaced evenly along it, the axis starts at rest. */
    int32_t shape;                      /**< ENT_SHAPE_* (default ENT_SHAPE_HELIX). */
    double shape_center_m[3];           /**< line: start point; serpentine: centre; helix: centre of its base (default 0,0,0). */
    double shape_direction[3];          /**< line: direction, normalised by the library (default +x). */
    double shape_leg_length_m;          /**< serpentine: length of each straight leg, m (default 0.3). */
    double shape_leg_spacing_m;         /**< serpentine: distance between legs, m, >= 2 R (default 0.05). */
    double shape_helix_radius_m;        /**< helix: radius, m (default 0.1). */
    double shape_helix_pitch_m;         /**< helix: rise per turn, m, >= 2 R (default 0.03). */
    const double* shape_points_xyz_m;   /**< points: control_points x 3 coordinates, m (the library reads exactly
                                             that many: a binding fills both from one array). */

    /* Solver */
    int32_t integrator;                 /**< ENT_INTEGRATOR_* (default implicit Euler). */
    double timestep_s;                  /**< largest internal substep h, s (default 0.001). */
    uint32_t max_substeps;              /**< most substeps one ent_scene_step may take (default 1000). */
    uint32_t max_subdivisions;          /**< times the guard may halve the substep before giving up (default 4). */
    double max_speed_m_per_s;           /**< the guard treats a faster control point as an explosion (default 50). */

    /* ENT_EFFECT_GRAVITY */
    double gravity_m_per_s2[3];         /**< (default 0, 0, -9.81). */

    /* ENT_EFFECT_DAMPING */
    double drag_N_s_per_m2;             /**< drag per metre of axis per m/s of speed (default 0.05). */
    double stretch_damping_N_s;         /**< axial force per unit strain rate (default 0.05). */
    double bend_damping_N_m2_s;         /**< bending moment per unit curvature rate (default 0). */

    /* ENT_EFFECT_MESENTERY: tension-only springs from the axis to a root segment. */
    double mesentery_root_start_m[3];   /**< first end of the root line (default -0.075, 0, 0). */
    double mesentery_root_end_m[3];     /**< second end of the root line (default 0.075, 0, 0). */
    uint32_t mesentery_attachments;     /**< springs, spread evenly along the axis (default 60). */
    double mesentery_stiffness_N_per_m; /**< stiffness of each spring (default 5). */
    double mesentery_rest_length_m;     /**< slack length of every spring; 0: each spring's initial length (default 0). */

    /* ENT_EFFECT_PINNED: control points held at their initial position. */
    int32_t pinned_ends;                /**< ENT_PIN_* (default ENT_PIN_NONE). */
    const uint32_t* pinned_points;      /**< further control point indices to hold (may be NULL). */
    uint32_t pinned_point_count;        /**< entries in pinned_points. */

    /** Optional log and allocator hooks; NULL: silent, malloc/free. */
    const ent_callbacks* callbacks;

    /* Collision: spheres of radius R along the axis and the penalty contact law that every
       contact of the bowel uses: the environment, the self-contact and the tools. */
    double collision_sphere_spacing_m;  /**< sphere spacing along the axis at rest, m, <= R; 0: R / 2 (default 0). */
    double contact_stiffness_N_per_m;   /**< normal stiffness of one sphere's contact (default 500). */
    double contact_damping_N_s_per_m;   /**< normal damping, only while approaching, fading in over the first R/10 of penetration (default 0.5). */
    double contact_friction;            /**< Coulomb friction coefficient (default 0.3). */
    double contact_slip_speed_m_per_s;  /**< friction is viscous below about this sliding speed (default 0.01). */

    /** ENT_EFFECT_PINNED: ENT_PIN_* ends clamped: held at their initial position AND their
     *  tangent held in its initial direction, as where the bowel joins fixed anatomy (default
     *  ENT_PIN_NONE). A boundary condition of the axis (docs/architecture.md), not a second
     *  pinned point; ENT_PIN_BOTH needs >= 6 control points; control points 1, 2 (n-2, n-3)
     *  of a clamped end may not be in pinned_points. Added in 0.1 after the first scenes: a
     *  caller built against the older, smaller ent_scene_desc gets ENT_PIN_NONE. */
    int32_t clamped_ends;

    /* Properties along the length, each in place of its constant (docs/scene-json.md,
       intestine.radius_profile): `count` pairs (s, value) in 2 x count doubles, s the arc
       length from the first end at rest (m), strictly increasing, the first <= 0 and the last
       >= the length (a points shape's length: the spline's), each value > 0, piecewise linear
       between them. NULL and 0: the constant. A profile given with its constant changed from
       its default is refused (give one), as is one whose effect is off (its bit clear); the
       constant then reads back (ent_scene_read_desc) as the profile's largest value, and the
       arrays as NULL and 0. Added in 0.1 with the profiles: an older, smaller ent_scene_desc has none. */
    const double* radius_profile_m;                 /**< pairs (s m, radius m): the tube's radius R(s). */
    uint32_t radius_profile_count;                  /**< pairs in radius_profile_m. */
    const double* linear_density_profile_kg_per_m;  /**< pairs (s m, mass per metre kg/m). */
    uint32_t linear_density_profile_count;          /**< pairs in linear_density_profile_kg_per_m. */
    const double* stretch_stiffness_profile_N;      /**< pairs (s m, EA N); ENT_EFFECT_STRETCH. */
    uint32_t stretch_stiffness_profile_count;       /**< pairs in stretch_stiffness_profile_N. */
    const double* bend_stiffness_profile_N_m2;      /**< pairs (s m, EI N m^2); ENT_EFFECT_BEND. */
    uint32_t bend_stiffness_profile_count;          /**< pairs in bend_stiffness_profile_N_m2. */

    /* The fan mesentery and pinned spans (docs/scene-json.md, mesentery and pinned.spans;
       docs/anatomy.md). Arrays read at ent_scene_create, not kept; NULL and 0: not given.
       Added in 0.1 with the fan mesentery: an older, smaller ent_scene_desc has none. */
    /** ENT_EFFECT_MESENTERY: the root as a polyline of mesentery_root_point_count >= 2 points
     *  (3 finite doubles each, m; consecutive points apart when more than 2), in place of
     *  mesentery_root_start_m and mesentery_root_end_m, which must then keep their defaults
     *  (they read back, ent_scene_read_desc, as the polyline's ends, and this as NULL, 0). The
     *  attachment at fraction f of the bowel's rest length is tied to the point at fraction f
     *  of the polyline's length (or as mesentery_root_mapping says). */
    const double* mesentery_root_points_m;
    uint32_t mesentery_root_point_count;  /**< points in mesentery_root_points_m. */
    /** ENT_EFFECT_MESENTERY: where along the root each attachment is tied: count pairs
     *  (s, t) in 2 x count doubles, s the arc length along the bowel from its first end at
     *  rest (m, strictly increasing), t the fraction of the root's length (0..1, never
     *  decreasing), piecewise linear between pairs and held past the first and last. NULL
     *  and 0: t = s / length_m. */
    const double* mesentery_root_mapping;
    uint32_t mesentery_root_mapping_count;  /**< pairs in mesentery_root_mapping. */
    /** ENT_EFFECT_PINNED: spans of the bowel held in the world where they start: count pairs
     *  (from, to) in 2 x count doubles, m of arc length from the first end at rest,
     *  0 <= from <= to <= length_m; every control point whose rest arc length lies in a span
     *  is pinned (at least one per span; none a control point a clamped end moves). A span on
     *  an obstacle: the JSON pinned.spans, or ent_scene_pin_point per point after
     *  ent_scene_add_obstacle. */
    const double* pinned_spans_m;
    uint32_t pinned_span_count;  /**< pairs in pinned_spans_m. */
} ent_scene_desc;

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size to struct_size; nothing past struct_size is written. Call it through
 * ent_scene_desc_default, which passes the size from the header the program was compiled
 * with: a program built against an older header gets its older, smaller struct filled
 * (never overrun), and the library serves the fields it lacks with their defaults.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (a size no
 *         release of ent_scene_desc has; nothing written).
 */
ENT_API ent_status ent_scene_desc_init(ent_scene_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_scene_desc_default(desc) \
    ((void)ent_scene_desc_init((desc), (uint32_t)sizeof(ent_scene_desc)))

/* ------------------------------------------------------------------------------------ */
/* Scene                                                                                */
/* ------------------------------------------------------------------------------------ */

/** A simulated intestine and its surroundings. Opaque; made by ent_scene_create*. */
typedef struct ent_scene ent_scene;

/**
 * Creates a scene from a C description. The axis starts at rest in the initial shape and
 * the state is published at once, so the queries work before the first step.
 * A value far outside what a human abdomen has (gravity of 9810 m/s^2, a 150 m cavity, a
 * density a thousand times too large; the ranges are in docs/scene-json.md) is accepted,
 * with a warning through the log callback that names the field and the likely unit mistake.
 * @param desc filled by ent_scene_desc_default first; not retained.
 * @param out_scene receives the new scene; untouched on failure.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, bad value: the message names the
 *         field; where two fields disagree it names the one that differs from its default),
 *         ENT_ERROR_VERSION (struct_size not known), ENT_ERROR_OUT_OF_MEMORY.
 */
ENT_API ent_status ent_scene_create(const ent_scene_desc* desc, ent_scene** out_scene);

/**
 * Creates a scene from a JSON description (format v1, documented key by key in
 * docs/scene-json.md). Effects are opt-in: a key that is absent is an effect that does not
 * run; the bowel itself is elastic unless its stiffnesses are 0. A scene that cannot start
 * is refused: a control point beyond an obstacle's surface (outside the box_inside, inside
 * an organ) gives ENT_ERROR_INVALID_SCENE naming the obstacle and the control points.
 * Implausible values are warned about as in ent_scene_create.
 * @param json UTF-8 text, not necessarily NUL-terminated; @param length its bytes.
 * @return ENT_OK; ENT_ERROR_PARSE (not JSON: the message gives the byte offset);
 *         ENT_ERROR_INVALID_SCENE (unknown key, wrong type or bad value: the message names
 *         the path, e.g. "intestine.radius must be > 0, got -1"); ENT_ERROR_INVALID_ARGUMENT;
 *         ENT_ERROR_OUT_OF_MEMORY.
 */
ENT_API ent_status ent_scene_create_json(const char* json, size_t length, ent_scene** out_scene);

/** Like ent_scene_create_json, with log and allocator hooks (callbacks may be NULL). */
ENT_API ent_status ent_scene_create_json_with(const char* json, size_t length,
                                              const ent_callbacks* callbacks,
                                              ent_scene** out_scene);

/**
 * Creates a scene from a JSON description in a file: like ent_scene_create_json_with, and a
 * mesh obstacle's "file" is found relative to this file's directory (with
 * ent_scene_create_json*, relative to the process's current directory). Reading the mesh
 * files and preparing their distance fields takes time (docs/anatomy.md): not on a
 * real-time thread.
 * @param path the scene file (UTF-8, NUL-terminated); @param callbacks may be NULL.
 * @return as ent_scene_create_json; ENT_ERROR_INVALID_ARGUMENT also when the file cannot
 *         be read (the message names it); ENT_ERROR_INVALID_SCENE for a mesh file that is
 *         missing or not a mesh (the message names the obstacle and the file).
 */
ENT_API ent_status ent_scene_create_json_file(const char* path, const ent_callbacks* callbacks,
                                              ent_scene** out_scene);

/**
 * The description the scene was created from, as an ent_scene_desc, whether it came from C
 * or from JSON (docs/scene-json.md gives each key's C field): its values, in `effects` the
 * effects it turned on (a stiffness of 0 reads back with its bit clear), and for an effect
 * it left off the defaults. The arrays are not kept: shape_points_xyz_m, pinned_points,
 * mesentery_root_points_m (the root's ends read back in mesentery_root_start_m and
 * mesentery_root_end_m), mesentery_root_mapping and pinned_spans_m are NULL and their counts
 * 0 (ent_scene_control_points gives the points), callbacks NULL. What changed since (ent_scene_set_gravity, obstacles, tools, pins, a mesentery or a
 * clamped end attached) and what only JSON describes (its obstacles, tools, attached pins)
 * are not in it. So for a scene without arrays, ent_scene_create of what this gives makes
 * the same scene. Set out->struct_size first (ent_scene_desc_default does); fields beyond
 * an older, smaller struct_size are not written.
 * Any thread, any time (the description never changes); never waits; allocates nothing.
 * @code
 *   ent_scene_desc desc;
 *   ent_scene_desc_default(&desc);
 *   if (ent_scene_read_desc(scene, &desc) == ENT_OK) printf("R = %g m\n", desc.radius_m);
 * @endcode
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, destroyed scene); ENT_ERROR_VERSION
 *         (struct_size not known); *out untouched on failure.
 */
ENT_API ent_status ent_scene_read_desc(const ent_scene* scene, ent_scene_desc* out);

/**
 * Destroys a scene and everything it owns. NULL is ignored. Its skins stay valid: they keep
 * the last published state (and its memory) until they are destroyed too.
 * Calls on this scene already running on other threads when it is called (a step, a
 * query, a tool command) finish, or fail with a status; the scene's memory is then
 * released by the last of them as it returns, on that thread. It never waits for them.
 * A call begun after this one returned is the caller's bug: the handle may be gone (while
 * a skin or a call in flight still holds it, such a call gets ENT_ERROR_INVALID_ARGUMENT,
 * "scene was destroyed"). A second destroy of a scene whose skins keep its handle does
 * nothing.
 * @warning Stop your other threads' calls on the scene before destroying it; the library
 *          only makes the race harmless, it cannot make a later call valid.
 */
ENT_API void ent_scene_destroy(ent_scene* scene);

/**
 * Advances the simulation by dt_s seconds, in equal substeps no longer than the scene's
 * timestep (and, for explicit integrators, no longer than their stability limit), then
 * publishes the new state. It first takes the tools' commands (ent_tool_set_pose, _grasp,
 * _release). A stability guard checks the result (finite, speeds below max_speed, no
 * energy from nothing); when the check fails it rolls back and retries with halved
 * substeps, up to max_subdivisions times.
 * Allocates nothing after the first step and makes no system call.
 * Time: a step that succeeds at once costs n = ceil(dt_s / substep) substeps: a plain step.
 * The most work one step can do (docs/performance.md, "The worst case") is bounded by two
 * budgets, whatever the scene does:
 *   - the guard's subdivisions: at most 1 + max_subdivisions attempts, so at most
 *     (2^(max_subdivisions + 1) - 1) n substeps in all, 31 plain steps with the default 4
 *     (an attempt stops at its first rejected substep), plus, when every attempt fails, one
 *     evaluation of each effect to name the cause. Out of attempts, the step is refused
 *     with the state exactly as before (ENT_ERROR_UNSTABLE). max_subdivisions 0 bounds a
 *     step to one plain step, refusing any the guard rejects.
 *   - each proxy tool's solve, at every evaluation of a substep: at most 64 Newton
 *     iterations with at most 10 halvings of each one's line search, 769 evaluations of its
 *     balance (warm started it takes 3 to 7 iterations), twice when its grasp slips. Out of
 *     iterations, the proxy rests where the last one left it: on the bowel, never through
 *     it (every move stops at the first sphere it meets), its force within max_force,
 *     balanced with the bowel in an implicit step (its contacts scaled to max_force in an
 *     explicit one).
 * ent_stats says when a step took more than one attempt (last_step_attempts,
 * subdivided_steps) and when a proxy ran out (proxy_unbalanced_solves).
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, dt not finite or <= 0, or dt needing
 *         more than max_substeps substeps; nothing changes); ENT_ERROR_BUSY (another
 *         driving call is running; nothing changes); ENT_ERROR_UNSTABLE (the guard could
 *         not recover: positions, velocities, time and step count are exactly as before
 *         the call; substeps, rollbacks and effect times record the attempt; the message
 *         names the check that failed, non-finite, speed or energy, by how much, the
 *         control point and the effect that drove it).
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_scene_step(ent_scene* scene, double dt_s);

/**
 * Copies count points of the axis, evenly spaced in arc length from the first end to the
 * last, into points_xyz_m (count x 3 doubles, x y z per point, m). count >= 2.
 * In a scene of several intestines, the first one's (intestine 0: ent_scene_intestine_axis
 * reads any).
 * Reads the last published state: safe from any thread; allocates nothing.
 */
ENT_API ent_status ent_scene_axis(const ent_scene* scene, uint32_t count, double* points_xyz_m);

/**
 * Copies the control points (x y z each, m) of the last published state. *out_count
 * receives their number. With points_xyz_m NULL (and any capacity) only the count is
 * reported. A capacity (in points) below the count gives ENT_ERROR_BUFFER_TOO_SMALL,
 * with *out_count set and nothing copied. Safe from any thread.
 * In a scene of several intestines, the first one's points (intestine 0).
 */
ENT_API ent_status ent_scene_control_points(const ent_scene* scene, uint32_t capacity,
                                            double* points_xyz_m, uint32_t* out_count);

/**
 * The number of intestines (tubes) of the scene into *count: 1 for a scene of one
 * intestine, each its own axis, numbered from 0 in the order the description gives them.
 * Fixed for the scene's life.
 * Safe from any thread, at any time between create and destroy (two callers get the same
 * count); allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (scene or count NULL; *count untouched).
 */
ENT_API ent_status ent_scene_intestine_count(const ent_scene* scene, int32_t* count);

/**
 * Copies count points of intestine `intestine`'s axis (0 <= intestine <
 * ent_scene_intestine_count), evenly spaced in arc length from its first end to its last,
 * into points_xyz_m (count x 3 doubles, x y z per point, m). 2 <= count <= 4294967295.
 * Intestine 0 gives exactly what ent_scene_axis gives.
 * Reads the last published state, as ent_scene_axis: safe from any thread, concurrently with
 * the step and other readers (each reader copies one published state whole; two callers may
 * see two successive states); allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (scene or points_xyz_m NULL, intestine out of
 *         range, count out of range; nothing written).
 */
ENT_API ent_status ent_scene_intestine_axis(const ent_scene* scene, int32_t intestine, size_t count,
                                            double* points_xyz_m);

/**
 * Counters and energies of the last published state.
 *
 * The fields from last_step_attempts on tell what a slow step did, so that a simulator can
 * see in the field what `enteron_tail_bench` shows on a bench (docs/performance.md, "The
 * tail"): read them after a step whose last_step_ns was long. A step's wall time grows with
 * its attempts (each rejected attempt is redone with twice the substeps), its substeps, its
 * contacts and its tool proxies' iterations; a step that did no more work than its
 * neighbours but took longer was held up by the machine (preempted, a page fault): the
 * library makes no system call in a step, so it cannot see those itself. These fields
 * describe this scene's run, not its state: ent_scene_save_state does not save them and
 * ent_scene_restore_state leaves them as they were, except full_contact_searches, which
 * takes the saved scene's count (the search it counts belongs to the saved state: a
 * restored scene searches when the saved one would have).
 */
typedef struct ent_stats {
    uint32_t struct_size;          /**< set by the caller to sizeof(ent_stats). */
    uint32_t control_points;       /**< number of control points. */
    double time_s;                 /**< simulated time. */
    uint64_t steps;                /**< successful ent_scene_step calls. */
    uint64_t substeps;             /**< substeps taken by those steps (retries included). */
    uint64_t rollbacks;            /**< attempts the guard rejected and rolled back (a step that then fails counts max_subdivisions + 1). */
    double kinetic_energy_J;       /**< of the axis. */
    double potential_energy_J;     /**< elastic + gravity (zero at the origin) + springs + contacts. */
    uint32_t contacts;             /**< contacts in the last substep. */
    double max_penetration_m;      /**< deepest contact in the last substep. */
    uint64_t last_step_ns;         /**< wall time of the last ent_scene_step. */
    /* Appended later: an older struct ends at last_step_ns (see ent_scene_stats). */
    uint32_t last_step_attempts;   /**< attempts of the last ent_scene_step: 1, or 1 + the subdivisions the guard made (max_subdivisions + 1 for a step that failed); 0 before the first step. */
    uint32_t last_step_substeps;   /**< substeps the last step integrated, its rejected attempts' included. */
    uint32_t last_step_proxy_iterations;  /**< the most Newton iterations one tool proxy's solve took in the last step (at most 64; 0 without a proxy in contact or moving). */
    uint32_t last_step_proxy_evaluations; /**< the proxies' force balances evaluated in the last step, all tools and solves (each iteration, each halving of its line search): their work. */
    uint64_t max_step_ns;          /**< wall time of the longest ent_scene_step so far. */
    uint64_t late_steps;           /**< steps (failed ones too) whose wall time exceeded the dt_s they simulated: slower than real time. */
    uint64_t subdivided_steps;     /**< successful steps that took more than one attempt. */
    uint64_t proxy_unbalanced_solves; /**< tool proxy solves that ran out of iterations before their forces balanced (the proxy then rests where the last iteration left it). */
    uint64_t full_contact_searches;   /**< self-contact searches that listed the near pairs of every collision sphere (at the first step, and when a quarter of the spheres moved R/6 since their last search); the other steps search only the spheres that moved. */
} ent_stats;

/**
 * Copies the stats of the last published state into *out. Set out->struct_size first;
 * fields beyond an older, smaller struct_size are not written (older headers end it at
 * last_step_ns, or before it). Safe from any thread.
 */
ENT_API ent_status ent_scene_stats(const ent_scene* scene, ent_stats* out);

/** What one effect cost so far. */
typedef struct ent_effect_stats {
    uint32_t struct_size;   /**< set by the caller to sizeof(ent_effect_stats). */
    int32_t enabled;        /**< 1 if the scene simulates this effect, else 0. */
    uint64_t calls;         /**< evaluations (an RK4 substep evaluates 4 times). */
    uint64_t total_time_ns; /**< wall time spent in those evaluations. */
} ent_effect_stats;

/**
 * Reports the cost of one effect (ENT_EFFECT_*) as of the last published state. An effect
 * the scene does not name reports enabled 0, calls 0, time 0. An effect number this
 * library does not know gives ENT_ERROR_NOT_FOUND. Safe from any thread.
 */
ENT_API ent_status ent_scene_effect_stats(const ent_scene* scene, int32_t effect,
                                          ent_effect_stats* out);

/** The JSON-style name of an effect ("stretch", "gravity", ...), or NULL if unknown. */
ENT_API const char* ent_effect_name(int32_t effect);

/**
 * Saves the whole state of the scene into buffer: a versioned, self-describing binary image
 * (docs/scoring-and-state.md lays it out) of everything its future depends on: the control
 * points' positions and velocities, the time, the integrator's history, each effect's state
 * (the tools' poses, grasps and contact impulses; the self-contact's near pairs, which a
 * restored scene must search in the same order), the counters of ent_stats and
 * ent_effect_stats, and what the last step published (contacts, tool feedback). A scene
 * restored from it (ent_scene_restore_state) continues bit-identically to this one.
 * Commands posted to the tools' mailboxes and not yet taken are not part of it.
 * @code
 *   size_t size = 0;
 *   ent_scene_save_state(scene, NULL, 0, &size);       // how much room it needs now
 *   void* saved = malloc(2 * size);                     // the size varies with the contacts
 *   ent_scene_save_state(scene, saved, 2 * size, &size);
 *   ...
 *   ent_scene_restore_state(scene, saved, size);        // back to that instant
 * @endcode
 * @param buffer where to write the state; NULL: only *out_size is set.
 * @param capacity bytes that buffer holds.
 * @param out_size receives the size of the state, bytes (also on ENT_ERROR_BUFFER_TOO_SMALL).
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (scene or out_size NULL); ENT_ERROR_BUFFER_TOO_SMALL
 *         (capacity below the size: *out_size set, nothing written); ENT_ERROR_BUSY.
 * Allocates nothing; the scene does not change.
 * @warning A driving call: one at a time per scene (it reads the live state, not a snapshot).
 */
ENT_API ent_status ent_scene_save_state(ent_scene* scene, void* buffer, size_t capacity, size_t* out_size);

/**
 * Restores a state saved by ent_scene_save_state, into the scene it was saved from or into
 * another made from the same description (the same JSON or ent_scene_desc, and the same
 * obstacles and tools added in the same order), and publishes it: the queries and skins
 * see the saved instant at once, and the next ent_scene_step continues from it exactly as
 * the saved scene did (bit-identical, given the same calls). It also gets a scene out of a
 * state that keeps failing with ENT_ERROR_UNSTABLE. Tool commands posted and not yet taken
 * stay posted: the next step takes them.
 * The whole image is checked before anything changes: its format and version, that it was
 * saved from a scene with this one's description (a fingerprint), its size and checksum,
 * and every value (finite positions, velocities, time, poses; indices in range).
 * Allocates a little work space for that check.
 * @param buffer the image, size bytes; not retained.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, not a saved state, truncated or changed
 *         data, saved from another scene, a bad value: the message names it; nothing
 *         changes); ENT_ERROR_VERSION (saved by a newer library with a format this one does
 *         not read; nothing changes); ENT_ERROR_BUSY; ENT_ERROR_OUT_OF_MEMORY.
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_scene_restore_state(ent_scene* scene, const void* buffer, size_t size);

/* ------------------------------------------------------------------------------------ */
/* Environment: the abdominal cavity and other organs                                   */
/* ------------------------------------------------------------------------------------ */

/** Kind of a rigid obstacle (ent_obstacle_desc.kind). */
#define ENT_OBSTACLE_BOX_INSIDE 0 /**< the inside of an axis-aligned box: the abdominal cavity */
#define ENT_OBSTACLE_PLANE 1      /**< a plane; the bowel is kept on the side its normal points to */
#define ENT_OBSTACLE_SPHERE 2     /**< a solid sphere (an organ) */
#define ENT_OBSTACLE_CAPSULE 3    /**< a solid capsule: a segment swept by a sphere (an organ, a vessel) */
/** A triangle mesh (an organ segmented from CT), met through its signed distance field.
 *  Added in 0.1 with moving anatomy; docs/anatomy.md tells its accuracy and cost. */
#define ENT_OBSTACLE_MESH 4

/** No obstacle: the world (ent_scene_pin_point, ent_scene_attach_mesentery). */
#define ENT_NO_OBSTACLE (-1)

/**
 * A rigid obstacle. Fill with ent_obstacle_desc_default first; fields a kind does not use
 * are ignored. Every obstacle has a frame (position_m, orientation_wxyz) and its shape is
 * given in that frame; the default frame is the world, so the shape is where its fields
 * say. ent_obstacle_set_pose moves the frame.
 */
typedef struct ent_obstacle_desc {
    uint32_t struct_size;      /**< sizeof(ent_obstacle_desc); set by ent_obstacle_desc_default. */
    int32_t kind;              /**< ENT_OBSTACLE_* (default ENT_OBSTACLE_BOX_INSIDE). */
    double center_m[3];        /**< box, sphere: centre; plane: a point of the plane (default 0, 0, 0). */
    double half_extents_m[3];  /**< box: half of its size along x, y, z, each > 0 (default 0.12 each). */
    double normal[3];          /**< plane: normal toward the bowel's side, normalised by the library (default 0, 0, 1). */
    double start_m[3];         /**< capsule: first end of its axis (default 0, 0, 0). */
    double end_m[3];           /**< capsule: second end of its axis (default 0, 0, 0.1). */
    double radius_m;           /**< sphere, capsule: radius, > 0 (default 0.05). */
    /* Added in 0.1 with moving anatomy: a caller built against the older, smaller struct
       gets the defaults below. */
    /** mesh: vertex_count x 3 coordinates in the obstacle's frame, m; copied (default NULL). */
    const double* mesh_vertices_xyz_m;
    uint32_t mesh_vertex_count;        /**< mesh: vertices (default 0). */
    /** mesh: triangle_count x 3 vertex indices (from 0), counter-clockwise seen from the side
     *  the bowel is kept on; copied (default NULL). A closed mesh keeps the bowel outside
     *  (normals out) or inside (normals in: a cavity); an open or non-manifold one is
     *  accepted with a warning and pushes the bowel to the side its normals face. */
    const uint32_t* mesh_triangles;
    uint32_t mesh_triangle_count;      /**< mesh: triangles, 1 to 16777216 (default 0). */
    /** mesh: edge of the distance field's voxels, m, >= 0; 0: a quarter of the bowel's
     *  radius R (default 0). Coarser costs less memory and time to prepare; above R/4 the
     *  contacts near the surface take the exact closest point (docs/anatomy.md). */
    double mesh_voxel_size_m;
    double position_m[3];              /**< origin of the obstacle's frame, m (default 0, 0, 0). */
    double orientation_wxyz[4];        /**< orientation of its frame, normalised by the library (default 1, 0, 0, 0). */
    /** Coulomb friction coefficient of this obstacle's contacts, >= 0; negative: the scene's
     *  contact_friction (default -1). */
    double friction;
} ent_obstacle_desc;

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size; nothing past struct_size is written. Call it through
 * ent_obstacle_desc_default, which passes the size of the header the program was built with.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (unknown size).
 */
ENT_API ent_status ent_obstacle_desc_init(ent_obstacle_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_obstacle_desc_default(desc) \
    ((void)ent_obstacle_desc_init((desc), (uint32_t)sizeof(ent_obstacle_desc)))

/**
 * Adds a rigid obstacle to the scene's environment. The first obstacle turns the
 * environment effect on; its contacts use the scene's collision spheres and contact law
 * (ent_scene_desc collision_* and contact_* fields, JSON "collision"), with the obstacle's
 * own friction if it has one. The JSON description lists obstacles under "environment"
 * instead. A mesh's arrays are copied and its distance field built here: about 0.5 s of CPU
 * for 100k triangles at the default resolution (docs/anatomy.md); a mesh that is not
 * closed is accepted with a warning through the log callback. Allocates; not on a hard real-time path.
 * @param out_obstacle receives the obstacle's index (0, 1, ... in order of addition; JSON
 *        obstacles come first); may be NULL.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, unknown kind, non-finite value, size
 *         <= 0, zero normal: the message names the field; an obstacle with control points
 *         of the bowel, where it is now, beyond its surface: the message names them);
 *         ENT_ERROR_VERSION; ENT_ERROR_BUSY; nothing changes on failure.
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_scene_add_obstacle(ent_scene* scene, const ent_obstacle_desc* desc, int32_t* out_obstacle);

/**
 * Moves an obstacle: its frame reaches this pose (origin, m; orientation w x y z, normalised)
 * at the end of the next ent_scene_step, moving within that step continuously (the origin
 * linearly, the orientation by normalised linear interpolation), so a moved organ pushes
 * the bowel instead of jumping through it. The contacts see the bowel's velocity relative to
 * the moving surface (the pose change over the step, or the velocity ent_obstacle_set_velocity
 * gives), so damping and friction carry the bowel. Once an obstacle has moved, each of its
 * contacts pushes with at most k R (contact_stiffness times the radius): an obstacle that
 * jumps far in one step sweeps through the bowel, or lands on it, with a bounded force, as a
 * teleported tool does (an obstacle never moved keeps the plain law). Pins and a
 * mesentery root attached to the obstacle move with it. Setting the pose again before the
 * step replaces the target.
 * Thread: the driving thread, between steps (the organ's pose comes from the loop that
 * steps: a retractor, breathing, a table tilt); no lock, allocates nothing: may be called
 * before every step at 1 kHz.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, non-finite, zero quaternion);
 *         ENT_ERROR_NOT_FOUND (no such obstacle, or removed); ENT_ERROR_BUSY.
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_obstacle_set_pose(ent_scene* scene, int32_t obstacle, const double position_m[3],
                                         const double orientation_wxyz[4]);

/**
 * Gives the velocity the obstacle's contacts see during the next step, instead of the one of
 * its motion: the origin's (m/s) and the angular velocity (rad/s, world axes); a point x
 * moves at linear + angular x (x - origin). For a surface that slides without moving (a
 * belt) or a motion known exactly. Only for the next step; its pose still follows
 * ent_obstacle_set_pose. Thread and errors: as ent_obstacle_set_pose.
 */
ENT_API ent_status ent_obstacle_set_velocity(ent_scene* scene, int32_t obstacle, const double linear_m_per_s[3],
                                             const double angular_rad_per_s[3]);

/**
 * Sets an obstacle's Coulomb friction coefficient (>= 0; negative: the scene's
 * contact_friction) from the next step on. Recomputes the stability bounds (allocates;
 * about as long as one step). Thread: the driving thread, between steps.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, NaN); ENT_ERROR_NOT_FOUND; ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_obstacle_set_friction(ent_scene* scene, int32_t obstacle, double friction);

/**
 * Removes an obstacle from the next step on and frees its memory. Its id is not reused
 * (the others keep theirs); pins and a mesentery root attached to it stay where it left
 * them. Thread: the driving thread, between steps.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (no such obstacle,
 *         or already removed); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_remove_obstacle(ent_scene* scene, int32_t obstacle);

/**
 * The number of obstacles in the last published state (removed ones not counted).
 * Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL).
 */
ENT_API ent_status ent_scene_obstacle_count(const ent_scene* scene, uint32_t* out_count);

/**
 * Where an obstacle's frame rests in the last published state (origin, m; orientation
 * w x y z): for a renderer. Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (no such obstacle,
 *         or removed).
 */
ENT_API ent_status ent_obstacle_pose(const ent_scene* scene, int32_t obstacle, double position_m[3],
                                     double orientation_wxyz[4]);

/**
 * Copies a mesh obstacle's vertices (x y z each, in its frame, m) and triangles (3 indices
 * each), as the obstacle holds them: for a renderer. Either buffer may be NULL (its count is
 * still reported); a capacity below the count gives ENT_ERROR_BUFFER_TOO_SMALL with the
 * counts set and nothing copied. Thread: the driving thread, between steps (a removal frees
 * the mesh); call it before handing the scene to a physics thread.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL counts, not a mesh); ENT_ERROR_NOT_FOUND;
 *         ENT_ERROR_BUFFER_TOO_SMALL; ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_obstacle_mesh(ent_scene* scene, int32_t obstacle, uint32_t vertex_capacity,
                                     double* vertices_xyz_m, uint32_t* out_vertex_count, uint32_t triangle_capacity,
                                     uint32_t* triangles, uint32_t* out_triangle_count);

/* ------------------------------------------------------------------------------------ */
/* Run-time changes: gravity, pins, the mesentery's root                                */
/* ------------------------------------------------------------------------------------ */

/**
 * Sets gravity (m/s^2) from the next step on: a table tilted to Trendelenburg. A scene
 * without gravity gets it (ENT_EFFECT_GRAVITY turns on; allocates once); with gravity the
 * call allocates nothing, so a table may tilt a little before every step. The stability
 * guard measures the energy again, so the change is no energy from nothing.
 * Thread: the driving thread, between steps.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, non-finite); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_set_gravity(ent_scene* scene, const double gravity_m_per_s2[3]);

/**
 * Holds a control point where it is now: in the world (obstacle ENT_NO_OBSTACLE), or on an
 * obstacle's frame, moving with it from then on (a bowel end stapled to an organ). Its
 * velocity becomes zero (or its frame's). After a jump of its obstacle it follows at up to
 * half the scene's max_speed and catches up over the next steps. Pinning a pinned point
 * again moves it to the new frame. ENT_EFFECT_PINNED turns on with the first pin.
 * Thread: the driving thread, between steps; allocates, refactors the mass matrix (about
 * as long as one step).
 * A clamped end's end point (ent_scene_desc.clamped_ends) moves with its clamp only:
 * attach it with ent_scene_attach_clamped_end.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, control_point out of range, a clamped
 *         end's end point); ENT_ERROR_NOT_FOUND (no such obstacle); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_pin_point(ent_scene* scene, uint32_t control_point, int32_t obstacle);

/**
 * Lets a pinned control point go (a surgeon frees a loop), from the next step on.
 * Refactors the mass matrix (allocates; about as long as one step).
 * Thread: the driving thread, between steps.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, out of range, a clamped end's end point,
 *         which its clamp holds); ENT_ERROR_NOT_FOUND (the point is not pinned); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_unpin_point(ent_scene* scene, uint32_t control_point);

/**
 * Attaches the mesentery's root to an obstacle's frame: from then on it moves with the
 * obstacle (the posterior wall as a mesh the simulator moves), from where it is now.
 * ENT_NO_OBSTACLE leaves it in the world where it is. Thread: the driving thread, between
 * steps.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (no mesentery, no
 *         such obstacle); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_attach_mesentery(ent_scene* scene, int32_t obstacle);

/**
 * Attaches clamped ends (ent_scene_desc.clamped_ends; ends: ENT_PIN_FIRST, ENT_PIN_LAST or
 * ENT_PIN_BOTH) to an obstacle's frame from where they are now: from then on the end point
 * and its tangent's direction move with the obstacle (the duodenojejunal flexure on an organ
 * the simulator moves); the rest of the bowel follows through the clamp. ENT_NO_OBSTACLE
 * leaves them in the world where they are. After a jump of the obstacle the end catches up
 * over the next steps, as an attached pin does (ent_scene_pin_point). JSON:
 * pinned.clamped_attached. Thread: the driving thread, between steps; allocates, refactors
 * the mass matrix (about as long as one step). While the obstacle turns, each step factors
 * the clamped mass matrix again (explicit integrators) and allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, ends not one of those three);
 *         ENT_ERROR_NOT_FOUND (an end named is not clamped, no such obstacle); ENT_ERROR_BUSY.
 */
ENT_API ent_status ent_scene_attach_clamped_end(ent_scene* scene, int32_t ends, int32_t obstacle);

/* ------------------------------------------------------------------------------------ */
/* Tools: surgical instruments that push and grasp the bowel                            */
/* ------------------------------------------------------------------------------------ */

/**
 * A surgical tool: a rigid capsule driven by the caller (a haptic device, a script). Its tip
 * is at the pose's position; its shaft runs from the tip back along the orientation's
 * local +z axis for length_m, with radius radius_m. With the identity orientation
 * (1, 0, 0, 0) the shaft rises straight up from the tip: a vertical tool pointing down.
 * A grasper may have jaws (jaw_length_m, jaw_opening_m: what its grasp takes, see
 * ent_tool_grasp) and a retractor a flat blade at its tip (blade_width_m, blade_length_m);
 * both open or widen across the tool's local x axis.
 * Fill with ent_tool_desc_default first; it is not retained.
 */
typedef struct ent_tool_desc {
    uint32_t struct_size;            /**< sizeof(ent_tool_desc); set by ent_tool_desc_default. */
    double radius_m;                 /**< shaft radius, m, > 0 and <= 1 (default 0.005). */
    double length_m;                 /**< shaft length from the tip along local +z, m, >= 0 and <= 10 (default 0.3). */
    double max_force_N;              /**< bound of the force the tool exerts and reports, N, > 0 (default 5). */
    double grasp_margin_m;           /**< grasp reach beyond touching: reach = radius_m + R + this (R the radius there), m, >= 0 and <= 1 (default 0.005). */
    double grasp_stiffness_N_per_m;  /**< stiffness of the grasp spring from the held axis point to the tip (rest length radius_m + R), > 0 (default 200). */
    double grasp_damping_N_s_per_m;  /**< damping of the grasp spring, >= 0 (default 2). */
    double position_m[3];            /**< initial tip position, m (default 0, 0, 0). */
    double orientation_wxyz[4];      /**< initial orientation, a quaternion normalised by the library (default 1, 0, 0, 0). */
    /* Later fields (an older struct_size leaves them at their defaults; docs/haptics.md): */
    int32_t mode;                    /**< ENT_TOOL_MODE_PROXY (default) or ENT_TOOL_MODE_DIRECT. */
    int32_t passivity_limiter;       /**< 1: Hannaford and Ryu's time-domain passivity controller keeps ent_tool_stats' balance >= 0; 0 (default): off. */
    double coupling_stiffness_N_per_m; /**< proxy mode: the virtual coupling's spring from the proxy to the commanded tip, > 0 (default 1000, 1 N/mm). */
    double coupling_damping_N_s_per_m; /**< proxy mode: the coupling's damper, >= 0 (default 1). */
    double friction;                 /**< Coulomb coefficient of this tool's contacts, >= 0; < 0 (default -1): the scene's (contact_friction). */
    /* Later fields (an older struct_size leaves them at their defaults: the grasp takes what lies nearest the tip): */
    double jaw_length_m;             /**< a grasper's jaws: the last jaw_length_m of the shaft, m, >= 0 and <= 1 (default 0; see ent_tool_grasp). */
    double jaw_opening_m;            /**< how wide the jaws open, across the tool's local x axis, m, >= 0 and <= 1 (default 0). */
    /** A retractor's blade: the first blade_length_m of the shaft from the tip widened to
     *  blade_width_m across the tool's local x axis, as thick as the shaft (2 radius_m): a fan
     *  or paddle retractor, which spreads its max_force_N over a loop's width. Width 0
     *  (default): no blade, the capsule of a grasper. m, >= 0 and <= 1. */
    double blade_width_m;
    double blade_length_m;           /**< the blade's length from the tip, m, >= 0 and <= 10 (beyond length_m: the whole shaft; default 0). */
} ent_tool_desc;

/**
 * How a tool meets the bowel (ent_tool_desc.mode; docs/haptics.md).
 * Proxy: the capsule in the scene is a proxy that the bowel's contacts keep out of the tube
 * (it never passes through the bowel, however fast the device moves), joined to the
 * commanded pose by a virtual coupling (a spring-damper bounded by max_force_N). The bowel
 * receives what the proxy gives it; the wrench is the coupling's. Direct: the capsule is
 * where the caller puts it and its contacts are bounded together by max_force_N (the
 * behaviour of the first tools, before the proxy: a fast or forceful tool can pass
 * through the tube).
 */
#define ENT_TOOL_MODE_PROXY 0
#define ENT_TOOL_MODE_DIRECT 1

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size; nothing past struct_size is written. Call it through
 * ent_tool_desc_default, which passes the size of the header the program was built with.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (unknown size).
 */
ENT_API ent_status ent_tool_desc_init(ent_tool_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_tool_desc_default(desc) \
    ((void)ent_tool_desc_init((desc), (uint32_t)sizeof(ent_tool_desc)))

/**
 * Adds a tool at the desc's pose. The first tool turns ENT_EFFECT_TOOLS on. Every collision
 * sphere of the bowel touching the capsule (the proxy's in proxy mode, the default: see
 * ENT_TOOL_MODE_PROXY) gets the scene's penalty contact (ent_scene_desc contact_* fields,
 * JSON "collision"; the tool's own friction if set). The JSON description lists tools under "tools"
 * instead (they come first). Allocates; not on a hard real-time path.
 * @code
 *   ent_tool_desc tool;
 *   ent_tool_desc_default(&tool);
 *   tool.position_m[2] = 0.2;
 *   int32_t id;
 *   if (ent_tool_add(scene, &tool, &id) != ENT_OK) fprintf(stderr, "%s\n", ent_last_error());
 * @endcode
 * @param out_tool receives the tool's id (0, 1, ... in order of addition); may be NULL.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, a value out of range or non-finite, a
 *         zero quaternion: the message names the field); ENT_ERROR_VERSION;
 *         ENT_ERROR_BUSY; nothing changes on failure.
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_tool_add(ent_scene* scene, const ent_tool_desc* desc, int32_t* out_tool);

/**
 * The settings a tool was added with (ent_tool_add, or the JSON "tools"), and the pose it
 * was added at, its quaternion normalised: an ent_tool_desc that ent_tool_add would take.
 * Where the tool is now: ent_tool_read_feedback. Set out->struct_size first
 * (ent_tool_desc_default does); fields beyond an older, smaller struct_size are not written.
 * Any thread, any time, also while another adds a tool or steps: never waits, allocates
 * nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size not
 *         known); ENT_ERROR_NOT_FOUND (unknown or removed tool); *out untouched on failure.
 */
ENT_API ent_status ent_tool_read_desc(const ent_scene* scene, int32_t tool, ent_tool_desc* out);

/**
 * Sets where the tool is at the end of the next ent_scene_step: tip position (m) and
 * orientation (w x y z; a non-unit quaternion is normalised). During that step the tool
 * moves continuously from its current pose (the tip linearly, the orientation by
 * normalised linear interpolation) across the substeps, so a fast tool pushes the bowel
 * instead of jumping through it; its velocity, for contact damping, is the pose change
 * over the step. Setting the pose again before the step replaces the target: the step
 * takes the last pose posted before it starts.
 * Any thread, at any time, also while the scene steps: wait-free (no lock), allocates
 * nothing; safe at 1 kHz and more from a haptic thread.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, non-finite position, zero or
 *         non-finite quaternion); ENT_ERROR_NOT_FOUND (unknown tool); nothing changes on failure.
 */
ENT_API ent_status ent_tool_set_pose(ent_scene* scene, int32_t tool, const double position_m[3],
                                     const double orientation_wxyz[4]);

/**
 * The force (N) and the torque about the tip (N m) the bowel exerted on the tool in the
 * last accepted step: exactly minus what the bowel received over that step (the time
 * average of the forces the integrator applied), except where that force would exceed
 * max_force_N (possible only with clamped ends or bdf2, where the proxy is not solved with
 * the bowel: docs/haptics.md): the force is then clipped to max_force_N, its direction
 * kept. The force never exceeds max_force_N. Proxy mode: the
 * virtual coupling's force, bounded. Direct mode: the sum of the tool's contacts and
 * grasp; when their magnitudes add up to more than max_force_N they are all scaled down by
 * one factor, on the bowel as on the tool. Zero before the first step.
 * Reads the last published snapshot (as ent_tool_read_feedback does, which tells more):
 * any thread, never waits, allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_wrench(const ent_scene* scene, int32_t tool, double force_N[3], double torque_Nm[3]);

/**
 * Grasps the bowel at the start of the next ent_scene_step: the collision sphere whose
 * surface is nearest the tip (where the tool rests before that step), its centre within
 * radius_m + R + grasp_margin_m of it, is held to the tip by a tension-only spring-damper of
 * rest length radius_m + R (the held point stays on the tool's surface, where the contact
 * does not push, and the grasp starts without a jolt), R the sphere's radius (with a radius
 * profile, the profile's at its place: a thin stretch is held at its own surface); the
 * material point of the axis held stays the same as the bowel moves. With nothing within
 * reach nothing is held (still ENT_OK; ent_tool_state reports it once that step is
 * published). Grasping again picks the nearest point anew. A grasper with jaws
 * (jaw_length_m, jaw_opening_m) takes what lies between them instead: its jaws are the
 * last jaw_length_m of the shaft, opening jaw_opening_m wide across the tool's local x
 * axis, and of the centres within the same reach of the rectangle they sweep the one least
 * off that strip seen along the tool's axis is held (ties: the surface nearest the tip), so
 * a loop in the jaws' plane is taken before a nearer one beside them: place the jaws over a
 * loop and turn them onto it to aim (docs/haptics.md). ent_tool_read_contacts' grasp_u
 * says where it took hold. When holding would need more than max_force_N the grasp slips: it
 * is released at the end of that step, with no force jump beyond the bound.
 * Any thread, at any time: wait-free, like ent_tool_set_pose. Of a grasp and a release
 * posted before one step, the last one posted wins.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_grasp(ent_scene* scene, int32_t tool);

/**
 * Releases what the tool holds at the start of the next ent_scene_step (nothing held: no
 * effect). Any thread, at any time: wait-free, like ent_tool_grasp.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_release(ent_scene* scene, int32_t tool);

/**
 * Whether the tool holds the bowel in the last published state: *out_grasping is 1 while a
 * grasp holds, 0 after a release, a grasp with nothing in reach, or a slip. A grasp or a
 * release shows once the step that takes it is published.
 * Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_state(const ent_scene* scene, int32_t tool, int32_t* out_grasping);

/**
 * What a tool felt and did in the last published step: what a haptic loop renders, read in
 * one call from one snapshot. Later releases append fields (struct_size tells them apart).
 */
typedef struct ent_tool_feedback {
    uint32_t struct_size;  /**< set by the caller to sizeof(ent_tool_feedback). */
    int32_t grasping;      /**< 1 while a grasp holds, else 0 (as ent_tool_state). */
    double force_N[3];     /**< force of the bowel on the tool, N, never above max_force_N (clipped to it: as ent_tool_wrench). */
    double torque_Nm[3];   /**< torque of the bowel on the tool about its tip, N m. */
    uint32_t contacts;     /**< collision spheres touching the tool in the step's last evaluation. */
    double time_s;         /**< simulated time of the published state this comes from. */
    uint64_t steps;        /**< successful steps at that state (ent_stats.steps): a new value, a new step. */
    /* Later fields (an older struct_size does not get them): */
    double stiffness_N_per_m[9];      /**< as ent_tool_stiffness: d(force_N)/d(tip position), row-major, N/m. */
    double proxy_position_m[3];       /**< the tip of the tool in the scene (the proxy's; the commanded one in direct mode), m: what a viewer draws. */
    double commanded_position_m[3];   /**< the tip the caller commanded for that step, m. */
    double orientation_wxyz[4];       /**< the commanded orientation for that step (the proxy's too). */
    /** 1 if max_force_N bounded the tool's force in that step (the force is the bound, not what the
     *  contacts asked for: a device shim says so, as the LCM bridge's STATUS_FORCE_LIMITED does), else 0.
     *  Added in 0.1 after the proxy (issue 27): not written for an older, smaller struct_size. */
    int32_t saturated;
} ent_tool_feedback;

/**
 * Copies the tool's output in the last published snapshot into *out: wrench, grasp,
 * contacts, and the time and step count of that snapshot. Set out->struct_size first;
 * fields beyond an older, smaller struct_size are not written.
 * Any thread, also while the scene steps: never waits (it pins the snapshot only while it
 * copies) and allocates nothing. A haptic thread at 1 kHz:
 * @code
 *   ent_tool_feedback feedback = {0};
 *   feedback.struct_size = sizeof feedback;
 *   ent_tool_set_pose(scene, tool, device_position_m, device_orientation_wxyz);
 *   if (ent_tool_read_feedback(scene, tool, &feedback) == ENT_OK) render_force(feedback.force_N);
 * @endcode
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size);
 *         ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_read_feedback(const ent_scene* scene, int32_t tool, ent_tool_feedback* out);

/**
 * The tool's local stiffness at the last published step: K = d(force_N)/d(tip position),
 * N/m, row-major (K[3 i + j] = dF_i/dx_j), with the bowel held where it was and the
 * velocities held; contacts and grasp, within the max_force_N bound (a saturated coupling
 * is stiff only across the force). A device loop running faster than the physics renders
 * F + K (x - x_k) between physics ticks (examples/multirate_device.c, docs/haptics.md).
 * Symmetric where the law is (springs); friction and the bound make it non-symmetric.
 * Zero before the first step and with nothing touched.
 * Any thread; reads the published snapshot; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown or removed tool).
 */
ENT_API ent_status ent_tool_stiffness(const ent_scene* scene, int32_t tool, double K_N_per_m[9]);

/** A tool's counters since it was added (ent_tool_read_stats): its passivity observer. */
typedef struct ent_tool_stats {
    uint32_t struct_size;             /**< set by the caller to sizeof(ent_tool_stats). */
    int32_t grasping;                 /**< 1 while a grasp holds, else 0. */
    uint32_t contacts;                /**< collision spheres touching the tool in the last step. */
    uint32_t reserved;                /**< 0. */
    double energy_in_J;               /**< work the tool did on the scene (the device put in), J, >= 0. */
    double energy_out_J;              /**< work the scene did on the tool (given back to the device), J, >= 0. */
    double limiter_energy_J;          /**< energy the passivity limiter took out, J (0 when it is off). */
    double largest_force_change_N;    /**< largest change of the rendered force from one step to the next, N. */
    uint64_t steps;                   /**< successful scene steps at that state. */
} ent_tool_stats;

/**
 * Copies the tool's passivity observer and counters from the last published snapshot. The
 * work is that of the rendered wrench on the commanded motion of each step:
 * W = -(F . dx + tau . dtheta); energy_in_J sums the positive W, energy_out_J the negative.
 * The scene is passive at the tool while energy_in_J - energy_out_J >= 0: with the limiter
 * on (ent_tool_desc.passivity_limiter) it always is; off, a small deficit (the integrator's
 * own damping is the usual margin) tells a vendor the model gave the device energy.
 * Set out->struct_size first. Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size);
 *         ENT_ERROR_NOT_FOUND (unknown or removed tool).
 */
ENT_API ent_status ent_tool_read_stats(const ent_scene* scene, int32_t tool, ent_tool_stats* out);

/**
 * Removes a tool: from the next step it touches nothing and lets go of what it held, and
 * its id answers ENT_ERROR_NOT_FOUND from then on (ids are not reused: the other tools
 * keep theirs). Allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown or
 *         already removed tool); ENT_ERROR_BUSY; nothing changes on failure.
 * @warning A driving call: one at a time per scene.
 */
ENT_API ent_status ent_tool_remove(ent_scene* scene, int32_t tool);

/**
 * The number of tools in the scene: added and not removed. Ids run from 0 to the number
 * ever added minus one (removed ids stay unused). Any thread; never waits.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL).
 */
ENT_API ent_status ent_scene_tool_count(const ent_scene* scene, int32_t* out_count);

/* ------------------------------------------------------------------------------------ */
/* Contacts: what touches the bowel, where and how hard (for scoring a trainee)          */
/* ------------------------------------------------------------------------------------ */

/** What a contact of the bowel touches (ent_contact.kind). Passed as int32_t. */
#define ENT_CONTACT_SELF 0     /**< another fold of the bowel */
#define ENT_CONTACT_OBSTACLE 1 /**< an obstacle of the environment (ent_contact.index: its index) */
#define ENT_CONTACT_TOOL 2     /**< a tool (ent_contact.index: its id) */

/**
 * One contact of the bowel in the last published step: its last evaluation of the contact
 * forces, the one whose forces moved the bowel and whose sum the tools report. A place on
 * the bowel is u in [0, 1], its arc length from the first end over the axis' length (as
 * ent_mesh_view.axis_u), at the collision sphere that touches (spheres are
 * collision_sphere_spacing_m apart, R / 2 by default). Later releases append fields.
 */
typedef struct ent_contact {
    uint32_t struct_size; /**< set in the first element by the caller (see ent_scene_contacts). */
    int32_t kind;         /**< ENT_CONTACT_*. */
    int32_t index;        /**< the obstacle's index or the tool's id; -1 for a self-contact. */
    double u;             /**< where on the bowel, in [0, 1]. */
    double other_u;       /**< self-contact: where the other fold touches, in [0, 1] (> u); else -1. */
    double point_m[3];    /**< the contact point, m: on the obstacle's or the tool's surface; self-contact: midway between the folds' axes. */
    double normal[3];     /**< unit normal pushing the bowel at u away from what it touches (self-contact: from the fold at other_u). */
    double depth_m;       /**< penetration, m, > 0. */
    double force_N[3];    /**< force on the bowel at u, N (self-contact: the fold at other_u gets minus it). */
} ent_contact;

/**
 * Copies the contacts of the last published step into out: the tools' first (by tool id,
 * then along the bowel), then the obstacles', then the self-contacts'. Set
 * out[0].struct_size to sizeof(ent_contact): the library writes the first struct_size bytes
 * of each element, struct_size bytes apart, so a caller built against an older, smaller
 * ent_contact keeps working. *out_count receives the number of contacts listed; with out
 * NULL (any capacity) only the count is reported. A capacity below the count gives
 * ENT_ERROR_BUFFER_TOO_SMALL with *out_count set and nothing copied: size the array once
 * with ent_contact_summary.capacity, the most a step lists. A step lists at most 4 contacts
 * per collision sphere; beyond that it lists the first (ent_contact_summary counts those
 * found and those listed). After a step that failed (ENT_ERROR_UNSTABLE) the list is that of
 * its last attempt, as ent_stats.contacts is.
 * Any thread, also while the scene steps: never waits, allocates nothing.
 * @code
 *   ent_contact_summary summary = {0};
 *   summary.struct_size = sizeof summary;
 *   ent_scene_contact_summary(scene, &summary);
 *   ent_contact* contacts = calloc(summary.capacity + 1, sizeof *contacts);  // once
 *   contacts[0].struct_size = sizeof *contacts;
 *   uint32_t count = 0;
 *   if (ent_scene_contacts(scene, summary.capacity + 1, contacts, &count) == ENT_OK)
 *       for (uint32_t i = 0; i < count; ++i) if (contacts[i].kind == ENT_CONTACT_TOOL) score(contacts[i].u);
 * @endcode
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (scene or out_count NULL);
 *         ENT_ERROR_VERSION (out[0].struct_size); ENT_ERROR_BUFFER_TOO_SMALL.
 */
ENT_API ent_status ent_scene_contacts(const ent_scene* scene, uint32_t capacity, ent_contact* out,
                                      uint32_t* out_count);

/** The bowel's contacts and stretch in the last published step: what a trainer scores as tissue stress. */
typedef struct ent_contact_summary {
    uint32_t struct_size;       /**< set by the caller to sizeof(ent_contact_summary). */
    uint32_t capacity;          /**< the most contacts a step lists (4 per collision sphere; 0 without contact effects). */
    uint32_t listed;            /**< contacts ent_scene_contacts gives for this step. */
    uint32_t found;             /**< contacts found: more than listed when the list was full. */
    uint32_t self_contacts;     /**< found, of each kind. */
    uint32_t obstacle_contacts;
    uint32_t tool_contacts;
    double largest_force_N;     /**< the largest |force| of any contact found, N. */
    double largest_force_u;     /**< where on the bowel (u in [0, 1]); 0 without contacts. */
    /** The largest stretch of a segment of the axis between two control points: its arc length
     *  over its rest length, minus 1 (0.05: 5 % longer than at rest; negative: every segment shorter). */
    double largest_stretch;
    double largest_stretch_u;   /**< where: the middle of that segment (u in [0, 1]). */
    double time_s;              /**< simulated time of the published state. */
    uint64_t steps;             /**< its successful step count (as ent_stats.steps). */
} ent_contact_summary;

/**
 * Fills *out from the last published snapshot. Set out->struct_size first; fields beyond
 * an older, smaller struct_size are not written. The stretch is measured on the published
 * control points here, on the calling thread (one pass over the axis).
 * Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size).
 */
ENT_API ent_status ent_scene_contact_summary(const ent_scene* scene, ent_contact_summary* out);

/**
 * What one tool touches and holds in the last published step. The caller sets struct_size
 * and, to receive the ranges of the bowel the tool touches, range_capacity and ranges_u.
 */
typedef struct ent_tool_contacts {
    uint32_t struct_size;       /**< in: sizeof(ent_tool_contacts). */
    uint32_t range_capacity;    /**< in: ranges that ranges_u has room for. */
    /** in: an array of range_capacity x 2 doubles, or NULL. Receives the ranges of u the tool
     *  touches, first and last u of each, along the bowel: runs of neighbouring collision
     *  spheres touching it (a range of one sphere has first = last). */
    double* ranges_u;
    uint32_t range_count;       /**< ranges touched; when above range_capacity, only the first range_capacity are written. */
    uint32_t contacts;          /**< collision spheres touching the tool. */
    int32_t grasping;           /**< 1 while a grasp holds (as ent_tool_state). */
    double grasp_u;             /**< where the grasp took hold (u in [0, 1]) while grasping; else -1. */
    double largest_force_N;     /**< the largest |force| of one of its contacts, N. */
    /** The impulse of the bowel's contacts on the tool since it was added, N s: each step's
     *  contact force times its dt, summed as vectors. The grasp's force is not in it. */
    double contact_impulse_Ns[3];
    double contact_impulse_magnitude_Ns; /**< the same with each step's force magnitude: how hard for how long. */
    double time_s;              /**< simulated time of the published state. */
    uint64_t steps;             /**< its successful step count. */
} ent_tool_contacts;

/**
 * Fills *out with what the tool touched and held in the last published step, from one
 * snapshot. The sum of the tool's contact forces (ent_scene_contacts, kind ENT_CONTACT_TOOL)
 * and of its grasp spring is minus its wrench (ent_tool_wrench).
 * Any thread; never waits; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL; ranges_u NULL with a range_capacity);
 *         ENT_ERROR_VERSION (struct_size); ENT_ERROR_NOT_FOUND (unknown tool).
 */
ENT_API ent_status ent_tool_read_contacts(const ent_scene* scene, int32_t tool, ent_tool_contacts* out);

/* ------------------------------------------------------------------------------------ */
/* Exposure: how much of a target the bowel hides from a viewpoint (is the area cleared?) */
/* ------------------------------------------------------------------------------------ */

/**
 * A target prepared for ent_scene_exposure: its sample points, their weights and the work
 * space of the query, so that each query allocates nothing. Opaque; made by
 * ent_exposure_create for one scene.
 */
typedef struct ent_exposure ent_exposure;

/**
 * What to measure the exposure of. Fill it with ent_exposure_desc_default, set the target,
 * then call ent_exposure_create; it is not retained (the arrays are copied).
 * The target is a set of points, or a small patch of triangles on an organ (a gallbladder,
 * the posterior wall where the right colon lies), given in the world or in an obstacle's
 * frame, so that it moves with the organ (a liver a retractor lifts).
 */
typedef struct ent_exposure_desc {
    uint32_t struct_size;           /**< sizeof(ent_exposure_desc); set by ent_exposure_desc_default. */
    /** point_count x 3 coordinates, m, in the frame of `obstacle`: the target's points, or the
     *  patch's vertices (default NULL). */
    const double* points_xyz_m;
    uint32_t point_count;           /**< 1 to 1048576 (default 0). */
    /** triangle_count x 3 indices into the points (from 0): the target is this patch, each
     *  triangle sampled at samples_per_edge^2 points (the centroids of its sub-triangles);
     *  NULL: the target is the points themselves (default NULL). */
    const uint32_t* triangles;
    uint32_t triangle_count;        /**< triangles, 0 to 1048576; 0 with triangles NULL (default 0). */
    /** A weight >= 0 per point (no triangles) or per triangle (a patch: it multiplies the
     *  triangle's area); NULL: every point alike, or each triangle by its area (default NULL).
     *  The weights must not all be zero. */
    const double* weights;
    uint32_t samples_per_edge;      /**< a patch: each triangle's edge cut into this many parts, 1 to 32 (default 4: 16 samples a triangle). */
    /** The frame the points are given in: ENT_NO_OBSTACLE (the world; default) or an
     *  obstacle's index: each query places the target where that obstacle rests in the
     *  published state. */
    int32_t obstacle;
    /** The bowel's surface is taken as spheres swept along its axis sampled at this many
     *  chords per spline segment, 1 to 64 (default 4: the chord departs from the axis by under
     *  0.3 mm where the bowel bends at twice its radius, N = 240 on 6 m). */
    uint32_t axis_chords_per_segment;
} ent_exposure_desc;

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size; nothing past struct_size is written. Call it through
 * ent_exposure_desc_default. Added in 0.1 with the patient (issue 29).
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (unknown size).
 */
ENT_API ent_status ent_exposure_desc_init(ent_exposure_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_exposure_desc_default(desc) \
    ((void)ent_exposure_desc_init((desc), (uint32_t)sizeof(ent_exposure_desc)))

/**
 * Prepares a target for ent_scene_exposure on this scene: copies and samples it and sizes
 * the query's work space for the scene's bowel. Allocates (about 100 bytes per sample and
 * per chord of the axis); not on a real-time path.
 * Thread: any thread; it reads only constants of the scene and the published obstacle count.
 * @param out_exposure receives the prepared target; untouched on failure.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL; a count out of range; non-finite
 *         coordinates; an index past the points; a negative or non-finite weight, or all
 *         weights zero, or every triangle of zero area; samples_per_edge or
 *         axis_chords_per_segment out of range: the message names the field and the
 *         element); ENT_ERROR_NOT_FOUND (no such obstacle, or removed); ENT_ERROR_VERSION;
 *         ENT_ERROR_OUT_OF_MEMORY.
 */
ENT_API ent_status ent_exposure_create(const ent_scene* scene, const ent_exposure_desc* desc,
                                       ent_exposure** out_exposure);

/**
 * Destroys a prepared target. NULL is ignored. It may outlive its scene (it keeps no
 * reference to it).
 * @warning No call with this exposure may run during or after this one.
 */
ENT_API void ent_exposure_destroy(ent_exposure* exposure);

/**
 * The answer of ent_scene_exposure. The caller sets struct_size and, to receive them, the
 * arrays and their capacities; the rest is written by the call.
 */
typedef struct ent_exposure_result {
    uint32_t struct_size;        /**< in: sizeof(ent_exposure_result). */
    uint32_t span_capacity;      /**< in: spans the arrays below have room for. */
    /** in: span_capacity x 2 doubles, or NULL: receives, for each span of the bowel that hides
     *  part of the target, its first and last u (u in [0, 1]: arc length from the first end
     *  over the axis' length, as ent_contact.u). A span is a run of the axis whose surface
     *  crosses a sight line to the target; runs less than one local diameter apart along the
     *  bowel are one span (one loop). Listed along the bowel, tube by tube. */
    double* spans_u;
    /** in: span_capacity doubles, or NULL: receives the fraction of the target's weight each
     *  span hides (the weight of the sight lines it crosses, over the total). Spans may hide
     *  the same sight line: these may sum to more than 1 - visible_fraction. Moving the span
     *  with the largest fraction clears the most. */
    double* span_hidden_fractions;
    /** in: span_capacity int32, or NULL: receives the tube each span belongs to (0: the
     *  scene's one intestine). */
    int32_t* span_intestines;
    /** in: NULL, or an array with one double per element of the target (per point, or per
     *  triangle of a patch): receives the fraction of that element seen, 0 to 1. */
    double* element_visible;
    double visible_fraction;     /**< out: the weight of the target seen over its total weight, 0 to 1. */
    uint32_t span_count;         /**< out: spans that hide part of the target; above span_capacity only the first span_capacity are written. */
    uint32_t samples;            /**< out: sample points of the target (points, or triangles x samples_per_edge^2). */
    uint32_t hidden_samples;     /**< out: of those, hidden by the bowel. */
    double time_s;               /**< out: simulated time of the published state measured. */
    uint64_t steps;              /**< out: its successful step count (as ent_stats.steps). */
} ent_exposure_result;

/**
 * How much of a target the bowel leaves in sight from a viewpoint (the laparoscope's tip):
 * the weighted fraction of the target's sample points whose straight sight line from the
 * viewpoint does not pass through the bowel, a tube of its radius around the axis of the
 * last published state (the same surface the skins draw and the contacts keep apart), and
 * the spans of the bowel that hide the rest. Only the bowel hides: organs, the target's own
 * organ and which way its surface faces are the caller's (a point on the far side of the
 * liver counts as seen). A viewpoint inside the bowel sees nothing.
 * @code
 *   ent_exposure_desc desc;
 *   ent_exposure_desc_default(&desc);
 *   desc.points_xyz_m = gallbladder_xyz;  desc.point_count = 40;  // on the liver's frame:
 *   desc.obstacle = liver;
 *   ent_exposure* target = NULL;
 *   ent_exposure_create(scene, &desc, &target);                  // once: it allocates
 *   double spans[8 * 2];
 *   ent_exposure_result r = {0};
 *   r.struct_size = sizeof r;  r.span_capacity = 8;  r.spans_u = spans;
 *   ent_scene_exposure(scene, target, scope_tip_m, &r);          // any thread, often
 *   printf("%.0f %% seen\n", 100 * r.visible_fraction);
 * @endcode
 * Cost: about 1 us of CPU per sample with the 6 m bowel piled across every sight line
 * (0.13 ms for 97 points, 1 ms for 1009; bench/results/exposure.md), proportional to the
 * samples. Reads the last published snapshot: any thread, also while the scene steps; never
 * waits for the step (it pins the snapshot only while it copies the axis) and allocates
 * nothing. An exposure is used by one thread at a time: a second call on the same exposure
 * while one runs returns ENT_ERROR_BUSY at once and changes nothing (use one exposure per
 * thread).
 * @param viewpoint_m the eye, m, world frame.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, a non-finite viewpoint, spans_u NULL
 *         with a span_capacity, an exposure made for another scene); ENT_ERROR_VERSION
 *         (struct_size); ENT_ERROR_NOT_FOUND (the target's obstacle was removed);
 *         ENT_ERROR_BUSY (this exposure is measuring on another thread). Nothing is written
 *         on failure.
 */
ENT_API ent_status ent_scene_exposure(const ent_scene* scene, ent_exposure* exposure, const double viewpoint_m[3],
                                      ent_exposure_result* out);

/* ------------------------------------------------------------------------------------ */
/* Skins: a closed triangle mesh of the bowel surface, for rendering                    */
/* ------------------------------------------------------------------------------------ */

/**
 * A skin builds the surface of the intestine, a tube of radius R around the axis, from the
 * last published state of its scene. Opaque; made by ent_skin_create. A skin shares its
 * scene's published snapshots: it may outlive the scene, and then keeps building from the
 * last state the scene published.
 */
typedef struct ent_skin ent_skin;

/** Skinning methods (ent_skin_desc.method). Passed as int32_t. */
#define ENT_SKIN_TUBE 0           /**< rings on rotation-minimising frames: fastest; folds over itself at bends tighter than R */
#define ENT_SKIN_POINT_SKELETON 1 /**< distance surface of point skeletons, marching cubes on a narrow band */
#define ENT_SKIN_CONVOLUTION 2    /**< local convolution surface of the axis segments (kernel 1/r^3), seeded rings */

/**
 * How to skin. Fill it with ent_skin_desc_default, change what you need, then call
 * ent_skin_create; it is not retained. Lengths are in units of the intestine radius R, so
 * the same settings suit any bowel. Each method reads only the knobs it names. With a radius
 * profile (ent_scene_desc.radius_profile_m) R is its largest value: the knobs scale with it,
 * and every skin draws the profile's radius at each place along the axis (docs/skinning.md).
 */
typedef struct ent_skin_desc {
    uint32_t struct_size;          /**< sizeof(ent_skin_desc); set by ent_skin_desc_default. */
    int32_t method;                /**< ENT_SKIN_* (default ENT_SKIN_CONVOLUTION). */
    /** tube, convolution: vertices around each ring, 3 to 1024 (default 16). */
    uint32_t segments;
    /** tube, convolution: arc length between rings, in R, 0.05 to 8 (default 0.5). */
    double ring_spacing_radii;
    /** tube, convolution: rings of each hemispherical end cap, 0 to 64 (default 4). */
    uint32_t cap_rings;
    /** point_skeleton, convolution: arc length between skeleton points / segment ends, in R, 0.05 to 2 (default 0.25). */
    double skeleton_spacing_radii;
    /** point_skeleton: edge of a marching-cubes voxel, in R, 0.1 to 2 (default 1/3). */
    double voxel_size_radii;
    /** point_skeleton, convolution: half-width D of the arc-length window of local blending, in R, 0.25 to < 2 (default 1).
     *  A surface point blends only the skeleton within D of its own axis point, so folds never blend. */
    double window_radii;
    /** convolution: level of detail along the axis, in R, 0 to 1 (default 0: rings evenly ring_spacing_radii apart).
     *  Above 0, rings come closer where the axis bends, so that the straight edge between two rings departs
     *  from the tube by at most this (its sag on the outer side of the bend), down to 1/16 of
     *  ring_spacing_radii; ring_spacing_radii is then the spacing on straight parts. The ring count
     *  follows the bends from frame to frame (in steps, with stable_topology). Added in 0.1 after the
     *  first skins: a caller built against the older, smaller ent_skin_desc gets 0. */
    double ring_chord_error_radii;
    /** tube, convolution: 1 (default) keeps the vertex count and the triangle indices from update to update
     *  while the bowel moves, so that a renderer uploads the indices once (ent_mesh_view.topology_changed
     *  says when to do it again): the rings are as many as the axis' length at the skin's first update
     *  holds at ring_spacing_radii, spread evenly over its current length; with ring_chord_error_radii their count
     *  moves in steps of a sixteenth of that, up at once where the bends need more rings, down only once a
     *  whole step is spare. 0: rings every ring_spacing_radii of the current length, their count following
     *  the stretch. point_skeleton: ignored, its topology changes on every update. Added after
     *  ring_chord_error_radii: a caller built against an older, smaller ent_skin_desc gets 1. */
    int32_t stable_topology;
    /** point_skeleton, convolution: 1 (default) where two folds press into each other (their tubes of radius R
     *  around the axis overlap, the axis more than pi R apart along it) their surfaces meet on a shared contact
     *  surface, half-way between the two axes, instead of passing through each other, and the volume pushed out
     *  of the contact shows as a bulge beside it that keeps each cross-section's area (at most 11 % of R high,
     *  reaching at most 0.75 R from the other fold; more is lost: ent_skin_metrics.shape_volume_error). Continuous
     *  as contacts come and go. 0: the folds' surfaces pass through each other. The tube has no contact surfaces
     *  (they would cost several times its update; docs/skinning.md). Every method keeps its rings from folding
     *  over at bends tighter than R, whatever this says. Added after stable_topology: a caller built against an
     *  older, smaller ent_skin_desc gets 1. */
    int32_t contact_surfaces;
    /** convolution: 0 (default) places the segment ends evenly, skeleton_spacing_radii apart. Above 0 (in R, up to
     *  0.1) they follow the axis' curvature: closer where it bends, so that the polyline departs from the axis by
     *  at most this (its chords' sag), from skeleton_spacing_radii on straight parts down to an eighth of it (e.g.
     *  skeleton_spacing_radii 1 with 0.005: on a gently folded bowel the accuracy of even R / 4 for less time;
     *  docs/skinning.md). point_skeleton: ignored (its points stay even). Added with contact_surfaces: an older,
     *  smaller ent_skin_desc gets 0. */
    double skeleton_chord_error_radii;
} ent_skin_desc;

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size; nothing past struct_size is written. Call it through
 * ent_skin_desc_default, which passes the size of the header the program was built with.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (unknown size).
 */
ENT_API ent_status ent_skin_desc_init(ent_skin_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_skin_desc_default(desc) \
    ((void)ent_skin_desc_init((desc), (uint32_t)sizeof(ent_skin_desc)))

/**
 * Creates a skin of a scene. The mesh is empty until the first ent_skin_update.
 * The skin's buffers come from the C++ heap, not from the scene's allocator callbacks.
 * @param scene the scene to skin; the skin may outlive it.
 * @param desc filled by ent_skin_desc_default first; not retained.
 * @param out_skin receives the new skin; untouched on failure.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, unknown method, a knob out of its range:
 *         the message names the field); ENT_ERROR_VERSION (struct_size not known);
 *         ENT_ERROR_OUT_OF_MEMORY.
 * Thread: any thread; it reads only constants of the scene.
 */
ENT_API ent_status ent_skin_create(ent_scene* scene, const ent_skin_desc* desc, ent_skin** out_skin);

/**
 * Rebuilds the mesh from the scene's last published state (the one ent_scene_axis would
 * read; after ent_scene_destroy, the last state it published). Safe on a render thread while another thread calls ent_scene_step: it pins the
 * latest snapshot only while it copies the control points, and the stepping thread never
 * waits on it for more than a pointer swap. Reuses the skin's buffers: after the first
 * updates it allocates only when the mesh grows beyond any size it had before (its work
 * buffers keep headroom; tests/no_alloc/skin_no_alloc.cpp checks this on a moving bowel).
 * Invalidates the previous ent_skin_mesh view.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_OUT_OF_MEMORY (the previous
 *         mesh may then be incomplete: update again); ENT_ERROR_BUSY (another thread is in
 *         a call on this skin; nothing done).
 * @warning Calls on one skin (update, mesh, metrics) are made by one thread at a time; use
 *          one skin per thread, or your own lock. A call that overlaps another on the same
 *          skin is refused with ENT_ERROR_BUSY rather than corrupting its buffers.
 */
ENT_API ent_status ent_skin_update(ent_skin* skin);

/** A read-only view into a skin's mesh, valid until the next ent_skin_update or ent_skin_destroy. */
typedef struct ent_mesh_view {
    uint32_t struct_size;          /**< set by the caller to sizeof(ent_mesh_view). */
    uint32_t vertex_count;         /**< vertices. */
    uint32_t triangle_count;       /**< triangles. */
    const float* positions_xyz_m;  /**< vertex_count x 3 floats, m. */
    const float* normals_xyz;      /**< vertex_count x 3 floats, unit, pointing out of the bowel. */
    const float* axis_u;           /**< vertex_count floats in [0, 1]: the vertex's axis point, as arc length / total length (for texturing). */
    const uint32_t* indices;       /**< triangle_count x 3 vertex indices, counter-clockwise seen from outside. */
    double time_s;                 /**< simulated time of the state the mesh was made from. */
    uint64_t updates;              /**< ent_skin_update calls that succeeded so far. */
    /* Added after the first skins: not written for an older, smaller struct_size. */
    /** vertex_count floats in [0, 1): the vertex's angle around the axis / 2 pi, measured from the normal of
     *  the rotation-minimising frame of its axis point towards its binormal (the frame does not twist along the
     *  bowel, and starts each update from the last one's first normal, so v is continuous along the bowel and
     *  from frame to frame). It wraps from just below 1 to 0 across one column of triangles: sample a periodic
     *  texture there with care (e.g. fract in the fragment shader). */
    const float* around_v;
    /** vertex_count x 3 floats, unit, perpendicular to the normal: the surface's direction of increasing u
     *  (along the axis; towards the last pole on the end caps). tangent x normal points towards increasing v
     *  (for normal maps: the bitangent is cross(tangent, normal); glTF handedness -1). */
    const float* tangents_xyz;
    /** Counts the updates that changed the topology (vertex_count or indices), the first included: equal
     *  values, the same indices. A renderer that may skip updates compares it with the value of the indices
     *  it holds. */
    uint64_t topology_serial;
    /** 1 if the last ent_skin_update changed vertex_count or indices (the first update does), else 0: upload
     *  the indices only then. Positions, normals and tangents change on every update; around_v of the tube
     *  and convolution skins only with the topology, and axis_u too when their rings are even
     *  (ring_chord_error_radii 0) and stable_topology is 1. */
    int32_t topology_changed;
    /** 1 if this skin keeps its topology while the bowel moves (tube and convolution with
     *  ent_skin_desc.stable_topology), 0 if it may change on any update (point_skeleton: every update). */
    int32_t stable_topology;
} ent_mesh_view;

/**
 * Points *out at the skin's mesh, without copying. Set out->struct_size first; fields
 * beyond an older, smaller struct_size are not written. Before the first update the mesh
 * is empty (counts 0, pointers NULL).
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size);
 *         ENT_ERROR_BUSY (another thread is in a call on this skin).
 */
ENT_API ent_status ent_skin_mesh(const ent_skin* skin, ent_mesh_view* out);

/**
 * How close the mesh is to the ideal tube of radius R around the same axis. Used as
 * `struct ent_skin_metrics` (no typedef: the name is also the function that fills it).
 */
struct ent_skin_metrics {
    uint32_t struct_size;          /**< set by the caller to sizeof(ent_skin_metrics). */
    uint32_t vertex_count;
    uint32_t triangle_count;
    /** 1 if every edge is shared by exactly two triangles (a closed surface), else 0. */
    int32_t watertight;
    uint32_t open_edges;           /**< edges of only one triangle. */
    uint32_t nonmanifold_edges;    /**< edges of three or more triangles. */
    /** Vertices closer than 1.1 R to a part of the axis more than 4 R away along it: pulled into another fold. */
    uint32_t blended_vertices;
    /** Triangles facing the axis as seen from each of their three corners' axis points: the tube's
     *  fold-over at bends tighter than R. */
    uint32_t inverted_triangles;
    /** RMS over vertices of | |v - A(u)| - R | / R, A(u) the vertex's own axis point; with a radius profile R
     *  is the profile's at A(u)'s place (as in every radius, facet and volume error here; the measures
     *  "in R" take its largest value). */
    double radius_error_rms;
    double radius_error_max;       /**< largest of those. */
    double normal_deviation_rms_rad; /**< RMS angle between the vertex normal and the ideal tube's normal (v - A(u)) / |v - A(u)|. */
    double normal_deviation_max_rad; /**< largest of those. */
    double volume_m3;              /**< enclosed volume (divergence theorem). */
    double volume_error;           /**< (volume - pi R^2 L) / (pi R^2 L); rounded ends add 4 R / (3 L). */
    double axis_length_m;          /**< L, arc length of the axis skinned. */
    uint64_t last_update_ns;       /**< wall time of the last ent_skin_update. */
    /** RMS over triangles of | |c - axis| - R | / R, c the triangle's centroid and |c - axis| its distance
     *  to the axis: how far the flat triangles depart from the tube between the vertices (chord error).
     *  Added after the first skins: not written for an older, smaller struct_size. */
    double facet_error_rms;
    double facet_error_max;        /**< largest of those. */
    /* Where folds meet, and motion between updates. Added after facet_error_max: not written for an older,
     * smaller struct_size.
     * "Another fold" of a vertex: the mesh and axis more than pi R away along the axis from the vertex's own
     * axis point (the mechanics' neighbour window). Depths, gaps and motions in units of R. */
    /** Deepest vertex inside another fold's part of the mesh (signed distance to its nearest triangle): 0 when
     *  the folds meet on contact surfaces, the folds' pressing depth when their surfaces pass through each other. */
    double overlap_depth_max;
    /** Area of the triangles whose three corners lie inside another fold's part of the mesh by more than R / 100, m^2. */
    double overlap_area_m2;
    /** Deepest vertex inside another fold's ideal tube (radius R around its axis): how hard the folds press. */
    double tube_overlap_depth_max;
    /** Area of the triangles whose three corners lie inside another fold's ideal tube by more than R / 100, m^2:
     *  about the contact surfaces' area. */
    double tube_overlap_area_m2;
    /** Largest distance from a vertex inside another fold's ideal tube to that fold's skin, where the vertex lies
     *  outside it: folds pressed together whose surfaces do not meet. */
    double contact_gap_max;
    /** (V - V_tube) / V_tube, V_tube the volume of the same triangles with every vertex moved onto the ideal tube
     *  (R from its own axis point, in its own direction): the volume the skin's shape adds or loses (contacts,
     *  bulges, radius error), without the share of the facets and the rounded ends that volume_error carries. */
    double shape_volume_error;
    /** RMS radius error (like radius_error_rms) over the vertices nothing may deform: farther than 1.75 R from any
     *  other fold's axis, where the axis (R either way) bends with a radius above R. */
    double free_radius_error_rms;
    /** Largest distance from a vertex to the previous update's mesh: how far the surface moved there (a vertex
     *  sliding along the surface does not count), at most 1. */
    double vertex_motion_max;
    /** Largest amount by which the surface at a vertex moved farther, since the update before, than the tube
     *  around its own axis point A(u) did (|dA(u)| + R |dt(u)|, t the axis' tangent): popping, a change of the
     *  surface the axis under it does not explain. */
    double vertex_excess_motion_max;
    uint32_t free_vertex_count;    /**< vertices free_radius_error_rms is over. */
    /** 1 if vertex_motion_max and vertex_excess_motion_max compare with an update before (from the second update on), else 0. */
    int32_t has_previous_update;
};

/**
 * Measures the current mesh against the axis it was built from (see ent_skin_metrics).
 * Costs more than an update (it allocates work space and checks every edge): for tests,
 * benchmarks and tuning, not for every frame. Set out->struct_size first. Before the
 * first update every measure is 0.
 * @code
 *   struct ent_skin_metrics m = {0};
 *   m.struct_size = sizeof m;
 *   if (ent_skin_metrics(skin, &m) == ENT_OK) printf("radius RMS %.3f %%\n", 100 * m.radius_error_rms);
 * @endcode
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size);
 *         ENT_ERROR_OUT_OF_MEMORY; ENT_ERROR_BUSY (another thread is in a call on this skin).
 */
ENT_API ent_status ent_skin_metrics(const ent_skin* skin, struct ent_skin_metrics* out);

/**
 * Destroys a skin and its mesh (any view of it becomes invalid). NULL is ignored.
 * A call on this skin already running on another thread (an update) finishes, and the
 * skin's memory goes as it returns; a call begun after this one returned is the caller's
 * bug (the handle may be gone).
 */
ENT_API void ent_skin_destroy(ent_skin* skin);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* ENTERON_ENTERON_H */
