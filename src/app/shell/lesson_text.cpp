// The default text description of a lesson: its scene, if it has one (Lesson::describe).
#include "app/shell/lesson.hpp"
#include "core/checking/scene_text.hpp"

namespace csl::app {

std::string Lesson::describe() const {
  const Scene* s = const_cast<Lesson*>(this)->scene();
  return s ? describe_scene(*s, CollisionWorld(*s)) : std::string();
}

}  // namespace csl::app
