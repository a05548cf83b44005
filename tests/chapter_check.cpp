// Runs one chapter executable and judges the run. Used by CTest for every
// chapter regression test and every bad-input test:
//
//   vkt_chapter_check --exe PATH --out DIR --name NAME
//                     [--golden PNG [--tolerance
//                     RMSE,THRESHOLD,FRACTION[,BIAS,TILE]|across-devices]
//                                   [--blesses]]
//                     [--same-as PNG] [--exit N] [--expect REGEX]...
//                     [--pixel X,Y,R,G,B[,TOL]]... [--between X,Y,W,H,R,G,B,R,G,B,MIN,MAX]...
//                     [--isolate DIR] -- ARGS...
//   vkt_chapter_check --png FILE [--pixel X,Y,R,G,B[,TOL]]... [--between ...]...
//   vkt_chapter_check --compare REFERENCE PICTURE [--tolerance
//   RMSE,THRESHOLD,FRACTION|across-devices]
//
// It runs PATH ARGS (with --screenshot DIR/NAME.png added when --golden or a
// --pixel is given and ARGS names no screenshot of its own), keeps its stdout
// and stderr in DIR/NAME.stdout / .stderr, and fails unless: the exit status
// is N (default 0); no validation message appears on stdout or stderr,
// whatever the exit status (a refusal's path is read as closely as a
// drawing's); with exit 0 and --validation in ARGS, stderr says
// "validation: 0 warnings, 0 errors"; every REGEX matches stdout or stderr;
// every --pixel of the screenshot has that colour (within TOL, default 1);
// in each --between rectangle (W x H pixels from X,Y), where both colours
// must appear (within 2), from MIN to MAX pixels lie strictly between them
// (every channel within the two colours' range, give or take 2, and more
// than 2 from each colour in some channel: an edge's blend, chapter 21);
// the screenshot is within vkt::Tolerance of the golden image (with
// --tolerance: within that looser vkt::Tolerance, for two ways of drawing
// that differ by design, chapter 24's shadow map against its ray-traced
// shadows, a comparison that never blesses); and with --same-as, the
// screenshot equals PNG in every pixel. A stored golden is only ever
// compared with a tolerance, since llvmpipe rounds differently on another
// processor or LLVM; --same-as names a picture another test drew in this
// build on this machine (CTest fixtures order the two), for two ways of
// drawing that must agree to the bit.
// The --png form checks the pixels of an existing picture; the --compare
// form compares two pictures with the golden tolerance (or the one given):
// exit status 0 within it, 1 outside it, 2 for bad input, one line saying why.
// A failed comparison leaves NAME.png (rendered) and NAME.diff.png.
// With VKT_BLESS=1 in the environment, a test given --blesses (the one test
// that owns its golden image) replaces the golden image with its screenshot;
// every other test compares as usual, so blessing one chapter never rewrites
// another's picture.
// --isolate DIR runs a copy of the executable from DIR/bin, so that it finds
// DIR/shaders (prepared by the test: empty, or holding corrupt SPIR-V) instead
// of the build's.

#include "vkt/resources/image_io.hpp"

#ifdef _WIN32  // the Windows build, run under Wine (scripts/windows-build.sh)
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <windows.h>
#else
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

int fail(const std::string& message) {
    std::fprintf(stderr, "FAIL: %s\n", message.c_str());
    return 1;
}

#ifdef _WIN32
// One argument of a Windows command line, quoted as the C runtime parses it:
// backslashes are literal except before a quote, where they are doubled.
std::string quoted(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t\"") == std::string::npos) return arg;
    std::string out = "\"";
    size_t backslashes = 0;
    for (const char c : arg) {
        if (c == '\\') {
            ++backslashes;
            continue;
        }
        out.append(c == '"' ? 2 * backslashes + 1 : backslashes, '\\');
        backslashes = 0;
        out += c;
    }
    out.append(2 * backslashes, '\\');
    return out + "\"";
}

