#pragma once
// The app's JS-visible API: named commands taking and returning JSON, reached from the page
// through one exported C function, csl_call(). Tests drive the app with it, embedders will too.
// Requests are parsed strictly as JSON: nothing from the page is ever evaluated.
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace csl::app {

/// A command's refusal; its message reaches the caller as {"ok": false, "error": message}.
class ApiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using ApiHandler = std::function<nlohmann::json(const nlohmann::json& args)>;

class JsApi {
 public:
  /// Registers a command; `help` is one line shown by the "help" command.
  void add(const std::string& name, const std::string& help, ApiHandler handler);
  /// request {"cmd": NAME, "args": {...}} -> {"ok": true, "result": ...} or {"ok": false, "error": "..."}.
  std::string call(const std::string& request) const;
  /// Runs before every command's handler: what the app keeps up to date between frames (the
  /// scenes' names after an edit by the API) is up to date for every answer.
  void before_each(std::function<void()> hook) { before_ = std::move(hook); }

 private:
  struct Entry {
    std::string help;
    ApiHandler handler;
  };
  std::map<std::string, Entry> commands_;
  std::function<void()> before_;
};

/// The one instance the exported csl_call() uses.
JsApi& js_api();

}  // namespace csl::app

extern "C" {
/// Runs one API request (UTF-8 JSON). The returned string stays valid until the next call.
const char* csl_call(const char* request);
}
