#pragma once
// A resizable GLFW window with a Vulkan surface (chapter 03's window path).

#include "vkt/core/owned.hpp"
#include "vkt/frame/input.hpp"

#include <string>
#include <vector>

struct GLFWwindow;

namespace vkt {

class Window {
public:
    // Throws Error when GLFW cannot open a window (no display, no Vulkan support).
    // use: which input the chapter wants (chapter 11); with none, Escape still quits.
    Window(const std::string& title, VkExtent2D size, InputUse use = InputUse::none);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // The instance extensions GLFW needs to make a surface on this platform.
    static std::vector<const char*> required_instance_extensions();
    VkSurfaceKHR create_surface(VkInstance instance) const;

    bool should_close() const;
    void poll() const;
    VkExtent2D framebuffer_size() const;
    // Minimised: iconified by the window manager (on X11 the framebuffer keeps
    // its size then), or a framebuffer of 0x0 (what Windows reports).
    bool minimised() const;
    // Blocks in glfwWaitEvents while the window is minimised: no frames, no
    // spinning. Returns at once if it is not (or once it should close).
    void wait_while_minimised() const;
    // True once after the framebuffer changed size.
    bool take_resized();
    double seconds() const;
    // What happened since the last call (always empty for InputUse::none).
    Input take_input() { return input_.take(); }
    // A snapshot no frame used goes back (see InputAccumulator::give_back).
    void give_back_input(const Input& unused) { input_.give_back(unused); }

private:
    void capture_cursor(bool capture);

    GLFWwindow* window_ = nullptr;
    bool resized_ = false;
    InputUse use_ = InputUse::none;
    bool captured_ = false;
    InputAccumulator input_;
};

}  // namespace vkt
