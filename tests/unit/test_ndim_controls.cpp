// Chapter 18's keys as chapters 19 and 20 use them (vkt/scene/ndim_controls.hpp):
// the pose adds what the keys turned and moved to the scene's own; the keys
// turn the planes of the current page, move along axes, switch the projection
// and reset.
#include "vkt/scene/ndim_controls.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

namespace nd = vkt::ndim;

namespace {

// One frame's input with these keys held and just pressed.
vkt::Input pressing(std::initializer_list<int> codes) {
    vkt::Input input;
    for (int code : codes) {
        input.held.set(size_t(code));
        input.pressed.set(size_t(code));
    }
    return input;
}

}  // namespace

TEST_CASE("the keys' pose adds their angles and offsets to the scene's", "[ndim_controls]") {
    const nd::Scene scene = nd::make_scene("cube", 5, false);
    nd::Controls keys(5, nd::Projection::perspective);
    const nd::Transform plain = keys.pose(scene.objects[0], 0.5f);
    CHECK(plain.angles == scene.objects[0].at(0.5f).angles);
    keys.angles[3] = 0.25f;
    keys.offset[4] = -1.0f;
    const nd::Transform moved = keys.pose(scene.objects[0], 0.5f);
    CHECK(moved.angles[3] == Catch::Approx(plain.angles[3] + 0.25f));
    CHECK(moved.position[4] == Catch::Approx(plain.position[4] - 1.0f));
    CHECK(moved.angles[2] == plain.angles[2]);
}

TEST_CASE("the keys turn, move, page, switch and reset", "[ndim_controls]") {
    nd::Controls keys(6, nd::Projection::perspective);  // 15 planes: two pages
    keys.steer(pressing({'1', 290 + 3}), 0.5f);         // key 1, F4
    CHECK(keys.angles[0] == Catch::Approx(0.5f));
    CHECK(keys.offset[3] == Catch::Approx(0.75f));
    keys.steer(pressing({vkt::key::left_shift, '2'}), 0.5f);  // backwards
    CHECK(keys.angles[1] == Catch::Approx(-0.5f));
    keys.steer(pressing({']'}), 0.0f);
    CHECK(keys.page == 1);
    keys.steer(pressing({'1'}), 1.0f);  // page two: plane 10
    CHECK(keys.angles[10] == Catch::Approx(1.0f));
    keys.steer(pressing({'9'}), 1.0f);  // plane 18 does not exist for n = 6
    keys.steer(pressing({'O', vkt::key::space}), 0.0f);
    CHECK(keys.projection == nd::Projection::orthographic);
    CHECK(keys.paused);
    keys.steer(pressing({'R'}), 0.0f);
    for (float a : keys.angles) CHECK(a == 0.0f);
    for (float x : keys.offset) CHECK(x == 0.0f);
}
