// The harness around a frame loop (chapter 03): where the picture goes, the
// instance and device for it, the frame count and time, --screenshot,
// --benchmark and the exit status. Chapter 03's main.cpp and the runner
// (runner.cpp, presentation.cpp) each write their loop inside it.

#include "vkt/frame/harness.hpp"
#include "vkt/frame/overlay.hpp"

#include "guarded.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/swapchain.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/image_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace vkt {

const char* presentation_name(Presentation p) {
    switch (p) {
        case Presentation::window:
            return "window";
        case Presentation::headless_surface:
            return "headless surface";
        default:
            return "offscreen";
    }
}

namespace {

constexpr double fixed_time_step = 1.0 / 60.0;
constexpr uint32_t default_headless_frames = 60;

bool has_display() {
#ifdef _WIN32
    return true;  // a desktop is always there (where GLFW cannot open a window, it says so)
#else
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"})
        if (const char* value = std::getenv(name); value && *value) return true;
    return false;
#endif
}

// Fails early, with the reason, if the screenshot could not be written: better
// than finding out after a long run. Leaves no file behind.
void check_writable(const std::string& path) {
    const bool existed = std::filesystem::exists(path);
    std::FILE* file = std::fopen(path.c_str(), "ab");
    if (!file) throw Error("cannot write " + path + ": " + std::strerror(errno));
    std::fclose(file);
    if (!existed) std::filesystem::remove(path);
}

// VKT_HIDE_FEATURES=name,name,...: the tests' way to play a device that lacks
// a feature, an extension or a property's flag (vkt/core/hidden_names.hpp).
HiddenNames hidden_from_environment() {
    HiddenNames hidden;
    const char* list = std::getenv("VKT_HIDE_FEATURES");
    for (std::string_view rest = list ? list : ""; !rest.empty();) {
        const size_t comma = rest.find(',');
        hidden.names.emplace_back(rest.substr(0, comma));
        rest.remove_prefix(comma == std::string_view::npos ? rest.size() : comma + 1);
    }
    return hidden;
}

// VK_KHR_surface_maintenance1 and VK_KHR_swapchain_maintenance1 are the EXT
// extensions promoted, with the same structures and values (the EXT names are
// aliases): the KHR name where the driver offers it, else the EXT one. Hiding
// the EXT name from the tests hides both.
const char* surface_maintenance_name(const HiddenNames& hidden) {
    constexpr const char* khr = "VK_KHR_surface_maintenance1";
    return instance_extension_available(khr) && !hidden.hides(khr) &&
                   !hidden.hides(VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME)
               ? khr
               : VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME;
}
const char* swapchain_maintenance_name(VkPhysicalDevice device, const HiddenNames& hidden) {
    constexpr const char* khr = "VK_KHR_swapchain_maintenance1";
    return device_extension_available(device, khr) && !hidden.hides(khr) &&
                   !hidden.hides(VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME)
               ? khr
               : VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME;
}

// --overlay, for the chapters with the overlay (ChapterSpec::overlay,
// chapter 21) and no other: a headless run can show the panel too.
OptionSpec overlay_option() {
    return {.name = "--overlay",
            .type = OptionType::choice,
            .help =
                "the settings panel: on, in every run (headless and --frames too,\n"
                "so --screenshot shows it); off, in none (default: only in a\n"
                "window run without --frames, where the mouse can reach it)",
            .choices = {"on", "off"}};
}

}  // namespace

Harness::Harness(const Options& options, const ChapterSpec& spec, uint32_t frames_in_flight)
    : options_(options),
      spec_(spec),
      frames_in_flight_(frames_in_flight),
      hidden_(hidden_from_environment()) {
    if (!options.screenshot.empty()) check_writable(options.screenshot);
    open_presentation();
    if (options.benchmark) {
        // GPU time from two timestamps per frame, where the queue can write them.
        gpu_timer_ =
            GpuTimer(device_->physical(), *device_, device_->queue_family(), frames_in_flight_);
    }
}

Harness::~Harness() {
    if (device_) vkDeviceWaitIdle(*device_);  // nothing may be destroyed while in use
}

