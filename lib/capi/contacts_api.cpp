// SPDX-License-Identifier: Apache-2.0
// The contact entry points of the C API: the published contact list, the bowel's summary
// (largest force and stretch) and each tool's touches. Queries of the last published
// snapshot, from any thread: they pin it only while they copy.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "capi/call_guard.h"
#include "capi/scene_handle.h"
#include "capi/struct_size.h"
#include "collision/contact_log.h"
#include "spline/arc_length.h"

namespace {

using enteron::Error;
using enteron::ErrorCode;
using enteron::capi::SceneHandle;
using enteron::capi::guarded;
using enteron::capi::SceneCall;
using enteron::capi::require;
using enteron::collision::ContactKind;
using enteron::collision::ContactRecord;
using enteron::scene::ContactTotals;
using enteron::scene::Snapshot;

// The position u in [0, 1] of a collision sphere.
double u_of(uint32_t sphere, const ContactTotals& totals) {
    return totals.spheres > 1 ? double(sphere) / double(totals.spheres - 1) : 0.0;
}

// The kind of the k-th listed contact: the list holds the tools', the obstacles', then the
// self-contacts' (Scene::publish_contacts).
ContactKind kind_of(std::size_t k, const ContactTotals& totals) {
    const std::size_t tools = totals.listed[static_cast<std::size_t>(ContactKind::tool)];
    const std::size_t obstacles = totals.listed[static_cast<std::size_t>(ContactKind::obstacle)];
    if (k < tools) return ContactKind::tool;
    return k < tools + obstacles ? ContactKind::obstacle : ContactKind::self;
}

ent_contact to_ent_contact(const ContactRecord& record, ContactKind kind, const ContactTotals& totals) {
    ent_contact c{};
    c.kind = static_cast<int32_t>(kind);
    c.index = kind == ContactKind::self ? -1 : static_cast<int32_t>(record.other);
    c.u = u_of(record.sphere, totals);
    c.other_u = kind == ContactKind::self ? u_of(record.other, totals) : -1.0;
    for (int i = 0; i < 3; ++i) {
        c.point_m[i] = record.point[i];
        c.normal[i] = record.normal[i];
        c.force_N[i] = record.force[i];
    }
    c.depth_m = record.depth;
    return c;
}

}  // namespace

extern "C" {

ENT_API ent_status ent_scene_contacts(const ent_scene* scene, uint32_t capacity, ent_contact* out,
                                      uint32_t* out_count) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out_count, "out_count");
        // The sizes of ent_contact in released headers: only the current one so far.
        if (out != nullptr) enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_contact)}, "out[0] (ent_contact)");
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        const uint32_t count = static_cast<uint32_t>(snapshot->contacts.size());
        if (out != nullptr && capacity < count) {
            *out_count = count;
            throw Error(ErrorCode::buffer_too_small, "capacity is " + std::to_string(capacity) +
                                                         " contacts, the last step listed " + std::to_string(count) +
                                                         " (ent_contact_summary.capacity is the most a step lists)");
        }
        *out_count = count;
        if (out == nullptr) return;
        const std::size_t stride = out->struct_size;
        auto* bytes = reinterpret_cast<unsigned char*>(out);
        for (std::size_t k = 0; k < count; ++k) {
            ent_contact c = to_ent_contact(snapshot->contacts[k], kind_of(k, snapshot->contact_totals),
                                           snapshot->contact_totals);
            c.struct_size = static_cast<uint32_t>(stride);
            std::memcpy(bytes + k * stride, &c, stride);
        }
    });
}

