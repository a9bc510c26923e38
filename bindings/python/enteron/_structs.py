# SPDX-License-Identifier: Apache-2.0
"""ctypes mirrors of the structs in include/enteron/enteron.h (this binding's header: 0.1).

Every struct starts with struct_size, so a newer library serves this layout unchanged
and a field appended later simply is not seen here. The test test_layout compares each
size and offset with the C compiler's.
"""
import ctypes

LOG_FUNCTION = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int32, ctypes.c_char_p)
ALLOCATE_FUNCTION = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t)
RELEASE_FUNCTION = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t)

_vec3 = ctypes.c_double * 3


class ent_callbacks(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("log", LOG_FUNCTION),
        ("allocate", ALLOCATE_FUNCTION),
        ("release", RELEASE_FUNCTION),
        ("user_data", ctypes.c_void_p),
    ]


class ent_scene_desc(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("effects", ctypes.c_uint32),
        ("length_m", ctypes.c_double),
        ("radius_m", ctypes.c_double),
        ("control_points", ctypes.c_uint32),
        ("linear_density_kg_per_m", ctypes.c_double),
        ("stretch_stiffness_N", ctypes.c_double),
        ("bend_stiffness_N_m2", ctypes.c_double),
        ("shape", ctypes.c_int32),
        ("shape_center_m", _vec3),
        ("shape_direction", _vec3),
        ("shape_leg_length_m", ctypes.c_double),
        ("shape_leg_spacing_m", ctypes.c_double),
        ("shape_helix_radius_m", ctypes.c_double),
        ("shape_helix_pitch_m", ctypes.c_double),
        ("shape_points_xyz_m", ctypes.POINTER(ctypes.c_double)),
        ("integrator", ctypes.c_int32),
        ("timestep_s", ctypes.c_double),
        ("max_substeps", ctypes.c_uint32),
        ("max_subdivisions", ctypes.c_uint32),
        ("max_speed_m_per_s", ctypes.c_double),
        ("gravity_m_per_s2", _vec3),
        ("drag_N_s_per_m2", ctypes.c_double),
        ("stretch_damping_N_s", ctypes.c_double),
        ("bend_damping_N_m2_s", ctypes.c_double),
        ("mesentery_root_start_m", _vec3),
        ("mesentery_root_end_m", _vec3),
        ("mesentery_attachments", ctypes.c_uint32),
        ("mesentery_stiffness_N_per_m", ctypes.c_double),
        ("mesentery_rest_length_m", ctypes.c_double),
        ("pinned_ends", ctypes.c_int32),
        ("pinned_points", ctypes.POINTER(ctypes.c_uint32)),
        ("pinned_point_count", ctypes.c_uint32),
        ("callbacks", ctypes.POINTER(ent_callbacks)),
        ("collision_sphere_spacing_m", ctypes.c_double),
        ("contact_stiffness_N_per_m", ctypes.c_double),
        ("contact_damping_N_s_per_m", ctypes.c_double),
        ("contact_friction", ctypes.c_double),
        ("contact_slip_speed_m_per_s", ctypes.c_double),
        ("clamped_ends", ctypes.c_int32),
        ("radius_profile_m", ctypes.POINTER(ctypes.c_double)),
        ("radius_profile_count", ctypes.c_uint32),
        ("linear_density_profile_kg_per_m", ctypes.POINTER(ctypes.c_double)),
        ("linear_density_profile_count", ctypes.c_uint32),
        ("stretch_stiffness_profile_N", ctypes.POINTER(ctypes.c_double)),
        ("stretch_stiffness_profile_count", ctypes.c_uint32),
        ("bend_stiffness_profile_N_m2", ctypes.POINTER(ctypes.c_double)),
        ("bend_stiffness_profile_count", ctypes.c_uint32),
        ("mesentery_root_points_m", ctypes.POINTER(ctypes.c_double)),
        ("mesentery_root_point_count", ctypes.c_uint32),
        ("mesentery_root_mapping", ctypes.POINTER(ctypes.c_double)),
        ("mesentery_root_mapping_count", ctypes.c_uint32),
        ("pinned_spans_m", ctypes.POINTER(ctypes.c_double)),
        ("pinned_span_count", ctypes.c_uint32),
    ]


class ent_stats(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("control_points", ctypes.c_uint32),
        ("time_s", ctypes.c_double),
        ("steps", ctypes.c_uint64),
        ("substeps", ctypes.c_uint64),
        ("rollbacks", ctypes.c_uint64),
        ("kinetic_energy_J", ctypes.c_double),
        ("potential_energy_J", ctypes.c_double),
        ("contacts", ctypes.c_uint32),
        ("max_penetration_m", ctypes.c_double),
        ("last_step_ns", ctypes.c_uint64),
        ("last_step_attempts", ctypes.c_uint32),
        ("last_step_substeps", ctypes.c_uint32),
        ("last_step_proxy_iterations", ctypes.c_uint32),
        ("last_step_proxy_evaluations", ctypes.c_uint32),
        ("max_step_ns", ctypes.c_uint64),
        ("late_steps", ctypes.c_uint64),
        ("subdivided_steps", ctypes.c_uint64),
        ("proxy_unbalanced_solves", ctypes.c_uint64),
        ("full_contact_searches", ctypes.c_uint64),
    ]