// The Windows form of run() below: CreateProcess with the two files as its
// standard handles. An unhandled exception (0xC0000005, an access violation,
// and the like) counts as a crash.
int run(const std::vector<std::string>& args, const fs::path& out, const fs::path& err) {
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    auto create = [&](const fs::path& path) {
        return CreateFileW(path.c_str(), GENERIC_WRITE, FILE_SHARE_READ, &inherit, CREATE_ALWAYS,
                           FILE_ATTRIBUTE_NORMAL, nullptr);
    };
    HANDLE o = create(out), e = create(err);
    std::string command;
    for (const auto& a : args) command += (command.empty() ? "" : " ") + quoted(a);
    STARTUPINFOA startup{};
    startup.cb = sizeof(startup);
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
    startup.hStdOutput = o;
    startup.hStdError = e;
    PROCESS_INFORMATION process{};
    const BOOL started = CreateProcessA(nullptr, command.data(), nullptr, nullptr, TRUE, 0, nullptr,
                                        nullptr, &startup, &process);
    CloseHandle(o);
    CloseHandle(e);
    if (!started) {
        std::fprintf(stderr, "CreateProcessA failed (error %lu): %s\n", GetLastError(),
                     command.c_str());
        return 127;
    }
    WaitForSingleObject(process.hProcess, INFINITE);
    DWORD status = 0;
    GetExitCodeProcess(process.hProcess, &status);
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);
    if (status >= 0xC0000000u) {
        std::fprintf(stderr, "the chapter ended with exception 0x%08lX\n", status);
        return 128;
    }
    return static_cast<int>(status);
}
#else
// Runs argv with stdout and stderr sent to files; returns the exit status, or
// 128 + signal for a crash (which never counts as a clean failure).
int run(const std::vector<std::string>& args, const fs::path& out, const fs::path& err) {
    pid_t pid = fork();
    if (pid == 0) {
        int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(o, 1);
        dup2(e, 2);
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        std::perror("execv");
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WEXITSTATUS(status);
}
#endif

// Each spec is "x,y,r,g,b" or "x,y,r,g,b,tolerance" (default 1 per channel).
int check_pixels(const vkt::RgbaImage& actual, const std::vector<std::string>& pixels) {
    for (const auto& spec : pixels) {
        unsigned x, y, r, g, b, tolerance = 1;
        const int fields =
            std::sscanf(spec.c_str(), "%u,%u,%u,%u,%u,%u", &x, &y, &r, &g, &b, &tolerance);
        if (fields < 5 || x >= actual.width || y >= actual.height)
            return fail("bad --pixel " + spec + " for a " + std::to_string(actual.width) + "x" +
                        std::to_string(actual.height) + " picture");
        const uint8_t* p = &actual.pixels[(size_t{y} * actual.width + x) * 4];
        const unsigned want[3] = {r, g, b};
        for (int c = 0; c < 3; ++c)
            if (unsigned(std::abs(int(p[c]) - int(want[c]))) > tolerance)
                return fail("pixel " + std::to_string(x) + "," + std::to_string(y) + " is " +
                            std::to_string(p[0]) + "," + std::to_string(p[1]) + "," +
                            std::to_string(p[2]) + ", expected " + std::to_string(r) + "," +
                            std::to_string(g) + "," + std::to_string(b) + " (within " +
                            std::to_string(tolerance) + ")");
        std::printf("pixel %u,%u: %u,%u,%u as expected\n", x, y, p[0], p[1], p[2]);
    }
    return 0;
}

// Each spec is "x,y,w,h,r,g,b,r,g,b,min,max": see --between above.
int check_blends(const vkt::RgbaImage& actual, const std::vector<std::string>& specs) {
    for (const auto& spec : specs) {
        unsigned x0, y0, w, h, a[3], b[3], least, most;
        const int fields =
            std::sscanf(spec.c_str(), "%u,%u,%u,%u,%u,%u,%u,%u,%u,%u,%u,%u", &x0, &y0, &w, &h,
                        &a[0], &a[1], &a[2], &b[0], &b[1], &b[2], &least, &most);
        if (fields != 12 || x0 + w > actual.width || y0 + h > actual.height)
            return fail("bad --between " + spec + " for a " + std::to_string(actual.width) + "x" +
                        std::to_string(actual.height) + " picture");
        constexpr int slack = 2;
        auto close_to = [](const uint8_t* p, const unsigned* c) {
            for (int k = 0; k < 3; ++k)
                if (std::abs(int(p[k]) - int(c[k])) > slack) return false;
            return true;
        };
        unsigned blends = 0, as_a = 0, as_b = 0;
        for (unsigned y = y0; y < y0 + h; ++y)
            for (unsigned x = x0; x < x0 + w; ++x) {
                const uint8_t* p = &actual.pixels[(size_t{y} * actual.width + x) * 4];
                if (close_to(p, a)) {
                    ++as_a;
                    continue;
                }
                if (close_to(p, b)) {
                    ++as_b;
                    continue;
                }
                bool inside = true;
                for (int k = 0; k < 3; ++k)
                    inside = inside && int(p[k]) >= int(std::min(a[k], b[k])) - slack &&
                             int(p[k]) <= int(std::max(a[k], b[k])) + slack;
                blends += inside ? 1 : 0;
            }
        std::printf("--between %s: %u pixels of the first colour, %u of the second, %u between\n",
                    spec.c_str(), as_a, as_b, blends);
        if (as_a == 0 || as_b == 0)
            return fail("--between " + spec + ": the rectangle does not hold both colours");
        if (blends < least || blends > most)
            return fail("--between " + spec + ": " + std::to_string(blends) +
                        " pixels lie between the two colours, expected " + std::to_string(least) +
                        " to " + std::to_string(most));
    }
    return 0;
}

// A message of the validation layer, printed by our debug messenger
// ("[validation error] ...", vkt/core/instance.hpp) or by the layer itself
// when no messenger is there yet ("Validation Error: ...").
std::string validation_message(const std::string& text) {
    static const std::regex message(
        R"(\[validation (error|warning)\][^\n]*|Validation (Error|Warning):[^\n]*)");
    std::smatch found;
    if (std::regex_search(text, found, message)) return found.str();
    return {};
}

// "RMSE,THRESHOLD,FRACTION": two ways of drawing that differ by design, with no
// bias or tile limit (vkt::Tolerance::loose), or with them given after it
// (",BIAS,TILE_MEDIAN"); "across-devices": a GPU's
// picture against lavapipe's golden (vkt::Tolerance::across_devices).
bool parse_tolerance(const std::string& spec, vkt::Tolerance& t) {
    if (spec == "across-devices") {
        t = vkt::Tolerance::across_devices();
        return true;
    }
    double rmse = 0, fraction = 0, bias = 0;
    int threshold = 0, tile = 0;
    const int fields =
        std::sscanf(spec.c_str(), "%lf,%d,%lf,%lf,%d", &rmse, &threshold, &fraction, &bias, &tile);
    if (fields != 3 && fields != 5) return false;
    t = vkt::Tolerance::loose(rmse, threshold, fraction);
    if (fields == 5) {  // ",BIAS,TILE_MEDIAN": those limits too
        t.max_bias = bias;
        t.max_tile_median = tile;
    }
    return true;
}

// Prints how far `actual` is from `expected`; true when within `tolerance`.
// A tolerance of zero demands the same picture to the bit.
bool compare_and_report(const vkt::RgbaImage& actual, const vkt::RgbaImage& expected,
                        const vkt::Tolerance& tolerance) {
    const vkt::ImageDifference d = vkt::compare_images(actual, expected, tolerance.threshold);
    std::printf(
        "picture: RMSE %.3f (max %.1f), %.4f%% of pixels off by more than %d (max %.2f%%), "
        "largest channel difference %d, bias %.3f (max %.2f), tile median %d at %u,%u (max %d)\n",
        d.rmse, tolerance.max_rmse, 100 * d.fraction_over_threshold, tolerance.threshold,
        100 * tolerance.max_fraction, d.max_channel_difference, d.max_bias, tolerance.max_bias,
        d.max_tile_median, d.tile_x, d.tile_y, tolerance.max_tile_median);
    return vkt::within(d, tolerance);
}

std::string size_text(const vkt::RgbaImage& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// --compare REFERENCE PICTURE [--tolerance ...]: 0 within, 1 outside, 2 bad input.
int compare_files(const fs::path& reference, const fs::path& picture,
                  const vkt::Tolerance& tolerance) {
    vkt::RgbaImage a, b;
    try {
        a = vkt::read_png(reference);
        b = vkt::read_png(picture);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vkt_chapter_check --compare: %s\n", e.what());
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "vkt_chapter_check --compare: %s is %s, %s is %s\n", reference.c_str(),
                     size_text(a).c_str(), picture.c_str(), size_text(b).c_str());
        return 2;
    }
    if (compare_and_report(b, a, tolerance)) {
        std::printf("same: %s is within the tolerance of %s\n", picture.c_str(), reference.c_str());
        return 0;
    }
    std::printf("differs: %s is outside the tolerance of %s\n", picture.c_str(), reference.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path exe, out_dir, golden, same_as;
    std::string name;
    int expected_exit = 0;
    fs::path isolate, png_only;
    bool blesses = false;
    std::optional<vkt::Tolerance> loose;  // --tolerance
    std::optional<std::pair<fs::path, fs::path>> compare;
    std::vector<std::string> expects, pixels, blends, chapter_args;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) std::exit(fail(arg + " needs a value") + 1);
            return argv[++i];
        };
        if (arg == "--exe")
            exe = next();
        else if (arg == "--out")
            out_dir = next();
        else if (arg == "--name")
            name = next();
        else if (arg == "--golden")
            golden = next();
        else if (arg == "--same-as")
            same_as = next();
        else if (arg == "--blesses")
            blesses = true;
        else if (arg == "--exit")
            expected_exit = std::stoi(next());
        else if (arg == "--expect")
            expects.push_back(next());
        else if (arg == "--png")
            png_only = next();
        else if (arg == "--pixel")
            pixels.push_back(next());
        else if (arg == "--between")
            blends.push_back(next());
        else if (arg == "--isolate")
            isolate = next();
        else if (arg == "--compare") {
            const fs::path reference = next();
            compare = std::pair{reference, fs::path(next())};
        } else if (arg == "--tolerance") {
            const std::string spec = next();
            vkt::Tolerance t;
            if (!parse_tolerance(spec, t))
                return fail("bad --tolerance " + spec +
                            ": want RMSE,THRESHOLD,FRACTION[,BIAS,TILE_MEDIAN] or across-devices") +
                       1;
            loose = t;
        } else if (arg == "--") {
            chapter_args.assign(argv + i + 1, argv + argc);
            break;
        } else
            return fail("unknown checker argument " + arg) + 1;
    }
    if (compare)
        return compare_files(compare->first, compare->second, loose.value_or(vkt::Tolerance{}));
    if (!png_only.empty()) {  // no run: only check the pixels of an existing picture
        const vkt::RgbaImage picture = vkt::read_png(png_only);
        if (int failed = check_pixels(picture, pixels)) return failed;
        if (int failed = check_blends(picture, blends)) return failed;
        std::printf("PASS\n");
        return 0;
    }
    if (exe.empty() || out_dir.empty() || name.empty())
        return fail("--exe, --out and --name are required");
    if (loose && golden.empty()) return fail("--tolerance needs --golden (or --compare)");
    fs::create_directories(out_dir);

    if (!isolate.empty()) {
        const fs::path bin = isolate / "bin";
        fs::create_directories(bin);
        fs::copy_file(exe, bin / exe.filename(), fs::copy_options::overwrite_existing);
        exe = bin / exe.filename();
    }

    const fs::path screenshot = out_dir / (name + ".png");
    const fs::path diff = out_dir / (name + ".diff.png");
    fs::remove(screenshot);
    fs::remove(diff);
    std::vector<std::string> args{exe.string()};
    args.insert(args.end(), chapter_args.begin(), chapter_args.end());
    // Hand-worked pixels need a picture even without a golden image to
    // compare it with; a test that names its own screenshot checks it later
    // with --png.
    const bool own_screenshot =
        std::find(chapter_args.begin(), chapter_args.end(), "--screenshot") != chapter_args.end();
    if ((!golden.empty() || !same_as.empty()) && own_screenshot)
        return fail(
            "--golden and --same-as take the checker's own screenshot: leave --screenshot out of "
            "ARGS");
    const bool checks = !pixels.empty() || !blends.empty();
    const bool picture = !golden.empty() || !same_as.empty() || (checks && !own_screenshot);
    if (picture) {
        args.push_back("--screenshot");
        args.push_back(screenshot.string());
    }

