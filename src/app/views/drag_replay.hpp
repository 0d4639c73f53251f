#pragma once
// An edit of the scene replays the planner to the step the student is at (rebuild(steps)), so
// the roadmap stays the scene's. In a drag that happens on every frame, and the roadmap follows
// the obstacle live. After a large run a replay takes several frames (20000 samples and k = 10:
// 90-140 ms in the headless browser here, k = 50: 420 ms), and the drag would crawl; then the
// lessons keep the planner on the scene from before the drag, drawn faded, and replay once at
// the release.
#include <string>

#include "app/views/workspace_view.hpp"
#include "core/planning/planner.hpp"

namespace csl::app {

/// Replays up to this much work (samples drawn plus edges checked) on every frame of a drag:
/// about 20 ms in the headless browser here (the k = 10 run above is 130000 of them), a frame
/// at 50 Hz. A count, not a clock, so that what the student sees does not depend on the
/// machine, and tests can say when it happens.
inline constexpr long kLiveReplayWork = 20000;

/// Whether replaying `planner` to its current step is cheap enough for every frame of a drag.
inline bool replay_is_live(const Planner& planner) { return planner.replay_work() <= kLiveReplayWork; }

/// Fades what is drawn in `view` so far (the stale roadmap) and says why at its top left: the
/// drag's reason, or `text` (a replay catching up). Call between view.push_clip() and
/// view.pop_clip().
void draw_replay_pending(const WorkspaceView& view, const std::string& text = "");

}  // namespace csl::app
