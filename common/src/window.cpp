#include "vkt/window.hpp"

#include "vkt/check.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vkt {

Window::Window(const std::string& title, VkExtent2D size) {
    if (!glfwInit()) throw Error("GLFW cannot initialise (no display?)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
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
        if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    });
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
