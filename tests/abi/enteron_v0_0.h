/* SPDX-License-Identifier: Apache-2.0 */
/*
 * tests/abi/enteron_v0_0.h: the public header of the "0.0 preview" release, kept to prove
 * that programs built against an older header keep working with the current library.
 *
 * 0.0 is a SIMULATED release (none was published): this is the 0.1 header without the
 * fields appended since, namely ent_scene_desc.callbacks and ent_stats.last_step_ns, and
 * with version 0.0.0. The library serves those smaller struct_size values (lib/capi:
 * complete_desc in scene_desc.cpp, ent_scene_stats in scene_api.cpp). Do not edit it to
 * follow the current header: an old header never changes.
 */
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
 * Threads: one thread drives a scene (create, step, tools, destroy). The query calls
 * (ent_scene_axis, ent_scene_control_points, ent_scene_stats, ent_scene_effect_stats)
 * read the last published state, an immutable snapshot made after every successful step,
 * and may run on any number of other threads at the same time as the step. The stepping
 * thread never waits on a reader for more than a pointer swap. ent_scene_destroy must not
 * race with any other call on that scene.
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
#define ENT_VERSION_MINOR 0
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
 * but the function pointers and user_data must stay valid for the scene's lifetime.
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
#define ENT_EFFECT_COUNT 6          /**< number of effects this header knows */
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

/** Which ends are held fixed (ent_scene_desc.pinned_ends). */
#define ENT_PIN_NONE 0
#define ENT_PIN_FIRST 1
#define ENT_PIN_LAST 2
#define ENT_PIN_BOTH 3

/**
 * Everything needed to create a scene from C. Fill it with ent_scene_desc_default, change
 * what you need, then call ent_scene_create. No reference to it (or to the arrays it points
 * to) is kept after the call. The JSON description (ent_scene_create_json) offers the same
 * settings; the README documents both, key by key.
 */
typedef struct ent_scene_desc {
    uint32_t struct_size; /**< sizeof(ent_scene_desc); set by ent_scene_desc_default. */
    /** The effects to simulate: OR of ENT_EFFECT_BIT(ENT_EFFECT_*). Default: stretch, bend, damping, gravity. */
    uint32_t effects;

    /* The intestine */
    double length_m;                    /**< rest length of the axis, m (default 6). */
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
    const double* shape_points_xyz_m;   /**< points: control_points x 3 coordinates, m. */

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
 * @param desc filled by ent_scene_desc_default first; not retained.
 * @param out_scene receives the new scene; untouched on failure.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, bad value: the message names the
 *         field), ENT_ERROR_VERSION (struct_size not known), ENT_ERROR_OUT_OF_MEMORY.
 */
ENT_API ent_status ent_scene_create(const ent_scene_desc* desc, ent_scene** out_scene);

/**
 * Creates a scene from a JSON description (format v1, documented key by key in the
 * README). Effects are opt-in: a key that is absent is an effect that does not run.
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
 * Destroys a scene and everything it owns. NULL is ignored.
 * @warning No other call on this scene may run during or after this one.
 */
ENT_API void ent_scene_destroy(ent_scene* scene);

/**
 * Advances the simulation by dt_s seconds, in equal substeps no longer than the scene's
 * timestep (and, for explicit integrators, no longer than their stability limit), then
 * publishes the new state. A stability guard checks the result (finite, speeds below
 * max_speed, no energy from nothing); when the check fails it rolls back and retries
 * with halved substeps, up to max_subdivisions times.
 * Allocates nothing after the first step.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, dt not finite or <= 0, or dt needing
 *         more than max_substeps substeps; nothing changes); ENT_ERROR_UNSTABLE (the
 *         guard could not recover: positions, velocities, time and step count are exactly
 *         as before the call; substeps, rollbacks and effect times record the attempt).
 * @warning Call from the one thread that drives this scene.
 */
ENT_API ent_status ent_scene_step(ent_scene* scene, double dt_s);

/**
 * Copies count points of the axis, evenly spaced in arc length from the first end to the
 * last, into points_xyz_m (count x 3 doubles, x y z per point, m). count >= 2.
 * Reads the last published state: safe from any thread; allocates nothing.
 */
ENT_API ent_status ent_scene_axis(const ent_scene* scene, uint32_t count, double* points_xyz_m);

/**
 * Copies the control points (x y z each, m) of the last published state. *out_count
 * receives their number. With points_xyz_m NULL (and any capacity) only the count is
 * reported. A capacity (in points) below the count gives ENT_ERROR_BUFFER_TOO_SMALL,
 * with *out_count set and nothing copied. Safe from any thread.
 */
ENT_API ent_status ent_scene_control_points(const ent_scene* scene, uint32_t capacity,
                                            double* points_xyz_m, uint32_t* out_count);

/** Counters and energies of the last published state. */
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
} ent_stats;

/**
 * Copies the stats of the last published state into *out. Set out->struct_size first;
 * fields beyond an older, smaller struct_size are not written. Safe from any thread.
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

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* ENTERON_ENTERON_H */
