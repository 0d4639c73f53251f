#pragma once
#include "core/base/up.hpp"
