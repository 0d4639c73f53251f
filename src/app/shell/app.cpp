#include "app/shell/app.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <limits>
#include <optional>

#include "app/shell/bundled_scenes.hpp"
#include "app/shell/camera.hpp"
#include "app/shell/fonts.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/theme_api.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "core/base/text.hpp"
#include "core/base/version.hpp"

namespace csl::app {

using json = nlohmann::json;

namespace {
// A lesson with nothing to step answers the stepping calls as a stepper at step 0 that is done.
NoSteps no_stepper;
}  // namespace

Stepper& stepping(Lesson& lesson) {
  Stepper* s = lesson.stepper();
  return s ? *s : no_stepper;
}
bool shows_controls(const Lesson& lesson) {
  const Stepper* s = lesson.stepper();
  return s && s->shows_controls();
}

namespace {
json vec_json(ImVec2 v) { return json::array({v.x, v.y}); }

// Long work goes on over frames (Stepper::work); an API call finishes what it started before it
// returns, unless asked {background: true} (the page does, for links and restores, so that the
// first frames come at once and the progress shows).
constexpr double kFrameWorkMs = 25.0;
void finish(Lesson& lesson, const json& args) {
  if (!args.value("background", false)) stepping(lesson).work(std::numeric_limits<double>::infinity());
}

long count_arg(const json& args, const char* key, long fallback, long max) {
  if (!args.contains(key)) return fallback;
  const json& v = args[key];
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > max)
    throw ApiError(std::string(key) + ": an integer in [0, " + std::to_string(max) + "]");
  return v.get<long>();
}
}  // namespace

App::App(const Platform& platform) : platform_(platform) {
  theme::apply_style();
  register_api();
  select_lesson(lessons().front().id);
  // An answer sees a scene's name as the frames do, also right after another call edited it.
  js_api().before_each([this] {
    name_scenes();
    finish_notes();
  });
}

void App::name_scenes() {
  for (auto& [id, lesson] : instances_)
    if (lesson && lesson->scene()) extras_[id].scene_name.refresh(*lesson->scene());
}

void App::scene_loaded(const std::string& id) {
  auto it = instances_.find(id);
  if (it == instances_.end() || !it->second || !it->second->scene()) return;
  SceneName& name = extras_[id].scene_name;
  name.loaded(*it->second->scene());
  name.refresh(*it->second->scene());
}

void App::note_restored(const std::string& id, const std::string& from) {
  auto it = instances_.find(id);
  if (it == instances_.end() || !it->second) return;
  Lesson& l = *it->second;
  LessonExtras& e = extras_[id];
  // A replay over frames: the step it reaches is known once it ends (finish_notes()); a link's
  // steps=100000 may end at 1186, or where Cancel stopped it.
  e.restored_from = stepping(l).busy() ? from : std::string();
  const std::string name = l.scene() ? printable(l.scene()->name, 80) : std::string();
  const std::string cameras = cameras_text(cameras_json(l, false));
  e.log_note = !e.restored_from.empty() ? "Restoring from " + from + "..."
                : "Restored from " + from + " at step " + std::to_string(stepping(l).steps()) +
                      (name.empty() ? "" : ", scene \"" + name + "\"") + (cameras.empty() ? "" : "; " + cameras) +
                      ". Earlier steps are not listed.";
  if (id == lesson_id_) ctx_.log.set_note(e.log_note);
}

void App::finish_notes() {
  for (auto& [id, e] : extras_) {
    if (e.restored_from.empty()) continue;
    const auto lesson = instances_.find(id);
    // A copy: note_restored() clears e.restored_from, which must not be the text it writes.
    const std::string from = e.restored_from;
    if (lesson != instances_.end() && lesson->second && !stepping(*lesson->second).busy()) note_restored(id, from);
  }
}

json App::lesson_state(const json& args) const {
  json out = lesson_->state(args);
  strip_answer_fields(out, instructor::hidden_answers(lesson_id_));
  if (out.is_object() && lesson_->scene()) out["scene_name"] = lesson_->scene()->name;
  return out;
}

