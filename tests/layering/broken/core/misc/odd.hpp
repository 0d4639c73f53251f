#pragma once
// Broken on purpose: a folder that is no layer.
#include "core/base/up.hpp"
