#pragma once
// A short history of what the algorithm just did, in words ("sample #37 at (0.41, 0.77):
// rejected, inside disk 3"), newest last.
#include <deque>
#include <string>

namespace csl::app {

class EventLog {
 public:
  void add(long step, std::string text);
  /// The lines go; the note stays.
  void clear() { lines_.clear(); }
  /// A line above the others that clear() keeps: where the lesson came from ("restored from the
  /// link at step 173"), which a lesson restarting its log from where it stands would drop.
  void set_note(std::string text) { note_ = std::move(text); }
  const std::string& note() const { return note_; }
  /// Draws the log in the current window, scrolled to the newest line.
  void draw(const char* id, float height) const;
  const std::deque<std::pair<long, std::string>>& lines() const { return lines_; }
  std::string last() const { return lines_.empty() ? note_ : lines_.back().second; }

 private:
  static constexpr std::size_t kKeep = 200;
  std::deque<std::pair<long, std::string>> lines_;
  std::string note_;
};

}  // namespace csl::app
