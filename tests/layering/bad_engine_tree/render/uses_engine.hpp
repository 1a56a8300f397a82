#pragma once
// A planted violation for the test layering_rejects_render_using_engine: render sits below the
// four-lane engine and may not include it.
#include "engine/path_tracer_lanes.hpp"
#include "render/scene.hpp"
