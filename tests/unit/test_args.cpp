#include "vkt/args.hpp"

#include <catch2/catch_test_macros.hpp>

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
          "--device", "--validation", "--no-validation", "--help"})
        CHECK(help.find(flag) != std::string::npos);
    std::string text = vkt::usage_line("02_device", Flags::device);
    CHECK(text.find("--frames") == std::string::npos);
    CHECK(text.starts_with("usage: 02_device"));
    CHECK(text.find("--device") != std::string::npos);
    CHECK(vkt::usage_line("01_instance", Flags::instance).find("--device") == std::string::npos);
}
