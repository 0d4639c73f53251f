#pragma once
// Broken on purpose: a shared view naming a lesson.
#include "app/lessons/planner_session.hpp"
