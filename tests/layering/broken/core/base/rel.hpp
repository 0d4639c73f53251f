#pragma once
// Broken on purpose: a relative include, which the compiler finds and the rules would not see.
#include "../planning/prm.hpp"