json App::lesson_state_of(const std::string& id) const {
  const auto it = instances_.find(id);
  const LessonInfo* info = find_lesson(id);
  const std::string name = info ? info->name : id;
  if (it == instances_.end() || !it->second) throw ApiError(name + " is not open yet: open the item in the lab first");
  Lesson& l = *it->second;  // (scene() is not const)
  if (l.stepper() && l.stepper()->busy()) throw ApiError(name + " is still working: check again when it has finished");
  json out = l.state(json::object());
  strip_answer_fields(out, instructor::hidden_answers(id));
  if (out.is_object() && l.scene()) out["scene_name"] = l.scene()->name;
  return out;
}

std::string App::show_item(const std::string& id, const json& setup, bool preset, bool view) {
  if (!find_lesson(id)) return "the lab has no lesson \"" + id + "\"";
  // Locks hold in an assignment too: the item is shown as far as they allow, and the card says
  // what they kept (the item can still be answered).
  if (!instructor::lesson_allowed(id)) return instructor::lesson_refusal();
  std::string note;
  if (preset) {
    json s = setup;
    if (s.contains("scene") && instructor::scene_locked()) {
      s.erase("scene");
      note = instructor::scene_refusal();
    }
    try {
      show_in_lesson(id, s);
    } catch (const std::exception& e) {
      // A parameter the instructor fixed: the scene without the parameters, else as it is.
      if (note.empty()) note = e.what();
      if (s.contains("scene")) {
        s.erase("params");
        try {
          show_in_lesson(id, s);
        } catch (const std::exception&) {
        }
      }
    }
  }
  select_lesson(id);
  if (view && ctx_.compact) tab_ = Tab::View;
  return note;
}

void App::open_problem(const HomeworkProblem& p, bool preset) {
  if (!find_lesson(p.lesson)) throw ApiError("the lab has no lesson \"" + p.lesson + "\" for " + p.id);
  if (!instructor::lesson_allowed(p.lesson)) throw ApiError(instructor::lesson_refusal());
  if (preset) {
    json setup{{"params", p.params}};
    if (!p.scene.empty()) setup["scene"] = scene_to_json(bundled_scene(p.scene));
    show_in_lesson(p.lesson, setup);
  }
  select_lesson(p.lesson);
  // On a phone the problem's card (its exercise, the answer field) is on the Controls tab: a
  // student who opened a problem to read its question saw only the tool, and nothing said where.
  if (ctx_.compact) tab_ = Tab::Controls;
}

void App::show_in_lesson(const std::string& id, const json& setup) {
  const LessonInfo* info = find_lesson(id);
  if (!info) throw ApiError("no lesson \"" + id + "\"");
  std::optional<Scene> scene;
  if (setup.contains("scene")) scene = scene_from_json(setup["scene"]);  // throws before anything changes
  const json params = setup.value("params", json::object());
  // The instructor's locks hold here too: "Show these numbers in the tool" changes the scene.
  if (!instructor::lesson_allowed(id)) throw ApiError(instructor::lesson_refusal());
  if (scene && instructor::scene_locked()) throw ApiError(instructor::scene_refusal());
  Lesson& lesson = instance(id);
  check_params_allowed(lesson, params);
  // The scene as one edit (Undo brings the student's back); parameters the lesson refuses
  // (set_params changes nothing then) take the scene back with them.
  std::string why;
  if (scene && !lesson.accept_scene(*scene, why)) throw ApiError(why);
  if (!params.empty()) {
    try {
      lesson.set_params(params);
    } catch (...) {
      if (scene) lesson.undo();
      throw;
    }
  }
  if (scene) scene_loaded(id);
  stepping(lesson).work(std::numeric_limits<double>::infinity());
  select_lesson(id);
}

bool App::select_lesson(const std::string& id) {
  if (!find_lesson(id)) return false;
  lesson_ = &instance(id);
  lesson_id_ = id;
  ctx_.playback.playing = false;
  ctx_.views.clear();
  ctx_.plots.clear();
  ctx_.log.clear();
  const auto extras = extras_.find(id);
  ctx_.log.set_note(extras == extras_.end() ? std::string() : extras->second.log_note);
  lesson_->on_show();  // its log again (it went with the clear), from where it stands
  return true;
}

