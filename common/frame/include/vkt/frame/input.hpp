#pragma once
// What the user did since the last frame: keys held and pressed, mouse
// movement, scroll. Taught in chapter 11. In a window the runner fills it from
// GLFW for the chapters that ask (ChapterSpec::input); headless, under
// --frames, or for a chapter that did not ask, every frame sees it empty, so
// chapters script their motion from the frame index instead.

#include <bitset>

namespace vkt {

// Key codes are GLFW's: letters and digits are their ASCII codes ('W' is 87).
namespace key {
constexpr int space = 32, escape = 256, enter = 257, tab = 258, right = 262, left = 263, down = 264,
              up = 265, left_shift = 340, left_control = 341, right_shift = 344,
              right_control = 345;
constexpr int count = 512;  // every GLFW key code is below this
}  // namespace key

// What a chapter may use.
enum class InputUse {
    none,        // no input at all (Escape still quits)
    keys,        // keys and scroll
    mouse_look,  // keys, scroll, and mouse movement with the cursor captured:
                 // Escape first releases the cursor, a second Escape quits
    pointer,     // keys, scroll, and the free cursor's position and buttons
                 // (chapter 21's overlay is clicked with it)
};

struct Input {
    std::bitset<key::count> held;       // down now
    std::bitset<key::count> pressed;    // went down since the last frame
    double mouse_dx = 0, mouse_dy = 0;  // pixels since the last frame (cursor captured only)
    double scroll = 0;                  // wheel steps since the last frame
    bool cursor_captured = false;
    // InputUse::pointer: where the cursor is (window pixels from the top
    // left, while it is inside), and the mouse buttons (left, right, middle)
    // held now and pressed since the last frame.
    double cursor_x = 0, cursor_y = 0;
    bool cursor_inside = false;
    std::bitset<3> buttons, buttons_pressed;

    bool down(int code) const { return code >= 0 && code < key::count && held[size_t(code)]; }
    bool went_down(int code) const {
        return code >= 0 && code < key::count && pressed[size_t(code)];
    }
    bool shift() const { return down(key::left_shift) || down(key::right_shift); }
};

// Collects window events between frames; take() hands out one frame's
// snapshot and starts the next. Pure, so the unit tests can drive it.
class InputAccumulator {
public:
    void key(int code, bool is_down);
    void cursor(double x, double y);  // absolute cursor position, as GLFW reports it
    void cursor_inside(bool inside) { current_.cursor_inside = inside; }
    void button(int index, bool is_down);  // 0 left, 1 right, 2 middle; others ignored
    void scroll(double steps) { current_.scroll += steps; }
    void set_captured(bool captured);
    Input take();
    // A snapshot that no frame used (the runner took it, then had to recreate
    // the swapchain instead of drawing): its presses, movement and scroll go
    // back into the next snapshot, so that a key tapped then is not lost.
    void give_back(const Input& unused);

private:
    Input current_;
    bool have_cursor_ = false;  // the first position after capture gives no movement
    double last_x_ = 0, last_y_ = 0;
};

}  // namespace vkt
