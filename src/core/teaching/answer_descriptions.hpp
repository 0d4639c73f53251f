#pragma once
// Each hideable answer (restrictions.hpp) in words, and what stays in sight where that is a
// choice: for `cspacelab link --list` and the tests. Apart from the list itself so that the app,
// which does not show these sentences, does not carry them in its wasm (whose budget is tight).
#include <string_view>

namespace csl {

/// What answer `name` of `lesson` is, in one sentence; empty for an unknown one.
std::string_view answer_description(std::string_view lesson, std::string_view name);

}  // namespace csl