#ifndef _WIN32
    // Mesa 25.0's shader cache key leaves out llvmpipe's vector width (README:
    // "A processor without AVX"): a reader who sets LP_NATIVE_VECTOR_WIDTH
    // for the suite gets a cache folder of that width's own, not shaders
    // another width compiled, which crash lavapipe.
    if (const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH"); width && *width)
        if (const char* cache = std::getenv("MESA_SHADER_CACHE_DIR"); cache && *cache)
            setenv("MESA_SHADER_CACHE_DIR", (std::string(cache) + "_lp" + width).c_str(), 1);
#endif
    const fs::path out_file = out_dir / (name + ".stdout"), err_file = out_dir / (name + ".stderr");
    const int status = run(args, out_file, err_file);
    const std::string out = slurp(out_file), err = slurp(err_file);
    std::string command;
    for (const auto& a : args) command += a + " ";
    std::printf("ran: %s\nexit status: %d\n--- stderr ---\n%s", command.c_str(), status,
                err.c_str());

    if (status >= 128)
        return fail("the chapter crashed (signal " + std::to_string(status - 128) + ")");
    // Read before the exit status: a refusal that leaves a validation message
    // behind fails as surely as a drawing run would.
    for (const std::string* text : {&err, &out})
        if (const std::string message = validation_message(*text); !message.empty())
            return fail("a validation message (exit status " + std::to_string(status) +
                        "): " + message);
    if (status != expected_exit)
        return fail("exit status " + std::to_string(status) + ", expected " +
                    std::to_string(expected_exit));

    const bool validation =
        std::find(chapter_args.begin(), chapter_args.end(), "--validation") != chapter_args.end();
    if (expected_exit == 0 && validation &&
        err.find("validation: 0 warnings, 0 errors") == std::string::npos)
        return fail("no report of a clean validation run on stderr");

    for (const auto& pattern : expects)
        if (!std::regex_search(out, std::regex(pattern)) &&
            !std::regex_search(err, std::regex(pattern)))
            return fail("no output matches /" + pattern + "/");

    if (checks && own_screenshot)
        return fail(
            "--pixel and --between need the checker's own screenshot; check a picture the chapter "
            "wrote itself with --png FILE");
    if (!picture) {
        std::printf("PASS\n");
        return 0;
    }
    if (!fs::exists(screenshot)) return fail("the chapter wrote no screenshot");
    // The hand-worked pixels come first: not even blessing may contradict them.
    const vkt::RgbaImage actual = vkt::read_png(screenshot);
    if (int failed = check_pixels(actual, pixels)) return failed;
    if (int failed = check_blends(actual, blends)) return failed;
    const auto against = [&](const fs::path& reference, const vkt::Tolerance& tolerance) {
        const vkt::RgbaImage expected = vkt::read_png(reference);
        if (actual.width != expected.width || actual.height != expected.height)
            return fail("picture is " + size_text(actual) + ", " + reference.string() + " is " +
                        size_text(expected));
        if (!compare_and_report(actual, expected, tolerance)) {
            vkt::write_png(diff, vkt::difference_image(actual, expected));
            return fail("picture differs from " + reference.string() + "; see " +
                        screenshot.string() + " and " + diff.string());
        }
        return 0;
    };
    if (!same_as.empty()) {
        if (!fs::exists(same_as))
            return fail("no picture " + same_as.string() +
                        " to compare with: its test must run first (a CTest fixture orders them)");
        if (int failed = against(
                same_as, vkt::Tolerance{.max_rmse = 0.0, .threshold = 0, .max_fraction = 0.0}))
            return failed;
        std::printf("the same picture as %s, to the bit\n", same_as.c_str());
    }
    if (!golden.empty()) {
        if (const char* bless = std::getenv("VKT_BLESS");
            bless && std::string(bless) == "1" && blesses && !loose) {
            fs::create_directories(golden.parent_path());
            fs::copy_file(screenshot, golden, fs::copy_options::overwrite_existing);
            std::printf("blessed %s: look at it before you commit it\n", golden.c_str());
            return 0;
        }
        if (!fs::exists(golden))
            return fail("no golden image " + golden.string() + " (scripts/bless-goldens.sh)");
        if (int failed = against(golden, loose.value_or(vkt::Tolerance{}))) return failed;
    }
    std::printf("PASS\n");
    return 0;
}
