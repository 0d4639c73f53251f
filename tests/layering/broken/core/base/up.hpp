#pragma once
// Broken on purpose (tests/CMakeLists.txt expects the layer check to fail here): the bottom
// layer reaching up into planning.
#include "core/planning/prm.hpp"
