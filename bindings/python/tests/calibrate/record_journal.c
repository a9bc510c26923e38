/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Records a short LCM session's journal without a network or a device, for the replayed
 * journal experiment of enteron.calibrate (bindings/python/tests/calibrate/test_journal.py): an LCM bridge
 * on a scene file (lcm_url "": commands handed over with ent_lcm_bridge_feed_command),
 * ticked by hand on its own clock, one tool command per tick, as a haptic device would
 * send them. The tool (tool 0 of the scene) moves in y only, from where the scene puts it:
 *
 *   t in [0, 0.2) s    waits (the first tick has no command)
 *   t in [0.2, 0.5) s  goes to y = 4 cm
 *   t in [0.5, 0.9) s  goes across to y = -1 cm
 *   then               holds there
 *
 * With bindings/python/tests/calibrate/pushed_bowel.json (a bowel held at both ends along
 * y = 0, the tool's shaft across its height) it pushes the bowel's middle aside by 2.25 cm.
 *
 *   enteron_record_journal SCENE.json OUT.journal SECONDS
 *
 * Exit 0 with the journal written; 1 with a message naming what failed.
 */
#include <enteron/enteron_lcm.h>
#include <lcmtypes/enteron_tool_command_t.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char* read_file(const char* path, size_t* size) {
    FILE* file = fopen(path, "rb");
    char* text = NULL;
    long length;
    if (file == NULL) return NULL;
    if (fseek(file, 0, SEEK_END) == 0 && (length = ftell(file)) >= 0 && fseek(file, 0, SEEK_SET) == 0) {
        text = malloc((size_t)length + 1);
        if (text != NULL && fread(text, 1, (size_t)length, file) == (size_t)length) {
            text[length] = '\0';
            *size = (size_t)length;
        } else {
            free(text);
            text = NULL;
        }
    }
    fclose(file);
    return text;
}

/* Where the tool's tip is commanded at t (s): the path of the comment above, smoothstep between keys. */
static void tool_path(double t, const double start[3], double out[3]) {
    double from = start[1], to = 0.04, a;
    if (t < 0.2) {
        a = 0.0;
    } else if (t < 0.5) {
        a = (t - 0.2) / 0.3;
    } else {
        from = 0.04;
        to = -0.01;
        a = t < 0.9 ? (t - 0.5) / 0.4 : 1.0;
    }
    a = a * a * (3.0 - 2.0 * a);
    out[0] = start[0];
    out[1] = from + a * (to - from);
    out[2] = start[2];
}

int main(int argc, char** argv) {
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge* bridge = NULL;
    size_t size = 0;
    char* scene;
    long ticks, tick;
    double orientation[4] = {1, 0, 0, 0};
    ent_tool_feedback feedback;
    const int64_t ms = 1000000;
    if (argc != 4 || (ticks = (long)(atof(argv[3]) * 1000.0 + 0.5)) <= 0) {
        fprintf(stderr, "usage: enteron_record_journal SCENE.json OUT.journal SECONDS\n");
        return 1;
    }
    scene = read_file(argv[1], &size);
    if (scene == NULL) {
        fprintf(stderr, "record_journal: cannot read %s\n", argv[1]);
        return 1;
    }
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = scene;
    desc.scene_json_length = size;
    desc.lcm_url = "";
    desc.journal_path = argv[2];
    desc.state_hz = 0.0;
    if (ent_lcm_bridge_create(&desc, &bridge) != ENT_OK) {
        fprintf(stderr, "record_journal: %s\n", ent_lcm_last_error());
        free(scene);
        return 1;
    }
    /* The path starts where the scene puts the tool: where the first tick, without a
     * command, leaves it. */
    memset(&feedback, 0, sizeof feedback);
    feedback.struct_size = sizeof feedback;
    if (ent_lcm_bridge_tick(bridge, ms) != ENT_OK ||
        ent_tool_read_feedback(ent_lcm_bridge_scene(bridge), 0, &feedback) != ENT_OK) {
        fprintf(stderr, "record_journal: the scene has no tool 0: %s\n", ent_last_error());
        ent_lcm_bridge_destroy(bridge);
        free(scene);
        return 1;
    }
    for (tick = 2; tick <= ticks; ++tick) {
        enteron_tool_command_t command;
        uint8_t bytes[512];
        int encoded;
        memset(&command, 0, sizeof command);
        command.utime = tick * 1000;
        command.seq = tick;
        command.tool = 0;
        tool_path(1e-3 * (double)tick, feedback.commanded_position_m, command.position_m);
        memcpy(command.orientation_wxyz, orientation, sizeof orientation);
        command.force_enable = 1;
        encoded = enteron_tool_command_t_encode(bytes, 0, (int)sizeof bytes, &command);
        if (encoded < 0 || ent_lcm_bridge_feed_command(bridge, bytes, (size_t)encoded, tick * ms) != ENT_OK ||
            ent_lcm_bridge_tick(bridge, tick * ms) != ENT_OK) {
            fprintf(stderr, "record_journal: tick %ld: %s\n", tick, ent_lcm_last_error());
            ent_lcm_bridge_destroy(bridge);
            free(scene);
            return 1;
        }
    }
    ent_lcm_bridge_destroy(bridge); /* writes the journal's end record */
    free(scene);
    printf("record_journal: %ld ticks into %s\n", ticks, argv[2]);
    return 0;
}
