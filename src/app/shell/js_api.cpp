#include "app/shell/js_api.hpp"

#include "core/base/text.hpp"
#include "core/scene/scene.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#define CSL_EXPORT EMSCRIPTEN_KEEPALIVE
#else
#define CSL_EXPORT
#endif

namespace csl::app {

using json = nlohmann::json;

namespace {
// Invalid UTF-8 from the page (say, in an unknown command's name) must not make dump() throw.
std::string text(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }
}  // namespace

void JsApi::add(const std::string& name, const std::string& help, ApiHandler handler) {
  commands_[name] = Entry{help, std::move(handler)};
}

std::string JsApi::call(const std::string& request) const {
  // A message is one printable line whatever it quotes (a key, a scene's name, a command). Long
  // enough for every problem of an assignment file at once (assignment_open), each ~100 bytes.
  auto error = [](const std::string& message) { return text(json{{"ok", false}, {"error", printable(message, 8000)}}); };
  json req;
  try {
    // Strict and at most 64 levels deep: handlers copy their arguments, and copying a value
    // nested 100000 deep (a request written by hand, not by JSON.stringify) overflows the stack.
    req = parse_json_text(request);
  } catch (const std::invalid_argument& e) {
    return error(std::string("request: ") + e.what());
  }
  if (!req.is_object()) return error("request is not a JSON object");
  auto cmd = req.find("cmd");
  if (cmd == req.end() || !cmd->is_string()) return error("request has no \"cmd\" string");
  const std::string name = cmd->get<std::string>();
  if (name == "help") {
    json list = json::object();
    for (const auto& [n, e] : commands_) list[n] = e.help;
    return text(json{{"ok", true}, {"result", list}});
  }
  auto it = commands_.find(name);
  if (it == commands_.end()) return error("unknown command \"" + printable(name, 60) + "\" (try \"help\")");
  json args = req.value("args", json::object());
  if (!args.is_object()) return error("\"args\" must be an object");
  try {
    if (before_) before_();
    return text(json{{"ok", true}, {"result", it->second.handler(args)}});
  } catch (const std::exception& e) {
    // ApiError, SceneError and json type errors alike: the app state is untouched by a
    // handler that throws before it commits, which every handler is written to do.
    return error(e.what());
  }
}

JsApi& js_api() {
  static JsApi api;
  return api;
}

}  // namespace csl::app

extern "C" CSL_EXPORT const char* csl_call(const char* request) {
  static std::string response;
  response = csl::app::js_api().call(request ? request : "");
  return response.c_str();
}
