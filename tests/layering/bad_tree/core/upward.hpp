#pragma once
// A planted violation for the test layering_rejects_a_violation: core may not include render.
#include "core/math.hpp"
#include "render/scene.hpp"
