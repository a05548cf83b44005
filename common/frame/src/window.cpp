#include "vkt/frame/window.hpp"

#include "vkt/core/check.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#if VKT_WINDOW_X11
#include <X11/Xlib.h>
// GLFW's native-access functions for X11, declared here rather than through
// <GLFW/glfw3native.h>, which would also need the XRandR headers.
extern "C" Display* glfwGetX11Display(void);
extern "C" ::Window glfwGetX11Window(GLFWwindow* window);
#endif

namespace vkt {

namespace {

// Shows the window. On X11, GLFW 3.3 maps the window and then waits for the
// X server to say it is visible; that wait is meant to give up after 0.1 s,
// but it counts the time only while no other event is queued, so it lasts as
// long as the window manager takes to show the window: minutes, under one
// that had lost the map request (tests/window_repeat_record.txt). Nothing
// here needs the window to be visible before drawing (a swapchain can be
// made for a window not yet shown), so on X11 we map it ourselves and carry
// on; the X server shows it when it can, and GLFW learns of it from the
// events it polls.
void show(GLFWwindow* window) {
#if VKT_WINDOW_X11
    if (Display* display = glfwGetX11Display()) {
        XMapRaised(display, glfwGetX11Window(window));
        XFlush(display);
        return;
    }
#endif
    glfwShowWindow(window);
}

}  // namespace

Window::Window(const std::string& title, VkExtent2D size, InputUse use) : use_(use) {
#if GLFW_VERSION_MAJOR > 3 || (GLFW_VERSION_MAJOR == 3 && GLFW_VERSION_MINOR >= 4)
    // GLFW 3.4 can take the loader we link rather than look for one itself
    // (on macOS it would not look in Homebrew's lib folder). Debian's is 3.3.
    glfwInitVulkanLoader(vkGetInstanceProcAddr);
#endif
    if (!glfwInit()) throw Error("GLFW cannot initialise (no display?)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown by show(), below
    window_ = glfwCreateWindow(int(size.width), int(size.height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw Error("GLFW cannot open a window");
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->resized_ = true;
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
        if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) {
            // A captured cursor is released first, so the user is never stuck.
            if (self->captured_)
                self->capture_cursor(false);
            else
                glfwSetWindowShouldClose(w, GLFW_TRUE);
            return;
        }
        if (self->use_ != InputUse::none && action != GLFW_REPEAT)
            self->input_.key(key, action == GLFW_PRESS);
    });
    show(window_);
    if (use_ == InputUse::none) return;  // the chapter sees no input at all
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->input_.scroll(dy);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->input_.cursor(x, y);
    });
    if (use_ == InputUse::pointer) {
        glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int entered) {
            static_cast<Window*>(glfwGetWindowUserPointer(w))->input_.cursor_inside(entered);
        });
        glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
            static_cast<Window*>(glfwGetWindowUserPointer(w))
                ->input_.button(button, action == GLFW_PRESS);
        });
        // Where the cursor already is, for a window opened under it.
        double x = 0, y = 0;
        glfwGetCursorPos(window_, &x, &y);
        input_.cursor(x, y);
        input_.cursor_inside(glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE);
        return;
    }
    if (use_ != InputUse::mouse_look) return;
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int action, int) {
        auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
        if (action == GLFW_PRESS && !self->captured_) self->capture_cursor(true);
    });
    capture_cursor(true);
}

void Window::capture_cursor(bool capture) {
    captured_ = capture;
    glfwSetInputMode(window_, GLFW_CURSOR, capture ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
    // Raw motion (no pointer acceleration) where the platform has it.
    if (glfwRawMouseMotionSupported())
        glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, capture ? GLFW_TRUE : GLFW_FALSE);
    input_.set_captured(capture);
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<const char*> Window::required_instance_extensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("GLFW cannot make Vulkan surfaces on this display");
    return {names, names + count};
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
    VkSurfaceKHR surface;
    VKT_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

bool Window::should_close() const {
    return glfwWindowShouldClose(window_);
}
void Window::poll() const {
    glfwPollEvents();
}

VkExtent2D Window::framebuffer_size() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {uint32_t(width), uint32_t(height)};
}

bool Window::minimised() const {
    const VkExtent2D size = framebuffer_size();
    return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) || size.width == 0 || size.height == 0;
}

void Window::wait_while_minimised() const {
    while (minimised() && !should_close()) glfwWaitEvents();
}

bool Window::take_resized() {
    return std::exchange(resized_, false);
}
double Window::seconds() const {
    return glfwGetTime();
}

}  // namespace vkt
