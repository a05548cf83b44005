#include "vkt/frame/args.hpp"

#include "vkt/core/memory_budget.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <vector>

using vkt::Flags;
using vkt::Options;
using vkt::parse_args;
using vkt::UsageError;

static Options parse(std::vector<const char*> args, Flags flags = Flags::frame_loop) {
    return parse_args(args, flags);
}

TEST_CASE("no arguments give the defaults", "[args]") {
    Options o = parse({});
    CHECK_FALSE(o.headless);
    CHECK_FALSE(o.offscreen);
    CHECK_FALSE(o.frames.has_value());
    CHECK(o.width == 800);
    CHECK(o.height == 600);
    CHECK(o.screenshot.empty());
    CHECK_FALSE(o.benchmark);
    CHECK_FALSE(o.copy_to_swapchain);
    CHECK(o.device.empty());
    CHECK_FALSE(o.validation.has_value());
    CHECK_FALSE(o.help);
}

TEST_CASE("every flag is understood, with a separate or an inline value", "[args]") {
    Options o = parse({"--headless", "--frames", "12", "--size=640x480", "--screenshot", "a.png",
                       "--benchmark", "--device", "llvmpipe", "--no-validation"});
    CHECK(o.headless);
    CHECK(o.frames == 12u);
    CHECK(o.width == 640);
    CHECK(o.height == 480);
    CHECK(o.screenshot == "a.png");
    CHECK(o.benchmark);
    CHECK(o.device == "llvmpipe");
    CHECK(o.validation == false);
    CHECK(parse({"--validation"}).validation == true);
    CHECK(parse({"--copy-to-swapchain"}).copy_to_swapchain);
    CHECK(parse({"--frames=3"}).frames == 3u);
    CHECK(parse({"--help"}).help);
    CHECK(parse({"-h"}).help);
}

TEST_CASE("offscreen implies headless", "[args]") {
    Options o = parse({"--offscreen"});
    CHECK(o.offscreen);
    CHECK(o.headless);
}

TEST_CASE("the last of repeated flags wins", "[args]") {
    CHECK(parse({"--validation", "--no-validation"}).validation == false);
    CHECK(parse({"--frames", "2", "--frames", "5"}).frames == 5u);
}

TEST_CASE("malformed values are usage errors", "[args]") {
    CHECK_THROWS_AS(parse({"--frames", "-1"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames", "0"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames", "ten"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames", "10x"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames", "99999999999"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "0x0"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "640"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "640x"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "x480"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "-640x480"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "20000x20"}), UsageError);
    CHECK_THROWS_AS(parse({"--screenshot", ""}), UsageError);
    CHECK_THROWS_AS(parse({"--screenshot", "shot.jpg"}), UsageError);
    CHECK_THROWS_AS(parse({"--screenshot", ".png"}), UsageError);
    CHECK_THROWS_AS(parse({"--device="}), UsageError);
    CHECK_THROWS_AS(parse({"--headless=yes"}), UsageError);
}

TEST_CASE("unknown arguments are usage errors that name the argument", "[args]") {
    try {
        parse({"--frobnicate"});
        FAIL("no exception");
    } catch (const UsageError& e) {
        CHECK(std::string(e.what()) == "unknown argument '--frobnicate'");
    }
    CHECK_THROWS_AS(parse({"frames"}), UsageError);
}

TEST_CASE("text chapters refuse frame-loop flags but take the rest", "[args]") {
    CHECK_THROWS_AS(parse({"--frames", "3"}, Flags::device), UsageError);
    CHECK_THROWS_AS(parse({"--headless"}, Flags::device), UsageError);
    CHECK_THROWS_AS(parse({"--screenshot", "x.png"}, Flags::device), UsageError);
    CHECK_THROWS_AS(parse({"--device", "0"}, Flags::instance), UsageError);
    CHECK(parse({"--validation"}, Flags::instance).validation == true);
    Options o = parse({"--device", "1", "--validation"}, Flags::device);
    CHECK(o.device == "1");
    CHECK(o.validation == true);
}

TEST_CASE("usage and help name every flag the chapter takes", "[args]") {
    std::string help = vkt::help_text("04_triangle");
    for (const char* flag :
         {"--headless", "--offscreen", "--frames", "--size", "--screenshot", "--benchmark",
          "--copy-to-swapchain", "--device", "--validation", "--no-validation", "--help"})
        CHECK(help.find(flag) != std::string::npos);
    std::string text = vkt::usage_line("02_device", Flags::device);
    CHECK(text.find("--frames") == std::string::npos);
    CHECK(text.starts_with("usage: 02_device"));
    CHECK(text.find("--device") != std::string::npos);
    CHECK(vkt::usage_line("01_instance", Flags::instance).find("--device") == std::string::npos);
}

