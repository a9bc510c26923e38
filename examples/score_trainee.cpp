// SPDX-License-Identifier: Apache-2.0
// score_trainee: a trainer scoring a scripted trainee, through the C++ layer (enteron.hpp).
//
// A bowel lies on the floor of the cavity; the trainee's grasper comes down beside it,
// pushes it sideways, lets go of it, comes back, grasps it, pulls it up, and releases it.
// Every step the trainer reads what the tool touched (Tool::contacts: the ranges of the
// bowel touched, the grasp) and the bowel's tissue stress (Scene::contact_summary: the
// largest contact force and the largest stretch), and at the end prints the score:
//   touches, the part of the bowel touched, time grasped and where, the largest force and
//   where, the contact impulse (how hard for how long), the largest stretch.
// A restore (Scene::save_state / restore_state) replays the grasp as a trainer's "try
// again" would, and checks that the replay scores the same.
#include <enteron/enteron.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr double kDt = 1e-3;      // s
constexpr double kRadius = 0.0125;  // m, the default bowel radius

struct Score {
    int touches = 0;               // times the tool came into contact
    double u_first = 1.0, u_last = 0.0;  // the part of the bowel touched
    double grasp_time = 0.0;       // s
    double grasp_u = -1.0;         // where the grasp took hold
    double largest_force = 0.0;    // N, of any contact on the bowel
    double largest_force_u = 0.0;
    double largest_stretch = 0.0;  // of a segment of the axis (0.01: 1 %)
    double impulse = 0.0;          // N s, of the tool's contacts
    double aim_y = 0.0;            // the trainee's: where the bowel's middle was after the push, m
};

// The trainee's hand at step k (of 3000): tip position, grasp and release commands. It
// pushes the bowel sideways, backs off, comes back beside where the bowel's middle ended
// up (aim_y, read when the push ends), grasps, pulls up 5 cm and lets go.
void trainee(const enteron::Scene& scene, enteron::Tool& tool, int k, double& aim_y) {
    static const double identity[4] = {1.0, 0.0, 0.0, 0.0};
    const double push_end = 0.06 - 0.0001 * 800;
    if (k == 800) aim_y = scene.control_points()[3 * 8 + 1];  // the middle control point, at x = 0
    const double beside = aim_y + kRadius + 0.003, away = aim_y + kRadius + 0.03;
    double tip[3] = {0.0, 0.0, kRadius};
    if (k < 800) {
        tip[1] = 0.06 - 0.0001 * k;  // sideways into the bowel's side
    } else if (k < 1000) {
        tip[1] = push_end + (away - push_end) * (k - 800) / 200.0;  // back off
    } else if (k < 1400) {
        tip[1] = away + (beside - away) * std::min(1.0, (k - 1000) / 300.0);  // come back beside it
    } else {
        tip[1] = beside;
        tip[2] = kRadius + 0.00005 * std::clamp(k - 1500, 0, 1000);  // pull it up 5 cm
    }
    tool.set_pose(tip, identity);
    if (k == 1400) tool.grasp();
    if (k == 2600) tool.release();
}

void score_step(const enteron::Scene& scene, const enteron::Tool& tool, bool& touching, Score& score,
                std::vector<double>& ranges) {
    const ent_tool_contacts t = tool.contacts(&ranges);
    if (t.contacts > 0 && !touching) score.touches += 1;
    touching = t.contacts > 0;
    for (std::size_t r = 0; r + 1 < ranges.size(); r += 2) {
        score.u_first = std::min(score.u_first, ranges[r]);
        score.u_last = std::max(score.u_last, ranges[r + 1]);
    }
    if (t.grasping) {
        score.grasp_time += kDt;
        score.grasp_u = t.grasp_u;
    }
    score.impulse = t.contact_impulse_magnitude_Ns;
    const ent_contact_summary s = scene.contact_summary();
    if (s.largest_force_N > score.largest_force) {
        score.largest_force = s.largest_force_N;
        score.largest_force_u = s.largest_force_u;
    }
    score.largest_stretch = std::max(score.largest_stretch, s.largest_stretch);
}

// Steps `first` to `last` (exclusive) of the script, scoring each.
void run(enteron::Scene& scene, enteron::Tool& tool, int first, int last, Score& score) {
    bool touching = false;
    std::vector<double> ranges;
    for (int k = first; k < last; ++k) {
        trainee(scene, tool, k, score.aim_y);
        scene.step(kDt);
        score_step(scene, tool, touching, score, ranges);
    }
}

}  // namespace

int main() {
    try {
        enteron::SceneDesc desc;
        desc.length_m = 0.4;
        desc.control_points = 17;
        desc.shape = ENT_SHAPE_LINE;
        desc.shape_center_m[0] = -0.2;
        desc.shape_center_m[2] = kRadius;
        enteron::Scene scene(desc);
        enteron::ObstacleDesc floor;
        floor.kind = ENT_OBSTACLE_PLANE;
        scene.add_obstacle(floor);
        enteron::ToolDesc grasper;
        grasper.position_m[1] = 0.06;
        grasper.position_m[2] = kRadius;
        enteron::Tool tool = scene.add_tool(grasper);

        Score score;
        run(scene, tool, 0, 1200, score);
        const std::vector<unsigned char> before_grasp = scene.save_state();
        Score first = score;
        run(scene, tool, 1200, 3000, first);
        // "Try again": back to before the grasp, the same hand again, the same score.
        scene.restore_state(before_grasp);
        Score replay = score;
        run(scene, tool, 1200, 3000, replay);
        const bool same = replay.largest_force == first.largest_force && replay.impulse == first.impulse &&
                          replay.grasp_time == first.grasp_time && replay.touches == first.touches;

        std::printf("score_trainee: %d touches over u in [%.3f, %.3f], grasped %.3f s at u = %.3f, largest force "
                    "%.3f N at u = %.3f, contact impulse %.4f N s, largest stretch %.2f %%\n",
                    first.touches, first.u_first, first.u_last, first.grasp_time, first.grasp_u, first.largest_force,
                    first.largest_force_u, first.impulse, 100.0 * first.largest_stretch);
        std::printf("score_trainee: replay from the saved state before the grasp: %s\n",
                    same ? "the same score, bit for bit" : "A DIFFERENT SCORE");
        return same ? 0 : 1;
    } catch (const enteron::Error& error) {
        std::fprintf(stderr, "score_trainee: %s\n", error.what());
        return 1;
    }
}