void App::register_api() {
  JsApi& api = js_api();
  register_instructor_api();
  api.add("status", "frames drawn, frame times, version, pixel ratio, lesson, the side panel's measures and sections, the layout ({mode: wide|compact, tab, touch, views: [{name, x, y, w, h}]} in CSS px)", [this](const json&) {
    const FrameStats& f = platform_.frame_stats();
    return json{{"frames", platform_.frame_count()},
                {"version", kVersion},
                {"pixel_ratio", platform_.pixel_ratio()},
                {"lesson", lesson_id_},
                {"frame_ms", {{"mean", f.mean_interval_ms}, {"p95", f.p95_interval_ms}, {"max", f.max_interval_ms}}},
                {"cpu_ms", {{"mean", f.mean_cpu_ms}, {"p95", f.p95_cpu_ms}, {"max", f.max_cpu_ms}}},
                {"ui_ms", {{"mean", f.mean_ui_ms}, {"p95", f.p95_ui_ms}, {"max", f.max_ui_ms}}},
                {"vertices", f.vertices},
                {"notice", ImGui::GetTime() < ctx_.notice_until ? ctx_.notice : ""},
                {"notices", ctx_.notices},  // the notice's number: a repeat is news too
                {"panel", panel::state()},
                {"layout", layout_},
                {"busy", busy_json()},
                // What the page's controls (web/lab-access.js) must show as fixed: restrictions()'s.
                {"restrictions", restrictions_json()},
                // What the page's step buttons (web/lab-access.js) need: whether the lesson steps, where.
                {"stepping", {{"controls", shows_controls(*lesson_)},
                              {"steps", stepping(*lesson_).steps()},
                              {"finished", stepping(*lesson_).finished()},
                              {"playing", ctx_.playback.playing},
                              {"speed", ctx_.playback.steps_per_second}}}};
  });
  api.add("lessons", "the lessons: [{id, name, category, open}] (open: started, has state)", [this](const json&) {
    json out = json::array();
    for (const LessonInfo& l : lessons())
      out.push_back({{"id", l.id}, {"name", l.name}, {"category", l.category}, {"open", instances_.count(l.id) > 0}});
    return out;
  });
  api.add("select_lesson", "switch lesson: {id}", [this](const json& args) {
    const std::string id = args.value("id", "");
    if (!find_lesson(id)) throw ApiError("no lesson \"" + id + "\"");
    if (!instructor::lesson_allowed(id)) throw ApiError(instructor::lesson_refusal());
    select_lesson(id);
    return json(lesson_id_);
  });
  // A hidden answer (instructor.hpp) is not in the state: lesson_state() takes its fields out,
  // for every caller (the page's export of the state too).
  api.add("state", "the lesson's state ({roadmap: true} adds the roadmap) and its scene's name (scene_name)",
          [this](const json& args) { return lesson_state(args); });
  api.add("param_specs",
          "the lesson's parameters for native controls: [{name, label, kind, min, max, step, unit, help, value, choices?, list?, locked}]",
          [this](const json&) {
            json specs = param_specs_json(lesson_->params(), lesson_->param_fields());
            const std::vector<std::string> scene_keys = lesson_->scene_params();
            for (json& s : specs) {
              const std::string name = s["name"].get<std::string>();
              s["locked"] = instructor::param_locked(name) ||
                            (instructor::scene_locked() && std::find(scene_keys.begin(), scene_keys.end(), name) != scene_keys.end());
            }
            return specs;
          });
  api.add("describe", "what the lesson shows now, in sentences (the scene, the main view's result)",
          [this](const json&) {
            const Scene* scene = lesson_->scene();
            const std::string name = scene && !scene->name.empty() ? "Scene \"" + scene->name + "\". " : std::string();
            return json(name + lesson_->describe());
          });
  api.add("set_params", "the lesson's parameters: {params: {...}}", [this](const json& args) {
    const json params = args.value("params", json::object());
    check_params_allowed(*lesson_, params);
    lesson_->set_params(params);
    finish(*lesson_, args);
    name_scenes();  // (Collision checking's p and q are its scene's start and goal)
    return lesson_state(json::object());
  });
  api.add("step", "forward {count} steps (default 1)", [this](const json& args) {
    const long n = count_arg(args, "count", 1, 10000000);
    stepping(*lesson_).cancel_work();
    for (long i = 0; i < n && !stepping(*lesson_).finished(); ++i) stepping(*lesson_).step_forward();
    return json(stepping(*lesson_).steps());
  });
  api.add("step_back", "back {count} steps (default 1; {background: true}: over frames)", [this](const json& args) {
    stepping(*lesson_).run_to(std::max(0L, stepping(*lesson_).wanted_steps() - count_arg(args, "count", 1, 10000000)));
    finish(*lesson_, args);
    return json(stepping(*lesson_).steps());
  });
  api.add("play", "Play or pause, and its speed: {on?: bool, speed?: steps/s in [1, 5000]} -> {playing, speed}", [this](const json& args) {
    Playback& pb = ctx_.playback;
    for (auto it = args.begin(); it != args.end(); ++it)
      if (it.key() != "on" && it.key() != "speed") throw ApiError("unknown field \"" + it.key() + "\" (on, speed)");
    if (args.contains("speed")) {
      const json& v = args["speed"];
      if (!v.is_number() || !(v.get<double>() >= 1.0 && v.get<double>() <= 5000.0)) throw ApiError("speed: steps per second in [1, 5000]");
      pb.steps_per_second = v.get<float>();
    }
    if (args.contains("on")) {
      if (!args["on"].is_boolean()) throw ApiError("on: true or false");
      if (!shows_controls(*lesson_)) throw ApiError("this lesson has nothing to play");
      // As the button: nothing to play at the end (Reset or Back first).
      pb.playing = args["on"].get<bool>() && !stepping(*lesson_).finished();
    }
    return json{{"playing", pb.playing}, {"speed", pb.steps_per_second}};
  });
  api.add("run_to", "to step {steps} ({background: true}: over frames, see status().busy)", [this](const json& args) {
    stepping(*lesson_).run_to(count_arg(args, "steps", 0, 100000000));
    finish(*lesson_, args);
    return json(stepping(*lesson_).steps());
  });
  api.add("run", "to the end ({background: true}: over frames)", [this](const json& args) {
    stepping(*lesson_).run_all();
    finish(*lesson_, args);
    return json(stepping(*lesson_).steps());
  });
  api.add("finish_phase", "to the end of the current phase", [this](const json& args) {
    stepping(*lesson_).finish_phase();
    finish(*lesson_, args);
    return json(stepping(*lesson_).steps());
  });
  api.add("cancel", "stop the lesson's running work (a run, a replay) where it is", [this](const json&) {
    stepping(*lesson_).cancel_work();
    return json(stepping(*lesson_).steps());
  });
  api.add("reset", "back to step 0", [this](const json&) {
    stepping(*lesson_).reset();
    return json(stepping(*lesson_).steps());
  });
  api.add("get_scene", "the lesson's scene (schema version 1)", [this](const json&) {
    if (!lesson_->scene()) throw ApiError("this lesson has no scene");
    return scene_to_json(*lesson_->scene());
  });
  api.add("set_scene", "replace the lesson's scene: {scene}; refused with a message if invalid", [this](const json& args) {
    if (!args.contains("scene")) throw ApiError("args.scene is missing");
    if (instructor::scene_locked()) throw ApiError(instructor::scene_refusal());
    const Scene s = scene_from_json(args["scene"]);  // throws before anything changes
    std::string why;
    if (!lesson_->accept_scene(s, why)) throw ApiError(why);
    scene_loaded(lesson_id_);
    finish(*lesson_, args);
    return scene_to_json(*lesson_->scene());
  });
  api.add("undo", "undo the last scene edit", [this](const json& args) {
    if (instructor::scene_locked()) throw ApiError(instructor::scene_refusal());
    const bool done = lesson_->undo();
    finish(*lesson_, args);
    return json(done);
  });
  api.add("redo", "redo the last undone edit", [this](const json& args) {
    if (instructor::scene_locked()) throw ApiError(instructor::scene_refusal());
    const bool done = lesson_->redo();
    finish(*lesson_, args);
    return json(done);
  });
  api.add("view", "CSS pixels of world points in a view: {view: 'workspace'|'cspace'|a plot's name, points: [[x,y],...]}; its axes' labels, whether it shows its Fit button",
          [this](const json& args) {
            const std::string name = args.value("view", "workspace");
            if (auto plot = ctx_.plots.find(name); plot != ctx_.plots.end()) {
              // A plot: data points (its axes' units, log or not) to CSS pixels.
              json points = json::array();
              for (const json& p : args.value("points", json::array())) {
                if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                  throw ApiError("points must be [[x, y], ...]");
                points.push_back(vec_json(plot->second->to_screen(p[0].get<double>(), p[1].get<double>())));
              }
              return json{{"points", points}, {"plot", true}};
            }
            auto it = ctx_.views.find(name);
            if (it == ctx_.views.end()) throw ApiError("this lesson has no view \"" + name + "\"");
            const WorkspaceView& v = *it->second;
            json points = json::array();
            for (const json& p : args.value("points", json::array())) {
              if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                throw ApiError("points must be [[x, y], ...]");
              points.push_back(vec_json(v.to_screen(Vec2(p[0].get<double>(), p[1].get<double>()))));
            }
            const Vec2 centre = v.to_world(ImVec2(0.5f * (v.canvas_min().x + v.canvas_max().x),
                                                  0.5f * (v.canvas_min().y + v.canvas_max().y)));
            return json{{"canvas_min", vec_json(v.canvas_min())},
                        {"canvas_max", vec_json(v.canvas_max())},
                        {"scale", v.scale()},
                        {"center", {centre.x(), centre.y()}},  // the world point at the canvas's centre
                        {"fitted", v.fitted()},
                        {"points", points},
                        {"ticks", {{"x", v.tick_labels(0)}, {"y", v.tick_labels(1)}}},
                        {"fit_button", v.fit_button_shown()}};
          });
  // The whole state a link or an autosave needs to reproduce what is on screen exactly.
  api.add("snapshot", "{lesson, scene, params, steps, camera?}: everything needed to restore this view exactly ({lesson: id}: an open lesson's); camera only for views zoomed, panned or turned",
          [this](const json& args) {
            const std::string id = args.value("lesson", lesson_id_);
            auto it = instances_.find(id);
            if (it == instances_.end() || !it->second) throw ApiError("lesson: \"" + id + "\" is not open");
            Lesson& l = *it->second;
            json out{{"lesson", id},
                     {"scene", l.scene() ? scene_to_json(*l.scene()) : json(nullptr)},
                     {"params", l.params()},
                     {"steps", stepping(l).wanted_steps()}};
            // Left out while every view is as it starts: such snapshots (and links) stay as before.
            if (json camera = cameras_json(l, false); !camera.empty()) out["camera"] = camera;
            return out;
          });
  api.add("camera", "where each of the lesson's views looks: {name: [x, y, zoom] (a plane; zoom 1: Fit) | [yaw, pitch] (3-D)}",
          [this](const json&) { return cameras_json(*lesson_, true); });
  api.add("set_camera", "zoom and pan the lesson's views: {camera: {name: [x, y, zoom] | [yaw, pitch]}}; all checked first",
          [this](const json& args) {
            set_cameras(*lesson_, args.value("camera", json::object()));
            return cameras_json(*lesson_, true);
          });
  api.add("note_restored", "the log's first line says the lesson on screen was restored: {from: 'the link'}",
          [this](const json& args) {
            const auto from = args.find("from");
            if (from == args.end() || !from->is_string() || from->get<std::string>().empty())
              throw ApiError("from: what it was restored from");
            note_restored(lesson_id_, printable(from->get<std::string>(), 60));
            return json(ctx_.log.note());
          });
  api.add("restore", "restore a snapshot: {lesson, scene?, params?, steps?, camera?, background?, from?}; all checked before anything changes; from: the log says so ('your saved work')",
          [this](const json& request) {
            const std::string id = request.value("lesson", lesson_id_);
            const LessonInfo* info = find_lesson(id);
            if (!info) throw ApiError("lesson: no lesson \"" + id + "\"");
            // A lesson opened for the first time by this restore is held to its default.
            if (instructor::restrictions().any_lock() && !pins_.count(id) && !instances_.count(id)) pin(id, *info->create());
            const json args = pinned(id, request);
            std::optional<Scene> scene;
            if (args.contains("scene") && !args["scene"].is_null()) scene = scene_from_json(args["scene"]);
            const long steps = count_arg(args, "steps", 0, 100000000);
            // Try everything on a fresh lesson first: a bad part leaves the current one untouched.
            std::unique_ptr<Lesson> trial = info->create();
            std::string why;
            if (scene && !trial->accept_scene(*scene, why)) throw ApiError("scene: " + why);
            if (args.contains("params")) trial->set_params(args["params"]);
            if (args.contains("camera")) set_cameras(*trial, args["camera"]);  // after params: they may choose the views
            const auto from = args.find("from");
            if (from != args.end() && (!from->is_string() || from->get<std::string>().empty()))
              throw ApiError("from: what it was restored from");
            stepping(*trial).run_to(steps);
            finish(*trial, args);
            instances_[id] = std::move(trial);
            extras_[id].log_note.clear();
            extras_[id].restored_from.clear();
            scene_loaded(id);
            if (from != args.end()) note_restored(id, printable(from->get<std::string>(), 60));
            // (A lesson the lock keeps the lab from is restored, not shown.)
            if (instructor::lesson_allowed(id)) select_lesson(id);
            return json{{"lesson", lesson_id_}, {"steps", stepping(*lesson_).steps()}};
          });
  homework_.register_api(api);
  assignment_.register_api(api);
  web::register_api(api, ctx_);  // notify, page_state, bundled_scenes: the page around the app
  theme::register_api(api);      // the colours that carry meaning (accessibility tests)
  api.add("log", "the event log's lines, first its note if it has one ({step: 0, text, note: true}: where a restored lesson came from)", [this](const json&) {
    json out = json::array();
    if (!ctx_.log.note().empty()) {
      out.push_back({{"step", 0}, {"text", ctx_.log.note()}});
      out.back()["note"] = true;
    }
    for (const auto& [step, text] : ctx_.log.lines()) out.push_back({{"step", step}, {"text", text}});
    return out;
  });
}

