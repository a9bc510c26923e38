// SPDX-License-Identifier: Apache-2.0
// Shared by the skin tests of the C API (test_skin*.cpp): an owning skin handle, a skin
// made with the defaults but for the method, its mesh view and its metrics (the current
// struct sizes), each call checked.
#pragma once

#include "capi_test_support.h"

namespace skin_test {

struct SkinDeleter {
    void operator()(ent_skin* skin) const { ent_skin_destroy(skin); }
};
using SkinPtr = std::unique_ptr<ent_skin, SkinDeleter>;

inline SkinPtr make_skin(ent_scene* scene, const ent_skin_desc& desc) {
    ent_skin* skin = nullptr;
    EXPECT_EQ(ent_skin_create(scene, &desc, &skin), ENT_OK) << ent_last_error();
    return SkinPtr(skin);
}

// desc: ent_skin_desc_default, then `method`.
inline SkinPtr make_skin(ent_scene* scene, int32_t method) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    return make_skin(scene, desc);
}

inline struct ent_skin_metrics metrics(const ent_skin* skin) {
    struct ent_skin_metrics m;
    std::memset(&m, 0, sizeof m);
    m.struct_size = sizeof m;
    EXPECT_EQ(ent_skin_metrics(skin, &m), ENT_OK) << ent_last_error();
    return m;
}

inline ent_mesh_view mesh(const ent_skin* skin) {
    ent_mesh_view view;
    std::memset(&view, 0, sizeof view);
    view.struct_size = sizeof view;
    EXPECT_EQ(ent_skin_mesh(skin, &view), ENT_OK) << ent_last_error();
    return view;
}

}  // namespace skin_test
