/* SPDX-License-Identifier: Apache-2.0 */
/* Prints the size and field offsets of the public structs as the C compiler lays them out,
 * as JSON, for the Python binding's test_layout (which compares its ctypes mirrors). */
#include <enteron/enteron.h>

#include <stddef.h>
#include <stdio.h>

static int first;
/* BEGIN_AS: for a struct used without a typedef (struct ent_skin_metrics), named as its tag. */
#define BEGIN(type) BEGIN_AS(#type, type)
#define BEGIN_AS(name, type)                                                             \
    printf("%s\"%s\": {\"size\": %u, \"fields\": {", first ? "" : ", ", name,          \
           (unsigned)sizeof(type));                                                      \
    first = 0;                                                                           \
    {                                                                                    \
        int first_field = 1;                                                             \
        typedef type current_type;
#define FIELD(name)                                                                      \
    printf("%s\"%s\": [%u, %u]", first_field ? "" : ", ", #name,                        \
           (unsigned)offsetof(current_type, name), (unsigned)sizeof(((current_type*)0)->name)); \
    first_field = 0;
#define END()   \
    }           \
    printf("}}");

int main(void) {
    first = 1;
    printf("{");
    BEGIN(ent_callbacks)
    FIELD(struct_size) FIELD(log) FIELD(allocate) FIELD(release) FIELD(user_data)
    END()
    BEGIN(ent_scene_desc)
    FIELD(struct_size) FIELD(effects) FIELD(length_m) FIELD(radius_m) FIELD(control_points)
    FIELD(linear_density_kg_per_m) FIELD(stretch_stiffness_N) FIELD(bend_stiffness_N_m2) FIELD(shape)
    FIELD(shape_center_m) FIELD(shape_direction) FIELD(shape_leg_length_m) FIELD(shape_leg_spacing_m)
    FIELD(shape_helix_radius_m) FIELD(shape_helix_pitch_m) FIELD(shape_points_xyz_m) FIELD(integrator)
    FIELD(timestep_s) FIELD(max_substeps) FIELD(max_subdivisions) FIELD(max_speed_m_per_s)
    FIELD(gravity_m_per_s2) FIELD(drag_N_s_per_m2) FIELD(stretch_damping_N_s) FIELD(bend_damping_N_m2_s)
    FIELD(mesentery_root_start_m) FIELD(mesentery_root_end_m) FIELD(mesentery_attachments)
    FIELD(mesentery_stiffness_N_per_m) FIELD(mesentery_rest_length_m) FIELD(pinned_ends) FIELD(pinned_points)
    FIELD(pinned_point_count) FIELD(callbacks)
    FIELD(collision_sphere_spacing_m) FIELD(contact_stiffness_N_per_m) FIELD(contact_damping_N_s_per_m)
    FIELD(contact_friction) FIELD(contact_slip_speed_m_per_s) FIELD(clamped_ends)
    FIELD(radius_profile_m) FIELD(radius_profile_count) FIELD(linear_density_profile_kg_per_m)
    FIELD(linear_density_profile_count) FIELD(stretch_stiffness_profile_N) FIELD(stretch_stiffness_profile_count)
    FIELD(bend_stiffness_profile_N_m2) FIELD(bend_stiffness_profile_count)
    FIELD(mesentery_root_points_m) FIELD(mesentery_root_point_count) FIELD(mesentery_root_mapping)
    FIELD(mesentery_root_mapping_count) FIELD(pinned_spans_m) FIELD(pinned_span_count)
    END()
    BEGIN(ent_stats)
    FIELD(struct_size) FIELD(control_points) FIELD(time_s) FIELD(steps) FIELD(substeps) FIELD(rollbacks)
    FIELD(kinetic_energy_J) FIELD(potential_energy_J) FIELD(contacts) FIELD(max_penetration_m)
    FIELD(last_step_ns) FIELD(last_step_attempts) FIELD(last_step_substeps) FIELD(last_step_proxy_iterations)
    FIELD(last_step_proxy_evaluations) FIELD(max_step_ns) FIELD(late_steps) FIELD(subdivided_steps)
    FIELD(proxy_unbalanced_solves) FIELD(full_contact_searches)
    END()
    BEGIN(ent_effect_stats)
    FIELD(struct_size) FIELD(enabled) FIELD(calls) FIELD(total_time_ns)
    END()
    BEGIN(ent_obstacle_desc)
    FIELD(struct_size) FIELD(kind) FIELD(center_m) FIELD(half_extents_m) FIELD(normal) FIELD(start_m)
    FIELD(end_m) FIELD(radius_m) FIELD(mesh_vertices_xyz_m) FIELD(mesh_vertex_count) FIELD(mesh_triangles)
    FIELD(mesh_triangle_count) FIELD(mesh_voxel_size_m) FIELD(position_m) FIELD(orientation_wxyz) FIELD(friction)
    END()
    BEGIN(ent_contact)
    FIELD(struct_size) FIELD(kind) FIELD(index) FIELD(u) FIELD(other_u) FIELD(point_m) FIELD(normal)
    FIELD(depth_m) FIELD(force_N)
    END()
    BEGIN(ent_contact_summary)
    FIELD(struct_size) FIELD(capacity) FIELD(listed) FIELD(found) FIELD(self_contacts) FIELD(obstacle_contacts)
    FIELD(tool_contacts) FIELD(largest_force_N) FIELD(largest_force_u) FIELD(largest_stretch)
    FIELD(largest_stretch_u) FIELD(time_s) FIELD(steps)
    END()
    BEGIN(ent_tool_contacts)
    FIELD(struct_size) FIELD(range_capacity) FIELD(ranges_u) FIELD(range_count) FIELD(contacts) FIELD(grasping)
    FIELD(grasp_u) FIELD(largest_force_N) FIELD(contact_impulse_Ns) FIELD(contact_impulse_magnitude_Ns)
    FIELD(time_s) FIELD(steps)
    END()
    BEGIN(ent_exposure_desc)
    FIELD(struct_size) FIELD(points_xyz_m) FIELD(point_count) FIELD(triangles) FIELD(triangle_count) FIELD(weights)
    FIELD(samples_per_edge) FIELD(obstacle) FIELD(axis_chords_per_segment)
    END()
    BEGIN(ent_exposure_result)
    FIELD(struct_size) FIELD(span_capacity) FIELD(spans_u) FIELD(span_hidden_fractions) FIELD(span_intestines)
    FIELD(element_visible) FIELD(visible_fraction) FIELD(span_count) FIELD(samples) FIELD(hidden_samples)
    FIELD(time_s) FIELD(steps)
    END()
    BEGIN(ent_tool_desc)
    FIELD(struct_size) FIELD(radius_m) FIELD(length_m) FIELD(max_force_N) FIELD(grasp_margin_m)
    FIELD(grasp_stiffness_N_per_m) FIELD(grasp_damping_N_s_per_m) FIELD(position_m) FIELD(orientation_wxyz)
    FIELD(mode) FIELD(passivity_limiter) FIELD(coupling_stiffness_N_per_m) FIELD(coupling_damping_N_s_per_m)
    FIELD(friction) FIELD(jaw_length_m) FIELD(jaw_opening_m) FIELD(blade_width_m) FIELD(blade_length_m)
    END()
    BEGIN(ent_tool_feedback)
    FIELD(struct_size) FIELD(grasping) FIELD(force_N) FIELD(torque_Nm) FIELD(contacts) FIELD(time_s) FIELD(steps)
    FIELD(stiffness_N_per_m) FIELD(proxy_position_m) FIELD(commanded_position_m) FIELD(orientation_wxyz)
    FIELD(saturated)
    END()
    BEGIN(ent_tool_stats)
    FIELD(struct_size) FIELD(grasping) FIELD(contacts) FIELD(reserved) FIELD(energy_in_J) FIELD(energy_out_J)
    FIELD(limiter_energy_J) FIELD(largest_force_change_N) FIELD(steps)
    END()
    BEGIN(ent_skin_desc)
    FIELD(struct_size) FIELD(method) FIELD(segments) FIELD(ring_spacing_radii) FIELD(cap_rings)
    FIELD(skeleton_spacing_radii) FIELD(voxel_size_radii) FIELD(window_radii) FIELD(ring_chord_error_radii)
    FIELD(stable_topology) FIELD(contact_surfaces) FIELD(skeleton_chord_error_radii)
    END()
    BEGIN(ent_mesh_view)
    FIELD(struct_size) FIELD(vertex_count) FIELD(triangle_count) FIELD(positions_xyz_m) FIELD(normals_xyz)
    FIELD(axis_u) FIELD(indices) FIELD(time_s) FIELD(updates) FIELD(around_v) FIELD(tangents_xyz)
    FIELD(topology_serial) FIELD(topology_changed) FIELD(stable_topology)
    END()
    BEGIN_AS("ent_skin_metrics", struct ent_skin_metrics)
    FIELD(struct_size) FIELD(vertex_count) FIELD(triangle_count) FIELD(watertight) FIELD(open_edges)
    FIELD(nonmanifold_edges) FIELD(blended_vertices) FIELD(inverted_triangles) FIELD(radius_error_rms)
    FIELD(radius_error_max) FIELD(normal_deviation_rms_rad) FIELD(normal_deviation_max_rad) FIELD(volume_m3)
    FIELD(volume_error) FIELD(axis_length_m) FIELD(last_update_ns) FIELD(facet_error_rms) FIELD(facet_error_max)
    FIELD(overlap_depth_max) FIELD(overlap_area_m2) FIELD(tube_overlap_depth_max) FIELD(tube_overlap_area_m2)
    FIELD(contact_gap_max) FIELD(shape_volume_error) FIELD(free_radius_error_rms) FIELD(vertex_motion_max)
    FIELD(vertex_excess_motion_max) FIELD(free_vertex_count) FIELD(has_previous_update)
    END()
    printf("}\n");
    return 0;
}
