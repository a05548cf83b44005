// Chapter 23's checks of its own pictures (chapters/23_materials/verify.hpp)
// fed made-up HDR images, so that each is seen to fail: the chapter tests
// only ever show them passing on the GPU's picture. The white furnace passes
// a sphere at exactly the sky's radiance and refuses one 4% dark or 4%
// bright; the CPU-reference check refuses a black picture.
#include "../../chapters/23_materials/verify.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

using Catch::Matchers::ContainsSubstring;

namespace {
constexpr VkExtent2D kExtent{320, 240};

std::vector<glm::vec3> uniform_picture(float value) {
    return std::vector<glm::vec3>(size_t(kExtent.width) * kExtent.height, glm::vec3(value));
}

std::string furnace_error(float value) {
    try {
        verify::check("furnace", uniform_picture(value), kExtent, true);
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST_CASE("furnace check: a sphere at the sky's radiance passes, 4% off either way fails",
          "[materials]") {
    CHECK(furnace_error(1.0f).empty());
    CHECK(furnace_error(0.98f).empty());
    CHECK_THAT(furnace_error(0.96f), ContainsSubstring("more than 3% off"));
    CHECK_THAT(furnace_error(1.04f), ContainsSubstring("more than 3% off"));
}

TEST_CASE("CPU-reference check: a black picture of the sphere grid fails", "[materials]") {
    CHECK_THROWS_WITH(verify::check("cpu", uniform_picture(0.0f), kExtent, false),
                      ContainsSubstring("the CPU reference says"));
}
