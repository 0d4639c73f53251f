// C-Space Lab, the interactive app: a desktop window natively, a WebGL2 canvas in the browser.
//   cspacelab_app [--frames N]    (desktop; --frames quits after N frames, for smoke tests)
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "app/shell/app.hpp"
#include "app/shell/platform.hpp"

int main(int argc, char** argv) {
  csl::app::PlatformOptions options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      options.max_frames = std::strtol(argv[++i], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: cspacelab_app [--frames N]\n");
      return 2;
    }
  }
  static csl::app::Platform platform;  // static: outlives main() in the browser's loop
  if (!platform.init(options)) return 1;
  static csl::app::App app(platform);
  platform.run([] { app.frame(); });
  platform.shutdown();
  return 0;
}
