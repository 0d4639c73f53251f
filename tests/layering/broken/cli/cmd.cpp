// Broken on purpose: the CLI reaching into the app.
#include <app/shell/lesson.hpp>