json App::busy_json() const {
  for (const auto& [id, lesson] : instances_)
    if (lesson && stepping(*lesson).busy())
      return json{{"lesson", id}, {"text", stepping(*lesson).busy_text()}, {"progress", stepping(*lesson).progress()},
                  {"steps", stepping(*lesson).steps()}};
  return nullptr;
}

void App::work() {
  // The lesson on screen first; when it has nothing to do, a lesson restored in the background
  // (a saved state of several lessons comes back while the student looks at one).
  if (stepping(*lesson_).busy()) return stepping(*lesson_).work(kFrameWorkMs);
  for (auto& [id, lesson] : instances_)
    if (lesson && stepping(*lesson).busy()) return stepping(*lesson).work(kFrameWorkMs);
}

void App::playback_controls() {
  if (!shows_controls(*lesson_)) return;
  Playback& pb = ctx_.playback;
  if (stepping(*lesson_).busy()) {
    // Long work runs over frames: what it is, how far, and a way out.
    pb.playing = false;
    ImGui::TextWrapped("%s", stepping(*lesson_).busy_text().c_str());
    const float cancel_w = ui::button_width("Cancel");
    ImGui::ProgressBar(static_cast<float>(stepping(*lesson_).progress()), ImVec2(-cancel_w - ImGui::GetStyle().ItemSpacing.x, 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) stepping(*lesson_).cancel_work();
    web::record_control("cancel");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("stop here (Esc)");
    ImGui::Spacing();
    return;
  }
  ImGui::BeginDisabled(stepping(*lesson_).steps() == 0);
  if (ImGui::Button("\xE2\x97\x80 Back")) stepping(*lesson_).step_back();  // ◀
  web::record_control("back");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("step back (,)");
  ImGui::EndDisabled();
  ui::flow(ui::button_width("Step \xE2\x96\xB6"));
  ImGui::BeginDisabled(stepping(*lesson_).finished());
  if (ImGui::Button("Step \xE2\x96\xB6")) stepping(*lesson_).step_forward();  // ▶
  web::record_control("step");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("one step (.)");
  ui::flow(ui::button_width("Finish phase"));
  if (ImGui::Button("Finish phase")) stepping(*lesson_).finish_phase();
  web::record_control("finish-phase");
  ui::flow(ui::button_width("Run all"));
  if (ImGui::Button("Run all")) stepping(*lesson_).run_all();
  web::record_control("run-all");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(stepping(*lesson_).finished() && !pb.playing);
  if (ImGui::Button(pb.playing ? "Pause " : "\xE2\x96\xB6 Play")) pb.playing = !pb.playing;
  web::record_control("play");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("play or pause (Space)");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    stepping(*lesson_).reset();
    pb.playing = false;
  }
  ImGui::SameLine();
  ImGui::PushItemWidth(-1);
  ImGui::SliderFloat("##speed", &pb.steps_per_second, 1.0f, 5000.0f, "%.0f steps/s", ImGuiSliderFlags_Logarithmic);
  ImGui::PopItemWidth();
  ImGui::Spacing();
}