ENT_API ent_status ent_scene_contact_summary(const ent_scene* scene, ent_contact_summary* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_contact_summary)}, "ent_contact_summary");
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        const ContactTotals& totals = snapshot->contact_totals;
        ent_contact_summary full{};
        full.struct_size = out->struct_size;
        full.capacity = static_cast<uint32_t>(snapshot->contacts.capacity());
        full.listed = static_cast<uint32_t>(snapshot->contacts.size());
        full.self_contacts = totals.found[static_cast<std::size_t>(ContactKind::self)];
        full.obstacle_contacts = totals.found[static_cast<std::size_t>(ContactKind::obstacle)];
        full.tool_contacts = totals.found[static_cast<std::size_t>(ContactKind::tool)];
        full.found = full.self_contacts + full.obstacle_contacts + full.tool_contacts;
        full.largest_force_N = totals.largest_force;
        full.largest_force_u = full.found > 0 ? u_of(totals.largest_force_sphere, totals) : 0.0;
        const std::size_t points = handle.published->control_points();
        const double rest_segment = snapshot->stats.rest_length / double(points - 1);
        const enteron::spline::SegmentStretch stretch =
            enteron::spline::largest_segment_stretch(snapshot->control_points.data(), points, rest_segment,
                                                     handle.published->ends());
        full.largest_stretch = stretch.stretch;
        full.largest_stretch_u = stretch.u;
        full.time_s = snapshot->stats.time;
        full.steps = snapshot->stats.steps;
        std::memcpy(out, &full, out->struct_size);
    });
}

ENT_API ent_status ent_tool_read_contacts(const ent_scene* scene, int32_t tool, ent_tool_contacts* out) {
    return guarded([&] {
        const SceneCall call(scene);
        const SceneHandle& handle = call.handle();
        require(out, "out");
        enteron::capi::check_struct_size(out->struct_size, {sizeof(ent_tool_contacts)}, "ent_tool_contacts");
        if (out->ranges_u == nullptr && out->range_capacity > 0)
            throw Error(ErrorCode::invalid_argument, "ranges_u is NULL with a range_capacity of " +
                                                         std::to_string(out->range_capacity));
        const enteron::scene::SnapshotPublisher::Reader snapshot(*handle.published);
        if (tool < 0 || static_cast<std::size_t>(tool) >= snapshot->tools.size())
            throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " does not exist (the scene has " +
                                                  std::to_string(snapshot->tools.size()) + " tools)");
        const enteron::collision::ToolOutput& output = snapshot->tools[static_cast<std::size_t>(tool)];
        if (output.removed) throw Error(ErrorCode::not_found, "tool " + std::to_string(tool) + " was removed");
        const ContactTotals& totals = snapshot->contact_totals;
        ent_tool_contacts full{};
        full.struct_size = out->struct_size;
        full.range_capacity = out->range_capacity;
        full.ranges_u = out->ranges_u;
        full.contacts = output.contacts;
        full.grasping = output.grasping ? 1 : 0;
        full.grasp_u = output.grasping ? u_of(output.grasp_sphere, totals) : -1.0;
        for (int c = 0; c < 3; ++c) full.contact_impulse_Ns[c] = output.contact_impulse[c];
        full.contact_impulse_magnitude_Ns = output.contact_impulse_magnitude;
        full.time_s = snapshot->stats.time;
        full.steps = snapshot->stats.steps;
        // The tool's contacts come first in the list, tool by tool, each along the bowel:
        // runs of consecutive spheres are the ranges it touches.
        const std::size_t tools_listed = totals.listed[static_cast<std::size_t>(ContactKind::tool)];
        double largest_squared = 0.0;
        uint32_t previous = 0;
        for (std::size_t k = 0; k < tools_listed; ++k) {
            const ContactRecord& record = snapshot->contacts[k];
            if (record.other != static_cast<uint32_t>(tool)) continue;
            largest_squared = std::max(largest_squared, record.force.squaredNorm());
            const bool extends = full.range_count > 0 && record.sphere == previous + 1;
            previous = record.sphere;
            if (!extends) full.range_count += 1;
            const std::size_t range = full.range_count - 1;
            if (range >= full.range_capacity) continue;
            const double u = u_of(record.sphere, totals);
            if (!extends) full.ranges_u[2 * range] = u;
            full.ranges_u[2 * range + 1] = u;
        }
        full.largest_force_N = std::sqrt(largest_squared);
        std::memcpy(out, &full, out->struct_size);
    });
}

}  // extern "C"