class ent_effect_stats(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("enabled", ctypes.c_int32),
        ("calls", ctypes.c_uint64),
        ("total_time_ns", ctypes.c_uint64),
    ]


class ent_skin_desc(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("method", ctypes.c_int32),
        ("segments", ctypes.c_uint32),
        ("ring_spacing_radii", ctypes.c_double),
        ("cap_rings", ctypes.c_uint32),
        ("skeleton_spacing_radii", ctypes.c_double),
        ("voxel_size_radii", ctypes.c_double),
        ("window_radii", ctypes.c_double),
        ("ring_chord_error_radii", ctypes.c_double),
        ("stable_topology", ctypes.c_int32),
        ("contact_surfaces", ctypes.c_int32),
        ("skeleton_chord_error_radii", ctypes.c_double),
    ]


class ent_mesh_view(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("vertex_count", ctypes.c_uint32),
        ("triangle_count", ctypes.c_uint32),
        # Addresses (c_void_p, not POINTER(c_float)) so the binding can view them with numpy.
        ("positions_xyz_m", ctypes.c_void_p),
        ("normals_xyz", ctypes.c_void_p),
        ("axis_u", ctypes.c_void_p),
        ("indices", ctypes.c_void_p),
        ("time_s", ctypes.c_double),
        ("updates", ctypes.c_uint64),
        ("around_v", ctypes.c_void_p),
        ("tangents_xyz", ctypes.c_void_p),
        ("topology_serial", ctypes.c_uint64),
        ("topology_changed", ctypes.c_int32),
        ("stable_topology", ctypes.c_int32),
    ]


class ent_skin_metrics(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("vertex_count", ctypes.c_uint32),
        ("triangle_count", ctypes.c_uint32),
        ("watertight", ctypes.c_int32),
        ("open_edges", ctypes.c_uint32),
        ("nonmanifold_edges", ctypes.c_uint32),
        ("blended_vertices", ctypes.c_uint32),
        ("inverted_triangles", ctypes.c_uint32),
        ("radius_error_rms", ctypes.c_double),
        ("radius_error_max", ctypes.c_double),
        ("normal_deviation_rms_rad", ctypes.c_double),
        ("normal_deviation_max_rad", ctypes.c_double),
        ("volume_m3", ctypes.c_double),
        ("volume_error", ctypes.c_double),
        ("axis_length_m", ctypes.c_double),
        ("last_update_ns", ctypes.c_uint64),
        ("facet_error_rms", ctypes.c_double),
        ("facet_error_max", ctypes.c_double),
        ("overlap_depth_max", ctypes.c_double),
        ("overlap_area_m2", ctypes.c_double),
        ("tube_overlap_depth_max", ctypes.c_double),
        ("tube_overlap_area_m2", ctypes.c_double),
        ("contact_gap_max", ctypes.c_double),
        ("shape_volume_error", ctypes.c_double),
        ("free_radius_error_rms", ctypes.c_double),
        ("vertex_motion_max", ctypes.c_double),
        ("vertex_excess_motion_max", ctypes.c_double),
        ("free_vertex_count", ctypes.c_uint32),
        ("has_previous_update", ctypes.c_int32),
    ]


class ent_obstacle_desc(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("kind", ctypes.c_int32),
        ("center_m", _vec3),
        ("half_extents_m", _vec3),
        ("normal", _vec3),
        ("start_m", _vec3),
        ("end_m", _vec3),
        ("radius_m", ctypes.c_double),
        ("mesh_vertices_xyz_m", ctypes.POINTER(ctypes.c_double)),
        ("mesh_vertex_count", ctypes.c_uint32),
        ("mesh_triangles", ctypes.POINTER(ctypes.c_uint32)),
        ("mesh_triangle_count", ctypes.c_uint32),
        ("mesh_voxel_size_m", ctypes.c_double),
        ("position_m", _vec3),
        ("orientation_wxyz", ctypes.c_double * 4),
        ("friction", ctypes.c_double),
    ]


