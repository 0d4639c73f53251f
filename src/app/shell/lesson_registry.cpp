#include <algorithm>

#include "app/shell/lesson.hpp"

namespace csl::app {
namespace {
// A function-local static: registrations from other files may run before this file's statics.
std::vector<LessonInfo>& registry() {
  static std::vector<LessonInfo> all;
  return all;
}
}  // namespace

LessonRegistration::LessonRegistration(const char* id, const char* name, const char* category,
                                       std::function<std::unique_ptr<Lesson>()> create) {
  auto& all = registry();
  all.push_back({id, name, category, std::move(create)});
  std::sort(all.begin(), all.end(), [](const LessonInfo& a, const LessonInfo& b) {
    return a.category != b.category ? a.category < b.category : a.name < b.name;
  });
}

const std::vector<LessonInfo>& lessons() { return registry(); }

const LessonInfo* find_lesson(const std::string& id) {
  for (const LessonInfo& l : registry())
    if (l.id == id) return &l;
  return nullptr;
}

}  // namespace csl::app
