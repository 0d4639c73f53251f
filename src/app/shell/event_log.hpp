#pragma once
// A short history of what the algorithm just did, in words ("sample #37 at (0.41, 0.77):
// rejected, inside disk 3"), newest last.
#include <deque>
#include <string>

namespace csl::app {

class EventLog {
 public:
  void add(long step, std::string text);
  void clear() { lines_.clear(); }
  /// Draws the log in the current window, scrolled to the newest line.
  void draw(const char* id, float height) const;
  const std::deque<std::pair<long, std::string>>& lines() const { return lines_; }
  std::string last() const { return lines_.empty() ? std::string() : lines_.back().second; }

 private:
  static constexpr std::size_t kKeep = 200;
  std::deque<std::pair<long, std::string>> lines_;
};

}  // namespace csl::app