// --- A chapter's own flags (ChapterSpec::options) ---------------------------

static const std::vector<vkt::OptionSpec> chapter_options = {
    {.name = "--lights",
     .type = vkt::OptionType::integer,
     .value_name = "N",
     .help = "point lights",
     .default_value = "16",
     .min = 1,
     .max = 65536},
    {.name = "--exposure",
     .type = vkt::OptionType::number,
     .help = "exposure",
     .default_value = "1.5",
     .min = 0.25,
     .max = 4},
    {.name = "--view",
     .type = vkt::OptionType::choice,
     .help = "what to show",
     .default_value = "lit",
     .choices = {"lit", "albedo", "normal"}},
    {.name = "--model", .type = vkt::OptionType::text, .value_name = "FILE", .help = "a glTF file"},
};

static Options parse_chapter(std::vector<const char*> args) {
    return parse_args(args, Flags::frame_loop, chapter_options);
}

TEST_CASE("a chapter's flags get their defaults", "[args][chapter-options]") {
    Options o = parse_chapter({});
    CHECK(o.integer("--lights") == 16);
    CHECK(o.number("--exposure") == 1.5);
    CHECK(o.text("--view") == "lit");
    CHECK_FALSE(o.has("--model"));  // no default: unset
    CHECK_THROWS_AS(o.text("--model"), std::logic_error);
    CHECK_THROWS_AS(o.integer("--undeclared"), std::logic_error);
}

TEST_CASE("a chapter's flags take values in range, separate or inline", "[args][chapter-options]") {
    Options o = parse_chapter({"--lights", "65536", "--exposure=0.25", "--view", "normal",
                               "--model", "scene.glb", "--headless"});
    CHECK(o.integer("--lights") == 65536);
    CHECK(o.number("--exposure") == 0.25);
    CHECK(o.text("--view") == "normal");
    CHECK(o.text("--model") == "scene.glb");
    CHECK(o.headless);
    CHECK(parse_chapter({"--lights", "1"}).integer("--lights") == 1);
}

// Found by tests/fuzz/fuzz_args.cpp (regressions/args/subnormal_number): a
// subnormal number passed the range check but std::stod refused to read it
// back, so 14_physics --warmup 4e-320 ended with "error: stod".
TEST_CASE("a number the check accepts reads back, subnormal ones too", "[args][chapter-options]") {
    const std::vector<vkt::OptionSpec> from_zero = {
        {.name = "--warmup", .type = vkt::OptionType::number, .min = 0, .max = 60}};
    const std::vector<const char*> args = {"--warmup", "4e-320"};
    const Options o = parse_args(args, Flags::frame_loop, from_zero);
    CHECK(o.number("--warmup") > 0.0);
    CHECK(o.number("--warmup") < 1e-300);
}