void Harness::open_presentation() {
    // [choose-presentation]
    // Where the picture goes: a window if we can, else a headless surface, else
    // our own images only.
    if (options_.offscreen) {
        presentation_ = Presentation::offscreen;
    } else if (!options_.headless && has_display()) {
        try {
            window_ = std::make_unique<Window>(
                spec_.title, VkExtent2D{options_.width, options_.height},
                spec_.overlay && overlay_available() && spec_.input != InputUse::mouse_look &&
                        overlay_choice() != "off"
                    ? InputUse::pointer
                    : spec_.input);
            presentation_ = Presentation::window;
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: %s; running headless\n", spec_.name.c_str(), e.what());
        }
    }
    if (!window_ && !options_.offscreen)
        presentation_ = instance_extension_available(VK_EXT_HEADLESS_SURFACE_EXTENSION_NAME)
                            ? Presentation::headless_surface
                            : Presentation::offscreen;
    // [/choose-presentation]

    std::vector<const char*> extensions;
    if (presentation_ == Presentation::window) extensions = Window::required_instance_extensions();
    if (presentation_ == Presentation::headless_surface)
        extensions = {VK_KHR_SURFACE_EXTENSION_NAME, VK_EXT_HEADLESS_SURFACE_EXTENSION_NAME};

    const bool layer = instance_layer_available(validation_layer_name);
    const bool validation = options_.validation.value_or(layer);
    // Where there will be a swapchain: the instance extensions that
    // VK_KHR_swapchain_maintenance1 (present fences) builds on, where offered.
    // Not in a window under validation layers older than 1.3.290 (Debian 12
    // has 1.3.239): with the extension on, they check a new swapchain's size
    // against a fresh query of the window's, which a resize between our query
    // and vkCreateSwapchainKHR makes a false error (the race described in
    // KhronosGroup/Vulkan-Docs#1144); later layers check it against our own query, as they do
    // without the extension. There the fallback retires swapchains instead.
    const bool racy_layer =
        validation && presentation_ == Presentation::window &&
        instance_layer_version(validation_layer_name) < VK_MAKE_API_VERSION(0, 1, 3, 290);
    const bool surface_maintenance =
        presentation_ != Presentation::offscreen && !racy_layer &&
        instance_extension_available(VK_KHR_GET_SURFACE_CAPABILITIES_2_EXTENSION_NAME) &&
        instance_extension_available(surface_maintenance_name(hidden_)) &&
        !hidden_.hides(surface_maintenance_name(hidden_));
    if (surface_maintenance) {
        extensions.push_back(VK_KHR_GET_SURFACE_CAPABILITIES_2_EXTENSION_NAME);
        extensions.push_back(surface_maintenance_name(hidden_));
    }

    if (options_.validation.value_or(false) && !layer)
        throw Error(
            "--validation: the Khronos validation layer is not installed "
            "(on Debian: apt install vulkan-validationlayers)");
    instance_ = std::make_unique<Instance>(InstanceConfig{
        .application_name = spec_.name,
        .validation = validation,
        .extensions = extensions,
    });

    if (presentation_ == Presentation::window) {
        surface_ = SurfaceHandle(*instance_, window_->create_surface(*instance_));
    } else if (presentation_ == Presentation::headless_surface) {
        auto create = reinterpret_cast<PFN_vkCreateHeadlessSurfaceEXT>(
            vkGetInstanceProcAddr(*instance_, "vkCreateHeadlessSurfaceEXT"));
        VkHeadlessSurfaceCreateInfoEXT info{.sType =
                                                VK_STRUCTURE_TYPE_HEADLESS_SURFACE_CREATE_INFO_EXT};
        VkSurfaceKHR surface;
        VKT_CHECK(create(*instance_, &info, nullptr, &surface));
        surface_ = SurfaceHandle(*instance_, surface);
    }

    // A window needs a device that can present to it. Headless, the device is
    // chosen on its own merits; if it cannot present to the headless surface
    // (another driver may have provided that), it renders offscreen instead.
    DeviceRequirements requirements = spec_.requirements;
    requirements.hidden = hidden_;
    if (window_) requirements.extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    const auto candidates =
        survey_devices(*instance_, window_ ? surface_.get() : VK_NULL_HANDLE, requirements);
    const DeviceCandidate& chosen = choose_device(candidates, options_.device);
    if (presentation_ == Presentation::headless_surface) {
        if (can_present(chosen.handle, chosen.queue_family, surface_)) {
            requirements.extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        } else {
            surface_.reset();
            presentation_ = Presentation::offscreen;
        }
    }
    VkPhysicalDeviceSwapchainMaintenance1FeaturesEXT maintenance{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SWAPCHAIN_MAINTENANCE_1_FEATURES_EXT};
    if (surface_ && surface_maintenance &&
        device_extension_available(chosen.handle,
                                   swapchain_maintenance_name(chosen.handle, hidden_)) &&
        !hidden_.hides(swapchain_maintenance_name(chosen.handle, hidden_))) {
        VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                        .pNext = &maintenance};
        vkGetPhysicalDeviceFeatures2(chosen.handle, &query);
        present_fences_ = maintenance.swapchainMaintenance1 == VK_TRUE;
    }
    if (present_fences_) {
        maintenance.pNext = requirements.extension_features;  // after the chapter's own
        requirements.extension_features = &maintenance;
        requirements.extensions.push_back(swapchain_maintenance_name(chosen.handle, hidden_));
    }
    device_ = std::make_unique<Device>(chosen, requirements);

    const uint32_t largest = device_->properties().limits.maxImageDimension2D;
    if (options_.width > largest || options_.height > largest)
        throw Error("--size " + std::to_string(options_.width) + "x" +
                    std::to_string(options_.height) + ": this device's images are at most " +
                    std::to_string(largest) + "x" + std::to_string(largest));
}

