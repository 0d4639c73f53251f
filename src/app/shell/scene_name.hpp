#pragma once
// A scene's name says what it is. A bundled scene's name ("P12: one disk across the path") stays
// only while the scene is that bundled scene: any change (the editor's mouse and keys, a marker
// dragged in C-space, a parameter that moves start or goal, other content set or imported under
// that name) makes it "P12: one disk across the path (edited)", and undoing back to the
// original brings the plain name back. A scene of its own name (a file's, a link's) is marked
// the same way once it differs from what was loaded. So a Share link never names a bundled
// scene for an edited one, and snapshots, exports, state() and describe agree on the name.
//
// The app keeps one per lesson and refreshes it after every frame and around API calls: it
// sees every path that changes a scene, including ones a lesson adds later, at the cost of a
// hash of the scene's numbers when nothing changed.
#include <cstdint>
#include <string>

#include "core/scene/scene.hpp"

namespace csl::app {

/// "NAME (edited)" (once; within the schema's kMaxNameLength); "" stays "".
std::string edited_name(const std::string& name);

class SceneName {
 public:
  /// The scene came from elsewhere (a link, a file, the API, a restore): what it refers to is
  /// its origin, the bundled scene whose name it carries (marked edited or not), else itself.
  void loaded(const Scene& scene);
  /// After anything may have changed `scene`: its name becomes the origin's while its content
  /// is the origin's, edited_name() of it otherwise. A name that changed since the last call
  /// (an undo across a load, a lesson loading a bundled scene itself) is a new origin.
  void refresh(Scene& scene);

 private:
  const Scene& origin() const { return bundled_ ? *bundled_ : own_; }
  bool has_origin_ = false;
  const Scene* bundled_ = nullptr;  // the origin when it is a bundled scene (parsed once, kept)
  Scene own_;                       // the origin otherwise
  std::string origin_name_;
  std::uint64_t origin_print_ = 0;
  std::string named_;              // the name refresh() left
  std::uint64_t seen_print_ = 0;   // the content refresh() saw last
};

}  // namespace csl::app
