#pragma once
// The embedded UI font (DejaVu Sans, subset at build time by cmake/EmbedFont.cmake).
namespace csl::app {
extern const unsigned char kUiFontData[];
extern const int kUiFontSize;
/// ImGui glyph ranges matching the subset: pairs of code points, zero-terminated.
extern const unsigned short kUiFontRanges[];
}  // namespace csl::app
