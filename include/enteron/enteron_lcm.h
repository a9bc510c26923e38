/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Enteron LCM bridge: haptic-device drivers, viewers and loggers talk to a running scene
 * over LCM (Lightweight Communications and Marshalling, https://lcm-proj.github.io).
 *
 * This is the public header of libenteron_lcm, a library of its own: libenteron never
 * links LCM (liblcm prints to stderr; the core never prints). Like enteron.h it is plain
 * C99 (it also compiles as C++), exposes only opaque handles and description structs that
 * start with `struct_size`, returns an ent_status from every call that can fail and
 * passes enums as int32_t. docs/lcm.md is the manual: the messages, the channels, the
 * safety rules, the server, the journal and the measured latency.
 *
 * A bridge owns a scene, made from its JSON description, and one LCM instance. Each tick
 * takes the newest accepted command of every tool, applies it through the safety rules
 * (watchdog, bounded tool speed, force ramp, deadman, clamps, workspace mapping), steps
 * the scene and queues the feedback; the bridge's own threads receive commands and
 * publish the feedback, the state, the mesh, the session and the status.
 *
 * Messages (bindings/lcm/, one .lcm file per type, package enteron; channels get the suffix):
 *   ENTERON_TOOL_COMMAND   tool_command_t   device -> bridge, up to every tick
 *   ENTERON_TOOL_FEEDBACK  tool_feedback_t  bridge -> device, every tick, every tool
 *   ENTERON_STATE          scene_state_t    at state_hz
 *   ENTERON_MESH           mesh_t           at mesh_hz
 *   ENTERON_SESSION        session_t        at the start, then once a second
 *   ENTERON_STATUS         server_status_t  once a second
 *
 * Threads:
 * - The driving thread calls ent_lcm_bridge_tick: the host's own 1 kHz thread, or the
 *   bridge's physics thread after ent_lcm_bridge_start. The tick makes no system call and
 *   allocates nothing after the first ticks (tests/lcm checks both): it exchanges with the
 *   other threads through preallocated wait-free queues and mailboxes.
 * - The bridge's receive thread decodes and checks commands; its publishing thread sends
 *   the feedback; its report thread sends the state, session and status and writes the
 *   journal; its mesh thread (mesh_hz > 0) skins the scene. None of them ever waits for
 *   the driving thread, nor it for them.
 * - ent_lcm_bridge_create, _start, _stop and _destroy are made by one controlling thread
 *   (not concurrently). ent_lcm_bridge_stats, _notify, _feed_command, ent_lcm_last_error,
 *   ent_lcm_version, ent_lcm_monotonic_ns and ent_lcm_check_message are safe from any
 *   thread.
 * - The bridge's scene (ent_lcm_bridge_scene) may be queried and skinned from any thread
 *   (enteron.h); only the bridge drives it: never call ent_scene_step, ent_tool_* or
 *   ent_scene_add_obstacle on it, or the journal no longer replays.
 *
 * Logging: the bridge logs (rejected commands, watchdog trips, journal trouble) through the
 * log callback of the desc's ent_callbacks, which the scene also uses. Calls never overlap;
 * they come from the bridge's threads or the thread of the failing call; lines the scene
 * logs during a tick are queued and handed over by the report thread, so that the tick
 * never waits on the callback. Rejections are logged once per reason and then summed once
 * a second, so that a flood of bad commands cannot flood the log.
 *
 * Typical use, with the bridge's own threads (the server, apps/lcm, does this):
 * @code
 *   ent_lcm_bridge_desc desc;
 *   ent_lcm_bridge_desc_default(&desc);
 *   desc.scene_json = json;
 *   desc.scene_json_length = strlen(json);
 *   ent_lcm_bridge* bridge = NULL;
 *   if (ent_lcm_bridge_create(&desc, &bridge) != ENT_OK ||
 *       ent_lcm_bridge_start(bridge) != ENT_OK) {
 *       fprintf(stderr, "enteron_lcm: %s\n", ent_lcm_last_error());
 *       return 1;
 *   }
 *   ... until asked to stop ...
 *   ent_lcm_bridge_destroy(bridge);
 * @endcode
 * On the host's own 1 kHz thread instead of ent_lcm_bridge_start:
 * @code
 *   for (;;) {
 *       ent_lcm_bridge_tick(bridge, ent_lcm_monotonic_ns());
 *       ent_lcm_bridge_notify(bridge);          // hand the feedback to the publisher
 *       ... sleep until the next tick ...
 *   }
 * @endcode
 */
#ifndef ENTERON_ENTERON_LCM_H
#define ENTERON_ENTERON_LCM_H

#include <enteron/enteron.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------------------ */
/* Version and errors                                                                   */
/* ------------------------------------------------------------------------------------ */

/**
 * The version of libenteron_lcm actually loaded, packed like ENT_VERSION (the bridge and
 * the core are released together, so it equals the ENT_VERSION of this header).
 * Thread-safe; never fails.
 */
ENT_API uint32_t ent_lcm_version(void);

/**
 * The message of the last failing ent_lcm_* call on the calling thread, naming the bad
 * input ("desc.watchdog_s must be > 0, got 0"); it carries libenteron's own message when
 * the failure came from the core (a bad scene JSON). "" if no ent_lcm_* call has failed on
 * this thread. Owned by the library; valid until the next failing ent_lcm_* call on this
 * thread. (ent_last_error() keeps reporting libenteron's own calls.)
 */
ENT_API const char* ent_lcm_last_error(void);

/**
 * CLOCK_MONOTONIC in nanoseconds: the bridge's clock. Pass it to ent_lcm_bridge_tick and
 * ent_lcm_bridge_feed_command; the receive thread stamps commands with it. Staleness and
 * command ages are judged on this clock only, never by comparing two hosts' clocks.
 * Thread-safe; no system call on Linux (vDSO).
 */
ENT_API int64_t ent_lcm_monotonic_ns(void);

/* ------------------------------------------------------------------------------------ */
/* Bridge description                                                                   */
/* ------------------------------------------------------------------------------------ */

/** The default LCM URL: multicast on the local host only (ttl=0). */
#define ENT_LCM_DEFAULT_URL "udpm://239.255.76.67:7667?ttl=0"

/**
 * Everything needed to create a bridge. Fill it with ent_lcm_bridge_desc_default, change
 * what you need, then call ent_lcm_bridge_create; no reference to it (or to the strings
 * it points to) is kept after the call.
 *
 * The workspace mapping takes a device's poses into the scene and the forces back:
 *   p_scene = workspace_offset_m + workspace_scale * R p_device
 *   q_scene = q_R * q_device                                  (orientations)
 *   F_device = force_scale * R^T F_scene                       (forces)
 *   T_device = force_scale / workspace_scale * R^T T_scene     (torques: force x length units)
 *   K_device = force_scale * workspace_scale * R^T K_scene R   (stiffness)
 * with R the rotation of workspace_rotation_wxyz (device axes into scene axes). A device
 * reporting millimetres in its own axes sets workspace_scale 0.001 and the rotation.
 */
typedef struct ent_lcm_bridge_desc {
    uint32_t struct_size;               /**< sizeof(ent_lcm_bridge_desc); set by ent_lcm_bridge_desc_default. */
    /** The scene, JSON v1 (docs/scene-json.md); the bridge creates and owns it. Required. */
    const char* scene_json;
    size_t scene_json_length;           /**< bytes of scene_json (need not be NUL-terminated). */
    /** Log and allocator hooks for the scene and the bridge's log lines; NULL: silent, malloc/free. */
    const ent_callbacks* callbacks;
    /** LCM provider URL; NULL: ENT_LCM_DEFAULT_URL; "": no LCM at all (commands only through
     *  ent_lcm_bridge_feed_command, feedback only through ent_lcm_bridge_feedback). */
    const char* lcm_url;
    const char* channel_suffix;         /**< appended to every channel name; NULL: "" (default). */
    /** LCM log file (lcm_eventlog) to write the journal into: the session, then what the scene
     *  was given at every tick (docs/lcm.md). NULL: no journal (default). */
    const char* journal_path;

    double tick_s;                      /**< physics period and step, s, in (0, 0.1] (default 0.001). */
    double watchdog_s;                  /**< no command for this long: zero force, tool held, STALE; in (0, 10] (default 0.030). */
    double state_hz;                    /**< scene_state_t rate, Hz, 0 to 1000; 0: none (default 60). */
    uint32_t state_axis_points;         /**< axis points in each scene_state_t, 2 to 100000 (default 200). */
    double mesh_hz;                     /**< mesh_t rate, Hz, 0 to 100; 0: none (default 0: a mesh is ~1 MB). */
    int32_t mesh_skin_method;           /**< ENT_SKIN_* of the mesh (default ENT_SKIN_CONVOLUTION). */

    double force_ramp_s;                /**< after a stop (stale, deadman, no command, unstable) the force ramps back in over this, s, 0 to 10 (default 0.1). */
    double max_tool_speed_m_per_s;      /**< the tool moves toward the command at most this fast, scene frame, > 0 (default 1). */
    double max_tool_angular_speed_rad_per_s; /**< and turns at most this fast, > 0 (default 10). */
    double device_max_force;            /**< clamp of |F_device|, device force units, >= 0; 0: only the tools' max_force (default 0). */
    double max_force_change_per_tick;   /**< largest change of F_device from one tick to the next, >= 0; 0: unlimited (default 0).
                                             Never delays a drop to zero force. */

    double workspace_scale;             /**< scene metres per device length unit, > 0 (default 1). */
    double workspace_rotation_wxyz[4];  /**< device axes into scene axes, a non-zero quaternion, normalised by the library (default 1, 0, 0, 0). */
    double workspace_offset_m[3];       /**< scene position of the device's origin, m (default 0, 0, 0). */
    double force_scale;                 /**< device force units per newton, > 0 (default 1). */

    /** SCHED_FIFO priority (1 to 99) of the physics thread of ent_lcm_bridge_start; the receive
     *  and publishing threads (and the socket thread LCM starts for the receive thread) get one
     *  less: every thread on the command-to-feedback path. 0: normal scheduling (default).
     *  Without the privilege the threads log a warning and run normally. */
    int32_t realtime_priority;
} ent_lcm_bridge_desc;

/**
 * Fills the first struct_size bytes of *desc with the defaults listed above and sets
 * desc->struct_size; nothing past struct_size is written. Call it through
 * ent_lcm_bridge_desc_default, which passes the size of the header the program was built with.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (desc NULL); ENT_ERROR_VERSION (unknown size).
 */
ENT_API ent_status ent_lcm_bridge_desc_init(ent_lcm_bridge_desc* desc, uint32_t struct_size);

/** Fills *desc with the defaults listed above and sets struct_size. NULL is ignored. */
#define ent_lcm_bridge_desc_default(desc) \
    ((void)ent_lcm_bridge_desc_init((desc), (uint32_t)sizeof(ent_lcm_bridge_desc)))

/* ------------------------------------------------------------------------------------ */
/* Bridge                                                                               */
/* ------------------------------------------------------------------------------------ */

/** A scene served over LCM. Opaque; made by ent_lcm_bridge_create. */
typedef struct ent_lcm_bridge ent_lcm_bridge;

/**
 * Creates the scene from desc->scene_json, opens LCM (unless lcm_url is "") and the
 * journal (if asked), subscribes to ENTERON_TOOL_COMMAND<suffix> and starts the receive,
 * publishing and report threads (and the mesh thread when mesh_hz > 0). Publishes the
 * session at once. Ticks are run by the caller (ent_lcm_bridge_tick) until
 * ent_lcm_bridge_start hands them to the bridge's own physics thread.
 * @param out_bridge receives the bridge; untouched on failure.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, a setting out of range, an LCM URL that
 *         LCM refuses, a journal that cannot be created: the message names the field);
 *         ENT_ERROR_VERSION (struct_size); ENT_ERROR_PARSE or ENT_ERROR_INVALID_SCENE (the
 *         scene JSON, with libenteron's message); ENT_ERROR_OUT_OF_MEMORY. Nothing is left
 *         running or open on failure.
 */
ENT_API ent_status ent_lcm_bridge_create(const ent_lcm_bridge_desc* desc, ent_lcm_bridge** out_bridge);

/**
 * Stops the bridge's threads (the physics thread too, if started), publishes a last
 * status, closes the journal (it then ends with its end record), LCM and the scene.
 * Returns within about 100 ms. NULL is ignored.
 * @warning No other call on this bridge (or its scene) may run during or after this one.
 */
ENT_API void ent_lcm_bridge_destroy(ent_lcm_bridge* bridge);

/**
 * The bridge's scene, for queries and skins from any thread (never to drive: see
 * "Threads" above). Valid until ent_lcm_bridge_destroy. NULL if bridge is NULL.
 */
ENT_API ent_scene* ent_lcm_bridge_scene(ent_lcm_bridge* bridge);

/**
 * The LCM instance (an lcm_t*) of the bridge, for peers in the same process, which is the
 * only way to reach a memq:// bridge: lcm_publish on it, and subscribe on it (the handlers
 * then run on the bridge's receive thread; never call lcm_handle on it yourself). Valid
 * until ent_lcm_bridge_destroy.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (lcm_url was "").
 */
ENT_API ent_status ent_lcm_bridge_lcm(ent_lcm_bridge* bridge, void** out_lcm);

/**
 * One physics tick, on the driving thread: for every tool, takes the newest accepted
 * command, applies the safety rules and sets the tool's pose and grasp; steps the scene by
 * tick_s; reads every tool's wrench; queues one tool_feedback_t per tool for the
 * publishing thread and the journal entries for the report thread. now_ns is the
 * bridge's clock (ent_lcm_monotonic_ns) at the tick: the watchdog and the command ages are
 * judged against it. Makes no system call and allocates nothing after the first ticks.
 * A step that fails (ENT_ERROR_UNSTABLE) is a tick like the others: zero force,
 * STATUS_UNSTABLE; it is still ENT_OK here.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL; the bridge was started: its physics
 *         thread ticks); ENT_ERROR_INTERNAL (a call into the scene failed unexpectedly).
 */
ENT_API ent_status ent_lcm_bridge_tick(ent_lcm_bridge* bridge, int64_t now_ns);

/**
 * Wakes the publishing thread to send what the last ticks queued: one non-blocking
 * system call (a futex wake), never a wait. Call it after ent_lcm_bridge_tick, outside the
 * tick's critical part (the physics thread of ent_lcm_bridge_start does it before it
 * sleeps). Without it the queued feedback still goes out within a millisecond: the
 * publishing thread also wakes every millisecond. Any thread; NULL is ignored.
 */
ENT_API void ent_lcm_bridge_notify(ent_lcm_bridge* bridge);

/**
 * Starts the bridge's physics thread: one tick every tick_s on an absolute-deadline
 * clock (CLOCK_MONOTONIC, TIMER_ABSTIME). A tick that ends after its deadline counts a
 * missed deadline, and the schedule restarts from that moment (no burst of late ticks).
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL, already started);
 *         ENT_ERROR_INTERNAL (the thread could not be created).
 */
ENT_API ent_status ent_lcm_bridge_start(ent_lcm_bridge* bridge);

/**
 * Stops the physics thread of ent_lcm_bridge_start, within one tick; the other threads keep
 * running and the caller may tick again. Not started: no effect.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL).
 */
ENT_API ent_status ent_lcm_bridge_stop(ent_lcm_bridge* bridge);

/**
 * Hands the bridge the bytes of one message as if it had arrived on ENTERON_TOOL_COMMAND,
 * at received_ns on the bridge's clock: what tests and fuzzers use instead of a network.
 * The bytes go through every check a received command goes through (exact encoded size,
 * fingerprint, finite values, non-zero quaternion, existing tool, 0/1 levels, increasing
 * seq); a rejected command is counted by reason and logged, never applied, and the tool's
 * feedback carries STATUS_COMMANDS_REJECTED with the reason for the watchdog time
 * (docs/lcm.md). Any thread; calls are serialised with the receive thread, never with the
 * tick.
 * @return ENT_OK when accepted; ENT_ERROR_INVALID_ARGUMENT (NULL bridge, or bytes NULL
 *         with size > 0, or the command was rejected: the message says why).
 */
ENT_API ent_status ent_lcm_bridge_feed_command(ent_lcm_bridge* bridge, const void* bytes, size_t size,
                                              int64_t received_ns);

/**
 * The last feedback of a tool, encoded exactly as it was (or would have been) published:
 * a tool_feedback_t with its fingerprint, to decode with the generated types. Before the
 * first tick: ENT_ERROR_NOT_FOUND. Allocates nothing.
 * @param capacity bytes available at buffer; *out_size receives the encoded size (also
 *        when it is too small). out_size may be NULL.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_NOT_FOUND (unknown tool, no
 *         tick yet); ENT_ERROR_BUFFER_TOO_SMALL.
 * @warning Call from the driving thread (it reads what the tick wrote).
 */
ENT_API ent_status ent_lcm_bridge_feedback(const ent_lcm_bridge* bridge, int32_t tool, void* buffer,
                                          size_t capacity, size_t* out_size);

/** Counters of a bridge since its creation (the fields of server_status_t). */
typedef struct ent_lcm_stats {
    uint32_t struct_size;               /**< set by the caller to sizeof(ent_lcm_stats). */
    int64_t session_id;                 /**< random per bridge, as in session_t. */
    int64_t ticks;                      /**< ticks run. */
    double sim_time_s;                  /**< simulated time after the last tick. */
    int64_t missed_deadlines;           /**< ticks of the physics thread that ended after their deadline. */
    int64_t commands_received;          /**< messages on ENTERON_TOOL_COMMAND or fed in, accepted or not. */
    int64_t commands_accepted;
    int64_t commands_coalesced;         /**< accepted, then replaced by a newer one before a tick took it. */
    int64_t rejected_size;              /**< encoded size is not tool_command_t's. */
    int64_t rejected_fingerprint;       /**< not a tool_command_t. */
    int64_t rejected_not_finite;        /**< a NaN or infinite number. */
    int64_t rejected_zero_quaternion;
    int64_t rejected_unknown_tool;
    int64_t rejected_sequence;          /**< seq not larger than the last accepted one of that tool. */
    int64_t rejected_out_of_range;      /**< grasp or force_enable not 0 or 1, a position beyond 1 km once mapped. */
    int64_t sequence_gaps;              /**< accepted commands whose seq skipped some. */
    int64_t commands_missed;            /**< the seqs skipped, in total. */
    int64_t watchdog_trips;             /**< times a tool went stale. */
    int64_t step_failures;              /**< steps that returned an error. */
    int32_t step_us_median;             /**< physics step wall time over the last full second, us. */
    int32_t step_us_max;
    int32_t tick_us_max;                /**< whole tick over the last full second, us (own physics thread only). */
    int64_t feedback_published;
    int64_t feedback_dropped;           /**< the publisher's queue was full. */
    int64_t journal_entries;            /**< ticks written to the journal. */
    int64_t journal_dropped;            /**< ticks the journal lost: its queue was full or its file could not be written (the replay stops there). */
    int64_t log_lines_dropped;          /**< lines logged during ticks that the queue to the callback could not hold. */
} ent_lcm_stats;

/**
 * Copies the bridge's counters into *out. Set out->struct_size first; fields beyond an
 * older, smaller struct_size are not written. Any thread; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (NULL); ENT_ERROR_VERSION (struct_size).
 */
ENT_API ent_status ent_lcm_bridge_stats(const ent_lcm_bridge* bridge, ent_lcm_stats* out);

/* ------------------------------------------------------------------------------------ */
/* Checking received bytes before decoding them                                         */
/* ------------------------------------------------------------------------------------ */

/** The message types of bindings/lcm (ent_lcm_check_message). Passed as int32_t. */
#define ENT_LCM_TOOL_COMMAND 0
#define ENT_LCM_TOOL_FEEDBACK 1
#define ENT_LCM_SCENE_STATE 2
#define ENT_LCM_MESH 3
#define ENT_LCM_SESSION 4
#define ENT_LCM_SERVER_STATUS 5
#define ENT_LCM_JOURNAL_TOOL 6
#define ENT_LCM_JOURNAL_STEP 7

/**
 * Whether bytes received from a network or read from a file are exactly one message of
 * the given type: its fingerprint, and a size equal to what its array counts and string
 * length say (counts not negative, the string NUL-terminated). The decoders lcm-gen 1.3.1
 * writes trust the counts inside a message (a hostile count makes the C decoder allocate
 * up to 2^64 bytes); decode only what passed this check. Any thread; allocates nothing.
 * @return ENT_OK; ENT_ERROR_INVALID_ARGUMENT (bytes NULL with size > 0, or not such a
 *         message: the message says what is wrong); ENT_ERROR_NOT_FOUND (unknown type).
 */
ENT_API ent_status ent_lcm_check_message(int32_t type, const void* bytes, size_t size);

/* ------------------------------------------------------------------------------------ */
/* Journal replay                                                                       */
/* ------------------------------------------------------------------------------------ */

/** What ent_lcm_replay_journal found. */
typedef struct ent_lcm_replay_result {
    uint32_t struct_size;               /**< set by the caller to sizeof(ent_lcm_replay_result). */
    int32_t identical;                  /**< 1 if every replayed tick reached the journal's state digest, bit for bit. */
    int64_t ticks;                      /**< ticks replayed and compared. */
    int64_t first_difference_tick;      /**< the first tick that differs (or whose entry is damaged); -1 if none. */
    int64_t journal_digest;             /**< the journal's state digest at that tick. */
    int64_t replay_digest;              /**< the replay's at that tick. */
    int32_t complete;                   /**< 1 if the journal ends with its end record (the session stopped cleanly). */
    char message[256];                  /**< one line saying what was found, for people. */
} ent_lcm_replay_result;

/**
 * Re-creates the scene of a journal (its session entry) and replays every tick exactly as
 * the journal says the scene was given it, comparing the state digest after every step.
 * Stops at the first difference or damaged entry. Logs through callbacks (may be NULL).
 * @return ENT_OK (see out->identical); ENT_ERROR_INVALID_ARGUMENT (NULL, a file that cannot
 *         be read or is not a journal: no session entry first); ENT_ERROR_VERSION
 *         (out->struct_size); a scene creation error (the session's JSON).
 */
ENT_API ent_status ent_lcm_replay_journal(const char* path, const ent_callbacks* callbacks,
                                         ent_lcm_replay_result* out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* ENTERON_ENTERON_LCM_H */