void App::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (stepping(*lesson_).busy() && !io.WantTextInput && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) stepping(*lesson_).cancel_work();
  if (io.WantTextInput || io.KeyCtrl || io.KeyAlt) return;
  // F: every view of the lesson back to its whole rectangle (after zooming and panning).
  for (ImWchar c : io.InputQueueCharacters)
    if (c == 'f' || c == 'F')
      for (auto& [name, view] : ctx_.views) view->reset_view();
  if (!shows_controls(*lesson_)) return;
  for (ImWchar c : io.InputQueueCharacters) {
    if (c == ' ') ctx_.playback.playing = !ctx_.playback.playing && !stepping(*lesson_).finished();
    if (c == '.') stepping(*lesson_).step_forward();
    if (c == ',') stepping(*lesson_).step_back();
  }
}

void App::notice() {
  notice_box_ = {};
  if (ctx_.notice.empty() || ImGui::GetTime() > ctx_.notice_until) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // At the bottom it covered a phone's panel (P13's Field sliders, for 5 s) or its views' strip:
  // in the compact layout it is over the top bar, whose buttons are not what was just used (and
  // take a tap through it).
  const bool top = ctx_.compact;
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f,
                                 top ? vp->WorkPos.y + 4 : vp->WorkPos.y + vp->WorkSize.y - 24),
                          ImGuiCond_Always, ImVec2(0.5f, top ? 0.0f : 1.0f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  ImGui::Begin("##notice", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  // Long notices wrap (on a phone, within the screen's width).
  ImGui::PushTextWrapPos(ctx_.compact ? vp->WorkSize.x - 4 * ImGui::GetStyle().WindowPadding.x
                                      : std::max(200.0f, vp->WorkSize.x * 0.7f));
  ImGui::TextColored(theme::vec4(theme::kTextNotice), "%s", ctx_.notice.c_str());
  ImGui::PopTextWrapPos();
  notice_box_ = {ImGui::GetWindowPos(), ImVec2(ImGui::GetWindowPos().x + ImGui::GetWindowWidth(),
                                               ImGui::GetWindowPos().y + ImGui::GetWindowHeight())};
  ImGui::End();
}

}  // namespace csl::app
