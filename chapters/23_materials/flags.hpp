#pragma once
// Chapter 23's flags that do not go together, refused before anything is
// made, each with what to change; the bloom's --bloom-average; and --term,
// one factor of the BRDF alone.

#include "vkt/frame/args.hpp"

#include <vulkan/vulkan.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
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

// --term d|f|v: scene.frag draws one factor of the specular BRDF alone, as a
// plain number (page 23's row of pictures); all: the whole shading.
inline vkt::OptionSpec term_option() {
    return {.name = "--term",
            .type = vkt::OptionType::choice,
            .value_name = "TERM",
            .help =
                "all: the whole BRDF; or one factor of its specular part alone, as a number "
                "(under the uniform sky): d (GGX), f (Fresnel), v (Smith's, as G)",
            .default_value = "all",
            .choices = {"all", "d", "f", "v"}};
}

// [term-constant]
// The choice reaches the shader as its specialization constant 0: the
// compiler drops the branches the pipeline never takes. For all, no
// specialization at all: the pipeline is the one made without the flag.
// main.cpp makes it as a temporary inside the pipeline's create call: it
// lives until that call has returned, as info() must.
class TermConstant {
public:
    explicit TermConstant(const vkt::Options& options)
        : value_(options.text("--term") == "d"   ? 1
                 : options.text("--term") == "f" ? 2
                 : options.text("--term") == "v" ? 3
                                                 : 0) {}
    TermConstant(const TermConstant&) = delete;  // info_ points into this object
    TermConstant& operator=(const TermConstant&) = delete;
    const VkSpecializationInfo* info() const { return value_ == 0 ? nullptr : &info_; }

private:
    int32_t value_;
    VkSpecializationMapEntry entry_{0, 0, sizeof(int32_t)};
    VkSpecializationInfo info_{1, &entry_, sizeof(int32_t), &value_};
};
// [/term-constant]

// --term with what it cannot show, refused first: it draws the grid's spheres
// by scene.frag, the uniform sky's shader, lit by the grid's key light.
inline void check_term(const vkt::Options& options) {
    const std::string& term = options.text("--term");
    if (term == "all") return;
    const std::string flag = "--term " + term;
    if (options.has("--model"))
        throw vkt::UsageError(flag + " shows the sphere grid's BRDF: leave out --model");
    if (options.text("--scene") == "furnace")
        throw vkt::UsageError(flag + " needs the grid's lights: leave out --scene furnace");
    if (options.has("--verify"))
        throw vkt::UsageError("--verify " + options.text("--verify") +
                              " checks the whole BRDF: leave out " + flag);
    if (options.text("--view") != "scene")
        throw vkt::UsageError(flag + " draws the spheres: leave out --view " +
                              options.text("--view"));
    if (options.text("--sky") != "uniform")
        throw vkt::UsageError(flag +
                              " is drawn by the uniform sky's shader: leave out --sky environment");
}

inline void check_flags(const vkt::Options& options) {
    check_term(options);
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
            "--verify cpu checks the uniform sky's CPU reference: leave out --sky environment");
    if (verify == "lut" && uniform)
        throw vkt::UsageError(
            "--verify lut checks the environment's BRDF table: add --sky environment");
    if (view != "scene" && view != "bloom" && uniform)
        throw vkt::UsageError("--view " + view +
                              " shows the environment's images: add --sky environment");
    // The chain is made only with --bloom F (above 0): without it, there is nothing to show.
    if (view == "bloom" && options.number("--bloom") == 0)
        throw vkt::UsageError("--view bloom shows the bloom's levels: add --bloom F");
    if (options.text("--bloom-average") != "box" && options.number("--bloom") == 0)
        throw vkt::UsageError("--bloom-average " + options.text("--bloom-average") +
                              " changes the bloom: add --bloom F");
    if (view != "scene" && (verify == "cpu" || verify == "furnace"))
        throw vkt::UsageError("--verify " + verify + " checks the scene: leave out --view " + view);
}

// The flags' choices, said once at start-up (the tests read this line).
inline void print_settings(const vkt::Options& options) {
    const double exposure = options.number("--exposure");
    std::fprintf(
        stderr,
        "23_materials: %s, sky %s, HDR target R16G16B16A16_SFLOAT, exposure %+.2f EV "
        "(x%.3f), tone map %s, bloom %.2f%s\n",
        options.has("--model")                 ? "a glTF model"
        : options.text("--scene") == "furnace" ? "the white furnace"
                                               : "the sphere grid",
        options.text("--sky") == "environment" ? "environment (image-based light)" : "uniform",
        exposure, std::exp2(exposure),
        options.text("--tone-map") == "aces" ? "ACES (Narkowicz's fit)" : "clamp",
        options.number("--bloom"),
        options.text("--bloom-average") == "karis" ? ", Karis average" : "");
}
