#include "vkt/frame/input.hpp"

namespace vkt {

void InputAccumulator::key(int code, bool is_down) {
    if (code < 0 || code >= key::count) return;  // GLFW_KEY_UNKNOWN (-1) and the like
    if (is_down && !current_.held[size_t(code)]) current_.pressed[size_t(code)] = true;
    current_.held[size_t(code)] = is_down;
}

void InputAccumulator::button(int index, bool is_down) {
    if (index < 0 || index >= 3) return;
    if (is_down && !current_.buttons[size_t(index)]) current_.buttons_pressed[size_t(index)] = true;
    current_.buttons[size_t(index)] = is_down;
}

void InputAccumulator::cursor(double x, double y) {
    current_.cursor_x = x;
    current_.cursor_y = y;
    if (current_.cursor_captured && have_cursor_) {
        current_.mouse_dx += x - last_x_;
        current_.mouse_dy += y - last_y_;
    }
    have_cursor_ = true;
    last_x_ = x;
    last_y_ = y;
}

void InputAccumulator::set_captured(bool captured) {
    current_.cursor_captured = captured;
    have_cursor_ = false;  // the cursor jumps when it is captured or released
}

Input InputAccumulator::take() {
    Input out = current_;
    current_.pressed.reset();
    current_.buttons_pressed.reset();
    current_.mouse_dx = current_.mouse_dy = current_.scroll = 0;
    return out;
}

void InputAccumulator::give_back(const Input& unused) {
    current_.pressed |= unused.pressed;
    current_.buttons_pressed |= unused.buttons_pressed;
    current_.mouse_dx += unused.mouse_dx;
    current_.mouse_dy += unused.mouse_dy;
    current_.scroll += unused.scroll;
}

}  // namespace vkt
