// SPDX-License-Identifier: Apache-2.0
// Every ENT_* constant of enteron.h equals the internal value it stands for, so that the
// library can pass them through with a cast: a change on either side stops the build.
#include "base/error.h"
#include "base/logger.h"
#include "collision/obstacle.h"
#include "enteron/enteron.h"
#include "mechanics/effect_id.h"
#include "mechanics/integrator_kind.h"
#include "scene/scene_config.h"
#include "skinning/skin_settings.h"

namespace {

template <typename Enum>
constexpr int value(Enum e) {
    return static_cast<int>(e);
}

using enteron::mechanics::EffectId;
using enteron::ErrorCode;
using enteron::LogLevel;
using enteron::collision::ObstacleKind;
using enteron::mechanics::IntegratorKind;
using enteron::scene::ShapeKind;
using enteron::skinning::SkinMethod;

static_assert(ENT_OK == 0);
static_assert(ENT_ERROR_INVALID_ARGUMENT == value(ErrorCode::invalid_argument));
static_assert(ENT_ERROR_VERSION == value(ErrorCode::version));
static_assert(ENT_ERROR_PARSE == value(ErrorCode::parse));
static_assert(ENT_ERROR_INVALID_SCENE == value(ErrorCode::invalid_scene));
static_assert(ENT_ERROR_UNSTABLE == value(ErrorCode::unstable));
static_assert(ENT_ERROR_OUT_OF_MEMORY == value(ErrorCode::out_of_memory));
static_assert(ENT_ERROR_NOT_FOUND == value(ErrorCode::not_found));
static_assert(ENT_ERROR_BUFFER_TOO_SMALL == value(ErrorCode::buffer_too_small));
static_assert(ENT_ERROR_INTERNAL == value(ErrorCode::internal));
static_assert(ENT_ERROR_BUSY == value(ErrorCode::busy));

static_assert(ENT_LOG_DEBUG == value(LogLevel::debug));
static_assert(ENT_LOG_INFO == value(LogLevel::info));
static_assert(ENT_LOG_WARNING == value(LogLevel::warning));
static_assert(ENT_LOG_ERROR == value(LogLevel::error));

static_assert(ENT_EFFECT_STRETCH == value(EffectId::stretch));
static_assert(ENT_EFFECT_BEND == value(EffectId::bend));
static_assert(ENT_EFFECT_DAMPING == value(EffectId::damping));
static_assert(ENT_EFFECT_GRAVITY == value(EffectId::gravity));
static_assert(ENT_EFFECT_MESENTERY == value(EffectId::mesentery));
static_assert(ENT_EFFECT_PINNED == value(EffectId::pinned));
static_assert(ENT_EFFECT_ENVIRONMENT == value(EffectId::environment));
static_assert(ENT_EFFECT_SELF_COLLISION == value(EffectId::self_collision));
static_assert(ENT_EFFECT_TOOLS == value(EffectId::tools));
static_assert(ENT_EFFECT_COUNT == enteron::mechanics::kEffectCount);

static_assert(ENT_SHAPE_LINE == value(ShapeKind::line));
static_assert(ENT_SHAPE_SERPENTINE == value(ShapeKind::serpentine));
static_assert(ENT_SHAPE_HELIX == value(ShapeKind::helix));
static_assert(ENT_SHAPE_POINTS == value(ShapeKind::points));

static_assert(ENT_INTEGRATOR_RK4 == value(IntegratorKind::rk4));
static_assert(ENT_INTEGRATOR_SYMPLECTIC_EULER == value(IntegratorKind::symplectic_euler));
static_assert(ENT_INTEGRATOR_IMPLICIT_EULER == value(IntegratorKind::implicit_euler));
static_assert(ENT_INTEGRATOR_BDF2 == value(IntegratorKind::bdf2));

static_assert(ENT_PIN_NONE == enteron::scene::pin_none);
static_assert(ENT_PIN_FIRST == enteron::scene::pin_first);
static_assert(ENT_PIN_LAST == enteron::scene::pin_last);
static_assert(ENT_PIN_BOTH == enteron::scene::pin_both);

static_assert(ENT_OBSTACLE_BOX_INSIDE == value(ObstacleKind::box_inside));
static_assert(ENT_OBSTACLE_PLANE == value(ObstacleKind::plane));
static_assert(ENT_OBSTACLE_SPHERE == value(ObstacleKind::sphere));
static_assert(ENT_OBSTACLE_CAPSULE == value(ObstacleKind::capsule));

static_assert(ENT_SKIN_TUBE == value(SkinMethod::tube));
static_assert(ENT_SKIN_POINT_SKELETON == value(SkinMethod::point_skeleton));
static_assert(ENT_SKIN_CONVOLUTION == value(SkinMethod::convolution));

}  // namespace