Harness::Next Harness::next_frame(uint64_t frames_drawn) {
    const auto now = std::chrono::steady_clock::now();
    if (frames_drawn == 0 && last_drawn_ == 0 && window_) start_seconds_ = window_->seconds();
    if (options_.benchmark && frames_drawn > last_drawn_)  // only --benchmark keeps them
        cpu_ms_.push_back(std::chrono::duration<double, std::milli>(now - frame_begin_).count());
    last_drawn_ = frames_drawn;

    if (frames_drawn >= options_.frames.value_or(window_ ? UINT64_MAX : default_headless_frames))
        return Next::stop;
    if (window_) {
        window_->poll();
        if (window_->should_close()) return Next::stop;
    }
    if (!window_ || !window_->minimised()) {
        frame_begin_ = std::chrono::steady_clock::now();
        return Next::draw;
    }
    // A minimised window shows nothing, so draw nothing: sleep until the
    // window manager gives it back (or closes it), then start afresh.
    std::fprintf(stderr, "%s: minimised after %llu frames: waiting\n", spec_.name.c_str(),
                 (unsigned long long)frames_drawn);
    window_->wait_while_minimised();
    if (window_->should_close()) return Next::stop;
    std::fprintf(stderr, "%s: restored, still at %llu frames\n", spec_.name.c_str(),
                 (unsigned long long)frames_drawn);
    frame_begin_ = std::chrono::steady_clock::now();
    return Next::restored;
}

bool Harness::fixed_step() const {
    // Headless, or with --frames in a window, time is a function of the frame
    // index only, so the same frame always gives the same picture. An
    // open-ended window run follows the wall clock instead.
    return !window_ || options_.frames.has_value();
}

std::string_view Harness::overlay_choice() const {
    return options_.has("--overlay") ? std::string_view(options_.text("--overlay")) : "";
}

bool Harness::overlay() const {
    if (!spec_.overlay || overlay_choice() == "off") return false;
    // Where the reader can use it: a window run without --frames (with it,
    // as headless, no input reaches the frames). --overlay on: every run.
    return overlay_choice() == "on" || (window_ && !fixed_step());
}

double Harness::time(uint64_t index) const {
    return fixed_step() ? double(index) * fixed_time_step : window_->seconds() - start_seconds_;
}

VkExtent2D Harness::wanted_extent() const {
    return window_ ? window_->framebuffer_size() : VkExtent2D{options_.width, options_.height};
}

bool Harness::take_resized() {
    return window_ && window_->take_resized();
}

bool Harness::wait_while_minimised() {
    if (!window_) return true;
    window_->wait_while_minimised();
    return !window_->should_close();
}

