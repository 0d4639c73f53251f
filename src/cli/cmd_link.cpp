// cspacelab link [SCENE.json] --lesson ID [--params JSON] [--lock ...] [--hide ...]
// [--reveal ...] [--task TEXT] [--base URL]: the link (and the iframe) that opens the lab on a
// lesson with a scene from a file, written as the page's own Share and Embed write them, so
// that the browser reads back the file's scene bit for bit (web/lab-url.js decodes it).
//
// The scene is z.<base64url of the deflate-raw of its JSON>, what a browser's
// CompressionStream('deflate-raw') makes: zlib with the same settings (level 6, a raw 32 KB
// window, memLevel 8), which is what Chromium's stream runs, so a link is as short as the
// page's own. Without zlib (the wasm build of the CLI, which has no zlib port offline) the
// scene is written j.<base64url of the JSON>, which every browser reads too.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/base/text.hpp"
#include "core/teaching/answer_descriptions.hpp"
#include "core/teaching/lesson_catalogue.hpp"
#include "core/teaching/restrictions.hpp"

#ifdef CSPACELAB_HAVE_ZLIB
#include <zlib.h>
#endif

namespace csl::cli {
namespace {

using json = nlohmann::json;

// web/lab-url.js's LIMITS: an encoded scene, a task and any other value, as a link may carry them.
constexpr std::size_t kMaxSceneParam = 64 * 1024;
constexpr std::size_t kMaxTaskParam = 12 * 1024;
constexpr std::size_t kMaxValue = 256;
// web/lab-task.js: a task holds at most this many characters.
constexpr std::size_t kMaxTaskChars = 1000;

// Characters (code points) of UTF-8 text: what Array.from(text).length counts.
std::size_t characters(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// The task as web/lab-task.js normalise() shows it: lines, each trimmed, runs of spaces one,
// control characters (and the bidi overrides) spaces, empty lines gone.
std::vector<std::string> task_lines(const std::string& raw) {
  std::string text;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(raw[i]);
    if (c == '\r') {
      text += '\n';
      if (i + 1 < raw.size() && raw[i + 1] == '\n') ++i;
    } else if (c == '\n') {
      text += '\n';
    } else if (c < 0x20 || c == 0x7f) {
      text += ' ';
    } else if (c == 0xC2 && i + 1 < raw.size() && static_cast<unsigned char>(raw[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(raw[i + 1]) <= 0x9f) {
      text += ' ';  // a C1 control
      ++i;
    } else if (c == 0xE2 && i + 2 < raw.size() &&
               ((raw[i + 1] == '\x80' && static_cast<unsigned char>(raw[i + 2]) >= 0xAA && static_cast<unsigned char>(raw[i + 2]) <= 0xAE) ||
                (raw[i + 1] == '\x81' && static_cast<unsigned char>(raw[i + 2]) >= 0xA6 && static_cast<unsigned char>(raw[i + 2]) <= 0xA9))) {
      text += ' ';  // U+202A-202E, U+2066-2069: the bidi overrides
      i += 2;
    } else {
      text += static_cast<char>(c);
    }
  }
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    std::string squeezed;
    for (const char c : line)
      if (!(c == ' ' && !squeezed.empty() && squeezed.back() == ' ')) squeezed += c;
    const std::size_t a = squeezed.find_first_not_of(' ');
    if (a != std::string::npos) lines.push_back(squeezed.substr(a, squeezed.find_last_not_of(' ') - a + 1));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

// The iframe's extra height for the task above the canvas (web/lab-task.js height(), at 700 px).
int task_height(const std::vector<std::string>& lines) {
  if (lines.empty()) return 0;
  const int width = 700, per_line = std::max(20, (width - 26) * 2 / 15);  // floor((width - 26) / 7.5)
  int rows = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int chars = static_cast<int>(characters(lines[i])) + (i ? 0 : 6);
    rows += std::max(1, (chars + per_line - 1) / per_line);
  }
  return std::min(width * 2 / 5, 14 + 20 * rows + 2 * (static_cast<int>(lines.size()) - 1));
}

std::string base64url(const std::string& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                            static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                            static_cast<unsigned char>(bytes[i + 2]);
    for (int shift = 18; shift >= 0; shift -= 6) out += kAlphabet[(v >> shift) & 63];
  }
  // No padding, as the page writes it: 1 byte left is 2 characters, 2 bytes 3.
  if (i < bytes.size()) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    if (i + 1 < bytes.size()) out += kAlphabet[(v >> 6) & 63];
  }
  return out;
}

#ifdef CSPACELAB_HAVE_ZLIB
// deflate-raw as CompressionStream makes it: Z_DEFAULT_COMPRESSION (6), windowBits -15, memLevel 8.
std::string deflate_raw(const std::string& in) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: deflateInit2 failed");
  std::string out(deflateBound(&z, static_cast<uLong>(in.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  const std::size_t size = z.total_out;
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("zlib: deflate did not finish");
  out.resize(size);
  return out;
}
#endif

// A double as JavaScript's Number#toString writes it (JSON.stringify's numbers): the shortest
// digits that read back as it, "1" not "1.0", "0.000001" not "1e-06", "1e-7" not "1e-07". The
// page's Share deflates JSON.stringify's text; the same text deflates to the same length.
std::string js_number(double v) {
  if (v == 0.0) return "0";  // -0 too, as JSON.stringify writes it
  std::string text = json(v).dump();  // nlohmann: the shortest round-trip digits
  std::string sign;
  if (text[0] == '-') {
    sign = "-";
    text.erase(0, 1);
  }
  int exponent = 0;
  if (const std::size_t e = text.find_first_of("eE"); e != std::string::npos) {
    exponent = std::stoi(text.substr(e + 1));
    text.erase(e);
  }
  const std::size_t point = text.find('.');
  const int int_len = static_cast<int>(point == std::string::npos ? text.size() : point);
  if (point != std::string::npos) text.erase(point, 1);
  // value = 0.D x 10^n, D without leading or trailing zeros.
  const std::size_t lead = text.find_first_not_of('0');
  std::string digits = text.substr(lead);
  digits.erase(digits.find_last_not_of('0') + 1);
  const int n = int_len - static_cast<int>(lead) + exponent, k = static_cast<int>(digits.size());
  if (k <= n && n <= 21) return sign + digits + std::string(static_cast<std::size_t>(n - k), '0');
  if (0 < n && n <= 21) return sign + digits.substr(0, static_cast<std::size_t>(n)) + "." + digits.substr(static_cast<std::size_t>(n));
  if (-6 < n && n <= 0) return sign + "0." + std::string(static_cast<std::size_t>(-n), '0') + digits;
  const int e = n - 1;
  return sign + digits.substr(0, 1) + (k > 1 ? "." + digits.substr(1) : "") + "e" + (e < 0 ? "-" : "+") +
         std::to_string(e < 0 ? -e : e);
}

// JSON.stringify's text of `j`: compact, in the object's own key order (the app's, sorted),
// strings as nlohmann escapes them (the same escapes), numbers by js_number().
void js_json(const json& j, std::string& out) {
  switch (j.type()) {
    case json::value_t::object: {
      out += '{';
      bool first = true;
      for (auto it = j.begin(); it != j.end(); ++it) {
        if (!first) out += ',';
        first = false;
        out += json(it.key()).dump(-1, ' ', false);
        out += ':';
        js_json(it.value(), out);
      }
      out += '}';
      break;
    }
    case json::value_t::array: {
      out += '[';
      for (std::size_t i = 0; i < j.size(); ++i) {
        if (i) out += ',';
        js_json(j[i], out);
      }
      out += ']';
      break;
    }
    case json::value_t::number_float: out += js_number(j.get<double>()); break;
    default: out += j.dump(-1, ' ', false); break;
  }
}

std::string encode_scene(const Scene& scene) {
  // Compact JSON in UTF-8, as JSON.stringify and TextEncoder write it (the app's key order).
  std::string text;
  js_json(scene_to_json(scene), text);
#ifdef CSPACELAB_HAVE_ZLIB
  return "z." + base64url(deflate_raw(text));
#else
  return "j." + base64url(text);
#endif
}

// encodeURIComponent, leaving ':' and ',' as they are (web/lab-url.js encodeValue).
std::string encode_value(const std::string& text) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out;
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       std::string("-_.!~*'():,").find(static_cast<char>(c)) != std::string::npos;
    if (plain) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

// A parameter's value as a link writes it (web/lab-url.js formatValue): a number in the
// shortest text that reads back as it, true/false, a string, comma-separated numbers.
std::string format_value(const std::string& key, const json& v) {
  if (v.is_number_float()) return js_number(v.get<double>());
  if (v.is_number() || v.is_boolean()) return v.dump();
  if (v.is_string()) return v.get<std::string>();
  bool numbers = v.is_array() && !v.empty();
  std::string out;
  for (std::size_t i = 0; numbers && i < v.size(); ++i) {
    numbers = v[i].is_number();
    out += (i ? "," : "") + (v[i].is_number_float() ? js_number(v[i].get<double>()) : v[i].dump());
  }
  if (numbers) return out;
  throw UsageError("--params: " + key + " cannot be written in a link");
}

std::string escape_attribute(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

// FNV-1a over the UTF-16 code units of `text`, as web/lab-url.js's hash(): a link's id.
std::string fnv_hex(const std::string& text) {
  std::uint32_t h = 0x811c9dc5u;
  for (const char c : text) {  // the query is ASCII (everything else is percent-encoded)
    h ^= static_cast<unsigned char>(c);
    h *= 0x01000193u;
  }
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", h);
  return buf;
}

// The folder of index.html and embed.html: "" (next to the course page) or a URL ending in '/'.
std::string check_base(const std::string& base) {
  if (base.empty()) return base;
  const bool bad_char = base.find_first_of(" \t\r\n\"'<>`") != std::string::npos;
  const bool scheme_ok = base.rfind("https://", 0) == 0 || base.rfind("http://", 0) == 0 ||
                         (base.find(':') == std::string::npos);  // a relative folder: "../lab/"
  if (bad_char || !scheme_ok || base.back() != '/')
    throw UsageError("--base: '" + printable(base, 80) +
                     "' is not the lab's folder: an http(s) URL or a relative path ending in '/', without spaces or quotes");
  return base;
}

void add(std::string& query, const std::string& key, const std::string& encoded) {
  const std::size_t limit = key == "scene" ? kMaxSceneParam : key == "task" ? kMaxTaskParam : kMaxValue;
  if (encoded.size() > limit)
    throw UsageError(std::string(key == "scene" ? "the scene" : "--" + key) + " takes " + std::to_string(encoded.size()) +
                     " characters in a link, more than the " + std::to_string(limit) + " a link may carry" +
                     (key == "scene" ? " (share the scene file instead)" : ""));
  query += (query.empty() ? "" : "&") + key + "=" + encoded;
}

// --list: the lessons and what a link may lock and hide in each (core's lists).
json catalogue_json() {
  const auto words = [](std::initializer_list<std::string_view> list) {
    json out = json::array();
    for (const std::string_view w : list) out.push_back(std::string(w));
    return out;
  };
  json lessons = json::array(), answers = json::array();
  for (const CataloguedLesson& l : lesson_catalogue()) {
    json params = json::array();
    for (const LessonParam& p : l.params) params.push_back(std::string(p.name));
    lessons.push_back({{"id", std::string(l.id)}, {"name", std::string(l.name)}, {"params", params}, {"robots", words(l.robots)}});
  }
  for (const HideableAnswer& a : hideable_answers())
    answers.push_back({{"name", std::string(a.name)}, {"lesson", std::string(a.lesson)},
                       {"what", std::string(answer_description(a.lesson, a.name))},
                       {"problems", words(a.problems)}, {"fields", words(a.fields)}});
  return {{"lessons", lessons}, {"answers", answers}};
}

int run_link(Args& args, std::ostream& os) {
  if (args.take_flag("list")) {
    args.finish();
    print_json(os, catalogue_json());
    return 0;
  }
  const std::optional<std::string> lesson_id = args.take("lesson");
  if (!lesson_id) throw UsageError("--lesson is missing (" + lesson_ids_text() + ")");
  const CataloguedLesson* lesson = find_catalogued_lesson(*lesson_id);
  if (!lesson) throw UsageError("--lesson: '" + printable(*lesson_id, 40) + "' is not a lesson (" + lesson_ids_text() + ")");
  const std::optional<std::string> params_text = args.take("params");
  const std::string lock = args.take("lock").value_or("");
  const std::string hide = args.take("hide").value_or("");
  const std::optional<std::string> reveal = args.take("reveal");
  const std::optional<std::string> task = args.take("task");
  const std::string base = check_base(args.take("base").value_or(""));
  std::optional<Scene> scene;
  if (lesson->robots.size() > 0) scene = load_scene(args.take_positional("SCENE.json"));
  args.finish();

  if (scene)
    if (const std::string problem = lesson_scene_problem(*lesson, *scene); !problem.empty())
      throw UsageError("SCENE.json: " + problem);
  json params = json::object();
  if (params_text) {
    try {
      params = parse_json_text(*params_text);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--params: not JSON: ") + e.what());
    }
    if (const std::string problem = lesson_params_problem(*lesson, params); !problem.empty())
      throw UsageError("--params: " + problem);
  }
  Restrictions r;
  try {
    r = parse_restrictions(lock, hide, reveal.value_or(""), std::string(lesson->id));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--") + e.what());
  }

  // In the order of the page's Share (lesson, scene, parameters) and then the rest.
  std::string query;
  add(query, "lesson", encode_value(std::string(lesson->id)));
  if (scene) add(query, "scene", encode_scene(*scene));
  for (auto it = params.begin(); it != params.end(); ++it) add(query, it.key(), encode_value(format_value(it.key(), *it)));
  if (!r.lock_text().empty()) add(query, "lock", encode_value(r.lock_text()));
  if (!r.hide_text().empty()) add(query, "hide", encode_value(r.hide_text()));
  if (reveal) add(query, "reveal", encode_value(r.reveal_text()));
  // The task, as the page shows it (web/lab-task.js): refused past its 1000 characters, where the
  // page would cut it.
  std::string with_task;
  std::vector<std::string> lines;
  if (task) {
    lines = task_lines(*task);
    std::string text;
    for (const std::string& l : lines) text += (text.empty() ? "" : "\n") + l;
    if (text.empty()) throw UsageError("--task: an empty text");
    if (characters(text) > kMaxTaskChars)
      throw UsageError("--task: " + std::to_string(characters(text)) + " characters; a task holds at most " +
                       std::to_string(kMaxTaskChars));
    std::string task_query;
    add(task_query, "task", encode_value(text));
    with_task = "&" + task_query;
  }
  // The Embed dialog's iframe (web/lab-shell.js embedSnippets()): the task after the state, its
  // own autosave id from the link, and as much taller than 600 px as the task above the canvas.
  const std::string id = "lab-" + fnv_hex(query).substr(0, 6);
  const std::string iframe = "<iframe src=\"" + escape_attribute(base + "embed.html?" + query + with_task + "&id=" + id) +
                             "\" width=\"100%\" height=\"" + std::to_string(600 + task_height(lines)) +
                             "\" style=\"border:0\" title=\"C-Space Lab: " + escape_attribute(std::string(lesson->name)) +
                             "\" allow=\"clipboard-write\"></iframe>";
  print_json(os, {{"url", base + "index.html?" + query + with_task}, {"iframe", iframe}});
  return 0;
}

}  // namespace

const Command kLinkCommand{
    "link", "the link and iframe that open a lesson with a scene file, locked and hidden as asked",
    "Usage: cspacelab link [SCENE.json] --lesson ID [--params JSON] [--lock WORDS] [--hide WORDS]\n"
    "                      [--reveal never|after-answer] [--task TEXT] [--base URL]\n"
    "       cspacelab link --list\n\n"
    "Prints {\"url\": ..., \"iframe\": ...}: the link that opens the lab on lesson ID with the scene of\n"
    "SCENE.json (validated as `cspacelab validate` does; lessons without a scene, notation and\n"
    "distances, take none), and the iframe the lab's Embed button would write for it. The browser\n"
    "reads back exactly the file's scene, to the last bit of every number.\n\n"
    "  --lesson ID      torus, notation, cspace-3d, collision, compare, distances, analysis,\n"
    "                   potential or step-prm\n"
    "  --params JSON    the lesson's parameters, e.g. '{\"grid_n\": 9, \"p\": [0.2, 0.3]}': each key one of\n"
    "                   the lesson's (cspacelab link --list names them), each value of its kind\n"
    "                   and range; the lab checks what depends on the scene (budgets) when it opens.\n"
    "                   A list (analysis's sample_counts, potential's from) must have as many numbers\n"
    "                   as the lesson's own value: a link cannot change a list's length\n"
    "  --lock WORDS     comma-separated: scene (no edit of the scene), params (no parameter changes),\n"
    "                   lesson (no other lesson), or a parameter's name (that one fixed)\n"
    "  --hide WORDS     answers (every lesson's), none, or answers by name: collision min_n;\n"
    "                   analysis p8_n, p9_probability; distances s1_distance, segment_distance;\n"
    "                   potential p13_forces; notation q_notation; torus, step-prm and compare\n"
    "                   path_length\n"
    "  --reveal WHEN    never (default), or after-answer: a hidden answer comes back once the\n"
    "                   homework exercise of its problem was answered right in that visit\n"
    "  --task TEXT      the exercise's text, shown above the lab (the link's task=): plain text, each\n"
    "                   line a paragraph, at most 1000 characters; the iframe is taller by its height\n"
    "  --base URL       the lab's folder, ending in '/' (https://your.site/cspacelab/); default\n"
    "                   none: index.html and embed.html next to the course page\n\n"
    "--list prints the lessons and what a link may lock and hide in each:\n"
    "  {\"lessons\": [{\"id\", \"name\", \"params\", \"robots\"}],\n"
    "   \"answers\": [{\"name\", \"lesson\", \"what\", \"problems\", \"fields\"}]}\n"
    "(fields: where the lesson's state() holds the answer; the lab leaves them out while hidden).\n\n"
    "The scene is written z.<base64url of its deflate-raw JSON>, as the page's Share writes it\n"
    "(j.<base64url of the JSON> from a build without zlib). Servers often refuse addresses over\n"
    "about 8 KB: a scene that needs more is better shared as its file. A value past what a link\n"
    "may carry (the scene 64 KB, anything else 256 characters) is an error.\n"
    "docs/web.md lists what each lock and each hidden answer does in the lab.\n",
    run_link};

}  // namespace csl::cli
