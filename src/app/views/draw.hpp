#pragma once
// Drawing what the core computes: robots at a configuration, roadmaps (coloured by connected
// component, edges split where they cross a seam of the torus), paths.
#include <algorithm>
#include <vector>

#include "app/views/workspace_view.hpp"
#include "core/planning/prm.hpp"
#include "core/robots/robot.hpp"

namespace csl::app {

/// The robot at q in the workspace: a dot, the arm's two links and joints, or the polygon.
void draw_robot(const WorkspaceView& view, const Robot& robot, const Config& q, ImU32 color, float thickness = 3.0f);

/// A straight C-space segment from a to a + delta in a 2-D chart; on angular axes it leaves
/// through one edge of the square and comes back through the opposite one (drawn as pieces).
void draw_chart_segment(const WorkspaceView& view, const Space& space, const Config& a, const Config& delta,
                        ImU32 color, float thickness);

/// The roadmap's edges (by component colour, or all one colour if labels are empty) and
/// vertices, in a 2-D chart (coordinates 0 and 1 of each configuration). `checked`: a planner's
/// checked_edge_flags() (Lazy PRM), whose edges never checked are drawn dashed.
void draw_roadmap(const WorkspaceView& view, const Space& space, const Roadmap& roadmap,
                  const std::vector<int>& component_labels, const std::vector<unsigned char>* checked = nullptr);

/// draw_roadmap() with its geometry kept between frames: redrawn only when `version` (which the
/// caller bumps whenever the roadmap or its colours change) or the view's transform changes;
/// otherwise the previous frame's vertices are copied. A static 5000-node roadmap then costs a
/// memcpy a frame.
/// The most roadmap edges drawn: past it, an even subset, and the view says so.
inline constexpr std::size_t kMaxDrawnEdges = 50000;

class RoadmapLayer {
 public:
  /// (The caller's `version` must change when `checked` does: a step of the planner does.)
  void draw(const WorkspaceView& view, const Space& space, const Roadmap& roadmap,
            const std::vector<int>& component_labels, long long version,
            const std::vector<unsigned char>* checked = nullptr);

 private:
  long long version_ = -1;
  ImVec2 origin_{0, 0}, unit_{0, 0};  // screen images of (0,0) and (1,1): the transform
  ImVector<ImDrawVert> vertices_;
  ImVector<ImDrawIdx> indices_;  // relative to the first vertex
};

/// The version a RoadmapLayer should draw: `version` itself, but while long work grows the
/// roadmap (`busy`) at most a new one every quarter second (or 8 frames, if longer). Rebuilding the layer's geometry
/// costs a pass over every edge, and a run to the end changes it every frame (20000 samples and
/// k = 50: 300-700 ms a frame in the headless browser, where the work itself took 25).
class RedrawThrottle {
 public:
  long long operator()(long long version, bool busy) {
    const double now = ImGui::GetTime();
    // Where frames are slow (a huge roadmap in software WebGL), less often still: a rebuild at
    // most every 8 frames.
    const double interval = std::max(0.25, 8.0 * static_cast<double>(ImGui::GetIO().DeltaTime));
    if (busy && drawn_ >= 0 && now - at_ < interval) return drawn_;
    drawn_ = version;
    at_ = now;
    return version;
  }

 private:
  long long drawn_ = -1;
  double at_ = 0.0;
};

/// Draws a planner rejected (RecordingPlanner's), each a small cross: apart from the roadmap's
/// squares, so that where a sampler does not keep shows next to where it does.
void draw_rejected_samples(const WorkspaceView& view, const std::vector<Config>& rejected);

/// The path through roadmap vertices, wide and outlined so it stands out of the roadmap.
void draw_path(const WorkspaceView& view, const Space& space, const Roadmap& roadmap, const std::vector<int>& path);

}  // namespace csl::app