void Harness::announce(const Destination& where) const {
    std::string text = presentation_name(presentation_);
    if (where.swapchain_format != VK_FORMAT_UNDEFINED)
        text += std::string(" ") + format_name(where.swapchain_format) + " " +
                present_mode_name(where.present_mode) + " x" + std::to_string(where.images) +
                (where.drawn_into ? " drawn into" : " copied into");
    std::fprintf(stderr, "%s: %s, %s, %ux%u %s, validation %s\n", spec_.name.c_str(),
                 device_->properties().deviceName, text.c_str(), where.extent.width,
                 where.extent.height, format_name(where.format),
                 instance_->validation() ? "on (with synchronisation)" : "off");
}

void Harness::note_presented(VkExtent2D extent, size_t retired_kept) {
    if (extent.width != presented_.width || extent.height != presented_.height) {
        presented_ = extent;
        std::fprintf(stderr, "%s: presented a frame at %ux%u\n", spec_.name.c_str(), extent.width,
                     extent.height);
    }
    if (draining_ && retired_kept <= 1) {
        draining_ = false;
        std::fprintf(stderr, "%s: retired swapchains down to %zu kept\n", spec_.name.c_str(),
                     retired_kept);
    }
}

void Harness::note_recreated(VkExtent2D extent, size_t kept) {
    presented_ = {};  // the next present is reported, whatever its size
    draining_ = true;
    std::fprintf(stderr, "%s: swapchain recreated at %ux%u (%zu retired kept until %s)\n",
                 spec_.name.c_str(), extent.width, extent.height, kept,
                 present_fences_ ? "their present fences signal" : "a later present ends");
}

void Harness::finish(const Destination& where, const Readback* last_frame) {
    for (uint32_t i = 0; i < frames_in_flight_; ++i) gpu_timer_.collect(i);
    if (!options_.screenshot.empty()) {
        // The GPU is idle, and the read-back's barrier to the HOST stage made
        // the bytes visible.
        if (!last_frame) throw Error("no frame was drawn, so there is no screenshot to write");
        write_png(options_.screenshot,
                  to_rgba(last_frame->buffer.mapped, last_frame->extent, last_frame->format));
        std::fprintf(stderr, "%s: wrote %s (%ux%u)\n", spec_.name.c_str(),
                     options_.screenshot.c_str(), last_frame->extent.width,
                     last_frame->extent.height);
    }
    if (!options_.benchmark) return;
    std::string scopes;  // "name": {summary}, one per GPU scope the chapter named
    for (const auto& scope : gpu_timer_.scopes())
        scopes += (scopes.empty() ? "" : ", ") + json_string(scope.name) + ": " +
                  json_summary(scope.samples);
    std::printf(
        "{\"chapter\": %s, \"device\": %s, \"presentation\": %s, \"width\": %u, \"height\": "
        "%u, \"into_swapchain\": %s, "
        "\"frames\": %zu, \"cpu_frame_ms\": %s, \"gpu_frame_ms\": %s, \"gpu_scopes_ms\": "
        "{%s}}\n",
        json_string(spec_.name).c_str(), json_string(device_->properties().deviceName).c_str(),
        json_string(presentation_name(presentation_)).c_str(), where.extent.width,
        where.extent.height,
        where.swapchain_format == VK_FORMAT_UNDEFINED ? "null"
        : where.drawn_into                            ? "\"drawn\""
                                                      : "\"copied\"",
        cpu_ms_.size(), json_summary(cpu_ms_).c_str(),
        json_summary(gpu_timer_.samples_ms()).c_str(), scopes.c_str());
}

int run_in_harness(int argc, char** argv, const ChapterSpec& spec, uint32_t frames_in_flight,
                   const std::function<void(Harness&)>& loop) {
    // The chapter's flags, and --overlay where it has one. Not a copy of the
    // spec: a chapter's check_options may still change its requirements
    // (chapter 28 asks for mesh shaders only with --path task).
    std::vector<OptionSpec> flags = spec.options;
    if (spec.overlay) flags.push_back(overlay_option());
    return detail::guarded(argc, argv, Flags::frame_loop, flags, spec.check_options,
                           [&](const Options& options) {
                               std::shared_ptr<const ValidationCounts> counts;
                               {
                                   Harness harness(options, spec, frames_in_flight);
                                   if (harness.validation()) counts = harness.counts();
                                   loop(harness);
                               }  // everything destroyed: the layer has said all it will say
                               return detail::report_validation(spec.name, counts.get());
                           });
}

}  // namespace vkt