class ent_tool_desc(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("radius_m", ctypes.c_double),
        ("length_m", ctypes.c_double),
        ("max_force_N", ctypes.c_double),
        ("grasp_margin_m", ctypes.c_double),
        ("grasp_stiffness_N_per_m", ctypes.c_double),
        ("grasp_damping_N_s_per_m", ctypes.c_double),
        ("position_m", _vec3),
        ("orientation_wxyz", ctypes.c_double * 4),
        ("mode", ctypes.c_int32),
        ("passivity_limiter", ctypes.c_int32),
        ("coupling_stiffness_N_per_m", ctypes.c_double),
        ("coupling_damping_N_s_per_m", ctypes.c_double),
        ("friction", ctypes.c_double),
        ("jaw_length_m", ctypes.c_double),
        ("jaw_opening_m", ctypes.c_double),
        ("blade_width_m", ctypes.c_double),
        ("blade_length_m", ctypes.c_double),
    ]


class ent_tool_feedback(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("grasping", ctypes.c_int32),
        ("force_N", _vec3),
        ("torque_Nm", _vec3),
        ("contacts", ctypes.c_uint32),
        ("time_s", ctypes.c_double),
        ("steps", ctypes.c_uint64),
        ("stiffness_N_per_m", ctypes.c_double * 9),
        ("proxy_position_m", _vec3),
        ("commanded_position_m", _vec3),
        ("orientation_wxyz", ctypes.c_double * 4),
        ("saturated", ctypes.c_int32),
    ]


class ent_tool_stats(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("grasping", ctypes.c_int32),
        ("contacts", ctypes.c_uint32),
        ("reserved", ctypes.c_uint32),
        ("energy_in_J", ctypes.c_double),
        ("energy_out_J", ctypes.c_double),
        ("limiter_energy_J", ctypes.c_double),
        ("largest_force_change_N", ctypes.c_double),
        ("steps", ctypes.c_uint64),
    ]


class ent_contact(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("kind", ctypes.c_int32),
        ("index", ctypes.c_int32),
        ("u", ctypes.c_double),
        ("other_u", ctypes.c_double),
        ("point_m", _vec3),
        ("normal", _vec3),
        ("depth_m", ctypes.c_double),
        ("force_N", _vec3),
    ]


class ent_contact_summary(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("capacity", ctypes.c_uint32),
        ("listed", ctypes.c_uint32),
        ("found", ctypes.c_uint32),
        ("self_contacts", ctypes.c_uint32),
        ("obstacle_contacts", ctypes.c_uint32),
        ("tool_contacts", ctypes.c_uint32),
        ("largest_force_N", ctypes.c_double),
        ("largest_force_u", ctypes.c_double),
        ("largest_stretch", ctypes.c_double),
        ("largest_stretch_u", ctypes.c_double),
        ("time_s", ctypes.c_double),
        ("steps", ctypes.c_uint64),
    ]


class ent_tool_contacts(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("range_capacity", ctypes.c_uint32),
        ("ranges_u", ctypes.POINTER(ctypes.c_double)),
        ("range_count", ctypes.c_uint32),
        ("contacts", ctypes.c_uint32),
        ("grasping", ctypes.c_int32),
        ("grasp_u", ctypes.c_double),
        ("largest_force_N", ctypes.c_double),
        ("contact_impulse_Ns", _vec3),
        ("contact_impulse_magnitude_Ns", ctypes.c_double),
        ("time_s", ctypes.c_double),
        ("steps", ctypes.c_uint64),
    ]


class ent_exposure_desc(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("points_xyz_m", ctypes.POINTER(ctypes.c_double)),
        ("point_count", ctypes.c_uint32),
        ("triangles", ctypes.POINTER(ctypes.c_uint32)),
        ("triangle_count", ctypes.c_uint32),
        ("weights", ctypes.POINTER(ctypes.c_double)),
        ("samples_per_edge", ctypes.c_uint32),
        ("obstacle", ctypes.c_int32),
        ("axis_chords_per_segment", ctypes.c_uint32),
    ]


class ent_exposure_result(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32),
        ("span_capacity", ctypes.c_uint32),
        ("spans_u", ctypes.POINTER(ctypes.c_double)),
        ("span_hidden_fractions", ctypes.POINTER(ctypes.c_double)),
        ("span_intestines", ctypes.POINTER(ctypes.c_int32)),
        ("element_visible", ctypes.POINTER(ctypes.c_double)),
        ("visible_fraction", ctypes.c_double),
        ("span_count", ctypes.c_uint32),
        ("samples", ctypes.c_uint32),
        ("hidden_samples", ctypes.c_uint32),
        ("time_s", ctypes.c_double),
        ("steps", ctypes.c_uint64),
    ]


ALL = (ent_callbacks, ent_scene_desc, ent_stats, ent_effect_stats, ent_obstacle_desc, ent_tool_desc,
       ent_tool_feedback, ent_tool_stats, ent_skin_desc, ent_mesh_view, ent_skin_metrics, ent_contact,
       ent_contact_summary, ent_tool_contacts, ent_exposure_desc, ent_exposure_result)
