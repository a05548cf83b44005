#pragma once
// The command line of the n-dimensional chapters (taught in chapter 18,
// shared by 18, 19 and 20): which scene of vkt::ndim::make_scene, its
// dimension, the projection, and whether the objects turn.

#include "vkt/frame/args.hpp"

#include <string>
#include <vector>

namespace vkt::ndim {

// --scene, --dim (3..12), --projection and --motion, with their help text.
std::vector<OptionSpec> scene_options();

struct SceneChoice {
    std::string scene;  // default, cube or many
    int n = 4;          // 4 for the default scene
    bool orthographic = false;
    bool still = false;
};

// Reads the flags of scene_options(). Throws when --dim is given with the
// default scene, which is 4-dimensional whatever the flag says.
SceneChoice scene_choice(const Options& options);

}  // namespace vkt::ndim
