#pragma once
// Chapter 23's flags that do not go together, refused before anything is
// made, each with what to change; and the bloom's --bloom-average.

#include "vkt/frame/args.hpp"

#include <string>

// How the bloom's first halving averages its four taps (page 23d): box, the
// plain mean; karis, each weighed by 1 / (1 + luma), which keeps a lone
// bright pixel from blinking as a square when it moves (a firefly).
inline vkt::OptionSpec bloom_average_option() {
    return {.name = "--bloom-average",
            .type = vkt::OptionType::choice,
            .value_name = "KIND",
            .help =
                "the bloom's first halving: box (the mean of 4 taps) or karis (each weighed "
                "by 1/(1+luma), against fireflies)",
            .default_value = "box",
            .choices = {"box", "karis"}};
}

inline void check_flags(const vkt::Options& options) {
    const bool model = options.has("--model"), furnace = options.text("--scene") == "furnace";
    if (model && furnace)
        throw vkt::UsageError("--model draws a glTF file: leave out --scene furnace");
    if (model && options.has("--verify"))
        throw vkt::UsageError("--verify checks the generated spheres: leave out --model");
    const std::string verify = options.has("--verify") ? options.text("--verify") : "";
    const std::string& view = options.text("--view");
    const bool uniform = options.text("--sky") == "uniform";
    if (verify == "furnace" && !furnace)
        throw vkt::UsageError("--verify furnace needs --scene furnace");
    if (verify == "cpu" && !uniform)
        throw vkt::UsageError(
            "--verify cpu checks the uniform sky's CPU reference: add --sky uniform");
    if (verify == "lut" && uniform)
        throw vkt::UsageError(
            "--verify lut checks the environment's BRDF table: leave out --sky uniform");
    if (view != "scene" && uniform)
        throw vkt::UsageError("--view " + view +
                              " shows the environment's images: leave out --sky uniform");
    if (options.text("--bloom-average") != "box" && options.number("--bloom") == 0)
        throw vkt::UsageError("--bloom-average " + options.text("--bloom-average") +
                              " changes the bloom: add --bloom F");
    if (view != "scene" && (verify == "cpu" || verify == "furnace"))
        throw vkt::UsageError("--verify " + verify + " checks the scene: leave out --view " + view);
}
