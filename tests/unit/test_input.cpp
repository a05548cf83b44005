#include "vkt/frame/input.hpp"

#include <catch2/catch_test_macros.hpp>

using vkt::InputAccumulator;

TEST_CASE("an empty snapshot has nothing in it", "[input]") {
    vkt::Input input;
    CHECK_FALSE(input.down('W'));
    CHECK_FALSE(input.went_down('W'));
    CHECK_FALSE(input.shift());
    CHECK(input.mouse_dx == 0);
    CHECK(input.scroll == 0);
    CHECK_FALSE(input.down(-1));  // out-of-range codes are never down
    CHECK_FALSE(input.down(100000));
}

TEST_CASE("a key press is seen once as pressed and held until released", "[input]") {
    InputAccumulator events;
    events.key('W', true);
    vkt::Input first = events.take();
    CHECK(first.down('W'));
    CHECK(first.went_down('W'));
    vkt::Input second = events.take();
    CHECK(second.down('W'));
    CHECK_FALSE(second.went_down('W'));
    events.key('W', true);  // key repeat: still not a new press
    CHECK_FALSE(events.take().went_down('W'));
    events.key('W', false);
    CHECK_FALSE(events.take().down('W'));
}

TEST_CASE("a tap between two frames is still seen as pressed", "[input]") {
    InputAccumulator events;
    events.key('E', true);
    events.key('E', false);
    vkt::Input input = events.take();
    CHECK(input.went_down('E'));
    CHECK_FALSE(input.down('E'));
}

// The runner takes a snapshot, then finds the swapchain out of date and draws
// nothing: that snapshot goes back, so a key tapped in it is still seen.
TEST_CASE("a snapshot given back is seen by the next one", "[input]") {
    InputAccumulator events;
    events.key('R', true);
    events.key('R', false);
    events.scroll(2);
    const vkt::Input unused = events.take();
    events.key('W', true);
    events.scroll(1);
    events.give_back(unused);
    const vkt::Input next = events.take();
    CHECK(next.went_down('R'));
    CHECK_FALSE(next.down('R'));
    CHECK(next.went_down('W'));
    CHECK(next.down('W'));
    CHECK(next.scroll == 3);
    CHECK_FALSE(events.take().went_down('R'));  // and only once
}

TEST_CASE("unknown key codes are ignored", "[input]") {
    InputAccumulator events;
    events.key(-1, true);
    events.key(vkt::key::count, true);
    vkt::Input input = events.take();
    CHECK(input.held.none());
    CHECK(input.pressed.none());
}

TEST_CASE("mouse movement counts only while the cursor is captured", "[input]") {
    InputAccumulator events;
    events.cursor(10, 10);
    events.cursor(30, 50);
    CHECK(events.take().mouse_dx == 0);  // not captured: no look movement
    events.set_captured(true);
    events.cursor(100, 100);  // the jump on capture is not movement
    events.cursor(103, 96);
    events.cursor(110, 90);
    vkt::Input input = events.take();
    CHECK(input.cursor_captured);
    CHECK(input.mouse_dx == 10);
    CHECK(input.mouse_dy == -10);
    CHECK(events.take().mouse_dx == 0);  // per frame
}

TEST_CASE("scroll adds up within a frame", "[input]") {
    InputAccumulator events;
    events.scroll(1);
    events.scroll(2.5);
    CHECK(events.take().scroll == 3.5);
    CHECK(events.take().scroll == 0);
}

TEST_CASE("shift is either shift key", "[input]") {
    InputAccumulator events;
    events.key(vkt::key::right_shift, true);
    CHECK(events.take().shift());
}

TEST_CASE("the pointer: where the cursor is, and a click between two frames", "[input]") {
    vkt::InputAccumulator input;
    input.cursor_inside(true);
    input.cursor(120.5, 40.0);
    input.button(0, true);
    input.button(0, false);  // down and up before the frame: a click all the same
    input.button(7, true);   // buttons past the middle one are ignored
    const vkt::Input first = input.take();
    CHECK(first.cursor_inside);
    CHECK(first.cursor_x == 120.5);
    CHECK(first.cursor_y == 40.0);
    CHECK_FALSE(first.buttons[0]);
    CHECK(first.buttons_pressed[0]);
    CHECK(first.mouse_dx == 0);  // not captured: a position, not a movement
    const vkt::Input second = input.take();
    CHECK_FALSE(second.buttons_pressed[0]);
    CHECK(second.cursor_x == 120.5);  // the cursor stays where it was
    // Held across frames, pressed only in the first; a click given back counts again.
    input.button(1, true);
    const vkt::Input third = input.take();
    CHECK(third.buttons[1]);
    CHECK(third.buttons_pressed[1]);
    input.give_back(third);
    const vkt::Input fourth = input.take();
    CHECK(fourth.buttons_pressed[1]);
    CHECK(fourth.buttons[1]);
    input.cursor_inside(false);
    CHECK_FALSE(input.take().cursor_inside);
}