TEST_CASE("a chapter's flags refuse bad values with a clear message", "[args][chapter-options]") {
    auto message = [](std::vector<const char*> args) {
        try {
            parse_chapter(std::move(args));
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(message({"--lights", "0"}) == "--lights wants a whole number from 1 to 65536, not '0'");
    CHECK(message({"--lights", "65537"}) ==
          "--lights wants a whole number from 1 to 65536, not '65537'");
    CHECK(message({"--lights", "3.5"}) ==
          "--lights wants a whole number from 1 to 65536, not '3.5'");
    CHECK(message({"--lights", ""}) == "--lights wants a whole number from 1 to 65536, not ''");
    CHECK(message({"--exposure", "5"}) == "--exposure wants a number from 0.25 to 4, not '5'");
    CHECK(message({"--exposure", "nan"}) == "--exposure wants a number from 0.25 to 4, not 'nan'");
    CHECK(message({"--view", "depth"}) == "--view wants one of lit, albedo, normal, not 'depth'");
    CHECK(message({"--model"}) == "--model needs a value");
    CHECK(message({"--model="}) == "--model needs a value");
    CHECK(message({"--count", "3"}) == "unknown argument '--count'");
}

TEST_CASE("--help and the usage line list a chapter's flags", "[args][chapter-options]") {
    const std::string usage = vkt::usage_line("10_gltf", Flags::frame_loop, chapter_options);
    CHECK(usage.find("[--lights N]") != std::string::npos);
    CHECK(usage.find("[--view lit|albedo|normal]") != std::string::npos);
    CHECK(usage.find("[--model FILE]") != std::string::npos);
    const std::string help = vkt::help_text("10_gltf", Flags::frame_loop, chapter_options);
    CHECK(help.find("point lights (1..65536) [default: 16]") != std::string::npos);
    CHECK(help.find("a glTF file") != std::string::npos);
    CHECK(help.find("--screenshot FILE.png") != std::string::npos);
    // A range the help's own words give is not repeated.
    const vkt::OptionSpec cascades[] = {{.name = "--cascades",
                                         .type = vkt::OptionType::integer,
                                         .value_name = "N",
                                         .help = "how many cascades (1..4)",
                                         .default_value = "3",
                                         .min = 1,
                                         .max = 4}};
    CHECK(vkt::help_text("22_shadows", Flags::frame_loop, cascades)
              .find("how many cascades (1..4) [default: 3]") != std::string::npos);
}

TEST_CASE("the alternatives --headless and --offscreen: both given is a usage error", "[args]") {
    for (const auto& args :
         {std::vector<const char*>{"--headless", "--offscreen"},
          std::vector<const char*>{"--offscreen", "--frames", "2", "--headless"}}) {
        try {
            parse(args);
            FAIL("no exception");
        } catch (const UsageError& e) {
            CHECK(std::string(e.what()).starts_with(
                "--headless and --offscreen are alternatives: give one"));
        }
    }
    CHECK(parse({"--headless", "--headless"}).headless);
    CHECK(parse({"--offscreen", "--offscreen"}).offscreen);
}

TEST_CASE("a flag that wants a value does not take the next flag as its value", "[args]") {
    try {
        parse({"--device", "--offscreen"});
        FAIL("no exception");
    } catch (const UsageError& e) {
        CHECK(std::string(e.what()) ==
              "--device needs a value, not the flag '--offscreen' (write --device=--offscreen "
              "if that is the value)");
    }
    CHECK_THROWS_AS(parse({"--screenshot", "--benchmark"}), UsageError);
    CHECK_THROWS_AS(parse({"--frames", "--headless"}), UsageError);
    CHECK_THROWS_AS(parse({"--size", "-h"}), UsageError);
    CHECK_THROWS_AS(parse({"--device", "--no-such-flag"}), UsageError);
    // Inline, a value may begin with "--"; a single "-" is a value (a number).
    CHECK(parse({"--device=--odd"}).device == "--odd");
    CHECK(parse({"--device", "-1"}).device == "-1");
}

TEST_CASE("the shared flag --max-memory takes a size in bytes or with K M G T",
          "[args][chapter-options]") {
    const std::vector<vkt::OptionSpec> options = {vkt::max_memory_option()};
    auto parse = [&](std::vector<const char*> args) {
        return parse_args(args, Flags::frame_loop, options);
    };
    // The default, 1G: the flag's text and vkt::default_max_memory agree.
    CHECK(parse({}).integer("--max-memory") == int64_t(1) << 30);
    CHECK(uint64_t(parse({}).integer("--max-memory")) == vkt::default_max_memory);
    CHECK(parse({"--max-memory", "512M"}).integer("--max-memory") == int64_t(512) << 20);
    CHECK(parse({"--max-memory=4G"}).integer("--max-memory") == int64_t(4) << 30);
    CHECK_THROWS_WITH(parse({"--max-memory", "lots"}),
                      "--max-memory wants a size from 16 MiB to 1024 GiB (a number of bytes, or "
                      "with K, M, G: 512M, 4G), not 'lots'");
    CHECK_THROWS_AS(parse({"--max-memory", "1M"}), UsageError);  // below 16 MiB
    CHECK_THROWS_AS(parse({"--max-memory", "2P"}), UsageError);
    CHECK(vkt::help_text("10_gltf", Flags::frame_loop, options).find("--max-memory SIZE") !=
          std::string::npos);
}

// The shared flags are one table: every flag the usage line names is one the
// parser takes, and the help text explains it, for each kind of chapter.
TEST_CASE("the usage line, the help text and the parser agree on the shared flags", "[args]") {
    const std::vector<std::pair<std::string, std::string>> values = {
        {"--frames", "3"}, {"--size", "64x32"}, {"--screenshot", "x.png"}, {"--device", "0"}};
    for (Flags flags : {Flags::instance, Flags::device, Flags::frame_loop}) {
        const std::string usage = vkt::usage_line("c", flags);
        const std::string help = vkt::help_text("c", flags);
        size_t named = 0;
        for (size_t at = usage.find("--"); at != std::string::npos; at = usage.find("--", at + 2)) {
            const std::string flag = usage.substr(at, usage.find_first_of(" ]", at) - at);
            ++named;
            INFO(flag);
            CHECK(help.find("  " + flag) != std::string::npos);
            std::vector<const char*> args = {flag.c_str()};
            for (const auto& [name, value] : values)
                if (name == flag) args.push_back(value.c_str());
            CHECK_NOTHROW(parse(args, flags));
        }
        CHECK(named == (flags == Flags::instance ? 3u : flags == Flags::device ? 4u : 11u));
    }
}
