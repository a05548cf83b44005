#include "vkt/resources/acceleration.hpp"

#include "vkt/scene/camera_math.hpp"

#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

// The instance's 3x4 matrix is row-major: row r holds the r-th coordinate of
// the three axes and the translation.
TEST_CASE("an instance's transform is the matrix's first three rows", "[acceleration]") {
    const glm::mat4 m = vkt::transform({5, 6, 7}, 0, {0, 1, 0}, {2, 3, 4});
    const VkTransformMatrixKHR t = vkt::instance_transform(m);
    const float expected[3][4] = {{2, 0, 0, 5}, {0, 3, 0, 6}, {0, 0, 4, 7}};
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 4; ++column)
            CHECK(t.matrix[row][column] == expected[row][column]);
}

TEST_CASE("a rotated instance maps a point as its matrix does", "[acceleration]") {
    // A quarter turn about y takes +x to -z; then the translation.
    const glm::mat4 m = glm::translate(glm::mat4(1), {1, 2, 3}) *
                        glm::rotate(glm::mat4(1), glm::radians(90.0f), {0, 1, 0});
    const VkTransformMatrixKHR t = vkt::instance_transform(m);
    const float p[4] = {1, 0, 0, 1};
    float out[3];
    for (int row = 0; row < 3; ++row) {
        out[row] = 0;
        for (int k = 0; k < 4; ++k) out[row] += t.matrix[row][k] * p[k];
    }
    CHECK(std::abs(out[0] - 1) < 1e-6f);
    CHECK(std::abs(out[1] - 2) < 1e-6f);
    CHECK(std::abs(out[2] - 2) < 1e-6f);  // 3 - 1
}

TEST_CASE("scratch regions start at multiples of the alignment", "[acceleration]") {
    const std::vector<VkDeviceSize> sizes{100, 128, 1, 0, 300};
    const std::vector<VkDeviceSize> offsets = vkt::scratch_offsets(sizes, 128);
    // Worked by hand: 0, then 100 up to 128, 128 + 128 = 256, 257 up to 384,
    // 384 (an empty region takes no room), 684 up to 768 (the total).
    CHECK(offsets == std::vector<VkDeviceSize>{0, 128, 256, 384, 384, 768});
    CHECK(vkt::scratch_offsets({}, 256) == std::vector<VkDeviceSize>{0});
}
