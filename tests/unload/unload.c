// SPDX-License-Identifier: Apache-2.0
/*
 * A host that unloads libenteron (Mono closes its P/Invoke libraries at exit; an editor
 * reloads its plugins) must not crash. Building a mesh obstacle's distance field starts
 * Embree's TBB worker threads, which outlive the call: if dlclose unmapped libenteron and,
 * with it, TBB, those threads would run on unmapped code. So the library is linked with
 * -z nodelete and stays loaded: this program loads it with dlopen, builds a mesh obstacle,
 * destroys the scene, calls dlclose and checks that the library is still there.
 *
 *   enteron_unload LIBRARY     prints "unload: ... still loaded after dlclose"
 */
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <enteron/enteron.h>

#define LOAD(name) \
    name##_function name = (name##_function)dlsym(library, #name); \
    if (!name) { fprintf(stderr, "unload: %s not found: %s\n", #name, dlerror()); return 1; }

typedef ent_status (*ent_scene_create_json_function)(const char*, size_t, ent_scene**);
typedef ent_status (*ent_obstacle_desc_init_function)(ent_obstacle_desc*, uint32_t);
typedef ent_status (*ent_scene_add_obstacle_function)(ent_scene*, const ent_obstacle_desc*, int32_t*);
typedef ent_status (*ent_scene_step_function)(ent_scene*, double);
typedef void (*ent_scene_destroy_function)(ent_scene*);
typedef const char* (*ent_last_error_function)(void);

int main(int argc, char** argv) {
    static const char json[] = "{\"intestine\": {\"length\": 0.3, \"control_points\": 12}}";
    /* A tetrahedron (an organ) away from the bowel, which lies along +x from the origin. */
    static const double vertices[] = {0, 0.3, 0.1, 0.05, 0.3, 0.1, 0, 0.35, 0.1, 0, 0.3, 0.15};
    static const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    void* library;
    ent_scene* scene = NULL;
    ent_obstacle_desc organ;

    if (argc != 2) {
        fprintf(stderr, "usage: enteron_unload LIBRARY\n");
        return 2;
    }
    library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        fprintf(stderr, "unload: %s\n", dlerror());
        return 1;
    }
    {
        LOAD(ent_scene_create_json)
        LOAD(ent_obstacle_desc_init)
        LOAD(ent_scene_add_obstacle)
        LOAD(ent_scene_step)
        LOAD(ent_scene_destroy)
        LOAD(ent_last_error)
        if (ent_scene_create_json(json, strlen(json), &scene) != ENT_OK) {
            fprintf(stderr, "unload: %s\n", ent_last_error());
            return 1;
        }
        ent_obstacle_desc_init(&organ, (uint32_t)sizeof organ);
        organ.kind = ENT_OBSTACLE_MESH;
        organ.mesh_vertices_xyz_m = vertices;
        organ.mesh_vertex_count = 4;
        organ.mesh_triangles = triangles;
        organ.mesh_triangle_count = 4;
        if (ent_scene_add_obstacle(scene, &organ, NULL) != ENT_OK || ent_scene_step(scene, 0.001) != ENT_OK) {
            fprintf(stderr, "unload: %s\n", ent_last_error());
            ent_scene_destroy(scene);
            return 1;
        }
        ent_scene_destroy(scene);
    }
    if (dlclose(library) != 0) {
        fprintf(stderr, "unload: dlclose: %s\n", dlerror());
        return 1;
    }
    if (!dlopen(argv[1], RTLD_NOW | RTLD_NOLOAD)) {
        fprintf(stderr, "unload: FAILED: dlclose unloaded %s (and the TBB its mesh obstacles' threads run in); "
                        "it must be linked with -z nodelete\n", argv[1]);
        return 1;
    }
    printf("unload: a mesh obstacle built, the scene destroyed, %s still loaded after dlclose\n", argv[1]);
    return 0;
}
