// The showcase scene behind "builtin:default" (internal: reached through make_procedural_scene).
#pragma once
#include <zraster/scene.hpp>

namespace zraster {

Scene make_default_scene();

}  // namespace zraster
