#include "vkt/scene/ndim_options.hpp"

namespace vkt::ndim {

// [scene-options]
std::vector<OptionSpec> scene_options() {
    return {
        {.name = "--scene",
         .type = OptionType::choice,
         .help = "a tesseract and a 24-cell, one n-cube, or 250 n-cubes",
         .default_value = "default",
         .choices = {"default", "cube", "many"}},
        // 3: below that there is nothing to project. 12: 250 12-cubes are
        // 6.1 million lines a frame (chapter 18: 141 MiB of line vertices
        // per frame in flight; 20: a 49 MiB index buffer); each step up
        // doubles the vertices and more than doubles the edges, and the
        // shaders of 19 and 20 size their arrays for 12.
        {.name = "--dim",
         .type = OptionType::integer,
         .value_name = "N",
         .help = "the dimension n of the cubes of --scene cube and many (default 4)",
         .min = 3,
         .max = 12},
        {.name = "--projection",
         .type = OptionType::choice,
         .help = "perspective (the eye on each last axis) or orthographic (drop it)",
         .default_value = "perspective",
         .choices = {"perspective", "orthographic"}},
        {.name = "--motion",
         .type = OptionType::choice,
         .help = "turn in every plane, or stand still with every angle 0",
         .default_value = "spin",
         .choices = {"spin", "still"}},
    };
}
// [/scene-options]

SceneChoice scene_choice(const Options& options) {
    SceneChoice choice;
    choice.scene = options.text("--scene");
    if (choice.scene == "default" && options.has("--dim"))
        throw UsageError("--dim " + options.text("--dim") +
                         ": the default scene is 4-dimensional; use --scene cube or "
                         "--scene many to choose n");
    choice.n = options.has("--dim") ? int(options.integer("--dim")) : 4;
    choice.orthographic = options.text("--projection") == "orthographic";
    choice.still = options.text("--motion") == "still";
    return choice;
}

}  // namespace vkt::ndim
